//! Rendering scenes to files (DESIGN §2: one library call per command): the plates of each
//! scene built through one session (scene → session → sheets), turned into SVG, PNG (in
//! parallel) and one PDF per scene, all in memory, then written atomically — a failed run
//! writes nothing. `tmm render`, the plate regression tests and the bench go through here.

use crate::construct::Drafting;
use crate::plate::{self, Plate};
use crate::scale::Lang;
use crate::scene::{PlateKind, Scene};
use crate::sheets::{self, BuildError};
use crate::study::Session;
use crate::threads;
use rayon::prelude::*;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Which files [`render`] writes: `<out>/<scene>/<plate>.svg`, `.png`, `.dxf`, and
/// `<out>/<scene>/<scene>.pdf`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Formats {
    /// One SVG per sheet.
    pub svg: bool,
    /// One PNG per sheet, at [`Options::dpi`].
    pub png: bool,
    /// One PDF per scene, every sheet a page, 1:1.
    pub pdf: bool,
    /// The scene's explanatory note, `<scene>-note.pdf`.
    pub note: bool,
    /// One DXF drawing per sheet (`<out>/<scene>/<plate>.dxf`, [`plate::to_dxf`]).
    pub dxf: bool,
}

/// The PNG resolution `tmm render` writes unless asked otherwise, dots per inch.
pub const DEFAULT_DPI: u32 = 150;

/// How the plates are rendered.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// The labels' language.
    pub lang: Lang,
    /// The drafting model every reading is taken under.
    pub drafting: Drafting,
    /// The files to write.
    pub formats: Formats,
    /// PNG resolution, dots per inch.
    pub dpi: u32,
}

/// Why the plates of a run cannot be rendered.
#[derive(Debug, Error)]
pub enum RenderError {
    /// A plate of a scene cannot be built.
    #[error("{}: plate `{}`: {error}", .scene.display(), .kind.stem())]
    Build {
        /// The scene's file.
        scene: PathBuf,
        /// The plate.
        kind: PlateKind,
        /// Why.
        error: BuildError,
    },
    /// A sheet too large for a PNG at the resolution asked.
    #[error("--dpi {dpi}: {}: {error}", .path.display())]
    Resolution {
        /// The resolution, dots per inch.
        dpi: u32,
        /// The sheet's file, without its extension.
        path: PathBuf,
        /// Why.
        error: plate::PlateError,
    },
    /// The force analysis fails its own equilibrium check.
    #[error("{}: {why}", .scene.display())]
    Unbalanced {
        /// The scene's file.
        scene: PathBuf,
        /// Where, with the residuals.
        why: String,
    },
    /// A PNG that cannot be rasterised.
    #[error("{}: {error}", .path.display())]
    Png {
        /// The sheet's file, without its extension.
        path: PathBuf,
        /// Why.
        error: plate::PlateError,
    },
    /// A DXF that cannot be written.
    #[error("{}: {error}", .path.display())]
    Dxf {
        /// The DXF's file.
        path: PathBuf,
        /// Why.
        error: plate::PlateError,
    },
    /// A PDF that cannot be produced.
    #[error("{}: {error}", .path.display())]
    Pdf {
        /// The PDF's file.
        path: PathBuf,
        /// Why.
        error: plate::PdfError,
    },
    /// A scene's explanatory note that cannot be written.
    #[error("{}: the explanatory note: {error}", .scene.display())]
    Note {
        /// The scene's file.
        scene: PathBuf,
        /// Why (boxed: a study's error is large).
        error: Box<crate::note::NoteError>,
    },
    /// A file that cannot be written (nothing is written).
    #[error("{}: cannot write: {error}", .path.display())]
    Write {
        /// The first file that cannot be written.
        path: PathBuf,
        /// Why.
        error: std::io::Error,
    },
}

impl RenderError {
    /// The input is at fault rather than a construction: a scale the scene gives that no
    /// sheet can hold, a resolution too fine for a sheet, a file that cannot be written.
    pub fn is_input(&self) -> bool {
        match self {
            RenderError::Build { error, .. } => {
                matches!(
                    error,
                    BuildError::TooLarge { fits: Some(_), .. }
                        | BuildError::NoAdmissibleScale { .. }
                        | BuildError::TooCoarse { .. }
                )
            }
            RenderError::Resolution { .. } | RenderError::Write { .. } => true,
            RenderError::Png { .. }
            | RenderError::Dxf { .. }
            | RenderError::Pdf { .. }
            | RenderError::Note { .. }
            | RenderError::Unbalanced { .. } => false,
        }
    }
}

/// The plates of a scene, built through one session. A drawing too large at a scale the
/// scene gives has the suggested scale verified on every plate the key sets (the
/// suggestion of the first drawing alone may not fit the others).
///
/// # Errors
/// The first plate that cannot be built.
pub fn plates(
    s: &Scene,
    lang: Lang,
    drafting: Drafting,
) -> Result<Vec<(PlateKind, Plate)>, RenderError> {
    plates_of(&Session::new(s, drafting), lang)
}

/// What `tmm check` asks of a scene: its plates built (as [`plates`]) and, where it has a
/// force analysis, every force position passing its own equilibrium check
/// ([`Session::unbalanced`]).
///
/// # Errors
/// The first plate that cannot be built, or the positions whose routes fail the check.
pub fn check(s: &Scene) -> Result<(), RenderError> {
    let session = Session::new(s, Drafting::EXACT);
    plates_of(&session, Lang::Ru)?;
    let failures = session.unbalanced().map_err(|e| RenderError::Unbalanced {
        scene: s.path.clone(),
        why: e.to_string(),
    })?;
    if failures.is_empty() {
        Ok(())
    } else {
        Err(RenderError::Unbalanced {
            scene: s.path.clone(),
            why: (failures.iter().map(ToString::to_string))
                .collect::<Vec<_>>()
                .join("; "),
        })
    }
}

/// The plates of the scene of `session`, as [`plates`].
fn plates_of(session: &Session<'_>, lang: Lang) -> Result<Vec<(PlateKind, Plate)>, RenderError> {
    let s = session.scene();
    let drafting = session.drafting();
    sheets::build_all(session, lang).map_err(|(kind, e)| RenderError::Build {
        scene: s.path.clone(),
        kind,
        error: refit(s, e, drafting, lang),
    })
}

/// A drawing too large at a scale the scene gives: the scale suggested verified on every
/// plate the key sets; a drawing that fits when read exactly is blamed on the reading.
fn refit(s: &Scene, e: BuildError, drafting: Drafting, lang: Lang) -> BuildError {
    let e = suggest(s, e, drafting, lang);
    let too_large_at = |e: &BuildError| match e {
        BuildError::TooLarge {
            fits: Some((k, _)), ..
        }
        | BuildError::NoAdmissibleScale { key: k, .. } => Some(k.key),
        _ => None,
    };
    let Some(key) = too_large_at(&e).filter(|_| drafting.resolution_mm() > 0.0) else {
        return e;
    };
    let exact = sheets::build_all(&Session::new(s, Drafting::EXACT), lang);
    let fits_exactly = match &exact {
        Ok(_) => true,
        Err((_, other)) => too_large_at(other) != Some(key),
    };
    if fits_exactly {
        BuildError::TooCoarse {
            resolution_mm: drafting.resolution_mm(),
            error: Box::new(e),
        }
    } else {
        e
    }
}

/// [`refit`]'s suggestion: verified, or none when the scene refuses every scale that fits.
fn suggest(s: &Scene, e: BuildError, drafting: Drafting, lang: Lang) -> BuildError {
    match e {
        BuildError::TooLarge {
            what,
            need,
            fits: Some((key, first)),
        } => match sheets::verified_fit(s, key.key, first, drafting, lang) {
            sheets::Fit::Refused => BuildError::NoAdmissibleScale { what, need, key },
            sheets::Fit::Verified(fit) => BuildError::TooLarge {
                what,
                need,
                fits: Some((key, fit)),
            },
            sheets::Fit::Unverified => BuildError::TooLarge {
                what,
                need,
                fits: Some((key, first)),
            },
        },
        e => e,
    }
}

/// Every file of `scenes` under `out`, built in memory: per scene its sheets' SVG and PNG
/// (`<out>/<scene>/<sheet>.<ext>`), then each scene's PDF, then each scene's note.
///
/// # Errors
/// The first plate that cannot be built, a sheet too large for a PNG at `options.dpi`, a PNG
/// or PDF that cannot be produced.
pub fn files(
    scenes: &[Scene],
    out: &Path,
    options: &Options,
) -> Result<Vec<(PathBuf, Vec<u8>)>, RenderError> {
    let sessions: Vec<Session<'_>> = scenes
        .iter()
        .map(|s| Session::new(s, options.drafting))
        .collect();
    files_of(&sessions, out, options)
}

/// Every file of the scenes of `sessions` (as [`files`]); the sessions keep what their
/// studies computed (a report asked of them afterwards reuses it). Each session's own
/// drafting model is the one read.
fn files_of(
    sessions: &[Session<'_>],
    out: &Path,
    options: &Options,
) -> Result<Vec<(PathBuf, Vec<u8>)>, RenderError> {
    let Options {
        lang, formats, dpi, ..
    } = *options;
    let mut plates: Vec<(PathBuf, Plate)> = Vec::new();
    let mut sets: Vec<(PathBuf, std::ops::Range<usize>)> = Vec::new();
    // A note is composed from its session's sheets beside the drawings' rasterising.
    let mut notes: Vec<(&Session<'_>, Vec<(PlateKind, Plate)>)> = Vec::new();
    for session in sessions {
        let s = session.scene();
        let first = plates.len();
        let all = plates_of(session, lang)?;
        if formats.note {
            notes.push((session, all.clone()));
        }
        for (_, plate) in all {
            let base = out.join(&s.stem).join(&plate.name);
            if formats.png {
                let (w, h) = (plate.sheet.width_mm(), plate.sheet.height_mm());
                plate::png_size(w, h, dpi as f32).map_err(|error| RenderError::Resolution {
                    dpi,
                    path: base.clone(),
                    error,
                })?;
            }
            plates.push((base, plate));
        }
        if formats.pdf {
            let path = out.join(&s.stem).join(format!("{}.pdf", s.stem));
            sets.push((path, first..plates.len()));
        }
    }
    // Each sheet's DXF from its plate, before the plates go to their SVGs.
    let dxfs = if formats.dxf {
        dxfs_of(&plates)?
    } else {
        Vec::new()
    };
    // Each sheet written as SVG on a core of its own (a blocking contour's sheet is half a
    // megabyte of SVG).
    let svgs: Vec<(PathBuf, String)> = plates
        .into_par_iter()
        .map(|(base, plate)| (base, plate::to_svg(&plate)))
        .collect();
    // A sheet both a PNG and a PDF page is parsed (its text laid out) once, for both.
    let parsed: Vec<plate::ParsedSvg<'_>> = match formats.png && formats.pdf {
        true => svgs
            .par_iter()
            .map(|(base, svg)| {
                plate::ParsedSvg::new(svg).map_err(|error| RenderError::Png {
                    path: base.clone(),
                    error,
                })
            })
            .collect::<Result<_, _>>()?,
        false => Vec::new(),
    };
    // The PDF sets, the notes and the PNGs are made side by side: a set or a note takes one
    // core, the rasteriser every core there is.
    let set_pdfs = || -> Result<Vec<(PathBuf, Vec<u8>)>, RenderError> {
        sets.iter()
            .map(|(path, pages)| {
                let pdf = if parsed.is_empty() {
                    let pages: Vec<String> = svgs[pages.clone()]
                        .iter()
                        .map(|(_, svg)| svg.clone())
                        .collect();
                    plate::to_pdf(&pages)
                } else {
                    plate::to_pdf_parsed(&parsed[pages.clone()].iter().collect::<Vec<_>>())
                };
                let pdf = pdf.map_err(|error| RenderError::Pdf {
                    path: path.clone(),
                    error,
                })?;
                Ok((path.clone(), pdf))
            })
            .collect()
    };
    let note_pdfs = || -> Result<Vec<(PathBuf, Vec<u8>)>, RenderError> {
        notes
            .into_iter()
            .map(|(session, sheets)| {
                let s = session.scene();
                let pdf = crate::note::compose_with(session, lang, sheets)
                    .and_then(|note| crate::note::to_pdf(&note))
                    .map_err(|error| note_failed(s, error))?;
                Ok((note_path(out, s), pdf))
            })
            .collect()
    };
    let pngs = || -> Vec<Result<Vec<u8>, plate::PlateError>> {
        match (formats.png, parsed.is_empty()) {
            (false, _) => Vec::new(),
            (true, true) => {
                let texts: Vec<String> = svgs.iter().map(|(_, svg)| svg.clone()).collect();
                plate::to_png_dpi_all(&texts, dpi as f32)
            }
            (true, false) => parsed
                .par_iter()
                .map(|p| plate::png_of(p, dpi as f32))
                .collect(),
        }
    };
    // The PNGs and the notes on plain threads, the PDF sets on the calling one: a PDF or a
    // note waiting for its parts on a thread of the pool would take up other work there.
    let (pngs, (note_pdfs, set_pdfs)) =
        threads::beside(pngs, || threads::beside(note_pdfs, set_pdfs));
    let (set_pdfs, note_pdfs) = (set_pdfs?, note_pdfs?);
    let mut files: Vec<(PathBuf, Vec<u8>)> = Vec::new();
    let mut pngs = pngs.into_iter();
    let mut dxfs = dxfs.into_iter();
    for (base, svg) in svgs {
        if let Some(png) = pngs.next() {
            let png = png.map_err(|error| RenderError::Png {
                path: base.clone(),
                error,
            })?;
            files.push((base.with_extension("png"), png));
        }
        if formats.svg {
            files.push((base.with_extension("svg"), svg.into_bytes()));
        }
        if let Some(dxf) = dxfs.next() {
            files.push((base.with_extension("dxf"), dxf));
        }
    }
    files.extend(set_pdfs);
    files.extend(note_pdfs);
    Ok(files)
}

/// Each sheet as DXF ([`plate::to_dxf`]), in parallel, in order.
///
/// # Errors
/// The first sheet the DXF writer refuses.
fn dxfs_of(plates: &[(PathBuf, Plate)]) -> Result<Vec<Vec<u8>>, RenderError> {
    plates
        .par_iter()
        .map(|(base, plate)| {
            plate::to_dxf(plate).map_err(|error| RenderError::Dxf {
                path: base.with_extension("dxf"),
                error,
            })
        })
        .collect()
}

/// Render `scenes` to `out`: every file of [`files`], written atomically. Returns the files
/// written, in order.
///
/// # Errors
/// As [`files`]; a file that cannot be written (then nothing is).
pub fn render(
    scenes: &[Scene],
    out: &Path,
    options: &Options,
) -> Result<Vec<PathBuf>, RenderError> {
    write(files(scenes, out, options)?)
}

/// Render the scene of `session` to `out` as [`render`] does, through that session: what
/// its studies computed stays for its report (`tmm batch` asks both of a variant).
///
/// # Errors
/// As [`render`].
pub fn render_session(
    session: &Session<'_>,
    out: &Path,
    options: &Options,
) -> Result<Vec<PathBuf>, RenderError> {
    write(files_of(std::slice::from_ref(session), out, options)?)
}

/// Every file of the scene of `session` under `out` (as [`files`]), built in memory through
/// that session, for a caller that writes them with files of its own (a batch's variant with
/// its task sheet, all or none).
///
/// # Errors
/// As [`files`].
pub fn session_files(
    session: &Session<'_>,
    out: &Path,
    options: &Options,
) -> Result<Vec<(PathBuf, Vec<u8>)>, RenderError> {
    files_of(std::slice::from_ref(session), out, options)
}

/// Write `files` atomically (all or none); the paths written, in order.
///
/// # Errors
/// A file that cannot be written (then nothing is).
pub fn write(files: Vec<(PathBuf, Vec<u8>)>) -> Result<Vec<PathBuf>, RenderError> {
    plate::write_all_atomic(&files).map_err(|(path, error)| RenderError::Write { path, error })?;
    Ok(files.into_iter().map(|(path, _)| path).collect())
}

/// Where the note of `s` is written: `<out>/<scene>/<scene>-note.pdf`.
fn note_path(out: &Path, s: &Scene) -> PathBuf {
    out.join(&s.stem).join(format!("{}-note.pdf", s.stem))
}

/// The note of `s` that cannot be composed or typeset.
fn note_failed(s: &Scene, error: crate::note::NoteError) -> RenderError {
    RenderError::Note {
        scene: s.path.clone(),
        error: Box::new(error),
    }
}

/// The note of `s` composed by its session and typeset.
fn note_pdf(s: &Scene, lang: Lang, drafting: Drafting) -> Result<Vec<u8>, RenderError> {
    let note = crate::note::compose(&Session::new(s, drafting), lang)
        .map_err(|error| note_failed(s, error))?;
    crate::note::to_pdf(&note).map_err(|error| note_failed(s, error))
}

/// The explanatory note of each of `scenes`, typeset (`<out>/<scene>/<scene>-note.pdf`),
/// built in memory.
///
/// # Errors
/// The first note that cannot be composed or typeset.
pub fn note_files(
    scenes: &[Scene],
    out: &Path,
    lang: Lang,
    drafting: Drafting,
) -> Result<Vec<(PathBuf, Vec<u8>)>, RenderError> {
    scenes
        .iter()
        .map(|s| Ok((note_path(out, s), note_pdf(s, lang, drafting)?)))
        .collect()
}

/// Write the explanatory notes of `scenes` ([`note_files`]) atomically; returns the files
/// written.
///
/// # Errors
/// As [`note_files`]; a file that cannot be written (then nothing is).
pub fn notes(
    scenes: &[Scene],
    out: &Path,
    lang: Lang,
    drafting: Drafting,
) -> Result<Vec<PathBuf>, RenderError> {
    write(note_files(scenes, out, lang, drafting)?)
}
