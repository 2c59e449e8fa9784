//! The analytic table in the shape of seed 000 Table 5: φ₁, and per group the angle, ω and ε
//! of its links (and the slide of a slotted link), then |v|, |a| of every named point.

use crate::check::{Column, Table};
use crate::linkage::{owner, plain, GroupPairs, Pose, PositionPlan};

type Cell = Box<dyn Fn(&Pose) -> f64>;

/// The table's columns, each with the function of a pose that fills it and whether it is a
/// rate (a velocity or acceleration, undetermined where a group is at its toggle).
struct Columns {
    columns: Vec<Column>,
    cells: Vec<(Cell, bool)>,
}

impl Columns {
    fn push(&mut self, name: String, unit: &str, cell: Cell) {
        let rate = unit != "°" && unit != "m";
        self.push_as(name, unit, cell, rate);
    }

    /// A column whose cells are undetermined at a toggle when `rate`.
    fn push_as(&mut self, name: String, unit: &str, cell: Cell, rate: bool) {
        self.columns.push(Column {
            name,
            unit: unit.into(),
        });
        self.cells.push((cell, rate));
    }

    /// φ, ω, ε of link `l`.
    fn link(&mut self, l: usize, w1: f64) {
        self.push(
            format!("φ_{l}"),
            "°",
            Box::new(move |p: &Pose| p.angle(l).to_degrees().rem_euclid(360.0)),
        );
        self.push(
            format!("ω_{l}"),
            "rad/s",
            Box::new(move |p: &Pose| p.dangle[l] * w1),
        );
        self.push(
            format!("ε_{l}"),
            "rad/s²",
            Box::new(move |p: &Pose| p.ddangle[l] * w1 * w1),
        );
    }
}

/// The slide of the block at `a` along the slot of link `j` through `c`: the slot
/// coordinate s = (A − C)·t (t the slot's unit direction; |CA| when the slot passes through
/// C, its offset leg otherwise), and its rate ds/dφ₁ — the sliding velocity V_{A j A …}
/// that the velocity plan reads, so the column and the report's row mean the same thing.
fn slide(p: &Pose, a: usize, c: usize, j: usize) -> (f64, f64) {
    let (r, t) = (p.p[a] - p.p[c], p.dir[j]);
    let s = r.dot(t);
    let ds = (p.dp[a] - p.dp[c]).dot(t) + r.dot(t.perp()) * p.dangle[j];
    // The slot coordinate is counted from the foot of the perpendicular towards the block.
    (s.abs(), ds * s.signum())
}

/// The table of `plan` for a crank turning at ω₁ = `w1` (signed counter-clockwise).
pub fn analytic_table(plan: &PositionPlan, w1: f64) -> Table {
    let prog = &plan.program;
    let mut t = Columns {
        columns: Vec::new(),
        cells: Vec::new(),
    };
    t.push(
        "φ_1".into(),
        "°",
        Box::new(|p: &Pose| p.phi.to_degrees().rem_euclid(360.0)),
    );
    // A link that only translates (a slider) has no angle, ω or ε to tabulate.
    let turns = |l: usize| {
        plan.positions
            .iter()
            .any(|p| !crate::check::is_zero(p.pose.dangle[l], 1.0))
    };
    for g in prog.groups() {
        let links = g.links;
        match g.pairs {
            GroupPairs::Rpr { a, c } => {
                let j = links[1];
                t.link(j, w1);
                t.push(
                    format!("L_{j}"),
                    "m",
                    Box::new(move |p: &Pose| slide(p, a, c, j).0),
                );
                let name = plain(&prog.names[a]);
                t.push(
                    format!("V_{name}{j}{name}{}", owner(prog, a)),
                    "m/s",
                    Box::new(move |p: &Pose| slide(p, a, c, j).1 * w1),
                );
            }
            GroupPairs::Rpp { .. } | GroupPairs::Prp { .. } => {}
            _ => {
                for l in links.into_iter().filter(|&l| turns(l)) {
                    t.link(l, w1);
                }
            }
        }
    }
    for (k, name) in prog.names.iter().enumerate().skip(prog.fixed.len()) {
        let q = plain(name);
        // The crank pin moves with the crank whatever the groups do.
        let rate = k != prog.pin;
        t.push_as(
            format!("V_{q}"),
            "m/s",
            Box::new(move |p: &Pose| (p.dp[k] * w1).length()),
            rate,
        );
        t.push_as(
            format!("a_{q}"),
            "m/s²",
            Box::new(move |p: &Pose| (p.ddp[k] * w1 * w1).length()),
            rate,
        );
    }
    let rows = plan
        .positions
        .iter()
        .map(|pos| {
            // At a toggle the analogues are not determined: their cells stay empty.
            let toggle = pos.pose.toggle.is_some();
            let cells = t.cells.iter().map(|(c, rate)| {
                let v = c(&pos.pose);
                (!(toggle && *rate) && v.is_finite()).then_some(v)
            });
            (pos.label.clone(), cells.collect())
        })
        .collect();
    Table {
        title: "analytic".into(),
        columns: t.columns,
        rows,
    }
}
