//! The audited table as Markdown, JSON and a sheet to return to the student.

use super::{Audited, ColumnReading, Edit, Explanation, Formula, Held, Known, Slip, Verdict};
use crate::plate::text::plain;
use crate::plate::{Plate, SheetSize};
use crate::scale::{format_sig, Lang};
use crate::scene::Scene;
use crate::sheets::BuildError;
use crate::words::{AuditText as T, Text};
use serde::Serialize;
use std::fmt::Write as _;

/// Significant digits of the exact values written.
const DIGITS: usize = 4;

/// The headings of the marked-up table in `lang`.
fn headings(lang: Lang) -> [&'static str; 8] {
    [
        T::Line.get(lang),
        Text::Quantity.get(lang),
        Text::PosShort.get(lang),
        Text::Method.get(lang),
        T::Written.get(lang),
        T::Exact.get(lang),
        T::Error.get(lang),
        T::Verdict.get(lang),
    ]
}

/// A number's text as `lang` writes it: its decimal sign, a true minus.
fn number(text: &str, lang: Lang) -> String {
    text.replace('-', "−")
        .replace('.', &lang.decimal().to_string())
}

/// A slip in words (label markup) in `lang`.
fn slip(s: &Slip, lang: Lang) -> String {
    match s {
        Slip::Sign => T::Sign.get(lang).into(),
        Slip::Coarse => T::Coarse.get(lang).into(),
        Slip::Truncated => T::Truncated.get(lang).into(),
        Slip::Factor(k) => format!("{} ×{}", T::Scale.get(lang), format_sig(*k, 3, lang)),
        Slip::OtherScale { used, own, factor } => format!(
            "{used} {} {own} (×{})",
            T::InsteadOf.get(lang),
            format_sig(*factor, 3, lang)
        ),
        Slip::Unit { meant } => format!(
            "{} {}",
            T::UnitSlip.get(lang),
            crate::words::unit_in(meant, lang)
        ),
        Slip::Digits { edits, meant } => {
            let words: Vec<&str> = edits
                .iter()
                .map(|e| match e {
                    Edit::Transposed => T::Transposed,
                    Edit::Dropped => T::Dropped,
                    Edit::Added => T::Added,
                })
                .map(|w| w.get(lang))
                .collect();
            format!("{} ({})", words.join(" / "), number(meant, lang))
        }
        Slip::Position(p) => format!("{} {p}", T::OtherPosition.get(lang)),
        Slip::Quantity(q) => format!("{} {}", T::OtherQuantity.get(lang), q.notation(lang)),
        Slip::Formula(f) => match f {
            Formula::BaseRadiusCosAlphaW => T::BaseRadius,
            Formula::ContactRatioCosAlphaW => T::ContactRatio,
            Formula::MissingOmega1 => T::MissingOmega,
        }
        .get(lang)
        .into(),
    }
}

/// An explanation in words: its slips joined by `+`.
fn explanation(e: &Explanation, lang: Lang) -> String {
    e.iter()
        .map(|s| slip(s, lang))
        .collect::<Vec<_>>()
        .join(" + ")
}

/// The verdict in words (label markup).
pub(super) fn verdict(v: &Verdict, lang: Lang) -> String {
    match v {
        Verdict::Right => T::Right.get(lang).into(),
        Verdict::Slips(all) => {
            let each: Vec<String> = all.iter().map(|e| explanation(e, lang)).collect();
            let text = each.join(&format!(" {} ", T::Or.get(lang)));
            if each.len() > 1 {
                format!("{}: {text}", T::Ambiguous.get(lang))
            } else {
                text
            }
        }
        Verdict::Wrong { nearest } => match nearest {
            None => T::Wrong.get(lang).into(),
            Some((e, r)) => format!(
                "{}; {}: {} ({} %)",
                T::Wrong.get(lang),
                T::Nearest.get(lang),
                explanation(e, lang),
                number(&format!("{:+.1}", r * 100.0), lang)
            ),
        },
        Verdict::NotInReport { known } if known.is_empty() => T::NoQuantity.get(lang).into(),
        Verdict::NotInReport { known } => format!(
            "{}; {}: {}",
            T::NotInReport.get(lang),
            T::ReportHas.get(lang),
            has(known, lang)
        ),
    }
}

/// What the report has of a quantity: each method with its positions (`plan: 3, 10`).
fn has(known: &Known, lang: Lang) -> String {
    known
        .iter()
        .map(|(m, at)| {
            let method = m.map_or(T::Analytic.get(lang), |m| m.name(lang));
            let at: Vec<&str> = at.iter().filter_map(|p| p.as_deref()).collect();
            if at.is_empty() {
                method.to_string()
            } else {
                format!("{method} {} {}", T::AtPositions.get(lang), at.join(", "))
            }
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// The method a value was checked by: as the student names it, else the report's (`key`:
/// its key, `analytic` for a cell of the analytic table; else its name in `lang`), with the
/// position whose tolerance it borrows.
fn method(a: &Audited, lang: Lang, key: bool) -> String {
    let analytic = || {
        if key {
            "analytic"
        } else {
            T::Analytic.get(lang)
        }
    };
    let name = match (&a.checked, &a.entry.method) {
        (None, m) => m.clone().unwrap_or_default(),
        (Some(_), Some(m)) if key => m.clone(),
        (Some(c), _) => match c.method {
            Some(m) if !a.entry.analytic() => {
                if key {
                    m.key().to_string()
                } else {
                    m.name(lang).to_string()
                }
            }
            _ => analytic().to_string(),
        },
    };
    match a.checked.as_ref().map(|c| &c.held) {
        Some(Held::Borrowed { position }) => format!(
            "{name} ({} {})",
            T::ToleranceOf.get(lang),
            position.as_deref().unwrap_or("—")
        ),
        _ => name,
    }
}

/// A slip as a short key for JSON: `sign`, `factor:2`, `unit:mm`, `dropped:7.18`.
fn key(s: &Slip) -> String {
    match s {
        Slip::Sign => "sign".into(),
        Slip::Coarse => "coarse".into(),
        Slip::Truncated => "truncated".into(),
        Slip::Factor(k) => format!("factor:{k}"),
        Slip::OtherScale { used, own, .. } => format!("scale:{used}/{own}"),
        Slip::Unit { meant } => format!("unit:{meant}"),
        Slip::Digits { edits, meant } => {
            let kinds: Vec<&str> = edits
                .iter()
                .map(|e| match e {
                    Edit::Transposed => "transposed",
                    Edit::Dropped => "dropped",
                    Edit::Added => "added",
                })
                .collect();
            format!("{}:{meant}", kinds.join("+"))
        }
        Slip::Position(p) => format!("position:{p}"),
        Slip::Quantity(q) => format!("quantity:{}", q.name),
        Slip::Formula(f) => format!(
            "formula:{}",
            match f {
                Formula::BaseRadiusCosAlphaW => "base-radius-cos-alpha-w",
                Formula::ContactRatioCosAlphaW => "contact-ratio-cos-alpha-w",
                Formula::MissingOmega1 => "missing-omega-1",
            }
        ),
    }
}

/// The slips of an explanation as keys.
pub fn keys(e: &Explanation) -> Vec<String> {
    e.iter().map(key).collect()
}

fn pct(r: Option<f64>) -> String {
    r.map_or("—".into(), |r| format!("{:+.2}", r * 100.0))
}

/// The exact value as written in a table (`—` for a line the report lacks).
fn exact(a: &Audited, lang: Lang) -> String {
    a.checked
        .as_ref()
        .map_or("—".into(), |c| format_sig(c.exact, DIGITS, lang))
}

/// A column of the student's table: a quantity's name and the method written.
type Column<'a> = (&'a str, Option<&'a str>);

/// The columns of the table read as magnitudes, each once, in the order met.
fn magnitudes(audited: &[Audited]) -> Vec<Column<'_>> {
    let mut out: Vec<Column> = Vec::new();
    for a in audited {
        let read = a.checked.as_ref().map(|c| c.reading);
        let column = (a.entry.quantity.as_str(), a.entry.method.as_deref());
        if read == Some(ColumnReading::Magnitudes) && !out.contains(&column) {
            out.push(column);
        }
    }
    out
}

/// The columns (a quantity by the method written) of two values or more not 0 whose every
/// value not 0 has the opposite sign (alone or with another slip): a table of the other
/// sense of rotation.
fn opposite(audited: &[Audited]) -> Vec<Column<'_>> {
    let mut columns: Vec<(Column, usize, bool)> = Vec::new();
    for a in audited
        .iter()
        .filter(|a| a.checked.is_some() && !a.entry.written.is_zero())
    {
        let column = (a.entry.quantity.as_str(), a.entry.method.as_deref());
        let sign = matches!(&a.verdict, Verdict::Slips(all)
            if all.iter().all(|e| e.first() == Some(&Slip::Sign)));
        match columns.iter_mut().find(|c| c.0 == column) {
            Some(c) => {
                c.1 += 1;
                c.2 &= sign;
            }
            None => columns.push((column, 1, sign)),
        }
    }
    columns
        .into_iter()
        .filter(|c| c.1 >= 2 && c.2)
        .map(|c| c.0)
        .collect()
}

/// Columns named as the Markdown writes them: `v_D (plan)`, `omega_3`.
fn named(columns: &[Column]) -> String {
    columns
        .iter()
        .map(|(q, m)| match m {
            Some(m) => format!("{q} ({m})"),
            None => q.to_string(),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The convention the table is read in, in words: signed values as the textbook's tables,
/// with the columns read as magnitudes and those of the opposite sign throughout; or, when
/// every column is read as magnitudes, a table of magnitudes.
fn signs(audited: &[Audited], lang: Lang) -> String {
    let columns = magnitudes(audited);
    let checked = audited.iter().filter(|a| a.checked.is_some());
    let all = checked.clone().count() > 0
        && checked.clone().all(|a| {
            a.checked
                .as_ref()
                .is_some_and(|c| c.reading == ColumnReading::Magnitudes)
        });
    let mut s = format!("{}: ", T::Signs.get(lang));
    if all {
        s.push_str(&plain(T::NoSigns.get(lang)));
        s.push('.');
        return s;
    }
    s.push_str(&plain(T::SignedAsTextbook.get(lang)));
    s.push('.');
    for (word, columns) in [
        (T::ReadAsMagnitudes, columns),
        (T::OppositeSense, opposite(audited)),
    ] {
        if !columns.is_empty() {
            let _ = write!(s, " {}: {}.", plain(word.get(lang)), named(&columns));
        }
    }
    s
}

/// The audited table as Markdown: the convention its signs are read in, then a row per
/// value, its exact value in the unit written (as read: a magnitude in a column of
/// magnitudes), its error and its verdict.
pub fn to_markdown(scene: &str, audited: &[Audited], lang: Lang) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# {} — {scene}\n", plain(T::Title.get(lang)));
    let _ = writeln!(s, "{}\n", signs(audited, lang));
    let _ = writeln!(s, "| {} |", headings(lang).join(" | "));
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|");
    for a in audited {
        let e = &a.entry;
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} {} | {} | {} | {} |",
            e.line,
            e.quantity,
            e.position.as_deref().unwrap_or("—"),
            method(a, lang, true),
            e.written.text,
            e.unit.name,
            exact(a, Lang::En),
            pct(a.checked.as_ref().and_then(|c| c.rel_error)),
            plain(&verdict(&a.verdict, lang))
        );
    }
    s
}

#[derive(Serialize)]
struct JsonEntry<'a> {
    line: u64,
    quantity: &'a str,
    position: Option<&'a str>,
    method: String,
    written: &'a str,
    unit: &'a str,
    exact: Option<f64>,
    tolerance: Option<f64>,
    rel_error: Option<f64>,
    reading: Option<&'static str>,
    tolerance_of: Option<&'a str>,
    verdict: &'static str,
    explanations: Vec<Vec<String>>,
    nearest: Option<JsonNearest>,
    text: String,
}

#[derive(Serialize)]
struct JsonNearest {
    slips: Vec<String>,
    rel_error: f64,
}

/// The audited table as JSON: per value, its exact value and tolerance in the unit written,
/// how its column is read (`signed`, `magnitudes`), the position whose tolerance it borrows
/// when its construction is not made at its own, its verdict (`right`, `slip`, `wrong`,
/// `not-in-report`), each explanation as a list of slip keys (`sign`, `factor:2`, `unit:mm`,
/// `dropped:7.18`, `position:4`, `formula:missing-omega-1`, …) and the verdict in English
/// words.
pub fn to_json(audited: &[Audited]) -> String {
    let rows: Vec<JsonEntry> = audited
        .iter()
        .map(|a| {
            let e = &a.entry;
            let (verdict, explanations, nearest) = match &a.verdict {
                Verdict::Right => ("right", Vec::new(), None),
                Verdict::Slips(all) => ("slip", all.iter().map(keys).collect(), None),
                Verdict::Wrong { nearest } => (
                    "wrong",
                    Vec::new(),
                    nearest.as_ref().map(|(x, r)| JsonNearest {
                        slips: keys(x),
                        rel_error: *r,
                    }),
                ),
                Verdict::NotInReport { .. } => ("not-in-report", Vec::new(), None),
            };
            let c = a.checked.as_ref();
            JsonEntry {
                line: e.line,
                quantity: &e.quantity,
                position: e.position.as_deref(),
                method: method(a, Lang::En, true),
                written: &e.written.text,
                unit: e.unit.name,
                exact: c.map(|c| c.exact),
                tolerance: c.map(|c| c.tolerance),
                rel_error: c.and_then(|c| c.rel_error).filter(|r| r.is_finite()),
                reading: c.map(|c| match c.reading {
                    ColumnReading::Signed => "signed",
                    ColumnReading::Magnitudes => "magnitudes",
                }),
                tolerance_of: c.and_then(|c| match &c.held {
                    Held::Borrowed { position } => position.as_deref(),
                    _ => None,
                }),
                verdict,
                explanations,
                nearest,
                text: plain(&self::verdict(&a.verdict, Lang::En)),
            }
        })
        .collect();
    crate::report::json(&rows)
}

/// The audited table as sheets to return to the student (the smallest format from A4 as wide
/// as the table, as many sheets as it needs): each value with its method, its exact value,
/// its error and its verdict, in the textbook's notation — a quantity whose column is read as
/// magnitudes written |V_{D}|.
///
/// # Errors
/// [`BuildError`] when the table is wider than an A2.
pub fn to_sheet(scene: &Scene, audited: &[Audited], lang: Lang) -> Result<Vec<Plate>, BuildError> {
    const SIZES: [SheetSize; 3] = [SheetSize::A4, SheetSize::A3, SheetSize::A2];
    let rows: Vec<Vec<String>> = audited
        .iter()
        .map(|a| {
            let e = &a.entry;
            let unit = match e.unit.name {
                "1" => String::new(),
                name => crate::words::unit_in(name, lang),
            };
            let quantity = match &a.checked {
                Some(c) if c.reading == ColumnReading::Magnitudes => {
                    format!("|{}|", c.quantity.notation(lang))
                }
                Some(c) => c.quantity.notation(lang),
                None => e.quantity.clone(),
            };
            let exact = match &a.checked {
                Some(_) => format!("{} {unit}", exact(a, lang)),
                None => "—".into(),
            };
            vec![
                e.line.to_string(),
                quantity,
                e.position.clone().unwrap_or_else(|| "—".into()),
                method(a, lang, false),
                format!("{} {unit}", number(&e.written.text, lang))
                    .trim_end()
                    .to_string(),
                exact.trim_end().to_string(),
                number(&pct(a.checked.as_ref().and_then(|c| c.rel_error)), lang),
                verdict(&a.verdict, lang),
            ]
        })
        .collect();
    let width = |rows: &[Vec<String>], c: usize, head: &str| {
        rows.iter()
            .map(|r| r[c].as_str())
            .chain([head])
            .map(|t| crate::plate::text::approx_width(t, 3.0) + 4.0)
            .fold(12.0, f64::max)
    };
    let columns = headings(lang)
        .iter()
        .enumerate()
        .map(|(c, h)| (h.to_string(), width(&rows, c, h)))
        .collect();
    crate::sheets::table_sheet(
        scene,
        (T::Title.get(lang), T::Audit.get(lang)),
        columns,
        rows,
        (&SIZES, "audit"),
        lang,
    )
}
