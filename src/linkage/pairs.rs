//! The pairs of one Assur group as the force analysis reads them ([`GroupPairs`]): the
//! points of its revolute pairs and the links that carry its guides.

/// The pairs of a group: the points of its revolute pairs and the links that carry its
/// guides (0 the frame). Links i and j are [`super::GroupView::links`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GroupPairs {
    /// RRR: link i pivoted at `a`, link j at `c`, the two jointed at `joint`.
    Rrr {
        /// Outer pair of link i.
        a: usize,
        /// Outer pair of link j.
        c: usize,
        /// Inner pair.
        joint: usize,
    },
    /// RRP: link i pivoted at `a`, link j (the slider) on the guide of link `guide`, the two
    /// jointed at `joint`.
    Rrp {
        /// Outer pair of link i.
        a: usize,
        /// The link that carries the guide.
        guide: usize,
        /// Inner pair.
        joint: usize,
    },
    /// RPR: link i (the block) pivoted at `a`, link j (the slotted link) at `c`, the block
    /// sliding along link j.
    Rpr {
        /// Outer pair of link i.
        a: usize,
        /// Outer pair of link j.
        c: usize,
    },
    /// PRP: links i and j slide on the guides of links `gi` and `gj`, jointed at `joint`.
    Prp {
        /// The link that carries link i's guide.
        gi: usize,
        /// The link that carries link j's guide.
        gj: usize,
        /// Inner pair.
        joint: usize,
    },
    /// RPP: link i (the block) pivoted at `a` slides along link j, which slides on the guide
    /// of link `guide`; `joint` is link j's point.
    Rpp {
        /// Outer pair of link i.
        a: usize,
        /// The link that carries link j's guide.
        guide: usize,
        /// Link j's point.
        joint: usize,
    },
}
