//! Hard cases of the force analysis over every scene: a load at a slider's joint, every
//! position in equilibrium, a load's link where the joint is ambiguous, zero loads, a gear
//! drive holding the crank back, vanishing arms, a seed value echoed compactly.

use crate::forces::{num, refused_with_keys, rows_at};
use crate::support;
use serde_json::Value;
use support::{root, tmm};

/// A working resistance at the slider's joint B of the slider-crank acts on the slider 3 (the
/// textbooks' ram or piston), not on the rod 2: the rod–slider reaction R₂₋₃ at position 2 is
/// 1090.3 N (the 294.0 N of a load put on the rod is not produced), and the polygons, the
/// lever and the linear solve agree with it.
#[test]
fn a_load_at_the_sliders_joint_acts_on_the_slider() {
    let v = support::report_json("constructions/slider-crank.toml", None);
    let rows = rows_at(&v, "2");
    let r23 = rows
        .iter()
        .find(|r| r["quantity"] == "R_2_3" && r["method"] == "polygon")
        .expect("R_2_3");
    let (g, a) = (num(r23, "graphical"), num(r23, "analytic"));
    assert!((a - 1090.3).abs() <= 1e-3 * 1090.3, "R_2_3 = {a}");
    assert!((g - a).abs() <= 1e-9 * a);
    assert!((a - 294.0).abs() > 100.0);
}

/// Every force position of every scene: each moving link's own equations, evaluated from the
/// scene's loads and the reported reactions (with and without friction), hold to 1e-9 of the
/// largest force for the polygons (graphical) and the linear solve (analytic).
#[test]
fn every_force_position_of_every_scene_is_in_equilibrium() {
    let mut seen = 0;
    for entry in std::fs::read_dir(root().join("constructions")).expect("scenes") {
        let path = entry.expect("entry").path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).expect("scene");
        if !text.contains("[forces]") {
            continue;
        }
        let stem = path.file_stem().unwrap().to_string_lossy().to_string();
        let v = support::report_json(&format!("constructions/{stem}.toml"), None);
        let positions: std::collections::BTreeSet<String> = v["rows"]
            .as_array()
            .expect("rows")
            .iter()
            .filter(|r| r["quantity"] == "M_bal")
            .filter_map(|r| r["position"].as_str().map(str::to_string))
            .collect();
        assert!(!positions.is_empty(), "{stem}: no force positions");
        for p in &positions {
            let rows = rows_at(&v, p);
            let res: Vec<&&Value> = rows
                .iter()
                .filter(|r| {
                    r["quantity"]
                        .as_str()
                        .is_some_and(|q| q.starts_with("equilibrium_residual"))
                })
                .collect();
            let friction = text.contains("[forces.friction]");
            assert_eq!(res.len(), 1 + usize::from(friction), "{stem} {p}");
            for r in res {
                for col in ["graphical", "analytic"] {
                    let x = num(r, col);
                    assert!(
                        (0.0..=1e-9).contains(&x),
                        "{stem} {p} {}: {x}",
                        r["quantity"]
                    );
                }
            }
            seen += 1;
        }
    }
    assert!(seen >= 8, "{seen} force positions");
}

/// A load at a joint the rule cannot decide (the crank pin of a rod, two bars) must name its
/// link; a named link must carry the point.
#[test]
fn a_loads_link_is_named_where_the_joint_is_ambiguous() {
    refused_with_keys(
        "load-links",
        "slider-crank",
        &[
            (
                "point = \"B\"",
                "point = \"A\"",
                "forces.resistance[0].point",
            ),
            (
                "point = \"B\"",
                "point = \"B\"\nlink = 1",
                "forces.resistance[0].link",
            ),
        ],
    );
    // Naming the rod at A is accepted.
    let dir = support::scratch("load-links-ok");
    let text = std::fs::read_to_string(root().join("constructions/slider-crank.toml")).unwrap();
    let path = dir.join("s.toml");
    std::fs::write(
        &path,
        text.replace("point = \"B\"", "point = \"A\"\nlink = 2"),
    )
    .unwrap();
    let out = tmm(&["check", path.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Zero loads give zero reactions without a `scale_f`: the slider-crank with no masses and no
/// resistance (friction included) reports every reaction and the balancing moment as 0.
#[test]
fn zero_loads_give_zero_reactions_without_a_force_scale() {
    let text = std::fs::read_to_string(root().join("constructions/slider-crank.toml")).unwrap();
    let mut text = text
        .replace("mass = 3.0", "mass = 0.0")
        .replace("mass = 5.0", "mass = 0.0");
    let start = text.find("[[forces.resistance]]").expect("resistance");
    let end = start + text[start..].find("\n[forces.drive]").expect("drive");
    text.replace_range(start..end, "");
    assert!(!text.contains("scale_f"));
    let dir = support::scratch("zero-loads");
    let path = dir.join("zero.toml");
    std::fs::write(&path, text).unwrap();
    let v = support::report_json(path.to_str().unwrap(), None);
    let rows = v["rows"].as_array().expect("rows");
    let forces: Vec<&Value> = rows
        .iter()
        .filter(|r| {
            let q = r["quantity"].as_str().unwrap_or("");
            q.starts_with("R_") || q.starts_with("M_bal") || q.starts_with("F_bal")
        })
        .collect();
    assert!(forces.len() >= 20, "{}", forces.len());
    for r in forces {
        assert_eq!(num(r, "graphical"), 0.0, "{r}");
        assert_eq!(num(r, "analytic"), 0.0, "{r}");
    }
}

/// A gear drive whose balancing moment opposes ω₁ (the shaper's crank turns clockwise; at
/// positions 11 and 12 the balancing moment is counter-clockwise): the tooth only pushes, so
/// the balancing force is positive on the mirrored line of action, the polygons, the lever
/// and the linear solve agree, every link is in equilibrium with the frame's reaction on the
/// crank that this flank gives, and a note says so.
#[test]
fn a_gear_drive_that_holds_the_crank_back_pushes_on_the_other_flank() {
    let text = std::fs::read_to_string(root().join("constructions/shaper.toml")).unwrap();
    let text = text.replace(
        "positions = [\"3\", \"10\"]\n",
        "positions = [\"3\", \"10\", \"11\", \"12\"]\n",
    );
    assert!(text.contains("\"11\", \"12\""));
    let dir = support::scratch("gear-flank");
    let path = dir.join("shaper.toml");
    std::fs::write(&path, text).unwrap();
    let v = support::report_json(path.to_str().unwrap(), None);
    let notes = support::notes(&v);
    for p in ["11", "12"] {
        let rows = rows_at(&v, p);
        let find = |q: &str, m: &str| {
            rows.iter()
                .find(|r| r["quantity"] == q && r["method"] == m)
                .unwrap_or_else(|| panic!("{q} {m} at {p}"))
        };
        let m_bal = num(find("M_bal", "polygon"), "analytic");
        assert!(
            m_bal > 0.0,
            "M_bal at {p} = {m_bal}: opposes the clockwise crank"
        );
        for m in ["polygon", "lever"] {
            let r = find("F_bal", m);
            let (g, a) = (num(r, "graphical"), num(r, "analytic"));
            assert!(
                a > 0.0 && (g - a).abs() <= 1e-9 * a,
                "F_bal by {m} at {p}: {g} vs {a}"
            );
        }
        let res = find("equilibrium_residual", "polygon");
        assert!(num(res, "graphical") <= 1e-9 && num(res, "analytic") <= 1e-9);
        assert!(
            notes.contains(&format!("position {p}: the balancing moment"))
                && notes
                    .matches("opposes ω₁: the pinion holds the crank back")
                    .count()
                    == 2,
            "{notes}"
        );
    }
}

/// The v-engine's h_0_3 and h_0_5 (the arm of a reaction through a slider's own guide) are
/// rounding residues against 0: judged by the zero rule against the mechanism's size, never
/// ±100 % (JSON `rel_error` ±1).
#[test]
fn arms_that_vanish_are_judged_as_zero_not_as_a_hundred_per_cent() {
    let r = support::report_json("constructions/v-engine.toml", None);
    let arms: Vec<&serde_json::Value> = r["rows"]
        .as_array()
        .expect("rows")
        .iter()
        .filter(|row| {
            row["quantity"]
                .as_str()
                .is_some_and(|q| q.starts_with("h_0_"))
        })
        .collect();
    assert_eq!(arms.len(), 4);
    for row in arms {
        let analytic = row["analytic"].as_f64().expect("analytic");
        assert!(analytic.abs() < 1e-12, "{row}");
        assert!(row["rel_error"].is_null(), "{row}");
        assert!(row["abs_error"].as_f64().expect("abs") < 1e-12, "{row}");
    }
}

/// A seed value echoed in the notes as the scene gives it, compactly: `-1e-300`, not 300 zeros
/// (the full mutation sweep's last finding).
#[test]
fn a_seed_value_is_echoed_compactly() {
    let text = std::fs::read_to_string(root().join("constructions/shaper.toml")).expect("shaper");
    let text = text.replacen("value = 112.0\n", "value = -1e-300\n", 1);
    let dir = support::scratch("seed-echo");
    let path = dir.join("shaper.toml");
    std::fs::write(&path, text).expect("write");
    let o = tmm(&["report", path.to_str().expect("utf-8")]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        out.contains("F_bal (polygon): the seed prints -1e-300 kgf"),
        "{out}"
    );
    assert!(!out.contains("0.0000000000"), "{out}");
    let _ = std::fs::remove_dir_all(&dir);
}
