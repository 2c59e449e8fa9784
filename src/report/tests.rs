use crate::check::{Column, Key, Method, Report, Row, SummaryEntry, Symbol, Table};
use crate::scale::Lang;
use serde_json::Value;

fn row(quantity: &str, position: &str, method: Method, graphical: f64, analytic: f64) -> Row {
    let (symbol, subject) = match quantity.split_once('_') {
        Some(("a", s)) => (Symbol::Acceleration, s),
        Some((_, s)) => (Symbol::Velocity, s),
        None => (Symbol::Velocity, quantity),
    };
    Row {
        key: Key::at_position(symbol, subject, position),
        method,
        graphical,
        analytic,
        conditioning: Some(37.5),
        scale: 0.0,
    }
}

/// Section 1.6 of the seed, recomputed: plan velocities against the exact ram values.
fn sample() -> Report {
    Report {
        scene: "shaper-000".into(),
        rows: vec![
            row("v_D", "3", Method::Plan, 2.25, 2.5),
            row("v_D", "5", Method::Plan, 2.75, 2.5),
            row("v_D", "8′", Method::Plan, 0.001, 0.0),
            row("a_D", "1", Method::DiagramChords, 54.0, 60.0),
            row("a_D", "10", Method::DiagramChords, 66.0, 60.0),
            row("a_D", "3", Method::DiagramChords, 18.0, 20.0),
        ],
        tables: vec![Table {
            title: "Table 5".into(),
            columns: vec![
                Column {
                    name: "φ_1".into(),
                    unit: "°".into(),
                },
                Column {
                    name: "ω_3".into(),
                    unit: "1/s".into(),
                },
            ],
            rows: vec![
                ("1".into(), vec![Some(199.0), Some(0.0001)]),
                ("8′".into(), vec![Some(-19.0), None]),
            ],
        }],
        notes: Vec::new(),
    }
}

#[test]
fn errors_of_a_row() {
    let r = row("v_D", "1", Method::Plan, 2.25, -2.5);
    assert!((r.abs_error() - 4.75).abs() < 1e-15);
    assert!((r.rel_error(0.0).unwrap() - 1.9).abs() < 1e-15);
    assert_eq!(row("v_D", "1", Method::Plan, 1.0, 0.0).rel_error(0.0), None);
    assert_eq!(
        row("v_D", "1", Method::Plan, 1.0, 1e-13).rel_error(1.0),
        None
    );
    assert_eq!(
        row("v_D", "1", Method::Plan, 1.0, f64::NAN).rel_error(0.0),
        None
    );
}

#[test]
fn json_has_the_exact_keys_and_null_at_an_analytic_zero() {
    let report = sample();
    let v: Value = serde_json::from_str(&report.to_json()).unwrap();
    // The order in the text is checked below.
    assert_eq!(
        sorted_keys(&v),
        ["notes", "rows", "scene", "summary", "tables"]
    );
    assert_eq!(v["scene"], "shaper-000");
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 6);
    assert_eq!(
        sorted_keys(&rows[0]),
        [
            "abs_error",
            "analytic",
            "conditioning",
            "graphical",
            "method",
            "position",
            "quantity",
            "rel_error",
            "unit"
        ]
    );
    assert_eq!(rows[0]["method"], "plan");
    assert_eq!(rows[3]["method"], "diagram-chords");
    assert_eq!(rows[2]["position"], "8′");
    assert!(rows[2]["rel_error"].is_null());
    assert_eq!(rows[2]["graphical"].as_f64(), Some(0.001));
    assert_eq!(rows[0]["rel_error"].as_f64(), Some((2.25 - 2.5) / 2.5));
    assert_eq!(rows[0]["conditioning"].as_f64(), Some(37.5));
    let entry = &v["summary"]["entries"][0];
    assert_eq!(entry["quantity"], "v_D");
    assert_eq!(entry["count"], 2);
    assert_eq!(v["summary"]["mean_by_method"][0]["method"], "plan");
    assert_eq!(v["tables"][0]["rows"][1]["position"], "8′");
    assert!(v["tables"][0]["rows"][1]["values"][1].is_null());
    assert_eq!(v["tables"][0]["columns"][0]["name"], "φ_1");
    // The key order in the text is the documented one.
    let text = report.to_json();
    let at = |k: &str| text.find(&format!("\"{k}\"")).unwrap();
    assert!(at("scene") < at("rows") && at("rows") < at("summary") && at("summary") < at("tables"));
    let order = [
        "quantity",
        "position",
        "unit",
        "method",
        "graphical",
        "analytic",
        "abs_error",
        "rel_error",
        "conditioning",
    ];
    assert!(order.windows(2).all(|w| at(w[0]) < at(w[1])));
}

#[test]
fn json_never_contains_nan() {
    let mut report = sample();
    report.rows[0].graphical = f64::NAN;
    report.rows[1].conditioning = Some(f64::INFINITY);
    let text = report.to_json();
    assert!(!text.contains("NaN") && !text.contains("inf"));
    let v: Value = serde_json::from_str(&text).unwrap();
    assert!(v["rows"][0]["graphical"].is_null());
    assert_eq!(
        v["rows"][0]["non_finite"],
        serde_json::json!(["graphical", "abs_error", "rel_error"])
    );
    assert_eq!(
        v["rows"][1]["non_finite"],
        serde_json::json!(["conditioning"])
    );
    assert!(v["rows"][2].get("non_finite").is_none());
}

#[test]
fn csv_quotes_only_where_needed() {
    let mut report = sample();
    report.rows[0].key.subject = "D, \"ram\"".into();
    let csv = report.to_csv();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(
        lines[0],
        "quantity,position,unit,method,graphical,analytic,abs_error,rel_error,conditioning"
    );
    assert!(lines[1].starts_with("\"v_D, \"\"ram\"\"\",3,m/s,plan,2.25,2.5,0.25,-0.1,37.5"));
    assert_eq!(lines[3], "v_D,8′,m/s,plan,0.001,0.0,0.001,,37.5");
    assert_eq!(lines.len(), 7);
}

fn expect_entry(
    e: &SummaryEntry,
    (quantity, method, count): (&str, Method, usize),
    (mean, max): (f64, f64),
    worst: &str,
) {
    assert_eq!(
        (e.quantity.as_str(), e.method, e.count),
        (quantity, method, count)
    );
    assert!((e.mean_abs_rel - mean).abs() < 1e-12, "{e:?}");
    assert!((e.max_abs_rel - max).abs() < 1e-12, "{e:?}");
    assert_eq!(e.worst_position.as_deref(), Some(worst));
}

/// The keys of a JSON object, sorted.
pub(crate) fn sorted_keys(v: &Value) -> Vec<&str> {
    let mut keys: Vec<&str> = v
        .as_object()
        .map(|o| o.keys().map(String::as_str).collect())
        .unwrap_or_default();
    keys.sort_unstable();
    keys
}

#[test]
fn summary_means_of_a_hand_made_report() {
    let s = sample().summary();
    assert_eq!(s.entries.len(), 2);
    // A tie keeps the first position.
    expect_entry(&s.entries[0], ("v_D", Method::Plan, 2), (0.1, 0.1), "3");
    expect_entry(
        &s.entries[1],
        ("a_D", Method::DiagramChords, 3),
        (0.1, 0.1),
        "1",
    );
    assert_eq!(s.mean_by_method.len(), 2);
    assert_eq!(s.mean_by_method[0].0, Method::Plan);
    assert!((s.mean_by_method[0].1 - 0.1).abs() < 1e-12);

    let mut uneven = sample();
    uneven.rows[4].graphical = 75.0; // +25 %
    let s = uneven.summary();
    expect_entry(
        &s.entries[1],
        ("a_D", Method::DiagramChords, 3),
        (0.15, 0.25),
        "10",
    );
    // Pooled over the five diagram rows? No: plan and diagram are separate.
    assert!((s.mean_by_method[1].1 - 0.15).abs() < 1e-12);
}

#[test]
fn zero_threshold_is_relative_to_the_column() {
    let mut report = sample();
    report.rows[2].analytic = 1e-13; // 1e-12 × 2.5 = 2.5e-12 > 1e-13
    assert_eq!(report.rel_errors()[2], None);
    report.rows[2].analytic = 1e-11;
    assert!(report.rel_errors()[2].is_some());
}

#[test]
fn markdown_per_language() {
    let report = sample();
    let ru = report.to_markdown(Lang::Ru);
    let en = report.to_markdown(Lang::En);
    assert!(ru.contains("| v_D | план | 2 | 10 | 10 | 3 |"), "{ru}");
    assert!(
        ru.contains("| 3 | план | 2,25 | 2,5 | 0,25 | −10 | 37,5 |"),
        "{ru}"
    );
    assert!(
        en.contains("| 3 | vector plan | 2.25 | 2.5 | 0.25 | −10 | 37.5 |"),
        "{en}"
    );
    assert!(en.contains("mean \\|δ\\|, %"));
    assert!(ru.starts_with("# Графические и аналитические значения — shaper-000"));
    assert!(en.contains("## Table 5"));
    assert!(en.contains("| 8′ | −19 |  |"), "{en}");
    assert!(en.contains("Mean error by method: vector plan 10 %; diagram 10 %."));
    assert!(report.to_markdown(Lang::Uk).contains("діаграма"));
}

#[test]
fn output_is_deterministic() {
    let (a, b) = (sample(), sample());
    assert_eq!(a.to_json(), b.to_json());
    assert_eq!(a.to_csv(), b.to_csv());
    assert_eq!(a.to_markdown(Lang::Ru), b.to_markdown(Lang::Ru));
}

#[test]
fn an_empty_report_is_written() {
    let r = Report {
        scene: String::new(),
        rows: Vec::new(),
        tables: Vec::new(),
        notes: Vec::new(),
    };
    let v: Value = serde_json::from_str(&r.to_json()).unwrap();
    assert_eq!(v["rows"], serde_json::json!([]));
    assert_eq!(r.to_csv().lines().count(), 1);
    assert!(r.summary().entries.is_empty());
    assert!(r.to_markdown(Lang::En).starts_with("# "));
}
