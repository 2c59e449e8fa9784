//! The two vector equations of each Assur group drawn on the plan, kind by kind, and the
//! slotted link's rate at its pivot (the limit).

use super::builder::Builder;
use super::names::plain;
use super::PlanKind;
use crate::construct::ConstructionError;
use crate::geom::DVec2;
use crate::linkage::kinds::{Prp, Rpp, Rpr, Rrp, Rrr};
use crate::linkage::program::{PDir, PDyad, PGuide};

impl Builder<'_> {
    /// One Assur group on the plan: the image of its joint (of the slider's coincident point
    /// for RPR, RPP) from its two vector equations, kind by kind.
    pub(super) fn dyad(&mut self, links: [u32; 2], dyad: &PDyad) -> Result<(), ConstructionError> {
        let ij = links.map(|l| l as usize);
        let step = format!("group ({},{})", ij[0], ij[1]);
        match *dyad {
            PDyad::Rrr(Rrr { a, b, joint, .. }) => self.rrr(&step, ij, [a, b], joint),
            PDyad::Rrp(Rrp {
                a, guide, joint, ..
            }) => self.rrp(&step, ij, a, &guide, joint),
            PDyad::Rpr(Rpr { a, c, offset }) => self.rpr(&step, ij, (a, c), offset),
            PDyad::Prp(Prp { gi, gj, joint }) => self.prp(&step, ij, [&gi, &gj], joint),
            PDyad::Rpp(Rpp {
                a,
                slide,
                guide,
                joint,
            }) => self.rpp(&step, ij, a, (&slide, &guide), joint),
        }
    }

    /// The condition `cr` of a group's joint and its motion relative to `a` on link `i`.
    fn joint_relative(&mut self, joint: usize, (a, i): (usize, usize), cr: f64) {
        let (x, ai) = (self.image(joint), self.image(a));
        self.cond[joint] = Some(cr);
        self.relative((joint, i), x, (a, i), ai, cr);
    }

    /// RRR: the joint's image where the lines ⊥ link i through the image of `a` and ⊥ link j
    /// through the image of `b` meet.
    fn rrr(
        &mut self,
        step: &str,
        [i, j]: [usize; 2],
        [a, b]: [usize; 2],
        joint: usize,
    ) -> Result<(), ConstructionError> {
        let (ra, rb) = (self.r(a, joint), self.r(b, joint));
        let (ai, bi) = (self.image(a), self.image(b));
        let n1 = self.turning_base("link i", i, ai, ra);
        let n2 = self.turning_base("link j", j, bi, rb);
        let (x, cr) = self.meet(
            &format!("{step}: image of {}", self.name(joint)),
            ("⊥ link i", n1, ra.perp()),
            ("⊥ link j", n2, rb.perp()),
        )?;
        self.set_image(joint, x, &[]);
        let (ri, rj) = (self.rate_from(ra, n1, x), self.rate_from(rb, n2, x));
        self.finish_link(i, &[(a, ai), (joint, x)], ri);
        self.finish_link(j, &[(b, bi), (joint, x)], rj);
        self.joint_relative(joint, (a, i), cr);
        Ok(())
    }

    /// RRP: the joint's image where the line ⊥ link i through the image of `a` meets the
    /// line ∥ the guide through the image of the guide's coincident point (with the Coriolis
    /// term on the acceleration plan).
    fn rrp(
        &mut self,
        step: &str,
        [i, j]: [usize; 2],
        a: usize,
        guide: &PGuide,
        joint: usize,
    ) -> Result<(), ConstructionError> {
        let vel = self.kind == PlanKind::Velocity;
        let ra = self.r(a, joint);
        let ai = self.image(a);
        let k = guide.carrier;
        let e = self.dir(&guide.dir);
        let jk_name = format!("{}{k}", plain(self.name(joint)));
        let jk = self.image_on(k, self.b.p[joint], &jk_name);
        let n1 = self.turning_base("link i", i, ai, ra);
        let kk = if vel {
            jk
        } else {
            self.coriolis(k, self.vel_coincident(&jk_name), self.vel_image(joint), jk)
        };
        let (x, cr) = self.meet(
            &format!("{step}: image of {}", self.name(joint)),
            ("⊥ link i", n1, ra.perp()),
            ("∥ guide", kk, e),
        )?;
        self.set_image(joint, x, &[]);
        self.coincident.push((jk_name, jk));
        let ri = self.rate_from(ra, n1, x);
        self.finish_link(i, &[(a, ai), (joint, x)], ri);
        let rk = self.rate(k);
        self.finish_link(j, &[(joint, x)], rk);
        self.joint_relative(joint, (a, i), cr);
        Ok(())
    }

    /// RPR: the image of the slider's point coincident with the pin `a`, where the line ⊥ the
    /// slotted link through the image of the pivot `c` meets the line ∥ the slide through the
    /// image of `a` (at the pivot without offset: the slotted link's limit rate).
    fn rpr(
        &mut self,
        step: &str,
        [i, j]: [usize; 2],
        (a, c): (usize, usize),
        offset: f64,
    ) -> Result<(), ConstructionError> {
        let vel = self.kind == PlanKind::Velocity;
        let rc = self.r(c, a);
        let (ai, ci) = (self.image(a), self.image(c));
        let e = DVec2::from_angle(self.b.angle[j]);
        let an = format!("{}{j}", plain(self.name(a)));
        let limit = if offset == 0.0 {
            self.slot_limit(step, (a, c), j)?
        } else {
            None
        };
        // At the pivot the radius c → a vanishes: the slotted link's line stands for it.
        let across = if limit.is_some() { e.perp() } else { rc.perp() };
        let n = self.turning_base("slotted link", j, ci, rc);
        let kk = if vel {
            ai
        } else {
            self.coriolis(i, self.vel_image(a), self.vel_coincident(&an), ai)
        };
        let (x, cr) = self.meet(
            &format!("{step}: image of {an}"),
            ("⊥ to the slotted link", n, across),
            ("∥ slide", kk, e),
        )?;
        self.coincident_image(&an, a, j, x);
        let rj = match limit {
            Some(rate) => rate,
            None => self.rate_from(rc, n, x),
        };
        self.finish_link(j, &[(c, ci)], rj);
        // Beside the pivot the image of the coincident point is no base for the
        // similarity: further points of the link follow from the rate.
        if limit.is_none() {
            self.links.add(j, self.b.p[a], x);
        }
        self.finish_link(i, &[(a, ai)], rj);
        let owner_a = self.prog.owner(a);
        self.relative((a, j), x, (a, owner_a), ai, cr);
        Ok(())
    }

    /// PRP: the joint's image where the lines ∥ the two guides through the images of their
    /// coincident points meet.
    fn prp(
        &mut self,
        step: &str,
        [i, j]: [usize; 2],
        [gi, gj]: [&PGuide; 2],
        joint: usize,
    ) -> Result<(), ConstructionError> {
        let vel = self.kind == PlanKind::Velocity;
        let (k1, k2) = (gi.carrier, gj.carrier);
        let (e1, e2) = (self.dir(&gi.dir), self.dir(&gj.dir));
        let n1 = format!("{}{k1}", plain(self.name(joint)));
        let n2 = format!("{}{k2}", plain(self.name(joint)));
        let at = self.b.p[joint];
        let (j1, j2) = (self.image_on(k1, at, &n1), self.image_on(k2, at, &n2));
        let (s1, s2) = if vel {
            (j1, j2)
        } else {
            let vj = self.vel_image(joint);
            let (c1, c2) = (self.vel_coincident(&n1), self.vel_coincident(&n2));
            (self.coriolis(k1, c1, vj, j1), self.coriolis(k2, c2, vj, j2))
        };
        let (x, cr) = self.meet(
            &format!("{step}: image of {}", self.name(joint)),
            ("∥ guide i", s1, e1),
            ("∥ guide j", s2, e2),
        )?;
        self.set_image(joint, x, &[]);
        self.coincident.push((n1, j1));
        self.coincident.push((n2, j2));
        let (r1, r2) = (self.rate(k1), self.rate(k2));
        self.finish_link(i, &[(joint, x)], r1);
        self.finish_link(j, &[(joint, x)], r2);
        let _ = cr;
        Ok(())
    }

    /// RPP: the image of link j's point coincident with `a`, where the line ∥ the slide
    /// through the image of `a` meets the line ∥ the guide through the image of the guide's
    /// coincident point; the joint's image follows on link j.
    fn rpp(
        &mut self,
        step: &str,
        [i, j]: [usize; 2],
        a: usize,
        (slide, guide): (&PDir, &PGuide),
        joint: usize,
    ) -> Result<(), ConstructionError> {
        let vel = self.kind == PlanKind::Velocity;
        let k = guide.carrier;
        let (es, eg) = (self.dir(slide), self.dir(&guide.dir));
        let ai = self.image(a);
        let rk0 = self.rate(k);
        self.links.rate[i] = Some(rk0);
        let an = format!("{}{j}", plain(self.name(a)));
        let ak_name = format!("{}{k}", plain(self.name(a)));
        let ak = self.image_on(k, self.b.p[a], &ak_name);
        self.coincident.push((ak_name.clone(), ak));
        let (s1, s2) = if vel {
            (ai, ak)
        } else {
            let va = self.vel_coincident(&an);
            let (v_a, v_k) = (self.vel_image(a), self.vel_coincident(&ak_name));
            (self.coriolis(i, v_a, va, ai), self.coriolis(k, v_k, va, ak))
        };
        let (x, cr) = self.meet(
            &format!("{step}: image of {an}"),
            ("∥ slide", s1, es),
            ("∥ guide", s2, eg),
        )?;
        self.coincident_image(&an, a, j, x);
        let rk = self.rate(k);
        self.links.add(j, self.b.p[a], x);
        self.links.rate[j] = Some(rk);
        let jx = self.image_on(j, self.b.p[joint], self.prog.names[joint].as_str());
        self.set_image(joint, jx, &[]);
        self.finish_link(j, &[(joint, jx)], rk);
        self.finish_link(i, &[(a, ai)], rk);
        let owner_a = self.prog.owner(a);
        self.relative((a, j), x, (a, owner_a), ai, cr);
        Ok(())
    }

    /// The slotted link's rate when the pin `a` passes through its pivot `c` (RPR without
    /// offset): ω (velocity plan) or ε (acceleration plan) of link `j` as the limit of the
    /// rotation of the line c → a, from the relative motion of `a` about `c`: with Δv, Δa, Δj
    /// the relative velocity, acceleration and jerk, ω = [Δv × Δa]/(2|Δv|²) and
    /// ε = [Δv × Δj]/(3|Δv|²) − ω·(Δv·Δa)/|Δv|². `None` away from the pivot: where the
    /// crank travel h to the coincidence has h⁴ > 2δ/|w′| (δ the rounding of the positions,
    /// w′ = Δv/ω₁), the reading off the plan loses fewer digits than the limit's O(h); and
    /// where the pin passes the pivot at a distance beyond the rounding (the limit holds at
    /// the coincidence only; beside it the plan gives the true, ill-conditioned rate).
    /// Refused where the relative motion is not known from the crank alone.
    pub(super) fn slot_limit(
        &self,
        step: &str,
        (a, c): (usize, usize),
        j: usize,
    ) -> Result<Option<f64>, ConstructionError> {
        let (w1, mu_l) = (self.w1, self.mu_l);
        let dv = if self.kind == PlanKind::Velocity {
            (self.image(a) - self.image(c)) * self.mu()
        } else {
            self.vel_between(self.vel_image(c), self.vel_image(a))
        };
        let v2 = dv.length_squared() / (w1 * w1);
        let hp = self.r(c, a).length();
        let at = (self.b.p[a].length() + self.b.p[c].length()) * mu_l;
        let delta = f64::EPSILON * (at + v2.sqrt());
        let bound = 2.0 * delta * v2 * v2.sqrt();
        if bound.is_nan() || hp.powi(4) > bound {
            return Ok(None);
        }
        let refuse = |why: String| ConstructionError::Other {
            step: format!("{step}: rate of the slotted link {j}"),
            message: format!(
                "the pin {} is {:.3e} m from the pivot {} (|v_{}{}| = {:.6} m/s): {why}",
                self.name(a),
                hp,
                self.name(c),
                plain(self.name(a)),
                plain(self.name(c)),
                dv.length()
            ),
        };
        if v2 == 0.0 {
            return Err(refuse("the line through them is not determined".into()));
        }
        // Acceleration and jerk of a point of the frame or the crank (constant ω₁).
        let motion = |k: usize| -> Option<(DVec2, DVec2)> {
            if k < self.prog.fixed.len() {
                Some((DVec2::ZERO, DVec2::ZERO))
            } else if self.prog.on_frame_or_crank(k) {
                let v = if self.kind == PlanKind::Velocity {
                    self.image(k) * self.mu()
                } else {
                    self.vel_image(k) * self.known.mu_v
                };
                Some((-self.r(self.prog.centre, k) * (w1 * w1), -v * (w1 * w1)))
            } else {
                None
            }
        };
        // The limit holds only where the pin passes through the pivot: its closest approach,
        // w − w′s + w″s²/2 with w′ = Δv/ω₁, w″ = Δa/ω₁², s = w·w′/|w′|², within the rounding
        // and the neglected O(s³). A pin that passes at a distance is read off the plan.
        let rel = self.r(c, a);
        let w_d = dv / w1;
        let s = rel.dot(w_d) / v2;
        let (miss, neglected) = match (motion(a), motion(c)) {
            (Some((aa, ja)), Some((ac, jc))) => (
                (rel - w_d * s + (aa - ac) * (0.5 * s * s / (w1 * w1))).length(),
                ((ja - jc) / (w1 * w1 * w1)).length() * s.abs().powi(3),
            ),
            // Unknown curvature of the relative path: the first-order miss (across w′), which
            // an exact passage keeps within O(s²).
            _ => (rel.perp_dot(w_d).abs() / v2.sqrt(), v2.sqrt() * s * s),
        };
        if miss > 4.0 * delta + neglected {
            return Ok(None);
        }
        let (Some((aa, ja)), Some((ac, jc))) = (motion(a), motion(c)) else {
            return Err(refuse(format!(
                "the rate of link {j} is a limit that needs the relative acceleration and jerk, known only for points of the frame and the crank"
            )));
        };
        let dv2 = dv.length_squared();
        let da = aa - ac;
        let omega = dv.perp_dot(da) / (2.0 * dv2);
        Ok(Some(match self.kind {
            PlanKind::Velocity => omega,
            PlanKind::Acceleration => {
                let omega = self.known.vel.map_or(omega, |v| v.rate[j]);
                dv.perp_dot(ja - jc) / (3.0 * dv2) - omega * dv.dot(da) / dv2
            }
        }))
    }
}
