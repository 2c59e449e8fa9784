//! The note speaks one language (issue 44 §3): the typeset text of every shipped scene's
//! note in Russian and Ukrainian, read as the reader finds it, holds no English word, no
//! program identifier, no raw markup, no command-line flag and no seed line number. The
//! Latin words a note may show are the note's own list (`tmm::note::latin_allowed`).

use crate::support;
use tmm::{Drafting, Lang, Session};

/// What in `text` a Russian or Ukrainian reader should not find, each with some context.
fn leaks(text: &str) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let context = |from: usize, to: usize| -> String {
        let a = from.saturating_sub(30);
        let b = (to + 30).min(chars.len());
        chars[a..b].iter().collect::<String>().replace('\n', " ")
    };
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_ascii_alphabetic() {
            let start = i;
            while i < chars.len() && chars[i].is_ascii_alphabetic() {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            // A seed's line number: `L839`.
            let digits = chars[i..].iter().take_while(|c| c.is_ascii_digit()).count();
            if word == "L" && digits >= 3 {
                out.push(format!("line number «L…» in «{}»", context(start, i)));
            } else if !tmm::note::latin_allowed(&word) {
                out.push(format!("«{word}» in «{}»", context(start, i)));
            }
            continue;
        }
        if "_^#$\\`".contains(c) {
            out.push(format!("markup «{c}» in «{}»", context(i, i + 1)));
        } else if c == '-' && chars.get(i + 1) == Some(&'-') {
            out.push(format!("flag «--» in «{}»", context(i, i + 2)));
            i += 1;
        }
        i += 1;
    }
    out
}

#[test]
fn the_leak_finder_finds_what_the_issue_names() {
    let found = leaks("P_ ур by the force plans 112 kgf, seed 000 §2 L839 --drafting O_1 εalphabz");
    for what in [
        "markup «_»",
        "«by»",
        "«the»",
        "«kgf»",
        "«seed»",
        "line number",
        "flag «--»",
        "«drafting»",
        "«alphabz»",
    ] {
        assert!(found.iter().any(|f| f.contains(what)), "{what}: {found:?}");
    }
    // The symbols, functions, designations and plan segments a note writes.
    let clean = "V BA = ab μ v ; V S3 = ps 3 ; l AB ; cos α ; inv α w ; S max ; ω = const ; \
                 dS/d φ ; класс II ; отрезок kl ; h*";
    assert_eq!(leaks(clean), Vec::<String>::new());
}

#[test]
fn every_note_in_russian_and_ukrainian_is_written_in_its_language() {
    let mut found = Vec::new();
    let mut notes = 0;
    for path in support::scene_paths() {
        let scene = tmm::load(&path).expect("scene");
        let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("?");
        // As `tmm note` writes it (the hand's drafting by default) and exactly.
        for drafting in [Drafting::HAND, Drafting::EXACT] {
            let session = Session::new(&scene, drafting);
            for lang in [Lang::Ru, Lang::Uk] {
                let note = tmm::note::compose(&session, lang).expect("note");
                let text = tmm::note::to_text(&note).expect("typeset");
                notes += 1;
                let drafted = drafting.resolution_mm();
                for leak in leaks(&text) {
                    found.push(format!("{stem} {lang:?} (drafting {drafted} mm): {leak}"));
                }
            }
        }
    }
    assert!(notes >= 4 * 24, "{notes} notes");
    found.dedup();
    assert!(
        found.is_empty(),
        "{} leaks:\n{}",
        found.len(),
        found.join("\n")
    );
}

/// The shaper's table of the seed's values not reproduced gives each reason in the note's
/// language, its printed value in the note's units (кгс, not kgf).
#[test]
fn the_seeds_errata_are_explained_in_the_notes_language() {
    let path = support::root().join("constructions/shaper.toml");
    let scene = tmm::load(&path).expect("shaper");
    let session = Session::new(&scene, Drafting::EXACT);
    for (lang, words) in [
        (
            Lang::Ru,
            ["вычисленабезмассы", "порычагуЖуковского", "112кгс"],
        ),
        (
            Lang::Uk,
            ["обчисленобезмаси", "заважелемЖуковського", "112кгс"],
        ),
        (Lang::En, ["withoutthemass", "byZhukovsky'slever", "112kgf"]),
    ] {
        let note = tmm::note::compose(&session, lang).expect("note");
        let text: String = tmm::note::to_text(&note)
            .expect("typeset")
            .split_whitespace()
            .collect();
        for w in words {
            assert!(text.contains(w), "{lang:?}: {w}");
        }
    }
}

/// The driving link's balancing force is explained as the balancing force in every language:
/// its symbol in the note's notation (`F_b`, `F_зр`) was once taken for a couple's force on the
/// lever, «… of link  on the lever», with no link. And the program's word for the analytic
/// solution («двойник», twin) is not the note's. Read off the notes' sources (no typesetting).
#[test]
fn the_balancing_force_is_explained_as_such_in_every_language() {
    for stem in ["shaper", "v-engine"] {
        let path = support::root().join(format!("constructions/{stem}.toml"));
        let scene = tmm::load(&path).expect("scene");
        let session = Session::new(&scene, Drafting::EXACT);
        for (lang, no_link, balancing) in [
            (Lang::Ru, "звена  на рычаге", "уравновешивающая сила"),
            (Lang::Uk, "ланки  на важелі", "зрівноважувальна сила"),
            (Lang::En, "link  on the lever", "the balancing force"),
        ] {
            let source = tmm::note::compose(&session, lang).expect("note").source;
            assert!(!source.contains(no_link), "{stem} {lang:?}: «{no_link}»");
            assert!(source.contains(balancing), "{stem} {lang:?}: «{balancing}»");
            for jargon in ["двойник", "двійник", "twin"] {
                assert!(!source.contains(jargon), "{stem} {lang:?}: «{jargon}»");
            }
        }
    }
}
