//! Tables on a sheet (the textbook's tables of results): a thin grid, a header row and the
//! cells, each text fitted into its cell.

use super::path::{Map, PathData};
use super::style::{Mark, Paint, Pen};
use super::text::{Align, Placed};
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
    let lines = std::iter::once(header.iter().map(String::as_str).collect::<Vec<_>>()).chain(
        t.rows
            .iter()
            .map(|r| r.iter().map(String::as_str).collect()),
    );
    for (k, cells) in lines.enumerate() {
        let mut x = t.at.x;
        let cy = t.at.y + rh * (k as f64 + 0.5);
        for ((_, w), cell) in t.columns.iter().zip(cells) {
            if !cell.is_empty() {
                let p =
                    Placed::centred(DVec2::new(x + w * 0.5, cy), cell, t.size_mm, Align::Middle)
                        .fit(w - 1.0);
                marks.push(Mark::Text(p));
            }
            x += w;
        }
    }
    marks
}
