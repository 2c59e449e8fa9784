//! What the force and kinematic analyses ask of a compiled [`Program`]: its groups with the
//! points and guide carriers of their pairs, the points placed on known links, a piston's
//! axis. Topology only: lengths, branches and guide geometry stay inside the program.

use super::indexed::PDir;
use super::pairs::GroupPairs;
use super::program::{Op, Program};
use crate::geom::DVec2;

/// One group of a program, in attachment order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GroupView {
    /// Group number in file order.
    pub group: usize,
    /// Links i, j.
    pub links: [usize; 2],
    /// Its pairs.
    pub pairs: GroupPairs,
}

impl GroupView {
    /// The links of the group that slide, by position: the block of an RRP (j) or RPR (i)
    /// group, both links of a PRP or RPP group.
    pub fn sliders(&self) -> [Option<usize>; 2] {
        let [i, j] = self.links;
        match self.pairs {
            GroupPairs::Rrr { .. } => [None, None],
            GroupPairs::Rrp { .. } => [None, Some(j)],
            GroupPairs::Rpr { .. } => [Some(i), None],
            GroupPairs::Prp { .. } | GroupPairs::Rpp { .. } => [Some(i), Some(j)],
        }
    }
}

impl Program {
    /// The groups in attachment order.
    pub fn groups(&self) -> impl DoubleEndedIterator<Item = GroupView> + '_ {
        self.ops.iter().filter_map(|op| match *op {
            Op::Dyad { group, links, dyad } => Some(GroupView {
                group,
                links: links.map(|l| l as usize),
                pairs: dyad.group().pairs(),
            }),
            Op::Point { .. } => None,
        })
    }

    /// The points placed on known links (not the joints of groups), in program order.
    pub fn placed_points(&self) -> impl Iterator<Item = usize> + '_ {
        self.ops.iter().filter_map(|op| match *op {
            Op::Point { idx, .. } => Some(idx),
            Op::Dyad { .. } => None,
        })
    }

    /// When point `k` is a piston (the slider's joint of an RRP group): the unit direction of
    /// its guide with the points at `at`, and the slider's link.
    pub fn piston(&self, k: usize, at: impl Fn(usize) -> DVec2) -> Option<(DVec2, usize)> {
        let (guide, slider) = self.ops.iter().find_map(|op| match *op {
            Op::Dyad { links, dyad, .. } => dyad.group().piston(k).map(|g| (g, links[1] as usize)),
            Op::Point { .. } => None,
        })?;
        let axis = match guide.dir {
            PDir::Fixed(a) => DVec2::from_angle(a),
            PDir::Along { from, to, angle } => {
                DVec2::from_angle(angle).rotate((at(to) - at(from)).normalize_or_zero())
            }
        };
        Some((axis, slider))
    }
}
