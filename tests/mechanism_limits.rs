//! The documented ranges of the mechanism's and the kinematic study's keys (issue 17 §4, §5):
//! every value inside works, every value outside is refused at load naming the key and the
//! range (exit 2), and nothing grows without bound on the way.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

mod support;
use support::{root, scratch};

/// The shaper's text with its kinematics only (the loads of the force analysis come last).
fn shaper_kinematics() -> String {
    let text = std::fs::read_to_string(root().join("constructions/shaper.toml")).expect("shaper");
    text.split("\n[forces]").next().unwrap_or_default().replace(
        "\"kinematics\", \"forces\", \"dynamics\"]",
        "\"kinematics\"]",
    )
}

/// `tmm ARGS…` on `text` written to a scratch scene, with the address space limited to
/// 1 GiB (`ulimit -v`): a run that tries to allocate more fails instead of swapping.
fn run_limited(name: &str, text: &str, args: &[&str]) -> (Output, PathBuf) {
    let dir = scratch(name);
    let scene = dir.join(format!("{name}.toml"));
    std::fs::write(&scene, text).expect("write scene");
    let out = dir.join("out");
    let mut cmd = vec![env!("CARGO_BIN_EXE_tmm").to_string()];
    cmd.extend(args.iter().map(|a| a.to_string()));
    cmd.push(scene.to_string_lossy().into_owned());
    if args.first() == Some(&"render") {
        cmd.extend(["--out".into(), out.to_string_lossy().into_owned()]);
    }
    let quoted: Vec<String> = cmd.iter().map(|a| format!("'{a}'")).collect();
    let o = Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v 1048576 && exec {}", quoted.join(" ")))
        .output()
        .expect("run tmm");
    (o, out)
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Refused at load: exit 2, the message names each of `needles`, nothing written.
fn assert_refused(name: &str, text: &str, needles: &[&str]) {
    let (o, out) = run_limited(name, text, &["check"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{name}: {err}");
    for n in needles {
        assert!(err.contains(n), "{name}: the message lacks `{n}`: {err}");
    }
    assert!(!err.contains("panicked"), "{name}: {err}");
    assert!(!out.exists(), "{name}: wrote {}", out.display());
}

fn files_under(dir: &Path) -> usize {
    std::fs::read_dir(dir).map_or(0, |d| d.count())
}

/// §4: a link numbered 2e7 sized every per-link array by that number (21 GB, three minutes
/// for `tmm check`). Link numbers beyond 99 are refused at load with the key, inside 1 GiB.
#[test]
fn a_huge_link_number_is_refused_at_load() {
    let text = shaper_kinematics()
        .replace("links = [4, 5]", "links = [4, 20000000]")
        .replace("link = 5\n", "link = 20000000\n");
    assert_refused(
        "link-2e7",
        &text,
        &["mechanism.group[1].links", "20000000", "1 … 99"],
    );
    // The largest number allowed works: the ram numbered 99.
    let text = shaper_kinematics()
        .replace("links = [4, 5]", "links = [4, 99]")
        .replace("link = 5\n", "link = 99\n")
        .replace("links = [5, 0]", "links = [99, 0]");
    let (o, out) = run_limited("link-99", &text, &["render", "--format", "svg"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(files_under(&out.join("link-99")) >= 2);
}
