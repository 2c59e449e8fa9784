//! The command line: outputs, determinism, exit codes and messages on bad input, and that a
//! failed run writes nothing.

use std::path::{Path, PathBuf};

mod support;
use support::{root, scratch, tmm};

fn files_under(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    if let Ok(rd) = std::fs::read_dir(dir) {
        for e in rd.flatten() {
            let p = e.path();
            if p.is_dir() {
                out.extend(files_under(&p));
            } else {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

#[test]
fn render_writes_svg_and_png_and_is_byte_identical() {
    let dir = scratch("render");
    let (a, b) = (dir.join("a"), dir.join("b"));
    for out in [&a, &b] {
        let o = tmm(&[
            "render",
            "constructions/shaper.toml",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let fa = files_under(&a);
    let names: Vec<String> = fa
        .iter()
        .map(|p| p.strip_prefix(&a).unwrap().display().to_string())
        .collect();
    assert_eq!(
        names,
        [
            "shaper/dynamics.png",
            "shaper/dynamics.svg",
            "shaper/forces-2.png",
            "shaper/forces-2.svg",
            "shaper/forces.png",
            "shaper/forces.svg",
            "shaper/kinematics.png",
            "shaper/kinematics.svg",
            "shaper/positions.png",
            "shaper/positions.svg"
        ]
    );
    for f in &fa {
        let g = b.join(f.strip_prefix(&a).unwrap());
        assert_eq!(
            std::fs::read(f).unwrap(),
            std::fs::read(&g).unwrap(),
            "{} differs between runs",
            f.display()
        );
    }
    let svg = std::fs::read_to_string(a.join("shaper/positions.svg")).unwrap();
    assert!(
        svg.contains("width=\"841mm\"") && svg.contains("height=\"594mm\""),
        "A1 sheet in real millimetres"
    );
}

/// Run `render` on the shaper text edited by `edit`; return (exit code, stderr, files written).
fn render_edited(name: &str, edit: impl Fn(&str) -> String) -> (i32, String, Vec<PathBuf>) {
    let dir = scratch(name);
    let text = std::fs::read_to_string(root().join("constructions/shaper.toml")).unwrap();
    let edited = edit(&text);
    assert_ne!(edited, text, "the edit must change the scene");
    let scene = dir.join("bad.toml");
    std::fs::write(&scene, edited).unwrap();
    let out = dir.join("out");
    let o = tmm(&[
        "render",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stderr).into_owned(),
        files_under(&out),
    )
}

fn assert_refused(name: &str, code: i32, needles: &[&str], edit: impl Fn(&str) -> String) {
    let (got, err, files) = render_edited(name, edit);
    assert_eq!(got, code, "{name}: exit {got}, stderr: {err}");
    for n in needles {
        assert!(err.contains(n), "{name}: message lacks `{n}`: {err}");
    }
    assert!(files.is_empty(), "{name}: a failed run wrote {files:?}");
    assert!(!err.contains("panicked"), "{name}: {err}");
}

#[test]
fn negative_length_is_refused_naming_the_key() {
    assert_refused("negative", 2, &["mechanism.crank.length", "-140"], |t| {
        t.replace("length = 140.0", "length = -140.0")
    });
}

#[test]
fn zero_length_is_refused_naming_the_key() {
    assert_refused("zero", 2, &["mechanism.crank.length"], |t| {
        t.replace("length = 140.0", "length = 0.0")
    });
}

#[test]
fn nan_is_refused_naming_the_key() {
    assert_refused("nan", 2, &["mechanism.point[0].along", "nan"], |t| {
        t.replace("along = 710.0", "along = nan")
    });
}

#[test]
fn string_for_a_number_is_refused() {
    assert_refused("string", 2, &["length"], |t| {
        t.replace("length = 140.0", "length = \"140\"")
    });
}

#[test]
fn missing_key_is_refused() {
    assert_refused("missing", 2, &["length"], |t| {
        t.replace("length = 140.0\n", "")
    });
}

#[test]
fn mechanism_that_cannot_be_assembled_exits_1_naming_the_step() {
    // The block's slide turned parallel to the ram guide: the two lines never meet.
    assert_refused("assemble", 1, &["cannot be assembled", "group 2"], |t| {
        t.replace("slide = 90.0", "slide = 0.0")
    });
}

#[test]
fn usage_errors_exit_2() {
    assert_eq!(tmm(&["render"]).status.code(), Some(2));
    assert_eq!(
        tmm(&["render", "constructions/shaper.toml", "--lang", "fr"])
            .status
            .code(),
        Some(2)
    );
    let o = tmm(&[
        "render",
        "constructions/shaper.toml",
        "--drafting",
        "-1",
        "--out",
        scratch("drafting").to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let o = tmm(&["render", "no/such/scene.toml"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn check_and_list() {
    let o = tmm(&[
        "check",
        "constructions/shaper.toml",
        "constructions/slider-crank.toml",
        "constructions/four-bar.toml",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = tmm(&["list"]);
    let s = String::from_utf8_lossy(&o.stdout);
    for scene in ["shaper.toml", "slider-crank.toml", "four-bar.toml"] {
        assert!(s.contains(scene) && s.contains("positions"), "{s}");
    }
}

#[test]
fn check_says_a_scene_without_a_study_asks_for_nothing() {
    let dir = scratch("task-only");
    let path = dir.join("cam.toml");
    std::fs::write(&path, "[task]\ntitle = \"Кулачковый механизм\"\n").expect("scene");
    let o = tmm(&["check", path.to_str().expect("utf-8 path")]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("asks for nothing to construct"), "{err}");
    assert!(!err.contains("missing"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_given_scale_too_large_for_a_sheet_is_bad_input() {
    let dir = scratch("too-large");
    let path = edited_scene(&dir, "big.toml", |t| {
        t.replace("scale_v = 0.05 ", "scale_v = 0.002 ")
    });
    let o = tmm(&["check", path.to_str().expect("utf-8 path")]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("kinematics.scale_v = 0.004"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A scene file in `dir` edited from the shaper's.
fn edited_scene(dir: &Path, name: &str, edit: impl Fn(&str) -> String) -> PathBuf {
    let text = std::fs::read_to_string(root().join("constructions/shaper.toml")).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, edit(&text)).unwrap();
    path
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn check_checks_every_file_and_exits_with_the_worst_status() {
    let dir = scratch("check-all");
    let construction = edited_scene(&dir, "parallel.toml", |t| {
        t.replace("slide = 90.0", "slide = 0.0")
    });
    let input = edited_scene(&dir, "negative.toml", |t| {
        t.replace("length = 140.0", "length = -140.0")
    });
    let (c, i) = (construction.to_str().unwrap(), input.to_str().unwrap());

    let o = tmm(&["check", c, "constructions/four-bar.toml"]);
    let (out, err) = (text(&o.stdout), text(&o.stderr));
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert_eq!(out, "constructions/four-bar.toml: ok\n");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with("error: ") && err.contains("parallel.toml"),
        "{err}"
    );

    // Bad input outranks a construction failure, wherever it comes in the list.
    let o = tmm(&["check", i, c, "constructions/shaper.toml"]);
    let (out, err) = (text(&o.stdout), text(&o.stderr));
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(out, "constructions/shaper.toml: ok\n");
    assert!(err.contains("negative.toml") && err.contains("mechanism.crank.length"));
    assert!(err.contains("parallel.toml") && err.contains("cannot be assembled"));
    assert!(!err.contains("panicked"), "{err}");

    let o = tmm(&["check", c, i]);
    assert_eq!(o.status.code(), Some(2), "{}", text(&o.stderr));
}

#[test]
fn a_destination_that_is_a_directory_leaves_nothing_behind() {
    let dir = scratch("dest-dir");
    let out = dir.join("out");
    std::fs::create_dir_all(out.join("shaper/positions.svg")).unwrap();
    let o = tmm(&[
        "render",
        "constructions/shaper.toml",
        "--out",
        out.to_str().unwrap(),
        "--format",
        "svg",
    ]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("positions.svg") && err.contains("is a directory"),
        "{err}"
    );
    assert_eq!(files_under(&out), Vec::<PathBuf>::new());
    let names: Vec<_> = std::fs::read_dir(out.join("shaper"))
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, [std::ffi::OsString::from("positions.svg")]);

    // A file where a folder is needed: nothing is created, not even the folders.
    let blocked = dir.join("blocked");
    std::fs::write(&blocked, b"a file").unwrap();
    let o = tmm(&[
        "render",
        "constructions/shaper.toml",
        "--out",
        blocked.join("deeper").to_str().unwrap(),
        "--format",
        "svg",
    ]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("not a directory"), "{err}");
    assert_eq!(std::fs::read(&blocked).unwrap(), b"a file");
}

#[test]
fn two_scenes_with_one_stem_are_refused() {
    let dir = scratch("same-stem");
    let other = dir.join("other");
    std::fs::create_dir_all(&other).unwrap();
    let twin = edited_scene(&other, "shaper.toml", |t| t.to_string());
    let out = dir.join("out");
    for args in [
        vec!["constructions/shaper.toml", twin.to_str().unwrap()],
        vec!["constructions/shaper.toml", "constructions/shaper.toml"],
    ] {
        let mut all = vec!["render"];
        all.extend(args);
        all.extend(["--out", out.to_str().unwrap(), "--format", "svg"]);
        let o = tmm(&all);
        let err = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(
            err.contains("shaper.toml") && err.contains("both would write"),
            "{err}"
        );
        assert!(!out.exists(), "a refused run wrote {:?}", files_under(&out));
    }
}

#[test]
fn bad_numbers_on_the_command_line_are_one_line_naming_the_flag() {
    let out = scratch("flags");
    for (args, needle) in [
        (vec!["--drafting", "-1"], "--drafting -1"),
        (vec!["--drafting", "nan"], "--drafting NaN"),
        (vec!["--dpi", "0"], "--dpi 0"),
        (vec!["--dpi", "2401"], "--dpi 2401"),
        (vec!["--dpi", "2400"], "at most 1177 dpi"),
    ] {
        let mut all = vec!["render", "constructions/shaper.toml", "--out"];
        all.push(out.to_str().unwrap());
        all.extend(args.iter().copied());
        let o = tmm(&all);
        let err = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
    assert_eq!(files_under(&out), Vec::<PathBuf>::new());
    let help = text(&tmm(&["render", "--help"]).stdout);
    assert!(help.contains("2^30") && help.contains("1177 dpi"), "{help}");
}
