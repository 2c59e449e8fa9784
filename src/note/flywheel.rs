//! The flywheel worked (seed 000 §5.6–5.8): J_м by Wittenbauer's energy–mass diagram and by
//! Mertsalov's T_I, each formula with the segment read off its diagram; the constant moment and
//! the mean power; the exact flywheel; its material, D = (J/(K_j·ρ))^(1/5), m = K_m·ρ·D³
//! with the J_м the construction gives (Wittenbauer's, the sheet's: a hand-in sizes the
//! flywheel it draws), beside the exact J_м and the δ each gives, and the rim speed against
//! the material's limit.

use super::markup::{frac, inline, label, num, sym, text, unit};
use super::moments::{explain_words, fill};
use super::worked::{Printed, Worked};
use super::Writer;
use crate::check::{Key, Method, Symbol};
use crate::dynamics::{ConstantMoment, Dynamics, FlywheelKind, FlywheelSpec};
use crate::words::{unit_in, MachinesMeaning as M, MachinesNote as N, NoteText as T};

/// The digits K_j and K_m are written with.
const K_DIGITS: usize = FlywheelSpec::COEFFICIENT_DIGITS;

/// The unit of a moment of inertia (a key of the catalogue).
const JM: &str = "kg*m^2";

/// The report's key of the flywheel's `symbol` (J_м, D).
fn flywheel(symbol: Symbol) -> Key {
    Key::of_scene(symbol, "flywheel")
}

/// J_м by each textbook route, worked from what its diagram gives.
pub(super) fn routes(w: &mut Writer<'_, '_>, d: &Dynamics) {
    let lang = w.lang;
    let g = &d.diagrams;
    let (delta, om) = (d.spec.delta, d.w_avg);
    // Wittenbauer: kl read off the energy–mass diagram at its μ_T.
    let mu = g.scale_tw.value();
    let kl = g.wittenbauer.range / mu;
    w.doc.say(w.word(N::WittenbauerWorked));
    w.worked(
        Worked::new(
            sym("J_{м}"),
            frac(
                &format!("{} {}", sym("μ_{T}"), sym("kl")),
                &format!("δ {}^2", sym("ω_{ср}")),
            ),
            frac(
                &format!("{} dot {}", num(mu, 4, lang), num(kl, 4, lang)),
                &format!("{} dot {}^2", num(delta, 4, lang), num(om, 5, lang)),
            ),
            Printed::si(g.wittenbauer.read, 5, JM, lang),
        )
        .gives_by(flywheel(Symbol::Inertia), Method::Wittenbauer),
    );
    let items = [
        ("J_{м}", M::Flywheel, "kg*m^2"),
        ("μ_{T}", M::EnergyScale, "J/mm"),
        ("kl", M::Segment, "mm"),
        ("δ", M::Irregularity, ""),
        ("ω_{ср}", M::MeanSpeed, "rad/s"),
    ];
    explain_words(w, &items);
    // Mertsalov: the range of T_I, less the constant inertia.
    let j_const = d.spec.constant_inertia();
    w.doc.say(w.word(N::MertsalovWorked));
    w.worked(
        Worked::new(
            sym("J_{м}"),
            format!(
                "{} - {}",
                frac(&sym("ΔT_{I}"), &format!("δ {}^2", sym("ω_{ср}"))),
                sym("J_{const}")
            ),
            format!(
                "{} - {}",
                frac(
                    &num(g.mertsalov.range, 5, lang),
                    &format!("{} dot {}^2", num(delta, 4, lang), num(om, 5, lang))
                ),
                num(j_const, 5, lang)
            ),
            Printed::si(g.mertsalov.read, 5, JM, lang),
        )
        .gives_by(flywheel(Symbol::Inertia), Method::Mertsalov),
    );
    let items = [
        ("ΔT_{I}", M::MertsalovRange, "J"),
        ("J_{const}", M::ConstantInertia, "kg*m^2"),
    ];
    explain_words(w, &items);
}

/// The constant moment from the work of the varying side over the cycle, the mean power,
/// and the exact flywheel.
pub(super) fn drive(w: &mut Writer<'_, '_>, d: &Dynamics) {
    let lang = w.lang;
    let engine = d.spec.constant_moment == ConstantMoment::Resisting;
    let (m, y, intro) = if engine {
        ("M_{с}", "y_{с}", w.word(N::EngineMomentRead))
    } else {
        ("M_{д}", "y_{д}", w.word(N::DriveMomentRead))
    };
    // The moment as read through the pole: its ordinate, mm, at μ_M (seed 000 L1484).
    let g = &d.diagrams;
    let mu = g.scale_m.value();
    let mv = g.m_drive.abs();
    w.doc.par(&[label(intro)]);
    let moment = Key::of_scene(Symbol::Moment, if engine { "res" } else { "drive" });
    w.worked(
        Worked::new(
            sym(m),
            format!("{} {}", sym("μ_{M}"), sym(y)),
            format!("{} dot {}", num(mu, 4, lang), num(mv / mu, 4, lang)),
            Printed::si(mv, 5, "N*m", lang),
        )
        .gives_by(moment, Method::Integration),
    );
    explain_words(w, &[(m, M::ConstantMoment, "N*m"), (y, M::Ordinate, "mm")]);
    w.worked(Worked::new(
        sym("N_{ср}"),
        format!("{} {}", sym(m), sym("ω_{ср}")),
        format!("{} dot {}", num(mv, 5, lang), num(d.w_avg, 5, lang)),
        Printed::si(mv * d.w_avg, 5, "W", lang),
    ));
    let items = [("N_{ср}", M::MeanPower, "W")];
    explain_words(w, &items);
    w.doc.par(&[
        text(w.word(T::ExactFlywheel)),
        inline(&format!(
            "{} = {}{}, {} = {}{}, {} = {}{}",
            sym("J_{м}"),
            num(d.exact.j_fw, 5, lang),
            unit(&unit_in("kg*m^2", lang)),
            sym("ω_{max}"),
            num(d.exact.w_max.0, 5, lang),
            unit(&unit_in("rad/s", lang)),
            sym("ω_{min}"),
            num(d.exact.w_min.0, 5, lang),
            unit(&unit_in("rad/s", lang)),
        )),
    ]);
}

/// The flywheel's material and shape, its diameter and mass worked, the rim speed against
/// the material's limit, and the main dimensions.
pub(super) fn size(w: &mut Writer<'_, '_>, d: &Dynamics) {
    let lang = w.lang;
    let fw = &d.spec.flywheel;
    let s = &d.size;
    let material = w.word(if fw.cast_iron() {
        N::CastIron
    } else {
        N::Steel
    });
    let shape = match fw.kind {
        FlywheelKind::Rim => N::RimWheel,
        FlywheelKind::Disc => N::DiscWheel,
    };
    let sig = |x: f64, n: usize| crate::scale::format_sig(x, n, lang);
    // Sized from the construction's J_м (the sheet's), the exact one and the δ each gives.
    let sentence = fill(
        w.word(shape),
        &[
            ("material", material.to_string()),
            ("rho", sig(fw.rho, 5)),
            ("kj", sig(fw.k_j, K_DIGITS)),
            ("km", sig(fw.k_m, K_DIGITS)),
            ("jm", sig(s.j, 5)),
            ("delta", sig(d.delta_of[0], 4)),
            ("exact", sig(d.exact.j_fw, 5)),
            ("asked", sig(d.exact.delta(), 4)),
            ("exact_d", sig(d.exact_size.d, 4)),
        ],
    );
    w.doc.par(&[label(&sentence)]);
    w.worked(
        Worked::new(
            sym("D"),
            format!(
                "root(5, {})",
                frac(&sym("J_{м}"), &format!("{} ρ", sym("K_{j}")))
            ),
            format!(
                "root(5, {})",
                frac(
                    &num(s.j, 5, lang),
                    &format!(
                        "{} dot {}",
                        num(fw.k_j, K_DIGITS, lang),
                        num(fw.rho, 5, lang)
                    )
                )
            ),
            Printed::si(s.d, 4, "m", lang),
        )
        .gives_by(flywheel(Symbol::Length), Method::Wittenbauer),
    );
    let items = [
        ("D", M::Diameter, "m"),
        ("K_{j}", M::ShapeJ, ""),
        ("ρ", M::Density, "kg/m^3"),
    ];
    explain_words(w, &items);
    taken(w, d);
    let s = &d.made;
    shape_law(w, ("m", "K_{m}", fw.k_m), 3, d, (s.mass, 4, "kg"));
    let items = [("m", M::FlywheelMass, "kg"), ("K_{m}", M::ShapeM, "")];
    explain_words(w, &items);
    let verdict = crate::sheets::flywheel_verdict(d, lang).join(" ");
    w.doc.par(&[label(&verdict)]);
    w.doc.say(w.word(N::RimSpeed));
    let v = s.rim_speed(d.w_avg);
    w.worked(Worked::new(
        sym("v"),
        frac(&format!("{} {}", sym("ω_{ср}"), sym("D")), "2"),
        frac(
            &format!("{} dot {}", num(d.w_avg, 5, lang), num(s.d, 4, lang)),
            "2",
        ),
        Printed::si(v, 4, "m/s", lang),
    ));
    let items = [("v", M::RimSpeed, "m/s")];
    explain_words(w, &items);
    let limit = fw.rim_speed_limit();
    let verdict = if v <= limit {
        N::RimSpeedWithin
    } else {
        N::RimSpeedBeyond
    };
    let s2 = fill(
        w.word(verdict),
        &[
            ("material", material.to_string()),
            ("limit", crate::scale::format_sig(limit, 3, lang)),
        ],
    );
    w.doc.say(&s2);
    let dims: Vec<String> = s
        .dims
        .iter()
        .filter(|(name, _)| *name != "D")
        .map(|(name, x)| {
            format!(
                "{} = {}{}",
                sym(name),
                num(x * 1e3, 4, lang),
                unit(w.word(T::MmUnit))
            )
        })
        .collect();
    w.doc
        .par(&[text(w.word(T::FlywheelSize)), inline(&dims.join(", "))]);
}

/// The outer diameter taken, the worked one rounded up, and the flywheel's J at it: the part
/// drawn.
fn taken(w: &mut Writer<'_, '_>, d: &Dynamics) {
    let lang = w.lang;
    let fw = &d.spec.flywheel;
    let sig = |x: f64, n: usize| crate::scale::format_sig(x, n, lang);
    let s = &d.made;
    let step = crate::dynamics::diameter_step(d.size.d);
    let taken = fill(
        w.word(N::TakenDiameter),
        &[("step", sig(step * 1e3, 3)), ("d", sig(s.d, 4))],
    );
    w.doc.say(&taken);
    shape_law(w, ("J", "K_{j}", fw.k_j), 5, d, (s.j, 5, "kg*m^2"));
    let items = [("J", M::FlywheelInertia, "kg*m^2")];
    explain_words(w, &items);
}

/// A quantity of the flywheel made by its shape law, worked: `lhs` = K·ρ·D^`power` with the
/// coefficient (its symbol, its value), and the value (to its significant digits, in its unit).
fn shape_law(
    w: &mut Writer<'_, '_>,
    (lhs, k_sym, k): (&str, &str, f64),
    power: u32,
    d: &Dynamics,
    (value, digits, unit_key): (f64, usize, &str),
) {
    let lang = w.lang;
    w.worked(Worked::new(
        sym(lhs),
        format!("{} ρ {}^{power}", sym(k_sym), sym("D")),
        format!(
            "{} dot {} dot {}^{power}",
            num(k, K_DIGITS, lang),
            num(d.spec.flywheel.rho, 5, lang),
            num(d.made.d, 4, lang)
        ),
        Printed::si(value, digits, unit_key, lang),
    ));
}
