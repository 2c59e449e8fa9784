//! Kind 2, RRP (ВВП): link i pivoted at the known point `a` and jointed at the new point
//! `joint` to the slider j, which carries `joint` along a guide: the circle about `a` met by
//! the guide.

use super::{guide_uses, GroupKind, Planned, Solved, Words};
use crate::construct::{ConstructionError, Pick, Recorder};
use crate::linkage::analytic::jet::{self, cross, sub, Jet, TANGENT_REL};
use crate::linkage::analytic::state::State;
use crate::linkage::built::{heading, pick, Built, Frames};
use crate::linkage::compiled::Compiled;
use crate::linkage::indexed::PGuide;
use crate::linkage::model::{Branch, DyadKind};
use crate::linkage::pairs::GroupPairs;
use crate::linkage::pen::Pen;
use crate::linkage::plans::builder::Builder;
use crate::linkage::plans::names::plain;
use crate::linkage::plans::plan::PlanKind;
use crate::scale::format_plain;

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
        prog: &dyn Compiled,
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
    fn draw(&self, pen: &mut Pen<'_>, _: &dyn Compiled, b: &Built, [i, j]: [u32; 2]) {
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
    /// RRP: the joint where the circle of radius `la` about `a` crosses the guide, its rates
    /// from x = g + t·e with |x − a|² = la².
    #[inline(always)] // the kernel's inner loop: see `PDyad::solve`
    fn solve(&self, prog: &dyn Compiled, st: &mut State<'_>, [i, j]: [usize; 2]) -> Solved {
        let Rrp {
            a,
            la,
            guide,
            joint,
            branch,
        } = *self;
        let ja = st.jet(a);
        let gl = st.guide(&guide);
        let (g, e) = (gl.g, gl.e);
        let w = ja.p - g.p;
        let t0 = w.dot(e.p);
        let h = cross(e.p, w);
        if h.abs() > la * (1.0 + TANGENT_REL) {
            return Err(st.fail(format!(
                "{} is {} m from the guide, more than the link length {} m",
                prog.names()[a],
                format_plain(h.abs()),
                format_plain(la)
            )));
        }
        let half = (la * la - h * h).max(0.0).sqrt();
        let pick_fwd = if st.continuity {
            let q = st.pose.p[joint];
            (g.p + e.p * (t0 + half)).distance_squared(q)
                <= (g.p + e.p * (t0 - half)).distance_squared(q)
        } else {
            branch != Branch::Backward
        };
        let t = if pick_fwd { t0 + half } else { t0 - half };
        let x = g.p + e.p * t;
        let ra = x - ja.p;
        let den = ra.dot(e.p);
        // x = g + t·e with |x − a|² = la²: solve for t′, t″.
        let (dt, ddt) = if den.abs() <= 1e-14 * la {
            st.toggle(format!(
                "link {i} is perpendicular to the guide of link {j} (toggle position)"
            ));
            (0.0, 0.0)
        } else {
            let dt = -ra.dot(g.d + e.d * t - ja.d) / den;
            let v = g.d + e.p * dt + e.d * t;
            let ddt = -((v - ja.d).length_squared()
                + ra.dot(g.dd + e.d * (2.0 * dt) + e.dd * t - ja.dd))
                / den;
            (dt, ddt)
        };
        let jx = Jet {
            p: x,
            d: g.d + e.p * dt + e.d * t,
            dd: g.dd + e.p * ddt + e.d * (2.0 * dt) + e.dd * t,
        };
        st.set(joint, jx);
        st.set_link(i, jet::heading(sub(jx, ja)), a);
        st.set_link(j, gl.t, joint);
        st.pose.crossing_sin.push(half / la);
        Ok(())
    }
    /// RRP: the joint's image where the line ⊥ link i through the image of `a` meets the
    /// line ∥ the guide through the image of the guide's coincident point (with the Coriolis
    /// term on the acceleration plan).
    fn plan(&self, bl: &mut Builder<'_>, step: &str, [i, j]: [usize; 2]) -> Planned {
        let Rrp {
            a, guide, joint, ..
        } = *self;
        let vel = bl.kind == PlanKind::Velocity;
        let ra = bl.r(a, joint);
        let ai = bl.image(a);
        let k = guide.carrier;
        let e = bl.dir(&guide.dir);
        let jk_name = format!("{}{k}", plain(bl.name(joint)));
        let jk = bl.image_on(k, bl.b.p[joint], &jk_name);
        let n1 = bl.turning_base("link i", i, ai, ra);
        let kk = if vel {
            jk
        } else {
            bl.coriolis(k, bl.vel_coincident(&jk_name), bl.vel_image(joint), jk)
        };
        let (x, cr) = bl.meet(
            &format!("{step}: image of {}", bl.name(joint)),
            ("⊥ link i", n1, ra.perp()),
            ("∥ guide", kk, e),
        )?;
        bl.set_image(joint, x, &[]);
        bl.coincident.push((jk_name, jk));
        let ri = bl.rate_from(ra, n1, x);
        bl.finish_link(i, &[(a, ai), (joint, x)], ri);
        let rk = bl.rate(k);
        bl.finish_link(j, &[(joint, x)], rk);
        bl.joint_relative(joint, (a, i), cr);
        Ok(())
    }
}
