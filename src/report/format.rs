//! The writers of a [`Report`](crate::check::Report): JSON, CSV and Markdown.

use crate::check::{Column, Method, Report, Summary, SummaryEntry, Table};
use crate::scale::{format_sig, Lang};
use crate::words::number::{md_percent, md_value, ERROR_DIGITS};
use serde::Serialize;
use std::fmt::Write as _;

/// Significant digits of values in Markdown.
const VALUE_DIGITS: usize = 6;

/// `Some(x)` for a finite `x`, else `None` (written as `null`).
pub(crate) fn finite(x: f64) -> Option<f64> {
    x.is_finite().then_some(x)
}

/// Serialise `value` as pretty JSON with a final newline. The report types hold only strings,
/// numbers and sequences, so serialisation cannot fail; should it ever, the error is written
/// as a JSON object rather than panicking.
pub(crate) fn json<T: Serialize>(value: &T) -> String {
    match serde_json::to_string_pretty(value) {
        Ok(s) => s + "\n",
        Err(e) => format!("{{\"error\": {:?}}}\n", e.to_string()),
    }
}

#[derive(Serialize)]
struct JsonReport<'a> {
    scene: &'a str,
    rows: Vec<JsonRow>,
    summary: JsonSummary<'a>,
    tables: Vec<JsonTable<'a>>,
    notes: Vec<String>,
}

#[derive(Serialize)]
struct JsonRow {
    quantity: String,
    position: Option<String>,
    unit: &'static str,
    method: Method,
    graphical: Option<f64>,
    analytic: Option<f64>,
    abs_error: Option<f64>,
    rel_error: Option<f64>,
    conditioning: Option<f64>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    non_finite: Vec<&'static str>,
}

#[derive(Serialize)]
struct JsonSummary<'a> {
    entries: &'a [SummaryEntry],
    mean_by_method: Vec<JsonMean>,
}

#[derive(Serialize)]
struct JsonMean {
    method: Method,
    mean_abs_rel: f64,
}

#[derive(Serialize)]
struct JsonTable<'a> {
    title: &'a str,
    columns: &'a [Column],
    rows: Vec<JsonTableRow<'a>>,
}

#[derive(Serialize)]
struct JsonTableRow<'a> {
    position: &'a str,
    values: Vec<Option<f64>>,
}

/// CSV header of [`Report::to_csv`].
pub const CSV_HEADER: &str =
    "quantity,position,unit,method,graphical,analytic,abs_error,rel_error,conditioning";

impl Report {
    /// The report as JSON:
    /// `{"scene", "rows": [{"quantity", "position", "unit", "method", "graphical", "analytic",
    /// "abs_error", "rel_error", "conditioning"}], "summary": {"entries": [{"quantity",
    /// "method", "count", "mean_abs_rel", "max_abs_rel", "worst_position"}], "mean_by_method":
    /// [{"method", "mean_abs_rel"}]}, "tables": [{"title", "columns": [{"name", "unit"}],
    /// "rows": [{"position", "values"}]}]}`, keys in this order, floats at full precision.
    /// Absent and non-finite numbers are `null`; a row with a non-finite number also gets
    /// `"non_finite": [field names]`.
    pub fn to_json(&self) -> String {
        let rel = self.rel_errors();
        let rows = self
            .rows
            .iter()
            .zip(rel)
            .map(|(r, rel)| {
                let fields = [
                    ("graphical", Some(r.graphical)),
                    ("analytic", Some(r.analytic)),
                    ("abs_error", Some(r.abs_error())),
                    ("rel_error", rel),
                    ("conditioning", r.conditioning),
                ];
                let non_finite = fields
                    .iter()
                    .filter(|(_, v)| v.is_some_and(|v| !v.is_finite()))
                    .map(|(name, _)| *name)
                    .collect();
                JsonRow {
                    quantity: r.quantity(),
                    position: r.position(),
                    unit: r.unit(),
                    method: r.method,
                    graphical: finite(r.graphical),
                    analytic: finite(r.analytic),
                    abs_error: finite(r.abs_error()),
                    rel_error: rel.and_then(finite),
                    conditioning: r.conditioning.and_then(finite),
                    non_finite,
                }
            })
            .collect();
        let summary = self.summary();
        json(&JsonReport {
            scene: &self.scene,
            rows,
            summary: JsonSummary {
                entries: &summary.entries,
                mean_by_method: summary
                    .mean_by_method
                    .iter()
                    .map(|&(method, mean_abs_rel)| JsonMean {
                        method,
                        mean_abs_rel,
                    })
                    .collect(),
            },
            tables: self.tables.iter().map(json_table).collect(),
            notes: self.note_texts(),
        })
    }

    /// The rows as CSV: header [`CSV_HEADER`], one line per row (`\n` line ends), fields
    /// quoted per RFC 4180 when they hold a comma, quote or line break, an empty field for
    /// an absent value, floats at full precision.
    pub fn to_csv(&self) -> String {
        let mut out = String::from(CSV_HEADER);
        out.push('\n');
        for (r, rel) in self.rows.iter().zip(self.rel_errors()) {
            let fields = [
                csv_field(&r.quantity()),
                csv_field(&r.position().unwrap_or_default()),
                csv_field(r.unit()),
                r.method.key().to_string(),
                csv_value(r.graphical),
                csv_value(r.analytic),
                csv_value(r.abs_error()),
                csv_number(rel),
                csv_number(r.conditioning),
            ];
            out.push_str(&fields.join(","));
            out.push('\n');
        }
        out
    }

    /// The report as Markdown in `lang`: a heading with the scene, the section-1.6 summary
    /// (quantity, method, mean |δ| %, max |δ| %, worst position), one table per quantity
    /// (position, method, graphical, analytic, abs. error, δ %, conditioning), then the
    /// analytic tables. Numbers by [`format_sig`] with the language's decimal separator.
    pub fn to_markdown(&self, lang: Lang) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "# {} — {}\n",
            lang.pick(
                "Графические и аналитические значения",
                "Графічні та аналітичні значення",
                "Graphical against analytic values"
            ),
            md_cell(&self.scene)
        );
        summary_markdown(&mut out, &self.summary(), lang);
        let rel = self.rel_errors();
        for q in self.quantities() {
            let unit = self
                .rows
                .iter()
                .find(|r| r.quantity() == q)
                .map_or("", |r| r.unit());
            let _ = writeln!(out, "## {}, {}\n", md_cell(&q), md_cell(unit));
            md_header(
                &mut out,
                &[
                    lang.pick("положение", "положення", "position"),
                    lang.pick("метод", "метод", "method"),
                    lang.pick("графически", "графічно", "graphical"),
                    lang.pick("аналитически", "аналітично", "analytic"),
                    lang.pick("абс. погрешность", "абс. похибка", "abs. error"),
                    "δ, %",
                    lang.pick("обусловленность", "обумовленість", "conditioning"),
                ],
            );
            for (r, d) in self
                .rows
                .iter()
                .zip(&rel)
                .filter(|(r, _)| r.quantity() == q)
            {
                md_row(
                    &mut out,
                    &[
                        md_cell(&r.position().unwrap_or_default()),
                        r.method.name(lang).to_string(),
                        md_value(r.graphical, VALUE_DIGITS, lang),
                        md_value(r.analytic, VALUE_DIGITS, lang),
                        md_value(r.abs_error(), ERROR_DIGITS, lang),
                        d.map(|d| md_percent(d, lang)).unwrap_or_default(),
                        md_number(r.conditioning, ERROR_DIGITS, lang),
                    ],
                );
            }
            out.push('\n');
        }
        for t in &self.tables {
            table_markdown(&mut out, t, lang);
        }
        for n in self.note_texts() {
            out.push_str(&format!("* {n}\n"));
        }
        out
    }
}

fn json_table(t: &Table) -> JsonTable<'_> {
    JsonTable {
        title: &t.title,
        columns: &t.columns,
        rows: t
            .rows
            .iter()
            .map(|(position, values)| JsonTableRow {
                position,
                values: values.iter().map(|v| v.and_then(finite)).collect(),
            })
            .collect(),
    }
}

/// A CSV field, quoted (with doubled quotes) when it holds a comma, quote or line break.
pub(crate) fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// A number as JSON writes it (shortest round-trip form, exponent for very small or large
/// magnitudes); `NaN`/`inf` literally.
fn csv_value(x: f64) -> String {
    if x.is_finite() {
        serde_json::to_string(&x).unwrap_or_else(|_| x.to_string())
    } else {
        x.to_string()
    }
}

fn csv_number(x: Option<f64>) -> String {
    x.map(csv_value).unwrap_or_default()
}

/// Text for a Markdown table cell: `|` escaped, line breaks as spaces.
pub(crate) fn md_cell(s: &str) -> String {
    s.replace('|', "\\|").replace(['\n', '\r'], " ")
}

/// A Markdown table header with its separator line.
pub(crate) fn md_header(out: &mut String, names: &[&str]) {
    let cells: Vec<String> = names.iter().map(|n| md_cell(n)).collect();
    md_row(out, &cells);
    let _ = writeln!(out, "|{}", "---|".repeat(names.len()));
}

/// A Markdown table row of ready cells.
pub(crate) fn md_row(out: &mut String, cells: &[String]) {
    let _ = writeln!(out, "| {} |", cells.join(" | "));
}

fn md_number(x: Option<f64>, sig: usize, lang: Lang) -> String {
    x.map(|x| format_sig(x, sig, lang)).unwrap_or_default()
}

fn summary_markdown(out: &mut String, s: &Summary, lang: Lang) {
    let _ = writeln!(
        out,
        "## {}\n",
        lang.pick("Оценка погрешностей", "Оцінка похибок", "Error estimates")
    );
    md_header(
        out,
        &[
            lang.pick("величина", "величина", "quantity"),
            lang.pick("метод", "метод", "method"),
            "n",
            lang.pick("среднее |δ|, %", "середнє |δ|, %", "mean |δ|, %"),
            lang.pick("макс. |δ|, %", "макс. |δ|, %", "max |δ|, %"),
            lang.pick("худшее положение", "найгірше положення", "worst position"),
        ],
    );
    for e in &s.entries {
        md_row(
            out,
            &[
                md_cell(&e.quantity),
                e.method.name(lang).to_string(),
                e.count.to_string(),
                md_percent(e.mean_abs_rel, lang),
                md_percent(e.max_abs_rel, lang),
                md_cell(e.worst_named().unwrap_or("")),
            ],
        );
    }
    out.push('\n');
    if !s.mean_by_method.is_empty() {
        let means: Vec<String> = s
            .mean_by_method
            .iter()
            .map(|&(m, mean)| format!("{} {} %", m.name(lang), md_percent(mean, lang)))
            .collect();
        let _ = writeln!(
            out,
            "{}: {}.\n",
            lang.pick(
                "Средняя погрешность по методу",
                "Середня похибка за методом",
                "Mean error by method"
            ),
            means.join("; ")
        );
    }
}

fn table_markdown(out: &mut String, t: &Table, lang: Lang) {
    let _ = writeln!(out, "## {}\n", md_cell(&t.title));
    let names: Vec<String> = t
        .columns
        .iter()
        .map(|c| {
            if c.unit.is_empty() {
                c.name.clone()
            } else {
                format!("{}, {}", c.name, c.unit)
            }
        })
        .collect();
    let mut header = vec!["№"];
    header.extend(names.iter().map(String::as_str));
    md_header(out, &header);
    for (position, values) in &t.rows {
        let mut cells = vec![md_cell(position)];
        cells.extend(values.iter().map(|&v| md_number(v, VALUE_DIGITS, lang)));
        md_row(out, &cells);
    }
    out.push('\n');
}
