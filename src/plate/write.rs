//! Atomic file writing: a failed run never leaves a half-written plate.

use std::fs;
use std::io::{self, Write as _};
use std::path::Path;

/// Write `bytes` to `path` through a temporary file `.<name>.tmp-<pid>` in the same
/// directory, then rename it over `path`. Creates missing parent directories; removes the
/// temporary file when anything fails.
///
/// # Errors
/// Any I/O error; `InvalidInput` when `path` has no file name.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let name = path.file_name().ok_or_else(|| {
        io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{} has no file name", path.display()),
        )
    })?;
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    fs::create_dir_all(dir)?;
    let tmp = dir.join(format!(
        ".{}.tmp-{}",
        name.to_string_lossy(),
        std::process::id()
    ));
    let result = write_synced(&tmp, bytes).and_then(|()| fs::rename(&tmp, path));
    if result.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    result
}

fn write_synced(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let mut file = fs::File::create(path)?;
    file.write_all(bytes)?;
    file.sync_all()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn write_atomic_creates_dirs_and_leaves_no_temporary() {
        let dir = std::env::temp_dir().join(format!("tmm-write-atomic-{}", std::process::id()));
        let path = dir.join("a/b/plate.svg");
        write_atomic(&path, b"one").unwrap();
        write_atomic(&path, b"two").unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"two");
        let names: Vec<_> = fs::read_dir(dir.join("a/b"))
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names, vec![std::ffi::OsString::from("plate.svg")]);
        fs::remove_dir_all(&dir).unwrap();
    }
}
