//! One concept per file (issue 46, DESIGN): no source file of the crate, its examples or its
//! tests runs over [`MAX_LINES`] lines, counted as `wc -l` counts them. The test files
//! written before the limit was held here are listed with their length today: each may
//! shrink, none may grow, and a file leaves the list once it is split.

use crate::support::root;
use std::path::{Path, PathBuf};

/// The most lines a file holds.
const MAX_LINES: usize = 600;

/// Test files over the limit, with their length when it was first held (split them along
/// their seams; each is a room of tests for one study).
const OVER: &[(&str, usize)] = &[
    ("tests/all/gears.rs", 953),
    ("tests/all/forces.rs", 930),
    ("tests/all/kinematics.rs", 664),
    ("tests/all/hard_cases.rs", 616),
];

/// Every `.rs` file under `dir`.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

#[test]
fn no_file_runs_over_six_hundred_lines() {
    let root = root();
    let mut files = Vec::new();
    for dir in ["src", "examples", "tests"] {
        rust_files(&root.join(dir), &mut files);
    }
    assert!(files.len() > 500, "{} files", files.len());
    let mut over = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        let lines = text.lines().count();
        let name = f
            .strip_prefix(&root)
            .unwrap_or(f)
            .to_string_lossy()
            .into_owned();
        let allowed = OVER
            .iter()
            .find(|(n, _)| *n == name)
            .map_or(MAX_LINES, |&(_, l)| l);
        if lines > allowed {
            over.push(format!("{name}: {lines} lines (at most {allowed})"));
        }
    }
    assert!(over.is_empty(), "{}", over.join("\n"));
    // Every listed file is still over the limit (a file split leaves the list).
    for (name, _) in OVER {
        let text = std::fs::read_to_string(root.join(name)).unwrap_or_default();
        assert!(
            text.lines().count() > MAX_LINES,
            "{name} is within the limit now: take it off OVER"
        );
    }
}
