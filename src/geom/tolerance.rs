//! Tolerances, passed explicitly and scaled to the size of the model.

use thiserror::Error;

/// Why a [`Tolerances`] value was refused.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum InvalidTolerance {
    /// A field is not finite or not strictly positive.
    #[error("tolerance `{field}` must be finite and > 0, got {value}", value = crate::scale::format_plain(*value))]
    NotPositive {
        /// The field name.
        field: &'static str,
        /// The offending value.
        value: f64,
    },
    /// `parallel_sin` must stay well below 1 or every pair of lines is "parallel".
    #[error("tolerance `parallel_sin` must be < 0.1, got {0}")]
    ParallelTooLoose(f64),
}

/// Every tolerance a construction needs, with units, in one validated value.
///
/// Lengths are in the units of the figure they are used on (drawing millimetres for a
/// plan drawn at a scale μ); derive them from the size of that figure with
/// [`Tolerances::for_model_size`] rather than using a crate-wide epsilon.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances {
    /// Points closer than this (figure units) are the same point; a circle pair whose
    /// centre distance misses `r₁ + r₂` by less than this is tangent.
    pub coincident: f64,
    /// `|sin(angle)|` below which two directions count as parallel (dimensionless).
    pub parallel_sin: f64,
    /// Largest distance (paper mm) between a curve and the polyline that draws it.
    pub flatten_mm: f64,
    /// Target precision of iterative solvers, as a fraction of the model size.
    pub solver_accuracy: f64,
}

impl Tolerances {
    /// Relative size of a "same point" decision. f64 carries ~16 digits; a chain of a few
    /// dozen compass steps loses a few of them, so 1e-10 of the model keeps every honest
    /// intersection apart while still merging points that are equal by construction.
    const COINCIDENT_REL: f64 = 1e-10;
    /// sin of ~2e-8 rad: directions closer than this give an intersection farther away
    /// than 5e7 model sizes — meaningless on any drawing.
    const PARALLEL_SIN: f64 = 2e-8;
    /// 0.02 mm is below what a printer or a pen resolves.
    const FLATTEN_MM: f64 = 0.02;
    const SOLVER_REL: f64 = 1e-13;

    /// Tolerances for a figure whose largest extent is `extent` (its own units).
    pub fn for_model_size(extent: f64) -> Result<Self, InvalidTolerance> {
        if !(extent.is_finite() && extent > 0.0) {
            return Err(InvalidTolerance::NotPositive {
                field: "extent",
                value: extent,
            });
        }
        Self::new(
            extent * Self::COINCIDENT_REL,
            Self::PARALLEL_SIN,
            Self::FLATTEN_MM,
            Self::SOLVER_REL,
        )
    }

    /// Validated constructor.
    pub fn new(
        coincident: f64,
        parallel_sin: f64,
        flatten_mm: f64,
        solver_accuracy: f64,
    ) -> Result<Self, InvalidTolerance> {
        for (field, value) in [
            ("coincident", coincident),
            ("parallel_sin", parallel_sin),
            ("flatten_mm", flatten_mm),
            ("solver_accuracy", solver_accuracy),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(InvalidTolerance::NotPositive { field, value });
            }
        }
        if parallel_sin >= 0.1 {
            return Err(InvalidTolerance::ParallelTooLoose(parallel_sin));
        }
        Ok(Self {
            coincident,
            parallel_sin,
            flatten_mm,
            solver_accuracy,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tolerances_scale_with_model() {
        let t = Tolerances::for_model_size(500.0).unwrap();
        assert!((t.coincident - 5e-8).abs() < 1e-20);
    }

    #[test]
    fn tolerances_reject_nan_and_zero() {
        assert!(Tolerances::for_model_size(f64::NAN).is_err());
        assert!(Tolerances::for_model_size(0.0).is_err());
        assert!(Tolerances::new(1e-9, 0.5, 0.02, 1e-12).is_err());
    }
}
