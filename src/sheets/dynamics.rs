//! Plate "Динамика машины" (seed 000 §5): the diagram of the reduced moment of resistance with
//! the works A_с (graphical integration) and A_д, ΔT, J_пр, the energy–mass diagram with its
//! tangents, Mertsalov's T_I, ω(φ) with the flywheel, the data — the flywheel sized from the
//! construction's J_м, with the δ each J_м gives — and Tables 9/10 in the seed's shape
//! (graphical | analytic | error). One A1 sheet (more if the views need it); the flywheel's
//! part drawing is a sheet of its own ([`super::flywheel`]).

use super::digits::{value as num, Column as Precision};
use super::layout::{keyed, lay_out, quantity, Block, Column, Results};
use super::BuildError;
use crate::check::{Finding, NoFlywheel, Route};
use crate::dynamics::{ConstantMoment, Dynamics, FlywheelKind};
use crate::geom::DVec2;
use crate::plate::{Plate, Sheet, SheetSize, TableBlock};
use crate::scale::{format_fixed, format_sig, Key, Lang, Scale};
use crate::study::Session;
use crate::words::{unit_in, DynamicsText, Text};

/// Text height of the data lines and the tables, mm.
const TEXT_MM: f64 = 3.5;
const TABLE_MM: f64 = 2.5;

/// Build the dynamics sheet of the scene.
pub fn build(session: &Session<'_>, lang: Lang) -> Result<Vec<Plate>, BuildError> {
    let scene = session.scene();
    let d = session.dynamics()?;
    let g = &d.diagrams;
    // An engine: the driving side varies, the resisting moment is constant.
    let engine = d.spec.constant_moment == ConstantMoment::Resisting;
    // An energy scale is written μ_T (its quantity's symbol is A): `energy` marks it.
    let cap = |what: &str, scales: &[(Scale, bool)]| {
        let s: Vec<String> = scales
            .iter()
            .map(|&(s, energy)| {
                let c = s.caption(lang);
                if energy {
                    c.replacen("μ_{A}", "μ_{T}", 1)
                } else {
                    c
                }
            })
            .collect();
        format!("{what}, {}", s.join("; "))
    };
    let h = format!(
        "H = {} {}",
        format_sig(g.pole_h, 4, lang),
        unit_in("mm", lang)
    );
    let mut blocks = vec![
        Block::view(
            g.work.clone(),
            format!(
                "{}; {h}",
                cap(
                    if engine {
                        "M_{д}, A_{д}, A_{с}"
                    } else {
                        "M_{с}, A_{с}, A_{д}"
                    },
                    &[(g.scale_m, false), (g.scale_a, false), (g.scale_phi, false)]
                )
            ),
            keyed(Key::DynamicsScaleM, g.scale_m),
        ),
        Block::view(
            g.energy.clone(),
            cap("ΔT = A_{д} − A_{с}", &[(g.scale_t, true)]),
            keyed(Key::DynamicsScaleT, g.scale_t),
        ),
        Block::view(
            g.inertia.clone(),
            cap("J_{пр}(φ)", &[(g.scale_j, false)]),
            keyed(Key::DynamicsScaleJ, g.scale_j),
        ),
        Block::view(
            g.wittenbauer_figure.clone(),
            cap(
                DynamicsText::EnergyMass.get(lang),
                &[(g.scale_tw, true), (g.scale_j, false)],
            ),
            keyed(Key::DynamicsScaleT, g.scale_tw),
        ),
    ];
    blocks.extend([
        Block::view(
            g.mertsalov_figure.clone(),
            cap("T_{I} = ΔT − ω_{ср}^2 J_{пр}/2", &[(g.scale_t1, true)]),
            None,
        ),
        Block::view(
            d.omega.clone(),
            cap(
                DynamicsText::OmegaWithFlywheel.get(lang),
                &[(d.omega.scale, false)],
            ),
            None,
        ),
    ]);
    // An engine's indicator diagrams, whose gas forces give M_д.
    if session.scene().forces.is_some() {
        blocks.extend(super::indicator::views(session, lang)?);
    }
    let mut lines = data_lines(&d, lang);
    lines.push(String::new());
    lines.push(super::drafting_line(
        session.drafting(),
        super::Errs::Diagrams,
        lang,
    ));
    blocks.push(Block::Text {
        lines,
        size_mm: TEXT_MM,
    });
    let sheet = Sheet {
        size: SheetSize::A1,
        landscape: true,
    };
    // A row per position: the tables continue on further sheets when long.
    for table in [positions_table(&d, lang), results_table(&d, lang)] {
        blocks.extend(
            super::layout::split_table(&sheet, table, lang)
                .into_iter()
                .map(Block::Table),
        );
    }
    // Diagrams only: nothing of the machine is drawn at a length scale.
    let title = super::title_block(scene, DynamicsText::Title.get(lang), None, lang);
    lay_out(sheet, blocks, "dynamics", &title, lang)
}

/// The data and the results as text.
fn data_lines(d: &Dynamics, lang: Lang) -> Vec<String> {
    let s = &d.spec;
    let kgm2 = unit_in("kg*m^2", lang);
    let rad_s = unit_in("rad/s", lang);
    let mut out = vec![Text::Data.get(lang).to_string()];
    out.push(format!(
        "ω_{{ср}} = {} {}, δ = {} = 1/{}",
        num(d.w_avg, lang),
        rad_s,
        num(s.delta, lang),
        format_sig(1.0 / s.delta, 3, lang)
    ));
    for c in &s.constant {
        // The part the inertia belongs to, named where the catalogue knows it: J_{ред}
        // (редуктор).
        let part = crate::words::symbols::part(&c.name, lang)
            .map_or_else(String::new, |p| format!(" ({p})"));
        out.push(format!(
            "J_{{{}}}{part} = {} {kgm2}",
            c.name,
            num(c.inertia, lang)
        ));
    }
    out.push(String::new());
    out.push(DynamicsText::Flywheel.get(lang).to_string());
    let e = &d.exact;
    let none = DynamicsText::NoFlywheel.get(lang);
    // The verdicts "no flywheel is needed": the exact one (`None`) and each route's.
    let found: Vec<NoFlywheel> = crate::dynamics::findings(d)
        .into_iter()
        .filter_map(|f| match f {
            Finding::NoFlywheelNeeded(n) => Some(n),
            _ => None,
        })
        .collect();
    let unneeded = |by: Option<Route>| {
        found.iter().any(|n| match *n {
            NoFlywheel::Exact { .. } => by.is_none(),
            NoFlywheel::Reads { route, .. } => by == Some(route),
            NoFlywheel::Continuous { .. } => false,
        })
    };
    let j_or_none = |j: f64, by: Option<Route>| {
        if unneeded(by) {
            none.to_string()
        } else {
            format!("{} {kgm2}", num(j, lang))
        }
    };
    // Each J_м with the δ it really gives (the exact one gives the δ asked for).
    let with_delta = |j: String, delta: f64| {
        if j == none {
            j
        } else {
            format!("{j} (δ = {})", num(delta, lang))
        }
    };
    out.push(format!(
        "J_{{м}} {} = {}; ω_{{max}} = {}, ω_{{min}} = {} {}",
        DynamicsText::Exact.get(lang),
        with_delta(j_or_none(e.j_fw, None), e.delta()),
        num(e.w_max.0, lang),
        num(e.w_min.0, lang),
        rad_s
    ));
    // Each route's formula with what its diagram gave (its own μ_T), then J_м and its δ.
    let g = &d.diagrams;
    for (k, route, reading) in [
        (0, Route::Wittenbauer, &g.wittenbauer),
        (1, Route::Mertsalov, &g.mertsalov),
    ] {
        let (name, formula, worked) = route_formula(d, route, lang);
        let j = j_or_none(reading.j_fw, Some(route));
        out.push(if j == none {
            format!("J_{{м}} ({name}) = {formula} = {j}")
        } else {
            format!(
                "J_{{м}} ({name}) = {formula} = {worked} = {}",
                with_delta(j, d.delta_of[k])
            )
        });
    }
    let exact_delta = found.iter().find_map(|n| match *n {
        NoFlywheel::Exact { delta, .. } => Some(delta),
        _ => None,
    });
    if let Some(delta) = exact_delta {
        out.push(format!("{none}: δ = {}", num(delta, lang)));
        return out;
    }
    let z = &d.size;
    // The construction finds none needed: nothing to size (its line says so).
    if z.d <= 0.0 {
        return out;
    }
    let kind = match z.kind {
        FlywheelKind::Rim => DynamicsText::Rim.get(lang),
        FlywheelKind::Disc => DynamicsText::Disc.get(lang),
    };
    // The D found with its mass (the table's D_м and m_м), then the D taken with the mass
    // worked out at it (the part's, sheet of the flywheel).
    let (f, mm, kg) = (&d.spec.flywheel, unit_in("mm", lang), unit_in("kg", lang));
    out.push(format!(
        "{kind}, {}: D = (J_{{м}}/(K_{{j}}ρ))^{{1/5}} = {} {mm}, m = K_{{m}}ρD^3 = {} {kg}; {}: m = {}·{}·{}^3 = {} {kg}",
        DynamicsText::SizedByConstruction.get(lang),
        format_fixed(z.d * 1e3, 1, lang),
        Precision::of([z.mass]).cell(z.mass, lang),
        DynamicsText::Taken
            .get(lang)
            .replace("{d}", &format_fixed(d.made.d * 1e3, 0, lang))
            .replace("{mm}", &mm),
        num(f.k_m, lang),
        num(f.rho, lang),
        num(d.made.d, lang),
        num(d.made.mass, lang),
    ));
    out
}

/// Tables 9/10 in the seed's shape: per position M_с, J_пр (velocity plans | twin | error)
/// and ΔT (graphical integration | exact | error).
fn positions_table(d: &Dynamics, lang: Lang) -> TableBlock {
    // The error of the row's cells `(g, a)` as printed (a reader checking the row finds it,
    // issue 45), of the values `(gv, av)`: per cent of `of`, or of |a| when `None`
    // (digits::printed_error); «—» where `av` is zero against `scale`.
    let err_of = |(g, a): (&str, &str), (gv, av): (f64, f64), of: Option<f64>, scale: f64| {
        let zero = av.abs() <= 1e-9 * scale.max(1e-300) || av == 0.0;
        let fraction = match of {
            _ if zero => None,
            None => super::digits::printed_error(g, a, Some((gv - av) / av.abs()), lang),
            Some(of) => match (
                super::digits::printed(g, lang),
                super::digits::printed(a, lang),
            ) {
                (Some(g), Some(a)) => Some((g - a) / of),
                _ => Some((gv - av) / of),
            },
        };
        fraction.map_or(super::digits::NO_VALUE.to_string(), |e| {
            super::digits::error_pct(e, lang)
        })
    };
    let m_scale = d.analytic.iter().fold(0.0f64, |m, r| m.max(r.m().abs()));
    // The varying side's moment: M_с = −M_пр (a machine), M_д = M_пр (an engine).
    let (sgn, mv) = match d.spec.constant_moment {
        ConstantMoment::Driving => (-1.0, "M_{с}"),
        ConstantMoment::Resisting => (1.0, "M_{д}"),
    };
    let dt = |i: usize| {
        (
            d.diagrams.delta_t.get(i).copied().unwrap_or(f64::NAN),
            d.cycle.delta_t(d.travel[i]),
        )
    };
    // Each quantity's two columns at one precision (digits::Column: four digits of its
    // largest), as a drawing's table gives it.
    let both = |f: &dyn Fn(usize) -> (f64, f64)| {
        Precision::of(d.tabled().flat_map(|(i, _)| {
            let (g, a) = f(i);
            [g, a]
        }))
    };
    let m_col = both(&|i| (d.graphical[i].m(), d.analytic[i].m()));
    let j_col = both(&|i| (d.graphical[i].j, d.analytic[i].j));
    let t_col = both(&dt);
    let t_scale = d.tabled().fold(0.0f64, |m, (i, _)| m.max(dt(i).1.abs()));
    let rows = d
        .tabled()
        .map(|(i, label)| {
            let (g, a) = (&d.graphical[i], &d.analytic[i]);
            let (dt, dt_a) = dt(i);
            let m = (m_col.cell(sgn * g.m(), lang), m_col.cell(sgn * a.m(), lang));
            let j = (j_col.cell(g.j, lang), j_col.cell(a.j, lang));
            let t = (t_col.cell(dt, lang), t_col.cell(dt_a, lang));
            vec![
                label.clone(),
                format_fixed(d.travel[i].to_degrees(), 0, lang),
                m.0.clone(),
                m.1.clone(),
                // M_с printed with the sign of the varying side: δ of the cells as printed.
                err_of((&m.0, &m.1), (sgn * g.m(), sgn * a.m()), None, m_scale),
                j.0.clone(),
                j.1.clone(),
                err_of((&j.0, &j.1), (g.j, a.j), None, 1.0),
                t.0.clone(),
                t.1.clone(),
                // ΔT is an integral read off its diagram: its error per cent of the diagram's
                // largest ordinate (the V engine's pos. 2 is 5 J off a 20 J value).
                err_of((&t.0, &t.1), (dt, dt_a), Some(t_scale), t_scale),
            ]
        })
        .collect();
    let nm = unit_in("N*m", lang);
    let kg = unit_in("kg*m^2", lang);
    let j = unit_in("J", lang);
    TableBlock {
        at: DVec2::ZERO,
        title: DynamicsText::Tables.get(lang).replace(
            "{M}",
            if sgn > 0.0 {
                "M_{д} = M_{пр}"
            } else {
                "M_{с} = −M_{пр}"
            },
        ),
        columns: vec![
            (Text::Number.get(lang).into(), 8.0),
            ("φ, °".into(), 10.0),
            (format!("{mv}, {nm}"), 18.0),
            (format!("{mv}*, {nm}"), 18.0),
            ("δ_{M}, %".into(), 12.0),
            (format!("J_{{пр}}, {kg}"), 24.0),
            (format!("J_{{пр}}*, {kg}"), 24.0),
            ("δ_{J}, %".into(), 12.0),
            (format!("ΔT, {j}"), 16.0),
            (format!("ΔT*, {j}"), 16.0),
            ("δ_{ΔT}, %".into(), 12.0),
        ],
        rows,
        size_mm: TABLE_MM,
    }
}

/// A flywheel route's name, formula and the formula with its numbers: Wittenbauer's
/// `μ_{T}·kl/(δω_{ср}^2)` at the energy–mass diagram's μ_T, Mertsalov's `ΔT_{I}/(δω_{ср}^2) −
/// J_{ред} − J_{кс}` (the constant inertias, which T_I carries, taken off).
fn route_formula(d: &Dynamics, route: Route, lang: Lang) -> (&'static str, String, String) {
    let g = &d.diagrams;
    let under = format!("({}·{}^2)", num(d.spec.delta, lang), num(d.w_avg, lang));
    if route == Route::Wittenbauer {
        let mu = g.scale_tw.value();
        return (
            DynamicsText::Wittenbauer.get(lang),
            "μ_{T}·kl/(δω_{ср}^2)".into(),
            format!(
                "{}·{}/{under}",
                num(mu, lang),
                num(g.wittenbauer.range / mu, lang)
            ),
        );
    }
    let (mut formula, mut worked) = (
        "ΔT_{I}/(δω_{ср}^2)".to_string(),
        format!("{}/{under}", num(g.mertsalov.range, lang)),
    );
    for c in &d.spec.constant {
        formula.push_str(&format!(" − J_{{{}}}", c.name));
        worked.push_str(&format!(" − {}", num(c.inertia, lang)));
    }
    (DynamicsText::Mertsalov.get(lang), formula, worked)
}

/// The results of the whole cycle: graphical | unit | analytic | error.
fn results_table(d: &Dynamics, lang: Lang) -> TableBlock {
    let rows: Vec<_> = crate::dynamics::rows(d)
        .into_iter()
        .filter(|r| r.position().is_none())
        .collect();
    let title = if d.spec.constant_moment == ConstantMoment::Resisting {
        DynamicsText::EngineResults
    } else {
        DynamicsText::MachineResults
    };
    super::layout::results_table(
        &Results {
            title: title.get(lang).into(),
            columns: &[
                (Column::Quantity, 16.0),
                (Column::Method, 28.0),
                (Column::Unit, 14.0),
                (Column::Graphical, 20.0),
                (Column::Exact, 20.0),
                (Column::Error, 14.0),
            ],
            name: &|r| quantity(r, lang),
            unit: &|r| match crate::words::shown_unit(r.key.symbol).1 {
                "1" => String::new(),
                u => unit_in(u, lang),
            },
            // A row's two values at one precision, the larger to four digits.
            value: &|r, x, _| {
                let k = crate::words::shown_unit(r.key.symbol).0;
                super::digits::Column::of([r.graphical * k, r.analytic * k]).cell(x * k, lang)
            },
            graphical: &|_| None,
            size_mm: TABLE_MM,
        },
        &rows,
        lang,
    )
}
