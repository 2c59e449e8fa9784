//! The values of a variant's report a student may write — each row, and each cell of the
//! analytic table at every position — with the sign the auditor gives each, its magnitude
//! checked against the report's own.

use tmm::audit::Auditor;
use tmm::check::{Method, Report, Symbol};

/// A value of the report a student writes: a row (its method's key), or a cell of the
/// analytic table (`analytic`).
#[derive(Debug, Clone)]
pub(super) struct Value {
    pub(super) q: String,
    pub(super) p: String,
    pub(super) m: String,
    /// The construction; `None` for a cell of the analytic table.
    pub(super) method: Option<Method>,
    pub(super) symbol: Option<Symbol>,
    /// The SI unit as the report writes it.
    pub(super) unit: String,
    /// The exact value, signed as the auditor signs it (its magnitude checked against the
    /// report's).
    pub(super) e: f64,
    /// The report's own value (a row's analytic twin, the table's cell).
    pub(super) report: f64,
    /// An angle of a turn.
    pub(super) turn: bool,
    /// Zero to a millionth of its quantity's scale: written `0`, no slip made on it.
    pub(super) zero: bool,
}

/// The name, symbol and SI unit of the analytic table's column `name` (`φ_3` → `phi_3`;
/// `V_B3B1` → the report's `v_B3_B1`, its subject's parts apart).
fn column(name: &str, unit: &str, report: &Report) -> (String, Option<Symbol>, String) {
    let (head, sub) = name.split_once('_').expect("a subscript");
    let (prefix, symbol) = match head {
        "φ" => ("phi", None),
        "ω" => ("omega", Some(Symbol::AngularVelocity)),
        "ε" => ("eps", Some(Symbol::AngularAcceleration)),
        "V" => ("v", Some(Symbol::Velocity)),
        "a" => ("a", Some(Symbol::Acceleration)),
        other => (other, None),
    };
    let unit = match unit {
        "°" => "deg",
        "rad/s²" => "rad/s^2",
        "m/s²" => "m/s^2",
        u => u,
    };
    let name = report
        .rows
        .iter()
        .map(|r| r.quantity())
        .find(|q| {
            q.strip_prefix(&format!("{prefix}_"))
                .is_some_and(|s| s.replace('_', "") == sub)
        })
        .unwrap_or_else(|| format!("{prefix}_{sub}"));
    (name, symbol, unit.to_string())
}

/// Every value of `report` a student may write: its rows and its analytic table's cells,
/// each signed as `auditor` signs it — whose magnitude is the report's.
pub(super) fn values(report: &Report, auditor: &Auditor) -> Vec<Value> {
    let nonzero = |x: f64, scale: f64| x.abs() > 1e-6 * scale.abs().max(1e-300) && x.abs() > 1e-9;
    let mut out = Vec::new();
    for r in report.rows.iter().filter(|r| r.analytic.is_finite()) {
        let (q, p, m) = (
            r.quantity(),
            r.position().unwrap_or_default(),
            r.method.key(),
        );
        let e = auditor
            .value(&q, r.position().as_deref(), Some(m))
            .expect("the auditor has every row");
        out.push(Value {
            q,
            p,
            m: m.to_string(),
            method: Some(r.method),
            symbol: Some(r.key.symbol),
            unit: r.unit().to_string(),
            e,
            report: r.analytic,
            turn: false,
            zero: !nonzero(r.analytic, r.scale),
        });
    }
    for table in &report.tables {
        for (c, col) in table.columns.iter().enumerate() {
            let (q, symbol, unit) = column(&col.name, &col.unit, report);
            let largest = table
                .rows
                .iter()
                .filter_map(|(_, v)| v[c])
                .fold(0.0, |m: f64, x| m.max(x.abs()));
            for (label, cells) in &table.rows {
                let Some(x) = cells[c] else {
                    continue;
                };
                let e = auditor
                    .value(&q, Some(label), Some("analytic"))
                    .unwrap_or_else(|| panic!("{q} at {label}: every cell is audited"));
                out.push(Value {
                    q: q.clone(),
                    p: label.clone(),
                    m: "analytic".into(),
                    method: None,
                    symbol,
                    unit: unit.clone(),
                    e,
                    report: x,
                    turn: col.name.starts_with('φ'),
                    zero: !nonzero(x, largest),
                });
            }
        }
    }
    for v in &out {
        // The auditor's value is the report's, signed where the report writes |V|.
        assert!(
            (v.e.abs() - v.report.abs()).abs() <= 1e-9 * v.report.abs(),
            "{v:?}"
        );
        if v.e != v.report {
            assert!(
                v.symbol == Some(Symbol::Velocity) && v.report > 0.0,
                "{v:?}"
            );
        }
    }
    out
}
