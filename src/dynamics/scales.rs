//! The diagrams' scales: a scale the scene gives, checked by what it draws, or a round one
//! chosen for the diagram's largest value.

use super::DynamicsError;
use crate::scale::{Quantity, Scale};

/// Preferred drawn length of the abscissa 2π, mm.
pub(super) const TURN_MM: f64 = 180.0;
/// Preferred height of a diagram's largest ordinate, mm: the M, A and ΔT diagrams fill
/// their part of the A1 dynamics sheet (50 mm left a quarter of it empty).
pub(super) const HEIGHT_MM: f64 = 80.0;

/// The scale the scene gives, or the round one that draws `value` about `mm` long.
pub(super) fn scale_of(
    given: Option<Scale>,
    value: f64,
    mm: f64,
    q: Quantity,
    what: &'static str,
) -> Result<Scale, DynamicsError> {
    match given {
        Some(s) => Ok(s),
        None => Scale::round_for(value, mm, q).ok_or(DynamicsError::NoScale { what, value }),
    }
}

/// A scale the scene gives (`key`) must draw the largest `value` of its diagram within
/// [`crate::scale::DRAWN_MM`]: beyond, no sheet holds it and the chords lose their meaning
/// (μ_M = 1e-12 N·m/mm drew A_с 1e14 mm tall and failed in its integration).
pub(super) fn given_draws(
    given: Option<Scale>,
    key: crate::scale::Key,
    value: f64,
) -> Result<(), DynamicsError> {
    let (lo, hi) = crate::scale::DRAWN_MM;
    match given {
        Some(s)
            if value.is_finite() && value > 0.0 && !(lo..=hi).contains(&(value / s.value())) =>
        {
            Err(DynamicsError::Drawn {
                key: key.path(),
                scale: s.value(),
                value,
                drawn_mm: value / s.value(),
                range: (value / hi, value / lo),
            })
        }
        _ => Ok(()),
    }
}
