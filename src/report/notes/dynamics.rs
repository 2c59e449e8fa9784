//! The English of the dynamics' notes ([`DynamicsNote`]).

use super::finding::{self, num6 as n};
use super::sig;
use crate::check::notes::dynamics::{
    Balance, DynamicsNote, Exact, Flywheel, RouteFlywheel, Routes,
};
use crate::check::Finding;

/// How far `x` is from `r`, per cent of `r`: 3 significant digits.
fn pct(x: f64, r: f64) -> String {
    sig((x - r) / r * 100.0, 3)
}

/// The verdict where no flywheel is needed, else `needed`'s words.
fn either<T>(f: &Flywheel<T>, needed: impl FnOnce(&T) -> String) -> String {
    match f {
        Flywheel::Needed(t) => needed(t),
        Flywheel::None(none) => finding::english(&Finding::NoFlywheelNeeded(*none)),
    }
}

/// The note in English.
pub(super) fn english(note: &DynamicsNote) -> String {
    let said = match note {
        DynamicsNote::Exact(e) => exact(e),
        DynamicsNote::Routes(r) => routes(r),
        DynamicsNote::SeedFlywheel {
            j,
            exact,
            delta,
            asked,
        } => {
            let exact = match exact {
                Some(e) => format!("the exact value is {} kg·m² ({} % off)", n(*e), pct(*j, *e)),
                None => "no flywheel is needed".to_string(),
            };
            format!(
                "seed error: its flywheel J = {} kg·m² does not follow from its data: {exact}; with J = {} the machine runs at δ = {} = 1/{} instead of {}",
                n(*j),
                n(*j),
                n(*delta),
                sig(1.0 / delta, 3),
                n(*asked),
            )
        }
        DynamicsNote::SeedExpression { value, printed } => format!(
            "seed error: its expression μ_T·BD/(δ·ω²) − (J_b + J_d)/2 evaluates to {} kg·m², not the {} it prints",
            n(*value),
            printed.map_or_else(|| "value".into(), n),
        ),
        DynamicsNote::SeedInertias {
            constant,
            ratio: (lo, hi),
            positions,
        } => format!(
            "seed error: its table of reduced inertias J_пр is wrong wherever the links move: its variable part J_пр − {} is {}…{} × the correct one at {positions} positions",
            n(*constant),
            sig(*lo, 3),
            sig(*hi, 3),
        ),
    };
    format!("dynamics: {said}")
}

/// The exact solution.
fn exact(e: &Exact) -> String {
    let flywheel = either(&e.flywheel, |(j, delta)| {
        format!(
            "the energy equation integrated exactly gives J_flywheel = {} kg·m² for δ = {}",
            n(*j),
            n(*delta)
        )
    });
    let balance = match e.balance {
        Balance::Driving { a_res, m_drive } => {
            format!("A_res = {} J, M_drive = {} N·m", n(a_res), n(m_drive))
        }
        Balance::Resisting { a_drive, m_res } => format!(
            "A_drive = {} J of the indicator diagrams, the constant resisting moment M_res = {} N·m",
            n(a_drive),
            n(m_res)
        ),
    };
    format!(
        "{flywheel} at ω_avg = {} rad/s (ω_max = {} at {}°, ω_min = {} at {}° of crank travel from position {}); the cycle takes {} s; {balance}",
        n(e.omega_avg),
        n(e.w_max.0),
        sig(e.w_max.1.to_degrees(), 4),
        n(e.w_min.0),
        sig(e.w_min.1.to_degrees(), 4),
        e.from,
        n(e.cycle_time),
    )
}

/// The textbook routes against the exact flywheel.
fn routes(r: &Routes) -> String {
    let continuous = either(&r.continuous, |j| format!("gives {} kg·m²", n(*j)));
    format!(
        "at {} positions {}, {}; Mertsalov on the continuous exact data {continuous} (T_II with ω = ω_avg is the method's own error)",
        r.positions,
        route("Wittenbauer's tangents give", &r.wittenbauer),
        route("Mertsalov's route gives", &r.mertsalov),
    )
}

/// One route (`name`): its flywheel against the exact one, or none needed.
fn route(name: &str, f: &Flywheel<RouteFlywheel>) -> String {
    match f {
        Flywheel::None(none) => format!(
            "{name}: {}",
            finding::english(&Finding::NoFlywheelNeeded(*none))
        ),
        Flywheel::Needed(r) => match r.exact {
            Some(e) => format!(
                "{name} J_flywheel = {} kg·m² ({} %, δ really {})",
                n(r.j),
                pct(r.j, e),
                n(r.delta)
            ),
            None => format!(
                "{name} J_flywheel = {} kg·m² where none is needed (δ really {})",
                n(r.j),
                n(r.delta)
            ),
        },
    }
}
