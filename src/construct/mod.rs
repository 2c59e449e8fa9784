//! The construction recorder: every arc, line, intersection, measured segment and label a
//! draughtsman draws, with its role and provenance. A plate draws exactly what was recorded;
//! it never re-derives geometry.
//!
//! Coordinates are **drawing millimetres** of the figure, y up; the figure's scale μ turns them
//! into physical values. A construction starts from a [`Context`] (tolerances, drafting model)
//! with [`Recorder::in_context`]. Compass steps ([`Recorder::meet_circles`],
//! [`Recorder::meet_line_circle`], [`Recorder::meet_lines`]) record their notches and return a
//! diagnostic error carrying the numbers when the construction cannot be carried out.
//!
//! * [`Figure`] — the figure model: [`Step`]s with their [`Item`] (what is drawn), [`Role`]
//!   and [`Label`];
//! * [`Drafting`] — how a length is read off the drawing, and [`Measured`] lengths;
//! * [`Reading`] — a segment measured off a figure and the value it gave;
//! * [`Recorder`] — records steps into a figure; [`Compass`] and [`Pick`] — its compass steps.

mod compass;
mod context;
mod detail;
mod drafting;
mod error;
mod figure;
pub(crate) mod fit;
mod item;
mod label;
mod reading;
mod recorder;

pub use compass::{Compass, Pick};
pub use context::Context;
pub use drafting::{Drafting, Measured};
pub use error::ConstructionError;
pub use figure::{Figure, Role, Step, StepId};
pub use item::{Item, DIMENSION_TEXT_ROOM_MM, THIN_HEAD_MM};
pub use label::{number_box, Label, Names, DIGIT_MM, HALF_BOX_MM, NUMBER_CLEAR_MM, NUMBER_SIDE_MM};
pub use reading::Reading;
pub use recorder::Recorder;
