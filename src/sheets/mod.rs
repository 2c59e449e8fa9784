//! Sheets: the plates a scene asks for, composed from the studies of its session on ГОСТ
//! sheets.

mod captions;
mod fit;
mod kinematics;
mod positions;

use crate::plate::{Plate, PlateError, TitleBlock};
use crate::scale::Lang;
use crate::scene::{PlateKind, Scene};
use crate::study::{Session, StudyError};
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
    Tolerances(String),
}

impl From<crate::kinematics::KinError> for BuildError {
    fn from(e: crate::kinematics::KinError) -> Self {
        BuildError::Study(e.into())
    }
}

/// The title block of a plate of `scene`, filled from its `[task]`.
fn title_block(scene: &Scene, sheet_title: &str, sheet_no: u32, sheets: u32) -> TitleBlock {
    let t = &scene.title;
    TitleBlock {
        title: t.title.clone(),
        sheet_title: sheet_title.into(),
        designation: t.designation.clone(),
        author: t.author.clone(),
        checked: t.checked.clone(),
        organisation: t.organisation.clone(),
        scale: String::new(),
        sheet_no,
        sheets,
    }
}

/// Build one plate of the session's scene, in `lang`.
pub fn build(session: &Session<'_>, kind: PlateKind, lang: Lang) -> Result<Plate, BuildError> {
    match kind {
        PlateKind::Positions => positions::build(session, lang),
        PlateKind::Kinematics => kinematics::build(session, lang),
    }
}
