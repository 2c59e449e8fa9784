//! Issue 43's reproducers for `tmm batch`: a class of hundreds of variants (it overflowed a
//! worker's stack from 300 on), an impossible row in every hundred, and a write that fails
//! (a variant whole or absent, every diagnosis printed even when the answer key cannot be
//! written).

use crate::support::{run_limited, scratch};
use std::path::Path;

/// `tmm batch constructions/four-bar.toml GRID --out OUT --format svg` under the memory
/// limit; neither an abort nor a panic. Its status and standard error.
fn batch(grid: &Path, out: &Path) -> (Option<i32>, String) {
    let template = Path::new("constructions/four-bar.toml");
    run_limited("batch", &[template, grid], out, &["--format", "svg"])
}

/// The files of folder `dir`, sorted (none when it does not exist).
fn names(dir: &Path) -> Vec<String> {
    let mut n: Vec<String> = std::fs::read_dir(dir)
        .map(|d| {
            d.map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    n.sort();
    n
}

#[test]
fn a_class_of_thousands_with_an_impossible_row_in_each_hundred_is_drawn() {
    let dir = scratch("batch-class");
    // A department's year: thousands of variants (300 overflowed a worker's stack before).
    let n = 2000;
    let mut grid = String::from("variant,mechanism.crank.length,mechanism.group[0].la\n");
    for k in 0..n {
        // Every hundredth crank cannot turn (longer than the others allow).
        let crank = if k % 100 == 37 { 200 } else { 60 + k % 20 };
        grid += &format!("v{k:04},{crank},{}\n", 220 + k % 30);
    }
    let path = dir.join("grid.csv");
    std::fs::write(&path, grid).unwrap();
    let out = dir.join("out");
    let (code, err) = batch(&path, &out);
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains(&format!("{} of {n} variants", n / 100)),
        "{err}"
    );
    for k in (0..n).filter(|k| k % 100 == 37) {
        assert!(err.contains(&format!("variant v{k:04}:")), "{err}");
        assert!(!out.join(format!("v{k:04}")).exists());
    }
    let key = std::fs::read_to_string(out.join("answer-key.csv")).unwrap();
    assert_eq!(key.lines().count(), n + 1);
    assert_eq!(
        key.lines().filter(|l| l.ends_with(",ok")).count(),
        n - n / 100
    );
    for k in [0, 99, 250, 1999] {
        let v = out.join(format!("v{k:04}"));
        assert!(
            v.join("task.pdf").is_file() && v.join("kinematics.svg").is_file(),
            "{k}"
        );
    }
    // A class's sheets are many (about 300 MB): not kept after the test.
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn a_variant_that_cannot_be_written_is_absent_and_every_failure_is_reported() {
    let dir = scratch("batch-write");
    let path = dir.join("grid.csv");
    std::fs::write(
        &path,
        "variant,mechanism.crank.length\na,60\nb,65\nc,200\nd,70\n",
    )
    .unwrap();
    let out = dir.join("out");
    // Injected write failures: b's task sheet and the answer key name taken by folders.
    std::fs::create_dir_all(out.join("b").join("task.pdf")).unwrap();
    std::fs::create_dir_all(out.join("answer-key.csv")).unwrap();
    let (code, err) = batch(&path, &out);
    // The key that cannot be written is exit 2, after every variant's diagnosis.
    assert_eq!(code, Some(2), "{err}");
    let at = |what: &str| err.find(what).unwrap_or_else(|| panic!("{what}: {err}"));
    let (b, c, key) = (at("variant b:"), at("variant c:"), at("answer-key.csv"));
    assert!(b < key && c < key, "diagnoses first: {err}");
    assert!(err.contains("task.pdf"), "{err}");
    assert!(err.contains("2 of 4 variants"), "{err}");
    // b is absent: none of its sheets without its task sheet.
    assert_eq!(names(&out.join("b")), ["task.pdf"]);
    assert!(out.join("b/task.pdf").is_dir());
    assert!(!out.join("c").exists());
    for v in ["a", "d"] {
        let files = names(&out.join(v));
        assert!(files.contains(&"task.pdf".to_string()), "{v}: {files:?}");
        assert!(
            files.contains(&"kinematics.svg".to_string()),
            "{v}: {files:?}"
        );
        assert!(!files.iter().any(|f| f.starts_with('.')), "{v}: {files:?}");
    }
    assert!(out.join("answer-key.csv").is_dir() && !out.join("answer-key.pdf").exists());
}

/// `sh -c SCRIPT` in a mount namespace of its own (`unshare -m`), where a small tmpfs can be
/// mounted and is gone with the namespace; `None` when this machine allows no such
/// namespace or mount (then the injected failure above stands for a full disk).
fn in_own_mounts(script: &str, args: &[&str]) -> Option<std::process::Output> {
    let probe = std::process::Command::new("unshare")
        .args(["-m", "sh", "-c", "mount -t tmpfs -o size=64k tmpfs /mnt"])
        .output()
        .ok()?;
    if !probe.status.success() {
        return None;
    }
    std::process::Command::new("unshare")
        .args(["-m", "sh", "-c", script, "sh"])
        .args(args)
        .current_dir(crate::support::root())
        .output()
        .ok()
}

#[test]
fn a_batch_on_a_full_disk_writes_each_variant_whole_or_not_at_all() {
    let dir = scratch("batch-enospc");
    let path = dir.join("grid.csv");
    let variants: Vec<String> = (1..=8).map(|k| format!("v{k}")).collect();
    let mut grid = String::from("variant,mechanism.crank.length\n");
    for (k, n) in variants.iter().enumerate() {
        grid += &format!("{n},{}\n", 60 + k);
    }
    std::fs::write(&path, grid).unwrap();
    // Each variant is about 150 kB (its sheet and its task sheet): a disk of 400 kB holds
    // two or three of the eight.
    let disk = dir.join("disk");
    std::fs::create_dir_all(&disk).unwrap();
    let script = "mount -t tmpfs -o size=400k tmpfs \"$1\" || exit 99
        sh -c 'ulimit -v 1500000 && exec \"$0\" \"$@\"' \"$2\" batch constructions/four-bar.toml \"$3\" --out \"$1/out\" --format svg
        echo \"status $?\"
        cd \"$1/out\" && find . -print";
    let bin = env!("CARGO_BIN_EXE_tmm");
    let (disk_s, path_s) = (disk.to_str().unwrap(), path.to_str().unwrap());
    let Some(o) = in_own_mounts(script, &[disk_s, bin, path_s]) else {
        eprintln!("no mount namespace here: a full disk is tested by the injected failure");
        return;
    };
    let (out, err) = (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    );
    assert!(
        !err.contains("panicked") && !err.contains("overflow"),
        "{err}"
    );
    let status = out.lines().find_map(|l| l.strip_prefix("status "));
    // Some variants are not written: 1, or 2 when the answer key cannot be either.
    assert!(matches!(status, Some("1") | Some("2")), "{out}\n{err}");
    let listed: Vec<&str> = out.lines().filter(|l| l.starts_with("./")).collect();
    assert!(
        !listed
            .iter()
            .any(|l| l.contains(".tmp-") || l.contains(".bak-")),
        "a temporary left: {listed:?}"
    );
    // Each variant as a batch with room writes it, or nothing of it.
    let roomy = dir.join("roomy");
    let (code, err_roomy) = batch(&path, &roomy);
    assert_eq!(code, Some(0), "{err_roomy}");
    let (mut whole, mut absent) = (0, 0);
    for n in &variants {
        let prefix = format!("./{n}/");
        let mut files: Vec<&str> = listed
            .iter()
            .filter_map(|l| l.strip_prefix(prefix.as_str()))
            .collect();
        files.sort_unstable();
        if files.is_empty() {
            // Absent, and its diagnosis names the disk.
            let line = err
                .lines()
                .find(|l| l.contains(&format!("variant {n}:")))
                .unwrap_or_else(|| panic!("{n} not reported: {err}"));
            assert!(
                line.contains("No space left on device")
                    && line.contains("nothing of the variant written"),
                "{line}"
            );
            absent += 1;
        } else {
            assert_eq!(files, names(&roomy.join(n)), "{n} half-written");
            whole += 1;
        }
    }
    eprintln!("full disk: {whole} variants whole, {absent} absent");
    assert!(
        whole >= 1 && absent >= 1,
        "{whole} whole, {absent} absent: {listed:?}\n{err}"
    );
    assert!(err.contains(&format!("{absent} of 8 variants")), "{err}");
}
