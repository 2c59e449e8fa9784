//! The positions' numbers on a kinematic diagram's φ axis: under the displacement's (or ω's)
//! axis as on the plan of positions, and on each derivative's, where the pole's rays and the
//! chords' steps crowd the axis, at its node on whichever side the drawing leaves clear.

use crate::calculus::Diagram;
use crate::construct::{Item, Recorder, Role, Step, DIGIT_MM, HALF_BOX_MM};
use crate::geom::{curve, DVec2, Rect};
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
/// A number's middle stands at most this far beside its node, mm, and half an interval less
/// [`NUMBER_CLEAR_MM`] where the nodes stand nearer: nearer its own node than the next.
const NUMBER_SIDE_MM: f64 = 3.0;
/// See [`NUMBER_SIDE_MM`], mm.
const NUMBER_CLEAR_MM: f64 = 1.0;
/// The places beside its node tried for a number, this far apart, mm.
const COLUMN_STEP_MM: f64 = 0.25;
/// A number stands at most this far from the place found for it, mm (the placer's bound).
const NUMBER_REACH_MM: f64 = 0.5;
/// Chords of each piece of a smooth curve tried against a number's box.
const CURVE_CHORDS: usize = 8;

/// The positions' numbers at the φ axis at height `axis` (figure mm; at μ_φ `phi`) of a
/// diagram `src` charted at the `numbered` positions, or of one derived from it, as on the
/// plan of positions: each at its node, and the `extremes` between them (travel from
/// position 1, rad; label) at theirs — under the axis too where one stands clear of the
/// nodes, over it where it is too near one to stand beside it. On a derivative's axis
/// (`curve`: its ordinates at the nodes, physical units, non-empty), each number stands at
/// its node where no line of the drawing so far strikes it: on the side of the axis away from
/// the curve there, else on the other, beside the node within half an interval; struck
/// everywhere, where the least of the lines runs through it.
pub(super) fn number_phi_axis(
    rec: &mut Recorder,
    (src, numbered): (&Diagram, &[(usize, &crate::linkage::PlanPosition)]),
    extremes: &[(f64, &String)],
    (phi, axis, curve): (Scale, f64, &[f64]),
) {
    let nodes: Vec<f64> = (0..=numbered.len()).map(|idx| src.x(idx)).collect();
    let clear = |x: f64| (nodes.iter()).all(|n| phi.to_mm((x - n).abs()) >= AXIS_MARKS_APART_MM);
    let under = DVec2::new(0.0, -1.0);
    // Each mark: its abscissa, its number, whether it is an extreme's, the curve there.
    let marks = (numbered.iter().enumerate())
        .map(|(idx, (_, p))| (src.x(idx), &p.label, false, curve.get(idx)))
        .chain(extremes.iter().map(|&(x, label)| (x, label, true, None)));
    let column = (0.5 * phi.to_mm(src.dx) - NUMBER_CLEAR_MM).clamp(0.0, NUMBER_SIDE_MM);
    let lines = drawn_lines(rec.steps());
    let mut places = Vec::new();
    for (x, label, extreme, y) in marks {
        let at = DVec2::new(phi.to_mm(x), axis);
        let place = y.map(|y| {
            let away = if *y < 0.0 { 1.0 } else { -1.0 };
            let width = DIGIT_MM * label.chars().count() as f64;
            let middle = |side: f64, dx: f64, drop: f64| at + DVec2::new(dx, side * drop);
            // The first place no line strikes, else the one they strike least.
            let mut best: Option<(f64, DVec2)> = None;
            for m in (NUMBER_DROPS_MM.into_iter())
                .flat_map(|drop| [(away, drop), (-away, drop)])
                .flat_map(|(side, drop)| beside(column).map(move |dx| middle(side, dx, drop)))
            {
                let ink = ink_in(&lines, m, width);
                if best.is_none_or(|(b, _)| ink < b) {
                    best = Some((ink, m));
                }
                if ink == 0.0 {
                    break;
                }
            }
            best.map_or(middle(away, 0.0, NUMBER_DROPS_MM[0]), |(_, m)| m)
        });
        places.push((at, label, x, extreme, place));
    }
    for (at, label, x, extreme, place) in places {
        let note = match place {
            Some(_) => format!("position {label} on the derivative's φ axis"),
            None => format!("position {label} on the φ axis"),
        };
        let id = rec.draw(note, Item::Text(at), Role::Dimension, &[]);
        match place {
            // Centred at its place (the first the placer tries), kept there.
            Some(m) => {
                rec.label(id, label.clone(), m, DVec2::ZERO);
                rec.keep_label_within(id, NUMBER_REACH_MM);
                rec.keep_label_in_column(id, [NUMBER_REACH_MM; 2]);
            }
            None if !extreme || clear(x) => rec.label(id, label.clone(), at, under),
            None => rec.label(id, label.clone(), at, -under),
        }
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

/// The straight pieces of every line drawn on `steps` (segments, vectors, polylines, curves
/// as drawn), figure mm.
fn drawn_lines(steps: &[Step]) -> Vec<[DVec2; 2]> {
    let mut out = Vec::new();
    for s in steps {
        let points = match &s.item {
            Item::Segment(g) => vec![g.from, g.to],
            Item::Vector { from, to } => vec![*from, *to],
            Item::Polyline { points, closed } => {
                let mut p = points.clone();
                if *closed {
                    p.extend(points.first());
                }
                p
            }
            Item::Curve { points, closed } => curve::points(points, *closed, CURVE_CHORDS),
            _ => continue,
        };
        out.extend(points.windows(2).map(|w| [w[0], w[1]]));
    }
    out
}

/// How much of `lines` runs through the box of a number `width` mm wide centred at
/// `middle`, grown by [`LINE_CLEAR_MM`], mm.
fn ink_in(lines: &[[DVec2; 2]], middle: DVec2, width: f64) -> f64 {
    let half = DVec2::new(0.5 * width, HALF_BOX_MM) + LINE_CLEAR_MM;
    let then = Rect::new(middle - half, middle + half);
    lines
        .iter()
        .filter_map(|[a, b]| {
            then.segment_inside(*a, *b)
                .map(|(t0, t1)| (t1 - t0) * a.distance(*b))
        })
        .sum()
}
