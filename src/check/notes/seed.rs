//! A seed's printed value against the analysis, as a typed note: how far it is from the
//! row of the report, or that the report has no such row. Its English is written by `report`.

use crate::check::SeedValue;

/// The analysis' row a seed value is compared with.
#[derive(Debug, Clone, PartialEq)]
pub struct Analysed {
    /// The graphical value, in the row's unit.
    pub graphical: f64,
    /// The analytic value.
    pub analytic: f64,
    /// The row's unit.
    pub unit: &'static str,
}

/// The note on one value a seed prints.
#[derive(Debug, Clone, PartialEq)]
pub struct SeedNote {
    /// The value as the seed prints it, and where.
    pub seed: SeedValue,
    /// The analysis' row, `None` when the report has no such row.
    pub row: Option<Analysed>,
}
