//! The validated mechanism model: a crank plus class-II Assur groups (dyads) of the five kinds,
//! attached in order to known points and guides. All lengths in metres, angles in radians
//! (counter-clockwise from +x), the frame's y axis up.

use crate::geom::DVec2;

/// A named point fixed to the frame (a pivot, or a point a guide passes through).
#[derive(Debug, Clone, PartialEq)]
pub struct FixedPoint {
    /// The textbook letter (`A`, `C`, `O`).
    pub name: String,
    /// Position, m.
    pub at: DVec2,
}

/// Sense of rotation of the crank.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sense {
    /// Counter-clockwise (positive angles).
    CounterClockwise,
    /// Clockwise.
    Clockwise,
}

impl Sense {
    /// +1 for counter-clockwise, −1 for clockwise.
    pub fn sign(self) -> f64 {
        match self {
            Sense::CounterClockwise => 1.0,
            Sense::Clockwise => -1.0,
        }
    }

    /// The angle the crank turns through in this sense from `from` to `to`, radians in
    /// [0, 2π) (rem_euclid may round a travel a hair below 0 up to 2π itself: that is 0).
    pub fn travel(self, from: f64, to: f64) -> f64 {
        let travel = (self.sign() * (to - from)).rem_euclid(std::f64::consts::TAU);
        if travel >= std::f64::consts::TAU {
            0.0
        } else {
            travel
        }
    }
}

/// The driving link: a crank turning about a fixed pivot with constant angular speed.
#[derive(Debug, Clone, PartialEq)]
pub struct Crank {
    /// Link number (1 by convention).
    pub link: u32,
    /// Name of the fixed pivot (a [`FixedPoint`]).
    pub centre: String,
    /// Name of the crank pin.
    pub pin: String,
    /// Crank length, m (> 0).
    pub length: f64,
    /// |ω₁|, rad/s (> 0).
    pub omega: f64,
    /// Sense of rotation.
    pub sense: Sense,
}

/// A direction: fixed to the frame, or carried by a known link (the direction from one known
/// point to another, turned by `angle`).
#[derive(Debug, Clone, PartialEq)]
pub enum Dir {
    /// A frame direction, radians.
    Fixed(f64),
    /// The direction `from → to` turned counter-clockwise by `angle` radians.
    Along {
        /// Known point.
        from: String,
        /// Known point on the same link.
        to: String,
        /// Extra turn, radians.
        angle: f64,
    },
}

/// A guide line: through a known point along a direction, shifted `offset` m to its left.
#[derive(Debug, Clone, PartialEq)]
pub struct Guide {
    /// A known point of the link that carries the guide.
    pub through: String,
    /// Its direction.
    pub dir: Dir,
    /// Shift to the left of the direction, m.
    pub offset: f64,
    /// The link whose body carries the guide, as the scene names it (`link`); `None`: the
    /// one its points leave ([`carrier`](super::carrier::carrier)).
    pub link: Option<u32>,
}

/// Which of the two assemblies of a dyad to take at the first position; later positions
/// follow by continuity.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Branch {
    /// Left of the directed line between the two arc centres (RRR).
    Left,
    /// Right of that line (RRR).
    Right,
    /// Farther along the guide's direction (RRP).
    Forward,
    /// Farther back along the guide's direction (RRP).
    Backward,
}

/// The five kinds of class-II Assur groups, by their pairs outer–inner–outer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DyadKind {
    /// Kind 1, ВВВ.
    Rrr,
    /// Kind 2, ВВП.
    Rrp,
    /// Kind 3, ВПВ.
    Rpr,
    /// Kind 4, ПВП.
    Prp,
    /// Kind 5, ВПП.
    Rpp,
}

impl DyadKind {
    /// The kind number of the Russian/Ukrainian textbooks (вид 1…5).
    pub fn number(self) -> u32 {
        self.words().number
    }
    /// Latin pair letters (`RRP`).
    pub fn letters(self) -> &'static str {
        self.words().letters
    }
    /// Cyrillic pair letters (`ВВП`).
    pub fn letters_ru(self) -> &'static str {
        self.words().letters_ru
    }
    /// The pair letters as the sheets of `lang` write them: `RRP` in English, `ВВП`
    /// (вращательная, поступательная) in Russian, `ООП` (обертальна, поступальна) in
    /// Ukrainian.
    pub fn letters_in(self, lang: crate::scale::Lang) -> String {
        crate::words::pair_letters(self.letters(), self.letters_ru(), lang)
    }
}

/// The geometry of a dyad. Its two links are `i` (the first listed) and `j`.
#[derive(Debug, Clone, PartialEq)]
pub enum Dyad {
    /// Kind 1: link i pinned at known `a`, link j pinned at known `b`, pinned together at `joint`.
    Rrr {
        /// Known point of link i's outer pair.
        a: String,
        /// |a joint|, m.
        la: f64,
        /// Known point of link j's outer pair.
        b: String,
        /// |b joint|, m.
        lb: f64,
        /// The new joint.
        joint: String,
        /// Assembly at the first position (Left or Right of a → b).
        branch: Branch,
    },
    /// Kind 2: link i pinned at known `a` and at `joint`; slider j carries `joint` along `guide`.
    Rrp {
        /// Known point.
        a: String,
        /// |a joint|, m.
        la: f64,
        /// The line the joint moves on.
        guide: Guide,
        /// The new joint.
        joint: String,
        /// Assembly at the first position (Forward or Backward along the guide).
        branch: Branch,
    },
    /// Kind 3: block i pinned at known `a` slides along link j, which turns about known `c`;
    /// j's slide line passes at `offset` m to the left of `c` (0: through `c`).
    Rpr {
        /// Known point (the block's pin).
        a: String,
        /// Known pivot of link j.
        c: String,
        /// Offset of the slide line from `c`, m.
        offset: f64,
    },
    /// Kind 4: link i slides along `guide_i`, link j along `guide_j`; they are pinned at `joint`.
    Prp {
        /// Guide of link i (the line `joint` moves along relative to it).
        guide_i: Guide,
        /// Guide of link j.
        guide_j: Guide,
        /// The new joint.
        joint: String,
    },
    /// Kind 5: block i pinned at known `a` slides in link j along `slide`; link j translates
    /// along `guide`; `joint` is where the slide line through `a` meets the guide.
    Rpp {
        /// Known point (the block's pin).
        a: String,
        /// Direction of the inner sliding pair.
        slide: Dir,
        /// The guide of link j.
        guide: Guide,
        /// The new point on link j.
        joint: String,
    },
}

impl Dyad {
    /// The guides of the dyad, in the order of its pairs (RRP, RPP: the guide; PRP: i, j).
    pub fn guides(&self) -> [Option<&Guide>; 2] {
        match self {
            Dyad::Rrp { guide, .. } | Dyad::Rpp { guide, .. } => [Some(guide), None],
            Dyad::Prp {
                guide_i, guide_j, ..
            } => [Some(guide_i), Some(guide_j)],
            Dyad::Rrr { .. } | Dyad::Rpr { .. } => [None, None],
        }
    }

    /// The point the dyad creates, if any (RPR creates none).
    pub fn joint(&self) -> Option<&str> {
        match self {
            Dyad::Rrr { joint, .. }
            | Dyad::Rrp { joint, .. }
            | Dyad::Prp { joint, .. }
            | Dyad::Rpp { joint, .. } => Some(joint),
            Dyad::Rpr { .. } => None,
        }
    }

    /// The directions its links `[i, j]` keep when they translate: a slider's guide, an
    /// RPP block's slide; `None` for a link that turns whatever the directions are.
    pub fn link_dirs(&self) -> [Option<&Dir>; 2] {
        match self {
            Dyad::Rrr { .. } | Dyad::Rpr { .. } => [None, None],
            Dyad::Rrp { guide, .. } => [None, Some(&guide.dir)],
            Dyad::Prp {
                guide_i, guide_j, ..
            } => [Some(&guide_i.dir), Some(&guide_j.dir)],
            Dyad::Rpp { slide, guide, .. } => [Some(slide), Some(&guide.dir)],
        }
    }

    /// The outer pivot each of its links `[i, j]` has its frame start at, where it has one
    /// (RRR: a, b; RRP: a; RPR: a, c).
    pub fn origins(&self) -> [Option<&str>; 2] {
        match self {
            Dyad::Rrr { a, b, .. } => [Some(a), Some(b)],
            Dyad::Rrp { a, .. } => [Some(a), None],
            Dyad::Rpr { a, c, .. } => [Some(a), Some(c)],
            Dyad::Prp { .. } | Dyad::Rpp { .. } => [None, None],
        }
    }

    /// The link lengths it is given: (outer pivot, joint, length m) — RRR's two, RRP's one.
    pub fn lengths(&self) -> Vec<(&str, &str, f64)> {
        match self {
            Dyad::Rrr {
                a,
                la,
                b,
                lb,
                joint,
                ..
            } => vec![(a, joint, *la), (b, joint, *lb)],
            Dyad::Rrp { a, la, joint, .. } => vec![(a, joint, *la)],
            Dyad::Rpr { .. } | Dyad::Prp { .. } | Dyad::Rpp { .. } => Vec::new(),
        }
    }

    /// Its slide lines as given: the point each passes by and its offset from it, m (the
    /// guides' in the order of [`Dyad::guides`]; RPR's from its pivot c).
    pub fn slide_lines(&self) -> Vec<(&str, f64)> {
        match self {
            Dyad::Rpr { c, offset, .. } => vec![(c, *offset)],
            _ => self
                .guides()
                .into_iter()
                .flatten()
                .map(|g| (g.through.as_str(), g.offset))
                .collect(),
        }
    }

    /// The kind.
    pub fn kind(&self) -> DyadKind {
        match self {
            Dyad::Rrr { .. } => DyadKind::Rrr,
            Dyad::Rrp { .. } => DyadKind::Rrp,
            Dyad::Rpr { .. } => DyadKind::Rpr,
            Dyad::Prp { .. } => DyadKind::Prp,
            Dyad::Rpp { .. } => DyadKind::Rpp,
        }
    }
}

/// A further point of a moving link, in the link's frame: `along` the link's direction from
/// its origin and `across` to the left. Link frames: crank — origin at the centre, along the
/// pin; RRR — each link from its outer pivot toward the joint; RRP — link i from `a` to the
/// joint, slider j at the joint along the guide; RPR — both links along the slide line, i at
/// `a`, j at `c`; PRP — both at the joint along their guides; RPP — block i at `a` along the
/// slide, link j at the joint along the guide.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkPoint {
    /// Name (`D`, `S_3`).
    pub name: String,
    /// Link number.
    pub link: u32,
    /// Distance along the link frame, m.
    pub along: f64,
    /// Distance to the left, m.
    pub across: f64,
}

/// One Assur group of class II attached to the mechanism.
#[derive(Debug, Clone, PartialEq)]
pub struct Group {
    /// Link numbers i, j.
    pub links: [u32; 2],
    /// Geometry.
    pub dyad: Dyad,
}

/// A kinematic pair that repeats a constraint already imposed (a passive, redundant pair).
#[derive(Debug, Clone, PartialEq)]
pub struct RedundantPair {
    /// Its name (`E′`).
    pub name: String,
    /// Revolute (`false`) or prismatic (`true`).
    pub prismatic: bool,
    /// The two links it joins.
    pub links: [u32; 2],
    /// Why it is there (shown on the plate).
    pub reason: String,
}

/// What moves at the output: defines the extreme (dead) positions and the working stroke.
#[derive(Debug, Clone, PartialEq)]
pub enum Output {
    /// A rocker: the angle of link `link` (its frame direction).
    Rocker {
        /// Link number.
        link: u32,
    },
    /// A slider point moving along a frame direction.
    Slider {
        /// The point.
        point: String,
        /// Direction of travel, radians.
        dir: f64,
    },
}

/// A whole mechanism.
#[derive(Debug, Clone, PartialEq)]
pub struct Mechanism {
    /// Fixed points of the frame.
    pub fixed: Vec<FixedPoint>,
    /// The driving link.
    pub crank: Crank,
    /// Assur groups in order of attachment.
    pub groups: Vec<Group>,
    /// Further points of links (centres of mass, rocker ends).
    pub points: Vec<LinkPoint>,
    /// Redundant pairs, explained.
    pub redundant: Vec<RedundantPair>,
    /// The output whose extremes define the working stroke; the first one listed decides.
    pub outputs: Vec<Output>,
    /// The first output is a driving slider — an engine's piston, pushed by the gas of a
    /// `[[forces.indicator]]` — whose working (expansion) stroke begins at its outer dead
    /// centre; otherwise the working stroke is the slower one
    /// ([`super::Program::extremes`]).
    pub driving: bool,
}
