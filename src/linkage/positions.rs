//! The plan of positions (план положений): N crank positions plus the extreme positions,
//! solved and walked in crank order; `positions_draw` constructs each with compass and
//! straightedge and draws them into one figure with the trajectories of the link points, the
//! extreme positions, θ and the stroke H.

use super::analytic::Pose;
use super::built::Built;
use super::error::LinkageError;
use super::extremes::Extremes;
use super::model::{Mechanism, Sense};
use super::program::Program;
use crate::construct::Figure;
use std::f64::consts::TAU;

/// What positions to construct.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanRequest {
    /// Number of equally spaced crank positions.
    pub count: u32,
    /// Crank angle of position 1 (radians); `None`: the start of the working stroke.
    pub start: Option<f64>,
    /// Add the extreme positions that fall between the numbered ones (labelled `k′`), and
    /// the crank angle where the output stands in one of them again (the six-bar's `4′`).
    pub other_extreme: bool,
    /// Choose each assembly by continuity with the previous position instead of by the
    /// scene's side.
    pub continuity: bool,
}

/// One position of the plan: its label, crank angle and analytic twin, with what was
/// constructed there — a [`Built`] position on the plan of positions ([`PlanPosition`]),
/// nothing when the positions are only solved ([`PosePosition`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Position<B> {
    /// Its label (`1`…`12`, `8′`).
    pub label: String,
    /// Crank angle, radians.
    pub phi: f64,
    /// An extreme position.
    pub extreme: bool,
    /// As constructed (drawing mm).
    pub built: B,
    /// The analytic twin (m, with velocity analogues).
    pub pose: Pose,
}

/// A constructed position of the plan of positions.
pub type PlanPosition = Position<Built>;

/// A position solved analytically only (no construction).
pub type PosePosition = Position<()>;

/// The plan of positions.
#[derive(Debug, Clone, PartialEq)]
pub struct PositionPlan {
    /// The mechanism as the scene gives it (the equilibrium check reads its own picture of
    /// the bodies from it).
    pub mechanism: Mechanism,
    /// The compiled mechanism.
    pub program: Program,
    /// Extremes, when the outputs have them.
    pub extremes: Option<Extremes>,
    /// Positions in the order of crank rotation from position 1.
    pub positions: Vec<PlanPosition>,
    /// The recorded figure at μ_l.
    pub figure: Figure,
}

/// Crank angle of the numbered position `k` (0-based).
fn phi_of(start: f64, sense: Sense, k: usize, count: u32) -> f64 {
    (start + sense.sign() * TAU * k as f64 / count as f64).rem_euclid(TAU)
}

/// The sequence (label, φ, extreme?) in crank order.
fn sequence(
    req: &PlanRequest,
    start: f64,
    sense: Sense,
    ex: Option<&Extremes>,
) -> Vec<(String, f64, bool)> {
    let step = TAU / req.count as f64;
    // (the numbered position it follows, φ, extreme?, crank travel from position 1, a
    // further position?)
    let mut seq: Vec<(usize, f64, bool, f64, bool)> = (0..req.count as usize)
        .map(|k| {
            let phi = phi_of(start, sense, k, req.count);
            (k + 1, phi, false, step * k as f64, false)
        })
        .collect();
    if let (true, Some(ex)) = (req.other_extreme, ex) {
        // The output's extreme positions, and where it stands in one again (the six-bar's
        // slider at 6′ once more at φ₁ = 229°): a position the plan draws as well.
        let again = ex.reached_again().map(|(stop, _)| stop);
        for phi in [ex.phi_start, ex.phi_other].into_iter().chain(again) {
            let travel = sense.travel(start, phi);
            let k = ((travel / step).floor() as usize).min(req.count as usize - 1);
            let off = travel - step * k as f64;
            // An extreme that falls on a numbered position is that position.
            if off.min(step - off) <= 1e-9 {
                let at = if off <= 1e-9 {
                    k
                } else {
                    (k + 1) % req.count as usize
                };
                seq[at].2 = true;
                continue;
            }
            seq.push((k + 1, phi, true, travel, true));
        }
    }
    seq.sort_by(|a, b| a.3.total_cmp(&b.3));
    // A further position is named after the numbered one before it, primed once more for each
    // further one between the same two (`k′`, `k″`, `k‴`), in crank order.
    let mut out: Vec<(String, f64, bool)> = Vec::with_capacity(seq.len());
    for (k, phi, extreme, _, further) in seq {
        let label = if further {
            primed(k, |l| out.iter().any(|o| o.0 == l))
        } else {
            k.to_string()
        };
        out.push((label, phi, extreme));
    }
    out
}

/// The label of a further position after the numbered position `k`: `k′`, or `k″`, `k‴`
/// where a label before it (`taken`) holds it. The plan adds three further positions at
/// most, so the third is always free.
fn primed(k: usize, taken: impl Fn(&str) -> bool) -> String {
    ["′", "″"]
        .iter()
        .map(|m| format!("{k}{m}"))
        .find(|l| !taken(l))
        .unwrap_or_else(|| format!("{k}‴"))
}

/// The positions a plan of positions will construct, solved analytically: what a sheet
/// needs to choose its scales before anything is drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanPoses {
    /// The compiled mechanism.
    pub program: Program,
    /// Extremes, when the outputs have them.
    pub extremes: Option<Extremes>,
    /// Positions in the order of crank rotation from position 1.
    pub positions: Vec<PosePosition>,
}

/// The positions of the plan of `m` asked for by `req`, solved analytically.
pub fn plan_poses(m: &Mechanism, req: &PlanRequest) -> Result<PlanPoses, LinkageError> {
    let program = Program::compile(m)?;
    let (extremes, start) = start_of(&program, m, req)?;
    let positions = walk(m, req, &program, start, extremes.as_ref(), |_, _, _| Ok(()))?;
    Ok(PlanPoses {
        program,
        extremes,
        positions,
    })
}

/// Walk the positions of the plan in crank order: at each, `build` (label, φ, the previous
/// position when assembly goes by continuity) constructs what the plan draws, then the
/// analytic twin is solved. A construction that fails is reported with its own diagnosis.
pub(super) fn walk<B>(
    m: &Mechanism,
    req: &PlanRequest,
    program: &Program,
    start: f64,
    extremes: Option<&Extremes>,
    mut build: impl FnMut(&str, f64, Option<&Position<B>>) -> Result<B, LinkageError>,
) -> Result<Vec<Position<B>>, LinkageError> {
    let mut positions: Vec<Position<B>> = Vec::new();
    for (label, phi, extreme) in sequence(req, start, m.crank.sense, extremes) {
        let prev = positions.last().filter(|_| req.continuity);
        let built = build(&label, phi, prev)?;
        let pose = program
            .solve(phi, prev.map(|p| &p.pose))
            .map_err(|u| cannot_assemble(m, &label, phi, u.group, u.detail))?;
        positions.push(Position {
            label,
            phi,
            extreme,
            built,
            pose,
        });
    }
    Ok(positions)
}

/// The extremes and the crank angle of position 1. With a given start angle the extremes
/// are optional: a mechanism whose output turns fully has none, and one that cannot make a
/// full turn fails at a named position later.
pub(super) fn start_of(
    program: &Program,
    m: &Mechanism,
    req: &PlanRequest,
) -> Result<(Option<Extremes>, f64), LinkageError> {
    let found = program.extremes(&m.outputs, m.crank.sense, m.driving);
    match req.start {
        Some(s) => Ok((found.ok(), s)),
        None => {
            let ex = found?;
            let s = ex.phi_start;
            Ok((Some(ex), s))
        }
    }
}

pub(super) fn cannot_assemble(
    m: &Mechanism,
    label: &str,
    phi: f64,
    group: usize,
    detail: String,
) -> LinkageError {
    LinkageError::CannotAssemble {
        position: label.to_string(),
        phi_deg: phi.to_degrees(),
        group: group_name(m, group),
        detail,
    }
}

/// `2 (RRR, links 2, 3)`.
pub fn group_name(m: &Mechanism, g: usize) -> String {
    m.groups.get(g).map_or_else(
        || format!("{}", g + 1),
        |gr| {
            format!(
                "{} ({}, links {}, {})",
                g + 1,
                gr.dyad.kind().letters(),
                gr.links[0],
                gr.links[1]
            )
        },
    )
}
