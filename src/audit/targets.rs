//! What a student's value is checked against: the report's rows (a construction against its
//! analytic twin) and every cell of its analytic tables (the shape of seed 000 Table 5: φ, L,
//! a_D at every position, not only where a plan was constructed), each value signed as the
//! textbook's tables sign it.
//!
//! The signs are the textbook's (seed 000 Table 5): ω and ε counter-clockwise positive (as the
//! report writes them); a slide's velocity V_{B3B1} = dL₃/dt (the table's signed column, where
//! the report's row writes |V|); the velocity of a point of a link turning about a frame
//! pivot ω·r — the textbook's V_D = L_CD·ω₃, the projection on the counter-clockwise tangent
//! of its circle (the report writes |V|). Every other velocity and acceleration of a point,
//! a length, a force keeps the report's value.

use super::units;
use crate::check::{Method, Report, Row, Symbol, Table};
use crate::linkage::{plain, PositionPlan};
use crate::scale::Lang;

/// A quantity a student's table names.
#[derive(Debug, Clone, PartialEq)]
pub struct TableQuantity {
    /// The name: the report's (`v_B3_B1`, `omega_3`), or for a column of the analytic table
    /// that no row has, its name in the same spelling (`phi_3`, `L_3`).
    pub name: String,
    /// Its SI unit as the report writes it (`deg` for an angle of the analytic table).
    pub unit: &'static str,
    /// An angle of a turn (φ of the analytic table): compared modulo 360°.
    pub turn: bool,
    /// How the textbook writes it.
    pub notation: Notation,
}

/// A quantity's notation.
#[derive(Debug, Clone, PartialEq)]
pub enum Notation {
    /// A report row's symbol and subject.
    Row(Symbol, String),
    /// A column of the analytic table, in label markup (`φ_{3}`, `L_{3}`).
    Column(String),
}

impl TableQuantity {
    /// The quantity in the textbook's notation in `lang` (label markup).
    pub fn notation(&self, lang: Lang) -> String {
        match &self.notation {
            Notation::Row(symbol, subject) => crate::words::quantity(*symbol, subject, lang),
            Notation::Column(markup) => markup.clone(),
        }
    }

    /// The symbol of a report row's quantity.
    pub fn symbol(&self) -> Option<Symbol> {
        match self.notation {
            Notation::Row(symbol, _) => Some(symbol),
            Notation::Column(_) => None,
        }
    }
}

/// A value of the report: a row's, or a cell of an analytic table.
#[derive(Debug, Clone)]
pub(super) struct Target {
    /// Its quantity.
    pub quantity: TableQuantity,
    /// Its position's label; `None` for a quantity of the whole scene.
    pub position: Option<String>,
    /// The construction that read it; `None` for a cell of an analytic table.
    pub method: Option<Method>,
    /// The exact value, SI, signed as the textbook's tables sign it.
    pub value: f64,
    /// The zero reference of its quantity: the largest |value| of its column and rows.
    pub zero: f64,
    /// What a careful construction allows, SI: its error against the analytic twin and
    /// what a reading 0.5 mm off does (conditioning included); `None` for a table's cell.
    pub construction: Option<f64>,
}

/// The targets of `report`: its rows, each with what a reading 0.5 mm off changes
/// (`reading`), then the cells of its analytic tables, the velocities of points turning
/// about a frame pivot signed by `turning` (name without markup, position label, value).
pub(super) fn targets(
    report: &Report,
    reading: &dyn Fn(&Row) -> f64,
    turning: &[(String, String, f64)],
) -> Vec<Target> {
    let rows = &report.rows;
    let mut out: Vec<Target> = rows
        .iter()
        .map(|r| Target {
            quantity: TableQuantity {
                name: r.quantity(),
                unit: r.unit(),
                turn: false,
                notation: Notation::Row(r.key.symbol, r.key.subject.clone()),
            },
            position: r.position(),
            method: Some(r.method),
            value: r.analytic,
            zero: r.scale.abs(),
            construction: Some((r.graphical - r.analytic).abs() + reading(r)),
        })
        .collect();
    for table in &report.tables {
        out.extend(cells(table, rows, turning));
    }
    // A row takes the sign of its table's cell where both hold the same magnitude (the
    // report's |V_B3B1| and |V_D| rows; ω and ε agree already).
    let signed: Vec<(String, Option<String>, f64)> = out
        .iter()
        .filter(|t| t.method.is_none())
        .map(|t| (t.quantity.name.clone(), t.position.clone(), t.value))
        .collect();
    for t in out.iter_mut().filter(|t| t.method.is_some()) {
        let cell = signed
            .iter()
            .find(|(q, p, _)| *q == t.quantity.name && *p == t.position);
        if let Some(&(_, _, v)) = cell {
            let scale = v.abs().max(t.value.abs()).max(t.zero);
            if (v.abs() - t.value.abs()).abs() <= 1e-9 * scale {
                t.value = t.value.abs().copysign(v);
            }
        }
    }
    // Each quantity's zero reference: the largest |value| over its rows and cells.
    let mut largest: Vec<(String, f64)> = Vec::new();
    for t in out.iter().filter(|t| t.value.is_finite()) {
        match largest.iter_mut().find(|(q, _)| *q == t.quantity.name) {
            Some((_, m)) => *m = m.max(t.value.abs()),
            None => largest.push((t.quantity.name.clone(), t.value.abs())),
        }
    }
    for t in &mut out {
        if let Some((_, m)) = largest.iter().find(|(q, _)| *q == t.quantity.name) {
            t.zero = t.zero.max(*m);
        }
    }
    out
}

/// The cells of `table`, each column named as the report's rows name it.
fn cells(table: &Table, rows: &[Row], turning: &[(String, String, f64)]) -> Vec<Target> {
    let mut out = Vec::new();
    for (c, column) in table.columns.iter().enumerate() {
        let Some(quantity) = column_quantity(&column.name, &column.unit, rows) else {
            continue;
        };
        // A point's velocity (the table writes |V|) signed as ω·r where its link turns about
        // a frame pivot: the same magnitude, the sign of the turn.
        let point = column.name.strip_prefix("V_");
        for (label, values) in &table.rows {
            let Some(mut value) = values.get(c).copied().flatten() else {
                continue;
            };
            let same = |v: f64| (v.abs() - value.abs()).abs() <= 1e-9 * v.abs().max(value.abs());
            let turn = point.and_then(|p| {
                turning
                    .iter()
                    .find(|(n, l, v)| n == p && l == label && same(*v))
            });
            if let Some(&(_, _, v)) = turn {
                value = value.abs().copysign(v);
            }
            out.push(Target {
                quantity: quantity.clone(),
                position: Some(label.clone()),
                method: None,
                value,
                zero: 0.0,
                construction: None,
            });
        }
    }
    out
}

/// The quantity of the analytic table's column `name` (`φ_3`, `V_B3B1`) of unit `unit`
/// (`°`, `1/s`): the report's row of that quantity when there is one (`v_B3_B1`: the
/// subject's parts apart), else the name in the report's spelling (`phi_3`, `L_3`).
fn column_quantity(name: &str, unit: &str, rows: &[Row]) -> Option<TableQuantity> {
    let (head, sub) = name.split_once('_')?;
    let prefix = match head {
        "φ" => "phi",
        "ω" => "omega",
        "ε" => "eps",
        "V" => "v",
        other => other,
    };
    let si = units::kind(&units::normalise(unit)).first()?.name;
    let joined = |r: &&Row| r.key.subject.replace('_', "") == sub;
    let row = rows
        .iter()
        .filter(|r| r.key.symbol.key() == prefix && r.unit() == si)
        .find(|r| r.key.subject == sub)
        .or_else(|| {
            rows.iter()
                .filter(|r| r.key.symbol.key() == prefix && r.unit() == si)
                .find(joined)
        });
    Some(match row {
        Some(r) => TableQuantity {
            name: r.quantity(),
            unit: si,
            turn: false,
            notation: Notation::Row(r.key.symbol, r.key.subject.clone()),
        },
        None => TableQuantity {
            name: format!("{prefix}_{sub}"),
            unit: si,
            turn: head == "φ",
            notation: Notation::Column(crate::words::subscripted(name)),
        },
    })
}

/// The velocity of every point of a link turning about a frame pivot, signed as the
/// textbook signs it: ω·r, the projection of V on the counter-clockwise tangent of the
/// point's circle — each with the point's name without markup and the position's label; a
/// crank turning at ω₁ = `w1` (signed counter-clockwise). A position at a toggle (its rates
/// undetermined) has none.
pub(super) fn turning_points(plan: &PositionPlan, w1: f64) -> Vec<(String, String, f64)> {
    let prog = &plan.program;
    let fixed = prog.fixed.len();
    let mut out = Vec::new();
    for k in fixed..prog.names.len() {
        // The first link of the point hinged to the frame, and its pivot.
        let pivot = prog
            .links_of(k)
            .into_iter()
            .filter(|&l| l != 0)
            .find_map(|l| (0..fixed).find(|&c| prog.links_of(c).contains(&l)));
        let Some(c) = pivot else {
            continue;
        };
        for pos in plan.positions.iter().filter(|p| p.pose.toggle.is_none()) {
            let (p, dp) = (&pos.pose.p, &pos.pose.dp);
            let (Some(a), Some(o), Some(v)) = (p.get(k), p.get(c), dp.get(k)) else {
                continue;
            };
            let r = *a - *o;
            let length = r.length();
            if length > 0.0 {
                let value = r.perp_dot(*v * w1) / length;
                out.push((plain(&prog.names[k]), pos.label.clone(), value));
            }
        }
    }
    out
}
