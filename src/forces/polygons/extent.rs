//! The force sheets' drawings predicted before any is constructed: what each group's drawing
//! and the driving link's take at any μ_l, from the analytic twin — the links' points, the
//! arms' feet about each kind's moment centres ([`moment_centres`]) and the reactions'
//! points (SI), and what is drawn a fixed length from a point (a load's arrow, placed as
//! [`arrows::placed`] places it; a couple's arc; a guide run on past its reaction; an arm's
//! dimension on the guide; an arm dimensioned beside the line it would lie on). The session
//! sizes μ_l from these ([`crate::construct::fit`]). What it does not foresee moves an end by
//! about an arrow's length at most: an arrow the construction moves past another at a point
//! crowded at that μ_l only, an arm beside a line it lies within a millimetre of, a pulling
//! guide reaction drawn onto the block's far face when its arm falls under the block.

use super::driver::{wheel, Wheel};
use super::kinds::moment_centres;
use super::point_of;
use super::scheme::{ARM_DIMENSION_MM, ARROW_MM, GUIDE_PAST_MM};
use crate::construct::fit::Extent;
use crate::construct::Item;
use crate::forces::exact::at_position;
use crate::forces::loads::{Load, LoadKind};
use crate::forces::spec::{Drive, ForceSpec};
use crate::forces::twin::{Equilibrium, PairKind, Reaction};
use crate::forces::{arrows, phase_at, ForceError};
use crate::geom::DVec2;
use crate::linkage::{GroupPairs, Part, PlanPoses, Pose, Program};
use crate::scale::Scale;

/// A drawing of the force sheets predicted at any μ_l: its extent, and the gear drive of a
/// driving link, whose pitch arcs and line of action take lengths that depend on μ_l.
pub(crate) struct Predicted {
    extent: Extent,
    wheel: Option<Wheel>,
}

impl Predicted {
    /// The drawing's size at `mu`, mm (its labels not included).
    pub(crate) fn size_at(&self, mu: Scale) -> DVec2 {
        let Some((mut lo, mut hi)) = self.extent.bounds_at(mu) else {
            return DVec2::ZERO;
        };
        if let Some(w) = &self.wheel {
            let (pitch, pinion, action) = w.items(mu.value());
            for item in [pitch, pinion, Some(action)].iter().flatten() {
                item.bounding_points(|p| {
                    lo = lo.min(p);
                    hi = hi.max(p);
                });
            }
        }
        hi - lo
    }
}

/// The drawings of position `k` of `poses` on the force sheets, each predicted at any μ_l:
/// the groups from the last attached to the first, then the driving link.
pub(crate) fn predicted(
    spec: &ForceSpec,
    poses: &PlanPoses,
    k: usize,
    w1: f64,
) -> Result<Vec<Predicted>, ForceError> {
    let prog = &poses.program;
    let pos = &poses.positions[k];
    let phase = phase_at(poses.extremes.as_ref(), pos.phi, w1.signum());
    let (_, loads, solved) = at_position(spec, prog, (&pos.label, &pos.pose), phase, w1)?;
    Ok(drawings(prog, &pos.pose, &loads, &solved, &spec.drive))
}

/// One drawing predicted: its extent and the arrows, couples and lines placed on it so far.
struct Sketch<'a> {
    pose: &'a Pose,
    extent: Extent,
    /// Two points this close are one, two lines this close lie on each other, m: a
    /// billionth of the mechanism's reach.
    near: f64,
    /// The lines drawn at the scale of the mechanism (its links, the lines of action to the
    /// arms' feet, the arms), SI.
    lines: Vec<(DVec2, DVec2)>,
    /// The arms dimensioned beside the line they would lie on: how far out, mm.
    beside: Vec<(DVec2, DVec2, f64)>,
    /// Arrows drawn: the point (SI), the mark it is drawn from (mm), and the arrow (tail,
    /// head) from there, mm.
    arrows: Vec<(DVec2, DVec2, (DVec2, DVec2))>,
    /// Couples drawn: the point (SI) each is drawn about.
    couples: Vec<DVec2>,
}

impl<'a> Sketch<'a> {
    fn new(pose: &'a Pose) -> Self {
        Self {
            pose,
            extent: Extent::empty(0.0),
            near: crate::forces::reach(&pose.p) * 1e-9,
            lines: Vec::new(),
            beside: Vec::new(),
            arrows: Vec::new(),
            couples: Vec::new(),
        }
    }

    /// The links `links` of `part` as [`crate::linkage::draw_links`] draws them, and the
    /// lines joining each link's points.
    fn links(&mut self, prog: &Program, part: Part, links: &[usize]) {
        part.extent(prog, self.pose, &mut self.extent);
        for &l in links {
            let on: Vec<DVec2> = (0..self.pose.p.len())
                .filter(|&k| prog.links_of(k).contains(&l))
                .map(|k| self.pose.p[k])
                .collect();
            for (n, &a) in on.iter().enumerate() {
                self.lines.extend(on[n + 1..].iter().map(|&b| (a, b)));
            }
        }
    }

    /// A force's arrow along `e` at the point `x` (SI) and `base` (mm) from it, as
    /// [`arrows::arrow`] places it among the arrows drawn there.
    fn arrow(&mut self, (x, base): (DVec2, DVec2), e: DVec2, onto: bool) {
        let there: Vec<(DVec2, DVec2)> = self
            .arrows
            .iter()
            .filter(|(y, ..)| y.distance(x) <= self.near)
            .map(|&(_, b, (from, to))| (b - base + from, b - base + to))
            .collect();
        let (from, to) = arrows::placed(&there, (DVec2::ZERO, e, ARROW_MM), onto);
        for end in [from, to] {
            self.extent.mark(x, base + end);
        }
        self.arrows.push((x, base, (from, to)));
    }

    /// A load as [`super::Scheme::show`] draws it.
    fn show(&mut self, l: &Load) {
        if l.is_couple() {
            self.couple(self.pose.p[self.pose.origin[l.link]], l.moment);
        } else if let Some(e) = l.force.try_normalize() {
            self.arrow((self.pose.p[l.at] + l.shift, DVec2::ZERO), e, false);
        }
    }

    /// A couple's arc about `o` (SI), outside the couples' arcs drawn about `o` already.
    fn couple(&mut self, o: DVec2, moment: f64) {
        let around = self.couples.iter().filter(|c| **c == o).count();
        let lines = (self.lines.iter()).filter_map(|&(a, b)| arrows::leaving(o, a, b, self.near));
        let heads = (self.arrows.iter())
            .filter(|(x, ..)| x.distance(o) <= self.near)
            .filter_map(|&(_, b, (from, to))| {
                arrows::leaving(DVec2::ZERO, b + from, b + to, arrows::ON_LINE_MM)
            });
        let away: Vec<DVec2> = lines.chain(heads).collect();
        let arc = arrows::couple_arc(
            DVec2::ZERO,
            moment,
            around,
            arrows::couple_turn(&away, moment, around),
        );
        for i in 0..=16 {
            self.extent.mark(o, arc.eval(f64::from(i) / 16.0));
        }
        self.couples.push(o);
    }

    /// The arms of `loads` about `c` (SI) as [`arrows::arm`] draws them: from `c` to the
    /// foot on the load's line of action, or, where a line drawn lies there, dimensioned
    /// [`arrows::ARM_BESIDE_MM`] beside it, a step further out for each arm there already.
    fn arms(&mut self, c: DVec2, loads: &[&Load]) {
        for l in loads {
            let Some(e) = l.force.try_normalize() else {
                continue;
            };
            let x = self.pose.p[l.at] + l.shift;
            let foot = x + e * (c - x).dot(e);
            self.extent.add(foot);
            if foot.distance(c) <= self.near {
                continue;
            }
            let tol = (self.near, self.near);
            if self
                .lines
                .iter()
                .any(|&pq| arrows::lies_along(c, foot, pq, tol))
            {
                let out = self
                    .beside
                    .iter()
                    .filter(|(a, b, _)| arrows::lies_along(c, foot, (*a, *b), tol))
                    .map(|b| b.2)
                    .fold(0.0, f64::max)
                    + arrows::ARM_BESIDE_MM;
                let n = (foot - c).normalize().perp() * out;
                self.extent.mark(c, n);
                self.extent.mark(foot, n);
                self.beside.push((c, foot, out));
            } else {
                self.lines.extend([(x, foot), (c, foot)]);
            }
        }
    }

    /// A reaction as [`super::show_reaction`] draws it: the frame's on a slider on its
    /// guide, run on past it, with its arm dimensioned; any other at its point.
    fn reaction(&mut self, prog: &Program, r: &Reaction) {
        if let (
            0,
            Some(s),
            PairKind::Prismatic {
                reference,
                dir_link,
            },
        ) = (r.pair.from, r.offset, r.pair.kind)
        {
            let (axis, u) = (self.pose.p[reference], self.pose.dir[dir_link]);
            let towards =
                super::wall::guide_wall(u, axis, r.force, (self.pose.p[prog.centre], &self.pose.p));
            let side = towards * Item::SLIDER_HALF_MM.1;
            let (lo, hi) = (axis + u * s.min(0.0), axis + u * s.max(0.0));
            self.extent.mark(lo, side - u * GUIDE_PAST_MM);
            self.extent.mark(hi, side + u * GUIDE_PAST_MM);
            let beside = side + towards * ARM_DIMENSION_MM;
            self.extent.mark(lo, beside);
            self.extent.mark(hi, beside);
            if let Some(e) = r.force.try_normalize() {
                self.arrow((axis + u * s, side), e, e.dot(towards) >= 0.0);
            }
            return;
        }
        self.show(&carried(r, self.pose, r.pair.to, r.force));
    }
}

/// A reaction as a load on link `on` of force `force`: at its pair's point, shifted along
/// the slide by its offset.
fn carried(r: &Reaction, pose: &Pose, on: usize, force: DVec2) -> Load {
    let (at, shift) = point_of(r, |l| pose.dir[l]);
    Load {
        shift,
        ..Load::force(on, LoadKind::Reaction, String::new(), force, at)
    }
}

/// The drawings of the twin's `solved` position `pose` with its `loads`, in the order
/// [`super::polygons`] draws them.
pub(crate) fn drawings(
    prog: &Program,
    pose: &Pose,
    loads: &[Load],
    solved: &Equilibrium,
    drive: &Drive,
) -> Vec<Predicted> {
    let mut applied = loads.to_vec();
    let groups: Vec<_> = prog.groups().collect();
    let mut out: Vec<Predicted> = Vec::new();
    for (n, g) in groups.iter().enumerate().rev() {
        let [i, j] = g.links;
        let reactions = &solved.reactions[1 + 3 * n..4 + 3 * n];
        let mut sk = Sketch::new(pose);
        sk.links(prog, Part::Group(g.group), &[i, j]);
        let on = |l: usize| -> Vec<&Load> { applied.iter().filter(|x| x.link == l).collect() };
        let (li, lj) = (on(i), on(j));
        for l in li.iter().chain(&lj) {
            sk.show(l);
        }
        let [ci, cj] = moment_centres(g.pairs).map(|k| pose.p[k]);
        sk.arms(ci, &li);
        sk.arms(cj, &lj);
        // The inner reaction's arm about link j's centre: RPR's unit force normal to the
        // slide through A (its point not known yet), RPP's reaction at its point.
        let inner = &reactions[2];
        let at = match g.pairs {
            GroupPairs::Rpr { .. } => Some(Load {
                shift: DVec2::ZERO,
                ..carried(inner, pose, j, inner.force)
            }),
            GroupPairs::Rpp { .. } => Some(carried(inner, pose, j, inner.force)),
            _ => None,
        };
        if let Some(l) = at {
            sk.arms(cj, &[&l]);
        }
        for (k, r) in reactions.iter().enumerate() {
            if super::on_scheme(k, r) {
                sk.reaction(prog, r);
            }
        }
        for r in &reactions[..2] {
            if r.pair.from != 0 {
                let l = carried(r, pose, r.pair.from, -r.force);
                applied.push(l);
            }
        }
        out.push(Predicted {
            extent: sk.extent,
            wheel: None,
        });
    }
    out.push(driver(prog, pose, &applied, solved, drive));
    out
}

/// The driving link's drawing: its loads about its centre, the balancing moment's arc or
/// the wheel's pitch arcs, line of action and tooth force, and the frame's reaction.
fn driver(
    prog: &Program,
    pose: &Pose,
    applied: &[Load],
    solved: &Equilibrium,
    drive: &Drive,
) -> Predicted {
    let crank = prog.crank_link as usize;
    let mut sk = Sketch::new(pose);
    sk.links(prog, Part::Driver, &[crank]);
    let loads: Vec<&Load> = applied.iter().filter(|l| l.link == crank).collect();
    for l in &loads {
        sk.show(l);
    }
    let o = pose.p[prog.centre];
    sk.arms(o, &loads);
    let mut gear = None;
    match drive {
        Drive::Coupling if solved.m_bal != 0.0 => sk.couple(o, solved.m_bal),
        Drive::Coupling => {}
        Drive::Gear(g) => {
            let w = wheel(o, 1.0, g, solved.m_bal.signum());
            // The line of centres to P, the balancing force's arm and its arrow at P.
            sk.extent.add(w.p);
            sk.extent.add(w.p + w.d * (o - w.p).dot(w.d));
            sk.arrow((w.p, DVec2::ZERO), w.d, false);
            gear = Some(w);
        }
    }
    sk.reaction(prog, &solved.reactions[0]);
    Predicted {
        extent: sk.extent,
        wheel: gear,
    }
}
