//! What a student waits for, from a fresh process: `tmm note` and the whole project
//! (`tmm render --format svg,png,pdf,note`) run as commands, medians of their wall and CPU
//! times — no cache of an earlier run helps them, as none helps the student.

use super::{BenchError, Subject};
use std::path::Path;
use std::process::Command;
use std::time::Instant;

/// A command's medians over its runs.
#[derive(Debug, Clone, Copy)]
pub(super) struct Waited {
    /// Runs timed.
    pub runs: usize,
    /// Median wall time, s.
    pub wall: f64,
    /// Median CPU time (user and system, the process and its threads), s; `None` where
    /// `/proc` does not say.
    pub cpu: Option<f64>,
}

/// The median of `values` (their mean of the middle two when even); 0 for none.
fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    match n {
        0 => 0.0,
        _ if n % 2 == 1 => values[n / 2],
        _ => 0.5 * (values[n / 2 - 1] + values[n / 2]),
    }
}

/// Clock ticks per second of `/proc`'s times: the auxiliary vector's `AT_CLKTCK` (17), read
/// as pairs of native words; 100 (Linux's `USER_HZ`) when it cannot be read.
fn clock_ticks() -> f64 {
    const AT_CLKTCK: u64 = 17;
    let word = std::mem::size_of::<usize>();
    std::fs::read("/proc/self/auxv")
        .ok()
        .and_then(|auxv| {
            auxv.chunks_exact(2 * word).find_map(|pair| {
                let read = |b: &[u8]| {
                    let mut w = [0u8; 8];
                    w[..word].copy_from_slice(b);
                    u64::from_ne_bytes(w)
                };
                (read(&pair[..word]) == AT_CLKTCK).then(|| read(&pair[word..]))
            })
        })
        .filter(|&t| t > 0)
        .map_or(100.0, |t| t as f64)
}

/// The CPU seconds of this process's children waited for so far (`/proc/self/stat`).
fn children_cpu() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    Some(children_ticks(&stat)? / clock_ticks())
}

/// `cutime` + `cstime`, the 16th and 17th fields of a `/proc/PID/stat` line, in clock ticks.
fn children_ticks(stat: &str) -> Option<f64> {
    // The fields after the command's name, which is in parentheses and may hold spaces and
    // parentheses: the 3rd field (the state) first.
    let rest = &stat[stat.rfind(')')? + 1..];
    let fields: Vec<&str> = rest.split_whitespace().collect();
    let ticks = |k: usize| fields.get(k - 3)?.parse::<f64>().ok();
    Some(ticks(16)? + ticks(17)?)
}

/// `exe args` run `runs` times, each into a fresh scratch folder `out` (appended as
/// `--out out`, removed after): the medians of the runs' wall and CPU times.
fn waited(exe: &Path, args: &[&str], out: &Path, runs: usize) -> Result<Waited, String> {
    let (mut walls, mut cpus) = (Vec::new(), Vec::new());
    for _ in 0..runs.max(1) {
        let _ = std::fs::remove_dir_all(out);
        let cpu0 = children_cpu();
        let start = Instant::now();
        let done = Command::new(exe)
            .args(args)
            .arg("--out")
            .arg(out)
            .output()
            .map_err(|e| format!("{}: {e}", exe.display()))?;
        walls.push(start.elapsed().as_secs_f64());
        let _ = std::fs::remove_dir_all(out);
        if !done.status.success() {
            return Err(format!(
                "`tmm {}` failed: {}",
                args.join(" "),
                String::from_utf8_lossy(&done.stderr).trim()
            ));
        }
        if let (Some(a), Some(b)) = (cpu0, children_cpu()) {
            cpus.push(b - a);
        }
    }
    Ok(Waited {
        runs: walls.len(),
        wall: median(walls),
        cpu: (cpus.len() == runs.max(1)).then(|| median(cpus)),
    })
}

/// The note alone and the whole project of `s` from fresh processes of this program, `runs`
/// times each: `(note, project)`. `None` when this process is not `tmm` (a test harness).
pub(super) fn note_and_project(
    s: &Subject,
    scenes: &Path,
    runs: usize,
) -> Result<Option<(Waited, Waited)>, BenchError> {
    let exe = match std::env::current_exe() {
        Ok(exe) if exe.file_stem().is_some_and(|n| n == "tmm") => exe,
        _ => return Ok(None),
    };
    let failed = |detail: String| BenchError::Plate {
        scene: s.scene.stem.clone(),
        plate: "fresh process".into(),
        detail,
    };
    let scene = scenes.join(format!("{}.toml", s.scene.stem));
    let scene = scene.to_string_lossy();
    let out = std::env::temp_dir().join(format!("tmm-bench-fresh-{}", std::process::id()));
    let note = waited(&exe, &["note", &scene], &out, runs).map_err(failed)?;
    let project = waited(
        &exe,
        &["render", &scene, "--format", "svg,png,pdf,note"],
        &out,
        runs,
    )
    .map_err(failed)?;
    Ok(Some((note, project)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_median_is_the_middle_value_or_the_mean_of_the_middle_two() {
        assert_eq!(median(vec![3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(vec![4.0, 1.0, 3.0, 2.0]), 2.5);
        assert_eq!(median(Vec::new()), 0.0);
    }

    #[test]
    fn the_childrens_ticks_are_read_past_a_name_with_parentheses() {
        let stat = "4242 (tmm (x) y) S 1 2 3 4 5 6 7 8 9 10 11 12 34 56 20 0 1";
        assert_eq!(children_ticks(stat), Some(90.0));
        assert_eq!(children_ticks("4242 (tmm) S 1 2"), None);
    }
}
