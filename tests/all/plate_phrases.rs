//! No two word labels read as one phrase (issue 45): a name of a curve written right over
//! another without a shelf between reads on into it (en PZ1's detail A: «involute» over
//! «limit point», read "involute limit point"). Computed from each sheet's layout, on every
//! sheet of every scene in every configuration of the label rules.

use crate::plate_label_objects::CONFIGURATIONS;
use crate::plate_model::every_sheet_in;
use tmm::construct::Drafting;
use tmm::plate::{layout, Layout, PlacedLabel};
use tmm::scale::Lang;

/// A word stands at most this far under the text above it and reads as its next line, mm
/// (a line of text is about 3,5 mm high).
const LINE_GAP_MM: f64 = 4.0;

/// Whether a label is words (letters, spaces and hyphens, a word of three letters or more),
/// not a symbol, a number or a formula, which a reader does not read on into the next line.
fn words(text: &str) -> bool {
    let only = text
        .chars()
        .all(|c| c.is_alphabetic() || c == ' ' || c == '-');
    let long = text
        .split(|c: char| !c.is_alphabetic())
        .any(|w| w.chars().count() >= 3);
    only && long
}

/// Whether `lower` stands right under `upper`, written without a shelf: its top within
/// [`LINE_GAP_MM`] of `upper`'s bottom, across from it over half the narrower of the two.
fn reads_on(upper: &PlacedLabel, lower: &PlacedLabel) -> bool {
    let (a, b) = (&upper.rect, &lower.rect);
    let across = a.max.x.min(b.max.x) - a.min.x.max(b.min.x);
    let narrower = (a.max.x - a.min.x).min(b.max.x - b.min.x);
    let gap = b.min.y - a.max.y;
    upper.leader.is_none() && across > 0.5 * narrower && (0.0..=LINE_GAP_MM).contains(&gap)
}

/// `view N “upper” over “lower”` for each pair of word labels of `l` read as one phrase.
fn phrases(l: &Layout) -> Vec<String> {
    let word: Vec<&PlacedLabel> = l.labels.iter().filter(|x| words(&x.text)).collect();
    let mut out = Vec::new();
    for a in &word {
        for b in word.iter().filter(|b| b.view == a.view) {
            if reads_on(a, b) {
                out.push(format!(
                    "view {} “{}” over “{}”: read as one phrase",
                    a.view, a.text, b.text
                ));
            }
        }
    }
    out
}

/// No sheet writes two word labels as one phrase, in any configuration; the sheets do
/// write word labels (detail A's curve names, the cams' zones, the gears' notes).
#[test]
fn no_two_word_labels_read_as_one_phrase() {
    let mut found = Vec::new();
    let mut word_labels = 0;
    for (lang, drafting, said) in CONFIGURATIONS {
        for (name, plate) in every_sheet_in(lang, drafting) {
            let l = layout(&plate);
            word_labels += l.labels.iter().filter(|x| words(&x.text)).count();
            found.extend(
                phrases(&l)
                    .into_iter()
                    .map(|w| format!("{said}: {name}: {w}")),
            );
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
    assert!(word_labels >= 20, "{word_labels} word labels");
}

/// The rule fails where it should: en PZ1's «limit point» moved back right under
/// «involute», off its shelf (as the placer wrote it before the rule).
#[test]
fn the_phrase_rule_fails_on_a_plate_built_to_break_it() {
    let (_, plate) = every_sheet_in(Lang::En, Drafting::HAND)
        .into_iter()
        .find(|(n, _)| n == "gears-pz1/gears")
        .expect("gears-pz1/gears");
    let mut l = layout(&plate);
    assert!(phrases(&l).is_empty(), "{:?}", phrases(&l));
    let find = |l: &Layout, t: &str| {
        l.labels
            .iter()
            .position(|x| x.text == t)
            .unwrap_or_else(|| panic!("no label {t}"))
    };
    let (upper, lower) = (find(&l, "involute"), find(&l, "limit point"));
    let above = l.labels[upper].rect;
    let size = l.labels[lower].rect.max - l.labels[lower].rect.min;
    l.labels[lower].leader = None;
    l.labels[lower].rect.max = glam::DVec2::new(above.max.x, above.max.y + 2.8 + size.y);
    l.labels[lower].rect.min = l.labels[lower].rect.max - size;
    let found = phrases(&l).join("\n");
    assert!(
        found.contains("“involute” over “limit point”: read as one phrase"),
        "{found}"
    );
    // On a shelf of its own the upper word is parted from the lower.
    l.labels[upper].leader = l.labels.iter().find_map(|x| x.leader);
    assert!(phrases(&l).is_empty(), "{:?}", phrases(&l));
}
