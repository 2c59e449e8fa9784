//! Issue 43's reproducers for `tmm audit`: a long table (quadratic in its rows before: 52 000
//! rows took 53 s) and its sheet (65 kB a row before) audited under the memory limit, each
//! value's verdict the one it has in a short table.

use crate::support::{scratch, tmm_limited, LIMIT_KIB};

/// Seed 000's table (its header and its rows, comments left out) with its rows `times` times.
fn seed_table_times(times: usize) -> (String, usize) {
    let text = std::fs::read_to_string("constructions/tables/seed-000.csv").unwrap();
    let lines: Vec<&str> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .collect();
    let rows = &lines[1..];
    let mut out = vec![lines[0]];
    for _ in 0..times {
        out.extend_from_slice(rows);
    }
    (out.join("\n") + "\n", rows.len())
}

/// `tmm audit constructions/shaper.toml TABLE` with `extra` arguments under the memory
/// limit: it succeeds; its JSON values.
fn audited(table: &str, extra: &[&str]) -> Vec<serde_json::Value> {
    let dir = scratch("audit-long");
    let path = dir.join("table.csv");
    std::fs::write(&path, table).unwrap();
    let mut args = vec![
        "audit",
        "constructions/shaper.toml",
        path.to_str().unwrap(),
        "--format",
        "json",
    ];
    args.extend_from_slice(extra);
    let o = tmm_limited(LIMIT_KIB, &args);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    v.as_array().expect("values").clone()
}

/// A value's audit without its line.
fn verdict(v: &serde_json::Value) -> serde_json::Value {
    let mut v = v.clone();
    v.as_object_mut().unwrap().remove("line");
    v
}

#[test]
fn a_long_table_gives_each_value_its_verdict_in_the_short_one() {
    let (one, n) = seed_table_times(1);
    let short = audited(&one, &[]);
    assert_eq!(short.len(), n);
    let (long, _) = seed_table_times(120);
    let long = audited(&long, &[]);
    assert_eq!(long.len(), 120 * n);
    for (k, v) in long.iter().enumerate() {
        assert_eq!(verdict(v), verdict(&short[k % n]), "value {k}");
    }
    // Some of them copied from another column of their row: the look-up by row and number.
    assert!(short
        .iter()
        .any(|v| v["text"].as_str().unwrap_or("").contains("copied")
            || v["explanations"].to_string().contains("quantity:")));
}

#[test]
fn a_long_tables_sheet_is_written_within_the_memory_limit() {
    let (table, n) = seed_table_times(20);
    let pdf = scratch("audit-pdf").join("audit.pdf");
    let values = audited(&table, &["--pdf", pdf.to_str().unwrap()]);
    assert_eq!(values.len(), 20 * n);
    let bytes = std::fs::read(&pdf).expect("the sheet");
    assert!(bytes.starts_with(b"%PDF-"));
}
