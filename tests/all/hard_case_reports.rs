//! Hard cases through the whole report: the shaper's pin through and beside the rocker's
//! pivot, and an engine worked from its outer dead centre.

use crate::common;
use common::slider_crank;
use tmm::construct::Drafting;
use tmm::linkage::*;

/// Hard case 1 through the whole report: the shaper with its crank as long as A–C, started
/// where the pin passes through the rocker's pivot. Every row is finite and of the size of
/// the mechanism's motion (the old report printed ε₃ = 1.3e18 and a_D = 9.5e17 there).
#[test]
fn report_of_a_pin_through_the_pivot_holds_no_huge_number() {
    let report = shaper_report_with_crank("430.0");
    assert!(report.rows.len() > 100);
    // Through the coincidence the slotted link's direction (C → B) flips by 180° between
    // neighbouring crank angles and S_5 jumps: the chord diagrams are refused, naming the
    // position (they showed a_S5 = 504 against 43.8 m/s²).
    assert!(
        !report.rows.iter().any(|r| r.method.is_diagram()),
        "a diagram row across the flip"
    );
    assert!(
        report
            .note_texts()
            .iter()
            .any(|n| n.contains("link 3 turns 179.")
                && n.contains("nearest position 1 ")
                && n.contains("diagrams over a crank turn are refused")),
        "{:#?}",
        report.note_texts()
    );
    for r in &report.rows {
        assert!(
            r.graphical.is_finite() && r.analytic.is_finite() && r.analytic.abs() < 1e3,
            "{} at {:?}: {} / {}",
            r.quantity(),
            r.position(),
            r.graphical,
            r.analytic
        );
    }
    let at1 = |q: &str, m: tmm::Method| {
        report
            .rows
            .iter()
            .find(|r| r.quantity() == q && r.position().as_deref() == Some("1") && r.method == m)
            .unwrap_or_else(|| panic!("no {q}"))
    };
    let w = at1("omega_3", tmm::Method::Plan);
    assert!((w.graphical + 7.853981633974483).abs() < 1e-9, "{w:?}");
    assert!((w.analytic + 7.853981633974483).abs() < 1e-9, "{w:?}");
    let a = at1("a_D", tmm::Method::Plan);
    assert!((a.analytic - 43.7963695).abs() < 1e-6 && (a.graphical - a.analytic).abs() < 1e-9);
    assert!(at1("eps_3", tmm::Method::Plan).analytic.abs() < 1e-6);
}

/// The report of the shaper's kinematics with the crank `length` mm long (A–C is 430 mm),
/// started at φ₁ = −90° where the pin is nearest the rocker's pivot C; acceleration plans at
/// positions 1 and 4, at the common μ_a.
fn shaper_report_with_crank(length: &str) -> tmm::Report {
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("constructions/shaper.toml")).expect("shaper");
    // The kinematics only: the loads of the force analysis come last in the file.
    let text = text.split("\n[forces]").next().unwrap_or_default();
    let text = text
        .replace(
            "\"kinematics\", \"forces\", \"cam\", \"gears\", \"dynamics\", \"flywheel\"]",
            "\"kinematics\"]",
        )
        .replace("length = 140.0", &format!("length = {length}"))
        .replace("start = \"working-stroke\"", "start = -90.0")
        .replace(
            "acceleration_positions = [\"3\", \"10\"]",
            "acceleration_positions = [\"1\", \"4\"]",
        )
        .replace("own_scale_a = [\"3\"]", "");
    let scene = tmm::scene::parse(&text, &root.join("pin.toml")).expect("scene");
    tmm::study::Session::new(&scene, Drafting::EXACT)
        .report()
        .expect("report")
}

/// Issue 17 §1b through the whole report: the shaper's crank 429.99 mm, so the pin passes
/// m = 0.01 mm from the rocker's pivot at position 1 (φ₁ = 270°). The exact closed form there
/// (see [`kulisa_pin_beside_the_pivot_gives_the_true_huge_rate`]) is ω₃ = |ω₁|·r/m =
/// 5π·0.42999/1e-5 = 6.7543e5 rad/s (the 80-digit value of the issue), a_D = 0.71·ω₃², taken
/// with the scene's decimal m (the f64 inputs differ from it by ~5e-12 relative). The old
/// report printed ω₃ = −7.854 rad/s, L₃ = 8e-17 m, and its plan disagreed with its twin by
/// 100 % (v_B3B1), all without a note.
#[test]
fn report_of_a_pin_beside_the_pivot_gives_the_true_values_with_a_note() {
    let report = shaper_report_with_crank("429.99");
    let (r, m) = (0.42999, 1e-5);
    let w3 = 5.0 * std::f64::consts::PI * r / m;
    let at1 = |q: &str| {
        report
            .rows
            .iter()
            .find(|r| r.quantity() == q && r.position().as_deref() == Some("1"))
            .unwrap_or_else(|| panic!("no {q}"))
    };
    let w = at1("omega_3");
    for v in [w.graphical, w.analytic] {
        assert!(((v - w3) / w3).abs() < 1e-9, "ω₃ = {v} against {w3}");
    }
    let a = at1("a_D");
    let a_d = 0.71 * w3 * w3;
    for v in [a.graphical, a.analytic] {
        assert!(((v - a_d) / a_d).abs() < 1e-9, "a_D = {v} against {a_d}");
    }
    // The block slides across the slot at the nearest point: v_B3B1 = |v_B|·cos φ₁ ≈ 0.
    let v = at1("v_B3_B1");
    assert!(v.graphical.abs() < 1e-6 && v.analytic.abs() < 1e-6, "{v:?}");
    // The analytic table's L₃ = |CB| = m.
    let table = &report.tables[0];
    let col = table
        .columns
        .iter()
        .position(|c| c.name == "L_3")
        .expect("L_3");
    let row1 = table.rows.iter().find(|r| r.0 == "1").expect("row 1");
    let l3 = row1.1[col].expect("L_3 at 1");
    assert!((l3 - m).abs() < 1e-15, "L₃ = {l3}");
    assert!(
        report
            .note_texts()
            .iter()
            .any(|n| n.starts_with("position 1: the pin B passes 1.000e-5 m")
                && n.contains("ill-conditioned")),
        "{:#?}",
        report.note_texts()
    );
    // The slot whips round within 0.005° of the crank: the chord diagrams are refused there.
    assert!(!report.rows.iter().any(|r| r.method.is_diagram()));
    assert!(
        report
            .note_texts()
            .iter()
            .any(|n| n.contains("link 3 turns") && n.contains("nearest position 1 ")),
        "{:#?}",
        report.note_texts()
    );
}

/// The working stroke of a central slider-crank (θ = 0: both strokes take 180°) by the rule
/// of `Program::extremes`: driven (a pump, a compressor), the stroke from the slider's minimum
/// along `dir`; driving (an engine's piston), the stroke from the outer dead centre, the
/// crank along the cylinder (φ₁ = 0 here: B at r + l from O) — whichever way `dir` points.
#[test]
fn an_engine_works_from_its_outer_dead_centre() {
    let (r, l) = (0.04, 0.16);
    for dir in [0.0, std::f64::consts::PI] {
        let mut m = slider_crank(r, l);
        if let Some(Output::Slider { dir: d, .. }) = m.outputs.first_mut() {
            *d = dir;
        }
        let prog = Program::compile(&m).unwrap();
        let driven = prog.extremes(&m.outputs, m.crank.sense, false).unwrap();
        let engine = prog.extremes(&m.outputs, m.crank.sense, true).unwrap();
        let b = prog.index("B").unwrap();
        let reach = |phi: f64| prog.solve(phi, None).unwrap().p[b].length();
        // The outer dead centre: B at r + l from O, the crank at φ₁ = 0.
        assert!(
            (reach(engine.phi_start) - (r + l)).abs() < 1e-12,
            "dir {dir}"
        );
        assert!(
            (reach(engine.phi_other) - (l - r)).abs() < 1e-12,
            "dir {dir}"
        );
        assert!(engine.from_outer && !driven.from_outer);
        assert!((engine.work_travel - std::f64::consts::PI).abs() < 1e-9);
        assert!(engine.theta.abs() < 1e-9 && (engine.k - 1.0).abs() < 1e-9);
        // Driven: from the minimum along `dir`, the inner dead centre for dir 0, the outer
        // for dir 180°.
        let inner_first = dir == 0.0;
        let want = if inner_first { l - r } else { r + l };
        assert!((reach(driven.phi_start) - want).abs() < 1e-12, "dir {dir}");
    }
}
