//! The English of a balancing study's notes ([`BalancingNote`]).

use super::sig;
use crate::check::notes::balancing::{BalancingNote, Inertia};

/// A number of these notes: 4 significant digits.
fn num(x: f64) -> String {
    sig(x, 4)
}

/// The note in English.
pub(super) fn english(note: &BalancingNote) -> String {
    match note {
        BalancingNote::NoCorrection { plane } => {
            format!("balancing: plane {plane}: m·ρ = 0, no correcting mass is needed")
        }
        BalancingNote::Inertia(m) => format!(
            "balancing: m{} = {} kg at ρ = {} m, ω = {} rad/s: inertia force P = m·ω²·ρ = {} N; \
             weight G = m·g = {} N (g = {} m/s²); P/G = ω²·ρ/g = {}",
            m.index,
            num(m.mass),
            num(m.radius),
            num(m.omega),
            num(m.force),
            num(m.weight),
            num(m.g),
            num(m.force / m.weight)
        ),
        BalancingNote::W4Erratum(Inertia {
            mass,
            radius,
            omega,
            force: p,
            weight: g,
            g: course_g,
            ..
        }) => format!(
            "balancing: erratum of seed 001 (lecture 19, W4: m = {} kg, l = {} m, ω = {} 1/s): its \
             inertia force P = {} N is called \"900 times\" the ball's weight; with g = {} m/s² the \
             ratio is {} N / {} N = {} (900 holds only for g = 10 m/s²)",
            num(*mass),
            num(*radius),
            num(*omega),
            num(*p),
            num(*course_g),
            num(*p),
            num(*g),
            num(p / g)
        ),
    }
}
