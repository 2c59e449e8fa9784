//! How much of a line or an area a label's box takes in, and how far a box stands from a
//! line: the measures the placer's costs are made of.

use super::Rect;
use super::{Outline, Shape};
use crate::geom::DVec2;

/// How much of the outline `o` lies inside `r`: mm of a line, mm² of an area.
pub(super) fn ink_inside(o: &Outline, r: &Rect) -> f64 {
    match &o.shape {
        Shape::Line(a, b) => clipped_length(*a, *b, r),
        Shape::Area(pts) => clipped_area(pts, r),
    }
}

/// The distance from `rect` to the nearest of the lines among `own`; `None` without lines.
pub(super) fn own_distance<'o>(
    own: impl IntoIterator<Item = &'o Outline>,
    rect: &Rect,
) -> Option<f64> {
    own.into_iter()
        .filter_map(|o| match o.shape {
            Shape::Line(a, b) => Some(rect_segment_distance(rect, a, b)),
            Shape::Area(_) => None,
        })
        .reduce(f64::min)
}

/// The distance from the box `r` to the segment `a`–`b`, mm (0 when they meet).
pub(super) fn rect_segment_distance(r: &Rect, a: DVec2, b: DVec2) -> f64 {
    if r.contains(&Rect::new(a, a)) || clipped_length(a, b, r) > 0.0 {
        return 0.0;
    }
    let to_rect = |p: DVec2| (p - p.clamp(r.min, r.max)).length();
    let segment = crate::geom::Segment::new(a, b);
    let to_segment = |p: DVec2| segment.distance_to(p);
    let corners = [
        r.min,
        r.max,
        DVec2::new(r.min.x, r.max.y),
        DVec2::new(r.max.x, r.min.y),
    ];
    corners
        .into_iter()
        .map(to_segment)
        .chain([to_rect(a), to_rect(b)])
        .fold(f64::INFINITY, f64::min)
}

/// Length of the segment `a`–`b` inside `r` (Liang–Barsky clipping).
pub(super) fn clipped_length(a: DVec2, b: DVec2, r: &Rect) -> f64 {
    match r.segment_inside(a, b) {
        Some((t0, t1)) if t1 > t0 => (t1 - t0) * (b - a).length(),
        _ => 0.0,
    }
}

/// Area of the convex polygon `pts` inside `r` (Sutherland–Hodgman clipping).
pub(super) fn clipped_area(pts: &[DVec2], r: &Rect) -> f64 {
    let mut poly = pts.to_vec();
    let edges: [(usize, f64, f64); 4] = [
        (0, r.min.x, 1.0),
        (0, r.max.x, -1.0),
        (1, r.min.y, 1.0),
        (1, r.max.y, -1.0),
    ];
    for (axis, at, sign) in edges {
        let inside = |p: DVec2| (p[axis] - at) * sign >= 0.0;
        let mut next = Vec::with_capacity(poly.len() + 2);
        for (i, &p) in poly.iter().enumerate() {
            let q = poly[(i + 1) % poly.len()];
            if inside(p) {
                next.push(p);
            }
            if inside(p) != inside(q) {
                let t = (at - p[axis]) / (q[axis] - p[axis]);
                next.push(p + (q - p) * t);
            }
        }
        poly = next;
        if poly.is_empty() {
            return 0.0;
        }
    }
    let twice: f64 = (0..poly.len())
        .map(|i| poly[i].perp_dot(poly[(i + 1) % poly.len()]))
        .sum();
    twice.abs() * 0.5
}
