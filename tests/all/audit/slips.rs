//! The audit's property test: on ten four-bar and three shaper variants, every value of the
//! report — each row, and each cell of the analytic table at every position (φ, L, a_D where
//! no plan is built) — written exactly is right, signed or as magnitudes; and random slips
//! of every kind, signs among them on the signed quantities, are found as made.

use super::values::{values, Value};
use crate::support::root;
use std::path::Path;
use tmm::audit::{read_table, Auditor, ColumnReading, Edit, Formula, Slip, Verdict, Written};
use tmm::check::{Method, Symbol};
use tmm::scene;

/// A small deterministic generator (SplitMix64): the same slips every run.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// `x` written with three significant digits, as a student writes a table.
fn three(x: f64) -> String {
    let decimals = (2 - x.abs().log10().floor() as i32).max(0) as usize;
    format!("{x:.decimals$}")
}

/// The slips the generator makes.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Made {
    Factor,
    Unit,
    Sign,
    Transposed,
    Dropped,
    Position,
    Quantity,
    Formula,
    OtherScale,
}

const MADE: [Made; 9] = [
    Made::OtherScale,
    Made::Formula,
    Made::Factor,
    Made::Unit,
    Made::Sign,
    Made::Transposed,
    Made::Dropped,
    Made::Position,
    Made::Quantity,
];

/// A slip as the test expects it named: a slip, or the value of another quantity (by name).
#[derive(Debug, Clone, PartialEq)]
enum Expected {
    Slip(Slip),
    Quantity(String),
}

/// The values the generator draws from, and how it makes a slip of each.
struct Maker<'a> {
    all: &'a [Value],
    /// μ_v and μ_a of the variant's plans.
    mu: (f64, f64),
}

/// A number of `v` with a slip of `kind`, and the slip; `None` where the slip cannot be
/// made on it.
fn slip(kind: Made, v: &Value, maker: &Maker, rng: &mut Rng) -> Option<(String, Expected)> {
    if kind == Made::Quantity {
        return other_quantity(v, maker.all, rng);
    }
    made(kind, v, maker, rng).map(|(text, s)| (text, Expected::Slip(s)))
}

/// The value of another quantity of `v`'s unit at its position, by its construction.
fn other_quantity(v: &Value, all: &[Value], rng: &mut Rng) -> Option<(String, Expected)> {
    let others: Vec<&Value> = all
        .iter()
        .filter(|o| o.m == v.m && o.unit == v.unit && o.q != v.q && o.p == v.p && !o.zero)
        .collect();
    let o = (!others.is_empty()).then(|| others[rng.below(others.len())])?;
    let e = v.e;
    ((o.e - e).abs() > 0.1 * e.abs() && (o.e + e).abs() > 0.1 * e.abs())
        .then(|| (three(o.e), Expected::Quantity(o.q.clone())))
}

/// A number of `v` with a slip of `kind` (but another quantity's value), and the slip.
fn made(kind: Made, v: &Value, maker: &Maker, rng: &mut Rng) -> Option<(String, Slip)> {
    let (e, all, mu) = (v.e, maker.all, maker.mu);
    match kind {
        Made::Factor if !v.turn => {
            let k = [2.0, 0.5, 10.0][rng.below(3)];
            Some((three(k * e), Slip::Factor(k)))
        }
        Made::Unit => {
            let (x, meant) = match v.unit.as_str() {
                "N" => (e / 9.806_65, "kgf"),
                "N*m" => (e / 9.806_65, "kgf*m"),
                "m" => (e * 1e3, "mm"),
                "m/s" => (e * 1e3, "mm/s"),
                "m/s^2" => (e * 1e3, "mm/s^2"),
                "rad/s" => (e * 30.0 / std::f64::consts::PI, "rpm"),
                "deg" => (e.to_radians(), "rad"),
                _ => return None,
            };
            Some((three(x), Slip::Unit { meant }))
        }
        Made::Sign if !v.turn => Some((three(-e), Slip::Sign)),
        Made::OtherScale => {
            // A plan's millimetres converted with the other plan's μ.
            let (mv, ma) = mu;
            let (used, own, k) = match (v.symbol, v.method) {
                (Some(Symbol::Velocity), Some(Method::Plan)) => ("μ_a", "μ_v", ma / mv),
                (Some(Symbol::Acceleration), Some(Method::Plan)) => ("μ_v", "μ_a", mv / ma),
                _ => return None,
            };
            let slip = Slip::OtherScale {
                used,
                own,
                factor: k,
            };
            Some((three(e * k), slip))
        }
        Made::Formula => formula(v, all).map(|(x, f)| (three(x), Slip::Formula(f))),
        Made::Transposed | Made::Dropped => pen(kind, e, rng),
        Made::Position => {
            // A shifted row: the next position's value.
            let column: Vec<&Value> = all.iter().filter(|o| o.q == v.q && o.m == v.m).collect();
            let at = column.iter().position(|o| o.p == v.p);
            let o = at
                .and_then(|k| column.get(k + 1))
                .copied()
                .filter(|o| !o.zero)?;
            ((o.e - e).abs() > 0.1 * e.abs() && (o.e + e).abs() > 0.1 * e.abs())
                .then(|| (three(o.e), Slip::Position(o.p.clone())))
        }
        _ => None,
    }
}

/// The course's wrong formulas, each as the student evaluates it, where `v` has one.
fn formula(v: &Value, all: &[Value]) -> Option<(f64, Formula)> {
    let value = |q: &str| all.iter().find(|o| o.q == q && o.p.is_empty()).map(|o| o.e);
    let cos_w = value("alpha_w").map(|a| a.to_radians().cos());
    let w1 = all.iter().find(|o| o.q == "omega_1").map(|o| o.e.abs());
    let power = match (v.method.is_some_and(Method::is_diagram), v.symbol) {
        (true, Some(Symbol::Velocity | Symbol::AngularAcceleration)) => Some(1),
        (true, Some(Symbol::Acceleration)) => Some(2),
        _ => None,
    };
    if let (Some(n), Some(cos_w)) = (v.q.strip_prefix("r_b"), cos_w) {
        value(&format!("r_{n}")).map(|radius| (radius * cos_w, Formula::BaseRadiusCosAlphaW))
    } else if let (true, Some(cos_w), Some(rb), Some(radius)) =
        (v.q == "eps_alpha", cos_w, value("r_b1"), value("r_1"))
    {
        Some((v.e * rb / radius / cos_w, Formula::ContactRatioCosAlphaW))
    } else if let (Some(p), Some(w1)) = (power, w1) {
        Some((v.e / w1.powi(p), Formula::MissingOmega1))
    } else {
        None
    }
}

/// `e` written with two neighbouring digits swapped or a digit dropped (`None` where that
/// only moves the decimal point: a scale slip, made as such).
fn pen(kind: Made, e: f64, rng: &mut Rng) -> Option<(String, Slip)> {
    let meant = three(e);
    let sign = if meant.starts_with('-') { "-" } else { "" };
    let body: Vec<char> = meant.trim_start_matches('-').chars().collect();
    let places: Vec<usize> = (0..body.len())
        .filter(|&k| body[k].is_ascii_digit())
        .skip_while(|&k| body[k] == '0')
        .collect();
    let mut c = body.clone();
    let edit = if kind == Made::Transposed {
        let k = 1 + rng.below(places.len() - 1);
        let (a, b) = (places[k - 1], places[k]);
        if c[a] == c[b] || (k == 1 && c[b] == '0') {
            None
        } else {
            c.swap(a, b);
            Some(Edit::Transposed)
        }
    } else {
        c.remove(places[1 + rng.below(places.len() - 1)]);
        (c.last() != Some(&'.')).then_some(Edit::Dropped)
    };
    let text: String = c.iter().collect();
    let decade = (text.parse::<f64>().unwrap_or(0.0)
        / meant.trim_start_matches('-').parse::<f64>().unwrap_or(1.0))
    .abs()
    .log10();
    let edit = edit.filter(|_| (decade - decade.round()).abs() > 1e-9)?;
    let slip = Slip::Digits {
        edits: vec![edit],
        meant: meant.clone(),
    };
    Some((format!("{sign}{text}"), slip))
}

/// Whether the verdict names the slip made.
fn found_as_made(verdict: &Verdict, expected: &Expected) -> bool {
    let Verdict::Slips(all) = verdict else {
        return false;
    };
    all.iter().any(|e| match (e.as_slice(), expected) {
        ([Slip::Quantity(x)], Expected::Quantity(q)) => x.name == *q,
        (_, Expected::Quantity(_)) => false,
        (x, Expected::Slip(slip)) => match (x, slip) {
            ([Slip::Digits { edits: x, .. }], Slip::Digits { edits, .. }) => x.contains(&edits[0]),
            // A scale slip named by the plan whose μ makes it (μ_a ten times μ_v).
            ([Slip::Factor(x)], Slip::Factor(k)) => x == k,
            ([Slip::OtherScale { factor, .. }], Slip::Factor(k)) => (factor / k - 1.0).abs() < 1e-9,
            (
                [Slip::OtherScale {
                    used: u, own: o, ..
                }],
                Slip::OtherScale { used, own, .. },
            ) => u == used && o == own,
            (x, s) => x == [s.clone()],
        },
    })
}

/// What the generator made and found.
#[derive(Default)]
struct Tally {
    made: usize,
    found: usize,
    ambiguous: usize,
    /// Sign slips on a negative exact value (written positive, in a signed column).
    signs_written_positive: usize,
    /// Slips made on a cell of the analytic table.
    on_cells: usize,
    per_kind: std::collections::BTreeMap<String, usize>,
    missed: Vec<String>,
}

/// The report's values of a variant written exactly, signed and then all as magnitudes:
/// every value right, every column with a negative exact value read signed in the first
/// table and as magnitudes in the second. The tolerance of each value (SI) by quantity,
/// position and method.
fn exact_tables_are_right(
    name: &str,
    all: &[Value],
    auditor: &Auditor,
) -> std::collections::HashMap<(String, String, String), f64> {
    let header = "quantity,position,method,value,unit";
    let mut tolerance = std::collections::HashMap::new();
    for magnitudes in [false, true] {
        let lines = all.iter().map(|v| {
            let x = if magnitudes { v.e.abs() } else { v.e };
            let text = if v.zero { "0".to_string() } else { three(x) };
            format!("{},{},{},{text},{}", v.q, v.p, v.m, v.unit)
        });
        let table: Vec<String> = std::iter::once(header.to_string()).chain(lines).collect();
        let entries =
            read_table(&table.join("\n"), Path::new("exact.csv"), auditor).expect("a valid table");
        for (a, v) in auditor.audit(&entries).iter().zip(all) {
            assert_eq!(
                a.verdict,
                Verdict::Right,
                "{name} {:?}: {:?}",
                a.entry,
                a.verdict
            );
            let c = a.checked.as_ref().expect("checked");
            let negative = all
                .iter()
                .any(|o| o.q == v.q && o.m == v.m && o.e < 0.0 && !o.zero);
            let reading = if magnitudes && negative {
                ColumnReading::Magnitudes
            } else {
                ColumnReading::Signed
            };
            assert_eq!(c.reading, reading, "{name} {:?}", a.entry);
            tolerance.insert((v.q.clone(), v.p.clone(), v.m.clone()), c.tolerance);
        }
    }
    tolerance
}

/// Slips the generator makes on one variant per kind drawn.
const SLIPS: usize = 60;

/// `SLIPS` random slips on the values `all` of a variant, audited and tallied. A sign slip on
/// a negative value (written positive) comes with another value of its column written
/// exactly, negative: a column with no sign written is one of magnitudes.
fn slips_on(
    name: &str,
    all: &[Value],
    auditor: &Auditor,
    tolerance: &std::collections::HashMap<(String, String, String), f64>,
    (mu, rng): ((f64, f64), &mut Rng),
    tally: &mut Tally,
) {
    let mut lines = vec!["quantity,position,method,value,unit".to_string()];
    let mut expected: Vec<Option<(Made, Expected, bool)>> = Vec::new();
    let used = |lines: &[String], v: &Value| {
        lines
            .iter()
            .any(|l| l.starts_with(&format!("{},{},{},", v.q, v.p, v.m)))
    };
    let mut made = 0;
    while made < SLIPS {
        let kind = MADE[rng.below(MADE.len())];
        // A wrong formula is made where the course has one: base radii, ε_α, a diagram's
        // velocity or acceleration.
        let pool: Vec<&Value> = all
            .iter()
            .filter(|v| !v.zero && (kind != Made::Formula || formula(v, all).is_some()))
            .collect();
        if pool.is_empty() {
            continue;
        }
        let v = pool[rng.below(pool.len())];
        let Some((text, slip)) = slip(kind, v, &Maker { all, mu }, rng) else {
            continue;
        };
        if used(&lines, v) {
            continue;
        }
        // A slip that moves the value by less than what its construction and its digits
        // allow cannot be told from a right value: not one to find. (A slip to k·e is told
        // from e when the two tolerances, e's and k·e's, do not overlap.)
        let tol = tolerance[&(v.q.clone(), v.p.clone(), v.m.clone())];
        let w = Written::parse(&text, false).expect("a number");
        let k = (w.value / v.e).abs();
        // (An angle of a turn 360° off is the same angle: 517° for 157°.)
        let off = if v.turn {
            (w.value - v.e) - 360.0 * ((w.value - v.e) / 360.0).round()
        } else {
            w.value - v.e
        };
        if off.abs() <= (1.0 + k) * tol + 2.0 * w.half_unit() {
            continue;
        }
        // A positive number in a column of negative exact values is read as a magnitude
        // unless the column shows a sign.
        let context = (w.value >= 0.0 && v.e < 0.0).then(|| {
            all.iter().find(|o| {
                o.q == v.q && o.m == v.m && o.e < 0.0 && !o.zero && o.p != v.p && !used(&lines, o)
            })
        });
        match context {
            Some(None) if kind == Made::Sign => continue,
            Some(Some(o)) => {
                lines.push(format!("{},{},{},{},{}", o.q, o.p, o.m, three(o.e), o.unit));
                expected.push(None);
            }
            _ => {}
        }
        if kind == Made::Sign && v.e < 0.0 {
            tally.signs_written_positive += 1;
        }
        lines.push(format!("{},{},{},{text},{}", v.q, v.p, v.m, v.unit));
        expected.push(Some((kind, slip, v.method.is_none())));
        made += 1;
    }
    let entries =
        read_table(&lines.join("\n"), Path::new("slips.csv"), auditor).expect("a valid table");
    for (a, want) in auditor.audit(&entries).iter().zip(&expected) {
        let Some((kind, slip, on_cell)) = want else {
            assert_eq!(a.verdict, Verdict::Right, "{name} context {:?}", a.entry);
            continue;
        };
        tally.made += 1;
        tally.on_cells += usize::from(*on_cell);
        *tally.per_kind.entry(format!("{kind:?}")).or_insert(0) += 1;
        if found_as_made(&a.verdict, slip) {
            tally.found += 1;
            if matches!(&a.verdict, Verdict::Slips(all) if all.len() > 1) {
                tally.ambiguous += 1;
            }
        } else {
            let exact = a.checked.as_ref().map(|c| c.exact);
            tally.missed.push(format!(
                "{name} {kind:?} {} at {:?} ({:?}): written {} {} (exact {exact:?}): {:?}",
                a.entry.quantity,
                a.entry.position,
                a.entry.method,
                a.entry.written.text,
                a.entry.unit.name,
                a.verdict
            ));
        }
    }
}

#[test]
fn random_slips_on_random_variants_are_found_as_made() {
    // Ten four-bar variants and three of the shaper (every domain: plans, diagrams,
    // forces, the flywheel, the cam, the gears; the analytic table's cells).
    let mut variants = Vec::new();
    for (name, every) in [("four-bar", 3), ("shaper", 10)] {
        let template_path = root().join(format!("constructions/{name}.toml"));
        let template = std::fs::read_to_string(&template_path).expect("the template");
        let grid =
            std::fs::read_to_string(root().join(format!("constructions/variants/{name}.csv")))
                .expect("the template's grid");
        let grid = tmm::batch::read_grid(&template, &grid, Path::new("grid.csv"))
            .expect("the shipped grid");
        variants.extend(
            grid.into_iter()
                .step_by(every)
                .map(|v| (template_path.clone(), v)),
        );
    }
    let mut rng = Rng(22);
    let mut tally = Tally::default();
    let mut values_written = 0;
    for (template_path, v) in &variants {
        let scene = scene::parse(
            &v.text().expect("a variant's text"),
            &template_path.with_file_name("v.toml"),
        )
        .expect("a variant");
        let auditor = Auditor::new(&scene).expect("its report");
        let session = tmm::study::Session::new(&scene, tmm::construct::Drafting::EXACT);
        let report = session.report().expect("its report");
        let mu = session.kin_scales().expect("its scales");
        let all = values(&report, &auditor);
        values_written += all.len();
        let tolerance = exact_tables_are_right(&v.name, &all, &auditor);
        let mu = (mu.v.value(), mu.a.value());
        slips_on(
            &v.name,
            &all,
            &auditor,
            &tolerance,
            (mu, &mut rng),
            &mut tally,
        );
    }
    let Tally {
        made,
        found,
        ambiguous,
        ..
    } = tally;
    let share = found as f64 / made as f64;
    eprintln!(
        "values written exactly {values_written} (twice: signed, magnitudes); slips made {made} \
         ({} on the analytic table's cells, {} signs written positive), found as made {found} \
         ({:.1} %), of them ambiguous {ambiguous}",
        tally.on_cells,
        tally.signs_written_positive,
        100.0 * share
    );
    eprintln!("made per kind: {:?}", tally.per_kind);
    for m in &tally.missed {
        eprintln!("missed: {m}");
    }
    assert!(values_written >= 3000, "{values_written}");
    assert!(made >= 700, "{made}");
    assert!(tally.on_cells >= 150, "{}", tally.on_cells);
    assert!(
        tally.signs_written_positive >= 20,
        "{}",
        tally.signs_written_positive
    );
    // Every kind is made, and often.
    assert_eq!(tally.per_kind.len(), MADE.len(), "{:?}", tally.per_kind);
    assert!(
        tally.per_kind.values().all(|&n| n >= 10),
        "{:?}",
        tally.per_kind
    );
    assert!(
        share >= 0.95,
        "{found} of {made} found; missed:\n{}",
        tally.missed.join("\n")
    );
    // Most are named alone; the others beside a slip that gives the same number (a quantity
    // equal to another at that position, ω₁ ≈ 10 making "ω₁ missing" a ×0.1), named as
    // ambiguous.
    let alone = (found - ambiguous) as f64 / made as f64;
    assert!(alone >= 0.9, "{} of {made} named alone", found - ambiguous);
}
