//! A group's drawing at μ_l as the force analysis works it: its loads drawn as arrows, their
//! arms measured about a moment centre, and the reactions found drawn at their points (the
//! frame's reaction on a slider standing on its guide at its arm).

use super::MomentTerm;
use super::{drawn_dir, point_of, reaction_name, Board};
use crate::construct::{Item, Recorder, Role};
use crate::forces::loads::{Load, LoadKind};
use crate::forces::twin::{PairKind, Reaction};
use crate::geom::{DVec2, Segment};

/// Length of a load's arrow on a group's drawing, mm (the drawing shows where and which
/// way; the polygon shows how much).
pub(in crate::forces) const ARROW_MM: f64 = 14.0;

/// A link's loads and its arms measured on a drawing.
pub(super) struct Scheme<'a> {
    pub(super) board: &'a Board<'a>,
    pub(super) rec: Recorder,
    /// The arms numbered so far on the position's drawings: a new arm is `h_{arms + 1}`.
    pub(super) arms: usize,
    /// The moments taken since the log was last drained.
    pub(super) log: Vec<MomentTerm>,
}

impl<'a> Scheme<'a> {
    /// A drawing of the position titled `title`, its arms numbered on from `arms` (the
    /// drawings of one sheet number their arms on, so that no `h_{n}` names two arms).
    pub(super) fn new(board: &'a Board<'a>, title: String, arms: usize) -> Self {
        Self {
            board,
            rec: Recorder::in_context(title, board.setup.mu_l, &board.setup.ctx),
            arms,
            log: Vec::new(),
        }
    }

    /// Where a load acts on the drawing, mm.
    pub(super) fn at(&self, l: &Load) -> DVec2 {
        self.board.setup.built.p[l.at] + l.shift / self.board.setup.mu_l.value()
    }

    /// Draw a load: an arrow at its point (a couple: an arc arrow about the link's origin),
    /// apart from the loads already drawn there ([`crate::forces::arrows`]).
    pub(super) fn show(&mut self, l: &Load) {
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
    pub(super) fn arrow(&mut self, name: &str, x: DVec2, e: DVec2, onto: bool) {
        crate::forces::arrows::arrow(
            &mut self.rec,
            format!("load {name}"),
            name,
            (x, e, ARROW_MM),
            onto,
        );
    }

    /// The moment of `l` about `c` (mm), N·m: the arm measured on the drawing.
    pub(super) fn moment(&mut self, c: DVec2, l: &Load) -> f64 {
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
            if foot.distance(x) > 0.5 {
                self.rec.draw(
                    format!("line of action of {} to the foot of its arm", l.name),
                    Item::Segment(Segment::new(x, foot)),
                    Role::Construction,
                    &[],
                );
            }
            crate::forces::arrows::arm(
                &mut self.rec,
                format!("arm of {} about the moment centre", l.name),
                (c, foot),
                &format!("h_{{{}}}", self.arms),
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
    pub(super) fn moments(&mut self, c: DVec2, loads: &[&Load]) -> f64 {
        loads.iter().map(|l| self.moment(c, l)).sum()
    }

    /// A length measured on the drawing, m.
    pub(super) fn length(&mut self, a: DVec2, b: DVec2) -> f64 {
        self.rec.measure(a, b).value
    }
}

/// How far the frame's guide is drawn past the slider and past its reaction's point, mm.
pub(super) const GUIDE_PAST_MM: f64 = 12.0;

/// Offset of a reaction arm's dimension line from the guide, mm.
pub(super) const ARM_DIMENSION_MM: f64 = 10.0;

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
    // Hatched on the wall `guide_wall` takes (away from the mechanism, as on the plan of
    // positions); the guide's line on the block's side towards the hatching.
    let axis = b.p[reference];
    let towards = super::wall::guide_wall(u, axis, r.force, (b.p[prog.centre], &b.p));
    let (hatch, side) = if towards == -u.perp() {
        (crate::geom::Side::Right, -1.0)
    } else {
        (crate::geom::Side::Left, 1.0)
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
pub(super) fn show_reaction(sch: &mut Scheme<'_>, r: &Reaction) {
    if let (0, Some(offset)) = (r.pair.from, r.offset) {
        let on_guide = show_guide_arm(sch, r, offset);
        if let (Some((g, towards)), Some(e)) = (on_guide, r.force.try_normalize()) {
            // The frame's reaction stands on the guide's line: from it when it pushes the
            // block off the guide, onto it when it pulls the block to the guide.
            let name = reaction_name(r.pair.from, r.pair.to);
            let pulls = e.dot(towards) >= 0.0;
            let mu = sch.board.setup.mu_l.value();
            // A pull at a point of the block is the push of the guide's other side on the
            // block's other face: drawn onto that face, its arrow stays clear of the block
            // (onto the guide's line it crossed the block and its head lay under the joint).
            let across = if pulls && (offset / mu).abs() <= Item::SLIDER_HALF_MM.0 {
                towards * (2.0 * Item::SLIDER_HALF_MM.1)
            } else {
                DVec2::ZERO
            };
            sch.arrow(&name, g - across, e, pulls);
            return;
        }
    }
    let (at, shift) = point_of(r, drawn_dir(sch.board.setup.built));
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
