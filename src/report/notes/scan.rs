//! No English sentence built outside the report writer: a scan of `src/` for string literals
//! that build text (`format!`, `write!`, `push_str`, `.to_string()`, `.into()` …) and read as
//! an English sentence (four or more lower-case words in a row). The writer (`src/report/`),
//! the word catalogue (`src/words/`) and test code are not scanned; every other
//! file that still builds such text is listed in [`ALLOWED`] with its count and the reason,
//! and the test fails when a file builds more or fewer than listed — a note's sentence
//! written in a study fails it, and a file that sheds its sentences must leave the list.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A construction step's name in the recorder's log (what is drawn, named where it is
/// drawn: the figure's own words, read by tests, the studio and the SVG's ids, not a note).
const STEP: &str = "construction step names";
/// An error's or a diagnostic's message (a typed error's `Display`, its `why`/`detail`): the
/// words of a refusal, printed on the console, not a note of the report.
const ERROR: &str = "error messages";
/// The command line's and the studio's replies to the user.
const CONSOLE: &str = "console messages";
/// A catalogue-style match with its `Lang::En` arm beside the Russian and Ukrainian ones.
const CATALOGUE: &str = "catalogue rows";
/// The bench's rows and verdicts: the bench is a writer of its own beside `report` (DESIGN
/// §2), its words are its report's.
const BENCH: &str = "the bench's writer";
/// A file that names its construction steps and words its errors.
const STEP_ERROR: &str = "construction step names and error messages";

/// The files outside the writer that build English sentences: path, count, reason.
const ALLOWED: &[(&str, usize, &str)] = &[
    ("src/audit/read.rs", 8, ERROR),
    ("src/batch/key.rs", 2, CONSOLE),
    ("src/batch/mod.rs", 17, CONSOLE),
    ("src/bench/mod.rs", 2, BENCH),
    ("src/bench/peer.rs", 3, BENCH),
    ("src/bench/studio.rs", 1, BENCH),
    ("src/bench/throughput.rs", 11, BENCH),
    ("src/calculus/differentiate/mod.rs", 5, STEP),
    ("src/calculus/differentiate/tangents.rs", 4, STEP),
    ("src/calculus/integrate.rs", 2, STEP),
    ("src/calculus/mod.rs", 1, STEP),
    ("src/cam/flat_rocker/mod.rs", 1, STEP),
    ("src/cam/sliding.rs", 1, STEP),
    ("src/construct/compass.rs", 1, STEP),
    ("src/dynamics/part.rs", 2, STEP),
    ("src/forces/lever.rs", 3, STEP),
    ("src/forces/loads.rs", 3, ERROR),
    ("src/forces/pair_friction/mod.rs", 3, ERROR),
    ("src/forces/polygons/detail.rs", 1, STEP),
    ("src/forces/polygons/driver.rs", 1, STEP),
    ("src/forces/polygons/polygon.rs", 1, STEP),
    ("src/forces/polygons/scheme.rs", 2, STEP),
    ("src/friction/draw.rs", 2, STEP),
    ("src/friction/guide.rs", 2, STEP_ERROR),
    ("src/friction/incline.rs", 1, ERROR),
    ("src/friction/rolling.rs", 2, STEP),
    ("src/friction/wedge.rs", 1, STEP),
    ("src/gears/blocking/figure.rs", 2, STEP),
    ("src/gears/blocking/mod.rs", 1, ERROR),
    ("src/gears/mesh.rs", 3, STEP),
    ("src/gears/numbers.rs", 1, STEP),
    ("src/gears/rack.rs", 2, ERROR),
    ("src/gears/scheme/mod.rs", 5, STEP),
    ("src/gears/train/layout.rs", 2, ERROR),
    ("src/gears/train/mod.rs", 1, ERROR),
    ("src/gears/triangles/mod.rs", 3, STEP_ERROR),
    ("src/kinematics/mod.rs", 1, ERROR),
    ("src/linkage/built.rs", 1, STEP_ERROR),
    ("src/linkage/construction.rs", 1, STEP_ERROR),
    ("src/linkage/error.rs", 5, ERROR),
    ("src/linkage/extremes.rs", 1, ERROR),
    ("src/linkage/kinds/prp.rs", 1, ERROR),
    ("src/linkage/kinds/rpp.rs", 1, ERROR),
    ("src/linkage/kinds/rpr.rs", 2, STEP_ERROR),
    ("src/linkage/kinds/rpr/plan_slot.rs", 4, STEP_ERROR),
    ("src/linkage/kinds/rpr/slide.rs", 3, STEP_ERROR),
    ("src/linkage/kinds/rpr/twin_slot.rs", 2, ERROR),
    ("src/linkage/kinds/rrp.rs", 2, ERROR),
    ("src/linkage/kinds/rrr.rs", 1, ERROR),
    ("src/linkage/slide_lines.rs", 1, STEP),
    ("src/main.rs", 4, CONSOLE),
    ("src/note/mod.rs", 1, ERROR),
    ("src/plate/raster/canvas.rs", 2, ERROR),
    ("src/plate/raster/mod.rs", 2, ERROR),
    ("src/plate/write.rs", 1, ERROR),
    ("src/scene/balancing.rs", 1, ERROR),
    ("src/scene/cam.rs", 6, ERROR),
    ("src/scene/cam_layout.rs", 3, ERROR),
    ("src/scene/drawing.rs", 2, ERROR),
    ("src/scene/dynamics.rs", 1, ERROR),
    ("src/scene/follower.rs", 1, ERROR),
    ("src/scene/forces.rs", 2, ERROR),
    ("src/scene/friction.rs", 2, ERROR),
    ("src/scene/gear_values.rs", 2, ERROR),
    ("src/scene/gears.rs", 6, ERROR),
    ("src/scene/groups.rs", 2, ERROR),
    ("src/scene/kinematics.rs", 2, ERROR),
    ("src/scene/load.rs", 4, ERROR),
    ("src/scene/outputs.rs", 3, ERROR),
    ("src/scene/planetary.rs", 3, ERROR),
    ("src/scene/structure.rs", 6, ERROR),
    ("src/scene/text.rs", 1, ERROR),
    ("src/sheets/mod.rs", 2, ERROR),
    ("src/studio/api.rs", 2, CONSOLE),
];

/// The macros and calls whose first string literal builds text.
const OPENERS: [&str; 7] = [
    "format!(",
    "write!(",
    "writeln!(",
    "push_str(",
    "println!(",
    "eprintln!(",
    "String::from(",
];
/// The calls after a literal that make a `String` of it.
const CLOSERS: [&str; 4] = [".to_string()", ".into()", ".to_owned()", ".then("];

/// A string literal: where it opens and closes (just past its quote) and what it holds.
struct Literal {
    start: usize,
    end: usize,
    text: String,
}

/// The string literals of `src` (comments and char literals skipped; raw strings whole).
fn literals(src: &str) -> Vec<Literal> {
    let b = src.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'\'' if b.get(i + 2) == Some(&b'\'') || b.get(i + 1) == Some(&b'\\') => {
                // A char literal ('"', '\"', '\n'); a lifetime never has a quote two on.
                i += 1 + src[i + 1..].find('\'').map_or(b.len(), |e| e + 1);
                continue;
            }
            b'"' => {
                let hashes = src[..i].len() - src[..i].trim_end_matches('#').len();
                let raw = src[..i - hashes].ends_with('r');
                let (text, end) = if raw {
                    let close = format!("\"{}", "#".repeat(hashes));
                    let e = src[i + 1..].find(&close).map_or(b.len(), |e| i + 1 + e);
                    (src[i + 1..e].to_string(), e + close.len())
                } else {
                    quoted(src, i)
                };
                out.push(Literal {
                    start: i,
                    end,
                    text,
                });
                i = end;
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    out
}

/// The text of the (not raw) literal opening at `start`, and the offset just past it; a
/// line continuation reads as one space.
fn quoted(src: &str, start: usize) -> (String, usize) {
    let b = src.as_bytes();
    let mut text = String::new();
    let mut i = start + 1;
    while i < b.len() && b[i] != b'"' {
        if b[i] == b'\\' {
            if b.get(i + 1) == Some(&b'\n') {
                i += 1;
                while i + 1 < b.len() && b[i + 1].is_ascii_whitespace() {
                    i += 1;
                }
                text.push(' ');
            } else {
                i += 1;
            }
            i += 1;
            continue;
        }
        let c = src[i..].chars().next().unwrap_or(' ');
        text.push(c);
        i += c.len_utf8();
    }
    (text, i + 1)
}

/// True when `text` reads as an English sentence: four or more words of lower-case Latin
/// letters (with apostrophes) in a row, one space apart.
fn sentence(text: &str) -> bool {
    let mut run = 0;
    for w in text.split(' ') {
        let word = !w.is_empty()
            && w.starts_with(|c: char| c.is_ascii_lowercase())
            && w.chars()
                .all(|c| c.is_ascii_lowercase() || c == '\'' || c == '’');
        run = if word { run + 1 } else { 0 };
        if run >= 4 {
            return true;
        }
    }
    false
}

/// True when the literal at `start` (ending before `end`) builds text: an opener before it
/// (with at most a writer's name between) or a closer after it.
fn builds(src: &str, start: usize, end: usize) -> bool {
    let before = src[..start].trim_end();
    let before = before
        .strip_suffix(',')
        .map(|b| b.trim_end_matches(|c: char| c.is_alphanumeric() || c == '_' || c == '.'))
        .map_or(before, str::trim_end);
    OPENERS.iter().any(|o| before.ends_with(o)) || CLOSERS.iter().any(|c| src[end..].starts_with(c))
}

/// The source with its inline test module cut off.
fn without_tests(src: &str) -> &str {
    src.find("#[cfg(test)]\nmod tests {")
        .map_or(src, |i| &src[..i])
}

/// Every `.rs` file under `dir`, test files left out.
fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        let name = e.file_name().to_string_lossy().into_owned();
        if p.is_dir() {
            if !matches!(name.as_str(), "tests" | "proptests") {
                sources(&p, out);
            }
        } else if name.ends_with(".rs") && !name.starts_with("tests") {
            out.push(p);
        }
    }
}

/// The files outside the writer and the catalogue that build English sentences, with how
/// many each builds.
fn english_builders() -> BTreeMap<String, usize> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    sources(&root.join("src"), &mut files);
    let mut out = BTreeMap::new();
    for path in files {
        let rel = path
            .strip_prefix(root)
            .map_or_else(|_| path.display().to_string(), |p| p.display().to_string());
        // A whole file of tests (`#[cfg(test)] mod …_tests;`) is test code too.
        let test_file = rel.ends_with("_tests.rs") || rel.ends_with("/tests.rs");
        if rel.starts_with("src/report/") || rel.starts_with("src/words/") || test_file {
            continue;
        }
        let Ok(src) = std::fs::read_to_string(&path) else {
            continue;
        };
        let src = without_tests(&src);
        let n = literals(src)
            .into_iter()
            .filter(|l| sentence(&l.text) && builds(src, l.start, l.end))
            .count();
        if n > 0 {
            out.insert(rel, n);
        }
    }
    out
}

#[test]
fn no_english_sentence_is_built_outside_the_report_writer_but_the_listed_ones() {
    let found = english_builders();
    let allowed: BTreeMap<String, usize> = ALLOWED
        .iter()
        .map(|(f, n, _)| ((*f).to_string(), *n))
        .collect();
    let listed: Vec<String> = found
        .iter()
        .map(|(f, n)| format!("(\"{f}\", {n}, ?),"))
        .collect();
    assert_eq!(
        found,
        allowed,
        "English built outside the report writer: write a note's words in src/report/notes/, \
         or list the file with its reason. Found:\n{}",
        listed.join("\n")
    );
    // The reasons are the kinds the module names.
    for (f, _, why) in ALLOWED {
        assert!(
            [STEP, ERROR, CONSOLE, CATALOGUE, BENCH, STEP_ERROR].contains(why),
            "{f}: {why}"
        );
    }
}

#[test]
fn the_scan_sees_a_sentence_built_in_each_way_and_not_a_key() {
    let src = r#"let a = format!("cam: the roller is too big at {x}");
let b = "no flywheel is needed".to_string();
write!(f, "the guide runs through the joint")?;
let key = format!("alpha_{tag}");
let c = '"'; let d = "phi";"#;
    let hits: Vec<String> = literals(src)
        .into_iter()
        .filter(|l| sentence(&l.text) && builds(src, l.start, l.end))
        .map(|l| l.text)
        .collect();
    assert_eq!(
        hits,
        [
            "cam: the roller is too big at {x}",
            "no flywheel is needed",
            "the guide runs through the joint"
        ]
    );
}
