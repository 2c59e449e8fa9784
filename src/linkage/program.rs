//! A mechanism compiled into an indexed program: names resolved once, so solving a position
//! is a straight run over the operations with no lookups.

use super::compiled::Compiled;
use super::error::{LinkageError, ModelError};
use super::indexed::{PDir, PGuide};
pub(super) use super::kinds::PDyad;
use super::kinds::{Prp, Rpp, Rpr, Rrp, Rrr};
use super::model::{Dir, Dyad, Group, Guide, LinkPoint, Mechanism};
use crate::geom::DVec2;
use std::collections::HashMap;

/// One operation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Op {
    /// Place a further point of a known link.
    Point {
        /// Index of the new point.
        idx: usize,
        /// Its link.
        link: u32,
        /// Along the link frame, m.
        along: f64,
        /// Across (left), m.
        across: f64,
    },
    /// Attach a dyad (group number `group` in file order).
    Dyad {
        /// Group index.
        group: usize,
        /// Links i, j.
        links: [u32; 2],
        /// The geometry.
        dyad: PDyad,
    },
}

/// The compiled mechanism.
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    /// Point names by index: fixed points first, then the crank pin, then in order of creation.
    pub(crate) names: Vec<String>,
    /// Positions of the fixed points (indices `0..fixed.len()`), m.
    pub(crate) fixed: Vec<DVec2>,
    /// Crank centre index.
    pub(crate) centre: usize,
    /// Crank pin index.
    pub(crate) pin: usize,
    /// Crank length, m.
    pub(crate) crank_length: f64,
    /// Crank link number.
    pub(crate) crank_link: u32,
    /// Operations after the crank.
    pub(super) ops: Vec<Op>,
    /// Largest link number + 1.
    pub(crate) link_count: usize,
    /// Every frame direction of the operations with its unit vector (cos, sin), computed
    /// once here so that solving a position does not take their sines again.
    pub(super) fixed_dirs: Vec<(f64, DVec2)>,
}

/// The point names met so far while compiling, each with its index.
#[derive(Default)]
struct Names {
    /// By index, in order of naming.
    names: Vec<String>,
    /// Index by name.
    known: HashMap<String, usize>,
}

impl Names {
    /// Name a new point, refused when the name is taken.
    fn add(&mut self, n: &str) -> Result<usize, LinkageError> {
        if self.known.contains_key(n) {
            return Err(ModelError::DuplicatePoint(n.to_string()).into());
        }
        self.names.push(n.to_string());
        self.known.insert(n.to_string(), self.names.len() - 1);
        Ok(self.names.len() - 1)
    }

    /// The index of a named point known so far; `what` refers to it.
    fn look(&self, n: &str, what: &str) -> Result<usize, LinkageError> {
        self.known.get(n).copied().ok_or_else(|| {
            ModelError::UnknownPoint {
                what: what.to_string(),
                name: n.to_string(),
            }
            .into()
        })
    }

    /// A direction of group `what` with its points resolved.
    fn dir(&self, d: &Dir, what: &str) -> Result<PDir, LinkageError> {
        Ok(match d {
            Dir::Fixed(a) => PDir::Fixed(*a),
            Dir::Along { from, to, angle } => PDir::Along {
                from: self.look(from, what)?,
                to: self.look(to, what)?,
                angle: *angle,
            },
        })
    }

    /// A guide of group `what` with its points resolved.
    fn guide(&self, g: &Guide, what: &str) -> Result<PGuide, LinkageError> {
        Ok(PGuide {
            through: self.look(&g.through, what)?,
            dir: self.dir(&g.dir, what)?,
            offset: g.offset,
            carrier: 0,
        })
    }

    /// The dyad of group `what`: its given points resolved, then its joint named.
    fn dyad(&mut self, d: &Dyad, what: &str) -> Result<PDyad, LinkageError> {
        Ok(match d {
            Dyad::Rrr {
                a,
                la,
                b,
                lb,
                joint,
                branch,
            } => {
                let (a, b) = (self.look(a, what)?, self.look(b, what)?);
                PDyad::Rrr(Rrr {
                    a,
                    la: *la,
                    b,
                    lb: *lb,
                    joint: self.add(joint)?,
                    branch: *branch,
                })
            }
            Dyad::Rrp {
                a,
                la,
                guide,
                joint,
                branch,
            } => {
                let (a, guide) = (self.look(a, what)?, self.guide(guide, what)?);
                PDyad::Rrp(Rrp {
                    a,
                    la: *la,
                    guide,
                    joint: self.add(joint)?,
                    branch: *branch,
                })
            }
            Dyad::Rpr { a, c, offset } => PDyad::Rpr(Rpr {
                a: self.look(a, what)?,
                c: self.look(c, what)?,
                offset: *offset,
            }),
            Dyad::Prp {
                guide_i,
                guide_j,
                joint,
            } => {
                let (gi, gj) = (self.guide(guide_i, what)?, self.guide(guide_j, what)?);
                PDyad::Prp(Prp {
                    gi,
                    gj,
                    joint: self.add(joint)?,
                })
            }
            Dyad::Rpp {
                a,
                slide,
                guide,
                joint,
            } => {
                let (a, slide, guide) = (
                    self.look(a, what)?,
                    self.dir(slide, what)?,
                    self.guide(guide, what)?,
                );
                PDyad::Rpp(Rpp {
                    a,
                    slide,
                    guide,
                    joint: self.add(joint)?,
                })
            }
        })
    }
}

/// Place every further point whose link is known by now and not yet placed.
fn place_points(
    points: &[LinkPoint],
    placed: &mut [bool],
    links_known: &[u32],
    names: &mut Names,
    ops: &mut Vec<Op>,
) -> Result<(), LinkageError> {
    for (k, p) in points.iter().enumerate() {
        if !placed[k] && links_known.contains(&p.link) {
            placed[k] = true;
            let idx = names.add(&p.name)?;
            ops.push(Op::Point {
                idx,
                link: p.link,
                along: p.along,
                across: p.across,
            });
        }
    }
    Ok(())
}

/// The links of group `what` join the known ones; refused if one is the frame or known.
fn claim_links(
    links_known: &mut Vec<u32>,
    links: [u32; 2],
    what: &str,
) -> Result<(), LinkageError> {
    for l in links {
        if l == 0 || links_known.contains(&l) {
            return Err(ModelError::LinkReused {
                what: what.to_string(),
                link: l,
            }
            .into());
        }
        links_known.push(l);
    }
    Ok(())
}

/// An RPP group's slide is a direction of its link j (`link`), which turns with the guide's
/// carrier: both frame directions, or both along the same two points.
fn slide_with_guide(
    dyad: &PDyad,
    names: &Names,
    what: &str,
    link: u32,
) -> Result<(), LinkageError> {
    if let PDyad::Rpp(Rpp {
        a, slide, guide, ..
    }) = *dyad
    {
        let same = match (slide, guide.dir) {
            (PDir::Fixed(_), PDir::Fixed(_)) => true,
            (
                PDir::Along { from, to, .. },
                PDir::Along {
                    from: f2, to: t2, ..
                },
            ) => (from, to) == (f2, t2),
            _ => false,
        };
        if !same {
            return Err(ModelError::SlideAcrossGuide {
                what: what.to_string(),
                point: names.names[a].clone(),
                link,
            }
            .into());
        }
    }
    Ok(())
}

/// How the model's errors name group `gi`: `group 2 (RRP, links 4, 5)`.
pub(super) fn group_what(gi: usize, g: &Group) -> String {
    format!(
        "group {} ({}, links {}, {})",
        gi + 1,
        g.dyad.kind().letters(),
        g.links[0],
        g.links[1]
    )
}

/// Every frame direction of the operations with its unit vector, each once.
fn fixed_dirs(ops: &[Op]) -> Vec<(f64, DVec2)> {
    let mut fixed_dirs: Vec<(f64, DVec2)> = Vec::new();
    for op in ops {
        let Op::Dyad { dyad, .. } = op else { continue };
        for d in dyad.group().directions().into_iter().flatten() {
            if let PDir::Fixed(a) = d {
                if !fixed_dirs.iter().any(|f| f.0.to_bits() == a.to_bits()) {
                    fixed_dirs.push((a, DVec2::from_angle(a)));
                }
            }
        }
    }
    fixed_dirs
}

impl Program {
    /// Index of a named point.
    pub fn index(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
    }

    /// Compile a mechanism, checking every name and link reference in attachment order.
    pub fn compile(m: &Mechanism) -> Result<Self, LinkageError> {
        let mut names = Names::default();
        let fixed: Vec<DVec2> = m.fixed.iter().map(|f| f.at).collect();
        for f in &m.fixed {
            names.add(&f.name)?;
        }
        let centre = names.look(&m.crank.centre, "crank centre")?;
        if centre >= fixed.len() {
            return Err(ModelError::CentreNotFixed(m.crank.centre.clone()).into());
        }
        let pin = names.add(&m.crank.pin)?;
        let mut links_known = vec![m.crank.link];
        let mut ops = Vec::new();
        let mut placed = vec![false; m.points.len()];
        place_points(&m.points, &mut placed, &links_known, &mut names, &mut ops)?;
        for (gi, g) in m.groups.iter().enumerate() {
            let what = group_what(gi, g);
            let dyad = names.dyad(&g.dyad, &what)?;
            claim_links(&mut links_known, g.links, &what)?;
            slide_with_guide(&dyad, &names, &what, g.links[1])?;
            ops.push(Op::Dyad {
                group: gi,
                links: g.links,
                dyad,
            });
            place_points(&m.points, &mut placed, &links_known, &mut names, &mut ops)?;
        }
        if let Some(k) = placed.iter().position(|p| !p) {
            return Err(ModelError::PointOnUnknownLink {
                name: m.points[k].name.clone(),
                link: m.points[k].link,
            }
            .into());
        }
        let link_count = links_known.iter().copied().max().unwrap_or(1) as usize + 1;
        let fixed_dirs = fixed_dirs(&ops);
        let mut prog = Self {
            names: names.names,
            fixed,
            centre,
            pin,
            crank_length: m.crank.length,
            crank_link: m.crank.link,
            ops,
            link_count,
            fixed_dirs,
        };
        prog.resolve_carriers(m)?;
        Ok(prog)
    }
}

impl Program {
    /// Every guide of the groups with its group and the joint that slides on it, in the
    /// order of the program.
    pub(super) fn dyad_guides(&self) -> impl Iterator<Item = (usize, usize, PGuide)> + '_ {
        self.ops.iter().flat_map(|op| {
            let (group, joint, guides) = match op {
                Op::Dyad { group, dyad, .. } => (*group, dyad.joint(), dyad.guides()),
                Op::Point { .. } => (0, None, [None, None]),
            };
            joint
                .into_iter()
                .flat_map(move |j| guides.into_iter().flatten().map(move |g| (group, j, g)))
        })
    }

    /// The link a point belongs to: the first that carried it (0 for fixed points, the crank
    /// for its pin, a point's own link, link i for a dyad's joint — link j for RPP, whose
    /// joint is on the translating link).
    pub fn owner(&self, k: usize) -> usize {
        if k < self.fixed.len() {
            return 0;
        }
        if k == self.pin {
            return self.crank_link as usize;
        }
        for op in &self.ops {
            match *op {
                Op::Point { idx, link, .. } if idx == k => return link as usize,
                Op::Dyad { links, dyad, .. } if dyad.joint() == Some(k) => {
                    return links[usize::from(dyad.group().joint_on_j())] as usize;
                }
                _ => {}
            }
        }
        0
    }

    /// Fixed points that are revolute pairs with the frame.
    pub fn fixed_pivots(&self) -> Vec<usize> {
        let mut v = vec![self.centre];
        for op in &self.ops {
            if let Op::Dyad { dyad, .. } = op {
                v.extend(dyad.group().pivots());
            }
        }
        v.retain(|k| *k < self.fixed.len());
        v.sort_unstable();
        v.dedup();
        v
    }

    /// The links each point lies on (a pivot or joint lies on several; fixed points on the
    /// frame 0 and on the links pivoted there).
    pub fn links_of(&self, k: usize) -> Vec<usize> {
        self.links_in(&self.ops, k)
    }

    /// The links point `k` lies on once the operations `ops` (a prefix of the program's) are
    /// carried out.
    pub(super) fn links_in(&self, ops: &[Op], k: usize) -> Vec<usize> {
        let mut v = Vec::new();
        if k < self.fixed.len() {
            v.push(0);
        }
        if k == self.centre || k == self.pin {
            v.push(self.crank_link as usize);
        }
        for op in ops {
            match *op {
                Op::Point { idx, link, .. } if idx == k => v.push(link as usize),
                Op::Dyad {
                    links: [i, j],
                    dyad,
                    ..
                } => {
                    let [on_i, on_j] = dyad.group().on_links(k);
                    if on_i {
                        v.push(i as usize);
                    }
                    if on_j {
                        v.push(j as usize);
                    }
                }
                _ => {}
            }
        }
        v.sort_unstable();
        v.dedup();
        v
    }
}

impl Compiled for Program {
    fn names(&self) -> &[String] {
        &self.names
    }

    fn fixed_count(&self) -> usize {
        self.fixed.len()
    }

    fn centre(&self) -> usize {
        self.centre
    }

    fn owner(&self, k: usize) -> usize {
        Program::owner(self, k)
    }

    /// Whether point `k` is a further point of a link (`[[mechanism.point]]`: a centre of
    /// mass, a point to chart) that no group attaches to: its velocity is read, nothing is
    /// built on it, so its vector on a plan is a secondary one (drawn thin).
    fn is_leaf_point(&self, k: usize) -> bool {
        let is_point = self
            .ops
            .iter()
            .any(|op| matches!(*op, Op::Point { idx, .. } if idx == k));
        let used = self.ops.iter().any(|op| match *op {
            Op::Point { .. } => false,
            Op::Dyad { dyad, .. } => dyad.group().uses(k),
        });
        is_point && !used
    }

    /// Whether point `k` is fixed or carried by the crank (its motion is known from ω₁ alone).
    fn on_frame_or_crank(&self, k: usize) -> bool {
        k < self.fixed.len() || self.links_of(k).contains(&(self.crank_link as usize))
    }

    fn link_reach(&self, link: u32, mu: f64) -> f64 {
        self.ops
            .iter()
            .filter_map(|op| match op {
                Op::Point { link: l, along, .. } if *l == link => Some(*along / mu),
                _ => None,
            })
            .fold(0.0, f64::max)
    }
}
