//! The two cams beside the turning cam of [`super::build`], built for a scene: the rocker
//! with a flat face ([`super::flat_rocker`]) and the translating cam ([`super::sliding`]).
//! The law's diagrams come first, by graphical integration as for every cam
//! ([`super::diagrams`]); then the profile on the board by the mechanism's own module at a
//! round μ_l (the scene's, else one that draws the mechanism a preferred size), and the
//! translating cam's shortest travel X_min on its combined diagram ([`super::travel`]). The twin of
//! each is its module's closed form; [`Special::rows`] compares them
//! ([`super::special_rows`]).

use super::diagrams::{diagrams, CamDiagrams};
use super::flat_rocker::{self, FlatRocker};
use super::motion::{points, Point};
use super::sliding::{self, Sliding};
use super::travel::{travel_min, TravelConstruction};
use super::{CamError, CamLayout, CamSpec, Rotation};
use crate::construct::{Context, Figure};
use crate::scale::{Quantity, Scale};

/// The centre distance a of a flat-faced rocker is drawn at most this long, mm: the face
/// lines reach from the turned pivots (on the circle a about O₁) to the profile.
const CENTRES_MM: f64 = 120.0;
/// The travel X of a translating cam is drawn at most this long, mm.
const TRAVEL_MM: f64 = 400.0;

/// A flat-faced rocker's or a translating cam's construction with its task.
#[derive(Debug, Clone, PartialEq)]
pub struct Special {
    /// The task.
    pub spec: CamSpec,
    /// The diagram points (the profile's positions too).
    pub points: Vec<Point>,
    /// The diagrams.
    pub diagrams: CamDiagrams,
    /// μ_l of the profile.
    pub scale: Scale,
    /// The profile constructed.
    pub profile: SpecialProfile,
}

/// The profile of a [`Special`] cam: the frame and the board.
#[derive(Debug, Clone, PartialEq)]
pub enum SpecialProfile {
    /// The rocker with a flat face.
    FlatRocker {
        /// a, e, r₀.
        frame: FlatRocker,
        /// The face lines in the inverted positions and their envelope.
        board: flat_rocker::RockerConstruction,
    },
    /// The translating cam.
    Sliding {
        /// X and the roller.
        frame: Sliding,
        /// The follower's positions along the cam, the rollers and the profiles.
        board: sliding::SlidingConstruction,
        /// The shortest travel X_min constructed beside the diagrams.
        travel: TravelConstruction,
    },
}

impl Special {
    /// The profile's drawing.
    pub fn figure(&self) -> &Figure {
        match &self.profile {
            SpecialProfile::FlatRocker { board, .. } => &board.figure,
            SpecialProfile::Sliding { board, .. } => &board.figure,
        }
    }

    /// The pressure angle read off the board at every point, rad.
    pub fn angles_read(&self) -> Vec<f64> {
        match &self.profile {
            SpecialProfile::FlatRocker { board, .. } => {
                board.contacts.iter().map(|c| c.lambda).collect()
            }
            SpecialProfile::Sliding { board, .. } => {
                board.contacts.iter().map(|c| c.lambda).collect()
            }
        }
    }
}

/// Build the flat-faced rocker or the translating cam of `spec`.
///
/// # Errors
/// A failed integration, no drawing scale, a face that outruns the cam, a frame that does
/// not fit, neighbouring face lines parallel; the turning layout or a clockwise cam (the
/// scene refuses both for these layouts).
pub fn build_special(spec: &CamSpec, ctx: &Context) -> Result<Special, CamError> {
    if spec.rotation == Rotation::Cw {
        return Err(CamError::Layout(
            "the flat-faced rocker and the translating cam are built counter-clockwise only",
        ));
    }
    let points = points(spec);
    let diagrams = diagrams(spec, &points, ctx)?;
    let chosen = |size: f64, mm: f64| match spec.scale_l {
        Some(mu) => Ok(mu),
        None => Scale::round_for(size, mm, Quantity::Length)
            .ok_or(CamError::NoScale { what: "μ_l", size }),
    };
    let (scale, profile) = match spec.layout {
        CamLayout::FlatRocker(frame) => {
            let mu = chosen(frame.centres, CENTRES_MM)?;
            let board = flat_rocker::construct(spec, &frame, mu, ctx)?;
            (mu, SpecialProfile::FlatRocker { frame, board })
        }
        CamLayout::Sliding(frame) => {
            let mu = chosen(frame.travel, TRAVEL_MM)?;
            let board = sliding::construct(spec, &frame, mu, ctx)?;
            let travel = travel_min(spec, &points, &diagrams, ctx);
            (
                mu,
                SpecialProfile::Sliding {
                    frame,
                    board,
                    travel,
                },
            )
        }
        CamLayout::Turning => {
            return Err(CamError::Layout("the turning cam is built by build"));
        }
    };
    Ok(Special {
        spec: spec.clone(),
        points,
        diagrams,
        scale,
        profile,
    })
}
