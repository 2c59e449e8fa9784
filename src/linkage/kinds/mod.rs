//! The Assur group kinds, one file each (`rrr`, `rrp`, `rpr`, `prp`, `rpp`), behind one
//! trait, [`GroupKind`]: what the compiled program asks of a group — the point it creates,
//! its guides and frame directions, the links a point lies on, the points it is given, its
//! pairs for the force analysis, its pivots on the frame, its construction by compass, its
//! drawing, its twin's closed-form solve and its steps on the velocity and acceleration
//! plans — and its words in the scene ([`Words`]: the kind's number, its letters, the scene
//! keys of its table). A kind's data (the indices and lengths of its compiled group) is its
//! own struct; [`PDyad`] (`dyad.rs`) holds one of them and dispatches to it by a `match`
//! ([`PDyad::group`]; the twin's solve by [`PDyad::solve`], inlined into its run). A kind
//! reads the program that holds it through [`Compiled`], never the program itself.
//!
//! The construction, the twin and the plans are separate routes in one file (DESIGN §1):
//! each decides by itself from the program, sharing primitives only (the recorder, the
//! jets, the plan builder); none calls another. RPR, whose pin may pass through its pivot,
//! has a room beside its file (`rpr/`): each route's answer to that case is a file.
//! What still matches on the kind elsewhere: the model's `Dyad` and its readers (the
//! compilation in `program.rs`, the scene's validation, the structure, the data table, the
//! note) and the force analysis (`GroupPairs`).

mod dyad;
mod prp;
mod rpp;
mod rpr;
mod rrp;
mod rrr;

pub(in crate::linkage) use dyad::PDyad;

pub(in crate::linkage) use prp::Prp;
pub(in crate::linkage) use rpp::Rpp;
pub(in crate::linkage) use rpr::Rpr;
pub(in crate::linkage) use rrp::Rrp;
pub(in crate::linkage) use rrr::Rrr;

use super::analytic::state::{State, Unassembled};
use super::built::{Built, Frames};
use super::compiled::Compiled;
use super::indexed::{PDir, PGuide};
use super::model::DyadKind;
use super::pairs::GroupPairs;
use super::pen::Pen;
use super::plans::builder::Builder;
use crate::construct::{ConstructionError, Recorder};
use crate::geom::DVec2;

/// A kind's words: how the textbooks and the scene name it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Words {
    /// The kind number of the Russian/Ukrainian textbooks (вид 1…5).
    pub number: u32,
    /// Latin pair letters (`RRP`), the scene's `kind`.
    pub letters: &'static str,
    /// Cyrillic pair letters (`ВВП`), accepted by the scene too.
    pub letters_ru: &'static str,
    /// The keys of its `[[mechanism.group]]` table besides `kind`.
    pub keys: &'static [&'static str],
}

/// What a kind's twin solve gives: its group solved into the state, or why it cannot be
/// assembled at this crank angle.
pub(in crate::linkage) type Solved = Result<(), Unassembled>;

/// What a kind's plan steps give: its group drawn on the plan, or the step that failed.
pub(in crate::linkage) type Planned = Result<(), ConstructionError>;

/// What a compiled Assur group of one kind answers. Links i and j are the group's, in its
/// order; points are program indices.
pub(in crate::linkage) trait GroupKind {
    /// The kind.
    fn kind(&self) -> DyadKind;
    /// The point the group creates, if any (RPR creates none).
    fn joint(&self) -> Option<usize>;
    /// Whether the created point lies on link j (RPP: on the translating link), not on i.
    fn joint_on_j(&self) -> bool {
        false
    }
    /// Its guides, in the order of its pairs (RRP, RPP: the guide; PRP: i's, j's).
    fn guides(&self) -> [Option<PGuide>; 2] {
        [None, None]
    }
    /// Its guides to change, in the order of [`GroupKind::guides`].
    fn guides_mut(&mut self) -> [Option<&mut PGuide>; 2] {
        [None, None]
    }
    /// The directions it is drawn along that may be frame directions: its guides' (RPP:
    /// the slide's, then the guide's).
    fn directions(&self) -> [Option<PDir>; 2] {
        self.guides().map(|g| g.map(|g| g.dir))
    }
    /// Whether point `k` lies on link i, on link j.
    fn on_links(&self, k: usize) -> [bool; 2];
    /// Whether it is built on point `k`: a given point, or a point of a guide or direction.
    fn uses(&self, k: usize) -> bool;
    /// Its outer revolute pairs, whose points may be pivots on the frame.
    fn pivots(&self) -> Vec<usize>;
    /// Its pairs for the force analysis, the guides' carriers resolved.
    fn pairs(&self) -> GroupPairs;
    /// Construct it by compass and straightedge at the drawn position `pos` (step name `s`,
    /// `prev` the previous position, for continuity; `j` its link j): its joint (RPR: its
    /// slide line), and the frames of its links.
    fn construct(
        &self,
        prog: &dyn Compiled,
        rec: &mut Recorder,
        pos: &mut Built,
        prev: Option<&Built>,
        step: (&str, usize),
    ) -> Result<Frames, ConstructionError>;
    /// Draw its links `[i, j]` at the constructed position `b` with `pen` (a link's number
    /// at its anchor, its joints to be drawn).
    fn draw(&self, pen: &mut Pen<'_>, prog: &dyn Compiled, b: &Built, links: [u32; 2]);
    /// What its drawing takes beyond its links' points at the position `p` (SI, its links'
    /// directions `dir`), at any μ_l: the marks drawn a fixed length from a point, each a
    /// point and its offset in mm (RPR: link j run on past its pin).
    fn drawn_past(&self, _p: &[DVec2], _dir: &[DVec2], _links: [u32; 2]) -> Vec<(DVec2, DVec2)> {
        Vec::new()
    }
    /// Solve it in closed form at the position held by `st` (its group `st.group`), its
    /// links `[i, j]`: its joint (RPR: its slide line) and its links' frames with their
    /// first and second derivatives with respect to φ₁. The analytic twin's own route: it
    /// shares primitives with [`GroupKind::construct`] but no decision, and neither calls
    /// the other (DESIGN §1). The twin's run calls it through [`PDyad::solve`], not through
    /// `dyn GroupKind`, and a kind marks it `#[inline(always)]`: it is the analytic kernel's
    /// inner loop.
    fn solve(&self, prog: &dyn Compiled, st: &mut State<'_>, links: [usize; 2]) -> Solved;
    /// Draw its two vector equations on the plan `bl` (steps named after `step`, its links
    /// `[i, j]`): the image of its joint (RPR, RPP: of the slider's coincident point), its
    /// links' rates and its relative motions.
    fn plan(&self, bl: &mut Builder<'_>, step: &str, links: [usize; 2]) -> Planned;
    /// The guide of the slider whose joint is `k`, when `k` is a piston (RRP's joint).
    fn piston(&self, _k: usize) -> Option<PGuide> {
        None
    }
}

/// A direction of the program used by point `k`.
fn dir_uses(d: PDir, k: usize) -> bool {
    matches!(d, PDir::Along { from, to, .. } if from == k || to == k)
}

/// A guide of the program built on point `k`.
fn guide_uses(g: PGuide, k: usize) -> bool {
    g.through == k || dir_uses(g.dir, k)
}

#[cfg(test)]
mod tests;
