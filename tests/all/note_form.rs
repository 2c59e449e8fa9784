//! Issue 44 §2: the ГОСТ 2.105 form of every note, read off its typeset text (page by page,
//! `tmm::note::PAGE_BREAK` between): formulas numbered within their section in sequence,
//! «Рисунок N —» and «Таблица N —» captions numbered through the note, never «Рис.», no
//! number in exponent form, a table that runs onto the next page continued under
//! «Продолжение таблицы N», and each section opening a page (ГОСТ 7.32).

use crate::support;
use tmm::{Drafting, Lang, Session};

/// The typeset text of the note of the scene at `path` in `lang`, page by page, each page's
/// runs of white space made single spaces; and the titles of its sections.
fn pages(path: &std::path::Path, lang: Lang) -> (Vec<String>, Vec<String>) {
    let scene = tmm::load(path).expect("scene");
    let session = Session::new(&scene, Drafting::EXACT);
    let note = tmm::note::compose(&session, lang).expect("note");
    let text = tmm::note::to_text(&note).expect("typeset");
    let pages = text
        .split(tmm::note::PAGE_BREAK)
        .map(|p| p.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect();
    (pages, section_titles(&note.source))
}

/// Whether `text` holds a sentence: three words of four letters or more running (a title
/// block's captions and a drawing's labels are short, or stand apart); the eight words after
/// the word `caption` (a figure's caption, lower case), when given, are not counted.
fn has_sentence(text: &str, caption: Option<&str>) -> bool {
    let mut run = 0;
    for word in text.split(' ') {
        if caption.is_some_and(|c| word.to_lowercase() == c) {
            // A caption: its words are the figure's.
            run = -8;
        } else if word.chars().count() >= 4 && word.chars().all(char::is_alphabetic) {
            run += 1;
            if run >= 3 {
                return true;
            }
        } else {
            run = run.min(0);
        }
    }
    false
}

/// ГОСТ 7.32 (and ГОСТ 2.105's advice): each section, and each structural element after
/// them, opens a page: nothing of the text stands above its heading on its page, no formula,
/// no caption, no sentence, only the page's frame. The pages of the note, after its title
/// page and contents; `titles` its sections' in order, the numbered first.
fn sections_open_pages(name: &str, pages: &[String], titles: &[String]) {
    let mut from = 2;
    for (k, title) in titles.iter().enumerate() {
        // A numbered section's heading is its number and title; a structural element's, its
        // title in capitals.
        let heads = [format!("{} {title}", k + 1), title.to_uppercase()];
        let found = pages.iter().enumerate().skip(from).find_map(|(n, page)| {
            heads
                .iter()
                .filter_map(|h| page.find(h.as_str()))
                .min()
                .map(|at| (n, at))
        });
        let Some((n, at)) = found else {
            panic!("{name}: section «{title}» not found after page {from}");
        };
        let above = &pages[n][..at];
        assert!(
            formula_numbers(above).is_empty() && !has_sentence(above, None),
            "{name}: «{title}» does not open page {}: «{above}» above it",
            n + 1
        );
        // The next section may open no earlier (a broken note: on this page, below).
        from = n;
    }
}

/// Every `(S.K)` of `text` in order, as (S, K).
fn formula_numbers(text: &str) -> Vec<(u32, u32)> {
    let mut out = Vec::new();
    for (i, _) in text.match_indices('(') {
        let rest = &text[i + 1..];
        let Some(end) = rest.find(')') else { continue };
        if let Some((s, k)) = rest[..end].split_once('.') {
            if let (Ok(s), Ok(k)) = (s.parse(), k.parse()) {
                out.push((s, k));
            }
        }
    }
    out
}

/// The numbers N of every `<word> N —` of `text`, in order.
fn captions(text: &str, word: &str) -> Vec<u32> {
    text.match_indices(&format!("{word} "))
        .filter_map(|(i, m)| {
            let rest = &text[i + m.len()..];
            let (n, after) = rest.split_once(' ')?;
            after.starts_with('—').then(|| n.parse().ok()).flatten()
        })
        .collect()
}

/// The numbers N of every `<word> N` of `text` (a continued table), in order.
fn continued(text: &str, word: &str) -> Vec<u32> {
    text.match_indices(&format!("{word} "))
        .filter_map(|(i, m)| {
            let digits: String = text[i + m.len()..]
                .chars()
                .take_while(char::is_ascii_digit)
                .collect();
            digits.parse().ok()
        })
        .collect()
}

/// The titles of a note's headings of the first level, in order: its sections (`= #"…"` in
/// the source) and the structural elements after them (`#heading(numbering: none, …)`: the
/// references).
fn section_titles(source: &str) -> Vec<String> {
    source
        .lines()
        .filter_map(|l| {
            l.strip_prefix("= #\"")
                .or_else(|| l.strip_prefix("#heading(numbering: none, [#\""))
        })
        .filter_map(|l| l.split('"').next())
        .map(str::to_string)
        .collect()
}

/// The form of one note; its continued tables.
fn check(name: &str, pages: &[String], lang: Lang) -> usize {
    let (figure, table, cont) = match lang {
        Lang::Uk => ("Рисунок", "Таблиця", "Продовження таблиці"),
        _ => ("Рисунок", "Таблица", "Продолжение таблицы"),
    };
    let whole = pages.join(" ");
    // Formulas: (S.1), (S.2), … within each section, the sections in order.
    let numbers = formula_numbers(&whole);
    let mut last = (0, 0);
    for &(s, k) in &numbers {
        let next = if s == last.0 { (s, last.1 + 1) } else { (s, 1) };
        assert!(
            s >= last.0 && (s, k) == next,
            "{name}: formula ({s}.{k}) after ({}.{})",
            last.0,
            last.1
        );
        last = (s, k);
    }
    // Captions numbered through the note, the textbook's words.
    for word in [figure, table] {
        let n = captions(&whole, word);
        assert_eq!(
            n,
            (1..=n.len() as u32).collect::<Vec<_>>(),
            "{name}: {word}"
        );
    }
    assert!(!whole.contains("Рис. "), "{name}: «Рис.»");
    // «где» under a formula: every explanation («где W — …») follows a formula's number.
    let word = match lang {
        Lang::Uk => " де ",
        _ => " где ",
    };
    for (at, _) in whole.match_indices(word) {
        let after: String = whole[at + word.len()..].chars().take(40).collect();
        if !after.contains('—') {
            continue;
        }
        let before: String = whole[..at]
            .chars()
            .rev()
            .take(500)
            .collect::<Vec<_>>()
            .into_iter()
            .rev()
            .collect();
        assert!(
            !formula_numbers(&before).is_empty(),
            "{name}: «{}{after}» under no formula",
            word.trim()
        );
    }
    // No number in the `1,44e−8` form: a power of ten.
    let chars: Vec<char> = whole.chars().collect();
    for w in chars.windows(4) {
        assert!(
            !(w[0].is_ascii_digit() && w[1] == 'e' && "−-".contains(w[2]) && w[3].is_ascii_digit()),
            "{name}: an exponent form «{}»",
            w.iter().collect::<String>()
        );
    }
    // A formula keeps its «где» on its page: no page opens with an explanation.
    for (k, page) in pages.iter().enumerate() {
        let first_explanation = page.match_indices(word).find(|(at, _)| {
            let after: String = page[at + word.len()..].chars().take(40).collect();
            after.contains('—')
        });
        if let Some((at, _)) = first_explanation {
            assert!(
                !formula_numbers(&page[..at]).is_empty(),
                "{name}: page {} opens with «{}» away from its formula",
                k + 1,
                word.trim()
            );
        }
    }
    // Each continuation names the table running on from the page before, which is the last
    // table captioned so far; a page beginning under the running table says so.
    let mut running = 0;
    let mut count = 0;
    for (k, page) in pages.iter().enumerate() {
        for n in continued(page, cont) {
            assert_eq!(n, running, "{name}: page {}: {cont} {n}", k + 1);
            count += 1;
        }
        running = captions(page, table).last().copied().unwrap_or(running);
    }
    count
}

#[test]
fn every_note_keeps_the_form_of_gost_2_105() {
    let mut continued_tables = 0;
    for path in support::scene_paths() {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let (pages, titles) = pages(&path, Lang::Ru);
        continued_tables += check(&name, &pages, Lang::Ru);
        sections_open_pages(&name, &pages, &titles);
    }
    let shaper = support::root().join("constructions/shaper.toml");
    let (pages, titles) = pages(&shaper, Lang::Uk);
    let uk = check("shaper (uk)", &pages, Lang::Uk);
    sections_open_pages("shaper (uk)", &pages, &titles);
    // The shaper's long tables (the data, the plans' tables, the errors) run on.
    assert!(
        uk >= 5,
        "{uk} continued tables in the Ukrainian shaper note"
    );
    assert!(continued_tables >= 10, "{continued_tables}");
}

/// ГОСТ 2.105: under a formula that brings in a symbol, «где» and its meaning. Every
/// displayed formula of every note, in every language, has its left side explained, under
/// it or under an earlier one.
#[test]
fn every_formula_of_every_note_is_explained() {
    let mut missing = Vec::new();
    for path in support::scene_paths() {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let scene = tmm::load(&path).expect("scene");
        let session = Session::new(&scene, Drafting::EXACT);
        for lang in [Lang::Ru, Lang::Uk, Lang::En] {
            let note = tmm::note::compose(&session, lang).expect("note");
            missing.extend(
                note.unexplained
                    .iter()
                    .map(|m| format!("{name} {lang:?}: {m}")),
            );
        }
    }
    assert!(
        missing.is_empty(),
        "{} unexplained:\n{}",
        missing.len(),
        missing.join("\n")
    );
}

/// Issue 44 §2: no page of a note more than a quarter empty but the title page, the
/// contents and a page a section's end leaves: the next page opens a section, or only the
/// section's last figures stand between (the template places any still floating there).
#[test]
fn no_page_of_the_shapers_note_is_a_quarter_empty_inside_a_section() {
    let path = support::root().join("constructions/shaper.toml");
    for lang in [Lang::Ru, Lang::Uk, Lang::En] {
        let scene = tmm::load(&path).expect("scene");
        let session = Session::new(&scene, Drafting::HAND);
        let note = tmm::note::compose(&session, lang).expect("note");
        let fills = tmm::note::page_fills(&note).expect("typeset");
        let text = tmm::note::to_text(&note).expect("typeset");
        let pages: Vec<String> = text
            .split(tmm::note::PAGE_BREAK)
            .map(|p| p.split_whitespace().collect::<Vec<_>>().join(" "))
            .collect();
        let titles = section_titles(&note.source);
        // Where on a page a section opens: the byte offset of the first title on it.
        let opens = |page: &str| {
            let page = page.to_lowercase();
            titles
                .iter()
                .filter_map(|t| page.find(&t.to_lowercase().chars().take(24).collect::<String>()))
                .min()
        };
        // A page of figures alone: no sentence on it but their captions' (three words of
        // four letters running; a drawing's labels are short).
        let figure = match lang {
            Lang::En => "Figure ",
            _ => "Рисунок ",
        };
        let caption = figure.trim().to_lowercase();
        let figures_only = |page: &str| !has_sentence(page, Some(&caption));
        // A section's end: up to the next section's title, its last figures alone.
        let ends_section = |k: usize| {
            for page in &pages[k + 1..] {
                let lower = page.to_lowercase();
                match opens(page) {
                    Some(at) => return figures_only(&lower[..at]),
                    None if !figures_only(page) => return false,
                    None => {}
                }
            }
            true
        };
        let mut sparse = Vec::new();
        for (k, fill) in fills.iter().enumerate().skip(2) {
            if *fill < 0.75 && !ends_section(k) {
                sparse.push(format!("page {} {:.0} %", k + 1, fill * 100.0));
            }
        }
        assert!(sparse.is_empty(), "{lang:?}: {}", sparse.join(", "));
    }
}
