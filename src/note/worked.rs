//! A worked formula's pieces: the formula written out symbol by symbol, then with the
//! numbers substituted, then its value; angles in degrees; the involute function.

use super::markup::num;
use super::Writer;
use crate::scale::Lang;

/// The involute function in a formula.
pub(super) const INV: &str = "op(\"inv\")";

/// An angle (rad) in degrees in a formula: `26,581°`.
pub(super) fn deg(a: f64, lang: Lang) -> String {
    format!("{}°", num(a.to_degrees(), 5, lang))
}

/// Writes "`lhs` = `symbolic` = `substituted` = `value`" as one formula (`lhs` is math).
pub(super) fn worked(
    w: &mut Writer<'_, '_>,
    lhs: &str,
    symbolic: &str,
    substituted: &str,
    value: String,
) {
    w.formula(&format!("{lhs} = {symbolic} = {substituted} = {value}"));
}
