//! The values of a student's table by row and number: where a value copied from another
//! column of its row is looked for. One look-up per value, whatever the table's length (a
//! scan of the whole table for each value made an audit quadratic in its rows).

use super::{ColumnReading, Entry};
use std::collections::HashMap;

/// A value's row (its position) and its number in SI, `-0` taken as `0`.
type Key<'a> = (Option<&'a str>, u64);

/// The table's values indexed by [`Key`]: under each key the first value of each column
/// (quantity, method, unit and reading) — a second of the same column would name the same
/// copy.
pub(super) struct Copies<'a> {
    table: &'a [Entry],
    readings: &'a [ColumnReading],
    index: HashMap<Key<'a>, Vec<usize>>,
}

/// The key of `e`; `None` for a number that equals none (not a number).
fn key(e: &Entry) -> Option<Key<'_>> {
    let si = e.written.value * e.unit.factor;
    let bits = if si == 0.0 { 0 } else { si.to_bits() };
    (!si.is_nan()).then_some((e.position.as_deref(), bits))
}

/// The column of a value: its quantity, method, unit and reading.
fn column(e: &Entry, r: ColumnReading) -> (&str, Option<&str>, &str, ColumnReading) {
    (e.quantity.as_str(), e.method.as_deref(), e.unit.name, r)
}

impl<'a> Copies<'a> {
    /// The index of `table`, whose values' columns are read as `readings` (in order).
    pub fn new(table: &'a [Entry], readings: &'a [ColumnReading]) -> Self {
        let mut index: HashMap<Key<'a>, Vec<usize>> = HashMap::new();
        for (k, e) in table.iter().enumerate() {
            let Some(at) = key(e) else { continue };
            let same = index.entry(at).or_default();
            let this = column(e, readings[k]);
            if !same.iter().any(|&j| column(&table[j], readings[j]) == this) {
                same.push(k);
            }
        }
        Self {
            table,
            readings,
            index,
        }
    }

    /// The values of `entry`'s row whose number in SI is `entry`'s, one of each column
    /// (`entry`'s own among them), with how their columns are read.
    pub fn of<'s>(
        &'s self,
        entry: &'a Entry,
    ) -> impl Iterator<Item = (&'a Entry, ColumnReading)> + 's {
        let found: &'s [usize] = key(entry)
            .and_then(|k| self.index.get(&k))
            .map_or(&[], Vec::as_slice);
        found.iter().map(|&j| (&self.table[j], self.readings[j]))
    }
}
