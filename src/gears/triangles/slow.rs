//! The slow links read again: when the plan of angular velocities puts the output's intercept
//! within [`READABLE_MM`] of the foot (a train of u = 20 and more), a reading to the drafting
//! resolution errs by more than 5 % of it. The links from a pivot — a link the plan reads
//! well — to the output are then drawn once more, as a picture of their own (the sheet sets it
//! beside the first, at the same heights): the pivot's velocity at its pole with a link of
//! the route (ω as read off the first plan times the pole's radius) laid off at a finer μ_v,
//! every other line of the route through two known points as before, and a plan of angular
//! velocities of their own at the first plan's h. The picture draws the route's stage only —
//! its axes and its own poles —, not the pivot's other meshes; its plan, at the same h over a
//! stage no higher than the train, stands no higher than the first's. u is read stage by
//! stage, as the product of the two plans' readings (seed 002 §3.7: the stages' tan ψ ratios
//! multiplied).

use super::{
    distribution_lines, draw_links, draw_plan, given_height, mark_axes, slopes_of, Given, Heights,
    Readings,
};
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::gears::train::{Train, TrainError};
use crate::geom::{DVec2, Segment};
use crate::scale::{Quantity, Scale};

/// The shortest intercept the plan reads well, mm: read to the nearest 0,5 mm, it errs by
/// at most 0,25 mm, 5 % of it. (PZ2's example 3 reads its carrier at 2,5 mm: ±10 %.)
pub const READABLE_MM: f64 = 5.0;

/// The slow links' picture: the links from the pivot to the output at their own μ_v, with
/// their plan of angular velocities.
#[derive(Debug, Clone, PartialEq)]
pub struct SlowLinks {
    /// The pivot: the link both plans read, its velocity laid off from the first.
    pub pivot: usize,
    /// The links drawn, the pivot and the output among them, in shaft order.
    pub links: Vec<usize>,
    /// μ_v of this picture.
    pub scale_v: Scale,
    /// The pole distance h of its plan, mm.
    pub plan_h: f64,
    /// μ_ω = μ_v/(μ_l·h) of its plan.
    pub scale_w: Scale,
    /// Where its heading (its links, μ_v and μ_ω, the last line lowest) is written, centred
    /// over its plan, figure mm: the picture has no scheme beside its plan to write μ_ω
    /// over.
    pub heading_at: DVec2,
    /// The picture and its plan.
    pub figure: Figure,
    /// ω of every link drawn as read off its plan, rad/s (0 for the others).
    pub omega: Vec<f64>,
    /// Every drawn link's intercept (shaft, drawn, read, mm).
    pub ends: Vec<(usize, f64, f64)>,
}

/// A pivot tried: its route, μ_v, slopes at that μ_v and the plan's h.
struct Route {
    pivot: usize,
    links: Vec<usize>,
    scale_v: Scale,
    ends: Vec<(DVec2, DVec2)>,
    slopes: Vec<f64>,
    plan_h: f64,
}

/// The slow links' picture of `train` (its heights `layout` drawn at `heights`) from the
/// first plan's readings `read` (the first picture's μ_v and its plan's h: `first`); `None`
/// when that plan reads the output at [`READABLE_MM`] or more, or no pivot reads it better.
/// A differential (two given links) is read on one plan.
///
/// # Errors
/// [`TrainError::Layout`] when a route's line is not fixed or its scale has no value.
pub(super) fn slow_links(
    train: &Train,
    layout: (&[f64], &[f64]),
    heights: Heights,
    read: &Readings,
    first: (f64, f64),
    ctx: &Context,
) -> Result<Option<SlowLinks>, TrainError> {
    let drawn = |k: usize| {
        read.ends
            .iter()
            .find(|e| e.0 == k)
            .map_or(0.0, |e| e.1.abs())
    };
    let out = train.output;
    // (An intercept of READABLE_MM as constructed, to the last digits, reads well.)
    if train.second.is_some() || drawn(out) >= READABLE_MM * (1.0 - 1e-9) {
        return Ok(None);
    }
    // Every pivot the first plan reads longer than the output: the one whose least reading
    // on the way (its own on the first plan, the output's on its own) is the longest.
    let mut best: Option<(f64, Route)> = None;
    for p in 0..train.shafts.len() {
        if p == out || Some(p) == train.fixed || train.is_satellite(p) || drawn(p) <= drawn(out) {
            continue;
        }
        let Some(route) = route(train, layout, heights, (p, read.omega[p]), first)? else {
            continue;
        };
        let at = |k: usize| route.slopes[k].abs() * route.plan_h;
        let score = drawn(p).min(at(out));
        if best.as_ref().is_none_or(|(s, _)| score > *s) {
            best = Some((score, route));
        }
    }
    match best {
        Some((score, route)) if score > drawn(out) => {
            Ok(Some(draw(train, layout, heights, route, ctx)?))
        }
        _ => Ok(None),
    }
}

/// The route from pivot `p` turning at `omega` (as read): the links the output's line is
/// found through back to the pivot's, drawn from the pivot's velocity at its pole with a link
/// of the route, at a μ_v of their own: the finest round one at which the plan of the first
/// picture's h (`first`: its μ_v and h) puts the route's farthest intercept within
/// [`super::PLAN_REACH_MM`] of the foot, as the first plan's are; `None` when the output's line
/// is not found through the pivot's.
fn route(
    train: &Train,
    (ys, poles): (&[f64], &[f64]),
    heights: Heights,
    (p, omega): (usize, f64),
    (first_mv, plan_h): (f64, f64),
) -> Result<Option<Route>, TrainError> {
    let Some(first_pole) = given_height(train, p, (ys, poles)) else {
        return Ok(None);
    };
    let given = |height: f64, mv: f64| Given {
        link: p,
        height,
        omega,
        mv,
    };
    let lines = distribution_lines(train, (ys, poles), heights, given(first_pole, first_mv))?;
    let mut seen = vec![false; train.shafts.len()];
    let mut stack = vec![train.output];
    while let Some(k) = stack.pop() {
        if std::mem::replace(&mut seen[k], true) {
            continue;
        }
        if k != p {
            stack.extend(&lines.from[k]);
        }
    }
    if !seen[p] {
        return Ok(None);
    }
    let links: Vec<usize> = (0..seen.len()).filter(|k| seen[*k]).collect();
    let height = route_pole(train, (ys, poles), p, &links).unwrap_or(first_pole);
    // The velocity the route's steepest line reaches h above its axis: drawn at most
    // PLAN_REACH_MM, its ray meets the reading line there. A μ_v no finer than the first's
    // reads nothing better.
    let first = slopes_of(&lines.ends);
    let steepest = links.iter().fold(0.0f64, |m, k| m.max(first[*k].abs()));
    let reach = steepest * plan_h * first_mv;
    let Some(scale_v) = Scale::round_for(reach, super::PLAN_REACH_MM, Quantity::Velocity)
        .filter(|s| s.value() < first_mv * (1.0 - 1e-9))
    else {
        return Ok(None);
    };
    let lines = distribution_lines(train, (ys, poles), heights, given(height, scale_v.value()))?;
    let slopes = slopes_of(&lines.ends);
    Ok(Some(Route {
        pivot: p,
        links,
        scale_v,
        ends: lines.ends,
        slopes,
        plan_h,
    }))
}

/// Where the pivot `p`'s velocity is laid off on the route `links`: the pole of its first
/// mesh with a link of the route, or (a carrier) the axis of its first satellite on it;
/// `None` when it has neither.
fn route_pole(
    train: &Train,
    (ys, poles): (&[f64], &[f64]),
    p: usize,
    links: &[usize],
) -> Option<f64> {
    let on = |k: usize| k != p && links.contains(&k);
    train
        .meshes
        .iter()
        .zip(poles)
        .find(|(m, _)| {
            let (a, b) = (train.wheels[m.0].shaft, train.wheels[m.1].shaft);
            (a == p && on(b)) || (b == p && on(a))
        })
        .map(|(_, y)| *y)
        .or_else(|| {
            (Some(p) == train.carrier)
                .then(|| train.satellites.iter().find(|s| on(**s)).map(|s| ys[*s]))?
        })
        .filter(|y| (y - ys[p]).abs() > 1e-12)
}

/// The route's picture: its axis of heights over its own links, their axes, the plan of
/// angular velocities above them, and their lines and rays, read.
fn draw(
    train: &Train,
    (ys, poles): (&[f64], &[f64]),
    heights: Heights,
    r: Route,
    ctx: &Context,
) -> Result<SlowLinks, TrainError> {
    let bad = |s: &str| TrainError::Layout(s.to_string());
    let (mv, ml) = (r.scale_v.value(), heights.ml);
    let scale_w = Scale::new(mv / (ml * r.plan_h), Quantity::AngularVelocity)
        .ok_or_else(|| bad("μ_ω of the slow links"))?;
    let mut rec = Recorder::in_context("velocity triangles of the slow links", r.scale_v, ctx);
    // The heights of the route: its axes and the poles of its meshes (the pivot's given one
    // among them).
    let on = |k: usize| r.links.contains(&k);
    let spans = r
        .links
        .iter()
        .map(|k| ys[*k])
        .chain(
            train
                .meshes
                .iter()
                .zip(poles)
                .filter(|(m, _)| on(train.wheels[m.0].shaft) && on(train.wheels[m.1].shaft))
                .map(|(_, p)| *p),
        )
        .map(|y| heights.y(y));
    let (lo, hi) = spans.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), y| {
        (l.min(y), h.max(y))
    });
    rec.draw(
        "the axis of heights",
        Item::Segment(Segment::new(
            DVec2::new(0.0, lo - 5.0),
            DVec2::new(0.0, hi + 5.0),
        )),
        Role::Axis,
        &[],
    );
    let mine: Vec<f64> = r.links.iter().map(|k| r.slopes[*k]).collect();
    let plan = draw_plan(&mut rec, &mine, r.plan_h, hi + 10.0 + r.plan_h);
    mark_axes(&mut rec, train, ys, heights, &r.links);
    let read = draw_links(
        &mut rec,
        train,
        (&r.ends, &r.slopes),
        (ys, poles),
        heights,
        (&plan, scale_w),
        &r.links,
    );
    Ok(SlowLinks {
        pivot: r.pivot,
        links: r.links,
        scale_v: r.scale_v,
        plan_h: r.plan_h,
        scale_w,
        heading_at: plan.heading_at(),
        figure: rec.finish(),
        omega: read.omega,
        ends: read.ends,
    })
}
