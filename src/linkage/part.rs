//! Which part of a mechanism a drawing shows ([`Part`]): the whole, the driver, or one Assur
//! group drawn apart (the groups of the force analysis).

use super::program::{Op, Program};

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
}
