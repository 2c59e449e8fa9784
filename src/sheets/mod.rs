//! Sheets: the plates a scene asks for, composed from the domain figures on ГОСТ sheets.

mod kinematics;
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
    let m = &scene.mechanism;
    let scale_l = match scene.scale_l {
        Some(s) => s,
        None => {
            crate::scale::Scale::round_for(m.crank.length, 50.0, crate::scale::Quantity::Length)
                .ok_or_else(|| {
                    LinkageError::Model(format!(
                        "no drawing scale for the crank length {} m",
                        m.crank.length
                    ))
                })?
        }
    };
    let k = &scene.kinematics;
    Ok(crate::kinematics::KinRequest {
        positions: positions::request(scene),
        scale_l,
        scale_v: k.scale_v,
        scale_a: k.scale_a,
        acceleration_positions: k.acceleration_positions.clone(),
        diagram_point: k.diagram_point.clone(),
        scale_s: k.scale_s,
        scale_phi: k.scale_phi,
        pole_h1: k.pole_h1,
        pole_h2: k.pole_h2,
        hodograph: k.hodograph.clone(),
        tangents: k.tangents,
        drafting,
    })
}

/// Build one plate of a scene.
pub fn build(scene: &Scene, kind: PlateKind, opts: &RenderOptions) -> Result<Plate, BuildError> {
    match kind {
        PlateKind::Positions => positions::build(scene, opts),
        PlateKind::Kinematics => kinematics::build(scene, opts),
    }
}
