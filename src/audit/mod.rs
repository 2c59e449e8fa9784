//! Checking a student's table (`tmm audit`): each value a student wrote — a quantity of the
//! scene's report, at a position, in the textbook's units — classified against the exact
//! value.
//!
//! What a value is checked against (`targets`): the report's row of its quantity at its
//! position by the method named, or — a quantity of the report's analytic table at a
//! position no construction reads it at (φ₃, L₃, a_D where no acceleration plan is built),
//! or a value marked `analytic` — the exact value. A line the report has nothing for is
//! marked so ([`Verdict::NotInReport`]) and the rest of the table is audited.
//!
//! A value is **right** when it lies within what a careful hand construction gives at the
//! scene's scales: the error of the textbook's construction itself (the engine's exact
//! construction against the analytic twin) plus what a reading 0.5 mm off does to it — the
//! scene is constructed twice more, every length read 0.5 mm long and 0.5 mm short
//! ([`Drafting::biased`]), so the chains of readings (a velocity read, then divided by a
//! length read) and a position's conditioning (a short vector near a dead centre; a crossing
//! at an angle θ, the error divided by sin θ) are the construction's own — plus the rounding
//! of the digits written. A value the student marks `analytic` (a table of the analytic
//! method, the textbook's formulas) is held to [`ANALYTIC`] of its value (an angle of a turn
//! to [`ANALYTIC_DEG`]) and its digits. A value by a construction the scene does not make at
//! that position is held to the widest tolerance of that construction at the others.
//!
//! Signs: the exact values are signed as the textbook's tables sign them (`targets`); a
//! column of the student's table (a quantity by the method written) with no value written
//! negative where some exact value is negative is a table of magnitudes, and is read so
//! ([`ColumnReading`]). A written 0 is right only where the exact value is 0 to the
//! tolerance and three digits of the quantity's scale; no scale, unit or digit slip explains
//! it.
//!
//! A value that is not right is explained, when it can be, by the slips the course's
//! tables show ([`Slip`]): a scale slip (×2, ×½, ×10; a μ of another plan), a unit slip (mm
//! for m, rpm for rad/s, kgf for N), a sign, digits swapped, dropped or added, a value that
//! belongs to a neighbouring position (a shifted row) or another quantity (swapped columns,
//! a value copied from the next column), a known wrong formula (r_b or ε_α with cos α_w; a
//! derivative by φ taken for one by t, ω₁ missing), digits cut instead of rounded, or a
//! single significant digit. A value that fits two explanations names both. A value that
//! fits none is wrong, with its exact value, its relative error and, when one comes within
//! 20 %, the nearest of the scale, unit and formula slips.

mod copies;
mod digits;
mod explain;
mod read;
mod targets;
mod units;
mod write;

pub use digits::{Edit, NumberError, Written};
pub use read::read_table;
pub use targets::{Notation, TableQuantity};
pub use units::Unit;
pub use write::{to_json, to_markdown, to_sheet};

use crate::check::{Method, Report, Row};
use crate::construct::Drafting;
use crate::scene::user_table::CellError;
use crate::scene::Scene;
use crate::study::{Session, StudyError};
use explain::Case;
use std::collections::HashMap;
use std::path::PathBuf;
use targets::Target;
use thiserror::Error;

/// The tolerance of a value of the analytic method, a fraction of it: the rounding of the
/// textbook's intermediate values (its lengths to the millimetre, its angles to 0.1°).
pub const ANALYTIC: f64 = 0.005;
/// The tolerance of an angle of a turn (φ of the analytic table) by the analytic method,
/// degrees: the textbook's angles to 0.1°.
pub const ANALYTIC_DEG: f64 = 0.1;
/// The reading error of a hand construction, mm.
pub const READING_MM: f64 = crate::construct::Drafting::HAND.resolution_mm();

/// Why a table cannot be audited.
#[derive(Debug, Error)]
pub enum AuditError {
    /// The table is not readable, or its header lacks a column or names one twice.
    #[error("{}: {message}", .path.display())]
    Table {
        /// The table's file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
    /// One field of a row is refused.
    #[error(transparent)]
    Cell(#[from] CellError),
    /// The scene's report cannot be made.
    #[error("{}: {source}", .path.display())]
    Scene {
        /// The scene's file.
        path: PathBuf,
        /// Why.
        source: StudyError,
    },
}

/// One value of a student's table.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    /// Its line in the file.
    pub line: u64,
    /// The report's quantity (`v_B3`, `omega_3`, `phi_3`).
    pub quantity: String,
    /// The position's label, for a quantity read at a position.
    pub position: Option<String>,
    /// The method the student names: a report method's key, `analytic`, or none.
    pub method: Option<String>,
    /// The number as written.
    pub written: Written,
    /// The unit written.
    pub unit: Unit,
}

impl Entry {
    /// Whether the student names the analytic method.
    pub fn analytic(&self) -> bool {
        self.method.as_deref() == Some("analytic")
    }
}

/// A known wrong formula of the course.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Formula {
    /// A base radius as r·cos α_w (the pitch circle's α is meant: r_b = r·cos α).
    BaseRadiusCosAlphaW,
    /// A contact ratio over the base pitch π·m·cos α_w (the base pitch is π·m·cos α).
    ContactRatioCosAlphaW,
    /// A diagram's derivative by φ written for the derivative by time: ω₁ (or ω₁²) missing.
    MissingOmega1,
}

/// A slip that explains a value.
#[derive(Debug, Clone, PartialEq)]
pub enum Slip {
    /// The opposite sign.
    Sign,
    /// Right to the digits written, but a single significant digit.
    Coarse,
    /// The digits cut, not rounded.
    Truncated,
    /// A scale slip: the value × this factor.
    Factor(f64),
    /// The drawing's millimetres converted with another plan's μ.
    OtherScale {
        /// The μ used (`μ_a`).
        used: &'static str,
        /// The plan's own (`μ_v`).
        own: &'static str,
        /// The factor it puts on the value, μ used / μ own.
        factor: f64,
    },
    /// The number is in another unit than the one written beside it.
    Unit {
        /// The unit the number is in.
        meant: &'static str,
    },
    /// A slip of the pen: the number meant (the nearest of those meant), and every slip that
    /// makes the number written of one (they all mean the exact value).
    Digits {
        /// The slips, each kind once.
        edits: Vec<Edit>,
        /// The number meant, as written.
        meant: String,
    },
    /// The value of another position (a shifted row).
    Position(String),
    /// The value of another quantity (swapped columns, or copied from the next column).
    Quantity(TableQuantity),
    /// A known wrong formula.
    Formula(Formula),
}

/// An explanation: one slip, or a sign with another.
pub type Explanation = Vec<Slip>;

/// What the report has of a quantity: by each method (`None`: the analytic table), the
/// positions (`None`: the whole scene).
pub type Known = Vec<(Option<Method>, Vec<Option<String>>)>;

/// What a value is.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// Right: within the tolerance of its method and its digits.
    Right,
    /// Explained by slips: each explanation that fits (two or more: ambiguous).
    Slips(Vec<Explanation>),
    /// Wrong: no slip explains it; the nearest scale, unit or formula slip within 20 %,
    /// with the relative error left after it.
    Wrong {
        /// The nearest slip and the relative error left.
        nearest: Option<(Explanation, f64)>,
    },
    /// Not checked: the report has no value of this quantity at this position by this
    /// method; what it has of the quantity (nothing: no such quantity).
    NotInReport {
        /// The report's values of the quantity.
        known: Known,
    },
}

/// How a column of the student's table (a quantity by the method written) is read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ColumnReading {
    /// Signed, as the textbook's tables sign the quantity.
    Signed,
    /// Magnitudes: no value of the column is written negative, and some exact value is.
    Magnitudes,
}

impl ColumnReading {
    /// `x` as this reading compares it.
    pub fn of(self, x: f64) -> f64 {
        match self {
            ColumnReading::Signed => x,
            ColumnReading::Magnitudes => x.abs(),
        }
    }
}

/// How a value's tolerance is held.
#[derive(Debug, Clone, PartialEq)]
pub enum Held {
    /// The construction's own: its error against the analytic twin and a reading 0.5 mm off.
    Construction,
    /// The analytic method's ([`ANALYTIC`]).
    Analytic,
    /// The construction is not made at this position: the widest tolerance of the method at
    /// the positions it is made at, at `position`.
    Borrowed {
        /// The position whose tolerance is taken.
        position: Option<String>,
    },
}

/// What a value was checked against.
#[derive(Debug, Clone, PartialEq)]
pub struct Checked {
    /// The report's quantity.
    pub quantity: TableQuantity,
    /// The construction whose value it is; `None`: a cell of the analytic table.
    pub method: Option<Method>,
    /// How its tolerance is held.
    pub held: Held,
    /// How its column is read.
    pub reading: ColumnReading,
    /// The exact value in the unit the student wrote, as read (0 when it is zero to
    /// rounding; an angle of a turn in the turn nearest the value written).
    pub exact: f64,
    /// (written − exact)/|exact|, SI; `None` when the exact value is zero.
    pub rel_error: Option<f64>,
    /// The tolerance, in the unit written (its digits not included).
    pub tolerance: f64,
}

/// One value audited.
#[derive(Debug, Clone, PartialEq)]
pub struct Audited {
    /// The student's value.
    pub entry: Entry,
    /// What it was checked against; `None` when the report has nothing for it.
    pub checked: Option<Checked>,
    /// The classification.
    pub verdict: Verdict,
}

/// The scene's report, with everything the audit checks a table against.
#[derive(Debug, Clone)]
pub struct Auditor {
    targets: Vec<Target>,
    /// ω₁ of the mechanism, rad/s.
    omega1: Option<f64>,
    /// The μ of the kinematic plans: name and value.
    scales: Vec<(&'static str, f64)>,
}

type RowId = (String, Option<String>, Method);

fn id(r: &Row) -> RowId {
    (r.quantity(), r.position(), r.method)
}

/// What the biased constructions (every length read `READING_MM` long and short) change of
/// each row, SI: the larger of the two, divided by the sine of the row's crossing angle.
fn readings(
    base: &Report,
    long: Option<Result<Report, StudyError>>,
    short: Option<Result<Report, StudyError>>,
) -> HashMap<RowId, f64> {
    let read = |r: Option<Result<Report, StudyError>>| -> HashMap<RowId, f64> {
        r.and_then(Result::ok)
            .map(|r| r.rows.iter().map(|r| (id(r), r.graphical)).collect())
            .unwrap_or_default()
    };
    let (long, short) = (read(long), read(short));
    base.rows
        .iter()
        .map(|r| {
            let k = id(r);
            let off = [long.get(&k), short.get(&k)]
                .into_iter()
                .flatten()
                .map(|g| (g - r.graphical).abs())
                .filter(|d| d.is_finite())
                .fold(None, |m: Option<f64>, d| Some(m.map_or(d, |m| m.max(d))));
            // A row the biased constructions lost: a hundredth of its quantity's scale.
            let off = off.unwrap_or(0.01 * r.scale.abs());
            let sin = r.conditioning.filter(|c| c.is_finite()).map_or(1.0, |c| {
                c.to_radians().sin().abs().max(1.0_f64.to_radians().sin())
            });
            (k, off / sin)
        })
        .collect()
}

impl Auditor {
    /// The auditor of `scene`: its report and analytic tables, and its graphical values
    /// read 0.5 mm long and short.
    ///
    /// # Errors
    /// [`AuditError::Scene`] when the report cannot be made.
    pub fn new(scene: &Scene) -> Result<Self, AuditError> {
        // The exact session gives the report and the plans' scales.
        let exact = Session::new(scene, Drafting::EXACT);
        let biased = |mm: f64| {
            Drafting::EXACT
                .biased(mm)
                .map(|d| Session::new(scene, d).report())
        };
        let (base, (long, short)) = rayon::join(
            || exact.report(),
            || rayon::join(|| biased(READING_MM), || biased(-READING_MM)),
        );
        let base = base.map_err(|source| AuditError::Scene {
            path: scene.path.clone(),
            source,
        })?;
        let reading = readings(&base, long, short);
        let mut scales = Vec::new();
        let mut turning = Vec::new();
        if scene.mechanism.is_some() {
            if let Ok(k) = exact.kin_scales() {
                scales.push(("μ_l", k.l.value()));
                scales.push(("μ_v", k.v.value()));
                scales.push(("μ_a", k.a.value()));
                if let Some(s) = k.chart.s {
                    scales.push(("μ_S", s.value()));
                }
                if let Ok(kin) = exact.kinematics(&k) {
                    turning = targets::turning_points(&kin.plan, kin.w1);
                }
            }
        }
        let of = |r: &Row| reading.get(&id(r)).copied().unwrap_or(0.0);
        let omega1 = base
            .rows
            .iter()
            .find(|r| r.quantity() == "omega_1")
            .map(|r| r.analytic.abs());
        Ok(Self {
            targets: targets::targets(&base, &of, &turning),
            omega1,
            scales,
        })
    }

    /// The exact value (SI, signed as the textbook's tables) a value of `quantity` at
    /// `position` by `method` (a report method's key, `analytic` or none) is checked
    /// against; `None` when the report has none.
    pub fn value(
        &self,
        quantity: &str,
        position: Option<&str>,
        method: Option<&str>,
    ) -> Option<f64> {
        self.resolve(quantity, position, method)
            .ok()
            .map(|(t, _)| t.value)
    }

    /// The SI unit of `quantity` as the report writes it, when the report has it.
    pub fn unit(&self, quantity: &str) -> Option<&'static str> {
        self.targets
            .iter()
            .find(|t| t.quantity.name == quantity)
            .map(|t| t.quantity.unit)
    }

    /// What a value of `q` at `p` by `method` is checked against and how its tolerance is
    /// held: the row of the method named (none: the report's first method of `q`); where
    /// that construction is not made at `p`, the exact value with the method's widest
    /// tolerance; for `analytic`, or a quantity no construction reads, the exact value (a
    /// cell of the analytic table, else a row's analytic twin). What the report has of `q`
    /// when it has nothing for the value.
    fn resolve(
        &self,
        q: &str,
        p: Option<&str>,
        method: Option<&str>,
    ) -> Result<(&Target, Held), Known> {
        let of_q = || self.targets.iter().filter(move |t| t.quantity.name == q);
        let at = |t: &&Target| t.position.as_deref() == p;
        // The exact value: the table's cell before a row's twin.
        let exact = || of_q().filter(at).min_by_key(|t| t.method.is_some());
        let named = method.filter(|m| *m != "analytic").and_then(Method::parse);
        let construction = named.or_else(|| of_q().find_map(|t| t.method));
        let found = match construction.filter(|_| method != Some("analytic")) {
            Some(m) => {
                let by_m = || of_q().filter(move |t| t.method == Some(m));
                match by_m().find(at) {
                    Some(t) => Some((t, Held::Construction)),
                    None => {
                        let widest = by_m()
                            .filter(|t| t.construction.is_some_and(f64::is_finite))
                            .max_by(|a, b| {
                                a.construction
                                    .partial_cmp(&b.construction)
                                    .unwrap_or(std::cmp::Ordering::Equal)
                            });
                        widest.and_then(|w| {
                            exact().map(|t| {
                                let position = w.position.clone();
                                (t, Held::Borrowed { position })
                            })
                        })
                    }
                }
            }
            None => exact().map(|t| (t, Held::Analytic)),
        };
        found.ok_or_else(|| self.known(q))
    }

    /// What the report has of `quantity`: per method, its positions.
    fn known(&self, quantity: &str) -> Known {
        let mut out: Known = Vec::new();
        for t in self.targets.iter().filter(|t| t.quantity.name == quantity) {
            match out.iter_mut().find(|(m, _)| *m == t.method) {
                Some((_, at)) => at.push(t.position.clone()),
                None => out.push((t.method, vec![t.position.clone()])),
            }
        }
        out
    }

    /// The tolerance of `t`, SI, held as `held` says.
    fn tolerance(&self, t: &Target, held: &Held) -> f64 {
        let construction =
            |t: &Target| t.construction.filter(|_| t.method != Some(Method::Formula));
        match held {
            Held::Construction => construction(t).unwrap_or_else(|| analytic(t)),
            Held::Analytic => analytic(t),
            Held::Borrowed { position } => self
                .targets
                .iter()
                .find(|o| {
                    o.quantity.name == t.quantity.name
                        && o.position == *position
                        && o.construction.is_some()
                })
                .and_then(construction)
                .unwrap_or_else(|| analytic(t)),
        }
    }

    /// Every value of `entries` classified; a line the report has nothing for is marked so.
    pub fn audit(&self, entries: &[Entry]) -> Vec<Audited> {
        let resolved: Vec<Result<(&Target, Held), Known>> = entries
            .iter()
            .map(|e| self.resolve(&e.quantity, e.position.as_deref(), e.method.as_deref()))
            .collect();
        // Each column (a quantity by the method written): a value written negative, an
        // exact value negative.
        let mut columns: HashMap<(&str, Option<&str>), (bool, bool)> = HashMap::new();
        for (e, r) in entries.iter().zip(&resolved) {
            let c = columns
                .entry((e.quantity.as_str(), e.method.as_deref()))
                .or_default();
            c.0 |= e.written.value < 0.0;
            if let Ok((t, _)) = r {
                c.1 |= t.value < 0.0 && !crate::check::is_zero(t.value, t.zero);
            }
        }
        let readings: Vec<ColumnReading> = entries
            .iter()
            .map(
                |e| match columns.get(&(e.quantity.as_str(), e.method.as_deref())) {
                    Some((false, true)) => ColumnReading::Magnitudes,
                    _ => ColumnReading::Signed,
                },
            )
            .collect();
        let copies = copies::Copies::new(entries, &readings);
        entries
            .iter()
            .zip(resolved)
            .zip(&readings)
            .map(|((entry, r), &reading)| match r {
                Ok((t, held)) => {
                    let case = Case {
                        entry,
                        copies: &copies,
                        target: t,
                        tol: self.tolerance(t, &held),
                        reading,
                        analytic: held == Held::Analytic,
                    };
                    self.one(&case, held)
                }
                Err(known) => Audited {
                    entry: entry.clone(),
                    checked: None,
                    verdict: Verdict::NotInReport { known },
                },
            })
            .collect()
    }

    fn one(&self, case: &Case, held: Held) -> Audited {
        let (entry, t) = (case.entry, case.target);
        let u = entry.unit;
        let w_si = entry.written.value * u.factor;
        let e = case.exact(w_si);
        let zero = crate::check::is_zero(e, t.zero);
        Audited {
            entry: entry.clone(),
            checked: Some(Checked {
                quantity: t.quantity.clone(),
                method: t.method,
                held,
                reading: case.reading,
                exact: if zero { 0.0 } else { e / u.factor },
                rel_error: (e != 0.0 && !zero).then(|| (w_si - e) / e.abs()),
                tolerance: case.tol / u.factor,
            }),
            verdict: self.verdict(case),
        }
    }
}

/// The analytic method's tolerance of `t`, SI.
fn analytic(t: &Target) -> f64 {
    if t.quantity.turn {
        ANALYTIC_DEG
    } else {
        ANALYTIC * t.value.abs()
    }
}
