//! The friction in the kinematic pairs worked as seed 001 works its lectures 9–13: for each
//! case what is found, the formula, the numbers and the result — the friction angle, the
//! incline's force and efficiency, the V-slider's reduced coefficient, the screw's moment and
//! efficiency, the journal's friction circle, the load on rollers (W3) and the slider's state
//! against its cones. Every number is the case's twin's, the value the friction table checks
//! the force plans against.

use super::markup::{frac, num, sym};
use super::worked::{deg, Printed, Worked};
use super::Writer;
use crate::check::{Key, Symbol};
use crate::friction::{
    incline_twin, journal_twin, rolling_twin, screw_twin, slider_twin, wedge_twin, CaseKind,
    Incline, Journal, Motion, Rolling, Screw, Slider, SliderState, Wedge,
};
use crate::scale::Lang;
use crate::words::{CaseMeaning as M, CaseText as C, FrictionText};

/// Every case of the scene's friction under its title line (`Случай n: …`, as the sheet
/// numbers it), worked; a cam follower's case by [`super::friction`].
pub(super) fn cases(w: &mut Writer<'_, '_>) {
    w.doc.say(w.word(C::FrictionIntro));
    let cases = w.session.scene().friction.clone();
    // The friction angles worked so far (f): each worked once.
    let mut angles: Vec<f64> = Vec::new();
    for (i, case) in cases.iter().enumerate() {
        let name = crate::sheets::friction::case_name(&case.kind, w.lang);
        let title = format!("{} {}: {name}.", w.word(FrictionText::Case), i + 1);
        w.doc.say(&title);
        match &case.kind {
            CaseKind::Incline(c) => incline(w, (c, &case.name), &mut angles),
            CaseKind::Wedge(c) => wedge(w, c, &case.name),
            CaseKind::Screw(c) => screw(w, c, &case.name),
            CaseKind::Journal(c) => journal(w, (c, &case.name), &mut angles),
            CaseKind::Rolling(c) => rolling(w, c, &case.name),
            CaseKind::Slider(c) => slider(w, (c, &case.name), &mut angles),
            CaseKind::Guide(c) => super::friction::guide(w, c, &case.name),
            CaseKind::Pivot(c) => super::friction::pivot(w, c, &case.name),
        }
    }
}

/// A number of the worked formulas.
fn n(w: &Writer<'_, '_>, x: f64) -> String {
    num(x, 5, w.lang)
}

/// A force with its unit.
fn newtons(w: &Writer<'_, '_>, x: f64) -> Printed {
    Printed::si(x, 5, "N", w.lang)
}

/// The key of case `case`'s row `symbol` of `what` ([`crate::friction::subject`]).
fn key(symbol: Symbol, what: &str, case: &str) -> Key {
    Key::of_scene(symbol, crate::friction::subject(what, case))
}

/// φ = arctg f, worked unless an earlier case has worked it for the same f (`angles`).
fn friction_angle(
    w: &mut Writer<'_, '_>,
    (f, phi): (f64, f64),
    gives: Option<Key>,
    angles: &mut Vec<f64>,
) {
    if angles.contains(&f) {
        return;
    }
    angles.push(f);
    w.doc.say(w.word(C::FrictionAngle));
    let row = Worked::new(
        sym("φ"),
        "op(\"arctg\") f",
        format!("op(\"arctg\") {}", n(w, f)),
        Printed::deg(phi, w.lang),
    );
    w.worked(row.giving(gives));
    let (a, b) = (w.word(M::FrictionAngle), w.word(M::FrictionCoefficient));
    w.explain(&[("φ", a, "deg"), ("f", b, "")]);
}

/// Uniform motion on an inclined plane: P and R from the force triangle, P₀ and η.
fn incline(w: &mut Writer<'_, '_>, (c, name): (&Incline, &str), angles: &mut Vec<f64>) {
    let t = incline_twin(c);
    friction_angle(
        w,
        (c.f, t.phi),
        Some(key(Symbol::Angle, "phi", name)),
        angles,
    );
    let lang = w.lang;
    let s = if c.motion == Motion::Up { "+" } else { "-" };
    let (q, a, b, phi) = (
        n(w, c.load),
        deg(c.alpha, lang),
        deg(c.beta, lang),
        deg(t.phi, lang),
    );
    w.doc.say(w.word(C::InclineForce));
    let p = newtons(w, t.p);
    w.worked(
        Worked::new(
            sym("P"),
            frac(&format!("Q sin(α {s} φ)"), &format!("cos(α {s} φ - β')")),
            frac(
                &format!("{q} dot sin({a} {s} {phi})"),
                &format!("cos({a} {s} {phi} - {b})"),
            ),
            p,
        )
        .gives(key(Symbol::Force, "P", name)),
    );
    let words = [
        w.word(M::DrivingForce),
        w.word(M::Load),
        w.word(M::Slope),
        w.word(M::ForceTilt),
        w.word(M::Reaction),
    ];
    w.explain(&[
        ("P", words[0], "N"),
        ("Q", words[1], "N"),
        ("α", words[2], "deg"),
        ("β′", words[3], "deg"),
    ]);
    let pn = n(w, t.p);
    let r = newtons(w, t.r);
    w.worked(
        Worked::new(
            sym("R"),
            "sqrt((P cos β')^2 + (Q - P sin β')^2)",
            format!("sqrt(({pn} dot cos {b})^2 + ({q} - {pn} dot sin {b})^2)"),
            r,
        )
        .gives(key(Symbol::Reaction, "", name)),
    );
    w.explain(&[("R", words[4], "N")]);
    w.doc.say(w.word(C::InclineIdeal));
    let p0 = newtons(w, t.p0);
    w.worked(Worked::new(
        sym("P_{0}"),
        frac("Q sin α", "cos(α - β')"),
        frac(&format!("{q} dot sin {a}"), &format!("cos({a} - {b})")),
        p0,
    ));
    let ideal = w.word(M::IdealForce);
    w.explain(&[("P_{0}", ideal, "N")]);
    let p0n = n(w, t.p0);
    let (symbolic, numbers) = match c.motion {
        Motion::Up => (frac(&sym("P_{0}"), "P"), frac(&p0n, &pn)),
        Motion::Down => (frac("P", &sym("P_{0}")), frac(&pn, &p0n)),
    };
    w.worked(
        Worked::new(
            sym("η"),
            &symbolic,
            &numbers,
            Printed::plain(t.eta, 4, lang),
        )
        .gives(key(Symbol::Ratio, "", name)),
    );
    let e = w.word(M::Efficiency);
    w.explain(&[("η", e, "")]);
    if t.self_braking {
        w.doc.say(w.word(C::SelfBraking));
    }
}

/// The V-groove slider: the flanks' normal force, the pushing force, f′ and φ′.
fn wedge(w: &mut Writer<'_, '_>, c: &Wedge, name: &str) {
    let t = wedge_twin(c);
    let lang = w.lang;
    let (q, f, half) = (n(w, c.load), n(w, c.f), deg(c.groove / 2.0, lang));
    w.doc.say(w.word(C::WedgeWorked));
    let flank = newtons(w, t.n);
    w.worked(
        Worked::new(
            sym("N_{1}"),
            frac("Q", "2 sin(β/2)"),
            frac(&q, &format!("2 dot sin {half}")),
            flank,
        )
        .gives(key(Symbol::Force, "N", name)),
    );
    let (a, b) = (w.word(M::FlankNormal), w.word(M::Groove));
    w.explain(&[("N_{1}", a, "N"), ("β", b, "deg")]);
    let p = newtons(w, t.p);
    w.worked(
        Worked::new(
            sym("P"),
            frac("f Q", "sin(β/2)"),
            frac(&format!("{f} dot {q}"), &format!("sin {half}")),
            p,
        )
        .gives(key(Symbol::Force, "P", name)),
    );
    let words = [
        w.word(M::DrivingForce),
        w.word(M::FrictionCoefficient),
        w.word(M::ReducedCoefficient),
        w.word(M::ReducedAngle),
    ];
    w.explain(&[("P", words[0], "N"), ("f", words[1], "")]);
    let fr = num(t.f_reduced, 5, lang);
    w.worked(Worked::new(
        sym("f′"),
        frac("f", "sin(β/2)"),
        frac(&f, &format!("sin {half}")),
        Printed::number(t.f_reduced, lang),
    ));
    w.explain(&[("f′", words[2], "")]);
    w.worked(reduced_angle(&fr, t.phi_reduced, name, lang));
    w.explain(&[("φ′", words[3], "deg")]);
}

/// φ′ = arctg f′ (`fr` as printed) of case `name`.
fn reduced_angle(fr: &str, phi: f64, name: &str, lang: Lang) -> Worked {
    Worked::new(
        sym("φ′"),
        "op(\"arctg\") f'",
        format!("op(\"arctg\") {fr}"),
        Printed::deg(phi, lang),
    )
    .gives(key(Symbol::Angle, "phi", name))
}

/// The screw pair: f′, φ′, the tangential force, the moment and the efficiency.
fn screw(w: &mut Writer<'_, '_>, c: &Screw, name: &str) {
    let t = screw_twin(c);
    let lang = w.lang;
    let (q, f) = (n(w, c.load), n(w, c.f));
    let (lead, half) = (deg(c.lead, lang), deg(c.profile / 2.0, lang));
    w.doc.say(w.word(C::ScrewWorked));
    let fr = num(t.f_reduced, 5, lang);
    w.worked(Worked::new(
        sym("f′"),
        frac("f", "cos(δ/2)"),
        frac(&f, &format!("cos {half}")),
        Printed::number(t.f_reduced, lang),
    ));
    let words = [
        w.word(M::ReducedCoefficient),
        w.word(M::FrictionCoefficient),
        w.word(M::Profile),
        w.word(M::ReducedAngle),
    ];
    w.explain(&[
        ("f′", words[0], ""),
        ("f", words[1], ""),
        ("δ", words[2], "deg"),
    ]);
    let phi = deg(t.phi_reduced, lang);
    w.worked(reduced_angle(&fr, t.phi_reduced, name, lang));
    w.explain(&[("φ′", words[3], "deg")]);
    w.doc.say(w.word(C::ScrewForce));
    let s = if c.motion == Motion::Up { "+" } else { "-" };
    let p = newtons(w, t.p);
    w.worked(Worked::new(
        sym("P"),
        format!("Q op(\"tg\")(λ {s} φ')"),
        format!("{q} dot op(\"tg\")({lead} {s} {phi})"),
        p,
    ));
    let words = [
        w.word(M::ScrewForce),
        w.word(M::Load),
        w.word(M::Lead),
        w.word(M::ScrewMoment),
        w.word(M::MeanRadius),
        w.word(M::Efficiency),
    ];
    w.explain(&[
        ("P", words[0], "N"),
        ("Q", words[1], "N"),
        ("λ", words[2], "deg"),
    ]);
    w.worked(
        Worked::new(
            sym("M"),
            format!("P {}", sym("r_{1}")),
            format!("{} dot {}", n(w, t.p), n(w, c.radius)),
            Printed::si(t.moment, 5, "N*m", lang),
        )
        .gives(key(Symbol::Moment, "", name)),
    );
    w.explain(&[("M", words[3], "N*m"), ("r_{1}", words[4], "m")]);
    let tg = |x: f64| num(x.tan(), 5, lang);
    let (symbolic, numbers) = match c.motion {
        Motion::Up => (
            frac("op(\"tg\") λ", "op(\"tg\")(λ + φ')"),
            frac(&tg(c.lead), &tg(c.lead + t.phi_reduced)),
        ),
        Motion::Down => (
            frac("op(\"tg\")(λ - φ')", "op(\"tg\") λ"),
            frac(&tg(c.lead - t.phi_reduced), &tg(c.lead)),
        ),
    };
    w.worked(Worked::new(
        sym("η"),
        &symbolic,
        &numbers,
        Printed::plain(t.eta, 4, lang),
    ));
    w.explain(&[("η", words[5], "")]);
    if t.self_locking {
        w.doc.say(w.word(C::SelfLocking));
    }
}

/// The journal: φ, the friction circle's radius and the friction moment.
fn journal(w: &mut Writer<'_, '_>, (c, name): (&Journal, &str), angles: &mut Vec<f64>) {
    let t = journal_twin(c);
    friction_angle(w, (c.f, t.phi), None, angles);
    let lang = w.lang;
    w.doc.say(w.word(C::JournalWorked));
    w.worked(
        Worked::new(
            sym("ρ"),
            "r sin φ",
            format!("{} dot sin {}", n(w, c.radius * 1e3), deg(t.phi, lang)),
            Printed::mm(t.rho, 5, lang),
        )
        .gives(key(Symbol::Length, "rho", name)),
    );
    let (a, b) = (w.word(M::FrictionCircle), w.word(M::JournalRadius));
    w.explain(&[("ρ", a, "mm"), ("r", b, "mm")]);
    w.worked(
        Worked::new(
            sym("M_{тр}"),
            "Q ρ",
            format!("{} dot {}", n(w, c.load), n(w, t.rho)),
            Printed::si(t.moment, 5, "N*m", lang),
        )
        .gives(key(Symbol::Moment, "f", name)),
    );
    let (a, b) = (w.word(M::FrictionMoment), w.word(M::Load));
    w.explain(&[("M_{тр}", a, "N*m"), ("Q", b, "N")]);
}

/// The load on rollers (W3): the plane's reaction, the rolling force, whether the rolling
/// is pure, and the force without rollers.
fn rolling(w: &mut Writer<'_, '_>, c: &Rolling, name: &str) {
    let t = rolling_twin(c);
    let (q, g) = (n(w, c.load), n(w, c.roller_weight));
    let r = newtons(w, t.r_n2);
    w.worked(Worked::new(
        sym("R_{n2}"),
        "Q + 2 G",
        format!("{q} + 2 dot {g}"),
        r,
    ));
    let words = [
        w.word(M::PlaneReaction),
        w.word(M::Load),
        w.word(M::RollerWeight),
    ];
    w.explain(&[
        ("R_{n2}", words[0], "N"),
        ("Q", words[1], "N"),
        ("G", words[2], "N"),
    ]);
    w.doc.say(w.word(C::RollingWorked));
    let mm = |x: f64| n(w, x * 1e3);
    let (k1, k2, d) = (mm(c.k1), mm(c.k2), mm(c.diameter));
    let p = newtons(w, t.p_rolling);
    w.worked(
        Worked::new(
            sym("P"),
            frac(
                &format!("Q {} + (Q + 2 G) {}", sym("k_{1}"), sym("k_{2}")),
                "d",
            ),
            frac(&format!("{q} dot {k1} + ({q} + 2 dot {g}) dot {k2}"), &d),
            p,
        )
        .gives(key(Symbol::Force, "P", name)),
    );
    let words = [
        w.word(M::RollingForce),
        w.word(M::RollingUpper),
        w.word(M::RollingLower),
        w.word(M::RollerDiameter),
    ];
    w.explain(&[
        ("P", words[0], "N"),
        ("k_{1}", words[1], "mm"),
        ("k_{2}", words[2], "mm"),
        ("d", words[3], "mm"),
    ]);
    w.doc.say(w.word(if t.pure {
        C::RollingPure
    } else {
        C::RollingSlides
    }));
    w.doc.say(w.word(C::RollingWithout));
    let slide = newtons(w, t.p_sliding);
    w.worked(
        Worked::new(
            sym("P_{ск}"),
            format!("Q {}", sym("f_{2}")),
            format!("{q} dot {}", n(w, c.f2)),
            slide,
        )
        .gives(key(Symbol::Force, "Pslide", name)),
    );
    let (a, b) = (w.word(M::SlidingForce), w.word(M::PlaneFriction));
    w.explain(&[("P_{ск}", a, "N"), ("f_{2}", b, "")]);
}

/// A slider pressed at α: φ and φ₀, N, P₁, the net force and the state.
fn slider(w: &mut Writer<'_, '_>, (c, name): (&Slider, &str), angles: &mut Vec<f64>) {
    let t = slider_twin(c);
    let lang = w.lang;
    friction_angle(
        w,
        (c.f, t.phi),
        Some(key(Symbol::Angle, "phi", name)),
        angles,
    );
    w.worked(Worked::new(
        sym("φ_{0}"),
        format!("op(\"arctg\") {}", sym("f_{0}")),
        format!("op(\"arctg\") {}", n(w, c.f0)),
        Printed::deg(t.phi0, lang),
    ));
    let (a, b) = (w.word(M::StaticAngle), w.word(M::StaticCoefficient));
    w.explain(&[("φ_{0}", a, "deg"), ("f_{0}", b, "")]);
    w.doc.say(w.word(C::SliderWorked));
    let (p, alpha) = (n(w, c.load), deg(c.alpha, lang));
    let normal = newtons(w, t.n);
    w.worked(
        Worked::new(sym("N"), "P cos α", format!("{p} dot cos {alpha}"), normal).gives(key(
            Symbol::Force,
            "N",
            name,
        )),
    );
    let words = [
        w.word(M::NormalForce),
        w.word(M::SliderForce),
        w.word(M::ForceAngle),
        w.word(M::AlongForce),
        w.word(M::NetForce),
    ];
    w.explain(&[
        ("N", words[0], "N"),
        ("P", words[1], "N"),
        ("α", words[2], "deg"),
    ]);
    let along = newtons(w, t.p1);
    w.worked(Worked::new(
        sym("P_{1}"),
        "P sin α",
        format!("{p} dot sin {alpha}"),
        along,
    ));
    w.explain(&[("P_{1}", words[3], "N")]);
    let (f, state) = match t.state {
        SliderState::Rest => (format!("{} N", sym("f_{0}")), C::SliderRest),
        SliderState::Uniform => ("f N".to_string(), C::SliderUniform),
        SliderState::Accelerating => ("f N".to_string(), C::SliderAccelerates),
    };
    let coefficient = if t.state == SliderState::Rest {
        c.f0
    } else {
        c.f
    };
    let net = newtons(w, t.net);
    w.worked(
        Worked::new(
            sym("ΔP"),
            format!("{} - {f}", sym("P_{1}")),
            format!("{} - {} dot {}", n(w, t.p1), n(w, coefficient), n(w, t.n)),
            net,
        )
        .gives(key(Symbol::Force, "dP", name)),
    );
    w.explain(&[("ΔP", words[4], "N")]);
    w.doc.say(w.word(state));
}
