//! The explanatory note (расчётно-пояснительная записка) of a scene: the session's rows,
//! tables and findings and the sheets' own views composed into one document in the order of
//! seed 000 — title page, contents, the task, the structural analysis, the kinematics, the
//! kinetostatics, the dynamics, the cam, the gears, the conclusions and the references — each
//! section where the scene has its study. Every number comes from the session; nothing is
//! computed here that a study or a sheet has computed.
//!
//! [`compose`] writes the note as Typst markup with its figures (SVG, one per view cut out of
//! its sheet); [`to_pdf`] typesets it with the `typst` crate and bundled fonts only. A4
//! portrait, ГОСТ 2.105 text rules, ГОСТ 2.104 frames: form 2 on the first text page, form 2a
//! on the following ones. The words are the catalogue's ([`crate::words`]).

mod analytic;
mod cam;
mod cam_scales;
mod cam_special;
mod columns;
mod conclusions;
mod diagrams;
mod dynamics;
mod equations;
mod explain;
mod flywheel;
mod friction;
mod friction_pairs;
mod front;
mod gears;
mod genre;
mod kinematics;
mod kinetostatics;
mod lecture;
mod machines;
mod markup;
mod moments;
mod pair_worked;
mod plan_reads;
mod plan_worked;
mod plans;
mod positions;
mod practicum;
mod rows;
mod scripts;
mod train;
mod typeset;
mod worked;
mod zhukovsky;

pub use typeset::PAGE_BREAK;
pub use worked::{Printed, RowValue, Worked};

use crate::check::Report;
use crate::plate::{self, Plate};
use crate::scale::Lang;
use crate::scene::PlateKind;
use crate::sheets::data::{data_block, DataPart};
use crate::sheets::{self, BuildError};
use crate::study::{Session, StudyError};
use crate::words::{NoteText, Word};
use markup::Markup;
use thiserror::Error;

/// The Latin words of two letters or more a Russian or Ukrainian note may show: the
/// functions and operators of its formulas (`sin`, `arccos`, `inv α`, `const`, the
/// extremes' indices `max`, `min`) and the analogue's differential `dS` (`dS/dφ`). Its
/// units are Cyrillic (`мм`, `Н·м`); any other Latin word is a leak of English or of a
/// program's identifier ([`latin_allowed`]).
pub const LATIN_WORDS: &[&str] = &[
    "sin", "cos", "tg", "ctg", "arcsin", "arccos", "arctg", "inv", "max", "min", "const", "dS",
];

/// Whether a Russian or Ukrainian note may show the Latin `word` (a run of Latin letters
/// between non-letters): one of [`LATIN_WORDS`]; a designation of points, in capitals (a
/// link `AB`, a relative velocity's subscript `BA`, a plane `II`); or a segment of a plan,
/// two small letters from the pole `p` (`pb`, `ps`) or between two of the points `a` … `e`
/// (`ab`, `ce`), or Wittenbauer's `kl`. A single letter is a symbol.
pub fn latin_allowed(word: &str) -> bool {
    let letters = word.chars().count();
    if letters < 2 || LATIN_WORDS.contains(&word) || word == "kl" {
        return true;
    }
    if word.chars().all(|c| c.is_ascii_uppercase()) {
        return letters <= 4;
    }
    let points = |c: char| ('a'..='e').contains(&c);
    match word.chars().collect::<Vec<_>>()[..] {
        ['p', b] => points(b) || "ks".contains(b),
        [a, b] => a != b && points(a) && points(b),
        _ => false,
    }
}

/// A note ready to typeset: its Typst source and the files it reads (the figures).
#[derive(Debug, Clone, PartialEq)]
pub struct Note {
    /// The Typst source.
    pub source: String,
    /// The figures: the path the source names each by, and its bytes.
    pub files: Vec<(String, Vec<u8>)>,
    /// The left sides (Typst math) of the displayed formulas under which no «где» explains
    /// their symbol: a defect of the note's writer, which the tests hold empty.
    pub unexplained: Vec<String>,
    /// The worked formulas, in the order set.
    pub worked: Vec<Worked>,
}

/// Why a note cannot be written.
#[derive(Debug, Error)]
pub enum NoteError {
    /// A study of the scene cannot be carried out.
    #[error(transparent)]
    Study(#[from] StudyError),
    /// A sheet whose views the note shows cannot be built.
    #[error("sheet `{}`: {error}", .kind.stem())]
    Sheet {
        /// The plate.
        kind: PlateKind,
        /// Why.
        error: BuildError,
    },
    /// The typesetter refuses the note (a defect of the note's writer).
    #[error("typesetting the note: {0}")]
    Typeset(String),
}

/// The largest figure of the note, mm: the text's width and most of a page's height.
const FIGURE_W_MM: f64 = 170.0;
/// See [`FIGURE_W_MM`].
const FIGURE_H_MM: f64 = 200.0;

/// What every section writes with: the session, its report, the scene's sheets numbered as
/// one set, the markup and the figures so far.
struct Writer<'a, 's> {
    session: &'a Session<'s>,
    lang: Lang,
    report: Report,
    sheets: Vec<(PlateKind, Plate)>,
    /// Each sheet's views as figures, laid out once (a sheet's labels are placed over the
    /// whole sheet) when a section first shows one of them.
    views: Vec<Option<Vec<Option<plate::ViewSvg>>>>,
    doc: Markup,
    files: Vec<(String, Vec<u8>)>,
    explained: explain::Explained,
    worked: Vec<Worked>,
}

impl Writer<'_, '_> {
    /// A word of the catalogue in the note's language.
    fn word(&self, w: impl Word) -> &'static str {
        w.get(self.lang)
    }

    /// A heading of a section (level 1) or subsection (level 2).
    fn heading(&mut self, level: usize, w: impl Word) {
        let title = self.word(w);
        self.doc.heading(level, title);
    }

    /// The views whose caption `pick` accepts on the `nth` sheet of `kind` (every sheet of
    /// it when `None`), as figures: each captioned by `caption` (given the view's own caption)
    /// and the sheet it is drawn on.
    fn figures(
        &mut self,
        (kind, nth): (PlateKind, Option<usize>),
        pick: impl Fn(&str) -> bool,
        caption: impl Fn(&str) -> String,
    ) {
        let sheet_word = self.word(NoteText::SheetNo);
        let mut out = Vec::new();
        let Writer { sheets, views, .. } = self;
        let of_kind = sheets.iter().zip(views).filter(|((k, _), _)| *k == kind);
        for (_, ((_, p), svgs)) in of_kind
            .enumerate()
            .filter(|(n, _)| nth.is_none_or(|k| k == *n))
        {
            let svgs = svgs.get_or_insert_with(|| plate::view_svgs(p));
            for (i, (view, svg)) in p.views.iter().zip(svgs.iter()).enumerate() {
                let own = view.caption.as_deref().unwrap_or("");
                let Some(svg) = svg.as_ref().filter(|_| pick(own)).cloned() else {
                    continue;
                };
                let path = format!("/fig/{}-{i}.svg", p.name);
                let text = format!("{} ({sheet_word} {})", caption(own), p.title_block.sheet_no);
                out.push((path, svg, text));
            }
        }
        for (path, svg, text) in out {
            // A figure keeps its size on the sheet when it fits the text's field (170 mm
            // wide, 200 mm tall to leave its caption room on a page); a larger one is
            // reduced to fit it.
            let reduce = (FIGURE_W_MM / svg.width_mm)
                .min(FIGURE_H_MM / svg.height_mm)
                .min(1.0);
            let width = svg.width_mm * reduce;
            self.doc.figure(&path, width, &text);
            self.files.push((path, svg.svg.into_bytes()));
        }
    }
}

impl Writer<'_, '_> {
    /// The lines of the data blocks of the sheets of `kind` ([`data_block`]).
    fn sheet_data(&self, kind: PlateKind, part: DataPart) -> Vec<String> {
        let plates = self
            .sheets
            .iter()
            .filter(|(k, _)| *k == kind)
            .map(|(_, p)| p);
        data_block(plates, part, self.lang)
    }

    /// [`Self::sheet_data`] as a list.
    fn data_list(&mut self, kind: PlateKind, part: DataPart) {
        let lines = self.sheet_data(kind, part);
        for line in lines {
            self.doc.raw(&format!("- #{}", markup::label(&line)));
        }
        self.doc.raw("");
    }
}

/// The note of the scene of `session` in `lang`.
///
/// # Errors
/// A study or a sheet the note shows that cannot be carried out.
pub fn compose(session: &Session<'_>, lang: Lang) -> Result<Note, NoteError> {
    let sheets = sheets::build_all(session, lang)
        .map_err(|(kind, error)| NoteError::Sheet { kind, error })?;
    compose_with(session, lang, sheets)
}

/// The note of the scene of `session` in `lang` showing the views of `sheets`, the scene's
/// sheets as [`sheets::build_all`] numbers them (built once for the drawings and the note).
///
/// # Errors
/// A study the note shows that cannot be carried out.
pub fn compose_with(
    session: &Session<'_>,
    lang: Lang,
    sheets: Vec<(PlateKind, Plate)>,
) -> Result<Note, NoteError> {
    let report = session.report()?;
    let mut w = Writer {
        session,
        lang,
        report,
        views: sheets.iter().map(|_| None).collect(),
        sheets,
        doc: Markup::default(),
        files: Vec::new(),
        explained: explain::Explained::default(),
        worked: Vec::new(),
    };
    front::preamble(&mut w);
    front::title_page(&mut w);
    front::contents(&mut w);
    front::task(&mut w);
    let scene = session.scene();
    if scene.mechanism.is_some() {
        kinematics::structure(&mut w)?;
        kinematics::kinematics(&mut w)?;
    }
    if scene.forces.is_some() && scene.mechanism.is_some() {
        kinetostatics::kinetostatics(&mut w)?;
    }
    if scene.dynamics.is_some() {
        dynamics::dynamics(&mut w)?;
    }
    if scene.cam.is_some() {
        cam::cam(&mut w)?;
    }
    if scene.gears.is_some() {
        gears::gears(&mut w)?;
    }
    lecture::others(&mut w)?;
    conclusions::conclusions(&mut w);
    front::references(&mut w);
    w.explained.settle();
    Ok(Note {
        source: scripts::localise_functions(scripts::localise_scripts(&w.doc.finish(), lang), lang),
        files: w.files,
        unexplained: w.explained.missing,
        worked: w.worked,
    })
}

/// A user's text (a `[task]` string: the title, the author, the organisation, …) as the
/// note's markup sets it in `lang`: content of one Typst string, so that no character of it
/// is read as markup (the fuzzer's `note` target checks that it typesets to the text).
pub fn user_text(text: &str, lang: Lang) -> String {
    scripts::localise_scripts(&markup::text(text), lang)
}

/// The text Typst `content` (markup such as [`user_text`] gives) shows typeset alone on a
/// page with the note's fonts: each run of text followed by a space, as [`to_text`].
///
/// # Errors
/// [`NoteError::Typeset`] when the typesetter refuses the content.
pub fn typeset_content(content: &str) -> Result<String, NoteError> {
    typeset::text(&format!("#{content}"), &[])
}

/// The note typeset as PDF: the same note always gives the same bytes.
///
/// # Errors
/// [`NoteError::Typeset`] when the typesetter refuses the source.
pub fn to_pdf(note: &Note) -> Result<Vec<u8>, NoteError> {
    typeset::pdf(&note.source, &note.files)
}

/// How full each typeset page of the note is: the depth of its lowest line or picture over
/// the text field's height, 0 … 1 (ГОСТ 2.105's note leaves no page more than a quarter
/// empty but at a section's end).
///
/// # Errors
/// [`NoteError::Typeset`] when the typesetter refuses the source.
pub fn page_fills(note: &Note) -> Result<Vec<f64>, NoteError> {
    typeset::fills(&note.source, &note.files)
}

/// The text the typeset note shows, page by page in the order it is laid out, each run of
/// text (a line's stretch in one font) followed by a space and each page by a form feed
/// ([`PAGE_BREAK`]): what a reader finds by searching the PDF.
///
/// # Errors
/// [`NoteError::Typeset`] when the typesetter refuses the source.
pub fn to_text(note: &Note) -> Result<String, NoteError> {
    typeset::text(&note.source, &note.files)
}

/// Typst's floor for `note`: the same preamble (the page, its frame and title blocks, the
/// faces) with the note's typeset text ([`to_text`], the same characters) set as plain
/// paragraphs, one a page of the note, without a formula, table or figure — what the
/// typesetter costs whatever the markup, beside which the note's own time is read.
///
/// # Errors
/// [`NoteError::Typeset`] when the note does not typeset, or its source does not hold the
/// template.
pub fn plain_twin(note: &Note) -> Result<Note, NoteError> {
    let end = note
        .source
        .find(front::TEMPLATE)
        .map(|at| at + front::TEMPLATE.len())
        .ok_or_else(|| NoteError::Typeset("the note's source holds no template".into()))?;
    let mut source = note.source[..end].to_string();
    for page in to_text(note)?.split(PAGE_BREAK) {
        if !page.trim().is_empty() {
            source.push_str(&format!("\n#{}\n", markup::text(page.trim())));
        }
    }
    Ok(Note {
        source,
        files: Vec::new(),
        unexplained: Vec::new(),
        worked: Vec::new(),
    })
}
