//! Why a study cannot be carried out.

use super::*;

/// Why a study cannot be carried out.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum StudyError {
    /// The scene has no `[mechanism]` and the study needs one.
    #[error("the scene has no [mechanism]: {0} needs one")]
    NoMechanism(&'static str),
    /// The linkage cannot be constructed.
    #[error(transparent)]
    Linkage(#[from] LinkageError),
    /// The kinematic study cannot be carried out.
    #[error(transparent)]
    Kinematics(#[from] KinError),
    /// The tolerances of the figures cannot be set up.
    #[error("tolerances: {0}")]
    Tolerances(#[from] crate::geom::InvalidTolerance),
    /// The force analysis cannot be carried out.
    #[error(transparent)]
    Forces(#[from] ForceError),
    /// The scene has no `[forces]` and the study needs it.
    #[error("the scene has no [forces]: {0} needs the loads")]
    NoForces(&'static str),
    /// The scene has no `[dynamics]` and the study needs it.
    #[error("the scene has no [dynamics]: {0} needs it")]
    NoDynamics(&'static str),
    /// The dynamic study cannot be carried out.
    #[error(transparent)]
    Dynamics(#[from] crate::dynamics::DynamicsError),
    /// The drafting resolution reads every ordinate of a diagram as 0, so no scale is left
    /// to choose for it.
    #[error("dynamics: --drafting {resolution_mm} mm reads every ordinate of the diagram drawn at {what} as 0, so no scale can be chosen for it; a finer resolution reads it", resolution_mm = crate::scale::format_plain(*resolution_mm))]
    ReadAsZero {
        /// The scale that cannot be chosen (μ_T …).
        what: &'static str,
        /// The resolution, mm.
        resolution_mm: f64,
    },
    /// The scene has no `[balancing]` and the study needs one.
    #[error("the scene has no [balancing]: {0} needs one")]
    NoBalancing(&'static str),
    /// The balancing cannot be carried out.
    #[error(transparent)]
    Balancing(#[from] BalancingError),
    /// A friction case cannot be constructed.
    #[error(transparent)]
    Friction(#[from] FrictionError),
    /// The scene has no `[gears]` and the study needs it.
    #[error("the scene has no [gears]: {0} needs it")]
    NoGears(&'static str),
    /// The gear study cannot be carried out.
    #[error(transparent)]
    Gears(#[from] crate::gears::GearError),
    /// The scene has no `[cam]` and the study needs one.
    #[error("the scene has no [cam]: {0} needs one")]
    NoCam(&'static str),
    /// The cam cannot be constructed.
    #[error(transparent)]
    Cam(#[from] crate::cam::CamError),
}
