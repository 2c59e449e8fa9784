//! Sheets (ГОСТ 2.301), the frame and the main title block (ГОСТ 2.104, form 1).

use super::path::{Map, PathData};
use super::style::{Mark, Paint, Pen};
use super::text::{Align, Placed};
use super::Rect;
use crate::geom::DVec2;
use crate::scale::Lang;

/// A ГОСТ 2.301 sheet format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum SheetSize {
    /// 210 × 297 mm.
    A4,
    /// 297 × 420 mm.
    A3,
    /// 420 × 594 mm.
    A2,
    /// 594 × 841 mm (the course's plates).
    #[default]
    A1,
    /// 841 × 1189 mm.
    A0,
}

impl SheetSize {
    /// (short side, long side), mm.
    pub fn sides_mm(self) -> (f64, f64) {
        match self {
            SheetSize::A4 => (210.0, 297.0),
            SheetSize::A3 => (297.0, 420.0),
            SheetSize::A2 => (420.0, 594.0),
            SheetSize::A1 => (594.0, 841.0),
            SheetSize::A0 => (841.0, 1189.0),
        }
    }
    /// Parse `A4` … `A0` (either case).
    pub fn parse(s: &str) -> Option<Self> {
        match s.to_ascii_uppercase().as_str() {
            "A4" => Some(SheetSize::A4),
            "A3" => Some(SheetSize::A3),
            "A2" => Some(SheetSize::A2),
            "A1" => Some(SheetSize::A1),
            "A0" => Some(SheetSize::A0),
            _ => None,
        }
    }
}

/// Left margin of the frame (filing edge), mm.
pub const FRAME_LEFT_MM: f64 = 20.0;
/// Margin of the frame on the other three sides, mm.
pub const FRAME_MM: f64 = 5.0;
/// Size of the main title block, mm.
pub const TITLE_BLOCK_MM: (f64, f64) = (185.0, 55.0);
/// Size of the rotated designation box in the top-left corner, mm.
pub const DESIGNATION_BOX_MM: (f64, f64) = (70.0, 14.0);
/// Gap a laid-out sheet keeps between two items, mm.
pub const ITEM_GAP_MM: f64 = 5.0;
/// Margin a laid-out sheet keeps from its frame, mm.
pub const FIELD_MARGIN_MM: f64 = 3.0;

/// A sheet: format and orientation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Sheet {
    /// The format.
    pub size: SheetSize,
    /// Long side horizontal.
    pub landscape: bool,
}

impl Default for Sheet {
    /// A1 landscape, the course's plate.
    fn default() -> Self {
        Sheet {
            size: SheetSize::A1,
            landscape: true,
        }
    }
}

impl Sheet {
    /// (width, height), mm.
    pub fn size_mm(&self) -> (f64, f64) {
        let (short, long) = self.size.sides_mm();
        if self.landscape {
            (long, short)
        } else {
            (short, long)
        }
    }
    /// Width, mm.
    pub fn width_mm(&self) -> f64 {
        self.size_mm().0
    }
    /// Height, mm.
    pub fn height_mm(&self) -> f64 {
        self.size_mm().1
    }
    /// The frame: 20 mm from the left edge, 5 mm from the others.
    pub fn frame(&self) -> Rect {
        Rect::new(
            DVec2::new(FRAME_LEFT_MM, FRAME_MM),
            DVec2::new(self.width_mm() - FRAME_MM, self.height_mm() - FRAME_MM),
        )
    }
    /// The main title block, in the bottom-right corner inside the frame.
    pub fn title_block(&self) -> Rect {
        let f = self.frame();
        Rect::new(
            f.max - DVec2::new(TITLE_BLOCK_MM.0, TITLE_BLOCK_MM.1),
            f.max,
        )
    }
    /// The rotated designation box in the top-left corner of the frame.
    pub fn designation_box(&self) -> Rect {
        let f = self.frame();
        Rect::new(
            f.min,
            f.min + DVec2::new(DESIGNATION_BOX_MM.0, DESIGNATION_BOX_MM.1),
        )
    }
    /// The drawing field: inside the frame, below the designation box and above the title
    /// block, full frame width.
    pub fn field(&self) -> Rect {
        let f = self.frame();
        Rect::new(
            DVec2::new(f.min.x, self.designation_box().max.y),
            DVec2::new(f.max.x, self.title_block().min.y),
        )
    }
    /// The rest of the field: left of the title block, down to the frame (empty on A4
    /// portrait, where the title block is as wide as the frame).
    pub fn field_beside_title_block(&self) -> Rect {
        let (f, t) = (self.frame(), self.title_block());
        Rect::new(DVec2::new(f.min.x, t.min.y), DVec2::new(t.min.x, f.max.y))
    }
}

/// The filled main title block (ГОСТ 2.104, form 1). Texts are label markup.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct TitleBlock {
    /// Title of the work (the mechanism): the big centre cell.
    pub title: String,
    /// Title of this sheet, under `title`.
    pub sheet_title: String,
    /// Document designation (top cell and the rotated box).
    pub designation: String,
    /// Drawn by.
    pub author: String,
    /// Checked by.
    pub checked: String,
    /// Organisation (university, group).
    pub organisation: String,
    /// Scale, as written in the «Масштаб» cell.
    pub scale: String,
    /// Number of this sheet.
    pub sheet_no: u32,
    /// Number of sheets.
    pub sheets: u32,
    /// The part's mass in kg as written in the «Масса» cell (a part drawing's; empty on a
    /// scheme).
    pub mass: String,
    /// The part's material designation, the cell under the title (ГОСТ 2.104 graph 3; empty
    /// on a scheme).
    pub material: String,
}

/// Captions of the title block cells in one language (the explanatory note's frames write
/// them too).
pub(crate) struct Captions {
    /// Изм., Лист, № докум., Подп., Дата.
    pub(crate) changes: [&'static str; 5],
    /// Разраб., Пров., Т.контр., (blank), Н.контр., Утв.
    pub(crate) people: [&'static str; 6],
    /// Лит.
    pub(crate) letter: &'static str,
    /// Масса.
    pub(crate) mass: &'static str,
    /// Масштаб.
    pub(crate) scale: &'static str,
    /// Лист.
    pub(crate) sheet: &'static str,
    /// Листов (en: "of", as "Sheet 1 of 2").
    pub(crate) sheets: &'static str,
}

/// The title block's captions in `lang`.
pub(crate) fn captions(lang: Lang) -> Captions {
    use crate::words::TitleBlockText as T;
    let p = |t: T| t.get(lang);
    Captions {
        changes: [p(T::Rev), p(T::Sheet), p(T::DocNo), p(T::Sign), p(T::Date)],
        people: [
            p(T::Drawn),
            p(T::Checked),
            p(T::TechCheck),
            "",
            p(T::StdCheck),
            p(T::Approved),
        ],
        letter: p(T::Letter),
        mass: p(T::Mass),
        scale: p(T::Scale),
        sheet: p(T::Sheet),
        sheets: p(T::Sheets),
    }
}

/// Column edges of the change and signature part, mm from the block's left edge.
const COLUMNS: [f64; 6] = [0.0, 7.0, 17.0, 40.0, 55.0, 65.0];
/// Row pitch of the left part, mm.
const ROW: f64 = 5.0;
/// Left edge of the right part (Лит., Масса, Масштаб, Лист, organisation), mm.
const RIGHT: f64 = 135.0;
/// ГОСТ 2.304 size of the cell captions, mm.
const CAPTION_H: f64 = 2.5;

/// The trim border, the frame and the designation box.
pub(crate) fn frame_marks(sheet: &Sheet, tb: &TitleBlock) -> Vec<Mark> {
    let trim = Rect::new(DVec2::ZERO, DVec2::new(sheet.width_mm(), sheet.height_mm()));
    let boxed = sheet.designation_box();
    let mut out: Vec<Mark> = [
        (Pen::THIN, trim),
        (Pen::MAIN, sheet.frame()),
        (Pen::MAIN, boxed),
    ]
    .into_iter()
    .filter_map(|(pen, r)| {
        let mut d = PathData::new(Map::SHEET);
        d.rect(r.min, r.max);
        Mark::path(Paint::Stroke(pen), d)
    })
    .collect();
    // Rotated half a turn about the box centre: the capitals hang from the baseline.
    let mut text = fitted(
        boxed.center(),
        &tb.designation,
        5.0,
        boxed.width() - 4.0,
        Align::Middle,
    );
    text.at.y -= text.height;
    text.rotate = 180.0;
    out.push(Mark::Text(text));
    out
}

/// The title block: its grid and its texts.
pub(crate) fn title_block_marks(sheet: &Sheet, tb: &TitleBlock, lang: Lang) -> Vec<Mark> {
    let map = Map::sheet_at(sheet.title_block().min);
    let mut out = Vec::new();
    out.extend(grid(map, Pen::MAIN, &main_lines()));
    out.extend(grid(map, Pen::THIN, &thin_lines()));
    let c = captions(lang);
    let mut texts = Vec::new();
    captions_into(&c, &mut texts);
    filling_into(tb, &mut texts);
    texts.extend(sheet_numbers(&c, tb));
    out.extend(texts.into_iter().map(|t| Mark::Text(t.mapped(map))));
    out
}

type Line = ((f64, f64), (f64, f64));

fn grid(map: Map, pen: Pen, lines: &[Line]) -> Option<Mark> {
    let mut d = PathData::new(map);
    for &((x0, y0), (x1, y1)) in lines {
        d.segment(DVec2::new(x0, y0), DVec2::new(x1, y1));
    }
    Mark::path(Paint::Stroke(pen), d)
}

fn main_lines() -> Vec<Line> {
    let (w, h) = TITLE_BLOCK_MM;
    let mut v = vec![
        ((0.0, 0.0), (w, 0.0)),
        ((0.0, h), (w, h)),
        ((0.0, 0.0), (0.0, h)),
        ((w, 0.0), (w, h)),
        ((0.0, 25.0), (65.0, 25.0)),
        ((65.0, 15.0), (w, 15.0)),
        ((RIGHT, 20.0), (w, 20.0)),
        ((RIGHT, 35.0), (w, 35.0)),
        ((65.0, 40.0), (w, 40.0)),
        ((RIGHT, 15.0), (RIGHT, h)),
        ((150.0, 15.0), (150.0, 35.0)),
        ((167.0, 15.0), (167.0, 35.0)),
        ((155.0, 35.0), (155.0, 40.0)),
        ((7.0, 0.0), (7.0, 25.0)),
    ];
    v.extend(COLUMNS[2..].iter().map(|&x| ((x, 0.0), (x, h))));
    v
}

fn thin_lines() -> Vec<Line> {
    let rows = (1..11)
        .filter(|&k| k != 5)
        .map(|k| ((0.0, k as f64 * ROW), (65.0, k as f64 * ROW)));
    let letters = [140.0, 145.0].map(|x| ((x, 20.0), (x, 35.0)));
    rows.chain(letters).collect()
}

/// A cell of the block: (x0, y0, x1, y1) in block mm.
type Cell = (f64, f64, f64, f64);

/// Where a text stands in a cell (its capitals' centre, vertically centred) and the width
/// it may take.
fn cell_anchor((x0, y0, x1, y1): Cell, align: Align) -> (DVec2, f64) {
    let x = match align {
        Align::Start => x0 + 1.0,
        Align::Middle => (x0 + x1) * 0.5,
        Align::End => x1 - 1.0,
    };
    (DVec2::new(x, (y0 + y1) * 0.5), x1 - x0 - 3.0)
}

/// Text in a cell, vertically centred, shrunk when it would not fit the cell's width.
fn in_cell(cell: Cell, text: &str, height: f64, align: Align) -> Placed {
    let (at, width) = cell_anchor(cell, align);
    fitted(at, text, height, width, align)
}

/// A long text in a cell: on one line while fitting it keeps at least `min_height`, else
/// wrapped at the space nearest its middle into two lines (ГОСТ 2.104 fills a title so,
/// rather than shrinking it out of legibility).
fn wrapped_in_cell(
    (x0, y0, x1, y1): (f64, f64, f64, f64),
    text: &str,
    height: f64,
    min_height: f64,
    align: Align,
    out: &mut Vec<Placed>,
) {
    let width = x1 - x0 - 2.0 * TITLE_SIDE_MM;
    let one_line = super::text::fitting_width(text, height);
    let split = text
        .char_indices()
        .filter(|&(i, c)| c == ' ' && !hangs(&text[..i]))
        .map(|(i, _)| i)
        .min_by_key(|&i| (i as i64 - text.len() as i64 / 2).abs());
    match split {
        Some(i) if one_line > 0.0 && width / one_line * height < min_height => {
            let (a, b) = (text[..i].trim(), text[i..].trim());
            let h = (y1 - y0) / 4.0;
            // Two lines of capitals under a third of the cell each.
            let line_h = height.min((y1 - y0) / 3.2);
            // Both lines narrowed alike, as the longer needs: one size, one condensing.
            let natural = |line: &str| super::text::fitting_width(line, line_h);
            let ratio = (width / natural(a).max(natural(b))).min(1.0);
            for (line, (top, bottom)) in [(a, (y0, y0 + 2.0 * h)), (b, (y0 + 2.0 * h, y1))] {
                let (at, _) = cell_anchor((x0, top, x1, bottom), align);
                let placed = Placed::centred(at, line, line_h, align);
                out.push(if ratio < 1.0 {
                    placed.narrowed(ratio)
                } else {
                    placed
                });
            }
        }
        _ => {
            let (at, _) = cell_anchor((x0, y0, x1, y1), align);
            out.push(fitted(at, text, height, width, align));
        }
    }
}

/// True when the last word of `line` may not end a line: an article or a word of one or two
/// letters (a preposition, a conjunction: «в», «и», «of», «a»), which goes with the word after
/// it, as typesetting has it.
fn hangs(line: &str) -> bool {
    let last = line.rsplit(' ').next().unwrap_or(line);
    last.chars().count() <= 2 || last.eq_ignore_ascii_case("the")
}

/// A long text of the title block (its title, a part's material) keeps this far from each
/// side of its cell, mm: its ends, and the accents over its capitals (й, Й), clear of the
/// borders.
const TITLE_SIDE_MM: f64 = 2.5;

/// The smallest height a title block's title is shrunk to before it is wrapped, mm (ГОСТ
/// 2.304 size 3.5).
const TITLE_MIN_MM: f64 = 3.5;

/// A text with its capitals centred on `at`, at most `width` wide.
fn fitted(at: DVec2, text: &str, height: f64, width: f64, align: Align) -> Placed {
    Placed::centred(at, text, height, align).fit(width)
}

fn captions_into(c: &Captions, out: &mut Vec<Placed>) {
    for (k, name) in c.changes.iter().enumerate() {
        out.push(in_cell(
            (COLUMNS[k], 20.0, COLUMNS[k + 1], 25.0),
            name,
            CAPTION_H,
            Align::Middle,
        ));
    }
    for (k, name) in c.people.iter().enumerate().filter(|(_, n)| !n.is_empty()) {
        let y = 25.0 + k as f64 * ROW;
        out.push(in_cell(
            (0.0, y, 17.0, y + ROW),
            name,
            CAPTION_H,
            Align::Start,
        ));
    }
    let heads = [
        (RIGHT, 150.0, c.letter),
        (150.0, 167.0, c.mass),
        (167.0, 185.0, c.scale),
    ];
    for (x0, x1, name) in heads {
        out.push(in_cell(
            (x0, 15.0, x1, 20.0),
            name,
            CAPTION_H,
            Align::Middle,
        ));
    }
}

fn filling_into(tb: &TitleBlock, out: &mut Vec<Placed>) {
    out.push(in_cell(
        (17.0, 25.0, 40.0, 30.0),
        &tb.author,
        CAPTION_H,
        Align::Start,
    ));
    out.push(in_cell(
        (17.0, 30.0, 40.0, 35.0),
        &tb.checked,
        CAPTION_H,
        Align::Start,
    ));
    out.push(in_cell(
        (65.0, 0.0, 185.0, 15.0),
        &tb.designation,
        7.0,
        Align::Middle,
    ));
    if tb.sheet_title.is_empty() {
        let cell = (65.0, 15.0, RIGHT, 40.0);
        wrapped_in_cell(cell, &tb.title, 5.0, TITLE_MIN_MM, Align::Middle, out);
    } else {
        let cell = (65.0, 15.0, RIGHT, 29.0);
        wrapped_in_cell(cell, &tb.title, 5.0, TITLE_MIN_MM, Align::Middle, out);
        out.push(in_cell(
            (65.0, 28.0, RIGHT, 36.0),
            &tb.sheet_title,
            3.5,
            Align::Middle,
        ));
    }
    out.push(in_cell(
        (167.0, 20.0, 185.0, 35.0),
        &tb.scale,
        3.5,
        Align::Middle,
    ));
    out.push(in_cell(
        (RIGHT, 40.0, 185.0, 55.0),
        &tb.organisation,
        3.5,
        Align::Middle,
    ));
    // A part drawing's mass (kg, ГОСТ 2.104 graph 5) and material (graph 3); a scheme has
    // neither.
    if !tb.mass.is_empty() {
        out.push(in_cell(
            (150.0, 20.0, 167.0, 35.0),
            &tb.mass,
            3.5,
            Align::Middle,
        ));
    }
    if !tb.material.is_empty() {
        let cell = (65.0, 40.0, RIGHT, 55.0);
        wrapped_in_cell(cell, &tb.material, 5.0, TITLE_MIN_MM, Align::Middle, out);
    }
}

/// The «Лист N» and «Листов M» cells (captions and numbers together).
fn sheet_numbers(c: &Captions, tb: &TitleBlock) -> [Placed; 2] {
    [
        in_cell(
            (RIGHT, 35.0, 155.0, 40.0),
            &format!("{} {}", c.sheet, tb.sheet_no),
            CAPTION_H,
            Align::Middle,
        ),
        in_cell(
            (155.0, 35.0, 185.0, 40.0),
            &format!("{} {}", c.sheets, tb.sheets),
            CAPTION_H,
            Align::Middle,
        ),
    ]
}

#[cfg(test)]
mod title_tests {
    use super::*;

    /// A title too long for its cell is wrapped into two legible lines instead of being
    /// shrunk to 1.5 mm; a short one stays on one line at 5 mm.
    #[test]
    fn a_long_title_wraps_instead_of_shrinking() {
        let cell = (65.0, 15.0, RIGHT, 29.0);
        let mut out = Vec::new();
        let long = "Шестизвенный шарнирный механизм (W1, реконструкция)";
        wrapped_in_cell(cell, long, 5.0, TITLE_MIN_MM, Align::Middle, &mut out);
        assert_eq!(out.len(), 2);
        assert!(out.iter().all(|p| p.height >= 3.0), "{out:?}");
        assert!(out[0].at.y < out[1].at.y);
        let mut short = Vec::new();
        wrapped_in_cell(
            cell,
            "Кулачок",
            5.0,
            TITLE_MIN_MM,
            Align::Middle,
            &mut short,
        );
        assert_eq!(short.len(), 1);
        assert_eq!(short[0].height, 5.0);
    }

    /// A wrapped title's first line never ends with an article or a one- or two-letter word:
    /// «Трение / в кинематических парах», «Kinematics / of a planetary train».
    #[test]
    fn a_wrapped_line_does_not_end_with_a_short_word() {
        let cell = (65.0, 15.0, RIGHT, 29.0);
        for (title, first) in [
            ("Трение в кинематических парах", "Трение"),
            ("Kinematics of a planetary train", "Kinematics"),
            (
                "Кулачковый механизм с роликовым толкателем",
                "Кулачковый механизм",
            ),
        ] {
            let mut out = Vec::new();
            wrapped_in_cell(cell, title, 8.0, 7.0, Align::Middle, &mut out);
            assert_eq!(out.len(), 2, "{title}");
            assert_eq!(out[0].markup, first, "{title}");
        }
    }
}
