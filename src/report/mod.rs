//! Reports: graphical against analytic values, row by row, with the section-1.6 summary of
//! the seed (mean and largest relative error per quantity and method), and the output of
//! `tmm bench` (speed against error).
//!
//! The check of every construction produces [`Row`]s; a scene collects them into a
//! [`Report`] together with its analytic [`Table`]s (the shape of seed 000 Table 5). A report
//! is written as JSON ([`Report::to_json`]), CSV ([`Report::to_csv`]) or Markdown
//! ([`Report::to_markdown`]). This module depends on nothing above `scale` and `plate`: the
//! scenes fill it, it never reaches into them.
//!
//! Error conventions:
//! - `abs_error` = |graphical − analytic|, in the row's unit;
//! - `rel_error` = (graphical − analytic) / |analytic| (signed, as a fraction; the seed's
//!   tables print it in %), absent when |analytic| is at or below the column's zero threshold
//!   ([`Report::zero_threshold`]: [`ZERO_FRACTION`] × the largest |analytic| of the quantity).
//!
//! Non-finite numbers: JSON has no NaN or infinity, so every writer writes a non-finite number
//! as `null`; a JSON row in which that happened carries an extra key `"non_finite"` listing
//! the fields concerned (rows with finite numbers have exactly the documented keys). CSV
//! writes such a number as Rust prints it (`NaN`, `inf`, `-inf`) so that it is not mistaken
//! for an absent value; Markdown writes it the same way.

pub mod bench;
mod format;
mod plot;
#[cfg(test)]
mod tests;

use serde::Serialize;

pub use bench::{Bench, BenchRow, Throughput};
pub use plot::{decade_range, log_position};

/// The default zero threshold of a column, as a fraction of its largest |analytic| value: a
/// relative error is not computed against an analytic value this close to zero.
pub const ZERO_FRACTION: f64 = 1e-12;

/// How the graphical value was obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// A velocity or acceleration plan (vector polygon) at one position.
    Plan,
    /// A kinematic diagram: chord-method differentiation or integration over the cycle.
    Diagram,
}

impl Method {
    /// The method's name in `lang`.
    pub fn name(self, lang: crate::scale::Lang) -> &'static str {
        match self {
            Method::Plan => lang.pick("план", "план", "plan"),
            Method::Diagram => lang.pick("диаграмма", "діаграма", "diagram"),
        }
    }
    /// The name used in JSON and CSV: `plan` or `diagram`.
    pub fn key(self) -> &'static str {
        match self {
            Method::Plan => "plan",
            Method::Diagram => "diagram",
        }
    }
}

/// One checked value: a quantity at a position, graphical against analytic.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The quantity: `s_S5`, `v_D`, `a_D`, `omega_3`, `eps_3`, `v_B3_B1` (B3 relative to B1).
    pub quantity: String,
    /// The scene's position label: `1` … `12`, `8′`.
    pub position: String,
    /// SI unit: `m`, `m/s`, `m/s^2`, `rad/s`, `rad/s^2`.
    pub unit: String,
    /// How the graphical value was obtained.
    pub method: Method,
    /// The value read from the construction.
    pub graphical: f64,
    /// The analytic twin's value.
    pub analytic: f64,
    /// How well the construction fixed the value, e.g. the crossing angle (degrees) of the
    /// lines that fixed it; small means ill-conditioned.
    pub conditioning: Option<f64>,
}

impl Row {
    /// |graphical − analytic|, in the row's unit.
    pub fn abs_error(&self) -> f64 {
        (self.graphical - self.analytic).abs()
    }

    /// (graphical − analytic) / |analytic|, signed, as a fraction; `None` when |analytic| is
    /// at or below `zero` (or is not finite). The report passes its column threshold
    /// [`Report::zero_threshold`]; pass `0.0` to refuse only an exact zero.
    pub fn rel_error(&self, zero: f64) -> Option<f64> {
        let a = self.analytic.abs();
        (a.is_finite() && a > zero.max(0.0)).then(|| (self.graphical - self.analytic) / a)
    }
}

/// A column of an analytic table.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Column {
    /// Name in label markup, e.g. `φ_1` or `V_B3B1`.
    pub name: String,
    /// Unit, e.g. `°`, `m`, `1/s`; empty for none.
    pub unit: String,
}

/// An analytic table in the shape of seed 000 Table 5: one row per position.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// The caption.
    pub title: String,
    /// The value columns (the position column is implicit and comes first).
    pub columns: Vec<Column>,
    /// Per position: its label and one value per column (`None` for an empty cell).
    pub rows: Vec<(String, Vec<Option<f64>>)>,
}

/// The checked rows of one scene and its analytic tables.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// The scene's name.
    pub scene: String,
    /// The checked values, in the order written.
    pub rows: Vec<Row>,
    /// Analytic tables, written after the rows.
    pub tables: Vec<Table>,
    /// Notes: what could not be constructed, and why.
    pub notes: Vec<String>,
}

/// The error summary of one quantity and method (one line of section 1.6 of the seed).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SummaryEntry {
    /// The quantity.
    pub quantity: String,
    /// The method.
    pub method: Method,
    /// How many rows have a relative error (rows at an analytic zero are not counted).
    pub count: usize,
    /// Mean of |rel_error|, as a fraction.
    pub mean_abs_rel: f64,
    /// Largest |rel_error|, as a fraction.
    pub max_abs_rel: f64,
    /// The position of the largest |rel_error| (the first one on a tie).
    pub worst_position: String,
}

/// The section-1.6 summary of a report.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    /// One entry per (quantity, method) with at least one relative error, in the order the
    /// pair first appears among the rows.
    pub entries: Vec<SummaryEntry>,
    /// Per method (plan first): the mean |rel_error| over all its rows that have one — the
    /// seed's "mean 5 %" — as a fraction. Methods without such rows are left out.
    pub mean_by_method: Vec<(Method, f64)>,
}

impl Report {
    /// The zero threshold of `quantity`: [`ZERO_FRACTION`] × its largest finite |analytic|.
    pub fn zero_threshold(&self, quantity: &str) -> f64 {
        let largest = self
            .rows
            .iter()
            .filter(|r| r.quantity == quantity && r.analytic.is_finite())
            .fold(0.0_f64, |m, r| m.max(r.analytic.abs()));
        largest * ZERO_FRACTION
    }

    /// The relative error of every row against its column's zero threshold, in row order.
    pub fn rel_errors(&self) -> Vec<Option<f64>> {
        self.rows
            .iter()
            .map(|r| r.rel_error(self.zero_threshold(&r.quantity)))
            .collect()
    }

    /// The quantities in the order they first appear among the rows.
    pub fn quantities(&self) -> Vec<&str> {
        let mut out: Vec<&str> = Vec::new();
        for r in &self.rows {
            if !out.contains(&r.quantity.as_str()) {
                out.push(&r.quantity);
            }
        }
        out
    }

    /// The section-1.6 summary: mean and largest |relative error| per quantity and method,
    /// and the mean per method. Rows without a finite relative error are not counted.
    pub fn summary(&self) -> Summary {
        let rel = self.rel_errors();
        let mut entries: Vec<SummaryEntry> = Vec::new();
        let mut by_method: Vec<(Method, f64, usize)> = Vec::new();
        for (row, d) in self.rows.iter().zip(rel) {
            let Some(d) = d.map(f64::abs).filter(|d| d.is_finite()) else {
                continue;
            };
            match entries
                .iter_mut()
                .find(|e| e.quantity == row.quantity && e.method == row.method)
            {
                Some(e) => {
                    // Running sum in `mean_abs_rel`, divided below.
                    e.mean_abs_rel += d;
                    e.count += 1;
                    if d > e.max_abs_rel {
                        e.max_abs_rel = d;
                        e.worst_position.clone_from(&row.position);
                    }
                }
                None => entries.push(SummaryEntry {
                    quantity: row.quantity.clone(),
                    method: row.method,
                    count: 1,
                    mean_abs_rel: d,
                    max_abs_rel: d,
                    worst_position: row.position.clone(),
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
