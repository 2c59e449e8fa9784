//! Kind 1, RRR (ВВВ): link i pivoted at the known point `a`, link j at the known `b`, the two
//! jointed at the new point `joint`, found where the circles about `a` and `b` meet.

use super::{GroupKind, Planned, Solved, Words};
use crate::construct::{ConstructionError, Pick, Recorder};
use crate::geom::DVec2;
use crate::linkage::analytic::jet::{self, sub, Jet, Rows, TANGENT_REL};
use crate::linkage::analytic::State;
use crate::linkage::construction::{heading, pick, Built, Frames};
use crate::linkage::groups::GroupPairs;
use crate::linkage::model::{Branch, DyadKind};
use crate::linkage::plans::Builder;
use crate::linkage::positions_draw::Pen;
use crate::linkage::program::Program;
use crate::scale::format_plain;

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
    /// RRR: the joint where the circles of radius `la` about `a` and `lb` about `b` cross
    /// (law of cosines), its rates from |x − a|² = la², |x − b|² = lb².
    #[inline(always)] // the kernel's inner loop: see `PDyad::solve`
    fn solve(&self, prog: &Program, st: &mut State<'_>, [i, j]: [usize; 2]) -> Solved {
        let Rrr {
            a,
            la,
            b,
            lb,
            joint,
            branch,
        } = *self;
        let (ja, jb) = (st.jet(a), st.jet(b));
        let ab = jb.p - ja.p;
        let d2 = ab.length_squared();
        let d = d2.sqrt();
        // A tangency lost to rounding is still a tangency (the change point).
        let slack = TANGENT_REL * (la + lb);
        if d > la + lb + slack || d < (la - lb).abs() - slack || d == 0.0 {
            return Err(st.fail(format!(
                "|{}{}| = {} m is outside [|{} − {}|, {} + {}] m",
                prog.names[a],
                prog.names[b],
                format_plain(d),
                format_plain(la),
                format_plain(lb),
                format_plain(la),
                format_plain(lb)
            )));
        }
        // Law of cosines at a, in fractions of ab: the foot of the joint on ab at
        // la·cos α/d, the joint la·sin α/d across (to the left for the left branch).
        let inv = 1.0 / d2;
        let along = (la * la - lb * lb + d2) * 0.5 * inv;
        let across = (la * la * inv - along * along).max(0.0).sqrt();
        let foot = ja.p + ab * along;
        let left = foot + ab.perp() * across;
        let right = foot - ab.perp() * across;
        let pick_left = if st.continuity {
            let q = st.pose.p[joint];
            left.distance_squared(q) <= right.distance_squared(q)
        } else {
            branch != Branch::Right
        };
        let x = if pick_left { left } else { right };
        let (ra, rb) = (x - ja.p, x - jb.p);
        // |x − a|² = la², |x − b|² = lb², differentiated once and twice.
        let toggle = || {
            format!(
                "links {i} and {j} are in line at {} (toggle position)",
                prog.names[joint]
            )
        };
        let acc = Rows::new(ra, rb).map(|rows| {
            let v = rows.solve(DVec2::new(ra.dot(ja.d), rb.dot(jb.d)));
            let rhs = DVec2::new(
                ra.dot(ja.dd) - (v - ja.d).length_squared(),
                rb.dot(jb.dd) - (v - jb.d).length_squared(),
            );
            (v, rows.solve(rhs))
        });
        let (v, w) = acc.unwrap_or_else(|| {
            st.toggle(toggle());
            (DVec2::ZERO, DVec2::ZERO)
        });
        let jx = Jet { p: x, d: v, dd: w };
        st.set(joint, jx);
        st.set_link(i, jet::heading(sub(jx, ja)), a);
        st.set_link(j, jet::heading(sub(jx, jb)), b);
        // The circles cross at the angle between the radii: cos g by the law of cosines.
        let cos_g = ((la * la + lb * lb - d2) / (2.0 * la * lb)).clamp(-1.0, 1.0);
        st.pose.crossing_sin.push((1.0 - cos_g * cos_g).sqrt());
        Ok(())
    }
    /// RRR: the joint's image where the lines ⊥ link i through the image of `a` and ⊥ link j
    /// through the image of `b` meet.
    fn plan(&self, bl: &mut Builder<'_>, step: &str, [i, j]: [usize; 2]) -> Planned {
        let Rrr { a, b, joint, .. } = *self;
        let (ra, rb) = (bl.r(a, joint), bl.r(b, joint));
        let (ai, bi) = (bl.image(a), bl.image(b));
        let n1 = bl.turning_base("link i", i, ai, ra);
        let n2 = bl.turning_base("link j", j, bi, rb);
        let (x, cr) = bl.meet(
            &format!("{step}: image of {}", bl.name(joint)),
            ("⊥ link i", n1, ra.perp()),
            ("⊥ link j", n2, rb.perp()),
        )?;
        bl.set_image(joint, x, &[]);
        let (ri, rj) = (bl.rate_from(ra, n1, x), bl.rate_from(rb, n2, x));
        bl.finish_link(i, &[(a, ai), (joint, x)], ri);
        bl.finish_link(j, &[(b, bi), (joint, x)], rj);
        bl.joint_relative(joint, (a, i), cr);
        Ok(())
    }
}
