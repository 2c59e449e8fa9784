//! The notes of the dynamics as typed values carrying their numbers (SI): the exact
//! solution, the textbook routes against it, a seed's numbers that do not follow from its
//! data. Their English is written by `report`.

use crate::check::{Finding, NoFlywheel};

/// A flywheel found: its moment of inertia, or none needed (the verdict).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Flywheel<T> {
    /// A flywheel is needed: what is known of it.
    Needed(T),
    /// None is needed.
    None(NoFlywheel),
}

/// The constant moment found over the cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Balance {
    /// The driving moment is constant: the work of the resistances and the moment, J and N·m.
    Driving {
        /// A_res, J.
        a_res: f64,
        /// M_drive, N·m.
        m_drive: f64,
    },
    /// The resisting moment is constant: the indicator diagrams' work and the moment.
    Resisting {
        /// A_drive, J.
        a_drive: f64,
        /// M_res, N·m.
        m_res: f64,
    },
}

/// An extreme of ω: its value, rad/s, and the crank travel at it, rad.
pub type Extreme = (f64, f64);

/// The exact solution.
#[derive(Debug, Clone, PartialEq)]
pub struct Exact {
    /// J_flywheel and the δ it gives, or none needed.
    pub flywheel: Flywheel<(f64, f64)>,
    /// ω_avg, rad/s.
    pub omega_avg: f64,
    /// ω_max and where.
    pub w_max: Extreme,
    /// ω_min and where.
    pub w_min: Extreme,
    /// The position the crank travel is measured from.
    pub from: String,
    /// The cycle's time, s.
    pub cycle_time: f64,
    /// The constant moment.
    pub balance: Balance,
}

/// A textbook route's flywheel where one is needed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RouteFlywheel {
    /// J_flywheel read, kg·m².
    pub j: f64,
    /// The exact one, kg·m² (`None`: none is needed).
    pub exact: Option<f64>,
    /// The δ it really gives.
    pub delta: f64,
}

/// The textbook routes against the exact flywheel.
#[derive(Debug, Clone, PartialEq)]
pub struct Routes {
    /// The positions.
    pub positions: usize,
    /// Wittenbauer's tangents.
    pub wittenbauer: Flywheel<RouteFlywheel>,
    /// Mertsalov's route.
    pub mertsalov: Flywheel<RouteFlywheel>,
    /// Mertsalov's on the continuous exact data: J, kg·m².
    pub continuous: Flywheel<f64>,
}

/// A note of the dynamics.
#[derive(Debug, Clone, PartialEq)]
pub enum DynamicsNote {
    /// The exact solution.
    Exact(Exact),
    /// The textbook routes.
    Routes(Routes),
    /// The seed's flywheel does not follow from its data.
    SeedFlywheel {
        /// Its J, kg·m².
        j: f64,
        /// The exact J (`None`: none is needed), kg·m².
        exact: Option<f64>,
        /// The δ the machine runs at with it.
        delta: f64,
        /// The δ asked.
        asked: f64,
    },
    /// The seed's expression evaluates to another value than it prints.
    SeedExpression {
        /// Its value, kg·m².
        value: f64,
        /// The J it prints, kg·m².
        printed: Option<f64>,
    },
    /// The seed's table of reduced inertias is wrong where the links move.
    SeedInertias {
        /// The constant part of J_пр, kg·m².
        constant: f64,
        /// The least and largest ratio of its variable part to the correct one.
        ratio: (f64, f64),
        /// The positions compared.
        positions: usize,
    },
}

impl<T> Flywheel<T> {
    /// The verdict, where none is needed.
    fn finding(&self) -> Option<Finding> {
        match self {
            Flywheel::None(n) => Some(Finding::NoFlywheelNeeded(*n)),
            Flywheel::Needed(_) => None,
        }
    }
}

impl DynamicsNote {
    /// The verdicts this note states, in order.
    pub fn findings(&self) -> Vec<Finding> {
        match self {
            DynamicsNote::Exact(e) => e.flywheel.finding().into_iter().collect(),
            DynamicsNote::Routes(r) => [
                r.wittenbauer.finding(),
                r.mertsalov.finding(),
                r.continuous.finding(),
            ]
            .into_iter()
            .flatten()
            .collect(),
            _ => Vec::new(),
        }
    }
}

/// The verdicts of a list of notes, in order.
pub fn findings(notes: &[DynamicsNote]) -> Vec<Finding> {
    notes.iter().flat_map(DynamicsNote::findings).collect()
}
