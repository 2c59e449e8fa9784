//! Issue 43's reproducers: inputs a hostile user tried, each answered with a result or a clear
//! refusal (exit 2 or 1 naming the key or the position) — never an abort, a panic, memory
//! without bound or a half-written output.

use crate::support::{report_json, rows_of, run_limited, scratch};
use std::path::{Path, PathBuf};

/// The shaper's scene with the ram's mass (`[[forces.link]] link = 5`) set to `mass`, kg,
/// written into `dir`; its path.
fn shaper_with_ram(dir: &Path, mass: &str) -> PathBuf {
    let text = std::fs::read_to_string("constructions/shaper.toml").expect("shaper.toml");
    let ram = "link = 5\nmass = 22.0\n";
    assert!(text.contains(ram), "the template's ram");
    let path = dir.join("shaper.toml");
    std::fs::write(
        &path,
        text.replace(ram, &format!("link = 5\nmass = {mass}\n")),
    )
    .unwrap();
    path
}

#[test]
fn a_massless_ram_has_no_arm_and_its_sheets_are_drawn() {
    for mass in ["0.0", "1e-12"] {
        let dir = scratch("ram-mass");
        let scene = shaper_with_ram(&dir, mass);
        let out = dir.join("out");
        let (code, err) = run_limited("render", &[&scene], &out, &["--format", "svg"]);
        assert_eq!(code, Some(0), "mass {mass}: {err}");
        assert!(out.join("shaper/forces.svg").is_file(), "mass {mass}");
        // The guide's reaction on the ram is rounding noise of the loads (thousands of N):
        // zero, with no arm, on both routes.
        let report = report_json(scene.to_str().unwrap(), None);
        let reactions = rows_of(&report, "R_0_5");
        assert!(!reactions.is_empty(), "mass {mass}");
        for r in reactions {
            let exact = r["analytic"].as_f64().unwrap();
            assert!(exact.abs() < 1e-9, "mass {mass}: {r}");
        }
        assert!(rows_of(&report, "h_0_5").is_empty(), "mass {mass}");
    }
}

#[test]
fn a_ram_of_a_milligram_is_drawn_or_refused_naming_the_scale() {
    let dir = scratch("ram-mg");
    let scene = shaper_with_ram(&dir, "1e-6");
    // Read exactly, its arm is real (≈ 6·10⁶ m: the resistance's moment over a weight of
    // 10 μN) and no sheet holds it: refused naming the scale, nothing of the scene written.
    let exact = dir.join("exact");
    let (code, err) = run_limited("render", &[&scene], &exact, &["--drafting", "0"]);
    assert_eq!(code, Some(2), "{err}");
    // No scale the scene accepts holds it: no suggestion the scene would refuse (the
    // largest that fits, 10 000 m/mm, draws the crank 1e-5 mm long).
    assert!(
        err.contains("no mechanism.scale_l the scene accepts fits it"),
        "{err}"
    );
    assert!(!err.contains("10000"), "{err}");
    assert!(!exact.join("shaper").exists());
    // Read as by hand (the default), the 10 μN reaction is 0 mm on its polygon: no arm,
    // the sheet drawn.
    let hand = dir.join("hand");
    let (code, err) = run_limited("render", &[&scene], &hand, &[]);
    assert_eq!(code, Some(0), "{err}");
    assert!(hand.join("shaper/forces.svg").is_file());
}

#[test]
fn a_grid_row_with_a_massless_ram_is_drawn_with_the_others() {
    let dir = scratch("ram-grid");
    let grid = std::fs::read_to_string("constructions/variants/shaper.csv").unwrap();
    let mut lines: Vec<String> = grid.lines().take(4).map(str::to_string).collect();
    // The ram's mass is the grid's ninth column (forces.link[3].mass).
    let mut fields: Vec<&str> = lines[2].split(',').collect();
    assert_eq!(lines[0].split(',').nth(8), Some("forces.link[3].mass"));
    fields[8] = "0";
    lines[2] = fields.join(",");
    let path = dir.join("grid.csv");
    std::fs::write(&path, lines.join("\n") + "\n").unwrap();
    let out = dir.join("out");
    let template = Path::new("constructions/shaper.toml");
    let (code, err) = run_limited("batch", &[template, &path], &out, &["--format", "svg"]);
    assert_eq!(code, Some(0), "{err}");
    for v in ["01", "02", "03"] {
        assert!(out.join(v).join("task.pdf").is_file(), "{v}");
    }
    let key = std::fs::read_to_string(out.join("answer-key.csv")).unwrap();
    assert_eq!(
        key.lines().filter(|l| l.ends_with(",ok")).count(),
        3,
        "{key}"
    );
}

#[test]
#[cfg(unix)]
fn a_link_planted_at_a_temporarys_name_is_never_followed() {
    let dir = scratch("planted-link");
    let victim = dir.join("victim.txt");
    std::fs::write(&victim, b"not yours").unwrap();
    let dest = dir.join("out").join("plate.svg");
    std::fs::create_dir_all(dest.parent().unwrap()).unwrap();
    // The name this process's temporary for plate.svg takes first, and the backup's.
    let pid = std::process::id();
    let planted = [
        dest.with_file_name(format!(".plate.svg.tmp-{pid}")),
        dest.with_file_name(format!(".plate.svg.bak-{pid}")),
    ];
    std::os::unix::fs::symlink(&victim, &planted[0]).unwrap();
    tmm::plate::write_atomic(&dest, b"first").expect("written beside the link");
    std::os::unix::fs::symlink(&victim, &planted[1]).unwrap();
    tmm::plate::write_atomic(&dest, b"second").expect("replaced beside the links");
    assert_eq!(std::fs::read(&victim).unwrap(), b"not yours");
    let meta = std::fs::symlink_metadata(&dest).unwrap();
    assert!(
        meta.file_type().is_file(),
        "the destination is a file, not the link"
    );
    assert_eq!(std::fs::read(&dest).unwrap(), b"second");
    // The planted temporary's link is not ours to remove; no temporary of ours stays.
    assert!(std::fs::symlink_metadata(&planted[0])
        .unwrap()
        .file_type()
        .is_symlink());
    let left: Vec<String> = std::fs::read_dir(dest.parent().unwrap())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".tmp-") && !planted.iter().any(|p| p.ends_with(n)))
        .collect();
    assert!(left.is_empty(), "{left:?}");
}

/// The four-bar's scene with the title `title`, written into a scratch folder; its path.
fn four_bar_titled(title: &str) -> PathBuf {
    let text = std::fs::read_to_string("constructions/four-bar.toml").expect("four-bar.toml");
    let old = "title = \"Шарнирный четырёхзвенник\"";
    assert!(text.contains(old), "the template's title");
    let path = scratch("titled").join("titled.toml");
    std::fs::write(&path, text.replace(old, &format!("title = \"{title}\""))).unwrap();
    path
}

#[test]
fn a_title_too_long_or_too_marked_for_a_note_is_refused_naming_its_key() {
    for (title, says) in [
        (
            "Я".repeat(32_768),
            "32768 characters: expected at most 1000",
        ),
        (format!("a{}", "\u{301}".repeat(5000)), "5001 characters"),
        (format!("a{}", "\u{301}".repeat(900)), "900 combining marks"),
    ] {
        let scene = four_bar_titled(&title);
        let out = scene.with_file_name("out");
        let (code, err) = run_limited("note", &[&scene], &out, &[]);
        assert_eq!(code, Some(2), "{err}");
        assert!(err.contains("task.title") && err.contains(says), "{err}");
        assert!(!out.exists());
    }
    // As long and as marked as allowed: the note is typeset.
    for title in [
        "Я".repeat(1000),
        format!("a{}", "\u{301}".repeat(30)).repeat(32),
    ] {
        let scene = four_bar_titled(&title);
        let out = scene.with_file_name("out");
        let (code, err) = run_limited("note", &[&scene], &out, &[]);
        assert_eq!(code, Some(0), "{err}");
        assert!(out.join("titled/titled-note.pdf").is_file());
    }
}

#[test]
fn a_pin_a_hair_off_the_rockers_pivot_is_drawn_or_refused_naming_the_scale() {
    // The crank (A–B, 140 mm) made 430 mm − 1 pm long: its pin passes 1e-9 mm from the
    // rocker's pivot C, the rocker turns through 180° there and the ram runs ±710 mm.
    let text = std::fs::read_to_string("constructions/shaper.toml").expect("shaper.toml");
    let (crank, scale) = ("length = 140.0\n", "scale_l = 0.0025 ");
    assert!(text.contains(crank) && text.contains(scale), "the template");
    let dir = scratch("pin-off-pivot");
    let scene = dir.join("shaper.toml");
    let write = |s: &str| {
        let t = text
            .replacen(crank, "length = 429.999999999\n", 1)
            .replacen(scale, &format!("scale_l = {s} "), 1);
        std::fs::write(&scene, t).unwrap();
    };
    // At the shipped scale the ram's run does not fit a sheet: refused naming the scale
    // with one it accepts, nothing written.
    write("0.0025");
    let out = dir.join("at-0.0025");
    let (code, err) = run_limited("render", &[&scene], &out, &["--format", "svg"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("mechanism.scale_l") && err.contains("mechanism.scale_l = 0.005"),
        "{err}"
    );
    assert!(!out.join("shaper").exists());
    // At the scale suggested every sheet is drawn.
    write("0.005");
    let out = dir.join("at-0.005");
    let (code, err) = run_limited("render", &[&scene], &out, &["--format", "svg"]);
    assert_eq!(code, Some(0), "{err}");
    for sheet in ["kinematics", "forces", "dynamics", "cam"] {
        assert!(out.join(format!("shaper/{sheet}.svg")).is_file(), "{sheet}");
    }
}
