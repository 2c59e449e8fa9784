//! The textbook symbol of a checked quantity ([`Symbol`]): the letter a row is named by, which
//! fixes the physical quantity and its SI unit. The checks name their rows by it (and
//! `check` passes it on to its callers); the catalogue writes it in the sheet's language
//! ([`quantity`](super::quantity)).

/// The textbook symbol of a checked quantity; it fixes the physical quantity and SI unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Symbol {
    /// Displacement S of a point along its path, m.
    Displacement,
    /// Velocity V of a point (or of one point relative to another), m/s.
    Velocity,
    /// Acceleration a of a point (or relative), m/s².
    Acceleration,
    /// Angular velocity ω of a link, rad/s.
    AngularVelocity,
    /// Angular acceleration ε of a link, rad/s².
    AngularAcceleration,
    /// A force (inertia force, balancing force, a load), N.
    Force,
    /// A reaction in a kinematic pair (force of one link on another), N.
    Reaction,
    /// A moment (balancing moment, inertia moment, a friction moment), N·m.
    Moment,
    /// A mass (a correcting mass), kg.
    Mass,
    /// A static moment of mass m·ρ (an unbalance), kg·m.
    StaticMoment,
    /// A moment of an unbalance about a plane, m·ρ·z, kg·m².
    UnbalanceMoment,
    /// A length read off a force drawing (an arm, a point of application, a radius), m.
    Length,
    /// An angle (a friction angle, the direction of a correcting mass), rad.
    Angle,
    /// An efficiency or another ratio, 1.
    Ratio,
    /// A power, W.
    Power,
    /// A moment of inertia (reduced to the crank, a flywheel's), kg·m².
    Inertia,
    /// A work, J.
    Work,
    /// A change of kinetic energy ΔT, J.
    EnergyChange,
    /// The coefficient of irregularity δ of a machine's speed, 1.
    Irregularity,
    /// The angle of engagement of a gear mesh (α_w), degrees as the textbook writes it.
    EngagementAngle,
    /// A centre distance (a_w), m.
    CentreDistance,
    /// A radius of a gear's circle (r_w, r_a, r_b, r_f), m.
    Radius,
    /// A tooth thickness on a circle (s, s_a), m.
    ToothThickness,
    /// A space width on a circle (e_t: between two teeth on the pitch circle), m.
    SpaceWidth,
    /// A pitch (p, p_b), m.
    Pitch,
    /// The centre-distance coefficient y of a shifted pair, 1.
    DistanceCoefficient,
    /// The equalising shift coefficient Δy of a shifted pair, 1.
    EqualisingShift,
    /// A contact ratio (ε_α), 1.
    ContactRatio,
    /// A specific sliding (λ₁, λ₂), 1.
    SpecificSliding,
    /// A shift coefficient (x_min), 1.
    ShiftCoefficient,
    /// The deviation of a drawn envelope from the exact one, m.
    EnvelopeDeviation,
    /// A gear ratio (u₁₋₈), 1, signed.
    GearRatio,
    /// A length along the line of action (N₁N₂, B₁B₂), m.
    ActionLength,
    /// The velocity analogue dS/dφ of a cam's follower, m (per radian).
    VelocityAnalogue,
    /// The acceleration analogue d²S/dφ² of a cam's follower, m (per radian²).
    AccelerationAnalogue,
    /// The pressure angle of a cam mechanism, rad.
    PressureAngle,
    /// The transmission angle of a cam mechanism, rad.
    TransmissionAngle,
    /// A radius of curvature ρ, m.
    CurvatureRadius,
    /// The radius vector of a cam's practical profile, m.
    ProfileRadius,
    /// The largest normal distance between a drawn profile and the exact one, m.
    ProfileDeviation,
    /// The largest residual of the moving links' equations of motion evaluated from the
    /// scene's loads and a route's reactions, relative to the largest force, 1.
    EquilibriumResidual,
    /// The power balance Σ P·v + Σ M·ω of the scene's loads, inertia, friction and a route's
    /// balancing load, relative to the sum of the powers' magnitudes, 1.
    PowerResidual,
}

impl Symbol {
    /// The name's prefix in reports: `s`, `v`, `a`, `omega`, `eps`.
    pub fn key(self) -> &'static str {
        match self {
            Symbol::Displacement => "s",
            Symbol::Velocity => "v",
            Symbol::Acceleration => "a",
            Symbol::AngularVelocity => "omega",
            Symbol::AngularAcceleration => "eps",
            Symbol::Force => "F",
            Symbol::Reaction => "R",
            Symbol::Moment => "M",
            Symbol::Mass => "m",
            Symbol::StaticMoment => "mr",
            Symbol::UnbalanceMoment => "mrz",
            Symbol::Length => "h",
            Symbol::Angle => "angle",
            Symbol::Ratio => "eta",
            Symbol::Power => "P",
            Symbol::Inertia => "J",
            Symbol::Work => "A",
            Symbol::EnergyChange => "dT",
            Symbol::Irregularity => "delta",
            Symbol::EngagementAngle => "alpha",
            Symbol::CentreDistance => "a",
            Symbol::Radius => "r",
            Symbol::ToothThickness => "s",
            Symbol::SpaceWidth => "e",
            Symbol::Pitch => "p",
            Symbol::DistanceCoefficient => "y",
            Symbol::EqualisingShift => "dy",
            Symbol::ContactRatio => "eps",
            Symbol::SpecificSliding => "lambda",
            Symbol::ShiftCoefficient => "x",
            Symbol::EnvelopeDeviation => "envelope",
            Symbol::GearRatio => "u",
            Symbol::ActionLength => "g",
            Symbol::VelocityAnalogue => "ds_dphi",
            Symbol::AccelerationAnalogue => "d2s_dphi2",
            Symbol::PressureAngle => "pressure_angle",
            Symbol::TransmissionAngle => "transmission_angle",
            Symbol::CurvatureRadius => "rho",
            Symbol::ProfileRadius => "profile_radius",
            Symbol::ProfileDeviation => "profile_deviation",
            Symbol::EquilibriumResidual => "equilibrium_residual",
            Symbol::PowerResidual => "power_residual",
        }
    }
    /// The SI unit as the report writes it.
    pub fn unit(self) -> &'static str {
        match self {
            Symbol::Displacement => "m",
            Symbol::Velocity => "m/s",
            Symbol::Acceleration => "m/s^2",
            Symbol::AngularVelocity => "rad/s",
            Symbol::AngularAcceleration => "rad/s^2",
            Symbol::Force | Symbol::Reaction => "N",
            Symbol::Moment => "N*m",
            Symbol::Mass => "kg",
            Symbol::StaticMoment => "kg*m",
            Symbol::UnbalanceMoment => "kg*m^2",
            Symbol::Length => "m",
            Symbol::Angle => "rad",
            Symbol::Ratio => "1",
            Symbol::Power => "W",
            Symbol::Inertia => "kg*m^2",
            Symbol::Work | Symbol::EnergyChange => "J",
            Symbol::Irregularity => "1",
            Symbol::EngagementAngle => "deg",
            Symbol::CentreDistance
            | Symbol::Radius
            | Symbol::ToothThickness
            | Symbol::SpaceWidth
            | Symbol::Pitch
            | Symbol::EnvelopeDeviation
            | Symbol::ActionLength => "m",
            Symbol::ContactRatio
            | Symbol::SpecificSliding
            | Symbol::ShiftCoefficient
            | Symbol::DistanceCoefficient
            | Symbol::EqualisingShift
            | Symbol::GearRatio => "1",
            Symbol::VelocityAnalogue | Symbol::AccelerationAnalogue => "m",
            Symbol::PressureAngle | Symbol::TransmissionAngle => "rad",
            Symbol::CurvatureRadius | Symbol::ProfileRadius | Symbol::ProfileDeviation => "m",
            Symbol::EquilibriumResidual | Symbol::PowerResidual => "1",
        }
    }
}
