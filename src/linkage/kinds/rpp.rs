//! Kind 5, RPP (ВПП): the block i pivoted at the known point `a` slides in link j along a
//! slide direction; link j translates along a guide; the new point `joint` of link j is where
//! the slide line through `a` meets the guide.

use super::{dir_uses, guide_uses, GroupKind, Words};
use crate::construct::{ConstructionError, Item, Recorder, Role};
use crate::geom::{DVec2, Line, Segment};
use crate::linkage::construction::{other, Built, Frames};
use crate::linkage::groups::GroupPairs;
use crate::linkage::model::DyadKind;
use crate::linkage::positions_draw::Pen;
use crate::linkage::program::Program;
use crate::linkage::program::{PDir, PGuide};

/// The kind's words.
pub(super) const WORDS: Words = Words {
    number: 5,
    letters: "RPP",
    letters_ru: "ВПП",
    keys: &["links", "a", "slide", "guide", "joint"],
};

/// A compiled RPP group.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::linkage) struct Rpp {
    /// The block's pin (link i's outer pair).
    pub a: usize,
    /// The direction of the inner sliding pair.
    pub slide: PDir,
    /// Link j's guide.
    pub guide: PGuide,
    /// Link j's new point.
    pub joint: usize,
}

impl GroupKind for Rpp {
    fn kind(&self) -> DyadKind {
        DyadKind::Rpp
    }
    fn joint(&self) -> Option<usize> {
        Some(self.joint)
    }
    fn joint_on_j(&self) -> bool {
        true
    }
    fn guides(&self) -> [Option<PGuide>; 2] {
        [Some(self.guide), None]
    }
    fn guides_mut(&mut self) -> [Option<&mut PGuide>; 2] {
        [Some(&mut self.guide), None]
    }
    fn directions(&self) -> [Option<PDir>; 2] {
        [Some(self.slide), Some(self.guide.dir)]
    }
    fn on_links(&self, k: usize) -> [bool; 2] {
        [self.a == k, self.joint == k]
    }
    fn uses(&self, k: usize) -> bool {
        self.a == k || dir_uses(self.slide, k) || guide_uses(self.guide, k)
    }
    fn pivots(&self) -> Vec<usize> {
        vec![self.a]
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
        let a = pos.p[self.a];
        let sl = Line::new(a, DVec2::from_angle(prog.drawn_dir(&self.slide, &pos.p)))
            .ok_or_else(|| other(s, "slide direction"))?;
        let g = prog.line_or_fail(&self.guide, &pos.p, mu, s)?;
        let name = format!("slide line through {}", prog.names[self.a]);
        let on = (&*prog.guide_name(&self.guide), &g);
        let met = rec.meet_lines(&prog.joint_step(s, self.joint), (&name, &sl), on)?;
        rec.draw(
            format!("{s}: {name}"),
            Item::Segment(Segment::new(a, met.0)),
            Role::Construction,
            &[met.2],
        );
        let (_, crossing) = pos.place(self.joint, met);
        Ok(Frames {
            angle: [sl.angle(), g.angle()],
            origin: [self.a, self.joint],
            crossing,
        })
    }
    fn draw(&self, pen: &mut Pen<'_>, _: &Program, b: &Built, [i, j]: [u32; 2]) {
        let (a, joint) = (b.p[self.a], b.p[self.joint]);
        pen.link(j, a, joint);
        pen.slider(i, a, b.angle[i as usize]);
        pen.slider(j, joint, b.angle[j as usize]);
        pen.anchors.extend([(i, a), (j, joint)]);
        pen.joints.push(self.a);
    }
    fn pairs(&self) -> GroupPairs {
        GroupPairs::Rpp {
            a: self.a,
            guide: self.guide.carrier,
            joint: self.joint,
        }
    }
}
