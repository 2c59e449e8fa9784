//! The smooth curve drawn through points, as cubic Bézier pieces.
//!
//! A diagram's curve (an open curve whose points run one way along the abscissa: y of x) is
//! drawn shape-preserving, as the draughtsman's French curve follows the points: each piece
//! the cubic Hermite whose end slopes are the weighted harmonic mean of the neighbouring
//! chords' slopes (Fritsch–Butland, the `PCHIP` of numerical libraries), so that a piece
//! between two points neither of which is an extreme never leaves their range and never
//! runs past the end points; where the points turn, the curve goes on to the extreme between
//! them as the parabola through the three points does (Bessel's slope, bounded), so that a
//! reading of the drawn curve's extreme ([`points`]) finds it there; where the points stand
//! on two straight lines meeting (a triangle) the lines are drawn to their corner. Every
//! other curve (a trajectory, a hodograph, a closed curve) is drawn Catmull–Rom, centripetal.

use crate::geom::DVec2;

/// A cubic Bézier piece: its two control points and its end (it starts where the previous
/// one ended, the first at the curve's first point).
pub type Piece = [DVec2; 3];

/// Points whose chords' slopes differ by less than this (times the shorter chord) stand on
/// one straight line, mm.
const STRAIGHT_MM: f64 = 1e-3;
/// Two straight runs meet in a corner drawn as such when their lines part by at least this
/// over one chord, mm (a smooth curve's sampled points never part that much while staying
/// straight on both sides).
const CORNER_MM: f64 = 0.05;

/// The pieces of the curve through `pts` (at least two), closed back to the first point
/// when `closed`.
pub fn pieces(pts: &[DVec2], closed: bool) -> Vec<Piece> {
    if pts.len() < 2 {
        return Vec::new();
    }
    if !closed && runs_one_way(pts) {
        graph(pts)
    } else {
        catmull_rom(pts, closed)
    }
}

/// Points along the curve through `pts` as [`pieces`] draws it: `per` on each piece, after
/// the first point.
pub fn points(pts: &[DVec2], closed: bool, per: usize) -> Vec<DVec2> {
    match pts.first() {
        Some(first) => crate::geom::bezier_points(*first, &pieces(pts, closed), per),
        None => Vec::new(),
    }
}

/// Whether the abscissae of `pts` all increase or all decrease.
fn runs_one_way(pts: &[DVec2]) -> bool {
    let dx: Vec<f64> = pts.windows(2).map(|w| w[1].x - w[0].x).collect();
    dx.iter().all(|d| *d > 0.0) || dx.iter().all(|d| *d < 0.0)
}

/// A straight piece from `a` to `b`.
fn straight(a: DVec2, b: DVec2) -> Piece {
    [a + (b - a) / 3.0, b - (b - a) / 3.0, b]
}

/// The Hermite piece from `a` to `b` (abscissae apart) with slopes `ma`, `mb`.
fn hermite(a: DVec2, ma: f64, b: DVec2, mb: f64) -> Piece {
    let h = (b.x - a.x) / 3.0;
    [
        DVec2::new(a.x + h, a.y + ma * h),
        DVec2::new(b.x - h, b.y - mb * h),
        b,
    ]
}

/// Whether chords of slopes `a` and `b`, the shorter `h` long in abscissa, are one line.
fn straight_on(a: f64, b: f64, h: f64) -> bool {
    (a - b).abs() * h < STRAIGHT_MM
}

/// The shape-preserving curve y(x) through `pts` (abscissae strictly one way).
fn graph(pts: &[DVec2]) -> Vec<Piece> {
    let n = pts.len();
    let h: Vec<f64> = pts.windows(2).map(|w| w[1].x - w[0].x).collect();
    let d: Vec<f64> = pts
        .windows(2)
        .zip(&h)
        .map(|(w, h)| (w[1].y - w[0].y) / h)
        .collect();
    if n == 2 {
        return vec![straight(pts[0], pts[1])];
    }
    // The slope arriving at each point and the slope leaving it (two at a corner).
    let mut into = vec![0.0; n];
    let mut out = vec![0.0; n];
    for i in 1..n - 1 {
        let m = if d[i - 1] * d[i] <= 0.0 {
            0.0
        } else {
            let (w1, w2) = (2.0 * h[i] + h[i - 1], h[i] + 2.0 * h[i - 1]);
            (w1 + w2) / (w1 / d[i - 1] + w2 / d[i])
        };
        into[i] = m;
        out[i] = m;
    }
    // The extremes: where the points turn, the curve goes on to the extreme a French curve
    // finds between them, as the parabola through the three points there does (its slope,
    // Bessel's), instead of stopping flat at the highest point; a flat chord between a rise
    // and a fall on curved sides (a peak the points straddle) bulges the same way.
    // Where sparse points make that parabola wild (a steep chord beside a long flat one),
    // its slope is cut so that the curve reaches past a point by about the steeper side's
    // rise at most.
    // A chord that rises less than [`STRAIGHT_MM`] is flat (rounding leaves a crest's two
    // equal points a hair apart).
    let d0: Vec<f64> = d
        .iter()
        .zip(&h)
        .map(|(d, h)| if (d * h).abs() < STRAIGHT_MM { 0.0 } else { *d })
        .collect();
    let extreme = extremes(&h, &d0);
    for i in (1..n - 1).filter(|&i| extreme[i]) {
        let m = (h[i] * d0[i - 1] + h[i - 1] * d0[i]) / (h[i - 1] + h[i]);
        // The piece the curve goes on into past the point: after it when it keeps the
        // first chord's way (or the next chord is flat), else before it.
        let far = if m * d0[i - 1] > 0.0 || d0[i] == 0.0 {
            h[i]
        } else {
            h[i - 1]
        };
        let rise = (d0[i - 1] * h[i - 1]).abs().max((d0[i] * h[i]).abs());
        let cap = 4.0 * rise / far.abs();
        let m = m.clamp(-cap, cap);
        into[i] = m;
        out[i] = m;
    }
    out[0] = end_slope(h[0], h[1], d[0], d[1]);
    into[n - 1] = end_slope(h[n - 2], h[n - 3], d[n - 2], d[n - 3]);
    // Straight runs: the chord's own slope at their inner points and ends.
    let straight_at = |i: usize| {
        i >= 1 && i < n - 1 && straight_on(d[i - 1], d[i], h[i - 1].abs().min(h[i].abs()))
    };
    for i in 0..n {
        if straight_at(i) {
            into[i] = d[i - 1];
            out[i] = d[i];
        }
    }
    // Corners at a point: straight on both sides, the two lines different.
    for i in 2..n.saturating_sub(2) {
        let (l, r) = (d[i - 1], d[i]);
        let parting = (l - r).abs() * h[i - 1].abs().min(h[i].abs());
        if straight_at(i - 1) && straight_at(i + 1) && parting >= CORNER_MM {
            into[i] = l;
            out[i] = r;
        }
    }
    // Corners inside a chord: straight runs on both sides (two chords each) whose lines
    // meet between its ends.
    let mut inner: Vec<Option<DVec2>> = vec![None; n - 1];
    for i in 2..n.saturating_sub(3) {
        if !(straight_at(i - 1) && straight_at(i + 2)) {
            continue;
        }
        let (l, r) = (d[i - 1], d[i + 1]);
        let (a, b) = (pts[i], pts[i + 1]);
        if (l - r).abs() * h[i].abs() < CORNER_MM {
            continue;
        }
        let x = (b.y - a.y + l * a.x - r * b.x) / (l - r);
        if (x - a.x) * (x - b.x) < 0.0 {
            inner[i] = Some(DVec2::new(x, a.y + l * (x - a.x)));
            into[i] = l;
            out[i + 1] = r;
        }
    }
    // Fritsch–Carlson: each piece's end slopes within the circle of radius 3 chords, so that
    // it runs monotone between its two points — except the pieces that hold an extreme.
    for i in 0..n - 1 {
        if inner[i].is_some() || extreme[i] || extreme[i + 1] {
            continue;
        }
        if d[i] == 0.0 {
            out[i] = 0.0;
            into[i + 1] = 0.0;
            continue;
        }
        let (a, b) = (out[i] / d[i], into[i + 1] / d[i]);
        let (a, b) = (a.max(0.0), b.max(0.0));
        let r = a.hypot(b);
        let k = if r > 3.0 { 3.0 / r } else { 1.0 };
        out[i] = a * k * d[i];
        into[i + 1] = b * k * d[i];
    }
    (0..n - 1)
        .flat_map(|i| match inner[i] {
            Some(k) => vec![straight(pts[i], k), straight(k, pts[i + 1])],
            None => vec![hermite(pts[i], out[i], pts[i + 1], into[i + 1])],
        })
        .collect()
}

/// Which points stand at an extreme of the points (`h`, `d` the chords' lengths in abscissa
/// and slopes): the chords on their two sides rise and fall, and the points next to them
/// do not stand on one straight line with them on both sides (a corner, drawn as such); or
/// they end a flat chord that rises on one side and falls on the other, each side curved
/// (its two chords not one line, or a single chord).
fn extremes(h: &[f64], d: &[f64]) -> Vec<bool> {
    let n = d.len() + 1;
    let straight = |i: usize, j: usize| straight_on(d[i], d[j], h[i].abs().min(h[j].abs()));
    let mut out = vec![false; n];
    for i in 1..n - 1 {
        if d[i - 1] * d[i] < 0.0 {
            let left = i >= 2 && straight(i - 2, i - 1);
            let right = i + 1 < d.len() && straight(i, i + 1);
            out[i] = !(left && right);
        }
    }
    for i in 1..d.len().saturating_sub(1) {
        // A side too short to tell counts as curved.
        let curved =
            (i < 2 || !straight(i - 2, i - 1)) && (i + 2 >= d.len() || !straight(i + 1, i + 2));
        if d[i] == 0.0 && d[i - 1] * d[i + 1] < 0.0 && curved {
            out[i] = true;
            out[i + 1] = true;
        }
    }
    out
}

/// The slope at an end of the curve: the three-point estimate, kept on the side of the end
/// chord and within three times its slope (`h0`, `d0` the end chord, `h1`, `d1` the next).
fn end_slope(h0: f64, h1: f64, d0: f64, d1: f64) -> f64 {
    let m = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
    if m * d0 <= 0.0 {
        0.0
    } else if d0 * d1 <= 0.0 && m.abs() > 3.0 * d0.abs() {
        3.0 * d0
    } else {
        m
    }
}

/// Centripetal Catmull–Rom pieces through `pts` (an end's missing neighbour is the end
/// itself): each point's tangent weighs its two chords by the square roots of their lengths,
/// so that two points close together between far ones (a hodograph's 7 and 7′) are joined
/// without the loop or the corner the uniform curve makes there; on points evenly spaced it
/// is the uniform curve.
fn catmull_rom(pts: &[DVec2], closed: bool) -> Vec<Piece> {
    let n = pts.len();
    let at = |i: isize| -> DVec2 {
        let i = if closed {
            i.rem_euclid(n as isize)
        } else {
            i.clamp(0, n as isize - 1)
        };
        pts[i as usize]
    };
    let count = if closed { n } else { n - 1 } as isize;
    (0..count)
        .map(|i| {
            let (p0, p1, p2, p3) = (at(i - 1), at(i), at(i + 1), at(i + 2));
            let knot = |a: DVec2, b: DVec2| a.distance(b).sqrt();
            let (d01, d12, d23) = (knot(p0, p1), knot(p1, p2), knot(p2, p3));
            if d12 == 0.0 {
                return [p1, p2, p2];
            }
            // The tangents per unit of the parameter at p1 and p2 (Barry–Goldman); at an
            // open end, where the neighbour is the end itself, half the chord's, as the
            // uniform curve has it.
            let tangent = |a: DVec2, da: f64, b: DVec2, c: DVec2, dc: f64| {
                if da == 0.0 {
                    (c - b) / (2.0 * dc)
                } else if dc == 0.0 {
                    (b - a) / (2.0 * da)
                } else {
                    (b - a) / da - (c - a) / (da + dc) + (c - b) / dc
                }
            };
            let m1 = tangent(p0, d01, p1, p2, d12);
            let m2 = tangent(p1, d12, p2, p3, d23);
            [p1 + m1 * (d12 / 3.0), p2 - m2 * (d12 / 3.0), p2]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn drawn(pts: &[DVec2], closed: bool, per: usize) -> Vec<DVec2> {
        points(pts, closed, per)
    }

    proptest! {
        /// A diagram's curve stays, between two points, within their range of ordinates and
        /// between their abscissae, where neither point is an extreme of the points; a piece
        /// holding an extreme reaches past its points by no more than a neighbouring chord
        /// rises. It ends at the end points.
        #[test]
        fn a_graph_leaves_the_range_of_its_two_points_only_at_an_extreme(
            steps in prop::collection::vec((0.05f64..20.0, -50.0f64..50.0), 2..14),
            flat in prop::collection::vec(any::<bool>(), 14),
            backwards in any::<bool>(),
        ) {
            let mut pts = vec![DVec2::new(0.0, 0.0)];
            for (k, (dx, y)) in steps.iter().enumerate() {
                let last = pts[pts.len() - 1];
                let y = if flat[k] { last.y } else { *y };
                let dx = if backwards { -dx } else { *dx };
                pts.push(DVec2::new(last.x + dx, y));
            }
            let h: Vec<f64> = pts.windows(2).map(|w| w[1].x - w[0].x).collect();
            let d: Vec<f64> = pts.windows(2).zip(&h).map(|(w, h)| (w[1].y - w[0].y) / h).collect();
            let ext = if pts.len() > 2 { extremes(&h, &d) } else { vec![false; pts.len()] };
            let rise = |j: usize| pts.get(j + 1).zip(pts.get(j)).map_or(0.0, |(b, a)| (b.y - a.y).abs());
            let mut start = pts[0];
            let mut i = 0;
            for p in pieces(&pts, false) {
                let (a, b) = (pts[i], pts[i + 1]);
                let past = if ext[i] || ext[i + 1] {
                    rise(i.wrapping_sub(1)).max(rise(i)).max(rise(i + 1))
                } else {
                    0.0
                };
                let (lo, hi) = (a.y.min(b.y) - past - 1e-9, a.y.max(b.y) + past + 1e-9);
                let (l, r) = (a.x.min(b.x) - 1e-9, a.x.max(b.x) + 1e-9);
                // The first half of a corner drawn inside a chord ends off the points: only
                // its abscissae are bounded.
                let corner = p[2] != b;
                for k in 0..=32 {
                    let q = crate::geom::bezier_at(start, &p, k as f64 / 32.0);
                    prop_assert!(corner || (q.y >= lo && q.y <= hi), "{q:?} outside {a:?}–{b:?}");
                    prop_assert!(q.x >= l && q.x <= r, "{q:?} outside {a:?}–{b:?}");
                }
                start = p[2];
                if !corner {
                    i += 1;
                }
            }
            prop_assert_eq!(i, pts.len() - 1);
        }
    }

    /// A closed curve through two points 2 mm apart between points 100 mm off (a
    /// hodograph's 7 and 7′ at a dead centre) joins them without a loop: the piece between
    /// them stays within their distance of its chord's midpoint (the uniform Catmull–Rom
    /// curve ran over 4 mm out there).
    #[test]
    fn close_points_between_far_ones_are_joined_without_a_loop() {
        let pts = [
            DVec2::new(-100.0, 10.0),
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(100.0, 30.0),
            DVec2::new(0.0, 120.0),
        ];
        let per = 32;
        let along = drawn(&pts, true, per);
        let piece = &along[per..2 * per];
        let mid = (pts[1] + pts[2]) / 2.0;
        let far = piece.iter().map(|p| p.distance(mid)).fold(0.0, f64::max);
        assert!(
            far <= pts[1].distance(pts[2]),
            "{far} mm from the chord's midpoint"
        );
    }

    #[test]
    fn a_peak_the_points_straddle_is_drawn_not_flattened() {
        // The sine law's d²S/dφ² read at mid-interval points: its crest falls between two
        // equal points (the review's flat tops), its trough on a point of a shallower side.
        let f = |x: f64| 40.0 * (x * std::f64::consts::TAU / 8.0).sin();
        for shift in [0.5, 0.3] {
            let pts: Vec<DVec2> = (0..8)
                .map(|k| DVec2::new(k as f64 + shift, f(k as f64 + shift)))
                .collect();
            let curve = drawn(&pts, false, 64);
            let top = curve.iter().map(|q| q.y).fold(f64::MIN, f64::max);
            let bottom = curve.iter().map(|q| q.y).fold(f64::MAX, f64::min);
            let pts_top = pts.iter().map(|q| q.y).fold(f64::MIN, f64::max);
            // The points' own crest is 40·cos(π/8) = 36,96 at shift 0,5: the curve reaches
            // the true 40 to a fraction of the points' shortfall.
            assert!(
                top > pts_top + 0.5 * (40.0 - pts_top),
                "shift {shift}: crest {top} of points' {pts_top}"
            );
            // Within 2 % of the amplitude: a French curve through 8 points a period.
            assert!((top - 40.0).abs() < 0.8, "shift {shift}: crest {top}");
            assert!(
                (bottom + 40.0).abs() < 0.8,
                "shift {shift}: trough {bottom}"
            );
        }
    }

    #[test]
    fn straight_runs_meet_in_their_corner_and_stay_straight() {
        // A triangle sampled at mid-interval points with its ends: the «+ −» law's dS/dφ.
        let tri = |x: f64| 10.0 - (x - 3.0).abs() * 10.0 / 3.0;
        let mut pts = vec![DVec2::new(0.0, 0.0)];
        pts.extend((0..6).map(|k| DVec2::new(k as f64 + 0.5, tri(k as f64 + 0.5))));
        pts.push(DVec2::new(6.0, 0.0));
        let curve = drawn(&pts, false, 16);
        for q in &curve {
            assert!((q.y - tri(q.x)).abs() < 1e-9, "{q:?} off the triangle");
        }
        assert!(
            curve.iter().any(|q| (q.y - 10.0).abs() < 1e-9),
            "the apex drawn"
        );
    }

    #[test]
    fn other_curves_stay_catmull_rom() {
        let ring: Vec<DVec2> = (0..8)
            .map(|k| DVec2::from_angle(k as f64 * std::f64::consts::TAU / 8.0) * 10.0)
            .collect();
        let p = pieces(&ring, true);
        assert_eq!(p.len(), 8);
        assert!((p[0][0] - (ring[0] + (ring[1] - ring[7]) / 6.0)).length() < 1e-12);
    }
}
