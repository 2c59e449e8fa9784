//! Plates: recorded figures drawn 1:1 on ГОСТ drawing sheets, written as SVG and PNG.
//!
//! A [`Plate`] is a [`Sheet`] (ГОСТ 2.301 size, frame and title block per ГОСТ 2.104) with
//! [`View`]s — each a recorded [`Figure`] placed at a sheet position — and free [`TextBlock`]s.
//! Figures are drawn at their own μ and never rescaled: one figure millimetre is one sheet
//! millimetre. Line types follow ГОСТ 2.303 (see [`Pen`]), text is DejaVu Sans bundled with
//! the program, so the output is the same on every machine.
//!
//! Sheet coordinates are millimetres from the top-left corner, y **down** (the SVG
//! convention); figure coordinates are millimetres, y **up**.
//!
//! ```
//! use tmm::plate::{to_svg, Plate, Sheet, SheetSize, TitleBlock};
//! use tmm::scale::Lang;
//! let plate = Plate {
//!     name: "empty".into(),
//!     sheet: Sheet { size: SheetSize::A3, landscape: true },
//!     title_block: TitleBlock::default(),
//!     lang: Lang::Ru,
//!     views: Vec::new(),
//!     texts: Vec::new(),
//!     tables: Vec::new(),
//! };
//! let svg = to_svg(&plate);
//! assert!(svg.contains(r#"width="420mm""#));
//! assert_eq!(svg, to_svg(&plate));
//! ```

mod arrow;
pub mod chart;
mod dimension;
mod dxf;
mod fonts;
mod ink;
mod items;
mod labels;
mod metrics;
mod path;
mod pdf;
mod raster;
mod sheet;
mod style;
mod svg;
mod table;
pub mod text;
mod write;

use crate::construct::{Figure, StepId};
use crate::geom::DVec2;
use crate::scale::Lang;
use thiserror::Error;

pub use dxf::{to_dxf, DxfLayer, CURVE_TOLERANCE_MM};
pub(crate) use fonts::faces as bundled_faces;
pub use fonts::font_database;
pub use ink::{view_ink, Cell};
pub use items::{COINCIDENT_MM, LABEL_GAP_MM};
pub use labels::{
    layout, struck_dimension_texts, Layout, Leader, PlacedLabel, ViewLayout, JOINT_SEPARATOR,
};
pub use pdf::{plates_to_pdf, to_pdf, to_pdf_parsed, PdfError};
pub use raster::{
    forget_pngs, png_of, png_size, render_only, to_png, to_png_dpi, to_png_dpi_all, ParsedSvg,
    MAX_PIXELS,
};
pub(crate) use sheet::captions as title_block_captions;
pub use sheet::{Sheet, SheetSize, TitleBlock, FIELD_MARGIN_MM, ITEM_GAP_MM};
pub use style::Pen;
pub use svg::{to_svg, view_svgs, ViewSvg, FONT_FAMILY};
pub use table::TableBlock;
pub use text::{CAPTION_HEIGHT_MM, LABEL_HEIGHT_MM};

pub use write::{write_all_atomic, write_atomic};

/// An axis-aligned rectangle on the sheet, millimetres, origin top-left, y down: `min` the
/// top-left corner, `max` the bottom-right.
pub use crate::geom::Rect;

/// A figure placed on the sheet.
#[derive(Debug, Clone, PartialEq)]
pub struct View {
    /// The recorded figure, drawn 1:1 (its μ is the truth).
    pub figure: Figure,
    /// Where the figure's (0, 0) lands on the sheet (sheet mm, y down): a figure point `p`
    /// is drawn at `(origin.x + p.x, origin.y − p.y)`.
    pub origin: DVec2,
    /// Caption in label markup, written centred under the figure's bounds.
    pub caption: Option<String>,
    /// How far under the figure's bounds its caption's band starts, mm: room for what its
    /// symbols draw below its points (the ground of a fixed pivot).
    pub caption_drop: f64,
}

/// Height of the band kept under a figure for its caption, mm.
pub const CAPTION_BAND_MM: f64 = 14.0;

impl View {
    /// Place `figure` so that its bounds (plus the caption band when there is a caption) are
    /// centred in `region` (sheet mm, y down).
    ///
    /// # Errors
    /// [`PlateError::DoesNotFit`] when the figure is wider or taller than the region.
    pub fn centred(
        figure: Figure,
        region: Rect,
        caption: Option<String>,
    ) -> Result<View, PlateError> {
        let (lo, hi) = figure.bounds().unwrap_or((DVec2::ZERO, DVec2::ZERO));
        let band = if caption.is_some() {
            CAPTION_BAND_MM
        } else {
            0.0
        };
        let (need_w, need_h) = (hi.x - lo.x, hi.y - lo.y + band);
        if need_w > region.width() || need_h > region.height() {
            return Err(PlateError::DoesNotFit {
                view: figure.title.clone(),
                need_w,
                need_h,
                have_w: region.width(),
                have_h: region.height(),
            });
        }
        // The figure's bounds centre goes to the region centre, lifted by half the band.
        let c = region.center() - DVec2::new(0.0, band * 0.5);
        let mid = (lo + hi) * 0.5;
        let origin = DVec2::new(c.x - mid.x, c.y + mid.y);
        Ok(View {
            figure,
            origin,
            caption,
            caption_drop: 0.0,
        })
    }

    /// The joint labels the plate will write for `figure` (the names of points that coincide,
    /// joined as `p ≡ b₃ ≡ d`): each with its point in the figure's coordinates (mm, y up),
    /// its text, the width and height it takes on the sheet, mm, and the steps it names.
    pub fn joint_labels(figure: &Figure) -> Vec<(DVec2, String, DVec2, Vec<StepId>)> {
        labels::joint_labels(figure)
    }

    /// The length of the lines `figure` draws inside the box `lo`–`hi` (figure mm, y up), mm:
    /// how much a label written there would be struck through.
    pub fn line_length_in(figure: &Figure, lo: DVec2, hi: DVec2) -> f64 {
        labels::line_length_in(figure, lo, hi)
    }

    /// How far the figure's symbols (pairs and their ground, arrowheads, line widths) draw
    /// below its lowest point, mm (0 when nothing does).
    pub fn symbols_below(figure: &Figure) -> f64 {
        let Some((lo, _)) = figure.bounds() else {
            return 0.0;
        };
        let map = path::Map::figure(DVec2::ZERO);
        let drawn = figure
            .steps
            .iter()
            .flat_map(|s| items::step_outlines(s, map))
            .flat_map(|o| match o.shape {
                items::Shape::Line(a, b) => vec![a, b],
                items::Shape::Area(pts) => pts,
            })
            // Sheet y runs down: the lowest drawn point has the largest y.
            .map(|p| -p.y)
            .fold(f64::INFINITY, f64::min);
        if drawn.is_finite() {
            (lo.y - drawn).max(0.0)
        } else {
            0.0
        }
    }

    /// The box of what the plate draws for `step` (a pair's symbol with its ground, an
    /// arrowhead; a line by its centre) in the figure's coordinates (mm, y up): (lower left, upper right); `None`
    /// when it draws nothing (a text).
    pub fn step_bounds(step: &crate::construct::Step) -> Option<(DVec2, DVec2)> {
        let map = path::Map::figure(DVec2::ZERO);
        // Sheet y runs down: the figure's is its negative.
        let points: Vec<DVec2> = items::step_outlines(step, map)
            .into_iter()
            .flat_map(|o| match o.shape {
                items::Shape::Line(a, b) => vec![a, b],
                items::Shape::Area(pts) => pts,
            })
            .map(|p| DVec2::new(p.x, -p.y))
            .collect();
        let first = *points.first()?;
        Some(
            points
                .iter()
                .fold((first, first), |(lo, hi), p| (lo.min(*p), hi.max(*p))),
        )
    }

    /// The sheet position of a figure point.
    pub fn to_sheet(&self, p: DVec2) -> DVec2 {
        DVec2::new(self.origin.x + p.x, self.origin.y - p.y)
    }
}

/// Free text on the sheet (notes, tables of results).
#[derive(Debug, Clone, PartialEq)]
pub struct TextBlock {
    /// Top-left corner of the first line, sheet mm, y down.
    pub at: DVec2,
    /// Lines in label markup.
    pub lines: Vec<String>,
    /// Text height (ГОСТ 2.304 size: the height of capitals), mm.
    pub size_mm: f64,
}

/// A drawing sheet with its views and texts.
#[derive(Debug, Clone, PartialEq)]
pub struct Plate {
    /// Name (used for file names).
    pub name: String,
    /// The sheet.
    pub sheet: Sheet,
    /// The filled title block.
    pub title_block: TitleBlock,
    /// Language of the title block captions.
    pub lang: Lang,
    /// Views, drawn in order.
    pub views: Vec<View>,
    /// Free texts, drawn after the views.
    pub texts: Vec<TextBlock>,
    /// Tables, drawn last.
    pub tables: Vec<TableBlock>,
}

/// A plate that cannot be laid out or rendered.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PlateError {
    /// A figure is larger than the region it was given.
    #[error(
        "view “{view}” does not fit: it needs {need_w:.1} × {need_h:.1} mm, \
         the region is {have_w:.1} × {have_h:.1} mm"
    )]
    DoesNotFit {
        /// The figure's title.
        view: String,
        /// Width needed, mm.
        need_w: f64,
        /// Height needed (caption band included), mm.
        need_h: f64,
        /// Width available, mm.
        have_w: f64,
        /// Height available, mm.
        have_h: f64,
    },
    /// The SVG could not be parsed.
    #[error("SVG cannot be parsed: {0}")]
    Svg(String),
    /// The SVG could not be rasterised or encoded.
    #[error("PNG cannot be rendered: {0}")]
    Raster(String),
    /// The DXF writer refused the drawing.
    #[error("DXF cannot be written: {0}")]
    Dxf(String),
}

#[cfg(test)]
mod tests;
