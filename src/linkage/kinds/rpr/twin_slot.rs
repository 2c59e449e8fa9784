//! A slotted link whose block's pin passes through the link's pivot (RPR without offset, the
//! pin `a` at the pivot `c`): the two points no longer fix the slot line. Its direction is
//! the limit of the direction c → a, the direction of the velocity analogue w′ of a relative
//! to c; with w = a − c = w′s + w″s²/2 + w‴s³/6 + … about the coincidence (s the crank travel
//! since it), the slot turns at
//!
//! θ′ = [w′ × w″] / (2|w′|²),   θ″ = [w′ × w‴] / (3|w′|²) − θ′·(w′·w″)/|w′|²,
//!
//! which needs the third derivative of a relative to c: known here for points of the frame
//! (0) and of the crank (−dp/dφ₁: they turn at a constant rate about a fixed centre).
//! Otherwise the position is reported as undetermined.
//!
//! Near the coincidence the direct formula of the heading loses digits as δ/(|w′|h³) (δ the
//! rounding of the positions, h = |w|/|w′| the crank travel to the coincidence) while the
//! limit errs by O(h): the limit is taken where h⁴ ≤ 2δ/|w′|, the crossover of the two.
//!
//! The limit holds only where the pin really passes through the pivot, that is where its
//! closest approach, w(−s) = w − w′s + w″s²/2 (s = w·w′/|w′|²), is zero within the rounding
//! 4δ and the neglected term |w‴||s|³. A pin that passes the pivot at a distance m (a crank
//! 0.01 mm shorter than the centre distance) makes the slot turn at ≈ |w′|/m times the crank's
//! rate there: the direct formula gives that true, huge value to δ/m relative; the pose
//! records it as [`NearPivot`](crate::linkage::NearPivot) (ill-conditioned: a change of m in a length
//! changes it by ~100 %).

use crate::geom::DVec2;
use crate::linkage::analytic::jet::{cross, AngleJet, Jet};
use crate::linkage::analytic::state::Pose;
use crate::linkage::compiled::Compiled;

/// How the slot line of an RPR group without offset is found.
pub(super) enum Slot {
    /// From the two points (the pin is away from the pivot).
    Direct,
    /// The limit at the pivot, with its rates.
    Limit(AngleJet),
    /// At the pivot, the rates are not determined; the direction when it is known.
    Undetermined {
        /// The slot direction (unit), when known.
        e: Option<DVec2>,
        /// What is missing, with the numbers.
        detail: String,
    },
}

/// The third derivative of point `k` with respect to φ₁, when known.
fn third_derivative(prog: &dyn Compiled, pose: &Pose, k: usize) -> Option<DVec2> {
    prog.on_frame_or_crank(k).then(|| -pose.dp[k])
}

/// The slot of an RPR group without offset at pin `a`, pivot `c`, `w` = a − c; `prev`:
/// the previous slot direction (continuity). Inlined into the kind's solve, the kernel's
/// inner loop, as the rest of it (see `PDyad::solve`).
#[inline(always)]
pub(super) fn limit(
    prog: &dyn Compiled,
    pose: &Pose,
    (a, c): (usize, usize),
    w: Jet,
    prev: Option<DVec2>,
) -> Slot {
    let v2 = w.d.length_squared();
    let v = v2.sqrt();
    let hp = w.p.length();
    // Rounding of w: the magnitudes it is computed from (the points, and |w′| for the
    // link lengths that carry them) at the machine epsilon.
    let delta = f64::EPSILON * (pose.p[a].length() + pose.p[c].length() + v);
    if hp.powi(4) > 2.0 * delta * v * v2 {
        return Slot::Direct;
    }
    let (na, nc) = (&prog.names()[a], &prog.names()[c]);
    let phi = pose.phi.to_degrees();
    if v == 0.0 {
        let e = if hp > 0.0 { Some(w.p / hp) } else { prev };
        return Slot::Undetermined {
                e,
                detail: format!(
                    "the pin {na} is {hp:.3e} m from the pivot {nc} at φ₁ = {phi:.4}° and does not move relative to it (|d{nc}{na}/dφ₁| = 0): the slot's direction and rates are not determined"
                ),
            };
    }
    // Crank travel since the coincidence, rad.
    let s = w.p.dot(w.d) / v2;
    let third = third_derivative(prog, pose, a)
        .zip(third_derivative(prog, pose, c))
        .map(|(ta, tc)| ta - tc);
    // The closest approach to O(s³): beyond the rounding the pin passes the pivot at a
    // distance and the direct formula holds (true, ill-conditioned values).
    let miss = (w.p - w.d * s + w.dd * (0.5 * s * s)).length();
    let reach = third.map_or(w.dd.length() + v, DVec2::length);
    if miss > 4.0 * delta + reach * s.abs().powi(3) {
        return Slot::Direct;
    }
    // The slot direction to O(s²).
    let lim = (w.d - w.dd * (0.5 * s)).normalize_or(w.d / v);
    let sign = if hp > 4.0 * delta {
        s.signum()
    } else {
        match prev {
            Some(q) if q.dot(lim) < 0.0 => -1.0,
            _ => 1.0,
        }
    };
    let e = lim * sign;
    let Some(w3) = third else {
        return Slot::Undetermined {
                e: Some(e),
                detail: format!(
                    "the pin {na} passes {hp:.3e} m from the pivot {nc} at φ₁ = {phi:.4}° (|d{nc}{na}/dφ₁| = {v:.6} m): the slot's rates are limits that need the third derivative of {na} relative to {nc}, known only for points of the frame and the crank"
                ),
            };
    };
    let d = cross(w.d, w.dd) / (2.0 * v2);
    let dd = cross(w.d, w3) / (3.0 * v2) - d * w.d.dot(w.dd) / v2;
    Slot::Limit(AngleJet { d, dd, e })
}
