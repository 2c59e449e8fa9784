//! The cam's exact twins against independent dense evaluations written here (issue 17):
//! r_min of every follower kind (translating with offsets of both signs, rocker of both
//! senses and both closures, flat face) to 1e-9 relative on random laws, phases, offsets and
//! senses; the one rule at the ends of the phases for every law; the pitch curve's ρ_min to
//! 1e-12 with the roller at it (a cusp) or just over it (an undercut) reported.
//!
//! Nothing here calls the code's searches: the law is read through `Law::eval` only (the
//! closed form), the phases, the checked part of the cycle, the kinematics (the rocker's
//! common normal through the instant centre P₁₂ by Kennedy's theorem) and the extremum
//! searches are the test's own.

use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, TAU};
use tmm::cam::{
    build, exact, motion, CamLayout, CamSpec, Closure, Follower, Given, Law, Phases, RockerSense,
    Rotation,
};
use tmm::check::{Cusp, Finding};
use tmm::construct::{Context, Drafting};
use tmm::geom::DVec2;

/// Samples per moving phase of the dense evaluations (the 200 001).
const DENSE: usize = 200_000;

fn law(k: u8, ratio: f64) -> Law {
    match k % 6 {
        0 => Law::Uniform,
        1 => Law::ConstantAcceleration { ratio },
        2 => Law::Cosine,
        3 => Law::Sine,
        4 => Law::Trapezoidal,
        _ => Law::Polynomial345,
    }
}

/// A task: phases in degrees [rise, far, return] (near = the rest), one law each way.
#[allow(clippy::too_many_arguments)]
pub(crate) fn spec(
    deg: [f64; 3],
    rise: Law,
    ret: Law,
    stroke: f64,
    follower: Follower,
    gamma_deg: f64,
    force: bool,
) -> CamSpec {
    let near = 360.0 - deg[0] - deg[1] - deg[2];
    CamSpec {
        phases: Phases {
            rise: deg[0].to_radians(),
            far: deg[1].to_radians(),
            ret: deg[2].to_radians(),
            near: near.max(0.0).to_radians(),
        },
        rise,
        ret,
        stroke,
        follower,
        roller: Some(0.0),
        gamma_min: gamma_deg.to_radians(),
        rho_min: 0.002,
        base_radius: None,
        divisions: 12,
        scale_s: None,
        scale_l: None,
        scale_phi: None,
        poles: None,
        law_assumed: false,
        quoted_r_min: None,
        closure: if force {
            Closure::Force
        } else {
            Closure::Geometric
        },
        given: Given::D2s,
        rotation: Rotation::Ccw,
        layout: CamLayout::Turning,
    }
}

/// (S, S′, S″) of the test's own: phase `p` (0 rise, 1 far, 2 return, 3 near) at u, the law
/// evaluated on `side` (true: after a jump).
fn law_motion(s: &CamSpec, p: usize, u: f64, side: bool) -> (f64, f64, f64) {
    let h = s.stroke;
    match p {
        0 => {
            let l = s.phases.rise;
            let (f, f1, f2) = s.rise.eval(u, side);
            (h * f, h * f1 / l, h * f2 / (l * l))
        }
        2 => {
            let l = s.phases.ret;
            let (f, f1, f2) = s.ret.eval(u, side);
            (h * (1.0 - f), -h * f1 / l, -h * f2 / (l * l))
        }
        1 => (h, 0.0, 0.0),
        _ => (0.0, 0.0, 0.0),
    }
}

/// The samples (phase, u, side) of the test's dense evaluation: every moving phase at
/// `n` intervals with its ends on its own side, both sides of every inner jump; the dwells
/// of non-zero length once. `rise_only`: the rise alone.
fn samples(s: &CamSpec, n: usize, rise_only: bool) -> Vec<(usize, f64, bool)> {
    let mut out = Vec::new();
    for (p, law, len) in [
        (0usize, Some(s.rise), s.phases.rise),
        (1, None, s.phases.far),
        (2, Some(s.ret), s.phases.ret),
        (3, None, s.phases.near),
    ] {
        if len <= 0.0 || (rise_only && p != 0) {
            continue;
        }
        let Some(law) = law else {
            out.push((p, 0.5, true));
            continue;
        };
        for i in 0..=n {
            out.push((p, i as f64 / n as f64, i < n));
        }
        if let Law::ConstantAcceleration { ratio } = law {
            out.push((p, ratio, false));
            out.push((p, ratio, true));
        }
    }
    out
}

/// The largest of f over the samples.
fn dense_max(s: &CamSpec, rise_only: bool, f: impl Fn((f64, f64, f64)) -> f64) -> f64 {
    samples(s, DENSE, rise_only)
        .into_iter()
        .map(|(p, u, side)| f(law_motion(s, p, u, side)))
        .fold(f64::NEG_INFINITY, f64::max)
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    /// Translating roller / knife edge, offsets of both signs, both closures: the pressure
    /// angle tan λ = |S′ − e|/(s₀ + S) ≤ tan(90° − γ_min) on the checked part of the cycle
    /// gives s₀ ≥ |S′ − e|·tan γ_min − S; r_min = √(e² + s₀²).
    #[test]
    fn translating_r_min_is_the_true_minimum(
        k in 0u8..6, kr in 0u8..6, ratio in 0.1f64..0.9, rise in 40f64..170.0,
        far in prop_oneof![Just(0.0), 0f64..60.0], ret in 40f64..150.0,
        stroke in 0.005f64..0.06, e in -0.02f64..0.02, gamma in 30f64..75.0,
        force in any::<bool>(), near_zero in any::<bool>(),
    ) {
        let ret = if near_zero { 360.0 - rise - far } else { ret.min(359.0 - rise - far) };
        prop_assume!(ret >= 20.0);
        let s = spec([rise, far, ret], law(k, ratio), law(kr, 1.0 - ratio), stroke,
            Follower::Translating { offset: e }, gamma, force);
        let t = s.gamma_min.tan();
        let s0 = dense_max(&s, force, |(sv, ds, _)| (ds - e).abs() * t - sv).max(0.0);
        let want = e.hypot(s0);
        let (got, _) = exact::min_radius_translating(&s, e);
        // As for the flat face below: never below the samples, above them by the sampling
        // error at most.
        let tol = 1e-9 * stroke.max(want);
        prop_assert!(got >= want - 1e-3 * tol && got - want <= tol, "r_min {got} against {want}");
        // At that radius the largest pressure angle is λ_max (to rounding).
        let lmax = FRAC_PI_2 - s.gamma_min;
        let worst = dense_max(&s, force, |(sv, ds, _)| ((ds - e).abs() / (s0 + sv)).atan());
        prop_assert!(worst <= lmax + 1e-9, "{worst} > {lmax}");
    }

    /// Flat face: convexity r₀ + S + S″ ≥ ρ_min over the whole cycle, both sides of every
    /// jump of S″ (the "+ −" law's inside its phase, anywhere).
    #[test]
    fn flat_face_r_min_is_the_true_minimum(
        k in 0u8..6, kr in 0u8..6, ratio in 0.05f64..0.95, rise in 40f64..170.0,
        far in 0f64..60.0, ret in 40f64..150.0, stroke in 0.005f64..0.06,
        e in -0.01f64..0.01,
    ) {
        let ret = ret.min(359.0 - rise - far);
        prop_assume!(ret >= 20.0);
        let s = spec([rise, far, ret], law(k, ratio), law(kr, ratio), stroke,
            Follower::Flat { offset: e }, 60.0, false);
        let worst = dense_max(&s, false, |(sv, _, a)| -(sv + a));
        let want = worst.max(0.0) + s.rho_min;
        let (got, w) = exact::min_radius_flat(&s);
        // The twin refines every local maximum, the oracle only samples: the twin is never
        // below the samples (to rounding), and above them by the sampling error at most,
        // which scales with the stroke as much as with r_min (r_min 2.3 mm with a 58.5 mm
        // stroke came out 2.6e-12 m, 1.1e-9 relative, above the samples).
        let tol = 1e-9 * stroke.max(want);
        prop_assert!(
            got >= want - 1e-3 * tol && got - want <= tol,
            "r_min {got} against {want}"
        );
        // The worst −(S + S″) may be a cancellation near 0: to 1e-9 of the stroke.
        prop_assert!(
            (w - worst).abs() <= 1e-9 * worst.abs().max(stroke),
            "max −(S + S″) {w} against {worst}"
        );
    }
}

/// The rocker's transmission condition of the test's own: cam centre `o`, pivot O₂ at the
/// origin, A = L(cos ψ, sin ψ), ψ = 90° + σS/L. The common normal passes through A and the
/// instant centre P₁₂ = O/(1 − q), q = ω₂/ω₁ = σS′/L (Kennedy), so it is ∥ O − (1 − q)A;
/// A moves ⊥ O₂A. Returns |cos(normal, velocity)| − sin γ_min (≥ 0: admissible).
fn rocker_margin(s: &CamSpec, arm: f64, sigma: f64, o: DVec2, m: (f64, f64, f64)) -> f64 {
    let (sv, ds, _) = m;
    let psi = FRAC_PI_2 + sigma * sv / arm;
    let a = DVec2::new(psi.cos(), psi.sin()) * arm;
    let q = sigma * ds / arm;
    let n = o - a * (1.0 - q);
    let v = DVec2::new(-a.y, a.x);
    (n.dot(v) / (n.length() * v.length())).abs() - s.gamma_min.sin()
}

/// The smallest margin over the checked part of the cycle at `n` samples per phase.
fn rocker_worst(s: &CamSpec, arm: f64, sigma: f64, o: DVec2, n: usize) -> f64 {
    samples(s, n, s.closure == Closure::Force)
        .into_iter()
        .map(|(p, u, side)| rocker_margin(s, arm, sigma, o, law_motion(s, p, u, side)))
        .fold(f64::INFINITY, f64::min)
}

/// The smallest margin over the checked part of the cycle to rounding: [`rocker_worst`] at
/// 2000 samples per phase, then every sampled local minimum of each smooth piece refined.
fn rocker_worst_refined(s: &CamSpec, arm: f64, sigma: f64, o: DVec2) -> f64 {
    let mut worst = rocker_worst(s, arm, sigma, o, 2000);
    for (p, law) in [(0usize, s.rise), (2, s.ret)] {
        if s.closure == Closure::Force && p == 2 {
            continue;
        }
        let spans = match law {
            Law::ConstantAcceleration { ratio } => vec![(0.0, ratio), (ratio, 1.0)],
            _ => vec![(0.0, 1.0)],
        };
        for (a, b) in spans {
            // Inside the piece the side does not matter; its ends are sampled above.
            let f =
                |u: f64| -rocker_margin(s, arm, sigma, o, law_motion(s, p, u.clamp(a, b), u < b));
            let n = 2000;
            let xs: Vec<f64> = (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
            let vs: Vec<f64> = xs.iter().map(|&x| f(x)).collect();
            for i in 0..=n {
                let up = (i == 0 || vs[i] >= vs[i - 1]) && (i == n || vs[i] >= vs[i + 1]);
                if up {
                    let (lo, hi) = (xs[i.saturating_sub(1)], xs[(i + 1).min(n)]);
                    worst = worst.min(-search_max(lo, hi, 2, f));
                }
            }
        }
    }
    worst
}

/// Golden-section maximum of f on [a, b] after `n` samples (the best sample's neighbours).
fn search_max(a: f64, b: f64, n: usize, f: impl Fn(f64) -> f64) -> f64 {
    let xs: Vec<f64> = (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
    let (i, mut best) =
        xs.iter()
            .map(|&x| f(x))
            .enumerate()
            .fold(
                (0, f64::NEG_INFINITY),
                |m, (i, v)| if v > m.1 { (i, v) } else { m },
            );
    let (mut lo, mut hi) = (xs[i.saturating_sub(1)], xs[(i + 1).min(n)]);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..80 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        let (f1, f2) = (f(x1), f(x2));
        best = best.max(f1).max(f2);
        if f1 >= f2 {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    best
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(14))]

    /// Rocker, both senses, both closures: the centre found is admissible at 200 000
    /// samples per phase, and no point 1e-9 nearer A₀ is admissible — neither near it (the
    /// best over the directions around it, refined) nor anywhere (a coarse scan of every
    /// direction up to 0.99·r_min).
    #[test]
    fn rocker_r_min_is_the_true_minimum(
        k in 0u8..6, kr in 0u8..6, ratio in 0.1f64..0.9, rise in 60f64..160.0,
        far in 0f64..40.0, ret in 60f64..150.0, arm in 0.05f64..0.2, swing in 10f64..30.0,
        gamma in 40f64..65.0, same in any::<bool>(), force in any::<bool>(),
    ) {
        let ret = ret.min(359.0 - rise - far);
        prop_assume!(ret >= 40.0);
        let s = spec([rise, far, ret], law(k, ratio), law(kr, ratio),
            arm * swing.to_radians(), Follower::Rocker { arm, sense: if same { RockerSense::Same } else { RockerSense::Opposite } }, gamma, force);
        let sigma = if same { 1.0 } else { -1.0 };
        let Some((r, o)) = exact::min_radius_rocker(&s) else {
            return Err(TestCaseError::reject("no centre within reach"));
        };
        let a0 = DVec2::new(0.0, arm);
        prop_assert!(close(o.distance(a0), r, 1e-12));
        let at_o = rocker_worst(&s, arm, sigma, o, DENSE).min(rocker_worst_refined(&s, arm, sigma, o));
        prop_assert!(at_o >= -1e-11, "the centre violates γ_min by {at_o}");
        // Nothing admissible at 1 − 1e-9 of r near the centre's direction.
        let th = (o - a0).y.atan2((o - a0).x);
        let inner = r * (1.0 - 1e-9);
        let best = search_max(th - 0.02, th + 0.02, 100, |t| {
            rocker_worst_refined(&s, arm, sigma, a0 + DVec2::from_angle(t) * inner)
        });
        prop_assert!(best < 0.0, "a point at 1 − 1e-9 of r_min is admissible ({best})");
        // Nor anywhere nearer (coarse).
        for i in 0..180 {
            let dir = DVec2::from_angle(TAU * i as f64 / 180.0);
            for j in 1..=60 {
                let p = a0 + dir * (0.99 * r * j as f64 / 60.0);
                prop_assert!(rocker_worst(&s, arm, sigma, p, 400) < 0.0,
                    "{p} at {} of r_min is admissible", j as f64 / 60.0 * 0.99);
            }
        }
    }
}

/// Every law, random phases and divisions: the first point of a moving phase reports the
/// law at u = 0 (after), the last at u = 1 (before) — never the dwell's zero analogues —
/// and φ one ulp either side of a boundary is on it.
#[test]
fn the_ends_of_every_phase_report_the_phase_side() {
    let mut rng = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 11) as f64 / (1u64 << 53) as f64
    };
    for case in 0..600 {
        let rise = 20.0 + 150.0 * next();
        let far = 60.0 * next();
        let ret = if case % 5 == 0 {
            360.0 - rise - far
        } else {
            20.0 + (340.0 - rise - far - 20.0) * next()
        };
        let n = 2 + (next() * 40.0) as usize;
        let l = law(case as u8, 0.05 + 0.9 * next());
        let mut s = spec(
            [rise, far, ret],
            l,
            l,
            0.03,
            Follower::Translating { offset: 0.0 },
            60.0,
            false,
        );
        s.divisions = n;
        let pts = motion::points(&s);
        // n equal intervals, and a division point on every break of the given d²S/dφ²
        // between the nodes: the "+ −" law's jump, the trapezoidal law's corners.
        let knots = match l {
            Law::ConstantAcceleration { ratio } => vec![ratio],
            Law::Trapezoidal => vec![0.125, 0.375, 0.625, 0.875],
            _ => Vec::new(),
        };
        let off = knots
            .iter()
            .filter(|&&b| ((b * n as f64) - (b * n as f64).round()).abs() > 1e-9 * n as f64)
            .count();
        let per = n + 1 + off;
        assert_eq!(pts.len(), 2 * per, "case {case}: {:?} at n = {n}", l.key());
        for (phase, first) in [(0usize, 0usize), (2, per)] {
            let last = first + per - 1;
            assert!(pts[first].k == 0 && pts[last].last && pts[last].phase == phase);
            let h = s.stroke;
            let len = if phase == 0 {
                s.phases.rise
            } else {
                s.phases.ret
            };
            let sign = if phase == 0 { 1.0 } else { -1.0 };
            for (idx, u, side) in [(first, 0.0, true), (last, 1.0, false)] {
                let (f, f1, f2) = l.eval(u, side);
                let want = (
                    if phase == 0 { h * f } else { h * (1.0 - f) },
                    sign * h * f1 / len,
                    sign * h * f2 / (len * len),
                );
                let p = &pts[idx];
                for phi in [p.phi, p.phi.next_up(), p.phi.next_down()] {
                    let m = motion::motion(&s, phi, p.after);
                    let got = (m.s, m.ds, m.d2s);
                    let ok = (got.0 - want.0).abs() <= 1e-12
                        && (got.1 - want.1).abs() <= 1e-9 * (want.1.abs() + h / len)
                        && (got.2 - want.2).abs() <= 1e-9 * (want.2.abs() + h / (len * len));
                    assert!(
                        ok,
                        "case {case}: {:?} point {idx} at φ {phi}: {got:?} against {want:?}",
                        l.key()
                    );
                }
            }
        }
    }
}

fn ctx() -> Context {
    Context::for_model_size(300.0, Drafting::EXACT).expect("context")
}

/// The pitch curve's curvature of the test's own (translating follower, offset e, s₀): the
/// pitch point q = (e, s₀ + S) turned by −φ; with u = q′ − J·q and w = q″ − 2J·q′ − q the
/// cam-frame curvature is −(u × w)/|u|³ (> 0 convex seen from O).
fn pitch_kappa(e: f64, s0: f64, m: (f64, f64, f64)) -> f64 {
    let (sv, ds, d2s) = m;
    let q = DVec2::new(e, s0 + sv);
    let (q1, q2) = (DVec2::new(0.0, ds), DVec2::new(0.0, d2s));
    let j = |v: DVec2| DVec2::new(-v.y, v.x);
    let u = q1 - j(q);
    let w = q2 - j(q1) * 2.0 - q;
    -u.perp_dot(w) / u.length().powi(3)
}

/// ρ_min of the convex pitch curve to 1e-12 (dense, then refined per phase), and the
/// roller at it, just over it and just under it: a cusp, an undercut, nothing.
#[test]
fn pitch_rho_min_to_1e_12_and_the_roller_at_it() {
    for (k, e) in [(2u8, 0.0), (3, 0.004), (5, -0.003), (1, 0.002), (4, 0.0)] {
        let mut s = spec(
            [60.0, 60.0, 60.0],
            law(k, 0.4),
            law(k, 0.4),
            0.03,
            Follower::Translating { offset: e },
            40.0,
            false,
        );
        s.base_radius = Some(0.03);
        let s0 = (0.03f64 * 0.03 - e * e).sqrt();
        // Convex curvature: the dwells' arcs about O, then each moving phase (each piece of
        // the "+ −" law) dense and refined around its best sample.
        let mut kmax = f64::max(1.0 / e.hypot(s0), 1.0 / e.hypot(s0 + s.stroke));
        for p in [0usize, 2] {
            let f = |u: f64, side: bool| pitch_kappa(e, s0, law_motion(&s, p, u, side));
            let spans: Vec<(f64, f64)> = if k == 1 {
                vec![(0.0, 0.4), (0.4, 1.0)]
            } else {
                vec![(0.0, 1.0)]
            };
            for (a, b) in spans {
                kmax = kmax.max(f(a, true)).max(f(b, false));
                kmax = kmax.max(search_max(a, b, 20_000, |u| {
                    if u >= b {
                        f(b, false)
                    } else {
                        f(u.max(a), true)
                    }
                }));
            }
        }
        let rho = 1.0 / kmax;
        let cam = build(&s, &ctx()).expect("cam");
        let got = cam.exact_rho_min();
        assert!(close(got, rho, 1e-12), "law {k}: ρ_min {got} against {rho}");
        // The roller's verdict: a cusp, an undercut, or none.
        let cusp = |f: &Finding| matches!(f, Finding::Cusp(Cusp::Roller { .. }));
        let undercut = |f: &Finding| matches!(f, Finding::Undercut { .. });
        for (roller, cusps, undercuts) in [
            (rho, 1, 0),
            (rho * (1.0 + 5e-7), 0, 1),
            (rho * (1.0 - 1e-6), 0, 0),
        ] {
            let mut t = s.clone();
            t.roller = Some(roller);
            let found = build(&t, &ctx()).expect("cam").findings();
            let count = |p: &dyn Fn(&Finding) -> bool| found.iter().filter(|f| p(f)).count();
            assert_eq!(
                (count(&cusp), count(&undercut)),
                (cusps, undercuts),
                "law {k}, roller {roller}: {found:?}"
            );
        }
    }
}
