//! The friction of a cam's follower worked in the note (seed 001 lectures 15–16): for each
//! `guide` case the force P and the bearings' reactions from the rod's equilibrium, for each
//! `pivot` case the friction circle, the couple's arm and P; each with its jamming angle.
//! Symbols, numbers, result, as the other worked sections; the constructed values are in the
//! friction table beside them.

use super::markup::{frac, num, sym};
use super::worked::{deg, Printed, Worked};
use super::Writer;
use crate::check::{Key, Symbol};
use crate::friction::{guide_twin, pivot_twin, FollowerGuide, RockerPivot};
use crate::words::{CaseMeaning as M, NoteText as T};

/// A translating follower in its guide: P, N₁, N₂, R₁, R₂ and λ_кр.
pub(super) fn guide(w: &mut Writer<'_, '_>, c: &FollowerGuide, name: &str) {
    let Some(t) = guide_twin(c) else {
        return;
    };
    let lang = w.lang;
    let n = |x: f64| num(x, 4, lang);
    let mm = |x: f64| n(x * 1e3);
    let g = &c.guide;
    let (b, l, f) = (mm(g.length), mm(g.overhang), n(g.f));
    let lambda = deg(c.angle, lang);
    w.doc.say(w.word(T::FollowerGuideWorked));
    w.worked(
        Worked::new(
            sym("P"),
            frac(&sym("Q"), "cos λ - f sin λ (2 l + b)/b"),
            frac(
                &n(c.load),
                &format!("cos {lambda} - {f} dot sin {lambda} dot (2 dot {l} + {b})/{b}"),
            ),
            Printed::si(t.p, 4, "N", lang),
        )
        .gives(Key::of_scene(
            Symbol::Force,
            crate::friction::subject("P", name),
        )),
    );
    let words = [
        w.word(M::FollowerForce),
        w.word(M::Resistance),
        w.word(M::PressureAngle),
        w.word(M::FrictionCoefficient),
        w.word(M::GuideLength),
        w.word(M::Overhang),
        w.word(M::BearingNormal),
        w.word(M::BearingReaction),
        w.word(M::LockAngle),
    ];
    w.explain(&[
        ("P", words[0], "N"),
        ("Q", words[1], "N"),
        ("λ", words[2], "deg"),
        ("f", words[3], ""),
        ("l", words[5], "mm"),
        ("b", words[4], "mm"),
    ]);
    for (i, arm, value) in [(1, format!("({l} + {b})"), t.n[0]), (2, l.clone(), t.n[1])] {
        let near = if i == 1 { "(l + b)" } else { "l" };
        w.worked(Worked::new(
            sym(&format!("N_{{{i}}}")),
            frac(&format!("P sin λ dot {near}"), "b"),
            frac(&format!("{} dot sin {lambda} dot {arm}", n(t.p)), &b),
            Printed::si(value, 4, "N", lang),
        ));
        let normal = format!("N_{{{i}}}");
        w.explain(&[(normal.as_str(), words[6], "N")]);
        w.worked(
            Worked::new(
                sym(&format!("R_{{{i}}}")),
                format!("{} sqrt(1 + f^2)", sym(&format!("N_{{{i}}}"))),
                format!("{} dot sqrt(1 + {f}^2)", n(value)),
                Printed::si(t.r[i - 1], 4, "N", lang),
            )
            .gives(Key::of_scene(
                Symbol::Reaction,
                crate::friction::subject(&i.to_string(), name),
            )),
        );
        let total = format!("R_{{{i}}}");
        w.explain(&[(total.as_str(), words[7], "N")]);
    }
    w.doc.say(w.word(T::FollowerLock));
    w.worked(Worked::new(
        format!("op(\"tg\") {}", sym("λ_{кр}")),
        frac("b", "f (2 l + b)"),
        frac(&b, &format!("{f} dot (2 dot {l} + {b})")),
        Printed::plain(t.lock.tan(), 4, lang),
    ));
    w.explain(&[("λ_{кр}", words[8], "deg")]);
    w.formula(&format!(
        "{} = {} > λ = {lambda}",
        sym("λ_{кр}"),
        deg(t.lock, lang)
    ));
}

/// A rocker in its pivot: φ, ρ, h, P and λ_кр, the lecture's estimate beside it.
pub(super) fn pivot(w: &mut Writer<'_, '_>, c: &RockerPivot, name: &str) {
    let Some(t) = pivot_twin(c) else {
        return;
    };
    let lang = w.lang;
    let n = |x: f64| num(x, 4, lang);
    let v = &c.pivot;
    let (arm, d, f) = (n(v.arm * 1e3), n(v.diameter * 1e3), n(v.f));
    let (lambda, phi) = (deg(c.angle, lang), deg(v.f.atan(), lang));
    w.doc.say(w.word(T::FollowerPivotWorked));
    w.worked(Worked::new(
        sym("φ"),
        "op(\"arctg\") f",
        format!("op(\"arctg\") {f}"),
        Printed::deg(v.f.atan(), lang),
    ));
    let words = [
        w.word(M::FrictionAngle),
        w.word(M::FrictionCoefficient),
        w.word(M::FrictionCircle),
        w.word(M::PivotDiameter),
        w.word(M::ForceArm),
        w.word(M::RockerArm),
        w.word(M::PressureAngle),
        w.word(M::FollowerForce),
        w.word(M::ResistanceMoment),
        w.word(M::LockAngle),
    ];
    w.explain(&[("φ", words[0], "deg"), ("f", words[1], "")]);
    w.worked(
        Worked::new(
            sym("ρ"),
            "d/2 dot sin φ",
            format!("{d}/2 dot sin {phi}"),
            Printed::mm(t.rho, 4, lang),
        )
        .gives(Key::of_scene(
            Symbol::Length,
            crate::friction::subject("rho", name),
        )),
    );
    w.explain(&[("ρ", words[2], "mm"), ("d", words[3], "mm")]);
    w.worked(
        Worked::new(
            sym("h"),
            "L cos λ - ρ",
            format!("{arm} dot cos {lambda} - {}", n(t.rho * 1e3)),
            Printed::mm(t.h, 4, lang),
        )
        .gives(Key::of_scene(
            Symbol::Length,
            crate::friction::subject("", name),
        )),
    );
    w.explain(&[
        ("h", words[4], "mm"),
        ("L", words[5], "mm"),
        ("λ", words[6], "deg"),
    ]);
    w.worked(
        Worked::new(
            sym("P"),
            frac(&sym("M_{с}"), "h"),
            frac(&n(c.moment), &format!("{} dot 10^(-3)", n(t.h * 1e3))),
            Printed::si(t.p, 4, "N", lang),
        )
        .gives(Key::of_scene(
            Symbol::Force,
            crate::friction::subject("P", name),
        )),
    );
    w.explain(&[("P", words[7], "N"), ("M_{с}", words[8], "N*m")]);
    w.doc.say(w.word(T::FollowerLock));
    w.worked(Worked::new(
        format!("cos {}", sym("λ_{кр}")),
        frac("ρ", "L"),
        frac(&n(t.rho * 1e3), &arm),
        Printed::plain(t.lock.cos(), 4, lang),
    ));
    w.explain(&[("λ_{кр}", words[9], "deg")]);
    w.formula(&format!(
        "{} = {} > λ = {lambda}",
        sym("λ_{кр}"),
        deg(t.lock, lang)
    ));
    w.doc.say(w.word(T::FollowerLecture));
    w.worked(Worked::new(
        format!("op(\"tg\") {}", sym("λ_{кр}")),
        frac("2 L", "f d"),
        frac(&format!("2 dot {arm}"), &format!("{f} dot {d}")),
        Printed::plain(t.lock_lecture.tan(), 4, lang),
    ));
    w.formula(&format!(
        "{} = {}",
        sym("λ_{кр}"),
        deg(t.lock_lecture, lang)
    ));
}
