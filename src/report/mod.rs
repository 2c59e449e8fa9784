//! Reports: graphical against analytic values, row by row, with the section-1.6 summary of
//! the seed (mean and largest relative error per quantity and method), and the output of
//! `tmm bench` (speed against error).
//!
//! The check of every construction produces typed [`Row`]s ([`crate::check`]); a scene collects them into a
//! [`Report`] together with its analytic [`Table`]s (the shape of seed 000 Table 5). A report
//! is written as JSON ([`Report::to_json`]), CSV ([`Report::to_csv`]) or Markdown
//! ([`Report::to_markdown`]). This module depends on nothing above `scale` and `plate`: the
//! scenes fill it, it never reaches into them.
//!
//! Error conventions:
//! - `abs_error` = |graphical − analytic|, in the row's unit;
//! - `rel_error` = (graphical − analytic) / |analytic| (signed, as a fraction; the seed's
//!   tables print it in %), absent when the analytic value is zero to rounding against the
//!   quantity's scale over the cycle ([`crate::check::is_zero`]).
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

pub use crate::check::{Method, Row, Summary, SummaryEntry};
pub use bench::{Bench, BenchRow, Throughput};
pub use format::CSV_HEADER;
pub use plot::{decade_range, log_position};

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

impl Report {
    /// The relative error of every row against its zero reference ([`crate::check::scales`]).
    pub fn rel_errors(&self) -> Vec<Option<f64>> {
        crate::check::rel_errors(&self.rows)
    }

    /// The quantities in the order they first appear among the rows.
    pub fn quantities(&self) -> Vec<String> {
        let mut out: Vec<String> = Vec::new();
        for r in &self.rows {
            let q = r.quantity();
            if !out.contains(&q) {
                out.push(q);
            }
        }
        out
    }

    /// The section-1.6 summary: mean and largest |relative error| per quantity and method,
    /// and the mean per method.
    pub fn summary(&self) -> Summary {
        Summary::of(&self.rows)
    }
}
