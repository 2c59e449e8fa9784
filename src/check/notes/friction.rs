//! The notes of the friction studies as typed values: each case's comparison with the
//! textbook's formula, the seed's errata, self-braking and self-locking. Their English is
//! written by `report`.

/// How a slider moves under an inclined force.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SliderMotion {
    /// It stays.
    Rest,
    /// It moves uniformly.
    Uniform,
    /// It accelerates.
    Accelerating,
}

/// How rollers under a load move.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RollerMotion {
    /// Pure rolling.
    Rolling,
    /// The load slides on the rollers: P = Q·f₁.
    OnRollers {
        /// P, N.
        p: f64,
        /// P rolling would take, N.
        rolling: f64,
    },
    /// The load slides on the plane with them: P = (Q + 2G)·f₂.
    OnPlane {
        /// P, N.
        p: f64,
        /// P rolling would take, N.
        rolling: f64,
    },
}

/// A note of a friction case; `case` is the case's name.
#[derive(Debug, Clone, PartialEq)]
pub enum FrictionNote {
    /// A follower in its guide: it moves while λ < λ_кр; the useful and the guide's part of P.
    Guide {
        /// The case.
        case: String,
        /// λ, rad.
        angle: f64,
        /// λ_кр, rad.
        lock: f64,
        /// P·cos λ, N.
        useful: f64,
        /// P·sin λ, N.
        across: f64,
    },
    /// A body on an incline: the twin's formula, the seed's erratum.
    InclineErratum {
        /// The case.
        case: String,
        /// Up the plane (else down).
        up: bool,
    },
    /// A body on an incline is self-braking.
    SelfBraking {
        /// The case.
        case: String,
        /// α, rad.
        alpha: f64,
        /// φ, rad.
        phi: f64,
    },
    /// A journal: the friction circle against the textbook's ρ = f·r.
    Journal {
        /// The case.
        case: String,
        /// ρ = r·sin φ, m.
        rho: f64,
        /// ρ = f·r, m.
        textbook: f64,
        /// M_f = f·Q·r, N·m.
        moment: f64,
    },
    /// A rocker on its pivot: it moves while λ < λ_кр; the lecture's λ_кр.
    Pivot {
        /// The case.
        case: String,
        /// λ, rad.
        angle: f64,
        /// λ_кр, rad.
        lock: f64,
        /// ρ = (d/2)·sin φ, m.
        rho: f64,
        /// The lecture's λ_кр, rad.
        lecture: f64,
    },
    /// Rollers: k/d against f at each contact, and how they move.
    Rolling {
        /// The case.
        case: String,
        /// k₁/d and f₁.
        first: (f64, f64),
        /// k₂/d and f₂.
        second: (f64, f64),
        /// How they move.
        motion: RollerMotion,
    },
    /// Rollers: the seed's misprinted R_n2, the rollers' gain.
    RollingErratum {
        /// The case.
        case: String,
        /// R_n2 = Q + 2G, N.
        r_n2: f64,
        /// P without rollers over P with them.
        gain: f64,
    },
    /// A screw as an inclined plane; the seed's false substitution.
    ScrewErratum {
        /// The case.
        case: String,
        /// Raising the load (else lowering).
        up: bool,
    },
    /// A screw is self-locking.
    SelfLocking {
        /// The case.
        case: String,
        /// λ, rad.
        lead: f64,
        /// φ′, rad.
        phi: f64,
    },
    /// A slider under an inclined force: its motion by the angles and by the triangle.
    Slider {
        /// The case.
        case: String,
        /// α, rad.
        alpha: f64,
        /// φ, rad.
        phi: f64,
        /// φ₀, rad.
        phi0: f64,
        /// By the angles.
        by_angles: SliderMotion,
        /// By the triangle.
        by_triangle: SliderMotion,
        /// ΔP read, N.
        net: f64,
    },
}
