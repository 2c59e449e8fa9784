//! The construction recorder: every arc, line, intersection, measured segment and label a
//! draughtsman draws, with its role and provenance. A plate draws exactly what was recorded;
//! it never re-derives geometry.
//!
//! Coordinates are **drawing millimetres** of the figure, y up; the figure's scale μ turns them
//! into physical values. Compass steps ([`Recorder::meet_circles`], [`Recorder::meet_line_circle`],
//! [`Recorder::meet_lines`]) record their notches and return a diagnostic error carrying the
//! numbers when the construction cannot be carried out.

mod error;
mod recorder;

pub use error::ConstructionError;
pub use recorder::{
    Compass, Drafting, Figure, Item, Label, Measured, Pick, Recorder, Role, Step, StepId,
};
