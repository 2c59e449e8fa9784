//! Every word on a sheet speaks the sheet's language: every scene of `constructions/` is
//! built in ru, uk and en, and the text of its SVG is read back. A Russian or Ukrainian sheet
//! holds no Latin identifier (a run of two or more Latin letters) beyond the few the textbook
//! itself writes in Latin ([`LATIN_ALLOWED`]); an English sheet holds no Cyrillic letter. The
//! user's own text — the title block's fields from `[task]` — is left out.

use std::path::PathBuf;
use tmm::construct::Drafting;
use tmm::scale::Lang;
use tmm::scene;
use tmm::sheets;
use tmm::study::Session;

use crate::support::svg_texts;

/// The runs of Latin letters the Russian and Ukrainian textbooks write in Latin too.
const LATIN_ALLOWED: &[&str] = &[
    // Extremes as subscripts: r_min, ω_max, γ_min, x_min (the textbooks' own spelling).
    "max", "min", // The follower's displacement in the analogues dS/dφ, d²S/dφ².
    "dS",  // Functions: sin, cos, tg, arctg (the Russian spelling of tan and arctan).
    "sin", "cos", "tg", "arctg",
    // The segment kl that Wittenbauer's tangents cut off the ΔT axis.
    "kl", // A surface's roughness parameter (ГОСТ 2.309: Ra 1,6).
    "Ra",
];

/// A run of capitals is allowed up to this length: points named together (`V_{BA}`,
/// `l_{AB}`) and the Roman numerals of a rotor's correction planes (`z_{II}`).
const CAPITALS: usize = 3;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn is_cyrillic(c: char) -> bool {
    ('\u{0400}'..='\u{04FF}').contains(&c)
}

/// The runs of two or more Latin letters in `text` not in [`LATIN_ALLOWED`].
fn latin_words(text: &str) -> Vec<String> {
    text.split(|c: char| !c.is_ascii_alphabetic())
        .filter(|w| w.len() >= 2 && !LATIN_ALLOWED.contains(w))
        .filter(|w| w.len() > CAPITALS || !w.chars().all(|c| c.is_ascii_uppercase()))
        .map(str::to_string)
        .collect()
}

/// The user's own words on the sheets, in whatever language the scene file wrote them: the
/// title block's fields from `[task]`, the reasons given for redundant pairs and the names of
/// the constant inertias of `[dynamics]` (`J_{ред}`).
fn own_text(s: &scene::Scene) -> Vec<String> {
    let t = &s.title;
    let mut own = vec![
        t.title.clone(),
        t.designation.clone(),
        t.author.clone(),
        t.checked.clone(),
        t.organisation.clone(),
    ];
    if let Some(m) = &s.mechanism {
        own.extend(m.redundant.iter().map(|r| r.reason.clone()));
    }
    if let Some(d) = &s.dynamics {
        own.extend(d.constant.iter().map(|c| c.name.clone()));
    }
    own.retain(|o| !o.is_empty());
    own
}

#[test]
fn sheets_speak_their_language() {
    let mut found = Vec::new();
    let mut scenes = 0;
    let mut paths: Vec<PathBuf> = std::fs::read_dir(root().join("constructions"))
        .expect("constructions/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    for path in paths {
        let s = scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        scenes += 1;
        let own = own_text(&s);
        for lang in [Lang::Ru, Lang::Uk, Lang::En] {
            let session = Session::new(&s, Drafting::EXACT);
            let all = sheets::build_all(&session, lang).unwrap_or_else(|(_, e)| panic!("{e}"));
            for (_, plate) in all {
                for text in svg_texts(&tmm::plate::to_svg(&plate)) {
                    let plain = text.trim();
                    // A line of the user's text wrapped in the title block is a part of it.
                    if plain.is_empty() || own.iter().any(|o| o.contains(plain)) {
                        continue;
                    }
                    let text = own
                        .iter()
                        .fold(text.clone(), |t, o| t.replace(o.as_str(), " "));
                    let bad: Vec<String> = match lang {
                        Lang::En => {
                            if text.chars().any(is_cyrillic) {
                                vec![text.clone()]
                            } else {
                                vec![]
                            }
                        }
                        Lang::Ru | Lang::Uk => latin_words(&text),
                    };
                    if !bad.is_empty() {
                        found.push(format!(
                            "{}/{} [{lang:?}]: {bad:?} in “{plain}”",
                            s.stem, plate.name
                        ));
                    }
                }
            }
        }
    }
    assert!(scenes > 0, "no scenes in constructions/");
    found.sort();
    found.dedup();
    assert!(
        found.is_empty(),
        "{} texts in the wrong language:\n{}",
        found.len(),
        found.join("\n")
    );
}
