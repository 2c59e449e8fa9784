//! Kind 4, PRP (ПВП): link i slides along one guide, link j along another, the two jointed
//! at the new point `joint`, where the guides meet.

use super::{guide_uses, GroupKind, Words};
use crate::construct::{ConstructionError, Recorder};
use crate::geom::DVec2;
use crate::linkage::construction::{Built, Frames};
use crate::linkage::groups::GroupPairs;
use crate::linkage::model::DyadKind;
use crate::linkage::positions_draw::Pen;
use crate::linkage::program::PGuide;
use crate::linkage::program::Program;

/// The kind's words.
pub(super) const WORDS: Words = Words {
    number: 4,
    letters: "PRP",
    letters_ru: "ПВП",
    keys: &["links", "guide_i", "guide_j", "joint"],
};

/// A compiled PRP group.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::linkage) struct Prp {
    /// Link i's guide.
    pub gi: PGuide,
    /// Link j's guide.
    pub gj: PGuide,
    /// The new joint.
    pub joint: usize,
}

impl GroupKind for Prp {
    fn kind(&self) -> DyadKind {
        DyadKind::Prp
    }
    fn joint(&self) -> Option<usize> {
        Some(self.joint)
    }
    fn guides(&self) -> [Option<PGuide>; 2] {
        [Some(self.gi), Some(self.gj)]
    }
    fn guides_mut(&mut self) -> [Option<&mut PGuide>; 2] {
        [Some(&mut self.gi), Some(&mut self.gj)]
    }
    fn on_links(&self, k: usize) -> [bool; 2] {
        [self.joint == k, self.joint == k]
    }
    fn uses(&self, k: usize) -> bool {
        guide_uses(self.gi, k) || guide_uses(self.gj, k)
    }
    fn pivots(&self) -> Vec<usize> {
        Vec::new()
    }
    fn construct(
        &self,
        prog: &Program,
        rec: &mut Recorder,
        pos: &mut Built,
        _: Option<&Built>,
        (s, _): (&str, usize),
    ) -> Result<Frames, ConstructionError> {
        let mu = rec.scale().value();
        let l1 = prog.line_or_fail(&self.gi, &pos.p, mu, s)?;
        let l2 = prog.line_or_fail(&self.gj, &pos.p, mu, s)?;
        let (n1, n2) = (prog.guide_name(&self.gi), prog.guide_name(&self.gj));
        let step = prog.joint_step(s, self.joint);
        let met = rec.meet_lines(&step, (&n1, &l1), (&n2, &l2))?;
        let (_, crossing) = pos.place(self.joint, met);
        Ok(Frames {
            angle: [l1.angle(), l2.angle()],
            origin: [self.joint, self.joint],
            crossing,
        })
    }
    fn draw(&self, pen: &mut Pen<'_>, _: &Program, b: &Built, [i, j]: [u32; 2]) {
        let joint = b.p[self.joint];
        pen.slider(i, joint, b.angle[i as usize]);
        let u = DVec2::from_angle(b.angle[j as usize]) * 8.0;
        pen.link(j, joint - u, joint + u);
        pen.anchors.extend([(i, joint), (j, joint + u)]);
        pen.joints.push(self.joint);
    }
    fn pairs(&self) -> GroupPairs {
        GroupPairs::Prp {
            gi: self.gi.carrier,
            gj: self.gj.carrier,
            joint: self.joint,
        }
    }
}
