//! The notes of a balancing study as typed values: a plane that needs no correcting mass,
//! each mass's inertia force against its weight, the erratum of seed 001's W4. Their English
//! is written by `report`.

/// A mass turning at ω: its inertia force against its weight.
#[derive(Debug, Clone, PartialEq)]
pub struct Inertia {
    /// The mass's number (from 1).
    pub index: usize,
    /// The mass, kg.
    pub mass: f64,
    /// Its radius, m.
    pub radius: f64,
    /// ω, rad/s.
    pub omega: f64,
    /// P = m·ω²·ρ, N.
    pub force: f64,
    /// G = m·g, N.
    pub weight: f64,
    /// g, m/s².
    pub g: f64,
}

/// A note of a balancing study.
#[derive(Debug, Clone, PartialEq)]
pub enum BalancingNote {
    /// A plane whose m·ρ is 0: no correcting mass.
    NoCorrection {
        /// The plane's name.
        plane: String,
    },
    /// One mass's inertia force and weight.
    Inertia(Inertia),
    /// Seed 001's W4 calls its ball's inertia force "900 times" its weight, true only for
    /// g = 10 m/s².
    W4Erratum(Inertia),
}
