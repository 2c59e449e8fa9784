//! The verdict on one value: right, the slips that explain it, or wrong with the nearest.

use super::copies::Copies;
use super::targets::Target;
use super::{
    units, Auditor, ColumnReading, Edit, Entry, Explanation, Formula, Slip, Verdict, Written,
    ANALYTIC,
};
use crate::check::{Method, Symbol};

/// The scale slips tried: the factors a μ of twice, half, ten times its value makes.
const FACTORS: [f64; 6] = [2.0, 0.5, 10.0, 0.1, 100.0, 0.01];
/// A slip of scale, unit or formula is named as the nearest explanation of a wrong value
/// when it comes this close (relative).
const NEAREST: f64 = 0.2;
/// The significant digits a table's value is expected to carry.
const DIGITS: i32 = 3;

/// One value of the student's table against what it is checked against.
pub(super) struct Case<'a> {
    /// The value.
    pub entry: &'a Entry,
    /// The student's whole table by row and number (a value copied from another column of
    /// its row).
    pub copies: &'a Copies<'a>,
    /// The report's value.
    pub target: &'a Target,
    /// The tolerance, SI.
    pub tol: f64,
    /// How the value's column is read.
    pub reading: ColumnReading,
    /// Held to the analytic method's tolerance (and so are the rows it may belong to).
    pub analytic: bool,
}

impl Case<'_> {
    /// The target's value as the column reads it; an angle of a turn in the turn nearest
    /// `w_si`.
    pub fn exact(&self, w_si: f64) -> f64 {
        self.near(self.target, w_si)
    }

    /// `o`'s value as the column reads it, in the turn nearest `w_si` for an angle.
    fn near(&self, o: &Target, w_si: f64) -> f64 {
        near(o, self.reading, w_si)
    }

    /// The rounding `w` carries, SI. A written 0 carries no more than three digits of the
    /// quantity's scale: `0` beside values of 3.27 and 7.18 means 0.00, not 0 ± 0.5.
    fn half(&self, w: &Written) -> f64 {
        let half = w.half_unit() * self.entry.unit.factor;
        let zero = self.target.zero;
        if w.is_zero() && zero > 0.0 && zero.is_finite() {
            let three = 0.5 * 10f64.powf(zero.log10().floor() - f64::from(DIGITS - 1));
            half.min(three)
        } else {
            half
        }
    }
}

/// `o`'s value as `reading` reads it, in the turn nearest `w_si` for an angle.
fn near(o: &Target, reading: ColumnReading, w_si: f64) -> f64 {
    let x = reading.of(o.value);
    if o.quantity.turn && (w_si - x).is_finite() {
        x + 360.0 * ((w_si - x) / 360.0).round()
    } else {
        x
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

impl Auditor {
    /// The verdict on the case: right, else the slips that fit (of scale, unit, formula and
    /// digits, and the rows it belongs to), else those with a sign, else wrong with the
    /// nearest slip.
    pub(super) fn verdict(&self, case: &Case) -> Verdict {
        let w = &case.entry.written;
        let e = case.exact(w.value * case.entry.unit.factor);
        let (mut found, mut nearest) = match self.explain(w, case) {
            Found::Right => return Verdict::Right,
            Found::Slips(s, near) => (s, near),
        };
        let mut others = self.elsewhere(w, case);
        // The sign: alone, or with the digits' rounding; with another slip only when
        // nothing else explains the value.
        if !w.is_zero() && e.abs() > case.tol && !crate::check::is_zero(e, case.target.zero) {
            match self.explain(&w.negated(), case) {
                Found::Right => {
                    // Another row's value is named beside the sign only when it is about as
                    // near: a value written to a digit or two fits a row 5 % off too.
                    let w_si = w.value * case.entry.unit.factor;
                    let sign = (w_si + e).abs();
                    others.retain(|(_, miss)| *miss <= 3.0 * sign + case.tol);
                    found.extend(others.drain(..).map(|(x, _)| x));
                    found.push(vec![Slip::Sign]);
                }
                Found::Slips(s, near) => {
                    found.extend(others.drain(..).map(|(x, _)| x));
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
        found.extend(others.into_iter().map(|(x, _)| x));
        if found.is_empty() {
            Verdict::Wrong { nearest }
        } else {
            Verdict::Slips(found)
        }
    }

    /// What explains `w` (the entry's number, or its negation): right, or the slips of
    /// digits, scale, unit and formula that fit (none: the nearest of scale, unit and
    /// formula within [`NEAREST`]). A written 0 is right or nothing: no factor, unit or
    /// digit makes 0 of a value that is not.
    fn explain(&self, w: &Written, case: &Case) -> Found {
        let (t, tol) = (case.target, case.tol);
        let u = case.entry.unit;
        let w_si = w.value * u.factor;
        let e = case.exact(w_si);
        let half = case.half(w);
        let zero = crate::check::is_zero(e, t.zero);
        if w.is_zero() {
            return if zero || e.abs() <= tol + half {
                Found::Right
            } else {
                Found::Slips(Vec::new(), None)
            };
        }
        let (cut, rounded) = w.cut_and_rounded(e / u.factor);
        let truncated = w.is(cut) && !w.is(rounded) && !zero;
        if (w_si - e).abs() <= tol + half {
            // Right to the digits written; outside what three digits would hold, the digits
            // are cut instead of rounded, or a single digit is written.
            if !zero {
                let three = 0.5 * 10f64.powf(e.abs().log10().floor() - f64::from(DIGITS - 1));
                if (w_si - e).abs() > tol + three {
                    if truncated {
                        return Found::Slips(vec![vec![Slip::Truncated]], None);
                    }
                    if w.significant() < 2 {
                        return Found::Slips(vec![vec![Slip::Coarse]], None);
                    }
                }
            }
            return Found::Right;
        }
        let truncated = truncated && (w_si - e).abs() < 2.0 * half + tol;
        // A scale or unit slip acts on the value as the table has it (an angle of a turn in
        // [0°, 360°): 4.23 written for 242.3° is the angle in radians).
        let e0 = case.reading.of(t.value);
        let (mut found, near) = self.scale_slips((w_si, half, truncated), case, e0);
        if let Some(digits) = digit_slips(w, case) {
            found.push(vec![digits]);
        }
        Found::Slips(found, near)
    }

    /// The slips of scale, unit and formula that make the number `w_si` (its rounding `half`)
    /// of the exact `e` — after its digits cut, when `truncated` — and the nearest that does
    /// not fit within [`NEAREST`]. One cause
    /// under two names — a μ of another plan ten times this one's, or ×10 — is named once,
    /// by the specific slip; a factor that misses by over three times as much as the
    /// nearest fit is not named beside it.
    fn scale_slips(
        &self,
        (w_si, half, truncated): (f64, f64, bool),
        case: &Case,
        e: f64,
    ) -> (Vec<Explanation>, Option<(Explanation, f64)>) {
        let (t, tol, u) = (case.target, case.tol, case.entry.unit);
        let fits = |x: f64, tol_x: f64| (w_si - x).abs() <= tol_x + half;
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
        if truncated {
            found.push((vec![Slip::Truncated], 1.0));
        }
        for k in FACTORS {
            consider(Slip::Factor(k), k * e, k * tol, &mut found);
        }
        if let Some(own) = own_scale(t) {
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
        for other in units::kind(t.quantity.unit) {
            if (other.factor / u.factor - 1.0).abs() > 1e-9 {
                // The number is in `other`: its SI value is w × other.factor.
                let k = u.factor / other.factor;
                consider(Slip::Unit { meant: other.name }, k * e, k * tol, &mut found);
            }
        }
        for (f, x) in self.formulas(t) {
            let x = case.reading.of(x);
            consider(Slip::Formula(f), x, tol * (x / e).abs(), &mut found);
        }
        let factors: Vec<f64> = found
            .iter()
            .filter(|(x, _)| !matches!(x.as_slice(), [Slip::Factor(_)]))
            .map(|f| f.1)
            .collect();
        let miss = |k: f64| (w_si - k * e).abs();
        let nearest = found
            .iter()
            .map(|f| miss(f.1))
            .fold(f64::INFINITY, f64::min);
        let found = found
            .into_iter()
            .filter(|(x, k)| match x.as_slice() {
                [Slip::Factor(k)] => !factors.iter().any(|f| (f / k - 1.0).abs() < 1e-9),
                _ => true,
            } && miss(*k) <= 3.0 * nearest + half)
            .map(|f| f.0)
            .collect();
        (found, near)
    }

    /// The rows `w` belongs to instead of the case's: the same quantity at the neighbouring
    /// positions of its column (a shifted row), another quantity of the same unit at the same
    /// position (swapped columns), or another column of the student's own row (a copied
    /// value). Only the neighbours are tried, each to the analytic method's tolerance: across
    /// a whole column, some position's value lies within a reading of almost any number.
    /// Each with how far the number lies from that row's value.
    fn elsewhere(&self, w: &Written, case: &Case) -> Vec<(Explanation, f64)> {
        let (t, tol, entry) = (case.target, case.tol, case.entry);
        let u = entry.unit;
        let w_si = w.value * u.factor;
        let (e, half) = (case.exact(w_si), case.half(w));
        let held = if case.analytic {
            super::Held::Analytic
        } else {
            super::Held::Construction
        };
        let column: Vec<&Target> = self
            .targets
            .iter()
            .filter(|o| o.quantity.name == t.quantity.name && o.method == t.method)
            .collect();
        let at = column.iter().position(|o| std::ptr::eq(*o, t));
        let neighbours = at.into_iter().flat_map(|k| {
            [k.checked_sub(1), Some(k + 1)]
                .into_iter()
                .flatten()
                .filter_map(|j| column.get(j).copied())
        });
        let beside = self.targets.iter().filter(|o| {
            o.position == t.position
                && o.quantity.name != t.quantity.name
                && o.method == t.method
                && o.quantity.unit == t.quantity.unit
        });
        let mut found: Vec<(Explanation, f64)> = Vec::new();
        for o in neighbours.chain(beside) {
            let tol_o = self.tolerance(o, &held);
            let x = case.near(o, w_si);
            // The other row's value to the analytic method's tolerance (within a reading,
            // some neighbour fits almost any number), and not this row's value too, of
            // either sign (a sign names that).
            let strict = tol_o.min(ANALYTIC * x.abs()) + half;
            let other = (x - e).abs() > tol + tol_o && (x + e).abs() > tol + tol_o;
            if (w_si - x).abs() <= strict && other {
                let slip = if o.quantity.name == t.quantity.name {
                    Slip::Position(o.position.clone().unwrap_or_default())
                } else {
                    Slip::Quantity(o.quantity.clone())
                };
                found.push((vec![slip], (w_si - x).abs()));
            }
        }
        // The values of this row of this number, one of each column.
        for (s, read) in case.copies.of(entry).filter(|(s, _)| {
            s.quantity != entry.quantity && units::find(t.quantity.unit, s.unit.name).is_some()
        }) {
            // Copied from that column, not into it: nearer that quantity than this one, and
            // not of this one's magnitude (a sign names that).
            let from = self
                .resolve(&s.quantity, s.position.as_deref(), s.method.as_deref())
                .ok()
                .map(|(o, _)| (o, near(o, read, w_si)))
                .filter(|(o, x)| {
                    (w_si - x).abs() < (w_si - e).abs()
                        && (x + e).abs() > tol + self.tolerance(o, &held)
                });
            if let Some((o, x)) = from {
                let slip = Slip::Quantity(o.quantity.clone());
                if !found.iter().any(|f| f.0 == std::slice::from_ref(&slip)) {
                    found.push((vec![slip], (w_si - x).abs()));
                }
            }
        }
        found
    }

    /// The values the course's known wrong formulas give for `t`.
    fn formulas(&self, t: &Target) -> Vec<(Formula, f64)> {
        let scene_value = |q: &str| {
            self.targets
                .iter()
                .find(|o| o.quantity.name == q && o.position.is_none())
                .map(|o| o.value)
        };
        let mut out = Vec::new();
        let q = t.quantity.name.as_str();
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
                    t.value * rb / radius / cos_w,
                ));
            }
        }
        let diagram = t.method.is_some_and(Method::is_diagram);
        if let (Some(w1), true) = (self.omega1, diagram) {
            let power = match t.quantity.symbol() {
                Some(Symbol::Velocity | Symbol::AngularAcceleration) => Some(1),
                Some(Symbol::Acceleration) => Some(2),
                _ => None,
            };
            if let Some(p) = power.filter(|_| w1 > 0.0) {
                out.push((Formula::MissingOmega1, t.value / w1.powi(p)));
            }
        }
        out
    }
}

/// The μ a graphical value was converted with, by name.
fn own_scale(t: &Target) -> Option<&'static str> {
    match (t.quantity.symbol(), t.method) {
        (Some(Symbol::Velocity), Some(Method::Plan)) => Some("μ_v"),
        (Some(Symbol::Acceleration), Some(Method::Plan)) => Some("μ_a"),
        (Some(Symbol::Displacement), Some(m)) if m.is_diagram() => Some("μ_S"),
        _ => None,
    }
}

/// The slips of the pen that make the number written of one meaning the exact value:
/// right to the analytic method's tolerance and the finer of the two numbers' digits (a digit
/// put back proves nothing when any number within a reading would do), and moved by more
/// than twice what a reading and the digits allow.
fn digit_slips(w: &Written, case: &Case) -> Option<Slip> {
    let (tol, u) = (case.tol, case.entry.unit);
    let (w_si, half) = (w.value * u.factor, case.half(w));
    let mut edits: Vec<Edit> = Vec::new();
    let mut meant: Option<(f64, String)> = None;
    for (edit, m) in w.edits() {
        // A number meant that is the written one times a power of ten is a scale slip.
        let decade = (m.value / w.value).log10();
        if (decade - decade.round()).abs() < 1e-9 {
            continue;
        }
        let m_si = m.value * u.factor;
        let e = case.exact(m_si);
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
    let (_, meant) = meant?;
    edits.sort_by_key(|e| *e as u8);
    Some(Slip::Digits { edits, meant })
}
