//! A worked formula as data (seed 000 §§ 2–4): what it gives, the formula written out symbol
//! by symbol, the numbers substituted and the result with its unit, and the report's row it
//! works out. One writer sets every row; the note keeps them, so that a test holds each
//! printed result to its value and each value to the report's row.

use super::markup::{num, unit};
use super::Writer;
use crate::check::{Key, Method};
use crate::scale::Lang;
use crate::words::unit_in;

/// The involute function in a formula.
pub(super) const INV: &str = "op(\"inv\")";

/// An angle (rad) in degrees in a formula: `26,581°`.
pub(super) fn deg(a: f64, lang: Lang) -> String {
    let p = Printed::deg(a, lang);
    format!("{}{}", p.shown, p.unit)
}

/// Significant digits of a worked formula's result.
const DIGITS: usize = 5;

/// A worked formula's result: the value the printed number rounds, the number as printed
/// and its unit.
#[derive(Debug, Clone, PartialEq)]
pub struct Printed {
    /// The value in the unit printed (mm, °, N).
    pub value: f64,
    /// Significant digits the number is printed to.
    pub digits: usize,
    /// The number as printed (Typst math).
    pub shown: String,
    /// The unit after the number, as printed (Typst math; empty for none).
    pub unit: String,
    /// The printed unit in SI units: 1e-3 for mm, π/180 for °, 1 for N.
    pub to_si: f64,
}

impl Printed {
    /// `x` in a unit of `to_si` SI units, printed to `digits` and followed by `unit` (math).
    pub(super) fn new(x: f64, digits: usize, unit: String, to_si: f64, lang: Lang) -> Self {
        Self {
            value: x,
            digits,
            shown: num(x, digits, lang),
            unit,
            to_si,
        }
    }
    /// A number without a unit (a ratio, a coefficient), to `digits`.
    pub(super) fn plain(x: f64, digits: usize, lang: Lang) -> Self {
        Self::new(x, digits, String::new(), 1.0, lang)
    }
    /// A number without a unit to the formulas' five digits.
    pub(super) fn number(x: f64, lang: Lang) -> Self {
        Self::plain(x, DIGITS, lang)
    }
    /// An SI value to `digits` with its unit (a key of the catalogue: `N`, `N*m`, `kg`).
    pub(super) fn si(x: f64, digits: usize, unit_key: &str, lang: Lang) -> Self {
        Self::new(x, digits, unit(&unit_in(unit_key, lang)), 1.0, lang)
    }
    /// A length (m) in mm to `digits`.
    pub(super) fn mm(x: f64, digits: usize, lang: Lang) -> Self {
        Self::new(x * 1e3, digits, unit(&unit_in("mm", lang)), 1e-3, lang)
    }
    /// An angle (rad) in degrees, the sign against the number.
    pub(super) fn deg(a: f64, lang: Lang) -> Self {
        Self::degrees(a.to_degrees(), lang)
    }
    /// An angle given in degrees, the sign against the number.
    pub(super) fn degrees(x: f64, lang: Lang) -> Self {
        Self::new(x, DIGITS, "°".into(), std::f64::consts::PI / 180.0, lang)
    }
    /// The same number followed by `unit` (math) as printed instead.
    pub(super) fn with_unit(self, unit: String) -> Self {
        Self { unit, ..self }
    }
}

/// A worked formula of the note.
#[derive(Debug, Clone, PartialEq)]
pub struct Worked {
    /// What it gives (Typst math: `r_{1}`).
    pub symbol: String,
    /// The formula symbol by symbol (math; empty when the note has just written it).
    pub formula: String,
    /// The formula with the numbers substituted (math).
    pub substituted: String,
    /// The result.
    pub value: Printed,
    /// Whether the substituted numbers are a long sum on lines of their own, aligned at the
    /// first "=" (lines joined by `\`; the formula symbol by symbol is then left out).
    pub on_lines: bool,
    /// Set after the result (math; empty for none): a remark on it, as the drawn value
    /// beside the exact one (`quad ("на чертеже" 12,5 мм)`).
    pub aside: String,
    /// The report's row it works out and which of the row's values (`None`: a step the
    /// report does not tabulate).
    pub gives: Option<(Key, RowValue)>,
}

/// Which value of a report's row a worked formula gives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RowValue {
    /// The analytic twin's (the note works the twin's formula).
    Analytic,
    /// The graphical one of the row by this method (the note works the textbook's chain,
    /// [`Method::Formula`], or the reading off a drawing).
    Graphical(Method),
}

impl Worked {
    /// `symbol = formula = substituted = value`, giving no row of the report.
    pub(super) fn new(
        symbol: impl Into<String>,
        formula: impl Into<String>,
        substituted: impl Into<String>,
        value: Printed,
    ) -> Self {
        Self {
            symbol: symbol.into(),
            formula: formula.into(),
            substituted: substituted.into(),
            value,
            on_lines: false,
            aside: String::new(),
            gives: None,
        }
    }
    /// `symbol = a + b + … \ + … = value`: a long sum on `lines` ending with its total,
    /// which the formula's chain does not break at (set as a relation), so the lines stay
    /// as laid out.
    pub(super) fn on_lines(symbol: impl Into<String>, lines: &[String], value: Printed) -> Self {
        Self {
            on_lines: true,
            ..Self::new(symbol, "", lines.join(" \\ "), value)
        }
    }
    /// The same formula with the remark `aside` (math) after its result.
    pub(super) fn aside(self, aside: String) -> Self {
        Self { aside, ..self }
    }
    /// The same formula working out the analytic value of the report's row `key`.
    pub(super) fn gives(self, key: Key) -> Self {
        self.giving(Some(key))
    }
    /// The same formula working out the analytic value of the report's row `key`, if any.
    pub(super) fn giving(self, key: Option<Key>) -> Self {
        Self {
            gives: key.map(|k| (k, RowValue::Analytic)),
            ..self
        }
    }
    /// The same formula working out the graphical value of the report's row `key` by
    /// `method`.
    pub(super) fn gives_by(self, key: Key, method: Method) -> Self {
        Self {
            gives: Some((key, RowValue::Graphical(method))),
            ..self
        }
    }
    /// The formula as the note sets it: its sides joined by "=", an empty one left out.
    fn math(&self) -> String {
        let result = format!("{}{}{}", self.value.shown, self.value.unit, self.aside);
        if self.on_lines {
            return format!(
                "{} &= {} class(\"relation\", =) {result}",
                self.symbol, self.substituted
            );
        }
        [
            self.symbol.as_str(),
            &self.formula,
            &self.substituted,
            &result,
        ]
        .into_iter()
        .filter(|s| !s.is_empty())
        .collect::<Vec<_>>()
        .join(" = ")
    }
}

impl Writer<'_, '_> {
    /// Sets a worked formula as one numbered formula and keeps it.
    pub(super) fn worked(&mut self, row: Worked) {
        self.formula(&row.math());
        self.worked.push(row);
    }
}
