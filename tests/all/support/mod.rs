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

/// `tmm render SCENE --out OUT --format svg`, which must succeed (`what` names the case).
pub fn render_svg(scene: &std::path::Path, out: &std::path::Path, what: &str) {
    let o = tmm(&[
        "render",
        scene.to_str().expect("utf-8"),
        "--out",
        out.to_str().expect("utf-8"),
        "--format",
        "svg",
    ]);
    assert!(
        o.status.success(),
        "{what}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// The scene `constructions/<name>.toml`, loaded (a test's scene that fails to load panics).
pub fn scene(name: &str) -> tmm::Scene {
    let path = root().join("constructions").join(format!("{name}.toml"));
    tmm::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// Every scene of `constructions/`, sorted; at least the eighteen there are.
pub fn scene_paths() -> Vec<PathBuf> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(root().join("constructions"))
        .expect("constructions")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 18, "{paths:?}");
    paths
}

/// A fresh scratch folder for one test: its own even when two tests running at once give
/// the same name (a counter of the process).
pub fn scratch(name: &str) -> PathBuf {
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("tmm-test-{}-{n}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

/// `tmm report SCENE --format json` (with `--drafting` when given), parsed; the run must
/// succeed.
pub fn report_json(scene: &str, drafting: Option<&str>) -> serde_json::Value {
    let mut args = vec!["report", scene, "--format", "json"];
    if let Some(d) = drafting {
        args.extend(["--drafting", d]);
    }
    let o = tmm(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).expect("report JSON")
}

/// The report's rows of quantity `q`.
pub fn rows_of<'a>(v: &'a serde_json::Value, q: &str) -> Vec<&'a serde_json::Value> {
    v["rows"]
        .as_array()
        .expect("rows")
        .iter()
        .filter(|r| r["quantity"] == q)
        .collect()
}

/// A number of a row (`graphical`, `analytic`, …); a row without it fails the test.
pub fn num(r: &serde_json::Value, field: &str) -> f64 {
    r[field]
        .as_f64()
        .unwrap_or_else(|| panic!("{field} of {r}"))
}

/// The report's notes, one per line.
pub fn notes(v: &serde_json::Value) -> String {
    v["notes"]
        .as_array()
        .expect("notes")
        .iter()
        .filter_map(|n| n.as_str())
        .collect::<Vec<_>>()
        .join("\n")
}

/// Run `tmm` with `args` in the repository root under a limit of `kib` KiB of address space
/// (`ulimit -v`): an unbounded allocation aborts instead of taking the machine.
pub fn tmm_limited(kib: u64, args: &[&str]) -> Output {
    Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {kib} && exec \"$0\" \"$@\""))
        .arg(env!("CARGO_BIN_EXE_tmm"))
        .args(args)
        .current_dir(root())
        .output()
        .expect("run tmm under a memory limit")
}

/// The memory limit the hostile-input tests run `tmm` under, KiB (1.5 GB).
pub const LIMIT_KIB: u64 = 1_500_000;

/// `tmm COMMAND INPUTS… --out OUT EXTRA…` under [`LIMIT_KIB`]: neither an abort (a signal)
/// nor a panic. Its status and standard error.
pub fn run_limited(
    command: &str,
    inputs: &[&std::path::Path],
    out: &std::path::Path,
    extra: &[&str],
) -> (Option<i32>, String) {
    let mut args = vec![command];
    args.extend(inputs.iter().map(|p| p.to_str().expect("a UTF-8 path")));
    args.extend(["--out", out.to_str().expect("a UTF-8 path")]);
    args.extend_from_slice(extra);
    let o = tmm_limited(LIMIT_KIB, &args);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(o.status.code().is_some(), "killed by a signal: {err}");
    assert!(
        !err.contains("panicked") && !err.contains("overflow"),
        "{err}"
    );
    (o.status.code(), err)
}

/// Every file under `dir`, in order.
pub fn files_under(dir: &std::path::Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    if let Ok(rd) = std::fs::read_dir(dir) {
        for e in rd.flatten() {
            let p = e.path();
            if p.is_dir() {
                out.extend(files_under(&p));
            } else {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// The text elements of an SVG: each element's runs (the base text and every `<tspan>`),
/// unescaped, the runs joined by a space so that a subscript does not run into its base.
pub fn svg_texts(svg: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(start) = rest.find("<text") {
        let after = &rest[start..];
        let Some(end) = after.find("</text>") else {
            break;
        };
        let element = &after[..end];
        // Drop the opening tag's attributes, then every inner tag becomes a space.
        let body = element.split_once('>').map_or("", |(_, b)| b);
        let mut text = String::new();
        let mut in_tag = false;
        for c in body.chars() {
            match c {
                '<' => {
                    in_tag = true;
                    text.push(' ');
                }
                '>' => in_tag = false,
                _ if !in_tag => text.push(c),
                _ => {}
            }
        }
        let text = text
            .replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&quot;", "\"")
            .replace("&apos;", "'")
            .replace("&amp;", "&");
        out.push(text);
        rest = &after[end..];
    }
    out
}

/// The text of a PDF's dictionaries with the optional spaces between names and values taken
/// out (`/Type /Page` and `/Type/Page` both read `/Type/Page`).
pub fn pdf_dicts(pdf: &[u8]) -> String {
    String::from_utf8_lossy(pdf)
        .replace(" /", "/")
        .replace(" [", "[")
}

/// The pages of a PDF written without object streams: its page objects.
pub fn pdf_pages(pdf: &[u8]) -> usize {
    let text = pdf_dicts(pdf);
    text.matches("/Type/Page").count() - text.matches("/Type/Pages").count()
}
