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
/// named once, is not a directory, and its nearest existing ancestor is a directory) and the
/// stale temporaries of earlier runs in the destinations' folders are removed
/// (`remove_stale`); then the missing directories are created and every file is written to
/// its temporary `.<name>.tmp-<pid>`; only when all are written are they renamed over their
/// destinations, each file replaced kept as `.<name>.bak-<pid>` (a second link) until every
/// rename has succeeded. A failure at any step undoes the steps before it — the renames
/// done are rolled back (the files replaced restored, the new ones removed), the temporaries
/// and the directories created removed — so the file system is as it was.
///
/// # Errors
/// The first destination that cannot be written, with its I/O error.
pub fn write_all_atomic<B: AsRef<[u8]>>(
    files: &[(PathBuf, B)],
) -> Result<(), (PathBuf, io::Error)> {
    write_all_atomic_with(files, || {})
}

/// [`write_all_atomic`], calling `between` after staging and before the renames (the tests
/// change the file system there, as another process could).
fn write_all_atomic_with<B: AsRef<[u8]>>(
    files: &[(PathBuf, B)],
    between: impl FnOnce(),
) -> Result<(), (PathBuf, io::Error)> {
    let mut seen = std::collections::BTreeSet::new();
    for (path, _) in files {
        check_destination(path).map_err(|e| (path.clone(), e))?;
        if !seen.insert(path) {
            return Err((path.clone(), invalid("is written twice in one run")));
        }
    }
    let folders: std::collections::BTreeSet<&Path> =
        files.iter().map(|(path, _)| folder(path)).collect();
    for dir in folders {
        remove_stale(dir, std::time::SystemTime::now());
    }
    let mut staged = Staged::default();
    for (path, bytes) in files {
        if let Err(e) = staged.stage(path, bytes.as_ref()) {
            staged.undo();
            return Err((path.clone(), e));
        }
    }
    between();
    staged.commit()
}

/// The suffixes of the files `tmm` writes; a temporary or backup of another name is not ours.
const OUR_EXTENSIONS: [&str; 6] = ["svg", "png", "pdf", "dxf", "md", "json"];

/// After this long a temporary is stale whatever its process (a pid reused by another).
const STALE_AFTER: std::time::Duration = std::time::Duration::from_secs(24 * 3600);

/// The process id of a name of our pattern, `.<name>.<ext>.tmp-<pid>` (or
/// `….tmp-<pid>-<k>`, [`create_temporary`]) or `….bak-<pid>` with `<ext>` one of
/// [`OUR_EXTENSIONS`]; `None` for any other name.
fn our_temporary(name: &str) -> Option<u32> {
    let rest = name.strip_prefix('.')?;
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    let (stem, pid) = match rest.rsplit_once(".tmp-") {
        Some((stem, tail)) => match tail.split_once('-') {
            Some((pid, k)) if digits(k) => (stem, pid),
            _ => (stem, tail),
        },
        None => rest.rsplit_once(".bak-")?,
    };
    if !digits(pid) {
        return None;
    }
    let (base, ext) = stem.rsplit_once('.')?;
    if base.is_empty() || !OUR_EXTENSIONS.contains(&ext) {
        return None;
    }
    pid.parse().ok()
}

/// Whether process `pid` is running (read from `/proc`; `None` where there is none).
fn alive(pid: u32) -> Option<bool> {
    if !Path::new("/proc/self").exists() {
        return None;
    }
    Some(Path::new("/proc").join(pid.to_string()).exists())
}

/// Remove the temporaries and backups an earlier run left in `dir` (killed between staging
/// and renaming): only regular files of our own pattern ([`our_temporary`]), only of another
/// process that is no longer running, or older than a day. A destination is never among
/// them (a backup is a second link of a file still in place). Errors are ignored: what
/// cannot be removed stays.
pub(crate) fn remove_stale(dir: &Path, now: std::time::SystemTime) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(pid) = name.to_str().and_then(our_temporary) else {
            continue;
        };
        let Ok(meta) = entry.path().symlink_metadata() else {
            continue;
        };
        if !meta.is_file() || pid == std::process::id() {
            continue;
        }
        let old = meta
            .modified()
            .ok()
            .and_then(|t| now.duration_since(t).ok())
            .is_some_and(|age| age > STALE_AFTER);
        if old || alive(pid) == Some(false) {
            let _ = fs::remove_file(entry.path());
        }
    }
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
        let (tmp, file) = create_temporary(dir, &name.to_string_lossy())?;
        // Registered before writing: a half-written temporary is removed too.
        self.files.push((tmp, path.to_path_buf()));
        write_synced(file, bytes)
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

    /// Rename every temporary over its destination; on a failure roll back the renames
    /// done (restore each file replaced from its backup, remove each new one) and undo.
    fn commit(mut self) -> Result<(), (PathBuf, io::Error)> {
        let files = std::mem::take(&mut self.files);
        // (destination, backup of the file it replaced)
        let mut done: Vec<(&Path, Option<PathBuf>)> = Vec::new();
        for (k, (tmp, path)) in files.iter().enumerate() {
            match replace(tmp, path) {
                Ok(backup) => done.push((path, backup)),
                Err(e) => {
                    for (path, backup) in done.into_iter().rev() {
                        let _ = match backup {
                            Some(b) => fs::rename(b, path),
                            None => fs::remove_file(path),
                        };
                    }
                    self.files = files[k..].to_vec();
                    self.undo();
                    return Err((path.clone(), e));
                }
            }
        }
        for (_, backup) in done {
            if let Some(b) = backup {
                let _ = fs::remove_file(b);
            }
        }
        Ok(())
    }
}

/// Rename `tmp` over `path`, keeping what `path` was (a file or a link, not a directory) as
/// a second link `.<name>.bak-<pid>` beside it: the destination is never missing, and the
/// backup restores it with one rename.
fn replace(tmp: &Path, path: &Path) -> io::Result<Option<PathBuf>> {
    let backup = match fs::symlink_metadata(path) {
        Ok(m) if !m.is_dir() => {
            let name = path
                .file_name()
                .ok_or_else(|| invalid("has no file name"))?;
            let b = folder(path).join(format!(
                ".{}.bak-{}",
                name.to_string_lossy(),
                std::process::id()
            ));
            let _ = fs::remove_file(&b);
            fs::hard_link(path, &b).or_else(|_| copy_exclusive(path, &b))?;
            Some(b)
        }
        _ => None,
    };
    if let Err(e) = fs::rename(tmp, path) {
        if let Some(b) = &backup {
            let _ = fs::remove_file(b);
        }
        return Err(e);
    }
    Ok(backup)
}

/// Copy the file at `from` to a new file `to` ([`create_exclusive`]).
fn copy_exclusive(from: &Path, to: &Path) -> io::Result<()> {
    let mut source = fs::File::open(from)?;
    io::copy(&mut source, &mut create_exclusive(to)?).map(|_| ())
}

fn write_synced(mut file: fs::File, bytes: &[u8]) -> io::Result<()> {
    file.write_all(bytes)?;
    file.sync_all()
}

/// Names tried for a temporary before giving up.
const TEMPORARY_TRIES: u32 = 100;

/// A new temporary for the file `name` in `dir`, created exclusively
/// ([`create_exclusive`]): `.<name>.tmp-<pid>`, or `.<name>.tmp-<pid>-<k>` when that name is
/// taken (by a link planted there, or a file of another writer). Its path and the file.
///
/// # Errors
/// Any I/O error but a name taken; `AlreadyExists` when every name tried is.
fn create_temporary(dir: &Path, name: &str) -> io::Result<(PathBuf, fs::File)> {
    let pid = std::process::id();
    for k in 0..TEMPORARY_TRIES {
        let tmp = dir.join(match k {
            0 => format!(".{name}.tmp-{pid}"),
            _ => format!(".{name}.tmp-{pid}-{k}"),
        });
        match create_exclusive(&tmp) {
            Ok(file) => return Ok((tmp, file)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
    Err(io::Error::new(
        io::ErrorKind::AlreadyExists,
        format!(
            "{TEMPORARY_TRIES} names of temporaries in {} are taken",
            dir.display()
        ),
    ))
}

/// A file created at `path` for writing, which must not exist: never a file or a link that
/// is there already (O_CREAT | O_EXCL), and, on unix, never through a link (O_NOFOLLOW).
///
/// # Errors
/// `AlreadyExists` when anything is at `path`; any other I/O error.
pub(crate) fn create_exclusive(path: &Path) -> io::Result<fs::File> {
    let mut options = fs::OpenOptions::new();
    options.write(true).create_new(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt as _;
        options.custom_flags(libc::O_NOFOLLOW);
    }
    options.open(path)
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

    #[test]
    fn a_failed_rename_rolls_back_the_renames_done() {
        let dir = std::env::temp_dir().join(format!("tmm-write-rollback-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        let old = dir.join("a.svg");
        fs::write(&old, b"old a").unwrap();
        let files = [
            (old.clone(), b"new a".to_vec()),
            (dir.join("b.svg"), b"new b".to_vec()),
            (dir.join("c.pdf"), b"new c".to_vec()),
            (dir.join("sub/d.png"), b"new d".to_vec()),
        ];
        // A directory appears at c.pdf after the checks, before the renames.
        let (at, _) = write_all_atomic_with(&files, || fs::create_dir(dir.join("c.pdf")).unwrap())
            .expect_err("c.pdf is a directory");
        assert_eq!(at, dir.join("c.pdf"));
        assert_eq!(
            fs::read(&old).unwrap(),
            b"old a",
            "the file replaced is restored"
        );
        let mut names: Vec<_> = fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        assert_eq!(
            names,
            ["a.svg", "c.pdf"],
            "nothing new, no temporary, no backup"
        );
        // Without the obstacle every file is written and no backup stays.
        fs::remove_dir(dir.join("c.pdf")).unwrap();
        write_all_atomic(&files).unwrap();
        assert_eq!(fs::read(&old).unwrap(), b"new a");
        let mut names: Vec<_> = fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        assert_eq!(names, ["a.svg", "b.svg", "c.pdf", "sub"]);
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn stale_temporaries_of_dead_processes_are_removed_and_nothing_else() {
        let dir = std::env::temp_dir().join(format!("tmm-write-stale-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        // A process that has ended: its pid is free (until reused).
        let mut child = std::process::Command::new("true").spawn().unwrap();
        let dead = child.id();
        child.wait().unwrap();
        let live = std::os::unix::process::parent_id();
        let stale = [
            format!(".positions.svg.tmp-{dead}"),
            format!(".shaper.pdf.tmp-{dead}"),
            format!(".bench.json.bak-{dead}"),
            format!(".positions.svg.tmp-{dead}-2"),
        ];
        let kept = [
            format!(".positions.svg.tmp-{live}"),
            format!(".positions.svg.tmp-{}", std::process::id()),
            format!(".notes.txt.tmp-{dead}"),
            format!(".positions.svg.tmp-{dead}x"),
            format!(".positions.svg.tmp-{dead}-"),
            format!(".positions.svg.tmp-{dead}-2x"),
            format!("positions.svg.tmp-{dead}"),
            format!(".svg.tmp-{dead}"),
            "positions.svg".to_string(),
        ];
        for n in stale.iter().chain(&kept) {
            fs::write(dir.join(n), b"x").unwrap();
        }
        fs::create_dir(dir.join(format!(".forces.png.tmp-{dead}"))).unwrap();
        remove_stale(&dir, std::time::SystemTime::now());
        for n in &stale {
            assert!(!dir.join(n).exists(), "{n} is stale");
        }
        for n in &kept {
            assert!(dir.join(n).exists(), "{n} is not ours to remove");
        }
        assert!(dir.join(format!(".forces.png.tmp-{dead}")).is_dir());
        // A day later even a live process's temporary is stale; the destination is not.
        let later = std::time::SystemTime::now() + STALE_AFTER * 2;
        remove_stale(&dir, later);
        assert!(!dir.join(&kept[0]).exists());
        assert!(dir.join("positions.svg").exists());
        fs::remove_dir_all(&dir).unwrap();
    }
}
