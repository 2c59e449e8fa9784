//! A constructed velocity or acceleration plan ([`KinPlan`]) and what is read off it
//! ([`PlanReading`], [`Measure`]).

use crate::construct::Figure;
use crate::geom::DVec2;

/// Which plan.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlanKind {
    /// Velocities, pole `p`.
    Velocity,
    /// Accelerations, pole `π`.
    Acceleration,
}

/// A value read off a plan.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanReading {
    /// Quantity name (`v_D`, `v_B3_B1`, `omega_3`, `a_S5`, `eps_3`).
    pub quantity: String,
    /// What was read, structurally (for the analytic twin).
    pub what: Measure,
    /// The physical value (magnitudes for point quantities; ω, ε signed, counter-clockwise
    /// positive).
    pub value: f64,
    /// Crossing angle of the intersection that fixed it, degrees (None: not an intersection).
    pub conditioning: Option<f64>,
}

/// What a reading measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Measure {
    /// The absolute velocity (acceleration) of a point, by program index: a magnitude.
    Point(usize),
    /// The angular velocity (acceleration) of a link, signed counter-clockwise.
    Rate(usize),
    /// The absolute velocity (acceleration) of the point of link `.1` under point `.0` — the
    /// coincident point of a sliding pair (`B3`: link 3's point under B): a magnitude.
    Carried(usize, usize),
    /// The velocity (acceleration) of point `p.0` carried by link `p.1` relative to point
    /// `q.0` carried by link `q.1`: a magnitude.
    Relative {
        /// (point, link) of the moving point.
        p: (usize, usize),
        /// (point, link) of the reference point.
        q: (usize, usize),
    },
}

/// A constructed plan.
#[derive(Debug, Clone, PartialEq)]
pub struct KinPlan {
    /// Which plan.
    pub kind: PlanKind,
    /// The recorded figure (pole at the origin), at `scale`.
    pub figure: Figure,
    /// Image of every point by program index, plan mm.
    pub images: Vec<DVec2>,
    /// Images of coincident points of sliding pairs (`B3`: point of link 3 under B).
    pub coincident: Vec<(String, DVec2)>,
    /// Angular velocity (velocity plan) or acceleration (acceleration plan) of every link,
    /// as read off the plan, signed counter-clockwise.
    pub rate: Vec<f64>,
    /// The readings.
    pub readings: Vec<PlanReading>,
}
