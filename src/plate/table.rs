//! Tables on a sheet (the textbook's tables of results): a thin grid, a header row and the
//! cells, each text fitted into its cell.

use super::path::{Map, PathData};
use super::style::{Mark, Paint, Pen};
use super::text::{measure, Align, Extent, Placed};
use glam::DVec2;

/// Room beside a cell's text in its column, mm: the half millimetre each side the cell's text
/// is fitted within ([`table_marks`]), and as much again.
pub const CELL_ROOM_MM: f64 = 2.0;

/// A table drawn on the sheet.
#[derive(Debug, Clone, PartialEq)]
pub struct TableBlock {
    /// Top-left corner of the grid, sheet mm, y down.
    pub at: DVec2,
    /// A title written above the grid (label markup); empty for none.
    pub title: String,
    /// Column headers (label markup) with their widths, mm.
    pub columns: Vec<(String, f64)>,
    /// Rows of cells (label markup); missing cells stay empty.
    pub rows: Vec<Vec<String>>,
    /// Text height, mm.
    pub size_mm: f64,
}

impl TableBlock {
    /// Height of one row, mm.
    pub fn row_height(&self) -> f64 {
        self.size_mm * 2.0
    }
    /// The table with every column at least as wide as its widest text (heading or cell) at
    /// its natural width, with [`CELL_ROOM_MM`] beside it: a cell is condensed only where a
    /// column was given less room than its texts need (a unit's superscript squeezed onto its
    /// letters, a word against the rules).
    pub fn with_room(mut self) -> Self {
        for (k, (heading, w)) in self.columns.iter_mut().enumerate() {
            let cells = self.rows.iter().filter_map(|r| r.get(k));
            let first = crate::words::heading(heading);
            let widest = std::iter::once(first.as_str())
                .chain(cells.map(String::as_str))
                .map(|c| super::text::approx_width(c, self.size_mm))
                .fold(0.0, f64::max);
            *w = w.max(widest + CELL_ROOM_MM);
        }
        self
    }
    /// Overall size of the grid (width, height), mm.
    pub fn size(&self) -> DVec2 {
        let w: f64 = self.columns.iter().map(|c| c.1).sum();
        DVec2::new(w, self.row_height() * (self.rows.len() + 1) as f64)
    }
}

/// The marks of a table.
pub(crate) fn table_marks(t: &TableBlock) -> Vec<Mark> {
    let size = t.size();
    let rh = t.row_height();
    let mut d = PathData::new(Map::sheet_at(DVec2::ZERO));
    d.rect(t.at, t.at + size);
    for k in 1..=t.rows.len() {
        let y = t.at.y + rh * k as f64;
        d.segment(DVec2::new(t.at.x, y), DVec2::new(t.at.x + size.x, y));
    }
    let mut x = t.at.x;
    for (_, w) in t.columns.iter().take(t.columns.len().saturating_sub(1)) {
        x += w;
        d.segment(DVec2::new(x, t.at.y), DVec2::new(x, t.at.y + size.y));
    }
    let mut marks = vec![Mark::Path(Paint::Stroke(Pen::THIN), d)];
    if !t.title.is_empty() {
        marks.push(Mark::Text(Placed::new(
            t.at - DVec2::new(0.0, t.size_mm * 0.8),
            &t.title,
            t.size_mm,
            Align::Start,
        )));
    }
    let header: Vec<String> = t
        .columns
        .iter()
        .map(|c| crate::words::heading(&c.0))
        .collect();
    // Every cell with its ink's extent, measured once: the body rows' shared lift and each
    // cell's own both read it.
    let lines: Vec<Vec<(&str, Extent)>> = std::iter::once(&header)
        .chain(&t.rows)
        .map(|r| {
            (r.iter())
                .map(|c| (c.as_str(), measure(c, t.size_mm)))
                .collect()
        })
        .collect();
    let common = common_lift(lines[1..].iter().flatten().map(|c| &c.1), t.size_mm);
    for (k, cells) in lines.iter().enumerate() {
        // The heading keeps its own line; the body rows share one lift.
        let shared = if k == 0 { 0.0 } else { common };
        let mut x = t.at.x;
        let cy = t.at.y + rh * (k as f64 + 0.5);
        for ((_, w), &(cell, ref e)) in t.columns.iter().zip(cells) {
            if !cell.is_empty() {
                let at = DVec2::new(x + w * 0.5, cy - lift(e, t.size_mm, shared));
                let p = Placed::centred(at, cell, t.size_mm, Align::Middle).fit(w - 1.0);
                marks.push(Mark::Text(p));
            }
            x += w;
        }
    }
    marks
}

/// Least room between a cell's ink and a rule of its row, in text heights.
const CELL_CLEAR: f64 = 0.2;

/// How far a cell's text is raised from capitals centred in its row (`height` the text size,
/// the row twice as high): `common` (the table's [`common_lift`]) as far as its ink keeps
/// [`CELL_CLEAR`] off the rule above, so that the rows keep one baseline; a text whose
/// subscripts and superscripts cannot both keep it is centred by its ink.
fn lift(e: &Extent, height: f64, common: f64) -> f64 {
    let (need, room) = need_and_room(e, height);
    if need > room {
        0.5 * (e.min.y + e.max.y) + 0.5 * height
    } else {
        common.min(room).max(need)
    }
}

/// The lift a text's ink needs to keep [`CELL_CLEAR`] off the rule below, and the most it
/// takes keeping as much off the rule above (below the baseline of centred capitals there is
/// half a height before the rule, above it 1,5 heights).
fn need_and_room(e: &Extent, height: f64) -> (f64, f64) {
    let clear = CELL_CLEAR * height;
    let need = (e.max.y - (0.5 * height - clear)).max(0.0);
    (need, 1.5 * height - clear + e.min.y)
}

/// The lift the table's cells share: the most any of them needs for its subscripts (M_y,
/// V_D5D3) that its own top allows; cells too tall for their row do not count.
fn common_lift<'a>(cells: impl Iterator<Item = &'a Extent>, height: f64) -> f64 {
    cells
        .map(|e| need_and_room(e, height))
        .filter(|(need, room)| need <= room)
        .fold(0.0, |m, (need, _)| m.max(need))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every cell's ink keeps off its row's rules, a subscript's too (V_D5D3, M_y), and the
    /// body rows keep one baseline in their rows: but a cell too tall for its row (ω_кр, M_y
    /// at 2,5 mm, J_пр^(1)), centred by its ink.
    #[test]
    fn a_cells_subscripts_keep_off_the_rule_below_on_one_baseline() {
        let cells = [
            "V_{D5D3}",
            "a_S5",
            "ω_{кр}",
            "диаграмма",
            "0,31",
            "M_y",
            "J_{пр}^{(1)}",
        ];
        let t = TableBlock {
            at: DVec2::ZERO,
            title: String::new(),
            columns: vec![("Величина".into(), 40.0)],
            rows: cells.iter().map(|c| vec![c.to_string()]).collect(),
            size_mm: 2.5,
        };
        let texts: Vec<Placed> = (table_marks(&t).into_iter())
            .filter_map(|m| match m {
                Mark::Text(p) => Some(p),
                _ => None,
            })
            .collect();
        let rh = t.row_height();
        let mut offsets = Vec::new();
        for (k, cell) in cells.iter().enumerate() {
            let p = texts.iter().find(|p| p.markup == *cell).unwrap();
            let b = p.bounds();
            let (top, bottom) = (rh * (k + 1) as f64, rh * (k + 2) as f64);
            let gaps = (b.min.y - top, bottom - b.max.y);
            // Clear of both rules, or centred by its ink where it cannot be.
            let clear = gaps.0 >= 0.5 - 1e-9 && gaps.1 >= 0.5 - 1e-9;
            let centred = (gaps.0 - gaps.1).abs() < 1e-9 && gaps.0 > 0.0;
            assert!(clear || centred, "{cell}: {gaps:?}");
            if !centred {
                offsets.push((cell, p.at.y - top));
            }
        }
        // One baseline, raised from centred capitals (1,25 mm under the row's middle).
        let first = offsets[0].1;
        assert!(first < rh * 0.5 + 1.25 - 0.1, "{first}");
        for (cell, y) in &offsets {
            assert!((y - first).abs() < 1e-12, "{cell}: {y} against {first}");
        }
        assert!(offsets.len() >= 4, "{offsets:?}");
    }
}
