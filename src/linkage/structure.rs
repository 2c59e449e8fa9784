//! Structural analysis: links, kinematic pairs, mobility (Chebyshev), Assur decomposition,
//! the structure formula and the class of the mechanism.

use super::model::{Dir, Dyad, DyadKind, Guide, Mechanism};
use std::collections::HashMap;

/// One kinematic pair.
#[derive(Debug, Clone, PartialEq)]
pub struct PairInfo {
    /// Name (the point where it is).
    pub name: String,
    /// Prismatic (true) or revolute.
    pub prismatic: bool,
    /// The links it joins.
    pub links: [u32; 2],
    /// A passive pair that repeats a constraint.
    pub redundant: bool,
}

/// One Assur group of the decomposition.
#[derive(Debug, Clone, PartialEq)]
pub struct GroupInfo {
    /// Its links.
    pub links: [u32; 2],
    /// Kind.
    pub kind: DyadKind,
    /// Its three pairs (outer, inner, outer).
    pub pairs: [PairInfo; 3],
}

/// The structure of a mechanism.
#[derive(Debug, Clone, PartialEq)]
pub struct Structure {
    /// Moving links.
    pub n: u32,
    /// All pairs, the driver's first; redundant ones last.
    pub pairs: Vec<PairInfo>,
    /// Lower pairs without the redundant ones.
    pub p5: u32,
    /// Higher pairs (none in linkages).
    pub p4: u32,
    /// W = 3n − 2p₅ − p₄ without the redundant pairs.
    pub w: i32,
    /// p₅ counting the redundant pairs.
    pub p5_all: u32,
    /// W counting the redundant pairs.
    pub w_all: i32,
    /// The crank link (the class-I mechanism is frame 0 + this link).
    pub crank_link: u32,
    /// The groups in order of attachment.
    pub groups: Vec<GroupInfo>,
    /// Class of the mechanism (the highest class of its groups; 2 for dyads).
    pub class: u32,
}

fn pair(name: &str, prismatic: bool, a: u32, b: u32) -> PairInfo {
    PairInfo {
        name: name.to_string(),
        prismatic,
        links: [a, b],
        redundant: false,
    }
}

impl Structure {
    /// Analyse a mechanism.
    pub fn analyse(m: &Mechanism) -> Self {
        // Which link each known point belongs to (the first that carried it).
        let mut owner: HashMap<&str, u32> = m.fixed.iter().map(|f| (f.name.as_str(), 0)).collect();
        owner.insert(&m.crank.pin, m.crank.link);
        for p in &m.points {
            owner.entry(&p.name).or_insert(p.link);
        }
        let mut pairs = vec![pair(&m.crank.centre, false, 0, m.crank.link)];
        let mut groups = Vec::new();
        for g in &m.groups {
            let [i, j] = g.links;
            let own = |owner: &HashMap<&str, u32>, n: &str| owner.get(n).copied().unwrap_or(0);
            let guide_owner = |owner: &HashMap<&str, u32>, g: &Guide| match &g.dir {
                Dir::Along { from, .. } => own(owner, from),
                Dir::Fixed(_) => own(owner, &g.through),
            };
            let ps = match &g.dyad {
                Dyad::Rrr { a, b, joint, .. } => [
                    pair(a, false, own(&owner, a), i),
                    pair(joint, false, i, j),
                    pair(b, false, j, own(&owner, b)),
                ],
                Dyad::Rrp {
                    a, guide, joint, ..
                } => [
                    pair(a, false, own(&owner, a), i),
                    pair(joint, false, i, j),
                    pair(joint, true, j, guide_owner(&owner, guide)),
                ],
                Dyad::Rpr { a, c, .. } => [
                    pair(a, false, own(&owner, a), i),
                    pair(a, true, i, j),
                    pair(c, false, j, own(&owner, c)),
                ],
                Dyad::Prp {
                    guide_i,
                    guide_j,
                    joint,
                } => [
                    pair(joint, true, guide_owner(&owner, guide_i), i),
                    pair(joint, false, i, j),
                    pair(joint, true, j, guide_owner(&owner, guide_j)),
                ],
                Dyad::Rpp {
                    a, guide, joint, ..
                } => [
                    pair(a, false, own(&owner, a), i),
                    pair(a, true, i, j),
                    pair(joint, true, j, guide_owner(&owner, guide)),
                ],
            };
            if let Some(joint) = g.dyad_joint() {
                owner.entry(joint).or_insert(i);
            }
            pairs.extend(ps.iter().cloned());
            groups.push(GroupInfo {
                links: g.links,
                kind: g.dyad.kind(),
                pairs: ps,
            });
        }
        let p5 = pairs.len() as u32;
        pairs.extend(m.redundant.iter().map(|r| PairInfo {
            name: r.name.clone(),
            prismatic: r.prismatic,
            links: r.links,
            redundant: true,
        }));
        let n = 1 + 2 * m.groups.len() as u32;
        let p5_all = pairs.len() as u32;
        let w = 3 * n as i32 - 2 * p5 as i32;
        let w_all = 3 * n as i32 - 2 * p5_all as i32;
        Structure {
            n,
            pairs,
            p5,
            p4: 0,
            w,
            p5_all,
            w_all,
            crank_link: m.crank.link,
            groups,
            class: if m.groups.is_empty() { 1 } else { 2 },
        }
    }

    /// The structure formula: `I(0,1) → II(2,3) → II(4,5)`.
    pub fn formula(&self) -> String {
        let mut s = format!("I(0,{})", self.crank_link);
        for g in &self.groups {
            s.push_str(&format!(" → II({},{})", g.links[0], g.links[1]));
        }
        s
    }
}

impl super::model::Group {
    /// The point this group's dyad creates, if any.
    pub fn dyad_joint(&self) -> Option<&str> {
        match &self.dyad {
            Dyad::Rrr { joint, .. }
            | Dyad::Rrp { joint, .. }
            | Dyad::Prp { joint, .. }
            | Dyad::Rpp { joint, .. } => Some(joint),
            Dyad::Rpr { .. } => None,
        }
    }
}
