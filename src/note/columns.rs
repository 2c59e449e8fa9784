//! A note table's column widths, from what its cells hold: the typesetter then lays each
//! column out once at its width instead of measuring every cell of an auto column first (a
//! seventh of seed 000's typesetting, docs/bench.md). Each column is as wide as its
//! widest cell, as an auto column would be. A table that would come near the text width keeps
//! auto columns: there the typesetter's own measure decides which cells break, where an
//! estimate a little wide would break a row head that fits.

use super::markup::Cell;

/// The columns' widths, em of the table's text, when the table takes at most [`ROOM_SHARE`]
/// of the text width; `None` for auto columns.
pub(super) fn widths(header: &[Cell], rows: &[Vec<Cell>], columns: usize) -> Option<Vec<f64>> {
    let natural: Vec<f64> = (0..columns)
        .map(|k| {
            let widest = rows
                .iter()
                .filter_map(|r| r.get(k))
                .chain(header.get(k))
                .map(|c| shown_width(c))
                .fold(NARROWEST_EM, f64::max);
            widest + INSET_EM
        })
        .collect();
    (natural.iter().sum::<f64>() <= ROOM_SHARE * TEXT_WIDTH_EM).then_some(natural)
}

/// The share of the text width up to which a table's widths are estimated: the estimate is
/// a little wide (a tenth of an em a cell, and its letters' widths), never by this much.
const ROOM_SHARE: f64 = 0.85;
/// The note's text width in em of a table's 10 pt text: A4 less the page's margins of 25 and
/// 10 mm (`template.typ`), 175 mm.
const TEXT_WIDTH_EM: f64 = 175.0 / 25.4 * 72.0 / 10.0;
/// A cell's inset on both sides (Typst's 5 pt each), em of 10 pt text, and a tenth of an em
/// for the estimate's error.
const INSET_EM: f64 = 1.1;
/// The narrowest cell, em: a dash or a one-digit number still has a column a reader sees
/// as one.
const NARROWEST_EM: f64 = 1.0;
/// How much of a character a subscript or superscript takes.
const SCRIPT: f64 = 0.7;

/// The width a cell shows, em: that of its strings (`#"…"`, `"…"` in a formula), a script's
/// (`#sub("a1")`, `_(…)`, `^(…)`) smaller, and a formula's symbols outside strings.
fn shown_width(cell: &str) -> f64 {
    runs(cell)
        .iter()
        .map(|(run, scale)| run.chars().map(character_width).sum::<f64>() * scale)
        .sum()
}

/// A character's width in New Computer Modern, em: its figures and a space are set to fixed
/// widths, its letters about half an em (capitals more), a formula's signs with their spaces
/// more still.
fn character_width(c: char) -> f64 {
    match c {
        '0'..='9' => 0.5,
        ',' | '.' | ':' | ';' | '(' | ')' | '\'' | '′' => 0.3,
        ' ' => 0.33,
        '−' | '-' | '+' | '=' | '·' | '×' | '≤' | '≥' | '<' | '>' => 0.8,
        'м' | 'ш' | 'щ' | 'ж' | 'ю' | 'ы' | 'm' | 'w' => 0.8,
        c if c.is_uppercase() => 0.75,
        _ => 0.52,
    }
}

/// The shown runs of a cell's markup with the size each is set at: the text of its string
/// literals (a script's at [`SCRIPT`]) and, in a formula (`$…$`), its letters and signs
/// outside them.
fn runs(cell: &str) -> Vec<(String, f64)> {
    let math = cell.starts_with('$');
    let mut out = Vec::new();
    let mut chars = cell.chars().peekable();
    let mut outside = String::new();
    let mut scripted = false;
    while let Some(c) = chars.next() {
        match c {
            '"' => {
                let mut run = String::new();
                while let Some(d) = chars.next() {
                    match d {
                        '\\' => run.extend(chars.next()),
                        '"' => break,
                        d => run.push(d),
                    }
                }
                out.push((run, if scripted { SCRIPT } else { 1.0 }));
                scripted = false;
            }
            // A script: `#sub(` / `#super(` in text, `_` / `^` in a formula.
            '_' | '^' if math => scripted = true,
            '#' => {
                let name: String =
                    std::iter::from_fn(|| chars.next_if(|d| d.is_alphabetic())).collect();
                scripted |= name == "sub" || name == "super";
            }
            c if math && (c.is_alphanumeric() || "+-=·/<>≤≥".contains(c)) => outside.push(c),
            _ => {}
        }
    }
    if !outside.is_empty() {
        out.push((outside, 1.0));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::{shown_width, widths, INSET_EM as I};

    #[test]
    fn a_cell_is_as_wide_as_what_it_shows() {
        // «план сил»: seven letters and a space.
        assert!((shown_width(r#"[#"план сил"]"#) - (7.0 * 0.52 + 0.33)).abs() < 1e-12);
        // «r» and «, мм» whole, the subscript «a1» smaller.
        let r = shown_width(r##"[#"r"#sub("a1")#", мм"]"##);
        let want = 0.52 + 0.7 * (0.52 + 0.5) + (0.3 + 0.33 + 0.8 + 0.8);
        assert!((r - want).abs() < 1e-12, "{r}");
        assert!((shown_width(r#"[#"25,0"]"#) - 1.8).abs() < 1e-12);
    }

    #[test]
    fn a_column_is_as_wide_as_its_widest_cell_in_a_table_clear_of_the_text_width() {
        let header = vec![r#"[#"Величина"]"#.to_string(), r#"[#"δ, %"]"#.to_string()];
        let rows = vec![
            vec![r#"[#"R"]"#.to_string(), r#"[#"0,27"]"#.to_string()],
            vec![
                r##"[#"M"#sub("ур")]"##.to_string(),
                r#"[#"−12,25"]"#.to_string(),
            ],
        ];
        let w = widths(&header, &rows, 2);
        let want = vec![shown_width(&header[0]) + I, shown_width(&rows[1][1]) + I];
        assert_eq!(w, Some(want));
        // A missing cell is an empty one; a column of dashes keeps its narrowest width.
        let w = widths(&[], &[vec![r#"[#"—"]"#.to_string()]], 2);
        assert_eq!(w, Some(vec![1.0 + I, 1.0 + I]));
        // Fourteen columns of «0,000» and a long row head come near the text width: auto.
        let mut row = vec![r#"[#"Расстояние между неподвижными центрами"]"#.to_string()];
        row.extend((0..13).map(|_| r#"[#"0,000"]"#.to_string()));
        assert_eq!(widths(&[], &[row], 14), None);
    }
}
