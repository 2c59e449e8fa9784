//! Named hard cases of the plan of positions: a mechanism that cannot be assembled at some
//! crank angle, a change-point four-bar through its folded positions, dead centres.

use tmm::construct::{Context, Drafting, Recorder};
use tmm::geom::DVec2;
use tmm::linkage::*;

use crate::common;
use common::{four_bar, kulisa, slider_crank};
use tmm::scale::{Quantity, Scale};

fn mu() -> Scale {
    Scale::new(0.001, Quantity::Length).unwrap()
}

/// Twelve positions from `start` (radians; `None`: the working stroke), with the extremes
/// between them, each assembly on the scene's side.
fn request(start: Option<f64>) -> PlanRequest {
    PlanRequest {
        count: 12,
        start,
        other_extreme: true,
        continuity: false,
    }
}

/// The labels of the positions marked as extreme.
fn marked(plan: &PositionPlan) -> Vec<&str> {
    plan.positions
        .iter()
        .filter(|p| p.extreme)
        .map(|p| p.label.as_str())
        .collect()
}

#[test]
fn mechanism_that_cannot_be_assembled_names_position_and_group() {
    // Assembled only for φ₁ in [19.5°, 93.3°]: from 30° in steps of 30°, position 4 (120°) fails.
    let m = four_bar(0.2, 0.3, 0.25, 0.12);
    let req = request(Some(30f64.to_radians()));
    let err = plan_positions(&m, &req, mu(), Drafting::EXACT).unwrap_err();
    match &err {
        LinkageError::CannotAssemble {
            position, group, ..
        } => {
            assert_eq!(position, "4");
            assert!(group.starts_with("1 (RRR, links 2, 3)"), "{group}");
        }
        other => panic!("wanted CannotAssemble, got {other:?}"),
    }
    let msg = err.to_string();
    assert!(
        msg.contains("position 4") && msg.contains("120.0000°"),
        "{msg}"
    );
    // The numbers of the failing compass step: |AD| = √0.19 = 0.43589 m > 0.25 + 0.12 m.
    assert!(
        msg.contains("arcs from A (r = 0.25000 m) and D (r = 0.12000 m) do not meet"),
        "{msg}"
    );
    assert!(msg.contains("0.43589") && msg.contains("0.37000"), "{msg}");
}

#[test]
fn working_stroke_start_without_full_turn_is_refused_with_the_angle() {
    let m = four_bar(0.2, 0.3, 0.25, 0.12);
    let req = request(None);
    let msg = plan_positions(&m, &req, mu(), Drafting::EXACT)
        .unwrap_err()
        .to_string();
    assert!(
        msg.contains("cannot be assembled") && msg.contains("group 1"),
        "{msg}"
    );
}

#[test]
fn change_point_four_bar_passes_its_folded_positions_without_nan() {
    // a + b = c + d: crank 0.1 + coupler 0.2 = rocker 0.1 + frame 0.2 (a parallelogram).
    let m = four_bar(0.1, 0.2, 0.2, 0.1);
    let req = request(Some(0.0));
    let plan = plan_positions(&m, &req, mu(), Drafting::EXACT).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(plan.positions.len(), 12);
    let (a, b, d) = (
        plan.program.index("A").unwrap(),
        plan.program.index("B").unwrap(),
        plan.program.index("D").unwrap(),
    );
    for pos in &plan.positions {
        assert!(
            pos.built.p.iter().all(|p| p.is_finite()),
            "position {}",
            pos.label
        );
        assert!(
            pos.pose.p.iter().all(|p| p.is_finite()) && pos.pose.dp.iter().all(|p| p.is_finite())
        );
        let (pa, pb, pd) = (
            pos.built.p[a] * 0.001,
            pos.built.p[b] * 0.001,
            pos.built.p[d] * 0.001,
        );
        assert!(
            (pa.distance(pb) - 0.2).abs() < 1e-12 && (pd.distance(pb) - 0.1).abs() < 1e-12,
            "position {}",
            pos.label
        );
    }
    // Folded at φ₁ = 0 and stretched at 180°: the arcs touch, crossing angle 0, and the
    // analytic twin reports the toggle instead of a velocity.
    for k in [0, 6] {
        let pos = &plan.positions[k];
        assert!(
            pos.built.crossing[0] < 1e-6,
            "position {}: crossing {}",
            pos.label,
            pos.built.crossing[0]
        );
        assert!(pos.pose.toggle.is_some(), "position {}", pos.label);
    }
    // Held on the left branch at every position, the linkage is a parallelogram for
    // φ₁ ∈ (0°, 180°) and an anti-parallelogram for (180°, 360°): the rocker swings from 0° to
    // 180° and back, and its extremes are the two folded positions (positions 1 and 7).
    let ex = plan
        .extremes
        .as_ref()
        .expect("extremes at the folded positions");
    let r = &ex.ranges[0];
    assert!(
        r.phi_min.abs() < 1e-12
            && r.min.abs() < 1e-12
            && (r.phi_max - std::f64::consts::PI).abs() < 1e-12
            && (r.max - std::f64::consts::PI).abs() < 1e-12,
        "{r:?}"
    );
    assert_eq!(marked(&plan), ["1", "7"]);
}

#[test]
fn four_bar_dead_centres_have_crank_and_coupler_in_line() {
    let m = four_bar(0.08, 0.28, 0.25, 0.18);
    let prog = Program::compile(&m).unwrap();
    let ex = prog.extremes(&m.outputs, m.crank.sense, m.driving).unwrap();
    for phi in [ex.phi_start, ex.phi_other] {
        let pose = prog.solve(phi, None).unwrap();
        let (o, a, b) = (
            pose.p[0],
            pose.p[prog.index("A").unwrap()],
            pose.p[prog.index("B").unwrap()],
        );
        let s = (a - o).perp_dot(b - a) / ((a - o).length() * (b - a).length());
        assert!(
            s.abs() < 1e-12,
            "sin between crank and coupler at φ₁ = {}: {s}",
            phi.to_degrees()
        );
    }
    // Time ratio from the closed form: θ = ∠ between the dead-centre crank lines.
    let (l1, l2, l3, l4) = (0.08f64, 0.25f64, 0.18f64, 0.28f64);
    let ang = |c: f64| ((c * c + l4 * l4 - l3 * l3) / (2.0 * c * l4)).acos();
    let theta = (ang(l2 - l1) - ang(l2 + l1)).abs();
    assert!(
        (ex.theta.abs() - theta).abs() < 1e-12,
        "θ = {} vs {}",
        ex.theta,
        theta
    );
}

/// ω₁ of the kulisa: 5π rad/s clockwise.
const W1: f64 = -5.0 * std::f64::consts::PI;

/// The kulisa at φ₁ (degrees): the analytic ω₃, ε₃, a_D and D, and the same read off the
/// constructed velocity and acceleration plans (μ_l = 0.0025 m/mm, drafting 0).
fn kulisa_at(deg: f64) -> ([f64; 3], [f64; 3], DVec2, DVec2) {
    slot_at(0.43, deg)
}

/// [`kulisa_at`] with the crank `crank` m long (A–C is 0.43 m).
fn slot_at(crank: f64, deg: f64) -> ([f64; 3], [f64; 3], DVec2, DVec2) {
    let mut m = kulisa();
    m.crank.length = crank;
    let prog = Program::compile(&m).unwrap();
    let phi = deg.to_radians();
    let d = prog.index("D").unwrap();
    let pose = prog.solve(phi, None).unwrap();
    assert!(pose.toggle.is_none(), "{:?}", pose.toggle);
    let analytic = [
        pose.dangle[3] * W1,
        pose.ddangle[3] * W1 * W1,
        (pose.ddp[d] * W1 * W1).length(),
    ];
    let mu_l = Scale::new(0.0025, Quantity::Length).unwrap();
    let mut rec = Recorder::in_context(
        "t",
        mu_l,
        &Context::for_model_size(400.0, Drafting::EXACT).unwrap(),
    );
    let built = prog.construct(&mut rec, phi, None, "t").unwrap();
    let setup = PlanSetup {
        prog: &prog,
        built: &built,
        mu_l,
        w1: W1,
        ctx: Context::for_model_size(200.0, Drafting::EXACT).expect("tolerances"),
    };
    let sv = Scale::new(0.05, Quantity::Velocity).unwrap();
    let sa = Scale::new(0.5, Quantity::Acceleration).unwrap();
    let vp = kin_plan(&setup, PlanKind::Velocity, sv, None).unwrap();
    let ap = kin_plan(&setup, PlanKind::Acceleration, sa, Some(&vp)).unwrap();
    let plans = [vp.rate[3], ap.rate[3], (ap.images[d] * 0.5).length()];
    (analytic, plans, pose.p[d], built.p[d] * mu_l.value())
}

#[test]
fn kulisa_pin_through_the_pivot_takes_the_limit() {
    // B = C at φ₁ = 270°: the slot turns at ω₃ = ω₁/2 (inscribed angle), ε₃ = 0,
    // a_D = ω₃²·|CD| = (5π/2)²·0.71 m/s² = 43.7964 m/s².
    let w3 = W1 / 2.0;
    let a_d = w3 * w3 * 0.71;
    assert!((a_d - 43.80).abs() < 5e-3);
    let (analytic, plans, d_pose, d_built) = kulisa_at(270.0);
    for (what, [w, e, a]) in [("analytic", analytic), ("plans", plans)] {
        assert!(
            (w - (-7.853_981_633_974_483)).abs() < 1e-9,
            "{what}: ω₃ = {w}"
        );
        assert!(e.abs() < 1e-6, "{what}: ε₃ = {e}");
        assert!((a - a_d).abs() < 1e-9 * a_d, "{what}: a_D = {a}");
    }
    // The slot is the limit of the line CB: the tangent to B's path, horizontal.
    assert!(
        d_pose.distance(d_built) < 1e-12 && (d_pose.length() - 0.71).abs() < 1e-12,
        "D = {d_pose} vs {d_built}"
    );
    assert!(d_pose.y.abs() < 1e-12, "D = {d_pose}");
}

#[test]
fn kulisa_beside_the_pivot_gives_no_huge_number() {
    // The exact motion has ω₃ = ω₁/2 and ε₃ = 0 at every angle; beside the coincidence the
    // direct formulas lose digits as 1/h³, the limit takes over where it errs less.
    for k in 1..=12 {
        for sign in [-1.0, 1.0] {
            let deg = 270.0 + sign * 10f64.powi(-k);
            let (analytic, plans, _, _) = kulisa_at(deg);
            for [w, e, a] in [analytic, plans] {
                assert!((w - W1 / 2.0).abs() < 1e-4, "φ₁ = {deg}: ω₃ = {w}");
                assert!(e.abs() < 0.05, "φ₁ = {deg}: ε₃ = {e}");
                assert!((a - 43.796_369_53).abs() < 1e-3, "φ₁ = {deg}: a_D = {a}");
            }
        }
    }
}

/// Issue 17 §1b: a crank pin that passes a distance m beside the rocker's pivot is not the
/// coincidence. At the nearest position (φ₁ = 270°, the pin straight above C at m) the exact
/// closed form of the slotted link's rate is ω₃ = ω₁·[w × w′]/|w|² = −ω₁·r/m (w = B − C =
/// (r cos φ₁, d + r sin φ₁), d = 0.43 m, r = d − m, at sin φ₁ = −1), where m = d − r of the
/// f64 lengths is exact (Sterbenz: r and d within a factor 2), so nothing cancels; a_D = |CD|·√(ε₃² + ω₃⁴), and ε₃ = ω₁²·r·d·
/// cos φ₁·(|w|² − 2[w × w′])/|w|⁴ is ~1e-13·ω₃² at the f64 angle (cos φ₁ ≈ 1e-16), so a_D =
/// |CD|·ω₃² to 1e-20. Both the analytic twin and the plans must give it (the old code took the
/// pin-through-the-pivot limit ω₃ = ω₁/2 = −7.854 rad/s for m = 1e-5 m, 5 orders too small).
/// The relative rounding of the f64 route is ~δ/m (δ ≈ 1e-16 m), so the tolerance is
/// 1e-15/m + 1e-12 (ten times that, an acceleration doubles it).
#[test]
fn kulisa_pin_beside_the_pivot_gives_the_true_huge_rate() {
    for m in [1e-3, 1e-5, 1e-8, 1e-11] {
        let r = 0.43 - m;
        let m = 0.43 - r;
        let w3 = -W1 * r / m;
        let a_d = 0.71 * w3 * w3;
        let (analytic, plans, d_pose, d_built) = slot_at(r, 270.0);
        let tol = 1e-15 / m + 1e-12;
        for (what, [w, _, a]) in [("analytic", analytic), ("plans", plans)] {
            assert!(
                ((w - w3) / w3).abs() < tol,
                "m = {m}: {what}: ω₃ = {w} against {w3}"
            );
            assert!(
                ((a - a_d) / a_d).abs() < tol,
                "m = {m}: {what}: a_D = {a} against {a_d}"
            );
        }
        // The slot is the line C → B, B = (r cos φ₁, m) (φ₁ the f64 angle, cos φ₁ ≈ −1.8e-16):
        // D nearly straight above C.
        let d_exact = DVec2::new(r * 270f64.to_radians().cos(), m).normalize() * 0.71;
        for d in [d_pose, d_built] {
            assert!(
                d.distance(d_exact) < 0.71 * tol,
                "m = {m}: D = {d} against {d_exact}"
            );
        }
    }
}

#[test]
fn crank_rocker_at_toggle_has_the_toggle_as_an_extreme() {
    // 80 + 280 = 250 + 110: at φ₁ = 180° coupler and rocker are stretched (|AD| = 360 mm).
    // The rocker swings from ψ = 72.62° (crank and coupler stretched, |OB| = 330 mm) to the
    // toggle ψ = 180°.
    let m = four_bar(0.08, 0.28, 0.25, 0.11);
    let prog = Program::compile(&m).unwrap();
    let ex = prog
        .extremes(&m.outputs, m.crank.sense, m.driving)
        .unwrap_or_else(|e| panic!("{e}"));
    let x = (0.33f64.powi(2) - 0.11f64.powi(2) + 0.28f64.powi(2)) / (2.0 * 0.28);
    let y = (0.33f64.powi(2) - x * x).sqrt();
    let (psi_min, phi_min) = ((y.atan2(x - 0.28)), y.atan2(x));
    let r = &ex.ranges[0];
    assert!(
        (r.min - psi_min).abs() < 1e-9 && (r.phi_min - phi_min).abs() < 1e-7,
        "ψ_min = {}° at φ₁ = {}°",
        r.min.to_degrees(),
        r.phi_min.to_degrees()
    );
    assert!((psi_min.to_degrees() - 72.62).abs() < 5e-3);
    assert!((phi_min.to_degrees() - 18.55).abs() < 5e-3);
    assert!(
        (r.max - std::f64::consts::PI).abs() < 1e-12
            && (r.phi_max - std::f64::consts::PI).abs() < 1e-12,
        "ψ_max = {}° at φ₁ = {}°",
        r.max.to_degrees(),
        r.phi_max.to_degrees()
    );
    // Working stroke from the working-stroke start, and with a given start the extremes are
    // listed (k′) as well.
    for start in [None, Some(0.0)] {
        let req = request(start);
        let plan =
            plan_positions(&m, &req, mu(), Drafting::EXACT).unwrap_or_else(|e| panic!("{e}"));
        let ex = plan.extremes.as_ref().expect("extremes");
        let mut phis = [ex.phi_start, ex.phi_other];
        phis.sort_by(f64::total_cmp);
        assert!((phis[0] - phi_min).abs() < 1e-7 && (phis[1] - std::f64::consts::PI).abs() < 1e-12);
        assert_eq!(marked(&plan).len(), 2, "{start:?}: {:?}", marked(&plan));
    }
}

#[test]
fn slider_crank_with_coupler_equal_to_crank_has_one_extreme_per_dwell() {
    // l = r: B = r·cos φ₁ + r·|cos φ₁|, so the slider stands at the crank centre for
    // φ₁ ∈ [90°, 270°]. The extremes are the far dead centre (φ₁ = 0, x = 2r) and the arrival
    // at the stand-still in the sense of rotation (φ₁ = 90°, x = 0); nothing inside it.
    let m = slider_crank(0.1, 0.1);
    let prog = Program::compile(&m).unwrap();
    let ex = prog
        .extremes(&m.outputs, m.crank.sense, m.driving)
        .unwrap_or_else(|e| panic!("{e}"));
    let r = &ex.ranges[0];
    let d0 = r.phi_max.min(std::f64::consts::TAU - r.phi_max);
    assert!(
        d0 < 1e-9 && (r.max - 0.2).abs() < 1e-12,
        "max {} at {}",
        r.max,
        r.phi_max
    );
    assert!(
        (r.phi_min - std::f64::consts::FRAC_PI_2).abs() < 1e-9 && r.min.abs() < 1e-12,
        "min {} at {}°",
        r.min,
        r.phi_min.to_degrees()
    );
    // The dwell is in the stroke from the arrival: K = 270°/90° = 3.
    assert!((ex.k - 3.0).abs() < 1e-8, "K = {}", ex.k);
    let req = request(Some(0.0));
    let plan = plan_positions(&m, &req, mu(), Drafting::EXACT).unwrap_or_else(|e| panic!("{e}"));
    let extra: Vec<(String, f64)> = plan
        .positions
        .iter()
        .filter(|p| p.label.contains('′'))
        .map(|p| (p.label.clone(), p.phi.to_degrees()))
        .collect();
    assert!(extra.is_empty(), "{extra:?}");
    assert_eq!(marked(&plan), ["1", "4"]);
}

/// Hard case 4 of the independent check: an RPR group whose slide line is offset from the
/// rocker's pivot. The analytic table's `L_3` is the block's coordinate along the slot and
/// `V_B3B1` its rate — the sliding velocity the plan reads as `v_B3_B1` — not |CB| and
/// d|CB|/dt (0.45 % apart at an offset of 25.8 mm).
#[test]
fn slotted_link_with_offset_has_one_meaning_of_the_sliding_velocity() {
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("constructions/shaper.toml")).expect("shaper");
    let text = text.replace("offset = 0.0", "offset = 25.8");
    let scene = tmm::scene::parse(&text, &root.join("offset.toml")).expect("scene");
    let session = tmm::study::Session::new(&scene, Drafting::EXACT);
    let report = session.report().expect("report");
    let table = &report.tables[0];
    let col = |name: &str| {
        table
            .columns
            .iter()
            .position(|c| c.name == name)
            .unwrap_or_else(|| panic!("no column {name}"))
    };
    let (l3, v) = (col("L_3"), col("V_B3B1"));
    let kin = session
        .kinematics(&session.kin_scales().expect("scales"))
        .expect("kinematics");
    let plan = &kin.plan;
    let index = |name: &str| {
        (0..plan.positions[0].pose.p.len())
            .find(|&k| plan.point_name(k) == name)
            .unwrap_or_else(|| panic!("no point {name}"))
    };
    let (b, c) = (index("B"), index("C"));
    let w1 = kin.w1;
    let (mut compared, mut old_meaning_off) = (0, 0.0f64);
    for (label, values) in &table.rows {
        let row = report
            .rows
            .iter()
            .find(|r| r.quantity() == "v_B3_B1" && r.position().as_deref() == Some(label));
        let Some(row) = row else { continue };
        let (slide, rate) = (values[l3].expect("L_3"), values[v].expect("V_B3B1"));
        assert!(
            (rate.abs() - row.analytic).abs() <= 1e-12 * row.scale,
            "position {label}: table {rate}, row {}",
            row.analytic
        );
        assert!((row.graphical - row.analytic).abs() <= 1e-9 * row.scale);
        // The slot coordinate and the offset are the legs of |CB|.
        let pose = &plan
            .positions
            .iter()
            .find(|p| &p.label == label)
            .expect("position")
            .pose;
        let r = pose.p[b] - pose.p[c];
        assert!(
            (slide.hypot(0.0258) - r.length()).abs() < 1e-12,
            "{slide} {r}"
        );
        // What the column meant before: d|CB|/dt, visibly another quantity.
        let d_cb = r.dot(pose.dp[b] - pose.dp[c]) / r.length() * w1;
        old_meaning_off = old_meaning_off.max((d_cb.abs() - row.analytic).abs() / row.scale);
        compared += 1;
    }
    assert!(old_meaning_off > 1e-3, "{old_meaning_off}");
    assert_eq!(compared, 13);
}
