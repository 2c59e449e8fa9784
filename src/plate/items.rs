//! Recorded steps as marks: the textbook symbols of every [`Item`], and the labels.

use super::arrow::{vector, vector_head, Arrow};
use super::dimension::extension_lines;
use super::path::{pieces, Map, PathData};
use super::style::{Mark, Paint, Pen};
use crate::construct::{Drafting, Item, Names, Role, Step};
use crate::geom::{Arc, DVec2, Segment, Side};
use std::borrow::Cow;
use std::f64::consts::TAU;

/// Label points closer than this on the sheet are one point: their labels are joined, mm —
/// the drafting resolution a length is read to (0,5 mm, [`Drafting::HAND`]): points that
/// far apart are drawn apart, and "≡" joins only points that coincide on the drawing (the
/// tangent's `p ≡ a ≡ k` over 3,2 and 1,6 mm, issue 45).
pub const COINCIDENT_MM: f64 = Drafting::HAND.resolution_mm();
/// Least distance from a label's anchor to its text's box, mm (from a revolute pair's
/// circle for a label of the pair).
pub const LABEL_GAP_MM: f64 = 1.0;
/// Radius of a revolute pair, mm.
pub const JOINT_RADIUS_MM: f64 = 1.5;
/// Length and spacing of hatch strokes along a guide, mm.
pub const HATCH_MM: f64 = 2.5;

/// The steps of a view in the order they are painted: the recorder's order, except that the
/// hinges (joints) come last, so that a link or a line drawn after its hinge stops at the
/// hinge's white circle as on the drawing board, instead of running to its centre. (A slider
/// block keeps its place: the friction pictures draw their forces across the block.) The
/// replay addresses steps by id, so the order is the painter's only.
pub(crate) fn hinges_last(steps: &[Step]) -> impl Iterator<Item = &Step> {
    let pair = |s: &&Step| matches!(s.item, Item::Joint { .. });
    steps
        .iter()
        .filter(move |s| !pair(s))
        .chain(steps.iter().filter(pair))
}

/// The marks of one step's item under `map` (its label is laid out with the plate's others,
/// see [`layout`](super::layout)).
pub(crate) fn step_marks(step: &Step, map: Map) -> Vec<Mark> {
    let mut out = Vec::new();
    for (item, role, labelled) in drawn_items(step) {
        item_marks(&item, (role, labelled), Pen::for_role(role), map, &mut out);
    }
    out
}

/// What a step draws, each with its role and whether it is labelled: its item, or a short
/// labelled vector's point ([`short_vector`]); and a short plan image's dot
/// ([`short_image_tip`]).
fn drawn_items(step: &Step) -> Vec<(Cow<'_, Item>, Role, bool)> {
    let mut out = vec![match short_vector(step) {
        Some(p) => (Cow::Owned(Item::Point(p)), step.role, true),
        None => (Cow::Borrowed(&step.item), step.role, step.label.is_some()),
    }];
    if let Some(tip) = short_image_tip(step) {
        out.push((Cow::Owned(Item::Point(tip)), Role::Construction, true));
    }
    out
}

/// The head of a labelled plan image (a label naming the point at its head) shorter than
/// its full arrowhead, where a construction's dot marks it too: its head alone does not show
/// where it ends (the tangent's `c`, 1,6 mm from the pole on a 3,2 mm `pa`, issue 45).
/// `None` for any other step, and for an image drawn as its tail ([`short_vector`]).
fn short_image_tip(step: &Step) -> Option<DVec2> {
    let Item::Vector { from, to } = step.item else {
        return None;
    };
    let length = from.distance(to);
    let head = Arrow::for_pen(Pen::for_role(step.role)).len;
    let image = step.label.as_ref()?.names == Names::Point;
    (image && length >= COINCIDENT_MM && length < head).then_some(to)
}

/// The tail of a labelled vector drawn as the point it is there. A plan's image (a label
/// naming the point at its head) that ends where it starts on the drawing — shorter than the
/// drafting resolution ([`COINCIDENT_MM`], 0,5 mm) — as the textbook writes `p ≡ b` (issue
/// 45); a longer one is a vector, its arrowhead fitted to its length ([`Arrow::fitted`]): its
/// head is another point, 1,6 mm from its tail is not `p ≡ a`. A force (a label naming its
/// item, never joined) shorter than its arrowhead, as the point it acts at: the polygon's
/// detail draws it to scale. An unlabelled vector is drawn as it is ([`vector_head`]).
/// `None` for any other step.
pub(crate) fn short_vector(step: &Step) -> Option<DVec2> {
    let Item::Vector { from, to } = step.item else {
        return None;
    };
    let shorter = match step.label.as_ref()?.names {
        Names::Point => COINCIDENT_MM,
        Names::Item => Arrow::for_pen(Pen::for_role(step.role)).len,
    };
    (from.distance(to) < shorter).then_some(from)
}

/// The outlines of what a step draws under `map` ([`drawn_items`]).
pub(crate) fn step_outlines(step: &Step, map: Map) -> Vec<Outline> {
    (drawn_items(step).into_iter())
        .flat_map(|(item, role, labelled)| item_outlines(&item, (role, labelled), map))
        .collect()
}

/// What a drawn item covers on the sheet, for laying labels out clear of it and for the
/// view's drawn bounds.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Shape {
    /// A stroke between two points.
    Line(DVec2, DVec2),
    /// A filled or opaque convex area (pair symbols, blocks, arrowheads, dots).
    Area(Vec<DVec2>),
}

/// A shape with the weight of its line: `main` for the ГОСТ main (thick) line.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Outline {
    /// The shape, sheet mm.
    pub shape: Shape,
    /// Drawn with the main line.
    pub main: bool,
}

/// The outlines of what `item` draws in `role` under `map`, following [`step_marks`]: the
/// same symbol sizes, curves and arcs as polylines (a vector's head as [`vector_head`]).
pub(crate) fn item_outlines(item: &Item, (role, labelled): (Role, bool), map: Map) -> Vec<Outline> {
    let main = Pen::for_role(role).is_main();
    let mut lines: Vec<(DVec2, DVec2)> = Vec::new();
    let mut areas: Vec<(Vec<DVec2>, bool)> = Vec::new();
    let chain = |pts: &[DVec2], closed: bool, lines: &mut Vec<(DVec2, DVec2)>| {
        lines.extend(pts.windows(2).map(|w| (w[0], w[1])));
        if closed && pts.len() > 2 {
            lines.push((pts[pts.len() - 1], pts[0]));
        }
    };
    match item {
        Item::Point(p) => areas.push((square(*p, dot_radius(role)), main)),
        Item::Joint { at, fixed } => {
            if *fixed {
                areas.push((support_outline(*at).to_vec(), true));
            }
            areas.push((square(*at, JOINT_RADIUS_MM), main));
        }
        Item::Segment(s) => lines.push((s.from, s.to)),
        Item::Circle(c) => {
            let full = Arc {
                center: c.center,
                radius: c.radius,
                start: 0.0,
                sweep: TAU,
            };
            chain(&arc_points(&full), true, &mut lines)
        }
        Item::Arc(a) => chain(&arc_points(a), false, &mut lines),
        Item::Polyline { points, closed } => chain(points, *closed, &mut lines),
        // As drawn (`smooth`): a curve bulges off its chords between sparse points (the
        // hodograph's twelve ends), where a label beside a chord would stand on the curve.
        Item::Curve { points, closed } if points.len() >= 3 => {
            let drawn = crate::geom::curve::points(points, *closed, BEZIER_CHORDS);
            chain(&drawn, false, &mut lines)
        }
        Item::Curve { points, closed } => chain(points, *closed, &mut lines),
        Item::Bezier {
            start,
            pieces,
            closed,
        } => chain(
            &crate::geom::bezier_points(*start, pieces, BEZIER_CHORDS),
            *closed,
            &mut lines,
        ),
        Item::Vector { from, to } => {
            lines.push((*from, *to));
            if let Some(u) = (*to - *from).try_normalize() {
                let (arrow, _) = vector_head(Pen::for_role(role), labelled, from.distance(*to));
                areas.push((arrow.corners(*to, u).to_vec(), main));
            }
        }
        Item::Slider { at, angle } => areas.push((slider_corners(*at, *angle).to_vec(), main)),
        Item::Guide { segment, hatch } => {
            lines.push((segment.from, segment.to));
            let lean = hatch_lean(segment, *hatch);
            areas.push((
                vec![
                    segment.from,
                    segment.to,
                    segment.to + lean,
                    segment.from + lean,
                ],
                false,
            ));
        }
        Item::Dimension { from, to, offset } => {
            let n = (*to - *from).normalize_or_zero().perp() * *offset;
            let (start, end, _) = dimension_line(*from + n, *to + n);
            lines.extend([(*from, *from + n), (*to, *to + n), (start, end)]);
        }
        Item::Angle(a) | Item::Moment(a) => chain(&arc_points(a), false, &mut lines),
        Item::Text(_) => {}
        Item::Hatching { .. } => lines.extend(item.hatch_strokes().iter().map(|s| (s.from, s.to))),
    }
    let lines = lines.into_iter().map(|(a, b)| Outline {
        shape: Shape::Line(map.pt(a), map.pt(b)),
        main,
    });
    let areas = areas.into_iter().map(|(pts, main)| Outline {
        shape: Shape::Area(pts.into_iter().map(|p| map.pt(p)).collect()),
        main,
    });
    lines.chain(areas).collect()
}

/// Radius of a marked point's dot: larger for given data and results, mm.
fn dot_radius(role: Role) -> f64 {
    if matches!(role, Role::Given | Role::Result) {
        0.6
    } else {
        0.4
    }
}

/// The square of half-side `r` about `c`.
fn square(c: DVec2, r: f64) -> Vec<DVec2> {
    [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
        .map(|(x, y)| c + DVec2::new(x, y) * r)
        .to_vec()
}

/// Points along an arc, at most 15° apart (nothing for a degenerate arc).
fn arc_points(a: &Arc) -> Vec<DVec2> {
    let sweep = a.sweep.clamp(-TAU, TAU);
    if !(a.radius.is_finite() && a.radius > 0.0 && sweep.is_finite() && a.start.is_finite()) {
        return Vec::new();
    }
    let n = pieces(sweep.abs(), TAU / 24.0).clamp(1, 24) + 1;
    let piece = Arc { sweep, ..*a };
    (0..=n).map(|i| piece.eval(i as f64 / n as f64)).collect()
}

/// Stroke whatever `build` draws with `pen`.
pub(super) fn stroke(map: Map, pen: Pen, build: impl FnOnce(&mut PathData)) -> Option<Mark> {
    paint(map, Paint::Stroke(pen), build)
}

fn paint(map: Map, paint: Paint, build: impl FnOnce(&mut PathData)) -> Option<Mark> {
    let mut d = PathData::new(map);
    build(&mut d);
    Mark::path(paint, d)
}

fn item_marks(
    item: &Item,
    (role, labelled): (Role, bool),
    pen: Pen,
    map: Map,
    out: &mut Vec<Mark>,
) {
    match item {
        Item::Point(p) => out.extend(paint(map, Paint::Solid, |d| {
            d.circle(*p, dot_radius(role));
        })),
        Item::Joint { at, fixed } => {
            if *fixed {
                ground_support(map, *at, out);
            }
            out.extend(paint(map, Paint::Opaque(pen), |d| {
                d.circle(*at, JOINT_RADIUS_MM);
            }));
        }
        Item::Segment(s) => out.extend(stroke(map, pen, |d| {
            d.segment(s.from, s.to);
        })),
        Item::Hatching { .. } => out.extend(stroke(map, pen, |d| {
            for s in item.hatch_strokes() {
                d.segment(s.from, s.to);
            }
        })),
        Item::Circle(c) => out.extend(stroke(map, pen, |d| {
            d.circle(c.center, c.radius);
        })),
        Item::Arc(a) => out.extend(stroke(map, pen, |d| {
            d.arc(a);
        })),
        Item::Polyline { points, closed } => out.extend(stroke(map, pen, |d| {
            if *closed {
                d.polygon(points);
            } else {
                d.polyline(points);
            }
        })),
        Item::Curve { points, closed } => {
            out.extend(stroke(map, pen, |d| smooth(d, points, *closed)))
        }
        Item::Bezier {
            start,
            pieces,
            closed,
        } => out.extend(stroke(map, pen, |d| {
            d.move_to(*start);
            for [c1, c2, to] in pieces {
                d.cubic_to(*c1, *c2, *to);
            }
            if *closed {
                d.close();
            }
        })),
        Item::Vector { from, to } => vector(map, (pen, labelled), *from, *to, out),
        Item::Slider { at, angle } => out.extend(slider(map, pen, *at, *angle)),
        Item::Guide { segment, hatch } => guide(map, pen, segment, *hatch, out),
        Item::Dimension { from, to, offset } => dimension(map, *from, *to, *offset, out),
        Item::Angle(a) => arc_mark(map, a, true, out),
        Item::Moment(a) => arc_mark(map, a, false, out),
        Item::Text(_) => {}
    }
}

/// Depth of the ground line of a fixed pivot under the joint's centre, and its half-length, mm.
const SUPPORT_MM: (f64, f64) = (6.0, 4.0);
/// Spacing (and depth) of the hatch strokes under a fixed pivot's ground line, mm.
const SUPPORT_HATCH_MM: f64 = 1.6;

/// The box of a fixed pivot's symbol under the joint at `at` (legs, ground line, hatching).
fn support_outline(at: DVec2) -> [DVec2; 4] {
    let (depth, half) = SUPPORT_MM;
    let (top, bottom) = (-JOINT_RADIUS_MM * 0.866, -depth - SUPPORT_HATCH_MM);
    [(-half, top), (half, top), (half, bottom), (-half, bottom)].map(|(x, y)| at + DVec2::new(x, y))
}

/// The ГОСТ 2.770 fixed pivot under a joint: two legs down to a ground line, hatched below.
fn ground_support(map: Map, at: DVec2, out: &mut Vec<Mark>) {
    let r = JOINT_RADIUS_MM;
    let (depth, half) = SUPPORT_MM;
    let leg = |sx: f64| {
        (
            at + DVec2::new(sx * r * 0.5, -r * 0.866),
            at + DVec2::new(sx * 2.5, -depth),
        )
    };
    out.extend(stroke(map, Pen::MAIN, |d| {
        for (a, b) in [leg(-1.0), leg(1.0)] {
            d.segment(a, b);
        }
        d.segment(
            at + DVec2::new(-half, -depth),
            at + DVec2::new(half, -depth),
        );
    }));
    out.extend(stroke(map, Pen::THIN, |d| {
        let step = SUPPORT_HATCH_MM;
        for k in 0..=pieces(2.0 * half - step, step) {
            let top = at + DVec2::new(-half + step + k as f64 * step, -depth);
            d.segment(top, top + DVec2::new(-step, -step));
        }
    }));
}

/// A slider block 10 × 6 mm, long side along `angle`, white inside.
fn slider(map: Map, pen: Pen, at: DVec2, angle: f64) -> Option<Mark> {
    paint(map, Paint::Opaque(pen), |d| {
        d.polygon(&slider_corners(at, angle));
    })
}

/// The corners of a slider block 10 × 6 mm centred at `at`, long side along `angle`.
fn slider_corners(at: DVec2, angle: f64) -> [DVec2; 4] {
    let (half_length, half_width) = Item::SLIDER_HALF_MM;
    let u = DVec2::from_angle(angle);
    let (v, u) = (u.perp() * half_width, u * half_length);
    [at - u - v, at + u - v, at + u + v, at - u + v]
}

/// A guide: the line and 45° hatch strokes on the `hatch` side.
fn guide(map: Map, pen: Pen, s: &Segment, hatch: Side, out: &mut Vec<Mark>) {
    out.extend(stroke(map, pen, |d| {
        d.segment(s.from, s.to);
    }));
    let Some(u) = (s.to - s.from).try_normalize() else {
        return;
    };
    let lean = hatch_lean(s, hatch);
    out.extend(stroke(map, Pen::THIN, |d| {
        for k in 0..pieces(s.length(), HATCH_MM) {
            let foot = s.from + u * (HATCH_MM * (k as f64 + 1.0));
            d.segment(foot, foot + lean);
        }
    }));
}

/// A hatch stroke of a guide: from its foot on the line, 45° back on the `hatch` side (zero
/// for a degenerate guide).
fn hatch_lean(s: &Segment, hatch: Side) -> DVec2 {
    let u = (s.to - s.from).normalize_or_zero();
    let n = match hatch {
        Side::Left => u.perp(),
        Side::Right => -u.perp(),
    };
    (n - u).normalize_or_zero() * HATCH_MM
}

/// A smooth curve through `pts`: a diagram's curve shape-preserving, others Catmull–Rom
/// (see [`curve`](super::curve)).
fn smooth(d: &mut PathData, pts: &[DVec2], closed: bool) {
    if pts.len() < 3 {
        d.polyline(pts);
        return;
    }
    d.move_to(pts[0]);
    for [c1, c2, to] in crate::geom::curve::pieces(pts, closed) {
        d.cubic_to(c1, c2, to);
    }
    if closed {
        d.close();
    }
}

/// Chords of each piece of a Bézier curve where the labels' placer reads it as lines.
const BEZIER_CHORDS: usize = 8;

/// Room a dimension line needs between its extension lines for its two arrows, mm.
const ARROWS_INSIDE_MM: f64 = 2.0 * Arrow::THIN.len + 1.0;
/// How far a short dimension's line runs past each extension line, mm: its arrow and a
/// little more.
const LINE_PAST_MM: f64 = Arrow::THIN.len + 2.0;

/// The dimension line of a dimension from `a` to `b` (on the line): its ends, and whether
/// its arrows stand inside, or — too short for them (ГОСТ 2.307: [ρ] = 5 мм drawn 2,5 mm
/// on the cusp) — outside, pointing in, the line run past each extension line.
fn dimension_line(a: DVec2, b: DVec2) -> (DVec2, DVec2, bool) {
    let u = (b - a).normalize_or_zero();
    if a.distance(b) >= ARROWS_INSIDE_MM {
        (a, b, true)
    } else {
        (a - u * LINE_PAST_MM, b + u * LINE_PAST_MM, false)
    }
}

/// A linear dimension: extension lines, the dimension line with arrows at both ends.
fn dimension(map: Map, from: DVec2, to: DVec2, offset: f64, out: &mut Vec<Mark>) {
    let Some(u) = (to - from).try_normalize() else {
        return;
    };
    let n = u.perp();
    let (a, b) = (from + n * offset, to + n * offset);
    let (start, end, inside) = dimension_line(a, b);
    out.extend(stroke(map, Pen::THIN, |d| {
        for (p, q) in extension_lines(from, to, offset) {
            d.segment(p, q);
        }
        d.segment(start, end);
    }));
    let out_of = if inside { 1.0 } else { -1.0 };
    out.extend(Arrow::THIN.head(map, a, -u * out_of));
    out.extend(Arrow::THIN.head(map, b, u * out_of));
}

/// An angle mark: the thin arc with an arrowhead at each end, following the arc.
/// A thin arc with an arrowhead at its end, and at its start too when `both` (an angle's
/// dimension; a moment's arc has one, its sense).
fn arc_mark(map: Map, a: &Arc, both: bool, out: &mut Vec<Mark>) {
    out.extend(stroke(map, Pen::THIN, |d| {
        d.arc(a);
    }));
    if !(a.radius > 0.0 && a.sweep.is_finite() && a.sweep != 0.0) {
        return;
    }
    let arrow = Arrow::THIN;
    // The head points along the chord from the point one arrow length back on the arc.
    let back = (arrow.len / a.radius).min(a.sweep.abs() * 0.5) * a.sweep.signum();
    let at = |angle: f64| a.center + DVec2::from_angle(angle) * a.radius;
    let (start, end) = (a.start, a.start + a.sweep);
    out.extend(arrow.head(map, at(end), at(end) - at(end - back)));
    if both {
        out.extend(arrow.head(map, at(start), at(start) - at(start + back)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A moment's arc shows its sense by one arrowhead, at its end; an angle's dimension has
    /// one at each end (issue 45: the couples on the force sheets had both, and no sense).
    #[test]
    fn a_moment_has_one_arrowhead_and_an_angle_two() {
        let arc = Arc {
            center: DVec2::ZERO,
            radius: 9.0,
            start: 0.3,
            sweep: 1.6,
        };
        let heads = |item: Item| {
            let mut out = Vec::new();
            item_marks(&item, (Role::Result, true), Pen::THIN, Map::SHEET, &mut out);
            out.iter()
                .filter(|m| matches!(m, Mark::Path(Paint::Solid, _)))
                .count()
        };
        assert_eq!(heads(Item::Moment(arc)), 1);
        assert_eq!(heads(Item::Angle(arc)), 2);
    }

    /// A smooth curve through sparse points is read by the labels' placer as drawn, not as
    /// its chords (issue 45: the six-bar's hodograph bulged off the chord at its end 8, and
    /// the «8» placed clear of the chord stood on the curve).
    #[test]
    fn a_curve_is_read_as_drawn() {
        let points = vec![DVec2::ZERO, DVec2::new(10.0, 10.0), DVec2::new(20.0, 0.0)];
        let drawn = crate::geom::curve::points(&points, false, BEZIER_CHORDS);
        let curve = Item::Curve {
            points,
            closed: false,
        };
        let read = item_outlines(&curve, (Role::Result, false), Map::SHEET);
        assert_eq!(read.len(), drawn.len() - 1);
        for (o, w) in read.iter().zip(drawn.windows(2)) {
            assert_eq!(o.shape, Shape::Line(w[0], w[1]));
        }
        let chord = crate::geom::Segment::new(DVec2::ZERO, DVec2::new(10.0, 10.0));
        assert!(drawn.iter().any(|p| chord.distance_to(*p) > 0.1));
    }

    #[test]
    fn a_short_dimension_has_its_arrows_outside() {
        let (a, b) = (DVec2::ZERO, DVec2::new(2.5, 0.0));
        let (start, end, inside) = dimension_line(a, b);
        assert!(!inside);
        assert!(
            (start.x + LINE_PAST_MM).abs() < 1e-12 && (end.x - 2.5 - LINE_PAST_MM).abs() < 1e-12
        );
        let long = DVec2::new(ARROWS_INSIDE_MM, 0.0);
        assert_eq!(dimension_line(a, long), (a, long, true));
    }
}
