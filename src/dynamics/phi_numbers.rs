//! The positions' numbers on the φ axes of the dynamic study's diagrams (issue 45): the
//! ordinates of A, ΔT, J_пр, T_I and ω stand at the positions the tables give, and each is
//! numbered at its foot as on the plan of positions — under the axis where its diagram
//! stands above it there, over it where the diagram runs below. The integrand M_с, whose
//! chords' mean ordinates stand between the positions, is numbered on the A diagram under
//! it, as its axis carries the pole and the projections of its near-zero ordinates.

use crate::construct::{Context, Figure, Item, Recorder, Role, HALF_BOX_MM};
use crate::geom::DVec2;

/// The note of the axes the numbers go on (`calculus::draw_axes`).
const AXIS_NOTE: &str = "abscissa axis φ";
/// The note of a chord method's pole, on the integrand's axis (`calculus::integrate`).
const POLE_NOTE: &str = "pole ";
/// A number's middle stands this far from the axis, mm: half its box at the labels' 4,8 mm
/// type and a millimetre's gap.
const DROP_MM: f64 = HALF_BOX_MM + 1.0;
/// A number stands at most this far from its place, mm: under the axis's construction lines
/// there (the chord method's near-zero projections), never flown into the diagram.
const REACH_MM: f64 = 4.0;

/// Number every φ axis of `figure` but an integrand's at `marks` (mm from the ordinate axis,
/// label): each number on the side away from the nearest curve there.
pub(super) fn number(figure: Figure, ctx: &Context, marks: &[(f64, String)]) -> Figure {
    let poles: Vec<f64> = (figure.steps.iter())
        .filter(|s| s.note.starts_with(POLE_NOTE))
        .filter_map(|s| match s.item {
            Item::Point(p) => Some(p.y),
            _ => None,
        })
        .collect();
    let axes: Vec<f64> = (figure.steps.iter())
        .filter(|s| s.note == AXIS_NOTE)
        .filter_map(|s| match s.item {
            Item::Vector { from, .. } => Some(from.y),
            _ => None,
        })
        .filter(|y| !poles.contains(y))
        .collect();
    let curves: Vec<Vec<DVec2>> = (figure.steps.iter())
        .filter(|s| matches!(s.role, Role::Result | Role::Given))
        .filter_map(|s| match &s.item {
            Item::Curve { points, .. } | Item::Polyline { points, .. } => Some(points.clone()),
            _ => None,
        })
        .collect();
    let mut rec = Recorder::resume(figure, ctx);
    for axis in axes {
        for (x, label) in marks {
            // The curve nearest the axis at x decides the side (none: under it).
            let y = (curves.iter())
                .filter_map(|c| at_x(c, *x))
                .min_by(|a, b| (a - axis).abs().total_cmp(&(b - axis).abs()));
            let side = if y.is_some_and(|y| y < axis) {
                1.0
            } else {
                -1.0
            };
            let at = DVec2::new(*x, axis + side * DROP_MM);
            let id = rec.draw(
                format!("position {label} on the φ axis"),
                Item::Text(at),
                Role::Dimension,
                &[],
            );
            rec.label(id, label.clone(), at, DVec2::ZERO);
            rec.keep_label_within(id, REACH_MM);
        }
    }
    rec.finish()
}

/// The ordinate of polyline `c` at abscissa `x`, where it reaches there.
fn at_x(c: &[DVec2], x: f64) -> Option<f64> {
    c.windows(2).find_map(|w| {
        let (a, b) = (w[0], w[1]);
        let (lo, hi) = (a.x.min(b.x), a.x.max(b.x));
        if x < lo - 1e-9 || x > hi + 1e-9 {
            return None;
        }
        let t = if hi - lo > 0.0 {
            (x - a.x) / (b.x - a.x)
        } else {
            0.0
        };
        Some(a.y + t * (b.y - a.y))
    })
}
