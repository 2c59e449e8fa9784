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

/// The cells of `plate`'s tables whose text, at its face's natural width, does not fit its
/// column within the half millimetre each side the renderer keeps: condensed onto its rules
/// (en rotor-dynamic's «kg·mm²», its ² squeezed onto the m; «рычаг Жуковского» against the
/// rules of the force sheets).
fn squeezed_cells(plate: &tmm::plate::Plate) -> Vec<String> {
    let mut out = Vec::new();
    for t in &plate.tables {
        let header = t.columns.iter().map(|c| c.0.clone()).collect();
        for row in std::iter::once(header).chain(t.rows.iter().cloned()) {
            for ((_, w), cell) in t.columns.iter().zip(&row) {
                let natural = tmm::plate::text::measure(cell, t.size_mm).advance;
                if natural > w - 1.0 + 1e-9 {
                    out.push(format!("«{cell}» {natural:.1} mm in a {w:.1} mm column"));
                }
            }
        }
    }
    out
}

/// Issue 45: no table cell is condensed to fit its column, on every sheet of every scene in
/// ru, uk and en (read to 0,5 mm); and a column given back its old width breaks the rule.
#[test]
fn no_table_cell_is_squeezed_into_its_column() {
    use tmm::construct::Drafting;
    use tmm::scale::Lang;
    let mut found = Vec::new();
    for lang in [Lang::Ru, Lang::Uk, Lang::En] {
        for (name, plate) in crate::plate_model::every_sheet_in(lang, Drafting::HAND) {
            found.extend(
                (squeezed_cells(&plate).into_iter()).map(|c| format!("{lang:?} {name}: {c}")),
            );
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
    let mut narrow = sheet("rotor-dynamic/balancing");
    assert!(squeezed_cells(&narrow).is_empty());
    narrow.tables[0].columns[1].1 = 8.0;
    assert!(!squeezed_cells(&narrow).is_empty());
}
