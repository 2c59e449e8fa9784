//! The rows of a force analysis (graphical against analytic, zero references against the
//! mechanism's size) and its notes.

use super::pair_friction::sliding_friction;
use super::{Analysis, Load, LoadKind, PositionForces};
use crate::check::notes::forces::{ForcesNote, PositionFriction};
use crate::check::{Key, Method, Row, Symbol};
use crate::geom::DVec2;

/// A row of position `label` (its zero reference set by [`zero_references`]).
pub(super) fn row(
    label: &str,
    symbol: Symbol,
    subject: String,
    method: Method,
    g: f64,
    a: f64,
) -> Row {
    // −0 (a balancing moment of no loads) is written as 0.
    let key = Key::at_position(symbol, subject, label);
    Row::new(key, method, g + 0.0, a + 0.0, a.abs())
}

/// The inertia loads of one position, read off the acceleration plan.
pub(super) fn rows(label: &str, loads: &[Load], exact: &[Load]) -> Vec<Row> {
    let mut rows = Vec::new();
    for e in exact
        .iter()
        .filter(|l| matches!(l.kind, LoadKind::Inertia | LoadKind::InertiaMoment))
    {
        let g = loads.iter().find(|l| l.kind == e.kind && l.link == e.link);
        let (g_f, g_m) = g.map_or((0.0, 0.0), |g| (g.force.length(), g.moment));
        let subject = format!("in{}", e.link);
        rows.push(match e.kind {
            LoadKind::Inertia => row(
                label,
                Symbol::Force,
                subject,
                Method::Plan,
                g_f,
                e.force.length(),
            ),
            _ => row(label, Symbol::Moment, subject, Method::Plan, g_m, e.moment),
        });
    }
    rows
}

/// The reactions and their points (polygons), the balancing moment and force (polygons and
/// lever) of one position; `suffix` marks the analysis with friction (`_f`).
pub(super) fn reaction_rows(label: &str, suffix: &str, analysis: &Analysis) -> Vec<Row> {
    let (polygons, lever, twin) = (&analysis.polygons, &analysis.lever, &analysis.twin);
    let mut rows = Vec::new();
    let mut push = |symbol: Symbol, subject: String, method: Method, g: f64, a: f64| {
        rows.push(row(
            label,
            symbol,
            format!("{subject}{suffix}"),
            method,
            g,
            a,
        ));
    };
    let graphical = polygons.reactions();
    for r in &twin.reactions {
        let Some(g) = graphical
            .iter()
            .find(|g| g.pair.from == r.pair.from && g.pair.to == r.pair.to)
        else {
            continue;
        };
        let subject = format!("{}_{}", r.pair.from, r.pair.to);
        // The total reaction: in a sliding pair with friction the normal reaction N solved
        // plus the friction force f·|N| the route carried as a load (turned by φ).
        let total = |n: DVec2, loads: &[Load]| (n + sliding_friction(loads, r.pair)).length();
        push(
            Symbol::Reaction,
            subject.clone(),
            Method::Polygon,
            total(g.force, &analysis.loads),
            total(r.force, &analysis.loads_exact),
        );
        if let (Some(gs), Some(s)) = (g.offset, r.offset) {
            push(Symbol::Length, subject, Method::Polygon, gs, s);
        }
    }
    let bal = || "bal".to_string();
    push(
        Symbol::Moment,
        bal(),
        Method::Polygon,
        polygons.driver.m_bal,
        twin.m_bal,
    );
    push(
        Symbol::Moment,
        bal(),
        Method::Lever,
        lever.m_bal,
        twin.m_bal,
    );
    if let Some(f) = twin.f_bal {
        let p = polygons.driver.f_bal.unwrap_or(f64::NAN);
        push(Symbol::Force, bal(), Method::Polygon, p, f);
        let l = lever.f_bal.unwrap_or(f64::NAN);
        push(Symbol::Force, bal(), Method::Lever, l, f);
    }
    if let (Some(g), Some(a)) = (polygons.driver.arm, twin.arm) {
        push(Symbol::Length, bal(), Method::Polygon, g, a);
    }
    rows
}

/// A value's zero reference is the largest of its kind at the position, and for a length
/// (an arm, a guide reaction's point) at least the mechanism's size `size`, m, and for a
/// moment at least the largest force times that size: a guide reaction's point on its
/// reference point is zero against the mechanism, even where every such point is (the
/// v-engine's pistons, whose reactions pass through their joints: 1e-16 m is zero).
pub(super) fn zero_references(rows: &mut [Row], size: f64) {
    let largest = |s: Symbol, rows: &[Row]| {
        rows.iter()
            .filter(|r| r.key.symbol == s && r.analytic.is_finite())
            .fold(0.0f64, |m, r| m.max(r.analytic.abs()))
    };
    let force = largest(Symbol::Reaction, rows).max(largest(Symbol::Force, rows));
    let floor = |s: Symbol| match s {
        Symbol::Length => size,
        Symbol::Moment => force * size,
        _ => 0.0,
    };
    let scales: Vec<f64> = rows
        .iter()
        .map(|r| largest(r.key.symbol, rows).max(floor(r.key.symbol)))
        .collect();
    for (r, s) in rows.iter_mut().zip(scales) {
        r.scale = s;
    }
}

/// The notes of one position for the report: the power balance against the linear solve,
/// the polygon against the lever (the seed's «погрешность»), every slider whose guide
/// reaction falls outside it, and the friction in the pairs.
pub fn notes(f: &PositionForces) -> Vec<ForcesNote> {
    let label = || f.label.clone();
    let mut out = vec![
        ForcesNote::PowerBalance {
            label: label(),
            power: f.analysis.m_power,
            solve: f.analysis.twin.m_bal,
        },
        ForcesNote::Lever {
            label: label(),
            polygons: f.analysis.polygons.driver.m_bal,
            lever: f.analysis.lever.m_bal,
        },
    ];
    if let Some(force) = f
        .analysis
        .twin
        .f_bal
        .filter(|_| f.analysis.twin.m_bal * f.sense < 0.0)
    {
        out.push(ForcesNote::Opposes {
            label: label(),
            moment: f.analysis.twin.m_bal,
            force,
        });
    }
    for s in f.sliders.iter().filter(|s| s.outside()) {
        out.push(ForcesNote::SliderOutside {
            label: label(),
            pair: (s.pair.from, s.pair.to),
            force: s.force,
            offset: s.offset,
            length: s.length,
            ends: s.ends(),
        });
    }
    if let Some(w) = &f.friction {
        out.push(ForcesNote::Friction {
            label: label(),
            friction: PositionFriction {
                with: w.analysis.twin.m_bal,
                without: f.analysis.twin.m_bal,
                lost: -w.lost,
                by_power: w.analysis.m_power,
                approximations: w.approximations,
            },
        });
    }
    out
}
