//! Clipping to a circle: the parts of polylines and arcs that lie inside a circle, as a
//! draftsman copies a small zone of a drawing into an enlarged detail view.

use super::{Arc, Circle, DVec2};
use std::f64::consts::TAU;

/// The parameter interval `[t0, t1]` ⊂ [0, 1] of the segment `a → b` inside `circle` (its
/// boundary included); `None` when the segment misses the circle's inside.
fn segment_inside(a: DVec2, b: DVec2, circle: &Circle) -> Option<(f64, f64)> {
    let d = b - a;
    let f = a - circle.center;
    let dd = d.length_squared();
    let r2 = circle.radius * circle.radius;
    if dd == 0.0 {
        return (f.length_squared() <= r2).then_some((0.0, 1.0));
    }
    // |f + t d|² = r²: t² dd + 2 t (f·d) + |f|² − r² = 0.
    let half_b = f.dot(d);
    let disc = half_b * half_b - dd * (f.length_squared() - r2);
    if disc < 0.0 {
        return None;
    }
    let s = disc.sqrt();
    let (t0, t1) = ((-half_b - s) / dd, (-half_b + s) / dd);
    let (t0, t1) = (t0.max(0.0), t1.min(1.0));
    (t0 <= t1).then_some((t0, t1))
}

/// The runs of the polyline `points` inside `circle`, in order: a run starts and ends on
/// the circle where the polyline crosses it, or at the polyline's own ends inside it. A
/// run is at least two points; a polyline touching the circle at one point gives none.
pub fn polyline_in_circle(points: &[DVec2], circle: &Circle) -> Vec<Vec<DVec2>> {
    let mut runs: Vec<Vec<DVec2>> = Vec::new();
    let mut run: Vec<DVec2> = Vec::new();
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        match segment_inside(a, b, circle) {
            Some((t0, t1)) if t1 > t0 => {
                // A run goes on only through the shared vertex of two inside pieces.
                if t0 > 0.0 && !run.is_empty() {
                    runs.push(std::mem::take(&mut run));
                }
                if run.is_empty() {
                    run.push(a.lerp(b, t0));
                }
                run.push(a.lerp(b, t1));
                if t1 < 1.0 {
                    runs.push(std::mem::take(&mut run));
                }
            }
            _ => {
                if !run.is_empty() {
                    runs.push(std::mem::take(&mut run));
                }
            }
        }
    }
    if !run.is_empty() {
        runs.push(run);
    }
    runs.retain(|r| r.len() >= 2);
    runs
}

/// The pieces of `arc` inside `circle`, in the arc's order, each an arc of the same
/// centre, radius and sense.
pub fn arc_in_circle(arc: &Arc, circle: &Circle) -> Vec<Arc> {
    let sweep = arc.sweep.clamp(-TAU, TAU);
    if sweep == 0.0 || arc.radius <= 0.0 {
        return Vec::new();
    }
    let arc = Arc { sweep, ..*arc };
    let inside = |t: f64| arc.eval(t).distance(circle.center) <= circle.radius;
    // The fractions of the sweep where the arc's circle crosses `circle`.
    let mut cuts = vec![0.0, 1.0];
    let d = circle.center - arc.center;
    let dist = d.length();
    if dist > 0.0 {
        let x = (dist * dist + arc.radius * arc.radius - circle.radius * circle.radius)
            / (2.0 * dist * arc.radius);
        if x.abs() < 1.0 {
            let toward = d.y.atan2(d.x);
            for a in [toward - x.acos(), toward + x.acos()] {
                let t = ((a - arc.start) * sweep.signum()).rem_euclid(TAU) / sweep.abs();
                if t > 0.0 && t < 1.0 {
                    cuts.push(t);
                }
            }
        }
    }
    cuts.sort_by(f64::total_cmp);
    cuts.windows(2)
        .filter(|w| w[1] > w[0] && inside(0.5 * (w[0] + w[1])))
        .map(|w| Arc {
            center: arc.center,
            radius: arc.radius,
            start: arc.start + sweep * w[0],
            sweep: sweep * (w[1] - w[0]),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit() -> Circle {
        Circle::new(DVec2::ZERO, 1.0).unwrap()
    }

    #[test]
    fn a_polyline_through_a_circle_is_cut_on_its_boundary() {
        let pts = [
            DVec2::new(-2.0, 0.0),
            DVec2::new(0.0, 0.0),
            DVec2::new(0.0, 2.0),
            DVec2::new(3.0, 2.0),
        ];
        let runs = polyline_in_circle(&pts, &unit());
        assert_eq!(runs.len(), 1);
        let r = &runs[0];
        assert_eq!(r.len(), 3, "{r:?}");
        assert!((r[0] - DVec2::new(-1.0, 0.0)).length() < 1e-12);
        assert_eq!(r[1], DVec2::ZERO);
        assert!((r[2] - DVec2::new(0.0, 1.0)).length() < 1e-12);
        // Leaving and entering again: two runs; missing it: none.
        let zig = [
            DVec2::new(-0.5, 0.0),
            DVec2::new(-0.5, 5.0),
            DVec2::new(0.5, 5.0),
            DVec2::new(0.5, 0.0),
        ];
        assert_eq!(polyline_in_circle(&zig, &unit()).len(), 2);
        let far = [DVec2::new(2.0, 2.0), DVec2::new(3.0, 2.0)];
        assert!(polyline_in_circle(&far, &unit()).is_empty());
    }

    #[test]
    fn an_arc_keeps_the_pieces_inside_the_circle() {
        // A circle of radius 1 about (1, 0) against the unit circle: the piece within ±60°
        // of the origin's direction lies inside.
        let arc = Arc {
            center: DVec2::new(1.0, 0.0),
            radius: 1.0,
            start: 0.0,
            sweep: TAU,
        };
        let pieces = arc_in_circle(&arc, &unit());
        assert_eq!(pieces.len(), 1);
        let p = pieces[0];
        assert!((p.start - 2.0 * TAU / 6.0).abs() < 1e-12, "{p:?}");
        assert!((p.sweep - TAU / 3.0).abs() < 1e-12, "{p:?}");
        for t in [0.0, 0.5, 1.0] {
            assert!(p.eval(t).length() <= 1.0 + 1e-12);
        }
        // Clockwise, the same piece the other way round.
        let cw = Arc { sweep: -TAU, ..arc };
        let q = arc_in_circle(&cw, &unit());
        assert_eq!(q.len(), 1);
        assert!((q[0].sweep + TAU / 3.0).abs() < 1e-12, "{q:?}");
        // A concentric arc wholly inside or wholly outside.
        let small = Arc {
            center: DVec2::ZERO,
            radius: 0.5,
            ..arc
        };
        assert_eq!(arc_in_circle(&small, &unit()), vec![small]);
        assert!(arc_in_circle(
            &Arc {
                radius: 2.0,
                ..small
            },
            &unit()
        )
        .is_empty());
    }
}
