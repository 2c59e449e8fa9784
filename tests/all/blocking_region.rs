//! The blocking contour's region (issue 42 §2) against the twins: every piece of the
//! admissible region in the window traced (random pairs on a dense grid, the pairs whose region
//! goes on beyond a saddle of its limits), the λ₁ = λ₂ line drawn whole across it, every
//! choice a working pair with finite indices, and GearPair::working clear of the fillets.
//!
//! Admissible by the twins is [`twin_margin`] ≥ 0: GearPair::new and Cutting, never the contour's
//! own formulas, so a wrong tracing shows. A grid point may fall either way within the grid's
//! spacing of the traced boundary (a piece narrower than the tracing grid's spacing, 0.02,
//! may be missed).

use crate::blocking::{gost, twin_index, M};
use glam::DVec2;
use proptest::prelude::*;
use tmm::gears::blocking::{
    distance_to, twin_margin, twin_pair, twin_rho_l, twin_value, Blocking, BlockingStudy, Contour,
    Criterion, Hard, Kind,
};
use tmm::gears::PairSpec;

/// The region of `c` against the twins on an n × n grid of its window: the points whose
/// admissibility by the twins ([`twin_margin`]: GearPair::new, Cutting) differs from the traced
/// region's, farther than the grid's spacing from its boundary (and the points checked, the
/// admissible ones among them).
fn region_against_twins(c: &Contour, n: u32) -> (Vec<DVec2>, usize, usize) {
    let b = &c.blocking;
    let (lo, hi) = b.window;
    let step = (hi - lo) / f64::from(n);
    let near = step.max_element();
    let mut wrong = Vec::new();
    let (mut checked, mut admissible) = (0, 0);
    for i in 0..=n {
        for j in 0..=n {
            let p = lo + step * DVec2::new(f64::from(i), f64::from(j));
            let twin = twin_margin(b, M, c.hard, p).is_some_and(|m| m >= 0.0);
            checked += 1;
            admissible += usize::from(twin);
            if twin != c.contains(p) && distance_to(&c.boundary, p) > near {
                wrong.push(p);
            }
        }
    }
    (wrong, checked, admissible)
}

/// The least of the hard limits' indices less their limits at `x` by the twins
/// ([`twin_value`]), and the tolerance of the limit it is: 10⁻⁹, and for interference the
/// junction's roll's loss near the base circle, 8ε·r²/ρ_l (see the module's doc).
fn twin_least(b: &Blocking, hard: Hard, x: DVec2) -> (f64, f64) {
    let p = twin_pair(b, M, x).expect("the twin pair");
    b.hard_levels(hard)
        .into_iter()
        .map(|(kind, limit)| {
            let v = twin_value(b, M, kind, limit, x).expect("the twins");
            let tol = match kind {
                Kind::Interference(i) => {
                    let rho = twin_rho_l(&p, i).expect("the junction");
                    let r = p.r[i] / M;
                    1e-9 + 8.0 * f64::EPSILON * r * r / rho.abs().max(1e-300)
                }
                _ => 1e-9,
            };
            (v, tol)
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .expect("seven limits")
}

/// The ends of every piece of λ₁ = λ₂ that enters the region lie outside it (by the twins)
/// or on its boundary: the line is drawn whole across the region. The pieces that enter it.
fn sliding_line_crosses(c: &Contour, near: f64) -> usize {
    let b = &c.blocking;
    let mut crossing = 0;
    for curve in c.curves.iter().filter(|k| k.kind == Kind::EqualSliding) {
        if !curve.points.iter().any(|p| c.contains(*p)) {
            continue;
        }
        crossing += 1;
        let ends = [curve.points[0], curve.points[curve.points.len() - 1]];
        for e in ends {
            let inside = twin_margin(b, M, c.hard, e).is_some_and(|m| m > 0.0);
            assert!(
                !inside || distance_to(&c.boundary, e) <= near,
                "z = {:?}: λ₁ = λ₂ ends at {e} inside the region",
                b.z
            );
        }
    }
    crossing
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 20, failure_persistence: None, ..ProptestConfig::default() })]

    /// Random pairs z₁, z₂ ∈ [8, 100]: on a 90 × 90 grid of the window, every point the
    /// twins find admissible lies inside the traced region and every point inside it is
    /// admissible, but within the grid's spacing of the traced boundary; every point of the
    /// boundary on a limit is on it by the twins (to 1e-9); the λ₁ = λ₂ line reaches the
    /// region's boundary at both ends.
    #[test]
    fn the_traced_region_is_the_twins_admissible_region(z1 in 8u32..=100, z2 in 8u32..=100) {
        let b = Blocking::new([z1, z2], gost()).expect("a pair");
        let c = b.trace(BlockingStudy::HARD);
        let (wrong, checked, admissible) = region_against_twins(&c, 90);
        prop_assert!(wrong.is_empty(), "z = {:?}: {} of {checked} points misplaced: {:?}", [z1, z2], wrong.len(), &wrong[..wrong.len().min(5)]);
        prop_assert!(c.boundary.is_empty() == (admissible == 0));
        let (lo, hi) = b.window;
        for p in c.boundary.iter().flatten() {
            let edge = p.x == lo.x || p.y == lo.y || p.x >= hi.x || p.y >= hi.y;
            if !edge {
                let (m, tol) = twin_least(&b, c.hard, *p);
                prop_assert!(m.abs() <= tol, "z = {:?}: {p} off its limit by {m} > {tol}", [z1, z2]);
            }
        }
        let near = ((hi - lo) / 90.0).max_element();
        sliding_line_crosses(&c, near);
    }
}

/// The pairs of issue 42: beyond a saddle of the limit curves the region goes on — 58/60
/// (three pieces), 75/77, 30/80 — and every piece is traced (against the twins on a dense
/// grid); the line x₁ + x₂ = −1.14, which crosses the piece beyond the saddle on 58/60, has
/// its equal-sliding choice there; the λ₁ = λ₂ line crosses the region whole on PZ3's pair
/// and on 58/60.
#[test]
fn the_region_beyond_a_saddle_is_traced() {
    for (z, pieces) in [([58, 60], 3), ([75, 77], 3), ([30, 80], 2), ([11, 54], 2)] {
        let b = Blocking::new(z, gost()).unwrap();
        let c = b.trace(BlockingStudy::HARD);
        assert_eq!(c.boundary.len(), pieces, "{z:?}");
        let (wrong, _, admissible) = region_against_twins(&c, 150);
        assert!(
            wrong.is_empty(),
            "{z:?}: {:?}",
            &wrong[..wrong.len().min(5)]
        );
        assert!(admissible > 1000, "{z:?}: {admissible}");
    }
    let b = Blocking::new([58, 60], gost()).unwrap();
    let c = b
        .choose(
            Criterion::EqualSliding { x_sum: -1.14 },
            BlockingStudy::HARD,
        )
        .expect("the line crosses the region");
    // No λ₁ = λ₂ on the line's stretch inside: its end of the least |λ₁ − λ₂|, on a limit.
    let (v, tol) = twin_index(&b, Kind::EqualSliding, DVec2::from(c.indices.x));
    assert!(v.abs() <= tol || !c.on.is_empty(), "λ₁ − λ₂ = {v}");
    assert!(
        c.indices.x[1] < -1.4,
        "beyond the saddle: {:?}",
        c.indices.x
    );
    for z in [[13, 21], [58, 60]] {
        let c = contour_of(z);
        assert!(sliding_line_crosses(&c, 1e-9) >= 1, "{z:?}");
    }
}

fn contour_of(z: [u32; 2]) -> Contour {
    Blocking::new(z, gost()).unwrap().trace(BlockingStudy::HARD)
}

/// The largest ε_α of 17 pairs (it lay where the mate's tip reaches N₁ on 7 of them, λ₁(B₁)
/// = −1.2·10⁹ on the shaper's 13/30) and the other choices: every index finite, |λ| < 100,
/// the pair works (GearPair::working) and the twins' x of the limits it lies on is the choice's
/// to 1e-9.
#[test]
fn every_choice_is_a_working_pair() {
    let pairs = [
        [13, 30],
        [20, 40],
        [13, 21],
        [12, 18],
        [17, 17],
        [8, 30],
        [10, 50],
        [14, 28],
        [18, 72],
        [25, 50],
        [30, 76],
        [40, 41],
        [9, 12],
        [16, 80],
        [22, 23],
        [35, 90],
        [50, 52],
    ];
    for z in pairs {
        let b = Blocking::new(z, gost()).unwrap();
        for criterion in [
            Criterion::LargestContactRatio,
            Criterion::GreatestSumWithTip { sa_min: 0.25 },
            Criterion::EqualSliding { x_sum: 0.5 },
        ] {
            let Ok(c) = b.choose(criterion, BlockingStudy::HARD) else {
                assert!(
                    matches!(criterion, Criterion::EqualSliding { .. }),
                    "{z:?} {criterion:?}"
                );
                continue;
            };
            let ix = c.indices;
            let l = ix.lambda.expect("λ at both ends");
            assert!(
                l.iter().all(|v| v.is_finite() && v.abs() < 100.0),
                "{z:?} {criterion:?}: λ = {l:?}"
            );
            assert!(ix.eps.is_finite() && ix.sa.iter().all(|s| s.is_finite()));
            let spec = PairSpec {
                module: M,
                z,
                x: ix.x,
                rack: gost(),
                dy_table: None,
            };
            if let Err(e) = tmm::gears::GearPair::working(spec) {
                panic!("{z:?} {criterion:?} at {:?}: {e}", ix.x);
            }
            let twin = c.twin_x(&b, M).expect("the twins settle");
            assert!(
                twin.distance(DVec2::from(ix.x)) < 1e-9,
                "{z:?} {criterion:?}: {twin} against {:?}",
                ix.x
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, failure_persistence: None, ..ProptestConfig::default() })]

    /// GearPair::working against the contour's own interference index (N_iB_i − ρ_l,i, the flank's
    /// end's roll): a pair it accepts has the mate's tip at or above both flanks' ends, and a
    /// wheel without undercut whose index is negative is refused as interference with its
    /// fillet (an undercut wheel's junction lies higher still: refused or not, never accepted
    /// below its flank's end).
    #[test]
    fn working_pairs_keep_clear_of_the_fillets(
        z1 in 8u32..=100, z2 in 8u32..=100, x1 in -1.5f64..1.5, x2 in -1.5f64..1.5,
    ) {
        let z = [z1, z2];
        let b = Blocking::new(z, gost()).expect("a pair");
        let at = DVec2::new(x1, x2);
        let Some(ix) = b.indices(at) else { return Ok(()) };
        let spec = PairSpec { module: M, z, x: [x1, x2], rack: gost(), dy_table: None };
        let index = |i: usize| ix.of(Kind::Interference(i)).expect("an index");
        match tmm::gears::GearPair::working(spec) {
            Ok(_) => {
                for i in 0..2 {
                    prop_assert!(index(i) >= -1e-9, "{z:?} {at}: wheel {} at {}", i + 1, index(i));
                }
            }
            Err(tmm::gears::GearError::FilletInterference { wheel, depth_mm, .. }) => {
                prop_assert!(depth_mm > 0.0);
                let i = wheel - 1;
                if [x1, x2][i] >= b.x_min(i) {
                    prop_assert!(index(i) < 1e-9, "{z:?} {at}: wheel {wheel} refused at {}", index(i));
                }
            }
            Err(_) => {}
        }
    }
}
