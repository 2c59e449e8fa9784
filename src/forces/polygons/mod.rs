//! Force polygons (планы сил) as drawing-board constructions, group by group from the group
//! farthest from the driving link, then the driving link. Every arm is measured on the
//! group's drawing at μ_l and every reaction read off its polygon at μ_F, both under the
//! drafting model.
//!
//! Per kind (i, j the group's links; A, C the outer pairs, B the inner):
//! * RRR — F^τ of each outer reaction from the moments of its link about B; the polygon
//!   F^τ_A, loads of i, loads of j, F^τ_C is closed by lines ∥ AB and ∥ CB; the inner
//!   reaction joins the end of i's loads to the closing point.
//! * RRP — F^τ_A as above; closed by the line ∥ AB and the normal to the guide; the guide's
//!   reaction acts at h = −ΣM_B(j)/R from B.
//! * RPR — the inner reaction (normal to the slide) from the moments of link j about its
//!   pivot with the block's moment carried over; each link's polygon closes on it.
//! * PRP — closed by the two guides' normals; each reaction's point from its link's moments.
//! * RPP — link j's polygon closed by the normals to the slide and to the guide; the block's
//!   triangle gives the outer reaction.
//!
//! The driving link: through a coupling the balancing moment M_у = −ΣM_O; through a gear the
//! balancing force along the line of action at the pitch point from ΣM_O = 0 (its arm
//! measured), and the frame's reaction closes the triangle.

use super::loads::{Load, LoadKind};
use super::spec::Drive;
use super::twin::{line_of_action, Pair, PairKind, Reaction};
use crate::construct::{ConstructionError, Context, Figure, Item, Recorder, Role};
use crate::geom::{Circle, DVec2, Line, Segment};
use crate::linkage::{draw_links, Built, GroupPairs, Part, PlanSetup};
use crate::scale::Scale;
use std::f64::consts::{PI, TAU};

mod driver;
mod equations;
use driver::driver;
pub use equations::{MomentEquation, MomentTerm, Unknown};

/// Length of a load's arrow on a group's drawing, mm (the drawing shows where and which
/// way; the polygon shows how much).
const ARROW_MM: f64 = 14.0;

/// One group's force analysis as drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct GroupPolygon {
    /// Group index (file order).
    pub group: usize,
    /// Its links.
    pub links: [usize; 2],
    /// The group drawn apart at μ_l with its loads, reactions and measured arms.
    pub scheme: Figure,
    /// Its force polygon at μ_F.
    pub polygon: Figure,
    /// The polygon's small forces enlarged, when some are too short to read.
    pub details: Vec<PolygonDetail>,
    /// The reactions read off the polygon: the two outer pairs, then the inner.
    pub reactions: Vec<Reaction>,
    /// The moment equations the group's drawing works, in the order they are solved.
    pub equations: Vec<MomentEquation>,
}

/// The driving link's analysis as drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct DriverPolygon {
    /// The crank (with its wheel and line of action) at μ_l.
    pub scheme: Figure,
    /// Its force triangle at μ_F.
    pub polygon: Figure,
    /// The triangle's small forces enlarged, when some are too short to read.
    pub details: Vec<PolygonDetail>,
    /// The frame's reaction on the crank.
    pub reaction: Reaction,
    /// The balancing moment, N·m.
    pub m_bal: f64,
    /// The balancing force (gear drive), N.
    pub f_bal: Option<f64>,
    /// The balancing force's arm about the crank's centre, measured (gear drive), m.
    pub arm: Option<f64>,
    /// ΣM about the crank's centre, which gives the balancing load.
    pub equation: MomentEquation,
}

/// Everything one position's polygons give.
#[derive(Debug, Clone, PartialEq)]
pub struct Polygons {
    /// The groups, from the last attached to the first.
    pub groups: Vec<GroupPolygon>,
    /// The driving link.
    pub driver: DriverPolygon,
}

impl Polygons {
    /// Every reaction read off the polygons: the groups' from the last to the first, then
    /// the frame's on the crank.
    pub fn reactions(&self) -> Vec<Reaction> {
        self.groups
            .iter()
            .rev()
            .flat_map(|g| g.reactions.iter().copied())
            .chain(std::iter::once(self.driver.reaction))
            .collect()
    }
}

/// What the polygons of a position start from: the position as every drawing of it does
/// ([`PlanSetup`]) and μ_F.
pub struct Board<'a> {
    /// The mechanism, the constructed position, μ_l, ω₁ and the context.
    pub setup: PlanSetup<'a>,
    /// μ_F of the polygons.
    pub mu_f: Scale,
}

impl Board<'_> {
    /// The crank's sense, +1 counter-clockwise.
    fn sense(&self) -> f64 {
        self.setup.w1.signum()
    }
}

/// A link's loads and its arms measured on a drawing.
struct Scheme<'a> {
    board: &'a Board<'a>,
    rec: Recorder,
    arms: usize,
    /// The moments taken since the log was last drained.
    log: Vec<MomentTerm>,
}

impl<'a> Scheme<'a> {
    fn new(board: &'a Board<'a>, title: String) -> Self {
        Self {
            board,
            rec: Recorder::in_context(title, board.setup.mu_l, &board.setup.ctx),
            arms: 0,
            log: Vec::new(),
        }
    }

    /// Where a load acts on the drawing, mm.
    fn at(&self, l: &Load) -> DVec2 {
        self.board.setup.built.p[l.at] + l.shift / self.board.setup.mu_l.value()
    }

    /// Draw a load: an arrow at its point (a couple: an arc arrow about the link's origin),
    /// apart from the loads already drawn there ([`crate::forces::arrows`]).
    fn show(&mut self, l: &Load) {
        if l.is_couple() {
            let o = self.board.setup.built.p[self.board.setup.built.origin[l.link]];
            crate::forces::arrows::couple(&mut self.rec, &l.name, o, l.moment);
            return;
        }
        let Some(e) = l.force.try_normalize() else {
            return;
        };
        self.arrow(&l.name, self.at(l), e, false);
    }

    /// A force's arrow along `e` at its point `x`: from `x`, or ending at `x` (`onto`);
    /// labelled `name` at the end away from the point.
    fn arrow(&mut self, name: &str, x: DVec2, e: DVec2, onto: bool) {
        crate::forces::arrows::arrow(
            &mut self.rec,
            format!("load {name}"),
            name,
            (x, e, ARROW_MM),
            onto,
        );
    }

    /// The moment of `l` about `c` (mm), N·m: the arm measured on the drawing.
    fn moment(&mut self, c: DVec2, l: &Load) -> f64 {
        if l.force == DVec2::ZERO {
            self.log.push(MomentTerm {
                name: l.name.clone(),
                force: l.moment,
                arm: 0.0,
                arm_mm: 0.0,
                label: None,
                moment: l.moment,
                couple: true,
            });
            return l.moment;
        }
        let x = self.at(l);
        let e = l.force.normalize();
        let foot = x + e * (c - x).dot(e);
        let arm = self.rec.measure(c, foot);
        let sign = (x - c).perp_dot(e).signum();
        let mut label = None;
        if let Some(name) = crate::forces::arrows::arm_named(&self.rec, c, foot) {
            label = Some(name);
        } else if arm.drawn_mm > 0.5 {
            self.arms += 1;
            label = Some(format!("h_{{{}}}", self.arms));
            // The line of action extended from the force's point to the arm's foot.
            let line = (foot.distance(x) > 0.5).then(|| {
                self.rec.draw(
                    format!("line of action of {} to the foot of its arm", l.name),
                    Item::Segment(Segment::new(x, foot)),
                    Role::Construction,
                    &[],
                )
            });
            let id = self.rec.draw(
                format!("arm of {} about the moment centre", l.name),
                Item::Segment(Segment::new(c, foot)),
                Role::Construction,
                line.as_slice(),
            );
            self.rec.label(
                id,
                format!("h_{{{}}}", self.arms),
                c.lerp(foot, 0.5),
                (foot - c).perp().normalize_or_zero(),
            );
        }
        let moment = sign * l.force.length() * arm.value;
        self.log.push(MomentTerm {
            name: l.name.clone(),
            force: l.force.length(),
            arm: arm.value,
            arm_mm: arm.read_mm,
            label,
            moment,
            couple: false,
        });
        moment
    }

    /// Σ moments of `loads` about `c`.
    fn moments(&mut self, c: DVec2, loads: &[&Load]) -> f64 {
        loads.iter().map(|l| self.moment(c, l)).sum()
    }

    /// A length measured on the drawing, m.
    fn length(&self, a: DVec2, b: DVec2) -> f64 {
        self.rec.measure(a, b).value
    }
}

/// A force shorter than this on its polygon, mm, is drawn again in the polygon's detail.
const SMALL_FORCE_MM: f64 = 4.0;

/// The detail draws the smallest force about this long, mm.
const DETAIL_FORCE_MM: f64 = 12.0;

/// The detail's zone is drawn at most this wide, mm.
const DETAIL_MM: f64 = 110.0;

/// A detail's zone is drawn at least this large in radius, mm: room for its forces' labels.
const DETAIL_ROOM_MM: f64 = 30.0;

/// The zone about the small forces reaches this far past them (a share of their extent).
const DETAIL_MARGIN: f64 = 1.3;

/// A detail view (выносной элемент) of a force polygon: the zone of its small forces drawn
/// again at a larger μ_F, so that every force of the polygon can be read.
#[derive(Debug, Clone, PartialEq)]
pub struct PolygonDetail {
    /// The zone on the polygon, polygon mm.
    pub zone: Circle,
    /// The zone enlarged: the vectors cut at its border, with their labels.
    pub figure: Figure,
}

/// A polygon has at most this many details.
const MAX_DETAILS: usize = 3;

/// The details of `polygon` about its forces `laid` (polygon mm) drawn shorter than
/// [`SMALL_FORCE_MM`]: from the shortest force not yet shown, the round μ_F that draws it
/// about [`DETAIL_FORCE_MM`], and a zone about it and the other small forces near enough to
/// share a detail [`DETAIL_MM`] wide; then the next. Empty when every force reads. A force
/// zero to the polygon's scale (shorter than [`crate::forces::ZERO_PART`] of its longest) is
/// drawn as the point it is, with no detail.
fn details(polygon: &Figure, laid: &[(DVec2, DVec2)]) -> Vec<PolygonDetail> {
    let mu = polygon.scale;
    let longest = laid.iter().map(|(a, b)| a.distance(*b)).fold(0.0, f64::max);
    let zero = crate::forces::ZERO_PART * longest;
    let mut small: Vec<(DVec2, DVec2)> = laid
        .iter()
        .copied()
        .filter(|(a, b)| a.distance(*b) > zero && a.distance(*b) < SMALL_FORCE_MM)
        .collect();
    small.sort_by(|x, y| x.0.distance(x.1).total_cmp(&y.0.distance(y.1)));
    let mut out = Vec::new();
    while let (Some(&(a, b)), true) = (small.first(), out.len() < MAX_DETAILS) {
        let Some(scale) =
            Scale::round_for(a.distance(b) * mu.value(), DETAIL_FORCE_MM, mu.quantity)
                .filter(|d| d.value() * 2.0 <= mu.value())
        else {
            break;
        };
        // The zone's largest radius on the polygon, and who fits in it with the margin.
        let reach =
            0.5 * DETAIL_MM * scale.value() / mu.value() / DETAIL_MARGIN / std::f64::consts::SQRT_2;
        let c = a.lerp(b, 0.5);
        let (members, rest): (Vec<_>, Vec<_>) = small
            .iter()
            .partition(|(p, q)| p.distance(c) <= reach && q.distance(c) <= reach);
        let (lo, hi) = members.iter().fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), (p, q)| (lo.min(p.min(*q)), hi.max(p.max(*q))),
        );
        // At least a short force's room about it, at most the detail's width (drawing mm
        // of the detail turned into polygon mm).
        let k = mu.value() / scale.value();
        let radius = (0.5 * (hi - lo).length() * DETAIL_MARGIN)
            .max(DETAIL_ROOM_MM / k)
            .min(0.5 * DETAIL_MM / k);
        let Some(zone) = Circle::new(0.5 * (lo + hi), radius) else {
            break;
        };
        out.push(PolygonDetail {
            zone,
            figure: polygon.detail_with_vectors(&zone, scale),
        });
        small = rest;
    }
    out
}

/// A force polygon being laid off.
struct Polygon {
    rec: Recorder,
    tip: DVec2,
    /// The forces laid off, polygon mm.
    laid: Vec<(DVec2, DVec2)>,
}

impl Polygon {
    fn new(title: String, mu_f: Scale, ctx: &Context) -> Self {
        Self {
            rec: Recorder::in_context(title, mu_f, ctx),
            tip: DVec2::ZERO,
            laid: Vec::new(),
        }
    }

    /// The polygon as drawn, and the details its small forces need (their zones circled on
    /// the polygon).
    fn finish(mut self) -> (Figure, Vec<PolygonDetail>) {
        let drawn = Figure {
            title: String::new(),
            scale: self.rec.scale(),
            steps: self.rec.steps().to_vec(),
        };
        let d = details(&drawn, &self.laid);
        for d in &d {
            self.rec.draw(
                "the zone of the polygon's detail",
                Item::Circle(d.zone),
                Role::Construction,
                &[],
            );
        }
        (self.rec.finish(), d)
    }
    /// Lay off a force head to tail; returns its end.
    fn lay(&mut self, name: &str, f: DVec2) -> DVec2 {
        let to = self.tip + f / self.rec.scale().value();
        if to != self.tip {
            self.laid.push((self.tip, to));
            let id = self.rec.draw(
                format!("lay off {name}"),
                Item::Vector { from: self.tip, to },
                Role::Given,
                &[],
            );
            self.rec.label(
                id,
                name,
                self.tip.lerp(to, 0.5),
                (to - self.tip).perp().normalize_or_zero(),
            );
        }
        self.tip = to;
        to
    }
    fn lay_all(&mut self, loads: &[&Load]) -> DVec2 {
        for l in loads {
            if !l.is_couple() {
                self.lay(&l.name, l.force);
            }
        }
        self.tip
    }
    /// Close the polygon: the line through `a.1` along `a.2` meets the line through `b.1`
    /// along `b.2` (each named `.0`); each drawn thin from its point to the closing point and
    /// a little past it, as the draughtsman draws them (a line drawn across the closing point
    /// would run through the label of the short reaction beside it).
    fn close(
        &mut self,
        a: (&str, DVec2, DVec2),
        b: (&str, DVec2, DVec2),
    ) -> Result<DVec2, ConstructionError> {
        const STEP: &str = "closing the polygon";
        let line = |(name, p, d): (&str, DVec2, DVec2)| {
            Line::new(p, d).ok_or_else(|| ConstructionError::CoincidentPoints {
                step: STEP.into(),
                what: format!("direction {name}"),
                a: name.into(),
                b: name.into(),
            })
        };
        let (la, lb) = (line(a)?, line(b)?);
        let (h, _, _) = self.rec.meet_lines(STEP, (a.0, &la), (b.0, &lb))?;
        for (l, start) in [(la, a.1), (lb, b.1)] {
            let (t0, t1) = (l.project_t(start), l.project_t(h));
            let (from, to) = if (t1 - t0).abs() < CLOSING_PAST_MM {
                // The unknown is about nil: the direction drawn about the closing point.
                (l.eval(t1 - CLOSING_PAST_MM), l.eval(t1 + CLOSING_PAST_MM))
            } else {
                (
                    l.eval(t0),
                    l.eval(t1 + CLOSING_PAST_MM * (t1 - t0).signum()),
                )
            };
            self.rec.draw(
                format!("{STEP}: closing direction"),
                Item::Segment(Segment::new(from, to)),
                Role::Construction,
                &[],
            );
        }
        Ok(h)
    }
    /// Read a reaction off the polygon: the vector from `from` to `to`, its length read
    /// under the drafting model; drawn and labelled `name`.
    fn read(&mut self, name: &str, from: DVec2, to: DVec2) -> DVec2 {
        let m = self.rec.measure(from, to);
        if m.drawn_mm > 0.0 {
            let id = self.rec.draw(
                format!("read {name}"),
                Item::Vector { from, to },
                Role::Result,
                &[],
            );
            self.rec.label(
                id,
                name,
                from.lerp(to, 0.5),
                (to - from).perp().normalize_or_zero(),
            );
        }
        (to - from).normalize_or_zero() * m.value
    }
}

/// How far a polygon's closing direction is drawn past the closing point, mm.
const CLOSING_PAST_MM: f64 = 5.0;

/// The markup name of the force of link `a` on link `b`.
pub fn reaction_name(a: usize, b: usize) -> String {
    format!("R_{{{a}-{b}}}")
}

fn revolute(from: usize, to: usize, k: usize, force: DVec2) -> Reaction {
    Reaction {
        pair: Pair {
            from,
            to,
            kind: PairKind::Revolute(k),
        },
        force,
        offset: None,
    }
}

fn prismatic(
    from: usize,
    to: usize,
    reference: usize,
    dir_link: usize,
    force: DVec2,
    offset: Option<f64>,
) -> Reaction {
    Reaction {
        pair: Pair {
            from,
            to,
            kind: PairKind::Prismatic {
                reference,
                dir_link,
            },
        },
        force,
        offset,
    }
}

/// The loads (and the reactions already found) on link `l`.
fn on(loads: &[Load], l: usize) -> Vec<&Load> {
    loads.iter().filter(|x| x.link == l).collect()
}

/// The offset `s` along the slide that makes the moment about the reference of `f` (its
/// magnitude N along the unit normal `n`) and `k` (N·m) vanish: N·s + k = 0 (`None`: N is
/// zero to the loads' scale `scale`, N).
fn offset(f: DVec2, n: DVec2, k: f64, scale: f64) -> Option<f64> {
    crate::forces::arm(f.dot(n), k, scale)
}

/// The polygons of every group, last first, then the driving link. `loads` are the
/// position's external loads.
pub fn polygons(
    board: &Board<'_>,
    loads: &[Load],
    drive: &Drive,
) -> Result<Polygons, (usize, ConstructionError)> {
    let prog = board.setup.prog;
    let b = board.setup.built;
    let mut applied: Vec<Load> = loads.to_vec();
    // The drawing's points are in mm: the reach in m.
    let reach = crate::forces::reach(&b.p) * board.setup.mu_l.value();
    let scale = crate::forces::force_scale(loads, reach);
    let mut groups = Vec::new();
    let dir = |l: usize| DVec2::from_angle(b.angle[l]);
    for g in prog.groups().rev() {
        let (group, [i, j]) = (g.group, g.links);
        let title = format!("group {} ({}, {})", group + 1, i, j);
        let mut sch = Scheme::new(board, title.clone());
        draw_links(
            &mut sch.rec,
            prog,
            b,
            Role::Given,
            "group",
            Part::Group(group),
        );
        let li = on(&applied, i);
        let lj = on(&applied, j);
        for l in li.iter().chain(&lj) {
            sch.show(l);
        }
        let mut pol = Polygon::new(
            format!("force polygon of {title}"),
            board.mu_f,
            &board.setup.ctx,
        );
        let p = |k: usize| b.p[k];
        let err = |e| (group, e);
        let mut equations = Vec::new();
        let reactions = match g.pairs {
            GroupPairs::Rrr { a, c, joint } => {
                let (pa, pc, pb) = (p(a), p(c), p(joint));
                let (oa, oc) = (prog.owner(a), prog.owner(c));
                sch.drain();
                let tau_i = sch.moments(pb, &li) / sch.length(pa, pb);
                let t = sch.tangential(pa, pb, (oa, i), tau_i);
                equations.push(sch.equation(joint, &[i], t));
                let tau_j = sch.moments(pb, &lj) / sch.length(pc, pb);
                let t = sch.tangential(pc, pb, (oc, j), tau_j);
                equations.push(sch.equation(joint, &[j], t));
                let t_a = (pb - pa).normalize().perp() * tau_i;
                let t_c = (pb - pc).normalize().perp() * tau_j;
                let p0 = pol.tip;
                let p1 = pol.lay(&format!("R^τ_{{{oa}-{i}}}"), t_a);
                let pi = pol.lay_all(&li);
                pol.lay_all(&lj);
                let pbj = pol.tip;
                let e = pol.lay(&format!("R^τ_{{{oc}-{j}}}"), t_c);
                let h = pol
                    .close(("∥ CB", e, pb - pc), ("∥ AB", p0, pb - pa))
                    .map_err(err)?;
                let r_a = pol.read(&reaction_name(oa, i), h, p1);
                let r_c = pol.read(&reaction_name(oc, j), pbj, h);
                let r_ji = pol.read(&reaction_name(j, i), pi, h);
                vec![
                    revolute(oa, i, a, r_a),
                    revolute(oc, j, c, r_c),
                    revolute(i, j, joint, -r_ji),
                ]
            }
            GroupPairs::Rrp {
                a,
                guide: og,
                joint,
            } => {
                let (pa, pb) = (p(a), p(joint));
                let oa = prog.owner(a);
                sch.drain();
                let tau_i = sch.moments(pb, &li) / sch.length(pa, pb);
                let t = sch.tangential(pa, pb, (oa, i), tau_i);
                equations.push(sch.equation(joint, &[i], t));
                let t_a = (pb - pa).normalize().perp() * tau_i;
                let n_g = dir(j).perp();
                let p0 = pol.tip;
                let p1 = pol.lay(&format!("R^τ_{{{oa}-{i}}}"), t_a);
                let pi = pol.lay_all(&li);
                let e = pol.lay_all(&lj);
                let h = pol
                    .close(("⊥ guide", e, n_g), ("∥ AB", p0, pb - pa))
                    .map_err(err)?;
                let r_a = pol.read(&reaction_name(oa, i), h, p1);
                let r_g = pol.read(&reaction_name(og, j), e, h);
                let r_ji = pol.read(&reaction_name(j, i), pi, h);
                sch.drain();
                let k = sch.moments(pb, &lj);
                let s = offset(r_g, n_g, k, scale);
                equations.extend(sch.arm_equation(joint, j, (og, j), r_g.dot(n_g), s));
                vec![
                    revolute(oa, i, a, r_a),
                    prismatic(og, j, joint, j, r_g, s),
                    revolute(i, j, joint, -r_ji),
                ]
            }
            GroupPairs::Rpr { a, c } => {
                let (pa, pc) = (p(a), p(c));
                let (oa, oc) = (prog.owner(a), prog.owner(c));
                let u = dir(j);
                let n = u.perp();
                sch.drain();
                let k_i = sch.moments(pa, &li);
                let k_j = sch.moments(pc, &lj);
                let known = sch.drain();
                // The inner reaction N·n brought to A: its arm about C is measured.
                let probe = Load::force(j, LoadKind::Reaction, reaction_name(i, j), n, a);
                let arm = sch.moment(pc, &probe);
                let big_n = -(k_j + k_i) / arm;
                equations.push(sch.normal(c, [i, j], known, big_n));
                let p0 = pol.tip;
                let pi = pol.lay_all(&li);
                let pj = pol.lay_all(&lj);
                let q = pi - n * big_n / board.mu_f.value();
                pol.rec.draw(
                    "R_{ij} laid from the end of i's loads",
                    Item::Segment(Segment::new(pi, q)),
                    Role::Construction,
                    &[],
                );
                let r_ji = pol.read(&reaction_name(j, i), pi, q);
                let r_oj = pol.read(&reaction_name(oc, j), pj, q);
                let r_oi = pol.read(&reaction_name(oa, i), q, p0);
                let r_ij = -r_ji;
                vec![
                    revolute(oa, i, a, r_oi),
                    revolute(oc, j, c, r_oj),
                    prismatic(i, j, a, j, r_ij, offset(r_ij, n, -k_i, scale)),
                ]
            }
            GroupPairs::Prp {
                gi: ci,
                gj: cj,
                joint,
            } => {
                let pb = p(joint);
                let (n_i, n_j) = (dir(i).perp(), dir(j).perp());
                let p0 = pol.tip;
                let pi = pol.lay_all(&li);
                let e = pol.lay_all(&lj);
                let h = pol
                    .close(("⊥ guide j", e, n_j), ("⊥ guide i", p0, n_i))
                    .map_err(err)?;
                let r_j = pol.read(&reaction_name(cj, j), e, h);
                let r_i = pol.read(&reaction_name(ci, i), h, p0);
                let r_ji = pol.read(&reaction_name(j, i), pi, h);
                sch.drain();
                let k_i = sch.moments(pb, &li);
                let s_i = offset(r_i, n_i, k_i, scale);
                equations.extend(sch.arm_equation(joint, i, (ci, i), r_i.dot(n_i), s_i));
                let k_j = sch.moments(pb, &lj);
                let s_j = offset(r_j, n_j, k_j, scale);
                equations.extend(sch.arm_equation(joint, j, (cj, j), r_j.dot(n_j), s_j));
                vec![
                    prismatic(ci, i, joint, i, r_i, s_i),
                    prismatic(cj, j, joint, j, r_j, s_j),
                    revolute(i, j, joint, -r_ji),
                ]
            }
            GroupPairs::Rpp {
                a,
                guide: og,
                joint,
            } => {
                let (pa, pj_) = (p(a), p(joint));
                let oa = prog.owner(a);
                let (n_s, n_g) = (dir(i).perp(), dir(j).perp());
                let p0 = pol.tip;
                let pj = pol.lay_all(&lj);
                let h = pol
                    .close(("⊥ guide", pj, n_g), ("⊥ slide", p0, n_s))
                    .map_err(err)?;
                let r_g = pol.read(&reaction_name(og, j), pj, h);
                let r_ij = pol.read(&reaction_name(i, j), h, p0);
                pol.tip = h;
                let q = pol.lay_all(&li);
                let r_oi = pol.read(&reaction_name(oa, i), q, p0);
                // The block about A: where the inner reaction acts on the slide.
                sch.drain();
                let k_i = sch.moments(pa, &li);
                let s = offset(r_ij, n_s, -k_i, scale);
                equations.extend(sch.arm_equation(a, i, (i, j), -r_ij.dot(n_s), s));
                // Link j about its joint, with the inner reaction at its point.
                let shift = dir(i) * s.unwrap_or(0.0);
                let mut inner = Load::force(j, LoadKind::Reaction, reaction_name(i, j), r_ij, a);
                inner.shift = shift;
                let k_j = sch.moments(pj_, &lj) + sch.moment(pj_, &inner);
                let s_g = offset(r_g, n_g, k_j, scale);
                equations.extend(sch.arm_equation(joint, j, (og, j), r_g.dot(n_g), s_g));
                vec![
                    revolute(oa, i, a, r_oi),
                    prismatic(og, j, joint, j, r_g, s_g),
                    prismatic(i, j, a, i, r_ij, s),
                ]
            }
        };
        // The reactions on earlier links become their loads.
        for r in &reactions[..2] {
            if r.pair.from != 0 {
                let (at, shift) = point_of(r, b);
                let mut l = Load::force(
                    r.pair.from,
                    LoadKind::Reaction,
                    reaction_name(r.pair.to, r.pair.from),
                    -r.force,
                    at,
                );
                l.shift = shift;
                applied.push(l);
            }
        }
        for r in &reactions {
            show_reaction(&mut sch, r);
        }
        let (polygon, detail) = pol.finish();
        groups.push(GroupPolygon {
            group,
            links: [i, j],
            scheme: sch.rec.finish(),
            polygon,
            details: detail,
            reactions,
            equations,
        });
    }
    let driver = driver(board, &applied, drive).map_err(|e| (usize::MAX, e))?;
    Ok(Polygons { groups, driver })
}

/// Where a reaction acts: its pair's point, shifted along the slide by its offset.
fn point_of(r: &Reaction, b: &Built) -> (usize, DVec2) {
    match r.pair.kind {
        PairKind::Revolute(k) => (k, DVec2::ZERO),
        PairKind::Prismatic {
            reference,
            dir_link,
        } => {
            let u = DVec2::from_angle(b.angle[dir_link]);
            (reference, u * r.offset.unwrap_or(0.0))
        }
    }
}

/// How far the frame's guide is drawn past the slider and past its reaction's point, mm.
const GUIDE_PAST_MM: f64 = 12.0;

/// Offset of a reaction arm's dimension line from the guide, mm.
const ARM_DIMENSION_MM: f64 = 10.0;

/// The frame's guide under a slider whose reaction's point lies `offset` (m) along it from
/// the slider's joint: the guide drawn (hatched on the frame's side) against the block's
/// side, from past the slider to past the point — so that the loads along the slide's axis
/// stay clear of it — and the arm dimensioned from the joint, labelled h₀₋ⱼ: the reaction
/// stands on the guide at its arm, as the moment equation placed it. Returns the reaction's
/// point on the guide's line (mm) and the unit normal from the slide's axis to that line.
fn show_guide_arm(sch: &mut Scheme<'_>, r: &Reaction, offset: f64) -> Option<(DVec2, DVec2)> {
    let PairKind::Prismatic {
        reference,
        dir_link,
    } = r.pair.kind
    else {
        return None;
    };
    let b = sch.board.setup.built;
    let prog = sch.board.setup.prog;
    let mu = sch.board.setup.mu_l.value();
    let u = DVec2::from_angle(b.angle[dir_link]);
    // Hatched on the side away from the mechanism, as on the plan of positions; the guide's
    // line on the block's side towards the hatching.
    let axis = b.p[reference];
    let (hatch, side, towards) = if u.perp_dot(b.p[prog.centre] - axis) > 0.0 {
        (crate::geom::Side::Right, -1.0, -u.perp())
    } else {
        (crate::geom::Side::Left, 1.0, u.perp())
    };
    let joint = axis + towards * Item::SLIDER_HALF_MM.1;
    let point = joint + u * (offset / mu);
    let (lo, hi) = (offset.min(0.0) / mu, offset.max(0.0) / mu);
    sch.rec.draw(
        format!("guide of link {} under its reaction", r.pair.to),
        Item::Guide {
            segment: Segment::new(
                joint + u * (lo - GUIDE_PAST_MM),
                joint + u * (hi + GUIDE_PAST_MM),
            ),
            hatch,
        },
        Role::Given,
        &[],
    );
    if sch.rec.measure(joint, point).drawn_mm > 0.5 {
        // The dimension beyond the hatching, clear of the group.
        let (from, to) = if offset >= 0.0 {
            (joint, point)
        } else {
            (point, joint)
        };
        sch.rec.dimension(
            format!(
                "arm of {} on the guide",
                reaction_name(r.pair.from, r.pair.to)
            ),
            (from, to, ARM_DIMENSION_MM * side),
            format!("h_{{{}-{}}}", r.pair.from, r.pair.to),
        );
    }
    Some((point, towards))
}

/// Draw a reaction found on the group's drawing, at its point (the frame's reaction on a
/// slider on its guide, with its arm).
fn show_reaction(sch: &mut Scheme<'_>, r: &Reaction) {
    if let (0, Some(offset)) = (r.pair.from, r.offset) {
        let on_guide = show_guide_arm(sch, r, offset);
        if let (Some((g, towards)), Some(e)) = (on_guide, r.force.try_normalize()) {
            // The frame's reaction stands on the guide's line: from it when it pushes the
            // block off the guide, onto it when it pulls the block to the guide.
            let name = reaction_name(r.pair.from, r.pair.to);
            sch.arrow(&name, g, e, e.dot(towards) >= 0.0);
            return;
        }
    }
    let (at, shift) = point_of(r, sch.board.setup.built);
    let l = Load::force(
        r.pair.to,
        LoadKind::Reaction,
        reaction_name(r.pair.from, r.pair.to),
        r.force,
        at,
    );
    let l = Load { shift, ..l };
    sch.show(&l);
}
