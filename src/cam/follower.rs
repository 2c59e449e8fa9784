//! The follower's geometry, the primitives both routes share: where the follower stands
//! (its placement about the cam centre), its point B with the φ-derivatives and the point K
//! of the combined diagram, the pressure / transmission angle at one position, the turn into
//! the cam's frame, the flat face's contact, and the γ_min condition on a cam centre. They
//! take a motion (S, S′, S″) from whichever route calls them: the construction's values read
//! off its diagrams, the twin's closed forms.

use super::motion::FollowerMotion;
use super::{CamSpec, Follower, RockerSense};
use crate::geom::{rotate, DVec2};
use std::f64::consts::FRAC_PI_2;

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

/// The reach of the search for a rocker cam's centre, in arms: no centre farther than this
/// from A₀ is looked for (on the drawing or by the twin).
pub const REACH_ARMS: f64 = 20.0;

/// J: a quarter turn counter-clockwise.
pub fn jay(v: DVec2) -> DVec2 {
    DVec2::new(-v.y, v.x)
}

impl Placement {
    /// The follower at the motion `m` (fixed frame).
    pub fn kin(&self, m: FollowerMotion) -> Kin {
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
pub fn flat_contact(r0: f64, m: FollowerMotion) -> (DVec2, f64) {
    (DVec2::new(m.ds, r0 + m.s), r0 + m.s + m.d2s)
}

/// The rocker's arm and sense σ (+1: with the cam on the rise).
pub fn rocker_of(spec: &CamSpec) -> (f64, f64) {
    match spec.follower {
        Follower::Rocker { arm, sense } => (
            arm,
            match sense {
                RockerSense::Same => 1.0,
                RockerSense::Opposite => -1.0,
            },
        ),
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
