//! Sheets: the plates a scene asks for, composed from the domain figures on ГОСТ sheets.

mod positions;

use crate::construct::Drafting;
use crate::linkage::LinkageError;
use crate::plate::{Plate, PlateError};
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
    /// The drawing does not fit the sheet.
    #[error(transparent)]
    Plate(#[from] PlateError),
}

/// Build one plate of a scene.
pub fn build(scene: &Scene, kind: PlateKind, opts: &RenderOptions) -> Result<Plate, BuildError> {
    match kind {
        PlateKind::Positions => positions::build(scene, opts),
        PlateKind::Kinematics => Err(BuildError::Linkage(LinkageError::Model(
            "the kinematics plate is not built yet".into(),
        ))),
    }
}
