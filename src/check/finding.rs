//! Findings: the verdicts a domain reaches about its scene — a source's erratum, a limit
//! exceeded, a cusp, an undercut, rigid shocks, an offset on the wrong side, no flywheel
//! needed — as typed values carrying their numbers. The domains produce them, in their place
//! in a study's notes ([`super::notes`]); `report` writes their English (the one place it is
//! written), `sheets` their ru/uk/en lines through the word catalogue; tests match variants.
//! All numbers are SI (m, rad, kg·m²).

/// A verdict with its numbers.
#[derive(Debug, Clone, PartialEq)]
pub enum Finding {
    /// The source quotes the cam's r_min, inconsistent with its data; not used.
    Erratum {
        /// The value the source quotes, m.
        quoted: f64,
        /// The value that follows from the data, m.
        exact: f64,
        /// What it follows from.
        basis: RadiusBasis,
    },
    /// The worst angle over the cycle passes its limit at the base radius used.
    LimitExceeded {
        /// The angle limited.
        what: Limit,
        /// Its worst value over the cycle, rad.
        worst: f64,
        /// Its limit (λ_max or γ_min), rad.
        limit: f64,
        /// The base radius it was checked at.
        base: BaseUsed,
    },
    /// The profile comes to a point or loops back.
    Cusp(Cusp),
    /// The roller exceeds the pitch curve's smallest convex radius of curvature: the
    /// practical profile is cut away.
    Undercut {
        /// The roller radius, m.
        roller: f64,
        /// The pitch curve's smallest convex radius of curvature, m.
        rho_min: f64,
    },
    /// The law's velocity jumps at the phase's ends: rigid shocks.
    RigidShock {
        /// The phase's start, rad of cam turn.
        from: f64,
        /// The phase's end, rad of cam turn.
        to: f64,
        /// The jump of dS/dφ from 0, m.
        jump: f64,
    },
    /// The follower's offset is on the side that raises the pressure angle on the rise.
    WrongSide {
        /// The offset as the scene gives it, m.
        offset: f64,
        /// The largest pressure angle on the rise with it, rad.
        rise_max: f64,
        /// The offset on the other side of the centre, m.
        other_offset: f64,
        /// The largest pressure angle on the rise with that one, rad.
        other_max: f64,
    },
    /// The machine runs within the δ asked without a flywheel.
    NoFlywheelNeeded(NoFlywheel),
}

/// What an r_min follows from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RadiusBasis {
    /// A flat face: the profile convex, r₀ ≥ max(−(S + S″)) + ρ_min.
    Convexity {
        /// The least radius of curvature of the profile asked, m.
        rho_min: f64,
    },
    /// The transmission angle γ ≥ γ_min on the rise only (force closure).
    AngleOnRise {
        /// γ_min, rad.
        gamma_min: f64,
    },
    /// The transmission angle γ ≥ γ_min over the whole cycle.
    AngleOverCycle {
        /// γ_min, rad.
        gamma_min: f64,
    },
}

/// The angle whose limit a cam passes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Limit {
    /// The pressure angle above λ_max (translating follower).
    PressureAngle,
    /// The transmission angle below γ_min (rocker).
    TransmissionAngle,
}

/// The base radius a limit was checked at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BaseUsed {
    /// The scene's base radius.
    Given,
    /// Read off the combined diagram.
    Read {
        /// The diagram's points.
        points: usize,
        /// The base radius read and used, m.
        used: f64,
        /// The exact r_min, m.
        exact: f64,
    },
}

/// Where a profile comes to a point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cusp {
    /// A flat face: the profile concave, ρ = r₀ + S + S″ < 0.
    Flat {
        /// The least ρ, m (negative).
        rho: f64,
        /// The base radius r₀ used, m.
        base: f64,
        /// The least r₀ with a convex profile, m.
        r_min: f64,
    },
    /// The roller radius equals the pitch curve's smallest convex radius of curvature to
    /// 1e-12.
    Roller {
        /// The roller radius, m.
        roller: f64,
        /// The pitch curve's smallest convex radius of curvature, m.
        rho_min: f64,
    },
}

/// How a flywheel was found unnecessary.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NoFlywheel {
    /// The energy equation integrated exactly keeps δ within the δ asked without one.
    Exact {
        /// δ without a flywheel.
        delta: f64,
        /// δ asked.
        asked: f64,
    },
    /// A textbook route reads J ≤ 0.
    Reads {
        /// The route.
        route: Route,
        /// The J read, kg·m².
        read: f64,
    },
    /// Mertsalov's route on the continuous exact data gives J ≤ 0.
    Continuous {
        /// The J it gives, kg·m².
        j: f64,
    },
}

/// A textbook route to the flywheel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Route {
    /// Wittenbauer's diagram and its tangents.
    Wittenbauer,
    /// Mertsalov's T_I diagram.
    Mertsalov,
}
