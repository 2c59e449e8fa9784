//! The friction equations reduced to the friction loads' magnitudes. With the friction loads
//! of the pairs that rub given per newton of their reactions, every reaction is an affine
//! function of those magnitudes m: R_k(m) = r0_k + Σ_j y_kj·m_j (the analysis is linear in its
//! loads), and the friction equations are m_k = |R_k(m)| — one unknown per rubbing pair.
//!
//! They are solved by Newton's method (the Jacobian δ_kj − e_k·y_kj, e_k the unit direction of
//! R_k), continued in the friction's size: t·f for t from 0 (no friction, m = |r0|) to 1, each
//! step's solution the next one's start. Convergence does not hang on a count of steps: the
//! path either reaches t = 1, or ends at a t* < 1 where the equations' Jacobian turns singular
//! — its magnitudes growing without bound, or the path meeting a second solution and turning
//! back (where a reaction vanishes, or with every reaction bounded) —: for f ≥ t*·f the given
//! loads cannot be carried — the mechanism self-locks — and past t* the path has no
//! continuation.

use crate::geom::{damped_newton, determinant, solve_system, DVec2};

/// The reduced friction equations: `r0[k]` the reactions without friction, `y[k][j]` reaction
/// k's change per newton of pair j's friction magnitude.
#[derive(Debug, Clone, PartialEq)]
pub struct Reduced {
    /// The rubbing pairs' reactions with no friction, N.
    pub r0: Vec<DVec2>,
    /// `y[k][j]`: the change of reaction k per unit magnitude of pair j's friction.
    pub y: Vec<Vec<DVec2>>,
}

/// How the reduced equations end.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// The magnitudes at t = 1 and the Newton steps taken in all.
    Solved(Vec<f64>, usize),
    /// The path ends at `t` (< 1) where the equations' Jacobian turns singular: the
    /// magnitudes grow without bound as t approaches it, or (`bounded`) the path meets a
    /// second solution there and turns back with every reaction bounded and none vanishing
    /// (one pair, r0·y < 0: m = |r0 + t·y·m|'s two roots meet at t = |r0|/|r0 × y|). A lock
    /// either way; `direction` is the magnitudes there (unbounded) or their change along the
    /// turn (bounded), normalised to a largest of 1: the pairs that lock.
    Fold {
        /// The friction's fraction t* at which the path ends.
        t: f64,
        /// The normalised magnitudes, or their change, at the last point of the path.
        direction: Vec<f64>,
        /// Whether the reactions stay bounded there (the path turns back).
        bounded: bool,
    },
    /// The path turns back at `t` (< 1) where the reaction of pair `pair` falls to zero: the
    /// solution meets a second one there (the Jacobian's determinant has opposite signs on the
    /// two sides of the vanishing reaction) and past `t` neither exists — a lock with bounded
    /// reactions.
    Turn {
        /// The friction's fraction t* at which the path turns.
        t: f64,
        /// The rubbing pair (index into the unknowns) whose reaction vanishes there.
        pair: usize,
    },
    /// The path stops at `t` with bounded magnitudes (not a lock: the equations could not be
    /// followed there).
    Stalled {
        /// Where the continuation stopped.
        t: f64,
    },
}

/// Magnitudes beyond this multiple of the frictionless reactions are unbounded.
const UNBOUNDED: f64 = 1e9;
/// Where the path stops with bounded magnitudes, its Jacobian I − t·e·y is singular (the path
/// turns back) when its determinant is below this share of the product of its rows' lengths,
/// each at least the identity's 1: it falls as √(t* − t), about 1e-6 at the smallest step from
/// the turn.
const SINGULAR_TURN: f64 = 1e-3;
/// A continuation step below this is no step.
const SMALLEST_STEP: f64 = 1e-12;
/// The continuation's bound on its steps (a safety net; the path ends well before it).
const MOST_STEPS: usize = 100_000;

impl Reduced {
    /// The number of unknowns.
    fn len(&self) -> usize {
        self.r0.len()
    }

    /// The reactions at magnitudes `m` with the friction scaled by `t`.
    fn reactions(&self, m: &[f64], t: f64) -> Vec<DVec2> {
        self.r0
            .iter()
            .zip(&self.y)
            .map(|(r, row)| *r + row.iter().zip(m).map(|(y, m)| *y * m).sum::<DVec2>() * t)
            .collect()
    }

    /// The residual m − |R(m)| and the Jacobian I − t·e·y at `m`.
    fn residual(&self, m: &[f64], t: f64) -> (Vec<f64>, Vec<Vec<f64>>) {
        let n = self.len();
        let r = self.reactions(m, t);
        let g = m.iter().zip(&r).map(|(m, r)| m - r.length()).collect();
        let jac = (0..n)
            .map(|k| {
                let e = r[k].normalize_or_zero();
                (0..n)
                    .map(|j| f64::from(u8::from(k == j)) - t * e.dot(self.y[k][j]))
                    .collect()
            })
            .collect();
        (g, jac)
    }

    /// The size of the problem at `m`: the largest frictionless reaction or magnitude.
    fn size(&self, m: &[f64]) -> f64 {
        let s = self.r0.iter().fold(0.0f64, |a, r| a.max(r.length()));
        m.iter().fold(s, |a, m| a.max(m.abs()))
    }

    /// Newton's method at `t` from `start`, with a halving line search on the residual
    /// ([`damped_newton`]); `None` when it does not converge (to 1e-14 of the problem's size).
    fn newton(&self, t: f64, start: &[f64]) -> Option<(Vec<f64>, usize)> {
        damped_newton(|m| self.residual(m, t), start, |m| 1e-14 * self.size(m), 60)
    }

    /// Follow the solution from t = 0 to t = 1 (see the module's documentation).
    pub fn solve(&self) -> Outcome {
        let n = self.len();
        let s = self.size(&[]);
        let mut m: Vec<f64> = self.r0.iter().map(|r| r.length()).collect();
        if n == 0 || s == 0.0 {
            return Outcome::Solved(m, 0);
        }
        let (mut t, mut dt, mut steps) = (0.0f64, 1.0f64, 0usize);
        for _ in 0..MOST_STEPS {
            let t1 = (t + dt).min(1.0);
            // The tangent dm/dt = J⁻¹·(e·y·m) predicts the next point.
            let (_, jac) = self.residual(&m, t);
            let (full, now) = (self.reactions(&m, 1.0), self.reactions(&m, t));
            let rhs: Vec<f64> = (0..n)
                .map(|k| now[k].normalize_or_zero().dot(full[k] - self.r0[k]))
                .collect();
            let tangent = solve_system(jac, rhs, 0.0).unwrap_or_else(|| vec![0.0; n]);
            let guess: Vec<f64> = m
                .iter()
                .zip(&tangent)
                .map(|(m, d)| m + d * (t1 - t))
                .collect();
            let next = self.newton(t1, &guess).or_else(|| self.newton(t1, &m));
            match next {
                Some((m1, k)) if self.size(&m1) <= UNBOUNDED * s => {
                    steps += k;
                    m = m1;
                    t = t1;
                    if t >= 1.0 {
                        return Outcome::Solved(m, steps);
                    }
                    dt = (dt * 2.0).min(1.0);
                }
                Some((m1, _)) => return fold(t1, &m1, false),
                None => {
                    dt /= 4.0;
                    if dt < SMALLEST_STEP {
                        // Bounded magnitudes that cannot be followed: a fold only if they
                        // have grown far beyond the frictionless ones.
                        if self.size(&m) > 1e3 * s {
                            return fold(t, &m, false);
                        }
                        return self
                            .turn(t, &m)
                            .or_else(|| self.meet(t, &m))
                            .unwrap_or(Outcome::Stalled { t });
                    }
                }
            }
        }
        Outcome::Stalled { t }
    }
}

impl Reduced {
    /// Where the path stops at `t`, `m` with bounded magnitudes: a turning point if a
    /// reaction has (nearly) vanished and the Jacobian's determinant differs in sign with that
    /// reaction's direction reversed.
    fn turn(&self, t: f64, m: &[f64]) -> Option<Outcome> {
        let r = self.reactions(m, t);
        let size = self.size(m);
        let (k, small) = r
            .iter()
            .enumerate()
            .map(|(k, r)| (k, r.length()))
            .min_by(|a, b| a.1.total_cmp(&b.1))?;
        if small > 1e-6 * size {
            return None;
        }
        // The reaction's direction just before it vanished: along its change with m.
        let e = r[k].try_normalize().or_else(|| {
            let d: DVec2 = self.y[k].iter().zip(m).map(|(y, m)| *y * *m).sum();
            d.try_normalize()
        })?;
        let det_with = |e_k: DVec2| {
            let n = self.len();
            let jac: Vec<Vec<f64>> = (0..n)
                .map(|i| {
                    let e = if i == k {
                        e_k
                    } else {
                        r[i].normalize_or_zero()
                    };
                    (0..n)
                        .map(|j| f64::from(u8::from(i == j)) - t * e.dot(self.y[i][j]))
                        .collect()
                })
                .collect();
            determinant(jac)
        };
        (det_with(e) * det_with(-e) < 0.0).then_some(Outcome::Turn { t, pair: k })
    }

    /// Where the path stops at `t`, `m` with bounded magnitudes and no reaction vanishing: a
    /// turn where it meets a second solution if the Jacobian is singular there
    /// ([`SINGULAR_TURN`]), the magnitudes' change along the turn read by one step of inverse
    /// iteration (J·x = 1 is dominated by J's near-null vector).
    fn meet(&self, t: f64, m: &[f64]) -> Option<Outcome> {
        let (_, jac) = self.residual(m, t);
        let rows: f64 = jac
            .iter()
            .map(|row| row.iter().map(|x| x * x).sum::<f64>().sqrt().max(1.0))
            .product();
        if determinant(jac.clone()).abs() > SINGULAR_TURN * rows {
            return None;
        }
        let n = self.len();
        let change = solve_system(jac, vec![1.0; n], 0.0).unwrap_or_else(|| vec![1.0; n]);
        Some(fold(t, &change, true))
    }
}

/// A fold at `t` with the magnitudes `m` there (`bounded`: their change along the turn).
fn fold(t: f64, m: &[f64], bounded: bool) -> Outcome {
    let big = m.iter().fold(0.0f64, |a, m| a.max(m.abs()));
    Outcome::Fold {
        t,
        direction: m.iter().map(|m| m.abs() / big).collect(),
        bounded,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One pair: m = |r0 + t·y·m| has m = r0/(1 − y) for y < 1 and no solution for y ≥ 1;
    /// the path's magnitudes grow without bound as t → 1/y.
    #[test]
    fn one_pair_solves_or_folds_at_one_over_y() {
        for y in [-3.0, -0.5, 0.0, 0.3, 0.9, 0.999] {
            let r = Reduced {
                r0: vec![DVec2::new(100.0, 0.0)],
                y: vec![vec![DVec2::new(y, 0.0)]],
            };
            let Outcome::Solved(m, _) = r.solve() else {
                panic!("y = {y}: no solution");
            };
            assert!(
                (m[0] - 100.0 / (1.0 - y)).abs() <= 1e-12 * m[0],
                "y = {y}: {m:?}"
            );
        }
        for y in [1.25, 2.0, 10.0] {
            let r = Reduced {
                r0: vec![DVec2::new(100.0, 0.0)],
                y: vec![vec![DVec2::new(y, 0.0)]],
            };
            match r.solve() {
                Outcome::Fold { t, direction, .. } => {
                    assert!((t - 1.0 / y).abs() <= 1e-6 / y, "y = {y}: t* = {t}");
                    assert_eq!(direction, vec![1.0]);
                }
                o => panic!("y = {y}: {o:?}"),
            }
        }
    }

    /// One pair with its friction against its reaction and across it, r0 = (100, 0),
    /// y = (−1, 2): m = |r0 + t·y·m| has (5t² − 1)m² − 200t·m + 10⁴ = 0, whose two positive
    /// roots meet at t* = 1/2 (m = 200, R = (0, 200): bounded, not vanishing) and do not exist
    /// past it — a lock where the path turns back, not a stall.
    #[test]
    fn a_path_that_turns_back_with_bounded_reactions_is_a_lock() {
        let r = Reduced {
            r0: vec![DVec2::new(100.0, 0.0)],
            y: vec![vec![DVec2::new(-1.0, 2.0)]],
        };
        match r.solve() {
            Outcome::Fold {
                t,
                direction,
                bounded: true,
            } => {
                assert!((t - 0.5).abs() <= 1e-6, "t* = {t}");
                assert_eq!(direction, vec![1.0]);
            }
            o => panic!("{o:?}"),
        }
    }

    /// A reaction turned by its friction (y across r0) and a second pair coupled to the
    /// first: the solution satisfies m_k = |R_k(m)| to rounding, and agrees with plain
    /// successive approximations where those contract.
    #[test]
    fn coupled_pairs_agree_with_successive_approximations() {
        let r = Reduced {
            r0: vec![DVec2::new(300.0, -40.0), DVec2::new(-20.0, 90.0)],
            y: vec![
                vec![DVec2::new(0.1, 0.4), DVec2::new(0.2, -0.1)],
                vec![DVec2::new(0.3, 0.05), DVec2::new(-0.2, 0.1)],
            ],
        };
        let Outcome::Solved(m, _) = r.solve() else {
            panic!("no solution");
        };
        let mut p: Vec<f64> = r.r0.iter().map(|r| r.length()).collect();
        for _ in 0..500 {
            p = r.reactions(&p, 1.0).iter().map(|r| r.length()).collect();
        }
        let now = r.reactions(&m, 1.0);
        for k in 0..2 {
            assert!((m[k] - now[k].length()).abs() <= 1e-12 * 300.0);
            assert!((m[k] - p[k]).abs() <= 1e-10 * 300.0, "{m:?} vs {p:?}");
        }
    }

    /// Two sliding pairs whose first's normal reaction falls to zero as the friction grows:
    /// the path meets a second solution there and turns back (checked against every sign
    /// pattern of the two normals solved exactly), so the friction asked for has none.
    #[test]
    fn a_vanishing_reaction_where_the_solution_turns_back_is_a_lock() {
        // N₂ = 24 + t(1.2863·m₂ + 1.3163·m₃), N₃ = 76.97 − t(1.3163·m₂ + 1.2863·m₃), m = |N|
        // (a random mechanism's two guides): the branch N₃ > 0 ends where N₃ = 0.
        let (n2, n3) = (DVec2::X, DVec2::Y);
        let r = Reduced {
            r0: vec![n2 * 24.0, n3 * 76.97],
            y: vec![
                vec![n2 * 1.2863, n2 * 1.3163],
                vec![n3 * -1.3163, n3 * -1.2863],
            ],
        };
        // Every sign pattern solved as a linear system: where does a consistent one exist?
        let exists = |t: f64| {
            [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)]
                .iter()
                .any(|&(s2, s3): &(f64, f64)| {
                    let a = [
                        [1.0 - s2 * t * 1.2863, -s2 * t * 1.3163],
                        [s3 * t * 1.3163, 1.0 + s3 * t * 1.2863],
                    ];
                    let (b0, b1) = (s2 * 24.0, s3 * 76.97);
                    let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
                    let m2 = (b0 * a[1][1] - a[0][1] * b1) / det;
                    let m3 = (a[0][0] * b1 - a[1][0] * b0) / det;
                    m2 >= 0.0 && m3 >= 0.0
                })
        };
        match r.solve() {
            Outcome::Turn { t, pair } => {
                assert_eq!(pair, 1);
                assert!(exists(t - 1e-6) && !exists(t + 1e-6), "t* = {t}");
                assert!(!exists(1.0));
            }
            o => panic!("{o:?}"),
        }
    }

    /// A map whose successive approximations diverge (y = 1.5 across, the journal's couple
    /// growing the reaction faster than it turns it) still has its solution found.
    #[test]
    fn solves_where_successive_approximations_diverge() {
        // m = |(100, 0) + (−1.5·m, 0)|: m = 100 − 1.5·m for m < 66.7 → m = 40; plain
        // iteration: m → |100 − 1.5·m| oscillates and diverges from 40 (slope −1.5).
        let r = Reduced {
            r0: vec![DVec2::new(100.0, 0.0)],
            y: vec![vec![DVec2::new(-1.5, 0.0)]],
        };
        let Outcome::Solved(m, _) = r.solve() else {
            panic!("no solution");
        };
        assert!((m[0] - 40.0).abs() <= 1e-12);
        let mut p = 100.0f64;
        for _ in 0..50 {
            p = (100.0 - 1.5 * p).abs();
        }
        assert!((p - 40.0).abs() > 1.0, "plain iteration settled at {p}");
    }
}
