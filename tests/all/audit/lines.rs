//! Lines of a student's table the audit reads with care: a point's velocity signed as the
//! textbook signs it, a written 0, a line the report has nothing for (marked, the rest
//! audited), and a table refused whole for a fault of the file.

use super::audit;
use crate::support::{root, scratch, tmm};
use tmm::audit::{Auditor, Held, Slip, Verdict};
use tmm::scene::{self, Scene};

/// The shipped four-bar (crank 80 mm at ω₁ = 10 rad/s clockwise, rocker O₃B 180 mm).
fn four_bar() -> Scene {
    scene::load(&root().join("constructions/four-bar.toml")).expect("the four-bar")
}

#[test]
fn a_point_turning_about_a_frame_pivot_has_the_sign_of_its_link() {
    // The textbook's V_D = L_CD·ω₃: V of a point of a link turning about a fixed pivot is
    // ω·r. On the four-bar, the crank pin A (r = 0.08 m, ω₁ = −10 rad/s) and the rocker's
    // B (r = 0.18 m); the coupler point S₂ turns about no fixed pivot and stays |V|.
    let scene = four_bar();
    let auditor = Auditor::new(&scene).expect("the auditor");
    let report = tmm::study::Session::new(&scene, tmm::construct::Drafting::EXACT)
        .report()
        .expect("the report");
    let mut checked = 0;
    for w3 in report.rows.iter().filter(|r| r.quantity() == "omega_3") {
        let p = w3.position();
        let p = p.as_deref();
        for method in [Some("analytic"), Some("plan"), None] {
            let v = |q: &str| auditor.value(q, p, method).expect("a velocity");
            assert!((v("v_A") + 0.8).abs() < 1e-12, "v_A at {p:?}: {}", v("v_A"));
            assert!(
                (v("v_B") - 0.18 * w3.analytic).abs() < 1e-12,
                "v_B at {p:?}"
            );
            assert!(v("v_S2") >= 0.0, "v_S2 at {p:?}");
        }
        checked += 1;
    }
    assert_eq!(checked, 13);
}

#[test]
fn a_written_zero_is_right_only_where_the_value_is_zero() {
    // A 0 matched every scale slip that makes a small number (×0.1 or ×0.01 or …) and, with
    // its half unit of 0.5, any value under 0.5: V_B = 0.107 m/s at position 7. An exponent
    // of −2³¹ overflowed the half unit (to infinity in a release build: anything was right);
    // one of 2³¹ − 1 on a 0 is a 0 still.
    let scene = four_bar();
    let table = "quantity,position,method,value,unit
v_A,3,plan,0,m/s
v_B,7,plan,0,m/s
v_B,7,analytic,0.00,m/s
v_B,7′,plan,0,m/s
v_B,7′,analytic,0e-2147483648,m/s
omega_3,7′,plan,0e2147483647,rad/s
v_A,4,plan,0e2147483647,m/s
v_A,5,plan,8e-1,m/s
v_A,6,plan,0.8000000000000000000001e0,m/s
v_A,2,plan,0.000000008e8,m/s
v_A,8,plan,0.0e-2147483648,m/s
";
    let all = audit(&scene, table);
    let verdicts: Vec<&Verdict> = all.iter().map(|a| &a.verdict).collect();
    let wrong = Verdict::Wrong { nearest: None };
    // 0 for V_B at 7 is the value of the next position, 7′ (a shifted row).
    let shifted = Verdict::Slips(vec![vec![Slip::Position("7′".into())]]);
    assert_eq!(
        verdicts,
        [
            &wrong,
            &shifted,
            &shifted,
            &Verdict::Right,
            &Verdict::Right,
            &Verdict::Right,
            &wrong,
            &Verdict::Right,
            &Verdict::Right,
            &Verdict::Right,
            &wrong
        ]
    );
}

#[test]
fn a_line_the_report_lacks_is_marked_and_the_rest_audited() {
    // φ₃, L₃ and the accelerations at every position are the analytic table's; the four-bar
    // builds acceleration plans at some positions only. A quantity, position or method the
    // report has nothing for is one line marked, not the whole table refused.
    let scene = four_bar();
    let auditor = Auditor::new(&scene).expect("the auditor");
    let value = |q: &str, p: &str| {
        auditor
            .value(q, Some(p), Some("analytic"))
            .unwrap_or_else(|| panic!("{q} at {p}"))
    };
    let (phi3, a_b) = (value("phi_3", "5"), value("a_B", "5"));
    let planned: Vec<String> = tmm::study::Session::new(&scene, tmm::construct::Drafting::EXACT)
        .report()
        .expect("the report")
        .rows
        .iter()
        .filter(|r| r.quantity() == "a_B" && r.method.key() == "plan")
        .filter_map(|r| r.position())
        .collect();
    assert!(!planned.contains(&"5".to_string()), "{planned:?}");
    let table = format!(
        "quantity,position,method,value,unit
v_A,1,,0.8,m/s
v_Q,1,,0.6,m/s
v_A,99,,0.6,m/s
v_B,3,lever,0.6,m/s
phi_3,5,analytic,{:.2},deg
phi_3,5,,{:.4},rad
a_B,5,analytic,{:.4},m/s^2
a_B,5,plan,{:.4},m/s^2
L_3,5,analytic,0.18,m
",
        phi3,
        phi3.to_radians(),
        a_b,
        a_b * 1.001
    );
    let all = audit(&scene, &table);
    let not_in_report = |k: usize| match &all[k].verdict {
        Verdict::NotInReport { known } => known.clone(),
        v => panic!("line {}: {v:?}", all[k].entry.line),
    };
    assert_eq!(all[0].verdict, Verdict::Right);
    assert!(not_in_report(1).is_empty(), "v_Q: no such quantity");
    // v_A at 99: the report has it by plan and in the table, at 1 … 12.
    let known = not_in_report(2);
    assert!(
        known.iter().any(|(m, at)| m.is_none() && at.len() >= 12),
        "{known:?}"
    );
    assert!(!not_in_report(3).is_empty(), "v_B by the lever");
    for (k, held) in [
        (4, Held::Analytic),
        (5, Held::Analytic),
        (6, Held::Analytic),
        (7, Held::Borrowed { position: None }),
    ] {
        let a = &all[k];
        let c = a
            .checked
            .as_ref()
            .unwrap_or_else(|| panic!("line {}", a.entry.line));
        assert_eq!(a.verdict, Verdict::Right, "line {}", a.entry.line);
        match (&c.held, &held) {
            (Held::Borrowed { position }, Held::Borrowed { .. }) => {
                assert!(
                    position.as_ref().is_some_and(|p| planned.contains(p)),
                    "{position:?}"
                )
            }
            (h, _) => assert_eq!(h, &held, "line {}", a.entry.line),
        }
    }
    // L₃ of a four-bar is no column of its table (its groups have no slide).
    assert!(not_in_report(8).is_empty());
    // The command writes every line, the lacking ones marked; its status is 0.
    let dir = scratch("audit-lacking");
    let path = dir.join("table.csv");
    std::fs::write(&path, &table).expect("the table");
    let four = root().join("constructions/four-bar.toml");
    let o = tmm(&[
        "audit",
        &four.display().to_string(),
        &path.display().to_string(),
        "--lang",
        "en",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let md = String::from_utf8_lossy(&o.stdout);
    assert!(
        md.contains("| 3 | v_Q | 1 |  | 0.6 m/s | — | — | no such quantity in the report |"),
        "{md}"
    );
    assert!(md.contains("| 4 | v_A | 99 |  | 0.6 m/s | — | — | not in the report; the report has: vector plan at pos. 1, 2,"), "{md}");
    assert!(
        md.contains("| 9 | a_B | 5 | plan (tolerance of pos. "),
        "{md}"
    );
    // No value of v_A is written negative where the crank pin's is (ω₁ < 0): magnitudes.
    assert!(md.contains("though exact values are): v_A."), "{md}");
}

#[test]
fn a_bad_table_is_refused_with_its_line_column_and_key() {
    let dir = scratch("audit-bad");
    let four_bar = root().join("constructions/four-bar.toml");
    for (name, text, expected) in [
        (
            "no-unit",
            "quantity,position,value\nv_A,1,0.6\n",
            "the header has no column `unit`",
        ),
        (
            "twice",
            "quantity,position,value,unit,value\nv_A,1,0.6,m/s,0.8\n",
            "the header names the column `value` twice (columns 3 and 5)",
        ),
        (
            "twice-quantity",
            "Quantity,position,value,unit,QUANTITY\nv_A,1,0.6,m/s,v_B\n",
            "the header names the column `quantity` twice (columns 1 and 5)",
        ),
        (
            "too-large",
            "quantity,position,value,unit\nv_A,1,1e400,m/s\n",
            "line 2, column 3 (value): \"1e400\": out of the range of a number",
        ),
        (
            "too-small",
            "quantity,position,value,unit\nv_A,1,8e-2147483648,m/s\n",
            "line 2, column 3 (value): \"8e-2147483648\": out of the range of a number",
        ),
        (
            "unknown-unit",
            "quantity,position,value,unit\nv_Q,1,0.6,furlong\n",
            "line 2, column 4 (unit): \"furlong\": not a unit the audit knows",
        ),
        (
            "not-a-number",
            "quantity,position,value,unit\nv_A,1,0.6,m/s\nv_A,2,abc,m/s\n",
            "line 3, column 3 (value): \"abc\": not a number",
        ),
        (
            "bad-unit",
            "quantity,position,value,unit\nv_A,1,0.6,kg\n",
            "line 2, column 4 (unit): \"kg\": not a unit of v_A",
        ),
        (
            "short",
            "quantity,position,value,unit\nv_A,1,0.6\n",
            "line 2, column 4 (unit): 3 fields, the header has 4",
        ),
        (
            "method",
            "quantity,position,value,unit,method\nv_A,1,0.6,m/s,compass\n",
            "line 2, column 5 (method)",
        ),
    ] {
        let table = dir.join(format!("{name}.csv"));
        std::fs::write(&table, text).expect("the table");
        let pdf = dir.join(format!("{name}.pdf"));
        let o = tmm(&[
            "audit",
            &four_bar.display().to_string(),
            &table.display().to_string(),
            "--pdf",
            &pdf.display().to_string(),
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{name}: {err}");
        assert!(err.contains(expected), "{name}: {err}");
        assert!(
            o.stdout.is_empty() && !pdf.exists(),
            "{name}: nothing is written"
        );
    }
}
