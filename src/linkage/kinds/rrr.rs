//! Kind 1, RRR (ВВВ): link i pivoted at the known point `a`, link j at the known `b`, the two
//! jointed at the new point `joint`, found where the circles about `a` and `b` meet.

use super::{GroupKind, Planned, Solved, Words};
use crate::construct::{ConstructionError, Pick, Recorder};
use crate::geom::DVec2;
use crate::linkage::analytic::jet::{self, cross, sub, Jet, TANGENT_REL};
use crate::linkage::analytic::state::State;
use crate::linkage::built::{heading, pick, Built, Frames};
use crate::linkage::compiled::Compiled;
use crate::linkage::model::{Branch, DyadKind};
use crate::linkage::pairs::GroupPairs;
use crate::linkage::pen::Pen;
use crate::linkage::plans::builder::Builder;
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
        prog: &dyn Compiled,
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
    fn draw(&self, pen: &mut Pen<'_>, _: &dyn Compiled, b: &Built, [i, j]: [u32; 2]) {
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
    /// RRR: the joint where the circles of radius `la` about `a` and `lb` about `b` cross,
    /// its rates from |x − a|² = la², |x − b|² = lb².
    ///
    /// Written for the kernel's chain of dependent operations: with ab = b − a and d² = |ab|²,
    /// the joint is x = a + (s·ab ± t·ab⊥)/d², where s = (x − a)·ab = (la² − lb² + d²)/2 and
    /// t = |(x − a) × ab| = √(la²·d² − s²) (twice the triangle's area); the rows' determinant
    /// (x − a) × (x − b) over la·lb is the sine of the circles' crossing angle, and
    /// |x − a| = la, |x − b| = lb give the links' unit vectors and rates without a square
    /// root. One square root and the determinant's reciprocal stand in the chain from the
    /// given points to the joint's rates (the form before took seven square roots and
    /// eight divisions).
    #[inline(always)] // the kernel's inner loop: see `PDyad::solve`
    fn solve(&self, prog: &dyn Compiled, st: &mut State<'_>, [i, j]: [usize; 2]) -> Solved {
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
        // A tangency lost to rounding is still a tangency (the change point). Compared in
        // squares: the distance's square root is taken only to say why it fails.
        let slack = TANGENT_REL * (la + lb);
        let (far, near) = (la + lb + slack, (la - lb).abs() - slack);
        if d2 > far * far || (near > 0.0 && d2 < near * near) || d2 == 0.0 {
            return Err(st.fail(format!(
                "|{}{}| = {} m is outside [|{} − {}|, {} + {}] m",
                prog.names()[a],
                prog.names()[b],
                format_plain(d2.sqrt()),
                format_plain(la),
                format_plain(lb),
                format_plain(la),
                format_plain(lb)
            )));
        }
        let s = 0.5 * (la * la - lb * lb + d2);
        // t² within the rounding of its two terms is a tangency: its square root would be
        // noise of √ε relative (the stretched or folded positions of a four-bar).
        let t2 = la * la * d2 - s * s;
        let t = if t2 > 4.0 * f64::EPSILON * la * la * d2 {
            t2.sqrt()
        } else {
            0.0
        };
        // Left of a → b when the previous joint is (or, without continuity, the branch says
        // so): the nearer of the two crossings to it.
        let left = if st.continuity {
            cross(ab, st.pose.p[joint] - ja.p) >= 0.0
        } else {
            branch != Branch::Right
        };
        let t = if left { t } else { -t };
        let x = ja.p + (ab * s + ab.perp() * t) * (1.0 / d2);
        let (ra, rb) = (x - ja.p, x - jb.p);
        // |x − a|² = la², |x − b|² = lb², differentiated once and twice: the rows (ra, rb).
        // Their determinant is t in exact arithmetic, but near a toggle t carries the
        // rounding of la²·d² − s² (relatively ε/sin²α): the rates are solved with the
        // determinant of the rows as rounded, one reciprocal for both right-hand sides.
        let det = cross(ra, rb);
        let inv_det = 1.0 / det;
        let solve = |rhs: DVec2| jet::adjugate(ra, rb, rhs) * inv_det;
        let (v, w) = if det.abs() > 1e-14 * la * lb {
            let v = solve(DVec2::new(ra.dot(ja.d), rb.dot(jb.d)));
            let rhs = DVec2::new(
                ra.dot(ja.dd) - (v - ja.d).length_squared(),
                rb.dot(jb.dd) - (v - jb.d).length_squared(),
            );
            (v, solve(rhs))
        } else {
            st.toggle(format!(
                "links {i} and {j} are in line at {} (toggle position)",
                prog.names()[joint]
            ));
            (DVec2::ZERO, DVec2::ZERO)
        };
        let jx = Jet { p: x, d: v, dd: w };
        st.set(joint, jx);
        st.set_link(i, jet::heading_at(sub(jx, ja), la), a);
        st.set_link(j, jet::heading_at(sub(jx, jb), lb), b);
        st.pose.crossing_sin.push((det.abs() / (la * lb)).min(1.0));
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
