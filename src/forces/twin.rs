//! The analytic twin of the force analysis: every joint reaction and the balancing moment (or
//! force) from one linear solve of the equilibrium equations of every moving link — three
//! per link, ΣF = 0 and ΣM = 0 — and the balancing moment a second way from the power
//! balance Σ F·v + Σ M·ω + M_bal·ω₁ = 0. Shares nothing with the polygons but the loads.

use super::loads::{Load, PositionMotion};
use super::spec::Drive;
use super::ForceError;
use crate::geom::DVec2;
use crate::linkage::{GroupPairs, Pose, Program};

/// A kinematic pair as the equilibrium equations see it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PairKind {
    /// A revolute pair at a point (program index).
    Revolute(usize),
    /// A prismatic pair: the reaction is normal to the sliding direction, which is the frame
    /// direction of link `dir_link`; `reference` is the point the offset of its line of
    /// action is measured from (along the sliding direction).
    Prismatic {
        /// The point of reference on the line of sliding.
        reference: usize,
        /// The link whose frame direction is the sliding direction.
        dir_link: usize,
    },
}

/// A pair between link `from` (the link known first, 0 the frame) and link `to` (a link of
/// the group that attaches it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pair {
    /// The link that acts.
    pub from: usize,
    /// The link acted on.
    pub to: usize,
    /// Revolute or prismatic.
    pub kind: PairKind,
}

/// The pairs of a mechanism in the order of its groups: the crank's pivot, then per group
/// its two outer pairs and its inner pair.
pub fn pairs(prog: &Program) -> Vec<Pair> {
    let crank = prog.crank_link as usize;
    let mut v = vec![Pair {
        from: 0,
        to: crank,
        kind: PairKind::Revolute(prog.centre),
    }];
    for g in prog.groups() {
        let [i, j] = g.links;
        let rev = |from: usize, to: usize, k: usize| Pair {
            from,
            to,
            kind: PairKind::Revolute(k),
        };
        let pri = |from: usize, to: usize, reference: usize, dir_link: usize| Pair {
            from,
            to,
            kind: PairKind::Prismatic {
                reference,
                dir_link,
            },
        };
        match g.pairs {
            GroupPairs::Rrr { a, c, joint } => v.extend([
                rev(prog.owner(a), i, a),
                rev(prog.owner(c), j, c),
                rev(i, j, joint),
            ]),
            GroupPairs::Rrp { a, guide, joint } => v.extend([
                rev(prog.owner(a), i, a),
                pri(guide, j, joint, j),
                rev(i, j, joint),
            ]),
            GroupPairs::Rpr { a, c } => v.extend([
                rev(prog.owner(a), i, a),
                rev(prog.owner(c), j, c),
                pri(i, j, a, j),
            ]),
            GroupPairs::Prp { gi, gj, joint } => {
                v.extend([pri(gi, i, joint, i), pri(gj, j, joint, j), rev(i, j, joint)])
            }
            GroupPairs::Rpp { a, guide, joint } => v.extend([
                rev(prog.owner(a), i, a),
                pri(guide, j, joint, j),
                pri(i, j, a, i),
            ]),
        }
    }
    v
}

/// A reaction found: the force of `pair.from` on `pair.to` and where its line of action
/// passes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reaction {
    /// The pair.
    pub pair: Pair,
    /// The force on `pair.to`, N.
    pub force: DVec2,
    /// A prismatic pair's point of application: its offset from the reference point along
    /// the sliding direction, m (`None` for a revolute pair, or when the reaction vanishes).
    pub offset: Option<f64>,
}

/// The result of the force analysis of one position.
#[derive(Debug, Clone, PartialEq)]
pub struct Equilibrium {
    /// Every pair's reaction, in the order of `pairs`.
    pub reactions: Vec<Reaction>,
    /// The balancing moment on the crank, N·m, counter-clockwise.
    pub m_bal: f64,
    /// The balancing force at the pitch point along the line of action (gear drive), N: the
    /// magnitude of the tooth force, on the flank that turns the crank in the sense of
    /// `m_bal` (`line_of_action`).
    pub f_bal: Option<f64>,
    /// The balancing force's arm about the crank's centre (gear drive), m.
    pub arm: Option<f64>,
}

impl Equilibrium {
    /// The largest reaction's magnitude, N.
    pub fn largest(&self) -> f64 {
        self.reactions
            .iter()
            .map(|r| r.force.length())
            .fold(0.0, f64::max)
    }

    /// The force of link `from` on link `to`.
    pub fn reaction(&self, from: usize, to: usize) -> Option<DVec2> {
        self.reactions
            .iter()
            .find(|r| r.pair.from == from && r.pair.to == to)
            .map(|r| r.force)
    }
}

/// The gear drive's line of action: the pitch point P (m) and the unit direction of the force
/// the pinion's tooth exerts on the crank's wheel when that force turns the wheel in the sense
/// `turn` (+1 counter-clockwise): its tangential component along `turn`, its radial component
/// towards the wheel's centre. A tooth only pushes, so the line depends on which flank is in
/// contact: when the balancing moment turns the crank with its rotation the pinion drives it
/// (`turn` = the sense of ω₁); when the balancing moment opposes ω₁ the pinion holds the crank
/// back on the other flank, and the line of action is the mirror image about the line of
/// centres (`turn` = −the sense of ω₁). Either way the force's magnitude F_bal is positive.
pub fn line_of_action(
    centre: DVec2,
    r: f64,
    towards: f64,
    alpha: f64,
    turn: f64,
) -> (DVec2, DVec2) {
    let e = DVec2::from_angle(towards);
    let p = centre + e * r;
    let d = e.perp() * (turn * alpha.cos()) - e * alpha.sin();
    (p, d)
}

/// The reactions and the balancing moment of `loads` at `pose`: one linear solve. With a gear
/// drive the solve first takes the flank on which the pinion drives the crank (`sense`, that
/// of ω₁); a negative force there means the pinion holds the crank back, and the solve is
/// repeated on the mirrored line of action (`line_of_action`), where the force is positive.
pub fn solve(
    prog: &Program,
    pose: &Pose,
    loads: &[Load],
    drive: &Drive,
    sense: f64,
) -> Result<Equilibrium, ForceError> {
    let e = solve_on(prog, pose, loads, drive, sense)?;
    match e.f_bal {
        Some(f) if f < 0.0 => solve_on(prog, pose, loads, drive, -sense),
        _ => Ok(e),
    }
}

/// [`solve`] with a gear drive's tooth force turning the crank in the sense `turn`.
fn solve_on(
    prog: &Program,
    pose: &Pose,
    loads: &[Load],
    drive: &Drive,
    turn: f64,
) -> Result<Equilibrium, ForceError> {
    let pairs = pairs(prog);
    let moving: Vec<usize> = std::iter::once(prog.crank_link as usize)
        .chain(prog.groups().flat_map(|g| g.links))
        .collect();
    let row_of = |l: usize| moving.iter().position(|&m| m == l);
    let n = 3 * moving.len();
    let cols = 2 * pairs.len() + 1;
    if cols != n {
        return Err(ForceError::NotDeterminate {
            equations: n,
            unknowns: cols,
        });
    }
    let origin = pose.p[prog.centre];
    let mut a = vec![vec![0.0; n + 1]; n];
    // Adds force `f` (per unit unknown) at `x` and couple `m` to link `l`'s rows in column `c`.
    let put = |a: &mut Vec<Vec<f64>>, l: usize, c: usize, f: DVec2, x: DVec2, m: f64| {
        if let Some(r) = row_of(l) {
            a[3 * r][c] += f.x;
            a[3 * r + 1][c] += f.y;
            a[3 * r + 2][c] += (x - origin).perp_dot(f) + m;
        }
    };
    for (k, pair) in pairs.iter().enumerate() {
        let (cx, cy) = (2 * k, 2 * k + 1);
        match pair.kind {
            PairKind::Revolute(x) => {
                let x = pose.p[x];
                for (c, e) in [(cx, DVec2::X), (cy, DVec2::Y)] {
                    put(&mut a, pair.to, c, e, x, 0.0);
                    put(&mut a, pair.from, c, -e, x, 0.0);
                }
            }
            PairKind::Prismatic {
                reference,
                dir_link,
            } => {
                let x = pose.p[reference];
                let nrm = pose.dir[dir_link].perp();
                put(&mut a, pair.to, cx, nrm, x, 0.0);
                put(&mut a, pair.from, cx, -nrm, x, 0.0);
                put(&mut a, pair.to, cy, DVec2::ZERO, x, 1.0);
                put(&mut a, pair.from, cy, DVec2::ZERO, x, -1.0);
            }
        }
    }
    let crank = prog.crank_link as usize;
    let bal = cols - 1;
    let gear = match drive {
        Drive::Coupling => {
            put(&mut a, crank, bal, DVec2::ZERO, origin, 1.0);
            None
        }
        Drive::Gear(g) => {
            let (p, d) = line_of_action(origin, g.radius(), g.towards, g.pressure_angle, turn);
            put(&mut a, crank, bal, d, p, 0.0);
            Some((p, d))
        }
    };
    for load in loads {
        if let Some(r) = row_of(load.link) {
            let x = pose.p[load.at];
            a[3 * r][n] -= load.force.x;
            a[3 * r + 1][n] -= load.force.y;
            a[3 * r + 2][n] -= (x - origin).perp_dot(load.force) + load.moment;
        }
    }
    let x = crate::geom::solve_linear(a).ok_or(ForceError::Singular)?;
    let scale = super::force_scale(loads, super::reach(&pose.p));
    let reactions = pairs
        .iter()
        .enumerate()
        .map(|(k, &pair)| {
            let (u, v) = (x[2 * k], x[2 * k + 1]);
            match pair.kind {
                PairKind::Revolute(_) => Reaction {
                    pair,
                    force: DVec2::new(u, v),
                    offset: None,
                },
                PairKind::Prismatic { dir_link, .. } => Reaction {
                    pair,
                    force: pose.dir[dir_link].perp() * u,
                    // Couple v about the reference point = N·s.
                    offset: super::arm(u, -v, scale),
                },
            }
        })
        .collect();
    let (m_bal, f_bal, arm) = match gear {
        None => (x[bal], None, None),
        Some((p, d)) => {
            let arm = (p - origin).perp_dot(d);
            (arm * x[bal], Some(x[bal]), Some(arm.abs()))
        }
    };
    Ok(Equilibrium {
        reactions,
        m_bal,
        f_bal,
        arm,
    })
}

/// The balancing moment from the power balance: M_bal·ω₁ + Σ F·v + Σ M·ω = 0 (the ideal
/// pairs' reactions do no work).
pub fn power_balance(loads: &[Load], motion: &PositionMotion, w1: f64) -> f64 {
    let power: f64 = loads
        .iter()
        .map(|l| {
            l.force.dot(motion.v[l.at])
                + l.moment * motion.omega.get(l.link).copied().unwrap_or(0.0)
        })
        .sum();
    -power / w1
}
