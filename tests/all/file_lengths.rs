//! One concept per file (issue 46, DESIGN): no source file of the crate, its examples or its
//! tests runs over [`MAX_LINES`] lines, counted as `wc -l` counts them.

use crate::support::root;
use std::path::{Path, PathBuf};

/// The most lines a file holds.
const MAX_LINES: usize = 600;

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
        if lines > MAX_LINES {
            over.push(format!("{name}: {lines} lines"));
        }
    }
    assert!(over.is_empty(), "{}", over.join("\n"));
}
