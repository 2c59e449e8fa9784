//! The φ axis of a cam diagram marked as the textbook marks it (issue 45): a tick across it
//! at every phase boundary, the number of every division point at its foot — under the axis
//! where the diagram stands above it there, over it where the diagram runs below; where a
//! steep curve crosses the axis at a point and would strike its number wherever it stands,
//! the crossing itself marks the point — and, over
//! the displacement diagram, the phases dimensioned between extension lines from the
//! curve's points at their boundaries. The phases' dimensions are labelled with the Russian
//! textbooks' symbols; the sheet writes each in its language with its angle
//! ([`PHASE_NOTES`] finds them).

use crate::cam::motion::Point;
use crate::cam::CamSpec;
use crate::construct::{number_box, Item, Recorder, Role, Step, DIGIT_MM, HALF_BOX_MM};
use crate::construct::{NUMBER_CLEAR_MM, NUMBER_SIDE_MM};
use crate::geom::{DVec2, Segment};
use crate::scale::Scale;

/// The notes of the four phases' dimensions on the displacement diagram: rise, far dwell,
/// return, near dwell.
pub const PHASE_NOTES: [&str; 4] = [
    "phase of the rise on the φ axis",
    "phase of the far dwell on the φ axis",
    "phase of the return on the φ axis",
    "phase of the near dwell on the φ axis",
];
/// The note of a phase boundary's tick.
pub const TICK_NOTE: &str = "phase boundary on the φ axis";

/// The phases' symbols in the Russian textbooks' markup (the sheet writes its language's).
const PHASE_SYMBOLS: [&str; 4] = ["φ_{у}", "φ_{д.в.}", "φ_{п}", "φ_{б.в.}"];
/// A boundary's tick reaches this far each side of the axis, mm: short of the outer row of
/// numbers.
const TICK_MM: f64 = 2.5;
/// Two numbers side by side keep this much clear between them, mm (the placer's clearance
/// and a gap). Points nearer than their numbers' half widths and this are numbered in two
/// rows, every other one a row further from the axis ([`ROW_MM`]); nearer than half of it,
/// every k-th point of a phase is numbered, its first and last always.
const NUMBER_GAP_MM: f64 = 1.2;
/// A number's middle stands this far from the axis in the first row, mm: half its box and a
/// millimetre's gap.
const NUMBER_DROP_MM: f64 = HALF_BOX_MM + 1.0;
/// The second row of numbers stands this much further from the axis, mm: a box and a gap.
/// A phase's first and last numbers stand in it, clear of the boundary's tick.
const ROW_MM: f64 = 5.6;
/// The numbers reach this far from the axis, mm: the second row's middle and half a box.
pub(super) const NUMBERS_MM: f64 = NUMBER_DROP_MM + ROW_MM + HALF_BOX_MM;
/// A number stands at most this far from its place, sheet mm: at its point, not flown off
/// above the curve where the diagram's lines crowd (the placer's limit).
const NUMBER_REACH_MM: f64 = 1.5;
/// A number's middle stands at least this far across from its point where it must, sheet
/// mm, and at most [`NUMBER_SIDE_MM`]: on each side as far as keeps it [`NUMBER_CLEAR_MM`]
/// nearer its point than the next point's on that side (they stand 4 mm apart and more), so
/// that a number the curve or a construction line crosses stands clear of it beside its
/// point, not beside the next one (the first number of an axis clear of the ordinate axis).
const NUMBER_COLUMN_MM: f64 = 1.0;
/// A number beside a crossing of its axis stands at least this clear of the curve there, mm:
/// nearer, the curve strikes it.
const CROSSING_CLEAR_MM: f64 = 0.2;
/// The places of a number in its column tried for [`CROSSING_CLEAR_MM`], this far apart, mm.
const COLUMN_STEP_MM: f64 = 0.1;
/// The phases' dimension line lies this far over the displacement diagram's top, mm: under
/// the tip of its ordinate axis (12 mm over it), which is the first phase's extension line,
/// and under the axis's name.
const PHASE_LINE_MM: f64 = 8.0;
/// An extension line runs this far past its dimension line, mm (ГОСТ 2.307: 1…5).
const PAST_LINE_MM: f64 = 2.0;
/// A phase drawn shorter than this has no room for its text between its arrows, mm: its
/// dimension line lies [`TIER_MM`] higher, its text written past an arrow on the line's
/// extension, nearer its own line than the neighbours' and clear of their texts.
const SHORT_PHASE_MM: f64 = 32.0;
/// The second tier's height over the first, mm.
const TIER_MM: f64 = 8.0;

/// Mark the φ axis of one diagram: the ticks, the numbers of `points` (each on the side of
/// the axis away from the diagram's `values` there — a phase's end by its neighbour's — SI
/// at the recorder's μ) and, with
/// `phases`, the phases' dimensions over the diagram.
pub(super) fn mark(
    rec: &mut Recorder,
    spec: &CamSpec,
    points: &[Point],
    phi: Scale,
    values: &[f64],
    phases: bool,
) {
    let st = spec.starts();
    for (k, at) in st.iter().enumerate() {
        // A boundary of no phase (two equal starts) is ticked once.
        if k > 0 && (at - st[k - 1]).abs() <= 0.0 {
            continue;
        }
        let x = phi.to_mm(*at);
        rec.draw(
            TICK_NOTE,
            Item::Segment(Segment::new(
                DVec2::new(x, -TICK_MM),
                DVec2::new(x, TICK_MM),
            )),
            Role::Construction,
            &[],
        );
    }
    let numbers = numbered(points, phi);
    let xs: Vec<f64> = numbers
        .iter()
        .map(|&(i, _)| phi.to_mm(points[i].phi))
        .collect();
    for (n, &(i, row)) in numbers.iter().enumerate() {
        let p = &points[i];
        // A phase's end stands where its diagram meets the axis (dS/dφ = 0 there): its
        // number on the side of its phase's, by its neighbour in the phase.
        let by = match (p.k == 0, p.last) {
            (true, false) => i + 1,
            (false, true) => i.saturating_sub(1),
            _ => i,
        };
        let side = if values.get(by).is_none_or(|v| *v >= 0.0) {
            -1.0
        } else {
            1.0
        };
        let at = DVec2::new(
            phi.to_mm(p.phi),
            side * (NUMBER_DROP_MM + ROW_MM * row as f64),
        );
        // Where the curve crosses the axis at the point, the number is first tried in the
        // quadrant it leaves clear.
        let clear = crossing_side(values, i, side);
        // Each side as far as keeps it nearer its point than the neighbour's on that side (at
        // a crossing half as clear of the middle: the curve through its tick names its point).
        let side_room = |next: Option<&f64>| {
            next.map_or(NUMBER_SIDE_MM, |x| {
                (x - xs[n]).abs() * 0.5 - NUMBER_CLEAR_MM * (1.0 - clear.abs() * 0.5)
            })
            .clamp(NUMBER_COLUMN_MM, NUMBER_SIDE_MM)
        };
        let column = [
            side_room(n.checked_sub(1).and_then(|k| xs.get(k))),
            side_room(xs.get(n + 1)),
        ];
        // At a crossing, where the curve leaves it room.
        let column = if clear == 0.0 {
            Some(column)
        } else {
            clear_column(rec.steps(), at, &p.label, column)
        };
        let Some(column) = column else {
            // A steep curve would strike the number wherever its column lets it stand, and
            // beside it the number reads as the next point's: the point is marked by the
            // curve's crossing itself, as an every-k-th numbering leaves points unnumbered.
            continue;
        };
        let id = rec.draw(
            format!("number of point {} on the φ axis", p.label),
            Item::Text(at),
            Role::Dimension,
            &[],
        );
        // Centred at its place (the first the placer tries), kept there.
        rec.label(id, p.label.clone(), at, DVec2::new(clear, 0.0));
        rec.keep_label_within(id, NUMBER_REACH_MM);
        rec.keep_label_in_column(id, column);
    }
    if phases {
        dimension_phases(rec, spec, points, phi, values);
    }
}

/// Where the curve crosses the axis at point `i` (its neighbours' `values` of opposite signs:
/// the sine law's d²S at the middle of its phase), the side of the point (−1 left, +1 right)
/// whose quadrant on the number's `side` of the axis the curve leaves clear — away from the
/// neighbour whose diagram stands there; elsewhere 0.
fn crossing_side(values: &[f64], i: usize, side: f64) -> f64 {
    let before = i.checked_sub(1).and_then(|k| values.get(k));
    match (before, values.get(i + 1)) {
        (Some(b), Some(a)) if b * a < 0.0 => {
            if a * side > 0.0 {
                -1.0
            } else {
                1.0
            }
        }
        _ => 0.0,
    }
}

/// The places in its column where a main line of `steps` (the diagram's curve, given or
/// constructed) passes clear of the box of the number `label` written at `at`, grown by
/// [`CROSSING_CLEAR_MM`]: the run of its middle's offsets from `at` (figure mm, in
/// [`COLUMN_STEP_MM`]) nearest `at` within `column` (mm left and right), as the column's
/// bounds; `None` where the curve strikes it everywhere.
fn clear_column(steps: &[Step], at: DVec2, label: &str, column: [f64; 2]) -> Option<[f64; 2]> {
    let mut lines = Vec::new();
    for s in steps
        .iter()
        .filter(|s| matches!(s.role, Role::Given | Role::Result))
    {
        if matches!(s.item, Item::Polyline { .. } | Item::Curve { .. }) {
            s.item.straight_pieces(|a, b| lines.push((a, b)));
        }
    }
    let clear = |x: f64| {
        let then = number_box(at + DVec2::new(x, 0.0), label, CROSSING_CLEAR_MM);
        !(lines.iter()).any(|&(a, b)| then.segment_inside(a, b).is_some())
    };
    let count = ((column[0] + column[1]) / COLUMN_STEP_MM).ceil() as usize;
    let places: Vec<(f64, bool)> = (0..=count)
        .map(|k| (-column[0] + k as f64 * COLUMN_STEP_MM).min(column[1]))
        .map(|x| (x, clear(x)))
        .collect();
    // The clear place nearest the point, and the run of clear places about it.
    let n = (0..places.len())
        .filter(|&k| places[k].1)
        .min_by(|&a, &b| places[a].0.abs().total_cmp(&places[b].0.abs()))?;
    let lo = (0..=n)
        .rev()
        .take_while(|&k| places[k].1)
        .last()
        .unwrap_or(n);
    let hi = (n..places.len())
        .take_while(|&k| places[k].1)
        .last()
        .unwrap_or(n);
    Some([-places[lo].0, places[hi].0])
}

/// The phases dimensioned over the displacement diagram: an extension line up from the
/// curve's point at every boundary (the drawn S of the phase's end there; at φ = 0 the
/// ordinate axis), the phase's dimension between two of them, a short phase's a tier
/// higher.
fn dimension_phases(
    rec: &mut Recorder,
    spec: &CamSpec,
    points: &[Point],
    phi: Scale,
    values: &[f64],
) {
    let st = spec.starts();
    let mu = rec.scale();
    let y = |i: Option<usize>| i.and_then(|i| values.get(i)).map_or(0.0, |v| mu.to_mm(*v));
    let end = |phase: usize, last: bool| {
        points
            .iter()
            .position(|p| p.phase == phase && if last { p.last } else { p.k == 0 })
    };
    // The curve at the boundaries: the rise's start and end, the return's, the cycle's end.
    let feet = [
        y(end(0, false)),
        y(end(0, true)),
        y(end(2, false)),
        y(end(2, true)),
        y(end(0, false)),
    ];
    let top = values.iter().map(|v| mu.to_mm(*v)).fold(0.0f64, f64::max);
    let line = top + PHASE_LINE_MM;
    let lengths: Vec<f64> = (0..4)
        .map(|k| phi.to_mm(st[k + 1]) - phi.to_mm(st[k]))
        .collect();
    let level = |k: usize| {
        if lengths[k] < SHORT_PHASE_MM {
            line + TIER_MM
        } else {
            line
        }
    };
    for (b, foot) in feet.iter().enumerate() {
        // As high as the higher of the two phases it bounds.
        let reach = [b.checked_sub(1), (b < 4).then_some(b)]
            .into_iter()
            .flatten()
            .filter(|&k| lengths[k] > 0.0)
            .map(level)
            .fold(f64::NEG_INFINITY, f64::max);
        let x = phi.to_mm(st[b]);
        // At φ = 0 the ordinate axis itself.
        if reach.is_finite() && x > 0.0 {
            rec.draw(
                "extension line of a phase boundary",
                Item::Segment(Segment::new(
                    DVec2::new(x, *foot + 1.0),
                    DVec2::new(x, reach + PAST_LINE_MM),
                )),
                Role::Dimension,
                &[],
            );
        }
    }
    for (k, note) in PHASE_NOTES.iter().enumerate() {
        if lengths[k] <= 0.0 {
            continue;
        }
        let h = level(k);
        let (x0, x1) = (phi.to_mm(st[k]), phi.to_mm(st[k + 1]));
        rec.dimension(
            *note,
            (DVec2::new(x0, h), DVec2::new(x1, h), 0.0),
            PHASE_SYMBOLS[k],
        );
    }
}

/// How far apart the numbers `a` and `b` must stand side by side in one row, mm.
fn pitch(a: &str, b: &str) -> f64 {
    let digits = (a.chars().count() + b.chars().count()) as f64;
    0.5 * DIGIT_MM * digits + NUMBER_GAP_MM
}

/// Whether neighbouring points `step_mm` apart on the φ axis each get their numbers `a`
/// and `b`, alternating between the two rows.
pub(super) fn numbers_fit(step_mm: f64, a: &str, b: &str) -> bool {
    step_mm >= 0.5 * pitch(a, b)
}

/// The points whose numbers are written, each with its row (0 at the axis, 1 further): the
/// phase's first and last in the second row (clear of the boundary's tick), the others in the
/// first where their numbers stand clear side by side ([`DIGIT_MM`], [`NUMBER_GAP_MM`]),
/// else alternating between the rows from
/// the first row beside each end (a number in the second row beside the last is left out);
/// nearer than half the pitch, every k-th point of a phase is numbered, its ends always (the
/// return's first unless it stands that near the rise's last).
fn numbered(points: &[Point], phi: Scale) -> Vec<(usize, usize)> {
    let x = |i: usize| phi.to_mm(points[i].phi);
    let one_row = |i: usize, j: usize| pitch(&points[i].label, &points[j].label);
    // Point `i` after `j` keeps its number, the two alternating between the rows.
    let fits = |i: usize, j: usize| numbers_fit(x(i) - x(j), &points[i].label, &points[j].label);
    let mut out: Vec<(usize, usize)> = Vec::with_capacity(points.len());
    for phase in [0usize, 2] {
        let idx: Vec<usize> = (0..points.len())
            .filter(|&i| points[i].phase == phase)
            .collect();
        // The return's first point is the rise's last one's neighbour across the far dwell.
        let before = out.last().map(|&(i, _)| i);
        let mut kept: Vec<usize> = before.into_iter().collect();
        for &i in &idx {
            match kept.last() {
                Some(&j) if !fits(i, j) => {}
                _ => kept.push(i),
            }
        }
        // The phase's last point is numbered: the ones too near before it give way.
        if let Some(&last) = idx.last() {
            let first = kept.first().copied();
            kept.retain(|&j| Some(j) == first || fits(last, j));
            if kept.last() != Some(&last) {
                kept.push(last);
            }
        }
        kept.retain(|i| points[*i].phase == phase);
        let crowded = kept
            .windows(2)
            .any(|w| x(w[1]) - x(w[0]) < one_row(w[0], w[1]));
        let m = kept.len().saturating_sub(1);
        let row = |k: usize| match (k == 0 || k == m, crowded) {
            (true, _) => 1,
            (false, false) => 0,
            (false, true) => (k + 1) % 2,
        };
        for (k, &i) in kept.iter().enumerate() {
            // Beside the last (in the second row too) it would crowd it.
            if crowded && k + 1 == m && row(k) == 1 {
                continue;
            }
            out.push((i, row(k)));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::crossing_side;

    /// The sine law's d²S crosses the axis at the middle of its phase: falling through it (+
    /// before, − after) it leaves clear the quadrant below left and above right; rising, below
    /// right and above left. A number off a crossing is tried at its point.
    #[test]
    fn a_number_where_the_curve_crosses_is_tried_in_the_quadrant_left_clear() {
        let falling = [0.17, 0.0, -0.17];
        assert_eq!(crossing_side(&falling, 1, -1.0), -1.0);
        assert_eq!(crossing_side(&falling, 1, 1.0), 1.0);
        let rising = [-0.17, -0.0, 0.17];
        assert_eq!(crossing_side(&rising, 1, -1.0), 1.0);
        assert_eq!(crossing_side(&rising, 1, 1.0), -1.0);
        assert_eq!(crossing_side(&[0.1, 0.17, 0.1], 1, -1.0), 0.0);
        assert_eq!(crossing_side(&[0.0, 0.1, 0.17], 1, -1.0), 0.0);
        assert_eq!(crossing_side(&falling, 0, -1.0), 0.0);
    }
}
