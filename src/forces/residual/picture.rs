//! The equilibrium check's own picture of the mechanism, read from the scene's text alone
//! ([`Mechanism`]): which bodies hold each named point (every body pinned there), and which
//! bodies slide on which (each prismatic pair with its line). Nothing here comes from the
//! compiled program: a guide is carried by the link the scene names, else by the one body its
//! points lie on, read here again, so that a carrier the solve got wrong shows in the check.

use crate::geom::DVec2;
use crate::linkage::{Dir, Dyad, Guide, Mechanism};

/// The line a prismatic pair slides along, as the scene gives it.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Line {
    /// A guide `{ through, dir, offset }`.
    Guide(Guide),
    /// An RPR group's slot: through the block's pin `a`, passing `offset` to the left of the
    /// slotted link's pivot `c`.
    Slot {
        /// The block's pin.
        a: String,
        /// The slotted link's pivot.
        c: String,
        /// The offset, m.
        offset: f64,
    },
    /// An RPP group's slide: through the block's pin along a direction.
    Slide(Dir),
}

/// A prismatic pair: body `slider` slides on body `on` (0 the frame) along `line`; `at` is a
/// point of the slider on the line.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Slide {
    /// The sliding body.
    pub slider: u32,
    /// The body it slides on.
    pub on: u32,
    /// The line.
    pub line: Line,
    /// A point of the slider on the line.
    pub at: String,
}

/// The bodies and pairs of a mechanism as its scene writes them.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Picture {
    /// The crank's link and its centre.
    pub crank: (u32, String),
    /// The moving bodies, the crank first.
    pub bodies: Vec<u32>,
    /// Every named point with the bodies that hold it (0 the frame), in the order they came.
    pub points: Vec<(String, Vec<u32>)>,
    /// The prismatic pairs.
    pub slides: Vec<Slide>,
}

impl Picture {
    /// The picture of `m`; `None` where a guide's carrier is not to be told from the text (a
    /// scene validator refuses such a guide before any analysis).
    pub fn of(m: &Mechanism) -> Option<Self> {
        let c = &m.crank;
        let mut p = Picture {
            crank: (c.link, c.centre.clone()),
            bodies: vec![c.link],
            points: Vec::new(),
            slides: Vec::new(),
        };
        for f in &m.fixed {
            p.hold(&f.name, 0);
        }
        p.hold(&c.centre, c.link);
        p.hold(&c.pin, c.link);
        p.place_points(m, c.link);
        for g in &m.groups {
            let [i, j] = g.links;
            match &g.dyad {
                Dyad::Rrr { a, b, joint, .. } => {
                    p.hold_all(&[(a, i), (b, j), (joint, i), (joint, j)]);
                }
                Dyad::Rrp {
                    a, guide, joint, ..
                } => {
                    let on = p.carrier(guide)?;
                    p.hold_all(&[(a, i), (joint, i), (joint, j)]);
                    p.slide(j, on, Line::Guide(guide.clone()), joint);
                }
                Dyad::Rpr { a, c, offset } => {
                    p.hold_all(&[(a, i), (c, j)]);
                    let slot = Line::Slot {
                        a: a.clone(),
                        c: c.clone(),
                        offset: *offset,
                    };
                    p.slide(i, j, slot, a);
                }
                Dyad::Prp {
                    guide_i,
                    guide_j,
                    joint,
                } => {
                    let (on_i, on_j) = (p.carrier(guide_i)?, p.carrier(guide_j)?);
                    p.hold_all(&[(joint, i), (joint, j)]);
                    p.slide(i, on_i, Line::Guide(guide_i.clone()), joint);
                    p.slide(j, on_j, Line::Guide(guide_j.clone()), joint);
                }
                Dyad::Rpp {
                    a,
                    slide,
                    guide,
                    joint,
                } => {
                    let on = p.carrier(guide)?;
                    p.hold_all(&[(a, i), (joint, j)]);
                    p.slide(i, j, Line::Slide(slide.clone()), a);
                    p.slide(j, on, Line::Guide(guide.clone()), joint);
                }
            }
            p.bodies.extend(g.links);
            for l in g.links {
                p.place_points(m, l);
            }
        }
        Some(p)
    }

    /// The bodies that hold point `name` (none for a name the scene does not give).
    pub fn on(&self, name: &str) -> &[u32] {
        self.points
            .iter()
            .find(|(n, _)| n == name)
            .map_or(&[], |(_, b)| b.as_slice())
    }

    /// Every revolute pair: a point with the first body that holds it and each further one.
    pub fn pins(&self) -> impl Iterator<Item = (&str, u32, u32)> + '_ {
        self.points.iter().flat_map(|(name, bodies)| {
            let first = bodies.first().copied().unwrap_or(0);
            bodies
                .iter()
                .skip(1)
                .map(move |&b| (name.as_str(), first, b))
        })
    }

    /// The bodies that slide: the block of an RRP or RPR group, both links of a PRP or RPP.
    pub fn is_slider(&self, body: u32) -> bool {
        self.slides.iter().any(|s| s.slider == body)
    }

    /// The prismatic pair between two bodies, either way round.
    pub fn slide_between(&self, a: u32, b: u32) -> Option<&Slide> {
        self.slides
            .iter()
            .find(|s| (s.slider, s.on) == (a, b) || (s.slider, s.on) == (b, a))
    }

    /// Body `body` holds point `name`.
    fn hold(&mut self, name: &str, body: u32) {
        match self.points.iter_mut().find(|(n, _)| n == name) {
            Some((_, bodies)) if bodies.contains(&body) => {}
            Some((_, bodies)) => bodies.push(body),
            None => self.points.push((name.to_string(), vec![body])),
        }
    }

    fn hold_all(&mut self, held: &[(&String, u32)]) {
        for (name, body) in held {
            self.hold(name, *body);
        }
    }

    fn slide(&mut self, slider: u32, on: u32, line: Line, at: &str) {
        self.slides.push(Slide {
            slider,
            on,
            line,
            at: at.to_string(),
        });
    }

    /// The further points the scene puts on link `link`.
    fn place_points(&mut self, m: &Mechanism, link: u32) {
        for pt in m.points.iter().filter(|pt| pt.link == link) {
            self.hold(&pt.name, link);
        }
    }

    /// The body that carries a guide, read from the text: the link the scene names; else for
    /// a frame direction the frame at a fixed point and the one moving body at a moving
    /// point, for a direction along two points the one moving body that holds both (the
    /// frame when only it does).
    fn carrier(&self, g: &Guide) -> Option<u32> {
        if let Some(l) = g.link {
            return Some(l);
        }
        let holding: Vec<u32> = match &g.dir {
            Dir::Fixed(_) if self.on(&g.through).contains(&0) => return Some(0),
            Dir::Fixed(_) => self.on(&g.through).to_vec(),
            Dir::Along { from, to, .. } => {
                let b = self.on(to);
                self.on(from)
                    .iter()
                    .copied()
                    .filter(|l| b.contains(l))
                    .collect()
            }
        };
        let moving: Vec<u32> = holding.iter().copied().filter(|&l| l != 0).collect();
        match moving[..] {
            [l] => Some(l),
            [] if holding.contains(&0) => Some(0),
            _ => None,
        }
    }
}

impl Line {
    /// The unit direction of the line with the points at `at` (`None` where a point is
    /// missing or the direction degenerates).
    pub fn direction(&self, at: &impl Fn(&str) -> Option<DVec2>) -> Option<DVec2> {
        let along = |d: &Dir| -> Option<DVec2> {
            match d {
                Dir::Fixed(angle) => Some(DVec2::from_angle(*angle)),
                Dir::Along { from, to, angle } => {
                    let e = (at(to)? - at(from)?).try_normalize()?;
                    Some(DVec2::from_angle(*angle).rotate(e))
                }
            }
        };
        match self {
            Line::Guide(g) => along(&g.dir),
            Line::Slide(d) => along(d),
            Line::Slot { a, c, offset } => {
                // The line through a whose left normal n has (a − c)·n = offset: with
                // w = a − c, u = (t·w − offset·w⊥) / |w|², t = √(|w|² − offset²).
                let w = at(a)? - at(c)?;
                let t = (w.length_squared() - offset * offset).max(0.0).sqrt();
                (w * t - w.perp() * *offset).try_normalize()
            }
        }
    }
}
