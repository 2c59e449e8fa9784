//! A point placed on the contour, and the textbook's choices of x₁, x₂ inside it: the
//! largest ε_α, equal sliding on a given x_Σ, the greatest x_Σ with a tip thickness — each
//! searched over the whole admissible region (every piece of it the grid finds), and each
//! kept [`CHOICE_MARGIN`] inside every hard limit: a supremum on a limit (the largest ε_α
//! lies where the mate's tip reaches N₁, λ₁(B₁) = −∞) is a pair that does not work.

use super::plane::BRACKET_TO;
use super::trace::Contour;
use super::{
    levels, twin_value, Blocking, BlockingError, Criterion, Hard, Indices, Kind, DIFF_STEP,
    NEWTON_TO, ON_LIMIT,
};
use crate::geom::{golden_max, illinois, level_newton, plane_newton, DVec2, PlaneNewton};

/// How far inside every hard limit a choice lies, in the index's own unit: s_a ≥ (s_a,min +
/// 0.05)m, ε_α ≥ ε_min + 0.05, x ≥ x_min + 0.05, N_iB_i ≥ ρ_l,i + 0.05m.
pub const CHOICE_MARGIN: f64 = 0.05;

/// A chosen point.
#[derive(Debug, Clone, PartialEq)]
pub struct Choice {
    /// The criterion.
    pub criterion: Criterion,
    /// Its indices.
    pub indices: Indices,
    /// The hard limits (each [`CHOICE_MARGIN`] inside) it lies on, and λ₁ = λ₂ when it
    /// holds there.
    pub on: Vec<(Kind, f64)>,
}

/// Where a point lies against one curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveSide {
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
pub struct OnContour {
    /// Its indices.
    pub indices: Indices,
    /// Against every limit the contour draws.
    pub sides: Vec<CurveSide>,
    /// Inside the admissible region of the contour's hard limits.
    pub admissible: bool,
}

impl Blocking {
    /// Place the point `x` on the contour: its indices, its side of every level, whether it
    /// meets `hard`.
    ///
    /// # Errors
    /// [`BlockingError::NotFinite`], [`BlockingError::Domain`].
    pub fn place(&self, x: DVec2, hard: Hard) -> Result<OnContour, BlockingError> {
        if !(x.x.is_finite() && x.y.is_finite()) {
            return Err(BlockingError::NotFinite { x1: x.x, x2: x.y });
        }
        let indices = self
            .indices(x)
            .ok_or(BlockingError::Domain { x1: x.x, x2: x.y })?;
        let sides = levels(&self.rack, self.z)
            .into_iter()
            .filter_map(|(kind, limit)| {
                let value = indices.of(kind)?;
                Some(CurveSide {
                    kind,
                    limit,
                    value,
                    inside: kind.good_above().map(|_| value >= limit),
                })
            })
            .collect();
        Ok(OnContour {
            indices,
            sides,
            admissible: self.margin(x, hard).is_some_and(|m| m >= 0.0),
        })
    }

    /// The hard limits a choice by `criterion` meets: `hard` (with the criterion's s_a,min),
    /// each [`CHOICE_MARGIN`] inside.
    pub fn choice_hard(criterion: Criterion, hard: Hard) -> Hard {
        let sa_min = match criterion {
            Criterion::GreatestSumWithTip { sa_min } => sa_min,
            _ => hard.sa_min,
        };
        Hard {
            sa_min,
            inset: CHOICE_MARGIN,
            ..hard
        }
    }

    /// The point `criterion` chooses inside the admissible region of `hard`, searched over
    /// the whole region, [`CHOICE_MARGIN`] inside every limit.
    ///
    /// # Errors
    /// [`BlockingError::Empty`] when no point is that far inside, [`BlockingError::LineOutside`]
    /// when the line of [`Criterion::EqualSliding`] misses that region.
    pub fn choose(&self, criterion: Criterion, hard: Hard) -> Result<Choice, BlockingError> {
        self.choose_in(criterion, &self.region(Self::choice_hard(criterion, hard)))
    }

    /// [`Self::choose`] in `region`, the region of [`Self::choice_hard`] traced.
    pub fn choose_in(
        &self,
        criterion: Criterion,
        region: &Contour,
    ) -> Result<Choice, BlockingError> {
        let hard = region.hard;
        let empty = || {
            let (lo, hi) = self.window;
            BlockingError::Empty {
                x1: [lo.x, hi.x],
                x2: [lo.y, hi.y],
                hard,
            }
        };
        if region.boundary.is_empty() {
            return Err(empty());
        }
        let x = match criterion {
            Criterion::LargestContactRatio => self.maximise(region, |ix| ix.eps),
            Criterion::GreatestSumWithTip { .. } => self.maximise(region, |ix| ix.x[0] + ix.x[1]),
            Criterion::EqualSliding { x_sum } => Some(self.equal_sliding(region, x_sum)?),
        };
        let x = x.ok_or_else(empty)?;
        let indices = self
            .indices(x)
            .ok_or(BlockingError::Domain { x1: x.x, x2: x.y })?;
        let mut on: Vec<(Kind, f64)> = self
            .hard_levels(hard)
            .into_iter()
            .filter(|(k, l)| indices.of(*k).is_some_and(|v| (v - l).abs() <= ON_LIMIT))
            .collect();
        if matches!(criterion, Criterion::EqualSliding { .. })
            && indices
                .lambda
                .is_some_and(|l| (l[0] - l[1]).abs() <= ON_LIMIT)
        {
            on.push((Kind::EqualSliding, 0.0));
        }
        Ok(Choice {
            criterion,
            indices,
            on,
        })
    }

    /// The largest `obj` over `region`: the best of its boundary's points, each refined along
    /// the boundary to its neighbours (golden sections, the boundary found across the chord
    /// by bracketing the margin), and of a grid twice as coarse inside it, refined by golden
    /// sections along x₁ and x₂ in turn. `None` when no point has a value.
    fn maximise(&self, region: &Contour, obj: impl Fn(&Indices) -> f64) -> Option<DVec2> {
        let hard = region.hard;
        let h = region.spacing;
        // The objective where the margin is ≥ 0 (a boundary point's is, to its bracket's
        // rounding or its corner's Newton steps).
        let value = |p: DVec2| {
            self.indices(p)
                .filter(|ix| self.margin_of(ix, hard).is_some_and(|m| m >= -NEWTON_TO))
                .map_or(f64::NEG_INFINITY, |ix| obj(&ix))
        };
        let mut best = (f64::NEG_INFINITY, DVec2::ZERO);
        let mut keep = |v: f64, p: DVec2| {
            if v > best.0 {
                best = (v, p);
            }
        };
        // The boundary's best point, and the arcs to its neighbours.
        let mut at: Option<(usize, usize, f64)> = None;
        for (r, ring) in region.boundary.iter().enumerate() {
            for (w, p) in ring.iter().enumerate() {
                let v = value(*p);
                if at.is_none_or(|a| v > a.2) {
                    at = Some((r, w, v));
                }
            }
        }
        if let Some((r, w, v)) = at {
            let ring = &region.boundary[r];
            keep(v, ring[w]);
            // A ring repeats its first point last.
            let n = ring.len().saturating_sub(1).max(1);
            let (prev, next) = (ring[(w + n - 1) % n], ring[(w + 1) % n]);
            for q in [prev, next] {
                let (a, b) = (ring[w], q);
                let on_arc = |s: f64| self.across(a + (b - a) * s, b - a, hard, h);
                let (v, s) = golden_max(0.0, 1.0, |s| value(on_arc(s)));
                keep(v, on_arc(s));
            }
        }
        // Inside: the grid twice as coarse over the region's extent, then the best refined.
        let (lo, hi) = region
            .boundary
            .iter()
            .flatten()
            .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(l, u), p| {
                (l.min(*p), u.max(*p))
            });
        let step = 2.0 * h;
        let n = ((hi - lo) / step).ceil();
        let mut inner = (f64::NEG_INFINITY, lo);
        for i in 0..=n.x as usize {
            for j in 0..=n.y as usize {
                let p = lo + DVec2::new(i as f64, j as f64) * step;
                let v = value(p);
                if v > inner.0 {
                    inner = (v, p);
                }
            }
        }
        if inner.0 > at.map_or(f64::NEG_INFINITY, |a| a.2) {
            let (mut p, mut w) = (inner.1, step);
            for _ in 0..6 {
                for axis in [DVec2::X, DVec2::Y] {
                    let (v, t) = golden_max(-w, w, |t| value(p + axis * t));
                    if v >= value(p) {
                        p += axis * t;
                    }
                }
                w *= 0.25;
            }
            keep(value(p), p);
        }
        best.0.is_finite().then_some(best.1)
    }

    /// The region's boundary across the chord `d` at `c`: the margin of `hard` bracketed along
    /// the chord's normal within `h` (its inside end); `c` itself where the margin keeps its
    /// sign there (the window's edge, straight).
    fn across(&self, c: DVec2, d: DVec2, hard: Hard, h: f64) -> DVec2 {
        let nrm = DVec2::new(-d.y, d.x).normalize_or_zero();
        let f = |t: f64| Some(self.margin(c + nrm * t, hard).unwrap_or(-1.0));
        let (Some(a), Some(b)) = (f(-h), f(h)) else {
            return c;
        };
        if (a >= 0.0) == (b >= 0.0) {
            return c;
        }
        match illinois(f, (-h, a), (h, b), |u, v| (u - v).abs() <= BRACKET_TO) {
            Some([(lo, f_lo), (hi, _)]) => c + nrm * if f_lo >= 0.0 { lo } else { hi },
            None => c,
        }
    }

    /// The equal-sliding point of the line x₁ + x₂ = `x_sum` in `region` (see
    /// [`Criterion::EqualSliding`]): of the roots of λ₁ − λ₂ on the line's stretches inside
    /// the region, the one deepest inside; with none, the stretches' end of the least
    /// |λ₁ − λ₂|.
    fn equal_sliding(&self, region: &Contour, x_sum: f64) -> Result<DVec2, BlockingError> {
        let hard = region.hard;
        if !x_sum.is_finite() {
            return Err(BlockingError::NotFinite {
                x1: x_sum,
                x2: x_sum,
            });
        }
        let (lo, hi) = self.window;
        let a = lo.x.max(x_sum - hi.y);
        let b = hi.x.min(x_sum - lo.y);
        let outside = |m: f64| BlockingError::LineOutside {
            x_sum,
            inset: hard.inset,
            deepest: m + hard.inset,
        };
        if a.partial_cmp(&b) != Some(std::cmp::Ordering::Less) {
            return Err(outside(f64::NEG_INFINITY));
        }
        let on = |x1: f64| DVec2::new(x1, x_sum - x1);
        let margin = |x1: f64| Some(self.margin(on(x1), hard).unwrap_or(-1.0));
        let d = |x1: f64| self.indices(on(x1))?.of(Kind::EqualSliding);
        // The line sampled at a quarter of the grid's spacing.
        let n = ((b - a) / (0.25 * region.spacing)).ceil().max(200.0) as usize;
        let xs: Vec<(f64, f64)> = (0..=n)
            .map(|k| {
                let x = a + (b - a) * k as f64 / n as f64;
                (x, margin(x).unwrap_or(-1.0))
            })
            .collect();
        let deepest = xs.iter().map(|s| s.1).fold(f64::NEG_INFINITY, f64::max);
        if deepest < 0.0 {
            return Err(outside(deepest));
        }
        // The ends of each stretch, bracketed on its inside; the roots inside it.
        let end = |p: (f64, f64), q: (f64, f64)| match illinois(margin, p, q, |u, v| {
            (u - v).abs() <= BRACKET_TO
        }) {
            Some([(x, fx), (y, _)]) => {
                if fx >= 0.0 {
                    x
                } else {
                    y
                }
            }
            None => p.0,
        };
        let mut roots: Vec<(f64, f64)> = Vec::new();
        let mut ends: Vec<f64> = Vec::new();
        for k in 0..n {
            let (p, q) = (xs[k], xs[k + 1]);
            if (p.1 >= 0.0) != (q.1 >= 0.0) {
                ends.push(end(p, q));
            }
            if p.1 >= 0.0 && q.1 >= 0.0 {
                if let (Some(u), Some(v)) = (d(p.0), d(q.0)) {
                    if (u >= 0.0) != (v >= 0.0) {
                        let r = illinois(d, (p.0, u), (q.0, v), |s, t| (s - t).abs() <= BRACKET_TO);
                        if let Some([(x, fx), (y, fy)]) = r {
                            let x1 = if fx.abs() <= fy.abs() { x } else { y };
                            roots.push((x1, margin(x1).unwrap_or(-1.0)));
                        }
                    }
                }
            }
        }
        if xs[0].1 >= 0.0 {
            ends.push(xs[0].0);
        }
        if xs[n].1 >= 0.0 {
            ends.push(xs[n].0);
        }
        let x1 = match roots
            .iter()
            .filter(|r| r.1 >= 0.0)
            .max_by(|p, q| p.1.total_cmp(&q.1))
        {
            Some(r) => r.0,
            None => ends
                .iter()
                .copied()
                .filter(|x| margin(*x).is_some_and(|m| m >= 0.0))
                .min_by(|p, q| {
                    let f = |x: f64| d(x).map_or(f64::INFINITY, f64::abs);
                    f(*p).total_cmp(&f(*q))
                })
                .ok_or_else(|| outside(deepest))?,
        };
        Ok(on(x1))
    }
}

impl Choice {
    /// The choice's x by the twins ([`twin_value`]: [`crate::gears::GearPair::new`],
    /// [`crate::gears::Cutting`]), from the limits it lies on and, for equal sliding, its
    /// line, each solved by Newton's steps on the twins' indices (central differences) from
    /// the choice: two limits, their crossing; one, its point on its normal through the
    /// choice; on the line, its point on the line. `None` when it lies on no limit (an
    /// inner maximum) or the twins do not settle to 10⁻¹⁰.
    pub fn twin_x(&self, b: &Blocking, module: f64) -> Option<DVec2> {
        let x0 = DVec2::from(self.indices.x);
        let f = |k: usize, p: DVec2| {
            let (kind, limit) = self.on[k];
            twin_value(b, module, kind, limit, p)
        };
        let line = match self.criterion {
            Criterion::EqualSliding { .. } => Some(DVec2::new(1.0, -1.0)),
            _ => None,
        };
        // The equations solved: on the line, the last of `on` (λ₁ = λ₂ when it holds).
        let solved: Vec<usize> = match (self.on.len(), line) {
            (0, _) => return None,
            (k, Some(_)) => vec![k - 1],
            (1, None) => vec![0],
            (_, None) => vec![0, 1],
        };
        let steps = (DIFF_STEP, NEWTON_TO);
        let end = match solved[..] {
            [k] => level_newton(|p| f(k, p), x0, line, steps, 30),
            [a, b] => plane_newton(|p| Some(DVec2::new(f(a, p)?, f(b, p)?)), x0, steps, 30, 0.0),
            _ => return None,
        };
        let (PlaneNewton::Settled(p) | PlaneNewton::Unsettled(p)) = end else {
            return None;
        };
        let settled = solved
            .iter()
            .all(|k| f(*k, p).is_some_and(|v| v.abs() <= 1e-10));
        (settled && (p - x0).length() < 1e-3).then_some(p)
    }
}
