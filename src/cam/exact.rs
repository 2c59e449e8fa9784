//! The analytic twin: the closed-form law over the cycle, the pitch curve and its exact
//! envelope with curvature, the pressure / transmission angle, and the minimum radius over
//! the whole cycle (not only at the drawn points).

pub use super::centre::min_radius_rocker;
use super::extremum::{checked_pieces, max_over, pieces};
pub use super::motion::{locate, motion, motion_u, points, Motion, Point};
use super::{CamSpec, Follower};
use crate::geom::{rotate, DVec2};
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
        .filter(|&(phi, after)| !spec.force_closure || phi < end || (phi == end && !after))
        .collect()
}

/// Where the follower is relative to the cam centre O (the origin) when φ = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Placement {
    /// A translating follower (roller centre, knife edge or the face's foot on the axis):
    /// axis x = e, lowest point at height s₀.
    Translating {
        /// e, m.
        offset: f64,
        /// s₀ = √(r₀² − e²), m.
        s0: f64,
    },
    /// A rocker: pivot O₂, arm L, initial angle ψ₀ of O₂A, sense σ = ±1 on the rise.
    Rocker {
        /// O₂, m.
        pivot: DVec2,
        /// L, m.
        arm: f64,
        /// ψ₀, rad.
        psi0: f64,
        /// σ: +1 counter-clockwise on the rise.
        sigma: f64,
    },
}

/// The follower's point B (roller centre) in the fixed frame with its φ-derivatives, the
/// direction of its motion, and the point K = B + J·B′ of the combined diagram (OK is
/// parallel to the common normal: the seed's "dS/dφ laid along the rocker").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kin {
    /// B, m.
    pub b: DVec2,
    /// dB/dφ.
    pub b1: DVec2,
    /// d²B/dφ².
    pub b2: DVec2,
    /// Unit direction of the follower's motion for S′ > 0.
    pub path: DVec2,
    /// The line dS/dφ is laid along (unit): ⊥ the path, along the rocker.
    pub along: DVec2,
    /// K, m.
    pub k: DVec2,
}

/// J: a quarter turn counter-clockwise.
pub fn jay(v: DVec2) -> DVec2 {
    DVec2::new(-v.y, v.x)
}

impl Placement {
    /// The follower at the motion `m` (fixed frame).
    pub fn kin(&self, m: Motion) -> Kin {
        let (b, b1, b2, path, along) = match *self {
            Placement::Translating { offset, s0 } => (
                DVec2::new(offset, s0 + m.s),
                DVec2::new(0.0, m.ds),
                DVec2::new(0.0, m.d2s),
                DVec2::Y,
                DVec2::X,
            ),
            Placement::Rocker {
                pivot,
                arm,
                psi0,
                sigma,
            } => {
                let psi = psi0 + sigma * m.s / arm;
                let e = DVec2::from_angle(psi);
                let je = jay(e);
                (
                    pivot + e * arm,
                    je * (sigma * m.ds),
                    je * (sigma * m.d2s) - e * (m.ds * m.ds / arm),
                    je * sigma,
                    e,
                )
            }
        };
        Kin {
            b,
            b1,
            b2,
            path,
            along,
            k: b + jay(b1),
        }
    }
}

impl Kin {
    /// The pressure angle λ: between the common normal (∥ OK) and the follower's motion, rad.
    pub fn pressure_angle(&self) -> f64 {
        let n = self.k;
        let c = (n.dot(self.path).abs() / n.length()).clamp(0.0, 1.0);
        c.acos()
    }
    /// The transmission angle γ = 90° − λ, rad.
    pub fn transmission_angle(&self) -> f64 {
        FRAC_PI_2 - self.pressure_angle()
    }
    /// The radius of curvature of the pitch curve, m: positive where convex (seen from O),
    /// negative where concave, infinite where straight.
    pub fn pitch_radius(&self) -> f64 {
        let u = self.b1 - jay(self.b);
        let w = self.b2 - jay(self.b1) * 2.0 - self.b;
        let cross = u.perp_dot(w);
        -u.length().powi(3) / cross
    }
    /// The outward unit normal of the pitch curve (fixed frame): along OK.
    pub fn normal(&self) -> DVec2 {
        self.k.normalize_or_zero()
    }
    /// The practical (roller) profile point in the fixed frame: B − r·n.
    pub fn roller_point(&self, r: f64) -> DVec2 {
        self.b - self.normal() * r
    }
}

/// A point of the fixed frame at cam angle φ in the cam's own frame (turned by −φ).
pub fn to_cam(p: DVec2, phi: f64) -> DVec2 {
    rotate(p, -phi)
}

/// The flat face's contact point (fixed frame) at r₀: (S′, r₀ + S), and its radius of
/// curvature r₀ + S + S″.
pub fn flat_contact(r0: f64, m: Motion) -> (DVec2, f64) {
    (DVec2::new(m.ds, r0 + m.s), r0 + m.s + m.d2s)
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

/// The rocker's arm and sense σ (+1: with the cam on the rise).
pub fn rocker_of(spec: &CamSpec) -> (f64, f64) {
    match spec.follower {
        Follower::Rocker { arm, same_sense } => (arm, if same_sense { 1.0 } else { -1.0 }),
        _ => (1.0, 1.0),
    }
}

/// True when a cam centre at `o` keeps γ ≥ γ_min at every constraint (K, rocker line), to a
/// relative slack `slack` of sin γ_min.
pub fn admits(o: DVec2, constraints: &[(DVec2, DVec2)], sin_g: f64, slack: f64) -> bool {
    constraints.iter().all(|&(k, e)| {
        let d = k - o;
        e.perp_dot(d).abs() >= (sin_g - slack) * d.length()
    })
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
    let u = k.b1 - jay(k.b);
    let w = k.b2 - jay(k.b1) * 2.0 - k.b;
    -u.perp_dot(w) / u.length().powi(3)
}

/// The smallest radius of curvature of the convex parts of the pitch curve over the whole
/// cycle (the largest admissible roller is just under it), and the most concave one (its
/// smallest |ρ|, `None` when the pitch curve is convex everywhere): the largest curvature
/// of each sign over every smooth piece (the dwells are arcs about O), every local maximum
/// refined, to rounding.
pub fn pitch_rho_min(spec: &CamSpec, place: &Placement) -> (f64, Option<f64>) {
    let all = pieces(spec, false);
    let kappa = |m: Motion| curvature(&place.kin(m));
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
    let (mut a, mut b) = (best_e - h, best_e + h);
    let g = 0.618_033_988_749_894_9;
    for _ in 0..60 {
        let (x1, x2) = (b - g * (b - a), a + g * (b - a));
        if r(x1) < r(x2) {
            b = x2;
        } else {
            a = x1;
        }
    }
    let e = 0.5 * (a + b);
    let v = r(e);
    if v < best_r {
        (v, e)
    } else {
        (best_r, best_e)
    }
}
