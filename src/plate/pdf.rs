//! PDF: the sheets of a scene as the pages of one print-ready document, drawn 1:1.
//!
//! Each plate's SVG is parsed by the same `usvg` as the PNG's (fonts: only the bundled DejaVu
//! Sans faces, never system fonts) and drawn by krilla onto a page of the sheet's size: an A1
//! landscape sheet is a page of 841 × 594 mm. Text stays text, with the subset of DejaVu Sans
//! it uses embedded. The document carries no date and no random identifier: the same plates
//! give the same bytes.

use super::raster::ParsedSvg;
use krilla::geom::Size;
use krilla::page::PageSettings;
use krilla::{Document, SerializeSettings};
use krilla_svg::{SurfaceExt, SvgSettings};
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
    /// The PDF writer could not draw a parsed SVG or write the document.
    #[error("{}PDF: {message}", page.map(|p| format!("page {p}: ")).unwrap_or_default())]
    Convert {
        /// The page, from 1, when the failure belongs to one.
        page: Option<usize>,
        /// The writer's message.
        message: String,
    },
}

/// One PDF document whose pages are `svgs`, in order, each at its own size 1:1 (an SVG
/// `width="841mm" height="594mm"` is a page of 841 × 594 mm). Text is embedded as text in
/// DejaVu Sans. Deterministic: no creation date, no random document ID.
///
/// # Errors
/// [`PdfError::NoPages`] for an empty slice; [`PdfError::Svg`] for an SVG that does not
/// parse; [`PdfError::Convert`] when the writer fails.
pub fn to_pdf(svgs: &[String]) -> Result<Vec<u8>, PdfError> {
    // Each page parsed as it is drawn and dropped after: a document of many pages never
    // holds more than one page's tree.
    let mut document = new_document(svgs.len())?;
    for (k, svg) in svgs.iter().enumerate() {
        add_page(&mut document, k + 1, &parsed_page(k + 1, svg)?.tree)?;
    }
    finish(document)
}

/// [`to_pdf`] of `plates`, each written as SVG only when its page is drawn (a sheet of a
/// long table runs to many pages: one page's SVG and tree held at a time).
///
/// # Errors
/// As [`to_pdf`].
pub fn plates_to_pdf(plates: &[super::Plate]) -> Result<Vec<u8>, PdfError> {
    let mut document = new_document(plates.len())?;
    for (k, plate) in plates.iter().enumerate() {
        let svg = super::to_svg(plate);
        add_page(&mut document, k + 1, &parsed_page(k + 1, &svg)?.tree)?;
    }
    finish(document)
}

/// The SVG of page `page` (from 1) parsed.
fn parsed_page(page: usize, svg: &str) -> Result<ParsedSvg<'_>, PdfError> {
    ParsedSvg::new(svg).map_err(|e| PdfError::Svg {
        page,
        message: match e {
            super::PlateError::Svg(message) => message,
            other => other.to_string(),
        },
    })
}

/// [`to_pdf`] of SVGs already parsed (the same bytes).
///
/// # Errors
/// [`PdfError::NoPages`] for an empty slice; [`PdfError::Convert`] when the writer fails.
pub fn to_pdf_parsed(pages: &[&ParsedSvg<'_>]) -> Result<Vec<u8>, PdfError> {
    let mut document = new_document(pages.len())?;
    for (k, parsed) in pages.iter().enumerate() {
        add_page(&mut document, k + 1, &parsed.tree)?;
    }
    finish(document)
}

/// An empty document for `pages` pages (none: [`PdfError::NoPages`]), with no metadata
/// that would change from run to run.
fn new_document(pages: usize) -> Result<Document, PdfError> {
    if pages == 0 {
        return Err(PdfError::NoPages);
    }
    Ok(Document::new_with(SerializeSettings {
        xmp_metadata: false,
        enable_tagging: false,
        ..SerializeSettings::default()
    }))
}

/// Draw `tree` on a new page (number `page`, from 1) of its own size.
fn add_page(
    document: &mut Document,
    page: usize,
    tree: &resvg::usvg::Tree,
) -> Result<(), PdfError> {
    // usvg sizes are CSS pixels (96 per inch); the page is in points (72 per inch).
    let (w, h) = (tree.size().width() * 0.75, tree.size().height() * 0.75);
    let convert = |message: &str| PdfError::Convert {
        page: Some(page),
        message: message.into(),
    };
    let size = Size::from_wh(w, h).ok_or_else(|| convert("empty page"))?;
    let mut sheet = document.start_page_with(PageSettings::new(size));
    let mut surface = sheet.surface();
    surface
        .draw_svg(tree, size, SvgSettings::default())
        .ok_or_else(|| convert("the SVG could not be drawn"))?;
    surface.finish();
    sheet.finish();
    // The writer memoizes each page's compressed content, which no later page asks for
    // again: a memo not used by the last few pages is dropped, or a long document holds
    // every page twice.
    comemo::evict(PAGE_MEMO_AGE);
    Ok(())
}

/// A memoized result of the PDF writer not used by the last this many pages is dropped.
const PAGE_MEMO_AGE: usize = 4;

/// The document's bytes.
fn finish(document: Document) -> Result<Vec<u8>, PdfError> {
    document.finish().map_err(|e| PdfError::Convert {
        page: None,
        message: e.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Text in three faces of DejaVu Sans (a sheet's lettering is oblique; the note's and a
    /// chart's may be upright or bold).
    const SVG: &str = r##"<svg xmlns="http://www.w3.org/2000/svg" width="60mm" height="40mm" viewBox="0 0 60 40">
        <rect width="60" height="40" fill="#fff"/>
        <text x="4" y="10" font-size="5" font-style="italic">Лист 2 ω₁</text>
        <text x="4" y="20" font-size="5">Масштаб 1:2,5</text>
        <text x="4" y="30" font-size="5" font-weight="bold">ТММ.КП.000</text>
    </svg>"##;

    #[test]
    fn parsed_pages_give_the_pdf_of_their_text() {
        let other = SVG.replace("Лист 2", "Лист 3");
        let (a, b) = (
            ParsedSvg::new(SVG).unwrap(),
            ParsedSvg::new(&other).unwrap(),
        );
        assert_eq!(
            to_pdf_parsed(&[&a, &b]).unwrap(),
            to_pdf(&[SVG.to_string(), other.clone()]).unwrap()
        );
        assert!(matches!(to_pdf_parsed(&[]), Err(PdfError::NoPages)));
    }

    #[test]
    fn several_font_faces_give_the_same_bytes_every_time() {
        let pages = [SVG.to_string(), SVG.replace("Лист 2", "Лист 3")];
        let first = to_pdf(&pages).unwrap();
        // Each face its own embedded subset (the dictionaries are not compressed).
        let text = String::from_utf8_lossy(&first);
        for face in ["DejaVuSans-Oblique", "DejaVuSans-Bold"] {
            assert!(text.contains(&format!("+{face}")), "{face} embedded");
        }
        assert!(
            text.match_indices("+DejaVuSans")
                .any(|(at, m)| { !text[at + m.len()..].starts_with('-') }),
            "the upright face embedded"
        );
        for _ in 0..4 {
            assert_eq!(to_pdf(&pages).unwrap(), first);
        }
        // Made on other threads (other hash seeds), the same bytes.
        let elsewhere = std::thread::spawn(move || to_pdf(&pages).unwrap())
            .join()
            .unwrap();
        assert_eq!(elsewhere, first);
    }
}
