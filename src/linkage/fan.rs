//! The fan at a fixed pivot of the plan of positions. Every further position (drawn thin)
//! of a link turning about a pivot of the frame is a line from that pivot; when the links
//! swing through a narrow angle, or a link with three hinges sends two sides to the pivot
//! at every position (the six-bar's rocker DBC at D: 26 thin lines within 97°), the lines
//! run together near the pivot and print there as a black spot. The draughtsman's rule
//! (`geom::fan_start`, as for the cam rocker's fan): the further positions begin where their
//! lines stand apart — [`clearances`] finds that radius per pivot from the positions, and the
//! pen ([`super::pen::trim`], [`super::pen::trim_contour`]) starts the thin lines there. The given position, drawn
//! with the main line, still runs to its pivot; a fan whose lines stand apart at the hinge
//! (a crank's twelve positions) is not touched.

use super::built::Built;
use super::program::Program;
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
    prog.fixed_pivots()
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
