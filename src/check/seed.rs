//! A value a seed (a textbook) prints for a row of the report (`[[seed]]`, `[[forces.seed]]`)
//! and the report's note on it ([`SeedNote`]): how far it is from the analysis, so that a
//! seed's error is flagged, never matched.

use super::notes::seed::{Analysed, SeedNote};
use super::{Method, Row};

/// A value the seed prints for a row of the report (`[[seed]]`, `[[forces.seed]]`): the report notes
/// how far it is from the analysis, so that a seed's error is flagged, never matched.
#[derive(Debug, Clone, PartialEq)]
pub struct SeedValue {
    /// The row's quantity (`F_bal`, `h_0_5`).
    pub quantity: String,
    /// The row's position label (`None`: a quantity of the whole scene, `r_b1`).
    pub position: Option<String>,
    /// The row's method (`None`: the first row of the quantity at the position).
    pub method: Option<Method>,
    /// The seed's value in the row's SI unit (its magnitude is compared).
    pub value: f64,
    /// The value as the seed prints it (`112 kgf`).
    pub printed: String,
    /// The number the seed prints, in its unit.
    pub printed_value: f64,
    /// The unit the seed prints it in (`kgf`, `mm`).
    pub printed_unit: &'static str,
    /// Where the seed prints it and what is wrong with it.
    pub source: String,
    /// What is wrong with it, in each language of the note (`None`: the note says only
    /// that the value is not reproduced).
    pub why: Option<crate::scale::Localised>,
}

impl SeedValue {
    /// The report's row it names: its quantity at its position (none for a quantity of the
    /// whole scene) by its method (the first such row when it names none).
    pub fn row<'r>(&self, rows: &'r [Row]) -> Option<&'r Row> {
        rows.iter().find(|r| {
            r.quantity() == self.quantity
                && r.position() == self.position
                && self.method.is_none_or(|m| m == r.method)
        })
    }
}

/// The seed's printed values against the rows of the analysis: each note gives the seed's
/// value, the analysis' (graphical and analytic) and how far apart they are; a seed value
/// whose row the report does not have says so.
pub fn seed_notes(seed: &[SeedValue], rows: &[Row]) -> Vec<SeedNote> {
    seed.iter()
        .map(|s| SeedNote {
            seed: s.clone(),
            row: s.row(rows).map(|r| Analysed {
                graphical: r.graphical,
                analytic: r.analytic,
                unit: r.unit(),
            }),
        })
        .collect()
}
