//! The rows and notes of the dynamic study.

use super::{ConstantMoment, Dynamics, SeedClaims};
use crate::check::notes::dynamics::{
    Balance, DynamicsNote, Exact, Flywheel, RouteFlywheel, Routes,
};
use crate::check::{self, Finding, Key, Method, NoFlywheel, Route, Row, Symbol};

/// The rows: `M_red`, `J_red` (velocity plans) and `dT` (graphical integration) per
/// position; `A_res`, `M_drive` (integration), `J_flywheel` and `delta` (Wittenbauer,
/// Mertsalov), the flywheel's D (`h_flywheel`) and mass (`m_flywheel`) sized from Wittenbauer's
/// J_м of the whole scene, each against the analytic twin.
pub fn rows(d: &Dynamics) -> Vec<Row> {
    let mut rows = Vec::new();
    let big = |f: &dyn Fn(usize) -> f64| (0..d.labels.len()).fold(0.0f64, |m, i| m.max(f(i).abs()));
    let m_scale = big(&|i| d.analytic[i].m());
    let j_scale = big(&|i| d.analytic[i].j);
    let t_scale = big(&|i| d.cycle.delta_t(d.travel[i]));
    for (i, label) in d.tabled() {
        let (g, a) = (&d.graphical[i], &d.analytic[i]);
        let mut push = |symbol: Symbol, subject: &str, method: Method, g: f64, a: f64, s: f64| {
            rows.push(Row::new(
                Key::at_position(symbol, subject, label),
                method,
                g,
                a,
                s,
            ))
        };
        push(Symbol::Moment, "red", Method::Plan, g.m(), a.m(), m_scale);
        push(Symbol::Inertia, "red", Method::Plan, g.j, a.j, j_scale);
        let dt = d.diagrams.delta_t.get(i).copied().unwrap_or(f64::NAN);
        push(
            Symbol::EnergyChange,
            "",
            Method::Integration,
            dt,
            d.cycle.delta_t(d.travel[i]),
            t_scale,
        );
    }
    let mut scene = |symbol: Symbol, subject: &str, method: Method, g: f64, a: f64| {
        rows.push(Row::new(
            Key::of_scene(symbol, subject),
            method,
            g,
            a,
            a.abs(),
        ))
    };
    let a_c = d.diagrams.a_c.last().copied().unwrap_or(f64::NAN);
    match d.spec.constant_moment {
        ConstantMoment::Driving => {
            scene(Symbol::Work, "res", Method::Integration, a_c, d.cycle.a_res);
            scene(
                Symbol::Moment,
                "drive",
                Method::Integration,
                d.diagrams.m_drive,
                d.cycle.m_drive,
            );
        }
        // An engine: the work of the gas forces and the constant resisting moment.
        ConstantMoment::Resisting => {
            scene(
                Symbol::Work,
                "drive",
                Method::Integration,
                a_c,
                d.cycle.a_drive,
            );
            scene(
                Symbol::Moment,
                "res",
                Method::Integration,
                d.diagrams.m_drive,
                -d.cycle.m_drive,
            );
        }
    }
    let routes = [
        (
            Method::Wittenbauer,
            d.diagrams.wittenbauer.j_fw,
            d.delta_of[0],
        ),
        (Method::Mertsalov, d.diagrams.mertsalov.j_fw, d.delta_of[1]),
    ];
    for (m, j, _) in routes {
        scene(Symbol::Inertia, "flywheel", m, j, d.exact.j_fw);
    }
    for (m, _, delta) in routes {
        scene(Symbol::Irregularity, "", m, delta, d.exact.delta());
    }
    // The flywheel a hand-in sizes, from Wittenbauer's J_м, against the twin's, sized from
    // the exact J_м: its outer diameter D and its mass.
    if d.size.d > 0.0 || d.exact_size.d > 0.0 {
        let (g, a) = (&d.size, &d.exact_size);
        scene(Symbol::Length, "flywheel", Method::Wittenbauer, g.d, a.d);
        scene(
            Symbol::Mass,
            "flywheel",
            Method::Wittenbauer,
            g.mass,
            a.mass,
        );
    }
    rows
}

/// The verdicts of the notes.
pub fn findings(d: &Dynamics) -> Vec<Finding> {
    check::notes::dynamics::findings(&noted(d))
}

/// The notes: the exact solution, the textbook routes against it, the seed's numbers that do
/// not follow from its data.
pub fn noted(d: &Dynamics) -> Vec<DynamicsNote> {
    let mut out = vec![exact_note(d), routes_note(d)];
    if let Some(seed) = &d.spec.seed {
        seed_notes(d, seed, &mut out);
    }
    out
}

/// The exact solution: its flywheel (or none needed) for δ, ω_avg with the extremes of ω,
/// the cycle's time and the constant moment.
fn exact_note(d: &Dynamics) -> DynamicsNote {
    let e = &d.exact;
    let flywheel = if e.j_fw > 0.0 {
        Flywheel::Needed((e.j_fw, e.delta()))
    } else {
        Flywheel::None(NoFlywheel::Exact {
            delta: e.delta(),
            asked: d.spec.delta,
        })
    };
    DynamicsNote::Exact(Exact {
        flywheel,
        omega_avg: e.omega_avg(),
        w_max: e.w_max,
        w_min: e.w_min,
        from: d.labels.first().map_or("1", String::as_str).to_string(),
        cycle_time: d.cycle_time,
        balance: match d.spec.constant_moment {
            ConstantMoment::Driving => Balance::Driving {
                a_res: d.cycle.a_res,
                m_drive: d.cycle.m_drive,
            },
            ConstantMoment::Resisting => Balance::Resisting {
                a_drive: d.cycle.a_drive,
                m_res: -d.cycle.m_drive,
            },
        },
    })
}

/// The textbook routes against the exact flywheel: Wittenbauer's tangents, Mertsalov's route,
/// and Mertsalov's on the continuous exact data.
fn routes_note(d: &Dynamics) -> DynamicsNote {
    let mertsalov_exact = d.cycle.mertsalov(d.w_avg, d.spec.delta).0 - d.spec.constant_inertia();
    let continuous = if mertsalov_exact > 0.0 {
        Flywheel::Needed(mertsalov_exact)
    } else {
        Flywheel::None(NoFlywheel::Continuous { j: mertsalov_exact })
    };
    DynamicsNote::Routes(Routes {
        positions: d.labels.len(),
        wittenbauer: route_note(
            d,
            Route::Wittenbauer,
            &d.diagrams.wittenbauer,
            d.delta_of[0],
        ),
        mertsalov: route_note(d, Route::Mertsalov, &d.diagrams.mertsalov, d.delta_of[1]),
        continuous,
    })
}

/// One textbook route (`by`): its flywheel against the exact one, or none needed; `delta`
/// the δ it really gives.
fn route_note(
    d: &Dynamics,
    by: Route,
    r: &super::draw::RouteReading,
    delta: f64,
) -> Flywheel<RouteFlywheel> {
    if r.j_fw <= 0.0 {
        Flywheel::None(NoFlywheel::Reads {
            route: by,
            read: r.read,
        })
    } else {
        Flywheel::Needed(RouteFlywheel {
            j: r.j_fw,
            exact: (d.exact.j_fw > 0.0).then_some(d.exact.j_fw),
            delta,
        })
    }
}

/// The seed's numbers that do not follow from its data: its flywheel, its expression, its
/// table of reduced inertias.
fn seed_notes(d: &Dynamics, seed: &SeedClaims, out: &mut Vec<DynamicsNote>) {
    let e = &d.exact;
    if let Some(j) = seed.flywheel {
        out.push(DynamicsNote::SeedFlywheel {
            j,
            exact: (e.j_fw > 0.0).then_some(e.j_fw),
            delta: d.cycle.with_flywheel(j, d.w_avg).delta(),
            asked: d.spec.delta,
        });
    }
    if let Some(value) = seed.expression_value(d.spec.delta, d.w_avg) {
        out.push(DynamicsNote::SeedExpression {
            value,
            printed: seed.flywheel,
        });
    }
    if !seed.j_red.is_empty() {
        let c = d.spec.constant_inertia();
        // Where the links move enough for the variable part to be read: at least a tenth of
        // its largest value.
        let top = d.analytic.iter().fold(0.0f64, |m, a| m.max(a.j - c));
        let ratios: Vec<f64> = seed
            .j_red_among(d.analytic.len())
            .into_iter()
            .map(|(k, s)| (s, &d.analytic[k]))
            .filter(|(_, a)| a.j - c > 0.1 * top)
            .map(|(s, a)| (s - c) / (a.j - c))
            .collect();
        if let (Some(lo), Some(hi)) = (
            ratios.iter().copied().reduce(f64::min),
            ratios.iter().copied().reduce(f64::max),
        ) {
            out.push(DynamicsNote::SeedInertias {
                constant: c,
                ratio: (lo, hi),
                positions: ratios.len(),
            });
        }
    }
}
