//! Atomic file writing: a failed run never leaves a half-written plate.

use std::fs;
use std::io::{self, Write as _};
use std::path::{Path, PathBuf};

/// Write `bytes` to `path` through a temporary file `.<name>.tmp-<pid>` in the same
/// directory, then rename it over `path`. Creates missing parent directories; removes the
/// temporary file when anything fails.
///
/// # Errors
/// Any I/O error; `InvalidInput` when `path` has no file name.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    write_all_atomic(&[(path.to_path_buf(), bytes)]).map_err(|(_, e)| e)
}

/// Write every file or none. First every destination is checked (it has a file name, is
/// named once, is not a directory, and its nearest existing ancestor is a directory); then
/// the missing directories are created and every file is written to its temporary
/// `.<name>.tmp-<pid>`; only when all are written are they renamed over their destinations.
/// A failure before the renames removes the temporaries and the directories created, so
/// the file system is as it was.
///
/// # Errors
/// The first destination that cannot be written, with its I/O error.
pub fn write_all_atomic<B: AsRef<[u8]>>(
    files: &[(PathBuf, B)],
) -> Result<(), (PathBuf, io::Error)> {
    let mut seen = std::collections::BTreeSet::new();
    for (path, _) in files {
        check_destination(path).map_err(|e| (path.clone(), e))?;
        if !seen.insert(path) {
            return Err((path.clone(), invalid("is written twice in one run")));
        }
    }
    let mut staged = Staged::default();
    for (path, bytes) in files {
        if let Err(e) = staged.stage(path, bytes.as_ref()) {
            staged.undo();
            return Err((path.clone(), e));
        }
    }
    staged.commit()
}

fn invalid(what: &str) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidInput, what.to_string())
}

/// The folder `path` is written in (`.` for a bare name).
fn folder(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// Whether `path` can be written without touching anything else.
fn check_destination(path: &Path) -> io::Result<()> {
    if path.file_name().is_none() {
        return Err(invalid("has no file name"));
    }
    if path.is_dir() {
        return Err(invalid("is a directory"));
    }
    let mut dir = folder(path);
    loop {
        match fs::metadata(dir) {
            Ok(m) if m.is_dir() => return Ok(()),
            Ok(_) => {
                return Err(invalid(&format!(
                    "{} is a file, not a directory",
                    dir.display()
                )))
            }
            Err(e)
                if matches!(
                    e.kind(),
                    io::ErrorKind::NotFound | io::ErrorKind::NotADirectory
                ) =>
            {
                match dir.parent() {
                    Some(p) if !p.as_os_str().is_empty() => dir = p,
                    _ => return Ok(()),
                }
            }
            Err(e) => return Err(e),
        }
    }
}

/// Temporary files written and directories created, not yet committed.
#[derive(Default)]
struct Staged {
    /// (temporary, destination), in order.
    files: Vec<(PathBuf, PathBuf)>,
    /// Directories created, outermost first.
    dirs: Vec<PathBuf>,
}

impl Staged {
    fn stage(&mut self, path: &Path, bytes: &[u8]) -> io::Result<()> {
        let name = path
            .file_name()
            .ok_or_else(|| invalid("has no file name"))?;
        let dir = folder(path);
        let mut missing: Vec<&Path> = dir
            .ancestors()
            .take_while(|d| !d.as_os_str().is_empty() && !d.exists())
            .collect();
        missing.reverse();
        for d in missing {
            fs::create_dir(d).or_else(|e| if d.is_dir() { Ok(()) } else { Err(e) })?;
            self.dirs.push(d.to_path_buf());
        }
        let tmp = dir.join(format!(
            ".{}.tmp-{}",
            name.to_string_lossy(),
            std::process::id()
        ));
        // Registered first: a half-written temporary is removed too.
        self.files.push((tmp.clone(), path.to_path_buf()));
        write_synced(&tmp, bytes)
    }

    /// Remove every temporary and every directory created (those left empty).
    fn undo(&mut self) {
        for (tmp, _) in self.files.drain(..) {
            let _ = fs::remove_file(tmp);
        }
        for d in self.dirs.drain(..).rev() {
            let _ = fs::remove_dir(d);
        }
    }

    /// Rename every temporary over its destination.
    fn commit(mut self) -> Result<(), (PathBuf, io::Error)> {
        let files = std::mem::take(&mut self.files);
        for (k, (tmp, path)) in files.iter().enumerate() {
            if let Err(e) = fs::rename(tmp, path) {
                // The files renamed so far stay (they are whole); the rest are dropped.
                self.files = files[k..].to_vec();
                self.undo();
                return Err((path.clone(), e));
            }
        }
        Ok(())
    }
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

    #[test]
    fn a_bad_destination_writes_nothing() {
        let dir = std::env::temp_dir().join(format!("tmm-write-all-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(dir.join("taken.png")).unwrap();
        fs::write(dir.join("file"), b"x").unwrap();
        let ok = (dir.join("new/a.svg"), b"a".to_vec());
        for bad in [
            dir.join("taken.png"),
            dir.join("file/b.svg"),
            dir.join("new/a.svg"),
        ] {
            let (at, e) =
                write_all_atomic(&[ok.clone(), (bad.clone(), b"b".to_vec())]).expect_err("refused");
            assert_eq!(at, bad, "{e}");
            assert!(!dir.join("new").exists(), "{e}");
        }
        // A write that fails after the checks (a read-only folder would do; a name too long
        // for the file system is portable) removes what was staged.
        let long = dir.join("new").join("x".repeat(300));
        let (at, _) = write_all_atomic(&[ok.clone(), (long.clone(), b"b".to_vec())]).unwrap_err();
        assert_eq!(at, long);
        assert!(!dir.join("new").exists());
        write_all_atomic(std::slice::from_ref(&ok)).unwrap();
        assert_eq!(fs::read(&ok.0).unwrap(), b"a");
        fs::remove_dir_all(&dir).unwrap();
    }
}
