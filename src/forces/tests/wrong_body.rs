//! The equilibrium check against a mechanism told wrongly: a guide or a load on the wrong
//! body is flagged by both routes' checks (the block on the slider).

use super::super::*;
use super::reported;
use crate::forces::twin::solve;
use crate::linkage::proptests::plan_context;
use crate::linkage::{kin_plan, Mechanism, PlanKind, PlanSetup};

/// The scene of a block sliding in a vertical guide on the slider, its force position 2
/// (`tests/scenes/block-on-slider.toml`), with the plans at the report's ω₁ = 10 rad/s.
fn block_on_slider() -> (Mechanism, ForceSpec, crate::linkage::PositionPlan) {
    use crate::linkage::{plan_positions, PlanRequest};
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/scenes/block-on-slider.toml");
    let scene = crate::scene::load(&path).expect("the scene loads");
    let m = scene.mechanism.expect("a mechanism");
    let spec = scene.forces.expect("forces");
    let req = PlanRequest {
        count: 12,
        start: None,
        other_extreme: false,
        continuity: false,
    };
    let mu_l = Scale::new(0.002, Quantity::Length).unwrap();
    let plan = plan_positions(&m, &req, mu_l, crate::construct::Drafting::EXACT).expect("a plan");
    (m, spec, plan)
}

/// The force analysis of position `k` of `plan` with its own plans.
fn analysed(spec: &ForceSpec, plan: &crate::linkage::PositionPlan, k: usize) -> PositionForces {
    let (w1, mu_l) = (10.0, Scale::new(0.002, Quantity::Length).unwrap());
    let setup = PlanSetup {
        prog: &plan.program,
        built: &plan.positions[k].built,
        mu_l,
        w1,
        ctx: plan_context(),
    };
    let sv = Scale::new(0.01, Quantity::Velocity).unwrap();
    let sa = Scale::new(0.1, Quantity::Acceleration).unwrap();
    let vp = kin_plan(&setup, PlanKind::Velocity, sv, None).expect("velocity plan");
    let ap = kin_plan(&setup, PlanKind::Acceleration, sa, Some(&vp)).expect("acceleration plan");
    analyse(spec, plan, k, mu_l, &vp, &ap, w1, &plan_context()).expect("analysed")
}

/// The rows `equilibrium_residual` and `power_residual` of an analysis: (graphical,
/// analytic) of each.
fn residual_values(f: &PositionForces) -> [(f64, f64); 2] {
    let rows = f.residual_rows();
    let of = |s: Symbol| {
        let r = rows
            .iter()
            .find(|r| r.key.symbol == s)
            .expect("a residual row");
        (r.graphical, r.analytic)
    };
    [of(Symbol::EquilibriumResidual), of(Symbol::PowerResidual)]
}

/// The guide through the joint B put on the rod 2 on purpose, as the program once read the
/// joint: the plans turn it with the rod, the polygons and the linear solve give balancing
/// moments 10 % and more off — and both rows of the check, the bodies' equations and the
/// power balance, flag both routes. Carried by the slider 3, as the scene names it, every
/// row holds to 1e-12.
#[test]
fn a_guide_on_the_wrong_body_is_flagged_by_both_checks() {
    let (_, spec, right) = block_on_slider();
    let mut wrong = right.clone();
    wrong.program = wrong.program.carried_by(1, 0, 2);
    let (good, bad) = (analysed(&spec, &right, 1), analysed(&spec, &wrong, 1));
    for (g, a) in residual_values(&good) {
        assert!(g <= 1e-12 && a <= 1e-12, "{g} {a}");
    }
    for (g, a) in residual_values(&bad) {
        assert!(g >= 1e-3 && a >= 1e-3, "the wrong carrier passes: {g} {a}");
    }
    let m_good = good.analysis.twin.m_bal;
    for m_bad in [bad.analysis.twin.m_bal, bad.analysis.polygons.driver.m_bal] {
        assert!(
            (m_bad - m_good).abs() > 0.1 * m_good.abs(),
            "{m_bad} vs {m_good}"
        );
    }
}

/// The moment of resistance on the rocker 4 solved on the block 5 on purpose: the linear
/// solve balances its own loads, but the bodies' equations miss the couple on the rocker and
/// the power balance the power it takes (the block does not turn). A load moved between two
/// bodies at their joint, by contrast, does no other work there: only the bodies' equations
/// can see it (`a_load_on_the_wrong_link_leaves_a_residual`).
#[test]
fn a_load_on_the_wrong_body_is_flagged_by_both_checks() {
    let (m, spec, plan) = block_on_slider();
    let k = 1;
    let pos = &plan.positions[k];
    let exact = PositionMotion::analytic(&pos.pose, 10.0);
    let loads = loads(&spec, &plan.program, &exact, None).expect("loads");
    let misplaced: Vec<Load> = loads
        .into_iter()
        .map(|l| {
            if l.link == 4 && l.kind == LoadKind::Resistance {
                Load { link: 5, ..l }
            } else {
                l
            }
        })
        .collect();
    let twin = solve(&plan.program, &pos.pose, &misplaced, &spec.drive, 1.0).expect("solved");
    let state = residual::State {
        motion: &exact,
        dir: &pos.pose.dir,
        w1: 10.0,
        phase: None,
    };
    let v = residual::residual(
        &spec,
        &m,
        &plan.program,
        &state,
        &reported(&twin.reactions, twin.m_bal, twin.f_bal),
        None,
    );
    assert!(v.equilibrium >= 1e-3 && v.power >= 1e-3, "{v:?}");
}
