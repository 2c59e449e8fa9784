//! The notes of a kinematic study as typed values: what was refused, a toggle's undetermined
//! rates, a slotted link's pin passing its pivot, the links accelerating and decelerating.
//! Their English is written by `report`.

/// A slotted link's pin passing close to its pivot at one position.
#[derive(Debug, Clone, PartialEq)]
pub struct PinNearPivot {
    /// The position's label.
    pub position: String,
    /// The pin's name.
    pub pin: String,
    /// The pivot's name.
    pub pivot: String,
    /// The pin's distance from the pivot, m.
    pub distance: f64,
    /// The slotted link.
    pub link: usize,
    /// Its group (from 0).
    pub group: usize,
    /// |d(pivot pin)/dφ₁|, m.
    pub speed: f64,
    /// The link's ω, rad/s.
    pub omega: f64,
}

/// A note of a kinematic study.
#[derive(Debug, Clone, PartialEq)]
pub enum KinematicsNote {
    /// A diagram or plan refused: the refusal's diagnosis (the error's own message).
    Refused(String),
    /// No velocity plan at a position: the diagnosis.
    NoPlan {
        /// The position's label.
        position: String,
        /// Why (the error's own message).
        why: String,
    },
    /// The analytic rates undetermined at a group's toggle.
    Toggle {
        /// The position's label.
        position: String,
        /// The group (from 0).
        group: usize,
    },
    /// A slotted link's pin passes close to its pivot.
    NearPivot(PinNearPivot),
    /// The links accelerating and decelerating by the plans at a position, and where the twin
    /// differs.
    Turning {
        /// The position's label.
        position: String,
        /// The links accelerating.
        accelerating: Vec<String>,
        /// The links decelerating.
        decelerating: Vec<String>,
        /// The links whose verdict the twin does not share.
        differ: Vec<String>,
    },
}
