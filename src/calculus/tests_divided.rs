//! Graphical integration over a division that need not be equal: a division point on a
//! jump makes a step exact, unequal intervals keep the midpoint rule's bound, and a bad
//! division is refused.

use super::tests::{layout, recorder, scale};
use super::*;
use crate::scale::Quantity;

/// Integrate the division `d` (drawn at μ_x = 0.01 rad/mm, μ_y = 0.05/mm, H = 25 mm) from 0.
fn integrate_division(d: &Divided) -> Integral {
    let sc = Scales {
        x: scale(0.01, Quantity::Angle),
        y: scale(0.05, Quantity::Length),
    };
    let mut rec = recorder(0.05 * 25.0 * 0.01, 0.0);
    integrate_divided_in(Figures::One(&mut rec), d, sc, 25.0, 0.0, &layout()).expect("integral")
}

/// A step of J = −3 at x = 0.3: with a division point on the jump every interval is
/// constant and the chords are exact; with the jump inside an interval the mid-interval
/// ordinate takes one side for the whole interval, J·(distance of the jump from the middle)
/// off — no finer division removes that from its interval.
#[test]
fn a_division_point_on_a_jump_integrates_a_step_exactly() {
    let f = |x: f64| if x < 0.3 { 1.0 } else { -2.0 };
    let exact = |x: f64| if x < 0.3 { x } else { 0.3 - 2.0 * (x - 0.3) };
    let equal: Vec<f64> = (0..=12).map(|k| k as f64 / 12.0).collect();
    let mut at_jump = equal.clone();
    at_jump.push(0.3);
    at_jump.sort_by(f64::total_cmp);
    let mids = |x: &[f64]| x.windows(2).map(|w| f(0.5 * (w[0] + w[1]))).collect();
    let split = Divided::new(at_jump.clone(), mids(&at_jump)).expect("division");
    let i = integrate_division(&split);
    assert_eq!(i.x, at_jump);
    for (x, v) in i.x.iter().zip(&i.node) {
        assert!((v - exact(*x)).abs() < 1e-12, "at {x}: {v}");
    }
    // 0.3 lies in [0.25, 1/3], its middle 0.2917 < 0.3 takes +1: the end is 3·(1/3 − 0.3)
    // too high.
    let plain = integrate_division(&Divided::new(equal.clone(), mids(&equal)).expect("division"));
    let off = plain.node[12] - exact(1.0);
    assert!((off - 3.0 * (1.0 / 3.0 - 0.3)).abs() < 1e-12, "{off}");
}

/// Unequal intervals over a smooth integrand: the midpoint rule's bound Σ hᵢ³/24·max|y″|
/// holds at every node, and equal ones give what the equal-interval construction gives.
#[test]
fn unequal_intervals_keep_the_midpoint_bound() {
    let x = vec![0.0, 0.1, 0.15, 0.4, 0.45, 0.8, 1.1, 1.2, 1.6];
    let d = Divided::new(
        x.clone(),
        x.windows(2).map(|w| (0.5 * (w[0] + w[1])).cos()).collect(),
    )
    .expect("division");
    let i = integrate_division(&d);
    let mut bound = 0.0;
    for k in 1..x.len() {
        let h = x[k] - x[k - 1];
        bound += h * h * h / 24.0;
        let e = (i.node[k] - x[k].sin()).abs();
        assert!(e <= bound + 1e-12, "node {k}: {e} > {bound}");
    }
    assert!(bound > 1e-4, "the bound is not vacuous: {bound}");
    let equal: Vec<f64> = (0..=10).map(|k| 0.1 * k as f64).collect();
    let mids: Vec<f64> = equal
        .windows(2)
        .map(|w| (0.5 * (w[0] + w[1])).cos())
        .collect();
    let a = integrate_division(&Divided::new(equal, mids.clone()).expect("division"));
    let sc = Scales {
        x: scale(0.01, Quantity::Angle),
        y: scale(0.05, Quantity::Length),
    };
    let mut rec = recorder(0.05 * 25.0 * 0.01, 0.0);
    let src = Diagram::new(0.0, 0.1, mids, false).expect("mids");
    let b = integrate_chords(
        &mut rec,
        &src,
        Sampling::Midpoints,
        sc,
        25.0,
        0.0,
        &layout(),
    )
    .expect("integral");
    for (p, q) in a.node.iter().zip(&b.node) {
        assert!((p - q).abs() < 1e-12, "{p} against {q}");
    }
}

#[test]
fn a_bad_division_is_refused() {
    let x = vec![0.0, 0.5, 1.0];
    assert!(Divided::new(x.clone(), vec![1.0, 2.0]).is_ok());
    assert_eq!(
        Divided::new(x.clone(), vec![1.0]),
        Err(CalculusError::Ordinates {
            intervals: 2,
            ordinates: 1
        })
    );
    assert!(matches!(
        Divided::new(vec![0.0, 0.5, 0.5], vec![1.0, 2.0]),
        Err(CalculusError::BadInterval { .. })
    ));
    assert!(matches!(
        Divided::new(vec![0.0, 1.0], vec![1.0]),
        Err(CalculusError::TooFewIntervals { intervals: 1 })
    ));
    assert!(matches!(
        Divided::new(x, vec![1.0, f64::NAN]),
        Err(CalculusError::NonFinite { index: 1, .. })
    ));
}
