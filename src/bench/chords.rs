//! The chord-method sweep: a coordinate of a mechanism charted over one crank turn,
//! differentiated twice by chords and compared with its analytic analogues.

use super::BenchRow;
use super::{best_time, BenchError, Reps, Subject, CHORD_RESOLUTIONS, DIAGRAM_EXTENT_MM};
use crate::calculus::{
    derivative_scale, pole_for, CalculusError, Derivation, Derivative, Diagram, DiagramLayout,
    Scales,
};
use crate::construct::{Context, Drafting, Recorder};
use crate::geom::{wrap_pi, DVec2};
use crate::linkage::Pose;
use crate::scale::{Quantity, Scale};
use std::f64::consts::TAU;
use std::hint::black_box;

/// What the chord method charts: a coordinate of the mechanism with its two analogues.
pub(super) struct Charted {
    /// Quantity names of the first and second derivative (`v_S5`, `a_S5`).
    pub(super) names: [&'static str; 2],
    /// Their units.
    pub(super) units: [&'static str; 2],
    /// Ordinate scales' quantities: the coordinate, its analogues.
    pub(super) quantity: Quantity,
    /// The coordinate.
    pub(super) coord: Coord,
}

/// A coordinate of the mechanism.
#[derive(Debug, Clone, Copy)]
pub(super) enum Coord {
    /// The x coordinate of a point (program index).
    PointX(usize),
    /// The frame angle of a link.
    LinkAngle(usize),
}

impl Coord {
    /// Value, first and second analogue w.r.t. the crank angle at a pose.
    fn read(self, p: &Pose) -> [f64; 3] {
        match self {
            Coord::PointX(k) => [p.p[k].x, p.dp[k].x, p.ddp[k].x],
            Coord::LinkAngle(l) => [p.angle(l), p.dangle[l], p.ddangle[l]],
        }
    }
}

/// Differentiate `src` by chords at the textbook pole (steepest ray 40 mm up), recorder at
/// the derivative's scale in `ctx`.
fn chords_once(
    src: &Diagram,
    scales: Scales,
    q: Quantity,
    ctx: &Context,
) -> Result<Derivative, CalculusError> {
    let pole = pole_for(src, scales, 40.0)?;
    let mu = derivative_scale(scales.y, scales.x, pole, q)?;
    let mut rec = Recorder::in_context("bench", mu, ctx);
    let layout = DiagramLayout::new(DVec2::new(0.0, 150.0), DVec2::ZERO);
    Derivation::Chords.differentiate(&mut rec, src, scales, pole, &layout)
}

/// Both differentiations of one diagram.
fn chords_twice(
    src: &Diagram,
    (mu_x, mu_y): (Scale, Scale),
    q: Quantity,
    ctx: &Context,
) -> Result<(Derivative, Derivative), CalculusError> {
    let d1 = chords_once(src, Scales { x: mu_x, y: mu_y }, q, ctx)?;
    let d2 = chords_once(
        &d1.diagram()?,
        Scales {
            x: mu_x,
            y: d1.scale,
        },
        q,
        ctx,
    )?;
    Ok((d1, d2))
}

/// Max and mean |got − want|.
fn errors(got: &[f64], want: &[f64]) -> (f64, f64) {
    let n = got.len().min(want.len());
    if n == 0 || got.len() != want.len() {
        return (f64::NAN, f64::NAN);
    }
    let e = got.iter().zip(want).map(|(g, w)| (g - w).abs());
    let (max, sum) = e.fold((0.0f64, 0.0), |(m, s), x| (m.max(x), s + x));
    (max, sum / n as f64)
}

/// The chord-method rows of one charted coordinate at every resolution.
pub(super) fn chord_rows(
    s: &Subject,
    c: &Charted,
    reps: Reps,
) -> Result<Vec<BenchRow>, BenchError> {
    let ctx = Context::for_model_size(DIAGRAM_EXTENT_MM, Drafting::EXACT)?;
    let mut rows = Vec::new();
    let w = s.w1.abs();
    for n in CHORD_RESOLUTIONS {
        let calc = |source| BenchError::Calculus {
            scene: s.scene.stem.clone(),
            n,
            source,
        };
        let jets: Vec<[f64; 3]> = s.poses(n)?.iter().map(|p| c.coord.read(p)).collect();
        // The chart: the coordinate from its value at node 0, against the angle turned
        // (an angle unwrapped step by step).
        let mut y = Vec::with_capacity(n);
        for (k, j) in jets.iter().enumerate() {
            y.push(match (c.coord, k) {
                (_, 0) => 0.0,
                (Coord::LinkAngle(_), _) => y[k - 1] + wrap_pi(j[0] - jets[k - 1][0]),
                (Coord::PointX(_), _) => j[0] - jets[0][0],
            });
        }
        let src = Diagram::new(0.0, TAU / n as f64, y, true).map_err(calc)?;
        let span = src.y.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let mu_x = Scale::new(TAU / 180.0, Quantity::Angle);
        let mu_y = Scale::new(span.max(f64::MIN_POSITIVE) / 50.0, c.quantity);
        let (Some(mu_x), Some(mu_y)) = (mu_x, mu_y) else {
            return Err(calc(CalculusError::BadScale { value: span / 50.0 }));
        };
        let (d1, d2) = chords_twice(&src, (mu_x, mu_y), c.quantity, &ctx).map_err(calc)?;
        let time = best_time(reps.best_of, || {
            for _ in 0..reps.diagrams.max(1) {
                black_box(chords_twice(
                    black_box(&src),
                    (mu_x, mu_y),
                    c.quantity,
                    &ctx,
                )?);
            }
            Ok::<_, CalculusError>(())
        })
        .map_err(calc)?
            / reps.diagrams.max(1) as f64;
        // d/dt = |ω₁|·d/d(turned) and, for the analytic twin, d/dt = ω₁·d/dφ₁.
        let got = [
            d1.node.iter().map(|v| v * w).collect::<Vec<_>>(),
            d2.node.iter().map(|a| a * w * w).collect(),
        ];
        let want = [
            jets.iter().map(|j| j[1] * s.w1).collect::<Vec<_>>(),
            jets.iter().map(|j| j[2] * s.w1 * s.w1).collect(),
        ];
        for k in 0..2 {
            let (max_error, mean_error) = errors(&got[k], &want[k]);
            rows.push(BenchRow {
                method: format!("chord N={n}"),
                resolution: n as u32,
                quantity: c.names[k].into(),
                max_error,
                mean_error,
                time_s: time,
                unit: c.units[k].into(),
            });
        }
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_are_max_and_mean_or_nan_when_the_lengths_differ() {
        assert_eq!(errors(&[1.0, 2.0], &[1.5, 1.0]), (1.0, 0.75));
        assert!(errors(&[1.0], &[1.0, 2.0]).0.is_nan());
        assert!(errors(&[], &[]).1.is_nan());
    }
}
