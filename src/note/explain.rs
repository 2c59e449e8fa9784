//! The displayed formulas of the note and the explanation of their symbols under them
//! (ГОСТ 2.105): after a formula that brings in a symbol, «где» and each new symbol with its
//! meaning and unit, each symbol explained once in the note for each meaning (the cam's μ_φ,
//! the scale of the cam's angle, is not the crank's μ_φ of the kinematic diagrams). Every formula goes through
//! [`Writer::formula`], every explanation through [`Writer::explain`]; a formula whose left
//! side no explanation has reached by the next formula is recorded in
//! [`super::Note::unexplained`], which the tests hold empty.

use super::markup::{label, sym};
use super::Writer;
use crate::words::unit_in;
use std::collections::{HashMap, HashSet};

/// What the note has explained so far, and what it left unexplained.
#[derive(Debug, Default)]
pub(super) struct Explained {
    /// The explained symbols' formula markup ([`sym`] of their label markup), each with the
    /// meanings it was explained with.
    known: HashMap<String, HashSet<String>>,
    /// The left side of the last formula, until an explanation reaches it.
    pending: Option<String>,
    /// The left sides of the formulas left unexplained.
    pub(super) missing: Vec<String>,
}

impl Explained {
    /// Whether the formula markup `lhs` shows an explained symbol whole (not the `α` of
    /// `α_w`).
    fn covers(&self, lhs: &str) -> bool {
        self.known.keys().any(|s| {
            lhs.match_indices(s.as_str())
                .any(|(at, _)| !matches!(lhs[at + s.len()..].chars().next(), Some('_' | '^')))
        })
    }

    /// Closes the last formula: recorded as unexplained unless an explanation covers it.
    pub(super) fn settle(&mut self) {
        if let Some(lhs) = self.pending.take() {
            if !self.covers(&lhs) {
                self.missing.push(lhs);
            }
        }
    }
}

/// A symbol to explain: its label markup (`α_{w}`), its meaning in the note's language and
/// its unit in SI notation (`N*m`, `deg`, empty for a number).
pub(super) type Explanation<'a> = (&'a str, &'a str, &'a str);

impl Writer<'_, '_> {
    /// A displayed formula, numbered ([`super::markup::Markup::formula`]); its left side
    /// (up to the first sign of equality) is to be explained, here or before.
    pub(super) fn formula(&mut self, math: &str) {
        self.left_side_pending(math);
        self.doc.formula(math);
    }

    /// [`Self::formula`] set on one line or, when that is too wide, as `broken`
    /// ([`super::markup::Markup::formula_or`]).
    pub(super) fn formula_or(&mut self, one: &str, broken: &str) {
        self.left_side_pending(one);
        self.doc.formula_or(one, broken);
    }

    /// The left side of the formula `math` (up to its first sign of equality) to be
    /// explained next, the one before settled.
    fn left_side_pending(&mut self, math: &str) {
        self.explained.settle();
        self.explained.pending = Some(super::markup::first_side(math).to_owned());
    }

    /// «где» and the symbols of `items` not yet explained in the note with this meaning,
    /// each «— meaning, unit», in the order given (the formula's); nothing when all are
    /// known.
    pub(super) fn explain(&mut self, items: &[Explanation<'_>]) {
        let mut rows = Vec::new();
        for &(symbol, meaning, unit) in items {
            let math = sym(symbol);
            let meanings = self.explained.known.entry(math.clone()).or_default();
            if !meanings.insert(meaning.to_owned()) {
                continue;
            }
            let unit = unit_in(unit, self.lang);
            let meaning = if unit.is_empty() {
                format!("#{}", label(meaning))
            } else {
                format!("#{}, #{}", label(meaning), label(&unit))
            };
            rows.push(format!("([${math}$], [{meaning}])"));
        }
        if !rows.is_empty() {
            self.doc
                .raw(&format!("#explained({})\n", rows.join(", ") + ","));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Explained;
    use crate::note::markup::sym;

    #[test]
    fn a_symbol_is_covered_whole_not_by_its_stem() {
        let mut e = Explained::default();
        e.known.entry(sym("α")).or_default();
        assert!(!e.covers(&sym("α_{w}")));
        assert!(e.covers(&format!("op(\"inv\") {}", sym("α"))));
        e.known.entry(sym("α_{w}")).or_default();
        assert!(e.covers(&sym("α_{w}")));
        e.pending = Some(sym("y"));
        e.settle();
        assert_eq!(e.missing, vec![sym("y")]);
    }
}
