//! The body of the `note` target (`fuzz_targets/note.rs`): a user's text — a `[task]` string
//! (the title, the author, …) — through the note's markup (`tmm::note::user_text`). The
//! property: no panic, and the markup is one Typst string whose value is the text (Typst's
//! own parser, every input) and which typesets to the text (one input in
//! [`TYPESET_ONE_IN`]); one input in [`NOTE_ONE_IN`] is also every `[task]` string of a whole
//! note, composed and typeset.

use std::path::Path;
use std::sync::OnceLock;
use tmm::{note, Drafting, Lang, Scene, Session};
use typst::syntax::{ast, SyntaxKind, SyntaxNode};

/// Texts longer than this are skipped: a title is a line or two (the scene's own limits are
/// the `scene` target's).
pub const MAX_INPUT: usize = 2048;

/// One input in this many is typeset alone (a few milliseconds each).
pub const TYPESET_ONE_IN: u32 = 16;

/// One input in this many is the `[task]` of a whole note (about a second each).
pub const NOTE_ONE_IN: u32 = 4096;

/// The scene whose note carries the fuzzed `[task]` (the smallest shipped note).
fn scene() -> &'static Scene {
    static SCENE: OnceLock<Scene> = OnceLock::new();
    SCENE.get_or_init(|| {
        let text = include_str!("../../constructions/gears-pz1.toml");
        tmm::scene::parse(text, Path::new("gears-pz1.toml"))
            .unwrap_or_else(|e| panic!("the shipped gears-pz1: {e}"))
    })
}

/// A stable choice among inputs (by their bytes).
fn choice(data: &[u8]) -> u32 {
    data.iter().fold(0x9e37_79b9_u32, |h, &b| {
        (h ^ u32::from(b)).wrapping_mul(0x0100_0193)
    })
}

/// The values of the string literals of `node`, in order.
fn strings(node: &SyntaxNode, out: &mut Vec<String>) {
    if node.kind() == SyntaxKind::Str {
        if let Some(s) = node.cast::<ast::Str>() {
            out.push(s.get().to_string());
        }
    }
    for child in node.children() {
        strings(child, out);
    }
}

/// What a reader finds of `text`: which letters, digits and ASCII punctuation it shows,
/// sorted (a typeset line is laid out in runs, and the runs of mixed directions in visual
/// order), each once: a letter whose mark the note's font lacks is laid out in two runs, the
/// letter in that font and the mark in a fallback, and each run carries the whole cluster's
/// text (`fuzz/regressions/note/mark-in-a-fallback-font`).
fn shown(text: &str) -> Vec<char> {
    let mut v: Vec<char> = text
        .chars()
        .filter(|c| c.is_alphanumeric() || c.is_ascii_punctuation())
        .collect();
    v.sort_unstable();
    v.dedup();
    v
}

/// Check the user text `data` through the note's markup; typeset it, or a whole note, for
/// the inputs [`choice`] picks.
pub fn run(data: &[u8]) {
    let pick = choice(data);
    check(data, pick % TYPESET_ONE_IN == 0, pick % NOTE_ONE_IN == 0);
}

/// Check the user text `data` through the note's markup; typeset it alone with `typeset`, in
/// a whole note with `whole`.
pub fn check(data: &[u8], typeset: bool, whole: bool) {
    if data.len() > MAX_INPUT {
        return;
    }
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let lang = [Lang::Ru, Lang::Uk, Lang::En][data.len() % 3];
    let content = note::user_text(text, lang);
    let root = typst::syntax::parse(&format!("#{content}"));
    assert!(
        !root.diagnosis().errors,
        "{content}: not valid Typst markup"
    );
    let mut values = Vec::new();
    strings(&root, &mut values);
    assert_eq!(values, [text], "{content}: not one string of the text");
    if typeset {
        let typeset = note::typeset_content(&content)
            .unwrap_or_else(|e| panic!("{content}: refused by the typesetter: {e}"));
        assert_eq!(
            shown(&typeset),
            shown(text),
            "{content}: typeset as {typeset:?}"
        );
    }
    if whole {
        whole_note(text, lang);
    }
}

/// The note of the shipped scene with every `[task]` string replaced by a piece of `text`
/// (cut at line feeds): composed and typeset without a refusal.
fn whole_note(text: &str, lang: Lang) {
    let mut scene = scene().clone();
    let mut pieces = text.split('\n').map(str::to_string);
    let mut next = || pieces.next().unwrap_or_default();
    let t = &mut scene.title;
    for field in [
        &mut t.title,
        &mut t.designation,
        &mut t.author,
        &mut t.checked,
        &mut t.organisation,
        &mut t.group,
        &mut t.year,
    ] {
        *field = next();
    }
    let session = Session::new(&scene, Drafting::EXACT);
    let composed = note::compose(&session, lang)
        .unwrap_or_else(|e| panic!("{text:?}: the note is not composed: {e}"));
    if let Err(e) = note::to_pdf(&composed) {
        panic!("{text:?}: the note is not typeset: {e}");
    }
}
