//! A compiled group of any kind ([`PDyad`]): the one `match` over the kinds, which hands a
//! group to its kind's file behind [`GroupKind`], and each kind's words ([`DyadKind::words`]).

use super::prp::{self, Prp};
use super::rpp::{self, Rpp};
use super::rpr::{self, Rpr};
use super::rrp::{self, Rrp};
use super::rrr::{self, Rrr};
use super::{GroupKind, Solved, Words};
use crate::linkage::analytic::state::State;
use crate::linkage::compiled::Compiled;
use crate::linkage::indexed::PGuide;
use crate::linkage::model::DyadKind;

/// A dyad with resolved indices: one kind's group.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::linkage) enum PDyad {
    /// Kind 1, RRR.
    Rrr(Rrr),
    /// Kind 2, RRP.
    Rrp(Rrp),
    /// Kind 3, RPR.
    Rpr(Rpr),
    /// Kind 4, PRP.
    Prp(Prp),
    /// Kind 5, RPP.
    Rpp(Rpp),
}

impl PDyad {
    /// The group behind the trait: a new kind adds an arm here, in [`PDyad::group_mut`] and
    /// in [`PDyad::solve`].
    pub(in crate::linkage) fn group(&self) -> &dyn GroupKind {
        match self {
            PDyad::Rrr(g) => g,
            PDyad::Rrp(g) => g,
            PDyad::Rpr(g) => g,
            PDyad::Prp(g) => g,
            PDyad::Rpp(g) => g,
        }
    }

    /// Solve the group by its kind's [`GroupKind::solve`], dispatched by the variant rather
    /// than through [`PDyad::group`]'s `&dyn GroupKind`: the twin's run over the program is
    /// the analytic kernel's inner loop, and a solve called through the trait object stays a
    /// call of its own (its state passed through memory, its helpers no longer inlined)
    /// where, inlined, it is one function with the run, as fast as the run was when it
    /// matched on the kinds itself.
    #[inline(always)]
    pub(in crate::linkage) fn solve(
        &self,
        prog: &dyn Compiled,
        st: &mut State<'_>,
        links: [usize; 2],
    ) -> Solved {
        match self {
            PDyad::Rrr(g) => g.solve(prog, st, links),
            PDyad::Rrp(g) => g.solve(prog, st, links),
            PDyad::Rpr(g) => g.solve(prog, st, links),
            PDyad::Prp(g) => g.solve(prog, st, links),
            PDyad::Rpp(g) => g.solve(prog, st, links),
        }
    }

    /// The kind.
    pub(in crate::linkage) fn kind(&self) -> DyadKind {
        self.group().kind()
    }

    /// The point the group creates, if any (RPR creates none).
    pub(in crate::linkage) fn joint(&self) -> Option<usize> {
        self.group().joint()
    }

    /// Its guides, in the order of its pairs (RRP, RPP: the guide; PRP: i's, j's).
    pub(in crate::linkage) fn guides(&self) -> [Option<PGuide>; 2] {
        self.group().guides()
    }

    /// Its guides to change, in the order of [`PDyad::guides`].
    pub(in crate::linkage) fn guides_mut(&mut self) -> [Option<&mut PGuide>; 2] {
        self.group_mut().guides_mut()
    }

    /// The group behind the trait, to change.
    pub(in crate::linkage) fn group_mut(&mut self) -> &mut dyn GroupKind {
        match self {
            PDyad::Rrr(g) => g,
            PDyad::Rrp(g) => g,
            PDyad::Rpr(g) => g,
            PDyad::Prp(g) => g,
            PDyad::Rpp(g) => g,
        }
    }
}

impl DyadKind {
    /// Every kind, in the textbooks' order (вид 1…5): what a scene may name.
    pub const ALL: [DyadKind; 5] = [
        DyadKind::Rrr,
        DyadKind::Rrp,
        DyadKind::Rpr,
        DyadKind::Prp,
        DyadKind::Rpp,
    ];

    /// The kind's words (its file's `WORDS`).
    pub(crate) fn words(self) -> &'static Words {
        match self {
            DyadKind::Rrr => &rrr::WORDS,
            DyadKind::Rrp => &rrp::WORDS,
            DyadKind::Rpr => &rpr::WORDS,
            DyadKind::Prp => &prp::WORDS,
            DyadKind::Rpp => &rpp::WORDS,
        }
    }
}
