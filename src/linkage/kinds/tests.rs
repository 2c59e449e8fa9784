//! The kinds behind their trait, and a toy kind showing where a new kind is added.

use super::{GroupKind, PDyad, Planned, Rpr, Rrr, Solved, Words};
use crate::construct::{ConstructionError, Context, Drafting, Item, Pick, Recorder, Role};
use crate::geom::DVec2;
use crate::linkage::analytic::state::State;
use crate::linkage::built::{heading, pick, Built, Frames};
use crate::linkage::compiled::Compiled;
use crate::linkage::model::{Branch, DyadKind};
use crate::linkage::pairs::GroupPairs;
use crate::linkage::pen::Pen;
use crate::linkage::plans::builder::Builder;
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
    let walk: Vec<DyadKind> = std::iter::successors(Some(DyadKind::Rrr), |&k| next(k)).collect();
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
        prog: &dyn Compiled,
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
    fn draw(&self, pen: &mut Pen<'_>, _: &dyn Compiled, b: &Built, [i, j]: [u32; 2]) {
        pen.link(i, b.p[self.a], b.p[self.joint]);
        pen.link(j, b.p[self.b], b.p[self.joint]);
        pen.joints.extend([self.a, self.b, self.joint]);
    }
    fn solve(&self, prog: &dyn Compiled, st: &mut State<'_>, links: [usize; 2]) -> Solved {
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
