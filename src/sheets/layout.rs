//! What a sheet holds — views, stacks of views, text and tables — sized from what they really
//! draw and laid out on as many sheets of a format as they need ([`super::pack`]).

use super::label_room;
use super::pack::{caption_drops, pack, sheet_overflow};
use super::BuildError;
use crate::check::Row;
use crate::construct::fit::{raised, LABEL_MARGIN};
use crate::construct::Figure;
use crate::geom::DVec2;
use crate::plate::{
    text, Plate, Rect, Sheet, SheetSize, TableBlock, TextBlock, TitleBlock, View, CAPTION_BAND_MM,
    CAPTION_HEIGHT_MM,
};
use crate::scale::{format_fixed, Key, Lang, Scale};
use crate::words::{symbols, Text, Word};

/// The scale a block is drawn at and the scene key that sets it, for the message when the
/// block does not fit a sheet.
#[derive(Debug, Clone, PartialEq)]
pub struct ScaleKey {
    /// The scene key ([`Key::KinematicsScaleV`]).
    pub key: Key,
    /// The scale.
    pub scale: Scale,
}

/// A view's scale and its key, for [`Block::view`].
pub(super) fn keyed(key: Key, scale: Scale) -> Option<ScaleKey> {
    Some(ScaleKey { key, scale })
}

/// One view of a [`Block::Views`]: its figure, where its origin lies in the first figure's
/// coordinates (mm, y up), and its caption, written under it in a band of
/// [`CAPTION_BAND_MM`].
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Part {
    /// The figure.
    pub figure: Figure,
    /// Offset of its origin in the first figure's coordinates, mm.
    pub at: DVec2,
    /// Its caption.
    pub caption: Option<String>,
    /// How far under the figure's bounds the caption's band starts, mm
    /// ([`View::caption_drop`]).
    pub caption_drop: f64,
    /// The box its long joint labels take beside their points, in its coordinates (mm, y up):
    /// kept free for them ([`Block::with_label_room`]).
    pub label_room: Option<(DVec2, DVec2)>,
}

impl Part {
    /// A view at `at` with `caption` under it, clear of what the figure's symbols draw below
    /// its points (the ground of a fixed pivot, an arrowhead), not over it.
    pub fn new(figure: Figure, at: DVec2, caption: Option<String>) -> Self {
        Part {
            caption_drop: View::symbols_below(&figure),
            figure,
            at,
            caption,
            label_room: None,
        }
    }
}

/// One thing on a sheet.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Block {
    /// Figures drawn together (a view, or a stack such as S, dS/dφ, d²S/dφ² whose parts lie at
    /// offsets in the first one's coordinates), each with its caption under it, if any.
    Views {
        /// The views.
        parts: Vec<Part>,
        /// What sets its size.
        scale: Option<ScaleKey>,
    },
    /// Lines of text.
    Text {
        /// Lines in label markup.
        lines: Vec<String>,
        /// Text height, mm.
        size_mm: f64,
    },
    /// A table (its `at` is set by the layout).
    Table(TableBlock),
}

impl Block {
    /// One figure with a caption.
    pub fn view(figure: Figure, caption: String, scale: Option<ScaleKey>) -> Self {
        Block::Views {
            parts: vec![Part::new(figure, DVec2::ZERO, Some(caption))],
            scale,
        }
    }

    /// The block with each part changed by `f`.
    fn map_parts(self, f: impl Fn(Part) -> Part) -> Self {
        match self {
            Block::Views { parts, scale } => Block::Views {
                parts: parts.into_iter().map(f).collect(),
                scale,
            },
            other => other,
        }
    }

    /// The block with room beside each long joint label's point for the label (the pole of a
    /// plan where every point coincides: `p ≡ b₃ ≡ d ≡ s₃ ≡ d₅ ≡ e ≡ s₅`), so that it is not
    /// written over the next block.
    pub fn with_label_room(self) -> Self {
        self.map_parts(|p| {
            let (figure, label_room) = label_room::with_long_joint_labels(p.figure);
            Part {
                figure,
                label_room,
                ..p
            }
        })
    }

    /// The block with room for every label written outward beside a point at its figure's
    /// edge (the numbers of a chart's axis), so that it is not written over the next block's
    /// texts.
    pub fn with_edge_label_room(self) -> Self {
        self.with_edge_label_room_of(|_| true)
    }

    /// [`Self::with_edge_label_room`] for the labels whose text `keep` takes alone (the
    /// poles of a diagram, left of its ordinate axis).
    pub fn with_edge_label_room_of(self, keep: impl Fn(&str) -> bool) -> Self {
        self.map_parts(|p| Part {
            label_room: label_room::edge_labels(&p.figure, &keep),
            ..p
        })
    }

    /// The block with every subscript of its labels, caption, lines and cells in `lang`
    /// ([`symbols::localise`]): the domains label their drawings in the Russian textbooks'
    /// markup.
    fn localised(self, lang: Lang) -> Self {
        if lang == Lang::Ru {
            return self;
        }
        let l = |s: &str| symbols::localise(s, lang);
        match self {
            Block::Views { parts, scale } => Block::Views {
                parts: parts
                    .into_iter()
                    .map(|mut part| {
                        let steps = part.figure.steps.iter_mut();
                        for label in steps.filter_map(|s| s.label.as_mut()) {
                            label.text = l(&label.text);
                        }
                        part.caption = part.caption.as_deref().map(l);
                        part
                    })
                    .collect(),
                scale,
            },
            Block::Text { lines, size_mm } => Block::Text {
                lines: lines.iter().map(|x| l(x)).collect(),
                size_mm,
            },
            Block::Table(t) => Block::Table(TableBlock {
                title: l(&t.title),
                columns: t.columns.iter().map(|(c, w)| (l(c), *w)).collect(),
                rows: t
                    .rows
                    .iter()
                    .map(|r| r.iter().map(|x| l(x)).collect())
                    .collect(),
                ..t
            }),
        }
    }

    /// Bounds of the figures with their caption bands, in the first one's coordinates (y up).
    fn bounds(parts: &[Part]) -> (DVec2, DVec2) {
        parts
            .iter()
            .filter_map(|p| {
                let band = if p.caption.is_some() {
                    CAPTION_BAND_MM + p.caption_drop
                } else {
                    0.0
                };
                p.figure.bounds().map(|(lo, hi)| {
                    let (lo, hi) = p
                        .label_room
                        .map_or((lo, hi), |(a, b)| (lo.min(a), hi.max(b)));
                    (lo + p.at - DVec2::new(0.0, band), hi + p.at)
                })
            })
            .fold(
                (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
                |(lo, hi), (a, b)| (lo.min(a), hi.max(b)),
            )
    }

    /// The abscissae the parts' drawings and captions span, in the first one's coordinates:
    /// a caption is written centred under its figure and may be wider than the drawing.
    fn span(parts: &[Part]) -> (f64, f64) {
        let (lo, hi) = Self::bounds(parts);
        parts
            .iter()
            .filter_map(|p| {
                let (a, b) = p.figure.bounds()?;
                let w = text::approx_width(p.caption.as_deref()?, CAPTION_HEIGHT_MM);
                let c = (a.x + b.x) * 0.5 + p.at.x;
                Some((c - w * 0.5, c + w * 0.5))
            })
            .fold((lo.x, hi.x), |(l, h), (a, b)| (l.min(a), h.max(b)))
    }

    /// The size the block takes on the sheet, mm: its drawing with room for labels and the
    /// caption bands.
    pub(super) fn size(&self) -> DVec2 {
        match self {
            Block::Views { parts, .. } => {
                let (lo, hi) = Self::bounds(parts);
                let drawn = if lo.x <= hi.x { hi - lo } else { DVec2::ZERO };
                // A caption wider than its drawing widens the block.
                let (left, right) = Self::span(parts);
                let captioned = if left <= right { right - left } else { 0.0 };
                DVec2::new(
                    (drawn.x + LABEL_MARGIN).max(captioned),
                    drawn.y + LABEL_MARGIN,
                )
            }
            Block::Text { lines, size_mm } => {
                let w = lines
                    .iter()
                    .map(|l| text::approx_width(l, *size_mm))
                    .fold(0.0, f64::max);
                DVec2::new(w, 2.0 * size_mm * lines.len() as f64)
            }
            // A title wider than its grid widens the block.
            Block::Table(t) => DVec2::new(
                t.size().x.max(text::approx_width(&t.title, t.size_mm)),
                t.size().y + title_height(t),
            ),
        }
    }
}

/// A table titled `title` with the columns (heading, width in mm) and `rows`, its text
/// `size_mm` high, in `lang` (its `at` is set by the layout).
pub(super) fn table<W: Word>(
    title: W,
    columns: &[(W, f64)],
    rows: Vec<Vec<String>>,
    size_mm: f64,
    lang: Lang,
) -> TableBlock {
    TableBlock {
        at: DVec2::ZERO,
        title: title.get(lang).into(),
        columns: columns
            .iter()
            .map(|&(c, w)| (c.get(lang).into(), w))
            .collect(),
        rows,
        size_mm,
    }
}

/// A column of a graphical-against-analytic table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Column {
    /// The quantity in the textbook's notation, with its position when it has one.
    Quantity,
    /// The method the graphical value was found by.
    Method,
    /// The unit.
    Unit,
    /// The graphical value.
    Graphical,
    /// The analytic value, headed "analytic".
    Analytic,
    /// The analytic value, headed "exact".
    Exact,
    /// The relative error, %.
    Error,
}

/// How a graphical-against-analytic table writes its rows.
pub(super) struct Results<'a> {
    /// The title.
    pub title: String,
    /// The columns with their widths, mm.
    pub columns: &'a [(Column, f64)],
    /// A row's quantity (usually [`quantity`]).
    pub name: &'a dyn Fn(&Row) -> String,
    /// A row's unit in the sheet's language.
    pub unit: &'a dyn Fn(&Row) -> String,
    /// A value of a row, given the row's zero reference ([`crate::check::scales`]).
    pub value: &'a dyn Fn(&Row, f64, f64) -> String,
    /// A row's graphical value, when written otherwise than [`Self::value`] writes it (to
    /// the step it was read to); `None` from it for a row [`Self::value`] writes.
    pub graphical: &'a dyn Fn(&Row) -> Option<String>,
    /// Text height, mm.
    pub size_mm: f64,
}

/// A row's quantity in the textbook's notation in `lang`, its position in brackets: a
/// point of a drawing with its index subscripted as the drawing names it, λ_{1} (B_{1}).
pub(super) fn quantity(r: &Row, lang: Lang) -> String {
    let name = symbols::quantity(r.key.symbol, &r.key.subject, lang);
    match r.position() {
        Some(p) => format!("{name} ({})", symbols::indexed(&p)),
        None => name,
    }
}

/// A value of a results table's row to the precision a drawing table gives: four
/// significant digits of the row's larger value (`factor` its unit from SI), the same
/// decimals for its graphical and its analytic value — a reading no finer than the `step`
/// (SI) it was read to, when given: `9,0` of a tooth read to 0,5 mm, not `9,003`.
pub(super) fn drawn_value(r: &Row, x: f64, factor: f64, step: Option<f64>, lang: Lang) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let reference = r.graphical.abs().max(r.analytic.abs()) * factor;
    let mut decimals = if reference > 0.0 && reference.is_finite() {
        (3 - reference.log10().floor() as i32).clamp(0, 6) as usize
    } else {
        0
    };
    if let Some(d) = super::digits::step_decimals(step.map(|s| s * factor)) {
        decimals = decimals.min(d);
    }
    format_fixed(x * factor, decimals, lang)
}

/// The table "graphical | analytic | error" of `rows`, the columns as `results` asks.
pub(super) fn results_table(results: &Results<'_>, rows: &[Row], lang: Lang) -> TableBlock {
    let errors = crate::check::rel_errors(rows);
    let scales = crate::check::scales(rows);
    let body = rows
        .iter()
        .zip(errors.into_iter().zip(scales))
        .map(|(r, (e, s))| {
            let graphical =
                (results.graphical)(r).unwrap_or_else(|| (results.value)(r, r.graphical, s));
            let analytic = (results.value)(r, r.analytic, s);
            let error = super::digits::printed_error(&graphical, &analytic, e, lang).map_or_else(
                || super::digits::NO_VALUE.into(),
                |e| super::digits::error_pct(e, lang),
            );
            results
                .columns
                .iter()
                .map(|(c, _)| match c {
                    Column::Quantity => (results.name)(r),
                    Column::Method => r.method.name(lang).to_string(),
                    // A dimensionless quantity's unit cell holds the dash (ГОСТ 2.105).
                    Column::Unit => Some((results.unit)(r))
                        .filter(|u| !u.is_empty())
                        .unwrap_or_else(|| super::digits::NO_VALUE.into()),
                    Column::Graphical => graphical.clone(),
                    Column::Analytic | Column::Exact => analytic.clone(),
                    Column::Error => error.clone(),
                })
                .collect()
        })
        .collect();
    let heading = |c: Column| match c {
        Column::Quantity => Text::Quantity.get(lang),
        Column::Method => Text::Method.get(lang),
        Column::Unit => Text::Unit.get(lang),
        Column::Graphical => Text::Graphical.get(lang),
        Column::Analytic => Text::Analytic.get(lang),
        Column::Exact => Text::Exact.get(lang),
        Column::Error => Text::RelativeError.get(lang),
    };
    TableBlock {
        at: DVec2::ZERO,
        title: results.title.clone(),
        columns: results
            .columns
            .iter()
            .map(|&(c, w)| (heading(c).to_string(), w))
            .collect(),
        rows: body,
        size_mm: results.size_mm,
    }
}

/// A table too tall for an empty sheet cut into parts that each fit, the rows in order; the
/// parts after the first titled "… (continued)". A table that fits, or whose width alone does
/// not, is returned whole.
pub(super) fn split_table(sheet: &Sheet, t: TableBlock, lang: Lang) -> Vec<TableBlock> {
    let size = t.size() + DVec2::new(0.0, title_height(&t));
    if sheet_overflow(sheet, size) <= 1.0 {
        return vec![t];
    }
    // The tallest room the table's width fits.
    let height = super::pack::rooms(sheet)
        .iter()
        .filter(|r| r.x >= size.x)
        .map(|r| r.y)
        .fold(0.0f64, f64::max);
    // Rows under the heading row and the title.
    let fit = ((height - title_height(&t)) / t.row_height()).floor() - 1.0;
    if fit.is_nan() || fit < 1.0 {
        return vec![t];
    }
    let per = fit as usize;
    let continued = format!("{} {}", t.title, Text::Continued.get(lang));
    t.rows
        .chunks(per)
        .enumerate()
        .map(|(i, rows)| TableBlock {
            title: if i == 0 {
                t.title.clone()
            } else {
                continued.clone()
            },
            rows: rows.to_vec(),
            ..t.clone()
        })
        .collect()
}

/// Room above a table's grid for its title, mm.
fn title_height(t: &TableBlock) -> f64 {
    if t.title.is_empty() {
        0.0
    } else {
        t.size_mm * 1.6
    }
}

/// The parts of a sheet, filled in place by [`lay_out`].
#[derive(Default)]
struct Parts {
    views: Vec<View>,
    texts: Vec<TextBlock>,
    tables: Vec<TableBlock>,
}

/// Put `block` into `rect`; a one-view block's caption `drop` lower, its rectangle as much
/// longer ([`caption_drops`]).
fn put(block: Block, rect: Rect, drop: f64, parts: &mut Parts) {
    match block {
        Block::Views {
            parts: mut figures, ..
        } => {
            let rect = match figures.as_mut_slice() {
                [one] if drop > 0.0 => {
                    one.caption_drop += drop;
                    Rect::new(rect.min, rect.max + DVec2::new(0.0, drop))
                }
                _ => rect,
            };
            // The whole group's bounds, caption bands included, go to the rectangle's centre.
            let (lo, hi) = Block::bounds(&figures);
            let (left, right) = Block::span(&figures);
            let c = rect.center();
            let mid = DVec2::new((left + right) * 0.5, (lo.y + hi.y) * 0.5);
            let origin = DVec2::new(c.x - mid.x, c.y + mid.y);
            for p in figures {
                parts.views.push(View {
                    figure: p.figure,
                    origin: origin + DVec2::new(p.at.x, -p.at.y),
                    caption: p.caption,
                    caption_drop: p.caption_drop,
                });
            }
        }
        Block::Text { lines, size_mm } => parts.texts.push(TextBlock {
            at: rect.min,
            lines,
            size_mm,
        }),
        Block::Table(mut t) => {
            t.at = rect.min + DVec2::new(0.0, title_height(&t));
            parts.tables.push(t);
        }
    }
}

/// Lay `blocks` out on the smallest landscape sheet of `sizes` (smallest first) that holds
/// them on one page; on the last size, over as many pages as they need.
pub(super) fn lay_out_smallest(
    sizes: &[SheetSize],
    blocks: Vec<Block>,
    name: &str,
    title: &TitleBlock,
    lang: Lang,
) -> Result<Vec<Plate>, BuildError> {
    let mut last = Ok(Vec::new());
    for &size in sizes {
        let sheet = Sheet {
            size,
            landscape: true,
        };
        match lay_out(sheet, blocks.clone(), name, title, lang) {
            Ok(plates) if plates.len() == 1 => return Ok(plates),
            other => last = other,
        }
    }
    last
}

/// Lay `blocks` out in order on sheets of format `sheet`, as many as they need; the plates are
/// named `name`, `name-2`, …, each with the title block `title` (numbered later, across the
/// scene). A block larger than an empty sheet is an error naming the scene key of its scale
/// and the largest round scale at which it would fit.
pub(super) fn lay_out(
    sheet: Sheet,
    blocks: Vec<Block>,
    name: &str,
    title: &TitleBlock,
    lang: Lang,
) -> Result<Vec<Plate>, BuildError> {
    lay_out_in_rows(sheet, blocks, &[], name, title, lang)
}

/// [`lay_out`], the block `k` of the series `series[k]` (if any) placed in that series' rows
/// ([`super::pack`]): the plans read 1 … 12 left to right, row under row, the captions of a
/// row nearly level set level ([`caption_drops`]).
pub(super) fn lay_out_in_rows(
    sheet: Sheet,
    blocks: Vec<Block>,
    series: &[Option<u8>],
    name: &str,
    title: &TitleBlock,
    lang: Lang,
) -> Result<Vec<Plate>, BuildError> {
    let blocks: Vec<Block> = blocks
        .into_iter()
        .map(|b| match b.localised(lang) {
            Block::Table(t) => Block::Table(t.with_room()),
            b => b,
        })
        .collect();
    let sizes: Vec<DVec2> = blocks.iter().map(Block::size).collect();
    let placed = pack(&sheet, &sizes, series).map_err(|k| too_large(&sheet, &blocks, &sizes, k))?;
    let count = placed.iter().map(|p| p.0 + 1).max().unwrap_or(1);
    let mut pages: Vec<Parts> = (0..count).map(|_| Parts::default()).collect();
    let drops = caption_drops(&sheet, &placed, series);
    for ((block, (page, rect)), drop) in blocks.into_iter().zip(placed).zip(drops) {
        put(block, rect, drop, &mut pages[page]);
    }
    Ok(pages
        .into_iter()
        .enumerate()
        .map(|(k, p)| Plate {
            name: sheet_name(name, k),
            sheet,
            title_block: title.clone(),
            lang,
            views: p.views,
            texts: p.texts,
            tables: p.tables,
        })
        .collect())
}

/// The name of the sheet `k` (0-based) of the plate `stem`: `stem`, `stem-2`, `stem-3`, …
pub(super) fn sheet_name(stem: &str, k: usize) -> String {
    if k == 0 {
        stem.to_string()
    } else {
        format!("{stem}-{}", k + 1)
    }
}

/// The error for the block `k` that does not fit an empty sheet. The scale it names fits
/// every block drawn at the same scale key (the force polygons of all groups share μ_F): the
/// one that overflows most decides it.
fn too_large(sheet: &Sheet, blocks: &[Block], sizes: &[DVec2], k: usize) -> BuildError {
    let scale_of = |b: &Block| match b {
        Block::Views { scale, .. } => scale.clone(),
        Block::Text { .. } | Block::Table(_) => None,
    };
    let what = match &blocks[k] {
        Block::Views { parts, .. } => parts
            .first()
            .map_or_else(String::new, |p| p.figure.title.clone()),
        Block::Text { .. } => "text".into(),
        Block::Table(t) => t.title.clone(),
    };
    let fits = scale_of(&blocks[k]).and_then(|s| {
        let over = blocks
            .iter()
            .zip(sizes)
            .filter(|(b, _)| scale_of(b).is_some_and(|o| o.key == s.key))
            .map(|(_, &size)| sheet_overflow(sheet, size))
            .fold(1.0, f64::max);
        raised(s.scale, over).map(|f| (s, f))
    });
    BuildError::TooLarge {
        what,
        need: sizes[k],
        fits,
    }
}
