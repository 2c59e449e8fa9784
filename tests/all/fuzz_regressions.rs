//! The fuzz target's body (`fuzz/src/lib.rs`: scene text → load → every study → every plate
//! in memory) run as a normal test: over the committed scenes (the CI smoke of the
//! fuzzer, no libFuzzer needed). A panic fails the test. Minimised findings of the fuzz runs
//! are kept here too (see `fuzz/README.md`).

#[path = "../../fuzz/src/lib.rs"]
mod fuzz_body;

use std::path::{Path, PathBuf};

/// The `.toml` files of `dir`, sorted.
fn scenes(dir: &str) -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
    let mut v: Vec<PathBuf> = std::fs::read_dir(&root)
        .unwrap_or_else(|e| panic!("{}: {e}", root.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    v.sort();
    v
}

/// Run the target's body on every file, naming the file that panics.
fn run_all(files: &[PathBuf]) {
    for f in files {
        let data = std::fs::read(f).unwrap();
        let r = std::panic::catch_unwind(|| fuzz_body::run(&data));
        assert!(r.is_ok(), "{}: the fuzz target panicked", f.display());
    }
}

#[test]
fn committed_scenes_run_through_the_fuzz_target() {
    let files = scenes("constructions");
    assert!(files.len() >= 18, "{} files", files.len());
    run_all(&files);
}

/// The inputs the fuzz runs stopped on (`fuzz/regressions/`, see `fuzz/README.md`): each must
/// run through the target without a panic.
#[test]
fn fuzz_findings_run_through_the_fuzz_target() {
    let files = scenes("fuzz/regressions");
    assert!(!files.is_empty());
    run_all(&files);
}
