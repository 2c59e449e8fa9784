//! The equilibrium check that shares nothing with the solve: every moving body's own
//! equations — ΣF = m·a_S and ΣM_S = I_S·ε (d'Alembert) — and the power balance
//! Σ F·v + Σ M·ω = 0 of the loads with the balancing moment (or force) a route reports,
//! evaluated on the check's own picture of the mechanism and with its own motion:
//!
//! - which bodies meet where, which body a guide belongs to, which bodies slide on which:
//!   read again from the scene's text ([`picture`]);
//! - the velocities and accelerations: solved again from that picture's constraints with the
//!   positions alone ([`motion`]), never the plans' or the twin's;
//! - which body a load acts on, where a resistance points, the friction in the pairs from the
//!   reported reactions, the tooth force on its flank: decided here again.
//!
//! A route's reaction is taken at its word for its size, but must act on a pair the picture
//! has (a revolute pair at a point both bodies hold, a prismatic pair between a slider and the
//! body it slides on) and, in a prismatic pair, across the line. A wrong decision made once and
//! consumed by both the polygons and the linear solve (a load on the wrong link, a guide
//! turning with the wrong body) leaves their rows equal, but not these residuals.
//!
//! Only pure facts of the scene's data are shared with the solve, never a decision:
//! [`ForceSpec::weight`] (m·g along gravity), [`ForceSpec::acting`] (the resistances that act
//! on a position's stroke), the indicator's pressure law and the gear's line of action.

mod balance;
mod motion;
mod picture;

use super::loads::{Phase, PositionMotion};
use super::pair_friction::PairFriction;
use super::spec::{Action, Drive, ForceSpec};
use super::twin::{line_of_action, PairKind, Reaction};
use crate::geom::DVec2;
use crate::linkage::{Mechanism, Program};
use balance::{Balance, Term};
use motion::Screws;
use picture::Picture;

/// What a route reports of one position: its reactions, its balancing moment and (gear
/// drive) the magnitude of its balancing force.
#[derive(Debug, Clone, Copy)]
pub struct Reported<'a> {
    /// Every reaction, acting on its pair's `to` link.
    pub reactions: &'a [Reaction],
    /// The balancing moment on the crank, N·m.
    pub m_bal: f64,
    /// The balancing force's magnitude (gear drive), N.
    pub f_bal: Option<f64>,
}

/// The position as the route drew it: its points, its links' frame directions (where a
/// route's prismatic reaction acts is measured along its sliding link's frame), the crank's
/// rate and the stroke.
#[derive(Debug, Clone, Copy)]
pub struct State<'a> {
    /// The route's motion; the check takes its positions only.
    pub motion: &'a PositionMotion,
    /// Unit frame direction of every link, by link number, as the route knew it.
    pub dir: &'a [DVec2],
    /// ω₁, rad/s, counter-clockwise positive.
    pub w1: f64,
    /// The stroke.
    pub phase: Phase,
}

/// The two residuals of a route at one position, each relative: 0 for an exact equilibrium,
/// ~1e-15 in f64, and 1 where the check cannot set up its own equations (a toggle, a scene
/// whose guide is not to be told).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Residuals {
    /// The worst of every body's ΣF − m·a_S (to the largest force) and ΣM − I_S·ε (to the
    /// largest moment), and of a reaction on a pair the picture lacks or along a guide.
    pub equilibrium: f64,
    /// Σ P·v + Σ M·ω of the loads, inertia, friction and the balancing load, to the sum of
    /// the powers' magnitudes.
    pub power: f64,
}

impl Residuals {
    /// The check could not be made.
    const UNSET: Residuals = Residuals {
        equilibrium: 1.0,
        power: 1.0,
    };
}

/// The check's view of a position: its picture, the positions and its own motion.
struct Scene<'a> {
    pic: Picture,
    prog: &'a Program,
    state: &'a State<'a>,
    screws: Screws,
}

impl Scene<'_> {
    /// The position of named point `name`.
    fn at(&self, name: &str) -> Option<DVec2> {
        let k = self.prog.index(name)?;
        self.state.motion.p.get(k).copied()
    }
    /// The position of the route's point `k`.
    fn at_index(&self, k: usize) -> DVec2 {
        self.state.motion.p.get(k).copied().unwrap_or(DVec2::ZERO)
    }
    /// The name of the route's point `k`.
    fn name(&self, k: usize) -> &str {
        self.prog.names.get(k).map_or("", String::as_str)
    }
    /// The speed of every named point of a moving body.
    fn speeds(&self) -> Vec<f64> {
        self.pic
            .points
            .iter()
            .filter_map(|(name, bodies)| {
                let b = bodies.iter().copied().find(|&b| b != 0)?;
                Some(self.screws.v(b, self.at(name)?).length())
            })
            .collect()
    }
    /// The body a load at point `name` acts on when the scene names none: the only moving
    /// body there, else the one slider among the bodies pinned there (the textbooks' ram,
    /// piston, block), else none.
    fn loaded(&self, name: &str) -> Option<u32> {
        let here: Vec<u32> = self
            .pic
            .on(name)
            .iter()
            .copied()
            .filter(|&b| b != 0)
            .collect();
        if let [b] = here[..] {
            return Some(b);
        }
        let mut sliding = here.iter().copied().filter(|&b| self.pic.is_slider(b));
        match (sliding.next(), sliding.next()) {
            (Some(b), None) => Some(b),
            _ => None,
        }
    }
}

/// The residuals of a route's report at one position of `mech` (the scene's mechanism;
/// `prog` only names its points).
pub fn residual(
    spec: &ForceSpec,
    mech: &Mechanism,
    prog: &Program,
    state: &State<'_>,
    reported: &Reported<'_>,
    friction: Option<&PairFriction>,
) -> Residuals {
    let Some(pic) = Picture::of(mech) else {
        return Residuals::UNSET;
    };
    let at = |name: &str| {
        prog.index(name)
            .and_then(|k| state.motion.p.get(k).copied())
    };
    let Some(screws) = motion::solve(&pic, &at, state.w1) else {
        return Residuals::UNSET;
    };
    let sc = Scene {
        pic,
        prog,
        state,
        screws,
    };
    let mut b = Balance::default();
    weights(spec, &sc, &mut b);
    resistances(spec, &sc, &mut b);
    gas_forces(spec, &sc, &mut b);
    reactions(&sc, reported, &mut b);
    if let Some(fr) = friction {
        friction_terms(&sc, reported, fr, &mut b);
    }
    drive(spec, &sc, reported, &mut b);
    inertia(spec, &sc, &mut b);
    let o = sc.at(&sc.pic.crank.1).unwrap_or(DVec2::ZERO);
    Residuals {
        equilibrium: b.equilibrium(&sc.pic.bodies, o, &state.motion.p),
        power: b.power(&sc.screws),
    }
}

/// The weights at the centres of mass.
fn weights(spec: &ForceSpec, sc: &Scene<'_>, b: &mut Balance) {
    for lm in &spec.links {
        if let Some(s) = sc.at(&lm.centre) {
            b.load(Term::force(lm.link, spec.weight(lm.mass), s));
        }
    }
}

/// The working resistances: forces on their body (the scene's, else [`Scene::loaded`]),
/// against the point's velocity where no direction is given; moments against ω.
fn resistances(spec: &ForceSpec, sc: &Scene<'_>, b: &mut Balance) {
    for r in spec.acting(sc.state.phase) {
        match &r.action {
            Action::Force {
                point,
                link,
                magnitude,
                dir,
            } => {
                let (Some(x), Some(l)) = (sc.at(point), link.or_else(|| sc.loaded(point))) else {
                    continue;
                };
                let e = match dir {
                    Some(a) => DVec2::from_angle(*a),
                    None => (-sc.screws.v(l, x)).normalize_or_zero(),
                };
                b.load(Term::force(l, e * *magnitude, x));
            }
            Action::Moment { link, magnitude } => {
                let w = sc.screws.omega(*link);
                if w != 0.0 {
                    b.load(Term::couple(*link, -w.signum() * magnitude));
                }
            }
        }
    }
}

/// The gas forces of the indicator diagrams, on the piston at their point.
fn gas_forces(spec: &ForceSpec, sc: &Scene<'_>, b: &mut Balance) {
    for ind in &spec.indicators {
        let (Ok(Some(load)), Some(x)) = (ind.load(sc.prog, sc.state.motion), sc.at(&ind.point))
        else {
            continue;
        };
        if let Some(l) = sc.loaded(&ind.point) {
            b.load(Term::force(l, load.force, x));
        }
    }
}

/// The reactions, on `to` and (the opposite) on `from`, each on a pair the picture must have:
/// a revolute pair at a point both bodies hold, a prismatic pair between the two bodies with
/// the reaction across its line.
fn reactions(sc: &Scene<'_>, reported: &Reported<'_>, b: &mut Balance) {
    for r in reported.reactions {
        let (from, to) = (r.pair.from as u32, r.pair.to as u32);
        let x = match r.pair.kind {
            PairKind::Revolute(k) => {
                let on = sc.pic.on(sc.name(k));
                if !(on.contains(&from) && on.contains(&to)) {
                    b.stray(r.force.length());
                }
                sc.at_index(k)
            }
            PairKind::Prismatic {
                reference,
                dir_link,
            } => {
                let u = sc
                    .pic
                    .slide_between(from, to)
                    .and_then(|s| s.line.direction(&|n: &str| sc.at(n)));
                match u {
                    Some(u) => b.stray(r.force.dot(u).abs()),
                    None => b.stray(r.force.length()),
                }
                let along = sc.state.dir.get(dir_link).copied().unwrap_or(DVec2::ZERO);
                sc.at_index(reference) + along * r.offset.unwrap_or(0.0)
            }
        };
        b.reaction(Term::force(to, r.force, x));
        b.reaction(Term::force(from, -r.force, x));
    }
}

/// Friction in the pairs, from the reported reactions and the check's own motion: a couple
/// against the relative rotation in a revolute pair, a force against the relative sliding
/// along the line in a prismatic one.
fn friction_terms(sc: &Scene<'_>, reported: &Reported<'_>, fr: &PairFriction, b: &mut Balance) {
    let s = &sc.screws;
    let speeds = sc.speeds();
    let rates: Vec<f64> = sc.pic.bodies.iter().map(|&l| s.omega(l)).collect();
    for r in reported.reactions {
        let (from, to) = (r.pair.from as u32, r.pair.to as u32);
        let size = r.force.length();
        match r.pair.kind {
            PairKind::Revolute(k) => {
                let w_rel = s.omega(to) - s.omega(from);
                if at_rest(w_rel, &rates) {
                    continue;
                }
                let radius = fr
                    .radii
                    .iter()
                    .find(|(name, _)| name == sc.name(k))
                    .map_or(fr.radius, |(_, r)| *r);
                let c = -w_rel.signum() * fr.f * radius * size;
                b.load(Term::couple(to, c));
                b.load(Term::couple(from, -c));
            }
            PairKind::Prismatic {
                reference,
                dir_link,
            } => {
                let Some(u) = sc
                    .pic
                    .slide_between(from, to)
                    .and_then(|sl| sl.line.direction(&|n: &str| sc.at(n)))
                else {
                    continue;
                };
                let along = sc.state.dir.get(dir_link).copied().unwrap_or(DVec2::ZERO);
                let x = sc.at_index(reference) + along * r.offset.unwrap_or(0.0);
                let v_rel = (s.v(to, x) - s.v(from, x)).dot(u);
                if at_rest(v_rel, &speeds) {
                    continue;
                }
                let f = u * (-v_rel.signum() * fr.f * size);
                b.load(Term::force(to, f, x));
                b.load(Term::force(from, -f, x));
            }
        }
    }
}

/// The drive on the crank: the balancing force on its line of action (gear drive), else the
/// balancing moment.
fn drive(spec: &ForceSpec, sc: &Scene<'_>, reported: &Reported<'_>, b: &mut Balance) {
    let crank = sc.pic.crank.0;
    let o = sc.at(&sc.pic.crank.1).unwrap_or(DVec2::ZERO);
    match (&spec.drive, reported.f_bal) {
        (Drive::Gear(g), Some(f)) => {
            let turn = if reported.m_bal == 0.0 {
                sc.state.w1.signum()
            } else {
                reported.m_bal.signum()
            };
            let (p, d) = line_of_action(o, g.radius(), g.towards, g.pressure_angle, turn);
            b.load(Term::force(crank, d * f, p));
        }
        _ => b.load(Term::couple(crank, reported.m_bal)),
    }
}

/// The inertia from the check's own motion: m·a_S at the centre of mass and I_S·ε.
fn inertia(spec: &ForceSpec, sc: &Scene<'_>, b: &mut Balance) {
    for lm in &spec.links {
        if let Some(s) = sc.at(&lm.centre) {
            let l = lm.link;
            b.inertia(Term {
                link: l,
                force: sc.screws.a(l, s) * lm.mass,
                at: s,
                moment: lm.inertia * sc.screws.eps(l),
            });
        }
    }
}

/// A relative rate that rounding cannot tell from rest (1e-9 of the largest of `of`).
fn at_rest(rate: f64, of: &[f64]) -> bool {
    let big = of.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    rate.abs() <= 1e-9 * big
}
