//! Which part of a mechanism a drawing shows ([`Part`]): the whole, the driver, or one Assur
//! group drawn apart (the groups of the force analysis).

use super::analytic::state::Pose;
use super::program::{Op, Program};
use crate::construct::fit::Extent;

/// Which part of a mechanism to draw.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Part {
    /// Everything.
    All,
    /// The class-I mechanism: frame and crank.
    Driver,
    /// One Assur group (index in file order).
    Group(usize),
}

impl Part {
    /// Whether link `l` is drawn with this part.
    pub(super) fn draws(self, prog: &Program, l: u32) -> bool {
        match self {
            Part::All => true,
            Part::Driver => l == prog.crank_link,
            Part::Group(g) => prog.ops.iter().any(
                |op| matches!(op, Op::Dyad { group, links, .. } if *group == g && links.contains(&l)),
            ),
        }
    }

    /// What its drawing ([`super::draw_links`]) takes at the position `pose`, at any μ_l,
    /// taken into `e`: the points of the links it draws (SI), and what is drawn a fixed
    /// length from a point (a kind's link run on past its pin, a slide line past its block).
    pub(crate) fn extent(self, prog: &Program, pose: &Pose, e: &mut Extent) {
        for (k, &p) in pose.p.iter().enumerate() {
            if prog.links_of(k).iter().any(|&l| self.draws(prog, l as u32)) {
                e.add(p);
            }
        }
        for op in &prog.ops {
            if let Op::Dyad { group, links, dyad } = op {
                if matches!(self, Part::All) || self == Part::Group(*group) {
                    for (at, off) in dyad.group().drawn_past(&pose.p, &pose.dir, *links) {
                        e.mark(at, off);
                    }
                }
            }
        }
        super::slide_lines::slide_extent(prog, &pose.p, self, e);
    }
}
