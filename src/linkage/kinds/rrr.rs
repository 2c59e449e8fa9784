//! Kind 1, RRR (ВВВ): link i pivoted at the known point `a`, link j at the known `b`, the two
//! jointed at the new point `joint`, found where the circles about `a` and `b` meet.

use super::{GroupKind, Words};
use crate::construct::{ConstructionError, Pick, Recorder};
use crate::linkage::construction::{heading, pick, Built, Frames};
use crate::linkage::groups::GroupPairs;
use crate::linkage::model::{Branch, DyadKind};
use crate::linkage::positions_draw::Pen;
use crate::linkage::program::Program;

/// The kind's words.
pub(super) const WORDS: Words = Words {
    number: 1,
    letters: "RRR",
    letters_ru: "ВВВ",
    keys: &["links", "a", "la", "b", "lb", "joint", "branch"],
};

/// A compiled RRR group.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::linkage) struct Rrr {
    /// Link i's outer pair.
    pub a: usize,
    /// |a joint|, m.
    pub la: f64,
    /// Link j's outer pair.
    pub b: usize,
    /// |b joint|, m.
    pub lb: f64,
    /// The new joint.
    pub joint: usize,
    /// The assembly at the first position (left or right of a → b).
    pub branch: Branch,
}

impl GroupKind for Rrr {
    fn kind(&self) -> DyadKind {
        DyadKind::Rrr
    }
    fn joint(&self) -> Option<usize> {
        Some(self.joint)
    }
    fn on_links(&self, k: usize) -> [bool; 2] {
        [
            self.a == k || self.joint == k,
            self.b == k || self.joint == k,
        ]
    }
    fn uses(&self, k: usize) -> bool {
        self.a == k || self.b == k
    }
    fn pivots(&self) -> Vec<usize> {
        vec![self.a, self.b]
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
        let side = if self.branch == Branch::Right {
            Pick::Right
        } else {
            Pick::Left
        };
        let (ca, cb) = (
            prog.compass(&pos.p, self.a, self.la / mu),
            prog.compass(&pos.p, self.b, self.lb / mu),
        );
        let step = prog.joint_step(s, self.joint);
        let met = rec.meet_circles(&step, ca, cb, pick(prev, self.joint, side))?;
        let (x, crossing) = pos.place(self.joint, met);
        Ok(Frames {
            angle: [heading(x - pos.p[self.a]), heading(x - pos.p[self.b])],
            origin: [self.a, self.b],
            crossing,
        })
    }
    fn draw(&self, pen: &mut Pen<'_>, _: &Program, b: &Built, [i, j]: [u32; 2]) {
        let (a, c, joint) = (b.p[self.a], b.p[self.b], b.p[self.joint]);
        pen.link(i, a, joint);
        pen.link(j, c, joint);
        pen.anchors
            .extend([(i, a.lerp(joint, 0.5)), (j, c.lerp(joint, 0.5))]);
        pen.joints.extend([self.a, self.b, self.joint]);
    }
    fn pairs(&self) -> GroupPairs {
        GroupPairs::Rrr {
            a: self.a,
            c: self.b,
            joint: self.joint,
        }
    }
}
