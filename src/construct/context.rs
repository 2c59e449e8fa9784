//! The construction context: what every recorder of a study is started with.

use super::drafting::Drafting;
use crate::geom::{InvalidTolerance, Tolerances};

/// What a construction is carried out with, shared by the figures of a study: the
/// tolerances (figure millimetres), the drafting model and the size of the compass notches.
/// Start a recorder in it with [`Recorder::in_context`](super::Recorder::in_context).
///
/// ```
/// use tmm::construct::{Context, Drafting, Recorder};
/// use tmm::scale::{Quantity, Scale};
/// let ctx = Context::for_model_size(300.0, Drafting::EXACT)?;
/// let mu = Scale::new(0.0025, Quantity::Length).expect("a valid μ");
/// let rec = Recorder::in_context("plan", mu, &ctx);
/// assert_eq!(rec.tolerances(), &ctx.tol);
/// # Ok::<(), tmm::geom::InvalidTolerance>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Context {
    /// Tolerances in figure millimetres.
    pub tol: Tolerances,
    /// How measured lengths are read off the drawing.
    pub drafting: Drafting,
    /// Half-length of a compass notch, mm.
    pub notch_mm: f64,
}

impl Context {
    /// Half-length of a compass notch, mm: long enough to read at 1:1, short enough not
    /// to cross the neighbouring construction.
    pub const NOTCH_MM: f64 = 4.0;

    /// A context with these tolerances and drafting model and notches of [`Self::NOTCH_MM`].
    pub fn new(tol: Tolerances, drafting: Drafting) -> Self {
        Self {
            tol,
            drafting,
            notch_mm: Self::NOTCH_MM,
        }
    }

    /// A context for figures whose largest extent is `extent_mm` (figure mm): the
    /// tolerances of [`Tolerances::for_model_size`].
    ///
    /// # Errors
    /// [`InvalidTolerance`] when `extent_mm` is not finite and > 0.
    pub fn for_model_size(extent_mm: f64, drafting: Drafting) -> Result<Self, InvalidTolerance> {
        Ok(Self::new(Tolerances::for_model_size(extent_mm)?, drafting))
    }

    /// The same context with another drafting model.
    pub fn with_drafting(self, drafting: Drafting) -> Self {
        Self { drafting, ..self }
    }
}
