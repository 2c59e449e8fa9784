//! The blocking contour (блокирующий контур) of an external pair z₁, z₂ cut by a basic rack,
//! in the x₁–x₂ plane (seed 000 L1004–1008, seed 002 PZ3 and its appendices; issue 21 §1):
//! the curves on which one quality index of the pair reaches its limit, each traced from its
//! definition by bracketing along rays — never read from a table.
//!
//! The indices, per unit module (the contour does not depend on m), by this module's own
//! lean formulas ([`Blocking::indices`]); the analytic twins are [`Pair::new`] and
//! [`Cutting`] (the tests and the rows evaluate each traced curve through them):
//! - undercut of wheel i: x_i = x_min,i with x_min = h_l* − z sin²α/2, where h_l* = −v_j* is
//!   the depth below the rack's mean line at which the tool's straight flank ends (its
//!   tangency with the tip rounding ρ_f*). This is the limit [`Cutting::undercut`] decides by;
//!   for the ГОСТ 13755 rack h_l* = 0.99997, so it lies 3·10⁻⁵ left of the textbook's
//!   h_a* − z sin²α/2 ([`super::x_min`]);
//! - tooth pointing: s_a,i = 0, and the quality isolines s_a,i = 0.25 and 0.4 (× m), with the
//!   tip shortened by the exact Δy = x_Σ − y: r_a = r + (h_a* + x − Δy)m;
//! - the contact ratio ε_α = 1 and 1.2;
//! - interference with the transition curve of wheel i: the end of the active line nearer
//!   N_i (the mate's tip) falls short of the lower limit point of wheel i's involute, the point
//!   its flank's end generates, ρ_l,i = r_i sin α − (h_l* − x_i)m/sin α from N_i. The index:
//!   N_iB_i − ρ_l,i, its curve where it is 0;
//! - equal specific sliding at the ends of the active line: λ₁ at B₁ (where the root of
//!   wheel 1 works) equals λ₂ at B₂, λ₁ = 1 − ρ₂/(uρ₁), λ₂ = 1 − uρ₁/ρ₂.
//!
//! A reference point inside the admissible region (the grid point of the plane's window
//! with the largest least margin) is the centre of a fan of rays; on each ray every index
//! less its limit is sampled outward and its every change of sign bracketed to 10⁻¹³ (x per
//! module, so 10⁻¹³ m; regula falsi, [`crate::geom::illinois`]), far below the 10⁻⁹ asked.
//! A curve is the ordered run of the first crossings; a ray that never crosses (within the
//! window, before the formulas leave their domain) adds nothing, and a run breaks where it
//! does not or where consecutive crossings jump (the first crossing has moved to another
//! branch). The crossings behind the first are a curve's stretches hidden behind itself as
//! seen from the centre (PZ3's s_a1 = 0.4m turns back about a ray): they are linked ray to
//! ray and joined to the runs, and where a curve folds back about a ray tangent to it the
//! two ends are joined by following the curve from one to the other (steps along its
//! tangent, each put back on it by Newton's steps to 10⁻¹² of its index), so no curve is
//! cut short. Everything is bounded: a fixed fan, a fixed number of samples per ray, at
//! most 200 steps of the bracket, a fold followed for at most three times its chord.

use super::involute::{inv, inv_inverse_with_tan, inv_with_tan};
use super::{BasicRack, Cutting, GearError, Pair, PairSpec};
use crate::geom::{golden_max, illinois, DVec2};
use crate::kept::Recent;
use rayon::prelude::*;
use std::f64::consts::PI;

/// The studies [`Study::of`] keeps.
const KEPT: usize = 8;
/// The studies [`Study::of`] keeps: the pair, the criterion asked, the study.
static STUDIES: Recent<(PairSpec, Option<Criterion>), Result<Study, BlockingError>> =
    Recent::new(KEPT);
/// The rays of the fan.
const RAYS: usize = 720;
/// Samples along a ray (to the window's edge).
const SAMPLES: usize = 400;
/// The crossing's end: the bracket's length along a ray (x per module).
const BRACKET_TO: f64 = 1e-13;
/// The quality isolines of the tip thickness, × m.
pub const TIP_LIMITS: [f64; 3] = [0.0, 0.25, 0.4];
/// The contact ratio's lines.
pub const EPS_LIMITS: [f64; 2] = [1.0, 1.2];

/// What a curve of the contour bounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Kind {
    /// Undercut of wheel 0 or 1 (index x_i, limit x_min,i).
    Undercut(usize),
    /// The tip thickness of wheel i (index s_a,i/m).
    Tip(usize),
    /// The contact ratio ε_α.
    ContactRatio,
    /// Interference with the fillet of wheel i (index (N_iB_i − ρ_l,i)/m, limit 0).
    Interference(usize),
    /// Equal specific sliding (index λ₁(B₁) − λ₂(B₂), limit 0).
    EqualSliding,
}

impl Kind {
    /// The index is at least its limit on the admissible side (`None`: a line, no side).
    pub fn good_above(self) -> Option<bool> {
        match self {
            Kind::EqualSliding => None,
            _ => Some(true),
        }
    }
}

/// One traced curve: its kind, its limit and its points (x₁, x₂) in order along the fan.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// What it bounds.
    pub kind: Kind,
    /// The index's value on it.
    pub limit: f64,
    /// The points (x₁, x₂).
    pub points: Vec<DVec2>,
}

/// The hard limits of the admissible region.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hard {
    /// The least tip thickness, × m.
    pub sa_min: f64,
    /// The least contact ratio.
    pub eps_min: f64,
}

impl Default for Hard {
    /// s_a ≥ 0.25m, ε_α ≥ 1.2 (with no undercut and no interference).
    fn default() -> Self {
        Hard {
            sa_min: 0.25,
            eps_min: 1.2,
        }
    }
}

/// The indices of a point (x₁, x₂), per unit module.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Indices {
    /// x₁, x₂.
    pub x: [f64; 2],
    /// α_w, rad.
    pub alpha_w: f64,
    /// y.
    pub y: f64,
    /// Δy = x_Σ − y.
    pub dy: f64,
    /// r_a/m.
    pub ra: [f64; 2],
    /// s_a/m.
    pub sa: [f64; 2],
    /// ε_α.
    pub eps: f64,
    /// N₁B₁ and N₂B₂ (/m): the ends of the active line from the centre-side N of each wheel.
    pub near_end: [f64; 2],
    /// ρ_l (/m): the lower limit points of the involutes from N₁ and N₂.
    pub rho_l: [f64; 2],
    /// λ₁ at B₁ and λ₂ at B₂ (`None` when B is at or beyond N: no sliding there).
    pub lambda: Option<[f64; 2]>,
}

impl Indices {
    /// The index a curve of `kind` is a level line of.
    pub fn of(&self, kind: Kind) -> Option<f64> {
        match kind {
            Kind::Undercut(i) => Some(self.x[i]),
            Kind::Tip(i) => Some(self.sa[i]),
            Kind::ContactRatio => Some(self.eps),
            Kind::Interference(i) => Some(self.near_end[i] - self.rho_l[i]),
            Kind::EqualSliding => self.lambda.map(|l| l[0] - l[1]),
        }
    }
}

/// Why a contour cannot be traced or a choice made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BlockingError {
    /// The pair or the rack out of range.
    #[error("blocking contour: {0}")]
    Gear(#[from] GearError),
    /// A point not finite.
    #[error("blocking contour: the point ({0}, {1}) is not finite")]
    NotFinite(f64, f64),
    /// The involute formulas have no value at the point.
    #[error("blocking contour: the pair has no geometry at x₁ = {0}, x₂ = {1} (no α_w or a tip inside the base circle)")]
    Domain(f64, f64),
    /// No point of the plane meets every hard limit.
    #[error("blocking contour: no point of x₁ ∈ [{0:.3}, {1:.3}], x₂ ∈ [{2:.3}, {3:.3}] meets every hard limit (s_a ≥ {4}m, ε_α ≥ {5}, no undercut, no interference)")]
    Empty(f64, f64, f64, f64, f64, f64),
    /// The criterion's line misses the admissible region.
    #[error("blocking contour: the line x₁ + x₂ = {0} does not cross the admissible region")]
    LineOutside(f64),
}

/// The contour's problem: the pair's tooth numbers and the rack.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Blocking {
    /// z₁, z₂.
    pub z: [u32; 2],
    /// The rack.
    pub rack: BasicRack,
    /// h_l* = −v_j*: the depth of the flank's end below the rack's mean line, × m.
    pub hl: f64,
    /// The plane's window: (x₁ min, x₂ min), (x₁ max, x₂ max).
    pub window: (DVec2, DVec2),
    /// The rack's sin α, cos α, tg α and inv α, for [`Self::indices`].
    trig: [f64; 4],
}

/// The traced contour.
#[derive(Debug, Clone, PartialEq)]
pub struct Contour {
    /// The problem.
    pub blocking: Blocking,
    /// The centre of the fan of rays.
    pub centre: DVec2,
    /// Every traced curve (a kind and limit may have several runs).
    pub curves: Vec<Curve>,
    /// The hard limits of `boundary`.
    pub hard: Hard,
    /// The admissible region's boundary, closed (empty when the centre is not admissible).
    pub boundary: Vec<DVec2>,
}

/// A criterion of the choice of x₁, x₂ inside the contour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Criterion {
    /// Maximise ε_α over the admissible region.
    LargestContactRatio,
    /// On the line x₁ + x₂ = x_Σ, the point where λ₁ at B₁ equals λ₂ at B₂ (or, when that
    /// point is outside the admissible region, the admissible point of the line with the
    /// least |λ₁ − λ₂|).
    EqualSliding {
        /// x_Σ.
        x_sum: f64,
    },
    /// Maximise x₁ + x₂ (the stiffest, strongest teeth) with both tips s_a ≥ `sa_min`·m.
    GreatestSumWithTip {
        /// The least tip thickness, × m.
        sa_min: f64,
    },
}

/// A chosen point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Choice {
    /// The criterion.
    pub criterion: Criterion,
    /// Its indices.
    pub indices: Indices,
}

/// Where a point lies against one curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Side {
    /// The curve's kind.
    pub kind: Kind,
    /// Its limit.
    pub limit: f64,
    /// The point's index.
    pub value: f64,
    /// On the admissible side (the index ≥ its limit); `None` for a line without a side.
    pub inside: Option<bool>,
}

/// A point placed on the contour.
#[derive(Debug, Clone, PartialEq)]
pub struct Placement {
    /// Its indices.
    pub indices: Indices,
    /// Against every limit the contour draws.
    pub sides: Vec<Side>,
    /// Inside the admissible region of the contour's hard limits.
    pub admissible: bool,
}

/// Every (kind, limit) the contour traces.
pub fn levels(rack: &BasicRack, z: [u32; 2]) -> Vec<(Kind, f64)> {
    let hl = -rack.per_module().vj;
    let sin2 = rack.alpha.sin().powi(2);
    let mut out = Vec::new();
    for (i, zi) in z.iter().enumerate() {
        out.push((Kind::Undercut(i), hl - f64::from(*zi) * sin2 / 2.0));
    }
    for i in 0..2 {
        for l in TIP_LIMITS {
            out.push((Kind::Tip(i), l));
        }
    }
    for l in EPS_LIMITS {
        out.push((Kind::ContactRatio, l));
    }
    out.push((Kind::Interference(0), 0.0));
    out.push((Kind::Interference(1), 0.0));
    out.push((Kind::EqualSliding, 0.0));
    out
}

impl Blocking {
    /// The problem of z₁, z₂ cut by `rack`; its window spans each x from 0.4 below the
    /// undercut limit (or −1.4) to 1.5 beyond the shift that points the wheel cut alone (the
    /// pair's Δy shortens the tip and moves its pointing out by up to about that), within
    /// ±3.
    ///
    /// # Errors
    /// [`GearError::Spec`] for fewer than 5 teeth, [`GearError::Rack`].
    pub fn new(z: [u32; 2], rack: BasicRack) -> Result<Self, BlockingError> {
        rack.validate()?;
        for (i, zi) in z.iter().enumerate() {
            if *zi < 5 {
                return Err(GearError::Spec {
                    what: if i == 0 { "z1" } else { "z2" },
                    value: f64::from(*zi),
                    expected: "at least 5 teeth",
                }
                .into());
            }
        }
        let hl = -rack.per_module().vj;
        let sin2 = rack.alpha.sin().powi(2);
        let mut lo = [0.0; 2];
        let mut hi = [0.0; 2];
        for i in 0..2 {
            let zi = f64::from(z[i]);
            lo[i] = ((hl - zi * sin2 / 2.0).max(-1.0) - 0.4).max(-3.0);
            // The wheel alone (Δy = 0) points where s_a = 0: bisection on x (s_a falls).
            let sa = |x: f64| {
                let r = zi / 2.0;
                let ra = r + rack.ha + x;
                let rb = r * rack.alpha.cos();
                if ra <= rb {
                    return 1.0;
                }
                let s = PI / 2.0 + 2.0 * x * rack.alpha.tan();
                2.0 * ra * (s / (2.0 * r) + inv(rack.alpha) - inv((rb / ra).acos()))
            };
            let (mut a, mut b) = (lo[i], 3.0);
            if sa(b) > 0.0 {
                hi[i] = 3.0;
            } else {
                for _ in 0..100 {
                    let mid = 0.5 * (a + b);
                    if sa(mid) > 0.0 {
                        a = mid;
                    } else {
                        b = mid;
                    }
                }
                hi[i] = (b + 1.5).min(3.0);
            }
            if hi[i] < lo[i] + 0.5 {
                hi[i] = (lo[i] + 0.5).min(3.0);
            }
        }
        let a = rack.alpha;
        Ok(Self {
            z,
            rack,
            hl,
            window: (DVec2::new(lo[0], lo[1]), DVec2::new(hi[0], hi[1])),
            trig: [a.sin(), a.cos(), a.tan(), inv(a)],
        })
    }

    /// x_min,i = h_l* − z_i sin²α/2.
    pub fn x_min(&self, i: usize) -> f64 {
        self.hl - f64::from(self.z[i]) * self.rack.alpha.sin().powi(2) / 2.0
    }

    /// The indices at (x₁, x₂) by the lean formulas; `None` outside their domain (no α_w,
    /// a tip circle inside its base circle).
    pub fn indices(&self, x: DVec2) -> Option<Indices> {
        if !(x.x.is_finite() && x.y.is_finite()) {
            return None;
        }
        let ha = self.rack.ha;
        let [sa_, ca, ta, inv_alpha] = self.trig;
        let xs = [x.x, x.y];
        let zz = self.z.map(f64::from);
        let zs = zz[0] + zz[1];
        let x_sum = xs[0] + xs[1];
        let (alpha_w, tan_w) = inv_inverse_with_tan(2.0 * x_sum * ta / zs + inv_alpha).ok()?;
        // 1 / cos α_w = √(1 + tg²α_w).
        let y = zs / 2.0 * (ca * (1.0 + tan_w * tan_w).sqrt() - 1.0);
        let dy = x_sum - y;
        let r = zz.map(|z| z / 2.0);
        let rb = r.map(|r| r * ca);
        let ra = [0, 1].map(|i| r[i] + ha + xs[i] - dy);
        // A tip on or inside its base circle (or not a number): no involute flank.
        if ra
            .iter()
            .zip(rb)
            .any(|(a, b)| a.partial_cmp(&b) != Some(std::cmp::Ordering::Greater))
        {
            return None;
        }
        // The tip's roll: N_iB of the own tip, r_b tg α_a.
        let tip = [0, 1].map(|i| (ra[i] * ra[i] - rb[i] * rb[i]).sqrt());
        let sa = [0, 1].map(|i| {
            let aa = (rb[i] / ra[i]).acos();
            let half = (PI / 2.0 + 2.0 * xs[i] * ta) / (2.0 * r[i]);
            2.0 * ra[i] * (half + inv_alpha - inv_with_tan(aa, tip[i] / rb[i]))
        });
        // N₁N₂ from the base circles: (r_b1 + r_b2) tg α_w.
        let g = (rb[0] + rb[1]) * tan_w;
        let eps = (tip[0] + tip[1] - g) / (PI * ca);
        let near_end = [g - tip[1], g - tip[0]];
        let rho_l = [0, 1].map(|i| r[i] * sa_ - (self.hl - xs[i]) / sa_);
        let u = zz[1] / zz[0];
        let lambda = (near_end[0] > 0.0 && near_end[1] > 0.0).then(|| {
            [
                1.0 - tip[1] / (u * near_end[0]),
                1.0 - u * tip[0] / near_end[1],
            ]
        });
        Some(Indices {
            x: xs,
            alpha_w,
            y,
            dy,
            ra,
            sa,
            eps,
            near_end,
            rho_l,
            lambda,
        })
    }

    /// The hard limits as level lines: at a point, the least of their indices less their
    /// limits is [`Self::margin`].
    fn hard_levels(&self, hard: Hard) -> [(Kind, f64); 7] {
        [
            (Kind::ContactRatio, hard.eps_min),
            (Kind::Undercut(0), self.x_min(0)),
            (Kind::Undercut(1), self.x_min(1)),
            (Kind::Tip(0), hard.sa_min),
            (Kind::Tip(1), hard.sa_min),
            (Kind::Interference(0), 0.0),
            (Kind::Interference(1), 0.0),
        ]
    }

    /// The least margin of the hard limits at `x` (≥ 0: admissible), in the indices' own
    /// units (x and lengths per module, ε_α).
    pub fn margin(&self, x: DVec2, hard: Hard) -> Option<f64> {
        let ix = self.indices(x)?;
        self.hard_levels(hard)
            .iter()
            .try_fold(f64::INFINITY, |m, (kind, limit)| {
                Some(m.min(ix.of(*kind)? - limit))
            })
    }

    /// The distance along the ray from `c` in the direction `d` to the window's edge.
    fn reach(&self, c: DVec2, d: DVec2) -> f64 {
        let (lo, hi) = self.window;
        let mut t = f64::INFINITY;
        for (ci, di, l, h) in [(c.x, d.x, lo.x, hi.x), (c.y, d.y, lo.y, hi.y)] {
            if di > 1e-15 {
                t = t.min((h - ci) / di);
            } else if di < -1e-15 {
                t = t.min((l - ci) / di);
            }
        }
        t.max(0.0)
    }

    /// The centre of the fan: the point of a 41 × 41 grid over the window with the largest
    /// least margin of `hard`.
    pub fn centre(&self, hard: Hard) -> DVec2 {
        let (lo, hi) = self.window;
        let n = 40;
        let mut best = (f64::NEG_INFINITY, (lo + hi) * 0.5);
        for i in 0..=n {
            for j in 0..=n {
                let p = DVec2::new(
                    lo.x + (hi.x - lo.x) * f64::from(i) / f64::from(n),
                    lo.y + (hi.y - lo.y) * f64::from(j) / f64::from(n),
                );
                if let Some(m) = self.margin(p, hard) {
                    if m > best.0 {
                        best = (m, p);
                    }
                }
            }
        }
        best.1
    }

    /// The first crossing of `f` = 0 along the ray c + t·d, t ∈ (0, reach], by sampling and
    /// [`crossing`]; `None` when it never changes sign there (or leaves its domain first).
    fn first_crossing(&self, c: DVec2, d: DVec2, f: &dyn Fn(DVec2) -> Option<f64>) -> Option<f64> {
        let t_max = self.reach(c, d);
        if t_max <= 0.0 {
            return None;
        }
        let f0 = f(c)?;
        let mut prev = (0.0, f0);
        for k in 1..=SAMPLES {
            let t = t_max * k as f64 / SAMPLES as f64;
            let v = f(c + d * t)?;
            if (v >= 0.0) != (prev.1 >= 0.0) {
                return crossing(|t| f(c + d * t), prev, (t, v));
            }
            prev = (t, v);
        }
        None
    }

    /// Every crossing of every level along the ray c + t·d, nearest the centre first (each
    /// as [`Self::first_crossing`] finds the first; the indices evaluated once per sample).
    fn crossings(&self, c: DVec2, d: DVec2, levels: &[(Kind, f64)]) -> Vec<Vec<f64>> {
        let mut out = vec![Vec::new(); levels.len()];
        let t_max = self.reach(c, d);
        let Some(ix0) = self.indices(c).filter(|_| t_max > 0.0) else {
            return out;
        };
        let value = |ix: &Indices, k: usize| Some(ix.of(levels[k].0)? - levels[k].1);
        let mut prev: Vec<Option<(f64, f64)>> = (0..levels.len())
            .map(|k| value(&ix0, k).map(|v| (0.0, v)))
            .collect();
        for s in 1..=SAMPLES {
            let t = t_max * s as f64 / SAMPLES as f64;
            let Some(ix) = self.indices(c + d * t) else {
                break;
            };
            for k in 0..levels.len() {
                let v = value(&ix, k);
                if let (Some((t0, v0)), Some(v)) = (prev[k], v) {
                    if (v >= 0.0) != (v0 >= 0.0) {
                        let f = |t: f64| value(&self.indices(c + d * t)?, k);
                        match crossing(f, (t0, v0), (t, v)) {
                            Some(tc) => out[k].push(tc),
                            // A level whose bracket left the domain is not crossed here.
                            None => {
                                prev[k] = None;
                                continue;
                            }
                        }
                    }
                }
                // A level undefined at a sample (λ with B beyond N) brackets nothing across it.
                prev[k] = v.map(|v| (t, v));
            }
        }
        out
    }

    /// Trace every level of [`levels`] and the admissible region's boundary of `hard`.
    pub fn trace(&self, hard: Hard) -> Contour {
        let centre = self.centre(hard);
        let dirs: Vec<DVec2> = (0..RAYS)
            .map(|k| {
                let a = fan_angle(k, RAYS);
                DVec2::new(a.cos(), a.sin())
            })
            .collect();
        // The largest spacing of neighbouring crossings that stays one run.
        let (lo, hi) = self.window;
        let jump = (hi - lo).length() * 0.05;
        let levels = levels(&self.rack, self.z);
        // The hard limits, each a level line (those `levels` lacks appended): the margin of
        // `hard` is their least index less its limit, so the admissible region's boundary
        // along a ray is their first crossing nearest the centre.
        let mut all = levels.clone();
        let hard_levels: Vec<usize> = self
            .hard_levels(hard)
            .into_iter()
            .map(|l| {
                all.iter().position(|m| *m == l).unwrap_or_else(|| {
                    all.push(l);
                    all.len() - 1
                })
            })
            .collect();
        // Along each ray the indices once per sample; each level's every change of sign
        // bracketed on its own index. The rays on all cores.
        let found: Vec<Vec<Vec<f64>>> = dirs
            .par_iter()
            .map(|d| self.crossings(centre, *d, &all))
            .collect();
        let mut hits: Vec<Vec<Vec<DVec2>>> = vec![Vec::with_capacity(RAYS); levels.len()];
        let mut reach = Vec::with_capacity(RAYS);
        for (d, found) in dirs.iter().zip(found) {
            for (h, ts) in hits.iter_mut().zip(&found) {
                h.push(ts.iter().map(|t| centre + *d * *t).collect());
            }
            let first = hard_levels
                .iter()
                .filter_map(|k| found[*k].first().copied())
                .reduce(f64::min);
            reach.push(first.unwrap_or_else(|| self.reach(centre, *d)));
        }
        let mut curves = Vec::new();
        for ((kind, limit), hits) in levels.iter().zip(&hits) {
            let bridge = |a: DVec2, b: DVec2| self.follow((*kind, *limit), a, b, jump / 10.0);
            for points in whole_runs(hits, jump, &bridge) {
                curves.push(Curve {
                    kind: *kind,
                    limit: *limit,
                    points,
                });
            }
        }
        let admissible = self.margin(centre, hard).is_some_and(|m| m > 0.0);
        let boundary = if admissible {
            dirs.iter()
                .zip(reach)
                .map(|(d, t)| centre + *d * t)
                .collect()
        } else {
            Vec::new()
        };
        Contour {
            blocking: *self,
            centre,
            curves,
            hard,
            boundary,
        }
    }

    /// Place the point `x` on the contour: its indices, its side of every level, whether it
    /// meets `hard`.
    ///
    /// # Errors
    /// [`BlockingError::NotFinite`], [`BlockingError::Domain`].
    pub fn place(&self, x: DVec2, hard: Hard) -> Result<Placement, BlockingError> {
        if !(x.x.is_finite() && x.y.is_finite()) {
            return Err(BlockingError::NotFinite(x.x, x.y));
        }
        let indices = self.indices(x).ok_or(BlockingError::Domain(x.x, x.y))?;
        let sides = levels(&self.rack, self.z)
            .into_iter()
            .filter_map(|(kind, limit)| {
                let value = indices.of(kind)?;
                Some(Side {
                    kind,
                    limit,
                    value,
                    inside: kind.good_above().map(|_| value >= limit),
                })
            })
            .collect();
        Ok(Placement {
            indices,
            sides,
            admissible: self.margin(x, hard).is_some_and(|m| m >= 0.0),
        })
    }

    /// The point `criterion` chooses inside the admissible region of `hard`.
    ///
    /// # Errors
    /// [`BlockingError::Empty`] when no point is admissible, [`BlockingError::LineOutside`]
    /// when the line of [`Criterion::EqualSliding`] misses the region.
    pub fn choose(&self, criterion: Criterion, hard: Hard) -> Result<Choice, BlockingError> {
        self.choose_on(criterion, hard, None)
    }

    /// [`Self::choose`], the grid of the admissible boundary taken from `traced` when it is
    /// this problem's contour of the same hard limits (its fan's every other ray).
    fn choose_on(
        &self,
        criterion: Criterion,
        hard: Hard,
        traced: Option<&Contour>,
    ) -> Result<Choice, BlockingError> {
        let hard = match criterion {
            Criterion::GreatestSumWithTip { sa_min } => Hard { sa_min, ..hard },
            _ => hard,
        };
        let centre = self.centre(hard);
        if !self.margin(centre, hard).is_some_and(|m| m > 0.0) {
            let (lo, hi) = self.window;
            return Err(BlockingError::Empty(
                lo.x,
                hi.x,
                lo.y,
                hi.y,
                hard.sa_min,
                hard.eps_min,
            ));
        }
        // A maximum lies on the boundary, to the bracket's 1e-13: drawn in by 1e-9 of its
        // distance from the centre, it meets every hard limit strictly, so the pair built on
        // it works whatever the rounding of its own formulas. (The equal-sliding point keeps
        // its line; the ends of the line's stretch are bracketed on the admissible side.)
        let inside = |x: DVec2| centre + (x - centre) * (1.0 - 1e-9);
        let fan = traced
            .filter(|t| {
                t.blocking == *self
                    && t.hard == hard
                    && t.centre == centre
                    && t.boundary.len() == RAYS
            })
            .map(|t| t.boundary.as_slice());
        let x = match criterion {
            Criterion::LargestContactRatio => inside(self.maximise(centre, hard, fan, |ix| ix.eps)),
            Criterion::GreatestSumWithTip { .. } => {
                inside(self.maximise(centre, hard, fan, |ix| ix.x[0] + ix.x[1]))
            }
            Criterion::EqualSliding { x_sum } => self.equal_sliding(x_sum, hard)?,
        };
        let indices = self.indices(x).ok_or(BlockingError::Domain(x.x, x.y))?;
        Ok(Choice { criterion, indices })
    }

    /// The level line `level` followed from `a` to `b` (both on it) in steps of `h` along
    /// its tangent, each step put back on the line by Newton's steps along the gradient
    /// (central differences); the points between `a` and `b`. `None` when it leaves the
    /// domain, does not settle on the line (to 1e-12), or has not arrived after three times
    /// the straight distance.
    fn follow(&self, level: (Kind, f64), a: DVec2, b: DVec2, h: f64) -> Option<Vec<DVec2>> {
        let f = |p: DVec2| Some(self.indices(p)?.of(level.0)? - level.1);
        let grad = |p: DVec2| {
            let e = 1e-7;
            let dx = f(p + DVec2::new(e, 0.0))? - f(p - DVec2::new(e, 0.0))?;
            let dy = f(p + DVec2::new(0.0, e))? - f(p - DVec2::new(0.0, e))?;
            let g = DVec2::new(dx, dy) / (2.0 * e);
            (g.length_squared() > 0.0).then_some(g)
        };
        let tangent = |p: DVec2, toward: DVec2| {
            let g = grad(p)?;
            let t = DVec2::new(-g.y, g.x).normalize();
            Some(if t.dot(toward) < 0.0 { -t } else { t })
        };
        let mut p = a;
        let mut t = tangent(p, b - a)?;
        let mut out = Vec::new();
        let steps = (3.0 * (b - a).length() / h).ceil() as usize + 8;
        for _ in 0..steps {
            if (b - p).length() <= h {
                return Some(out);
            }
            let mut q = p + t * h;
            let mut newton = 0;
            loop {
                let v = f(q)?;
                if v.abs() <= 1e-12 {
                    break;
                }
                if newton == 12 {
                    return None;
                }
                let g = grad(q)?;
                q -= g * (v / g.length_squared());
                newton += 1;
            }
            out.push(q);
            p = q;
            t = tangent(p, t)?;
        }
        None
    }

    /// The admissible boundary's distance along the ray from `c` at the angle `a`.
    fn boundary_at(&self, c: DVec2, a: f64, hard: Hard) -> f64 {
        let d = DVec2::new(a.cos(), a.sin());
        let f = |p: DVec2| self.margin(p, hard);
        self.first_crossing(c, d, &f)
            .unwrap_or_else(|| self.reach(c, d))
    }

    /// Maximise `obj` over the admissible region, star-shaped about `c`: the points c +
    /// s·t_b(θ)·(cos θ, sin θ), s ∈ [0, 1], t_b the boundary's distance; a 360 × 21 grid of
    /// (θ, s), then golden sections in θ and in s, alternately, on shrinking brackets. `fan`:
    /// the boundary already traced from `c` along [`RAYS`] rays, whose every other ray is
    /// the grid's.
    fn maximise(
        &self,
        c: DVec2,
        hard: Hard,
        fan: Option<&[DVec2]>,
        obj: impl Fn(&Indices) -> f64 + Sync,
    ) -> DVec2 {
        let value = |p: DVec2| self.indices(p).map_or(f64::NEG_INFINITY, |ix| obj(&ix));
        // The ray at the angle a and the boundary's distance along it.
        let ray = |a: f64| (DVec2::new(a.cos(), a.sin()), self.boundary_at(c, a, hard));
        let (na, ns) = (RAYS / 2, 20);
        let da = 2.0 * PI / na as f64;
        // The grid's best (value, angle, s), the angles on all cores; of equal values the
        // first in the grid's order.
        let best_on = |i: usize| {
            let a = fan_angle(i, na);
            let d = DVec2::new(a.cos(), a.sin());
            let tb = match fan {
                Some(b) => (b[2 * i] - c).length(),
                None => self.boundary_at(c, a, hard),
            };
            let mut best = (f64::NEG_INFINITY, a, 0.0);
            for j in 0..=ns {
                let s = f64::from(j) / f64::from(ns);
                let v = value(c + d * (tb * s));
                if v > best.0 {
                    best = (v, a, s);
                }
            }
            best
        };
        let best = (0..na)
            .into_par_iter()
            .map(best_on)
            .reduce_with(|p, q| if q.0 > p.0 { q } else { p })
            .unwrap_or((f64::NEG_INFINITY, 0.0, 0.0));
        let (mut a, mut s) = (best.1, best.2);
        let (mut wa, mut ws) = (da, 1.0 / f64::from(ns));
        for _ in 0..6 {
            a = golden_max(a - wa, a + wa, |a| {
                let (d, tb) = ray(a);
                value(c + d * (tb * s))
            })
            .1;
            let (d, tb) = ray(a);
            s = golden_max((s - ws).max(0.0), (s + ws).min(1.0), |s| {
                value(c + d * (tb * s))
            })
            .1;
            wa *= 0.25;
            ws *= 0.25;
        }
        let (d, tb) = ray(a);
        c + d * (tb * s)
    }

    /// The equal-sliding point of the line x₁ + x₂ = `x_sum` (see [`Criterion::EqualSliding`]).
    fn equal_sliding(&self, x_sum: f64, hard: Hard) -> Result<DVec2, BlockingError> {
        if !x_sum.is_finite() {
            return Err(BlockingError::NotFinite(x_sum, x_sum));
        }
        let (lo, hi) = self.window;
        let a = lo.x.max(x_sum - hi.y);
        let b = hi.x.min(x_sum - lo.y);
        if a.partial_cmp(&b) != Some(std::cmp::Ordering::Less) {
            return Err(BlockingError::LineOutside(x_sum));
        }
        let on = |x1: f64| DVec2::new(x1, x_sum - x1);
        // The admissible stretch of the line, sampled, then its ends bisected.
        let n = 2000;
        let xs: Vec<f64> = (0..=n)
            .map(|k| a + (b - a) * f64::from(k) / f64::from(n))
            .collect();
        let ok = |x1: f64| self.margin(on(x1), hard).is_some_and(|m| m >= 0.0);
        let Some(k0) = xs.iter().position(|x| ok(*x)) else {
            return Err(BlockingError::LineOutside(x_sum));
        };
        let k1 = xs.iter().rposition(|x| ok(*x)).unwrap_or(k0);
        let margin = |x: f64| self.margin(on(x), hard);
        // The ends of the stretch on its admissible side.
        let from = if k0 > 0 {
            bracket(xs[k0 - 1], xs[k0], false, &margin).map_or(xs[k0], |(_, h)| h)
        } else {
            xs[k0]
        };
        let to = if k1 < n as usize {
            bracket(xs[k1], xs[k1 + 1], true, &margin).map_or(xs[k1], |(l, _)| l)
        } else {
            xs[k1]
        };
        let d = |x1: f64| self.indices(on(x1))?.of(Kind::EqualSliding);
        match (d(from), d(to)) {
            (Some(u), Some(v)) if (u >= 0.0) != (v >= 0.0) => {
                let x1 = crossing(d, (from, u), (to, v)).unwrap_or(from);
                Ok(on(x1))
            }
            (u, v) => {
                let u = u.map_or(f64::INFINITY, f64::abs);
                let v = v.map_or(f64::INFINITY, f64::abs);
                Ok(on(if u <= v { from } else { to }))
            }
        }
    }
}

/// The zero of `f` between `a` and `b` (each a point and its value, of opposite signs),
/// bracketed to [`BRACKET_TO`] by [`illinois`]: the end whose value is nearer 0; `None` when
/// `f` leaves its domain inside.
fn crossing(f: impl Fn(f64) -> Option<f64>, a: (f64, f64), b: (f64, f64)) -> Option<f64> {
    let [(lo, fl), (hi, fh)] = illinois(f, a, b, |u, v| (u - v).abs() <= BRACKET_TO)?;
    Some(if fl.abs() <= fh.abs() { lo } else { hi })
}

/// The angle of ray `k` of a fan of `n`: 2πk/n (the same angle for 2k of 2n).
fn fan_angle(k: usize, n: usize) -> f64 {
    2.0 * PI * k as f64 / n as f64
}

/// The bracket (a-side end, b-side end) of a change of `f`'s sign, halved to [`BRACKET_TO`]
/// (f(a) ≥ 0 is `a_nonneg`; f is not evaluated at a or b, where it may have no value).
fn bracket(a: f64, b: f64, a_nonneg: bool, f: &impl Fn(f64) -> Option<f64>) -> Option<(f64, f64)> {
    let (mut lo, mut hi) = (a, b);
    for _ in 0..200 {
        if (hi - lo).abs() <= BRACKET_TO {
            break;
        }
        let mid = 0.5 * (lo + hi);
        if mid == lo || mid == hi {
            break;
        }
        if (f(mid)? >= 0.0) == a_nonneg {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some((lo, hi))
}

/// The runs of consecutive crossings of a closed fan (the last ray neighbours the first),
/// broken where a ray misses or two crossings are more than `jump` apart.
/// The curves of one level from its crossings on every ray of the fan (`hits[k]`: ray k's,
/// nearest the centre first). The first crossings make the runs [`runs`] finds; the others
/// are the stretches hidden behind the curve itself as seen from the centre. These are
/// linked ray to ray, each to the nearest within `jump`, and joined end to end with the runs:
/// where one goes on from the other's end on the next ray (within `jump`), and where the
/// curve folds back about a ray tangent to it (two ends on the same or the next ray, farther
/// apart: `bridge` follows the curve from one to the other and gives the points between) —
/// or left as runs of their own. A level crossed at most once on every ray gives exactly the
/// runs of its first crossings.
fn whole_runs(
    hits: &[Vec<DVec2>],
    jump: f64,
    bridge: &dyn Fn(DVec2, DVec2) -> Option<Vec<DVec2>>,
) -> Vec<Vec<DVec2>> {
    let first: Vec<Option<DVec2>> = hits.iter().map(|h| h.first().copied()).collect();
    let mut out: Vec<Ended> = runs(&first, jump)
        .into_iter()
        .map(|points| Ended::locate(points, hits))
        .collect();
    let mut pieces: Vec<Option<Ended>> = hidden_tracks(hits, jump).into_iter().map(Some).collect();
    if pieces.is_empty() {
        return out.into_iter().map(|r| r.points).collect();
    }
    let n = hits.len();
    // The ends facing each other across at most one ray: (distance, hidden piece, its end,
    // the other (a run, or a hidden piece), its end), the nearest first.
    let facing = |out: &[Ended], pieces: &[Option<Ended>]| {
        let mut pairs = Vec::new();
        for (i, a) in pieces.iter().enumerate() {
            let Some(a) = a else { continue };
            let others = out
                .iter()
                .enumerate()
                .map(|(j, r)| (Other::Run(j), r))
                .chain(
                    pieces
                        .iter()
                        .enumerate()
                        .filter(|(j, _)| *j != i)
                        .filter_map(|(j, r)| r.as_ref().map(|r| (Other::Hidden(j), r))),
                );
            for (other, b) in others {
                if b.closed() {
                    continue;
                }
                for (a_last, b_last) in [(false, false), (false, true), (true, false), (true, true)]
                {
                    let ((ra, pa), (rb, pb)) = (a.end(a_last), b.end(b_last));
                    if facing_rays(ra, rb, n) {
                        pairs.push(((pa - pb).length(), i, a_last, other, b_last));
                    }
                }
            }
        }
        pairs.sort_by(|x, y| x.0.total_cmp(&y.0));
        pairs
    };
    // First the stretches that go on within `jump`, then the folds, each bridged.
    for fold in [false, true] {
        'join: loop {
            for (dist, i, a_last, other, b_last) in facing(&out, &pieces) {
                let via = if dist <= jump {
                    Vec::new()
                } else if fold {
                    let (Some(a), b) = (&pieces[i], other.of(&out, &pieces)) else {
                        continue;
                    };
                    // From the other's end to this piece's end.
                    match bridge(b.end(b_last).1, a.end(a_last).1) {
                        Some(via) => via,
                        None => continue,
                    }
                } else {
                    continue;
                };
                let a = pieces[i].take().expect("a hidden stretch not yet joined");
                match other {
                    Other::Run(j) => {
                        out[j] = std::mem::take(&mut out[j]).joined(via, a, b_last, a_last)
                    }
                    Other::Hidden(j) => {
                        let b = pieces[j].take().expect("another hidden stretch");
                        pieces[j] = Some(b.joined(via, a, b_last, a_last));
                    }
                }
                continue 'join;
            }
            break;
        }
    }
    out.extend(pieces.into_iter().flatten());
    // A curve whose two ends now face each other round a second fold is closed.
    for r in out.iter_mut().filter(|r| r.joins > 0 && !r.closed()) {
        let ((ra, pa), (rb, pb)) = (r.end(true), r.end(false));
        if facing_rays(ra, rb, n) {
            if let Some(via) = bridge(pa, pb) {
                r.points.extend(via);
                r.points.push(pb);
            }
        }
    }
    let mut out: Vec<Vec<DVec2>> = out.into_iter().map(|r| r.points).collect();
    out.retain(|r| r.len() >= 2);
    out
}

/// Rays `a` and `b` of a fan of `n` are the same or neighbours (across ray 0 too).
fn facing_rays(a: usize, b: usize, n: usize) -> bool {
    let apart = (a + n - b) % n;
    apart <= 1 || apart == n - 1
}

/// What a hidden stretch is joined to.
#[derive(Debug, Clone, Copy)]
enum Other {
    /// A run of first crossings.
    Run(usize),
    /// Another hidden stretch.
    Hidden(usize),
}

impl Other {
    fn of<'a>(self, out: &'a [Ended], pieces: &'a [Option<Ended>]) -> &'a Ended {
        match self {
            Other::Run(j) => &out[j],
            Other::Hidden(j) => pieces[j].as_ref().expect("a hidden stretch not yet joined"),
        }
    }
}

/// A polyline of crossings with the rays of its two ends.
#[derive(Debug, Clone, Default)]
struct Ended {
    points: Vec<DVec2>,
    /// The rays of the first and the last point.
    rays: (usize, usize),
    /// The stretches joined to it.
    joins: usize,
}

impl Ended {
    /// `points` with the rays of its ends found among `hits` (a point is where it was found).
    fn locate(points: Vec<DVec2>, hits: &[Vec<DVec2>]) -> Self {
        let ray = |p: Option<&DVec2>| {
            p.and_then(|p| hits.iter().position(|h| h.contains(p)))
                .unwrap_or(0)
        };
        let rays = (ray(points.first()), ray(points.last()));
        Self {
            points,
            rays,
            joins: 0,
        }
    }

    /// A closed run (round the whole fan, its first point repeated last) takes no join.
    fn closed(&self) -> bool {
        self.points.len() > 2 && self.points.first() == self.points.last()
    }

    /// The last end (`true`) or the first, with its ray.
    fn end(&self, last: bool) -> (usize, DVec2) {
        if last {
            (self.rays.1, *self.points.last().expect("a run has points"))
        } else {
            (self.rays.0, self.points[0])
        }
    }

    /// This polyline with `other` joined at this one's end `at_last` and other's end
    /// `other_last`, through `via` (the points between, from this one's end on).
    fn joined(
        mut self,
        mut via: Vec<DVec2>,
        mut other: Ended,
        at_last: bool,
        other_last: bool,
    ) -> Ended {
        if at_last {
            if other_last {
                other.points.reverse();
                other.rays = (other.rays.1, other.rays.0);
            }
            self.points.extend(via);
            self.points.extend(other.points);
            self.rays.1 = other.rays.1;
        } else {
            if !other_last {
                other.points.reverse();
                other.rays = (other.rays.1, other.rays.0);
            }
            via.reverse();
            other.points.extend(via);
            other.points.extend(self.points);
            self.points = other.points;
            self.rays.0 = other.rays.0;
        }
        self.joins += 1 + other.joins;
        self
    }
}

/// The crossings of a level beyond the first on each ray, linked ray to ray: a crossing
/// continues the stretch whose last crossing, on the ray before, is nearest (within `jump`;
/// the nearest pairs first), or starts one.
fn hidden_tracks(hits: &[Vec<DVec2>], jump: f64) -> Vec<Ended> {
    let mut done: Vec<Ended> = Vec::new();
    let mut open: Vec<Ended> = Vec::new();
    for (k, h) in hits.iter().enumerate() {
        let here = h.get(1..).unwrap_or(&[]);
        let mut pairs: Vec<(f64, usize, usize)> = Vec::new();
        for (i, t) in open.iter().enumerate() {
            for (j, p) in here.iter().enumerate() {
                let d = (t.end(true).1 - *p).length();
                if d <= jump {
                    pairs.push((d, i, j));
                }
            }
        }
        pairs.sort_by(|a, b| a.0.total_cmp(&b.0).then((a.1, a.2).cmp(&(b.1, b.2))));
        let (mut track_used, mut point_used) = (vec![false; open.len()], vec![false; here.len()]);
        let mut next: Vec<Ended> = Vec::new();
        for (_, i, j) in pairs {
            if !track_used[i] && !point_used[j] {
                track_used[i] = true;
                point_used[j] = true;
                let mut t = open[i].clone();
                t.points.push(here[j]);
                t.rays.1 = k;
                next.push(t);
            }
        }
        for (t, used) in open.into_iter().zip(track_used) {
            if !used {
                done.push(t);
            }
        }
        for (p, used) in here.iter().zip(point_used) {
            if !used {
                next.push(Ended {
                    points: vec![*p],
                    rays: (k, k),
                    joins: 0,
                });
            }
        }
        open = next;
    }
    done.extend(open);
    done
}

fn runs(hits: &[Option<DVec2>], jump: f64) -> Vec<Vec<DVec2>> {
    let n = hits.len();
    let breaks = |k: usize| -> bool {
        // A break between ray k−1 and ray k.
        match (hits[(k + n - 1) % n], hits[k]) {
            (Some(a), Some(b)) => (a - b).length() > jump,
            _ => true,
        }
    };
    let Some(start) = (0..n).find(|&k| breaks(k)) else {
        // One closed run round the whole fan.
        let mut all: Vec<DVec2> = hits.iter().flatten().copied().collect();
        if let Some(first) = all.first().copied() {
            all.push(first);
        }
        return vec![all];
    };
    let mut out = Vec::new();
    let mut cur: Vec<DVec2> = Vec::new();
    for j in 0..n {
        let k = (start + j) % n;
        if breaks(k) && !cur.is_empty() {
            out.push(std::mem::take(&mut cur));
        }
        if let Some(p) = hits[k] {
            cur.push(p);
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out.retain(|r| r.len() >= 2);
    out
}

/// The pair of a point of the plane as [`Pair::new`] computes it (module `module`, the
/// exact Δy): the analytic twin of [`Blocking::indices`].
///
/// # Errors
/// Those of [`Pair::new`].
pub fn twin_pair(b: &Blocking, module: f64, x: DVec2) -> Result<Pair, GearError> {
    Pair::new(PairSpec {
        module,
        z: b.z,
        x: [x.x, x.y],
        rack: b.rack,
        dy_table: None,
    })
}

/// The lower limit point of wheel `i`'s involute from N_i, per module, by [`Cutting`]: the
/// roll of the junction of involute and fillet, √(|J|² − r_b²), on the blank of the pair's
/// r_a (the twin of [`Indices::rho_l`]; the flank's end's state when the wheel is
/// undercut, where the junction moves up the fillet's cut).
///
/// # Errors
/// Those of [`Cutting::with_tip`].
pub fn twin_rho_l(p: &Pair, i: usize) -> Result<f64, GearError> {
    let m = p.spec.module;
    let c = Cutting::with_tip(m, p.spec.z[i], p.spec.x[i], p.spec.rack, p.ra[i])?;
    let (sa, ca) = (c.rack.alpha.sin(), c.rack.alpha.cos());
    if c.undercut() {
        let st = c.states();
        return Ok(((st.q_j - st.q_p) * ca + c.r() * sa) / m);
    }
    let j = c.junction().0.length();
    let rb = c.rb();
    Ok(((j - rb) * (j + rb)).max(0.0).sqrt() / m)
}

/// The contour of a scene's pair: traced, the scene's point placed, the textbook's choices.
#[derive(Debug, Clone, PartialEq)]
pub struct Study {
    /// The module, m (the rows' lengths).
    pub module: f64,
    /// The traced contour (its hard limits: [`Study::HARD`]).
    pub contour: Contour,
    /// The scene's (x₁, x₂) placed.
    pub placed: Placement,
    /// The criterion the scene's (x₁, x₂) was chosen by (`None`: the scene gives it).
    pub chosen: Option<Criterion>,
    /// Each criterion's choice, or why there is none.
    pub choices: Vec<(Criterion, Result<Choice, BlockingError>)>,
    /// The largest difference of a traced curve's index by the twins from its limit over
    /// the sampled points (s_a/m, ε_α, lengths/m, λ relative), and the points sampled.
    pub twin_check: (f64, usize),
}

impl Study {
    /// The study's hard limits: s_a ≥ 0.25m, ε_α ≥ 1 (with no undercut, no interference).
    pub const HARD: Hard = Hard {
        sa_min: 0.25,
        eps_min: 1.0,
    };

    /// The contour of the pair `spec` with its point placed and the choices: the largest
    /// ε_α, equal sliding on the scene's x_Σ, the greatest x_Σ with s_a ≥ 0.25m — or, of
    /// the kind the scene `chosen` its point by, that criterion as the scene put it.
    ///
    /// A study is a function of the pair and `chosen` alone, and a class's variants mostly
    /// share their gears: the last [`KEPT`] studies are kept ([`Recent`]), so a batch traces
    /// each pair about once.
    ///
    /// # Errors
    /// Those of [`Blocking::new`] and [`Blocking::place`].
    pub fn of(spec: &PairSpec, chosen: Option<Criterion>) -> Result<Self, BlockingError> {
        let key = (*spec, chosen);
        if let Some(study) = STUDIES.find(|k| *k == key) {
            return study;
        }
        let study = Self::trace_of(spec, chosen);
        STUDIES.keep(key, study.clone());
        study
    }

    /// Forget the studies [`Self::of`] keeps (the bench times each run as a fresh process).
    pub fn forget() {
        STUDIES.clear();
    }

    /// [`Self::of`], traced.
    fn trace_of(spec: &PairSpec, chosen: Option<Criterion>) -> Result<Self, BlockingError> {
        let b = Blocking::new(spec.z, spec.rack)?;
        let contour = b.trace(Self::HARD);
        let placed = b.place(DVec2::new(spec.x[0], spec.x[1]), Self::HARD)?;
        // The choices on all cores: each searches the region on its own.
        let choices = [
            Criterion::LargestContactRatio,
            Criterion::EqualSliding {
                x_sum: spec.x_sum(),
            },
            Criterion::GreatestSumWithTip { sa_min: 0.25 },
        ]
        .into_par_iter()
        .map(|c| match chosen {
            Some(asked) if std::mem::discriminant(&asked) == std::mem::discriminant(&c) => asked,
            _ => c,
        })
        .map(|c| (c, b.choose_on(c, Self::HARD, Some(&contour))))
        .collect();
        let twin_check = twin_check(&contour, spec.module, 10);
        Ok(Self {
            module: spec.module,
            contour,
            placed,
            chosen,
            choices,
            twin_check,
        })
    }

    /// The points the rows and the sheet name: the scene's and each choice's, with a tag.
    pub fn points(&self) -> Vec<(&'static str, Indices)> {
        let mut out = vec![("bz", self.placed.indices)];
        for (c, r) in &self.choices {
            if let Ok(ch) = r {
                out.push((criterion_tag(*c), ch.indices));
            }
        }
        out
    }

    /// The rows: at each point, ε_α, s_a1, s_a2, α_w and Δy by the contour's lean formulas
    /// (graphical column) against [`Pair::new`] at that point (analytic).
    pub fn rows(&self) -> Vec<crate::check::Row> {
        use super::rows::row;
        use crate::check::{Method, Symbol};
        let f = Method::Formula;
        let m = self.module;
        let b = &self.contour.blocking;
        let mut out = Vec::new();
        for (tag, ix) in self.points() {
            let Ok(p) = twin_pair(b, m, DVec2::from(ix.x)) else {
                continue;
            };
            out.push(row(
                Symbol::ContactRatio,
                &format!("alpha_{tag}"),
                f,
                ix.eps,
                p.eps,
                p.eps,
            ));
            for i in 0..2 {
                out.push(row(
                    Symbol::ToothThickness,
                    &format!("a{}_{tag}", i + 1),
                    f,
                    ix.sa[i] * m,
                    p.sa[i],
                    m,
                ));
            }
            out.push(row(
                Symbol::EngagementAngle,
                &format!("w_{tag}"),
                f,
                ix.alpha_w.to_degrees(),
                p.alpha_w.to_degrees(),
                p.alpha_w.to_degrees(),
            ));
            out.push(row(Symbol::EqualisingShift, tag, f, ix.dy, p.dy, 1.0));
        }
        out
    }

    /// The notes: the contour traced and checked, the scene's point and the choices.
    pub fn notes(&self) -> Vec<String> {
        let num = |x: f64, s| crate::scale::format_sig(x, s, crate::scale::Lang::En);
        let b = &self.contour.blocking;
        let n: usize = self.contour.curves.iter().map(|c| c.points.len()).sum();
        let mut out = vec![format!(
            "blocking contour z₁ = {}, z₂ = {}: {} curves, {n} points traced along {RAYS} rays (regula falsi to 1e-13 of m; where a curve folds back about a ray, followed along it by Newton's steps to 1e-12); at {} sampled points the twins (Pair::new, Cutting) give the limits to {:.1e}; undercut limit x_min = h_l* − z sin²α/2 with h_l* = {} (the flank's end): x_min1 = {}, x_min2 = {}",
            b.z[0],
            b.z[1],
            self.contour.curves.len(),
            self.twin_check.1,
            self.twin_check.0,
            num(b.hl, 6),
            num(b.x_min(0), 5),
            num(b.x_min(1), 5),
        )];
        let describe = |ix: &Indices| {
            let l = ix.lambda.map_or("—".to_string(), |l| {
                format!("λ₁(B₁) = {}, λ₂(B₂) = {}", num(l[0], 5), num(l[1], 5))
            });
            format!(
                "x₁ = {}, x₂ = {}: α_w = {}°, y = {}, Δy = {}, ε_α = {}, s_a1 = {}m, s_a2 = {}m, {l}",
                num(ix.x[0], 6),
                num(ix.x[1], 6),
                num(ix.alpha_w.to_degrees(), 6),
                num(ix.y, 5),
                num(ix.dy, 5),
                num(ix.eps, 5),
                num(ix.sa[0], 4),
                num(ix.sa[1], 4),
            )
        };
        let outside: Vec<String> = self
            .placed
            .sides
            .iter()
            .filter(|s| s.inside == Some(false))
            .map(|s| level_name(s.kind, s.limit))
            .collect();
        out.push(format!(
            "blocking contour: the scene's point{} {}; {} (s_a ≥ 0.25m, ε_α ≥ 1, no undercut, no interference){}",
            self.chosen.map_or(String::new(), |c| format!(
                ", chosen on the contour by {} (`choose`),",
                criterion_name(c)
            )),
            describe(&self.placed.indices),
            if self.placed.admissible {
                "inside"
            } else {
                "outside"
            },
            if outside.is_empty() {
                String::new()
            } else {
                format!("; on the wrong side of {}", outside.join(", "))
            }
        ));
        for (c, r) in &self.choices {
            out.push(match r {
                Ok(ch) => format!(
                    "blocking contour: {}: {}",
                    criterion_name(*c),
                    describe(&ch.indices)
                ),
                Err(e) => format!("blocking contour: {}: none ({e})", criterion_name(*c)),
            });
        }
        out
    }
}

/// The short label of a point of [`Study::points`] on the drawing (the sheet's lines give
/// its x₁, x₂ and indices under the same name): K the scene's point, ε_{α max}, λ (equal
/// sliding), x_{Σ max}.
pub fn point_label(tag: &str) -> &'static str {
    match tag {
        "bz" => "K",
        "beps" => "ε_{α max}",
        "bsl" => "λ_1 = λ_2",
        _ => "x_{Σ max}",
    }
}

/// A criterion's tag in row subjects.
pub fn criterion_tag(c: Criterion) -> &'static str {
    match c {
        Criterion::LargestContactRatio => "beps",
        Criterion::EqualSliding { .. } => "bsl",
        Criterion::GreatestSumWithTip { .. } => "bsum",
    }
}

/// A criterion in words (the notes).
fn criterion_name(c: Criterion) -> String {
    match c {
        Criterion::LargestContactRatio => "the largest ε_α".into(),
        Criterion::EqualSliding { x_sum } => format!(
            "equal sliding λ₁(B₁) = λ₂(B₂) on x₁ + x₂ = {}",
            crate::scale::format_sig(x_sum, 6, crate::scale::Lang::En)
        ),
        Criterion::GreatestSumWithTip { sa_min } => format!(
            "the greatest x₁ + x₂ with s_a ≥ {}m",
            crate::scale::format_sig(sa_min, 3, crate::scale::Lang::En)
        ),
    }
}

/// A level in words (the notes).
fn level_name(kind: Kind, limit: f64) -> String {
    let l = crate::scale::format_sig(limit, 4, crate::scale::Lang::En);
    match kind {
        Kind::Undercut(i) => format!("x{} ≥ x_min{} = {l}", i + 1, i + 1),
        Kind::Tip(i) => format!("s_a{} ≥ {l}m", i + 1),
        Kind::ContactRatio => format!("ε_α ≥ {l}"),
        Kind::Interference(i) => format!("no interference with the fillet of wheel {}", i + 1),
        Kind::EqualSliding => "λ₁ = λ₂".into(),
    }
}

/// The twins' check of a contour: at up to `per_curve` points of every curve, the index by
/// [`Pair::new`] and [`Cutting`] less its limit (s_a and lengths per m, ε_α, λ relative to
/// max(1, |λ|)); the largest and the number of points.
pub fn twin_check(c: &Contour, module: f64, per_curve: usize) -> (f64, usize) {
    let b = &c.blocking;
    let mut worst = 0.0_f64;
    let mut n = 0;
    for curve in &c.curves {
        let step = (curve.points.len() / per_curve.max(1)).max(1);
        for p in curve.points.iter().step_by(step) {
            if let Some(d) = twin_deviation(b, module, curve.kind, curve.limit, *p) {
                worst = worst.max(d);
                n += 1;
            }
        }
    }
    (worst, n)
}

/// The index of `kind` at `x` by the twins less `limit` (see [`twin_check`]); `None` when a
/// twin has no value there.
pub fn twin_deviation(b: &Blocking, module: f64, kind: Kind, limit: f64, x: DVec2) -> Option<f64> {
    let p = twin_pair(b, module, x).ok()?;
    let m = module;
    Some(match kind {
        Kind::Undercut(i) => {
            // The flank's end at N: the junction state's roll from N is 0.
            let c = Cutting::with_tip(m, b.z[i], [x.x, x.y][i], b.rack, p.ra[i]).ok()?;
            let st = c.states();
            let (sa, ca) = (c.rack.alpha.sin(), c.rack.alpha.cos());
            (((st.q_j - st.q_p) * ca + c.r() * sa) / m).abs()
        }
        Kind::Tip(i) => (p.sa[i] / m - limit).abs(),
        Kind::ContactRatio => (p.eps - limit).abs(),
        Kind::Interference(i) => {
            let near = if i == 0 {
                p.active_ends()[0]
            } else {
                p.g - p.active_ends()[1]
            };
            (near / m - twin_rho_l(&p, i).ok()? - limit).abs()
        }
        Kind::EqualSliding => {
            let ends = p.active_ends();
            let (l1, l2) = (p.sliding(ends[0])[0], p.sliding(ends[1])[1]);
            (l1 - l2 - limit).abs() / l1.abs().max(l2.abs()).max(1.0)
        }
    })
}

/// The words a drawing of the contour needs from the sheet's catalogue.
#[derive(Debug, Clone, Copy)]
pub struct Words<'a> {
    /// "interference" (with a wheel's fillet).
    pub interference: &'a str,
}

/// Clip the segment a–b to the rectangle [0, w] × [0, h] (Liang–Barsky).
fn clip(a: DVec2, b: DVec2, w: f64, h: f64) -> Option<(DVec2, DVec2)> {
    let d = b - a;
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (p, q) in [(-d.x, a.x), (d.x, w - a.x), (-d.y, a.y), (d.y, h - a.y)] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    (t0 <= t1).then(|| (a + d * t0, a + d * t1))
}

/// The polyline `pts` clipped to [0, w] × [0, h]: its pieces inside.
fn clip_polyline(pts: &[DVec2], w: f64, h: f64) -> Vec<Vec<DVec2>> {
    let mut out: Vec<Vec<DVec2>> = Vec::new();
    let mut cur: Vec<DVec2> = Vec::new();
    for s in pts.windows(2) {
        match clip(s[0], s[1], w, h) {
            Some((a, b)) => {
                if cur.last().is_none_or(|l| (*l - a).length() > 1e-9) {
                    if cur.len() >= 2 {
                        out.push(std::mem::take(&mut cur));
                    }
                    cur = vec![a];
                }
                cur.push(b);
            }
            None => {
                if cur.len() >= 2 {
                    out.push(std::mem::take(&mut cur));
                }
                cur.clear();
            }
        }
    }
    if cur.len() >= 2 {
        out.push(cur);
    }
    out
}

/// The room about `p` (figure mm): its distance to the drawn curves (but the level `skip`),
/// to the labels already placed and to the plane's edges.
fn room(
    drawn: &[(usize, Vec<DVec2>)],
    skip: Option<usize>,
    taken: &[DVec2],
    p: DVec2,
    w: f64,
    h: f64,
) -> f64 {
    let others = drawn
        .iter()
        .filter(|(j, _)| Some(*j) != skip)
        .flat_map(|(_, q)| q.iter().step_by(2))
        .chain(taken.iter())
        .map(|q| (*q - p).length())
        .fold(f64::INFINITY, f64::min);
    others.min(p.x).min(p.y).min(w - p.x).min(h - p.y)
}

/// The label of a level in label markup.
fn level_label(kind: Kind, limit: f64, lang: crate::scale::Lang, words: Words<'_>) -> String {
    let l = crate::scale::format_sig(limit, 3, lang);
    match kind {
        Kind::Undercut(i) => format!("x_{{min{}}}", i + 1),
        Kind::Tip(i) if limit == 0.0 => format!("s_{{a{}}} = 0", i + 1),
        Kind::Tip(i) => format!("s_{{a{}}} = {l}m", i + 1),
        Kind::ContactRatio => format!("ε_α = {l}"),
        Kind::Interference(i) => format!("{} {}", words.interference, i + 1),
        Kind::EqualSliding => "λ_1 = λ_2".into(),
    }
}

impl Study {
    /// The drawing of the contour: the axes x₁, x₂ with ticks every 0.2 (0.1 on a small
    /// plane), every traced curve labelled (thin: the limits; dash-dot: the quality
    /// isolines s_a = 0.25m, 0.4m, ε_α = 1.2 and the line of equal sliding), the admissible
    /// region's boundary bold, the scene's point and each choice marked and labelled. Figure
    /// mm, a round 40–120 mm per unit of x (the larger side up to 220 mm).
    pub fn figure(
        &self,
        scale: crate::scale::Scale,
        lang: crate::scale::Lang,
        words: Words<'_>,
    ) -> crate::construct::Figure {
        use crate::construct::{Figure, Item, Label, Role, Step, StepId};
        use crate::geom::Segment;
        let fmt = |x: f64| crate::scale::format_sig(x, 3, lang);
        let c = &self.contour;
        // The plotted plane: the admissible region and the points, 0.3 about them, within
        // the window; rounded out to tenths.
        let mut lo = DVec2::splat(f64::INFINITY);
        let mut hi = DVec2::splat(f64::NEG_INFINITY);
        let mut grow = |p: DVec2| {
            lo = lo.min(p);
            hi = hi.max(p);
        };
        c.boundary.iter().for_each(|p| grow(*p));
        for (_, ix) in self.points() {
            grow(DVec2::from(ix.x));
        }
        if !lo.is_finite() || !hi.is_finite() {
            (lo, hi) = c.blocking.window;
        }
        let (wlo, whi) = c.blocking.window;
        let lo = (lo - DVec2::splat(0.25)).max(wlo);
        let mut hi = (hi + DVec2::splat(0.25)).min(whi);
        let lo = lo.min(hi - DVec2::splat(0.2));
        // Far enough to show where each wheel's tooth points (s_a = 0) beside the region,
        // up to 0.5 more.
        let (lo0, hi0) = (lo, hi);
        for cv in c.curves.iter().filter(|cv| cv.limit == 0.0) {
            for p in &cv.points {
                match cv.kind {
                    Kind::Tip(0) if p.y >= lo0.y && p.y <= hi0.y => hi.x = hi.x.max(p.x + 0.05),
                    Kind::Tip(1) if p.x >= lo0.x && p.x <= hi0.x => hi.y = hi.y.max(p.y + 0.05),
                    _ => {}
                }
            }
        }
        let hi = hi.min(hi0 + DVec2::splat(0.5));
        let lo = (lo.max(wlo) * 10.0).floor() / 10.0;
        let hi = (hi.min(whi) * 10.0).ceil() / 10.0;
        let span = (hi - lo).max(DVec2::splat(0.2));
        // mm per unit: the larger side about 150 mm.
        let per_unit = [40.0, 50.0, 60.0, 80.0, 100.0, 120.0]
            .into_iter()
            .rev()
            .find(|s| span.max_element() * s <= 220.0)
            .unwrap_or(40.0);
        let to = |p: DVec2| (p - lo) * per_unit;
        let (w, h) = (span.x * per_unit, span.y * per_unit);
        let mut steps: Vec<Step> = Vec::new();
        let mut push =
            |note: String, item: Item, role: Role, label: Option<(String, DVec2, DVec2)>| {
                let id = StepId(steps.len() as u32);
                steps.push(Step {
                    id,
                    note,
                    item,
                    role,
                    label: label.map(|(text, anchor, toward)| Label {
                        text,
                        anchor,
                        toward,
                    }),
                    from: Vec::new(),
                    group: 0,
                });
            };
        // The axes along the plane's lower and left edges, with their ticks.
        push(
            "the axis x₁".into(),
            Item::Segment(Segment::new(DVec2::ZERO, DVec2::new(w + 6.0, 0.0))),
            Role::Construction,
            Some((
                "x_1".into(),
                DVec2::new(w + 6.0, 0.0),
                DVec2::new(1.0, -0.6),
            )),
        );
        push(
            "the axis x₂".into(),
            Item::Segment(Segment::new(DVec2::ZERO, DVec2::new(0.0, h + 6.0))),
            Role::Construction,
            Some((
                "x_2".into(),
                DVec2::new(0.0, h + 6.0),
                DVec2::new(-0.6, 1.0),
            )),
        );
        let step = if span.max_element() > 1.0 { 0.2 } else { 0.1 };
        for axis in 0..2 {
            let (a, b) = if axis == 0 {
                (lo.x, hi.x)
            } else {
                (lo.y, hi.y)
            };
            let mut k = (a / step).ceil() as i64;
            while (k as f64) * step <= b + 1e-9 {
                let v = k as f64 * step;
                let at = (v - a) * per_unit;
                let (p, q, toward) = if axis == 0 {
                    (
                        DVec2::new(at, 0.0),
                        DVec2::new(at, -2.0),
                        DVec2::new(0.0, -1.0),
                    )
                } else {
                    (
                        DVec2::new(0.0, at),
                        DVec2::new(-2.0, at),
                        DVec2::new(-1.0, 0.0),
                    )
                };
                let text = if v.abs() < 1e-9 {
                    "0".to_string()
                } else {
                    fmt(v)
                };
                push(
                    format!("a tick of x{} at {v:.1}", axis + 1),
                    Item::Segment(Segment::new(p, q)),
                    Role::Construction,
                    Some((text, q, toward)),
                );
                k += 1;
            }
        }
        // The curves, each labelled once on its longest piece, where the label is farthest
        // from the other curves and labels.
        let levels = levels(&c.blocking.rack, c.blocking.z);
        let mut drawn: Vec<(usize, Vec<DVec2>)> = Vec::new();
        for (k, (kind, limit)) in levels.iter().enumerate() {
            let mut pieces: Vec<Vec<DVec2>> = c
                .curves
                .iter()
                .filter(|cv| cv.kind == *kind && cv.limit == *limit)
                .flat_map(|cv| {
                    let pts: Vec<DVec2> = cv.points.iter().map(|p| to(*p)).collect();
                    clip_polyline(&pts, w, h)
                })
                .collect();
            pieces.sort_by_key(|p| std::cmp::Reverse(p.len()));
            drawn.extend(pieces.into_iter().map(|p| (k, p)));
        }
        let mut taken: Vec<DVec2> = Vec::new();
        let mut first_of = vec![true; levels.len()];
        for (k, piece) in &drawn {
            let (kind, limit) = levels[*k];
            let dashed = matches!((kind, limit), (Kind::Tip(_), l) if l > 0.0)
                || (kind == Kind::ContactRatio && limit > 1.0)
                || kind == Kind::EqualSliding;
            let role = if dashed {
                Role::Axis
            } else {
                Role::Construction
            };
            // Each level's longest piece labelled, and any other piece 15 mm long.
            let long = piece
                .windows(2)
                .map(|s| (s[1] - s[0]).length())
                .sum::<f64>()
                >= 15.0;
            let first = std::mem::replace(&mut first_of[*k], false);
            let label = (first || long).then(|| {
                let room = |p: DVec2| room(&drawn, Some(*k), &taken, p, w, h);
                let n = piece.len() - 1;
                let at = (1..20)
                    .map(|f| n * f / 20)
                    .max_by(|a, b| room(piece[*a]).total_cmp(&room(piece[*b])))
                    .unwrap_or(n / 2);
                let p = piece[at];
                let t = (piece[(at + 1).min(n)] - piece[at.saturating_sub(1)]).normalize_or_zero();
                let mut nrm = DVec2::new(-t.y, t.x);
                // Toward the side with more room.
                if room(p + nrm * 4.0) < room(p - nrm * 4.0) {
                    nrm = -nrm;
                }
                taken.push(p + nrm * 6.0);
                (level_label(kind, limit, lang, words), p, nrm)
            });
            push(
                format!("the curve {}", level_name(kind, limit)),
                Item::Polyline {
                    points: piece.clone(),
                    closed: false,
                },
                role,
                label,
            );
        }
        // The admissible region's boundary, bold.
        let ring: Vec<DVec2> = c
            .boundary
            .iter()
            .chain(c.boundary.first())
            .map(|p| to(*p))
            .collect();
        for piece in clip_polyline(&ring, w, h) {
            push(
                "the admissible region's boundary".into(),
                Item::Polyline {
                    points: piece,
                    closed: false,
                },
                Role::Result,
                None,
            );
        }
        // The points.
        for (tag, ix) in self.points() {
            let at = to(DVec2::from(ix.x));
            if !(at.x >= 0.0 && at.y >= 0.0 && at.x <= w && at.y <= h) {
                continue;
            }
            let text = point_label(tag).to_string();
            // Toward the most room of eight directions, 6 mm out.
            let toward = (0..8)
                .map(|k| {
                    let a = PI / 4.0 * f64::from(k) + PI / 8.0;
                    DVec2::new(a.cos(), a.sin())
                })
                .max_by(|a, b| {
                    room(&drawn, None, &taken, at + *a * 6.0, w, h).total_cmp(&room(
                        &drawn,
                        None,
                        &taken,
                        at + *b * 6.0,
                        w,
                        h,
                    ))
                })
                .unwrap_or(DVec2::new(1.0, 1.0));
            taken.push(at + toward * 6.0);
            push(
                format!("the point {tag}"),
                Item::Point(at),
                Role::Given,
                Some((text, at, toward)),
            );
        }
        Figure {
            title: "blocking contour".into(),
            scale,
            steps,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A circle of radius 1 about (3, 0) seen from the origin: the rays within asin(1/3) of
    /// the x axis cross it twice, the far crossing hidden behind the near one.
    #[test]
    fn a_curve_hidden_behind_itself_is_joined_round_its_folds() {
        let n = 720;
        let centre = DVec2::new(3.0, 0.0);
        let hits: Vec<Vec<DVec2>> = (0..n)
            .map(|k| {
                let a = fan_angle(k, n);
                let d = DVec2::new(a.cos(), a.sin());
                let (b, c) = (d.dot(centre), centre.length_squared() - 1.0);
                let disc = b * b - c;
                if disc < 0.0 || b <= 0.0 {
                    return Vec::new();
                }
                [b - disc.sqrt(), b + disc.sqrt()].map(|t| d * t).to_vec()
            })
            .collect();
        // The arc from a to b the shorter way round, in steps of 0.01 (its points between).
        let bridge = |a: DVec2, b: DVec2| {
            let (ta, tb) = ((a - centre).to_angle(), (b - centre).to_angle());
            let mut turn = tb - ta;
            turn -= (turn / (2.0 * PI)).round() * 2.0 * PI;
            let steps = (turn.abs() / 0.01).ceil() as usize;
            Some(
                (1..steps)
                    .map(|i| centre + DVec2::from_angle(ta + turn * i as f64 / steps as f64))
                    .collect(),
            )
        };
        let whole = whole_runs(&hits, 0.1, &bridge);
        assert_eq!(whole.len(), 1, "{} runs", whole.len());
        let ring = &whole[0];
        assert_eq!(ring.first(), ring.last(), "closed");
        // Every crossing is on it, and it goes round without a jump.
        for p in hits.iter().flatten() {
            assert!(ring.contains(p), "{p:?} left out");
        }
        for s in ring.windows(2) {
            assert!(
                (s[1] - s[0]).length() < 0.1,
                "a jump {:?} → {:?}",
                s[0],
                s[1]
            );
            assert!(((s[0] - centre).length() - 1.0).abs() < 1e-12);
        }
        // Crossed once at most on every ray, the runs are those of the first crossings.
        let near: Vec<Vec<DVec2>> = hits
            .iter()
            .map(|h| h.iter().take(1).copied().collect())
            .collect();
        let first: Vec<Option<DVec2>> = near.iter().map(|h| h.first().copied()).collect();
        assert_eq!(whole_runs(&near, 0.1, &bridge), runs(&first, 0.1));
    }

    /// On PZ3's pair and the shaper's, every crossing of every level on every ray of the fan
    /// is a point of a traced curve: the stretches hidden behind a curve (s_a1 = 0.4m on
    /// 13/21 turns back about a ray, and was cut short there) are traced too, joined to the
    /// rest, and the bridges over the folds lie on their level.
    #[test]
    fn every_crossing_is_on_a_traced_curve() {
        for z in [[13, 21], [13, 30]] {
            let b = Blocking::new(z, BasicRack::GOST_13755).expect("a pair");
            let contour = b.trace(Study::HARD);
            let all = levels(&b.rack, z);
            let mut hidden = 0;
            for k in 0..RAYS {
                let a = fan_angle(k, RAYS);
                let d = DVec2::new(a.cos(), a.sin());
                for ((kind, limit), ts) in all.iter().zip(b.crossings(contour.centre, d, &all)) {
                    hidden += ts.len().saturating_sub(1);
                    // The first crossings are the runs' as before (an isolated one, a
                    // single point, is no curve); those behind them are checked here.
                    for t in ts.into_iter().skip(1) {
                        let p = contour.centre + d * t;
                        assert!(
                            contour.curves.iter().any(|c| c.kind == *kind
                                && c.limit == *limit
                                && c.points.contains(&p)),
                            "z = {z:?}: {kind:?} = {limit} crossed at {p:?} on ray {k}, not traced"
                        );
                    }
                }
            }
            assert!(hidden >= 10, "z = {z:?}: {hidden} hidden crossings");
            let tip = contour
                .curves
                .iter()
                .filter(|c| c.kind == Kind::Tip(0) && c.limit == 0.4)
                .count();
            assert_eq!(tip, 1, "z = {z:?}: s_a1 = 0.4m in {tip} pieces");
            for c in &contour.curves {
                for p in &c.points {
                    let v = b.indices(*p).and_then(|ix| ix.of(c.kind)).expect("a value");
                    assert!(
                        (v - c.limit).abs() < 1e-9,
                        "{:?} = {}: {v} at {p:?}",
                        c.kind,
                        c.limit
                    );
                }
            }
        }
    }
}
