//! Friction in the pairs of a mechanism's force analysis (seed 001, lectures 10–11): the
//! friction loads — in a sliding pair the force f·|N| along the guide against the relative
//! sliding, which turns the total reaction from the normal by exactly φ = arctg f; in a
//! revolute pair the couple ρ·|R| against the relative rotation, ρ = f·r the friction
//! circle's radius, which puts the reaction tangent to that circle — depend on the reactions
//! they change.
//!
//! The textbook finds them by successive approximations: the reactions without friction give
//! the friction loads, the analysis is repeated with them, and so on. That converges slowly or
//! not at all when the friction is large, although the equations have a solution. Here each
//! route ([`settle`]) makes the same analysis with one rubbing pair's friction load at a time
//! (its own solves: the force polygons on the drawing, or the twin's linear solve), so that its
//! reactions are an affine function of the friction loads' magnitudes, and solves the friction
//! equations m_k = |R_k(m)| for those magnitudes by Newton's method continued in the size of
//! the friction ([`reduced`]); the analysis with the friction loads found is then carried out
//! once more and must reproduce its magnitudes (otherwise the affine model is re-anchored
//! there and the step repeated). A lock is called only when the equations have no solution:
//! the reactions grow without bound as the friction rises to some f* ≤ f
//! ([`ForceError::SelfLocking`] names the position, the group and f*).
//!
//! The friction's power is always negative, so the balancing moment's power M_bal·ω₁ grows by
//! exactly the power lost in the pairs.

pub mod reduced;

use super::diagnose::{group_of, order_of};
use super::loads::{Load, LoadKind, PositionMotion};
pub use super::spec::PairFriction;
use super::twin::{Pair, PairKind, Reaction};
use super::ForceError;
use crate::geom::DVec2;
use crate::linkage::Program;

impl PairFriction {
    /// The friction circle's radius ρ = f·r of the journal at point `k`.
    fn rho(&self, prog: &Program, k: usize) -> f64 {
        let r = self
            .radii
            .iter()
            .find(|(name, _)| prog.index(name) == Some(k))
            .map_or(self.radius, |(_, r)| *r);
        self.f * r
    }
}

/// What one route needs to place the friction loads: the links' frame directions and
/// origins, and the motion.
pub struct PairMotion<'a> {
    /// The mechanism.
    pub prog: &'a Program,
    /// Unit frame direction of every link.
    pub dir: Vec<DVec2>,
    /// A point of every link (its frame origin), by link number.
    pub origin: &'a [usize],
    /// The motion (velocities and ω).
    pub motion: &'a PositionMotion,
}

impl PairMotion<'_> {
    /// The velocity of link `l`'s point at `x` (m), m/s: the frame is at rest.
    fn velocity(&self, l: usize, x: DVec2) -> DVec2 {
        if l == 0 {
            return DVec2::ZERO;
        }
        let o = self.origin[l];
        self.motion.v[o] + (x - self.motion.p[o]).perp() * self.omega(l)
    }

    /// ω of link `l`, rad/s (the frame's is zero).
    fn omega(&self, l: usize) -> f64 {
        if l == 0 {
            0.0
        } else {
            self.motion.omega.get(l).copied().unwrap_or(0.0)
        }
    }

    /// A relative rotation (rad/s) or sliding (m/s) too small to tell from rounding against
    /// the motion's largest ω or velocity counts as none: the pair does not slide and its
    /// friction is not determined, so none is applied.
    fn slides(&self, rate: f64, of: &[f64]) -> bool {
        let big = of.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        rate.abs() > RELATIVE_REST * big
    }
}

/// A relative rate below this fraction of the largest is rest.
const RELATIVE_REST: f64 = 1e-9;

/// The friction loads of `reactions` (each acting on its pair's `to` link, the opposite on
/// `from`; nothing on the frame), of the size f·|R| or ρ·|R| of each reaction.
pub fn friction_loads(fr: &PairFriction, k: &PairMotion<'_>, reactions: &[Reaction]) -> Vec<Load> {
    let sizes: Vec<f64> = reactions.iter().map(|r| r.force.length()).collect();
    friction_loads_of(fr, k, reactions, &sizes)
}

/// The friction loads of the pairs of `reactions` for reaction magnitudes `sizes` (N, by
/// reaction): the pairs' kinds, senses and a sliding pair's point from `reactions`, the loads'
/// size from `sizes`. A pair at relative rest, a frictionless journal or a zero size has none.
pub fn friction_loads_of(
    fr: &PairFriction,
    k: &PairMotion<'_>,
    reactions: &[Reaction],
    sizes: &[f64],
) -> Vec<Load> {
    let mut out = Vec::new();
    let mut push = |l: usize, load: Load| {
        if l != 0 {
            out.push(load);
        }
    };
    for (r, &size) in reactions.iter().zip(sizes) {
        let (from, to) = (r.pair.from, r.pair.to);
        if size == 0.0 {
            continue;
        }
        let name = |l: usize, other: usize| format!("M_{{тр{other}-{l}}}");
        match r.pair.kind {
            PairKind::Revolute(x) => {
                let w_rel = k.omega(to) - k.omega(from);
                let rho = fr.rho(k.prog, x);
                if !k.slides(w_rel, &k.motion.omega) || rho == 0.0 {
                    continue;
                }
                let m = -w_rel.signum() * rho * size;
                push(to, Load::couple(to, LoadKind::Friction, name(to, from), m));
                push(
                    from,
                    Load::couple(from, LoadKind::Friction, name(from, to), -m),
                );
            }
            PairKind::Prismatic {
                reference,
                dir_link,
            } => {
                let u = k.dir[dir_link];
                let x = k.motion.p[reference];
                let v_rel = (k.velocity(to, x) - k.velocity(from, x)).dot(u);
                let speeds: Vec<f64> = k.motion.v.iter().map(|v| v.length()).collect();
                if !k.slides(v_rel, &speeds) {
                    continue;
                }
                let f = u * (-v_rel.signum() * fr.f * size);
                let shift = u * r.offset.unwrap_or(0.0);
                let force = |l: usize, other: usize, f: DVec2| Load {
                    shift,
                    ..Load::force(l, LoadKind::Friction, sliding_name(other, l), f, reference)
                };
                push(to, force(to, from, f));
                push(from, force(from, to, -f));
            }
        }
    }
    out
}

/// The name of the sliding friction force of link `from` on link `to`: `F_{тр0-3}`.
fn sliding_name(from: usize, to: usize) -> String {
    format!("F_{{тр{from}-{to}}}")
}

/// The sliding friction force among `loads` that the pair's `from` link exerts on its `to`
/// link (zero when there is none: a revolute pair, a pair at rest, no friction): with the
/// normal reaction N it makes the total reaction N + F, turned from the normal by φ.
pub fn sliding_friction(loads: &[Load], pair: Pair) -> DVec2 {
    if !matches!(pair.kind, PairKind::Prismatic { .. }) {
        return DVec2::ZERO;
    }
    let name = sliding_name(pair.from, pair.to);
    loads
        .iter()
        .filter(|l| l.kind == LoadKind::Friction && l.link == pair.to && l.name == name)
        .map(|l| l.force)
        .sum()
}

/// The power of the friction loads, W (never positive).
pub fn friction_power(loads: &[Load], k: &PairMotion<'_>) -> f64 {
    loads
        .iter()
        .map(|l| {
            let x = k.motion.p[l.at] + l.shift;
            l.force.dot(k.velocity(l.link, x)) + l.moment * k.omega(l.link)
        })
        .sum()
}

/// One route's analysis with friction: its solution, the friction loads it carries and the
/// number of analyses (polygons drawn, or linear solves) it took.
#[derive(Debug, Clone, PartialEq)]
pub struct Settled<T> {
    /// The analysis with the friction loads.
    pub solution: T,
    /// The friction loads.
    pub loads: Vec<Load>,
    /// How many analyses the route carried out.
    pub solves: usize,
}

/// What a route's friction equations are about, for its diagnoses.
pub struct FrictionRoute<'a> {
    /// The mechanism.
    pub prog: &'a Program,
    /// The position's label.
    pub label: &'a str,
    /// The route's name (`the force polygons`, `the linear solve`).
    pub name: &'a str,
    /// The coefficient of friction asked for.
    pub f: f64,
    /// The settling tolerance relative to the largest reaction.
    pub relative: f64,
    /// The settling tolerance in newtons (a drawing's resolution), N.
    pub absolute: f64,
}

impl FrictionRoute<'_> {
    /// The lock of `pair`'s group past the fraction `t` of the friction.
    fn lock(&self, pair: Option<Pair>, t: f64, detail: String) -> ForceError {
        ForceError::SelfLocking {
            position: self.label.to_string(),
            group: pair.map_or_else(|| "the mechanism".into(), |p| group_of(self.prog, p.to)),
            f: self.f,
            f_lock: t * self.f,
            detail: format!("{detail}, by {}", self.name),
        }
    }
}

/// The most times the affine model is re-anchored before the route gives up (it settles in one
/// or two on an exact route; a drawing's rounding may take a few more).
const MOST_REANCHORINGS: usize = 50;

/// Settle the friction of one route: `solve` the analysis of some loads, `reactions` of a
/// solution (in a fixed order), `friction(reactions, sizes)` the friction loads of reaction
/// magnitudes `sizes` (see the module's documentation).
pub fn settle<T>(
    route: &FrictionRoute<'_>,
    loads: &[Load],
    mut solve: impl FnMut(&[Load]) -> Result<T, ForceError>,
    reactions: impl Fn(&T) -> Vec<Reaction>,
    friction: impl Fn(&[Reaction], &[f64]) -> Vec<Load>,
) -> Result<Settled<T>, ForceError> {
    let mut solves = 0usize;
    let mut with = |sizes: &[f64], at: &[Reaction]| -> Result<(T, Vec<Load>), ForceError> {
        let fl = friction(at, sizes);
        let all: Vec<Load> = loads.iter().chain(&fl).cloned().collect();
        solves += 1;
        Ok((solve(&all)?, fl))
    };
    let none = vec![0.0; 0];
    let (first, _) = with(&none, &[])?;
    let r0 = reactions(&first);
    let n = r0.len();
    let big = r0.iter().fold(0.0f64, |m, r| m.max(r.force.length()));
    let unit = |k: usize, size: f64| {
        let mut v = vec![0.0; n];
        v[k] = size;
        v
    };
    let rubbing: Vec<usize> = (0..n)
        .filter(|&k| !friction(&r0, &unit(k, 1.0)).is_empty())
        .collect();
    if rubbing.is_empty() || big == 0.0 {
        return Ok(Settled {
            solution: first,
            loads: Vec::new(),
            solves,
        });
    }
    // The responses to one newton of each rubbing pair's friction (measured with `big`).
    let mut y = vec![vec![DVec2::ZERO; rubbing.len()]; rubbing.len()];
    for (j, &pj) in rubbing.iter().enumerate() {
        let (t, _) = with(&unit(pj, big), &r0)?;
        let rj = reactions(&t);
        for (k, &pk) in rubbing.iter().enumerate() {
            let now = rj.get(pk).map_or(DVec2::ZERO, |r| r.force);
            y[k][j] = (now - r0[pk].force) / big;
        }
    }
    let mut model = reduced::Reduced {
        r0: rubbing.iter().map(|&k| r0[k].force).collect(),
        y,
    };
    let mut at = r0.clone();
    for _ in 0..MOST_REANCHORINGS {
        let m = match model.solve() {
            reduced::Outcome::Solved(m, _) => m,
            reduced::Outcome::Fold {
                t,
                direction,
                bounded,
            } => {
                // The group that locks is the last (in the order of attachment) whose pairs
                // carry the unbounded (or turning) reactions: the groups before it only pass
                // them on.
                let pair = rubbing
                    .iter()
                    .zip(&direction)
                    .filter(|(_, d)| **d >= 1e-3)
                    .map(|(&k, _)| r0[k].pair)
                    .max_by_key(|p| order_of(route.prog, p.to));
                let detail = if bounded {
                    "the solution turns back there, every reaction bounded".to_string()
                } else {
                    "the reactions grow without bound as f approaches it".to_string()
                };
                return Err(route.lock(pair, t, detail));
            }
            reduced::Outcome::Turn { t, pair } => {
                let p = r0[rubbing[pair]].pair;
                let detail = format!(
                    "the reaction R_{}_{} falls to zero there and the solution turns back",
                    p.from, p.to
                );
                return Err(route.lock(Some(p), t, detail));
            }
            reduced::Outcome::Stalled { t } => {
                return Err(ForceError::FrictionUnsettled {
                    position: route.label.to_string(),
                    route: route.name.to_string(),
                    f: t * route.f,
                })
            }
        };
        let mut sizes = vec![0.0; n];
        for (&k, m) in rubbing.iter().zip(&m) {
            sizes[k] = *m;
        }
        let (solution, _) = with(&sizes, &at)?;
        let now = reactions(&solution);
        let size = sizes.iter().fold(big, |a, m| a.max(*m));
        let tol = (route.relative * size).max(route.absolute);
        let off = rubbing
            .iter()
            .map(|&k| (sizes[k] - now.get(k).map_or(0.0, |r| r.force.length())).abs())
            .fold(0.0f64, f64::max);
        at = now;
        if off <= tol {
            return Ok(Settled {
                loads: friction(&at, &sizes),
                solution,
                solves,
            });
        }
        // Re-anchor the affine model at the analysis just made.
        for (k, &pk) in rubbing.iter().enumerate() {
            let moved: DVec2 = model.y[k].iter().zip(&m).map(|(y, m)| *y * *m).sum();
            model.r0[k] = at.get(pk).map_or(DVec2::ZERO, |r| r.force) - moved;
        }
    }
    Err(ForceError::FrictionUnsettled {
        position: route.label.to_string(),
        route: route.name.to_string(),
        f: route.f,
    })
}
