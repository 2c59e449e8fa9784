//! Issue 46 §1: the note's worked formulas are data — symbol, formula, numbers, result and
//! unit — which one writer sets. Each is held here to two things: the number it prints is
//! its value to the digits printed, and a formula that works out a row of the report gives
//! that row's value: the graphical one of the row by its method where the note works the
//! textbook's chain or a reading, the analytic one where it works the twin's formula.

use std::path::PathBuf;
use tmm::check::{Key, Report, Symbol};
use tmm::note::{Printed, RowValue, Worked};
use tmm::{Drafting, Lang, Session};

fn scene(path: &std::path::Path) -> tmm::Scene {
    tmm::load(path).expect("scene")
}

/// Every shipped scene's file.
fn scenes() -> Vec<PathBuf> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("constructions");
    let mut out: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("constructions")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    out.sort();
    out
}

/// The number a formula prints (Typst math: `"0,5"`, `-"12,25"`, `"1,7" dot 10^(-5)`).
fn parse(shown: &str) -> Option<f64> {
    let (mantissa, power) = match shown.split_once(" dot 10^(") {
        Some((m, p)) => (m, p.strip_suffix(')')?.parse::<i32>().ok()?),
        None => (shown, 0),
    };
    let plain: String = mantissa
        .chars()
        .filter(|c| !matches!(c, '"' | ' ' | '\u{2009}' | '\u{202f}' | '\u{a0}'))
        .map(|c| match c {
            ',' => '.',
            '−' => '-',
            c => c,
        })
        .collect();
    Some(plain.parse::<f64>().ok()? * 10f64.powi(power))
}

/// Half a unit of the last of `digits` significant digits of `x`.
fn half_step(x: f64, digits: usize) -> f64 {
    if x == 0.0 {
        return 0.0;
    }
    let magnitude = x.abs().log10().floor() as i32;
    0.5 * 10f64.powi(magnitude + 1 - digits as i32)
}

/// A row's value in SI (the report keeps a gear's angles in degrees).
fn row_si(symbol: Symbol, x: f64) -> f64 {
    if symbol.unit() == "deg" {
        x.to_radians()
    } else {
        x
    }
}

/// What is wrong with the worked formulas `rows` against `report`, a line each.
fn faults(rows: &[Worked], report: &Report) -> Vec<String> {
    let mut out = Vec::new();
    for w in rows {
        let v = &w.value;
        match parse(&v.shown) {
            Some(x) if (x - v.value).abs() <= half_step(v.value, v.digits) * 1.000_001 => {}
            other => out.push(format!(
                "{} prints {:?} ({other:?}) for {}",
                w.symbol, v.shown, v.value
            )),
        }
        let Some((key, column)) = &w.gives else {
            continue;
        };
        let row = report.rows.iter().find(|r| {
            &r.key == key
                && match column {
                    RowValue::Analytic => true,
                    RowValue::Graphical(m) => r.method == *m,
                }
        });
        let Some(r) = row else {
            out.push(format!(
                "{} gives {key:?} {column:?}, which the report has not",
                w.symbol
            ));
            continue;
        };
        let want = row_si(
            key.symbol,
            match column {
                RowValue::Analytic => r.analytic,
                RowValue::Graphical(_) => r.graphical,
            },
        );
        let got = v.value * v.to_si;
        if (got - want).abs() > 1e-9 * want.abs().max(1e-12) {
            out.push(format!(
                "{} = {got} gives {} = {want} ({:?})",
                w.symbol,
                r.quantity(),
                r.method
            ));
        }
    }
    out
}

/// The note's worked formulas of a scene in `lang`, and its report.
fn worked(path: &std::path::Path, lang: Lang) -> (Vec<Worked>, Report) {
    let s = scene(path);
    let session = Session::new(&s, Drafting::HAND);
    let note = tmm::note::compose(&session, lang).expect("note");
    (note.worked, session.report().expect("report"))
}

#[test]
fn every_worked_formula_prints_its_value_and_gives_the_reports_row() {
    let mut found = Vec::new();
    let mut giving = Vec::new();
    for path in scenes() {
        let stem = path
            .file_stem()
            .expect("stem")
            .to_string_lossy()
            .to_string();
        for lang in [Lang::Ru, Lang::En] {
            let (rows, report) = worked(&path, lang);
            found.extend(
                faults(&rows, &report)
                    .into_iter()
                    .map(|f| format!("{stem} {lang:?}: {f}")),
            );
            if lang == Lang::Ru {
                giving.push((
                    stem.clone(),
                    rows.iter().filter(|w| w.gives.is_some()).count(),
                ));
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
    let of = |stem: &str| giving.iter().find(|(s, _)| s == stem).map(|(_, n)| *n);
    // The pair's geometry (24 rows: p, p_b, y, a_w, each wheel's r, r_b, r_w, r_f, r_a, h,
    // s, α_a, s_a; ε_α twice; Δy is the scene's table's), the friction cases, the rotor's
    // corrections.
    assert!(of("gears-pz3").is_some_and(|n| n >= 24), "{giving:?}");
    assert!(of("friction").is_some_and(|n| n >= 14), "{giving:?}");
    assert!(of("rotor-dynamic").is_some_and(|n| n >= 6), "{giving:?}");
    assert!(
        of("gears-differential").is_some_and(|n| n >= 1),
        "{giving:?}"
    );
}

/// A formula that prints another number than its value, or gives another value than its
/// row's, is found, with its numbers.
#[test]
fn a_worked_formula_off_its_value_or_its_row_is_found() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("constructions/gears-pz3.toml");
    let (rows, report) = worked(&path, Lang::Ru);
    let radius = Key::of_scene(Symbol::Radius, "a1");
    let mut bad = rows
        .iter()
        .find(|w| w.gives.as_ref().is_some_and(|(k, _)| k == &radius))
        .expect("r_a1 worked")
        .clone();
    assert!(faults(std::slice::from_ref(&bad), &report).is_empty());
    // The tip radius worked 0,01 mm off: the report's r_a1 is not what the note works.
    bad.value.value += 0.01;
    let found = faults(std::slice::from_ref(&bad), &report);
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(found[0].contains("prints"), "{found:?}");
    assert!(found[1].contains("r_a1"), "{found:?}");
    // Printed as another number than its value.
    let mut misprinted = bad.clone();
    misprinted.value = Printed {
        shown: "\"41,5\"".into(),
        ..rows
            .iter()
            .find(|w| w.gives.as_ref().is_some_and(|(k, _)| k == &radius))
            .expect("r_a1")
            .value
            .clone()
    };
    let found = faults(std::slice::from_ref(&misprinted), &report);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("prints"), "{found:?}");
    assert_eq!(parse("-\"1,25\" dot 10^(-3)"), Some(-0.00125));
}
