//! Structural analysis: links, kinematic pairs, mobility (Chebyshev), Assur decomposition,
//! the structure formula and the class of the mechanism.

use super::model::{Dyad, DyadKind, Mechanism};
use super::program::{Op, Program};

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

/// Chebyshev's count of a planar mechanism: W = 3n − 2p₅ − p₄.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mobility {
    /// Moving links.
    pub n: u32,
    /// Lower pairs counted.
    pub p5: u32,
    /// Higher pairs counted.
    pub p4: u32,
    /// The degree of freedom.
    pub w: i32,
}

impl Mobility {
    /// W = 3n − 2p₅ − p₄.
    pub fn chebyshev(n: u32, p5: u32, p4: u32) -> Self {
        Self {
            n,
            p5,
            p4,
            w: 3 * n as i32 - 2 * p5 as i32 - p4 as i32,
        }
    }
}

impl Structure {
    /// Analyse a mechanism. The link carrying each point and guide is the compiled
    /// program's ([`Program::owner`], `Program::carrier`); a name the program does not
    /// know (a mechanism that does not compile) is taken on the frame.
    pub fn analyse(m: &Mechanism) -> Self {
        let prog = Program::compile(m).ok();
        let index = |n: &str| prog.as_ref().and_then(|p| p.index(n).map(|k| (p, k)));
        let own = |n: &str| index(n).map_or(0, |(p, k)| p.owner(k) as u32);
        let guide_owner = |gi: usize, which: usize| {
            let carrier = |p: &Program| {
                let guides = p.ops.iter().find_map(|op| match *op {
                    Op::Dyad { group, dyad, .. } if group == gi => Some(dyad.guides()),
                    _ => None,
                })?;
                guides[which].map(|g| g.carrier as u32)
            };
            prog.as_ref().and_then(carrier).unwrap_or(0)
        };
        let mut pairs = vec![pair(&m.crank.centre, false, 0, m.crank.link)];
        let mut groups = Vec::new();
        for (gi, g) in m.groups.iter().enumerate() {
            let [i, j] = g.links;
            let ps = match &g.dyad {
                Dyad::Rrr { a, b, joint, .. } => [
                    pair(a, false, own(a), i),
                    pair(joint, false, i, j),
                    pair(b, false, j, own(b)),
                ],
                Dyad::Rrp { a, joint, .. } => [
                    pair(a, false, own(a), i),
                    pair(joint, false, i, j),
                    pair(joint, true, j, guide_owner(gi, 0)),
                ],
                Dyad::Rpr { a, c, .. } => [
                    pair(a, false, own(a), i),
                    pair(a, true, i, j),
                    pair(c, false, j, own(c)),
                ],
                Dyad::Prp { joint, .. } => [
                    pair(joint, true, guide_owner(gi, 0), i),
                    pair(joint, false, i, j),
                    pair(joint, true, j, guide_owner(gi, 1)),
                ],
                Dyad::Rpp { a, joint, .. } => [
                    pair(a, false, own(a), i),
                    pair(a, true, i, j),
                    pair(joint, true, j, guide_owner(gi, 0)),
                ],
            };
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
        let (bare, all) = (
            Mobility::chebyshev(n, p5, 0),
            Mobility::chebyshev(n, p5_all, 0),
        );
        Structure {
            n,
            pairs,
            p5,
            p4: 0,
            w: bare.w,
            p5_all,
            w_all: all.w,
            crank_link: m.crank.link,
            groups,
            class: if m.groups.is_empty() { 1 } else { 2 },
        }
    }

    /// Whether redundant pair `r` repeats a pair of the structure (same kind, same links).
    pub fn repeats(&self, r: &PairInfo) -> bool {
        let [x, y] = r.links;
        self.pairs
            .iter()
            .filter(|p| !p.redundant)
            .any(|p| p.prismatic == r.prismatic && (p.links == [x, y] || p.links == [y, x]))
    }

    /// The mobility counting the redundant pairs that repeat no pair of the structure (a
    /// redundant pair that repeats one is discounted: it adds no constraint).
    pub fn mobility(&self) -> Mobility {
        let stray = self
            .pairs
            .iter()
            .filter(|p| p.redundant && !self.repeats(p))
            .count() as u32;
        Mobility::chebyshev(self.n, self.p5 + stray, self.p4)
    }

    /// The structure formula: each group after the element (the driver or a group before
    /// it) it is attached to, the latest of them when it holds on to several. A chain when
    /// each is attached to the one before (the shaper's `I(0,1) → II(2,3) → II(4,5)`); two
    /// branches from the driver either side of it (the V engine's two groups on the crank,
    /// `II(2,3) ← I(0,1) → II(4,5)`), more with `;` between them. A group attached to the
    /// middle of a branch leaves the groups in their order of attachment.
    pub fn formula(&self) -> String {
        let name = |i: &usize| {
            let g = &self.groups[*i];
            format!("II({},{})", g.links[0], g.links[1])
        };
        let driver = format!("I(0,{})", self.crank_link);
        let chain = |b: &[usize], arrow: &str| {
            let names: Vec<String> = b.iter().map(name).collect();
            names.join(arrow)
        };
        let all: Vec<usize> = (0..self.groups.len()).collect();
        match self.branches().as_deref() {
            Some([left, right]) => {
                let left: Vec<usize> = left.iter().rev().copied().collect();
                format!(
                    "{} ← {driver} → {}",
                    chain(&left, " ← "),
                    chain(right, " → ")
                )
            }
            Some(b) if b.len() > 2 => b
                .iter()
                .map(|b| format!("{driver} → {}", chain(b, " → ")))
                .collect::<Vec<_>>()
                .join("; "),
            _ if all.is_empty() => driver,
            _ => format!("{driver} → {}", chain(&all, " → ")),
        }
    }

    /// The groups as branches from the driver, each a run of group indices in which every
    /// group is attached to the one before it (the first to the driver); `None` when a group
    /// is attached to one that another group already follows.
    fn branches(&self) -> Option<Vec<Vec<usize>>> {
        let mut branches: Vec<Vec<usize>> = Vec::new();
        for (i, g) in self.groups.iter().enumerate() {
            // The latest earlier group one of its outer pairs joins (none: the driver).
            let parent = (0..i).rev().find(|&j| {
                [&g.pairs[0], &g.pairs[2]]
                    .iter()
                    .flat_map(|p| p.links)
                    .any(|l| self.groups[j].links.contains(&l))
            });
            match parent {
                None => branches.push(vec![i]),
                Some(j) => branches.iter_mut().find(|b| b.last() == Some(&j))?.push(i),
            }
        }
        Some(branches)
    }
}
