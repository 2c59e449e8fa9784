//! The fan at a fixed pivot of the plan of positions. Every further position (drawn thin)
//! of a link turning about a pivot of the frame is a line from that pivot; when the links
//! swing through a narrow angle, or a link with three hinges sends two sides to the pivot
//! at every position (the six-bar's rocker DBC at D: 26 thin lines within 97°), the lines
//! run together near the pivot and print there as a black spot. The draughtsman's rule is
//! the one of the cam rocker's fan: the further positions begin where their lines stand
//! apart — [`clearances`] finds that radius per pivot from the positions themselves, and the
//! pen ([`trim`], [`trim_contour`]) starts the thin lines there. The given position, drawn
//! with the main line, still runs to its pivot; a fan whose lines stand apart at the hinge
//! (a crank's twelve positions) is not touched.

use super::construction::Built;
use super::positions_draw::fixed_pivots;
use super::program::Program;
use super::rigid::AT_MM;
use crate::geom::DVec2;
use std::f64::consts::TAU;

/// Side of the square the eye reads as one spot (the legibility measure's cell), mm.
const SPOT_MM: f64 = 5.0;
/// Thin lines a spot holds apart: a thin line prints about 0,5 mm wide (the 0,25 mm pen and
/// its anti-aliased edges), so five of them ink half of a spot.
const LINES_PER_SPOT: usize = 5;
/// The step of the radius tried, mm.
const STEP_MM: f64 = 0.5;
/// The farthest a fan begins from its pivot, mm (as the cam rocker's fan).
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
                        .map(|u| u.to_angle().rem_euclid(TAU))
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

/// Where the lines at `angles` (radians in [0, 2π)) begin, mm. A fan is crowded when one
/// spot at a spot's distance from the pivot (an arc of [`SPOT_MM`] at radius [`SPOT_MM`])
/// holds more than [`LINES_PER_SPOT`] of its lines; it then begins at the least radius past
/// that (a multiple of [`STEP_MM`], at most [`MAX_CLEAR_MM`]) at which no spot's arc holds
/// more. An uncrowded fan begins at its pivot (0).
fn clear_radius(mut angles: Vec<f64>) -> f64 {
    angles.sort_by(f64::total_cmp);
    let crowded = |r: f64| most_within(&angles, SPOT_MM / r) > LINES_PER_SPOT;
    if !crowded(SPOT_MM) {
        return 0.0;
    }
    let mut r = SPOT_MM;
    while r < MAX_CLEAR_MM && crowded(r) {
        r += STEP_MM;
    }
    r.min(MAX_CLEAR_MM)
}

/// The most of the sorted `angles` within one window `width` radians wide, round the circle.
fn most_within(angles: &[f64], width: f64) -> usize {
    let n = angles.len();
    (0..n)
        .map(|i| {
            (0..n)
                .filter(|&j| (angles[j] - angles[i]).rem_euclid(TAU) <= width)
                .count()
        })
        .max()
        .unwrap_or(0)
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
    fn a_crank_fan_stands_apart_and_a_narrow_fan_begins_out() {
        // Twelve crank positions 30° apart and the extreme 5° past one of them stand apart.
        let mut crank: Vec<f64> = (0..12).map(|i| i as f64 * TAU / 12.0).collect();
        crank.push(5f64.to_radians());
        assert_eq!(clear_radius(crank), 0.0);
        // 26 lines within 97°: five to a spot only at 5 mm / (97° · 5/26) ≈ 15 mm, capped.
        let narrow: Vec<f64> = (0..26)
            .map(|i| (180.0 + i as f64 * 97.0 / 25.0).to_radians())
            .collect();
        assert_eq!(clear_radius(narrow), MAX_CLEAR_MM);
        // Four lines 10° apart stand apart; six are crowded at 5 mm (all within 57°) and five
        // to a spot once its arc is under 50°: 5 mm / 6 mm = 47,7°.
        let four: Vec<f64> = (0..4).map(|i| (i as f64 * 10.0).to_radians()).collect();
        assert_eq!(clear_radius(four), 0.0);
        let six: Vec<f64> = (0..6).map(|i| (i as f64 * 10.0).to_radians()).collect();
        assert_eq!(clear_radius(six), 6.0);
    }

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
