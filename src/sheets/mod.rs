//! Sheets: the plates a scene asks for, composed from the domain figures on ГОСТ sheets.

mod kinematics;
mod positions;

use crate::construct::Drafting;
use crate::linkage::LinkageError;
use crate::plate::{Plate, PlateError, TitleBlock};
use crate::scale::Lang;
use crate::scene::{PlateKind, Scene};
use thiserror::Error;

/// How to render.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RenderOptions {
    /// Label language.
    pub lang: Lang,
    /// The drafting model for measured lengths.
    pub drafting: Drafting,
}

impl Default for RenderOptions {
    fn default() -> Self {
        Self {
            lang: Lang::Ru,
            drafting: Drafting::EXACT,
        }
    }
}

/// Why a plate cannot be built.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BuildError {
    /// A construction failed.
    #[error(transparent)]
    Linkage(#[from] LinkageError),
    /// The kinematic analysis failed.
    #[error(transparent)]
    Kinematics(Box<crate::kinematics::KinError>),
    /// The drawing does not fit the sheet.
    #[error(transparent)]
    Plate(#[from] PlateError),
}

/// The kinematic analysis a scene asks for, at its μ_l (or the textbook's choice for the crank).
pub fn kin_request(
    scene: &Scene,
    drafting: Drafting,
) -> Result<crate::kinematics::KinRequest, BuildError> {
    let scale_l = match scene.scale_l {
        Some(s) => s,
        None => positions::crank_scale(&scene.mechanism)?,
    };
    Ok(crate::kinematics::KinRequest {
        positions: positions::request(scene),
        scale_l,
        spec: scene.kinematics.clone(),
        drafting,
    })
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

/// Build one plate of a scene.
pub fn build(scene: &Scene, kind: PlateKind, opts: &RenderOptions) -> Result<Plate, BuildError> {
    match kind {
        PlateKind::Positions => positions::build(scene, opts),
        PlateKind::Kinematics => kinematics::build(scene, opts),
    }
}
