//! The notes of a cam study as typed values carrying their numbers (SI: m, rad): each phase's
//! law and its shocks, the radius r_min against the diagram, the roller's choice, the angles
//! against their limits, the special profiles' frames, and every verdict ([`Finding`]) in its
//! place. Their English is written by `report`.

use crate::check::{BaseUsed, Cusp, Finding, Limit, RadiusBasis};

/// A phase of the cam's cycle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CamPhase {
    /// The rise.
    Rise,
    /// The return.
    Return,
}

/// A phase's law as the note names it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LawName {
    /// Constant acceleration "+ −" with the ratio of its two parts.
    ConstantAcceleration {
        /// The ratio.
        ratio: f64,
    },
    /// Any other law, by its scene key.
    Key(&'static str),
}

/// The shocks a phase's law gives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shocks {
    /// The velocity jumps by `jump` (dS/dφ, m) at the phase's ends: a
    /// [`Finding::RigidShock`].
    Rigid {
        /// The jump of dS/dφ from 0, m.
        jump: f64,
    },
    /// The acceleration jumps (finite).
    Soft,
    /// None.
    None,
}

/// The angle checked over the cycle against its limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngleCheck {
    /// The angle (pressure or transmission).
    pub what: Limit,
    /// Checked on the rise only (force closure); else over the cycle.
    pub on_rise: bool,
    /// Its worst value, rad.
    pub worst: f64,
    /// Its limit (λ_max or γ_min), rad.
    pub limit: f64,
    /// Where it passes its limit: the base radius it was checked at.
    pub exceeded: Option<BaseUsed>,
}

/// A note of a cam study.
#[derive(Debug, Clone, PartialEq)]
pub enum CamNote {
    /// It turns clockwise: constructed as its mirror image.
    Mirrored,
    /// A phase's law and its shocks.
    Law {
        /// The phase.
        phase: CamPhase,
        /// Its start, rad of cam turn.
        from: f64,
        /// Its end, rad of cam turn.
        to: f64,
        /// The law.
        law: LawName,
        /// Its shocks.
        shocks: Shocks,
    },
    /// The source's diagrams are lost: the laws (scene keys) are assumed.
    LawAssumed {
        /// The rise's law.
        rise: &'static str,
        /// The return's law.
        ret: &'static str,
    },
    /// The equal-return check read off the diagrams.
    EqualReturn {
        /// dS/dφ at the end of the rise and of the return, m.
        ends: [f64; 2],
        /// S at the end of the rise, m.
        top: f64,
        /// The stroke, m.
        stroke: f64,
    },
    /// r_min exact (and what it follows from) against the one read off the combined diagram.
    RMin {
        /// Exact, m.
        exact: f64,
        /// What it follows from.
        basis: RadiusBasis,
        /// Read, m.
        read: f64,
        /// The diagram's points.
        points: usize,
    },
    /// A verdict on its own.
    Found(Finding),
    /// A flat face: the convexity's worst value, exact and read at the 45° tangent, m.
    FlatConvexity {
        /// Exact, m.
        exact: f64,
        /// Read, m.
        read: f64,
    },
    /// A flat face's least half-length from the follower's axis, m.
    FlatHalfLength(f64),
    /// The worst angle against its limit.
    Angle(AngleCheck),
    /// The roller's choice.
    Roller {
        /// r₀, m.
        base: f64,
        /// ρ_min of the drawn pitch curve, m.
        drawn: f64,
        /// ρ_min exact, m.
        exact: f64,
        /// The roller radius, m.
        roller: f64,
        /// The scene gives it (else chosen).
        given: bool,
    },
    /// The smallest cam with the offset free against the scene's offset.
    OffsetFree {
        /// Its r_min, m.
        r_min: f64,
        /// Its offset, m.
        offset: f64,
        /// The scene's offset, m.
        scene_offset: f64,
        /// r_min with it, m.
        scene_r_min: f64,
    },
    /// A special profile's (a flat-faced rocker's, a translating cam's).
    Special(SpecialNote),
}

/// A note of a flat-faced rocker or a translating cam.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SpecialNote {
    /// A flat-faced rocker's frame.
    RockerFrame {
        /// The centre distance a, m.
        centres: f64,
        /// The face's offset e, m.
        face_offset: f64,
        /// r₀, m.
        base: f64,
        /// The face's start ψ₀, rad.
        psi0: f64,
    },
    /// A flat-faced rocker's smallest radius of curvature, exact and read, m.
    RockerCurvature {
        /// Exact, m.
        exact: f64,
        /// Read off the face lines' crossings, m.
        read: f64,
        /// The points.
        points: usize,
    },
    /// A flat-faced rocker's largest pressure angle at the points, rad.
    RockerAngle(f64),
    /// A flat-faced rocker's profile sharper than asked.
    Concave {
        /// Its ρ_min, m.
        rho: f64,
        /// The ρ_min asked, m.
        asked: f64,
    },
    /// A translating cam's frame.
    Sliding {
        /// The travel X, m.
        travel: f64,
        /// The roller radius, m.
        roller: f64,
    },
    /// A translating cam's largest pressure angle and its shortest travel.
    SlidingAngle {
        /// The largest pressure angle at the points, rad.
        worst: f64,
        /// λ_max, rad.
        lambda_max: f64,
        /// X_min exact, m.
        exact: f64,
        /// X_min from the drawn angles, m.
        read: f64,
    },
    /// A translating cam's travel shorter than X_min.
    ShortTravel {
        /// The travel X, m.
        travel: f64,
        /// X_min, m.
        x_min: f64,
        /// λ_max, rad.
        lambda_max: f64,
    },
    /// A translating cam's pitch curve's smallest convex radius of curvature.
    SlidingCurvature {
        /// Exact, m.
        exact: f64,
        /// Through three drawn roller centres, m.
        read: f64,
    },
}

impl From<Cusp> for CamNote {
    fn from(c: Cusp) -> CamNote {
        CamNote::Found(Finding::Cusp(c))
    }
}

impl CamNote {
    /// The verdict this note states, if any.
    pub fn finding(&self) -> Option<Finding> {
        match *self {
            CamNote::Found(ref f) => Some(f.clone()),
            CamNote::Law {
                from,
                to,
                shocks: Shocks::Rigid { jump },
                ..
            } => Some(Finding::RigidShock { from, to, jump }),
            CamNote::Angle(AngleCheck {
                what,
                worst,
                limit,
                exceeded: Some(base),
                ..
            }) => Some(Finding::LimitExceeded {
                what,
                worst,
                limit,
                base,
            }),
            _ => None,
        }
    }
}

/// The verdicts of a list of notes, in order.
pub fn findings(notes: &[CamNote]) -> Vec<Finding> {
    notes.iter().filter_map(CamNote::finding).collect()
}
