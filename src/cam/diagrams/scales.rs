//! The diagrams' scales and poles: μ_φ, μ_S and the pole distances H₁, H₂ the student
//! chooses, the analogues' scales that follow from them, and μ_S found from the stroke when
//! the law's d²S/dφ² is integrated (seed 002 (4.2)).

use super::phi_axis::numbers_fit;
use crate::cam::motion::{motion_u, Point};
use crate::cam::{CamError, CamSpec};
use crate::scale::{Quantity, Scale};
use std::f64::consts::TAU;

/// Drawn length of the cycle on the diagrams' abscissa, mm (μ_φ = 2π / 240 mm = 1,5°/mm):
/// the diagrams' column takes about 300 mm of an A1 sheet's width.
const CYCLE_MM: f64 = 240.0;

/// The cycle's drawn length where [`CYCLE_MM`] would crowd the φ axis's numbers, mm
/// (μ_φ = 2π / 300 mm = 1,2°/mm): 12 divisions of a 60° phase stand 4,2 mm apart, room for
/// two two-digit numbers a row (3,7 mm), and the sheet's other views beside the diagrams.
const LONG_CYCLE_MM: f64 = 300.0;

/// Drawn stroke on the diagrams (at most, μ_S round), mm: the S diagram and the combined
/// diagram about a sixth of an A1 sheet's height.
const STROKE_MM: f64 = 100.0;

/// Drawn height of the analogues' peaks when the scene gives no poles, mm: the three
/// diagrams stacked fill an A1 sheet's height.
const PEAK_MM: f64 = 65.0;

/// An analogue's scale: μ_S′ in m/(rad·mm), μ_S″ in m/(rad²·mm), as the note works them
/// (the sheet wrote м/мм), named `what` in the error.
fn analogue(v: f64, quantity: Quantity, what: &'static str) -> Result<Scale, CamError> {
    Scale::new(v, quantity).ok_or(CamError::NoScale { what, size: v })
}

/// The scales and poles the diagrams are drawn at: μ_φ, μ_S (given, or round for the
/// stroke to take about [`STROKE_MM`]), H₁, H₂ (given or chosen), μ_S′ = μ_S/(H₂·μ_φ),
/// μ_S″ = μ_S′/(H₁·μ_φ). When d²S/dφ² is given and μ_S is not, these draw the law's shape,
/// and [`fitted`] gives the scales it is read at.
pub(super) fn scales(
    spec: &CamSpec,
    points: &[Point],
) -> Result<(Scale, [Scale; 3], [f64; 2]), CamError> {
    let phi = match spec.scale_phi {
        Some(s) => s,
        None => Scale::new(TAU / cycle_mm(points), Quantity::Angle).ok_or(CamError::NoScale {
            what: "μ_φ",
            size: TAU,
        })?,
    };
    let s_scale = match spec.scale_s {
        Some(s) => s,
        None => {
            Scale::round_for(spec.stroke, STROKE_MM, Quantity::Length).ok_or(CamError::NoScale {
                what: "μ_S",
                size: spec.stroke,
            })?
        }
    };
    let [h1, h2] = spec
        .poles
        .unwrap_or_else(|| chosen_poles(spec, s_scale, phi));
    let ds = s_scale.value() / (h2 * phi.value());
    let ds_scale = analogue(ds, Quantity::VelocityAnalogue, "μ_S′")?;
    let d2s = ds_scale.value() / (h1 * phi.value());
    let d2s_scale = analogue(d2s, Quantity::AccelerationAnalogue, "μ_S″")?;
    Ok((phi, [s_scale, ds_scale, d2s_scale], [h1, h2]))
}

/// The cycle's drawn length, mm: [`CYCLE_MM`], or [`LONG_CYCLE_MM`] where two neighbouring
/// points of a phase would stand too near there for their numbers on the φ axis, each
/// in its row ([`super::phi_axis::numbers_fit`]).
fn cycle_mm(points: &[Point]) -> f64 {
    let crowded = points.windows(2).any(|w| {
        let step = (w[1].phi - w[0].phi) / TAU * CYCLE_MM;
        w[0].phase == w[1].phase && !numbers_fit(step, &w[0].label, &w[1].label)
    });
    if crowded {
        LONG_CYCLE_MM
    } else {
        CYCLE_MM
    }
}

/// The largest |dS/dφ| and |d²S/dφ²| of the given law over the cycle (the tallest ordinates
/// the diagrams must hold): each moving phase at 200 intervals, both sides of every jump.
fn peaks(spec: &CamSpec) -> (f64, f64) {
    const PER_PHASE: usize = 200;
    let mut out = (0.0f64, 0.0f64);
    for (phase, law) in [(0usize, spec.rise), (2, spec.ret)] {
        let nodes = (0..=PER_PHASE).map(|k| (k as f64 / PER_PHASE as f64, k < PER_PHASE));
        let jumps = law
            .breaks()
            .into_iter()
            .flat_map(|b| [(b, false), (b, true)]);
        for (u, after) in nodes.chain(jumps) {
            let m = motion_u(spec, phase, u, after);
            out = (out.0.max(m.ds.abs()), out.1.max(m.d2s.abs()));
        }
    }
    out
}

/// The pole distances a student chooses: H₂ = μ_S/(μ_S′·μ_φ) and H₁ = μ_S′/(μ_S″·μ_φ) with
/// μ_S′, μ_S″ drawing the analogues' peaks about [`PEAK_MM`] tall, rounded to whole millimetres.
/// A law without acceleration (uniform) sets no μ_S″: H₁ is then H₂.
fn chosen_poles(spec: &CamSpec, s: Scale, phi: Scale) -> [f64; 2] {
    let (v, a) = peaks(spec);
    let h2 = (s.value() / (v.max(1e-12) / PEAK_MM * phi.value()))
        .round()
        .clamp(5.0, 200.0);
    let mu_v = s.value() / (h2 * phi.value());
    let h1 = if a > 1e-9 * v {
        (mu_v / (a / PEAK_MM * phi.value()))
            .round()
            .clamp(5.0, 200.0)
    } else {
        h2
    };
    [h1, h2]
}

/// The scales of diagrams integrated from the given d²S/dφ²'s shape drawn at `drawn`
/// (seed 002 (4.2), seed 000's μ_S = S_max/60 мм): μ_S = h / y_max, y_max the S diagram's
/// largest ordinate as read (`s_max_read` is the S it reads at the drawn μ_S), and μ_S′,
/// μ_S″ from it through the same poles — each the drawn one times k = h / S read, returned
/// with them. The S diagram then reaches the stroke exactly; the analogues carry what the
/// integration lost. `None` when nothing was read (no stroke).
pub(super) fn fitted(drawn: [Scale; 3], stroke: f64, s_max_read: f64) -> Option<(f64, [Scale; 3])> {
    let k = stroke / s_max_read;
    if !(k.is_finite() && k > 0.0) {
        return None;
    }
    let mut out = drawn;
    for (o, d) in out.iter_mut().zip(drawn) {
        *o = Scale::new(d.value() * k, d.quantity)?;
    }
    Some((k, out))
}
