//! PDF: the sheets of a scene as the pages of one print-ready document, drawn 1:1.
//!
//! Each plate's SVG is parsed with svg2pdf's own `usvg` (fonts: only the bundled DejaVu
//! Sans faces, never system fonts), converted to a Form XObject, and painted over a page of
//! the sheet's size: an A1 landscape sheet is a page of 841 × 594 mm. Text stays text, with
//! the subset of DejaVu Sans it uses embedded. The document carries no date and no random
//! identifier: the same plates give the same bytes.

use super::fonts::{faces, family};
use pdf_writer::{Content, Finish, Name, Pdf, Rect, Ref};
use std::collections::HashMap;
use std::sync::{Arc, OnceLock};
use svg2pdf::usvg::{fontdb::Database, Options, Tree};
use svg2pdf::ConversionOptions;
use thiserror::Error;

/// Why a PDF could not be made.
#[derive(Debug, Error)]
pub enum PdfError {
    /// No SVG was given: a PDF needs at least one page.
    #[error("no pages")]
    NoPages,
    /// An SVG could not be parsed.
    #[error("page {page}: SVG: {message}")]
    Svg {
        /// The page, from 1.
        page: usize,
        /// The parser's message.
        message: String,
    },
    /// svg2pdf could not convert a parsed SVG.
    #[error("page {page}: PDF conversion: {message}")]
    Convert {
        /// The page, from 1.
        page: usize,
        /// svg2pdf's message.
        message: String,
    },
}

/// The bundled DejaVu Sans faces as a font database of svg2pdf's `usvg` (a different
/// `fontdb` version from the one [`super::font_database`] serves resvg with).
fn database() -> Arc<Database> {
    static DB: OnceLock<Arc<Database>> = OnceLock::new();
    DB.get_or_init(|| {
        let mut db = Database::new();
        for face in faces() {
            db.load_font_data(face.to_vec());
        }
        let name = family();
        db.set_serif_family(name);
        db.set_sans_serif_family(name);
        db.set_monospace_family(name);
        db.set_cursive_family(name);
        db.set_fantasy_family(name);
        Arc::new(db)
    })
    .clone()
}

/// One PDF document whose pages are `svgs`, in order, each at its own size 1:1 (an SVG
/// `width="841mm" height="594mm"` is a page of 841 × 594 mm). Text is embedded as text in
/// DejaVu Sans (a subset per page). Deterministic: no creation date, no document ID.
///
/// # Errors
/// [`PdfError::NoPages`] for an empty slice; [`PdfError::Svg`] for an SVG that does not
/// parse; [`PdfError::Convert`] when svg2pdf fails.
pub fn to_pdf(svgs: &[String]) -> Result<Vec<u8>, PdfError> {
    if svgs.is_empty() {
        return Err(PdfError::NoPages);
    }
    let opt = Options {
        fontdb: database(),
        font_family: family().into(),
        ..Options::default()
    };
    let mut alloc = Ref::new(1);
    let catalog_id = alloc.bump();
    let tree_id = alloc.bump();
    let mut pdf = Pdf::new();
    let mut page_ids = Vec::with_capacity(svgs.len());
    for (k, svg) in svgs.iter().enumerate() {
        let page = k + 1;
        let tree = Tree::from_str(svg, &opt).map_err(|e| PdfError::Svg {
            page,
            message: e.to_string(),
        })?;
        let (chunk, svg_id) =
            svg2pdf::to_chunk(&tree, ConversionOptions::default()).map_err(|e| {
                PdfError::Convert {
                    page,
                    message: e.to_string(),
                }
            })?;
        // The chunk's objects renumbered after ours, in the order they are met.
        let mut map = HashMap::new();
        let chunk = chunk.renumber(|old| *map.entry(old).or_insert_with(|| alloc.bump()));
        let svg_id = map[&svg_id];
        // usvg sizes are CSS pixels (96 per inch); the page is in points (72 per inch).
        let (w, h) = (tree.size().width() * 0.75, tree.size().height() * 0.75);
        let page_id = alloc.bump();
        let content_id = alloc.bump();
        let name = Name(b"S1");
        let mut page_dict = pdf.page(page_id);
        page_dict.media_box(Rect::new(0.0, 0.0, w, h));
        page_dict.parent(tree_id);
        page_dict.contents(content_id);
        page_dict.resources().x_objects().pair(name, svg_id);
        page_dict.finish();
        // The XObject is one point square: scale it to the page.
        let mut content = Content::new();
        content.transform([w, 0.0, 0.0, h, 0.0, 0.0]).x_object(name);
        pdf.stream(content_id, &content.finish());
        pdf.extend(&chunk);
        page_ids.push(page_id);
    }
    pdf.catalog(catalog_id).pages(tree_id);
    pdf.pages(tree_id)
        .count(page_ids.len() as i32)
        .kids(page_ids);
    Ok(pdf.finish())
}
