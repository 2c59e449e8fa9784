//! The two-cylinder V engine (`constructions/v-engine.toml`): the work of the indicator
//! diagrams against an independent integration of p·A over the pistons' exact travel, the
//! constant resisting moment, ΔT closing over the cycle, the exact flywheel's δ, and the
//! reduced moment against the force analysis' balancing moment.

use super::reduce::reduce_loads;
use super::*;
use crate::construct::Drafting;
use crate::forces::{LoadKind, PositionMotion};
use crate::geom::DVec2;
use crate::study::Session;
use std::f64::consts::{PI, TAU};
use std::path::Path;

/// The scene's crank and rods, m; the cylinders' axes, degrees; ω₁ (1500 rpm, ccw).
const R: f64 = 0.040;
const L: f64 = 0.160;
const AXES_DEG: [f64; 2] = [45.0, 135.0];
const W1: f64 = 50.0 * PI;

fn engine() -> crate::scene::Scene {
    crate::scene::load(Path::new("constructions/v-engine.toml")).expect("the V engine scene")
}

/// The pressure of a table at cycle angle θ ∈ [θ_k, θ_k+1] by its own linear formula.
fn p_lin(a: (f64, f64), b: (f64, f64), t: f64) -> f64 {
    a.1 + (b.1 - a.1) * (t - a.0) / (b.0 - a.0)
}

/// The work of one cylinder over a turn, independently: the piston's distance from the crank
/// centre x(φ) = r·cos(φ − α) + √(l² − r²·sin²(φ − α)), the gas force p·A pushing towards the
/// crank (−x), so A = −∮ p·A·x′(φ) dφ, by Simpson's rule on every span of the table (where p
/// is linear and x smooth), φ = φ₀ + θ.
fn indicator_work(ind: &crate::forces::Indicator, axis: f64) -> f64 {
    let dx = |phi: f64| {
        let u = phi - axis;
        -R * u.sin() - R * R * u.sin() * u.cos() / (L * L - R * R * u.sin().powi(2)).sqrt()
    };
    let area = PI * ind.bore * ind.bore / 4.0;
    let n = 400;
    ind.pressure
        .windows(2)
        .map(|w| {
            let h = (w[1].0 - w[0].0) / n as f64;
            let f = |t: f64| -p_lin(w[0], w[1], t) * area * dx(ind.offset + t);
            let s: f64 = (0..=n)
                .map(|i| {
                    let c = if i == 0 || i == n {
                        1.0
                    } else if i % 2 == 1 {
                        4.0
                    } else {
                        2.0
                    };
                    c * f(w[0].0 + h * i as f64)
                })
                .sum();
            s * h / 3.0
        })
        .sum()
}

#[test]
fn the_pressure_table_is_read_linearly_and_periodically() {
    let scene = engine();
    let ind = &scene.forces.as_ref().expect("[forces]").indicators[0];
    // Between [0°, 2.6 MPa] and [10°, 4.2 MPa]; the table's rows themselves; periodic.
    let at = |deg: f64| ind.pressure_at(deg.to_radians()) / 1e6;
    assert!((at(5.0) - 3.4).abs() < 1e-12);
    assert!((at(10.0) - 4.2).abs() < 1e-12);
    assert!((at(180.0) - 0.0).abs() < 1e-12);
    assert!((at(365.0) - 3.4).abs() < 1e-12);
    assert!((at(-355.0) - 3.4).abs() < 1e-12);
    assert!((at(359.0) - (1.7 + 0.9 * 0.95)).abs() < 1e-12);
    // The cycle angle runs with the crank from the cylinder's offset.
    assert!((ind.cycle_angle(50f64.to_radians(), 1.0) - 5f64.to_radians()).abs() < 1e-12);
    assert!((ind.cycle_angle(40f64.to_radians(), -1.0) - 5f64.to_radians()).abs() < 1e-12);
}

#[test]
fn the_work_of_the_gas_forces_is_the_integral_of_p_a_ds() {
    let scene = engine();
    let fs = scene.forces.as_ref().expect("[forces]");
    assert_eq!(fs.indicators.len(), 2);
    let want: f64 = fs
        .indicators
        .iter()
        .zip(AXES_DEG)
        .map(|(ind, a)| indicator_work(ind, a.to_radians()))
        .sum();
    let session = Session::new(&scene, Drafting::EXACT);
    let d = session.dynamics().expect("the dynamics");
    // Positive work: the expansion outdoes the compression; about 383 J per turn.
    assert!(want > 300.0 && want < 450.0, "{want}");
    assert!(
        (d.cycle.a_drive - want).abs() < 1e-8 * want,
        "A_д {} vs ∮p·A·ds {want}",
        d.cycle.a_drive
    );
    // The constant resisting moment M_с = A_д/2π (the weights do no work over a turn).
    assert!((-d.cycle.m_drive - want / TAU).abs() < 1e-8 * want / TAU);
    // No working resistance in the scene.
    assert_eq!(d.cycle.a_res, 0.0);
    // ΔT closes over the cycle, exactly and as integrated by chords.
    assert!(d.cycle.delta_t(TAU).abs() < 1e-9 * want);
    let last = d.diagrams.delta_t.last().copied().expect("ΔT");
    assert!(last.abs() < 1e-9 * want, "ΔT(2π) by chords {last}");
    // The chords over 12 positions: the graphical A_д within 1 %, M_с read within 1 %.
    let a_g = d.diagrams.a_c.last().copied().expect("A_д");
    assert!((a_g - want).abs() < 0.01 * want, "{a_g}");
    assert!((d.diagrams.m_drive - want / TAU).abs() < 0.01 * want / TAU);
    // The exact flywheel gives the scene's δ = 1/80 at ω_ср.
    assert!(
        (d.exact.delta() - 0.0125).abs() < 1e-6,
        "{}",
        d.exact.delta()
    );
    assert!((d.exact.omega_avg() - 157.08).abs() < 1e-6 * 157.08);
    let again = d.cycle.with_flywheel(d.exact.j_fw, 157.08).delta();
    assert!((again - 0.0125).abs() < 1e-6, "{again}");
    assert!(d.exact.j_fw > 0.0);
}

#[test]
fn the_driving_side_varies_and_the_resisting_side_is_constant() {
    let scene = engine();
    let session = Session::new(&scene, Drafting::EXACT);
    let d = session.dynamics().expect("the dynamics");
    assert_eq!(d.spec.constant_moment, ConstantMoment::Resisting);
    // The reduced moment of the gas forces changes sign over the turn (compression) and
    // peaks just past each cylinder's top dead centre (travel 0° and 90°).
    let m: Vec<f64> = d.analytic.iter().map(|r| r.m_drv).collect();
    assert!(
        m.iter().any(|&v| v > 0.0) && m.iter().any(|&v| v < 0.0),
        "{m:?}"
    );
    let big = m.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    assert!(big > 5.0 * d.cycle.a_drive / TAU, "{big}");
    assert!(d.analytic.iter().all(|r| r.m_res == 0.0));
}

#[test]
fn reduced_moment_is_the_force_analysis_balancing_moment() {
    let scene = engine();
    let session = Session::new(&scene, Drafting::EXACT);
    let sc = session.kin_scales().expect("scales");
    let plan = session.positions(sc.l).expect("plan");
    let fs = scene.forces.as_ref().expect("[forces]");
    let sense = W1.signum();
    let positions = session.force_positions().expect("positions");
    assert_eq!(positions.len(), 2);
    for k in positions {
        let f = session.forces(&sc, k).expect("force analysis");
        let pos = &plan.positions[k];
        // The gas forces are among the loads.
        let gas = f
            .analysis
            .loads_exact
            .iter()
            .filter(|l| l.kind == LoadKind::Driving)
            .count();
        assert!(gas >= 1, "position {}", pos.label);
        let exact = PositionMotion::analytic(&pos.pose, W1);
        // Every load (inertia included): M_пр = −sign(ω₁)·M_у.
        let m = reduce_loads(&f.analysis.loads_exact, &exact, W1.abs());
        assert!(
            (m + sense * f.analysis.twin.m_bal).abs() < 1e-9 * f.analysis.twin.m_bal.abs(),
            "position {}: {m} vs M_у {}",
            pos.label,
            f.analysis.twin.m_bal
        );
        // The dynamics' own loads (weights and gas forces): the equilibrium's M_у.
        let red = Reducer::new(
            &plan.program,
            fs,
            None,
            plan.extremes.clone(),
            (plan.positions[0].phi, W1),
            0.0,
        )
        .expect("a reducer");
        let motion = PositionMotion {
            a: vec![DVec2::ZERO; exact.a.len()],
            eps: vec![0.0; exact.eps.len()],
            ..exact.clone()
        };
        let kinds = [LoadKind::Weight, LoadKind::Driving];
        let r = super::tests::assert_quasi_static(&red, fs, &plan, k, &motion, None, &kinds, sense);
        assert!(r.m_drv != 0.0);
    }
}

/// The V engine's A diagram under its M_д diagram (issue 45): the work rises to A_д's top
/// before falling back to its value at 2π, and the A axis's arrowhead and name ran up
/// among the M diagram's projections, 2,2 mm under the lowest. The layout takes the A
/// diagram's top from the work's running sum, so the axis ends well clear of them.
#[test]
fn the_work_axis_ends_clear_of_the_moment_diagram() {
    let scene = engine();
    let session = Session::new(&scene, Drafting::EXACT);
    let d = session.dynamics().expect("the dynamics");
    let steps = &d.diagrams.work.steps;
    let ys = |s: &crate::construct::Step| {
        let mut out = Vec::new();
        s.item.bounding_points(|p| out.push(p.y));
        out
    };
    let axis = (steps.iter())
        .find(|s| s.label.as_ref().is_some_and(|l| l.text == "A"))
        .expect("the A axis");
    let top = ys(axis).into_iter().fold(f64::NEG_INFINITY, f64::max);
    let lowest = (steps.iter())
        .filter(|s| s.note.starts_with("projection ") || s.note.starts_with("ray "))
        .flat_map(ys)
        .fold(f64::INFINITY, f64::min);
    let gap = lowest - top;
    assert!(
        gap >= 10.0,
        "{gap} mm between the A axis's end and the M diagram"
    );
}
