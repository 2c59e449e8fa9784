//! The numbers of the report's, the sheets' and the note's tables as they are written: a
//! value to a number of significant digits, "—" where it does not exist, and a relative
//! error in % ([`md_value`], [`md_percent`]), with the decimal comma in ru and uk.

use crate::scale::{format_sig, residue_to_zero, Lang};

/// Significant digits of errors in the tables.
pub(crate) const ERROR_DIGITS: usize = 3;

/// A value of a row: "—" where it does not exist (the analytic rate at a change point is NaN).
pub(crate) fn md_value(x: f64, sig: usize, lang: Lang) -> String {
    if x.is_finite() {
        format_sig(x, sig, lang)
    } else {
        "—".into()
    }
}

/// A length (m) in mm, to 5 significant digits: as the task's data gives it.
pub(crate) fn mm(x: f64, lang: Lang) -> String {
    md_value(x * 1e3, 5, lang)
}

/// A relative error in %, to [`ERROR_DIGITS`] significant digits; a rounding residue (at most
/// 1e-9 of the value, [`residue_to_zero`]) is 0 — the construction at drafting 0 is exact.
pub(crate) fn md_percent(rel: f64, lang: Lang) -> String {
    format_sig(residue_to_zero(rel, 1.0) * 100.0, ERROR_DIGITS, lang)
}

#[cfg(test)]
mod tests {
    use super::{md_percent, md_value};
    use crate::scale::Lang;

    #[test]
    fn values_and_errors_are_written_in_the_sheets_language() {
        assert_eq!(md_value(f64::NAN, 6, Lang::Ru), "—");
        assert_eq!(md_value(0.125, 3, Lang::Ru), "0,125");
        assert_eq!(md_value(0.125, 3, Lang::En), "0.125");
        assert_eq!(md_percent(0.012_34, Lang::Uk), "1,23");
        assert_eq!(md_percent(-2.0e-16, Lang::En), "0");
    }
}
