//! The precision of the numbers a sheet's text prints, one place for every sheet (issue 45):
//! what a drawing's table gives — four significant digits, an angle's too, a length in
//! millimetres with its unit — so that no text block prints six or seven digits, nor a
//! length in metres with a run of zeros (`0,004975 м` is `4,975 мм`).

use crate::scale::{format_fixed, format_sig, Lang, Scale};
use crate::words::unit_in;

/// A table's cell that gives no value (ГОСТ 2.105: a dash, never a blank).
pub(crate) const NO_VALUE: &str = "—";

/// Significant digits of a value in a sheet's text.
pub(crate) const SIG: usize = 4;
/// Decimals of a relative error in per cent in a sheet's tables (0,01 %).
const ERROR_DECIMALS: usize = 2;

/// A value in a sheet's text: [`SIG`] significant digits.
pub(crate) fn value(x: f64, lang: Lang) -> String {
    format_sig(x, SIG, lang)
}

/// An angle given in radians, in degrees with the degree sign, to [`SIG`] significant digits
/// as a table's cell of it gives them (the friction's φ′ = 9,826° in its line and its table
/// alike), the zeros a round angle would trail left off as the textbook writes it
/// (θ = 38°, φ₁ = 199° at an extreme position, not 38,00° and 199,00°).
pub(crate) fn degrees(radians: f64, lang: Lang) -> String {
    format!("{}°", value(radians.to_degrees(), lang))
}

/// A relative error given as a fraction, in per cent to [`ERROR_DECIMALS`] (the unit is the
/// column's): `−16,67`.
pub(crate) fn error_pct(fraction: f64, lang: Lang) -> String {
    format_fixed(fraction * 100.0, ERROR_DECIMALS, lang)
}

/// The number a cell prints, read back as a reader reads it (`−57,5` → −57,5); `None` for a
/// cell that is no number (`—`).
pub(crate) fn printed(text: &str, lang: Lang) -> Option<f64> {
    text.replace('−', "-")
        .replace(lang.decimal(), ".")
        .parse()
        .ok()
        .filter(|x: &f64| x.is_finite())
}

/// The relative error of a row as its table prints it (issue 45: a reader who checks the
/// row finds the δ the table gives): from the graphical and the analytic value as printed,
/// `(g − a) / |a|`; `unrounded` (from the values before printing) where a cell is no
/// number; `None` where `unrounded` is (an analytic zero to rounding) or the printed
/// analytic is 0.
pub(crate) fn printed_error(
    graphical: &str,
    analytic: &str,
    unrounded: Option<f64>,
    lang: Lang,
) -> Option<f64> {
    unrounded?;
    match (printed(graphical, lang), printed(analytic, lang)) {
        (Some(_), Some(0.0)) => None,
        (Some(g), Some(a)) => Some((g - a) / a.abs()),
        _ => unrounded,
    }
}

/// A table column's precision (issue 45: the same per column): the decimals that give its
/// largest magnitude [`SIG`] significant digits, kept for every value of it, so that a column
/// reads `−3,200 / −2,504 / −0,337`, not `−3,2 / −2,504 / −0,3366`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Column {
    largest: f64,
    decimals: usize,
}

impl Column {
    /// The precision of a column holding `values` (the non-finite left out).
    pub(crate) fn of(values: impl IntoIterator<Item = f64>) -> Self {
        let largest = values
            .into_iter()
            .filter(|x| x.is_finite())
            .fold(0.0f64, |m, x| m.max(x.abs()));
        // The decimals of the largest value's last significant digit, one fewer when the
        // rounding carries it into the next decade (9999,6 → 10000).
        let decimals = if largest > 0.0 {
            let d = (SIG as i32 - 1 - largest.log10().floor() as i32).clamp(0, 15);
            let carried = (largest * 10f64.powi(d)).round() >= 10f64.powi(SIG as i32);
            (d - i32::from(carried)).max(0) as usize
        } else {
            0
        };
        Self { largest, decimals }
    }

    /// `x` in this column: 0 when it is zero to rounding against the column's largest (the
    /// report's rule, [`crate::check::is_zero`]), else to the column's decimals.
    pub(crate) fn cell(&self, x: f64, lang: Lang) -> String {
        if crate::check::is_zero(x, self.largest) {
            "0".into()
        } else {
            format_fixed(x, self.decimals, lang)
        }
    }
}

/// A table cell: [`SIG`] significant digits; what is zero to rounding against `scale` (the
/// report's rule, [`crate::check::is_zero`]) is written 0.
pub(crate) fn cell(x: f64, scale: f64, lang: Lang) -> String {
    if crate::check::is_zero(x, scale) {
        "0".into()
    } else {
        value(x, lang)
    }
}

/// The decimals of a value read to `step` (in its printed unit): those of the step's first
/// digit (0,5 → 1; 1 → 0; 0,02 → 2); `None` for no step (read exactly).
pub(crate) fn step_decimals(step: Option<f64>) -> Option<usize> {
    let step = step.filter(|s| *s > 0.0 && s.is_finite())?;
    Some((-step.log10() - 1e-9).ceil().clamp(0.0, 6.0) as usize)
}

/// A value read to `step` (in its printed unit): no finer than the step's decimals, nor
/// than [`SIG`] digits: `9,0` of a tooth read to 0,5 mm; [`value`] when read exactly.
pub(crate) fn read(x: f64, step: Option<f64>, lang: Lang) -> String {
    match read_decimals(x, step) {
        Some(d) => format_fixed(x, d, lang),
        None => value(x, lang),
    }
}

/// The value a reader carries on from `x` read to `step` (in its printed unit): `x` rounded
/// as [`read`] writes it (69 of 68,59 read to 1 mm); `x` itself when read exactly.
pub(crate) fn carried(x: f64, step: Option<f64>) -> f64 {
    match read_decimals(x, step) {
        Some(d) => {
            let f = 10f64.powi(d as i32);
            (x * f).round() / f
        }
        None => x,
    }
}

/// The decimals [`read`] writes `x` to: the step's, no finer than [`SIG`] digits; `None` for
/// no step or a zero.
fn read_decimals(x: f64, step: Option<f64>) -> Option<usize> {
    let d = step_decimals(step).filter(|_| x != 0.0)?;
    let sig = (SIG as i32 - 1 - x.abs().log10().floor() as i32).max(0) as usize;
    Some(d.min(sig))
}

/// A scale in a sheet's text at the sheet's precision: `μ_{φ} = 0,05236 рад/мм` (a derived
/// μ, not round, printed to [`SIG`] digits as every value of the sheet).
pub(crate) fn caption(scale: Scale, lang: Lang) -> String {
    format!(
        "μ_{{{}}} = {} {}",
        scale.quantity.symbol(),
        value(scale.value(), lang),
        scale.quantity.unit(lang)
    )
}

/// A length given in metres, in millimetres to [`SIG`] digits with the unit: `316,3 мм`.
pub(crate) fn mm(metres: f64, lang: Lang) -> String {
    format!("{} {}", value(metres * 1e3, lang), unit_in("mm", lang))
}

#[cfg(test)]
mod tests {
    use super::{degrees, error_pct, mm, printed_error, read, value, Column};
    use crate::scale::Lang;

    #[test]
    fn a_sheet_prints_a_drawings_precision() {
        // The review's strings (issue 45): α_w = 26,58075°, a_w = 316,276 (m),
        // ρ = 0,004975 м, H = 0,46233 м.
        assert_eq!(degrees(26.58075f64.to_radians(), Lang::Ru), "26,58°");
        assert_eq!(mm(0.316276, Lang::Uk), "316,3 мм");
        assert_eq!(mm(0.004975, Lang::Ru), "4,975 мм");
        assert_eq!(mm(0.46233, Lang::En), "462.3 mm");
        assert_eq!(value(5.43944, Lang::En), "5.439");
        // A round angle as the textbook writes it; φ′ = 9,8264° as its table's cell.
        assert_eq!(degrees(38.0016f64.to_radians(), Lang::Uk), "38°");
        assert_eq!(degrees(199.0008f64.to_radians(), Lang::Ru), "199°");
        assert_eq!(degrees(9.8264f64.to_radians(), Lang::En), "9.826°");
        // The gear table's δ of a ratio read 16,667 % off, the cam's 0,034 %.
        assert_eq!(error_pct(-0.16667, Lang::Ru), "−16,67");
        assert_eq!(error_pct(0.00034, Lang::En), "0.03");
    }

    #[test]
    fn a_reading_is_written_to_the_step_it_was_read_to() {
        // The shaper's gear sheet read to 0,5 mm (issue 45): s_a = 9,003 mm on the 1:1
        // rack picture, B₁B₂ = 48,00 mm on the 1:2 meshing picture (1 mm), λ = −0,8200 off
        // its 25 mm unit (0,02), ε_α = 1,161 to 1 mm over p_b = 41,33 mm.
        assert_eq!(read(9.003, Some(0.5), Lang::Ru), "9,0");
        assert_eq!(read(48.0, Some(1.0), Lang::Ru), "48");
        assert_eq!(read(-0.82, Some(0.02), Lang::En), "−0.82");
        assert_eq!(read(1.1614, Some(1.0 / 41.33), Lang::Ru), "1,16");
        // No finer than four digits; exactly read, four digits.
        assert_eq!(read(316.27, Some(0.001), Lang::En), "316.3");
        assert_eq!(read(9.003, None, Lang::Ru), "9,003");
        assert_eq!(read(9.003, Some(0.0), Lang::Ru), "9,003");
    }

    #[test]
    fn an_error_follows_the_values_as_printed() {
        // The shaper's gear table (issue 45): ω₈ read −16,25 to 1,25 rad/s printed −16
        // against −15,75: δ −1,59 %, not the −3,17 % of the unprinted reading.
        let e = printed_error("−16", "−15,75", Some(-0.0317), Lang::Ru).expect("δ");
        assert_eq!(error_pct(e, Lang::Ru), "−1,59");
        let e = printed_error("5.9", "5.877", Some(0.0043), Lang::En).expect("δ");
        assert_eq!(error_pct(e, Lang::En), "0.39");
        // No number printed: the unrounded δ; an analytic zero: none.
        assert_eq!(printed_error("—", "1,0", Some(0.5), Lang::Ru), Some(0.5));
        assert_eq!(printed_error("1", "0", Some(0.5), Lang::Ru), None);
        assert_eq!(printed_error("1", "2", None, Lang::Ru), None);
    }

    #[test]
    fn a_column_keeps_its_largest_values_decimals() {
        // The review's four-bar ω₂ column (issue 45).
        let c = Column::of([-3.2, -2.50412, -0.33661, f64::NAN]);
        let cells: Vec<String> = [-3.2, -2.50412, -0.33661]
            .iter()
            .map(|x| c.cell(*x, Lang::Ru))
            .collect();
        assert_eq!(cells, ["−3,200", "−2,504", "−0,337"]);
        // A column of hundreds keeps one decimal, its small values too; zero is 0.
        let c = Column::of([316.27, 5.123, 0.0]);
        assert_eq!(c.cell(316.27, Lang::En), "316.3");
        assert_eq!(c.cell(5.123, Lang::En), "5.1");
        assert_eq!(c.cell(0.0, Lang::En), "0");
        // 9999,6 rounds to five digits: no decimals.
        assert_eq!(Column::of([9999.6, 1.26]).cell(1.26, Lang::En), "1");
    }
}
