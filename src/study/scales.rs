//! The one decider of the kinematic study's scales. Each is decided once per session, before
//! anything is constructed, and every sheet and the report ask for it: the scene's as given;
//! else the textbook's choice — μ_l draws the crank about `CRANK_MM` (50 mm), μ_v and μ_a the crank
//! pin's vector at least 80 mm — raised along the round series until its drawing, predicted
//! from the analytic twin, fits its field (the plan of positions `POSITIONS_ROOM`, which an
//! empty A1 sheet also holds; every velocity or acceleration plan `VECTOR_PLAN_ROOM`, and the
//! plans of a kind together `PLANS_AREA_MM2`).

use super::*;
use crate::construct::fit::{fit_scale, overflow, Extent};
use crate::geom::DVec2;
use crate::kinematics::{self, drawn_points};
use crate::linkage::{guide_ends, GUIDE_MARGIN_MM};
use crate::scale::Quantity;

/// Preferred drawn length of the crank when the scene gives no μ_l (textbook: 40–60 mm).
const CRANK_MM: f64 = 50.0;
/// The field of the plan of positions, mm: the right part of an A1 sheet, beside the
/// structural scheme on the positions sheet.
const POSITIONS_ROOM: DVec2 = DVec2::new(530.0, 502.0);
/// The field of a velocity or acceleration plan chosen the textbook way, mm: the crank pin's
/// vector drawn 80 mm, coarser when another vector would make the plan larger.
const VECTOR_PLAN_ROOM: DVec2 = DVec2::new(150.0, 150.0);
/// Allowance of a plan of positions: pivot symbols, slider blocks (its guides are marks).
const PLAN_ALLOWANCE: f64 = 1.0;
/// Allowance of a velocity or acceleration plan: direction lines drawn 6 mm past their
/// points, arrowheads.
const VECTOR_PLAN_ALLOWANCE: f64 = 6.0;

/// The extent of the plan of positions: every point at every position, the fixed points.
fn positions_extent(poses: &PlanPoses) -> Extent {
    let mut e = Extent::empty(PLAN_ALLOWANCE);
    for p in &poses.positions {
        for &x in &p.pose.p {
            e.add(x);
        }
    }
    for (at, dir) in guide_ends(poses) {
        e.mark(at, dir * GUIDE_MARGIN_MM);
    }
    e
}

/// The largest labelled size, at `mu`, of the plans of `kind` at the positions `ks`, each
/// drawn through its points (SI).
fn largest_plan(
    poses: &PlanPoses,
    ks: &[usize],
    w1: f64,
    kind: PlanKind,
) -> impl Fn(Scale) -> DVec2 {
    let extents: Vec<Extent> = ks
        .iter()
        .map(|&k| {
            let mut e = Extent::empty(VECTOR_PLAN_ALLOWANCE);
            drawn_points(poses, k, w1, kind)
                .into_iter()
                .for_each(|p| e.add(p));
            e
        })
        .collect();
    move |mu| {
        extents
            .iter()
            .fold(DVec2::ZERO, |m, e| m.max(e.labelled_size_at(mu)))
    }
}

/// A plan more than this many times larger than the typical plan of its kind (the lower
/// median) at the common μ is drawn at its own μ, stated beside it: the common μ is not set by
/// a few plans near a singular position (the tangent mechanism's 29.9 m/s near φ = 90°),
/// which would leave the others a few millimetres long.
const OWN_SCALE_RATIO: f64 = 3.0;

/// The positions `ks` without the plans far larger than the typical one ([`OWN_SCALE_RATIO`]),
/// sized at `mu`.
fn typical_plans(
    poses: &PlanPoses,
    ks: &[usize],
    w1: f64,
    kind: PlanKind,
    mu: Scale,
) -> Vec<usize> {
    let sizes: Vec<f64> = ks
        .iter()
        .map(|&k| largest_plan(poses, &[k], w1, kind)(mu).max_element())
        .collect();
    let mut sorted = sizes.clone();
    sorted.sort_by(f64::total_cmp);
    let Some(&typical) = sorted.get(sorted.len().saturating_sub(1) / 2) else {
        return Vec::new();
    };
    ks.iter()
        .zip(&sizes)
        .filter(|(_, &size)| size <= OWN_SCALE_RATIO * typical)
        .map(|(&k, _)| k)
        .collect()
}

/// The room all the velocity (or acceleration) plans of a sheet share, mm²: about a third of
/// an A1 sheet's drawing field, so that the plan of positions, the diagrams and the tables
/// keep theirs.
const PLANS_AREA_MM2: f64 = 175_000.0;

/// The labelled area of the plans of `kind` at the positions `ks` at `mu`, summed, mm².
fn plans_area(poses: &PlanPoses, ks: &[usize], w1: f64, kind: PlanKind, mu: Scale) -> f64 {
    ks.iter()
        .map(|&k| {
            let s = largest_plan(poses, &[k], w1, kind)(mu);
            s.x * s.y
        })
        .sum()
}

/// `start` raised along the round series until the largest of the plans `ks` fits
/// `VECTOR_PLAN_ROOM` and all of them `PLANS_AREA_MM2`.
fn plans_fit(poses: &PlanPoses, ks: &[usize], w1: f64, kind: PlanKind, start: Scale) -> Scale {
    let largest = largest_plan(poses, ks, w1, kind);
    fit_scale(start, |mu| {
        let area = plans_area(poses, ks, w1, kind, mu) / PLANS_AREA_MM2;
        overflow(largest(mu), VECTOR_PLAN_ROOM).max(area.sqrt())
    })
    .unwrap_or(start)
}

/// `start` raised along the round series until `size(μ)` fits `room`.
fn raised_to_fit(start: Scale, room: DVec2, size: impl Fn(Scale) -> DVec2) -> Scale {
    fit_scale(start, |mu| overflow(size(mu), room)).unwrap_or(start)
}

/// μ_l of the plan of positions.
struct ScaleL;
impl Cache for ScaleL {
    type Key = ();
    type Value = Result<Scale, StudyError>;
}

/// Each plan's μ, by (kind, position).
struct PlanScales;
impl Cache for PlanScales {
    type Key = (PlanKind, usize);
    type Value = Result<Scale, StudyError>;
}

/// The kinematic study's scales.
struct Scales;
impl Cache for Scales {
    type Key = ();
    type Value = Result<KinScales, StudyError>;
}

impl<'s> Session<'s> {
    /// μ_l of every drawing of the plan of positions, decided once: the scene's, else the
    /// crank drawn about `CRANK_MM` (50 mm) and raised until the plan fits `POSITIONS_ROOM`.
    pub fn scale_l(&self) -> Result<Scale, StudyError> {
        self.caches.get::<ScaleL>((), || {
            if let Some(s) = self.scene.scale_l {
                return Ok(s);
            }
            let m = self.mechanism("the plan of positions")?;
            let start = kinematics::round_scale(m.crank.length, CRANK_MM, Quantity::Length)?;
            let plan = positions_extent(&*self.poses()?);
            Ok(raised_to_fit(start, POSITIONS_ROOM, |mu| {
                plan.labelled_size_at(mu)
            }))
        })
    }

    /// The kinematic study's scales, decided once: μ_l ([`Session::scale_l`]); μ_v and μ_a the
    /// scene's, else the crank pin's vector drawn about 80 mm and raised until the largest
    /// typical plan fits `VECTOR_PLAN_ROOM` (a plan far larger takes its own,
    /// [`Session::plan_scale`]); the displacement chart's as the scene gives them (the
    /// rest chosen for the chart by the study).
    pub fn kin_scales(&self) -> Result<KinScales, StudyError> {
        self.caches.get::<Scales>((), || {
            let m = self.mechanism("the kinematic analysis")?;
            let spec = self.spec();
            let (mut v, mut a) = kinematics::plan_scales(&m.crank, spec)?;
            let (poses, w1) = (self.poses()?, self.w1()?);
            if spec.scale_v.is_none() {
                let all: Vec<usize> = (0..poses.positions.len()).collect();
                let ks = typical_plans(&poses, &all, w1, PlanKind::Velocity, v);
                v = plans_fit(&poses, &ks, w1, PlanKind::Velocity, v);
            }
            if spec.scale_a.is_none() {
                let all = self.acceleration_positions()?;
                let ks = typical_plans(&poses, &all, w1, PlanKind::Acceleration, a);
                a = plans_fit(&poses, &ks, w1, PlanKind::Acceleration, a);
            }
            Ok(KinScales {
                l: self.scale_l()?,
                v,
                a,
                chart: ChartScales {
                    s: spec.scale_s,
                    phi: spec.scale_phi,
                    h1: spec.pole_h1,
                    h2: spec.pole_h2,
                },
            })
        })
    }

    /// The μ of the plan of `kind` at position `k`: the common one of [`Session::kin_scales`],
    /// or, for a plan that does not fit `VECTOR_PLAN_ROOM` at it (one far larger than the
    /// typical plan), its own, raised until it fits. A scale the scene gives is every plan's.
    pub fn plan_scale(&self, kind: PlanKind, k: usize) -> Result<Scale, StudyError> {
        self.caches.get::<PlanScales>((kind, k), || {
            let sc = self.kin_scales()?;
            let (common, given) = match kind {
                PlanKind::Velocity => (sc.v, self.spec().scale_v.is_some()),
                PlanKind::Acceleration => (sc.a, self.spec().scale_a.is_some()),
            };
            if given {
                return Ok(common);
            }
            let size = largest_plan(&*self.poses()?, &[k], self.w1()?, kind);
            Ok(raised_to_fit(common, VECTOR_PLAN_ROOM, size))
        })
    }
}
