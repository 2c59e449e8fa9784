//! Velocity and acceleration plans at the positions of the plan of positions, and their
//! readings against the analytic twin.

use super::KinError;
use crate::check::{Key, Method, Row, Symbol};
use crate::construct::{ConstructionError, Context};
use crate::geom::DVec2;
use crate::linkage::{
    kin_plan, plain, KinPlan, Measure, PlanKind, PlanPoses, PlanSetup, Pose, PositionPlan,
};
use crate::scale::{Quantity, Scale};
use std::f64::consts::TAU;

/// A velocity plan at one position: built, or refused where it does not exist.
#[derive(Debug, Clone, PartialEq)]
pub enum Velocity {
    /// The plan with its rows.
    Built {
        /// The plan.
        plan: KinPlan,
        /// Its readings against the analytic twin.
        rows: Vec<Row>,
    },
    /// A dyad at its toggle position: the plan does not exist; the diagnosis says why.
    Refused(String),
}

impl Velocity {
    /// The plan, when it exists.
    pub fn plan(&self) -> Option<&KinPlan> {
        match self {
            Velocity::Built { plan, .. } => Some(plan),
            Velocity::Refused(_) => None,
        }
    }
    /// Its rows (none when refused).
    pub fn rows(&self) -> &[Row] {
        match self {
            Velocity::Built { rows, .. } => rows,
            Velocity::Refused(_) => &[],
        }
    }
}

fn setup<'a>(
    plan: &'a PositionPlan,
    k: usize,
    mu_l: f64,
    w1: f64,
    ctx: &Context,
) -> Result<PlanSetup<'a>, KinError> {
    let pos = plan.positions.get(k).ok_or(KinError::NoIndex {
        index: k,
        count: plan.positions.len(),
    })?;
    Ok(PlanSetup {
        prog: &plan.program,
        built: &pos.built,
        mu_l: Scale::new(mu_l, Quantity::Length).ok_or(KinError::NoLengthScale(mu_l))?,
        w1,
        ctx: *ctx,
    })
}

/// The velocity plan at position `k` of `plan` (drawn at μ_l = `mu_l`) at μ_v = `scale`.
pub fn velocity(
    plan: &PositionPlan,
    k: usize,
    mu_l: f64,
    w1: f64,
    scale: Scale,
    ctx: &Context,
) -> Result<Velocity, KinError> {
    let s = setup(plan, k, mu_l, w1, ctx)?;
    let pos = &plan.positions[k];
    match kin_plan(&s, PlanKind::Velocity, scale, None) {
        Ok(vp) => {
            let rows = rows(plan, k, &vp, w1);
            Ok(Velocity::Built { plan: vp, rows })
        }
        Err((group, error @ ConstructionError::LinesParallel { .. })) => {
            Ok(Velocity::Refused(format!("group {}: {error}", group + 1)))
        }
        Err((group, error)) => Err(KinError::Plan {
            position: pos.label.clone(),
            kind: PlanKind::Velocity,
            group: group + 1,
            error: Box::new(error),
        }),
    }
}

/// The acceleration plan at position `k` from its velocity plan `vp`, at μ_a = `scale`, with
/// its rows.
pub fn acceleration(
    plan: &PositionPlan,
    k: usize,
    mu_l: f64,
    w1: f64,
    vp: &KinPlan,
    scale: Scale,
    ctx: &Context,
) -> Result<(KinPlan, Vec<Row>), KinError> {
    let s = setup(plan, k, mu_l, w1, ctx)?;
    let ap = kin_plan(&s, PlanKind::Acceleration, scale, Some(vp)).map_err(|(group, error)| {
        KinError::Plan {
            position: plan.positions[k].label.clone(),
            kind: PlanKind::Acceleration,
            group: group + 1,
            error: Box::new(error),
        }
    })?;
    let rows = rows(plan, k, &ap, w1);
    Ok((ap, rows))
}

/// The points a velocity (or acceleration) plan at position `k` of `poses` draws, from the
/// analytic twin, m/s (m/s²): the pole, every point's image and, on an acceleration plan,
/// the end of each normal component laid from a link's origin — what a sheet sizes the plan
/// by before constructing it.
pub fn drawn_points(poses: &PlanPoses, k: usize, w1: f64, kind: PlanKind) -> Vec<DVec2> {
    let Some(pose) = poses.positions.get(k).map(|p| &p.pose) else {
        return Vec::new();
    };
    let mut out = vec![DVec2::ZERO];
    for j in 0..pose.p.len() {
        match kind {
            PlanKind::Velocity => out.push(pose.dp[j] * w1),
            PlanKind::Acceleration => {
                out.push(pose.ddp[j] * (w1 * w1));
                for l in poses.program.links_of(j).into_iter().filter(|&l| l > 0) {
                    let o = pose.origin[l];
                    let w = pose.dangle[l] * w1;
                    out.push(pose.ddp[o] * (w1 * w1) - (pose.p[j] - pose.p[o]) * (w * w));
                }
            }
        }
    }
    out
}

/// Velocity of the point `k` carried by link `l`, and its acceleration (m/s, m/s²).
fn carried(pose: &Pose, w1: f64, k: usize, l: usize) -> (DVec2, DVec2) {
    if l == 0 {
        return (DVec2::ZERO, DVec2::ZERO);
    }
    let o = pose.origin[l];
    let r = pose.p[k] - pose.p[o];
    let (w, e) = (pose.dangle[l], pose.ddangle[l]);
    let v = pose.dp[o] + r.perp() * w;
    let a = pose.ddp[o] + r.perp() * e - r * (w * w);
    (v * w1, a * (w1 * w1))
}

/// The analytic value of a reading.
fn analytic(pose: &Pose, w1: f64, what: Measure, kind: PlanKind) -> f64 {
    let vel = kind == PlanKind::Velocity;
    match what {
        Measure::Point(k) if vel => (pose.dp[k] * w1).length(),
        Measure::Point(k) => (pose.ddp[k] * (w1 * w1)).length(),
        Measure::Rate(l) if vel => pose.dangle[l] * w1,
        Measure::Rate(l) => pose.ddangle[l] * w1 * w1,
        Measure::Carried(k, l) => {
            let (v, a) = carried(pose, w1, k, l);
            if vel {
                v.length()
            } else {
                a.length()
            }
        }
        Measure::Relative { p, q } => {
            let (vp, ap) = carried(pose, w1, p.0, p.1);
            let (vq, aq) = carried(pose, w1, q.0, q.1);
            if vel {
                (vp - vq).length()
            } else {
                (ap - aq).length()
            }
        }
    }
}

/// The typed key of a reading.
fn key(plan: &PositionPlan, what: Measure, kind: PlanKind, label: &str) -> Key {
    let names = &plan.program.names;
    let (point, relative, rate) = match kind {
        PlanKind::Velocity => (Symbol::Velocity, Symbol::Velocity, Symbol::AngularVelocity),
        PlanKind::Acceleration => (
            Symbol::Acceleration,
            Symbol::Acceleration,
            Symbol::AngularAcceleration,
        ),
    };
    let (symbol, subject) = match what {
        Measure::Point(k) => (point, plain(&names[k])),
        Measure::Rate(l) => (rate, l.to_string()),
        Measure::Carried(k, l) => (point, format!("{}{l}", plain(&names[k]))),
        Measure::Relative { p, q } => {
            // Coincident points of a sliding pair carry their link's number (`B3_B1`).
            let tag = |(k, l): (usize, usize)| {
                let suffix = if p.0 == q.0 {
                    l.to_string()
                } else {
                    String::new()
                };
                format!("{}{suffix}", plain(&names[k]))
            };
            (relative, format!("{}_{}", tag(p), tag(q)))
        }
    };
    Key::at_position(symbol, subject, label)
}

/// The readings of plan `kp` at position `k`, each with its analytic twin and the
/// quantity's scale over the positions of the plan.
fn rows(plan: &PositionPlan, k: usize, kp: &KinPlan, w1: f64) -> Vec<Row> {
    let pos = &plan.positions[k];
    kp.readings
        .iter()
        .map(|r| {
            let scale = super::peak(
                plan.positions
                    .iter()
                    .map(|p| analytic(&p.pose, w1, r.what, kp.kind)),
            );
            Row::new(
                key(plan, r.what, kp.kind, &pos.label),
                Method::Plan,
                r.value,
                analytic(&pos.pose, w1, r.what, kp.kind),
                scale,
            )
            .conditioned(r.conditioning)
        })
        .collect()
}

/// The positions named by the scene key `kinematics.{key}` (`asked`), as indices into
/// `labels` (each position's label and whether it is an extreme position).
pub fn position_indices(
    labels: &[(&str, bool)],
    asked: &[String],
    key: &'static str,
) -> Result<Vec<usize>, KinError> {
    asked
        .iter()
        .map(|l| {
            labels
                .iter()
                .position(|p| p.0 == l)
                .ok_or_else(|| KinError::NoSuchPosition {
                    key,
                    label: l.clone(),
                    valid: labels.iter().map(|p| p.0.to_string()).collect(),
                })
        })
        .collect()
}

/// The positions that get an acceleration plan, as indices into `labels` (each position's
/// label and whether it is an extreme position): as asked, or one in the middle of the
/// working stroke (`work_travel` of crank, when the output has extremes) and one in the
/// middle of the return — the nearest to them that is not an extreme position nor one of
/// `avoid` (the positions whose plans take a μ of their own, `kinematics.own_scale`: near a
/// singular position, where the crank pin's acceleration is a dot beside the others), nor
/// one that `alike` finds in the configuration of one chosen already (the tangent
/// mechanism's block on the crank's line stands where it stood half a turn before).
pub fn acceleration_indices(
    labels: &[(&str, bool)],
    work_travel: Option<f64>,
    (asked, avoid): (Option<&[String]>, &[usize]),
    alike: impl Fn(usize, usize) -> bool,
) -> Result<Vec<usize>, KinError> {
    if let Some(asked) = asked {
        return position_indices(labels, asked, "acceleration_positions");
    }
    let work = work_travel.unwrap_or(TAU / 2.0);
    let numbered = labels.iter().filter(|p| p.0.parse::<u32>().is_ok()).count();
    let step = TAU / numbered.max(1) as f64;
    // Crank travel from position 1 in the sense of rotation; extremes are never chosen.
    let travel = |k: usize| match labels[k].0.parse::<u32>() {
        Ok(n) if !labels[k].1 => step * (n - 1) as f64,
        _ => f64::INFINITY,
    };
    let mut out = Vec::new();
    for target in [work / 2.0, work + (TAU - work) / 2.0] {
        let best = (0..labels.len())
            .filter(|&k| !labels[k].1 && !avoid.contains(&k))
            .filter(|&k| !out.iter().any(|&o| alike(o, k)))
            .min_by(|&a, &b| angular(travel(a), target).total_cmp(&angular(travel(b), target)));
        if let Some(k) = best.filter(|k| !out.contains(k)) {
            out.push(k);
        }
    }
    Ok(out)
}

fn angular(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}
