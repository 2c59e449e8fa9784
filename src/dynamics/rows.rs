//! The rows and notes of the dynamic study.

use super::{ConstantMoment, Dynamics, SeedClaims};
use crate::check::finding::Note;
use crate::check::{self, Finding, Key, Method, NoFlywheel, Route, Row, Symbol};
use crate::scale::{format_sig, Lang};

/// The rows: `M_red`, `J_red` (velocity plans) and `dT` (graphical integration) per
/// position; `A_res`, `M_drive` (integration), `J_flywheel` and `delta` (Wittenbauer,
/// Merkin), the flywheel's D (`h_flywheel`) and mass (`m_flywheel`) sized from Wittenbauer's
/// J_м of the whole scene, each against the analytic twin.
pub fn rows(d: &Dynamics) -> Vec<Row> {
    let mut rows = Vec::new();
    let big = |f: &dyn Fn(usize) -> f64| (0..d.labels.len()).fold(0.0f64, |m, i| m.max(f(i).abs()));
    let m_scale = big(&|i| d.analytic[i].m());
    let j_scale = big(&|i| d.analytic[i].j);
    let t_scale = big(&|i| d.cycle.delta_t(d.travel[i]));
    for (i, label) in d.labels.iter().enumerate() {
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
        (Method::Merkin, d.diagrams.merkin.j_fw, d.delta_of[1]),
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
    check::finding::findings(&noted(d))
}

/// A value in the notes: 6 significant digits.
fn n(x: f64) -> String {
    format_sig(x, 6, Lang::En)
}

/// How far `x` is from `r`, per cent of `r`: 3 significant digits.
fn pct(x: f64, r: f64) -> String {
    format_sig((x - r) / r * 100.0, 3, Lang::En)
}

/// The notes: the exact solution, the textbook routes against it, the seed's numbers that do
/// not follow from its data.
pub fn noted(d: &Dynamics) -> Vec<Note> {
    let mut out = vec![exact_note(d), routes_note(d)];
    if let Some(seed) = &d.spec.seed {
        seed_notes(d, seed, &mut out);
    }
    out
}

/// The exact solution: its flywheel (or none needed) for δ, ω_avg with the extremes of ω,
/// the cycle's time and the constant moment.
fn exact_note(d: &Dynamics) -> Note {
    let e = &d.exact;
    let exact = if e.j_fw > 0.0 {
        Note::text(format!(
            "the energy equation integrated exactly gives J_flywheel = {} kg·m² for δ = {}",
            n(e.j_fw),
            n(e.delta())
        ))
    } else {
        Note::default().with(Finding::NoFlywheelNeeded(NoFlywheel::Exact {
            delta: e.delta(),
            asked: d.spec.delta,
        }))
    };
    Note::text("dynamics: ").append(exact).then(format!(
        " at ω_avg = {} rad/s (ω_max = {} at {}°, ω_min = {} at {}° of crank travel from position {}); the cycle takes {} s; {}",
        n(e.omega_avg()),
        n(e.w_max.0),
        format_sig(e.w_max.1.to_degrees(), 4, Lang::En),
        n(e.w_min.0),
        format_sig(e.w_min.1.to_degrees(), 4, Lang::En),
        d.labels.first().map_or("1", String::as_str),
        n(d.cycle_time),
        match d.spec.constant_moment {
            ConstantMoment::Driving => format!(
                "A_res = {} J, M_drive = {} N·m",
                n(d.cycle.a_res),
                n(d.cycle.m_drive)
            ),
            ConstantMoment::Resisting => format!(
                "A_drive = {} J of the indicator diagrams, the constant resisting moment M_res = {} N·m",
                n(d.cycle.a_drive),
                n(-d.cycle.m_drive)
            ),
        },
    ))
}

/// The textbook routes against the exact flywheel: Wittenbauer's tangents, Merkin's route,
/// and Merkin's on the continuous exact data.
fn routes_note(d: &Dynamics) -> Note {
    let merkin_exact = d.cycle.merkin(d.w_avg, d.spec.delta).0 - d.spec.constant_inertia();
    let continuous = if merkin_exact > 0.0 {
        Note::text(format!("gives {} kg·m²", n(merkin_exact)))
    } else {
        Note::default().with(Finding::NoFlywheelNeeded(NoFlywheel::Continuous {
            j: merkin_exact,
        }))
    };
    Note::text(format!("dynamics: at {} positions ", d.labels.len()))
        .append(route_note(
            d,
            ("Wittenbauer's tangents give", Route::Wittenbauer),
            &d.diagrams.wittenbauer,
            d.delta_of[0],
        ))
        .then(", ")
        .append(route_note(
            d,
            ("Merkin's route gives", Route::Merkin),
            &d.diagrams.merkin,
            d.delta_of[1],
        ))
        .then("; Merkin on the continuous exact data ")
        .append(continuous)
        .then(" (T_II with ω = ω_avg is the method's own error)")
}

/// One textbook route (`name`, `by`): its flywheel against the exact one, or none needed;
/// `delta` the δ it really gives.
fn route_note(d: &Dynamics, (name, by): (&str, Route), r: &super::draw::Route, delta: f64) -> Note {
    let e = &d.exact;
    if r.j_fw <= 0.0 {
        Note::finding(
            format!("{name}: "),
            Finding::NoFlywheelNeeded(NoFlywheel::Reads {
                route: by,
                read: r.read,
            }),
        )
    } else if e.j_fw > 0.0 {
        Note::text(format!(
            "{name} J_flywheel = {} kg·m² ({} %, δ really {})",
            n(r.j_fw),
            pct(r.j_fw, e.j_fw),
            n(delta)
        ))
    } else {
        Note::text(format!(
            "{name} J_flywheel = {} kg·m² where none is needed (δ really {})",
            n(r.j_fw),
            n(delta)
        ))
    }
}

/// The seed's numbers that do not follow from its data: its flywheel, its expression, its
/// table of reduced inertias.
fn seed_notes(d: &Dynamics, seed: &SeedClaims, out: &mut Vec<Note>) {
    let e = &d.exact;
    if let Some(j) = seed.flywheel {
        let got = d.cycle.with_flywheel(j, d.w_avg).delta();
        let exact = if e.j_fw > 0.0 {
            format!(
                "the exact value is {} kg·m² ({} % off)",
                n(e.j_fw),
                pct(j, e.j_fw)
            )
        } else {
            "no flywheel is needed".to_string()
        };
        out.push(Note::text(format!(
            "dynamics: seed error: its flywheel J = {} kg·m² does not follow from its data: {exact}; with J = {} the machine runs at δ = {} = 1/{} instead of {}",
            n(j),
            n(j),
            n(got),
            format_sig(1.0 / got, 3, Lang::En),
            n(d.spec.delta),
        )));
    }
    if let Some(v) = seed.expression_value(d.spec.delta, d.w_avg) {
        out.push(Note::text(format!(
            "dynamics: seed error: its expression μ_T·BD/(δ·ω²) − (J_b + J_d)/2 evaluates to {} kg·m², not the {} it prints",
            n(v),
            seed.flywheel.map_or_else(|| "value".into(), n),
        )));
    }
    if !seed.j_red.is_empty() {
        let c = d.spec.constant_inertia();
        // Where the links move enough for the variable part to be read: at least a tenth of
        // its largest value.
        let top = d.analytic.iter().fold(0.0f64, |m, a| m.max(a.j - c));
        let ratios: Vec<f64> = seed
            .j_red
            .iter()
            .zip(&d.analytic)
            .filter(|(_, a)| a.j - c > 0.1 * top)
            .map(|(s, a)| (s - c) / (a.j - c))
            .collect();
        if let (Some(lo), Some(hi)) = (
            ratios.iter().copied().reduce(f64::min),
            ratios.iter().copied().reduce(f64::max),
        ) {
            out.push(Note::text(format!(
                "dynamics: seed error: its table of reduced inertias J_пр is wrong wherever the links move: its variable part J_пр − {} is {}…{} × the correct one at {} positions",
                n(c),
                format_sig(lo, 3, Lang::En),
                format_sig(hi, 3, Lang::En),
                ratios.len(),
            )));
        }
    }
}
