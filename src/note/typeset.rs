//! The typesetter: a note's Typst source and its figures compiled to PDF by the `typst` crate,
//! with bundled fonts only (New Computer Modern and its math face from `typst-assets`, the
//! plates' DejaVu Sans for the frames and the figures' texts), no clock, no file system and
//! no packages, so that the same note always gives the same bytes.

use super::NoteError;
use std::collections::HashMap;
use std::sync::OnceLock;
use typst::diag::{FileError, FileResult, SourceDiagnostic};
use typst::foundations::{Bytes, Datetime, Duration, Smart};
use typst::layout::{Frame, FrameItem};
use typst::syntax::{FileId, RootedPath, Source, VirtualPath, VirtualRoot};
use typst::text::{Font, FontBook};
use typst::utils::LazyHash;
use typst::{Library, LibraryExt, World, WorldExt};
use typst_layout::PagedDocument;

/// The fonts of every note, loaded once: the book and the faces in its order.
fn fonts() -> &'static (LazyHash<FontBook>, Vec<Font>) {
    static FONTS: OnceLock<(LazyHash<FontBook>, Vec<Font>)> = OnceLock::new();
    FONTS.get_or_init(|| {
        let mut faces: Vec<Font> = Vec::new();
        for data in typst_assets::fonts() {
            faces.extend(Font::iter(Bytes::new(data)));
        }
        for data in crate::plate::bundled_faces() {
            faces.extend(Font::iter(Bytes::new(data)));
        }
        (LazyHash::new(FontBook::from_fonts(&faces)), faces)
    })
}

/// The standard library, built once.
fn library() -> &'static LazyHash<Library> {
    static LIBRARY: OnceLock<LazyHash<Library>> = OnceLock::new();
    LIBRARY.get_or_init(|| LazyHash::new(Library::default()))
}

/// The file id of `path` in the note's project root.
fn file_id(path: &str) -> Result<FileId, NoteError> {
    let vpath = VirtualPath::new(path).map_err(|e| NoteError::Typeset(format!("{path}: {e}")))?;
    Ok(RootedPath::new(VirtualRoot::Project, vpath).intern())
}

/// One note's world: its main source and its figures.
struct NoteWorld {
    main: Source,
    files: HashMap<FileId, Bytes>,
}

impl World for NoteWorld {
    fn library(&self) -> &LazyHash<Library> {
        library()
    }

    fn book(&self) -> &LazyHash<FontBook> {
        &fonts().0
    }

    fn main(&self) -> FileId {
        self.main.id()
    }

    fn source(&self, id: FileId) -> FileResult<Source> {
        if id == self.main.id() {
            Ok(self.main.clone())
        } else {
            Err(FileError::NotSource)
        }
    }

    fn file(&self, id: FileId) -> FileResult<Bytes> {
        if id == self.main.id() {
            return Ok(Bytes::from_string(self.main.clone()));
        }
        self.files
            .get(&id)
            .cloned()
            .ok_or_else(|| FileError::NotFound(id.get().vpath().get_with_slash().into()))
    }

    fn font(&self, index: usize) -> Option<Font> {
        fonts().1.get(index).cloned()
    }

    fn today(&self, _offset: Option<Duration>) -> Option<Datetime> {
        // No clock: a note is the same on every day.
        None
    }
}

/// The world of a Typst `source` whose figures are `files` (path in the source → bytes).
fn world(source: &str, files: &[(String, Vec<u8>)]) -> Result<NoteWorld, NoteError> {
    let main = Source::new(file_id("/note.typ")?, source.to_string());
    let files = files
        .iter()
        .map(|(path, bytes)| Ok((file_id(path)?, Bytes::new(bytes.clone()))))
        .collect::<Result<HashMap<_, _>, NoteError>>()?;
    Ok(NoteWorld { main, files })
}

/// The laid-out pages of a world's source.
fn layout(world: &NoteWorld) -> Result<PagedDocument, NoteError> {
    typst::compile(world)
        .output
        .map_err(|errors| NoteError::Typeset(diagnostics(world, &errors)))
}

/// The PDF of a Typst `source` whose figures are `files` (path in the source → bytes).
///
/// # Errors
/// [`NoteError::Typeset`] with Typst's first diagnostics when the source does not compile.
pub(super) fn pdf(source: &str, files: &[(String, Vec<u8>)]) -> Result<Vec<u8>, NoteError> {
    let world = world(source, files)?;
    let document = layout(&world)?;
    let options = typst_pdf::PdfOptions {
        ident: Smart::Custom("tmm-note".into()),
        creator: Smart::Custom(Some("tmm".into())),
        ..Default::default()
    };
    typst_pdf::pdf(&document, &options)
        .map_err(|errors| NoteError::Typeset(diagnostics(&world, &errors)))
}

/// What ends each page's text in [`text`]: a form feed.
pub const PAGE_BREAK: char = '\u{c}';

/// The text the pages of a Typst `source` show, in the order it is laid out: each run of
/// text (a line's stretch in one font) followed by a space, each page by [`PAGE_BREAK`].
///
/// # Errors
/// As [`pdf`].
pub(super) fn text(source: &str, files: &[(String, Vec<u8>)]) -> Result<String, NoteError> {
    fn runs(frame: &Frame, out: &mut String) {
        for (_, item) in frame.items() {
            match item {
                FrameItem::Text(run) => {
                    out.push_str(&run.text);
                    out.push(' ');
                }
                FrameItem::Group(group) => runs(&group.frame, out),
                _ => {}
            }
        }
    }
    let document = layout(&world(source, files)?)?;
    let mut out = String::new();
    for page in document.pages() {
        runs(&page.frame, &mut out);
        out.push(PAGE_BREAK);
    }
    Ok(out)
}

/// The page's text field, mm from its top edge: under the top margin, above the bottom one
/// (the template's `#set page(margin: …)`).
const FIELD_MM: (f64, f64) = (15.0, 25.0);

/// How full the text field of each page of a Typst `source` is: the depth of its lowest text
/// or picture below the field's top over the field's height, 0 … 1 (the frame and its title
/// block, under the field, left out).
///
/// # Errors
/// As [`pdf`].
pub(super) fn fills(source: &str, files: &[(String, Vec<u8>)]) -> Result<Vec<f64>, NoteError> {
    /// The lowest point (pt from the page's top) of the text and pictures of `frame` at
    /// `dy` that lie above `floor`.
    fn lowest(frame: &Frame, dy: f64, floor: f64, low: &mut f64) {
        for (at, item) in frame.items() {
            let y = dy + at.y.to_pt();
            let bottom = match item {
                FrameItem::Text(_) => y,
                FrameItem::Image(_, size, _) => y + size.y.to_pt(),
                FrameItem::Group(group) => {
                    let ty = group.transform.ty.to_pt();
                    lowest(&group.frame, y + ty, floor, low);
                    continue;
                }
                _ => continue,
            };
            if bottom <= floor {
                *low = low.max(bottom);
            }
        }
    }
    let pt = |mm: f64| mm * 72.0 / 25.4;
    let document = layout(&world(source, files)?)?;
    Ok(document
        .pages()
        .iter()
        .map(|page| {
            let top = pt(FIELD_MM.0);
            let floor = page.frame.height().to_pt() - pt(FIELD_MM.1);
            let mut low = top;
            lowest(&page.frame, 0.0, floor + 1.0, &mut low);
            ((low - top) / (floor - top)).clamp(0.0, 1.0)
        })
        .collect())
}

/// The first few diagnostics, each with the source line it points at.
fn diagnostics(world: &NoteWorld, errors: &[SourceDiagnostic]) -> String {
    errors
        .iter()
        .take(5)
        .map(|e| {
            let line = world
                .range(e.span)
                .and_then(|r| world.main.lines().byte_to_line(r.start))
                .map(|l| format!("line {}: ", l + 1))
                .unwrap_or_default();
            format!("{line}{}", e.message)
        })
        .collect::<Vec<_>>()
        .join("; ")
}
