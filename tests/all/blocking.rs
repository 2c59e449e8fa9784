//! Tests of the blocking contour (issue 21 §1): every traced curve evaluated at its points
//! through the analytic twins — `Pair::new` (s_a, ε_α, the line of action, λ) and
//! `Cutting` (undercut, the involute–fillet junction) — never through the module's own
//! formulas; the seeds' points placed; the choices against a brute-force grid; the hard
//! cases.
//!
//! Tolerances. A traced point lies within 10⁻¹³ (x per module) of its crossing along its
//! ray; the indices' gradients in x are O(1)–O(10) (s_a/m, ε_α, the lengths along the line
//! of action per m), so the index is at its limit to ~10⁻¹² before rounding; the twins
//! compute the same quantities by other routes in SI with m = 10 mm, which agree to ~10⁻¹⁴.
//! Each index is held to 10⁻⁹ in its own unit (s_a and lengths in m units, ε_α absolute,
//! λ relative to max(1, |λ|)), 1000 times the expected error. The junction's roll
//! √(|J|² − r_b²) loses ε·r²/ρ_l near the base circle: that bound is added where it matters.

use glam::DVec2;
use proptest::prelude::*;
use tmm::gears::blocking::{
    levels, twin_margin, twin_pair, twin_rho_l, Blocking, BlockingStudy, Contour, Criterion, Hard,
    Kind, Studies, CHOICE_MARGIN,
};
use tmm::gears::{BasicRack, Cutting, PairSpec};

/// The module of the twins' pairs, m.
pub(crate) const M: f64 = 0.01;

/// The ГОСТ 13755 rack.
pub(crate) fn gost() -> BasicRack {
    BasicRack::GOST_13755
}

/// The index of `kind` at `x` by the twins, and the tolerance it is held to there.
pub(crate) fn twin_index(b: &Blocking, kind: Kind, x: DVec2) -> (f64, f64) {
    let p = twin_pair(b, M, x).expect("the twin pair");
    match kind {
        Kind::Undercut(i) => {
            // Cutting decides the undercut: the traced x is the flip of its verdict.
            let xi = [x.x, x.y][i];
            let cut = |x: f64| Cutting::alone(M, b.z[i], x, b.rack).expect("a cutting");
            assert!(
                !cut(xi + 2e-9).undercut() && cut(xi - 2e-9).undercut(),
                "z = {}: x = {xi} is not Cutting's undercut limit",
                b.z[i]
            );
            // The textbook's x_min = h_a* − z sin²α/2 differs by 1 − h_l* = 3·10⁻⁵.
            (xi - cut(xi).x_min(), 1e-4)
        }
        Kind::Tip(i) => (p.sa[i] / M, 1e-9),
        Kind::ContactRatio => (p.eps, 1e-9),
        Kind::Interference(i) => {
            let near = if i == 0 {
                p.active_ends()[0]
            } else {
                p.g - p.active_ends()[1]
            };
            let rho = twin_rho_l(&p, i).expect("the junction");
            let r = p.r[i] / M;
            let tol = 1e-9 + 8.0 * f64::EPSILON * r * r / rho.abs().max(1e-300);
            (near / M - rho, tol)
        }
        Kind::EqualSliding => {
            let ends = p.active_ends();
            let (l1, l2) = (p.sliding(ends[0])[0], p.sliding(ends[1])[1]);
            (l1 - l2, 1e-9 * l1.abs().max(l2.abs()).max(1.0))
        }
    }
}

/// Check every curve of `c` at up to `per_curve` points; the number of points checked.
fn check_contour(c: &Contour, per_curve: usize) -> usize {
    let b = &c.blocking;
    let mut n = 0;
    for curve in &c.curves {
        let step = (curve.points.len() / per_curve).max(1);
        for p in curve.points.iter().step_by(step) {
            let (v, tol) = twin_index(b, curve.kind, *p);
            let limit = match curve.kind {
                Kind::Undercut(_) => 0.0,
                _ => curve.limit,
            };
            assert!(
                (v - limit).abs() <= tol,
                "z = {:?}: {:?} = {} at ({}, {}): {v} by the twins, off by {:e} > {tol:e}",
                b.z,
                curve.kind,
                curve.limit,
                p.x,
                p.y,
                v - limit
            );
            n += 1;
        }
    }
    n
}

fn contour(z: [u32; 2]) -> Contour {
    Blocking::new(z, gost())
        .expect("a pair")
        .trace(Hard::default())
}

/// The kinds traced (with at least 2 points).
fn traced(c: &Contour, kind: Kind, limit: f64) -> usize {
    c.curves
        .iter()
        .filter(|k| k.kind == kind && k.limit == limit)
        .map(|k| k.points.len())
        .sum()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, failure_persistence: None, ..ProptestConfig::default() })]

    /// On every traced curve of a random pair, its index by the twins equals its limit.
    #[test]
    fn every_traced_curve_is_its_index_at_its_limit(z1 in 8u32..=80, z2 in 8u32..=80) {
        let c = contour([z1, z2]);
        // The undercut and contact ratio's lines are in every window, and most others.
        prop_assert!(traced(&c, Kind::ContactRatio, 1.0) > 10);
        let kinds = levels(&gost(), [z1, z2])
            .into_iter()
            .filter(|(k, l)| traced(&c, *k, *l) > 10)
            .count();
        prop_assert!(kinds >= 8, "only {kinds} levels traced");
        let n = check_contour(&c, 12);
        prop_assert!(n > 60, "only {n} points checked");
    }
}

#[test]
fn thirteen_twenty_one_traces_every_curve() {
    let c = contour([13, 21]);
    for (kind, limit) in levels(&gost(), [13, 21]) {
        assert!(
            traced(&c, kind, limit) > 10,
            "{kind:?} = {limit}: {} points",
            traced(&c, kind, limit)
        );
    }
    assert!(check_contour(&c, 40) > 400);
    assert_eq!(c.boundary.len(), 1, "one piece of region");
}

/// Seed 000's x₁ = 0.8, x₂ = 0.471 on its own pair z 13/30 (the shaper's, where its Δy = 0.18
/// is the exact 0.17983 rounded) and on z 13/21 as issue 21 names it, and PZ3's 0.694, 0.384
/// (z 13/21): their indices equal Pair::new's (with the exact Δy), and where they lie among
/// the isolines.
#[test]
fn the_seeds_points_are_placed() {
    let hard = BlockingStudy::HARD;
    // (z, x, s_a1 between, Δy)
    let cases = [
        ([13, 30], (0.8, 0.471), (0.25, 0.4), Some(0.18)),
        ([13, 21], (0.694, 0.384), (0.4, 1.0), Some(0.160)),
        ([13, 21], (0.8, 0.471), (0.0, 1.0), None),
    ];
    for (z, (x1, x2), (sa_lo, sa_hi), dy) in cases {
        let b = Blocking::new(z, gost()).unwrap();
        let at = DVec2::new(x1, x2);
        let pl = b.place(at, hard).unwrap();
        let p = twin_pair(&b, M, at).unwrap();
        let ix = pl.indices;
        assert!((ix.eps - p.eps).abs() < 1e-12, "ε {} {}", ix.eps, p.eps);
        for i in 0..2 {
            assert!((ix.sa[i] - p.sa[i] / M).abs() < 1e-12);
            assert!((ix.ra[i] - p.ra[i] / M).abs() < 1e-12);
        }
        assert!((ix.alpha_w - p.alpha_w).abs() < 1e-14);
        assert!((ix.dy - p.dy).abs() < 1e-12);
        let l = ix.lambda.unwrap();
        let ends = p.active_ends();
        assert!((l[0] - p.sliding(ends[0])[0]).abs() < 1e-12);
        assert!((l[1] - p.sliding(ends[1])[1]).abs() < 1e-12);
        // The tables' Δy is the exact one rounded.
        if let Some(dy) = dy {
            assert!((ix.dy - dy).abs() < 1e-3, "{z:?}: Δy = {}", ix.dy);
        }
        let side = |kind: Kind, limit: f64| {
            pl.sides
                .iter()
                .find(|s| s.kind == kind && s.limit == limit)
                .and_then(|s| s.inside)
        };
        eprintln!("{z:?} ({x1}, {x2}): {ix:?} admissible {}", pl.admissible);
        if dy.is_none() {
            continue;
        }
        // Inside the contour of s_a ≥ 0.25m, ε_α ≥ 1; between ε_α = 1 and 1.2; s_a1 between
        // its isolines, s_a2 above 0.4m.
        assert!(pl.admissible, "{z:?} ({x1}, {x2}) {ix:?}");
        assert!(ix.eps > 1.0 && ix.eps < 1.2);
        assert!(
            ix.sa[0] > sa_lo && ix.sa[0] < sa_hi,
            "{z:?}: s_a1 = {}",
            ix.sa[0]
        );
        assert!(ix.sa[1] > 0.4);
        assert_eq!(side(Kind::ContactRatio, 1.2), Some(false));
        assert_eq!(side(Kind::ContactRatio, 1.0), Some(true));
        assert_eq!(side(Kind::Interference(0), 0.0), Some(true));
        assert_eq!(side(Kind::Interference(1), 0.0), Some(true));
        assert_eq!(side(Kind::Undercut(0), b.x_min(0)), Some(true));
        assert_eq!(side(Kind::Tip(0), 0.4), Some(sa_lo >= 0.4));
        // With ε_α ≥ 1.2 the seeds' points are outside.
        assert!(!b.place(at, Hard::default()).unwrap().admissible);
    }
}

/// Each criterion's choice lies `CHOICE_MARGIN` inside every hard limit by the twins, and is
/// best against a brute-force grid of the region that far inside; equal sliding holds by
/// Pair::new.
#[test]
fn the_choices_are_admissible_and_best() {
    for z in [[13, 21], [8, 30], [20, 20], [17, 60]] {
        let b = Blocking::new(z, gost()).unwrap();
        let hard = BlockingStudy::HARD;
        let inset = Hard {
            inset: CHOICE_MARGIN,
            ..hard
        };
        let (lo, hi) = b.window;
        let n = 120;
        let grid: Vec<DVec2> = (0..=n)
            .flat_map(|i| {
                (0..=n).map(move |j| {
                    DVec2::new(
                        lo.x + (hi.x - lo.x) * f64::from(i) / f64::from(n),
                        lo.y + (hi.y - lo.y) * f64::from(j) / f64::from(n),
                    )
                })
            })
            .filter(|p| b.margin(*p, inset).is_some_and(|m| m >= 0.0))
            .collect();
        assert!(
            grid.len() > 50,
            "{z:?}: {} admissible grid points",
            grid.len()
        );
        let best = |f: &dyn Fn(DVec2) -> f64| grid.iter().map(|p| f(*p)).fold(f64::MIN, f64::max);
        // The choice's margin by the twins: CHOICE_MARGIN inside every limit.
        let inside = |at: DVec2, h: Hard| {
            let m = twin_margin(&b, M, h, at).expect("the twins");
            assert!(m >= -1e-9, "{z:?} {at}: {m}");
        };
        let eps = |p: DVec2| twin_pair(&b, M, p).unwrap().eps;
        let c = b.choose(Criterion::LargestContactRatio, hard).unwrap();
        let at = DVec2::from(c.indices.x);
        inside(at, inset);
        assert!(!c.on.is_empty(), "{z:?}: on no limit");
        assert!(
            eps(at) >= best(&eps) - 1e-9,
            "{z:?}: {} < {}",
            eps(at),
            best(&eps)
        );
        let sum = |p: DVec2| p.x + p.y;
        let c = b
            .choose(Criterion::GreatestSumWithTip { sa_min: 0.4 }, hard)
            .unwrap();
        let at = DVec2::from(c.indices.x);
        let h4 = Hard {
            sa_min: 0.4,
            ..inset
        };
        inside(at, h4);
        let best4 = grid
            .iter()
            .filter(|p| b.margin(**p, h4).is_some_and(|m| m >= 0.0))
            .map(|p| sum(*p))
            .fold(f64::MIN, f64::max);
        assert!(sum(at) >= best4 - 1e-9, "{z:?}: {} < {best4}", sum(at));
        // Equal sliding on the line through the middle of the admissible grid's sums.
        let mid = grid.iter().map(|p| sum(*p)).sum::<f64>() / grid.len() as f64;
        let c = b
            .choose(Criterion::EqualSliding { x_sum: mid }, hard)
            .unwrap();
        let at = DVec2::from(c.indices.x);
        assert!((sum(at) - mid).abs() < 1e-12);
        inside(at, inset);
        let (v, tol) = twin_index(&b, Kind::EqualSliding, at);
        // Either λ₁ = λ₂ or the line's stretch inside ends first.
        let on_boundary = b.margin(at, inset).unwrap() < 1e-9;
        assert!(v.abs() <= tol || on_boundary, "{z:?}: λ₁ − λ₂ = {v}");
        if z[0] == z[1] {
            assert!((at.x - at.y).abs() < 1e-9, "symmetric: {at}");
        }
    }
}

/// z₁ = z₂: the contour is symmetric — each wheel's curves are the other's mirrored, and
/// equal sliding is the diagonal.
#[test]
fn equal_wheels_give_a_symmetric_contour() {
    let b = Blocking::new([20, 20], gost()).unwrap();
    let c = b.trace(Hard::default());
    let mut n = 0;
    for curve in &c.curves {
        let mirror = match curve.kind {
            Kind::Tip(i) => Kind::Tip(1 - i),
            Kind::Interference(i) => Kind::Interference(1 - i),
            Kind::Undercut(i) => Kind::Undercut(1 - i),
            k => k,
        };
        for p in curve.points.iter().step_by(7) {
            let q = DVec2::new(p.y, p.x);
            let v = b.indices(q).unwrap().of(mirror).unwrap();
            let w = b.indices(*p).unwrap().of(curve.kind).unwrap();
            assert!((v - w).abs() < 1e-9, "{:?} at {p}: {v} vs {w}", curve.kind);
            if curve.kind == Kind::EqualSliding {
                assert!((p.x - p.y).abs() < 1e-9, "{p}");
            }
            n += 1;
        }
    }
    assert!(n > 100);
    assert!(traced(&c, Kind::EqualSliding, 0.0) > 20);
}

/// z₁ = 8: the undercut limit binds — the admissible region's left edge is x₁ = x_min,1.
#[test]
fn eight_teeth_are_bound_by_undercut() {
    let b = Blocking::new([8, 40], gost()).unwrap();
    let c = b.trace(BlockingStudy::HARD);
    let xmin = b.x_min(0);
    assert!(xmin > 0.5);
    let on = c
        .boundary
        .iter()
        .flatten()
        .filter(|p| (p.x - xmin).abs() < 1e-9)
        .count();
    assert!(on > 30, "{on} boundary points on x₁ = x_min1 = {xmin}");
    let ch = b.choose(Criterion::LargestContactRatio, c.hard).unwrap();
    assert!(ch.indices.x[0] >= xmin + CHOICE_MARGIN - 1e-9);
    assert!(check_contour(&c, 20) > 100);
}

/// z₂ = 200 and the least tooth numbers trace without panic; z₂ = 200's curves hold.
#[test]
fn extreme_tooth_numbers() {
    let c = contour([13, 200]);
    assert!(check_contour(&c, 12) > 50);
    for z in [[5, 5], [5, 200], [200, 200], [7, 9]] {
        let b = Blocking::new(z, gost()).unwrap();
        let c = b.trace(Hard::default());
        for curve in &c.curves {
            assert!(curve.points.iter().all(|p| p.is_finite()));
        }
        for cr in [
            Criterion::LargestContactRatio,
            Criterion::GreatestSumWithTip { sa_min: 0.25 },
            Criterion::EqualSliding { x_sum: 0.5 },
        ] {
            // A choice or a diagnosis, never a panic.
            let _ = b.choose(cr, Hard::default());
        }
    }
    assert!(Blocking::new([4, 20], gost()).is_err());
    let b = Blocking::new([13, 21], gost()).unwrap();
    assert!(b.place(DVec2::new(f64::NAN, 0.0), Hard::default()).is_err());
    assert!(b.place(DVec2::new(-40.0, -40.0), Hard::default()).is_err());
    assert!(b
        .choose(
            Criterion::EqualSliding {
                x_sum: f64::INFINITY
            },
            Hard::default()
        )
        .is_err());
}

/// A point exactly on a traced curve is placed on it: its index is the limit.
#[test]
fn a_point_on_a_curve_is_placed_at_its_limit() {
    let b = Blocking::new([13, 21], gost()).unwrap();
    let c = b.trace(Hard::default());
    let curve = c
        .curves
        .iter()
        .find(|k| k.kind == Kind::Tip(0) && k.limit == 0.25)
        .unwrap();
    let p = curve.points[curve.points.len() / 2];
    let pl = b.place(p, Hard::default()).unwrap();
    let side = pl
        .sides
        .iter()
        .find(|s| s.kind == Kind::Tip(0) && s.limit == 0.25)
        .unwrap();
    assert!((side.value - 0.25).abs() < 1e-12, "{}", side.value);
    let (v, _) = twin_index(&b, Kind::Tip(0), p);
    assert!((v - 0.25).abs() < 1e-9);
    // A step of 10⁻⁶ across it changes the side.
    let d = 1e-6;
    let a = b.indices(p + DVec2::new(d, 0.0)).unwrap().sa[0];
    let bb = b.indices(p - DVec2::new(d, 0.0)).unwrap().sa[0];
    assert!(a < 0.25 && bb > 0.25);
}

/// A kept study is the study of the pair asked for: two pairs asked in turn each get their
/// own, the same as traced afresh, and a choice by the same criterion shares the traced
/// boundary without moving it (the choice as `Blocking::choose` makes it on its own).
#[test]
fn a_kept_study_is_the_pairs_own_and_its_choices_those_made_alone() {
    let spec = |z: [u32; 2], x: [f64; 2]| PairSpec {
        module: M,
        z,
        x,
        rack: gost(),
        dy_table: None,
    };
    let (a, b) = (spec([13, 27], [0.5, 0.3]), spec([17, 40], [0.3, 0.1]));
    let kept = Studies::default();
    let first = kept.of(&a, None).unwrap();
    let other = kept.of(&b, None).unwrap();
    assert_ne!(first.contour.blocking.z, other.contour.blocking.z);
    assert_eq!(kept.of(&a, None).unwrap(), first);
    assert_eq!(
        Studies::default().of(&a, None).unwrap(),
        first,
        "traced afresh, the same"
    );
    assert_eq!(
        BlockingStudy::of(&a, None).unwrap(),
        first,
        "traced alone, the same"
    );
    let alone = Blocking::new(a.z, a.rack).unwrap();
    for (criterion, chosen) in &first.choices {
        let own = alone.choose(*criterion, BlockingStudy::HARD);
        match (chosen, own) {
            (Ok(c), Ok(o)) => {
                // The maximisers' objective is flat at its top: the same point to the
                // golden sections' reach (on PZ3's pair, the grid's boundary taken from the
                // fan moved the greatest x_Σ's s_a by 5e-8 of itself; here nothing moves).
                let d = DVec2::from(c.indices.x).distance(DVec2::from(o.indices.x));
                assert!(d < 1e-7, "{criterion:?}: {d}");
            }
            (c, o) => assert_eq!(c.is_ok(), o.is_ok(), "{criterion:?}"),
        }
    }
}
