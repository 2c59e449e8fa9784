//! The unit vector (cos a, sin a) of an angle where speed counts: the analytic kernel's
//! first step, which every other waits on. The `libm` crate's `sincos` (musl's, in Rust):
//! the system libm's, called through the dynamic linker with every vector register spilled
//! around it, cost the kernel a third of its time (docs/bench.md, 2026-12-08). Within an
//! ulp of the system's, bit for bit for most angles.

use glam::DVec2;

/// (cos a, sin a).
#[inline]
pub fn unit_at(a: f64) -> DVec2 {
    let (sin, cos) = libm::sincos(a);
    DVec2::new(cos, sin)
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
        assert!(unit_at(f64::NAN).x.is_nan() && unit_at(f64::INFINITY).y.is_nan());
    }

    #[test]
    fn a_million_angles_within_seven_radians_are_within_an_ulp_of_the_system_libm() {
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
        fn every_angle_is_within_two_ulps_of_the_system_libm(a in -1e9f64..1e9) {
            let (s, c) = a.sin_cos();
            let e = unit_at(a);
            // Each component within two of its own ulps, or (near zero) of the vector's.
            let near = |x: f64, y: f64| ulps(x, y) <= 2.0 || (x - y).abs() <= 2.0 * f64::EPSILON;
            prop_assert!(near(e.x, c), "{}: cos {} vs {}", a, e.x, c);
            prop_assert!(near(e.y, s), "{}: sin {} vs {}", a, e.y, s);
        }
    }
}
