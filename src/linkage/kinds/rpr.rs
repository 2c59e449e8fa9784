//! Kind 3, RPR (ВПВ): the block i pivoted at the known point `a` slides along link j, which
//! turns about the known pivot `c`; j's slide line passes `offset` m to the left of `c`. It
//! creates no point: its slide line is found.

use super::{GroupKind, Words};
use crate::construct::{ConstructionError, Recorder};
use crate::geom::DVec2;
use crate::linkage::construction::{Built, Frames};
use crate::linkage::groups::GroupPairs;
use crate::linkage::model::DyadKind;
use crate::linkage::positions_draw::{link_reach, Pen};
use crate::linkage::program::Program;

/// The kind's words.
pub(super) const WORDS: Words = Words {
    number: 3,
    letters: "RPR",
    letters_ru: "ВПВ",
    keys: &["links", "a", "c", "offset"],
};

/// A compiled RPR group.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::linkage) struct Rpr {
    /// The block's pin (link i's outer pair).
    pub a: usize,
    /// Link j's pivot.
    pub c: usize,
    /// The offset of the slide line from `c`, m.
    pub offset: f64,
}

impl GroupKind for Rpr {
    fn kind(&self) -> DyadKind {
        DyadKind::Rpr
    }
    fn joint(&self) -> Option<usize> {
        None
    }
    fn on_links(&self, k: usize) -> [bool; 2] {
        [self.a == k, self.c == k]
    }
    fn uses(&self, k: usize) -> bool {
        self.a == k || self.c == k
    }
    fn pivots(&self) -> Vec<usize> {
        vec![self.a, self.c]
    }
    fn construct(
        &self,
        prog: &Program,
        rec: &mut Recorder,
        pos: &mut Built,
        prev: Option<&Built>,
        (s, j): (&str, usize),
    ) -> Result<Frames, ConstructionError> {
        let prev = prev.map(|q| q.angle[j]);
        let th = prog.slide_line(rec, s, &pos.p, (self.a, self.c), self.offset, prev)?;
        Ok(Frames {
            angle: [th, th],
            origin: [self.a, self.c],
            crossing: std::f64::consts::FRAC_PI_2,
        })
    }
    fn draw(&self, pen: &mut Pen<'_>, prog: &Program, b: &Built, [i, j]: [u32; 2]) {
        let th = b.angle[j as usize];
        let u = DVec2::from_angle(th);
        let (a, c) = (b.p[self.a], b.p[self.c]);
        let mu = pen.rec.scale().value();
        let reach = link_reach(prog, j, mu).max((a - c).dot(u) + 6.0);
        pen.link(j, c, c + u * reach);
        pen.slider(i, a, th);
        pen.anchors.extend([(i, a), (j, c + u * (reach * 0.8))]);
        pen.joints.extend([self.a, self.c]);
    }
    fn pairs(&self) -> GroupPairs {
        GroupPairs::Rpr {
            a: self.a,
            c: self.c,
        }
    }
}
