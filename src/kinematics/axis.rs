//! The positions' numbers on a kinematic diagram's φ axis: under the displacement's (or ω's)
//! axis as on the plan of positions, and on each derivative's, where the pole's rays and the
//! chords' steps crowd the axis, at its node on whichever side the drawing leaves clear.

use crate::calculus::Diagram;
use crate::construct::{number_box, Item, Recorder, Role, HALF_BOX_MM};
use crate::construct::{NUMBER_CLEAR_MM, NUMBER_SIDE_MM};
use crate::geom::DVec2;
use crate::scale::Scale;

/// How far from a numbered position's mark an extreme's number on the φ axis must stand to
/// be written there, mm (about two digits' width).
const AXIS_MARKS_APART_MM: f64 = 5.0;
/// A number's middle on a derivative's axis stands this far from the axis, mm: half its box
/// at the labels' 4,8 mm type and a millimetre's gap; where the lines strike it on both
/// sides there, a little further out, short of reading as another row.
const NUMBER_DROPS_MM: [f64; 3] = [HALF_BOX_MM + 1.0, HALF_BOX_MM + 2.2, HALF_BOX_MM + 3.4];
/// A number stands this clear of every line of the drawing, mm.
const LINE_CLEAR_MM: f64 = 0.2;
/// The places beside its node tried for a number, this far apart, mm.
const COLUMN_STEP_MM: f64 = 0.25;
/// A number stands at most this far from the place found for it, mm (the placer's bound).
const NUMBER_REACH_MM: f64 = 0.5;

/// The positions' numbers under the φ axis (at μ_φ `phi`) of a diagram `src` charted at the
/// `numbered` positions, as on the plan of positions: each at its node, and the `extremes`
/// between them (travel from position 1, rad; label) at theirs — under the axis too where
/// one stands clear of the nodes, over it where it is too near one to stand beside it.
pub(super) fn number_phi_axis(
    rec: &mut Recorder,
    (src, numbered): (&Diagram, &[(usize, &crate::linkage::PlanPosition)]),
    extremes: &[(f64, &String)],
    phi: Scale,
) {
    let nodes: Vec<f64> = (0..=numbered.len()).map(|idx| src.x(idx)).collect();
    let clear = |x: f64| (nodes.iter()).all(|n| phi.to_mm((x - n).abs()) >= AXIS_MARKS_APART_MM);
    let under = DVec2::new(0.0, -1.0);
    let marks = (numbered.iter().enumerate())
        .map(|(idx, (_, p))| (src.x(idx), &p.label, under))
        .chain(
            (extremes.iter()).map(|&(x, label)| (x, label, if clear(x) { under } else { -under })),
        );
    for (x, label, toward) in marks {
        let at = DVec2::new(phi.to_mm(x), 0.0);
        let id = rec.draw(
            format!("position {label} on the φ axis"),
            Item::Text(at),
            Role::Dimension,
            &[],
        );
        rec.label(id, label.clone(), at, toward);
    }
}

/// The positions' numbers on the φ axis at height `axis` (figure mm; at μ_φ `phi`) of the
/// derivative of a diagram `src` charted at the `numbered` positions, whose pole's rays and
/// chords' steps crowd the axis (`curve`: the derivative's ordinates at the nodes, physical
/// units). Each number stands at its node where no line of the drawing so far strikes it: on
/// the side of the axis away from the curve there, else on the other, beside the node within
/// half an interval, a little further out; struck everywhere, where the least of the lines
/// runs through it. Kept there: a number flown off among the steps names no node.
pub(super) fn number_derivative_axis(
    rec: &mut Recorder,
    (src, numbered): (&Diagram, &[(usize, &crate::linkage::PlanPosition)]),
    (phi, axis, curve): (Scale, f64, &[f64]),
) {
    let column = (0.5 * phi.to_mm(src.dx) - NUMBER_CLEAR_MM).clamp(0.0, NUMBER_SIDE_MM);
    let mut lines = Vec::new();
    for s in rec.steps() {
        s.item.straight_pieces(|a, b| lines.push((a, b)));
    }
    for (idx, (_, p)) in numbered.iter().enumerate() {
        let label = &p.label;
        let at = DVec2::new(phi.to_mm(src.x(idx)), axis);
        let away = if curve.get(idx).is_some_and(|y| *y < 0.0) {
            1.0
        } else {
            -1.0
        };
        // The first place no line strikes, else the one they strike least.
        let mut best: Option<(f64, DVec2)> = None;
        for m in (NUMBER_DROPS_MM.into_iter())
            .flat_map(|drop| [away * drop, -away * drop])
            .flat_map(|drop| beside(column).map(move |dx| at + DVec2::new(dx, drop)))
        {
            let ink = ink_in(&lines, m, label);
            if best.is_none_or(|(b, _)| ink < b) {
                best = Some((ink, m));
            }
            if ink == 0.0 {
                break;
            }
        }
        let m = best.map_or(at + DVec2::new(0.0, away * NUMBER_DROPS_MM[0]), |(_, m)| m);
        let id = rec.draw(
            format!("position {label} on the derivative's φ axis"),
            Item::Text(at),
            Role::Dimension,
            &[],
        );
        // Centred at its place (the first the placer tries), kept there.
        rec.label(id, label.clone(), m, DVec2::ZERO);
        rec.keep_label_within(id, NUMBER_REACH_MM);
        rec.keep_label_in_column(id, [NUMBER_REACH_MM; 2]);
    }
}

/// Offsets beside a node out to `column` mm each way, the nearest first: 0, +s, −s, +2s, …
fn beside(column: f64) -> impl Iterator<Item = f64> {
    let steps = (column / COLUMN_STEP_MM).floor() as i32;
    (0..=2 * steps).map(|k| {
        let n = f64::from(k.div_euclid(2) + k.rem_euclid(2));
        let sign = if k % 2 == 1 { 1.0 } else { -1.0 };
        sign * n * COLUMN_STEP_MM
    })
}

/// How much of `lines` runs through the box of the number `label` centred at `middle`,
/// grown by [`LINE_CLEAR_MM`], mm.
fn ink_in(lines: &[(DVec2, DVec2)], middle: DVec2, label: &str) -> f64 {
    let then = number_box(middle, label, LINE_CLEAR_MM);
    lines
        .iter()
        .filter_map(|(a, b)| {
            then.segment_inside(*a, *b)
                .map(|(t0, t1)| (t1 - t0) * a.distance(*b))
        })
        .sum()
}
