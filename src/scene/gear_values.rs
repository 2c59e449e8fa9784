//! The numbers every gear section gives: a module and a tooth number, in their ranges.

use super::check::{number, Checker};

/// The range of a module, mm.
const MODULE_MM: (f64, f64) = (0.01, 1000.0);

/// A module in mm within [`MODULE_MM`], in metres (0 after a problem).
pub(super) fn module_mm(check: &mut Checker, key: &str, v: f64) -> f64 {
    let (lo, hi) = MODULE_MM;
    if v.is_finite() && (lo..=hi).contains(&v) {
        v * 1e-3
    } else {
        check.push(
            key,
            Some(number(v)),
            format!("expected a module from {lo} to {hi} mm"),
        );
        0.0
    }
}

/// A tooth number (5 … 1000).
pub(super) fn teeth(check: &mut Checker, key: &str, v: i64) -> u32 {
    teeth_from(check, key, v, 5)
}

/// A tooth number from `least` to 1000 at `key` (a train's wheel is counted, not cut: 4).
pub(super) fn teeth_from(check: &mut Checker, key: &str, v: i64, least: u32) -> u32 {
    match u32::try_from(v) {
        Ok(z) if (least..=1000).contains(&z) => z,
        _ => {
            check.push(
                key,
                Some(v.to_string()),
                format!("expected a tooth number from {least} to 1000"),
            );
            least.max(5)
        }
    }
}
