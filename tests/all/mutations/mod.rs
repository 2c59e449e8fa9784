//! The mutation sweep: every number of every scene in `constructions/` replaced by −1, 0, nan,
//! inf, "x", 1e300, −1e-300, 1e-9, 1e9, 2³¹, or deleted, and every scene cut in half (by lines, each
//! half); each mutant is rendered (SVG and a low-dpi PNG) and reported. Every run must end
//! with exit 0 and its output, or exit 1/2 with a message on standard error: no panic, no
//! abort, no signal, no file left behind by a failed run, no temporary left by any run, and
//! within 1 GiB of address space and 60 s of CPU (`ulimit -v`, `ulimit -t`: a run beyond
//! either dies of a signal, which is a finding) and 60 s of wall time (a run that has not
//! answered by then is killed and counted as a hang).
//!
//! `cargo test --release --test all mutations::` runs a deterministic sample (about
//! [`SAMPLE`] mutants, spread over the scenes and mutations by a hash); `TMM_MUTATIONS=all`
//! runs every mutant, `TMM_MUTATIONS=<n>` a sample of about n. `TMM_MUTATIONS_SCENE=<stem>`
//! keeps the scenes whose stem contains it; `TMM_MUTATIONS_OUT=<file>` writes the findings
//! (one per line, tab-separated: scene, key, mutation, command, what happened); `TMM_BIN`
//! runs another `tmm` binary than the one built with the test.

use rayon::prelude::*;
use std::path::{Path, PathBuf};

use crate::support;
use support::{files_under, root};

mod limits;
use limits::{run, run_within};

/// The mutants of the default sample.
const SAMPLE: usize = 160;
/// The replacements of a number (deletion is the eleventh).
const REPLACEMENTS: [&str; 10] = [
    "-1",
    "0",
    "nan",
    "inf",
    "\"x\"",
    "1e300",
    "-1e-300",
    "1e-9",
    "1e9",
    "2147483648",
];

/// A number literal of a scene: its bytes and its key path.
#[derive(Debug)]
struct Number {
    start: usize,
    end: usize,
    /// Where a deletion starts: the key of `key = number`, or the number in an array.
    delete_from: usize,
    key: String,
}

/// One mutated scene.
struct Mutant {
    scene: String,
    key: String,
    mutation: String,
    text: String,
}

/// What the lexer is inside of, outside strings and comments.
enum Nest {
    /// An array, with the index of the current element.
    Array(usize),
    /// An inline table, with the depth of the key path at its opening.
    Table(usize),
}

/// The lexer's state over a TOML text: the current table, the keys of the current value,
/// what it is inside of, and the numbers found so far.
struct Lexer<'t> {
    text: &'t str,
    out: Vec<Number>,
    table: String,
    /// How many of each array of tables were opened.
    counts: Vec<(String, usize)>,
    /// The keys of the current value: the table's key, then inline tables' keys.
    keys: Vec<(String, usize)>,
    nest: Vec<Nest>,
    word_start: Option<usize>,
    /// The last significant byte: a number starts a value after `=`, `[` or `,` in an array.
    last: u8,
}

impl Lexer<'_> {
    /// The table header at `i` (`[name]` or `[[name]]`, counted): the end of its line.
    fn header(&mut self, i: usize) -> usize {
        let text = self.text;
        let end = text[i..].find('\n').map_or(text.len(), |k| i + k);
        let line = text[i..end].trim();
        if let Some(name) = line.strip_prefix("[[").and_then(|l| l.split("]]").next()) {
            let name = name.trim().to_string();
            let n = match self.counts.iter_mut().find(|(n, _)| *n == name) {
                Some((_, k)) => {
                    *k += 1;
                    *k - 1
                }
                None => {
                    self.counts.push((name.clone(), 1));
                    0
                }
            };
            self.table = format!("{name}[{n}]");
        } else if let Some(name) = line.strip_prefix('[').and_then(|l| l.split(']').next()) {
            self.table = name.trim().to_string();
        }
        end
    }

    /// The `=` at `i`: the key before it opens a value at the current depth.
    fn key(&mut self, i: usize) {
        let from = self.word_start.unwrap_or(i);
        let key = self.text[from..i].trim().to_string();
        let depth = match self.nest.last() {
            Some(Nest::Table(d)) => *d,
            _ => 0,
        };
        self.keys.truncate(depth);
        self.keys.push((key, from));
        self.word_start = None;
        self.last = b'=';
    }

    /// The number starting at `i` when it is in value position (recorded with its key
    /// path): its end.
    fn number(&mut self, i: usize) -> Option<usize> {
        let (text, bytes, c) = (self.text, self.text.as_bytes(), self.text.as_bytes()[i]);
        let last = self.last;
        let value_position = last == b'=' || last == b'[' || last == b',';
        let in_array = matches!(self.nest.last(), Some(Nest::Array(_)));
        let starts_number = c.is_ascii_digit()
            || ((c == b'-' || c == b'+') && bytes.get(i + 1).is_some_and(|b| b.is_ascii_digit()));
        if !(value_position && (in_array || last == b'=') && starts_number) {
            return None;
        }
        let end = (i..bytes.len())
            .find(|&k| !(bytes[k].is_ascii_alphanumeric() || b"._+-:".contains(&bytes[k])))
            .unwrap_or(bytes.len());
        let token = text[i..end].replace('_', "");
        if token.parse::<f64>().is_ok() {
            let mut path: Vec<&str> = vec![];
            if !self.table.is_empty() {
                path.push(&self.table);
            }
            path.extend(self.keys.iter().map(|(k, _)| k.as_str()));
            let mut key = path.join(".");
            let delete_from = if let Some(Nest::Array(k)) = self.nest.last() {
                key.push_str(&format!("[{k}]"));
                i
            } else {
                self.keys.last().map_or(i, |(_, from)| *from)
            };
            self.out.push(Number {
                start: i,
                end,
                delete_from,
                key,
            });
        }
        Some(end)
    }
}

/// The number literals of a TOML text in value position, with their key paths. A small
/// lexer: table headers, comments, basic and literal strings, arrays and inline tables.
fn numbers(text: &str) -> Vec<Number> {
    let bytes = text.as_bytes();
    let mut lx = Lexer {
        text,
        out: Vec::new(),
        table: String::new(),
        counts: Vec::new(),
        keys: Vec::new(),
        nest: Vec::new(),
        word_start: None,
        last: b'\n',
    };
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        match c {
            b'#' => {
                while i < bytes.len() && bytes[i] != b'\n' {
                    i += 1;
                }
                continue;
            }
            b'\n' if lx.nest.is_empty() => {
                lx.last = b'\n';
                lx.word_start = None;
            }
            b' ' | b'\t' | b'\r' | b'\n' => {}
            b'[' if lx.nest.is_empty() && lx.last == b'\n' => {
                i = lx.header(i);
                continue;
            }
            b'"' | b'\'' => {
                i += 1;
                while i < bytes.len() && bytes[i] != c {
                    if c == b'"' && bytes[i] == b'\\' {
                        i += 1;
                    }
                    i += 1;
                }
                lx.last = c;
            }
            b'=' => lx.key(i),
            b'[' => {
                lx.nest.push(Nest::Array(0));
                lx.last = c;
            }
            b'{' => {
                lx.nest.push(Nest::Table(lx.keys.len()));
                lx.last = c;
            }
            b']' | b'}' => {
                lx.nest.pop();
                lx.last = c;
            }
            b',' => {
                if let Some(Nest::Array(k)) = lx.nest.last_mut() {
                    *k += 1;
                }
                lx.word_start = None;
                lx.last = c;
            }
            _ => {
                if let Some(end) = lx.number(i) {
                    i = end;
                    lx.last = b'0';
                    continue;
                }
                if lx.word_start.is_none() {
                    lx.word_start = Some(i);
                }
                lx.last = c;
            }
        }
        i += 1;
    }
    lx.out
}

/// The text without `[from, to)` and one comma beside it (the following one, else the
/// preceding one), so that arrays and inline tables stay well formed.
fn delete(text: &str, from: usize, to: usize) -> String {
    let b = text.as_bytes();
    let (mut s, mut e) = (from, to);
    let mut k = e;
    while k < b.len() && (b[k] == b' ' || b[k] == b'\t') {
        k += 1;
    }
    if k < b.len() && b[k] == b',' {
        e = k + 1;
    } else {
        let mut k = s;
        while k > 0 && (b[k - 1] == b' ' || b[k - 1] == b'\t') {
            k -= 1;
        }
        if k > 0 && b[k - 1] == b',' {
            s = k - 1;
        }
    }
    format!("{}{}", &text[..s], &text[e..])
}

/// Every mutant of every scene, in a fixed order.
fn mutants() -> Vec<Mutant> {
    let dir = root().join("constructions");
    let filter = std::env::var("TMM_MUTATIONS_SCENE").ok();
    let mut scenes: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("constructions/")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .filter(|p| {
            filter.as_ref().is_none_or(|f| {
                p.file_stem()
                    .is_some_and(|s| s.to_string_lossy().contains(f))
            })
        })
        .collect();
    scenes.sort();
    let mut out = Vec::new();
    for path in scenes {
        let text = std::fs::read_to_string(&path).expect("scene");
        let scene = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        for n in numbers(&text) {
            for r in REPLACEMENTS {
                out.push(Mutant {
                    scene: scene.clone(),
                    key: n.key.clone(),
                    mutation: r.to_string(),
                    text: format!("{}{r}{}", &text[..n.start], &text[n.end..]),
                });
            }
            out.push(Mutant {
                scene: scene.clone(),
                key: n.key.clone(),
                mutation: "deleted".into(),
                text: delete(&text, n.delete_from, n.end),
            });
        }
        let lines: Vec<&str> = text.lines().collect();
        let half = lines.len() / 2;
        for (name, part) in [
            ("first half", &lines[..half]),
            ("second half", &lines[half..]),
        ] {
            out.push(Mutant {
                scene: scene.clone(),
                key: "-".into(),
                mutation: name.into(),
                text: part.join("\n") + "\n",
            });
        }
    }
    out
}

/// FNV-1a, for a sample that does not depend on the order of the mutants.
fn hash(s: &str) -> u64 {
    s.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// The first line of a message, shortened.
fn gist(s: &str) -> String {
    let line = s
        .lines()
        .find(|l| l.contains("panicked"))
        .or_else(|| s.lines().find(|l| !l.trim().is_empty()))
        .unwrap_or("");
    line.chars().take(200).collect()
}

/// A number printed badly in `text`: a run of more than 24 digits (a huge value echoed in
/// full), a rounding residue printed as a value (`0.0000000000000002`: ten zeros after the
/// point, then a digit) or a NaN.
fn bad_number(text: &str) -> Option<String> {
    let b = text.as_bytes();
    let mut k = 0;
    while k < b.len() {
        if b[k].is_ascii_digit() {
            let start = k;
            while k < b.len() && (b[k].is_ascii_digit() || b[k] == b'.' || b[k] == b',') {
                k += 1;
            }
            let token = &text[start..k];
            let digits = token.bytes().filter(u8::is_ascii_digit).count();
            let residue = ["0.0000000000", "0,0000000000"].iter().any(|z| {
                token.starts_with(z)
                    && token[z.len()..]
                        .bytes()
                        .any(|d| d.is_ascii_digit() && d != b'0')
            });
            if digits > 24 || residue {
                let from = text[..start]
                    .char_indices()
                    .rev()
                    .nth(40)
                    .map_or(0, |(i, _)| i);
                let line: String = text[from..].chars().take(120).collect();
                return Some(line.replace('\n', " "));
            }
        } else {
            k += 1;
        }
    }
    text.split(|c: char| !c.is_ascii_alphanumeric())
        .find(|w| *w == "NaN")
        .map(|_| "NaN printed".to_string())
}

/// What is wrong with one run, if anything.
fn judge(
    status: &Result<i32, String>,
    stdout: &str,
    stderr: &str,
    written: &[PathBuf],
) -> Option<String> {
    let code = match status {
        Err(signal) => return Some(format!("{signal}: {}", gist(stderr))),
        Ok(c) => *c,
    };
    if stderr.contains("panicked") {
        return Some(format!("panic: {}", gist(stderr)));
    }
    if let Some(at) = bad_number(stderr) {
        return Some(format!(
            "exit {code}, a number printed badly in the message: …{at}"
        ));
    }
    if let Some(t) = written
        .iter()
        .find(|p| p.to_string_lossy().contains(".tmp-"))
    {
        return Some(format!("temporary left behind: {}", t.display()));
    }
    match code {
        0 if stdout.trim().is_empty() => Some("exit 0 without output".into()),
        0 => None,
        1 | 2 if stderr.trim().is_empty() => Some(format!("exit {code} without a message")),
        1 | 2 if !written.is_empty() => Some(format!(
            "exit {code} left {} file(s) behind: {}",
            written.len(),
            gist(stderr)
        )),
        1 | 2 => None,
        c => Some(format!("exit {c}: {}", gist(stderr))),
    }
}

/// Render and report one mutant; its findings (command, what happened).
fn sweep_one(index: usize, m: &Mutant, base: &Path) -> Vec<(String, String)> {
    let dir = base.join(index.to_string());
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch");
    let scene = dir.join(format!("{}.toml", m.scene));
    std::fs::write(&scene, &m.text).expect("mutant");
    let out = dir.join("out");
    let scene_arg = scene.to_string_lossy().into_owned();
    let out_arg = out.to_string_lossy().into_owned();
    let mut findings = Vec::new();
    let render = [
        "render", &scene_arg, "--out", &out_arg, "--format", "svg,png", "--dpi", "10",
    ];
    let (status, stdout, stderr) = run(&render, &dir);
    let written = files_under(&out);
    if let Some(f) = judge(&status, &stdout, &stderr, &written) {
        findings.push(("render".to_string(), f));
    } else if status == Ok(0) {
        // Every file the run names exists.
        if let Some(missing) = stdout.lines().find(|l| !Path::new(l.trim()).is_file()) {
            findings.push((
                "render".into(),
                format!("names a file it did not write: {missing}"),
            ));
        }
    }
    let (status, stdout, stderr) = run(&["report", &scene_arg], &dir);
    if let Some(f) = judge(&status, &stdout, &stderr, &[]) {
        findings.push(("report".to_string(), f));
    } else if let Some(at) = bad_number(&stdout) {
        findings.push(("report".into(), format!("a number printed badly: …{at}")));
    }
    let _ = std::fs::remove_dir_all(&dir);
    findings
}

/// A run that does not answer in time is a finding, not a pass (a hang shows).
#[test]
fn a_run_with_no_answer_is_counted_as_a_hang() {
    let dir = support::scratch("hang");
    let (status, _, _) = run_within("sleep", &["30"], &dir, 1);
    let status = status.expect_err("a hang is not an exit");
    assert!(status.contains("a hang"), "{status}");
    assert!(judge(&Err(status), "", "", &[]).is_some());
    let (status, _, _) = run_within("true", &[], &dir, 5);
    assert_eq!(status, Ok(0));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn every_mutant_of_every_scene_ends_with_output_or_a_message() {
    let all = mutants();
    assert!(
        all.len() > 1000,
        "the lexer finds the scenes' numbers: {}",
        all.len()
    );
    let wanted = std::env::var("TMM_MUTATIONS").ok();
    let chosen: Vec<(usize, &Mutant)> = match wanted.as_deref() {
        Some("all") => all.iter().enumerate().collect(),
        other => {
            let n = other.and_then(|s| s.parse().ok()).unwrap_or(SAMPLE).max(1) as u64;
            let total = all.len() as u64;
            all.iter()
                .enumerate()
                .filter(|(_, m)| hash(&format!("{}|{}|{}", m.scene, m.key, m.mutation)) % total < n)
                .collect()
        }
    };
    let base = std::env::temp_dir().join(format!("tmm-mutations-{}", std::process::id()));
    let started = std::time::Instant::now();
    let findings: Vec<String> = chosen
        .par_iter()
        .flat_map_iter(|(k, m)| {
            sweep_one(*k, m, &base).into_iter().map(move |(cmd, what)| {
                format!("{}\t{}\t{}\t{}\t{}", m.scene, m.key, m.mutation, cmd, what)
            })
        })
        .collect();
    let _ = std::fs::remove_dir_all(&base);
    let summary = format!(
        "{} mutants of {} ({} runs) in {:.0} s: {} finding(s)",
        chosen.len(),
        all.len(),
        2 * chosen.len(),
        started.elapsed().as_secs_f64(),
        findings.len()
    );
    eprintln!("{summary}");
    if let Ok(path) = std::env::var("TMM_MUTATIONS_OUT") {
        let body = format!("# {summary}\n{}\n", findings.join("\n"));
        std::fs::write(path, body).expect("findings file");
    }
    assert!(findings.is_empty(), "{summary}\n{}", findings.join("\n"));
}

#[test]
fn bad_numbers_are_told() {
    assert!(bad_number("R = 294.0 N, 0.00001 m, 1e300, 1,0025").is_none());
    assert!(bad_number(&format!("x = {}", 1e300)).is_some());
    assert!(bad_number("the resistances do -0.0000000000000002237 J").is_some());
    assert!(bad_number("| ε | NaN |").is_some());
}

#[test]
fn the_lexer_finds_values_not_keys_strings_or_comments() {
    let text = "# 1 2\n[[a.b]]\nx = 1.5 # 3\nname = \"S_2 4\"\nz1 = [2, -3]\n\
                g = { dir = 0.0, off = 25 }\n[[a.b]]\ny = 1e3\n";
    let got: Vec<(String, &str)> = numbers(text)
        .iter()
        .map(|n| (n.key.clone(), &text[n.start..n.end]))
        .collect();
    let want = [
        ("a.b[0].x", "1.5"),
        ("a.b[0].z1[0]", "2"),
        ("a.b[0].z1[1]", "-3"),
        ("a.b[0].g.dir", "0.0"),
        ("a.b[0].g.off", "25"),
        ("a.b[1].y", "1e3"),
    ];
    let want: Vec<(String, &str)> = want.iter().map(|(k, v)| (k.to_string(), *v)).collect();
    assert_eq!(got, want);
    let ns = numbers(text);
    assert_eq!(
        delete(text, ns[3].delete_from, ns[3].end),
        text.replace("dir = 0.0,", "")
    );
    assert_eq!(
        delete(text, ns[4].delete_from, ns[4].end),
        text.replace(", off = 25", "")
    );
    assert_eq!(
        delete(text, ns[2].delete_from, ns[2].end),
        text.replace(", -3", "")
    );
    assert_eq!(
        delete(text, ns[0].delete_from, ns[0].end),
        text.replace("x = 1.5", "")
    );
}
