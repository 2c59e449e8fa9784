//! Linkages: structure (mobility, Assur groups), dyads of the five kinds, positions as
//! compass constructions with their analytic twin, extreme positions.

mod analytic;
mod built;
mod carrier;
mod compiled;
mod construction;
mod error;
mod extremes;
mod fan;
mod grashof;
mod groups;
mod indexed;
mod kinds;
mod model;
mod pairs;
mod part;
mod part_extent;
mod pen;
mod plans;
mod positions;
mod positions_draw;
mod program;
#[cfg(test)]
pub(crate) mod proptests;
mod rigid;
mod scheme;
mod slide_lines;
mod structure;
#[cfg(test)]
mod tests;

pub use analytic::{NearPivot, Pose, Unassembled, NEAR_PIVOT_RATIO, SWEEP_ANCHOR};
pub use built::Built;
pub use carrier::{candidates, carrier};
pub use construction::Failed;
pub use error::{CarrierError, LinkageError, ModelError};
pub use extremes::{Extremes, OutputCoord};
pub use grashof::{Bar, FourBar, Relation};
pub use groups::GroupView;
pub use model::{
    Branch, Crank, Dir, Dyad, DyadKind, FixedPoint, Group, Guide, LinkPoint, Mechanism, Output,
    RedundantPair, Sense,
};
pub use pairs::GroupPairs;
pub use part::Part;
pub use plans::{
    image_label, kin_plan, owner, plain, KinPlan, Measure, PlanKind, PlanReading, PlanSetup,
};
pub use positions::{
    group_name, plan_poses, PlanPoses, PlanPosition, PlanRequest, PosePosition, Position,
    PositionPlan,
};
pub use positions_draw::{
    draw_links, frame_guides, guide_ends, name_points, plan_positions, FrameGuide, GUIDE_MARGIN_MM,
};
pub use program::Program;
pub use scheme::structure_figure;
pub use structure::{GroupInfo, Mobility, PairInfo, Structure};
