//! The analytic twin at a position of the plan, where both the force analysis and the
//! prediction of its drawings start: the analytic motion, the loads it gives and their one
//! linear solve, a failure located at the position's group.

use super::diagnose::located;
use super::loads::{loads, Load, Phase, PositionMotion};
use super::spec::ForceSpec;
use super::twin::{solve, Equilibrium};
use super::ForceError;
use crate::linkage::{Pose, Program};

/// The twin at a position `(label, pose)` on the stroke `phase`, the crank turning at `w1`:
/// the analytic motion, the loads it gives and their solve (its failure located at the
/// position).
pub fn at_position(
    spec: &ForceSpec,
    prog: &Program,
    (label, pose): (&str, &Pose),
    phase: Phase,
    w1: f64,
) -> Result<(PositionMotion, Vec<Load>, Equilibrium), ForceError> {
    let exact = PositionMotion::analytic(pose, w1);
    let loads = loads(spec, prog, &exact, phase)?;
    let twin = solve(prog, pose, &loads, &spec.drive, w1.signum())
        .map_err(|e| located(e, label, prog, pose))?;
    Ok((exact, loads, twin))
}
