//! Running the `tmm` binary from the integration tests.

use std::path::PathBuf;
use std::process::{Command, Output};

/// The repository root (the scenes' paths are relative to it).
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Run `tmm` with `args` in the repository root.
pub fn tmm(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tmm"))
        .args(args)
        .current_dir(root())
        .output()
        .expect("run tmm")
}

/// A fresh scratch folder for one test.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("tmm-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}
