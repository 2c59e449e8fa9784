//! The cam diagrams' scales in the note (seed 002 (4.1)–(4.4)): μ_φ from the cycle's base,
//! μ_S from the stroke and the S diagram's largest ordinate where the law's d²S/dφ² was
//! integrated, and the analogues' scales through the pole distances.

use super::markup::{frac, num, sym};
use super::worked::{Printed, Worked};
use super::Writer;
use crate::cam::{CamDiagrams, CamSpec};
use crate::words::{CaseMeaning as M, NoteText as T};
use std::f64::consts::TAU;

/// The unit of μ_S′: dS/dφ (m/rad) per mm of its diagram.
const VELOCITY_UNIT: &str = "m/(rad*mm)";
/// The unit of μ_S″: d²S/dφ² (m/rad²) per mm.
const ACCELERATION_UNIT: &str = "m/(rad^2*mm)";

/// μ_φ = 2π/L; μ_S = h/y_max when found from the stroke; μ_S′ = μ_S/(μ_φ·H₂);
/// μ_S″ = μ_S′/(μ_φ·H₁) — each with its numbers and its «где».
pub(super) fn scales(w: &mut Writer<'_, '_>, d: &CamDiagrams, spec: &CamSpec) {
    let lang = w.lang;
    let n = |x: f64| num(x, 4, lang);
    let (phi, [h1, h2]) = (d.phi.value(), d.poles);
    w.doc.say(w.word(T::CamScalesWorked));
    w.worked(Worked::new(
        sym("μ_{φ}"),
        frac("2 π", &sym("L")),
        frac(&num(TAU, 5, lang), &n(d.phi.to_mm(TAU))),
        Printed::si(phi, 4, "rad/mm", lang),
    ));
    w.explain(&[
        ("μ_{φ}", w.word(M::CamAngleScale), "rad/mm"),
        ("L", w.word(M::CycleBase), "mm"),
    ]);
    if let Some(y) = d.y_max {
        let h = spec.stroke_symbol();
        w.worked(Worked::new(
            sym("μ_{S}"),
            frac(&sym(h), &sym("y_{max}")),
            frac(&format!("{} dot 10^(-3)", n(spec.stroke * 1e3)), &n(y)),
            Printed::si(d.s_scale.value(), 4, "m/mm", lang),
        ));
        w.explain(&[
            ("μ_{S}", w.word(M::DisplacementScale), "m/mm"),
            (h, w.word(M::Stroke), "mm"),
            ("y_{max}", w.word(M::DiagramTop), "mm"),
        ]);
    }
    // μ_S′ through H₂, μ_S″ through H₁: each where its pole is drawn.
    let poled = [d.drawn_poles[1], d.drawn_poles[0]];
    for ((scale, value), of, pole, h, meaning, pole_meaning, si) in [
        (
            ("μ_{S′}", d.ds_scale.value()),
            ("μ_{S}", d.s_scale.value(), M::DisplacementScale, "m/mm"),
            "H_{2}",
            h2,
            M::VelocityAnalogueScale,
            M::PoleOfDisplacement,
            VELOCITY_UNIT,
        ),
        (
            ("μ_{S″}", d.d2s_scale.value()),
            (
                "μ_{S′}",
                d.ds_scale.value(),
                M::VelocityAnalogueScale,
                VELOCITY_UNIT,
            ),
            "H_{1}",
            h1,
            M::AccelerationAnalogueScale,
            M::PoleOfAnalogues,
            ACCELERATION_UNIT,
        ),
    ]
    .into_iter()
    .zip(poled)
    .filter_map(|(row, poled)| poled.then_some(row))
    {
        w.worked(Worked::new(
            sym(scale),
            frac(&sym(of.0), &format!("{} {}", sym("μ_{φ}"), sym(pole))),
            frac(&n(of.1), &format!("{} dot {}", n(phi), n(h))),
            Printed::si(value, 4, si, lang),
        ));
        w.explain(&[
            (scale, w.word(meaning), si),
            (of.0, w.word(of.2), of.3),
            (pole, w.word(pole_meaning), "mm"),
        ]);
    }
    if !d.drawn_poles[0] {
        w.doc.say(w.word(T::CamNoAccelerationPole));
    }
}
