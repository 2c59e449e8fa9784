//! Fitting a drawing's μ to its field, before anything is constructed: the drawing's size at
//! a trial μ is predicted (its extent in SI ÷ μ plus the constant allowance its construction
//! lines and symbols take), and μ moves along the round 1–2–2.5–4–5 series until the drawing
//! fits. The session decides each figure's μ with these rules; a sheet sizes its own views
//! (the structural scheme) and its refusals with them.

use super::Figure;
use crate::geom::DVec2;
use crate::scale::Scale;

/// Room around a drawing for its labels, mm.
pub(crate) const LABEL_MARGIN: f64 = 8.0;

/// A drawing predicted at any μ: the points it draws (SI) and marks drawn a fixed distance
/// from a point (a guide run on past its stroke: SI point, offset in mm), with an allowance,
/// mm on each side, for what is drawn at a constant size (pivot symbols, arrowheads).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Extent {
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
        self.bounds_at(mu).map_or(DVec2::ZERO, |(lo, hi)| {
            hi - lo + DVec2::splat(2.0 * self.allowance)
        })
    }
    /// Where its points and marks lie at `mu`, (min, max) mm (the allowance not included;
    /// `None`: nothing taken in).
    pub fn bounds_at(&self, mu: Scale) -> Option<(DVec2, DVec2)> {
        if self.lo.x > self.hi.x {
            return None;
        }
        let m = mu.value();
        let (mut lo, mut hi) = (self.lo / m, self.hi / m);
        for &(at, off) in &self.marks {
            lo = lo.min(at / m + off);
            hi = hi.max(at / m + off);
        }
        Some((lo, hi))
    }
    /// The size at `mu` with the labels' margin, mm.
    pub fn labelled_size_at(&self, mu: Scale) -> DVec2 {
        self.size_at(mu) + DVec2::splat(LABEL_MARGIN)
    }
}

/// How much a drawing of size `size` overflows `room` (≤ 1: fits).
pub(crate) fn overflow(size: DVec2, room: DVec2) -> f64 {
    (size.x / room.x).max(size.y / room.y)
}

/// The round μ next along the series that draws a drawing overflowing its room `need`
/// times (> 1) small enough to fit.
pub(crate) fn raised(s: Scale, need: f64) -> Option<Scale> {
    Scale::round_for(s.value() * need.max(1.0001), 1.0, s.quantity)
}

/// The μ, from `start` (the given or textbook μ) raised along the round series until the
/// drawing fits: kept unless it overflows; `overflow(μ)` tells how much the drawing at μ
/// overflows its room (≤ 1: it fits). `None` when no round μ can be formed.
pub(crate) fn fit_scale(start: Scale, overflow: impl Fn(Scale) -> f64) -> Option<Scale> {
    let mut s = start;
    for _ in 0..8 {
        let need = overflow(s);
        if need <= 1.0 {
            return Some(s);
        }
        let next = raised(s, need)?;
        if next == s {
            break;
        }
        s = next;
    }
    Some(s)
}

/// Whether every drawing of `figures`, as constructed, fits `room` (mm).
pub(crate) fn fit_room<'a>(figures: impl IntoIterator<Item = &'a Figure>, room: DVec2) -> bool {
    figures.into_iter().all(|f| {
        f.bounds()
            .is_none_or(|(lo, hi)| (hi - lo).cmple(room).all())
    })
}

/// Most finer steps [`finest_fitting`] takes.
const FINER_STEPS: usize = 6;

/// `built`, drawn at `mu`, redrawn at each next finer round μ ([`Scale::finer`]) while the
/// drawing `build` constructs there (`None`: it cannot) still `fits`: the largest drawing
/// that fits its room, each try constructed and measured.
pub(crate) fn finest_fitting<T>(
    mut mu: Scale,
    mut built: T,
    build: impl Fn(Scale) -> Option<T>,
    fits: impl Fn(&T) -> bool,
) -> T {
    for _ in 0..FINER_STEPS {
        let Some((next, t)) = mu.finer().and_then(|next| build(next).map(|t| (next, t))) else {
            break;
        };
        if !fits(&t) {
            break;
        }
        (mu, built) = (next, t);
    }
    built
}
