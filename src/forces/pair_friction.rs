//! Friction in the pairs of a mechanism's force analysis (seed 001, lectures 10–11), by
//! successive approximations as the textbook does it: the reactions found without friction
//! give the friction loads — in a sliding pair the force f·|N| along the guide against the
//! relative sliding, which turns the total reaction from the normal by exactly φ = arctg f; in
//! a revolute pair the couple ρ·|R| against the relative rotation, ρ = f·r the friction
//! circle's radius, which puts the reaction tangent to that circle — and the analysis is
//! repeated with them until the reactions stop changing.
//!
//! Both routes iterate the same way: the force polygons with the friction loads of the
//! previous polygons (friction forces laid on the drawing like any other load), and the
//! twin's linear solve with those of the previous solve. At drafting 0 they converge to the
//! same reactions; the friction's power is always negative, so the balancing moment's power
//! M_bal·ω₁ grows by exactly the power lost in the pairs.

use super::loads::{Load, LoadKind, Motion};
use super::twin::{PairKind, Reaction};
use super::ForceError;
use crate::geom::DVec2;
use crate::linkage::Program;

/// The most approximations before the friction is declared self-locking.
pub const MAX_APPROXIMATIONS: usize = 200;

/// Friction in the pairs of a mechanism (`[forces.friction]`), SI.
#[derive(Debug, Clone, PartialEq)]
pub struct PairFriction {
    /// The coefficient of sliding friction f, in the sliding pairs and the journals.
    pub f: f64,
    /// The journals' radius r, m (every revolute pair not in `radii`; 0: frictionless).
    pub radius: f64,
    /// Journals of their own radius, by point name, m.
    pub radii: Vec<(String, f64)>,
}

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
pub struct Kinematics<'a> {
    /// The mechanism.
    pub prog: &'a Program,
    /// Unit frame direction of every link.
    pub dir: Vec<DVec2>,
    /// A point of every link (its frame origin), by link number.
    pub origin: &'a [usize],
    /// The motion (velocities and ω).
    pub motion: &'a Motion,
}

impl Kinematics<'_> {
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
/// `from`; nothing on the frame).
pub fn friction_loads(fr: &PairFriction, k: &Kinematics<'_>, reactions: &[Reaction]) -> Vec<Load> {
    let mut out = Vec::new();
    let mut push = |l: usize, load: Load| {
        if l != 0 {
            out.push(load);
        }
    };
    for r in reactions {
        let (from, to) = (r.pair.from, r.pair.to);
        let size = r.force.length();
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
                    ..Load::force(
                        l,
                        LoadKind::Friction,
                        format!("F_{{тр{other}-{l}}}"),
                        f,
                        reference,
                    )
                };
                push(to, force(to, from, f));
                push(from, force(from, to, -f));
            }
        }
    }
    out
}

/// The power of the friction loads, W (never positive).
pub fn friction_power(loads: &[Load], k: &Kinematics<'_>) -> f64 {
    loads
        .iter()
        .map(|l| {
            let x = k.motion.p[l.at] + l.shift;
            l.force.dot(k.velocity(l.link, x)) + l.moment * k.omega(l.link)
        })
        .sum()
}

/// Successive approximations: `solve` the loads plus the friction loads of the previous
/// reactions (none at first) until the largest change of a reaction is at most `tol` (N).
/// Returns the last solution, its friction loads and the number of approximations;
/// [`ForceError::SelfLocking`] when they do not settle.
pub fn approximate<T>(
    loads: &[Load],
    tol: f64,
    mut solve: impl FnMut(&[Load]) -> Result<T, ForceError>,
    reactions: impl Fn(&T) -> Vec<Reaction>,
    friction: impl Fn(&[Reaction]) -> Vec<Load>,
) -> Result<(T, Vec<Load>, usize), ForceError> {
    let mut all = loads.to_vec();
    let mut last = solve(&all)?;
    let mut prev = reactions(&last);
    for n in 1..=MAX_APPROXIMATIONS {
        let fl = friction(&prev);
        all.truncate(loads.len());
        all.extend(fl.iter().cloned());
        last = solve(&all)?;
        let now = reactions(&last);
        let change = now
            .iter()
            .zip(&prev)
            .map(|(a, b)| (a.force - b.force).length())
            .fold(0.0, f64::max);
        prev = now;
        if change <= tol {
            return Ok((last, fl, n));
        }
    }
    Err(ForceError::SelfLocking {
        approximations: MAX_APPROXIMATIONS,
    })
}
