//! Recorded steps as marks: the textbook symbols of every [`Item`], and the labels.

use super::path::{pieces, Map, PathData};
use super::style::{Mark, Paint, Pen};
use super::text::{Align, Placed};
use crate::construct::{Item, Label, Role, Step};
use crate::geom::{Arc, DVec2, Segment, Side};

/// ГОСТ 2.304 size of labels (height of capitals), mm.
pub const LABEL_HEIGHT_MM: f64 = 3.5;
/// Distance from a label's anchor to its text, mm.
pub const LABEL_GAP_MM: f64 = 2.5;
/// Radius of a revolute pair, mm.
pub const JOINT_RADIUS_MM: f64 = 1.5;
/// Length and spacing of hatch strokes along a guide, mm.
pub const HATCH_MM: f64 = 2.5;

/// An arrowhead: length along the line and full width at its base, mm.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Arrow {
    len: f64,
    width: f64,
}

impl Arrow {
    /// Arrowhead of a result vector (main line).
    const MAIN: Arrow = Arrow {
        len: 4.0,
        width: 1.2,
    };
    /// Arrowhead of thin lines: dimensions, angle marks, construction vectors.
    const THIN: Arrow = Arrow {
        len: 3.0,
        width: 0.9,
    };

    fn for_pen(pen: Pen) -> Arrow {
        if pen.is_main() {
            Arrow::MAIN
        } else {
            Arrow::THIN
        }
    }

    /// The filled head with its tip at `tip`, pointing along `dir` (any length); nothing for
    /// a zero direction.
    fn head(self, map: Map, tip: DVec2, dir: DVec2) -> Option<Mark> {
        let u = dir.try_normalize()?;
        let base = tip - u * self.len;
        let side = u.perp() * (self.width * 0.5);
        let mut d = PathData::new(map);
        d.polygon(&[tip, base + side, base - side]);
        Mark::path(Paint::Solid, d)
    }
}

/// All marks of one step under `map`: the item, then its label.
pub(crate) fn step_marks(step: &Step, map: Map) -> Vec<Mark> {
    let pen = Pen::for_role(step.role);
    let mut out = Vec::new();
    item_marks(&step.item, step.role, pen, map, &mut out);
    if let Some(label) = &step.label {
        let placed = match &step.item {
            Item::Dimension { from, to, offset } => {
                dimension_text(map, *from, *to, *offset, &label.text)
            }
            Item::Joint { .. } => Some(label_text(label, map, LABEL_GAP_MM + JOINT_RADIUS_MM)),
            _ => Some(label_text(label, map, LABEL_GAP_MM)),
        };
        out.extend(placed.map(Mark::Text));
    }
    out
}

/// Stroke whatever `build` draws with `pen`.
fn stroke(map: Map, pen: Pen, build: impl FnOnce(&mut PathData)) -> Option<Mark> {
    paint(map, Paint::Stroke(pen), build)
}

fn paint(map: Map, paint: Paint, build: impl FnOnce(&mut PathData)) -> Option<Mark> {
    let mut d = PathData::new(map);
    build(&mut d);
    Mark::path(paint, d)
}

fn item_marks(item: &Item, role: Role, pen: Pen, map: Map, out: &mut Vec<Mark>) {
    match item {
        Item::Point(p) => {
            let r = if matches!(role, Role::Given | Role::Result) {
                0.6
            } else {
                0.4
            };
            out.extend(paint(map, Paint::Solid, |d| {
                d.circle(*p, r);
            }));
        }
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
        Item::Vector { from, to } => vector(map, pen, *from, *to, out),
        Item::Slider { at, angle } => out.extend(slider(map, pen, *at, *angle)),
        Item::Guide { segment, hatch } => guide(map, pen, segment, *hatch, out),
        Item::Dimension { from, to, offset } => dimension(map, *from, *to, *offset, out),
        Item::Angle(a) => angle_mark(map, a, out),
        Item::Text(_) => {}
    }
}

/// A vector: the line stopped inside its arrowhead (so a thick line does not show past the
/// head's flanks), and the head.
fn vector(map: Map, pen: Pen, from: DVec2, to: DVec2, out: &mut Vec<Mark>) {
    let arrow = Arrow::for_pen(pen);
    let Some(u) = (to - from).try_normalize() else {
        return;
    };
    let stop = if from.distance(to) > arrow.len {
        to - u * (arrow.len * 0.85)
    } else {
        from
    };
    out.extend(stroke(map, pen, |d| {
        d.segment(from, stop);
    }));
    out.extend(arrow.head(map, to, u));
}

/// The ГОСТ 2.770 fixed pivot under a joint: two legs down to a ground line, hatched below.
fn ground_support(map: Map, at: DVec2, out: &mut Vec<Mark>) {
    let r = JOINT_RADIUS_MM;
    let (depth, half) = (6.0, 4.0);
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
        let step = 1.6;
        for k in 0..=pieces(2.0 * half - step, step) {
            let top = at + DVec2::new(-half + step + k as f64 * step, -depth);
            d.segment(top, top + DVec2::new(-step, -step));
        }
    }));
}

/// A slider block 10 × 6 mm, long side along `angle`, white inside.
fn slider(map: Map, pen: Pen, at: DVec2, angle: f64) -> Option<Mark> {
    let u = DVec2::from_angle(angle) * 5.0;
    let v = u.perp() * 0.6;
    paint(map, Paint::Opaque(pen), |d| {
        d.polygon(&[at - u - v, at + u - v, at + u + v, at - u + v]);
    })
}

/// A guide: the line and 45° hatch strokes on the `hatch` side.
fn guide(map: Map, pen: Pen, s: &Segment, hatch: Side, out: &mut Vec<Mark>) {
    out.extend(stroke(map, pen, |d| {
        d.segment(s.from, s.to);
    }));
    let Some(u) = (s.to - s.from).try_normalize() else {
        return;
    };
    let n = match hatch {
        Side::Left => u.perp(),
        Side::Right => -u.perp(),
    };
    let lean = (n - u).normalize() * HATCH_MM;
    out.extend(stroke(map, Pen::THIN, |d| {
        for k in 0..pieces(s.length(), HATCH_MM) {
            let foot = s.from + u * (HATCH_MM * (k as f64 + 1.0));
            d.segment(foot, foot + lean);
        }
    }));
}

/// A smooth curve through `pts`: Catmull–Rom pieces written as cubic Béziers.
fn smooth(d: &mut PathData, pts: &[DVec2], closed: bool) {
    let n = pts.len();
    if n < 3 {
        d.polyline(pts);
        return;
    }
    let at = |i: isize| -> DVec2 {
        let i = if closed {
            i.rem_euclid(n as isize)
        } else {
            i.clamp(0, n as isize - 1)
        };
        pts[i as usize]
    };
    d.move_to(pts[0]);
    let pieces = if closed { n } else { n - 1 } as isize;
    for i in 0..pieces {
        let (p0, p1, p2, p3) = (at(i - 1), at(i), at(i + 1), at(i + 2));
        d.cubic_to(p1 + (p2 - p0) / 6.0, p2 - (p3 - p1) / 6.0, p2);
    }
    if closed {
        d.close();
    }
}

/// A linear dimension: extension lines, the dimension line with arrows at both ends.
fn dimension(map: Map, from: DVec2, to: DVec2, offset: f64, out: &mut Vec<Mark>) {
    let Some(u) = (to - from).try_normalize() else {
        return;
    };
    let n = u.perp();
    let (a, b) = (from + n * offset, to + n * offset);
    // Extension lines run 2 mm past the dimension line (ГОСТ 2.307: 1…5 mm).
    let beyond = n * (2.0 * offset.signum());
    out.extend(stroke(map, Pen::THIN, |d| {
        if offset != 0.0 {
            d.segment(from, a + beyond).segment(to, b + beyond);
        }
        d.segment(a, b);
    }));
    out.extend(Arrow::THIN.head(map, a, -u));
    out.extend(Arrow::THIN.head(map, b, u));
}

/// The dimension text: over the middle of the dimension line, parallel to it, readable.
fn dimension_text(map: Map, from: DVec2, to: DVec2, offset: f64, text: &str) -> Option<Placed> {
    let u = (to - from).try_normalize()?;
    let mid = map.pt((from + to) * 0.5 + u.perp() * offset);
    let s = map.dir(u);
    let mut deg = s.y.atan2(s.x).to_degrees();
    // ГОСТ 2.307: horizontal texts read left to right, vertical ones bottom to top.
    if deg >= 90.0 {
        deg -= 180.0;
    } else if deg < -90.0 {
        deg += 180.0;
    }
    let up = DVec2::new(deg.to_radians().sin(), -deg.to_radians().cos());
    let mut placed = Placed::new(mid + up * 1.0, text, LABEL_HEIGHT_MM, Align::Middle);
    placed.rotate = deg;
    Some(placed)
}

/// An angle mark: the thin arc with an arrowhead at each end, following the arc.
fn angle_mark(map: Map, a: &Arc, out: &mut Vec<Mark>) {
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
    out.extend(arrow.head(map, at(start), at(start) - at(start + back)));
}

/// A label `gap` mm from its anchor toward `toward`, aligned so that the text lies on that
/// side; centred on the anchor when `toward` is zero.
fn label_text(label: &Label, map: Map, gap: f64) -> Placed {
    let t = map.dir(label.toward).normalize_or_zero();
    let c = map.pt(label.anchor) + t * gap;
    let align = if t.x > 0.35 {
        Align::Start
    } else if t.x < -0.35 {
        Align::End
    } else {
        Align::Middle
    };
    let h = LABEL_HEIGHT_MM;
    let baseline = if t.y > 0.35 {
        c.y + h
    } else if t.y < -0.35 {
        c.y
    } else {
        c.y + h * 0.5
    };
    Placed::new(DVec2::new(c.x, baseline), &label.text, h, align)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn placed(toward: DVec2) -> Placed {
        let label = Label {
            text: "B".into(),
            anchor: DVec2::new(10.0, 10.0),
            toward,
        };
        label_text(&label, Map::figure(DVec2::new(100.0, 100.0)), LABEL_GAP_MM)
    }

    #[test]
    fn labels_sit_on_the_side_they_point_to() {
        // Anchor (10, 10) in the figure is (110, 90) on the sheet.
        let right = placed(DVec2::X);
        assert_eq!(
            (right.align, right.at),
            (Align::Start, DVec2::new(112.5, 91.75))
        );
        let above = placed(DVec2::Y);
        assert_eq!(
            (above.align, above.at),
            (Align::Middle, DVec2::new(110.0, 87.5))
        );
        let below = placed(-DVec2::Y);
        assert_eq!(
            (below.align, below.at),
            (Align::Middle, DVec2::new(110.0, 96.0))
        );
        let left = placed(-DVec2::X);
        assert_eq!(left.align, Align::End);
        let centred = placed(DVec2::ZERO);
        assert_eq!(
            (centred.align, centred.at),
            (Align::Middle, DVec2::new(110.0, 91.75))
        );
    }

    #[test]
    fn dimension_text_is_readable_and_above_its_line() {
        let t = dimension_text(
            Map::figure(DVec2::ZERO),
            DVec2::new(50.0, 0.0),
            DVec2::ZERO,
            10.0,
            "50",
        )
        .unwrap();
        // Right to left with the offset below: the text still reads left to right, above.
        assert_eq!(t.rotate, 0.0);
        assert!((t.at - DVec2::new(25.0, 9.0)).length() < 1e-9, "{:?}", t.at);
        let v = dimension_text(
            Map::figure(DVec2::ZERO),
            DVec2::ZERO,
            DVec2::new(0.0, 40.0),
            5.0,
            "40",
        )
        .unwrap();
        assert_eq!(v.rotate, -90.0);
    }
}
