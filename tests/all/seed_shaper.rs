//! Seed 000 fixtures: the slotted-link shaper's plan of positions against the exact values of
//! `seed-000-cases.md` §000.2, §000.3 and Table 5 (§000.9).

use tmm::construct::Drafting;
use tmm::geom::DVec2;
use tmm::linkage::{plan_positions, OutputCoord, PlanRequest, PositionPlan, Structure};
use tmm::scale::{Quantity, Scale};

fn shaper_plan() -> (tmm::scene::Scene, PositionPlan) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("constructions/shaper.toml");
    let scene = tmm::scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let req = PlanRequest {
        count: 12,
        start: None,
        other_extreme: true,
        continuity: false,
    };
    let scale = Scale::new(0.0025, Quantity::Length).unwrap();
    let plan = plan_positions(
        scene.mechanism.as_ref().expect("a mechanism"),
        &req,
        scale,
        Drafting::EXACT,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    (scene, plan)
}

/// Table 5, exact columns: φ₃ (degrees) and L₃ = |CB| (m), positions 1…8, 8′, 9…12.
const TABLE5: [(&str, f64, f64, f64); 13] = [
    ("1", 199.0, 109.001, 0.4066),
    ("2", 169.0, 106.747, 0.4769),
    ("3", 139.0, 101.446, 0.5324),
    ("4", 109.0, 94.634, 0.5642),
    ("5", 79.0, 87.305, 0.5681),
    ("6", 49.0, 80.270, 0.5435),
    ("7", 19.0, 74.446, 0.4937),
    ("8", -11.0, 71.182, 0.4261),
    ("8′", -19.0, 70.999, 0.4066),
    ("9", -41.0, 72.648, 0.3543),
    ("10", -71.0, 81.293, 0.3011),
    ("11", -101.0, 95.217, 0.2938),
    ("12", -131.0, 105.811, 0.3371),
];

#[test]
fn shaper_swing_time_ratio_and_stroke() {
    let (_, plan) = shaper_plan();
    let ex = plan
        .extremes
        .as_ref()
        .expect("the shaper has extreme positions");
    assert!(
        (ex.theta.to_degrees() - 38.0016).abs() < 5e-5,
        "θ = {}",
        ex.theta.to_degrees()
    );
    assert!((ex.k - 1.5352).abs() < 5e-5, "K = {}", ex.k);
    // The seed rounds K to 1.5 (L14): that value must not come out.
    assert!((ex.k - 1.5).abs() > 0.03);
    let stroke = ex
        .ranges
        .iter()
        .find(|r| matches!(r.coord, OutputCoord::Slider(..)))
        .map(|r| r.max - r.min)
        .expect("ram output");
    assert!((stroke - 0.46233).abs() < 5e-6, "H = {stroke}");
    // The seed's "S = 0.93 m" (L196) is twice the stroke.
    assert!((stroke - 0.93).abs() > 0.4);
}

#[test]
fn shaper_extreme_positions_are_exact() {
    let (_, plan) = shaper_plan();
    let ex = plan.extremes.as_ref().unwrap();
    let exact = 180.0 + (0.14f64 / 0.43).asin().to_degrees();
    assert!(
        (ex.phi_start.to_degrees() - exact).abs() < 1e-9,
        "{}",
        ex.phi_start.to_degrees()
    );
    assert!((ex.phi_other.to_degrees() - (540.0 - exact)).abs() < 1e-9);
    // At both extremes the rocker is tangent to the crank circle: CB ⊥ AB.
    for pos in plan.positions.iter().filter(|p| p.extreme) {
        let a = plan.program.index("A").unwrap();
        let b = plan.program.index("B").unwrap();
        let c = plan.program.index("C").unwrap();
        let (pa, pb, pc) = (pos.built.p[a], pos.built.p[b], pos.built.p[c]);
        assert!((pb - pa).dot(pb - pc).abs() < 1e-9 * (pb - pa).length() * (pb - pc).length());
    }
}

#[test]
fn shaper_table5_phi3_and_l3_at_all_13_positions() {
    let (_, plan) = shaper_plan();
    let labels: Vec<&str> = plan.positions.iter().map(|p| p.label.as_str()).collect();
    assert_eq!(labels, TABLE5.iter().map(|r| r.0).collect::<Vec<_>>());
    let mu = 0.0025;
    let (b, c) = (
        plan.program.index("B").unwrap(),
        plan.program.index("C").unwrap(),
    );
    for (pos, (label, phi1, phi3_table, l3_table)) in plan.positions.iter().zip(TABLE5) {
        // The positions are the seed's, at the exact extreme 199.0008° instead of 199°.
        let d_phi = (pos.phi.to_degrees() - phi1).rem_euclid(360.0);
        assert!(
            d_phi.min(360.0 - d_phi) < 1e-3,
            "position {label}: φ₁ = {}",
            pos.phi.to_degrees()
        );
        // Exact closed form (§000.3): B = A + 0.14(cos φ₁, sin φ₁), C at the origin.
        let bx = DVec2::new(0.0, 0.43) + DVec2::from_angle(pos.phi) * 0.14;
        let (phi3_exact, l3_exact) = (bx.y.atan2(bx.x).to_degrees(), bx.length());
        let cb = (pos.built.p[b] - pos.built.p[c]) * mu;
        let phi3 = pos.built.angle[3].to_degrees();
        let l3 = cb.length();
        assert!(
            (phi3 - phi3_exact).abs() < 0.01,
            "position {label}: φ₃ = {phi3}, exact {phi3_exact}"
        );
        assert!(
            (l3 - l3_exact).abs() * 1000.0 < 0.01,
            "position {label}: L₃ = {l3}, exact {l3_exact}"
        );
        // Construction and closed form agree to rounding, not just to the tolerance.
        assert!(
            (phi3 - phi3_exact).abs() < 1e-9 && (l3 - l3_exact).abs() < 1e-12,
            "position {label}"
        );
        // And the table's exact column at its printed precision.
        assert!(
            (phi3 - phi3_table).abs() < 6e-4,
            "position {label}: φ₃ = {phi3}, table {phi3_table}"
        );
        assert!(
            (l3 - l3_table).abs() < 6e-5,
            "position {label}: L₃ = {l3}, table {l3_table}"
        );
    }
    // The seed's typo φ₃ = 106 at position 2 (exact 106.747) is not reproduced.
    assert!((plan.positions[1].built.angle[3].to_degrees() - 106.0).abs() > 0.7);
}

#[test]
fn shaper_structure_as_in_the_seed() {
    let (scene, _) = shaper_plan();
    let st = Structure::analyse(scene.mechanism.as_ref().expect("a mechanism"));
    assert_eq!((st.n, st.p5, st.p4, st.w), (5, 7, 0, 1));
    assert_eq!((st.p5_all, st.w_all), (8, -1));
    assert_eq!(st.formula(), "I(0,1) → II(2,3) → II(4,5)");
    assert_eq!(st.class, 2);
}

/// Table 5 exact columns in the seed's sign convention (ω₁ = +5π in its formulas):
/// (φ₁°, ω₃ 1/s, V_B3B1 m/s, V_D m/s, ε₃ 1/s², a_D m/s²).
const TABLE5_KIN: [(f64, f64, f64, f64, f64, f64); 13] = [
    (199.0, 0.0001, -2.1991, 0.0001, -84.962, 60.323),
    (169.0, 2.1467, -1.9462, 1.5241, -46.579, 33.233),
    (139.0, 3.2744, -1.3404, 2.3248, -23.058, 18.054),
    (109.0, 3.7758, -0.5456, 2.6808, -7.888, 11.568),
    (79.0, 3.8307, 0.3176, 2.7198, 4.499, 10.897),
    (49.0, 3.4586, 1.1415, 2.4556, 18.464, 15.620),
    (19.0, 2.5266, 1.8112, 1.7939, 39.091, 28.122),
    (-11.0, 0.7021, 2.1787, 0.4985, 73.143, 51.933),
    (-19.0, 0.0001, 2.1991, 0.0001, 84.962, 60.323),
    (-41.0, -2.4899, 2.0144, -1.7678, 117.633, 83.635),
    (-71.0, -6.4662, 1.0225, -4.5910, 97.258, 75.164),
    (-101.0, -7.1875, -0.6142, -5.1031, -62.888, 57.784),
    (-131.0, -3.5711, -1.8404, -2.5355, -124.751, 89.035),
];

/// Table 8: (φ₁°, V_S3, V_S5 (ram), |ω₃|), magnitudes.
const TABLE8: [(f64, f64, f64, f64); 11] = [
    (169.0, 0.6225, 1.4595, 2.1467),
    (139.0, 0.9496, 2.2786, 3.2744),
    (109.0, 1.0950, 2.6720, 3.7758),
    (79.0, 1.1109, 2.7168, 3.8307),
    (49.0, 1.0030, 2.4203, 3.4586),
    (19.0, 0.7327, 1.7282, 2.5266),
    (-11.0, 0.2036, 0.4718, 0.7021),
    (-41.0, 0.7221, 1.6874, 2.4899),
    (-71.0, 1.8752, 4.5381, 6.4662),
    (-101.0, 2.0844, 5.0820, 7.1875),
    (-131.0, 1.0356, 2.4395, 3.5711),
];

fn close(got: f64, want: f64, half_ulp: f64) -> bool {
    (got - want).abs() <= half_ulp * 1.0001 + 1e-12
}

#[test]
fn shaper_analytic_twin_reproduces_table5_and_table8() {
    let (scene, plan) = shaper_plan();
    let prog = &plan.program;
    let w1 = scene.mechanism.as_ref().expect("a mechanism").crank.omega; // |ω₁| = 5π
    let seed_w1 = w1; // the seed's formulas: ω₁ = +5π although the crank turns clockwise
    let (b, c, d, e, s3) = (
        prog.index("B").unwrap(),
        prog.index("C").unwrap(),
        prog.index("D").unwrap(),
        prog.index("E").unwrap(),
        prog.index("S_3").unwrap(),
    );
    for (phi1, w3, vrel, vd, e3, ad) in TABLE5_KIN {
        let pose = prog.solve(phi1.to_radians(), None).unwrap();
        // Seed convention: d/dt = +ω₁·d/dφ₁.
        let omega3 = seed_w1 * pose.dangle[3];
        let eps3 = seed_w1 * seed_w1 * pose.ddangle[3];
        let l3 = (pose.p[b] - pose.p[c]).length();
        let v_rel = seed_w1 * (pose.p[b] - pose.p[c]).dot(pose.dp[b] - pose.dp[c]) / l3;
        let a_d = (pose.ddp[d] * w1 * w1).length();
        assert!(close(omega3, w3, 5e-5), "φ₁ = {phi1}: ω₃ {omega3} vs {w3}");
        assert!(
            close(v_rel, vrel, 5e-5),
            "φ₁ = {phi1}: V_B3B1 {v_rel} vs {vrel}"
        );
        assert!(
            close(0.71 * omega3, vd, 5e-5),
            "φ₁ = {phi1}: V_D {} vs {vd}",
            0.71 * omega3
        );
        assert!(close(eps3, e3, 5e-4), "φ₁ = {phi1}: ε₃ {eps3} vs {e3}");
        assert!(close(a_d, ad, 5e-4), "φ₁ = {phi1}: a_D {a_d} vs {ad}");
        // The physical sense (the crank turns clockwise) is the opposite of the seed's.
        let physical = -w1 * pose.dangle[3];
        assert!((physical + omega3).abs() < 1e-12);
    }
    for (phi1, vs3, vs5, w3) in TABLE8 {
        let pose = prog.solve(phi1.to_radians(), None).unwrap();
        assert!(
            close(w1 * pose.dp[s3].length(), vs3, 5e-5),
            "φ₁ = {phi1}: V_S3"
        );
        assert!(
            close(w1 * pose.dp[e].length(), vs5, 5e-5),
            "φ₁ = {phi1}: V_S5 {}",
            w1 * pose.dp[e].length()
        );
        assert!(
            close(w1 * pose.dangle[3].abs(), w3, 5e-5),
            "φ₁ = {phi1}: ω₃"
        );
    }
    // The seed's typos are not reproduced: ω₃ = −7.8 at position 11, V_S5 = 4.485 at index 9.
    let p11 = prog.solve((-101f64).to_radians(), None).unwrap();
    assert!((w1 * p11.dangle[3].abs() - 7.8).abs() > 0.5);
    let p10 = prog.solve((-71f64).to_radians(), None).unwrap();
    assert!((w1 * p10.dp[e].length() - 4.485).abs() > 0.05);
}
