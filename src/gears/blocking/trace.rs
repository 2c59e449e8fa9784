//! The contour traced: every level of [`levels`] and the admissible region of the hard
//! limits, as the zero sets of their indices on a grid of the plane ([`zero_sets`]). The
//! region is {margin ≥ 0}, the margin the least of the hard limits' indices less their
//! limits: its boundary follows each limit curve where that limit binds, and where the
//! binding limit changes inside a cell the two curves' crossing is solved (Newton's steps on
//! both indices to 10⁻¹²), so the boundary turns exactly at its corners. Every piece of the
//! region in the window is found, whatever its shape, down to the grid's spacing.

use super::indices::twin_margin;
use super::plane::{inside_rings, zero_sets, Fields, Grid};
use super::{
    levels, twin_deviation, Blocking, Curve, Hard, Indices, Kind, DIFF_STEP, NEWTON_TO, ON_LIMIT,
    SPACING,
};
use crate::geom::{plane_newton, DVec2, PlaneNewton};

/// The traced contour.
#[derive(Debug, Clone, PartialEq)]
pub struct Contour {
    /// The problem.
    pub blocking: Blocking,
    /// Every traced curve (a kind and limit may have several pieces).
    pub curves: Vec<Curve>,
    /// The hard limits of `boundary`.
    pub hard: Hard,
    /// The admissible region's boundary: closed rings (each's first point repeated last),
    /// the region on their left; a point is admissible when inside an odd number of them
    /// ([`Contour::contains`]). Empty when no point of the window is admissible.
    pub boundary: Vec<Vec<DVec2>>,
    /// The grid's spacing.
    pub spacing: f64,
}

impl Contour {
    /// `p` inside the traced region (a point on its boundary may fall either way).
    pub fn contains(&self, p: DVec2) -> bool {
        inside_rings(&self.boundary, p)
    }
}

/// The functions the grid traces: the levels' indices less their limits, then each hard
/// limit set's margin.
struct Plane<'a> {
    b: &'a Blocking,
    levels: Vec<(Kind, f64)>,
    hards: Vec<Hard>,
    /// α_w and tg α_w of each diagonal i + j of the grid (x₁ + x₂ is constant along it).
    operating: Vec<Option<(f64, f64)>>,
}

impl Plane<'_> {
    fn value(&self, ix: &Indices, k: usize) -> Option<f64> {
        match self.levels.get(k) {
            Some((kind, limit)) => Some(ix.of(*kind)? - limit),
            None => self.b.margin_of(ix, self.hards[k - self.levels.len()]),
        }
    }
}

impl Fields for Plane<'_> {
    fn count(&self) -> usize {
        self.levels.len() + self.hards.len()
    }

    fn row(&self, grid: &Grid, j: usize, out: &mut [f64]) {
        let c = self.count();
        for i in 0..=grid.n[0] {
            let slot = &mut out[i * c..(i + 1) * c];
            let ix =
                self.operating[i + j].and_then(|(a, t)| self.b.indices_with(grid.node(i, j), a, t));
            for (k, v) in slot.iter_mut().enumerate() {
                *v = ix
                    .as_ref()
                    .and_then(|ix| self.value(ix, k))
                    .unwrap_or(f64::NAN);
            }
        }
    }

    fn at(&self, k: usize, p: DVec2) -> Option<f64> {
        self.value(&self.b.indices(p)?, k)
    }
}

impl Blocking {
    /// The grid over the window.
    pub(super) fn grid(&self) -> Grid {
        Grid::over(self.window.0, self.window.1, SPACING)
    }

    /// The zero sets of `levels` (open) and of the margins of `hards` (closed) on the grid.
    fn zero_sets(&self, levels: Vec<(Kind, f64)>, hards: Vec<Hard>) -> Vec<Vec<Vec<DVec2>>> {
        let grid = self.grid();
        let lo = grid.lo.x + grid.lo.y;
        let operating = (0..=grid.n[0] + grid.n[1])
            .map(|d| self.operating(lo + d as f64 * grid.h))
            .collect();
        let mut closed = vec![false; levels.len()];
        closed.extend(hards.iter().map(|_| true));
        let plane = Plane {
            b: self,
            levels,
            hards,
            operating,
        };
        zero_sets(&grid, &plane, &closed)
    }

    /// Trace every level of [`levels`] and the admissible region's boundary of `hard`.
    pub fn trace(&self, hard: Hard) -> Contour {
        let levels = levels(&self.rack, self.z);
        let mut sets = self.zero_sets(levels.clone(), vec![hard]);
        let rings = sets.pop().unwrap_or_default();
        let curves = levels
            .iter()
            .zip(sets)
            .flat_map(|((kind, limit), lines)| {
                lines.into_iter().map(|points| Curve {
                    kind: *kind,
                    limit: *limit,
                    points,
                })
            })
            .collect();
        self.contour(curves, rings, hard)
    }

    /// The admissible region of `hard` alone (no curves).
    pub fn region(&self, hard: Hard) -> Contour {
        let rings = self
            .zero_sets(Vec::new(), vec![hard])
            .pop()
            .unwrap_or_default();
        self.contour(Vec::new(), rings, hard)
    }

    fn contour(&self, curves: Vec<Curve>, rings: Vec<Vec<DVec2>>, hard: Hard) -> Contour {
        let h = self.grid().h;
        Contour {
            blocking: *self,
            curves,
            hard,
            boundary: rings.iter().map(|r| self.cornered(r, hard, h)).collect(),
            spacing: h,
        }
    }

    /// The hard limit a point of the region's boundary lies on (the least index less its
    /// limit, within [`ON_LIMIT`] of 0); `None` off every limit (the window's edge).
    fn binding(&self, p: DVec2, hard: Hard) -> Option<usize> {
        let ix = self.indices(p)?;
        let (k, v) = self
            .hard_levels(hard)
            .iter()
            .enumerate()
            .filter_map(|(k, (kind, limit))| Some((k, ix.of(*kind)? - limit)))
            .min_by(|a, b| a.1.total_cmp(&b.1))?;
        (v <= ON_LIMIT).then_some(k)
    }

    /// The ring `ring` of the region of `hard` with its corners: between two consecutive
    /// points on different limits, the limits' crossing.
    fn cornered(&self, ring: &[DVec2], hard: Hard, h: f64) -> Vec<DVec2> {
        let tags: Vec<Option<usize>> = ring.iter().map(|p| self.binding(*p, hard)).collect();
        let mut out = Vec::with_capacity(ring.len() + 8);
        for (w, p) in ring.iter().enumerate() {
            if w > 0 {
                if let (Some(a), Some(b)) = (tags[w - 1], tags[w]) {
                    if a != b {
                        out.extend(self.corners(hard, [a, b], [ring[w - 1], *p], h));
                    }
                }
            }
            out.push(*p);
        }
        out
    }

    /// The corners between `ends[0]` on the hard limit `at[0]` and `ends[1]` on `at[1]`:
    /// their crossing, or when a third limit cuts it off, the two crossings with that one;
    /// none when they do not settle within a cell's reach or inside the window.
    fn corners(&self, hard: Hard, at: [usize; 2], ends: [DVec2; 2], h: f64) -> Vec<DVec2> {
        let hl = self.hard_levels(hard);
        // Within a cell's reach of both ends, and inside the window (a corner beyond it is
        // cut off by the window's edge: the chord stays).
        let (lo, hi) = self.window;
        let near = |p: DVec2| {
            ends.iter().all(|e| (*e - p).length() <= 2.0 * h)
                && p.cmpge(lo).all()
                && p.cmple(hi).all()
        };
        let solve = |a: usize, b: usize| {
            self.crossing(hl[a], hl[b], (ends[0] + ends[1]) * 0.5)
                .filter(|p| near(*p))
        };
        let Some(c) = solve(at[0], at[1]) else {
            return Vec::new();
        };
        match self.binding(c, hard) {
            Some(k) if k == at[0] || k == at[1] => vec![c],
            Some(_) | None => {
                // A third limit binds there: the corners with it, when both are on the region.
                let Some(third) = self.least(c, hard) else {
                    return Vec::new();
                };
                let pair = [solve(at[0], third), solve(third, at[1])];
                match pair {
                    [Some(p), Some(q)]
                        if self.margin(p, hard).is_some_and(|m| m >= -ON_LIMIT)
                            && self.margin(q, hard).is_some_and(|m| m >= -ON_LIMIT) =>
                    {
                        vec![p, q]
                    }
                    _ => Vec::new(),
                }
            }
        }
    }

    /// The hard limit with the least index less its limit at `p`.
    fn least(&self, p: DVec2, hard: Hard) -> Option<usize> {
        let ix = self.indices(p)?;
        self.hard_levels(hard)
            .iter()
            .enumerate()
            .filter_map(|(k, (kind, limit))| Some((k, ix.of(*kind)? - limit)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(k, _)| k)
    }

    /// The crossing of the levels `a` and `b` nearest `from`: Newton's steps on both indices
    /// (central differences), to 10⁻¹² of each; `None` when they are parallel there, leave
    /// the formulas' domain or do not settle in 30 steps.
    pub(super) fn crossing(&self, a: (Kind, f64), b: (Kind, f64), from: DVec2) -> Option<DVec2> {
        let f = |p: DVec2| {
            let ix = self.indices(p)?;
            Some(DVec2::new(ix.of(a.0)? - a.1, ix.of(b.0)? - b.1))
        };
        match plane_newton(f, from, (DIFF_STEP, NEWTON_TO), 30, 1e-9) {
            PlaneNewton::Settled(p) => Some(p),
            _ => None,
        }
    }
}

/// The twins' check of a contour: at up to `per_curve` points of every curve, the index by
/// [`crate::gears::GearPair::new`] and [`crate::gears::Cutting`] off its limit (s_a and lengths
/// per m, ε_α, λ relative to max(1, |λ|)), and at as many points of each ring of the
/// region's boundary on a limit (not the window's edge), the twins' least margin off 0; the
/// largest and the number of points.
pub fn twin_check(c: &Contour, module: f64, per_curve: usize) -> (f64, usize) {
    let b = &c.blocking;
    let mut worst = 0.0_f64;
    let mut n = 0;
    let every = |len: usize| (len / per_curve.max(1)).max(1);
    for curve in &c.curves {
        for p in curve.points.iter().step_by(every(curve.points.len())) {
            if let Some(d) = twin_deviation(b, module, curve.kind, curve.limit, *p) {
                worst = worst.max(d);
                n += 1;
            }
        }
    }
    for ring in &c.boundary {
        for p in ring.iter().step_by(every(ring.len())) {
            if b.binding(*p, c.hard).is_none() {
                continue;
            }
            if let Some(m) = twin_margin(b, module, c.hard, *p) {
                worst = worst.max(m.abs());
                n += 1;
            }
        }
    }
    (worst, n)
}
