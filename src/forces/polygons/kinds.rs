//! Each group kind's force polygon: which reactions the moments on its drawing give, which
//! two directions close its polygon, and where a reaction on a slide acts (one method per
//! kind of class-II group, the group's drawing and polygon handed in by [`super::polygons`]).

use super::equations::MomentEquation;
use super::polygon::Polygon;
use super::scheme::Scheme;
use super::{offset, prismatic, reaction_name, revolute};
use crate::construct::{ConstructionError, Item, Role};
use crate::forces::loads::{Load, LoadKind};
use crate::forces::twin::Reaction;
use crate::geom::{DVec2, Segment};
use crate::linkage::GroupPairs;

/// One group under analysis: its drawing at μ_l, its polygon at μ_F, the loads on its links
/// i and j (with the reactions of the groups already solved), its links [i, j], the loads'
/// force scale (N) and the moment equations worked so far.
pub(super) struct Work<'g, 'a>(
    pub(super) &'g mut Scheme<'a>,
    pub(super) &'g mut Polygon,
    pub(super) &'g [&'g Load],
    pub(super) &'g [&'g Load],
    pub(super) [usize; 2],
    pub(super) f64,
    pub(super) &'g mut Vec<MomentEquation>,
);

/// The points about which a group's drawing takes the moments of its links' loads, link
/// i's then link j's: the inner joint B, about which each link's moment leaves out the
/// unknown reaction there (RRR, RRP, PRP); the pivots A and C of an RPR group, each link
/// turning about its own; A for the block of an RPP group, its joint for link j.
pub(super) fn moment_centres(pairs: GroupPairs) -> [usize; 2] {
    match pairs {
        GroupPairs::Rrr { joint, .. }
        | GroupPairs::Rrp { joint, .. }
        | GroupPairs::Prp { joint, .. } => [joint, joint],
        GroupPairs::Rpr { a, c } => [a, c],
        GroupPairs::Rpp { a, joint, .. } => [a, joint],
    }
}

impl Work<'_, '_> {
    /// The group's reactions, read off its polygon: the two outer pairs, then the inner.
    pub(super) fn reactions(self, pairs: GroupPairs) -> Result<Vec<Reaction>, ConstructionError> {
        let m = moment_centres(pairs).map(|k| self.0.board.point(k));
        match pairs {
            GroupPairs::Rrr { a, c, joint } => self.rrr(a, c, joint, m),
            GroupPairs::Rrp {
                a,
                guide: og,
                joint,
            } => self.rrp(a, og, joint, m),
            GroupPairs::Rpr { a, c } => self.rpr(a, c, m),
            GroupPairs::Prp {
                gi: ci,
                gj: cj,
                joint,
            } => self.prp(ci, cj, joint, m),
            GroupPairs::Rpp {
                a,
                guide: og,
                joint,
            } => self.rpp(a, og, joint, m),
        }
    }

    /// RRR: F^τ of each outer reaction from its link's moments about B; the polygon closed by
    /// lines ∥ CB and ∥ AB; the inner reaction R_{i-j} (link i's on link j, as the tables name
    /// it) from the closing point to the end of i's loads, closing link j's polygon.
    fn rrr(
        self,
        a: usize,
        c: usize,
        joint: usize,
        [mi, mj]: [DVec2; 2],
    ) -> Result<Vec<Reaction>, ConstructionError> {
        let Work(sch, pol, li, lj, [i, j], _, equations) = self;
        let board = sch.board;
        let (pa, pc, pb) = (board.point(a), board.point(c), board.point(joint));
        let (oa, oc) = (board.setup.prog.owner(a), board.setup.prog.owner(c));
        sch.drain();
        let tau_i = sch.moments(mi, li) / sch.length(pa, pb);
        let t = sch.tangential(pa, pb, (oa, i), tau_i);
        equations.push(sch.equation(joint, &[i], t));
        let tau_j = sch.moments(mj, lj) / sch.length(pc, pb);
        let t = sch.tangential(pc, pb, (oc, j), tau_j);
        equations.push(sch.equation(joint, &[j], t));
        let t_a = (pb - pa).normalize().perp() * tau_i;
        let t_c = (pb - pc).normalize().perp() * tau_j;
        let p0 = pol.tip;
        let p1 = pol.lay(&format!("R^τ_{{{oa}-{i}}}"), t_a);
        let pi = pol.lay_all(li);
        pol.lay_all(lj);
        let pbj = pol.tip;
        let e = pol.lay(&format!("R^τ_{{{oc}-{j}}}"), t_c);
        let h = pol.close(("∥ CB", e, pb - pc), ("∥ AB", p0, pb - pa))?;
        let r_a = pol.read(&reaction_name(oa, i), h, p1);
        let r_c = pol.read(&reaction_name(oc, j), pbj, h);
        let r_ij = pol.read(&reaction_name(i, j), h, pi);
        Ok(vec![
            revolute(oa, i, a, r_a),
            revolute(oc, j, c, r_c),
            revolute(i, j, joint, r_ij),
        ])
    }

    /// RRP: F^τ_A from link i's moments about B; closed by the normal to the guide and ∥ AB; the
    /// guide's reaction acts at its arm from B.
    fn rrp(
        self,
        a: usize,
        og: usize,
        joint: usize,
        [mi, mj]: [DVec2; 2],
    ) -> Result<Vec<Reaction>, ConstructionError> {
        let Work(sch, pol, li, lj, [i, j], scale, equations) = self;
        let board = sch.board;
        let (pa, pb) = (board.point(a), board.point(joint));
        let oa = board.setup.prog.owner(a);
        sch.drain();
        let tau_i = sch.moments(mi, li) / sch.length(pa, pb);
        let t = sch.tangential(pa, pb, (oa, i), tau_i);
        equations.push(sch.equation(joint, &[i], t));
        let t_a = (pb - pa).normalize().perp() * tau_i;
        let n_g = board.dir(j).perp();
        let p0 = pol.tip;
        let p1 = pol.lay(&format!("R^τ_{{{oa}-{i}}}"), t_a);
        let pi = pol.lay_all(li);
        let e = pol.lay_all(lj);
        let h = pol.close(("⊥ guide", e, n_g), ("∥ AB", p0, pb - pa))?;
        let r_a = pol.read(&reaction_name(oa, i), h, p1);
        let r_g = pol.read(&reaction_name(og, j), e, h);
        let r_ij = pol.read(&reaction_name(i, j), h, pi);
        sch.drain();
        let k = sch.moments(mj, lj);
        let s = offset(r_g, n_g, k, scale);
        equations.extend(sch.arm_equation(joint, j, (og, j), r_g.dot(n_g), s));
        Ok(vec![
            revolute(oa, i, a, r_a),
            prismatic(og, j, joint, j, r_g, s),
            revolute(i, j, joint, r_ij),
        ])
    }

    /// RPR: the inner reaction, normal to the slide, from the moments of link j about its pivot
    /// with the block's moment carried over; each link's polygon closes on it.
    fn rpr(
        self,
        a: usize,
        c: usize,
        [mi, mj]: [DVec2; 2],
    ) -> Result<Vec<Reaction>, ConstructionError> {
        let Work(sch, pol, li, lj, [i, j], scale, equations) = self;
        let board = sch.board;
        let (oa, oc) = (board.setup.prog.owner(a), board.setup.prog.owner(c));
        let u = board.dir(j);
        let n = u.perp();
        sch.drain();
        let k_i = sch.moments(mi, li);
        let k_j = sch.moments(mj, lj);
        let known = sch.drain();
        // The inner reaction N·n brought to A: its arm about C is measured.
        let probe = Load::force(j, LoadKind::Reaction, reaction_name(i, j), n, a);
        let arm = sch.moment(mj, &probe);
        let big_n = -(k_j + k_i) / arm;
        equations.push(sch.normal(c, [i, j], known, big_n));
        let p0 = pol.tip;
        let pi = pol.lay_all(li);
        let pj = pol.lay_all(lj);
        let q = pi - n * big_n / pol.rec.scale().value();
        pol.rec.draw(
            "R_{ij} laid from the end of i's loads",
            Item::Segment(Segment::new(pi, q)),
            Role::Construction,
            &[],
        );
        let r_ij = pol.read(&reaction_name(i, j), q, pi);
        let r_oj = pol.read(&reaction_name(oc, j), pj, q);
        let r_oi = pol.read(&reaction_name(oa, i), q, p0);
        Ok(vec![
            revolute(oa, i, a, r_oi),
            revolute(oc, j, c, r_oj),
            prismatic(i, j, a, j, r_ij, offset(r_ij, n, -k_i, scale)),
        ])
    }

    /// PRP: closed by the two guides' normals; each reaction's point from its link's moments.
    fn prp(
        self,
        ci: usize,
        cj: usize,
        joint: usize,
        [mi, mj]: [DVec2; 2],
    ) -> Result<Vec<Reaction>, ConstructionError> {
        let Work(sch, pol, li, lj, [i, j], scale, equations) = self;
        let board = sch.board;
        let (n_i, n_j) = (board.dir(i).perp(), board.dir(j).perp());
        let p0 = pol.tip;
        let pi = pol.lay_all(li);
        let e = pol.lay_all(lj);
        let h = pol.close(("⊥ guide j", e, n_j), ("⊥ guide i", p0, n_i))?;
        let r_j = pol.read(&reaction_name(cj, j), e, h);
        let r_i = pol.read(&reaction_name(ci, i), h, p0);
        let r_ij = pol.read(&reaction_name(i, j), h, pi);
        sch.drain();
        let k_i = sch.moments(mi, li);
        let s_i = offset(r_i, n_i, k_i, scale);
        equations.extend(sch.arm_equation(joint, i, (ci, i), r_i.dot(n_i), s_i));
        let k_j = sch.moments(mj, lj);
        let s_j = offset(r_j, n_j, k_j, scale);
        equations.extend(sch.arm_equation(joint, j, (cj, j), r_j.dot(n_j), s_j));
        Ok(vec![
            prismatic(ci, i, joint, i, r_i, s_i),
            prismatic(cj, j, joint, j, r_j, s_j),
            revolute(i, j, joint, r_ij),
        ])
    }

    /// RPP: link j's polygon closed by the normals to the slide and to the guide; the block's
    /// triangle gives the outer reaction.
    fn rpp(
        self,
        a: usize,
        og: usize,
        joint: usize,
        [mi, mj]: [DVec2; 2],
    ) -> Result<Vec<Reaction>, ConstructionError> {
        let Work(sch, pol, li, lj, [i, j], scale, equations) = self;
        let board = sch.board;
        let oa = board.setup.prog.owner(a);
        let (n_s, n_g) = (board.dir(i).perp(), board.dir(j).perp());
        let p0 = pol.tip;
        let pj = pol.lay_all(lj);
        let h = pol.close(("⊥ guide", pj, n_g), ("⊥ slide", p0, n_s))?;
        let r_g = pol.read(&reaction_name(og, j), pj, h);
        let r_ij = pol.read(&reaction_name(i, j), h, p0);
        pol.tip = h;
        let q = pol.lay_all(li);
        let r_oi = pol.read(&reaction_name(oa, i), q, p0);
        // The block about A: where the inner reaction acts on the slide.
        sch.drain();
        let k_i = sch.moments(mi, li);
        let s = offset(r_ij, n_s, -k_i, scale);
        equations.extend(sch.arm_equation(a, i, (i, j), -r_ij.dot(n_s), s));
        // Link j about its joint, with the inner reaction at its point.
        let shift = board.dir(i) * s.unwrap_or(0.0);
        let mut inner = Load::force(j, LoadKind::Reaction, reaction_name(i, j), r_ij, a);
        inner.shift = shift;
        let k_j = sch.moments(mj, lj) + sch.moment(mj, &inner);
        let s_g = offset(r_g, n_g, k_j, scale);
        equations.extend(sch.arm_equation(joint, j, (og, j), r_g.dot(n_g), s_g));
        Ok(vec![
            revolute(oa, i, a, r_oi),
            prismatic(og, j, joint, j, r_g, s_g),
            prismatic(i, j, a, i, r_ij, s),
        ])
    }
}
