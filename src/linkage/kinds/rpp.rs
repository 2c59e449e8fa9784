//! Kind 5, RPP (ВПП): the block i pivoted at the known point `a` slides in link j along a
//! slide direction; link j translates along a guide; the new point `joint` of link j is where
//! the slide line through `a` meets the guide.

use super::{dir_uses, guide_uses, GroupKind, Planned, Solved, Words};
use crate::construct::{ConstructionError, Item, Recorder, Role};
use crate::geom::{DVec2, Line, Segment};
use crate::linkage::analytic::jet::{meet, unit, LineJet};
use crate::linkage::analytic::state::State;
use crate::linkage::built::{other, Built, Frames};
use crate::linkage::compiled::Compiled;
use crate::linkage::indexed::{PDir, PGuide};
use crate::linkage::model::DyadKind;
use crate::linkage::pairs::GroupPairs;
use crate::linkage::pen::Pen;
use crate::linkage::plans::builder::Builder;
use crate::linkage::plans::names::plain;
use crate::linkage::plans::plan::PlanKind;

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
        prog: &dyn Compiled,
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
        let name = format!("slide line through {}", prog.names()[self.a]);
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
    fn draw(&self, pen: &mut Pen<'_>, _: &dyn Compiled, b: &Built, [i, j]: [u32; 2]) {
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
    /// RPP: the joint where the slide line through `a` meets link j's guide, its rates from
    /// the two moving lines.
    #[inline(always)] // the kernel's inner loop: see `PDyad::solve`
    fn solve(&self, _: &dyn Compiled, st: &mut State<'_>, [i, j]: [usize; 2]) -> Solved {
        let Rpp {
            a,
            slide,
            guide,
            joint,
        } = *self;
        let ts = st.dir(&slide);
        let l1 = LineJet {
            g: st.jet(a),
            e: unit(ts),
            t: ts,
        };
        let l2 = st.guide(&guide);
        let (x, s) = meet(l1, l2).ok_or_else(|| {
            st.fail(format!(
                "the slide of link {i} is parallel to the guide of link {j}"
            ))
        })?;
        st.set(joint, x);
        st.set_link(i, ts, a);
        st.set_link(j, l2.t, joint);
        st.pose.crossing_sin.push(s);
        Ok(())
    }
    /// RPP: the image of link j's point coincident with `a`, where the line ∥ the slide
    /// through the image of `a` meets the line ∥ the guide through the image of the guide's
    /// coincident point; the joint's image follows on link j.
    fn plan(&self, bl: &mut Builder<'_>, step: &str, [i, j]: [usize; 2]) -> Planned {
        let Rpp {
            a,
            slide,
            guide,
            joint,
        } = *self;
        let vel = bl.kind == PlanKind::Velocity;
        let k = guide.carrier;
        let (es, eg) = (bl.dir(&slide), bl.dir(&guide.dir));
        let ai = bl.image(a);
        let rk0 = bl.rate(k);
        bl.links.rate[i] = Some(rk0);
        let an = format!("{}{j}", plain(bl.name(a)));
        let ak_name = format!("{}{k}", plain(bl.name(a)));
        let ak = bl.image_on(k, bl.b.p[a], &ak_name);
        bl.coincident.push((ak_name.clone(), ak));
        let (s1, s2) = if vel {
            (ai, ak)
        } else {
            let va = bl.vel_coincident(&an);
            let (v_a, v_k) = (bl.vel_image(a), bl.vel_coincident(&ak_name));
            (bl.coriolis(i, v_a, va, ai), bl.coriolis(k, v_k, va, ak))
        };
        let (x, cr) = bl.meet(
            &format!("{step}: image of {an}"),
            ("∥ slide", s1, es),
            ("∥ guide", s2, eg),
        )?;
        bl.coincident_image(&an, a, j, x);
        let rk = bl.rate(k);
        bl.links.add(j, bl.b.p[a], x);
        bl.links.rate[j] = Some(rk);
        let jx = bl.image_on(j, bl.b.p[joint], bl.prog.names()[joint].as_str());
        bl.set_image(joint, jx, &[]);
        bl.finish_link(j, &[(joint, jx)], rk);
        bl.finish_link(i, &[(a, ai)], rk);
        let owner_a = bl.prog.owner(a);
        bl.relative((a, j), x, (a, owner_a), ai, cr);
        Ok(())
    }
}
