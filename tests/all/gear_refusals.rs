//! Bad `[gears]` and `[planetary]` sections refused with the key that makes them, out of
//! range scales, modules and speeds refused at load, and the ends of the documented ranges
//! rendered.

use crate::gears::run_scene;
use crate::support;
use support::{notes, render_svg, report_json as report, scratch, tmm};

#[test]
fn bad_gear_sections_name_their_keys() {
    let cases: &[(&str, &[&str])] = &[
        // Interference: zero shifts on 13/21 teeth, the wheel's tip passes N₁.
        (
            "[gears]\nmodule = 10.0\n[gears.pair]\nz = [13, 21]\nx = [0.0, 0.0]\n",
            &["gears.pair.x = [0.0, 0.0]", "interference"],
        ),
        // A pointed pinion.
        (
            "[gears]\nmodule = 10.0\n[gears.pair]\nz = [13, 21]\nx = [1.6, 0.0]\n",
            &["gears.pair.x[0]", "pointed"],
        ),
        // An infeasible centre distance: below r_b1 + r_b2.
        (
            "[gears]\nmodule = 10.0\n[gears.pair]\nz = [13, 21]\nx = [0.5]\ncentre_distance = 150.0\n",
            &["gears.pair.centre_distance = 150", "infeasible"],
        ),
        // A rack-cut wheel whose flanks meet below its tip.
        (
            "[gears]\nmodule = 10.0\n[[gears.rack]]\nz = 10\nx = 0.9\n",
            &["gears.rack[0].x = 0.9", "meet below its tip circle"],
        ),
        (
            "[gears]\nmodule = -1.0\nrho_f = 0.9\n[[gears.rack]]\nz = 3\npositions = 1\n",
            &["gears.module = -1", "gears.rho_f", "gears.rack[0].z = 3", "gears.rack[0].positions = 1"],
        ),
        (
            "[gears]\nmodule = 2.0\n",
            &["expected a [gears.pair] or at least one [[gears.rack]]"],
        ),
        // A blank's shortening out of range, and one that takes the tip below the root.
        (
            "[gears]\nmodule = 10.0\n[[gears.rack]]\nz = 20\ndy = -0.5\n[[gears.rack]]\nz = 20\ndy = 2.5\n",
            &["gears.rack[0].dy = -0.5", "gears.rack[1].dy = 2.5", "above the root circle"],
        ),
        // The seed's printed values: positive, α_w below 90°, cos α_w at most 1.
        (
            "[gears]\nmodule = 10.0\n[gears.pair]\nz = [13, 21]\nx = [0.694, 0.384]\n[gears.seed]\neps_alpha = -1.0\nalpha_w = 95.0\ncos_alpha_w = 1.5\n",
            &["gears.seed.eps_alpha = -1", "gears.seed.alpha_w = 95", "gears.seed.cos_alpha_w = 1.5"],
        ),
        // An input that does not turn has no required ratio.
        (
            "[planetary]\ninput = \"1\"\noutput = \"2\"\nn_input = 0.0\nn_output = 10.0\n[[planetary.wheel]]\nname = \"1\"\nz = 20\nshaft = \"1\"\n[[planetary.wheel]]\nname = \"2\"\nz = 40\nshaft = \"2\"\n[[planetary.mesh]]\nwheels = [\"1\", \"2\"]\n",
            &["planetary.n_input = 0", "not 0"],
        ),
        (
            "[planetary]\ninput = \"1\"\noutput = \"2\"\n[[planetary.wheel]]\nname = \"1\"\nz = 20\nshaft = \"1\"\n[[planetary.wheel]]\nname = \"2\"\nz = 40\nshaft = \"2\"\n",
            &["planetary.mesh", "mobility"],
        ),
        (
            "[planetary]\ninput = \"1\"\noutput = \"9\"\nfixed = \"7\"\n[[planetary.wheel]]\nname = \"1\"\nz = 20\nshaft = \"1\"\n[[planetary.mesh]]\nwheels = [\"1\", \"5\"]\n",
            &["planetary.fixed = \"7\"", "planetary.mesh[0].wheels"],
        ),
    ];
    for (k, (text, expected)) in cases.iter().enumerate() {
        for cmd in [&["check"][..], &["report"][..]] {
            let (ok, code, err) = run_scene(&format!("bad-gears-{k}"), text, cmd);
            assert!(!ok && code == 2, "case {k} {cmd:?}: {code} {err}");
            assert!(!err.contains("panicked"), "case {k}: {err}");
            for e in *expected {
                assert!(err.contains(e), "case {k} {cmd:?}: `{e}` not in\n{err}");
            }
        }
    }
}

/// A train scene: wheels 1 and 2 meshing on shafts 1 and 2, `planetary` lines added to
/// `[planetary]`, and `rest` (more wheels and meshes) after them.
fn train(planetary: &str, rest: &str) -> String {
    format!(
        "[planetary]\n{planetary}\n[[planetary.wheel]]\nname = \"1\"\nz = 20\nshaft = \"1\"\n[[planetary.wheel]]\nname = \"2\"\nz = 40\nshaft = \"2\"\n[[planetary.mesh]]\nwheels = [\"1\", \"2\"]\n{rest}"
    )
}

#[test]
fn refusals_name_the_key_that_makes_them() {
    let seed_pair = "[gears]\nmodule = 14.0\n[gears.pair]\nz = [13, 30]\nx = [0.8, 0.471]\n";
    let cases: Vec<(String, &[&str], &[&str])> = vec![
        // α = 25° with ГОСТ's ρ_f* = 0.38: the rounding, not the pair's tooth numbers.
        (
            seed_pair.replace("[gears]\n", "[gears]\nalpha = 25.0\n"),
            &["gears.rho_f = 0.38 (the default)", "ρ_f* ≤ 0.3179 with α = 25°"],
            &["gears.pair.z", "gears.pair.x"],
        ),
        // Δy = 2.5: the tip of wheel 1 below its base circle (was ε_α = −3.42 on `x`).
        (
            format!("{seed_pair}dy = 2.5\n"),
            &["gears.pair.dy = 2.5", "falls below its base circle"],
            &["gears.pair.x", "ε_α"],
        ),
        // Δy = 0.6: ε_α < 1 with the table's Δy, but the pair works with the exact one.
        (
            format!("{seed_pair}dy = 0.6\n"),
            &["gears.pair.dy = 0.6", "ε_α"],
            &["gears.pair.x"],
        ),
        // A tool tooth pointed before its tip line.
        (
            "[gears]\nmodule = 2.0\nalpha = 40.0\nrho_f = 0.0\n[[gears.rack]]\nz = 20\n".into(),
            &["gears.alpha = 40", "α ≤ 32.1419°"],
            &["gears.rack[0].x"],
        ),
        (
            train("input = \"1\"\noutput = \"1\"", ""),
            &["planetary.output = \"1\"", "other than the input"],
            &[],
        ),
        (
            train("input = \"1\"\noutput = \"2\"\nfixed = \"1\"", ""),
            &["planetary.fixed = \"1\"", "other than the input"],
            &[],
        ),
        (
            train("input = \"1\"\noutput = \"2\"\nfixed = \"2\"", ""),
            &["planetary.fixed = \"2\"", "other than the output"],
            &[],
        ),
        // A carrier without satellites (was blamed on `planetary.mesh`).
        (
            train(
                "input = \"1\"\noutput = \"2\"\ncarrier = \"2\"",
                "",
            ),
            &["planetary.satellites: missing", "carrier 2"],
            &["planetary.mesh"],
        ),
        (
            train(
                "input = \"1\"\noutput = \"2\"\nsatellites = [\"2\"]",
                "",
            ),
            &["planetary.carrier: missing"],
            &["planetary.mesh"],
        ),
        // The input held at rest by 2'–3 with 3 fixed; 4 meshes nothing (was "a link turns
        // freely").
        (
            train(
                "input = \"1\"\noutput = \"4\"\nfixed = \"3\"",
                "[[planetary.wheel]]\nname = \"2'\"\nz = 20\nshaft = \"2\"\n[[planetary.wheel]]\nname = \"3\"\nz = 30\nshaft = \"3\"\n[[planetary.wheel]]\nname = \"4\"\nz = 30\nshaft = \"4\"\n[[planetary.mesh]]\nwheels = [\"2'\", \"3\"]\n",
            ),
            &["planetary.input = \"1\"", "hold the input shaft 1 at rest", "only 4 can turn"],
            &["turns freely"],
        ),
    ];
    for (k, (text, expected, absent)) in cases.iter().enumerate() {
        for cmd in [&["check"][..], &["report"][..]] {
            let (ok, code, err) = run_scene(&format!("refused-{k}"), text, cmd);
            assert!(!ok && code == 2, "case {k} {cmd:?}: {code} {err}");
            assert!(!err.contains("panicked"), "case {k}: {err}");
            for e in *expected {
                assert!(err.contains(e), "case {k} {cmd:?}: `{e}` not in\n{err}");
            }
            for e in *absent {
                assert!(!err.contains(e), "case {k} {cmd:?}: `{e}` in\n{err}");
            }
        }
    }
}

#[test]
fn a_drafting_that_reads_the_output_as_zero_names_drafting() {
    // Seed 000's reducer: the output's intercept on the plan of ω is 6.3 mm (ω₈ = 15.75 rad/s
    // at μ_ω = 2.5 rad/(s·mm): H = 20 mm keeps the satellite's 81 mm within the reach). The
    // project's scene also holds the dynamics, whose energy diagram reads as 0 by 100 mm.
    for (d, ok) in [("12.5", true), ("12.7", false), ("20", false)] {
        let o = tmm(&[
            "report",
            "constructions/shaper.toml",
            "--drafting",
            d,
            "--format",
            "json",
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.success(), ok, "{d}: {err}");
        if !ok {
            assert!(
                err.contains(&format!("--drafting {d} mm"))
                    && err.contains("intercept of shaft 8")
                    && err.contains("6.300 mm drawn")
                    && err.contains("below 12.600 mm"),
                "{err}"
            );
            assert!(!err.contains("does not turn"), "{err}");
        }
    }
    let o = tmm(&["report", "constructions/shaper.toml", "--drafting", "100"]);
    let err = String::from_utf8_lossy(&o.stderr);
    // The first output the drafting reads as 0 is named (the train's intercept).
    assert!(
        err.contains("--drafting 100 mm reads") && err.contains("as 0"),
        "{err}"
    );
}

#[test]
fn small_profile_angles_put_the_exact_junction_on_the_tooth() {
    for (alpha, r_mm) in [("1.0", 68.9905), ("2.0", 68.6919)] {
        let dir = scratch(&format!("alpha-{alpha}"));
        let path = dir.join("rack.toml");
        std::fs::write(
            &path,
            format!(
                "[gears]\nmodule = 10.0\nalpha = {alpha}\nrho_f = 0.0\n[[gears.rack]]\nz = 13\n"
            ),
        )
        .expect("write");
        let v = report(path.to_str().expect("utf-8"), None);
        let n = notes(&v);
        // r_a = 75 mm: was 711.634 mm (α = 1°) and 299.039 mm (α = 2°) "exactly".
        let want = format!(
            "the involute meets the fillet at r = {r_mm} mm on the drawing, {r_mm} mm exactly"
        );
        assert!(n.contains(&want), "{n}");
    }
}

#[test]
fn scales_modules_and_speeds_out_of_range_are_refused_at_load() {
    let rack = |line: &str| format!("[gears]\nmodule = 10.0\n[[gears.rack]]\nz = 13\n{line}\n");
    let pair = |line: &str| {
        format!("[gears]\nmodule = 14.0\n{line}\n[gears.pair]\nz = [13, 30]\nx = [0.8, 0.471]\n")
    };
    let cases: Vec<(String, &[&str])> = vec![
        // lyon's hatcher panicked (≥ 1e45); 1e-9 … 1e-10 hatched a 1e7 mm tooth (24 GB).
        (
            rack("scale_l = 1e300"),
            &["gears.rack[0].scale_l = 1e300", "4πm = 0.1257 m"],
        ),
        (rack("scale_l = 1e45"), &["gears.rack[0].scale_l = 1e45"]),
        (
            rack("scale_l = 1e-9"),
            &[
                "gears.rack[0].scale_l = 1e-9",
                "from 2.513e-5 to 0.006283 m/mm",
            ],
        ),
        (rack("scale_l = 1e-10"), &["gears.rack[0].scale_l = 1e-10"]),
        (
            rack("scale_l = 0.0063"),
            &["gears.rack[0].scale_l = 0.0063"],
        ),
        (
            pair("scale_l = 1e40"),
            &["gears.scale_l = 1e40", "a_w + r_a1 + r_a2"],
        ),
        (pair("scale_l = 1e-7"), &["gears.scale_l = 1e-7"]),
        (
            rack("module = 1e-300"),
            &["gears.rack[0].module", "from 0.01 to 1000 mm"],
        ),
        (pair("alpha = 1e30"), &["gears.alpha", "0° < α < 45°"]),
        (
            train("input = \"1\"\noutput = \"2\"\nmodule = 1e-300", ""),
            &["planetary.module", "from 0.01 to 1000 mm"],
        ),
        (
            train(
                "input = \"1\"\noutput = \"2\"\nn_input = 100.0\nn_output = 1e300",
                "",
            ),
            &["planetary.n_output", "at most 1e6"],
        ),
    ];
    for (k, (text, expected)) in cases.iter().enumerate() {
        // Under a 1 GB address-space limit: the refusal comes before any work.
        let dir = scratch(&format!("range-{k}"));
        let path = dir.join("scene.toml");
        std::fs::write(&path, text).expect("write scene");
        let o = std::process::Command::new("sh")
            .arg("-c")
            .arg("ulimit -v 1048576; exec \"$0\" check \"$1\"")
            .arg(env!("CARGO_BIN_EXE_tmm"))
            .arg(&path)
            .output()
            .expect("run tmm");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "case {k}: {err}");
        assert!(!err.contains("panicked"), "case {k}: {err}");
        for e in *expected {
            assert!(err.contains(e), "case {k}: `{e}` not in\n{err}");
        }
    }
}

#[test]
fn the_ends_of_the_documented_ranges_render() {
    let out = scratch("range-ends");
    let cases = [
        // The figures at their least size (4πm = 125.7 mm as 20.3 mm; the pair's 21 mm), the
        // modules at both ends, a profile angle of 1°, the most rack positions.
        "[gears]\nmodule = 10.0\n[[gears.rack]]\nz = 13\nscale_l = 0.0062\n",
        "[gears]\nmodule = 0.01\n[[gears.rack]]\nz = 13\n",
        "[gears]\nmodule = 1000.0\n[[gears.rack]]\nz = 13\n",
        "[gears]\nmodule = 10.0\nalpha = 1.0\n[[gears.rack]]\nz = 13\n",
        "[gears]\nmodule = 10.0\n[[gears.rack]]\nz = 13\npositions = 5000\n",
        "[gears]\nmodule = 14.0\nscale_l = 0.0316\n[gears.pair]\nz = [13, 30]\nx = [0.8, 0.471]\n",
    ];
    for (k, text) in cases.iter().enumerate() {
        let path = out.join(format!("end{k}.toml"));
        std::fs::write(&path, format!("{text}[plates]\nwanted = [\"gears\"]\n")).expect("write");
        render_svg(&path, &out, &format!("case {k}"));
    }
}
