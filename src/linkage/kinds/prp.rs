//! Kind 4, PRP (ПВП): link i slides along one guide, link j along another, the two jointed
//! at the new point `joint`, where the guides meet.

use super::{guide_uses, GroupKind, Planned, Solved, Words};
use crate::construct::{ConstructionError, Recorder};
use crate::geom::DVec2;
use crate::linkage::analytic::jet::meet;
use crate::linkage::analytic::state::State;
use crate::linkage::built::{Built, Frames};
use crate::linkage::compiled::Compiled;
use crate::linkage::indexed::PGuide;
use crate::linkage::model::DyadKind;
use crate::linkage::pairs::GroupPairs;
use crate::linkage::pen::Pen;
use crate::linkage::plans::builder::Builder;
use crate::linkage::plans::names::plain;
use crate::linkage::plans::plan::PlanKind;

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
        prog: &dyn Compiled,
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
    /// Two sliders joined by a pin (the textbook's ПВП): link j a block on its guide, link i
    /// a block on its own over it.
    fn draw(&self, pen: &mut Pen<'_>, _: &dyn Compiled, b: &Built, [i, j]: [u32; 2]) {
        let joint = b.p[self.joint];
        pen.slider(j, joint, b.angle[j as usize]);
        pen.slider(i, joint, b.angle[i as usize]);
        let u = DVec2::from_angle(b.angle[j as usize]) * 8.0;
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
    /// PRP: the joint where the two guides meet, its rates from the two moving lines.
    #[inline(always)] // the kernel's inner loop: see `PDyad::solve`
    fn solve(&self, _: &dyn Compiled, st: &mut State<'_>, [i, j]: [usize; 2]) -> Solved {
        let (l1, l2) = (st.guide(&self.gi), st.guide(&self.gj));
        let (x, s) = meet(l1, l2)
            .ok_or_else(|| st.fail(format!("the guides of links {i} and {j} are parallel")))?;
        st.set(self.joint, x);
        st.set_link(i, l1.t, self.joint);
        st.set_link(j, l2.t, self.joint);
        st.pose.crossing_sin.push(s);
        Ok(())
    }
    /// PRP: the joint's image where the lines ∥ the two guides through the images of their
    /// coincident points meet.
    fn plan(&self, bl: &mut Builder<'_>, step: &str, [i, j]: [usize; 2]) -> Planned {
        let Prp { gi, gj, joint } = *self;
        let vel = bl.kind == PlanKind::Velocity;
        let (k1, k2) = (gi.carrier, gj.carrier);
        let (e1, e2) = (bl.dir(&gi.dir), bl.dir(&gj.dir));
        let n1 = format!("{}{k1}", plain(bl.name(joint)));
        let n2 = format!("{}{k2}", plain(bl.name(joint)));
        let at = bl.b.p[joint];
        let (j1, j2) = (bl.image_on(k1, at, &n1), bl.image_on(k2, at, &n2));
        // The coincident points' images the guides' lines start from, named (b₁): a frame's
        // is the pole.
        for (k, img) in [(k1, j1), (k2, j2)] {
            if k != 0 {
                bl.mark_coincident(joint, k, img);
            }
        }
        let (s1, s2) = if vel {
            (j1, j2)
        } else {
            let vj = bl.vel_image(joint);
            let (c1, c2) = (bl.vel_coincident(&n1), bl.vel_coincident(&n2));
            (bl.coriolis(k1, c1, vj, j1), bl.coriolis(k2, c2, vj, j2))
        };
        let (x, cr) = bl.meet(
            &format!("{step}: image of {}", bl.name(joint)),
            ("∥ guide i", s1, e1),
            ("∥ guide j", s2, e2),
        )?;
        bl.set_image(joint, x, &[]);
        bl.coincident.push((n1, j1));
        bl.coincident.push((n2, j2));
        let (r1, r2) = (bl.rate(k1), bl.rate(k2));
        bl.finish_link(i, &[(joint, x)], r1);
        bl.finish_link(j, &[(joint, x)], r2);
        let _ = cr;
        Ok(())
    }
}
