//! Cam mechanisms (lectures 13–18 of seed 001, PZ4–PZ5 of seed 002, §3 of seed 000): the
//! follower's motion law per phase, its diagrams by graphical integration, the minimum cam
//! radius from the combined diagram (translating roller or knife edge, rocker) or from
//! convexity (flat face), the profile by inversion, and the pressure / transmission angle.
//!
//! Every procedure exists twice: a construction through the recorder (the diagrams
//! integrated with the chord/pole method of [`crate::calculus`], the combined diagram with
//! its γ_min lines and zone, the inverted follower positions with the roller circles or the
//! face lines and their envelope) and an analytic twin ([`exact`] and `centre`: the minimum
//! radius over the whole cycle, the pitch curve's curvature; the exact envelope and angles in
//! [`Cam::rows`], which compares them). They share only the given law ([`motion`]) and the
//! follower's primitives ([`follower`]): the construction builds the profile on the r₀ it
//! accepts from the r_min read off its own drawing (`accept`; or on the scene's base
//! radius) and never calls the twin.
//!
//! Frame: the cam turns counter-clockwise about O at the origin; in the inverted motion the
//! follower turns clockwise (by −φ). A translating follower moves along +y, its axis at
//! x = e (e > 0 is the side that lowers the pressure angle on the rise). A rocker's pivot O₂
//! is placed by the minimum-radius construction.

mod accept;
mod centre;
mod combined;
mod construct;
mod deviation;
mod diagrams;
pub mod exact;
pub mod extremum;
pub mod flat_rocker;
pub mod follower;
pub mod force;
mod inversion;
mod law;
pub mod motion;
mod radius;
mod reading;
mod rows;
pub mod sliding;
pub mod special;
mod special_rows;
#[cfg(test)]
mod tests;
mod travel;
mod zone;

pub(crate) use construct::roller_bound;
pub use construct::ANGLE_LIMIT_NOTE;
pub use construct::{build, Cam, Raised};
pub use deviation::{deviation, deviation_at, inversion_at};
pub use diagrams::{Analogue, CamDiagrams, PHASE_NOTES, POLES, TICK_NOTE};
pub use inversion::Inversion;
pub use law::{Law, Shock};
pub use radius::{RadiusConstruction, A_W_NOTE, RHO_ADMITTED, RHO_MIN_NOTE, TANGENT_NOTE};
pub use special::{build_special, Special, SpecialProfile};
pub use travel::{TravelConstruction, TRAVEL_NOTE, TRAVEL_RAY_NOTE};
pub use zone::{E_LINE_NOTE, E_NOTE, R0_NOTE, RAY_NOTE, R_MIN_NOTE};

use crate::scale::Scale;
use thiserror::Error;

/// The four phases (rise, far dwell, return, near dwell), radians; they sum to 2π.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Phases {
    /// φ_у, the rise.
    pub rise: f64,
    /// φ_д.в., the far dwell.
    pub far: f64,
    /// φ_п, the return.
    pub ret: f64,
    /// φ_б.в., the near dwell.
    pub near: f64,
}

/// The follower.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Follower {
    /// A translating follower with a roller (or a knife edge), its axis offset by `offset`
    /// (m, signed; > 0: the favourable side for the rise).
    Translating {
        /// e, m.
        offset: f64,
    },
    /// An oscillating (rocker) roller follower of arm `arm` (m); S = arm·β.
    Rocker {
        /// L, m.
        arm: f64,
        /// The rocker's sense on the rise against the cam's.
        sense: RockerSense,
    },
    /// A translating flat-faced follower (the face ⊥ its axis), axis offset `offset` (m).
    Flat {
        /// e, m (it does not change the profile).
        offset: f64,
    },
}

/// A cam task, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct CamSpec {
    /// The phases.
    pub phases: Phases,
    /// The law of the rise.
    pub rise: Law,
    /// The law of the return.
    pub ret: Law,
    /// The stroke S_max, m (for a rocker the arc arm·β_max).
    pub stroke: f64,
    /// The follower.
    pub follower: Follower,
    /// The roller radius, m: `Some(0)` a knife edge, `None` chosen as
    /// min(0.4·r_min, 0.8·ρ_min). Not used by a flat face.
    pub roller: Option<f64>,
    /// γ_min, rad (the pressure angle ≤ 90° − γ_min); a flat face's is unused.
    pub gamma_min: f64,
    /// ρ_min of a flat-faced cam's profile (the margin over convexity), m.
    pub rho_min: f64,
    /// The base (minimum) radius r₀ of the pitch curve, m; `None`: the minimum found.
    pub base_radius: Option<f64>,
    /// Equal intervals of the rise and of the return (the diagrams' and the inversion's
    /// points); a given d²S/dφ² that breaks between them gets a division point on each break
    /// too ([`motion::divisions`]).
    pub divisions: usize,
    /// μ_S of the diagrams (m/mm); `None`: chosen for a stroke drawn at most 100 mm.
    pub scale_s: Option<Scale>,
    /// μ_l of the profile (m/mm); `None`: chosen for a largest radius drawn at most 160 mm,
    /// coarser until the profile's drawing fits 240 × 240 mm.
    pub scale_l: Option<Scale>,
    /// μ_φ of the diagrams (rad/mm); `None`: a 240 mm cycle (1,5°/mm).
    pub scale_phi: Option<Scale>,
    /// The pole distances H₁ (d²S → dS) and H₂ (dS → S), mm; `None`: chosen so that the
    /// analogues' peaks are drawn about 65 mm tall.
    pub poles: Option<[f64; 2]>,
    /// The source lost its diagrams: the law is assumed (said on the plate).
    pub law_assumed: bool,
    /// An r_min quoted by the source, m, to be checked against (never matched).
    pub quoted_r_min: Option<f64>,
    /// How the follower is kept on the cam (`closure`).
    pub closure: Closure,
    /// What the scene gives the motion by (`given`).
    pub given: Given,
    /// The cam's sense of rotation (`rotation`).
    pub rotation: Rotation,
    /// The mechanism's layout: the turning cam of [`build`], or one of the two cams built by
    /// their own modules ([`special`]).
    pub layout: CamLayout,
}

/// The cam mechanism's layout (`follower = "flat_rocker"`, `travel`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CamLayout {
    /// The cam turns about O₁ and drives the `follower` ([`build`]).
    Turning,
    /// The cam turns and the rocker (the spec's follower) carries a flat face
    /// ([`flat_rocker`]).
    FlatRocker(flat_rocker::FlatRocker),
    /// The cam slides along its guide and drives a translating roller follower across it
    /// ([`sliding`]).
    Sliding(sliding::Sliding),
}

/// How the follower is kept on the cam (`closure = "geometric" | "force"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Closure {
    /// Geometric closure (a groove): the pressure angle is checked over the whole cycle.
    Geometric,
    /// Force (spring) closure: the pressure angle is checked on the rise only (seed 002,
    /// L1477).
    Force,
}

/// What the scene gives the motion by (`given = "d2s" | "s"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Given {
    /// d²S/dφ², integrated twice.
    D2s,
    /// S, differentiated twice by chords.
    S,
}

/// The cam's sense of rotation (`rotation = "ccw" | "cw"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rotation {
    /// Counter-clockwise: the model's own sense.
    Ccw,
    /// Clockwise: constructed as its mirror image, a counter-clockwise cam with the offset on
    /// the other side, and drawn mirrored back.
    Cw,
}

/// A rocker's sense on the rise (`sense = "same" | "opposite"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RockerSense {
    /// The rocker turns on the rise in the cam's sense (the seed's rule: dS/dφ laid towards
    /// the pivot on the rise).
    Same,
    /// Against the cam's sense.
    Opposite,
}

impl CamSpec {
    /// The phase starts φ₀ of rise, far dwell, return, near dwell and the end 2π.
    pub fn starts(&self) -> [f64; 5] {
        let p = &self.phases;
        [
            0.0,
            p.rise,
            p.rise + p.far,
            p.rise + p.far + p.ret,
            p.rise + p.far + p.ret + p.near,
        ]
    }
    /// The rocker's arm, when the follower is a rocker.
    pub fn arm(&self) -> Option<f64> {
        match self.follower {
            Follower::Rocker { arm, .. } => Some(arm),
            _ => None,
        }
    }
    /// Whether the angle at drawn point `p` limits the cam (its r_min, its check): every
    /// point under geometric closure, the rise's alone under force closure (the spring drives
    /// the return). The construction's decision; the twin ([`exact`]) makes its own.
    pub fn binds(&self, p: &motion::Point) -> bool {
        self.closure == Closure::Geometric || p.phase == 0
    }
    /// Whether its angle graph and tables show the transmission angle γ (a rocker), not the
    /// pressure angle λ (a translating or flat follower).
    pub fn shows_transmission_angle(&self) -> bool {
        self.arm().is_some()
    }
    /// The stroke's symbol on its sheet and in the note: a rocker's arc S_max = Lβ_max, a
    /// translating follower's h.
    pub fn stroke_symbol(&self) -> &'static str {
        if self.arm().is_some() {
            "S_{max}"
        } else {
            "h"
        }
    }
    /// The angle its graph and tables show: the rocker's transmission angle γ, a translating
    /// or flat follower's pressure angle λ.
    pub fn angle_symbol(&self) -> &'static str {
        if self.shows_transmission_angle() {
            "γ"
        } else {
            "λ"
        }
    }
    /// The limit of that angle: γ_min for a rocker, λ_max = 90° − γ_min otherwise.
    pub fn angle_limit_symbol(&self) -> &'static str {
        if self.shows_transmission_angle() {
            "γ_{min}"
        } else {
            "λ_{max}"
        }
    }
    /// That limit's value: γ_min, or 90° − γ_min.
    pub fn angle_limit(&self) -> f64 {
        if self.shows_transmission_angle() {
            self.gamma_min
        } else {
            std::f64::consts::FRAC_PI_2 - self.gamma_min
        }
    }
    /// The follower's offset e (0 for a rocker).
    pub fn offset(&self) -> f64 {
        match self.follower {
            Follower::Translating { offset } | Follower::Flat { offset } => offset,
            Follower::Rocker { .. } => 0.0,
        }
    }
}

/// Why a cam cannot be constructed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CamError {
    /// The graphical integration failed.
    #[error("cam: {0}")]
    Calculus(#[from] crate::calculus::CalculusError),
    /// No centre of the cam satisfies γ ≥ γ_min within the search.
    #[error(
        "cam: no cam centre keeps the transmission angle ≥ {gamma_deg:.1}° (searched up to \
         r = {searched:.4} m)"
    )]
    NoCentre {
        /// γ_min, degrees.
        gamma_deg: f64,
        /// The largest radius searched, m.
        searched: f64,
    },
    /// The roller is not smaller than the base radius.
    #[error(
        "cam: the roller radius {roller:.5} m is not smaller than the base radius {base:.5} m"
    )]
    RollerTooLarge {
        /// r_р, m.
        roller: f64,
        /// r₀, m.
        base: f64,
    },
    /// The given base radius is not larger than the offset.
    #[error("cam: the base radius {base:.5} m must exceed the offset |e| = {offset:.5} m")]
    BaseWithinOffset {
        /// r₀, m.
        base: f64,
        /// |e|, m.
        offset: f64,
    },
    /// No round drawing scale can be chosen.
    #[error("cam: no drawing scale {what} can be chosen for the size {size}", size = crate::scale::format_plain(*size))]
    NoScale {
        /// The scale.
        what: &'static str,
        /// The size, SI.
        size: f64,
    },
    /// The flat-faced rocker cannot be made (boxed: a construction's error is large).
    #[error(transparent)]
    FlatRocker(Box<flat_rocker::FlatRockerError>),
    /// The translating cam cannot be made.
    #[error(transparent)]
    Sliding(Box<sliding::SlidingError>),
    /// A builder was handed a layout it does not make (a defect of the caller).
    #[error("cam: {0}")]
    Layout(&'static str),
}

impl From<flat_rocker::FlatRockerError> for CamError {
    fn from(e: flat_rocker::FlatRockerError) -> Self {
        CamError::FlatRocker(Box::new(e))
    }
}

impl From<sliding::SlidingError> for CamError {
    fn from(e: sliding::SlidingError) -> Self {
        CamError::Sliding(Box::new(e))
    }
}
