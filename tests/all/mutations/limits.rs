//! How the sweep runs `tmm`: within an address space, CPU seconds and wall-clock seconds,
//! its output kept in files (a run that fills a pipe cannot stall the wait).

use std::path::Path;
use std::process::Command;

/// Address space per run, KiB (1 GiB).
pub const MEMORY_KIB: u64 = 1 << 20;
/// CPU seconds per run.
pub const CPU_SECONDS: u64 = 60;
/// Wall-clock seconds per run: a run that neither answers nor spends CPU (a wait, a lock)
/// is a hang.
pub const WALL_SECONDS: u64 = 60;

/// Run `tmm args` within the limits, its output kept in `dir`; (exit code or what ended it,
/// stdout, stderr). A run with no answer within [`WALL_SECONDS`] is killed and counted as a
/// hang: a finding like any other.
pub fn run(args: &[&str], dir: &Path) -> (Result<i32, String>, String, String) {
    let bin = std::env::var("TMM_BIN").unwrap_or_else(|_| env!("CARGO_BIN_EXE_tmm").into());
    run_within(&bin, args, dir, WALL_SECONDS)
}

/// [`run`] of `bin` with a wall-clock limit of `wall` seconds.
pub fn run_within(
    bin: &str,
    args: &[&str],
    dir: &Path,
    wall: u64,
) -> (Result<i32, String>, String, String) {
    use std::time::{Duration, Instant};
    let script = format!("ulimit -v {MEMORY_KIB}; ulimit -t {CPU_SECONDS}; exec \"$0\" \"$@\"",);
    let (out, err) = (dir.join(".stdout"), dir.join(".stderr"));
    let mut child = Command::new("sh")
        .arg("-c")
        .arg(script)
        .arg(bin)
        .args(args)
        .stdout(std::fs::File::create(&out).expect("stdout file"))
        .stderr(std::fs::File::create(&err).expect("stderr file"))
        .spawn()
        .expect("run sh");
    let deadline = Instant::now() + Duration::from_secs(wall);
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait") {
            break Some(s);
        }
        if Instant::now() >= deadline {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let status = match status {
        None => Err(format!("no answer within {wall} s (a hang)")),
        Some(st) => match st.code() {
            Some(c) => Ok(c),
            None => {
                use std::os::unix::process::ExitStatusExt;
                Err(match st.signal() {
                    Some(6) => {
                        "aborted (SIGABRT: memory beyond 1 GiB or a failed allocation)".into()
                    }
                    Some(9) => "killed (SIGKILL)".into(),
                    Some(11) => "crashed (SIGSEGV: stack overflow?)".into(),
                    Some(24) => format!("killed after {CPU_SECONDS} s of CPU (SIGXCPU)"),
                    s => format!("killed by signal {s:?}"),
                })
            }
        },
    };
    let read =
        |p: &Path| String::from_utf8_lossy(&std::fs::read(p).unwrap_or_default()).into_owned();
    let (stdout, stderr) = (read(&out), read(&err));
    let _ = std::fs::remove_file(&out);
    let _ = std::fs::remove_file(&err);
    (status, stdout, stderr)
}
