//! No word label reads on into another text (issue 45): a name of a curve written right over
//! another without a shelf between (en PZ1's detail A: «involute» over «limit point», read
//! "involute limit point"), or another label right after or before it on its row (PZ3's
//! «интерференция 1» 2 mm before the axis's «0», read «интерференция 10»); nor a chain of a
//! point's names into a symbol beside it (the shaper's «d₅′ ≡ e′ ≡ s₅′» 1,35 mm before «b₃′»,
//! read as one more name of the point). Computed from each sheet's layout, on every sheet of
//! every scene in every configuration of the label rules.

use crate::plate_label_objects::on_every_layout;
use crate::plate_model::every_sheet_in;
use tmm::construct::Drafting;
use tmm::plate::{layout, Layout, PlacedLabel};
use tmm::scale::Lang;

/// A word stands at most this far under the text above it and reads as its next line, mm
/// (a line of text is about 3,5 mm high).
const LINE_GAP_MM: f64 = 4.0;

/// A text stands at most this far after or before a word on its row and reads on from it,
/// mm (a digit's width; a word space is about 1 mm).
const SIDE_GAP_MM: f64 = 2.5;

/// Whether a label is words (letters, digits, spaces and hyphens, a word of three letters or
/// more), not a symbol, a number or a formula, which a reader does not read on.
fn words(text: &str) -> bool {
    let only = text
        .chars()
        .all(|c| c.is_alphanumeric() || c == ' ' || c == '-');
    let long = text
        .split(|c: char| !c.is_alphabetic())
        .any(|w| w.chars().count() >= 3);
    only && long
}

/// Whether a label is a chain of a point's names joined by «≡» (`d_{5}′ ≡ e′ ≡ s_{5}′`),
/// which a symbol beside it on its row reads on from as one more name.
fn chain(text: &str) -> bool {
    text.contains('≡')
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

/// Whether `other` stands on the row of `word` (across from it over half the lower of the
/// two) within [`SIDE_GAP_MM`] after or before it.
fn beside(word: &PlacedLabel, other: &PlacedLabel) -> bool {
    let (a, b) = (&word.rect, &other.rect);
    let row = a.max.y.min(b.max.y) - a.min.y.max(b.min.y);
    let lower = (a.max.y - a.min.y).min(b.max.y - b.min.y);
    let gap = (b.min.x - a.max.x).max(a.min.x - b.max.x);
    row > 0.5 * lower && (0.0..=SIDE_GAP_MM).contains(&gap)
}

/// `view N “upper” over “lower”` for each pair of word labels of `l` read as one phrase, and
/// `view N “word” beside “other”` for each label on the row of a word or a chain of names
/// read on from it.
fn phrases(l: &Layout) -> Vec<String> {
    let mut out = Vec::new();
    for a in l.labels.iter().filter(|x| words(&x.text) || chain(&x.text)) {
        for b in l.labels.iter().filter(|b| !std::ptr::eq(*b, a)) {
            if words(&a.text) && words(&b.text) && b.view == a.view && reads_on(a, b) {
                out.push(format!(
                    "view {} “{}” over “{}”: read as one phrase",
                    a.view, a.text, b.text
                ));
            }
            if beside(a, b) {
                out.push(format!(
                    "view {} “{}” beside “{}”: read on from it",
                    a.view, a.text, b.text
                ));
            }
        }
    }
    out
}

/// Label `i` of `l` moved onto the row of the box `at`, `gap` mm after it.
fn put_after(l: &mut Layout, i: usize, at: tmm::plate::Rect, gap: f64) {
    let size = l.labels[i].rect.max - l.labels[i].rect.min;
    l.labels[i].rect.min = glam::DVec2::new(at.max.x + gap, at.min.y);
    l.labels[i].rect.max = l.labels[i].rect.min + size;
}

/// No sheet writes a word label read on into another, in any configuration; the sheets do
/// write word labels (detail A's curve names, the blocking contour's curves).
#[test]
fn no_two_word_labels_read_as_one_phrase() {
    let (found, word_labels) = on_every_layout(phrases, |x| words(&x.text));
    assert!(found.is_empty(), "{}", found.join("\n"));
    assert!(word_labels >= 20, "{word_labels} word labels");
}

/// The rule fails where it should: en PZ1's «limit point» moved back right under
/// «involute», off its shelf (as the placer wrote it before the rule); «fillet» moved right
/// after «involute» on its row.
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
    // «fillet» moved onto «involute»'s row, 2 mm after it.
    let fillet = find(&l, "fillet");
    put_after(&mut l, fillet, above, 2.0);
    let found = phrases(&l).join("\n");
    assert!(
        found.contains("“involute” beside “fillet”: read on from it"),
        "{found}"
    );
}

/// A chain of a point's names read on into a symbol: the shaper's «b₃′» moved back to 1,35 mm
/// after «d₅′ ≡ e′ ≡ s₅′» on its row, as the placer wrote it before the rule.
#[test]
fn the_chain_rule_fails_on_a_plate_built_to_break_it() {
    let plate = crate::plate_model::sheet("shaper/kinematics");
    let mut l = layout(&plate);
    assert!(phrases(&l).is_empty(), "{:?}", phrases(&l));
    let chain = (l.labels.iter())
        .position(|x| x.view == 16 && x.text.contains('≡'))
        .expect("the chain of view 16");
    let b3 = (l.labels.iter())
        .position(|x| x.view == 16 && x.text == "b_{3}′")
        .expect("b₃′ of view 16");
    let at = l.labels[chain].rect;
    put_after(&mut l, b3, at, 1.35);
    let found = phrases(&l).join("\n");
    assert!(
        found.contains("beside “b_{3}′”: read on from it"),
        "{found}"
    );
}
