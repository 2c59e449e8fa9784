//! Choosing a drawing's μ the textbook way, before anything is constructed: the drawing's
//! size at a trial μ is predicted from the analytic twin (its extent in SI ÷ μ plus the
//! constant allowance its construction lines and symbols take), and μ moves along the round
//! 1–2–2.5–4–5 series until the drawing fits its field.

use crate::geom::DVec2;
use crate::linkage::{guide_ends, PlanPoses, GUIDE_MARGIN_MM};
use crate::scale::Scale;

/// Room around a drawing for its labels, mm.
pub(super) const LABEL_MARGIN: f64 = 8.0;

/// How a μ is fitted.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Fit {
    /// Keep μ unless the drawing overflows; then raise it (the given or textbook μ first).
    Raise,
    /// The finest round μ at which the drawing takes at most this share of its field.
    Fill(f64),
}

/// A drawing predicted at any μ: the points it draws (SI) and marks drawn a fixed distance
/// from a point (a guide run on past its stroke: SI point, offset in mm), with an allowance,
/// mm on each side, for what is drawn at a constant size (pivot symbols, arrowheads).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Extent {
    lo: DVec2,
    hi: DVec2,
    marks: Vec<(DVec2, DVec2)>,
    allowance: f64,
}

impl Extent {
    /// Nothing yet.
    pub fn empty(allowance: f64) -> Self {
        Self {
            lo: DVec2::splat(f64::INFINITY),
            hi: DVec2::splat(f64::NEG_INFINITY),
            marks: Vec::new(),
            allowance,
        }
    }
    /// Take in a point, SI.
    pub fn add(&mut self, p: DVec2) {
        if p.is_finite() {
            self.lo = self.lo.min(p);
            self.hi = self.hi.max(p);
        }
    }
    /// Take in a mark `offset_mm` from the point `at` (SI).
    pub fn mark(&mut self, at: DVec2, offset_mm: DVec2) {
        if at.is_finite() && offset_mm.is_finite() {
            self.marks.push((at, offset_mm));
        }
    }
    /// The drawing's size at `mu`, mm (its labels not included).
    pub fn size_at(&self, mu: Scale) -> DVec2 {
        if self.lo.x > self.hi.x {
            return DVec2::ZERO;
        }
        let m = mu.value();
        let (mut lo, mut hi) = (self.lo / m, self.hi / m);
        for &(at, off) in &self.marks {
            lo = lo.min(at / m + off);
            hi = hi.max(at / m + off);
        }
        hi - lo + DVec2::splat(2.0 * self.allowance)
    }
    /// The size at `mu` with the labels' margin, mm.
    pub fn labelled_size_at(&self, mu: Scale) -> DVec2 {
        self.size_at(mu) + DVec2::splat(LABEL_MARGIN)
    }
}

/// How much a drawing of size `size` overflows `room` (≤ 1: fits).
pub(super) fn overflow(size: DVec2, room: DVec2) -> f64 {
    (size.x / room.x).max(size.y / room.y)
}

/// The round μ next along the series that draws a drawing overflowing its room `need`
/// times (> 1) small enough to fit.
pub(super) fn raised(s: Scale, need: f64) -> Option<Scale> {
    Scale::round_for(s.value() * need.max(1.0001), 1.0, s.quantity)
}

/// The μ, from `start` along the round series, at which a drawing fits as `fit` asks;
/// `overflow(μ)` tells how much the drawing at μ overflows its room (≤ 1: it fits). `None`
/// when no round μ can be formed.
pub(super) fn fit_scale(start: Scale, fit: Fit, overflow: impl Fn(Scale) -> f64) -> Option<Scale> {
    let mut s = start;
    for _ in 0..8 {
        let need = overflow(s);
        let next = match fit {
            Fit::Raise if need <= 1.0 => return Some(s),
            Fit::Raise => raised(s, need)?,
            Fit::Fill(share) => Scale::round_for(s.value() * need, share, s.quantity)?,
        };
        if next == s {
            break;
        }
        s = next;
    }
    Some(s)
}

/// Allowance of a plan of positions: pivot symbols, slider blocks (its guides are marks).
const PLAN_ALLOWANCE: f64 = 1.0;
/// Allowance of a velocity or acceleration plan: direction lines drawn 6 mm past their
/// points, arrowheads.
const VECTOR_PLAN_ALLOWANCE: f64 = 6.0;

/// The extent of the plan of positions: every point at every position, the fixed points.
pub(super) fn positions_extent(poses: &PlanPoses) -> Extent {
    let mut e = Extent::empty(PLAN_ALLOWANCE);
    for p in &poses.positions {
        for &x in &p.pose.p {
            e.add(x);
        }
    }
    for (at, dir) in guide_ends(poses) {
        e.mark(at, dir * GUIDE_MARGIN_MM);
    }
    e
}

/// The extent of a vector plan drawn through `points` (SI).
pub(super) fn plan_extent(points: &[DVec2]) -> Extent {
    let mut e = Extent::empty(VECTOR_PLAN_ALLOWANCE);
    points.iter().for_each(|&p| e.add(p));
    e
}
