//! Kind 2, RRP (ВВП): link i pivoted at the known point `a` and jointed at the new point
//! `joint` to the slider j, which carries `joint` along a guide: the circle about `a` met by
//! the guide.

use super::{guide_uses, GroupKind, Words};
use crate::construct::{ConstructionError, Pick, Recorder};
use crate::linkage::construction::{heading, pick, Built, Frames};
use crate::linkage::groups::GroupPairs;
use crate::linkage::model::{Branch, DyadKind};
use crate::linkage::positions_draw::Pen;
use crate::linkage::program::PGuide;
use crate::linkage::program::Program;

/// The kind's words.
pub(super) const WORDS: Words = Words {
    number: 2,
    letters: "RRP",
    letters_ru: "ВВП",
    keys: &["links", "a", "la", "guide", "joint", "branch"],
};

/// A compiled RRP group.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::linkage) struct Rrp {
    /// Link i's outer pair.
    pub a: usize,
    /// |a joint|, m.
    pub la: f64,
    /// The line the joint moves on.
    pub guide: PGuide,
    /// The new joint.
    pub joint: usize,
    /// The assembly at the first position (forward or backward along the guide).
    pub branch: Branch,
}

impl GroupKind for Rrp {
    fn kind(&self) -> DyadKind {
        DyadKind::Rrp
    }
    fn joint(&self) -> Option<usize> {
        Some(self.joint)
    }
    fn guides(&self) -> [Option<PGuide>; 2] {
        [Some(self.guide), None]
    }
    fn guides_mut(&mut self) -> [Option<&mut PGuide>; 2] {
        [Some(&mut self.guide), None]
    }
    fn on_links(&self, k: usize) -> [bool; 2] {
        [self.a == k || self.joint == k, self.joint == k]
    }
    fn uses(&self, k: usize) -> bool {
        self.a == k || guide_uses(self.guide, k)
    }
    fn pivots(&self) -> Vec<usize> {
        vec![self.a]
    }
    fn construct(
        &self,
        prog: &Program,
        rec: &mut Recorder,
        pos: &mut Built,
        prev: Option<&Built>,
        (s, _): (&str, usize),
    ) -> Result<Frames, ConstructionError> {
        let mu = rec.scale().value();
        let line = prog.line_or_fail(&self.guide, &pos.p, mu, s)?;
        let side = if self.branch == Branch::Backward {
            Pick::Backward
        } else {
            Pick::Forward
        };
        let c = prog.compass(&pos.p, self.a, self.la / mu);
        let on = (&*prog.guide_name(&self.guide), &line);
        let step = prog.joint_step(s, self.joint);
        let met = rec.meet_line_circle(&step, on, c, pick(prev, self.joint, side))?;
        let (x, crossing) = pos.place(self.joint, met);
        Ok(Frames {
            angle: [heading(x - pos.p[self.a]), line.angle()],
            origin: [self.a, self.joint],
            crossing,
        })
    }
    fn draw(&self, pen: &mut Pen<'_>, _: &Program, b: &Built, [i, j]: [u32; 2]) {
        let (a, joint) = (b.p[self.a], b.p[self.joint]);
        pen.link(i, a, joint);
        pen.slider(j, joint, b.angle[j as usize]);
        pen.anchors.extend([(i, a.lerp(joint, 0.5)), (j, joint)]);
        pen.joints.extend([self.a, self.joint]);
    }
    fn pairs(&self) -> GroupPairs {
        GroupPairs::Rrp {
            a: self.a,
            guide: self.guide.carrier,
            joint: self.joint,
        }
    }
    fn piston(&self, k: usize) -> Option<PGuide> {
        (self.joint == k).then_some(self.guide)
    }
}
