//! The method error of the graphical calculus, as bounds: the chord method's at the
//! mid-interval points and at the nodes, the midpoint rule's of graphical integration.

use super::read::{stencil, weights};
use super::Diagram;

/// Bound of the method error at the mid-interval points: h²/24·max|y‴|.
pub fn chord_mid_bound(dx: f64, max_d3: f64) -> f64 {
    dx * dx / 24.0 * max_d3
}

/// Bound of the method error of the chord method at the nodes of `src`: the largest over
/// the nodes of Λ·h²/24·max|y‴| + |Π(t − tⱼ)|/24·max|y⁽⁵⁾|, where Λ is the absolute sum of
/// the cubic's weights and Π the product of distances to its four midpoints (Λ = 1.25,
/// Π = 0.5625·h⁴ between midpoints; larger at the ends of a non-periodic diagram).
pub fn chord_node_bound(src: &Diagram, max_d3: f64, max_d5: f64) -> f64 {
    let n = src.intervals();
    let h = src.dx;
    let nodes = if src.periodic { n } else { n + 1 };
    (0..nodes)
        .map(|k| {
            let t = k as f64;
            let ts: Vec<f64> = stencil(n, 0.5, src.periodic, t)
                .iter()
                .map(|s| s.0)
                .collect();
            let lambda: f64 = weights(&ts, t).iter().map(|w| w.abs()).sum();
            let pi: f64 = ts.iter().map(|tj| (t - tj).abs() * h).product();
            lambda * chord_mid_bound(h, max_d3) + pi / 24.0 * max_d5
        })
        .fold(0.0, f64::max)
}

/// Bound of the midpoint rule over a length `length` with intervals `dx`:
/// length·h²/24·max|y″| of the integrand (plus, for [`super::Sampling::Nodes`], the cubic's
/// reading error 0.5625·h⁴/24·max|y⁗| per interval mean ordinate, times the length).
pub fn midpoint_rule_bound(length: f64, dx: f64, max_d2: f64) -> f64 {
    length.abs() * dx * dx / 24.0 * max_d2
}
