//! The two-cylinder V engine end to end: the report's rows of an engine (the work of the
//! indicator diagrams, the constant resisting moment, the flywheel for δ = 1/80), and bad
//! `[[forces.indicator]]` and `[dynamics] constant_moment` keys refused with their paths.

use crate::support;
use support::{num, report_json as report, rows_of as rows, scratch, tmm};

fn report_json(scene: &str) -> serde_json::Value {
    report(scene, None)
}

const SCENE: &str = "constructions/v-engine.toml";

#[test]
fn the_engine_report_has_the_driving_work_and_the_resisting_moment() {
    let v = report_json(SCENE);
    // An engine: A_drive and M_res, not the machine's A_res and M_drive.
    assert!(rows(&v, "A_res").is_empty() && rows(&v, "M_drive").is_empty());
    let a = rows(&v, "A_drive");
    assert_eq!(a.len(), 1);
    assert!(a[0]["position"].is_null());
    assert_eq!(a[0]["method"], "integration");
    let a_d = num(a[0], "analytic");
    // 382.723 J per turn (the independent ∮p·A·ds is in the library's engine tests).
    assert!((a_d - 382.7231).abs() < 1e-3, "{a_d}");
    // The chords over 12 positions: within 1 %.
    assert!((num(a[0], "graphical") - a_d).abs() < 0.01 * a_d);
    let m = rows(&v, "M_res");
    assert_eq!(m.len(), 1);
    let m_c = num(m[0], "analytic");
    assert!(
        (m_c - a_d / std::f64::consts::TAU).abs() < 1e-9 * a_d,
        "{m_c}"
    );
    // The exact flywheel gives δ = 1/80; the textbook routes show their method error.
    for r in rows(&v, "delta") {
        assert!((num(r, "analytic") - 0.0125).abs() < 1e-6, "{r}");
    }
    let j = rows(&v, "J_flywheel");
    assert_eq!(j.len(), 2);
    // Over the scene's 12 positions (its `count`) each route is about 4 % short of the exact
    // flywheel (within 1 % over 24), never exactly it.
    for r in &j {
        let e = num(r, "rel_error");
        assert!(e < -0.01 && e > -0.05, "{r}");
    }
    // Per position: the reduction off the velocity plans equals the twin at drafting 0.
    for q in ["M_red", "J_red"] {
        let rs = rows(&v, q);
        assert_eq!(rs.len(), 12, "{q}");
        for r in rs {
            assert!(
                num(r, "abs_error") < 1e-9 * (1.0 + num(r, "analytic").abs()),
                "{r}"
            );
        }
    }
    // The force analysis: the polygons and the lever agree on M_bal at both positions.
    let mb = rows(&v, "M_bal");
    assert_eq!(mb.len(), 4);
    for r in mb {
        assert!(num(r, "rel_error").abs() < 1e-9, "{r}");
    }
}

#[test]
fn bad_indicator_keys_are_refused_with_their_paths() {
    let text = std::fs::read_to_string(support::root().join(SCENE)).expect("the scene");
    let first = "[[forces.indicator]]\npoint = \"B\"";
    assert!(text.contains(first));
    let table = "pressure = [\n    [0.0, 2.6], [10.0, 4.2], [25.0, 3.4], [45.0, 2.0], [70.0, 1.1], [100.0, 0.55],\n    [120.0, 0.3], [140.0, 0.05], [180.0, 0.0], [220.0, 0.05], [240.0, 0.12],\n    [270.0, 0.3], [300.0, 0.65], [320.0, 1.05], [340.0, 1.7], [360.0, 2.6],\n]";
    assert_eq!(text.matches(table).count(), 2);
    let one = |from: &str, to: &str| text.replacen(from, to, 1);
    let cases: Vec<(String, &[&str])> = vec![
        (
            one("[10.0, 4.2]", "[10.0, -4.2]"),
            &["forces.indicator[0].pressure[1] = -4.2", "≥ 0 MPa"],
        ),
        (
            one("[25.0, 3.4]", "[5.0, 3.4]"),
            &["forces.indicator[0].pressure[2] = 5", "increasing"],
        ),
        (
            one("[10.0, 4.2]", "[10.0, nan]"),
            &["forces.indicator[0].pressure[1] = nan"],
        ),
        (
            one("[340.0, 1.7], [360.0, 2.6],", "[340.0, 1.7],"),
            &["forces.indicator[0].pressure", "θ = 360°"],
        ),
        (
            one("[340.0, 1.7], [360.0, 2.6],", "[340.0, 1.7], [360.0, 2.0],"),
            &["forces.indicator[0].pressure", "periodic"],
        ),
        (
            one("[10.0, 4.2]", "[10.0, 4.2, 1.0]"),
            &["forces.indicator[0].pressure[1]", "[θ°, p MPa]"],
        ),
        (
            one(first, "[[forces.indicator]]\npoint = \"A\""),
            &["forces.indicator[0].point = \"A\"", "piston"],
        ),
        (
            one(first, "[[forces.indicator]]\npoint = \"Z\""),
            &["forces.indicator[0].point"],
        ),
        (
            one("bore = 70.0", "bore = -70.0"),
            &["forces.indicator[0].bore = -70"],
        ),
        (
            text.replacen("bore = 70.0\n", "", 2),
            &[
                "forces.indicator[0].bore: missing",
                "forces.indicator[1].bore: missing",
            ],
        ),
        (
            one("offset = 135.0", "offset = inf"),
            &["forces.indicator[1].offset"],
        ),
        (
            text.replacen(table, "", 1),
            &["forces.indicator[0].pressure: missing"],
        ),
        (
            one("point = \"C\"", "point = \"C\"\nstroke = 2"),
            &["unknown field"],
        ),
        (
            one(
                "constant_moment = \"resisting\"",
                "constant_moment = \"both\"",
            ),
            &["dynamics.constant_moment = \"both\""],
        ),
    ];
    for (k, (body, expected)) in cases.iter().enumerate() {
        let dir = scratch(&format!("bad-indicator-{k}"));
        let path = dir.join("bad.toml");
        std::fs::write(&path, body).expect("write");
        let o = tmm(&["check", path.to_str().expect("utf-8")]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "case {k}: {err}");
        assert!(!err.contains("panicked"), "case {k}: {err}");
        for e in *expected {
            assert!(err.contains(e), "case {k}: `{e}` not in\n{err}");
        }
    }
}

#[test]
fn an_engine_with_a_constant_driving_moment_is_refused() {
    // The gas forces drive: with the default constant driving moment there is no resistance
    // to balance, and the study says so instead of inventing a negative driving moment.
    let text = std::fs::read_to_string(support::root().join(SCENE)).expect("the scene");
    let body = text.replacen("constant_moment = \"resisting\"\n", "", 1);
    let dir = scratch("engine-driving");
    let path = dir.join("engine.toml");
    std::fs::write(&path, body).expect("write");
    let o = tmm(&["report", path.to_str().expect("utf-8"), "--format", "json"]);
    let all = format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(!all.contains("panicked"), "{all}");
    assert!(all.contains("working resistances do"), "{all}");
    assert!(all.contains("constant_moment = \"resisting\""), "{all}");
}

#[test]
fn a_crank_turning_clockwise_reads_the_cycle_the_other_way() {
    // θ = σ·(φ₁ − offset): turned clockwise, each cylinder meets the same diagram from its
    // top dead centre on, and the piston's travel x(axis ± u) is symmetric — the same work.
    let text = std::fs::read_to_string(support::root().join(SCENE)).expect("the scene");
    let body = text.replacen("sense = \"ccw\"", "sense = \"cw\"", 1);
    assert_ne!(body, text);
    let dir = scratch("engine-cw");
    let path = dir.join("engine.toml");
    std::fs::write(&path, body).expect("write");
    let v = report_json(path.to_str().expect("utf-8"));
    let a = num(rows(&v, "A_drive")[0], "analytic");
    assert!((a - 382.7231).abs() < 1e-3, "{a}");
    for r in rows(&v, "delta") {
        assert!((num(r, "analytic") - 0.0125).abs() < 1e-6, "{r}");
    }
}
