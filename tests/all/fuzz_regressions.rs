//! The fuzz targets' bodies (`fuzz/src/<target>.rs`) run as normal tests, without libFuzzer:
//! over the shipped inputs each target's corpus starts from (the CI smoke of the fuzzer) and
//! over every minimised finding of the fuzz runs, `fuzz/regressions/<target>/` (see
//! `fuzz/README.md`). A panic fails the test and names the file.

#[path = "../../fuzz/src/audit.rs"]
mod audit_body;
#[path = "../../fuzz/src/grid.rs"]
mod grid_body;
#[path = "../../fuzz/src/note.rs"]
mod note_body;
#[path = "../../fuzz/src/scene.rs"]
mod scene_body;

use std::path::{Path, PathBuf};

/// The files of `dir` (under the repository) whose name ends in `ext` (every file with
/// `""`), sorted.
fn files(dir: &str, ext: &str) -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
    let mut v: Vec<PathBuf> = std::fs::read_dir(&root)
        .unwrap_or_else(|e| panic!("{}: {e}", root.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_file() && p.to_string_lossy().ends_with(ext))
        .collect();
    v.sort();
    v
}

/// Run a target's body on every file, naming the file that panics.
fn run_all(files: &[PathBuf], body: fn(&[u8])) {
    for f in files {
        let data = std::fs::read(f).unwrap();
        let r = std::panic::catch_unwind(|| body(&data));
        assert!(r.is_ok(), "{}: the fuzz target panicked", f.display());
    }
}

#[test]
fn committed_scenes_run_through_the_fuzz_target() {
    let files = files("constructions", ".toml");
    assert!(files.len() >= 18, "{} files", files.len());
    run_all(&files, scene_body::run);
}

#[test]
fn shipped_grids_run_through_the_grid_target() {
    let files = files("constructions/variants", ".csv");
    assert!(files.len() >= 2, "{} files", files.len());
    run_all(&files, grid_body::run);
    // Each shipped grid is accepted by its template: the target reaches past the reader.
    for f in &files {
        let grid = std::fs::read_to_string(f).unwrap();
        let accepted = ["four-bar", "shaper"].iter().any(|t| {
            let template = Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("constructions")
                .join(format!("{t}.toml"));
            let template = std::fs::read_to_string(template).unwrap();
            tmm::batch::read_grid(&template, &grid, f).is_ok()
        });
        assert!(accepted, "{}: refused by both templates", f.display());
    }
}

#[test]
fn shipped_tables_run_through_the_audit_target() {
    let files = files("constructions/tables", ".csv");
    assert!(!files.is_empty());
    run_all(&files, audit_body::run);
}

/// Every `[task]` string of the shipped scenes through the note's markup, parsed and
/// typeset alone; the shaper's, once, as the strings of a whole note.
#[test]
fn shipped_task_strings_run_through_the_note_target() {
    let mut strings = Vec::new();
    for f in files("constructions", ".toml") {
        let t = tmm::load(&f).unwrap().title;
        for s in [t.title, t.designation, t.author, t.checked, t.organisation] {
            if !s.is_empty() && !strings.contains(&s) {
                strings.push(s);
            }
        }
    }
    assert!(strings.len() >= 10, "{strings:?}");
    for s in &strings {
        note_body::check(s.as_bytes(), true, false);
        note_body::run(s.as_bytes());
    }
    note_body::check(
        "Поперечно-строгальный станок\nТММ.КП.000\n\"Студент\" \\".as_bytes(),
        true,
        true,
    );
}

/// The inputs the fuzz runs stopped on (`fuzz/regressions/<target>/`, see `fuzz/README.md`):
/// each must run through its target without a panic (a note's string typeset alone and in
/// a whole note).
#[test]
fn fuzz_findings_run_through_the_fuzz_targets() {
    let scenes = files("fuzz/regressions/scene", ".toml");
    assert!(!scenes.is_empty());
    run_all(&scenes, scene_body::run);
    // A target without a finding has no folder (git keeps no empty one).
    let found = |target: &str| {
        let dir = format!("fuzz/regressions/{target}");
        let there = Path::new(env!("CARGO_MANIFEST_DIR")).join(&dir).is_dir();
        if there {
            files(&dir, "")
        } else {
            Vec::new()
        }
    };
    run_all(&found("grid"), grid_body::run);
    run_all(&found("audit"), audit_body::run);
    run_all(&found("note"), |data| {
        note_body::check(data, true, true);
    });
}
