//! The fan at a fixed pivot of the plan of positions. Every further position (drawn thin)
//! of a link turning about a pivot of the frame is a line from that pivot; when the links
//! swing through a narrow angle, or a link with three hinges sends two sides to the pivot
//! at every position (the six-bar's rocker DBC at D: 26 thin lines within 97°), the lines
//! run together near the pivot and print there as a black spot. The draughtsman's rule
//! (`geom::fan_start`, as for the cam rocker's fan): the further positions begin where their
//! lines stand apart — [`clearances`] finds that radius per pivot from the positions, and the
//! pen ([`trim`], [`trim_contour`]) starts the thin lines there. The given position, drawn
//! with the main line, still runs to its pivot; a fan whose lines stand apart at the hinge
//! (a crank's twelve positions) is not touched.

use super::construction::Built;
use super::positions_draw::fixed_pivots;
use super::program::Program;
use super::rigid::AT_MM;
use crate::geom::{fan_start, DVec2, SPOT_MM};

/// The farthest a plan's fan begins from its pivot, mm: its links are short beside a cam's
/// rocker, and a hinge's lines 8 mm out already read as one fan.
const MAX_CLEAR_MM: f64 = 8.0;

/// Per fixed pivot whose fan is crowded, its point and the radius its thin lines begin at,
/// mm ([`clear_radius`] of the lines the positions `thin` draw from it). Pivots whose lines
/// stand apart are left out.
pub(super) fn clearances(prog: &Program, thin: &[&Built]) -> Vec<(DVec2, f64)> {
    let Some(first) = thin.first() else {
        return Vec::new();
    };
    fixed_pivots(prog)
        .into_iter()
        .filter_map(|k| {
            let angles: Vec<f64> = thin
                .iter()
                .flat_map(|b| {
                    partners(prog, k)
                        .into_iter()
                        .filter_map(move |j| (b.p[j] - b.p[k]).try_normalize())
                        .map(|u| u.to_angle())
                })
                .collect();
            let r = clear_radius(angles);
            (r > 0.0).then_some((first.p[k], r))
        })
        .collect()
}

/// The hinges a line of the plan joins to the fixed pivot `k`: the points that share a
/// moving link with it and lie on a second link or the frame (a centre of mass lies on its
/// link alone and is not a line's end).
fn partners(prog: &Program, k: usize) -> Vec<usize> {
    let at_k: Vec<usize> = prog.links_of(k).into_iter().filter(|l| *l != 0).collect();
    (0..prog.names.len())
        .filter(|&j| j != k)
        .filter(|&j| {
            let links = prog.links_of(j);
            links.len() >= 2 && links.iter().any(|l| at_k.contains(l))
        })
        .collect()
}

/// Where the lines at `angles` begin, mm: [`fan_start`] searched from a spot's distance from
/// the pivot up to [`MAX_CLEAR_MM`].
fn clear_radius(angles: Vec<f64>) -> f64 {
    fan_start(angles, (SPOT_MM, MAX_CLEAR_MM))
}

/// The line `from`–`to` begun at its pivot's clearance (`clear`, [`clearances`]) at either
/// end that is a cleared pivot; `None` when the line is shorter than the clearance.
pub(super) fn trim(clear: &[(DVec2, f64)], from: DVec2, to: DVec2) -> Option<(DVec2, DVec2)> {
    let back = |at: DVec2, other: DVec2| match radius_at(clear, at) {
        Some(r) => (other - at).try_normalize().map(|u| at + u * r),
        None => Some(at),
    };
    let (a, b) = (back(from, to)?, back(to, from)?);
    ((b - a).dot(to - from) > 0.0).then_some((a, b))
}

/// A closed contour through `points` opened at a cleared pivot among them: the open line
/// from the clearance towards the next hinge, round the contour, to the clearance towards
/// the previous one. `None` when no vertex is a cleared pivot.
pub(super) fn trim_contour(clear: &[(DVec2, f64)], points: &[DVec2]) -> Option<Vec<DVec2>> {
    let n = points.len();
    let (i, r) = (0..n).find_map(|i| radius_at(clear, points[i]).map(|r| (i, r)))?;
    let v = points[i];
    let toward = |p: DVec2| v + (p - v).normalize_or_zero() * r.min(v.distance(p));
    let mut open = vec![toward(points[(i + 1) % n])];
    open.extend((1..n).map(|s| points[(i + s) % n]));
    open.push(toward(points[(i + n - 1) % n]));
    Some(open)
}

/// The clearance of the pivot at `at`, if it is a cleared one.
fn radius_at(clear: &[(DVec2, f64)], at: DVec2) -> Option<f64> {
    clear
        .iter()
        .find(|(p, _)| p.distance(at) <= AT_MM)
        .map(|(_, r)| *r)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_and_contours_begin_at_the_clearance() {
        let d = DVec2::new(10.0, 0.0);
        let clear = [(d, 4.0)];
        let (a, b) = trim(&clear, d, DVec2::new(10.0, -20.0)).expect("long enough");
        assert!((a - DVec2::new(10.0, -4.0)).length() < 1e-12);
        assert_eq!(b, DVec2::new(10.0, -20.0));
        // Reversed, the far end is the pivot's.
        let (a, b) = trim(&clear, DVec2::new(10.0, -20.0), d).expect("long enough");
        assert_eq!(a, DVec2::new(10.0, -20.0));
        assert!((b - DVec2::new(10.0, -4.0)).length() < 1e-12);
        assert!(trim(&clear, d, DVec2::new(12.0, 0.0)).is_none());
        assert_eq!(
            trim(&clear, DVec2::ZERO, DVec2::X),
            Some((DVec2::ZERO, DVec2::X))
        );
        let tri = [DVec2::new(0.0, -20.0), d, DVec2::new(20.0, -20.0)];
        let open = trim_contour(&clear, &tri).expect("D is a vertex");
        assert_eq!(open.len(), 4);
        assert_eq!(open[1], tri[2]);
        assert_eq!(open[2], tri[0]);
        assert!((open[0].distance(d) - 4.0).abs() < 1e-12);
        assert!((open[3].distance(d) - 4.0).abs() < 1e-12);
        assert!(trim_contour(&[], &tri).is_none());
    }
}
