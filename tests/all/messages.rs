//! Messages on hostile input say what is wrong in a line a user reads (issue 43 §9): a tiny
//! number written compactly, a table written twice named as such, a file that is not UTF-8
//! said to be so, whatever file it is.

use crate::support;
use support::{scratch, tmm};

/// The shaper's scene with `edit` applied, written to a scratch folder; its path.
fn shaper_with(name: &str, edit: impl Fn(&str) -> String) -> std::path::PathBuf {
    let text = std::fs::read_to_string(support::root().join("constructions/shaper.toml"))
        .expect("the shaper");
    let path = scratch(name).join(format!("{name}.toml"));
    std::fs::write(&path, edit(&text)).expect("write the scene");
    path
}

/// An edit of a scene's text that sets the first `key = …` line to `value`.
fn set(key: &'static str, value: &'static str) -> impl Fn(&str) -> String {
    move |t: &str| {
        let start = t.find(&format!("\n{key} = ")).expect("the key") + 1;
        let end = start + t[start..].find('\n').expect("its line");
        format!("{}{key} = {value}{}", &t[..start], &t[end..])
    }
}

/// `tmm args…`: its exit code and standard error.
fn run(args: &[&str]) -> (Option<i32>, String) {
    let o = tmm(args);
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn a_tiny_delta_is_echoed_compactly() {
    let scene = shaper_with("delta-tiny", set("delta", "1e-300"));
    let (code, err) = run(&["check", scene.to_str().unwrap()]);
    // No flywheel gives it: the construction fails (1), naming the key.
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("dynamics.delta") && err.contains("δ = 1e-300"),
        "{err}"
    );
    assert!(!err.contains("0000000000"), "{err}");
}

#[test]
fn a_table_written_twice_is_named_with_its_first_line() {
    let scene = shaper_with("table-twice", |t| {
        let start = t.find("[mechanism.crank]").expect("the crank");
        let end = start + 1 + t[start + 1..].find("\n[").expect("the next table");
        format!("{}\n{}", &t[..end], &t[start..])
    });
    let first = std::fs::read_to_string(&scene)
        .unwrap()
        .lines()
        .position(|l| l.trim() == "[mechanism.crank]")
        .unwrap()
        + 1;
    let (code, err) = run(&["check", scene.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains(&format!(
            "the table `[mechanism.crank]` is written twice (first at line {first})"
        )),
        "{err}"
    );
    assert!(!err.contains("answer_key"), "{err}");
}

#[test]
fn a_file_that_is_not_utf8_is_said_to_be_so() {
    let dir = scratch("not-utf8");
    let table = dir.join("table.csv");
    std::fs::write(
        &table,
        b"quantity,position,value,unit\nv_B,1,\xff\xfe,m/s\n",
    )
    .unwrap();
    let (code, err) = run(&[
        "audit",
        "constructions/shaper.toml",
        table.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("table.csv:2: not UTF-8 text (byte 35"),
        "{err}"
    );
    assert!(!err.contains("scene"), "{err}");
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, b"[task]\ntitle = \"\xc0\"\n").unwrap();
    let (code, err) = run(&["check", scene.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("scene.toml:2: not UTF-8 text"), "{err}");
}

/// A drawing too large only because its lengths are read coarsely is blamed on the reading
/// (issue 43 §8: `--drafting 100` blamed `kinematics.scale_s` alone).
#[test]
fn a_drawing_too_large_by_a_coarse_reading_names_the_reading() {
    let out = scratch("coarse-reading");
    let (code, err) = run(&[
        "render",
        "constructions/shaper.toml",
        "--format",
        "svg",
        "--drafting",
        "100",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("--drafting 100 mm: kinematics.scale_s"),
        "{err}"
    );
    assert!(err.contains("read exactly it fits"), "{err}");
    assert!(!out.join("shaper").exists());
}

/// The dynamics' given scale and pole are refused by what they draw, naming the key
/// (issue 43 §8: μ_M = 1e-12 with H = 1e-6 mm ended in "A_с: interval 0: the line does not
/// cut the interval's end ordinate").
#[test]
fn the_dynamics_scale_and_pole_are_refused_by_what_they_draw() {
    let scene = shaper_with("pole-tiny", set("pole_h", "1e-6"));
    let (code, err) = run(&["check", scene.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("dynamics.pole_h = 1e-6: expected a pole distance H from 1 to 500 mm"),
        "{err}"
    );
    let scene = shaper_with("scale-m-tiny", set("scale_m", "1e-12"));
    let (code, err) = run(&["check", scene.to_str().unwrap()]);
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("dynamics.scale_m = 1e-12: draws the diagram's largest value"),
        "{err}"
    );
    assert!(err.contains("expected 0.1 … 10000 mm"), "{err}");
}

/// An output that cannot be written is the user's to mend: exit 2 in `audit --pdf` as in
/// `render` (issue 43 §9: it was 1).
#[test]
fn an_unwritable_audit_sheet_is_exit_2() {
    let dir = scratch("audit-unwritable");
    let pdf = dir.join("sheet.pdf");
    std::fs::create_dir_all(&pdf).unwrap();
    let (code, err) = run(&[
        "audit",
        "constructions/shaper.toml",
        "constructions/tables/seed-000.csv",
        "--pdf",
        pdf.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("sheet.pdf: cannot write"), "{err}");
}
