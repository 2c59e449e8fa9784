//! The sums of the equilibrium check: every moving body's forces and moments against its
//! inertia, and the power of the loads against the inertia's.

use super::motion::Screws;
use crate::geom::DVec2;

/// One term of a body's equations: a force at a point, or a couple.
#[derive(Debug, Clone, Copy)]
pub(super) struct Term {
    /// The body.
    pub link: u32,
    /// The force, N.
    pub force: DVec2,
    /// Its point, m.
    pub at: DVec2,
    /// A couple, N·m.
    pub moment: f64,
}

impl Term {
    /// A force at a point.
    pub fn force(link: u32, force: DVec2, at: DVec2) -> Self {
        Term {
            link,
            force,
            at,
            moment: 0.0,
        }
    }
    /// A couple.
    pub fn couple(link: u32, moment: f64) -> Self {
        Term {
            link,
            force: DVec2::ZERO,
            at: DVec2::ZERO,
            moment,
        }
    }
    /// Its power with the body moving as `s` gives, W.
    fn power(&self, s: &Screws) -> f64 {
        self.force.dot(s.v(self.link, self.at)) + self.moment * s.omega(self.link)
    }
}

/// The terms gathered for one position.
#[derive(Debug, Default)]
pub(super) struct Balance {
    /// The loads: weights, resistances, gas forces, friction, the balancing load.
    loads: Vec<Term>,
    /// The reactions, each on both its bodies.
    reactions: Vec<Term>,
    /// m·a_S and I_S·ε of every body.
    inertia: Vec<Term>,
    /// The largest part of a reaction that no pair of the picture carries, N.
    stray: f64,
}

impl Balance {
    /// A load.
    pub fn load(&mut self, t: Term) {
        self.loads.push(t);
    }
    /// A reaction on one of its bodies.
    pub fn reaction(&mut self, t: Term) {
        self.reactions.push(t);
    }
    /// A body's inertia.
    pub fn inertia(&mut self, t: Term) {
        self.inertia.push(t);
    }
    /// A force, N, that a reaction carries where the picture has no pair to carry it.
    pub fn stray(&mut self, f: f64) {
        self.stray = self.stray.max(f);
    }

    /// The largest residual of the bodies' equations, moments about `o`, each relative to
    /// the largest force (the largest moment, or the largest force times the mechanism's
    /// size over `points`), and of the stray reactions.
    pub fn equilibrium(&self, bodies: &[u32], o: DVec2, points: &[DVec2]) -> f64 {
        let size = points.iter().map(|x| x.distance(o)).fold(0.0, f64::max);
        let all = || {
            self.loads
                .iter()
                .chain(&self.reactions)
                .chain(&self.inertia)
        };
        let big_f = all().map(|t| t.force.length()).fold(0.0, f64::max);
        let big_m = all().map(|t| t.moment.abs()).fold(big_f * size, f64::max);
        let mut worst = if big_f > 0.0 { self.stray / big_f } else { 0.0 };
        for &l in bodies {
            let (mut f, mut mo) = (DVec2::ZERO, 0.0);
            for t in self.loads.iter().chain(&self.reactions) {
                if t.link == l {
                    f += t.force;
                    mo += (t.at - o).perp_dot(t.force) + t.moment;
                }
            }
            for t in self.inertia.iter().filter(|t| t.link == l) {
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

    /// Σ P·v + Σ M·ω of the loads less the inertia's, relative to the sum of every term's
    /// magnitude (0 without power).
    pub fn power(&self, s: &Screws) -> f64 {
        let loads = self.loads.iter().map(|t| t.power(s));
        let inertia = self.inertia.iter().map(|t| -t.power(s));
        let (sum, scale) = loads
            .chain(inertia)
            .fold((0.0, 0.0), |(sum, scale), p| (sum + p, scale + p.abs()));
        if scale > 0.0 {
            sum.abs() / scale
        } else {
            0.0
        }
    }
}
