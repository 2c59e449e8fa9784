//! The equilibrium check that shares nothing with the solve: every moving link's own
//! equations — ΣF = m·a_S and ΣM_S = I_S·ε (d'Alembert) — evaluated from the loads as the
//! scene declares them and the reactions, balancing moment and balancing force a route
//! reports. The loads are read here again from the scene: which link a load acts on, the
//! friction in the pairs from the reported reactions, the tooth force on its flank. A wrong
//! decision made once and consumed by both the polygons and the linear solve (a load put on
//! the wrong link) leaves their rows equal, but not this residual.
//!
//! Only pure facts of the scene's data are shared with the solve, never a decision:
//! [`ForceSpec::weight`] (m·g along gravity) and [`ForceSpec::acting`] (the resistances that
//! act on a position's stroke).

use super::loads::{Motion, Phase};
use super::pair_friction::PairFriction;
use super::spec::{Action, Drive, ForceSpec};
use super::twin::{line_of_action, PairKind, Reaction};
use crate::geom::DVec2;
use crate::linkage::Program;

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

/// The motion of the position as the route knew it, with the links' frame directions (a
/// prismatic pair's point of application is measured along its sliding link's direction).
#[derive(Debug, Clone, Copy)]
pub struct State<'a> {
    /// The motion, SI.
    pub motion: &'a Motion,
    /// Unit frame direction of every link, by link number.
    pub dir: &'a [DVec2],
    /// The crank's sense of rotation, +1 counter-clockwise.
    pub sense: f64,
    /// The stroke.
    pub phase: Phase,
}

/// One term of a link's equations: a force at a point, or a couple.
struct Term {
    link: usize,
    force: DVec2,
    at: DVec2,
    moment: f64,
}

impl Term {
    /// A force at a point.
    fn force(link: usize, force: DVec2, at: DVec2) -> Self {
        Term {
            link,
            force,
            at,
            moment: 0.0,
        }
    }
}

/// The position of point `k` (the origin where the motion gives none).
fn at(m: &Motion, k: usize) -> DVec2 {
    m.p.get(k).copied().unwrap_or(DVec2::ZERO)
}

/// The largest residual of the moving links' equations of motion, relative to the largest
/// force (the moment equations to the largest force times the mechanism's size): 0 for an
/// exact equilibrium, ~1e-16 in f64.
pub fn residual(
    spec: &ForceSpec,
    prog: &Program,
    state: &State<'_>,
    reported: &Reported<'_>,
    friction: Option<&PairFriction>,
) -> f64 {
    let m = state.motion;
    let mut terms: Vec<Term> = Vec::new();
    let mut couples: Vec<(usize, f64)> = Vec::new();
    weights(spec, prog, m, &mut terms);
    resistances(spec, prog, state, &mut terms, &mut couples);
    gas_forces(spec, prog, m, &mut terms);
    reactions(state, reported, &mut terms);
    if let Some(fr) = friction {
        friction_terms(prog, state, reported, fr, &mut terms, &mut couples);
    }
    drive(spec, prog, state, reported, &mut terms, &mut couples);
    let o = at(m, prog.centre);
    for (link, moment) in couples {
        terms.push(Term {
            link,
            force: DVec2::ZERO,
            at: o,
            moment,
        });
    }
    worst(prog, m, &terms, &inertia(spec, prog, m))
}

/// The weights at the centres of mass.
fn weights(spec: &ForceSpec, prog: &Program, m: &Motion, terms: &mut Vec<Term>) {
    for lm in &spec.links {
        if let Some(s) = prog.index(&lm.centre) {
            terms.push(Term::force(
                lm.link as usize,
                spec.weight(lm.mass),
                at(m, s),
            ));
        }
    }
}

/// The working resistances: forces on their carrying link, moments against ω.
fn resistances(
    spec: &ForceSpec,
    prog: &Program,
    state: &State<'_>,
    terms: &mut Vec<Term>,
    couples: &mut Vec<(usize, f64)>,
) {
    let m = state.motion;
    // The same destructuring of a resistance as `loads::loads`, and the same selection
    // (`ForceSpec::acting`, a fact of the scene): which link carries it and where it points
    // are decided again here.
    for r in spec.acting(state.phase) {
        match &r.action {
            Action::Force {
                point,
                link,
                magnitude,
                dir,
            } => {
                let Some(k) = prog.index(point) else { continue };
                let Some(l) = link.map(|l| l as usize).or_else(|| loaded_link(prog, k)) else {
                    continue;
                };
                let e = match dir {
                    Some(a) => DVec2::from_angle(*a),
                    None => (-m.v[k]).normalize_or_zero(),
                };
                terms.push(Term::force(l, e * *magnitude, at(m, k)));
            }
            Action::Moment { link, magnitude } => {
                let l = *link as usize;
                let w = m.omega.get(l).copied().unwrap_or(0.0);
                if w != 0.0 {
                    couples.push((l, -w.signum() * magnitude));
                }
            }
        }
    }
}

/// The gas forces of the indicator diagrams, on the piston at their point.
fn gas_forces(spec: &ForceSpec, prog: &Program, m: &Motion, terms: &mut Vec<Term>) {
    for ind in &spec.indicators {
        if let (Ok(Some(load)), Some(k)) = (ind.load(prog, m), prog.index(&ind.point)) {
            if let Some(l) = loaded_link(prog, k) {
                terms.push(Term::force(l, load.force, at(m, k)));
            }
        }
    }
}

/// The reactions, on `to` and (the opposite) on `from`.
fn reactions(state: &State<'_>, reported: &Reported<'_>, terms: &mut Vec<Term>) {
    let m = state.motion;
    for r in reported.reactions {
        let x = match r.pair.kind {
            PairKind::Revolute(k) => at(m, k),
            PairKind::Prismatic {
                reference,
                dir_link,
            } => at(m, reference) + state.dir[dir_link] * r.offset.unwrap_or(0.0),
        };
        terms.push(Term::force(r.pair.to, r.force, x));
        terms.push(Term::force(r.pair.from, -r.force, x));
    }
}

/// Friction in the pairs, from the reported reactions: a couple against the relative
/// rotation in a revolute pair, a force against the relative sliding in a prismatic one.
fn friction_terms(
    prog: &Program,
    state: &State<'_>,
    reported: &Reported<'_>,
    fr: &PairFriction,
    terms: &mut Vec<Term>,
    couples: &mut Vec<(usize, f64)>,
) {
    let m = state.motion;
    for r in reported.reactions {
        let (from, to) = (r.pair.from, r.pair.to);
        let size = r.force.length();
        match r.pair.kind {
            PairKind::Revolute(k) => {
                let w_rel = rate(m, to) - rate(m, from);
                if at_rest(w_rel, &m.omega) {
                    continue;
                }
                let radius = fr
                    .radii
                    .iter()
                    .find(|(name, _)| prog.index(name) == Some(k))
                    .map_or(fr.radius, |(_, r)| *r);
                let c = -w_rel.signum() * fr.f * radius * size;
                couples.push((to, c));
                couples.push((from, -c));
            }
            PairKind::Prismatic {
                reference,
                dir_link,
            } => {
                let u = state.dir[dir_link];
                let x = at(m, reference) + u * r.offset.unwrap_or(0.0);
                let v_rel = (velocity(prog, m, to, x) - velocity(prog, m, from, x)).dot(u);
                let speeds: Vec<f64> = m.v.iter().map(|v| v.length()).collect();
                if at_rest(v_rel, &speeds) {
                    continue;
                }
                let f = u * (-v_rel.signum() * fr.f * size);
                terms.push(Term::force(to, f, x));
                terms.push(Term::force(from, -f, x));
            }
        }
    }
}

/// The drive on the crank: the balancing force on its line of action (gear drive), else the
/// balancing moment.
fn drive(
    spec: &ForceSpec,
    prog: &Program,
    state: &State<'_>,
    reported: &Reported<'_>,
    terms: &mut Vec<Term>,
    couples: &mut Vec<(usize, f64)>,
) {
    let crank = prog.crank_link as usize;
    let o = at(state.motion, prog.centre);
    match (&spec.drive, reported.f_bal) {
        (Drive::Gear(g), Some(f)) => {
            let turn = if reported.m_bal == 0.0 {
                state.sense
            } else {
                reported.m_bal.signum()
            };
            let (p, d) = line_of_action(o, g.radius(), g.towards, g.pressure_angle, turn);
            terms.push(Term::force(crank, d * f, p));
        }
        _ => couples.push((crank, reported.m_bal)),
    }
}

/// The inertia: m·a_S and the moment of the momentum's rate about O, I_S·ε.
fn inertia(spec: &ForceSpec, prog: &Program, m: &Motion) -> Vec<Term> {
    let mut inertia: Vec<Term> = Vec::new();
    for lm in &spec.links {
        if let Some(s) = prog.index(&lm.centre) {
            let l = lm.link as usize;
            inertia.push(Term {
                link: l,
                force: m.a[s] * lm.mass,
                at: at(m, s),
                moment: lm.inertia * m.eps.get(l).copied().unwrap_or(0.0),
            });
        }
    }
    inertia
}

/// The largest residual of the moving links' equations: the `terms` against the `inertia`,
/// moments about the crank's centre O, each relative to the largest force (the largest
/// moment, or the largest force times the mechanism's size).
fn worst(prog: &Program, m: &Motion, terms: &[Term], inertia: &[Term]) -> f64 {
    let o = at(m, prog.centre);
    let size = m.p.iter().map(|x| x.distance(o)).fold(0.0, f64::max);
    let big_f = terms
        .iter()
        .chain(inertia)
        .map(|t| t.force.length())
        .fold(0.0, f64::max);
    let big_m = terms
        .iter()
        .chain(inertia)
        .map(|t| t.moment.abs())
        .fold(big_f * size, f64::max);
    let mut worst = 0.0f64;
    for l in moving_links(prog) {
        let (mut f, mut mo) = (DVec2::ZERO, 0.0);
        for t in terms.iter().filter(|t| t.link == l) {
            f += t.force;
            mo += (t.at - o).perp_dot(t.force) + t.moment;
        }
        for t in inertia.iter().filter(|t| t.link == l) {
            f -= t.force;
            mo -= (t.at - o).perp_dot(t.force) + t.moment;
        }
        if big_f > 0.0 {
            worst = worst.max(f.length() / big_f);
        }
        if big_m > 0.0 {
            worst = worst.max(mo.abs() / big_m);
        }
    }
    worst
}

/// The moving links: the crank and both links of every group.
fn moving_links(prog: &Program) -> Vec<usize> {
    let mut v = vec![prog.crank_link as usize];
    for g in prog.groups() {
        v.extend(g.links);
    }
    v
}

/// The link a load at point `k` acts on when the scene names none: the only moving link
/// there, else the block or slider among the links jointed there (the textbooks' ram,
/// piston, block), else none.
fn loaded_link(prog: &Program, k: usize) -> Option<usize> {
    let mut blocks: Vec<usize> = Vec::new();
    for g in prog.groups() {
        blocks.extend(g.sliders().into_iter().flatten());
    }
    let here: Vec<usize> = prog.links_of(k).into_iter().filter(|&l| l > 0).collect();
    if here.len() == 1 {
        return here.first().copied();
    }
    let mut sliding = here.iter().copied().filter(|l| blocks.contains(l));
    match (sliding.next(), sliding.next()) {
        (Some(l), None) => Some(l),
        _ => None,
    }
}

/// ω of link `l` (the frame's is zero).
fn rate(m: &Motion, l: usize) -> f64 {
    if l == 0 {
        0.0
    } else {
        m.omega.get(l).copied().unwrap_or(0.0)
    }
}

/// The velocity of the point of link `l` at `x`, from any point of the link whose velocity
/// the motion gives.
fn velocity(prog: &Program, m: &Motion, l: usize, x: DVec2) -> DVec2 {
    if l == 0 {
        return DVec2::ZERO;
    }
    (0..m.p.len())
        .find(|&k| prog.links_of(k).contains(&l))
        .map_or(DVec2::ZERO, |k| m.v[k] + (x - m.p[k]).perp() * rate(m, l))
}

/// A relative rate that rounding cannot tell from rest (1e-9 of the largest of `of`).
fn at_rest(rate: f64, of: &[f64]) -> bool {
    let big = of.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    rate.abs() <= 1e-9 * big
}
