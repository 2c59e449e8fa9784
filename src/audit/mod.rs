//! Checking a student's table (`tmm audit`): each value a student wrote — a quantity of the
//! scene's report, at a position, in the textbook's units — classified against the exact
//! value.
//!
//! A value is **right** when it lies within what a careful hand construction gives at the
//! scene's scales: the error of the textbook's construction itself (the engine's exact
//! construction against the analytic twin) plus what a reading 0.5 mm off does to it — the
//! scene is constructed twice more, every length read 0.5 mm long and 0.5 mm short
//! ([`Drafting::biased`]), so the chains of readings (a velocity read, then divided by a
//! length read) and a position's conditioning (a short vector near a dead centre; a crossing
//! at an angle θ, the error divided by sin θ) are the construction's own — plus the rounding
//! of the digits written. A value the student marks `analytic` (a table of the analytic
//! method, the textbook's formulas) is held to [`ANALYTIC`] of its value and its digits.
//!
//! A value that is not right is explained, when it can be, by the slips the course's
//! tables show ([`Slip`]): a scale slip (×2, ×½, ×10; a μ of another plan), a unit slip (mm
//! for m, rpm for rad/s, kgf for N), a sign, digits swapped, dropped or added, a value that
//! belongs to a neighbouring position (a shifted row) or another quantity (swapped columns,
//! a value copied from the next column), a known wrong formula (r_b or ε_α with cos α_w; a
//! derivative by φ taken for one by t, ω₁ missing), digits cut instead of rounded, or a
//! single significant digit. A value that fits two explanations names both. A value that fits none is wrong, with its exact value, its
//! relative error and, when one comes within 20 %, the nearest of the scale, unit and
//! formula slips.

mod digits;
mod units;
mod write;

pub use digits::{Edit, Written};
pub use units::Unit;
pub use write::{to_json, to_markdown, to_sheet};

use crate::check::{Key, Method, Report, Row, Symbol};
use crate::construct::Drafting;
use crate::scene::user_table::{self, CellError};
use crate::scene::Scene;
use crate::study::{Session, StudyError};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// The tolerance of a value of the analytic method, a fraction of it: the rounding of the
/// textbook's intermediate values (its lengths to the millimetre, its angles to 0.1°).
pub const ANALYTIC: f64 = 0.005;
/// The reading error of a hand construction, mm.
pub const READING_MM: f64 = 0.5;
/// The scale slips tried: the factors a μ of twice, half, ten times its value makes.
const FACTORS: [f64; 6] = [2.0, 0.5, 10.0, 0.1, 100.0, 0.01];
/// A slip of scale, unit or formula is named as the nearest explanation of a wrong value
/// when it comes this close (relative).
const NEAREST: f64 = 0.2;
/// The significant digits a table's value is expected to carry.
const DIGITS: usize = 3;

/// Why a table cannot be audited.
#[derive(Debug, Error)]
pub enum AuditError {
    /// The table is not readable, or its header lacks a column.
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
    /// The report's quantity (`v_B3`, `omega_3`).
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
    Quantity(Key),
    /// A known wrong formula.
    Formula(Formula),
}

/// An explanation: one slip, or a sign with another.
pub type Explanation = Vec<Slip>;

/// What a value is.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// Right: within the tolerance of its method and its digits.
    Right,
    /// Explained by slips: each explanation that fits (two or more: ambiguous).
    Slips(Vec<Explanation>),
    /// Wrong: no slip explains it; the nearest scale, unit or formula slip within
    /// [`NEAREST`], with the relative error left after it.
    Wrong {
        /// The nearest slip and the relative error left.
        nearest: Option<(Explanation, f64)>,
    },
}

/// One value audited.
#[derive(Debug, Clone, PartialEq)]
pub struct Audited {
    /// The student's value.
    pub entry: Entry,
    /// The scene's row it was checked against.
    pub row: Row,
    /// The exact value in the unit the student wrote (0 when it is zero to rounding).
    pub exact: f64,
    /// (written − exact)/|exact|, SI; `None` when the exact value is zero.
    pub rel_error: Option<f64>,
    /// The tolerance of the value's method, in the unit written (its digits not included).
    pub tolerance: f64,
    /// The classification.
    pub verdict: Verdict,
}

/// A row of the scene with what a hand reading does to it.
#[derive(Debug, Clone)]
struct Target {
    row: Row,
    /// The zero reference of its quantity ([`crate::check::scales`]).
    zero: f64,
    /// The change a reading 0.5 mm off makes, SI (conditioning included).
    reading: f64,
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

impl Auditor {
    /// The auditor of `scene`: its report, and its graphical values read 0.5 mm long and
    /// short.
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
        let read = |r: Option<Result<Report, StudyError>>| -> HashMap<RowId, f64> {
            r.and_then(Result::ok)
                .map(|r| r.rows.iter().map(|r| (id(r), r.graphical)).collect())
                .unwrap_or_default()
        };
        let (long, short) = (read(long), read(short));
        let zeros = crate::check::scales(&base.rows);
        let targets = base
            .rows
            .iter()
            .zip(zeros)
            .map(|(r, zero)| {
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
                Target {
                    row: r.clone(),
                    zero,
                    reading: off / sin,
                }
            })
            .collect();
        let omega1 = base
            .rows
            .iter()
            .find(|r| r.quantity() == "omega_1")
            .map(|r| r.analytic.abs());
        let mut scales = Vec::new();
        if scene.mechanism.is_some() {
            if let Ok(k) = exact.kin_scales() {
                scales.push(("μ_l", k.l.value()));
                scales.push(("μ_v", k.v.value()));
                scales.push(("μ_a", k.a.value()));
                if let Some(s) = k.chart.s {
                    scales.push(("μ_S", s.value()));
                }
            }
        }
        Ok(Self {
            targets,
            omega1,
            scales,
        })
    }

    /// The scene's row `quantity` at `position` by `method` (the first of its methods when
    /// none or `analytic` is named).
    pub fn row(
        &self,
        quantity: &str,
        position: Option<&str>,
        method: Option<&str>,
    ) -> Option<&Row> {
        self.target(quantity, position, method).map(|t| &t.row)
    }

    fn target(
        &self,
        quantity: &str,
        position: Option<&str>,
        method: Option<&str>,
    ) -> Option<&Target> {
        let method = method.filter(|m| *m != "analytic");
        self.targets.iter().find(|t| {
            t.row.quantity() == quantity
                && t.row.position().as_deref() == position
                && method.is_none_or(|m| t.row.method.key() == m)
        })
    }

    /// The quantities and positions of the report, for a message naming what there is.
    fn known(&self, quantity: &str) -> Vec<String> {
        let mut out: Vec<String> = Vec::new();
        for t in self.targets.iter().filter(|t| t.row.quantity() == quantity) {
            let at = t.row.position().map_or(String::new(), |p| format!("@{p}"));
            let name = format!("{at}:{}", t.row.method.key());
            if !out.contains(&name) {
                out.push(name);
            }
        }
        out
    }

    /// The tolerance of `t` as `entry` names its method, SI.
    fn tolerance(&self, t: &Target, analytic: bool) -> f64 {
        let r = &t.row;
        if analytic || r.method == Method::Formula {
            ANALYTIC * r.analytic.abs()
        } else {
            (r.graphical - r.analytic).abs() + t.reading
        }
    }

    /// Every value of `entries` classified (one the report lacks is left out: [`read_table`]
    /// refuses it).
    pub fn audit(&self, entries: &[Entry]) -> Vec<Audited> {
        entries
            .iter()
            .filter_map(|e| self.one(e, entries))
            .collect()
    }

    fn one(&self, entry: &Entry, table: &[Entry]) -> Option<Audited> {
        let t = self.target(
            &entry.quantity,
            entry.position.as_deref(),
            entry.method.as_deref(),
        )?;
        let analytic = entry.analytic();
        let tol = self.tolerance(t, analytic);
        let e = t.row.analytic;
        let u = entry.unit;
        let w_si = entry.written.value * u.factor;
        let zero = crate::check::is_zero(e, t.zero);
        Some(Audited {
            entry: entry.clone(),
            row: t.row.clone(),
            exact: if zero { 0.0 } else { e / u.factor },
            rel_error: (e != 0.0 && !zero).then(|| (w_si - e) / e.abs()),
            tolerance: tol / u.factor,
            verdict: self.verdict(entry, table, t, tol),
        })
    }

    /// The verdict on `entry` against `t`: right, else the slips that fit (of scale, unit,
    /// formula and digits, and the rows it belongs to), else those with a sign, else wrong
    /// with the nearest slip.
    fn verdict(&self, entry: &Entry, table: &[Entry], t: &Target, tol: f64) -> Verdict {
        let e = t.row.analytic;
        let (mut found, mut nearest) = match self.explain(&entry.written, entry, t, tol) {
            Found::Right => return Verdict::Right,
            Found::Slips(s, near) => (s, near),
        };
        found.extend(self.elsewhere(&entry.written, entry, table, t, tol));
        // The sign: alone, or with the digits' rounding; with another slip only when
        // nothing else explains the value.
        if e.abs() > tol && !crate::check::is_zero(e, t.zero) {
            match self.explain(&entry.written.negated(), entry, t, tol) {
                Found::Right => found.push(vec![Slip::Sign]),
                Found::Slips(s, near) => {
                    let alone = found.is_empty();
                    found.extend(
                        s.into_iter()
                            .filter(|c| {
                                alone || matches!(c.as_slice(), [Slip::Truncated | Slip::Coarse])
                            })
                            .map(signed),
                    );
                    if let Some((c, r)) = near {
                        if nearest.as_ref().is_none_or(|(_, n)| r.abs() < n.abs()) {
                            nearest = Some((signed(c), r));
                        }
                    }
                }
            }
        }
        if found.is_empty() {
            Verdict::Wrong { nearest }
        } else {
            Verdict::Slips(found)
        }
    }

    /// What explains `w` (the entry's number, or its negation) against target `t`: right,
    /// or the slips of digits, scale, unit and formula that fit (none: the nearest of scale,
    /// unit and formula within [`NEAREST`]).
    fn explain(&self, w: &Written, entry: &Entry, t: &Target, tol: f64) -> Found {
        let u = entry.unit;
        let e = t.row.analytic;
        let w_si = w.value * u.factor;
        let half = w.half_unit() * u.factor;
        // Whether the number fits `x` (SI) held to `tol_x`.
        let fits = |x: f64, tol_x: f64| (w_si - x).abs() <= tol_x + half;
        let (cut, rounded) = w.cut_and_rounded(e / u.factor);
        let truncated = w.is(cut) && !w.is(rounded) && !crate::check::is_zero(e, t.zero);
        if fits(e, tol) {
            // Right to the digits written; outside what three digits would hold, the digits
            // are cut instead of rounded, or a single digit is written.
            let three = 0.5 * 10f64.powi(e.abs().log10().floor() as i32 - DIGITS as i32 + 1);
            if !crate::check::is_zero(e, t.zero) && (w_si - e).abs() > tol + three {
                if truncated {
                    return Found::Slips(vec![vec![Slip::Truncated]], None);
                }
                if w.significant() < 2 {
                    return Found::Slips(vec![vec![Slip::Coarse]], None);
                }
            }
            return Found::Right;
        }
        // Each fitting slip with the factor it puts on the value (one cause under two names
        // — a μ of another plan ten times this one's, or ×10 — is named once, by the
        // specific slip).
        let mut found: Vec<(Explanation, f64)> = Vec::new();
        let mut near: Option<(Explanation, f64)> = None;
        // A slip that moves the value by less than the two tolerances tells nothing.
        let mut consider = |slip: Slip, x: f64, tol_x: f64, found: &mut Vec<(Explanation, f64)>| {
            if (x - e).abs() <= tol + tol_x {
                return;
            }
            if fits(x, tol_x) {
                found.push((vec![slip], x / e));
            } else if x != 0.0 {
                let r = (w_si - x) / x.abs();
                if r.abs() < NEAREST && near.as_ref().is_none_or(|(_, n)| r.abs() < n.abs()) {
                    near = Some((vec![slip], r));
                }
            }
        };
        if truncated && (w_si - e).abs() < 2.0 * half + tol {
            found.push((vec![Slip::Truncated], 1.0));
        }
        for k in FACTORS {
            consider(Slip::Factor(k), k * e, k * tol, &mut found);
        }
        if let Some(own) = self.own_scale(&t.row) {
            if let Some(&(_, own_mu)) = self.scales.iter().find(|s| s.0 == own) {
                for &(used, mu) in self.scales.iter().filter(|s| s.0 != own) {
                    let k = mu / own_mu;
                    let slip = Slip::OtherScale {
                        used,
                        own,
                        factor: k,
                    };
                    consider(slip, k * e, k * tol, &mut found);
                }
            }
        }
        for other in units::kind(t.row.unit()) {
            if (other.factor / u.factor - 1.0).abs() > 1e-9 {
                // The number is in `other`: its SI value is w × other.factor.
                let k = u.factor / other.factor;
                consider(Slip::Unit { meant: other.name }, k * e, k * tol, &mut found);
            }
        }
        for (f, x) in self.formulas(&t.row) {
            consider(Slip::Formula(f), x, tol * (x / e).abs(), &mut found);
        }
        let factors: Vec<f64> = found
            .iter()
            .filter(|(x, _)| !matches!(x.as_slice(), [Slip::Factor(_)]))
            .map(|f| f.1)
            .collect();
        // Of the factors that fit, those about as near as the nearest: a factor that misses
        // by over three times as much (and the digits) is not named beside it.
        let miss = |k: f64| (w_si - k * e).abs();
        let nearest = found
            .iter()
            .map(|f| miss(f.1))
            .fold(f64::INFINITY, f64::min);
        let mut found: Vec<Explanation> = found
            .into_iter()
            .filter(|(x, k)| match x.as_slice() {
                [Slip::Factor(k)] => !factors.iter().any(|f| (f / k - 1.0).abs() < 1e-9),
                _ => true,
            } && miss(*k) <= 3.0 * nearest + half)
            .map(|f| f.0)
            .collect();
        // The slips of the pen that make the number written of one meaning the exact value:
        // right to the analytic method's tolerance and the finer of the two numbers' digits
        // (a digit put back proves nothing when any number within a reading would do), and
        // moved by more than twice what a reading and the digits allow.
        let mut edits: Vec<Edit> = Vec::new();
        let mut meant: Option<(f64, String)> = None;
        for (edit, m) in w.edits() {
            // A number meant that is the written one times a power of ten is a scale slip.
            let decade = (m.value / w.value).log10();
            if (decade - decade.round()).abs() < 1e-9 {
                continue;
            }
            let m_si = m.value * u.factor;
            let strict = tol.min(ANALYTIC * e.abs()) + half.min(m.half_unit() * u.factor);
            if (m_si - e).abs() <= strict && (m_si - w_si).abs() > 2.0 * (tol + half) {
                if !edits.contains(&edit) {
                    edits.push(edit);
                }
                if meant.as_ref().is_none_or(|(d, _)| (m_si - e).abs() < *d) {
                    meant = Some(((m_si - e).abs(), m.text.clone()));
                }
            }
        }
        if let Some((_, meant)) = meant {
            edits.sort_by_key(|e| *e as u8);
            found.push(vec![Slip::Digits { edits, meant }]);
        }
        Found::Slips(found, near)
    }

    /// The rows `w` belongs to instead of `t`'s: the same quantity at the neighbouring
    /// positions of its column (a shifted row), another quantity of the same unit at the same
    /// position (swapped columns), or another column of the student's own row (a copied
    /// value). Only the neighbours are tried, each to the analytic method's tolerance: across
    /// a whole column, some position's value lies within a reading of almost any number.
    fn elsewhere(
        &self,
        w: &Written,
        entry: &Entry,
        table: &[Entry],
        t: &Target,
        tol: f64,
    ) -> Vec<Explanation> {
        let u = entry.unit;
        let (e, w_si, half) = (t.row.analytic, w.value * u.factor, w.half_unit() * u.factor);
        let analytic = entry.analytic();
        let column: Vec<&Target> = self
            .targets
            .iter()
            .filter(|o| o.row.key.same_quantity(&t.row.key) && o.row.method == t.row.method)
            .collect();
        let at = column.iter().position(|o| std::ptr::eq(*o, t));
        let neighbours = at.into_iter().flat_map(|k| {
            [k.checked_sub(1), Some(k + 1)]
                .into_iter()
                .flatten()
                .filter_map(|j| column.get(j).copied())
        });
        let beside = self.targets.iter().filter(|o| {
            o.row.position() == t.row.position()
                && !o.row.key.same_quantity(&t.row.key)
                && o.row.method == t.row.method
                && o.row.unit() == t.row.unit()
        });
        let mut found: Vec<Explanation> = Vec::new();
        for o in neighbours.chain(beside) {
            let tol_o = self.tolerance(o, analytic);
            // The other row's value to the analytic method's tolerance (within a reading,
            // some neighbour fits almost any number), and not this row's value too.
            let strict = tol_o.min(ANALYTIC * o.row.analytic.abs()) + half;
            if (w_si - o.row.analytic).abs() <= strict && (o.row.analytic - e).abs() > tol + tol_o {
                found.push(vec![if o.row.key.same_quantity(&t.row.key) {
                    Slip::Position(o.row.position().unwrap_or_default())
                } else {
                    Slip::Quantity(o.row.key.clone())
                }]);
            }
        }
        for s in table.iter().filter(|s| {
            s.position == entry.position
                && s.quantity != entry.quantity
                && units::find(t.row.unit(), s.unit.name).is_some()
                && s.written.value * s.unit.factor == w_si
        }) {
            // Copied from that column, not into it: nearer that quantity than this one.
            let from = self.target(&s.quantity, s.position.as_deref(), s.method.as_deref());
            let from = from.filter(|o| (w_si - o.row.analytic).abs() < (w_si - e).abs());
            if let Some(slip) = from.map(|k| Slip::Quantity(k.row.key.clone())) {
                if !found.iter().any(|f| f == std::slice::from_ref(&slip)) {
                    found.push(vec![slip]);
                }
            }
        }
        found
    }

    /// The μ a graphical row's value was converted with, by name.
    fn own_scale(&self, r: &Row) -> Option<&'static str> {
        match (r.key.symbol, r.method) {
            (Symbol::Velocity, Method::Plan) => Some("μ_v"),
            (Symbol::Acceleration, Method::Plan) => Some("μ_a"),
            (Symbol::Displacement, m) if m.is_diagram() => Some("μ_S"),
            _ => None,
        }
    }

    /// The values the course's known wrong formulas give for `r`.
    fn formulas(&self, r: &Row) -> Vec<(Formula, f64)> {
        let scene_value = |q: &str| {
            self.targets
                .iter()
                .find(|t| t.row.quantity() == q && t.row.position().is_none())
                .map(|t| t.row.analytic)
        };
        let mut out = Vec::new();
        let q = r.quantity();
        let cos_w = scene_value("alpha_w").map(|a| a.to_radians().cos());
        if let (Some(n), Some(cos_w)) = (q.strip_prefix("r_b"), cos_w) {
            if let Some(radius) = scene_value(&format!("r_{n}")) {
                out.push((Formula::BaseRadiusCosAlphaW, radius * cos_w));
            }
        }
        if q == "eps_alpha" {
            if let (Some(rb), Some(radius), Some(cos_w)) =
                (scene_value("r_b1"), scene_value("r_1"), cos_w)
            {
                out.push((
                    Formula::ContactRatioCosAlphaW,
                    r.analytic * rb / radius / cos_w,
                ));
            }
        }
        if let (Some(w1), true) = (self.omega1, r.method.is_diagram()) {
            let power = match r.key.symbol {
                Symbol::Velocity | Symbol::AngularAcceleration => Some(1),
                Symbol::Acceleration => Some(2),
                _ => None,
            };
            if let Some(p) = power.filter(|_| w1 > 0.0) {
                out.push((Formula::MissingOmega1, r.analytic / w1.powi(p)));
            }
        }
        out
    }
}

/// `chain` with a sign slip before it.
fn signed(chain: Explanation) -> Explanation {
    std::iter::once(Slip::Sign).chain(chain).collect()
}

/// What explains a number.
enum Found {
    /// It is right.
    Right,
    /// The slips that fit (none: wrong), and the nearest that does not.
    Slips(Vec<Explanation>, Option<(Explanation, f64)>),
}

/// The columns of a student's table.
const COLUMNS: [&str; 5] = ["quantity", "position", "value", "unit", "method"];

/// The values of the student's table `text` (the file `path`), each checked against the
/// scene's report.
///
/// The table is CSV with a header naming its columns, in any order: `quantity` (the
/// report's name, `v_B3`), `position` (its label, `3`, `8′` or `8'`; empty for a quantity of
/// the whole scene), `value`, `unit` (the textbook's: `m/s`, `мм`, `об/мин`, `кгс`) and,
/// optionally, `method` (a report method, `plan`, `lever`, or `analytic`). A header with
/// `;` and no `,` is read with `;` between fields and decimal commas. Lines starting with
/// `#` are comments.
///
/// # Errors
/// [`AuditError`] for the first problem, with its line, column and key; nothing is audited.
pub fn read_table(text: &str, path: &Path, auditor: &Auditor) -> Result<Vec<Entry>, AuditError> {
    let whole = |message: String| AuditError::Table {
        path: path.to_path_buf(),
        message,
    };
    let (mut reader, semicolons) = user_table::reader(text);
    let header: Vec<String> = reader
        .headers()
        .map_err(|e| whole(format!("the header: {e}")))?
        .iter()
        .map(|h| h.trim().to_lowercase())
        .collect();
    let column = |name: &str| header.iter().position(|h| h == name);
    for h in &header {
        if !COLUMNS.contains(&h.as_str()) {
            return Err(whole(format!(
                "the header names a column {h:?}: expected quantity, position, value, unit and, optionally, method"
            )));
        }
    }
    let need = |name: &str| {
        column(name).ok_or_else(|| {
            whole(format!(
                "the header has no column `{name}` (expected quantity, position, value, unit and, optionally, method)"
            ))
        })
    };
    let (cq, cp, cv, cu) = (
        need("quantity")?,
        need("position")?,
        need("value")?,
        need("unit")?,
    );
    let cm = column("method");
    let mut entries = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| whole(e.to_string()))?;
        let line = record.position().map_or(0, |p| p.line());
        if record.iter().all(|f| f.trim().is_empty()) {
            continue;
        }
        let cell = |c: usize, message: String| {
            AuditError::Cell(CellError {
                path: path.to_path_buf(),
                line,
                column: c + 1,
                key: header[c].clone(),
                message,
            })
        };
        if record.len() != header.len() {
            let c = record.len().min(header.len() - 1);
            return Err(cell(
                c,
                format!("{} fields, the header has {}", record.len(), header.len()),
            ));
        }
        let field = |c: usize| record[c].trim();
        let quantity = field(cq).to_string();
        let position = Some(field(cp).replace('\'', "′")).filter(|p| !p.is_empty());
        let method = cm.map(|c| field(c).to_string()).filter(|m| !m.is_empty());
        if let Some(m) = &method {
            if m != "analytic" && Method::parse(m).is_none_or(|p| p.key() != m) {
                return Err(cell(
                    cm.unwrap_or(0),
                    format!("{m:?}: expected a report method (plan, diagram-chords, polygon, lever, …) or analytic"),
                ));
            }
        }
        let Some(row) = auditor.row(&quantity, position.as_deref(), method.as_deref()) else {
            let known = auditor.known(&quantity);
            let (c, message) = if known.is_empty() {
                (cq, format!("{quantity:?}: the scene's report has no such quantity (see `tmm report --format csv`)"))
            } else {
                (
                    cp,
                    format!(
                        "{quantity} at {} by {}: not in the scene's report, which has {}",
                        position.as_deref().unwrap_or("the whole scene"),
                        method.as_deref().unwrap_or("any method"),
                        known.join(", ")
                    ),
                )
            };
            return Err(cell(c, message));
        };
        let written = Written::parse(field(cv), semicolons)
            .ok_or_else(|| cell(cv, format!("{:?}: not a number", field(cv))))?;
        let unit = units::find(row.unit(), field(cu)).ok_or_else(|| {
            let names: Vec<&str> = units::kind(row.unit()).iter().map(|u| u.name).collect();
            cell(
                cu,
                format!(
                    "{:?}: not a unit of {quantity} (expected one of {})",
                    field(cu),
                    names.join(", ")
                ),
            )
        })?;
        entries.push(Entry {
            line,
            quantity,
            position,
            method,
            written,
            unit,
        });
    }
    if entries.is_empty() {
        return Err(whole("no value: expected a row after the header".into()));
    }
    Ok(entries)
}
