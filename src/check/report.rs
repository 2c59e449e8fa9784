//! A scene's results: its checked [`Row`]s, its analytic [`Table`]s (the shape of seed 000
//! Table 5) and its notes. The writers (JSON, CSV, Markdown) are in [`crate::report`].

use super::{Row, Summary};
use serde::Serialize;

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
    /// Notes: what could not be constructed, and why; typed, their English written by
    /// `report`.
    pub notes: Vec<super::ReportNote>,
}

impl Report {
    /// The relative error of every row against its zero reference ([`super::scales`]).
    pub fn rel_errors(&self) -> Vec<Option<f64>> {
        super::rel_errors(&self.rows)
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
