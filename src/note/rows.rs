//! The report's rows as the note's tables: by position (graphical, analytic and their
//! difference for each quantity, the seed's Tables 2 and 9 shape) and of the whole scene.

use super::markup::{label, power_of_ten, text, Align, LEAST_PLAIN};
use super::Writer;
use crate::check::{is_zero, Method, Row, ZERO_FRACTION};
use crate::scale::format_sig_from;
use crate::words::{quantity, shown_unit, unit_in, NoteText as T, Text as S};

pub(super) use crate::words::md_percent as percent;

/// A value as the note prints it: to `sig` significant digits, below 0,001 as a power of ten
/// (`1,44133·10⁻⁸`, the superscript set by the note's markup; ГОСТ 2.105 has neither the
/// `e` form nor runs of zeros, [`LEAST_PLAIN`]); `—` for no number.
pub(super) fn fmt(x: f64, sig: usize, lang: crate::scale::Lang) -> String {
    if !x.is_finite() {
        return crate::words::md_value(x, sig, lang);
    }
    power_of_ten(&format_sig_from(x, sig, lang, LEAST_PLAIN))
}

/// Significant digits of a value in the note's tables.
pub(super) const DIGITS: usize = 4;

/// A row's value with a rounding residue against its quantity's scale written as 0 (a plan
/// at drafting 0 is exact: ω₄ = 1e−16 is ω₄ = 0).
pub(super) fn value(x: f64, r: &Row) -> f64 {
    if is_zero(x, r.scale) {
        0.0
    } else {
        x
    }
}

/// The quantities (name and method) of the rows `keep` accepts, in the order they first
/// appear; a quantity zero everywhere (a translating link's ω) is left out.
pub(super) fn quantities(rows: &[Row], keep: impl Fn(&Row) -> bool) -> Vec<(String, Method)> {
    let mut out: Vec<(String, Method)> = Vec::new();
    for r in rows.iter().filter(|r| keep(r)) {
        let q = (r.quantity(), r.method);
        if !out.contains(&q) {
            out.push(q);
        }
    }
    out.retain(|(q, m)| {
        rows.iter()
            .filter(|r| r.quantity() == *q && r.method == *m)
            .any(|r| value(r.analytic, r) != 0.0 || value(r.graphical, r) != 0.0)
    });
    out
}

/// A row's quantity in label markup as the sheets name it: the textbook's symbol
/// (`V_{B3}`, `F_{и3}`); a value of a friction case by its symbol on the friction sheet and
/// the case's number (`P (случай 1)`); a cut wheel's by its shift (`s_{a} (x = 0,6)`).
pub(super) fn symbol(w: &Writer<'_, '_>, r: &Row) -> String {
    if !w.session.scene().friction.is_empty() {
        if let Ok(solved) = w.session.friction() {
            for (n, s) in solved.iter().enumerate() {
                if let Some(x) = s.readings.iter().find(|x| x.row.key.same_quantity(&r.key)) {
                    return format!("{} ({} {})", x.symbol, w.word(S::Case), n + 1);
                }
            }
        }
    }
    if w.session.scene().gears.is_some() {
        if let Some(name) = w
            .session
            .gears()
            .ok()
            .and_then(|g| crate::sheets::cut_wheel_quantity(&g, r, w.lang))
        {
            return name;
        }
    }
    quantity(r.key.symbol, &r.key.subject, w.lang)
}

/// A row's value `x` (in SI) in the unit its column shows, as the sheets show it
/// ([`shown_unit`]: a length in millimetres, no run of zeros).
pub(super) fn shown(r: &Row, x: f64) -> f64 {
    x * shown_unit(r.key.symbol).0
}

/// A quantity's symbol and the unit it is shown in ([`shown`]) as a column head:
/// `V_{B3}, м/с`, `S, мм`.
pub(super) fn head(w: &Writer<'_, '_>, r: &Row) -> String {
    let unit = unit_in(shown_unit(r.key.symbol).1, w.lang);
    let symbol = symbol(w, r);
    if unit.is_empty() || unit == "1" {
        symbol
    } else {
        format!("{symbol}, {unit}")
    }
}

/// Tables by position of `quantities` (at most three to a table, so that one fits the
/// page's width): each quantity's graphical value, its analytic twin and their difference
/// in %, one row per position.
pub(super) fn by_position(w: &mut Writer<'_, '_>, caption: &str, quantities: &[(String, Method)]) {
    let lang = w.lang;
    let positions: Vec<String> = {
        let mut ps: Vec<String> = Vec::new();
        for r in &w.report.rows {
            if quantities.contains(&(r.quantity(), r.method)) {
                if let Some(p) = r.position() {
                    if !ps.contains(&p) {
                        ps.push(p);
                    }
                }
            }
        }
        ps
    };
    let rel = w.report.rel_errors();
    // At most three quantities to a table, the tables as even as the count allows (four
    // are two and two, not three and one).
    let tables = quantities.len().div_ceil(3).max(1);
    let chunks: Vec<&[(String, Method)]> = quantities
        .chunks(quantities.len().div_ceil(tables).max(1))
        .collect();
    let parts = chunks.len();
    for (c, chunk) in chunks.into_iter().enumerate() {
        let find = |q: &(String, Method), p: &str| {
            w.report.rows.iter().zip(&rel).find(|(r, _)| {
                r.quantity() == q.0 && r.method == q.1 && r.position().as_deref() == Some(p)
            })
        };
        let mut header = vec![text(w.word(T::PositionShort))];
        let mut align = vec![Align::Centre];
        for q in chunk {
            let Some((r, _)) = w
                .report
                .rows
                .iter()
                .zip(&rel)
                .find(|(r, _)| r.quantity() == q.0 && r.method == q.1)
            else {
                continue;
            };
            let h = head(w, r);
            header.push(label(&format!("{h} ({})", w.word(T::GraphicalShort))));
            header.push(label(&format!("{h} ({})", w.word(T::AnalyticShort))));
            header.push(text("δ, %"));
            align.extend([Align::Centre; 3]);
        }
        // Each cell's row, found once: [position][quantity].
        let found: Vec<Vec<_>> = positions
            .iter()
            .map(|p| chunk.iter().map(|q| find(q, p)).collect())
            .collect();
        // One precision per quantity: the decimals its largest value needs, graphical and
        // analytic alike (a drawing's table, issue 45).
        let decimals: Vec<Option<usize>> = (0..chunk.len())
            .map(|k| {
                let largest = found
                    .iter()
                    .filter_map(|cells| cells[k])
                    .flat_map(|(r, _)| [shown(r, r.graphical), shown(r, r.analytic)])
                    .filter(|x| x.is_finite())
                    .fold(0.0f64, |m, x| m.max(x.abs()));
                decimals(largest, DIGITS)
            })
            .collect();
        let body: Vec<Vec<String>> = positions
            .iter()
            .zip(&found)
            .map(|(p, cells)| {
                let mut row = vec![text(p)];
                for (cell, &d) in cells.iter().zip(&decimals) {
                    match cell {
                        Some((r, e)) => {
                            for x in [r.graphical, r.analytic] {
                                let x = shown(r, value(x, r));
                                row.push(text(&column_cell(x, d, DIGITS, lang)));
                            }
                            row.push(text(
                                &e.map(|e| percent(e, lang)).unwrap_or_else(|| "—".into()),
                            ));
                        }
                        None => row.extend([text("—"), text("—"), text("—")]),
                    }
                }
                row
            })
            .collect();
        let caption = if parts > 1 {
            format!("{caption} ({} {}/{parts})", w.word(T::Part), c + 1)
        } else {
            caption.to_string()
        };
        w.doc.table(&caption, &align, &header, &body);
    }
}

/// The rows of the whole scene `keep` accepts: quantity, method, graphical, analytic, δ;
/// each row as printed once.
pub(super) fn of_scene(w: &mut Writer<'_, '_>, caption: &str, keep: impl Fn(&Row) -> bool) {
    let lang = w.lang;
    let rel = w.report.rel_errors();
    let mut body: Vec<Vec<String>> = w
        .report
        .rows
        .iter()
        .zip(&rel)
        .filter(|(r, _)| keep(r))
        .map(|(r, d)| {
            let pair = same_decimals(
                [r.graphical, r.analytic].map(|x| shown(r, value(x, r))),
                DIGITS,
                lang,
            );
            vec![
                label(&head(w, r)),
                text(
                    &r.position()
                        .map(|p| format!("{} {p}", r.method.name(lang)))
                        .unwrap_or_else(|| r.method.name(lang).to_string()),
                ),
                text(&pair[0]),
                text(&pair[1]),
                text(&d.map(|d| percent(d, lang)).unwrap_or_else(|| "—".into())),
            ]
        })
        .collect();
    // A row the table already holds word for word once (x_min of two wheels of one z).
    let mut seen = std::collections::HashSet::new();
    body.retain(|row| seen.insert(row.clone()));
    if body.is_empty() {
        return;
    }
    let header = [
        text(w.word(S::Quantity)),
        text(w.word(S::Method)),
        text(w.word(S::Graphical)),
        text(w.word(S::Analytic)),
        text("δ, %"),
    ];
    w.doc.table(
        caption,
        &[
            Align::Left,
            Align::Left,
            Align::Centre,
            Align::Centre,
            Align::Centre,
        ],
        &header,
        &body,
    );
}

/// A column of numbers under its head (label markup); `None` for an empty cell.
pub(super) struct Column {
    /// The head: symbol and unit in label markup.
    pub head: String,
    /// The values, one per row.
    pub values: Vec<Option<f64>>,
    /// Significant digits.
    pub digits: usize,
    /// The zero reference of a rounding residue ([`is_zero`]); the column's largest value
    /// when `None`.
    pub scale: Option<f64>,
}

impl Column {
    /// A column of `values` to [`DIGITS`] significant digits.
    pub(super) fn new(head: impl Into<String>, values: Vec<Option<f64>>) -> Self {
        Self {
            head: head.into(),
            values,
            digits: DIGITS,
            scale: None,
        }
    }

    /// The same column with a rounding residue judged against `scale`.
    pub(super) fn against(self, scale: f64) -> Self {
        Self {
            scale: Some(scale),
            ..self
        }
    }
}

/// A table of numbers by position: the position column, then `columns`; in each column a
/// rounding residue against its largest value is written 0 ([`ZERO_FRACTION`]).
pub(super) fn numbers(
    w: &mut Writer<'_, '_>,
    caption: &str,
    positions: &[String],
    columns: &[Column],
) {
    let lang = w.lang;
    let mut header = vec![text(w.word(T::PositionShort))];
    header.extend(columns.iter().map(|c| label(&c.head)));
    let rows: Vec<Vec<String>> = positions
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let mut row = vec![text(p)];
            for c in columns {
                let largest = c
                    .values
                    .iter()
                    .flatten()
                    .fold(0.0f64, |m, x| m.max(x.abs()));
                let zero = c.scale.unwrap_or(largest);
                let x = c.values.get(k).copied().flatten();
                let x = x.map(|x| if is_zero(x, zero) { 0.0 } else { x });
                let d = decimals(largest, c.digits);
                row.push(text(
                    &x.map_or_else(|| "—".into(), |x| in_column(x, d, c.digits, lang)),
                ));
            }
            row
        })
        .collect();
    let align = vec![Align::Centre; header.len()];
    w.doc.table(caption, &align, &header, &rows);
}

/// The decimals every value of a column whose largest magnitude is `largest` is printed
/// with (ГОСТ 2.105: one number of decimals in a column): as many as the largest needs for
/// `digits` significant digits; `None` for a column whose largest value is below 0,001 (it
/// keeps its own significant digits, as powers of ten: [`LEAST_PLAIN`]) or of zeros.
fn decimals(largest: f64, digits: usize) -> Option<usize> {
    if largest == 0.0 || !largest.is_finite() {
        return None;
    }
    let magnitude = largest.log10().floor() as i32;
    let d = digits as i32 - 1 - magnitude;
    (magnitude >= LEAST_PLAIN).then_some(d.max(0) as usize)
}

/// Two values of one quantity (graphical and analytic) with one number of decimals, those
/// the larger needs for `digits` significant digits ([`decimals`]); as [`fmt`] past them.
fn same_decimals(values: [f64; 2], digits: usize, lang: crate::scale::Lang) -> [String; 2] {
    let largest = values[0].abs().max(values[1].abs());
    let d = decimals(largest, digits);
    values.map(|x| column_cell(x, d, digits, lang))
}

/// A value in a column of `d` decimals ([`in_column`]), 0 written «0».
fn column_cell(x: f64, d: Option<usize>, digits: usize, lang: crate::scale::Lang) -> String {
    match x {
        0.0 => "0".into(),
        _ => in_column(x, d.filter(|_| x.is_finite()), digits, lang),
    }
}

/// A value in a column of `d` decimals ([`decimals`]); as [`fmt`] to `digits` significant
/// digits in a column without.
fn in_column(x: f64, d: Option<usize>, digits: usize, lang: crate::scale::Lang) -> String {
    match d {
        Some(d) => crate::scale::format_fixed(x, d, lang),
        None => fmt(x, digits, lang),
    }
}

/// The positions at which any of `quantities` was read, in the report's order.
pub(super) fn positions_of(rows: &[Row], quantities: &[(String, Method)]) -> Vec<String> {
    let mut ps: Vec<String> = Vec::new();
    for r in rows {
        if quantities.contains(&(r.quantity(), r.method)) {
            if let Some(p) = r.position() {
                if !ps.contains(&p) {
                    ps.push(p);
                }
            }
        }
    }
    ps
}

/// The seed's shape of a table of readings (its Table 2): one column per quantity, its
/// graphical value at each position (no such table for an empty `caption`: its values stand
/// in another); then the same quantities' relative difference from the analytic twin, in %,
/// as a second table captioned `errors`.
pub(super) fn values_and_errors(
    w: &mut Writer<'_, '_>,
    (caption, errors): (&str, &str),
    quantities: &[(String, Method)],
) {
    let positions = positions_of(&w.report.rows, quantities);
    let rel = w.report.rel_errors();
    let mut values = Vec::new();
    let mut deltas = Vec::new();
    for q in quantities {
        let Some(first) = w
            .report
            .rows
            .iter()
            .find(|r| r.quantity() == q.0 && r.method == q.1)
        else {
            continue;
        };
        let head = head(w, first);
        let symbol = quantity(first.key.symbol, &first.key.subject, w.lang);
        let at = |p: &String| {
            w.report.rows.iter().zip(&rel).find(|(r, _)| {
                r.quantity() == q.0 && r.method == q.1 && r.position().as_ref() == Some(p)
            })
        };
        values.push(
            Column::new(
                head,
                positions
                    .iter()
                    .map(|p| at(p).map(|(r, _)| value(r.graphical, r)))
                    .collect(),
            )
            .against(first.scale),
        );
        let mut delta = Column::new(
            format!("δ{symbol}, %"),
            positions
                .iter()
                .map(|p| at(p).and_then(|(_, d)| d.map(|d| d * 100.0)))
                .collect(),
        );
        delta.digits = 3;
        // The report's rule: a relative error of at most 1e-9 is a rounding residue, 0.
        deltas.push(delta.against(1e-9 * 100.0 / ZERO_FRACTION));
    }
    if !caption.is_empty() {
        numbers(w, caption, &positions, &values);
    }
    numbers(w, errors, &positions, &deltas);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scale::Lang;

    #[test]
    fn a_tiny_value_is_a_power_of_ten_not_an_e_form() {
        assert_eq!(fmt(1.44133e-8, 6, Lang::Ru), "1,44133·10⁻⁸");
        assert_eq!(fmt(-8.538e-7, 4, Lang::Ru), "−8,538·10⁻⁷");
        assert_eq!(fmt(0.5, 4, Lang::Ru), "0,5");
    }

    #[test]
    fn a_column_prints_its_values_with_the_decimals_of_its_largest() {
        assert_eq!(decimals(2.175, 4), Some(3));
        assert_eq!(decimals(113.7, 4), Some(1));
        assert_eq!(decimals(45_000.0, 4), Some(0));
        assert_eq!(decimals(1.44e-8, 4), None);
        assert_eq!(decimals(0.0, 4), None);
    }
}
