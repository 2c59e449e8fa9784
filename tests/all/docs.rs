//! The documentation against the program: the synopsis of every command in
//! `docs/commands.md` names exactly the flags (and the values of each enumerated flag) that
//! `tmm <command> -h` lists; every command line written in `README.md` or `docs/*.md` uses
//! only flags and values its command has; the README is a page (at most 150 lines) whose
//! links lead to files that exist; what it says the seed-000 command writes is what it writes
//! (the sheets, the pages, the scenes, the quoted θ, H and K, what each sheet holds); a
//! `[kinematics]` section that no sheet draws is warned of.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use crate::support::{pdf_pages, root, scratch, svg_texts, tmm};

/// The flags a command's short help lists (`--help` and `--version` aside), each with its
/// possible values (empty for a free value or a switch).
fn help_flags(command: &str) -> BTreeMap<String, BTreeSet<String>> {
    let o = tmm(&[command, "-h"]);
    assert!(o.status.success(), "tmm {command} -h");
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    let options = text.split("Options:").nth(1).unwrap_or_default();
    let mut flags = BTreeMap::new();
    for line in options
        .lines()
        .map(str::trim)
        .filter(|l| l.starts_with('-'))
    {
        let Some(flag) = line
            .split_whitespace()
            .map(|w| w.trim_end_matches(','))
            .find(|w| w.starts_with("--"))
        else {
            continue;
        };
        if flag == "--help" || flag == "--version" {
            continue;
        }
        let values = line
            .split("[possible values: ")
            .nth(1)
            .and_then(|v| v.split(']').next())
            .map(|v| v.split(", ").map(String::from).collect())
            .unwrap_or_default();
        flags.insert(flag.to_string(), values);
    }
    flags
}

/// The commands `tmm -h` lists (`help` aside).
fn commands() -> Vec<String> {
    let o = tmm(&["-h"]);
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    let listed = text.split("Commands:").nth(1).unwrap_or_default();
    let listed = listed.split("Options:").next().unwrap_or_default();
    listed
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .map(String::from)
        .collect()
}

/// A command line written in the documentation: the command and its words after it.
struct Line {
    file: String,
    command: String,
    words: Vec<String>,
}

/// Every command line in the fenced code blocks of `text`: `tmm COMMAND …` or
/// `cargo run --release [--features F] -- COMMAND …`, a trailing `# comment` left out.
fn command_lines(file: &str, text: &str) -> Vec<Line> {
    let mut out = Vec::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if !fenced {
            continue;
        }
        let code = line.split(" #").next().unwrap_or_default().trim();
        let rest = if let Some(r) = code.strip_prefix("tmm ") {
            r
        } else if let Some((_, r)) = code
            .strip_prefix("cargo run --release")
            .and_then(|r| r.split_once("-- "))
        {
            r
        } else {
            continue;
        };
        let mut words = rest.split_whitespace().map(String::from);
        if let Some(command) = words.next() {
            out.push(Line {
                file: file.to_string(),
                command,
                words: words.collect(),
            });
        }
    }
    out
}

/// The flags of a line and the value written after each (`[--lang ru|uk|en]` gives
/// `--lang` with `ru`, `uk`, `en`; a switch, or a flag whose value is free, none).
fn written_flags(line: &Line) -> BTreeMap<String, BTreeSet<String>> {
    let words: Vec<&str> = line
        .words
        .iter()
        .map(|w| w.trim_matches(|c| c == '[' || c == ']'))
        .collect();
    let mut flags = BTreeMap::new();
    for (k, w) in words.iter().enumerate() {
        if !w.starts_with("--") {
            continue;
        }
        let value = words.get(k + 1).filter(|v| !v.starts_with("--"));
        let values = value
            .map(|v| {
                v.split([',', '|'])
                    .filter(|x| x.chars().all(|c| c.is_ascii_lowercase()))
                    .map(String::from)
                    .collect()
            })
            .unwrap_or_default();
        flags.insert((*w).to_string(), values);
    }
    flags
}

/// The Markdown files of the documentation: the README and every page of `docs/`.
fn pages() -> Vec<(String, String)> {
    let mut files = vec![root().join("README.md")];
    let mut docs: Vec<_> = std::fs::read_dir(root().join("docs"))
        .expect("docs/")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    docs.sort();
    files.extend(docs);
    files
        .iter()
        .map(|p| {
            let name = p.strip_prefix(root()).unwrap_or(p).display().to_string();
            (name, std::fs::read_to_string(p).unwrap_or_default())
        })
        .collect()
}

/// `docs/commands.md`'s synopsis (its first code block) names every command once, with exactly the flags its help
/// lists and, for a flag of a few values, exactly those values.
#[test]
fn the_synopsis_names_every_flag_the_help_lists() {
    let text = std::fs::read_to_string(root().join("docs/commands.md")).expect("docs/commands.md");
    // The synopsis is the page's first code block.
    let block = text.split("```").nth(1).unwrap_or_default();
    let lines = command_lines("docs/commands.md", &format!("```{block}```"));
    let listed = commands();
    assert!(listed.len() >= 8, "{listed:?}");
    for command in &listed {
        let synopsis: Vec<&Line> = lines.iter().filter(|l| &l.command == command).collect();
        assert_eq!(synopsis.len(), 1, "one synopsis line of `tmm {command}`");
        let written = written_flags(synopsis[0]);
        let help = help_flags(command);
        let names = |m: &BTreeMap<String, BTreeSet<String>>| m.keys().cloned().collect::<Vec<_>>();
        assert_eq!(
            names(&written),
            names(&help),
            "the flags of `tmm {command}`"
        );
        for (flag, values) in help.iter().filter(|(_, v)| !v.is_empty()) {
            assert_eq!(
                &written[flag], values,
                "the values of `tmm {command} {flag}`"
            );
        }
    }
}

/// Every command line of the README and of `docs/` runs a command `tmm` has, with flags and
/// values it takes.
#[test]
fn every_command_line_written_uses_flags_the_command_has() {
    let listed = commands();
    let mut helps = BTreeMap::new();
    let mut seen = 0;
    for (file, text) in pages() {
        for line in command_lines(&file, &text) {
            assert!(
                listed.contains(&line.command),
                "{}: `tmm {}` is no command of {listed:?}",
                line.file,
                line.command
            );
            let help = helps
                .entry(line.command.clone())
                .or_insert_with(|| help_flags(&line.command));
            for (flag, values) in written_flags(&line) {
                let Some(known) = help.get(&flag) else {
                    panic!("{}: `tmm {}` has no flag {flag}", line.file, line.command);
                };
                if !known.is_empty() {
                    assert!(
                        values.is_subset(known),
                        "{}: `tmm {} {flag}` takes {known:?}, not {values:?}",
                        line.file,
                        line.command
                    );
                }
            }
            seen += 1;
        }
    }
    assert!(seen >= 12, "{seen} command lines");
}

/// The README is a page: at most 150 lines, the seed-000 project's command and the test
/// command in it, and every relative link (a picture, a page of `docs/`) leads to a file.
#[test]
fn the_readme_is_a_page_whose_links_lead_somewhere() {
    let pages = pages();
    let readme = &pages[0].1;
    let lines = readme.lines().count();
    assert!(lines <= 150, "README.md: {lines} lines");
    assert!(readme.contains("cargo run --release -- render constructions/shaper.toml"));
    assert!(readme.contains("cargo test --release"));
    for (file, text) in &pages {
        let dir = root().join(file);
        let dir = dir.parent().unwrap_or(Path::new("."));
        for target in text.split("](").skip(1).filter_map(|t| t.split(')').next()) {
            let target = target.split('#').next().unwrap_or_default();
            if target.is_empty() || target.contains("://") {
                continue;
            }
            assert!(
                dir.join(target).exists(),
                "{file}: the link {target} leads nowhere"
            );
        }
    }
}

/// A `[kinematics]` section with no `[plates]` table (so no kinematics sheet) is read, and
/// `tmm check` warns of it on standard error, naming the file and the key.
#[test]
fn a_kinematics_section_no_sheet_draws_is_warned_of() {
    let dir = scratch("docs-kinematics-warning");
    let text = std::fs::read_to_string(root().join("constructions/four-bar.toml")).unwrap();
    let text = text.replacen(
        "[plates]\nwanted = [\"positions\", \"kinematics\"]\n",
        "",
        1,
    ) + "\n[kinematics]\nscale_v = 0.01\n";
    let scene = dir.join("undrawn.toml");
    std::fs::write(&scene, text).unwrap();
    let o = tmm(&["check", scene.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    let want = format!(
        "warning: {}: kinematics: no sheet draws it",
        scene.display()
    );
    assert!(err.contains(&want), "{err}");
    let o = tmm(&["check", "constructions/four-bar.toml"]);
    assert!(o.status.success() && o.stderr.is_empty());
}

/// The number before `unit` in `text` (`8 pages` → 8 for `pages`), after `after`.
fn count_before(text: &str, after: &str, unit: &str) -> usize {
    let rest = &text[text
        .find(after)
        .unwrap_or_else(|| panic!("README: no «{after}»"))..];
    let head = &rest[..rest
        .find(unit)
        .unwrap_or_else(|| panic!("README: no «{unit}»"))];
    let digits: String = head
        .trim_end()
        .chars()
        .rev()
        .take_while(char::is_ascii_digit)
        .collect();
    digits
        .chars()
        .rev()
        .collect::<String>()
        .parse()
        .expect("a count")
}

/// What the README says the seed-000 command writes, against what it writes: the sheets of
/// its table and what each holds, the drawing set's and the note's pages, the scenes shipped,
/// and the second sheet's θ, H and K as its caption quotes them.
#[test]
fn the_readme_says_what_the_program_writes() {
    let readme = std::fs::read_to_string(root().join("README.md")).expect("README.md");
    let out = scratch("readme");
    let dir = out.to_str().expect("a path");
    let o = tmm(&[
        "render",
        "constructions/shaper.toml",
        "--format",
        "svg,pdf,note",
        "--out",
        dir,
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let shaper = out.join("shaper");
    // The table's sheets: every `name.svg` on a row of `out/shaper/`, and nothing else.
    let named: BTreeSet<String> = readme
        .lines()
        .filter(|l| l.starts_with("| `out/shaper/"))
        .flat_map(|l| l.split('`').skip(1).step_by(2))
        .filter_map(|w| w.rsplit('/').next()?.strip_suffix(".svg"))
        .map(String::from)
        .collect();
    let written: BTreeSet<String> = std::fs::read_dir(&shaper)
        .expect("the scene's folder")
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter_map(|f| f.strip_suffix(".svg").map(String::from))
        .collect();
    assert_eq!(named, written, "README's sheets against those written");
    the_readme_says_what_each_sheet_holds(&readme, &shaper, named.len());
    let set = count_before(&readme, "the drawing set,", "pages");
    assert_eq!(
        set,
        pdf_pages(&std::fs::read(shaper.join("shaper.pdf")).expect("the set")),
        "the drawing set's pages"
    );
    let note = count_before(&readme, "the explanatory note, A4,", "pages");
    assert_eq!(
        note,
        pdf_pages(&std::fs::read(shaper.join("shaper-note.pdf")).expect("the note")),
        "the note's pages"
    );
    let scenes = std::fs::read_dir(root().join("constructions"))
        .expect("constructions/")
        .filter_map(Result::ok)
        .filter(|e| e.path().extension().is_some_and(|x| x == "toml"))
        .count();
    assert_eq!(
        count_before(&readme, "`constructions/` holds", "scenes"),
        scenes
    );
    // The caption's quotation of the second sheet: «(θ = 38°, H = 462,3 мм, K = 1,535)».
    let quoted = readme
        .split("(θ = ")
        .nth(1)
        .and_then(|r| r.split(')').next())
        .map(|q| format!("θ = {}", q.split_whitespace().collect::<Vec<_>>().join(" ")))
        .expect("README quotes θ, H and K");
    let sheet = std::fs::read_to_string(shaper.join("kinematics-2.svg")).expect("sheet 2");
    let texts = svg_texts(&sheet).join(" ");
    let texts = texts.split_whitespace().collect::<Vec<_>>().join(" ");
    for value in quoted.split(", ") {
        let v = value.split(" = ").nth(1).expect("a value");
        assert!(
            texts.contains(&format!("= {v}")),
            "README quotes «{value}»; sheet 2 reads otherwise"
        );
    }
}

/// The one or two items `text` lists after `after`: after «positions », «positions 3 and
/// 10 (…» gives «3», «10»; after «sheet », «sheet 5: …» gives «5».
fn listed_after<'r>(text: &'r str, after: &str) -> Vec<&'r str> {
    let Some((_, rest)) = text.split_once(after) else {
        return Vec::new();
    };
    let words: Vec<&str> = rest.split_whitespace().take(3).collect();
    match words.as_slice() {
        [a, "and", b, ..] => vec![a, b.trim_end_matches([',', ')', ':'])],
        [a, ..] => vec![a.trim_end_matches([',', ')', ':'])],
        [] => Vec::new(),
    }
}

/// What the README's table and its picture's caption say each seed-000 sheet holds, against
/// the sheets written to `shaper`: each file's sheet number is its title block's
/// designation; the force sheets' positions, the flywheel's scale and the rack's shift are
/// on their sheets; the first sheet has a velocity plan for each position the caption counts
/// and the acceleration plans at the positions it names.
fn the_readme_says_what_each_sheet_holds(readme: &str, shaper: &Path, sheets: usize) {
    let texts = |file: &str| {
        let svg = std::fs::read_to_string(shaper.join(file)).expect("a sheet written");
        svg_texts(&svg)
    };
    let joined = |file: &str| {
        texts(file)
            .join(" ")
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ")
    };
    let rows = readme
        .lines()
        .filter(|l| l.starts_with("| `out/shaper/") && l.contains(".svg"));
    let mut checked = 0;
    for row in rows {
        let cells: Vec<&str> = row.split('|').map(str::trim).collect();
        let files: Vec<&str> = cells[1]
            .split('`')
            .skip(1)
            .step_by(2)
            .filter_map(|w| w.rsplit('/').next())
            .collect();
        let what = cells[2];
        let numbers = if what.starts_with("sheets ") {
            listed_after(what, "sheets ")
        } else {
            listed_after(what, "sheet ")
        };
        assert_eq!(numbers.len(), files.len(), "README: «{row}»");
        for (file, n) in files.iter().zip(&numbers) {
            let n: u32 = n.parse().expect("a sheet number");
            let designation = format!("ТММ.КП.000.{n:02}");
            assert!(
                joined(file).contains(&designation),
                "{file}: README says sheet {n}"
            );
            checked += 1;
        }
        let positions = listed_after(what, "positions ");
        if !positions.is_empty() {
            assert_eq!(positions.len(), files.len(), "README: «{row}»");
            for (file, p) in files.iter().zip(&positions) {
                assert!(
                    joined(file).contains(&format!("оложение {p},")),
                    "{file}: README says position {p}"
                );
            }
        }
        if let Some((_, scale)) = what.split_once(" at 1:") {
            let scale = format!("1:{}", scale.split([' ', ',', ')']).next().unwrap_or(""));
            assert!(
                joined(files[0]).contains(&scale),
                "{}: README says {scale}",
                files[0]
            );
        }
        // The rack's shifts: «x = 0: undercut; x = 0,8».
        for x in what.split("x = ").skip(1) {
            let x = x.split([':', ';', ')']).next().unwrap_or("");
            assert!(
                joined(files[0]).contains(&format!("x = {x}, ")),
                "{}: README says x = {x}",
                files[0]
            );
        }
    }
    assert_eq!(checked, sheets, "every sheet of the table is numbered");
    // The caption: «a velocity plan for each of the 13 positions, the acceleration plans at
    // positions 3 and 10».
    let flat = readme.split_whitespace().collect::<Vec<_>>().join(" ");
    let first = texts("kinematics.svg");
    let count = count_before(&flat, "a velocity plan for each of the", "positions");
    let captions = first
        .iter()
        // «Пол. 8′» or the first plan's «Пол. 1, μ_v = …»; «Пол. 3: …» is the rotation note.
        .filter_map(|t| t.strip_prefix("Пол. ")?.split_whitespace().next())
        .filter(|label| !label.ends_with(':'))
        .count();
    assert_eq!(
        count, captions,
        "README counts the first sheet's velocity plans"
    );
    let at = listed_after(&flat, "the acceleration plans at positions ");
    assert_eq!(
        at.len(),
        2,
        "README names the acceleration plans' positions"
    );
    let first = first.join(" ");
    for p in at {
        assert!(
            first.contains(&format!("План ускорений, пол. {p},")),
            "README says an acceleration plan at position {p}"
        );
    }
}
