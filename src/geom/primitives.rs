//! Lines, segments, rays, circles and arcs on `glam::DVec2`.

use glam::DVec2;
use std::f64::consts::TAU;

/// An infinite straight line through `point` with unit `direction`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    /// A point of the line.
    pub point: DVec2,
    /// Unit direction; the line is directed, so "left" and "right" have a meaning.
    pub direction: DVec2,
}

impl Line {
    /// The line through `point` along `direction`; `None` for a zero or non-finite direction.
    pub fn new(point: DVec2, direction: DVec2) -> Option<Self> {
        let direction = direction.try_normalize()?;
        point.is_finite().then_some(Self { point, direction })
    }

    /// The directed line from `a` through `b`; `None` when the points coincide.
    pub fn through(a: DVec2, b: DVec2) -> Option<Self> {
        Self::new(a, b - a)
    }

    /// The point at parameter `t` (distance along the direction from `point`).
    pub fn eval(&self, t: f64) -> DVec2 {
        self.point + self.direction * t
    }

    /// Parameter of the foot of the perpendicular from `p`.
    pub fn project_t(&self, p: DVec2) -> f64 {
        (p - self.point).dot(self.direction)
    }

    /// Signed distance of `p` from the line: positive on the left.
    pub fn signed_distance(&self, p: DVec2) -> f64 {
        self.direction.perp_dot(p - self.point)
    }

    /// The parallel line shifted by `d` to the left (negative: to the right).
    pub fn offset(&self, d: f64) -> Self {
        Self {
            point: self.point + self.direction.perp() * d,
            direction: self.direction,
        }
    }

    /// Angle of the direction, radians, counter-clockwise from +x.
    pub fn angle(&self) -> f64 {
        self.direction.y.atan2(self.direction.x)
    }
}

/// A straight segment between two points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// Start point.
    pub from: DVec2,
    /// End point.
    pub to: DVec2,
}

impl Segment {
    /// The segment from `from` to `to`.
    pub fn new(from: DVec2, to: DVec2) -> Self {
        Self { from, to }
    }
    /// Length.
    pub fn length(&self) -> f64 {
        self.from.distance(self.to)
    }
    /// The point at fraction `t` (0 = from, 1 = to).
    pub fn eval(&self, t: f64) -> DVec2 {
        self.from.lerp(self.to, t)
    }
    /// The carrying line, `None` for a zero-length segment.
    pub fn to_line(&self) -> Option<Line> {
        Line::through(self.from, self.to)
    }
    /// The point of the segment nearest `p` (its nearer end beyond them).
    pub fn closest(&self, p: DVec2) -> DVec2 {
        let d = self.to - self.from;
        let len2 = d.length_squared();
        if len2 == 0.0 {
            return self.from;
        }
        let t = ((p - self.from).dot(d) / len2).clamp(0.0, 1.0);
        self.from + d * t
    }
    /// The distance from `p` to the segment (to its nearer end beyond them).
    pub fn distance_to(&self, p: DVec2) -> f64 {
        (p - self.closest(p)).length()
    }
    /// Where the carrying lines of `self` and `other` meet, and how far outside the segments
    /// that is, in their parameters (0 when inside both); `None` for lines parallel to
    /// rounding (the sine of their angle within an ulp of 1, where the cross product is
    /// rounding noise whatever the segments' size) or a segment of no length.
    pub fn meet(&self, other: &Segment) -> Option<(DVec2, f64)> {
        let r = self.to - self.from;
        let s = other.to - other.from;
        let den = r.perp_dot(s);
        if den.abs() <= f64::EPSILON * r.length() * s.length() {
            return None;
        }
        let w = other.from - self.from;
        let t = w.perp_dot(s) / den;
        let u = w.perp_dot(r) / den;
        let out = |x: f64| (-x).max(x - 1.0).max(0.0);
        Some((self.from + r * t, out(t).max(out(u))))
    }
    /// The point where the segments cross (ends included); `None` when they do not.
    pub fn crossing(&self, other: &Segment) -> Option<DVec2> {
        self.meet(other)
            .and_then(|(p, miss)| (miss == 0.0).then_some(p))
    }
}

/// A half-line from `origin` along unit `direction`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ray {
    /// Start point.
    pub origin: DVec2,
    /// Unit direction.
    pub direction: DVec2,
}

impl Ray {
    /// `None` for a zero direction.
    pub fn new(origin: DVec2, direction: DVec2) -> Option<Self> {
        Some(Self {
            origin,
            direction: direction.try_normalize()?,
        })
    }
    /// The point at distance `t ≥ 0` from the origin.
    pub fn eval(&self, t: f64) -> DVec2 {
        self.origin + self.direction * t
    }
    /// The carrying line.
    pub fn to_line(&self) -> Line {
        Line {
            point: self.origin,
            direction: self.direction,
        }
    }
}

/// A circle (a compass setting: centre and radius ≥ 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    /// Centre.
    pub center: DVec2,
    /// Radius, ≥ 0.
    pub radius: f64,
}

impl Circle {
    /// `None` for a negative or non-finite radius or centre.
    pub fn new(center: DVec2, radius: f64) -> Option<Self> {
        (center.is_finite() && radius.is_finite() && radius >= 0.0)
            .then_some(Self { center, radius })
    }
    /// The point at angle `a` (radians from +x).
    pub fn eval(&self, a: f64) -> DVec2 {
        self.center + DVec2::from_angle(a) * self.radius
    }
}

/// A circular arc from `start` (radians) sweeping `sweep` radians (positive: counter-clockwise).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arc {
    /// Centre.
    pub center: DVec2,
    /// Radius.
    pub radius: f64,
    /// Start angle, radians from +x.
    pub start: f64,
    /// Signed sweep, radians.
    pub sweep: f64,
}

impl Arc {
    /// A short compass notch: an arc of `half_width` (length units) on each side of `through`.
    pub fn notch(center: DVec2, through: DVec2, half_width: f64) -> Self {
        let d = through - center;
        let radius = d.length();
        let half = if radius > 0.0 {
            (half_width / radius).min(std::f64::consts::PI)
        } else {
            0.0
        };
        Self {
            center,
            radius,
            start: d.y.atan2(d.x) - half,
            sweep: 2.0 * half,
        }
    }

    /// The arc between directions `from` and `to` around `center`, the short way.
    pub fn between(center: DVec2, radius: f64, from: DVec2, to: DVec2) -> Self {
        let start = from.y.atan2(from.x);
        let sweep = from.perp_dot(to).atan2(from.dot(to));
        Self {
            center,
            radius,
            start,
            sweep,
        }
    }

    /// The point at fraction `t` of the sweep.
    pub fn eval(&self, t: f64) -> DVec2 {
        self.center + DVec2::from_angle(self.start + self.sweep * t) * self.radius
    }

    /// The end point.
    pub fn end(&self) -> DVec2 {
        self.eval(1.0)
    }

    /// True when the arc closes a full turn.
    pub fn is_full(&self) -> bool {
        self.sweep.abs() >= TAU
    }
}

/// Which side of a directed line a point (or a compass solution) lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Side {
    /// To the left (counter-clockwise) of the direction.
    Left,
    /// To the right (clockwise) of the direction.
    Right,
}

impl Side {
    /// The side of `p` relative to `line`; `None` when `p` is on it within `coincident`.
    pub fn of(p: DVec2, line: &Line, coincident: f64) -> Option<Side> {
        let d = line.signed_distance(p);
        if d > coincident {
            Some(Side::Left)
        } else if d < -coincident {
            Some(Side::Right)
        } else {
            None
        }
    }
    /// The other side.
    pub fn flip(self) -> Self {
        match self {
            Side::Left => Side::Right,
            Side::Right => Side::Left,
        }
    }
}

/// Whether `p` lies inside the polygon `pts` (even–odd rule; the closing edge implied).
pub fn polygon_contains(pts: &[DVec2], p: DVec2) -> bool {
    let mut odd = false;
    for (i, &a) in pts.iter().enumerate() {
        let b = pts[(i + 1) % pts.len()];
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            odd = !odd;
        }
    }
    odd
}

/// Rotate `v` by `angle` radians counter-clockwise.
pub fn rotate(v: DVec2, angle: f64) -> DVec2 {
    DVec2::from_angle(angle).rotate(v)
}

/// Wrap an angle to (−π, π].
pub fn wrap_pi(a: f64) -> f64 {
    let w = a.rem_euclid(TAU);
    if w > std::f64::consts::PI {
        w - TAU
    } else {
        w
    }
}

/// The index of the candidate nearest to `previous` (selection of a compass solution by
/// continuity with the previous position). `None` for an empty slice.
pub fn nearest(candidates: &[DVec2], previous: DVec2) -> Option<usize> {
    candidates
        .iter()
        .enumerate()
        .min_by(|a, b| {
            a.1.distance_squared(previous)
                .total_cmp(&b.1.distance_squared(previous))
        })
        .map(|(i, _)| i)
}

/// A curve as the draftsman's French curve draws it between `a` and `b`, touching the
/// directions `ta` there and `tb` here (the cubic with those end tangents, each turned along
/// the chord and as long as it), as `pieces + 1` points from `a` to `b`.
pub fn french_curve(a: DVec2, ta: DVec2, b: DVec2, tb: DVec2, pieces: usize) -> Vec<DVec2> {
    let (ma, mb) = french_derivatives(a, ta, b, tb);
    hermite(a, ma, b, mb, pieces)
}

/// [`french_curve`] as one cubic Bézier piece from `a`: its two control points and its end
/// `b` (the curve itself, not points on it).
pub fn french_piece(a: DVec2, ta: DVec2, b: DVec2, tb: DVec2) -> [DVec2; 3] {
    let (ma, mb) = french_derivatives(a, ta, b, tb);
    [a + ma / 3.0, b - mb / 3.0, b]
}

/// The French curve's end derivatives: each tangent turned along the chord and as long as it.
fn french_derivatives(a: DVec2, ta: DVec2, b: DVec2, tb: DVec2) -> (DVec2, DVec2) {
    let chord = b - a;
    let len = chord.length();
    let along = |t: DVec2| {
        let t = t.normalize_or_zero();
        if t.dot(chord) < 0.0 {
            -t * len
        } else {
            t * len
        }
    };
    (along(ta), along(tb))
}

/// The point at `t` ∈ [0, 1] of the cubic Bézier piece from `start` with the control points
/// and end `p`.
pub fn bezier_at(start: DVec2, p: &[DVec2; 3], t: f64) -> DVec2 {
    let s = 1.0 - t;
    start * (s * s * s) + p[0] * (3.0 * s * s * t) + p[1] * (3.0 * s * t * t) + p[2] * (t * t * t)
}

/// Distance from `p` to the cubic Bézier piece from `start` (its control points and end
/// `piece`): the nearest of 16 equal steps of its parameter, refined by Newton's method on
/// (B(t) − p)·B′(t) = 0 within the piece.
pub fn bezier_distance(p: DVec2, start: DVec2, piece: &[DVec2; 3]) -> f64 {
    let at = |t: f64| bezier_at(start, piece, t);
    let [c1, c2, end] = *piece;
    // B′ and B″ of the piece at t.
    let d1 = |t: f64| {
        let s = 1.0 - t;
        (c1 - start) * (3.0 * s * s) + (c2 - c1) * (6.0 * s * t) + (end - c2) * (3.0 * t * t)
    };
    let d2 =
        |t: f64| (c2 - 2.0 * c1 + start) * (6.0 * (1.0 - t)) + (end - 2.0 * c2 + c1) * (6.0 * t);
    let mut t = (0..=16)
        .map(|k| k as f64 / 16.0)
        .min_by(|a, b| {
            at(*a)
                .distance_squared(p)
                .total_cmp(&at(*b).distance_squared(p))
        })
        .unwrap_or(0.0);
    for _ in 0..8 {
        let (q, v, w) = (at(t) - p, d1(t), d2(t));
        let slope = v.length_squared() + q.dot(w);
        if slope.abs() <= f64::MIN_POSITIVE {
            break;
        }
        t = (t - q.dot(v) / slope).clamp(0.0, 1.0);
    }
    at(t).distance(p)
}

/// The curve of cubic Bézier `pieces` from `start` as points, `per` chords a piece (the
/// start, then each piece's inner points and its end).
pub fn bezier_points(start: DVec2, pieces: &[[DVec2; 3]], per: usize) -> Vec<DVec2> {
    let per = per.max(1);
    let mut out = vec![start];
    let mut at = start;
    for p in pieces {
        out.extend((1..=per).map(|k| bezier_at(at, p, k as f64 / per as f64)));
        at = p[2];
    }
    out
}

/// The cubic Hermite piece from `a` to `b` with the derivatives `ma`, `mb` (per the whole
/// piece) at its ends, as `pieces + 1` points: the Bézier curve with the control points
/// a + ma/3 and b − mb/3, within their hull.
pub fn hermite(a: DVec2, ma: DVec2, b: DVec2, mb: DVec2, pieces: usize) -> Vec<DVec2> {
    let pieces = pieces.max(1);
    (0..=pieces)
        .map(|k| {
            let u = k as f64 / pieces as f64;
            let (u2, u3) = (u * u, u * u * u);
            a * (2.0 * u3 - 3.0 * u2 + 1.0)
                + ma * (u3 - 2.0 * u2 + u)
                + b * (3.0 * u2 - 2.0 * u3)
                + mb * (u3 - u2)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A straight piece (0, 0) → (3, 0): 2 from a point 2 over its middle, 2 past its end, √2
    /// before its start; the quarter circle's cubic (k = 0,5523) lies within 3e-4 of radius 1
    /// from its centre, and 1 from (2, 0) at its start.
    #[test]
    fn the_distance_to_a_bezier_piece_is_to_its_nearest_point() {
        let line = [
            DVec2::new(1.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(3.0, 0.0),
        ];
        let d = |p: DVec2| bezier_distance(p, DVec2::ZERO, &line);
        assert!((d(DVec2::new(1.5, 2.0)) - 2.0).abs() < 1e-12);
        assert!((d(DVec2::new(5.0, 0.0)) - 2.0).abs() < 1e-12);
        assert!((d(DVec2::new(-1.0, 1.0)) - 2f64.sqrt()).abs() < 1e-12);
        let k = 0.5523;
        let arc = [DVec2::new(1.0, k), DVec2::new(k, 1.0), DVec2::new(0.0, 1.0)];
        let d = |p: DVec2| bezier_distance(p, DVec2::X, &arc);
        assert!((d(DVec2::ZERO) - 1.0).abs() < 3e-4, "{}", d(DVec2::ZERO));
        assert!((d(DVec2::new(2.0, 0.0)) - 1.0).abs() < 1e-12);
    }
}
