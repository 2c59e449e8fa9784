//! Drawing the plan of positions: the links of a position (whole, the driver, or one group),
//! the frame's pivots and guides, the trajectories and the extreme positions with θ, ψ, H.

use super::built::Built;
use super::compiled::Compiled;
use super::error::{LinkageError, ModelError};
use super::extremes::{Extremes, OutputCoord};
use super::fan::clearances;
use super::indexed::PDir;
use super::model::Mechanism;
use super::part::Part;
use super::pen::{covers, trim, Pen};
use super::positions::{
    cannot_assemble, start_of, walk, PlanPoses, PlanPosition, PlanRequest, PosePosition,
    PositionPlan,
};
use super::program::{Op, Program};
use super::rigid::{draw_rigid, rigid_links, RigidLink};
use crate::construct::{Context, Drafting, Item, Recorder, Role};
use crate::geom::{Arc, Circle, DVec2, Segment, Side, Tolerances};
use crate::scale::Scale;
use std::f64::consts::{PI, TAU};

/// Draw one position's links with `role`; returns, per link number drawn, a point to put its
/// number at.
pub fn draw_links(
    rec: &mut Recorder,
    prog: &Program,
    b: &Built,
    role: Role,
    note: &str,
    part: Part,
) -> Vec<(u32, DVec2)> {
    draw_links_from(rec, prog, b, (role, note), part, &[])
}

/// [`draw_links`], the lines at the crowded pivots `clear` begun at their clearance
/// ([`super::fan`]: the further positions of the plan).
fn draw_links_from(
    rec: &mut Recorder,
    prog: &Program,
    b: &Built,
    (role, note): (Role, &str),
    part: Part,
    clear: &[(DVec2, f64)],
) -> Vec<(u32, DVec2)> {
    let rigid: Vec<RigidLink> = rigid_links(prog)
        .into_iter()
        .filter(|r| part.draws(prog, r.link))
        .collect();
    let mut pen = Pen {
        rec,
        role,
        note,
        anchors: Vec::new(),
        joints: Vec::new(),
        rigid: rigid.iter().map(|r| r.placed(b)).collect(),
        clear,
    };
    if matches!(part, Part::All | Part::Driver) {
        let (centre, pin) = (b.p[prog.centre], b.p[prog.pin]);
        let covered = covers(&pen.rigid, prog.crank_link, (centre, pin));
        if let Some((from, to)) = trim(clear, centre, pin).filter(|_| !covered) {
            pen.rec.draw(
                format!("{note}: crank"),
                Item::Segment(Segment::new(from, to)),
                role,
                &[],
            );
        }
        pen.anchors.push((prog.crank_link, centre.lerp(pin, 0.5)));
        // The pin is a hinge where a group joins the crank; a crank a block slides along
        // (the tangent mechanism) ends in a point of its own, drawn as one.
        pen.joints.push(prog.centre);
        if prog.links_of(prog.pin).len() > 1 {
            pen.joints.push(prog.pin);
        }
    }
    for op in &prog.ops {
        let Op::Dyad { group, links, dyad } = op else {
            continue;
        };
        if !matches!(part, Part::All) && part != Part::Group(*group) {
            continue;
        }
        dyad.group().draw(&mut pen, prog, b, *links);
    }
    for r in &rigid {
        draw_rigid(pen.rec, r, b, (role, note), clear);
        pen.joints.extend(&r.hinges);
    }
    let Pen {
        rec,
        anchors,
        mut joints,
        ..
    } = pen;
    super::slide_lines::draw_slide_lines(rec, prog, b, (role, note), part);
    joints.retain(|k| *k >= prog.fixed.len() || part != Part::All);
    joints.sort_unstable();
    joints.dedup();
    for k in joints {
        let fixed = k < prog.fixed.len() && part == Part::Driver;
        rec.draw(
            format!("{note}: joint {}", prog.names[k]),
            Item::Joint { at: b.p[k], fixed },
            role,
            &[],
        );
    }
    anchors
}

/// Name the points of `part` drawn at `b` (those on a link the part draws), each by its
/// letter up and right of it ([`named_point`]: a joint's letter names its hinge or block, a
/// point on one link is a dot of its own). The scheme names the whole mechanism's moving
/// points so. A drawing of the force analysis (`loaded`: a group drawn apart, or the driver)
/// names the frame's joint too, as seed 000's group drawings name B, C, S₃; but not two
/// points at one place (the shaper's E and S₅ under the ram's loads): there the loads' own
/// labels, crowded round the block, name them.
pub fn name_points(rec: &mut Recorder, prog: &Program, b: &Built, part: Part, loaded: bool) {
    let on_part = |k: usize| {
        let links = prog.links_of(k);
        links.iter().any(|&l| part.draws(prog, l as u32))
            || (part == Part::Driver && (k == prog.centre || k == prog.pin))
    };
    let shown: Vec<usize> = (0..prog.names.len())
        .filter(|&k| (k >= prog.fixed.len() || loaded) && on_part(k))
        .collect();
    for &k in &shown {
        let name = &prog.names[k];
        let shared = || (shown.iter()).any(|&o| o != k && b.p[o].distance(b.p[k]) < ON_POINT_MM);
        if loaded && shared() {
            continue;
        }
        let (item, role) = named_point(prog, k, b.p[k]);
        let id = rec.draw(format!("point {name}"), item, role, &[]);
        rec.label(id, name.clone(), b.p[k], DVec2::new(0.8, 0.6).normalize());
    }
}

/// Two points of a drawing this close are at one place, mm.
const ON_POINT_MM: f64 = 0.5;

/// A guide of the frame as drawn: the group it belongs to, the piece of line spanning the
/// travel of its joint (with a margin) and the side its hatching goes on (away from the crank).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrameGuide {
    /// Group index.
    pub group: usize,
    /// The drawn piece of the guide line.
    pub segment: Segment,
    /// Side of the hatching.
    pub hatch: Side,
}

/// The frame's guides spanning the joint positions of `built`, with `margin` mm at each end.
pub fn frame_guides(prog: &Program, built: &[&Built], margin: f64) -> Vec<FrameGuide> {
    let mut v = Vec::new();
    let Some(first) = built.first() else { return v };
    let centre = first.p[prog.centre];
    for (group, joint, e) in fixed_guides(prog) {
        {
            let (lo, hi) = built
                .iter()
                .map(|b| b.p[joint].dot(e))
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), t| {
                    (lo.min(t), hi.max(t))
                });
            let p0 = first.p[joint];
            let base = p0 - e * p0.dot(e);
            let segment = Segment::new(base + e * (lo - margin), base + e * (hi + margin));
            let hatch = if e.perp_dot(centre - segment.from) > 0.0 {
                Side::Right
            } else {
                Side::Left
            };
            v.push(FrameGuide {
                group,
                segment,
                hatch,
            });
        }
    }
    v
}

/// How far a frame guide is drawn past the stroke of its slider, mm.
pub const GUIDE_MARGIN_MM: f64 = 15.0;

/// The ends of the frame's guides as a plan of positions draws them, predicted from the
/// analytic positions: for each end, the slider's extreme point (m) and the unit direction
/// in which the guide runs on past it by [`GUIDE_MARGIN_MM`].
pub fn guide_ends(poses: &PlanPoses) -> Vec<(DVec2, DVec2)> {
    let mut ends = Vec::new();
    for (_, joint, e) in fixed_guides(&poses.program) {
        let along = |p: &&PosePosition| p.pose.p[joint].dot(e);
        let positions = poses.positions.iter();
        let first = positions
            .clone()
            .min_by(|a, b| along(a).total_cmp(&along(b)));
        let last = positions.max_by(|a, b| along(a).total_cmp(&along(b)));
        if let (Some(f), Some(l)) = (first, last) {
            ends.push((f.pose.p[joint], -e));
            ends.push((l.pose.p[joint], e));
        }
    }
    ends
}

/// The frame's guides: per guide, its group, the joint sliding on it and its direction.
fn fixed_guides(prog: &Program) -> Vec<(usize, usize, DVec2)> {
    let n = prog.fixed.len();
    prog.dyad_guides()
        .filter(|(_, _, g)| g.is_fixed(n))
        .filter_map(|(group, joint, g)| match g.dir {
            PDir::Fixed(a) => Some((group, joint, DVec2::from_angle(a))),
            PDir::Along { .. } => None,
        })
        .collect()
}

/// Draw the frame's guides with their hatching.
pub fn draw_guides(rec: &mut Recorder, guides: &[FrameGuide]) {
    for g in guides {
        rec.draw(
            "guide of the frame",
            Item::Guide {
                segment: g.segment,
                hatch: g.hatch,
            },
            Role::Given,
            &[],
        );
    }
}

/// Draw the fixed pivots of `b` with the ground symbol and their letters.
pub fn draw_pivots(rec: &mut Recorder, prog: &Program, b: &Built) {
    for k in prog.fixed_pivots() {
        let id = rec.draw(
            format!("fixed pivot {}", prog.names[k]),
            Item::Joint {
                at: b.p[k],
                fixed: true,
            },
            Role::Given,
            &[],
        );
        rec.label(
            id,
            prog.names[k].clone(),
            b.p[k],
            DVec2::new(-1.0, 0.6).normalize(),
        );
    }
}

pub(super) fn draw_plan(
    rec: &mut Recorder,
    prog: &Program,
    positions: &[PlanPosition],
    ex: Option<&Extremes>,
) {
    let Some(first) = positions.first() else {
        return;
    };
    let centre = first.built.p[prog.centre];
    let r_mm = first.built.p[prog.pin].distance(centre);
    rec.draw(
        "crank circle",
        Item::Circle(Circle {
            center: centre,
            radius: r_mm,
        }),
        Role::Construction,
        &[],
    );
    // Guides of the frame, spanning the travel of their joints.
    let all: Vec<&Built> = positions.iter().map(|p| &p.built).collect();
    draw_guides(rec, &frame_guides(prog, &all, GUIDE_MARGIN_MM));
    // Every position thin, the extremes too (numbered, with the stroke or the swing
    // between them), begun clear of a crowded pivot; position 1, the one the letters name,
    // thick (ГОСТ 2.303 main line).
    let clear = clearances(prog, &all[1..]);
    for (k, pos) in positions.iter().enumerate() {
        rec.set_group(k as u32 + 1);
        let (role, clear) = if k == 0 {
            (Role::Given, &[][..])
        } else {
            (Role::Construction, &clear[..])
        };
        draw_links_from(
            rec,
            prog,
            &pos.built,
            (role, &format!("position {}", pos.label)),
            Part::All,
            clear,
        );
        let pin = pos.built.p[prog.pin];
        let out = (pin - centre).normalize_or_zero();
        let id = rec.draw(
            format!("position {}: number", pos.label),
            Item::Text(pin),
            Role::Dimension,
            &[],
        );
        // The number names the crank pin of its position: kept near it as a point's label.
        rec.label_point(id, pos.label.clone(), pin, out);
    }
    rec.set_group(0);
    // Trajectories of the link points.
    for op in &prog.ops {
        if let Op::Point { idx, .. } = op {
            let points: Vec<DVec2> = positions.iter().map(|p| p.built.p[*idx]).collect();
            rec.draw(
                format!("trajectory of {}", prog.names[*idx]),
                trajectory(prog, *idx, points, &first.built),
                Role::Construction,
                &[],
            );
        }
    }
    // Fixed pivots and the letters of position 1.
    draw_pivots(rec, prog, &first.built);
    for (k, name) in prog.names.iter().enumerate().skip(prog.fixed.len()) {
        let at = first.built.p[k];
        let id = rec.draw(
            format!("point {name} of position 1"),
            Item::Point(at),
            Role::Given,
            &[],
        );
        rec.label(id, name.clone(), at, DVec2::new(0.7, 0.7).normalize());
    }
    if let Some(ex) = ex {
        draw_extremes(rec, prog, positions, ex);
    }
}

/// The trajectory of point `k` through its constructed `points`: on a link turning about a
/// fixed pivot, the arc about the pivot from one extreme to the other (the whole circle
/// where the link turns round), drawn with the compass; else a smooth curve through the
/// points, as with the French curve. A closed curve through a rocker's points, swept there
/// and back, parts into two lines about its arc.
fn trajectory(prog: &Program, k: usize, points: Vec<DVec2>, built: &Built) -> Item {
    let pivots = prog.fixed_pivots();
    let pivot = (prog.links_of(k).into_iter())
        .filter(|&l| l != 0)
        .find_map(|l| {
            pivots
                .iter()
                .copied()
                .find(|&f| prog.links_of(f).contains(&l))
        });
    let (Some(f), Some(first), true) = (pivot, points.first(), points.len() > 2) else {
        return smooth(points);
    };
    let centre = built.p[f];
    let radius = first.distance(centre);
    // Every point at the one distance (to a millionth of it): a point on that link.
    let on_circle = |p: &DVec2| (p.distance(centre) - radius).abs() <= 1e-6 * radius;
    if radius <= 0.0 || !points.iter().all(on_circle) {
        return smooth(points);
    }
    // The angles unwrapped along the cycle back to its start, each step the short way round:
    // a link that turns round comes back a whole turn on, a rocker where it began.
    let angle = |p: &DVec2| (*p - centre).to_angle();
    let start = angle(first);
    let mut at = start;
    let (mut lo, mut hi) = (at, at);
    let cycle: Vec<&DVec2> = points.iter().chain([first]).collect();
    for w in cycle.windows(2) {
        at += (angle(w[1]) - angle(w[0]) + PI).rem_euclid(TAU) - PI;
        (lo, hi) = (lo.min(at), hi.max(at));
    }
    if (at - start).abs() > PI {
        return Item::Circle(Circle {
            center: centre,
            radius,
        });
    }
    Item::Arc(Arc {
        center: centre,
        radius,
        start: lo,
        sweep: hi - lo,
    })
}

/// A smooth curve through `points`, closed when they are more than two.
fn smooth(points: Vec<DVec2>) -> Item {
    let closed = points.len() > 2;
    Item::Curve { points, closed }
}

/// What names point `k` drawn at `at`: a point on one link only (a centre of mass, the
/// shaper's E) is a dot of its own; a joint's letter names the hinge or the block drawn there.
pub(super) fn named_point(prog: &Program, k: usize, at: DVec2) -> (Item, Role) {
    if prog.links_of(k).len() < 2 {
        (Item::Point(at), Role::Given)
    } else {
        (Item::Text(at), Role::Dimension)
    }
}

/// The shortest arc θ is marked with, mm: below it the crank's extremes are drawn in line.
const THETA_ARC_MM: f64 = 1.0;

fn draw_extremes(rec: &mut Recorder, prog: &Program, positions: &[PlanPosition], ex: &Extremes) {
    let find = |phi: f64| {
        positions.iter().find(|p| {
            (p.phi - phi)
                .rem_euclid(TAU)
                .min((phi - p.phi).rem_euclid(TAU))
                < 1e-9
        })
    };
    let (Some(a), Some(b)) = (find(ex.phi_start), find(ex.phi_other)) else {
        return;
    };
    for r in &ex.ranges {
        match r.coord {
            OutputCoord::Rocker(l) => {
                let o = a.built.p[a.built.origin[l]];
                let (ua, ub) = (
                    DVec2::from_angle(a.built.angle[l]),
                    DVec2::from_angle(b.built.angle[l]),
                );
                let reach =
                    (prog.link_reach(l as u32, rec.scale().value()) * 0.3).clamp(25.0, 70.0);
                let id = rec.draw(
                    "swing angle of the rocker",
                    Item::Angle(Arc::between(o, reach, ua, ub)),
                    Role::Dimension,
                    &[],
                );
                let mid = (ua + ub).normalize_or_zero();
                let name = if ex.theta_is_swing(r) { "θ" } else { "ψ" };
                rec.label(id, name, o + mid * (reach + 1.0), mid);
            }
            OutputCoord::Slider(i, d) => {
                let (pa, pb) = (a.built.p[i], b.built.p[i]);
                let n = d.perp();
                let off = if (pa - a.built.p[prog.centre]).dot(n) > 0.0 {
                    14.0
                } else {
                    -14.0
                };
                let (from, to) = if (pb - pa).dot(d) >= 0.0 {
                    (pa, pb)
                } else {
                    (pb, pa)
                };
                rec.dimension("stroke of the slider", (from, to, off), "H");
                // The point at the other extreme, primed (E′, B′), as the stroke's other end.
                let (item, role) = named_point(prog, i, pb);
                let id = rec.draw(format!("point {}′", prog.names[i]), item, role, &[]);
                rec.label(id, format!("{}′", prog.names[i]), pb, n * off.signum());
            }
        }
    }
    if ex.ratio_defined() && !ex.ranges.iter().any(|r| ex.theta_is_swing(r)) {
        // θ between the crank at one extreme and the extension of the crank at the other.
        let c = a.built.p[prog.centre];
        let (ua, ub) = (
            (c - a.built.p[prog.pin]).normalize_or_zero(),
            (b.built.p[prog.pin] - c).normalize_or_zero(),
        );
        let r = b.built.p[prog.pin].distance(c) * 0.7;
        // No angle to mark where the two extremes are in line (θ = 0: the V engine's
        // central cylinders; the text states it): an arc of no length under its letter.
        if ua.angle_to(ub).abs() * r < THETA_ARC_MM {
            return;
        }
        let id = rec.draw(
            "angle θ between the crank's extreme positions",
            Item::Angle(Arc::between(c, r, ua, ub)),
            Role::Dimension,
            &[],
        );
        let mid = (ua + ub).normalize_or_zero();
        rec.label(id, "θ", c + mid * (r + 1.0), mid);
        rec.draw(
            "extension of the crank",
            Item::Segment(Segment::new(c, c + ua * r * 1.2)),
            Role::Construction,
            &[],
        );
    }
}

/// Build the plan of positions of `m` at μ_l = `scale`.
pub fn plan_positions(
    m: &Mechanism,
    req: &PlanRequest,
    scale: Scale,
    drafting: Drafting,
) -> Result<PositionPlan, LinkageError> {
    let program = Program::compile(m)?;
    let (extremes, start) = start_of(&program, m, req)?;
    let extent_mm = model_extent(&program) / scale.value();
    let tol = Tolerances::for_model_size(extent_mm.max(1.0)).map_err(ModelError::from)?;
    let mut rec = Recorder::in_context("plan", scale, &Context::new(tol, drafting));
    let mut k = 0;
    let positions = walk(
        m,
        req,
        &program,
        start,
        extremes.as_ref(),
        |label, phi, prev| {
            k += 1;
            rec.set_group(k);
            program
                .construct(
                    &mut rec,
                    phi,
                    prev.map(|p| &p.built),
                    &format!("position {label}"),
                )
                .map_err(|f| cannot_assemble(m, label, phi, f.group, f.error.to_string()))
        },
    )?;
    rec.set_group(0);
    draw_plan(&mut rec, &program, &positions, extremes.as_ref());
    Ok(PositionPlan {
        mechanism: m.clone(),
        program,
        extremes,
        positions,
        figure: rec.finish(),
    })
}

/// Largest distance between fixed points and the crank reach, m (sets the tolerances).
fn model_extent(p: &Program) -> f64 {
    let mut e = p.crank_length;
    for a in &p.fixed {
        for b in &p.fixed {
            e = e.max(a.distance(*b));
        }
    }
    for op in &p.ops {
        if let Op::Point { along, across, .. } = op {
            e = e.max(along.hypot(*across));
        }
    }
    e
}
