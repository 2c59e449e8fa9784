//! The sections of the lecture cases (seed 001) a scene may have beside or instead of a
//! machine: the rotor's balancing and the friction, each a short worked report — what is
//! found, the formula, the numbers, the result — then its table checking the construction
//! against the calculation and its figures.

use super::markup::{frac, num, sym};
use super::rows::of_scene;
use super::worked::{deg, Printed, Worked};
use super::{NoteError, Writer};
use crate::balancing::{
    analytic, inertia_force, main_moment, main_vector, BalancingSpec, Correction, Corrective, Mass,
};
use crate::check::{Key, Symbol};
use crate::geom::DVec2;
use crate::scene::PlateKind;
use crate::words::{CaseMeaning as M, CaseText as C, NoteText as T};

/// The balancing and friction studies of a scene that has them.
pub(super) fn others(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let scene = w.session.scene();
    if let Some(spec) = &scene.balancing {
        w.heading(1, T::BalancingSection);
        rotor(w, spec);
        let caption = w.word(T::BalancingTable);
        of_scene(w, caption, |r| {
            matches!(
                r.key.symbol,
                Symbol::Mass | Symbol::StaticMoment | Symbol::UnbalanceMoment | Symbol::Angle
            )
        });
        w.figures(
            (PlateKind::Balancing, None),
            |_| true,
            |own| own.to_string(),
        );
    }
    if !scene.friction.is_empty() {
        w.heading(1, T::FrictionSection);
        super::friction_pairs::cases(w);
        let caption = w.word(T::FrictionTable);
        of_scene(w, caption, |r| {
            r.position().is_none() || r.key.subject.ends_with("_f")
        });
        w.figures((PlateKind::Friction, None), |_| true, |own| own.to_string());
    }
    Ok(())
}

/// The rotor worked: the masses' inertia forces, then the correcting mass of each plane.
fn rotor(w: &mut Writer<'_, '_>, spec: &BalancingSpec) {
    let lang = w.lang;
    if let Some(omega) = spec.omega {
        w.doc.say(w.word(C::RotorIntro));
        for (i, m) in spec.masses.iter().enumerate() {
            let k = i + 1;
            let force = format!("F_{{и{k}}}");
            w.worked(Worked::new(
                sym(&force),
                format!(
                    "{} ω^2 {}",
                    sym(&format!("m_{{{k}}}")),
                    sym(&format!("ρ_{{{k}}}"))
                ),
                format!(
                    "{} dot {}^2 dot {}",
                    num(m.mass, 4, lang),
                    num(omega, 4, lang),
                    num(m.radius, 4, lang)
                ),
                Printed::si(inertia_force(m, omega), 5, "N", lang),
            ));
            let (mass, radius) = (format!("m_{{{k}}}"), format!("ρ_{{{k}}}"));
            let words = [
                w.word(M::InertiaForce),
                w.word(M::Mass),
                w.word(M::AngularSpeed),
                w.word(M::Radius),
            ];
            w.explain(&[
                (force.as_str(), words[0], "N"),
                (mass.as_str(), words[1], "kg"),
                ("ω", words[2], "rad/s"),
                (radius.as_str(), words[3], "m"),
            ]);
        }
    }
    let corrections = analytic(spec);
    match spec.correction {
        Correction::Static { .. } => {
            w.doc.say(w.word(C::RotorStatic));
            let d = projections(w, &spec.masses, None);
            if let Some(c) = corrections.first() {
                w.doc.say(w.word(C::RotorCorrection));
                let parts = (sym("D_{x}"), sym("D_{y}"));
                correcting(w, c, (d, parts), "у");
            }
        }
        Correction::Dynamic { planes, .. } => {
            w.doc.say(w.word(C::RotorDynamic));
            let span = planes[1] - planes[0];
            // Plane II from the moments about plane I, plane I from the static moments with
            // plane II's correction.
            let moment = projections(w, &spec.masses, Some(planes[0]));
            let per = |axis: &str| frac(&sym(&format!("M_{{{axis}}}")), "L");
            if let Some(second) = corrections.get(1) {
                let parts = (per("x"), per("y"));
                correcting(w, second, (moment / span, parts), "уII");
            }
            let statics = projections(w, &spec.masses, None);
            if let (Some(first), Some(second)) = (corrections.first(), corrections.get(1)) {
                let parts = (
                    format!("{} - {}", sym("D_{x}"), per("x")),
                    format!("{} - {}", sym("D_{y}"), per("y")),
                );
                correcting(w, first, (statics + second.unbalance, parts), "уI");
            }
        }
    }
}

/// The projections of the masses' static moments Σ mρ on the axes (with `about`, of their
/// moments Σ mρ(z − z_I) about that plane), worked; their sum as a vector.
fn projections(w: &mut Writer<'_, '_>, masses: &[Mass], about: Option<f64>) -> DVec2 {
    let lang = w.lang;
    let n = |x: f64| num(x, 4, lang);
    let sum = match about {
        None => main_vector(masses),
        Some(z0) => main_moment(masses, z0),
    };
    // The static moments' sum D, the moments' sum M about plane I.
    let (name, unit_si) = match about {
        None => ("D", "kg*m"),
        Some(_) => ("M", "kg*m^2"),
    };
    for (axis, f, value) in [("x", "cos", sum.x), ("y", "sin", sum.y)] {
        let symbol = format!("{name}_{{{axis}}}");
        let arm = |k: usize| match about {
            None => String::new(),
            Some(_) => format!(" {}", sym(&format!("z_{{{k}}}"))),
        };
        let symbolic: Vec<String> = (1..=masses.len())
            .map(|k| {
                format!(
                    "{} {}{} {f} {}",
                    sym(&format!("m_{{{k}}}")),
                    sym(&format!("ρ_{{{k}}}")),
                    arm(k),
                    sym(&format!("α_{{{k}}}"))
                )
            })
            .collect();
        let numbers: Vec<String> = masses
            .iter()
            .map(|m| {
                let z = about.map_or(String::new(), |z0| format!(" dot {}", n(m.z - z0)));
                format!(
                    "{} dot {}{z} dot {f} {}",
                    n(m.mass),
                    n(m.radius),
                    deg(m.angle, lang)
                )
            })
            .collect();
        w.worked(Worked::new(
            sym(&symbol),
            symbolic.join(" + "),
            numbers.join(" + "),
            Printed::si(value, 5, unit_si, lang),
        ));
        let words = [
            w.word(if about.is_none() {
                M::StaticMoment
            } else {
                M::MomentProjection
            }),
            w.word(M::Angle),
            w.word(M::PlaneDistance),
        ];
        let angle = "α_{1}";
        let mut items = vec![
            (symbol.as_str(), words[0], unit_si),
            (angle, words[1], "deg"),
        ];
        if about.is_some() {
            items.push(("z_{1}", words[2], "m"));
        }
        w.explain(&items);
    }
    sum
}

/// A correcting mass `index` (`у`, `уI`, `уII`) from the sum `d` its static moment cancels,
/// given with its components in symbols: m_уρ_у = |d|, m_у = m_уρ_у/ρ_у, its angle opposite
/// to `d`.
fn correcting(
    w: &mut Writer<'_, '_>,
    c: &Corrective,
    (d, (dx, dy)): (DVec2, (String, String)),
    index: &str,
) {
    let lang = w.lang;
    let n = |x: f64| num(x, 5, lang);
    let (m, rho) = (format!("m_{{{index}}}"), format!("ρ_{{{index}}}"));
    let moment = c.unbalance.length();
    let of = |symbol: Symbol| Key::of_scene(symbol, c.plane.subject());
    w.worked(
        Worked::new(
            format!("{} {}", sym(&m), sym(&rho)),
            format!("sqrt(({dx})^2 + ({dy})^2)"),
            format!("sqrt(({})^2 + ({})^2)", n(d.x), n(d.y)),
            Printed::si(moment, 5, "kg*m", lang),
        )
        .gives(of(Symbol::StaticMoment)),
    );
    let words = [
        w.word(M::CorrectingMass),
        w.word(M::CorrectingRadius),
        w.word(M::CorrectingAngle),
    ];
    let mut items = vec![(m.as_str(), words[0], "kg"), (rho.as_str(), words[1], "m")];
    if dx.contains('L') {
        items.push(("L", w.word(M::PlaneSpan), "m"));
    }
    w.explain(&items);
    w.worked(
        Worked::new(
            sym(&m),
            frac(&format!("{} {}", sym(&m), sym(&rho)), &sym(&rho)),
            frac(&n(moment), &n(c.radius)),
            Printed::si(c.mass(), 5, "kg", lang),
        )
        .gives(of(Symbol::Mass)),
    );
    if let Some(angle) = c.angle() {
        let a = format!("α_{{{index}}}");
        w.worked(
            Worked::new(
                sym(&a),
                format!(
                    "op(\"arctg\") {}",
                    frac(&format!("-({dy})"), &format!("-({dx})"))
                ),
                format!("op(\"arctg\") {}", frac(&n(-d.y), &n(-d.x))),
                Printed::deg(angle, lang),
            )
            .gives(of(Symbol::Angle)),
        );
        w.explain(&[(a.as_str(), words[2], "deg")]);
    }
}
