//! No text block and no table of a sheet runs into another (issue 45): the layout gives each
//! block the room its lines' widths ask, and a line that runs wider than that room ends over
//! its neighbour — cam-shock's «Принимаем r₀ = 34 мм ≥ r_min = 32 мм: при r₀ = 33 мм …»
//! wrote its last 4 mm over the points table in uk and en while the packer took it for 244 mm
//! (its `=`, `≥` and `>` are wider than the character classes said). Computed from each
//! sheet's layout, the blocks' boxes from their lines as drawn, on every sheet of every scene
//! in every configuration of the label rules.

use crate::plate_label_objects::on_every_layout;
use crate::plate_model::sheet;
use tmm::plate::{layout, Layout, Rect};

/// The text blocks and tables of a layout, named.
fn blocks(l: &Layout) -> Vec<(String, Rect)> {
    let texts = (l.texts.iter().enumerate()).map(|(k, r)| (format!("text block {k}"), *r));
    let tables = (l.tables.iter().enumerate()).map(|(k, r)| (format!("table {k}"), *r));
    texts.chain(tables).collect()
}

/// Every two blocks of the layout whose boxes overlap, described.
fn blocks_overlapping(l: &Layout) -> Vec<String> {
    let all = blocks(l);
    let mut out = Vec::new();
    for (i, (a, ra)) in all.iter().enumerate() {
        for (b, rb) in &all[..i] {
            if ra.intersects(rb) {
                out.push(format!("{a} {ra:?} runs into {b} {rb:?}"));
            }
        }
    }
    out
}

#[test]
fn no_text_block_or_table_runs_into_another() {
    let (found, _) = on_every_layout(blocks_overlapping, |_| false);
    assert!(found.is_empty(), "{}", found.join("\n"));
}

/// The rule fails where it should: the cam sheet's data lines made longer than the room their
/// block was laid out in, and a table moved over the data.
#[test]
fn the_block_rule_fails_on_a_plate_built_to_break_it() {
    let plate = sheet("cam-shock/cam");
    assert!(blocks_overlapping(&layout(&plate)).is_empty());
    let data = plate
        .texts
        .iter()
        .position(|b| b.lines.len() > 3)
        .expect("the data block");
    let mut long = plate.clone();
    for line in &mut long.texts[data].lines {
        line.push_str(&" ≥ =".repeat(80));
    }
    assert!(!blocks_overlapping(&layout(&long)).is_empty());
    let mut moved = plate.clone();
    moved.tables[0].at = plate.texts[data].at;
    assert!(!blocks_overlapping(&layout(&moved)).is_empty());
}
