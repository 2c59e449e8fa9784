//! Kinematic analysis: `tmm report` against the analytic twin and the seed's tables, the
//! drafting model, and the hard cases of velocity and acceleration plans.

use std::path::PathBuf;
use std::process::Command;
use tmm::construct::{ConstructionError, Context, Drafting, Recorder};
use tmm::geom::DVec2;
use tmm::linkage::*;

use crate::common;
use common::four_bar;
use tmm::scale::{Quantity, Scale};

pub(crate) fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

pub(crate) fn report_json(scene: &str, drafting: &str) -> serde_json::Value {
    let o = Command::new(env!("CARGO_BIN_EXE_tmm"))
        .args(["report", scene, "--format", "json", "--drafting", drafting])
        .current_dir(root())
        .output()
        .expect("run tmm report");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).expect("report JSON")
}

pub(crate) fn rows(v: &serde_json::Value) -> Vec<&serde_json::Value> {
    v["rows"].as_array().expect("rows").iter().collect()
}

fn find<'a>(v: &'a serde_json::Value, q: &str, pos: &str, method: &str) -> &'a serde_json::Value {
    rows(v)
        .into_iter()
        .find(|r| r["quantity"] == q && r["position"] == pos && is_method(r, method))
        .unwrap_or_else(|| panic!("no row {q} {pos} {method}"))
}

/// The row's method is `method` or, for a prefix such as `diagram`, one of its kind
/// (`diagram-chords`, `diagram-tangents`).
fn is_method(r: &serde_json::Value, method: &str) -> bool {
    r["method"].as_str().is_some_and(|m| m.starts_with(method))
}

fn num(r: &serde_json::Value, key: &str) -> f64 {
    r[key].as_f64().unwrap_or_else(|| panic!("{key} in {r}"))
}

#[test]
fn shaper_report_plans_equal_analytic_at_drafting_0() {
    let v = report_json("constructions/shaper.toml", "0");
    assert_eq!(v["scene"], "shaper");
    let all = rows(&v);
    let mut plan_rows = 0;
    for r in &all {
        for key in [
            "quantity",
            "position",
            "unit",
            "method",
            "graphical",
            "analytic",
            "abs_error",
            "rel_error",
        ] {
            assert!(r.get(key).is_some(), "row lacks {key}: {r}");
        }
        if r["method"] == "plan" {
            plan_rows += 1;
            let (g, a) = (num(r, "graphical"), num(r, "analytic"));
            let ok = if a.abs() < 1e-9 {
                (g - a).abs() <= 1e-12
            } else {
                (g - a).abs() <= 1e-9 * a.abs()
            };
            assert!(ok, "plan ≠ analytic: {r}");
        }
    }
    assert!(plan_rows > 100, "{plan_rows} plan rows");
    // The quantities the issue names, on the plans and the diagrams.
    for q in [
        "v_D", "a_D", "v_S5", "a_S5", "v_S3", "omega_3", "eps_3", "v_B3_B1",
    ] {
        assert!(
            all.iter()
                .any(|r| r["quantity"] == q && r["method"] == "plan"),
            "no plan row {q}"
        );
    }
    for q in ["s_S5", "v_S5", "a_S5"] {
        assert!(
            all.iter()
                .any(|r| r["quantity"] == q && r["method"] == "diagram-chords"),
            "no diagram row {q}"
        );
    }
    let labels: Vec<&str> = all
        .iter()
        .filter(|r| r["quantity"] == "omega_3")
        .map(|r| r["position"].as_str().unwrap())
        .collect();
    assert_eq!(
        labels,
        ["1", "2", "3", "4", "5", "6", "7", "8", "8′", "9", "10", "11", "12"]
    );
}

/// Table 5 ω₃ (seed sign convention) and Table 8 V_S5 at positions 2…12 (exact columns).
const OMEGA3: [(&str, f64); 11] = [
    ("2", 2.1467),
    ("3", 3.2744),
    ("4", 3.7758),
    ("5", 3.8307),
    ("6", 3.4586),
    ("7", 2.5266),
    ("8", 0.7021),
    ("9", -2.4899),
    ("10", -6.4662),
    ("11", -7.1875),
    ("12", -3.5711),
];
const VS5: [(&str, f64); 11] = [
    ("2", 1.4595),
    ("3", 2.2786),
    ("4", 2.6720),
    ("5", 2.7168),
    ("6", 2.4203),
    ("7", 1.7282),
    ("8", 0.4718),
    ("9", 1.6874),
    ("10", 4.5381),
    ("11", 5.0820),
    ("12", 2.4395),
];

#[test]
fn shaper_report_analytic_values_match_tables_5_and_8() {
    let v = report_json("constructions/shaper.toml", "0");
    // The report's positions start at the exact extreme 199.0008°, the tables at 199°: the
    // 0.0008° shift moves ω₃ by at most |ε₃/ω₁|·1.4e-5 rad < 1.2e-4 1/s.
    for (pos, w) in OMEGA3 {
        let a = num(find(&v, "omega_3", pos, "plan"), "analytic");
        // The crank turns clockwise: the physical sense is the opposite of the seed's.
        assert!(
            (a + w).abs() < 5e-5 + 1.2e-4,
            "ω₃ at {pos}: {a} vs seed {w} (opposite sign)"
        );
    }
    for (pos, s5) in VS5 {
        let a = num(find(&v, "v_S5", pos, "plan"), "analytic");
        assert!(
            (a - s5).abs() < 5e-5 + 1.2e-4 * 0.71 * 8.0,
            "V_S5 at {pos}: {a} vs {s5}"
        );
    }
    // The seed's typos are not reproduced.
    assert!((num(find(&v, "omega_3", "11", "plan"), "analytic").abs() - 7.8).abs() > 0.5);
    assert!((num(find(&v, "v_S5", "10", "plan"), "analytic") - 4.485).abs() > 0.04);
    // At the dead centres the rocker stands: ω₃ = 0.
    for pos in ["1", "8′"] {
        assert!(num(find(&v, "omega_3", pos, "plan"), "analytic").abs() < 1e-12);
    }
}

/// The analytic table's column `name` by position label.
fn column(v: &serde_json::Value, name: &str) -> std::collections::HashMap<String, f64> {
    let t = &v["tables"][0];
    let cols = t["columns"].as_array().expect("columns");
    let c = cols
        .iter()
        .position(|c| c["name"] == name)
        .unwrap_or_else(|| panic!("no column {name}"));
    t["rows"]
        .as_array()
        .expect("table rows")
        .iter()
        .map(|r| {
            (
                r["position"].as_str().unwrap().to_string(),
                r["values"][c].as_f64().expect("a number"),
            )
        })
        .collect()
}

/// Drafting d = 0.5 mm on the shaper's plans (μ_v = 0.05 (m/s)/mm, μ_a = 1 (m/s²)/mm at
/// position 10 and 0.4 at 3, its own, shaper.toml). Every plan value is a length read off the drawing, rounded to d, times μ,
/// so its own reading error is at most d/2·μ; what a rounded reading feeds into later adds
/// to it. Derivation, row by row (RPR 2–3 about C, RPP 4–5 on a frame guide):
/// - velocity plan: every image comes from exact geometry (intersections, the similarity
///   theorem on two known images, the frame guide's zero rate), so v_X errs by ≤ d/2·μ_v;
/// - ω₃ = |c b₃|·μ_v / L₃ (L₃ = |CB|): ≤ d/2·μ_v/L₃; ω₂ copies it; ω₁, ω₄, ω₅ are exact;
/// - acceleration plan: the rounded ω₃ (δω ≤ d/2·μ_v/L₃) enters the normal component
///   ω₃²·L₃ (error 2|ω₃|L₃·δω ≤ |ω₃|·d·μ_v, along CB) and the Coriolis component
///   2ω₃·v_B3B2 (error 2|v_B3B2|·δω ≤ |v_B3B2|·d·μ_v/L₃, ⊥ CB); the two direction lines
///   cross at 90°, so the image b₃′ moves by at most their sum δ₃, and a point X of link 3
///   by |CX|/L₃·δ₃ (similarity on c′ = π and b₃′); E′ is D′ projected on the guide (≤ the
///   same), and d₅′ − d₃′ carries both (×2). ε₃ = |n b₃′|·μ_a/L₃ where n moves with b₃′
///   along CB, so only the Coriolis part shifts it: ≤ (d/2·μ_a + |v_B3B2|·d·μ_v/L₃)/L₃.
#[test]
fn drafting_half_a_millimetre_gives_hand_construction_errors() {
    let v = report_json("constructions/shaper.toml", "0.5");
    let (d, mu_v) = (0.5, 0.05);
    let mu_a = |pos: &str| if pos == "3" { 0.4 } else { 1.0 };
    let (l3, w3, vr) = (column(&v, "L_3"), column(&v, "ω_3"), column(&v, "V_B3B1"));
    let (cd, cs3) = (0.71, 0.29);
    let mut vel = Vec::new();
    // The plans' own readings (the inertia loads computed from them are the force tests').
    let kinematic = |r: &&&serde_json::Value| {
        r["method"] == "plan" && !["N", "N*m", "kg*m^2"].contains(&r["unit"].as_str().unwrap_or(""))
    };
    for r in rows(&v).iter().filter(kinematic) {
        let q = r["quantity"].as_str().unwrap();
        let pos = r["position"].as_str().unwrap();
        let err = (num(r, "graphical") - num(r, "analytic")).abs();
        let l = l3[pos];
        let shift = w3[pos].abs() * d * mu_v + vr[pos].abs() * d * mu_v / l;
        let mu_a = mu_a(pos);
        let propagated = |cx: f64| d / 2.0 * mu_a + cx / l * shift;
        let bound = match q {
            _ if q.starts_with("v_") => {
                vel.push(err / (d / 2.0 * mu_v));
                d / 2.0 * mu_v
            }
            _ if q.starts_with("omega_") => d / 2.0 * mu_v / l,
            "a_B" => d / 2.0 * mu_a,
            // b₃′ itself (the seed's a_B3) moves with the image: |CB₃| = L₃.
            "a_B3_B1" | "a_B3" => propagated(l),
            "a_S3" => propagated(cs3),
            // D₅, the ram's point under D, moves as E does.
            "a_D" | "a_E" | "a_S5" | "a_D5" => propagated(cd),
            "a_D5_D3" => propagated(2.0 * cd),
            _ if q.starts_with("eps_") => (d / 2.0 * mu_a + vr[pos].abs() * d * mu_v / l) / l,
            _ => panic!("no bound derived for {q}"),
        };
        assert!(
            err <= bound * (1.0 + 1e-9),
            "{q} at {pos}: error {err} over the drafting bound {bound}"
        );
    }
    // The readings really are rounded: with their fractional parts spread evenly a reading
    // errs by d/4 on average (half the bound); a run that did not round would give 0. The
    // window ±d/8 is wide for 117 readings (several repeat: v_B at every position).
    assert_eq!(vel.len(), 117);
    let mean = vel.iter().sum::<f64>() / vel.len() as f64;
    assert!(
        (0.25..=0.75).contains(&mean),
        "mean velocity reading error {mean} × d/2·μ_v"
    );
}

#[test]
fn chord_diagrams_are_less_accurate_than_plans_but_close() {
    let v = report_json("constructions/shaper.toml", "0");
    let mid = find(&v, "v_S5", "4", "diagram");
    let rel = num(mid, "rel_error").abs();
    assert!(
        rel > 1e-4 && rel < 0.03,
        "mid-stroke diagram velocity error {rel}"
    );
}

fn plans_at(
    m: &Mechanism,
    phi: f64,
) -> (Program, Built, Result<KinPlan, (usize, ConstructionError)>) {
    let prog = Program::compile(m).unwrap();
    let mu_l = Scale::new(0.001, Quantity::Length).unwrap();
    let mut rec = Recorder::in_context(
        "t",
        mu_l,
        &Context::for_model_size(1000.0, Drafting::EXACT).unwrap(),
    );
    let built = prog.construct(&mut rec, phi, None, "t").unwrap();
    let w1 = m.crank.sense.sign() * m.crank.omega;
    let setup = PlanSetup {
        prog: &prog,
        built: &built,
        mu_l,
        w1,
        ctx: Context::for_model_size(200.0, Drafting::EXACT).expect("tolerances"),
    };
    let vp = kin_plan(
        &setup,
        PlanKind::Velocity,
        Scale::new(0.01, Quantity::Velocity).unwrap(),
        None,
    );
    (prog, built, vp)
}

#[test]
fn toggle_position_is_refused_with_a_diagnosis() {
    // Parallelogram folded at φ₁ = 0: coupler and rocker in line, the two direction lines of
    // the velocity plan are parallel — refused, not a huge number.
    let m = four_bar(0.1, 0.2, 0.2, 0.1);
    let (_, _, vp) = plans_at(&m, 0.0);
    match vp {
        Err((0, e @ ConstructionError::LinesParallel { .. })) => {
            assert!(e.to_string().contains("parallel"), "{e}")
        }
        other => panic!("wanted a parallel-lines refusal, got {other:?}"),
    }
}

#[test]
fn nearly_parallel_direction_lines_report_their_conditioning() {
    // Close to the fold the crossing is shallow: the reading carries the small angle.
    let m = four_bar(0.1, 0.2, 0.2, 0.1);
    let (_, _, vp) = plans_at(&m, 0.02);
    let vp = vp.expect("still constructible");
    let cond = vp
        .readings
        .iter()
        .find(|r| r.quantity == "v_B_A")
        .and_then(|r| r.conditioning)
        .expect("conditioning");
    assert!(cond < 5.0 && cond > 0.0, "crossing angle {cond}°");
    let (_, _, vp) = plans_at(&m, 1.5);
    let cond = vp
        .unwrap()
        .readings
        .iter()
        .find(|r| r.quantity == "v_B_A")
        .and_then(|r| r.conditioning)
        .unwrap();
    assert!(cond > 30.0, "well-conditioned crossing {cond}°");
}

#[test]
fn coriolis_vanishes_with_the_relative_sliding_velocity() {
    // Shaper-like RPR: at φ₁ = 90° the pin B is on the line AC, the crank ⊥ the slot, so the
    // block does not slide (V_B3B1 = 0) and the Coriolis component vanishes.
    let m = Mechanism {
        fixed: vec![
            FixedPoint {
                name: "A".into(),
                at: DVec2::new(0.0, 0.43),
            },
            FixedPoint {
                name: "C".into(),
                at: DVec2::ZERO,
            },
        ],
        crank: Crank {
            link: 1,
            centre: "A".into(),
            pin: "B".into(),
            length: 0.14,
            omega: 15.7,
            sense: Sense::Clockwise,
        },
        groups: vec![Group {
            links: [2, 3],
            dyad: Dyad::Rpr {
                a: "B".into(),
                c: "C".into(),
                offset: 0.0,
            },
        }],
        points: vec![LinkPoint {
            name: "D".into(),
            link: 3,
            along: 0.71,
            across: 0.0,
        }],
        redundant: vec![],
        outputs: vec![Output::Rocker { link: 3 }],
        driving: false,
    };
    for (phi, vanishes) in [(90f64, true), (120f64, false)] {
        let prog = Program::compile(&m).unwrap();
        let mu_l = Scale::new(0.0025, Quantity::Length).unwrap();
        let mut rec = Recorder::in_context(
            "t",
            mu_l,
            &Context::for_model_size(400.0, Drafting::EXACT).unwrap(),
        );
        let built = prog
            .construct(&mut rec, phi.to_radians(), None, "t")
            .unwrap();
        let setup = PlanSetup {
            prog: &prog,
            built: &built,
            mu_l,
            w1: -15.7,
            ctx: Context::for_model_size(200.0, Drafting::EXACT).expect("tolerances"),
        };
        let vp = kin_plan(
            &setup,
            PlanKind::Velocity,
            Scale::new(0.05, Quantity::Velocity).unwrap(),
            None,
        )
        .unwrap();
        let ap = kin_plan(
            &setup,
            PlanKind::Acceleration,
            Scale::new(1.0, Quantity::Acceleration).unwrap(),
            Some(&vp),
        )
        .unwrap();
        let slip = vp
            .readings
            .iter()
            .find(|r| r.quantity == "v_B3_B1")
            .unwrap()
            .value;
        let has_coriolis = ap.figure.steps.iter().any(|s| s.note.contains("Coriolis"));
        assert_eq!(slip.abs() < 1e-12, vanishes, "φ₁ = {phi}: slip {slip}");
        assert_eq!(has_coriolis, !vanishes, "φ₁ = {phi}");
        // Either way the plan equals the analytic acceleration of D.
        let pose = prog.solve(phi.to_radians(), None).unwrap();
        let d = prog.index("D").unwrap();
        assert!((ap.images[d] * 1.0 - pose.ddp[d] * (15.7 * 15.7)).length() < 1e-9);
    }
}

#[test]
fn extreme_positions_have_zero_rocker_velocity_on_the_plan() {
    let v = report_json("constructions/shaper.toml", "0");
    for pos in ["1", "8′"] {
        let r = find(&v, "omega_3", pos, "plan");
        assert!(num(r, "graphical").abs() < 1e-12, "{r}");
        assert!(
            r["rel_error"].is_null(),
            "zero analytic value: relative error undefined"
        );
    }
}

#[test]
fn rocker_angular_velocity_diagram_gives_eps_with_the_factor_omega1() {
    // Seed 000 §1.5 (L574) writes ε₈ = 12·0.32 = 3.8 rad/s², forgetting ω₁; the exact ε₃ at
    // position 8 is 73.14 rad/s².
    let v = report_json("constructions/shaper.toml", "0");
    let r = find(&v, "eps_3", "8", "diagram");
    let (g, a) = (num(r, "graphical"), num(r, "analytic"));
    assert!((a.abs() - 73.14).abs() < 0.5, "analytic ε₃ at 8: {a}");
    assert!(
        (g - a).abs() < 0.25 * a.abs(),
        "diagram ε₃ at 8: {g} vs {a}"
    );
    assert!((g.abs() - 3.8).abs() > 30.0);
}

#[test]
fn tangent_method_is_an_option_of_the_scene() {
    let dir = std::env::temp_dir().join(format!("tmm-tangents-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let text = std::fs::read_to_string(root().join("constructions/shaper.toml")).unwrap();
    let scene = dir.join("shaper-tangents.toml");
    std::fs::write(
        &scene,
        text.replace(
            "[kinematics]\n",
            "[kinematics]\ndifferentiation = \"tangents\"\n",
        ),
    )
    .unwrap();
    let v = report_json(scene.to_str().unwrap(), "0");
    let chords = report_json("constructions/shaper.toml", "0");
    let t = num(find(&v, "v_S5", "4", "diagram-tangents"), "graphical");
    let c = num(find(&chords, "v_S5", "4", "diagram-chords"), "graphical");
    let a = num(find(&v, "v_S5", "4", "diagram"), "analytic");
    // The tangent at a node is the chord of its neighbours: the central difference
    // (S(φ+h) − S(φ−h))/2h = S′ + C·h² + D·h⁴ + … with C = S‴/6, D = S⁽⁵⁾/120: second
    // order. Halving h (24 positions: position 7 is position 4 of 12, the same φ₁) divides
    // the error by 4·(1 + ¾·(D/C)·h² + …) = 4·(1 + (3/80)·h²·S⁽⁵⁾/S‴); at h = π/6 that is
    // 4·(1 + 0.010·S⁽⁵⁾/S‴), so 4 ± 10 % holds while |S⁽⁵⁾/S‴| ≲ 10 (observed: 4.03).
    // Richardson's (4·t₂₄ − t₁₂)/3 cancels the h² term and leaves −D·h⁴/4, i.e.
    // (h²/80)·|S⁽⁵⁾/S‴| ≤ 0.034 of the 12-position error, itself ~2 % of v: ≤ 1e-3 of v
    // under the same |S⁽⁵⁾/S‴| ≲ 10 (observed 5e-5).
    std::fs::write(
        &scene,
        text.replace(
            "[kinematics]\n",
            "[kinematics]\ndifferentiation = \"tangents\"\n",
        )
        .replace("count = 12\n", "count = 24\n"),
    )
    .unwrap();
    let v24 = report_json(scene.to_str().unwrap(), "0");
    let t24 = num(find(&v24, "v_S5", "7", "diagram"), "graphical");
    assert_eq!(num(find(&v24, "v_S5", "7", "diagram"), "analytic"), a);
    let ratio = (t - a) / (t24 - a);
    assert!(
        (ratio - 4.0).abs() <= 0.4,
        "tangents: errors {} at 12 and {} at 24 positions, ratio {ratio}",
        t - a,
        t24 - a
    );
    let richardson = (4.0 * t24 - t) / 3.0;
    assert!(
        (richardson - a).abs() <= 1e-3 * a,
        "extrapolated {richardson} vs {a}"
    );
    assert!(t != c, "the tangent method must differ from the chords");
    // A misspelt method is refused naming the key.
    std::fs::write(
        &scene,
        text.replace(
            "[kinematics]\n",
            "[kinematics]\ndifferentiation = \"secants\"\n",
        ),
    )
    .unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_tmm"))
        .args(["check", scene.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("kinematics.differentiation"));
}

/// A kinematic sheet that draws the mechanism (its plan of positions or its scheme) writes
/// that drawing's scale in its title block; one that holds only plans and diagrams, whose
/// scales their captions give, writes «—» (issue 45: the shaper's and the V engine's second
/// sheets wrote 1:2,5 and 1:1 with no mechanism drawn on them).
#[test]
fn a_sheet_without_the_mechanism_writes_no_scale() {
    for (name, scales) in [
        ("shaper", vec!["1:2,5", "—"]),
        ("v-engine", vec!["1:1", "—"]),
        ("six-bar", vec!["1:2,5", "—"]),
        ("four-bar", vec!["1:2"]),
    ] {
        let s =
            tmm::scene::load(&crate::support::root().join(format!("constructions/{name}.toml")))
                .expect("scene");
        let session = tmm::study::Session::new(&s, Drafting::HAND);
        let kind = tmm::scene::PlateKind::parse("kinematics").expect("kind");
        let got: Vec<String> = tmm::build(&session, kind, tmm::scale::Lang::Ru)
            .expect("sheets")
            .iter()
            .map(|p| p.title_block.scale.clone())
            .collect();
        assert_eq!(got, scales, "{name}");
    }
}
