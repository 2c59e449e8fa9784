//! The flywheel of the shaper (seed 000 §5): each textbook route — Wittenbauer's tangents,
//! Mertsalov's T_I — on its diagrams at N equal positions (reduction by the analytic twin, so
//! only the method's own error remains, drafting exact) against the energy equation
//! integrated exactly; the time of the route, and of the exact solve.

use super::BenchRow;
use super::{best_time, BenchError, Reps, Subject, CHORD_RESOLUTIONS};
use crate::construct::{Context, Drafting};
use crate::dynamics::{diagrams, Cycle, ReducedPosition, Reducer};
use crate::linkage::{plan_poses, PlanRequest};
use std::f64::consts::TAU;

/// The rows `wittenbauer N=…` and `mertsalov N=…` of `J_flywheel`, and the time of the exact
/// solve (cycle integration + bracketed J_м), seconds.
pub(super) fn flywheel_rows(s: &Subject, reps: Reps) -> Result<(Vec<BenchRow>, f64), BenchError> {
    let fail = |e: &dyn std::fmt::Display| s.fail(e.to_string());
    let spec = s
        .scene
        .dynamics
        .as_ref()
        .ok_or_else(|| s.fail("no [dynamics]"))?;
    let forces = s
        .scene
        .forces
        .as_ref()
        .ok_or_else(|| s.fail("no [forces]"))?;
    let req = PlanRequest {
        count: 12,
        start: None,
        other_extreme: false,
        continuity: false,
    };
    let poses = plan_poses(&s.mechanism, &req).map_err(|e| fail(&e))?;
    let start = poses.positions.first().map_or(0.0, |p| p.phi);
    let red = Reducer::new(
        &s.prog,
        forces,
        spec.links.as_deref(),
        poses.extremes.clone(),
        (start, s.w1),
        spec.constant_inertia(),
    )
    .map_err(|e| fail(&e))?;
    let w_avg = spec.omega_avg.unwrap_or(s.w1.abs());
    let mut exact = None;
    let t_exact = best_time(reps.best_of, || {
        let cycle = Cycle::new(&red, crate::dynamics::PANELS)?;
        let sol = cycle.flywheel(w_avg, spec.delta)?;
        exact = Some(sol.j_fw);
        Ok::<_, crate::dynamics::DynamicsError>(sol)
    })
    .map_err(|e| fail(&e))?;
    let j_exact = exact.ok_or_else(|| s.fail("no exact flywheel"))?;
    let ctx = Context::for_model_size(super::DIAGRAM_EXTENT_MM, Drafting::EXACT)?;
    // Free scales: the scene's μ_φ and H are chosen for 12 positions.
    let free = crate::dynamics::DynamicsSpec {
        scale_m: None,
        scale_phi: None,
        pole_h: None,
        scale_t: None,
        scale_j: None,
        ..spec.clone()
    };
    let mut rows = Vec::new();
    for &n in &CHORD_RESOLUTIONS {
        let mut got = None;
        let t = best_time(reps.best_of, || {
            let reds = (0..n)
                .map(|i| red.exact(TAU * i as f64 / n as f64).map(|r| r.0))
                .collect::<Result<Vec<ReducedPosition>, _>>()?;
            let g = diagrams(&free, &reds, w_avg, &ctx)?;
            got = Some((g.wittenbauer.j_fw, g.mertsalov.j_fw));
            Ok::<_, crate::dynamics::DynamicsError>(())
        })
        .map_err(|e| fail(&e))?;
        let (w, m) = got.ok_or_else(|| s.fail("no route"))?;
        for (name, j) in [("wittenbauer", w), ("mertsalov", m)] {
            let e = (j - j_exact).abs();
            rows.push(BenchRow {
                method: format!("{name} N={n}"),
                resolution: n as u32,
                quantity: "J_flywheel".into(),
                max_error: e,
                mean_error: e,
                time_s: t,
                unit: "kg*m^2".into(),
            });
        }
    }
    Ok((rows, t_exact))
}
