//! Sheets: the plates a scene asks for, composed from the studies of its session on ГОСТ
//! sheets.

mod answer_key;
mod balancing;
mod cam;
pub(crate) mod cam_marks;
mod cam_special;
pub(crate) mod data;
mod digits;
pub use answer_key::{answer_key, table_sheet, KeyLine};
pub use task::task_sheet;
mod dynamics;
mod flywheel;
mod forces;
pub(crate) mod friction;
mod gears;
#[cfg(test)]
mod gears_tables_tests;
mod indicator;
mod layout;
mod train_lines;
mod train_view;
pub(crate) use flywheel::verdict as flywheel_verdict;
pub(crate) use gears::cut_wheel_quantity;
pub(crate) use kin_lines::verdict_lines;
pub use layout::ScaleKey;
mod kin_lines;
mod kinematics;
mod label_room;
mod pack;
mod plan_scales;
mod positions;
pub mod protocol;
mod refit;
mod task;

use crate::geom::DVec2;
use crate::plate::{Plate, PlateError, TitleBlock};
use crate::scale::Lang;
use crate::scale::Scale;
use crate::scene::{PlateKind, Scene};
use crate::study::{Session, StudyError};
pub use refit::{verified_fit, Fit};
use thiserror::Error;

/// Why a plate cannot be built.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BuildError {
    /// A study of the scene failed.
    #[error(transparent)]
    Study(#[from] StudyError),
    /// The drawing does not fit the sheet.
    #[error(transparent)]
    Plate(#[from] PlateError),
    /// No round drawing scale can be formed for a size.
    #[error("no drawing scale can be chosen for the size {0} m")]
    NoScale(f64),
    /// A sheet's views cannot be fitted on it by raising their scales.
    #[error("{0} cannot be fitted on A1")]
    NoFit(&'static str),
    /// The tolerances of a drawing cannot be set up.
    #[error("tolerances: {0}")]
    Tolerances(#[from] crate::geom::InvalidTolerance),
    /// A drawing too large only because its lengths are read coarsely: read exactly, it
    /// fits (a derivative of lengths read to 100 mm is their noise).
    #[error("--drafting {} mm: {error} (read exactly it fits: the reading to {} mm makes it so large)", crate::scale::format_plain(*.resolution_mm), crate::scale::format_plain(*.resolution_mm))]
    TooCoarse {
        /// The reading's resolution, mm.
        resolution_mm: f64,
        /// The drawing too large at it.
        error: Box<BuildError>,
    },
    /// A drawing larger than an empty sheet at every scale of its key the scene accepts.
    #[error("{}: {}; no {} the scene accepts fits it: the drawing is too large by its other data", .key.key, too_large(.what, *.need, None), .key.key)]
    NoAdmissibleScale {
        /// The drawing.
        what: String,
        /// Its size with its labels and caption, mm.
        need: DVec2,
        /// The scene key of its scale, and that scale.
        key: layout::ScaleKey,
    },
    /// A drawing is larger than an empty sheet at the scale it must be drawn at.
    #[error("{}", too_large(.what, *.need, .fits.as_ref()))]
    TooLarge {
        /// The drawing.
        what: String,
        /// Its size with its labels and caption, mm.
        need: DVec2,
        /// The scene key of its scale, that scale, and the largest round scale that fits.
        fits: Option<(layout::ScaleKey, Scale)>,
    },
}

fn too_large(what: &str, need: DVec2, fits: Option<&(layout::ScaleKey, Scale)>) -> String {
    let base = format!(
        "“{what}” needs {} × {} mm, more than an empty sheet holds",
        crate::scale::format_sig(need.x.round(), 6, Lang::En),
        crate::scale::format_sig(need.y.round(), 6, Lang::En)
    );
    match fits {
        Some((k, f)) => format!(
            "{key}: {base}; the largest scale at which it fits is {key} = {} {}",
            crate::scale::format_sig(f.value(), 4, Lang::En),
            k.scale.quantity.unit(Lang::En),
            key = k.key,
        ),
        None => base,
    }
}

impl From<crate::kinematics::KinError> for BuildError {
    fn from(e: crate::kinematics::KinError) -> Self {
        BuildError::Study(e.into())
    }
}

/// The title block of a plate of `scene`, filled from its `[task]`; "Масштаб" is the plan of
/// positions' μ_l as a ГОСТ 2.302 scale (μ_l = 0,0025 м/мм draws 2,5 mm of the machine in
/// one millimetre: 1:2,5; μ_l = 0,0004 м/мм: 2,5:1), or "—" for a sheet that draws nothing of
/// the machine at a length scale (diagrams, tables, figures each at a scale of its own).
fn title_block(scene: &Scene, sheet_title: &str, plan: Option<Scale>, lang: Lang) -> TitleBlock {
    let t = scene.title.in_lang(lang);
    TitleBlock {
        title: t.title.clone(),
        sheet_title: sheet_title.into(),
        designation: t.designation.clone(),
        author: t.author.clone(),
        checked: t.checked.clone(),
        organisation: t.organisation.clone(),
        scale: plan.map_or_else(|| "—".into(), |p| gost_scale(p, lang)),
        // Numbered across the scene by `build_all`.
        sheet_no: 1,
        sheets: 1,
        // A part drawing's own (the flywheel's sheet fills them).
        mass: String::new(),
        material: String::new(),
    }
}

/// The titles of the figures that draw the mechanism at μ_l: the plan of positions and the
/// structural scheme.
const MECHANISM_FIGURES: [&str; 2] = ["plan", "scheme"];

/// A kinematic sheet that draws no mechanism — the continuation of plans and diagrams, whose
/// scales are the μ of their captions — writes «—» for its scale in the title block: the
/// scale of ГОСТ 2.104 is its images' (the shaper's second sheet wrote 1:2,5).
fn scale_of_the_mechanism(p: &mut Plate) {
    let draws = (p.views.iter()).any(|v| MECHANISM_FIGURES.contains(&v.figure.title.as_str()));
    if !draws {
        p.title_block.scale = "—".into();
    }
}

/// μ_l as a ГОСТ 2.302 scale: a reduction 1:n (μ_l ≥ 0,001 м/мм) or an enlargement n:1.
fn gost_scale(plan: Scale, lang: Lang) -> String {
    let n = plan.value() * 1000.0;
    if n >= 1.0 {
        format!("1:{}", crate::scale::format_sig(n, 4, lang))
    } else {
        format!("{}:1", crate::scale::format_sig(1.0 / n, 4, lang))
    }
}

/// What a sheet's graphical values err by when its lengths are read exactly: the sheet's
/// own constructions, so that a gear or rotor sheet does not speak of plans and diagrams.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Errs {
    /// Plans (velocity, acceleration, force) and diagrams by the method of chords.
    PlansAndChords,
    /// Plans only.
    Plans,
    /// Diagrams by the method of chords only.
    Diagrams,
    /// Drawn lengths, rounded.
    Rounding,
}

impl Errs {
    fn word(self) -> crate::words::Text {
        match self {
            Self::PlansAndChords => crate::words::Text::ErrPlansAndChords,
            Self::Plans => crate::words::Text::ErrPlans,
            Self::Diagrams => crate::words::Text::ErrDiagrams,
            Self::Rounding => crate::words::Text::ErrRounding,
        }
    }
}

/// The line that states how lengths were read off the drawing (the drafting model), and
/// when exactly, what the sheet's values err by (`errs`).
fn drafting_line(d: crate::construct::Drafting, errs: Errs, lang: Lang) -> String {
    let r = d.resolution_mm();
    if r > 0.0 {
        format!(
            "{} {} {}",
            crate::words::Text::ReadTo.get(lang),
            crate::scale::format_sig(r, 3, lang),
            crate::words::Text::Millimetre.get(lang)
        )
    } else {
        format!(
            "{}: {}",
            crate::words::Text::ReadExactly.get(lang),
            errs.word().get(lang)
        )
    }
}

/// Build one plate of the session's scene, in `lang`: the sheets it takes (usually one; a
/// plate whose views need more room continues on `name-2`, …).
pub fn build(session: &Session<'_>, kind: PlateKind, lang: Lang) -> Result<Vec<Plate>, BuildError> {
    let wants = |k: PlateKind| session.scene().plates.contains(&k);
    match kind {
        PlateKind::Positions => positions::build(session, lang),
        // With the plan of positions wanted too, the kinematic sheet holds its structure.
        PlateKind::Kinematics => kinematics::build(session, lang, wants(PlateKind::Positions)),
        // An engine's indicator diagrams go on the dynamics sheet when there is one.
        PlateKind::Forces => forces::build(session, lang, !wants(PlateKind::Dynamics)),
        PlateKind::Balancing => balancing::build(session, lang),
        PlateKind::Friction => friction::build(session, lang),
        PlateKind::Dynamics => dynamics::build(session, lang),
        PlateKind::Flywheel => flywheel::build(session, lang),
        PlateKind::Gears => gears::build(session, lang),
        // A flat-faced rocker and a translating cam have a sheet of their own.
        PlateKind::Cam => match session.special_cam()? {
            Some(special) => cam_special::build(session, &special, lang),
            None => cam::build(session, lang),
        },
    }
}

/// The plates drawn for `scene`, in order: those it asks for, except the plan of positions
/// when it asks for the kinematic analysis too — the kinematic sheet then holds the plan with
/// its structure, as the textbook's sheet 1 does.
pub fn drawn(scene: &Scene) -> Vec<PlateKind> {
    let folded = scene.plates.contains(&PlateKind::Kinematics);
    scene
        .plates
        .iter()
        .copied()
        .filter(|&k| !(folded && k == PlateKind::Positions))
        .collect()
}

/// Every plate the scene asks for ([`drawn`]), in order, its sheets numbered 1 … n across
/// the scene (the title block's "sheet k of n"). A failure names the first plate, in that
/// order, that cannot be built.
///
/// The plates are built side by side, each on a thread of its own, sharing the session's
/// studies (each computed once, by the first to ask): the shaper's gear sheet traces its
/// blocking contour while the others are drawn. Plain threads, not the rayon pool's: a
/// study that waits on another's result then never holds a pool thread that the other's
/// parallel work needs. Called on a thread of the pool (a batch's variants, already side
/// by side), they are built one after another: a pool thread waiting for plain threads
/// whose studies need the pool would wait for ever.
pub fn build_all(
    session: &Session<'_>,
    lang: Lang,
) -> Result<Vec<(PlateKind, Plate)>, (PlateKind, BuildError)> {
    let kinds = drawn(session.scene());
    let one = |kind: PlateKind| build(session, kind, lang);
    let built: Vec<Result<Vec<Plate>, BuildError>> = match rayon::current_thread_index() {
        Some(_) => kinds.iter().map(|&kind| one(kind)).collect(),
        None => std::thread::scope(|scope| {
            let threads: Vec<_> = kinds
                .iter()
                .map(|&kind| scope.spawn(move || one(kind)))
                .collect();
            threads
                .into_iter()
                .map(|t| {
                    t.join()
                        .unwrap_or_else(|panic| std::panic::resume_unwind(panic))
                })
                .collect()
        }),
    };
    let mut all = Vec::new();
    for (kind, plates) in kinds.into_iter().zip(built) {
        let plates = plates.map_err(|e| (kind, e))?;
        all.extend(plates.into_iter().map(|p| (kind, p)));
    }
    let n = all.len() as u32;
    for (k, (_, p)) in all.iter_mut().enumerate() {
        let tb = &mut p.title_block;
        tb.sheet_no = k as u32 + 1;
        tb.sheets = n;
        tb.designation = sheet_designation(&tb.designation, tb.sheet_no, n);
    }
    Ok(all)
}

/// The sheets of a set standing alone (an answer key, a task sheet), numbered 1 … n in their
/// title blocks.
fn numbered(mut plates: Vec<Plate>) -> Vec<Plate> {
    let n = plates.len() as u32;
    for (k, p) in plates.iter_mut().enumerate() {
        p.title_block.sheet_no = k as u32 + 1;
        p.title_block.sheets = n;
    }
    plates
}

/// A sheet's designation in a set of `n`: the scene's (`[task] designation`, the set's) with
/// the sheet's two-digit number, ТММ.КП.000 → ТММ.КП.000.01 … ТММ.КП.000.07; a single sheet
/// carries the scene's own.
fn sheet_designation(set: &str, sheet_no: u32, n: u32) -> String {
    if n > 1 && !set.is_empty() {
        format!("{set}.{sheet_no:02}")
    } else {
        set.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::{gost_scale, sheet_designation};
    use crate::scale::{Lang, Quantity, Scale};

    #[test]
    fn a_sets_sheets_carry_its_designation_with_their_number() {
        assert_eq!(sheet_designation("ТММ.КП.000", 3, 7), "ТММ.КП.000.03");
        assert_eq!(sheet_designation("ТММ.КП.000", 7, 7), "ТММ.КП.000.07");
        assert_eq!(sheet_designation("ТММ.Л17.01", 1, 1), "ТММ.Л17.01");
        assert_eq!(sheet_designation("", 2, 2), "");
    }

    #[test]
    fn title_block_scales_reduce_and_enlarge_as_gost_writes_them() {
        let s = |mu: f64| gost_scale(Scale::new(mu, Quantity::Length).unwrap(), Lang::Ru);
        assert_eq!(s(0.0025), "1:2,5");
        assert_eq!(s(0.001), "1:1");
        assert_eq!(s(0.0004), "2,5:1");
        assert_eq!(s(0.0002), "5:1");
    }
}
