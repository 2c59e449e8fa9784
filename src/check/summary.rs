//! The error estimates of section 1.6 of the seed: mean and largest relative error per
//! quantity and method, and the mean per method.

use super::{rel_errors, Method, Row};
use crate::scale::residue_to_zero;
use serde::Serialize;

/// Relative difference within which two errors tie: the same reading of the same value at
/// two positions (the six-bar's ω₂ at 3 and at 10′) differs only by the rounding of its
/// analytic twin, and the first position keeps the largest error.
const TIE_REL: f64 = 1e-9;

/// The error summary of one quantity and method (one line of section 1.6 of the seed).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SummaryEntry {
    /// The quantity (`v_D`).
    pub quantity: String,
    /// The method.
    pub method: Method,
    /// How many rows have a relative error (rows at an analytic zero are not counted).
    pub count: usize,
    /// Mean of |rel_error|, as a fraction.
    pub mean_abs_rel: f64,
    /// Largest |rel_error|, as a fraction.
    pub max_abs_rel: f64,
    /// The position of the largest |rel_error| (the first one on a tie, within [`TIE_REL`]);
    /// `null` for a quantity of the whole scene.
    pub worst_position: Option<String>,
}

impl SummaryEntry {
    /// The position to name as the worst: none when the largest error is rounding (written
    /// 0, [`residue_to_zero`]) — thirteen residues of 1e-16 have no worst among them.
    pub fn worst_named(&self) -> Option<&str> {
        (residue_to_zero(self.max_abs_rel, 1.0) != 0.0)
            .then_some(self.worst_position.as_deref())
            .flatten()
    }
}

/// The section-1.6 summary of a set of rows.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    /// One entry per (quantity, method) with at least one relative error, in the order the
    /// pair first appears among the rows.
    pub entries: Vec<SummaryEntry>,
    /// Per method (in [`Method`] order): the mean |rel_error| over all its rows that have
    /// one — the seed's "mean 5 %" — as a fraction. Methods without such rows are left out.
    pub mean_by_method: Vec<(Method, f64)>,
}

impl Summary {
    /// Summarise `rows`. Rows without a finite relative error are not counted.
    pub fn of(rows: &[Row]) -> Self {
        let mut entries: Vec<SummaryEntry> = Vec::new();
        let mut by_method: Vec<(Method, f64, usize)> = Vec::new();
        for (row, d) in rows.iter().zip(rel_errors(rows)) {
            let Some(d) = d.map(f64::abs).filter(|d| d.is_finite()) else {
                continue;
            };
            let quantity = row.quantity();
            match entries
                .iter_mut()
                .find(|e| e.quantity == quantity && e.method == row.method)
            {
                Some(e) => {
                    // Running sum in `mean_abs_rel`, divided below.
                    e.mean_abs_rel += d;
                    e.count += 1;
                    if d > e.max_abs_rel * (1.0 + TIE_REL) {
                        e.max_abs_rel = d;
                        e.worst_position = row.position();
                    }
                }
                None => entries.push(SummaryEntry {
                    quantity,
                    method: row.method,
                    count: 1,
                    mean_abs_rel: d,
                    max_abs_rel: d,
                    worst_position: row.position(),
                }),
            }
            match by_method.iter_mut().find(|m| m.0 == row.method) {
                Some(m) => {
                    m.1 += d;
                    m.2 += 1;
                }
                None => by_method.push((row.method, d, 1)),
            }
        }
        for e in &mut entries {
            e.mean_abs_rel /= e.count as f64;
        }
        by_method.sort_by_key(|m| m.0);
        Summary {
            entries,
            mean_by_method: by_method
                .into_iter()
                .map(|(m, sum, n)| (m, sum / n as f64))
                .collect(),
        }
    }
}
