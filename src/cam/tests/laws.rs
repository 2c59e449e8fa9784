//! The motion laws against their own derivatives, the follower's pressure angle against its
//! formula, and translating cams at their exact r_min binding at λ_max (properties).

use super::{ctx, seed000, translating};
use crate::cam::exact;
use crate::cam::follower::Placement;
use crate::cam::motion;
use crate::cam::*;

#[test]
fn laws_are_consistent_with_their_derivatives() {
    let laws = [
        Law::Uniform,
        Law::ConstantAcceleration { ratio: 0.3 },
        Law::Cosine,
        Law::Sine,
        Law::Trapezoidal,
        Law::Polynomial345,
        Law::LinearBlended { blend: 0.2 },
        Law::LinearBlended { blend: 0.05 },
    ];
    for law in laws {
        let (f0, ..) = law.eval(0.0, true);
        let (f1, ..) = law.eval(1.0, false);
        assert!(f0.abs() < 1e-12 && (f1 - 1.0).abs() < 1e-12, "{law:?}");
        let h = 1e-5;
        for k in 1..20 {
            let u = k as f64 / 20.0 + 0.013;
            let (a, ..) = law.eval(u - h, true);
            let (b, d1, _) = law.eval(u, true);
            let (c, ..) = law.eval(u + h, true);
            assert!(((c - a) / (2.0 * h) - d1).abs() < 1e-6, "{law:?} f′ at {u}");
            let (_, e1, _) = law.eval(u - h, true);
            let (_, g1, _) = law.eval(u + h, true);
            let (_, _, d2) = law.eval(u, true);
            assert!(
                ((g1 - e1) / (2.0 * h) - d2).abs() < 1e-4,
                "{law:?} f″ at {u}"
            );
            let _ = b;
        }
    }
    // Linear with blends (seed 001 L1590): the middle at the uniform velocity 1/(1 − b),
    // the blends' acceleration ±1/(b(1 − b)); at b = ½ it is the symmetric "+ −" law.
    for b in [0.05, 0.1, 0.25, 0.4] {
        let l = Law::LinearBlended { blend: b };
        assert_eq!(l.breaks(), vec![b, 1.0 - b]);
        let (_, v, a) = l.eval(0.5, true);
        assert!((v - 1.0 / (1.0 - b)).abs() < 1e-12 && a == 0.0);
        let (_, _, a) = l.eval(b / 2.0, true);
        assert!((a - 1.0 / (b * (1.0 - b))).abs() < 1e-9, "{a}");
    }
    for k in 0..=20 {
        let u = f64::from(k) / 20.0;
        let a = Law::LinearBlended { blend: 0.5 }.eval(u, true);
        let b = Law::ConstantAcceleration { ratio: 0.5 }.eval(u, true);
        assert!(
            (a.0 - b.0).abs() < 1e-12 && (a.1 - b.1).abs() < 1e-12 && (a.2 - b.2).abs() < 1e-12
        );
    }
    // The trapezoidal law with straight ramps over eighths: f(½) = 3A/32 = ½, A = 16/3.
    let (_, _, a) = Law::Trapezoidal.eval(0.25, true);
    assert!((a - 16.0 / 3.0).abs() < 1e-12, "{a}");
}

#[test]
fn placement_pressure_angle_matches_the_formula() {
    let s = translating(Law::Cosine, 0.003);
    let p = Placement::Translating {
        offset: 0.003,
        s0: 0.02,
    };
    for k in 0..20 {
        let phi = k as f64 * 0.1;
        let m = motion::motion(&s, phi, true);
        let want = ((m.ds - 0.003) / (0.02 + m.s)).atan().abs();
        assert!((p.kin(m).pressure_angle() - want).abs() < 1e-12);
    }
}

mod props {
    use super::*;
    use proptest::prelude::*;

    fn law(k: u8, ratio: f64, blend: f64) -> Law {
        match k % 7 {
            0 => Law::Uniform,
            1 => Law::ConstantAcceleration { ratio },
            2 => Law::Cosine,
            3 => Law::Sine,
            4 => Law::Trapezoidal,
            5 => Law::LinearBlended { blend },
            _ => Law::Polynomial345,
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        /// A translating cam at its exact r_min: the largest pressure angle over the cycle
        /// is λ_max (binding, never exceeded); with a piecewise-constant analogue jumping at
        /// the nodes the inversion's roller centres are the exact pitch curve.
        #[test]
        fn translating_cams_bind_at_lambda_max(
            k in 0u8..7, j in 1usize..6, rise in 60f64..150.0, ret in 60f64..150.0,
            far in 0f64..40.0, stroke in 0.01f64..0.06, e in 0f64..0.01, gamma in 45f64..70.0,
            n in 6usize..16,
        ) {
            // The "+ −" law's jump and the blends' ends on nodes: their analogues are
            // integrated exactly.
            let l = law(k, j as f64 / n as f64, j.min(n / 2) as f64 / n as f64);
            let near = 360.0 - rise - ret - far;
            let s = CamSpec {
                phases: Phases {
                    rise: rise.to_radians(),
                    far: far.to_radians(),
                    ret: ret.to_radians(),
                    near: near.to_radians(),
                },
                rise: l,
                ret: l,
                stroke,
                follower: Follower::Translating { offset: e },
                gamma_min: gamma.to_radians(),
                divisions: n,
                quoted_r_min: None,
                poles: None,
                ..seed000()
            };
            let (r, _) = exact::min_radius_translating(&s, e);
            let s = CamSpec { base_radius: Some(r), ..s };
            let cam = build(&s, &ctx(0.0)).unwrap();
            let lmax = (90.0 - gamma).to_radians();
            let worst = cam.worst_angle();
            prop_assert!(worst <= lmax + 1e-6, "{} > {}", worst.to_degrees(), 90.0 - gamma);
            prop_assert!(worst >= lmax - 2e-3, "{} < {}", worst.to_degrees(), 90.0 - gamma);
            if matches!(l, Law::ConstantAcceleration { .. } | Law::Uniform | Law::LinearBlended { .. }) {
                for (g, x) in cam.inversion.centres.iter().zip(cam.exact_centres()) {
                    prop_assert!(g.distance(x) < 1e-9, "{g} vs {x}");
                }
            }
        }
    }
}
