//! The dynamic study of the shaper (seed 000 §5) against independent values
//! (`seed-000-cases.md` §000.14), the reduction against the force analysis, the energy
//! equation's properties and the chord method's rate.

use super::reduce::reduce_loads;
use super::*;
use crate::construct::{Context, Drafting};
use crate::forces::{loads, solve_twin as solve, LoadKind, PositionMotion};
use crate::geom::DVec2;
use crate::study::Session;
use std::path::Path;

fn shaper() -> crate::scene::Scene {
    crate::scene::load(Path::new("constructions/shaper.toml")).expect("the shaper scene")
}

fn ctx() -> Context {
    Context::for_model_size(300.0, Drafting::EXACT).expect("a context")
}

/// The shaper's reducer over `links` (the scene's when `None`, every link with `Some(None)`).
fn with_reducer<T>(links: Option<Option<Vec<u32>>>, f: impl FnOnce(&Reducer<'_>) -> T) -> T {
    let scene = shaper();
    let session = Session::new(&scene, Drafting::EXACT);
    let plan = session
        .positions(session.scale_l().expect("μ_l"))
        .expect("the plan");
    let spec = scene.dynamics.as_ref().expect("[dynamics]");
    let links = links.unwrap_or_else(|| spec.links.clone());
    let red = Reducer::new(
        &plan.program,
        scene.forces.as_ref().expect("[forces]"),
        links.as_deref(),
        plan.extremes.clone(),
        (plan.positions[0].phi, -5.0 * std::f64::consts::PI),
        spec.constant_inertia(),
    )
    .expect("a reducer");
    f(&red)
}

const J_CONST: f64 = 2.8449 + 0.3924;

#[test]
fn reduced_moment_matches_the_seed_table_9_exact_column() {
    // §000.14: −M_c by exact kinematics (ω = 15.7; M is independent of ω), i = 1 … 11.
    let exact = [
        120.283, 186.876, 217.820, 220.049, 194.803, 138.350, 37.654, 2.152, 2.837, -1.894, -2.820,
    ];
    let jp = [
        3.4597, 3.7757, 3.9743, 3.9988, 3.8438, 3.5486, 3.2606, 3.5348, 5.3680, 5.9040, 3.8578,
    ];
    with_reducer(None, |red| {
        for (i, (&m, &j)) in exact.iter().zip(&jp).enumerate() {
            let t = (i + 1) as f64 * std::f64::consts::PI / 6.0;
            let (r, _) = red.exact(t).expect("the twin");
            assert!(
                (-r.m() - m).abs() < 2e-3 * 220.0,
                "i = {}: {} vs {m}",
                i + 1,
                -r.m()
            );
            assert!((r.j - j).abs() < 2e-4, "i = {}: J {} vs {j}", i + 1, r.j);
        }
    });
}

#[test]
fn reduced_moment_is_the_force_analysis_balancing_moment() {
    let scene = shaper();
    let session = Session::new(&scene, Drafting::EXACT);
    let sc = session.kin_scales().expect("scales");
    let plan = session.positions(sc.l).expect("plan");
    let fs = scene.forces.as_ref().expect("[forces]");
    let w1 = -5.0 * std::f64::consts::PI;
    let sense = w1.signum();
    for k in session.force_positions().expect("positions") {
        let f = session.forces(&sc, k).expect("force analysis");
        let pos = &plan.positions[k];
        let exact = PositionMotion::analytic(&pos.pose, w1);
        // Every load of the force analysis (inertia included): M_пр = −sign(ω₁)·M_у.
        let m = reduce_loads(&f.analysis.loads_exact, &exact, w1.abs());
        assert!(
            (m + sense * f.analysis.twin.m_bal).abs() < 1e-9 * f.analysis.twin.m_bal.abs(),
            "position {}: {m} vs M_у {}",
            pos.label,
            f.analysis.twin.m_bal
        );
        // The same loads as the plans read them, against Zhukovsky's lever.
        let vel = session.velocity(&sc, k).expect("plan");
        let vp = vel.plan().expect("built");
        let drawn = Reducer::plan_motion(vp, &pos.built.p, sc.l.value(), &ctx());
        let mg = reduce_loads(&f.analysis.loads, &drawn, w1.abs());
        assert!(
            (mg + sense * f.analysis.lever.m_bal).abs() < 1e-6 * f.analysis.lever.m_bal.abs(),
            "position {}: {mg} vs the lever's {}",
            pos.label,
            f.analysis.lever.m_bal
        );
        // The dynamics' own loads (weights and resistance, every link): the linear solve of
        // the links' equilibrium under them gives the same moment.
        with_reducer(Some(None), |red| {
            let motion = PositionMotion {
                a: vec![DVec2::ZERO; exact.a.len()],
                eps: vec![0.0; exact.eps.len()],
                ..exact.clone()
            };
            let ph = crate::forces::phase(&plan, pos.phi, sense);
            let kinds = [LoadKind::Weight, LoadKind::Resistance];
            assert_quasi_static(red, fs, &plan, k, &motion, ph, &kinds, sense);
        });
    }
}

#[test]
fn reduced_inertia_at_the_dead_positions_is_the_constant_part_and_the_rotating_masses() {
    with_reducer(None, |red| {
        let ex = red.extremes.clone().expect("extremes");
        for t in [0.0, ex.work_travel] {
            let (r, _) = red.exact(t).expect("twin");
            assert!((r.j - J_CONST).abs() < 1e-9, "links 3, 5 at {t}: {}", r.j);
        }
    });
    // Every link of [forces]: block 2 turns with the crank pin B (v_B = ω₁·L_AB), block 4
    // rests at D with the rocker.
    with_reducer(Some(None), |red| {
        let ex = red.extremes.clone().expect("extremes");
        for t in [0.0, ex.work_travel] {
            let (r, _) = red.exact(t).expect("twin");
            let want = J_CONST + 2.0 * 0.14 * 0.14;
            assert!(
                (r.j - want).abs() < 1e-9,
                "every link at {t}: {} vs {want}",
                r.j
            );
        }
    });
}

#[test]
fn a_link_without_a_mass_is_refused() {
    let scene = shaper();
    let prog = crate::linkage::Program::compile(scene.mechanism.as_ref().expect("mechanism"))
        .expect("program");
    let err = Reducer::new(
        &prog,
        scene.forces.as_ref().expect("[forces]"),
        Some(&[3, 7]),
        None,
        (0.0, 1.0),
        0.0,
    )
    .err();
    assert_eq!(err, Some(DynamicsError::NoLinkMass { link: 7 }));
}

fn study() -> Dynamics {
    let scene = shaper();
    let session = Session::new(&scene, Drafting::EXACT);
    session
        .dynamics()
        .expect("the dynamic study")
        .as_ref()
        .clone()
}

#[test]
fn the_work_of_resistance_is_the_cutting_force_times_the_stroke() {
    let d = study();
    with_reducer(None, |red| {
        let ex = red.extremes.clone().expect("extremes");
        let e = red.prog.index("E").expect("E");
        let a = red.pose(0.0).expect("pose").p[e];
        let b = red.pose(ex.work_travel).expect("pose").p[e];
        let want = 1275.3 * (a - b).length();
        assert!(
            (d.cycle.a_res - want).abs() < 1e-9 * want,
            "{} vs {want}",
            d.cycle.a_res
        );
        // The driving moment does the same work; gravity nets to zero.
        assert!((d.cycle.m_drive * std::f64::consts::TAU - want).abs() < 1e-9 * want);
    });
    assert!((d.cycle.a_res - 589.604).abs() < 1e-3);
}

#[test]
fn delta_t_returns_to_zero_over_the_cycle() {
    let d = study();
    let tau = std::f64::consts::TAU;
    assert!(d.cycle.delta_t(tau).abs() < 1e-9 * d.cycle.a_res);
    let last = d.diagrams.delta_t.last().copied().expect("ΔT");
    assert!(
        last.abs() < 1e-9 * d.cycle.a_res,
        "graphical ΔT(2π) = {last}"
    );
    assert_eq!(d.diagrams.delta_t.len(), d.labels.len() + 1);
}

#[test]
fn the_flywheel_is_the_independent_value_and_gives_delta() {
    let d = study();
    // §000.14: 25.521 kg·m², ω_max 16.223, ω_min 15.177.
    assert!((d.exact.j_fw - 25.521).abs() < 1e-3, "{}", d.exact.j_fw);
    assert!((d.exact.w_max.0 - 16.223).abs() < 1e-3);
    assert!((d.exact.w_min.0 - 15.177).abs() < 1e-3);
    assert!((d.exact.delta() - 1.0 / 15.0).abs() < 1e-9);
    assert!((d.exact.omega_avg() - 15.7).abs() < 1e-9);
    // Integrated again on twice the panels: the same δ to 1e-6.
    with_reducer(None, |red| {
        let fine = Cycle::new(red, 2 * twin::PANELS).expect("cycle");
        let s = fine.with_flywheel(d.exact.j_fw, 15.7);
        assert!((s.delta() - 1.0 / 15.0).abs() < 1e-6, "{}", s.delta());
        // Wittenbauer's tangents with the exact slopes ω_max²/2, ω_min²/2 on the exact
        // curve are the energy equation itself.
        let w = fine.wittenbauer(d.exact.w_max.0, d.exact.w_min.0);
        assert!((w - d.exact.j_fw).abs() < 1e-6 * d.exact.j_fw, "{w}");
    });
    // Mertsalov on continuous exact data (§000.14: 27.000).
    let mertsalov = d.cycle.mertsalov(15.7, 1.0 / 15.0).0 - J_CONST;
    assert!((mertsalov - 27.000).abs() < 5e-3, "{mertsalov}");
}

#[test]
fn an_infinite_flywheel_gives_no_irregularity() {
    let d = study();
    let deltas: Vec<f64> = [1e2, 1e4, 1e6]
        .iter()
        .map(|&j| d.cycle.with_flywheel(j, 15.7).delta())
        .collect();
    assert!(deltas[0] > deltas[1] && deltas[1] > deltas[2]);
    assert!(deltas[2] < 1e-4, "{deltas:?}");
    // δ ≈ ΔT_max/(J·ω²) for a large J: δ·J tends to a constant.
    let (a, b) = (deltas[1] * 1e4, deltas[2] * 1e6);
    assert!((a - b).abs() < 0.01 * b, "{a} vs {b}");
}

#[test]
fn graphical_work_converges_at_the_chord_rate() {
    let d = study();
    let spec = d.spec.clone();
    let mut errors = Vec::new();
    with_reducer(None, |red| {
        for n in [24usize, 48, 96, 192, 384] {
            let reds: Vec<ReducedPosition> = (0..n)
                .map(|i| {
                    red.exact(std::f64::consts::TAU * i as f64 / n as f64)
                        .expect("twin")
                        .0
                })
                .collect();
            let free = DynamicsSpec {
                scale_m: None,
                scale_phi: None,
                pole_h: None,
                ..spec.clone()
            };
            let g = draw::diagrams(&free, &reds, 15.7, &ctx()).expect("diagrams");
            let e = g
                .a_c
                .iter()
                .enumerate()
                .map(|(i, a)| {
                    let psi = std::f64::consts::TAU * i as f64 / n as f64;
                    let exact = -(d.cycle.delta_t(psi) - d.cycle.m_drive * psi);
                    (a - exact).abs()
                })
                .fold(0.0, f64::max);
            errors.push(e);
        }
    });
    // The other extreme (218.0016° of travel) is never a node, so the kink of M_с there
    // makes the error oscillate about the h² line: the order is fitted over a factor of 16.
    let xs: Vec<f64> = [24f64, 48.0, 96.0, 192.0, 384.0]
        .iter()
        .map(|n| n.ln())
        .collect();
    let ys: Vec<f64> = errors.iter().map(|e| e.ln()).collect();
    let (mx, my) = (xs.iter().sum::<f64>() / 5.0, ys.iter().sum::<f64>() / 5.0);
    let slope = xs
        .iter()
        .zip(&ys)
        .map(|(x, y)| (x - mx) * (y - my))
        .sum::<f64>()
        / xs.iter().map(|x| (x - mx) * (x - mx)).sum::<f64>();
    assert!((-2.4..-1.7).contains(&slope), "order {slope}: {errors:?}");
    assert!(errors[4] < 0.01, "{errors:?}");
}

#[test]
fn the_seed_errors_are_flagged_and_never_matched() {
    let d = study();
    use crate::check::notes::DynamicsNote;
    let notes = noted(&d);
    let flywheel = notes.iter().find_map(|n| match n {
        DynamicsNote::SeedFlywheel { j, delta, .. } => Some((*j, *delta)),
        _ => None,
    });
    let (j, delta) = flywheel.expect("the seed's flywheel noted");
    assert!((j - 17.1).abs() < 1e-12, "{notes:?}");
    // It runs at δ = 1/10.8 (3 digits) instead of the δ asked.
    assert!((1.0 / delta - 10.8).abs() < 0.05, "{notes:?}");
    let expression = notes.iter().find_map(|n| match n {
        DynamicsNote::SeedExpression { value, .. } => Some(*value),
        _ => None,
    });
    let value = expression.expect("the seed's expression noted");
    assert!((value - 18.58).abs() < 0.005, "{notes:?}");
    assert!(
        notes
            .iter()
            .any(|n| matches!(n, DynamicsNote::SeedInertias { positions, .. } if *positions > 0)),
        "{notes:?}"
    );
    for r in rows(&d) {
        if r.key.symbol == crate::check::Symbol::Inertia && r.key.subject == "flywheel" {
            for v in [r.graphical, r.analytic] {
                assert!((v - 17.1).abs() > 1.0 && (v - 18.58).abs() > 1.0, "{v}");
            }
        }
    }
    // Table 10: none of the seed's J_пр at a moving position is produced.
    let seed = d.spec.seed.clone().expect("seed");
    let among = seed.j_red_among(d.analytic.len());
    assert_eq!(among.len(), seed.j_red.len());
    for (k, s) in among.into_iter().skip(1) {
        let a = &d.analytic[k];
        if a.j - J_CONST > 0.1 {
            assert!((s - a.j).abs() > 0.05, "{s} vs {}", a.j);
        }
    }
}

#[test]
fn the_seed_rim_is_sized_as_the_seed_does() {
    let s = flywheel::size(&FlywheelSpec::SEED_RIM, 17.1);
    assert!((s.d - 0.7852).abs() < 1e-4, "{}", s.d);
    assert!((s.mass - 165.0).abs() < 0.2, "{}", s.mass);
    let s = flywheel::size(&FlywheelSpec::SEED_RIM, 27.0);
    assert!((s.d - 0.8603).abs() < 1e-4 && (s.mass - 217.0).abs() < 0.2);
    assert!((s.dim("d_{3}").expect("d3") - 0.8 * s.d).abs() < 1e-12);
    // A disc with its bore d₁: J = m·(D² + d₁²)/8 holds for its own mass, and the mass is
    // the ring's, π/4·(D² − d₁²)·b·ρ.
    let disc = flywheel::size(&FlywheelSpec::disc(7800.0), 10.0);
    let (d, d1, b) = (
        disc.d,
        disc.dim("d_{1}").expect("bore"),
        disc.dim("b").expect("width"),
    );
    assert!((d1 - 0.2 * d).abs() < 1e-12 && (b - 0.2 * d).abs() < 1e-12);
    assert!((disc.mass * (d * d + d1 * d1) / 8.0 - 10.0).abs() < 1e-9);
    let ring = std::f64::consts::FRAC_PI_4 * (d * d - d1 * d1) * b * 7800.0;
    assert!(
        (disc.mass - ring).abs() < 1e-9 * ring,
        "{} vs {ring}",
        disc.mass
    );
}

#[test]
fn epsilon_is_the_rate_of_omega_and_the_cycle_time_is_about_the_nominal() {
    let d = study();
    let (j, t0) = (d.exact.j_fw, d.exact.t0);
    // ε = dω/dt = ω·dω/dψ, against a central difference of ω(ψ) away from the extremes.
    for k in 1..36 {
        let psi = std::f64::consts::TAU * (k as f64 + 0.37) / 36.0;
        let h = 1e-5;
        let dw = (d.cycle.omega(psi + h, j, t0) - d.cycle.omega(psi - h, j, t0)) / (2.0 * h);
        let want = d.cycle.omega(psi, j, t0) * dw;
        let eps = d.cycle.epsilon(psi, j, t0);
        assert!(
            (eps - want).abs() < 1e-4 * (1.0 + want.abs()),
            "ψ = {psi}: {eps} vs {want}"
        );
    }
    // Within δ/2 of 2π/ω_ср.
    let nominal = std::f64::consts::TAU / 15.7;
    assert!(
        (d.cycle_time - nominal).abs() < nominal / 30.0,
        "{}",
        d.cycle_time
    );
}

mod properties {
    use super::*;
    use proptest::prelude::*;
    use std::sync::OnceLock;

    /// The shaper's exact cycle, integrated once for every case.
    fn cycle() -> &'static Cycle {
        static CYCLE: OnceLock<Cycle> = OnceLock::new();
        CYCLE.get_or_init(|| study().cycle)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(12))]
        /// For any δ and ω_ср the bracketed flywheel gives exactly that δ and that mean
        /// speed, and Wittenbauer's tangents with the exact slopes find the same flywheel.
        #[test]
        fn the_flywheel_gives_the_delta_asked_for(delta in 0.01f64..0.3, w in 5.0f64..40.0) {
            let c = cycle();
            let s = c.flywheel(w, delta).expect("a flywheel");
            prop_assume!(s.j_fw > 0.0);
            prop_assert!((s.delta() - delta).abs() < 1e-9, "{} vs {delta}", s.delta());
            prop_assert!((s.omega_avg() - w).abs() < 1e-9 * w);
            let j = c.wittenbauer(s.w_max.0, s.w_min.0);
            prop_assert!((j - s.j_fw).abs() < 1e-6 * s.j_fw.max(1.0), "{j} vs {}", s.j_fw);
        }
    }
}

#[test]
fn the_bracketed_root_converges_on_smooth_steep_and_flat_functions() {
    use crate::geom::bracketed_root;
    let cbrt2 = bracketed_root(|x| x * x * x - 2.0, 0.0, 2.0);
    assert!((cbrt2 - 2f64.cbrt()).abs() < 1e-15 * 2.0, "{cbrt2}");
    // A √ singularity at the bracket's end, as ω near T₀ = −ΔT_min.
    let r = bracketed_root(|x: f64| x.max(0.0).sqrt() - 0.5, 0.0, 1.0);
    assert!((r - 0.25).abs() < 1e-15, "{r}");
    // Decreasing, the bracket given either way round.
    let e = bracketed_root(|x: f64| (-x).exp() - 0.1, 10.0, 0.0);
    assert!((e - 10f64.ln()).abs() < 1e-14, "{e}");
    // A jump: the root is the jump, kept in the bracket.
    let j = bracketed_root(|x| if x < 0.3 { -1.0 } else { 1.0 }, 0.0, 1.0);
    assert!((j - 0.3).abs() < 1e-14, "{j}");
    // No sign change: the end nearer zero.
    assert_eq!(bracketed_root(|x| x + 1.0, 0.0, 1.0), 0.0);
}

#[test]
fn illinois_keeps_the_ends_in_order_stops_at_the_width_asked_and_reports_a_domain_left() {
    use crate::geom::illinois;
    let f = |x: f64| Some(0.5 - x * x);
    let narrow = |a: f64, b: f64| (a - b).abs() <= 1e-13;
    // The ends come back in the order given, with their values, at most 1e-13 apart.
    let [(a, fa), (b, fb)] = illinois(f, (0.0, 0.5), (1.0, -0.5), narrow).unwrap();
    assert!(
        a <= b && b - a <= 1e-13 && fa >= 0.0 && fb <= 0.0,
        "{a} {b}"
    );
    assert!((a - 0.5f64.sqrt()).abs() <= 1e-13);
    let [(b2, _), (a2, _)] = illinois(f, (1.0, -0.5), (0.0, 0.5), narrow).unwrap();
    assert!(b2 >= a2 && (b2 - 0.5f64.sqrt()).abs() <= 1e-13);
    // Few steps where plain halving takes 43.
    let steps = std::cell::Cell::new(0);
    let counted = |x: f64| {
        steps.set(steps.get() + 1);
        f(x)
    };
    illinois(counted, (0.0, 0.5), (1.0, -0.5), narrow).unwrap();
    assert!(steps.get() <= 12, "{} steps", steps.get());
    // A point without a value: no bracket.
    let holed = |x: f64| (x < 0.6).then_some(0.5 - x * x);
    assert!(illinois(holed, (0.0, 0.5), (1.0, -0.5), narrow).is_none());
}

/// With the links at rest (`motion` without accelerations): the reducer's M_пр at position
/// `k` equals −sign(ω₁)·M_у of the links' equilibrium under the same loads of the `kinds`
/// (the linear solve). Returns the reduced values.
#[allow(clippy::too_many_arguments)]
pub(super) fn assert_quasi_static(
    red: &super::reduce::Reducer<'_>,
    fs: &crate::forces::ForceSpec,
    plan: &crate::linkage::PositionPlan,
    k: usize,
    motion: &PositionMotion,
    phase: crate::forces::Phase,
    kinds: &[LoadKind],
    sense: f64,
) -> super::reduce::ReducedPosition {
    let pos = &plan.positions[k];
    let r = red.at(motion, pos.phi).expect("reduction");
    let quasi: Vec<_> = loads(fs, &plan.program, motion, phase)
        .expect("loads")
        .into_iter()
        .filter(|l| kinds.contains(&l.kind))
        .collect();
    let eq = solve(&plan.program, &pos.pose, &quasi, &fs.drive, sense).expect("solve");
    assert!(
        (r.m() + sense * eq.m_bal).abs() < 1e-9 * eq.m_bal.abs().max(1.0),
        "position {}: M_пр {} vs the equilibrium's {}",
        pos.label,
        r.m(),
        eq.m_bal
    );
    r
}
