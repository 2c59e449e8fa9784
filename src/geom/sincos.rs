//! The unit vector (cos a, sin a) of an angle, in line where it is asked for: the analytic
//! kernel's first step, which every other waits on. A call to the libm there cost the
//! kernel a third of its time (through the dynamic linker, every vector register spilled
//! around it; docs/bench.md, 2026-12-08); this is a few products in line.
//!
//! The angle is reduced by the nearest multiple n of π/2, π/2 taken in three parts (the
//! first two of 33 bits, so that n times either is exact for |n| < 2²⁰); the sine and
//! cosine of the remainder r, |r| ≤ π/4, are their Taylor series to r¹⁷ and r¹⁸ (the first
//! term left off is under 10⁻¹⁹), with the remainder's rounding carried as a tail. Within an
//! ulp of the libm's (bit for bit for most angles); beyond |a| = 1.6·10⁶ rad, or NaN, the
//! libm's own.

use glam::DVec2;

/// π/2's first 33 bits.
const PIO2_1: f64 = f64::from_bits(0x3ff9_21fb_5440_0000);
/// π/2 − [`PIO2_1`], its next 33 bits.
const PIO2_2: f64 = f64::from_bits(0x3dd0_b461_1a60_0000);
/// π/2 − [`PIO2_1`] − [`PIO2_2`], rounded.
const PIO2_3: f64 = f64::from_bits(0x3ba3_198a_2e03_7073);
/// 2/π, rounded.
const TWO_OVER_PI: f64 = f64::from_bits(0x3fe4_5f30_6dc9_c883);
/// 1.5·2⁵²: added and taken away, it rounds a double under 2⁵¹ to the nearest integer.
const ROUNDER: f64 = 6_755_399_441_055_744.0;
/// The largest |angle| reduced here: n = |a|·2/π stays under 2²⁰.
const REDUCED_UP_TO: f64 = 1.6e6;

/// The sine series after r: sin r = r + r³·(S₀ + S₁r² + … + S₇r¹⁴), Sₖ = (−1)ᵏ⁺¹/(2k+3)!.
const S: [f64; 8] = [
    -1.0 / 6.0,
    1.0 / 120.0,
    -1.0 / 5_040.0,
    1.0 / 362_880.0,
    -1.0 / 39_916_800.0,
    1.0 / 6_227_020_800.0,
    -1.0 / 1_307_674_368_000.0,
    1.0 / 355_687_428_096_000.0,
];
/// The cosine series after 1 − r²/2: cos r = 1 − r²/2 + r⁴·(C₀ + C₁r² + … + C₇r¹⁴),
/// Cₖ = (−1)ᵏ/(2k+4)!.
const C: [f64; 8] = [
    1.0 / 24.0,
    -1.0 / 720.0,
    1.0 / 40_320.0,
    -1.0 / 3_628_800.0,
    1.0 / 479_001_600.0,
    -1.0 / 87_178_291_200.0,
    1.0 / 20_922_789_888_000.0,
    -1.0 / 6_402_373_705_728_000.0,
];

/// A polynomial of eight coefficients in z, z² and z⁴ given (Estrin's scheme: three levels of
/// products instead of Horner's seven).
#[inline(always)]
fn estrin(k: &[f64; 8], z: f64, z2: f64, z4: f64) -> f64 {
    let low = (k[0] + k[1] * z) + (k[2] + k[3] * z) * z2;
    let high = (k[4] + k[5] * z) + (k[6] + k[7] * z) * z2;
    low + high * z4
}

/// (cos a, sin a).
#[inline(always)]
pub fn unit_at(a: f64) -> DVec2 {
    if a.is_nan() || a.abs() > REDUCED_UP_TO {
        return DVec2::from_angle(a);
    }
    let n = (a * TWO_OVER_PI + ROUNDER) - ROUNDER;
    // The nearest multiple chooses the branch; within it the multiple is a constant, so that
    // the remainder waits on the angle alone, not on n's rounding.
    match n as i64 {
        0 => reduced(a, 0.0),
        1 => reduced(a, 1.0),
        -1 => reduced(a, -1.0),
        2 => reduced(a, 2.0),
        -2 => reduced(a, -2.0),
        3 => reduced(a, 3.0),
        -3 => reduced(a, -3.0),
        4 => reduced(a, 4.0),
        -4 => reduced(a, -4.0),
        _ => reduced(a, n),
    }
}

/// (cos a, sin a) for a = n·π/2 + r, |r| ≤ π/4.
#[inline(always)]
fn reduced(a: f64, n: f64) -> DVec2 {
    // n·PIO2_1 and n·PIO2_2 are exact, a − n·PIO2_1 too (the two within a factor of two of
    // each other, or n = 0); the next difference's rounding is the tail t.
    let high = a - n * PIO2_1;
    let w = n * PIO2_2;
    let r = high - w;
    let t = ((high - r) - w) - n * PIO2_3;
    let z = r * r;
    let z2 = z * z;
    let z4 = z2 * z2;
    let sin = r + (r * z * estrin(&S, z, z2, z4) + t * (1.0 - 0.5 * z));
    // 1 − z/2 rounded (`one`), and what that rounding lost, (1 − one) − z/2 (exact), given
    // back with the series.
    let half = 0.5 * z;
    let one = 1.0 - half;
    let cos = one + (((1.0 - one) - half) + (z2 * estrin(&C, z, z2, z4) - r * t));
    match (n as i64) & 3 {
        0 => DVec2::new(cos, sin),
        1 => DVec2::new(-sin, cos),
        2 => DVec2::new(-cos, -sin),
        _ => DVec2::new(sin, -cos),
    }
}

#[cfg(test)]
mod tests {
    use super::unit_at;
    use proptest::prelude::*;

    /// Distance in ulps between two doubles of one sign (or both near zero).
    fn ulps(a: f64, b: f64) -> f64 {
        (a - b).abs() / (f64::EPSILON * a.abs().max(b.abs()).max(f64::MIN_POSITIVE))
    }

    #[test]
    fn quadrants_and_the_exact_points() {
        assert_eq!(unit_at(0.0), glam::DVec2::new(1.0, 0.0));
        let q = unit_at(std::f64::consts::FRAC_PI_2);
        assert_eq!(q.y, 1.0);
        // cos of the double nearest π/2 is π/2 minus that double: 6.123233995736766e-17.
        assert!(ulps(q.x, 6.123_233_995_736_766e-17) <= 1.0, "{}", q.x);
        let h = unit_at(std::f64::consts::PI);
        assert_eq!(h.x, -1.0);
        assert!(ulps(h.y, 1.224_646_799_147_353_2e-16) <= 1.0, "{}", h.y);
        let e = unit_at(-3.0 * std::f64::consts::FRAC_PI_4);
        assert!(e.x < 0.0 && e.y < 0.0);
    }

    #[test]
    fn far_and_not_finite_angles_take_the_libm() {
        for a in [1e7, -3e9, f64::INFINITY, f64::NAN] {
            let (s, c) = a.sin_cos();
            let e = unit_at(a);
            assert!(e.x.to_bits() == c.to_bits() || (c.is_nan() && e.x.is_nan()));
            assert!(e.y.to_bits() == s.to_bits() || (s.is_nan() && e.y.is_nan()));
        }
    }

    #[test]
    fn a_million_angles_within_seven_radians_are_within_an_ulp_of_the_libm() {
        let mut worst = 0.0f64;
        let mut same = 0usize;
        let steps = 1_000_000;
        for k in 0..steps {
            let a = -7.0 + 14.0 * k as f64 / steps as f64;
            let (s, c) = a.sin_cos();
            let e = unit_at(a);
            // Measured against the larger component: the unit vector's own scale.
            let d = (e.x - c).abs().max((e.y - s).abs()) / f64::EPSILON;
            worst = worst.max(d);
            same += usize::from(e.x == c && e.y == s);
        }
        assert!(worst <= 1.0, "{worst} ulps of the vector");
        assert!(same * 10 >= steps * 9, "{same} of {steps} bit for bit");
    }

    proptest! {
        #[test]
        fn every_reduced_angle_is_within_two_ulps_of_the_libm(a in -1.5e6f64..1.5e6) {
            let (s, c) = a.sin_cos();
            let e = unit_at(a);
            // Each component within two of its own ulps, or (near zero) of the vector's.
            let near = |x: f64, y: f64| ulps(x, y) <= 2.0 || (x - y).abs() <= 2.0 * f64::EPSILON;
            prop_assert!(near(e.x, c), "{}: cos {} vs {}", a, e.x, c);
            prop_assert!(near(e.y, s), "{}: sin {} vs {}", a, e.y, s);
        }
    }
}
