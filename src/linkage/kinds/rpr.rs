//! Kind 3, RPR (ВПВ): the block i pivoted at the known point `a` slides along link j, which
//! turns about the known pivot `c`; j's slide line passes `offset` m to the left of `c`. It
//! creates no point: its slide line is found. Without offset the pin may pass through the
//! pivot, where the two points no longer fix the slot: each route meets that case by itself —
//! the construction with the tangent to the pin's path (`slide`), the twin with the limit of
//! the slot's direction and rates (`twin_slot`), the plans with the limit of the slotted
//! link's rate (`plan_slot`).

mod plan_slot;
mod slide;
mod twin_slot;

use super::{GroupKind, Planned, Solved, Words};
use crate::construct::{ConstructionError, Recorder};
use crate::geom::DVec2;
use crate::linkage::analytic::jet::{heading, sub, AngleJet};
use crate::linkage::analytic::state::{NearPivot, State, NEAR_PIVOT_RATIO};
use crate::linkage::built::{Built, Frames};
use crate::linkage::compiled::Compiled;
use crate::linkage::model::DyadKind;
use crate::linkage::pairs::GroupPairs;
use crate::linkage::pen::Pen;
use crate::linkage::plans::builder::Builder;
use crate::linkage::plans::names::plain;
use crate::linkage::plans::plan::PlanKind;
use slide::slide_line;
use twin_slot::Slot;

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

/// How far link j is drawn past the pin sliding on it at least, mm.
const PAST_PIN_MM: f64 = 6.0;

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
        prog: &dyn Compiled,
        rec: &mut Recorder,
        pos: &mut Built,
        prev: Option<&Built>,
        (s, j): (&str, usize),
    ) -> Result<Frames, ConstructionError> {
        let prev = prev.map(|q| q.angle[j]);
        let th = slide_line(prog, rec, s, &pos.p, (self.a, self.c), self.offset, prev)?;
        Ok(Frames {
            angle: [th, th],
            origin: [self.a, self.c],
            crossing: std::f64::consts::FRAC_PI_2,
        })
    }
    fn draw(&self, pen: &mut Pen<'_>, prog: &dyn Compiled, b: &Built, [i, j]: [u32; 2]) {
        let th = b.angle[j as usize];
        let u = DVec2::from_angle(th);
        let (a, c) = (b.p[self.a], b.p[self.c]);
        let mu = pen.rec.scale().value();
        let reach = prog.link_reach(j, mu).max((a - c).dot(u) + PAST_PIN_MM);
        pen.link(j, c, c + u * reach);
        pen.slider(i, a, th);
        pen.anchors.extend([(i, a), (j, c + u * (reach * 0.8))]);
        pen.joints.extend([self.a, self.c]);
    }
    fn drawn_past(&self, p: &[DVec2], dir: &[DVec2], [_, j]: [u32; 2]) -> Vec<(DVec2, DVec2)> {
        let (c, u) = (p[self.c], dir[j as usize]);
        vec![(c + u * (p[self.a] - c).dot(u), u * PAST_PIN_MM)]
    }
    fn pairs(&self) -> GroupPairs {
        GroupPairs::Rpr {
            a: self.a,
            c: self.c,
        }
    }
    /// RPR: the slide line through the pin `a` at `offset` from the pivot `c` (without
    /// offset at the pivot: the slot's limit), with its rates.
    #[inline(always)] // the kernel's inner loop: see `PDyad::solve`
    fn solve(&self, prog: &dyn Compiled, st: &mut State<'_>, [i, j]: [usize; 2]) -> Solved {
        let Rpr { a, c, offset } = *self;
        let w = sub(st.jet(a), st.jet(c));
        if offset == 0.0 {
            let prev = st.continuity.then(|| st.pose.dir[j]);
            let th = match twin_slot::limit(prog, st.pose, (a, c), w, prev) {
                Slot::Direct => None,
                Slot::Limit(th) => Some(th),
                Slot::Undetermined { e, detail } => {
                    let e = e.ok_or_else(|| st.fail(detail.clone()))?;
                    st.toggle(detail);
                    Some(AngleJet { d: 0.0, dd: 0.0, e })
                }
            };
            if let Some(th) = th {
                st.set_link(i, th, a);
                st.set_link(j, th, c);
                st.pose.crossing_sin.push(1.0);
                return Ok(());
            }
        }
        let d = w.p.length();
        if d < offset.abs() || d == 0.0 {
            return Err(st.fail(format!(
                "{} is {d:.6} m from {}, less than the offset {} m of the slide line",
                prog.names()[a],
                prog.names()[c],
                offset.abs()
            )));
        }
        let speed = w.d.length();
        if offset == 0.0 && speed > NEAR_PIVOT_RATIO * d {
            st.pose.near_pivot.push(NearPivot {
                group: st.group,
                link: j,
                pin: a,
                pivot: c,
                distance: d,
                speed,
            });
        }
        let beta = heading(w);
        // γ = asin(u), u = −offset/d.
        let dd1 = w.p.dot(w.d) / d;
        let dd2 = (w.d.length_squared() + w.p.dot(w.dd) - dd1 * dd1) / d;
        let u = -offset / d;
        let du = offset * dd1 / (d * d);
        let ddu = offset * (dd2 / (d * d) - 2.0 * dd1 * dd1 / (d * d * d));
        let k = 1.0 - u * u;
        if k <= 1e-28 {
            return Err(st.fail(format!(
                "{} lies on the offset circle of {}: the slide line is not determined",
                prog.names()[a],
                prog.names()[c]
            )));
        }
        // sin γ = u, cos γ = √k.
        let sk = k.sqrt();
        let gamma = AngleJet {
            d: du / sk,
            dd: ddu / sk + u * du * du / (k * sk),
            e: DVec2::new(sk, u),
        };
        let th = AngleJet {
            d: beta.d + gamma.d,
            dd: beta.dd + gamma.dd,
            e: gamma.e.rotate(beta.e),
        };
        st.set_link(i, th, a);
        st.set_link(j, th, c);
        st.pose.crossing_sin.push(1.0);
        Ok(())
    }
    /// RPR: the image of the slider's point coincident with the pin `a`, where the line ⊥ the
    /// slotted link through the image of the pivot `c` meets the line ∥ the slide through the
    /// image of `a` (at the pivot without offset: the slotted link's limit rate).
    fn plan(&self, bl: &mut Builder<'_>, step: &str, [i, j]: [usize; 2]) -> Planned {
        let Rpr { a, c, offset } = *self;
        let vel = bl.kind == PlanKind::Velocity;
        let rc = bl.r(c, a);
        let (ai, ci) = (bl.image(a), bl.image(c));
        let e = DVec2::from_angle(bl.b.angle[j]);
        let an = format!("{}{j}", plain(bl.name(a)));
        let limit = if offset == 0.0 {
            plan_slot::limit(bl, step, (a, c), j)?
        } else {
            None
        };
        // At the pivot the radius c → a vanishes: the slotted link's line stands for it.
        let across = if limit.is_some() { e.perp() } else { rc.perp() };
        let n = bl.turning_base("slotted link", j, ci, rc);
        let kk = if vel {
            ai
        } else {
            bl.coriolis(i, bl.vel_image(a), bl.vel_coincident(&an), ai)
        };
        let (x, cr) = bl.meet(
            &format!("{step}: image of {an}"),
            ("⊥ to the slotted link", n, across),
            ("∥ slide", kk, e),
        )?;
        bl.coincident_image(&an, a, j, x);
        let rj = match limit {
            Some(rate) => rate,
            None => bl.rate_from(rc, n, x),
        };
        bl.finish_link(j, &[(c, ci)], rj);
        // Beside the pivot the image of the coincident point is no base for the
        // similarity: further points of the link follow from the rate.
        if limit.is_none() {
            bl.links.add(j, bl.b.p[a], x);
        }
        bl.finish_link(i, &[(a, ai)], rj);
        let owner_a = bl.prog.owner(a);
        bl.relative((a, j), x, (a, owner_a), ai, cr);
        Ok(())
    }
}
