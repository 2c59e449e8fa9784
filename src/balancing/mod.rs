//! Balancing of rotating masses (lecture 19 of seed 001): static balancing of a thin rotor
//! by the plan of static moments, and complete (dynamic) balancing of a long rotor in two
//! correction planes by the polygon of moments and the polygon of static moments.
//!
//! Every unbalanced mass mᵢ at the radius vector ρᵢ carries the inertia force
//! `Pᵢ = mᵢ·ω²·ρᵢ` (along ρᵢ), so the measure of the unbalance is the *static moment* `mᵢρᵢ`
//! (a vector, kg·m). Balancing asks for the main vector and the main moment of the inertia
//! forces to vanish:
//!
//! * static (a thin rotor: gear, pulley, flywheel): `Σ mᵢρᵢ + m_уρ_у = 0` — the vectors mᵢρᵢ
//!   laid head to tail at μ_mρ (the textbook's K_mρ), the closing vector is m_уρ_у; with the
//!   chosen radius ρ_у, `m_у = |m_уρ_у| / ρ_у` in the direction of the closing vector;
//! * dynamic (a long rotor, two correction planes I and II at z_I, z_II): the moment centre
//!   in plane I, `Σ mᵢρᵢ(zᵢ − z_I) + U_II(z_II − z_I) = 0` — the polygon of moments closes to
//!   the correction of plane II — and then `Σ mᵢρᵢ + U_II + U_I = 0` — the polygon of static
//!   moments with U_II closes to the correction of plane I (U = m_уρ_у of each plane).
//!
//! The construction (`construct`) lays the vectors through the recorder and reads the
//! closing vectors off the drawing under the drafting model (the length with a ruler, the
//! direction from its two projections); the analytic twin ([`analytic`]) sums the vectors in
//! closed form; [`Balancing::rows`] compares them.

mod construct;
mod rotor;
mod rows;
#[cfg(test)]
mod tests;

pub use construct::{balance, Balancing, ClosingVector};
pub use rows::{inertia_force, inertia_notes, w4_erratum, W4};

use crate::geom::DVec2;
use crate::scale::Scale;
use thiserror::Error;

/// One unbalanced mass of a rotor, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mass {
    /// The mass, kg (> 0).
    pub mass: f64,
    /// Its distance from the axis of rotation, m (> 0).
    pub radius: f64,
    /// The direction of its radius vector, radians counter-clockwise from +x of the rotor's
    /// end view.
    pub angle: f64,
    /// The axial position of its plane, m (0 for a thin rotor).
    pub z: f64,
}

impl Mass {
    /// Its static moment mρ as a vector in the plane of rotation, kg·m.
    pub fn static_moment(&self) -> DVec2 {
        DVec2::from_angle(self.angle) * (self.mass * self.radius)
    }
}

/// Which balancing, with the correction radii chosen by the designer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Correction {
    /// Static balancing of a thin rotor: one correcting mass at `radius`, m.
    Static {
        /// ρ_у, m.
        radius: f64,
    },
    /// Complete (dynamic) balancing of a long rotor in two correction planes.
    Dynamic {
        /// Axial positions z_I, z_II of the correction planes, m (distinct).
        planes: [f64; 2],
        /// The radii of the correcting masses in planes I and II, m.
        radii: [f64; 2],
    },
}

/// A balancing task: the masses, the correction and the drawing's choices.
#[derive(Debug, Clone, PartialEq)]
pub struct BalancingSpec {
    /// The unbalanced masses (at least one).
    pub masses: Vec<Mass>,
    /// The kind of balancing and the correction radii.
    pub correction: Correction,
    /// The angular velocity of the rotor, rad/s, when the inertia forces are wanted.
    pub omega: Option<f64>,
    /// μ_mρ of the polygon of static moments, kg·m/mm; `None`: chosen the textbook way.
    pub scale_mr: Option<Scale>,
    /// μ_mρz of the polygon of moments, kg·m²/mm; `None`: chosen the textbook way.
    pub scale_mrz: Option<Scale>,
    /// μ_l of the rotor drawing, m/mm; `None`: chosen the textbook way.
    pub scale_l: Option<Scale>,
}

/// The correction plane a correcting mass is placed in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Plane {
    /// The plane of a thin rotor (static balancing): the textbook's m_у.
    Disc,
    /// Correction plane I (the moment centre of the dynamic balancing).
    First,
    /// Correction plane II.
    Second,
}

impl Plane {
    /// The subject in report keys: `y` (the textbook's у), `I`, `II`.
    pub fn subject(self) -> &'static str {
        match self {
            Plane::Disc => "y",
            Plane::First => "I",
            Plane::Second => "II",
        }
    }
    /// The index of the correcting mass in label markup: `у`, `уI`, `уII`.
    pub fn index(self) -> &'static str {
        match self {
            Plane::Disc => "у",
            Plane::First => "уI",
            Plane::Second => "уII",
        }
    }
}

/// One correcting mass: its plane, static moment and the mass at its chosen radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Corrective {
    /// Its plane.
    pub plane: Plane,
    /// Its axial position, m (0 for a thin rotor).
    pub z: f64,
    /// Its static moment U = m_уρ_у, kg·m.
    pub unbalance: DVec2,
    /// Its chosen radius ρ_у, m.
    pub radius: f64,
}

impl Corrective {
    /// The correcting mass m_у = |U| / ρ_у, kg.
    pub fn mass(&self) -> f64 {
        self.unbalance.length() / self.radius
    }
    /// The direction of its radius vector, radians in [0, 2π); `None` when no correction is
    /// needed (U = 0).
    pub fn angle(&self) -> Option<f64> {
        (self.unbalance != DVec2::ZERO).then(|| {
            self.unbalance
                .y
                .atan2(self.unbalance.x)
                .rem_euclid(std::f64::consts::TAU)
        })
    }
    /// As a mass of the rotor.
    pub fn as_mass(&self) -> Mass {
        Mass {
            mass: self.mass(),
            radius: self.radius,
            angle: self.angle().unwrap_or(0.0),
            z: self.z,
        }
    }
}

/// Why a balancing cannot be carried out.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BalancingError {
    /// The rotor has no mass to balance.
    #[error("balancing: the rotor has no unbalanced mass")]
    NoMasses,
    /// No round drawing scale can be formed for a size.
    #[error("balancing: no drawing scale {what} can be chosen for the size {size}")]
    NoScale {
        /// The scale (`μ_mρ`).
        what: &'static str,
        /// The size it was to draw.
        size: f64,
    },
}

/// The main vector Σ mᵢρᵢ of the static moments of `masses`, kg·m (the main vector of their
/// inertia forces divided by ω²).
pub fn main_vector(masses: &[Mass]) -> DVec2 {
    masses.iter().map(Mass::static_moment).sum()
}

/// The main moment Σ mᵢρᵢ(zᵢ − z₀) of the static moments of `masses` about the plane at `z0`,
/// kg·m² (a vector in the plane of rotation; the moment of the inertia forces is ω² times it,
/// turned by 90°, and has the same magnitude).
pub fn main_moment(masses: &[Mass], z0: f64) -> DVec2 {
    masses.iter().map(|m| m.static_moment() * (m.z - z0)).sum()
}

/// The analytic twin: the correcting static moments in closed form.
///
/// Static: `U = −Σ mᵢρᵢ`. Dynamic: `U_II = −Σ mᵢρᵢ(zᵢ − z_I)/(z_II − z_I)`,
/// `U_I = −Σ mᵢρᵢ − U_II`.
///
/// A correction that is zero to rounding against the static moments' scale Σ|mᵢρᵢ|
/// ([`crate::check::is_zero`]) is returned as exactly zero: that plane needs no mass.
pub fn analytic(spec: &BalancingSpec) -> Vec<Corrective> {
    let mut out = closed_form(spec);
    let scale: f64 = spec.masses.iter().map(|m| m.mass * m.radius).sum();
    for c in &mut out {
        if crate::check::is_zero(c.unbalance.length(), scale) {
            c.unbalance = DVec2::ZERO;
        }
    }
    out
}

/// The closed form of [`analytic`], unrounded.
fn closed_form(spec: &BalancingSpec) -> Vec<Corrective> {
    let sum = main_vector(&spec.masses);
    match spec.correction {
        Correction::Static { radius } => vec![Corrective {
            plane: Plane::Disc,
            z: 0.0,
            unbalance: -sum,
            radius,
        }],
        Correction::Dynamic { planes, radii } => {
            let u2 = -main_moment(&spec.masses, planes[0]) / (planes[1] - planes[0]);
            vec![
                Corrective {
                    plane: Plane::First,
                    z: planes[0],
                    unbalance: -sum - u2,
                    radius: radii[0],
                },
                Corrective {
                    plane: Plane::Second,
                    z: planes[1],
                    unbalance: u2,
                    radius: radii[1],
                },
            ]
        }
    }
}

/// The main vector of the corrected rotor, Σ mᵢρᵢ + Σ U, kg·m: zero when balanced.
pub fn residual_vector(masses: &[Mass], corrections: &[Corrective]) -> DVec2 {
    main_vector(masses) + corrections.iter().map(|c| c.unbalance).sum::<DVec2>()
}

/// The main moment of the corrected rotor about the plane at `z0`,
/// Σ mᵢρᵢ(zᵢ − z₀) + Σ U(z − z₀), kg·m²: zero when completely balanced.
pub fn residual_moment(masses: &[Mass], corrections: &[Corrective], z0: f64) -> DVec2 {
    main_moment(masses, z0)
        + corrections
            .iter()
            .map(|c| c.unbalance * (c.z - z0))
            .sum::<DVec2>()
}
