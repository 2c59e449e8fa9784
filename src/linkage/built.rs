//! One constructed position ([`Built`]) and what a group's construction gives besides its
//! joint ([`Frames`]), with the small decisions every construction step shares: a vector's
//! heading, the solution an intersection picks, the step that cannot go on.

use crate::construct::{ConstructionError, Pick, StepId};
use crate::geom::DVec2;

/// What a group's construction gives besides its joint: the frames of its links i and j
/// (their angles and the points they start from) and the acute crossing angle of the
/// intersection that fixed it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Frames {
    /// The angles of links i, j, radians.
    pub angle: [f64; 2],
    /// The origins (point indices) of links i, j.
    pub origin: [usize; 2],
    /// The crossing angle, radians.
    pub crossing: f64,
}

/// One constructed position, in drawing mm.
///
/// It mirrors the analytic twin's [`Pose`](super::Pose) field for field on purpose: the
/// drawing and the twin answer the same questions, in drawing mm here and in metres there.
#[derive(Debug, Clone, PartialEq)]
pub struct Built {
    /// Crank angle φ₁, radians.
    pub phi: f64,
    /// Point positions by program index, drawing mm.
    pub p: Vec<DVec2>,
    /// Link frame angle by link number, radians (from the drawn points).
    pub angle: Vec<f64>,
    /// Link frame origin (point index) by link number.
    pub origin: Vec<usize>,
    /// Per group: the acute crossing angle of the intersection that fixed it.
    pub crossing: Vec<f64>,
    /// The recorded step that produced each point (`None` for fixed points).
    pub step: Vec<Option<StepId>>,
}

pub(super) fn heading(v: DVec2) -> f64 {
    v.y.atan2(v.x)
}

impl Built {
    /// Record the joint a group's intersection found: its position and step; gives the point
    /// and the crossing angle.
    pub(super) fn place(
        &mut self,
        joint: usize,
        (x, crossing, id): (DVec2, f64, StepId),
    ) -> (DVec2, f64) {
        self.p[joint] = x;
        self.step[joint] = Some(id);
        (x, crossing)
    }
}

/// The solution a two-solution intersection takes: the one nearest to the previous
/// position's `joint` when there is one, else `first` (the scene's branch).
pub(super) fn pick(prev: Option<&Built>, joint: usize, first: Pick) -> Pick {
    match prev {
        Some(q) => Pick::Near(q.p[joint]),
        None => first,
    }
}

/// A step that cannot go on: the direction of `what` is not defined.
pub(super) fn other(step: &str, what: &str) -> ConstructionError {
    ConstructionError::Other {
        step: step.into(),
        message: format!("the direction of the {what} is not defined (coincident points)"),
    }
}
