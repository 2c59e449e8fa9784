//! The command line: outputs, determinism, exit codes and messages on bad input, and that a
//! failed run writes nothing.

use std::path::{Path, PathBuf};

use crate::support;
use support::{files_under, root, scratch, tmm};

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
            "shaper/cam.png",
            "shaper/cam.svg",
            "shaper/dynamics.png",
            "shaper/dynamics.svg",
            "shaper/flywheel.png",
            "shaper/flywheel.svg",
            "shaper/forces-2.png",
            "shaper/forces-2.svg",
            "shaper/forces.png",
            "shaper/forces.svg",
            "shaper/gears.png",
            "shaper/gears.svg",
            "shaper/kinematics-2.png",
            "shaper/kinematics-2.svg",
            "shaper/kinematics.png",
            "shaper/kinematics.svg"
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
    let svg = std::fs::read_to_string(a.join("shaper/kinematics.svg")).unwrap();
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
    // The scale that fits every drawing μ_v sets, on every plate (0.004 fitted the first
    // velocity plan only).
    assert!(err.contains("kinematics.scale_v = 0.025"), "{err}");
    let fixed = edited_scene(&dir, "fixed.toml", |t| {
        t.replace("scale_v = 0.05 ", "scale_v = 0.025 ")
    });
    let o = tmm(&["check", fixed.to_str().expect("utf-8 path")]);
    assert!(o.status.success(), "{}", text(&o.stderr));
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
    std::fs::create_dir_all(out.join("shaper/kinematics.svg")).unwrap();
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
        err.contains("kinematics.svg") && err.contains("is a directory"),
        "{err}"
    );
    assert_eq!(files_under(&out), Vec::<PathBuf>::new());
    let names: Vec<_> = std::fs::read_dir(out.join("shaper"))
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, [std::ffi::OsString::from("kinematics.svg")]);

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

/// Run `render` (SVG) on the shaper edited by `edit`; (exit code, stderr); the run must write
/// nothing when it fails.
fn render_shaper_edited(name: &str, format: &str, edit: impl Fn(&str) -> String) -> (i32, String) {
    let dir = scratch(name);
    let scene = edited_scene(&dir, "shaper.toml", edit);
    let out = dir.join("out");
    let o = tmm(&[
        "render",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--format",
        format,
    ]);
    let code = o.status.code().unwrap_or(-1);
    let err = text(&o.stderr);
    assert!(!err.contains("panicked"), "{name}: {err}");
    if code != 0 {
        assert_eq!(files_under(&out), Vec::<PathBuf>::new(), "{name}: {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
    (code, err)
}

#[test]
fn control_characters_in_any_text_are_refused_naming_the_key() {
    for (edit_from, edit_to, key) in [
        (
            "title = \"Поперечно-строгальный станок\"",
            "title = \"abc\\u0001def\"",
            "task.title = \"abc\\u{1}def\"",
        ),
        (
            "name = \"C\" ",
            "name = \"C\\u007f\" ",
            "mechanism.fixed[1].name",
        ),
        (
            "wanted = [\"positions\"",
            "wanted = [\"posi\\ttions\"",
            "plates.wanted[0]",
        ),
        ("[task]\n", "[task]\nnote = \"a\\nb\\u0085\"\n", "task.note"),
    ] {
        let (code, err) = render_shaper_edited("control", "svg", |t| {
            assert!(t.contains(edit_from), "{edit_from}");
            t.replacen(edit_from, edit_to, 1)
        });
        assert_eq!(code, 2, "{key}: {err}");
        assert!(err.contains(key), "{key}: {err}");
        assert!(err.contains("control characters"), "{key}: {err}");
    }
    // Unicode text that is not a control character stays welcome.
    let (code, err) = render_shaper_edited("unicode", "svg", |t| {
        t.replace("Поперечно-строгальный станок", "Станок — ω₁, μ_l «№ 5»")
    });
    assert_eq!(code, 0, "{err}");
}

#[test]
fn an_endless_or_huge_scene_file_is_refused_naming_it() {
    let o = tmm(&["check", "/dev/zero"]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("/dev/zero") && err.contains("larger than 1048576 bytes"),
        "{err}"
    );
    // Just over the cap, in comments: refused; the same text within the cap: read.
    let dir = scratch("huge");
    let scene = std::fs::read_to_string(root().join("constructions/four-bar.toml")).unwrap();
    let line = "# ".to_string() + &"x".repeat(1021) + "\n";
    let pad = |n: usize| line.repeat(n);
    let over = dir.join("over.toml");
    std::fs::write(&over, scene.clone() + &pad(1024)).unwrap();
    let under = dir.join("under.toml");
    std::fs::write(&under, scene.clone() + &pad(1000)).unwrap();
    let o = tmm(&["check", over.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2), "{}", text(&o.stderr));
    assert!(text(&o.stderr).contains("over.toml"));
    let o = tmm(&["check", under.to_str().unwrap()]);
    assert!(o.status.success(), "{}", text(&o.stderr));
}

#[test]
fn an_unknown_table_is_named_as_a_table() {
    for (added, want) in [
        ("[foo]\nx = 1\n", "unknown table `[foo]`"),
        ("[[foo.bar]]\nx = 1\n", "unknown table `[[foo]]`"),
        ("[forces.extra]\nx = 1\n", "unknown table `[forces.extra]`"),
    ] {
        let (code, err) = render_shaper_edited("table", "svg", |t| format!("{t}\n{added}"));
        assert_eq!(code, 2, "{err}");
        assert!(err.contains(want), "{want}: {err}");
    }
}

#[test]
fn render_of_a_scene_that_asks_for_nothing_says_so() {
    let dir = scratch("nothing");
    let empty = dir.join("empty.toml");
    std::fs::write(&empty, "[task]\ntitle = \"Ничего\"\n").unwrap();
    let no_plates = edited_scene(&dir, "no-plates.toml", |t| {
        t.replace(
            "wanted = [\"positions\", \"kinematics\", \"forces\", \"cam\", \"gears\", \"dynamics\", \"flywheel\"]",
            "wanted = []",
        )
    });
    for (scene, want) in [
        (&empty, "asks for nothing to construct"),
        (&no_plates, "plates.wanted = []"),
    ] {
        for format in ["svg", "pdf", "png"] {
            let out = dir.join("out");
            let o = tmm(&[
                "render",
                scene.to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
                "--format",
                format,
            ]);
            let err = text(&o.stderr);
            assert_eq!(o.status.code(), Some(2), "{format}: {err}");
            assert!(err.contains(want), "{format}: {err}");
            assert!(!out.exists(), "{format}: {:?}", files_under(&out));
        }
    }
    let o = tmm(&["check", no_plates.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("plates.wanted = []"));
}

/// The longest run of digits in `s`.
fn longest_digits(s: &str) -> usize {
    s.split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0)
}

#[test]
fn huge_and_tiny_values_are_echoed_compactly() {
    for (from, to, want) in [
        (
            "length = 140.0",
            "length = 1e300",
            "mechanism.crank.length = 1e300",
        ),
        (
            "length = 140.0",
            "length = -1e-300",
            "mechanism.crank.length = -1e-300",
        ),
        ("teeth = 100", "teeth = 1e300", "`1e300`"),
        ("teeth = 100", "teeth = nan", "forces.drive.teeth = nan"),
        (
            "pressure_angle = 20.0",
            "pressure_angle = 1e300",
            "pressure_angle = 1e300",
        ),
        ("slide = 90.0", "slide = 1e300", "slide = 1e300"),
    ] {
        let (code, err) = render_shaper_edited("compact", "svg", |t| t.replacen(from, to, 1));
        assert_eq!(code, 2, "{to}: {err}");
        assert!(err.contains(want), "{want}: {err}");
        assert!(longest_digits(&err) < 20, "{to}: {err}");
    }
}

#[test]
fn a_work_that_is_a_rounding_residue_is_printed_as_zero() {
    // A resistance of fixed direction square to the ram's travel does no work over the
    // cycle: the sum of the reduced moments is a residue of ~1e-15 J, of either sign.
    for dir in ["0.0", "90.0", "180.0"] {
        let (code, err) = render_shaper_edited("residue", "svg", |t| {
            t.replace(
                "stroke = \"working\"",
                &format!("stroke = \"always\"\ndir = {dir}"),
            )
        });
        assert_eq!(code, 1, "dir {dir}: {err}");
        assert!(
            err.contains("the working resistances do 0 J of work"),
            "dir {dir}: {err}"
        );
    }
}

/// Scales of 1e40 (an empty plate, exit 0) and 1e-40 (exit 1 with no key) in every section are
/// refused at load (exit 2) naming the key and the range: a scale with a reference in the scene
/// by what it draws of it, the dynamics' and the friction cases' by a fixed range.
#[test]
fn scales_far_out_of_range_are_refused_at_load_in_every_section() {
    let dir = scratch("scales-everywhere");
    let cases: [(&str, &str, &str, &str); 7] = [
        ("shaper", "[cam]\n", "scale_s", "cam.scale_s"),
        ("shaper", "[cam]\n", "scale_phi", "cam.scale_phi"),
        (
            "rotor-dynamic",
            "[balancing]\n",
            "scale_mr",
            "balancing.scale_mr",
        ),
        ("shaper", "[forces]\n", "scale_f", "forces.scale_f"),
        ("shaper", "[dynamics]\n", "scale_j", "dynamics.scale_j"),
        ("shaper", "[dynamics]\n", "scale_phi", "dynamics.scale_phi"),
        (
            "friction",
            "[[friction.case]]\n",
            "scale_f",
            "friction.case[0].scale_f",
        ),
    ];
    for (scene, header, k, key) in cases {
        let source = std::fs::read_to_string(root().join(format!("constructions/{scene}.toml")))
            .expect("scene");
        // Drop the scene's own value of the key in that section, then give the bad one.
        let at = source.find(header).expect("section") + header.len();
        let (head, tail) = source.split_at(at);
        let tail: String = {
            let end = tail.find("\n[").unwrap_or(tail.len());
            let (section, rest) = tail.split_at(end);
            let kept: Vec<&str> = section
                .lines()
                .filter(|l| !l.trim_start().starts_with(&format!("{k} ")))
                .collect();
            format!("{}{rest}", kept.join("\n"))
        };
        for v in ["1e40", "1e-40"] {
            let path = dir.join(format!("{scene}-{k}-{v}.toml"));
            std::fs::write(&path, format!("{head}{k} = {v}\n{tail}")).expect("write");
            let o = tmm(&["check", path.to_str().expect("utf-8 path")]);
            let err = text(&o.stderr);
            assert_eq!(o.status.code(), Some(2), "{key} = {v}: {err}");
            assert!(
                err.contains(&format!("{key} = {v}: expected")),
                "{key} = {v}: {err}"
            );
            assert!(err.contains(" from "), "{key} = {v}: no range in {err}");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
