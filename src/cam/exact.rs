//! The analytic twin, and only the twin: the given law in closed form sampled densely over
//! the whole cycle, the minimum radius over the whole cycle (not only at the drawn points),
//! the pitch curve's exact curvature, the smallest cam with the offset free. The
//! construction never calls it: the two share the law ([`super::motion`]) and the
//! follower's primitives ([`super::follower`]) only.

pub use super::centre::min_radius_rocker;
use super::extremum::{checked_pieces, max_over, pieces};
use super::follower::{rocker_of, Kin, Placement};
use super::motion::{motion, FollowerMotion};
use super::{CamSpec, Closure};
use crate::geom::{golden_section, DVec2, GoldenRule, Tie};
use std::f64::consts::FRAC_PI_2;

/// Samples of each moving phase the whole-cycle minimisations use (plus every break).
pub const DENSE: usize = 2000;

/// Dense samples of the cycle: every moving phase at [`DENSE`] intervals, both sides of
/// every jump, the dwells at their ends.
pub fn dense(spec: &CamSpec, per_phase: usize) -> Vec<(f64, bool)> {
    let st = spec.starts();
    let mut out = Vec::new();
    for (phase, len, law) in [
        (0usize, spec.phases.rise, spec.rise),
        (2, spec.phases.ret, spec.ret),
    ] {
        for k in 0..=per_phase {
            let u = k as f64 / per_phase as f64;
            let phi = if k == per_phase {
                st[phase + 1]
            } else {
                st[phase] + len * u
            };
            out.push((phi, k == 0));
        }
        for b in law.breaks() {
            out.push((st[phase] + len * b, false));
            out.push((st[phase] + len * b, true));
        }
        out.push((st[phase + 1], true));
    }
    out
}

/// The samples the angle limit is checked at: [`dense`], the rise only under force closure.
pub fn checked(spec: &CamSpec, per_phase: usize) -> Vec<(f64, bool)> {
    let end = spec.starts()[1];
    dense(spec, per_phase)
        .into_iter()
        .filter(|&(phi, after)| {
            spec.closure == Closure::Geometric || phi < end || (phi == end && !after)
        })
        .collect()
}

/// The exact minimum base radius of a translating roller / knife-edge follower with offset
/// e for λ ≤ 90° − γ_min over the whole cycle (the rise only under force closure):
/// s₀ = max(|S′ − e|·tan γ_min − S) over every smooth piece (its ends on its own side, every
/// local maximum refined), r₀ = √(e² + s₀²). Returns (r₀, s₀).
pub fn min_radius_translating(spec: &CamSpec, offset: f64) -> (f64, f64) {
    let t = spec.gamma_min.tan();
    let (need, _, _) = max_over(spec, &checked_pieces(spec), DENSE, |m| {
        (m.ds - offset).abs() * t - m.s
    });
    let s0 = need.max(0.0);
    (offset.hypot(s0), s0)
}

/// The rocker's constraints: for each dense angle, K and the rocker's line direction in the
/// frame of the pivot O₂ (origin) with A₀ at ψ₀ = 90°.
pub fn rocker_constraints(spec: &CamSpec, per_phase: usize) -> Vec<(DVec2, DVec2)> {
    let (arm, sigma) = rocker_of(spec);
    let place = Placement::Rocker {
        pivot: DVec2::ZERO,
        arm,
        psi0: FRAC_PI_2,
        sigma,
    };
    checked(spec, per_phase)
        .into_iter()
        .map(|(phi, after)| {
            let k = place.kin(motion(spec, phi, after));
            (k.k, k.along)
        })
        .collect()
}

/// The flat face's exact minimum r₀ = max(−(S + S″)) + ρ_min over the whole cycle (never
/// below ρ_min), and max(−(S + S″)) itself: over every smooth piece, both sides of every
/// jump of S″, every local maximum refined.
pub fn min_radius_flat(spec: &CamSpec) -> (f64, f64) {
    let (worst, _, _) = max_over(spec, &pieces(spec, false), DENSE, |m| -(m.s + m.d2s));
    (worst.max(0.0) + spec.rho_min, worst)
}

/// The pitch curve's curvature 1/ρ at a follower position (> 0 convex, < 0 concave).
fn curvature(k: &Kin) -> f64 {
    1.0 / k.pitch_radius()
}

/// The smallest radius of curvature of the convex parts of the pitch curve over the whole
/// cycle (the largest admissible roller is just under it), and the most concave one (its
/// smallest |ρ|, `None` when the pitch curve is convex everywhere): the largest curvature
/// of each sign over every smooth piece (the dwells are arcs about O), every local maximum
/// refined, to rounding.
pub fn pitch_rho_min(spec: &CamSpec, place: &Placement) -> (f64, Option<f64>) {
    let all = pieces(spec, false);
    let kappa = |m: FollowerMotion| curvature(&place.kin(m));
    let (convex, _, _) = max_over(spec, &all, DENSE, kappa);
    let (concave, _, _) = max_over(spec, &all, DENSE, |m| -kappa(m));
    let convex = if convex > 0.0 {
        1.0 / convex
    } else {
        f64::INFINITY
    };
    (convex, (concave > 0.0).then(|| 1.0 / concave))
}

/// The smallest translating cam with the offset free (lecture 15's O₁, where the two γ_min
/// tangents meet): the e minimising r₀(e) = √(e² + s₀(e)²) over the whole cycle, by a scan
/// and a golden-section refinement. Returns (r₀, e).
pub fn min_radius_free(spec: &CamSpec) -> (f64, f64) {
    let span = dense(spec, 200)
        .into_iter()
        .map(|(p, a)| motion(spec, p, a).ds.abs())
        .fold(0.0, f64::max)
        .max(spec.stroke);
    let r = |e: f64| min_radius_translating(spec, e).0;
    let steps = 80;
    let (mut best_e, mut best_r) = (0.0, r(0.0));
    for i in 0..=steps {
        let e = -span + 2.0 * span * i as f64 / steps as f64;
        let v = r(e);
        if v < best_r {
            best_r = v;
            best_e = e;
        }
    }
    let h = 2.0 * span / steps as f64;
    // 60 steps, both points afresh each step, the bracket's middle taken.
    let rule = GoldenRule {
        steps: 60,
        tie: Tie::Upper,
        fresh: true,
    };
    let end = golden_section(best_e - h, best_e + h, rule, |_, _| false, |e| -r(e));
    let e = 0.5 * (end.lo + end.hi);
    let v = r(e);
    if v < best_r {
        (v, e)
    } else {
        (best_r, best_e)
    }
}
