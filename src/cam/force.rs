//! The cam mechanism's force condition and self-locking (seed 001 lectures 15–16,
//! L1705–1797): the cam pushes the follower along the common normal, at the pressure angle λ
//! to the follower's velocity; only the component P·cos λ does work, the other loads the
//! guides (or the rocker's pivot) whose friction grows with it, and past a critical λ no force
//! P moves the follower — the mechanism jams (самозаклинивание).
//!
//! * Translating follower: the cam's contact K at the rod's end, the guide's bearings at l
//!   (the overhang) and l + b from K. Equilibrium of the rod with the resistance Q along its
//!   axis and the bearing reactions R₁, R₂ (each with its friction f·R against the motion)
//!   gives P = Q/(cos λ − f·sin λ·(2l + b)/b), locking at tg λ_кр = b/(f(2l + b)).
//! * Rocker: the roller at the arm's end L, the pivot a journal of diameter d. The pivot
//!   carries the whole of P, its reaction tangent to the friction circle ρ = (d/2)·sin φ
//!   (lecture 11; ≈ f·d/2 for small φ), so P(L·cos λ − ρ) = M_с and the rocker locks at
//!   cos λ_кр = ρ/L. The lecture's M_тр = P^n·f·d/2 takes the pivot's load as P^n = P·sin λ
//!   alone, which gives tg λ_кр = 2L/(f·d) ([`rocker_locking_lecture`]): an approximation,
//!   smaller while d/2 < L.
//!
//! Each has two routes: the closed form, and the equilibrium solved as the linear system of
//! the free body's equations (forces along and across, moments), its locking angle found by
//! bisection where the system's force P stops being finite and positive.

use crate::geom::{bisect, bracketed_root, solve_linear, Midpoint};
use std::convert::Infallible;
use std::f64::consts::FRAC_PI_2;

/// A translating follower's guide.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TranslatingGuide {
    /// The guide's length b between its bearings, m.
    pub length: f64,
    /// The overhang l from the cam's contact to the nearer bearing, m.
    pub overhang: f64,
    /// The coefficient of friction in the guide.
    pub f: f64,
}

/// The forces on a translating follower at one pressure angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GuideForces {
    /// The cam's force P, N.
    pub p: f64,
    /// The nearer bearing's normal reaction R₁, N.
    pub r1: f64,
    /// The farther bearing's normal reaction R₂, N.
    pub r2: f64,
}

/// The closed form: P, R₁ = P·sin λ·(l + b)/b, R₂ = P·sin λ·l/b for the resistance `q` (N)
/// at the pressure angle `lambda`; `None` when the follower jams (λ ≥ λ_кр).
pub fn translating_forces(q: f64, lambda: f64, g: &TranslatingGuide) -> Option<GuideForces> {
    let (s, c) = lambda.sin_cos();
    let (b, l) = (g.length, g.overhang);
    let useful = c - g.f * s * (2.0 * l + b) / b;
    if useful <= 0.0 || useful.is_nan() {
        return None;
    }
    let p = q / useful;
    Some(GuideForces {
        p,
        r1: p * s * (l + b) / b,
        r2: p * s * l / b,
    })
}

/// The locking angle of a translating follower, tg λ_кр = b/(f(2l + b)), radians.
pub fn translating_locking(g: &TranslatingGuide) -> f64 {
    (g.length / (g.f * (2.0 * g.overhang + g.length))).atan()
}

/// The twin route: the rod's equilibrium as the linear system in (P, R₁, R₂) — across the
/// axis P·sin λ − R₁ + R₂ = 0, along it P·cos λ − f(R₁ + R₂) = Q, moments about the contact
/// l·R₁ − (l + b)·R₂ = 0 — solved by elimination; `None` when it is singular or gives no
/// positive P (the follower jams).
pub fn translating_equilibrium(q: f64, lambda: f64, g: &TranslatingGuide) -> Option<GuideForces> {
    let (s, c) = lambda.sin_cos();
    let (b, l, f) = (g.length, g.overhang, g.f);
    let x = solve_linear(vec![
        vec![s, -1.0, 1.0, 0.0],
        vec![c, -f, -f, q],
        vec![0.0, l, -(l + b), 0.0],
    ])?;
    (x[0] > 0.0 && x[0].is_finite()).then_some(GuideForces {
        p: x[0],
        r1: x[1],
        r2: x[2],
    })
}

/// A rocker's pivot.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pivot {
    /// The arm L from the pivot to the roller's centre, m.
    pub arm: f64,
    /// The pivot's (journal's) diameter d, m.
    pub diameter: f64,
    /// The coefficient of friction in the pivot.
    pub f: f64,
}

impl Pivot {
    /// The friction circle's radius ρ = (d/2)·sin φ, φ = arctg f, m (lecture 11; the
    /// lecture's ρ ≈ f·d/2 for small φ).
    pub fn rho(&self) -> f64 {
        self.diameter / 2.0 * self.f.atan().sin()
    }
}

/// The cam's force P on a rocker against the moment of resistance `m` (N·m) at the pressure
/// angle `lambda`: P(L·cos λ − ρ) = M_с, the pivot carrying the whole of P; `None` when the
/// rocker jams.
pub fn rocker_force(m: f64, lambda: f64, p: &Pivot) -> Option<f64> {
    let useful = p.arm * lambda.cos() - p.rho();
    (useful > 0.0).then(|| m / useful)
}

/// The rocker's locking angle, cos λ_кр = ρ/L, radians (when ρ ≥ L it jams at every angle:
/// 0 is returned).
pub fn rocker_locking(p: &Pivot) -> f64 {
    let c = p.rho() / p.arm;
    if c >= 1.0 {
        0.0
    } else {
        c.acos()
    }
}

/// The lecture's locking angle with M_тр = P^n·f·d/2, tg λ_кр = 2L/(f·d), radians.
pub fn rocker_locking_lecture(p: &Pivot) -> f64 {
    (2.0 * p.arm / (p.f * p.diameter)).atan()
}

/// The twin route for a rocker: the moment balance about the pivot, P^τ·L = M_с + ρ·|R|
/// (the friction couple of the journal, ρ = (d/2)·sin φ) with the pivot's reaction R = −P
/// found from the rocker's force balance (its components P^τ = P cos λ, P^n = P sin λ summed
/// as vectors), solved for P as the bracketed root of the moment's residue; `None` when no
/// finite P balances it.
pub fn rocker_equilibrium(m: f64, lambda: f64, p: &Pivot) -> Option<f64> {
    let rho = p.diameter / 2.0 * (p.f / p.f.hypot(1.0));
    let residue = |force: f64| {
        let (pt, pn) = (force * lambda.cos(), force * lambda.sin());
        let reaction = pt.hypot(pn);
        pt * p.arm - m - rho * reaction
    };
    // The residue is linear in P: it grows when the useful arm is positive.
    let mut hi = m.abs().max(1.0);
    let mut k = 0;
    while residue(hi) <= 0.0 {
        hi *= 2.0;
        k += 1;
        if k > 200 {
            return None;
        }
    }
    Some(bracketed_root(residue, 0.0, hi))
}

/// The angle in (0, π/2) where `moves` turns false (the follower jams), by bisection to
/// `1e-13` rad; `None` when it moves at every angle or at none.
pub fn locking_by_bisection(moves: impl Fn(f64) -> bool) -> Option<f64> {
    let (lo, hi) = (0.0, FRAC_PI_2);
    if !moves(lo) || moves(hi - 1e-12) {
        return None;
    }
    let Ok((lo, hi)) = bisect(
        lo,
        hi,
        200,
        |lo, hi| hi - lo <= 1e-13,
        |mid| {
            Ok::<_, Infallible>(if moves(mid) {
                Midpoint::First
            } else {
                Midpoint::Second
            })
        },
    );
    Some(0.5 * (lo + hi))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// The closed forms against the free body's equilibrium: P, R₁, R₂ to 1e-9 at every
        /// angle below the locking one, the locking angles to 1e-9 rad.
        #[test]
        fn the_force_condition_by_its_closed_form_and_by_the_equilibrium(
            b in 0.02f64..0.2, l in 0.0f64..0.2, f in 0.02f64..0.5, q in 1.0f64..1e4,
            arm in 0.03f64..0.3, d in 0.005f64..0.06, share in 0.01f64..0.99,
        ) {
            let g = TranslatingGuide { length: b, overhang: l, f };
            let lock = translating_locking(&g);
            let by_eq = locking_by_bisection(|x| translating_equilibrium(q, x, &g).is_some()).unwrap();
            prop_assert!((lock - by_eq).abs() < 1e-9, "{lock} {by_eq}");
            let lambda = share * lock;
            let a = translating_forces(q, lambda, &g).unwrap();
            let e = translating_equilibrium(q, lambda, &g).unwrap();
            for (x, y) in [(a.p, e.p), (a.r1, e.r1), (a.r2, e.r2)] {
                prop_assert!((x - y).abs() <= 1e-9 * a.p, "{x} {y}");
            }
            prop_assert!(translating_forces(q, lock + 1e-6, &g).is_none());
            let p = Pivot { arm, diameter: d, f };
            let lock = rocker_locking(&p);
            let by_eq = locking_by_bisection(|x| rocker_equilibrium(1.0, x, &p).is_some()).unwrap();
            prop_assert!((lock - by_eq).abs() < 1e-9, "{lock} {by_eq}");
            let lambda = share * lock;
            let (x, y) = (rocker_force(q, lambda, &p).unwrap(), rocker_equilibrium(q, lambda, &p).unwrap());
            prop_assert!((x - y).abs() <= 1e-9 * x, "{x} {y}");
            // The lecture's M_тр = P^n·f·d/2 counts the pivot's load as P^n only but its
            // friction arm as f·d/2: with d/2 < L its angle is smaller.
            prop_assert!(rocker_locking_lecture(&p) < rocker_locking(&p));
        }
    }

    /// The lecture's limits λ_max = 30…40° against the jamming angle of a typical guide: with
    /// b = 2l, f = 0,15 the rod jams at λ_кр = arctg(2/(0,15·4)) = 73,3°; a long overhang
    /// l = 3b at f = 0,3 brings it to arctg(0,02/0,042) = 25,46°, below the usual λ_max.
    #[test]
    fn typical_guides_lock_far_beyond_the_admissible_pressure_angle() {
        let g = TranslatingGuide {
            length: 0.04,
            overhang: 0.02,
            f: 0.15,
        };
        assert!(
            (translating_locking(&g).to_degrees() - (2.0f64 / 0.6).atan().to_degrees()).abs()
                < 1e-12
        );
        assert!((translating_locking(&g).to_degrees() - 73.3007558).abs() < 1e-6);
        let long = TranslatingGuide {
            length: 0.02,
            overhang: 0.06,
            f: 0.3,
        };
        assert!((translating_locking(&long).to_degrees() - 25.4633451).abs() < 1e-6);
        // At λ = 0 the guide carries nothing: P = Q.
        let a = translating_forces(100.0, 0.0, &g).unwrap();
        assert!((a.p - 100.0).abs() < 1e-12 && a.r1 == 0.0 && a.r2 == 0.0);
        // A rocker L = 120 mm (seed 000) in a pivot d = 20 mm, f = 0,1: ρ = 10·sin(arctg 0,1)
        // = 0,995037 mm, cos λ_кр = ρ/L: λ_кр = 89,52490°.
        let p = Pivot {
            arm: 0.12,
            diameter: 0.02,
            f: 0.1,
        };
        assert!((p.rho() - 0.01 * 0.1 / 1.01f64.sqrt()).abs() < 1e-18);
        assert!((rocker_locking(&p).to_degrees() - 89.524899).abs() < 1e-6);
        assert!((rocker_locking_lecture(&p) - 120f64.atan()).abs() < 1e-15);
    }
}
