//! The documented ranges of the mechanism's and the kinematic study's keys (issue 17 §4, §5):
//! every value inside works, every value outside is refused at load naming the key and the
//! range (exit 2), and nothing grows without bound on the way.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::support;
use support::{root, scratch};

/// The shaper's text with its kinematics only (the loads of the force analysis come last).
fn shaper_kinematics() -> String {
    let text = std::fs::read_to_string(root().join("constructions/shaper.toml")).expect("shaper");
    text.split("\n[forces]").next().unwrap_or_default().replace(
        "\"kinematics\", \"forces\", \"cam\", \"gears\", \"dynamics\", \"flywheel\"]",
        "\"kinematics\"]",
    )
}

/// `tmm ARGS…` on `text` written to a scratch scene, with the address space limited to
/// 1 GiB (`ulimit -v`): a run that tries to allocate more fails instead of swapping.
fn run_limited(name: &str, text: &str, args: &[&str]) -> (Output, PathBuf) {
    let dir = scratch(name);
    let scene = dir.join(format!("{name}.toml"));
    std::fs::write(&scene, text).expect("write scene");
    let out = dir.join("out");
    let mut cmd = vec![env!("CARGO_BIN_EXE_tmm").to_string()];
    cmd.extend(args.iter().map(|a| a.to_string()));
    cmd.push(scene.to_string_lossy().into_owned());
    if args.first() == Some(&"render") {
        // The limits are the construction's: read exactly, not as a hand reading does (a
        // derivative of 200 positions read to 0.5 mm is noise no sheet holds).
        cmd.extend(["--out".into(), out.to_string_lossy().into_owned()]);
        cmd.extend(["--drafting".into(), "0".into()]);
    }
    let quoted: Vec<String> = cmd.iter().map(|a| format!("'{a}'")).collect();
    let o = Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v 1048576 && exec {}", quoted.join(" ")))
        .output()
        .expect("run tmm");
    (o, out)
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Refused at load: exit 2, the message names each of `needles`, nothing written.
fn assert_refused(name: &str, text: &str, needles: &[&str]) {
    let (o, out) = run_limited(name, text, &["check"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{name}: {err}");
    for n in needles {
        assert!(err.contains(n), "{name}: the message lacks `{n}`: {err}");
    }
    assert!(!err.contains("panicked"), "{name}: {err}");
    assert!(!out.exists(), "{name}: wrote {}", out.display());
}

fn files_under(dir: &Path) -> usize {
    std::fs::read_dir(dir).map_or(0, |d| d.count())
}

/// §4: a link numbered 2e7 sized every per-link array by that number (21 GB, three minutes
/// for `tmm check`). Link numbers beyond 99 are refused at load with the key, inside 1 GiB.
#[test]
fn a_huge_link_number_is_refused_at_load() {
    let text = shaper_kinematics()
        .replace("links = [4, 5]", "links = [4, 20000000]")
        .replace("link = 5\n", "link = 20000000\n");
    assert_refused(
        "link-2e7",
        &text,
        &["mechanism.group[1].links", "20000000", "1 … 99"],
    );
    // The largest number allowed works: the ram numbered 99.
    let text = shaper_kinematics()
        .replace("links = [4, 5]", "links = [4, 99]")
        .replace("link = 5\n", "link = 99\n")
        .replace("links = [5, 0]", "links = [99, 0]");
    let (o, out) = run_limited("link-99", &text, &["render", "--format", "svg"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(files_under(&out.join("link-99")) >= 2);
}

/// §5: `positions.count` above ≈ 112 with the kinematics plate failed (exit 1, no key: the
/// analytic table, one row per position, was taller than a sheet). The table is continued on
/// further sheets; 1 and 2 positions (no diagrams) work as well.
#[test]
fn every_documented_position_count_draws_the_kinematics_plate() {
    for n in [1, 2, 113, 200] {
        let text = shaper_kinematics()
            .replace("count = 12", &format!("count = {n}"))
            .replace("[\"3\", \"10\"]", "[\"1\"]")
            .replace("own_scale_a = [\"3\"]", "own_scale_a = [\"1\"]");
        let name = format!("count-{n}");
        let (o, out) = run_limited(&name, &text, &["render", "--format", "svg"]);
        assert!(o.status.success(), "count {n}: {}", stderr(&o));
        let dir = out.join(&name);
        let sheets: Vec<String> = (1..20)
            .map(|k| {
                let file = if k == 1 {
                    "kinematics.svg".to_string()
                } else {
                    format!("kinematics-{k}.svg")
                };
                std::fs::read_to_string(dir.join(file)).unwrap_or_default()
            })
            .filter(|s| !s.is_empty())
            .collect();
        assert!(!sheets.is_empty(), "count {n}: no kinematics sheet");
        // Every position's row is in the table: the last label appears, and a long table is
        // continued under its title.
        let all = sheets.concat();
        assert!(all.contains(&format!(">{n}<")), "count {n}: no row {n}");
        if n > 112 {
            assert!(all.contains("(продолжение)"), "count {n}: not continued");
        }
    }
}

/// §5: given scales and poles of the mechanism and the kinematic study, and its angles, are
/// refused at load with the key and the range outside it (μ_l = 1e40 drew an invisible
/// plate, exit 0; 1e-300 failed with exit 1 and no key; 1e30° was taken), and both ends of
/// each range are honoured: the coarse end draws (exit 0), the fine end draws a drawing too
/// large for a sheet, refused naming the key (exit 2).
#[test]
fn scales_poles_and_angles_outside_their_ranges_are_refused_at_load() {
    // The shaper: r = 0.14 m, ω₁ = 5π rad/s; the ranges draw r, ω₁r, ω₁²r 0.1 … 1e4 mm, 2π
    // 10 … 1e4 mm; poles 1 … 500 mm.
    let w = 5.0 * std::f64::consts::PI;
    let ends = [
        (
            "scale_l = 0.0025",
            "scale_l",
            0.14 / 0.1,
            0.14 / 1e4,
            "mechanism.scale_l",
        ),
        (
            "scale_v = 0.05",
            "scale_v",
            w * 0.14 / 0.1,
            w * 0.14 / 1e4,
            "kinematics.scale_v",
        ),
        (
            "scale_a = 1.0",
            "scale_a",
            w * w * 0.14 / 0.1,
            w * w * 0.14 / 1e4,
            "kinematics.scale_a",
        ),
        (
            "scale_s = 0.005",
            "scale_s",
            0.14 / 0.1,
            0.14 / 1e4,
            "kinematics.scale_s",
        ),
    ];
    for (given, key, coarse, fine, full) in ends {
        let with = |v: f64| shaper_kinematics().replace(given, &format!("{key} = {v:e}"));
        let (o, _) = run_limited(
            &format!("{key}-coarse"),
            &with(coarse),
            &["render", "--format", "svg"],
        );
        assert!(o.status.success(), "{key} = {coarse}: {}", stderr(&o));
        let (o, _) = run_limited(&format!("{key}-fine"), &with(fine), &["check"]);
        assert_eq!(o.status.code(), Some(2), "{key} = {fine}: {}", stderr(&o));
        assert!(stderr(&o).contains(full), "{key} = {fine}: {}", stderr(&o));
        for bad in [coarse * 1.01, fine / 1.01, 1e40, 1e-300] {
            assert_refused(
                &format!("{key}-bad"),
                &with(bad),
                &[full, "between 0.1 and 10000 mm"],
            );
        }
    }
    for (given, key, lo, hi) in [
        ("scale_phi = 0.052", "scale_phi", 0.0, 0.0),
        ("pole_h1 = 28.0", "pole_h1", 1.0, 500.0),
        ("pole_h2 = 7.5", "pole_h2", 1.0, 500.0),
    ] {
        let with = |v: f64| shaper_kinematics().replace(given, &format!("{key} = {v:e}"));
        let full = format!("kinematics.{key}");
        if lo > 0.0 {
            let (o, _) = run_limited(
                &format!("{key}-lo"),
                &with(lo),
                &["render", "--format", "svg"],
            );
            assert!(o.status.success(), "{key} = {lo}: {}", stderr(&o));
            for bad in [lo / 1.01, hi * 1.01, 1e40, 1e-300] {
                assert_refused(
                    &format!("{key}-bad"),
                    &with(bad),
                    &[&full, "from 1 to 500 mm"],
                );
            }
        } else {
            for bad in [
                std::f64::consts::TAU / 9.9,
                std::f64::consts::TAU / 1.01e4,
                1e40,
                1e-300,
            ] {
                assert_refused(
                    &format!("{key}-bad"),
                    &with(bad),
                    &[&full, "between 10 and 10000 mm"],
                );
            }
        }
    }
    for (given, to, key) in [
        (
            "start = \"working-stroke\"",
            "start = 1e30",
            "positions.start",
        ),
        (
            "dir = 0.0, offset",
            "dir = -1e30, offset",
            "mechanism.group[1].guide.dir",
        ),
        ("slide = 90.0", "slide = 3601.0", "mechanism.group[1].slide"),
    ] {
        let text = shaper_kinematics().replace(given, to);
        assert_refused("angle", &text, &[key, "within ±360"]);
    }
    // 3600° itself is an angle: the guide turned ten full turns is the same guide.
    let text = shaper_kinematics().replace("dir = 0.0, offset", "dir = 3600.0, offset");
    let (o, _) = run_limited("angle-3600", &text, &["check"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// §3: the force analysis at a change point named `kinematics.acceleration_positions`; it
/// names `forces.positions` and the position (a parallelogram four-bar folded at φ₁ = 0).
#[test]
fn forces_at_a_change_point_name_forces_positions() {
    let text = r#"
[[mechanism.fixed]]
name = "O_1"
at = [0.0, 0.0]
[[mechanism.fixed]]
name = "O_3"
at = [200.0, 0.0]
[mechanism.crank]
centre = "O_1"
pin = "A"
length = 100.0
omega = 10.0
sense = "ccw"
[[mechanism.group]]
kind = "RRR"
links = [2, 3]
a = "A"
la = 200.0
b = "O_3"
lb = 100.0
joint = "B"
branch = "left"
[[mechanism.output]]
rocker = 3
[positions]
start = 0.0
[forces]
positions = ["1"]
[[forces.link]]
link = 2
mass = 2.0
centre = "A"
[[forces.resistance]]
link = 3
moment = 10.0
[plates]
wanted = ["forces"]
"#;
    let (o, out) = run_limited("change-point", text, &["render", "--format", "svg"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("forces.positions: position 1: the force analysis needs its velocity plan"),
        "{err}"
    );
    assert!(!err.contains("kinematics.acceleration_positions"), "{err}");
    assert_eq!(files_under(&out), 0);
}

/// `[dynamics] count` over its documented range 4 … 360 draws the dynamics plate: Tables 9
/// and 10, a row per position, continue on further sheets (issue 43 §7: 360 needed
/// 158 × 1809 mm of one sheet).
#[test]
fn every_documented_dynamics_count_draws_the_dynamics_plate() {
    let text = std::fs::read_to_string(root().join("constructions/shaper.toml")).expect("shaper");
    let only = text.replace(
        "wanted = [\"positions\", \"kinematics\", \"forces\", \"cam\", \"gears\", \"dynamics\", \"flywheel\"]",
        "wanted = [\"dynamics\"]",
    );
    assert_ne!(only, text, "the shaper's wanted plates");
    for n in [4, 120, 360] {
        let with = only.replacen("\n[dynamics]\n", &format!("\n[dynamics]\ncount = {n}\n"), 1);
        let name = format!("dynamics-{n}");
        let (o, out) = run_limited(&name, &with, &["render", "--format", "svg"]);
        assert!(o.status.success(), "count {n}: {}", stderr(&o));
        let second = out.join(&name).join("dynamics-2.svg");
        if n == 360 {
            let svg = std::fs::read_to_string(&second).expect("the continuation");
            assert!(svg.contains("(продолжение)"), "count {n}");
            // Every position's row is on some sheet: the last one's label.
            let sheets: String = (1..)
                .map(|k| match k {
                    1 => out.join(&name).join("dynamics.svg"),
                    k => out.join(&name).join(format!("dynamics-{k}.svg")),
                })
                .map_while(|p| std::fs::read_to_string(p).ok())
                .collect();
            assert!(sheets.contains(">359<"), "count {n}: row 359");
        } else if n == 4 {
            assert!(!second.exists(), "count {n}: one sheet");
        }
    }
}
