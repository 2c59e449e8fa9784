//! Linkages: structure (mobility, Assur groups), dyads of the five kinds, positions as
//! compass constructions with their analytic twin, extreme positions.

mod analytic;
mod construction;
mod extremes;
mod model;
mod plans;
mod positions;
mod positions_draw;
mod program;
#[cfg(test)]
mod proptests;
mod scheme;
mod structure;
#[cfg(test)]
mod tests;

pub use analytic::{Pose, Unassembled};
pub use construction::{Built, Failed};
pub use extremes::{Extremes, OutputCoord};
pub use model::{
    Branch, Crank, Dir, Dyad, DyadKind, FixedPoint, Group, Guide, LinkPoint, Mechanism, Output,
    RedundantPair, Sense,
};
pub use plans::{kin_plan, owner, plain, KinPlan, Measure, PlanKind, PlanSetup, Reading};
pub use positions::{
    group_name, plan_poses, plan_positions, PlanPoses, PlanPosition, PlanRequest, PosePosition,
    Position, PositionPlan,
};
pub use positions_draw::{
    draw_links, fixed_pivots, frame_guides, guide_ends, FrameGuide, Part, GUIDE_MARGIN_MM,
};
pub use program::{Op, PDir, PDyad, PGuide, Program};
pub use scheme::structure_figure;
pub use structure::{GroupInfo, Mobility, PairInfo, Structure};

use thiserror::Error;

/// Why a linkage task cannot be carried out.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LinkageError {
    /// The model itself is inconsistent (unknown names, reused links).
    #[error("mechanism: {0}")]
    Model(String),
    /// A group cannot be assembled at a position.
    #[error(
        "position {position} (φ₁ = {phi_deg:.4}°): group {group} cannot be assembled: {detail}"
    )]
    CannotAssemble {
        /// The position's label.
        position: String,
        /// Crank angle, degrees.
        phi_deg: f64,
        /// The group (`2 (RRR, links 2, 3)`).
        group: String,
        /// What fails, with its numbers.
        detail: String,
    },
    /// The crank cannot make a full turn, so the extreme positions cannot be searched for.
    #[error("the crank cannot make a full turn: at φ₁ = {phi_deg:.4}° group {group} cannot be assembled: {detail}; give `start` as an angle to construct the positions that exist")]
    CannotTurn {
        /// Crank angle, degrees.
        phi_deg: f64,
        /// The group.
        group: String,
        /// What fails.
        detail: String,
    },
    /// The output has no extreme positions (it turns fully or does not move).
    #[error("output {output}: {detail}")]
    NoExtremes {
        /// The output.
        output: String,
        /// Explanation.
        detail: String,
    },
}
