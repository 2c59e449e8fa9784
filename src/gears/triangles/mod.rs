//! The velocity triangles of a train (Smirnov / Kutzbach): the axes and the mesh poles at
//! their heights at μ_l, the distribution line of each link through two known points, and
//! the plan of angular velocities — rays from the pole p_ω at h under the reading line,
//! parallel to the lines, each named by its link where it meets the reading line; the
//! intercepts from the foot 0 of the pole read ω at μ_ω = μ_v/(μ_l·h).

use super::train::{Train, TrainError};
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::{DVec2, Segment};
use crate::scale::{Quantity, Scale};

mod names;
mod slow;
pub use slow::SlowLinks;

/// The velocity triangles and the plan of angular velocities, and what was read off them.
#[derive(Debug, Clone, PartialEq)]
pub struct Triangles {
    /// μ_l of the heights.
    pub scale_l: Scale,
    /// μ_v of the velocities.
    pub scale_v: Scale,
    /// The pole distance h of the plan of angular velocities, mm.
    pub plan_h: f64,
    /// μ_ω = μ_v/(μ_l·h) of the plan.
    pub scale_w: Scale,
    /// Where the plan's μ_ω is written, ending there: past the left end of its reading line
    /// ([`Plan::scale_at`]), figure mm.
    pub scale_w_at: DVec2,
    /// The picture of linear velocities (and the plan of angular velocities beside it).
    pub figure: Figure,
    /// ω of every shaft read off the plan, rad/s (intercepts as read × μ_ω).
    pub omega: Vec<f64>,
    /// u = ω_in/ω_out as read (the intercepts' ratio).
    pub ratio: f64,
    /// The slow links' own picture, when this plan cannot read the output.
    pub slow: Option<SlowLinks>,
}

/// The name of the plan's pole distance: h, since H names the carrier.
pub const POLE_DISTANCE: &str = "h";

/// The pole distances h of the plan of angular velocities a student picks from, mm, the
/// largest first.
pub const PLAN_H: [f64; 9] = [60.0, 50.0, 40.0, 30.0, 25.0, 20.0, 15.0, 10.0, 5.0];

/// The farthest an intercept of the plan may fall from the pole's foot, mm: h is the largest
/// of [`PLAN_H`] that keeps the fastest link's within it and makes μ_ω round (1, 2, 2.5, 4,
/// 5 × 10ⁿ), or failing that the largest that keeps it within.
pub const PLAN_REACH_MM: f64 = 100.0;

/// The longest the span of a train's radii is drawn, mm (μ_l round, at most this): under
/// the height an A3 sheet leaves a drawing beside its data and table.
const TRIANGLES_SPAN_MM: f64 = 180.0;

/// The gap between the kinematic scheme (its rightmost line, support or name) and the
/// leftmost velocity, mm.
const SCHEME_GAP_MM: f64 = 10.0;

/// How far the reading line runs past the outermost intercepts, mm.
const PLAN_OVERHANG_MM: f64 = 8.0;

/// How far the dimension h stands past the end of the reading line, mm.
const PLAN_DIMENSION_MM: f64 = 4.0;

/// How far above the reading line a text over the plan is written (the middle of its line),
/// mm: a line above the rays' names.
const PLAN_HEADING_MM: f64 = 9.0;

/// The height where a given shaft's velocity is laid off: its first pole, or a carrier's
/// first satellite's axis; `None` when it has neither off its own axis.
fn given_height(train: &Train, k: usize, (ys, poles): (&[f64], &[f64])) -> Option<f64> {
    train
        .meshes
        .iter()
        .zip(poles)
        .find(|(m, _)| train.wheels[m.0].shaft == k || train.wheels[m.1].shaft == k)
        .map(|(_, p)| *p)
        .or_else(|| (Some(k) == train.carrier).then(|| train.satellites.first().map(|&s| ys[s]))?)
        .filter(|h| (h - ys[k]).abs() > 1e-12)
}

/// Heights on the drawing: a height y (m) is drawn (y − lo)/μ_l above the lowest.
#[derive(Debug, Clone, Copy)]
struct Heights {
    lo: f64,
    ml: f64,
}

impl Heights {
    /// The drawn height of `y`, mm.
    fn y(&self, y: f64) -> f64 {
        (y - self.lo) / self.ml
    }
}

/// A line given by two drawn points: its x at the drawn height `y`.
fn x_at(l: &(DVec2, DVec2), y: f64) -> f64 {
    let (a, b) = *l;
    a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y)
}

/// The plan of angular velocities as drawn: its pole, the pole's foot on the reading line
/// (the intercepts' origin), the pole distance h, the reading line's ends.
struct Plan {
    pole: DVec2,
    foot: DVec2,
    h: f64,
    left: f64,
    right: f64,
}

impl Plan {
    /// Where its μ_ω is written, ending there: level with the reading line, past its left
    /// end and the dimension h that may stand there. On the first picture that is over the
    /// kinematic scheme (drawn left of the velocities, below the plan), a room nothing else
    /// takes; it neither widens the picture to the right nor heightens it, so that a second
    /// picture can stand close beside it.
    fn scale_at(&self) -> DVec2 {
        DVec2::new(
            self.left - PLAN_DIMENSION_MM - PLAN_OVERHANG_MM,
            self.foot.y,
        )
    }

    /// Where a heading over the plan is written: centred over the reading line,
    /// [`PLAN_HEADING_MM`] above it.
    fn heading_at(&self) -> DVec2 {
        DVec2::new(
            0.5 * (self.left + self.right),
            self.foot.y + PLAN_HEADING_MM,
        )
    }
}

/// What the links' lines and rays read: ω of every shaft, every drawn link's intercept
/// (shaft, drawn, read, mm), and the leftmost velocity drawn.
struct Readings {
    omega: Vec<f64>,
    ends: Vec<(usize, f64, f64)>,
    leftmost: f64,
}

/// Construct the velocity triangles of `train` for the input turning at `omega_in` rad/s
/// in `ctx`.
///
/// # Errors
/// [`TrainError::Layout`] when the scheme cannot be laid out, `omega_in` is 0 or not finite,
/// or a link's line is not fixed.
pub fn triangles(train: &Train, omega_in: f64, ctx: &Context) -> Result<Triangles, TrainError> {
    let (ys, poles) = train.layout()?;
    let lo = ys
        .iter()
        .chain(&poles)
        .fold(f64::INFINITY, |a, v| a.min(*v));
    let hi = ys
        .iter()
        .chain(&poles)
        .fold(f64::NEG_INFINITY, |a, v| a.max(*v));
    let span = (hi - lo).max(train.module);
    let bad = |s: &str| TrainError::Layout(s.to_string());
    // The scheme's span at most TRIANGLES_SPAN_MM: a train's triangles with its data and
    // its table fit an A3 sheet.
    let mu_l =
        Scale::round_for(span, TRIANGLES_SPAN_MM, Quantity::Length).ok_or_else(|| bad("μ_l"))?;
    // The input's pole: the first mesh of the input shaft (a carrier's: its satellite's axis).
    let pin = given_height(train, train.input, (&ys, &poles))
        .ok_or_else(|| bad("the input has no pole off its axis"))?;
    if !(omega_in.is_finite() && omega_in != 0.0) {
        return Err(bad("the input's ω is 0 or not finite"));
    }
    let v_in = (pin - ys[train.input]).abs().max(train.module) * omega_in.abs();
    let mu_v = Scale::round_for(v_in, 60.0, Quantity::Velocity).ok_or_else(|| bad("μ_v"))?;
    let mut rec = Recorder::in_context("velocity triangles", mu_v, ctx);
    let (ml, mv) = (mu_l.value(), mu_v.value());
    let heights = Heights { lo, ml };
    // The axis of heights.
    rec.draw(
        "the axis of heights",
        Item::Segment(Segment::new(
            DVec2::new(0.0, -5.0),
            DVec2::new(0.0, heights.y(hi) + 5.0),
        )),
        Role::Axis,
        &[],
    );
    let given = Given {
        link: train.input,
        height: pin,
        omega: omega_in,
        mv,
    };
    let lines = distribution_lines(train, (&ys, &poles), heights, given)?;
    // The slope of each line (its v over its height, drawn mm per mm): a ray's intercept is
    // h times it.
    let slopes = slopes_of(&lines.ends);
    let plan_h = plan_distance(&slopes, (mv, ml));
    let scale_w =
        Scale::new(mv / (ml * plan_h), Quantity::AngularVelocity).ok_or_else(|| bad("μ_ω"))?;
    let plan = draw_plan(&mut rec, &slopes, plan_h, heights.y(hi) + 10.0 + plan_h);
    let all: Vec<usize> = (0..train.shafts.len()).collect();
    mark_axes(&mut rec, train, &ys, heights, &all);
    let read = draw_links(
        &mut rec,
        train,
        (&lines.ends, &slopes),
        (&ys, &poles),
        heights,
        (&plan, scale_w),
        &all,
    );
    // The slow links read again on a picture of their own when this plan cannot read the
    // output; the ratio from the better reading of each link.
    let slow = slow::slow_links(train, (&ys, &poles), heights, &read, (mv, plan_h), ctx)?;
    let mut omega = read.omega.clone();
    let mut ends: Vec<(usize, f64, f64)> = read.ends.clone();
    if let Some(s) = &slow {
        for &k in s.links.iter().filter(|k| **k != s.pivot) {
            omega[k] = s.omega[k];
        }
        ends.retain(|e| !s.links.contains(&e.0) || e.0 == s.pivot);
        ends.extend(s.ends.iter().filter(|e| e.0 != s.pivot));
    }
    // A resolution that reads the input's or the output's intercept as 0 leaves no ratio.
    let ends: Vec<&(usize, f64, f64)> = ends
        .iter()
        .filter(|e| e.0 == train.input || e.0 == train.output)
        .collect();
    if ends
        .iter()
        .any(|(_, drawn, read)| *read == 0.0 && *drawn > 0.0)
    {
        if let Some((k, drawn, _)) = ends
            .iter()
            .filter(|(_, drawn, _)| *drawn > 0.0)
            .min_by(|a, b| a.1.total_cmp(&b.1))
        {
            return Err(TrainError::Unreadable {
                shaft: train.shafts[*k].clone(),
                drawn_mm: *drawn,
                resolution_mm: ctx.drafting.resolution_mm(),
            });
        }
    }
    let (wi, wo) = (omega[train.input], omega[train.output]);
    if wo.abs() < 1e-300 {
        return Err(TrainError::OutputAtRest);
    }
    // The kinematic scheme to the left of the velocities as drawn, at their heights.
    super::scheme::draw_scheme(
        &mut rec,
        train,
        (&ys, &poles),
        |y| heights.y(y),
        ml,
        read.leftmost - SCHEME_GAP_MM,
    );
    Ok(Triangles {
        scale_l: mu_l,
        scale_v: mu_v,
        plan_h,
        scale_w,
        scale_w_at: plan.scale_at(),
        figure: rec.finish(),
        omega,
        ratio: wi / wo,
        slow,
    })
}

/// The slope of each distribution line: its v over its height, drawn mm per mm (a ray's
/// intercept is h times it).
fn slopes_of(ends: &[(DVec2, DVec2)]) -> Vec<f64> {
    ends.iter()
        .map(|(a, b)| (b.x - a.x) / (b.y - a.y))
        .collect()
}

/// The heights of the axes of `links`, marked on the axis of heights.
fn mark_axes(rec: &mut Recorder, train: &Train, ys: &[f64], heights: Heights, links: &[usize]) {
    for &k in links {
        let y = heights.y(ys[k]);
        rec.draw(
            format!("the axis of {}", train.shafts[k]),
            Item::Segment(Segment::new(DVec2::new(-3.0, y), DVec2::new(3.0, y))),
            Role::Construction,
            &[],
        );
    }
}

/// Each link's distribution line as two drawn points (x = v/μ_v, y = its drawn height): the
/// fixed shaft's on the axis; the input's through its axis and the velocity ω_in·r at its
/// pole `pin` (ω_in, μ_v); a differential's second input's likewise; every other
/// link's through two known points at distinct heights (its axis, a pole shared with a link
/// already drawn, a satellite's axis on the carrier's line).
///
/// # Errors
/// [`TrainError::Layout`] when a link's line is not fixed.
fn distribution_lines(
    train: &Train,
    (ys, poles): (&[f64], &[f64]),
    heights: Heights,
    given: Given,
) -> Result<Lines, TrainError> {
    let n = train.shafts.len();
    let yy = |y: f64| heights.y(y);
    let mut lines: Vec<Option<(DVec2, DVec2)>> = vec![None; n];
    let mut from: Vec<Vec<usize>> = vec![Vec::new(); n];
    if let Some(f) = train.fixed {
        lines[f] = Some((DVec2::new(0.0, yy(ys[f])), DVec2::new(0.0, yy(ys[f]) + 1.0)));
    }
    // Given: the link's pole velocity ω·r.
    let (g, pin, omega_in, mv) = (given.link, given.height, given.omega, given.mv);
    lines[g] = Some((
        DVec2::new(0.0, yy(ys[g])),
        DVec2::new((pin - ys[g]) * omega_in / mv, yy(pin)),
    ));
    // A differential's second input: its line through its axis and the velocity at its
    // first pole (the carrier's: at its first satellite's axis).
    if let Some((k, w)) = train.second.filter(|_| g == train.input) {
        let height = given_height(train, k, (ys, poles)).ok_or_else(|| {
            TrainError::Layout("the second input has no pole off its axis".to_string())
        })?;
        lines[k] = Some((
            DVec2::new(0.0, yy(ys[k])),
            DVec2::new((height - ys[k]) * w * omega_in / mv, yy(height)),
        ));
    }
    for _ in 0..2 * n + 2 {
        for k in 0..n {
            if lines[k].is_some() {
                continue;
            }
            // Each known point with the link whose line gave it (`None`: its own axis).
            let mut pts: Vec<(DVec2, Option<usize>)> = Vec::new();
            let sat = train.is_satellite(k);
            if !sat {
                pts.push((DVec2::new(0.0, yy(ys[k])), None));
            }
            for (mi, m) in train.meshes.iter().enumerate() {
                for (a, b) in [(m.0, m.1), (m.1, m.0)] {
                    let other = train.wheels[b].shaft;
                    if train.wheels[a].shaft == k {
                        if let Some(l) = &lines[other] {
                            let y = yy(poles[mi]);
                            pts.push((DVec2::new(x_at(l, y), y), Some(other)));
                        }
                    }
                }
            }
            if let Some(h) = train.carrier {
                if sat {
                    if let Some(l) = &lines[h] {
                        pts.push((DVec2::new(x_at(l, yy(ys[k])), yy(ys[k])), Some(h)));
                    }
                } else if k == h {
                    for &s in &train.satellites {
                        if let Some(l) = &lines[s] {
                            pts.push((DVec2::new(x_at(l, yy(ys[s])), yy(ys[s])), Some(s)));
                        }
                    }
                }
            }
            // Two points at distinct heights fix the line.
            if let Some(p0) = pts.first().copied() {
                if let Some(p1) = pts.iter().copied().find(|p| (p.0.y - p0.0.y).abs() > 1e-9) {
                    lines[k] = Some((p0.0, p1.0));
                    from[k] = [p0.1, p1.1].into_iter().flatten().collect();
                }
            }
        }
    }
    let ends = lines
        .into_iter()
        .enumerate()
        .map(|(k, l)| {
            l.ok_or_else(|| {
                TrainError::Layout(format!(
                    "the velocities of shaft {} cannot be drawn",
                    train.shafts[k]
                ))
            })
        })
        .collect::<Result<_, _>>()?;
    Ok(Lines { ends, from })
}

/// The link whose velocity is laid off first, at its pole: `height` (m), turning at
/// `omega` rad/s, drawn at μ_v = `mv`.
#[derive(Debug, Clone, Copy)]
struct Given {
    link: usize,
    height: f64,
    omega: f64,
    mv: f64,
}

/// The distribution lines of every link (two drawn points each), and for each the links
/// whose lines gave its points.
struct Lines {
    ends: Vec<(DVec2, DVec2)>,
    from: Vec<Vec<usize>>,
}

/// The pole distance h of the plan: the largest of [`PLAN_H`] within the reach whose
/// μ_ω = μ_v/(μ_l·h) is round; the largest within it otherwise.
fn plan_distance(slopes: &[f64], (mv, ml): (f64, f64)) -> f64 {
    let steepest = slopes.iter().fold(0.0_f64, |m, s| m.max(s.abs()));
    let reach = |h: &f64| steepest * h <= PLAN_REACH_MM;
    let round = |h: &f64| {
        let w = mv / (ml * h);
        Scale::round_for(w, 1.0, Quantity::AngularVelocity)
            .is_some_and(|r| (r.value() - w).abs() <= 1e-9 * w)
    };
    PLAN_H
        .into_iter()
        .find(|h| reach(h) && round(h))
        .or_else(|| PLAN_H.into_iter().find(reach))
        .unwrap_or(PLAN_H[PLAN_H.len() - 1])
}

/// The plan's frame with its reading line at the drawn height `y_ref`: the reading line past
/// the outermost intercepts, the pole p_ω h below it, its foot 0, and the dimension h.
fn draw_plan(rec: &mut Recorder, slopes: &[f64], plan_h: f64, y_ref: f64) -> Plan {
    let pole = DVec2::new(0.0, y_ref - plan_h);
    let foot = DVec2::new(0.0, y_ref);
    let (left, right) = slopes.iter().fold((0.0_f64, 0.0_f64), |(l, r), s| {
        (l.min(s * plan_h), r.max(s * plan_h))
    });
    let (left, right) = (left - PLAN_OVERHANG_MM, right + PLAN_OVERHANG_MM);
    rec.draw(
        "the reading line of the plan of ω, H above the pole",
        Item::Segment(Segment::new(
            DVec2::new(left, y_ref),
            DVec2::new(right, y_ref),
        )),
        Role::Construction,
        &[],
    );
    rec.point(
        "the pole of the plan of ω",
        pole,
        Role::Given,
        "p_ω",
        DVec2::new(-1.0, -0.5),
        &[],
    );
    // The intercepts are read from the pole's foot 0; h is the pole's distance.
    rec.point(
        "the foot of the pole on the reading line: the origin of the intercepts",
        foot,
        Role::Construction,
        "0",
        DVec2::new(-0.4, 1.0),
        &[],
    );
    // The dimension h past the nearer end of the reading line, clear of the rays and their
    // names (its offset is to the left of pole → foot: −x).
    let (side, reach_mm) = if -left <= right {
        (1.0, -left)
    } else {
        (-1.0, right)
    };
    let h_dim = rec.draw(
        "the pole distance H",
        Item::Dimension {
            from: pole,
            to: foot,
            offset: side * (reach_mm + PLAN_DIMENSION_MM),
        },
        Role::Dimension,
        &[],
    );
    rec.label(
        h_dim,
        POLE_DISTANCE,
        0.5 * (pole + foot),
        DVec2::new(-side, 0.0),
    );
    Plan {
        pole,
        foot,
        h: plan_h,
        left,
        right,
    }
}

/// Each link: the velocities of its poles, its distribution line between its own points
/// (named beside it), and the ray of the plan parallel to it, named and read where
/// it meets the reading line: ω = intercept·μ_ω, signed by the side.
fn draw_links(
    rec: &mut Recorder,
    train: &Train,
    (lines, slopes): (&[(DVec2, DVec2)], &[f64]),
    (ys, poles): (&[f64], &[f64]),
    heights: Heights,
    (plan, scale_w): (&Plan, Scale),
    links: &[usize],
) -> Readings {
    let yy = |y: f64| heights.y(y);
    let mut out = Readings {
        omega: vec![0.0; train.shafts.len()],
        ends: Vec::new(),
        leftmost: 0.0,
    };
    let (mut named, mut arrows) = (Vec::new(), Vec::new());
    for &k in links {
        let line = &lines[k];
        // The link's own points: its axis and its poles with the links drawn; its line drawn
        // between them.
        let with = |o: usize| links.contains(&o);
        let mut hs = vec![yy(ys[k])];
        for (mi, m) in train.meshes.iter().enumerate() {
            let (a, b) = (train.wheels[m.0].shaft, train.wheels[m.1].shaft);
            if (a == k && with(b)) || (b == k && with(a)) {
                hs.push(yy(poles[mi]));
                let tip = DVec2::new(x_at(line, yy(poles[mi])), yy(poles[mi]));
                if tip.x.abs() > 1e-9 {
                    arrows.push((DVec2::new(0.0, tip.y), tip));
                    rec.draw(
                        "the velocity of the pole",
                        Item::Vector {
                            from: DVec2::new(0.0, tip.y),
                            to: tip,
                        },
                        Role::Result,
                        &[],
                    );
                }
            }
        }
        if train.carrier == Some(k) {
            hs.extend(
                train
                    .satellites
                    .iter()
                    .filter(|s| with(**s))
                    .map(|s| yy(ys[*s])),
            );
        }
        let (ylo, yhi) = hs
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
                (l.min(*v), h.max(*v))
            });
        let (pa, pb) = (
            DVec2::new(x_at(line, ylo), ylo),
            DVec2::new(x_at(line, yhi), yhi),
        );
        out.leftmost = out.leftmost.min(pa.x).min(pb.x);
        let id = rec.draw(
            format!("the distribution line of {}", train.shafts[k]),
            Item::Segment(Segment::new(pa, pb)),
            Role::Result,
            &[],
        );
        named.push((id, k, (pa, pb)));
        // The ray of the plan parallel to it, to the reading line, named by the link where
        // it meets it; the intercept marked there.
        let hit = DVec2::new(slopes[k] * plan.h, plan.foot.y);
        let ray = rec.draw(
            format!("the ray of ω of {}", train.shafts[k]),
            Item::Segment(Segment::new(plan.pole, hit)),
            Role::Construction,
            &[],
        );
        rec.label(
            ray,
            &train.shafts[k],
            hit,
            DVec2::new(hit.x.signum() * 0.3, 1.0),
        );
        rec.draw(
            format!("the intercept of ω of {}", train.shafts[k]),
            Item::Point(hit),
            Role::Construction,
            &[ray],
        );
        let read = rec.measure(plan.foot, hit);
        out.ends.push((k, read.drawn_mm, read.read_mm));
        // ω = intercept · μ_ω, μ_ω = μ_v/(μ_l h), signed by the side.
        out.omega[k] = hit.x.signum() * read.read_mm * scale_w.value();
    }
    // Each line named beside itself, clear of the other lines and the poles' velocities
    // ([`names::line_name`]).
    for &(id, k, seg) in &named {
        let others: Vec<_> = (named.iter())
            .filter(|n| n.0 != id)
            .map(|n| n.2)
            .chain(arrows.iter().copied())
            .collect();
        let (at, toward) = names::line_name(seg, &others);
        rec.label_item(id, &train.shafts[k], at, toward);
    }
    out
}
