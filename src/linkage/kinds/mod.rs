//! The Assur group kinds, one file each (`rrr`, `rrp`, `rpr`, `prp`, `rpp`), behind one
//! trait, [`GroupKind`]: what the compiled program asks of a group — the point it creates,
//! its guides and frame directions, the links a point lies on, the points it is given, its
//! pairs for the force analysis, its pivots on the frame, its construction by compass, its
//! drawing, its twin's closed-form solve and its steps on the velocity and acceleration
//! plans — and its words in the scene ([`Words`]: the kind's number, its letters, the scene
//! keys of its table). A kind's data (the indices and lengths of its compiled group) is its
//! own struct; [`PDyad`] holds one of them and dispatches to it by a `match`
//! ([`PDyad::group`]; the twin's solve by [`PDyad::solve`], inlined into its run).
//!
//! The construction, the twin and the plans are separate routes in one file (DESIGN §1):
//! each decides by itself from the program, sharing primitives only (the recorder, the
//! jets, the plan builder); none calls another. RPR, whose pin may pass through its pivot,
//! has a room beside its file (`rpr/`): each route's answer to that case is a file.
//! What still matches on the kind elsewhere: the model's `Dyad` and its readers (the
//! compilation in `program.rs`, the scene's validation, the structure, the data table, the
//! note) and the force analysis (`GroupPairs`).

mod prp;
mod rpp;
mod rpr;
mod rrp;
mod rrr;

pub(in crate::linkage) use prp::Prp;
pub(in crate::linkage) use rpp::Rpp;
pub(in crate::linkage) use rpr::Rpr;
pub(in crate::linkage) use rrp::Rrp;
pub(in crate::linkage) use rrr::Rrr;

use super::analytic::{State, Unassembled};
use super::construction::{Built, Frames};
use super::groups::GroupPairs;
use super::model::DyadKind;
use super::plans::Builder;
use super::positions_draw::Pen;
use super::program::Program;
use super::program::{PDir, PGuide};
use crate::construct::{ConstructionError, Recorder};

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
        prog: &Program,
        rec: &mut Recorder,
        pos: &mut Built,
        prev: Option<&Built>,
        step: (&str, usize),
    ) -> Result<Frames, ConstructionError>;
    /// Draw its links `[i, j]` at the constructed position `b` with `pen` (a link's number
    /// at its anchor, its joints to be drawn).
    fn draw(&self, pen: &mut Pen<'_>, prog: &Program, b: &Built, links: [u32; 2]);
    /// Solve it in closed form at the position held by `st` (its group `st.group`), its
    /// links `[i, j]`: its joint (RPR: its slide line) and its links' frames with their
    /// first and second derivatives with respect to φ₁. The analytic twin's own route: it
    /// shares primitives with [`GroupKind::construct`] but no decision, and neither calls
    /// the other (DESIGN §1). The twin's run calls it through [`PDyad::solve`], not through
    /// `dyn GroupKind`, and a kind marks it `#[inline(always)]`: it is the analytic kernel's
    /// inner loop.
    fn solve(&self, prog: &Program, st: &mut State<'_>, links: [usize; 2]) -> Solved;
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
        prog: &Program,
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

#[cfg(test)]
mod tests {
    use super::{GroupKind, PDyad, Planned, Rpr, Rrr, Solved, Words};
    use crate::construct::{ConstructionError, Context, Drafting, Item, Pick, Recorder, Role};
    use crate::geom::DVec2;
    use crate::linkage::analytic::State;
    use crate::linkage::construction::{heading, pick, Built, Frames};
    use crate::linkage::groups::GroupPairs;
    use crate::linkage::model::{Branch, DyadKind};
    use crate::linkage::plans::Builder;
    use crate::linkage::positions_draw::Pen;
    use crate::linkage::program::Program;
    use crate::scale::{Quantity, Scale};

    /// The kind after `k`, by an exhaustive `match`: a new kind does not compile until it is
    /// put in the walk, and then [`DyadKind::ALL`] is held against it.
    fn next(k: DyadKind) -> Option<DyadKind> {
        match k {
            DyadKind::Rrr => Some(DyadKind::Rrp),
            DyadKind::Rrp => Some(DyadKind::Rpr),
            DyadKind::Rpr => Some(DyadKind::Prp),
            DyadKind::Prp => Some(DyadKind::Rpp),
            DyadKind::Rpp => None,
        }
    }

    #[test]
    fn every_kind_is_listed_once_with_words_of_its_own() {
        let walk: Vec<DyadKind> =
            std::iter::successors(Some(DyadKind::Rrr), |&k| next(k)).collect();
        assert_eq!(walk, DyadKind::ALL);
        let words: Vec<&Words> = walk.iter().map(|k| k.words()).collect();
        for (n, w) in words.iter().enumerate() {
            assert_eq!(w.number as usize, n + 1);
            assert_eq!(w.letters.chars().count(), 3);
            assert_eq!(w.keys.first(), Some(&"links"));
            let others = &words[..n];
            assert!(others
                .iter()
                .all(|o| o.letters != w.letters && o.letters_ru != w.letters_ru));
        }
        assert_eq!(DyadKind::Rpp.letters_ru(), "ВПП");
        // Ukrainian sheets name the pairs обертальна (О) and поступальна (П).
        use crate::scale::Lang;
        assert_eq!(DyadKind::Rrp.letters_in(Lang::Uk), "ООП");
        assert_eq!(DyadKind::Prp.letters_in(Lang::Uk), "ПОП");
        assert_eq!(DyadKind::Rrp.letters_in(Lang::En), "RRP");
    }

    #[test]
    fn a_group_answers_through_its_kind() {
        let rpr = PDyad::Rpr(Rpr {
            a: 4,
            c: 1,
            offset: 0.0,
        });
        assert_eq!(rpr.kind(), DyadKind::Rpr);
        assert_eq!(rpr.joint(), None);
        assert_eq!(rpr.group().on_links(4), [true, false]);
        assert_eq!(rpr.group().on_links(1), [false, true]);
        assert!(rpr.group().uses(1) && !rpr.group().uses(2));
        assert_eq!(rpr.guides(), [None, None]);
    }

    /// A toy kind, written in test code as a new kind is written in its file: two links
    /// pinned at the known `a` and `b` and jointed at the new point, whose compass arcs the
    /// toy sets with its own radii. Its struct and its `GroupKind` are all of its behaviour
    /// (its construction and drawing its own; its twin's solve and its plan steps borrowed
    /// from the RRR group of the same radii, since the toy is one); registering it as a
    /// kind of the scene also takes a `DyadKind` variant (its `words` arm and its file's
    /// `WORDS`), a `PDyad` variant (its `group`, `group_mut` and `solve` arms), a model
    /// `Dyad` variant with its compilation (`program.rs`), its `GroupPairs` and force
    /// method (`forces/twin.rs`, `forces/polygons/`) and its table in the scene
    /// (`scene/groups.rs`).
    struct Toy {
        a: usize,
        b: usize,
        joint: usize,
        radii: [f64; 2],
    }

    impl GroupKind for Toy {
        fn kind(&self) -> DyadKind {
            DyadKind::Rrr
        }
        fn joint(&self) -> Option<usize> {
            Some(self.joint)
        }
        fn on_links(&self, k: usize) -> [bool; 2] {
            [
                k == self.a || k == self.joint,
                k == self.b || k == self.joint,
            ]
        }
        fn uses(&self, k: usize) -> bool {
            k == self.a || k == self.b
        }
        fn pivots(&self) -> Vec<usize> {
            vec![self.a, self.b]
        }
        fn pairs(&self) -> GroupPairs {
            GroupPairs::Rrr {
                a: self.a,
                c: self.b,
                joint: self.joint,
            }
        }
        fn construct(
            &self,
            prog: &Program,
            rec: &mut Recorder,
            pos: &mut Built,
            prev: Option<&Built>,
            (s, _): (&str, usize),
        ) -> Result<Frames, ConstructionError> {
            let mu = rec.scale().value();
            let ca = prog.compass(&pos.p, self.a, self.radii[0] / mu);
            let cb = prog.compass(&pos.p, self.b, self.radii[1] / mu);
            let step = prog.joint_step(s, self.joint);
            let met = rec.meet_circles(&step, ca, cb, pick(prev, self.joint, Pick::Left))?;
            let (x, crossing) = pos.place(self.joint, met);
            Ok(Frames {
                angle: [heading(x - pos.p[self.a]), heading(x - pos.p[self.b])],
                origin: [self.a, self.b],
                crossing,
            })
        }
        fn draw(&self, pen: &mut Pen<'_>, _: &Program, b: &Built, [i, j]: [u32; 2]) {
            pen.link(i, b.p[self.a], b.p[self.joint]);
            pen.link(j, b.p[self.b], b.p[self.joint]);
            pen.joints.extend([self.a, self.b, self.joint]);
        }
        fn solve(&self, prog: &Program, st: &mut State<'_>, links: [usize; 2]) -> Solved {
            self.as_rrr().solve(prog, st, links)
        }
        fn plan(&self, bl: &mut Builder<'_>, step: &str, links: [usize; 2]) -> Planned {
            self.as_rrr().plan(bl, step, links)
        }
    }

    impl Toy {
        /// The RRR group of the toy's radii.
        fn as_rrr(&self) -> Rrr {
            Rrr {
                a: self.a,
                la: self.radii[0],
                b: self.b,
                lb: self.radii[1],
                joint: self.joint,
                branch: Branch::Left,
            }
        }
    }

    /// A frame with the pivots A (0, 0) and B (5 mm, 0), a crank pin P and room for C.
    fn frame() -> (Program, Built) {
        let names = ["A", "B", "P", "C"].map(String::from).to_vec();
        let prog = Program {
            names,
            fixed: vec![DVec2::ZERO, DVec2::new(0.005, 0.0)],
            centre: 0,
            pin: 2,
            crank_length: 0.001,
            crank_link: 1,
            ops: Vec::new(),
            link_count: 4,
            fixed_dirs: Vec::new(),
        };
        let built = Built {
            phi: 0.0,
            p: vec![DVec2::ZERO, DVec2::new(5.0, 0.0), DVec2::X, DVec2::ZERO],
            angle: vec![0.0; 4],
            origin: vec![0; 4],
            crossing: Vec::new(),
            step: vec![None; 4],
        };
        (prog, built)
    }

    fn recorder() -> Recorder {
        let ctx = Context::for_model_size(300.0, Drafting::EXACT).expect("a context");
        let mu = Scale::new(0.001, Quantity::Length).expect("μ_l");
        Recorder::in_context("toy", mu, &ctx)
    }

    #[test]
    fn a_toy_kind_is_constructed_and_drawn_through_the_trait() {
        let toy = Toy {
            a: 0,
            b: 1,
            joint: 3,
            radii: [0.003, 0.004],
        };
        let rrr = PDyad::Rrr(Rrr {
            a: 0,
            la: 0.003,
            b: 1,
            lb: 0.004,
            joint: 3,
            branch: Branch::Left,
        });
        let mut joints = Vec::new();
        for group in [&toy as &dyn GroupKind, rrr.group()] {
            let (prog, mut pos) = frame();
            let mut rec = recorder();
            let frames = group
                .construct(&prog, &mut rec, &mut pos, None, ("group 1", 3))
                .expect("the arcs meet");
            // The 3-4-5 triangle on AB = 5 mm: C at (1.8, 2.4) mm, a right angle at C.
            assert!((pos.p[3] - DVec2::new(1.8, 2.4)).length() < 1e-12);
            assert!((frames.angle[0] - (2.4f64).atan2(1.8)).abs() < 1e-12);
            assert!((frames.crossing - std::f64::consts::FRAC_PI_2).abs() < 1e-9);
            assert_eq!(frames.origin, [0, 1]);
            let mut pen = Pen {
                rec: &mut rec,
                role: Role::Given,
                note: "toy",
                anchors: Vec::new(),
                joints: Vec::new(),
                rigid: Vec::new(),
                clear: &[],
            };
            group.draw(&mut pen, &prog, &pos, [2, 3]);
            joints.push(pen.joints.clone());
            let links = rec
                .steps()
                .iter()
                .filter(|s| matches!(s.item, Item::Segment(_)))
                .count();
            assert_eq!(links, 2);
            assert_eq!(group.on_links(3), [true, true]);
            assert_eq!(group.pivots(), vec![0, 1]);
        }
        assert_eq!(joints[0], joints[1]);
    }
}
