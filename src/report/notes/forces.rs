//! The English of the force analysis' notes ([`ForcesNote`]).

use super::sig;
use crate::check::notes::forces::{ForcesNote, PositionFriction};

/// A value of these notes: 6 significant digits.
fn n(x: f64) -> String {
    sig(x, 6)
}

/// The note in English.
pub(super) fn english(note: &ForcesNote) -> String {
    match note {
        ForcesNote::PowerBalance { label, power, solve } => format!(
            "position {label}: the balancing moment by the power balance Σ F·v + Σ M·ω + M_bal·ω₁ = 0 is {} N·m; the linear solve of the links' equilibrium gives {} N·m",
            sig(*power, 10),
            sig(*solve, 10),
        ),
        ForcesNote::Lever {
            label,
            polygons: p,
            lever: l,
        } => format!(
            "position {label}: M_bal by the force polygons {} N·m, by Zhukovsky's lever {} N·m: they differ by {} % of the polygons' value",
            n(*p),
            n(*l),
            sig(if *p != 0.0 { (p - l).abs() / p.abs() * 100.0 } else { 0.0 }, 3),
        ),
        ForcesNote::Opposes {
            label,
            moment,
            force,
        } => format!(
            "position {label}: the balancing moment {} N·m opposes ω₁: the pinion holds the crank back, so its tooth pushes on the other flank and the balancing force F_bal = {} N acts on the line of action mirrored about the line of centres",
            n(*moment),
            n(*force),
        ),
        ForcesNote::SliderOutside {
            label,
            pair: (from, to),
            force,
            offset,
            length,
            ends: [a, b],
        } => format!(
            "position {label}: the reaction R_{from}_{to} = {} N acts {} m from the slider's centre, outside the slider (length {} m): a force at the centre and a couple on the ends, which carry {} N and {} N",
            n(*force), n(*offset), n(*length), n(*a), n(*b)
        ),
        ForcesNote::Friction { label, friction } => pair_friction(label, friction),
    }
}

/// The friction in the pairs at position `label`, with the instantaneous efficiency when it
/// lies in (0, 1).
fn pair_friction(label: &str, w: &PositionFriction) -> String {
    let (m0, m) = (w.without, w.with);
    let eta = if m != 0.0 { m0 / m } else { f64::NAN };
    let eta = if eta > 0.0 && eta < 1.0 {
        format!(
            ", the instantaneous efficiency η = M_bal/M_bal_f = {}",
            sig(eta, 4)
        )
    } else {
        String::new()
    };
    format!(
        "position {label}: with friction in the pairs M_bal_f = {} N·m against M_bal = {} N·m without: the pairs lose {} W{eta}; the power balance with the friction's power gives {} N·m; the friction equations (Newton's method on the friction loads' magnitudes) took {} drawings of the force polygons and {} linear solves",
        sig(m, 10),
        sig(m0, 10),
        n(w.lost),
        sig(w.by_power, 10),
        w.approximations[0],
        w.approximations[1],
    )
}
