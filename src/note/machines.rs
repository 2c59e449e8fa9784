//! The sections of the machine's studies: the kinetostatics, the dynamics, the cam, the
//! gears, and the balancing and friction of a scene that has them.

use super::markup::{frac, inline, label, num, sym, text, unit};
use super::rows::{by_position, numbers, of_scene, quantities, Column, DIGITS};
use super::{NoteError, Writer};
use crate::check::{Method, Row, Symbol};
use crate::dynamics::{Breakdown, LinkShare};
use crate::scene::PlateKind;
use crate::sheets::captions::{quantity, unit_in, NoteText as T, Text as S};

/// The row of `quantity` by `method` at `position` (`None`: of the whole scene).
fn row<'r>(rows: &'r [Row], q: &str, method: Method, position: Option<&str>) -> Option<&'r Row> {
    rows.iter()
        .find(|r| r.quantity() == q && r.method == method && r.position().as_deref() == position)
}

/// The kinetostatics: the loads worked at each analysed position, the reactions by the
/// groups' polygons, the driving link, Zhukovsky's lever and the balancing moment by both
/// routes, and the drive's power.
pub(super) fn kinetostatics(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let lang = w.lang;
    let spec = w.session.force_spec("the explanatory note")?;
    let positions: Vec<String> = {
        let mut ps: Vec<String> = Vec::new();
        for r in &w.report.rows {
            if r.method == Method::Polygon {
                if let Some(p) = r.position() {
                    if !ps.contains(&p) {
                        ps.push(p);
                    }
                }
            }
        }
        ps
    };
    w.heading(1, T::Kinetostatics);
    w.doc.say(w.word(T::KinetostaticsIntro));
    let w1 = w.session.mechanism("the explanatory note")?.crank.omega;
    for (k, p) in positions.iter().enumerate() {
        w.doc
            .heading(2, &format!("{} {p}", w.word(T::LoadsAtPosition)));
        w.doc.say(w.word(T::InertiaLoads));
        let mut lines = Vec::new();
        for link in &spec.links {
            let k = link.link;
            let centre = link.centre.replace(['_', '{', '}'], "");
            let a = row(
                &w.report.rows,
                &format!("a_{centre}"),
                Method::Plan,
                Some(p),
            );
            let f = row(&w.report.rows, &format!("F_in{k}"), Method::Plan, Some(p));
            if let (Some(a), Some(f)) = (a, f) {
                lines.push(format!(
                    "{} = {} {} = {} dot {} = {}{}",
                    sym(&quantity(Symbol::Force, &format!("in{k}"), lang)),
                    sym(&format!("m_{{{k}}}")),
                    sym(&format!("a_{{{centre}}}")),
                    num(link.mass, 4, lang),
                    num(a.graphical.abs(), DIGITS, lang),
                    num(f.graphical.abs(), DIGITS, lang),
                    unit(&unit_in("N", lang))
                ));
            }
            let e = row(&w.report.rows, &format!("eps_{k}"), Method::Plan, Some(p));
            let mi = row(&w.report.rows, &format!("M_in{k}"), Method::Plan, Some(p));
            if let (Some(e), Some(mi), true) = (e, mi, link.inertia > 0.0) {
                lines.push(format!(
                    "{} = {} {} = {} dot {} = {}{}",
                    sym(&quantity(Symbol::Moment, &format!("in{k}"), lang)),
                    sym(&format!("J_{{S{k}}}")),
                    sym(&format!("ε_{{{k}}}")),
                    num(link.inertia, 4, lang),
                    num(e.graphical.abs(), DIGITS, lang),
                    num(mi.graphical.abs(), DIGITS, lang),
                    unit(&unit_in("N*m", lang))
                ));
            }
        }
        for l in lines {
            w.formula(&l);
        }
        w.doc.say(w.word(T::GroupsEquations));
        group_equations(w, k)?;
        of_scene_at(w, p);
        // The balancing moment by both routes.
        let poly = row(&w.report.rows, "M_bal", Method::Polygon, Some(p)).cloned();
        let lever = row(&w.report.rows, "M_bal", Method::Lever, Some(p)).cloned();
        if let (Some(a), Some(b)) = (poly, lever) {
            w.doc.say(w.word(T::BalancingBothRoutes));
            let diff = (a.graphical - b.graphical).abs() / a.graphical.abs().max(f64::MIN_POSITIVE);
            w.formula(&format!(
                "Δ = {} = {} = {} %",
                frac(
                    &format!(
                        "|{} - {}|",
                        sym(&format!(
                            "{}^{{{}}}",
                            quantity(Symbol::Moment, "bal", lang),
                            w.word(T::PolygonShort)
                        )),
                        sym(&format!(
                            "{}^{{{}}}",
                            quantity(Symbol::Moment, "bal", lang),
                            w.word(T::LeverShort)
                        ))
                    ),
                    &format!("|{}|", sym(&quantity(Symbol::Moment, "bal", lang)))
                ),
                frac(
                    &format!(
                        "|{} - ({})|",
                        num(a.graphical, 7, lang),
                        num(b.graphical, 7, lang)
                    ),
                    &num(a.graphical.abs(), 7, lang)
                ),
                num(crate::scale::residue_to_zero(diff, 1.0) * 100.0, 3, lang),
            ));
            w.doc.par(&[
                text(w.word(T::DrivePower)),
                inline(&format!(
                    "{} = |{}| {} = {} dot {} = {}{}",
                    sym("N"),
                    sym(&quantity(Symbol::Moment, "bal", lang)),
                    sym("ω_{1}"),
                    num(a.graphical.abs(), 5, lang),
                    num(w1, 5, lang),
                    num(a.graphical.abs() * w1, 5, lang),
                    unit(&unit_in("W", lang))
                )),
            ]);
            if let Some(eta) = spec.efficiency {
                let n = a.graphical.abs() * w1;
                w.doc.say(w.word(T::MotorPower));
                w.formula(&format!(
                    "{} = {} = {} = {}{}",
                    sym("N_{дв}"),
                    frac(&sym("N"), &sym("η")),
                    frac(&num(n, 5, lang), &num(eta, 3, lang)),
                    num(n / eta, 5, lang),
                    unit(&unit_in("W", lang))
                ));
            }
        }
        resistance_power(w, k, p)?;
        // The position's sheet: its groups, polygons and lever.
        w.figures(
            (PlateKind::Forces, Some(k)),
            |_| true,
            |own| own.to_string(),
        );
    }
    Ok(())
}

/// The force analysis's rows at position `p`: reactions, arms, the balancing load.
fn of_scene_at(w: &mut Writer<'_, '_>, p: &str) {
    let caption = format!("{} {p}", w.word(T::ReactionsTable));
    let p = p.to_string();
    of_scene(w, &caption, move |r: &Row| {
        r.position().as_deref() == Some(p.as_str())
            && matches!(r.method, Method::Polygon | Method::Lever)
    });
}

/// The dynamics: the analytic input of the reduction (the seed's Table 8), the reduced
/// moments load by load (Table 9) and the reduced moments of inertia link by link with the
/// links' kinetic energy (Table 10), the works and ΔT, the flywheel by Wittenbauer, by
/// Merkin and exactly, and its size.
pub(super) fn dynamics(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let lang = w.lang;
    let d = w.session.dynamics()?;
    w.heading(1, T::Dynamics);
    w.doc.say(w.word(T::DynamicsIntro));
    let positions = d.labels.clone();
    // The loads over the cycle (a resistance acts on the working stroke only) and the links.
    let mut loads: Vec<String> = Vec::new();
    for b in &d.analytic_shares {
        for l in &b.loads {
            if !loads.contains(&l.name) {
                loads.push(l.name.clone());
            }
        }
    }
    let links: Vec<u32> = d
        .analytic_shares
        .first()
        .map(|b| b.links.iter().map(|l| l.link).collect())
        .unwrap_or_default();
    let load_of = |b: &Breakdown, name: &str| b.loads.iter().find(|l| l.name == name).cloned();
    let link_of = |b: &Breakdown, k: u32| b.links.iter().find(|l| l.link == k).copied();
    // Table 8: the analytic input: the speeds of the centres, the links' ω, the angles of
    // the loads to their points' velocities.
    let mut cols = vec![Column::new(
        "φ, °",
        d.travel.iter().map(|t| Some(t.to_degrees())).collect(),
    )];
    for &k in &links {
        let of = |f: fn(&LinkShare) -> f64| -> Vec<Option<f64>> {
            d.analytic_shares
                .iter()
                .map(|b| link_of(b, k).map(|l| f(&l)))
                .collect()
        };
        cols.push(Column::new(
            format!("V_{{S{k}}}, {}", unit_in("m/s", lang)),
            of(|l| l.v_s),
        ));
        cols.push(Column::new(
            format!("ω_{{{k}}}, {}", unit_in("rad/s", lang)),
            of(|l| l.omega.abs()),
        ));
    }
    for name in &loads {
        cols.push(Column::new(
            format!("∠({name}, V), °"),
            d.analytic_shares
                .iter()
                .map(|b| load_of(b, name).and_then(|l| l.angle).map(f64::to_degrees))
                .collect(),
        ));
    }
    let caption = w.word(T::ReductionInput);
    numbers(w, caption, &positions, &cols);
    // Table 9: the reduced moment of every load, Σ, and the plans' M_пр against it.
    let nm = unit_in("N*m", lang);
    // A load whose moment vanishes over the cycle (a weight on a horizontal slide) is 0
    // against the largest reduced moment, not against its own residues.
    let largest = d.analytic.iter().fold(0.0f64, |m, a| m.max(a.m().abs()));
    let mut cols: Vec<Column> = loads
        .iter()
        .map(|name| {
            Column::new(
                format!("M_{{пр}}({name}), {nm}"),
                d.analytic_shares
                    .iter()
                    .map(|b| Some(load_of(b, name).map_or(0.0, |l| l.m_red)))
                    .collect(),
            )
            .against(largest)
        })
        .collect();
    let (an, gr) = (w.word(T::AnalyticShort), w.word(T::GraphicalShort));
    cols.push(Column::new(
        format!("M_{{пр}}, {nm} ({an})"),
        d.analytic.iter().map(|a| Some(a.m())).collect(),
    ));
    cols.push(Column::new(
        format!("M_{{пр}}, {nm} ({gr})"),
        d.graphical.iter().map(|g| Some(g.m())).collect(),
    ));
    let caption = w.word(T::ReducedMoments);
    numbers(w, caption, &positions, &cols);
    // Table 10: the reduced moments of inertia by links (from the plans), their sum against
    // the twin's, and the links' kinetic energy T_зв = (J_пр − J_const)·ω_ср²/2.
    let kgm2 = unit_in("kg*m^2", lang);
    let mut cols: Vec<Column> = links
        .iter()
        .map(|&k| {
            Column::new(
                format!("J_{{пр{k}}}, {kgm2}"),
                d.graphical_shares
                    .iter()
                    .map(|b| link_of(b, k).map(|l| l.j_red))
                    .collect(),
            )
        })
        .collect();
    cols.push(Column::new(
        format!("J_{{пр}}, {kgm2} ({gr})"),
        d.graphical.iter().map(|g| Some(g.j)).collect(),
    ));
    cols.push(Column::new(
        format!("J_{{пр}}, {kgm2} ({an})"),
        d.analytic.iter().map(|a| Some(a.j)).collect(),
    ));
    let j_const = d.graphical_shares.first().map_or(0.0, |b| b.j_const);
    cols.push(Column::new(
        format!("T_{{зв}}, {}", unit_in("J", lang)),
        d.graphical
            .iter()
            .map(|g| Some((g.j - j_const) * d.w_avg * d.w_avg / 2.0))
            .collect(),
    ));
    let caption = w.word(T::ReducedInertias);
    numbers(w, caption, &positions, &cols);
    if j_const > 0.0 {
        w.doc.par(&[
            text(w.word(T::ConstantInertia)),
            inline(&format!(
                "{} = {}{}",
                sym("J_{const}"),
                num(j_const, 5, lang),
                unit(&kgm2)
            )),
        ]);
    }
    let q = quantities(&w.report.rows, |r| {
        r.position().is_some() && r.key.symbol == Symbol::EnergyChange
    });
    let caption = w.word(T::EnergyTable);
    by_position(w, caption, &q);
    w.doc.say(w.word(T::FlywheelRoutes));
    let caption = w.word(T::FlywheelTable);
    of_scene(w, caption, |r| {
        r.position().is_none()
            && matches!(
                r.method,
                Method::Integration | Method::Wittenbauer | Method::Merkin
            )
    });
    // The driving moment from the work of the resistances over the cycle, and the mean power
    // the drive delivers (seed 000 §3: M_д·ω).
    if let (Some(a), Some(m)) = (
        row(&w.report.rows, "A_res", Method::Integration, None),
        row(&w.report.rows, "M_drive", Method::Integration, None),
    ) {
        let (a, m) = (a.graphical.abs(), m.graphical.abs());
        let nm = unit(&unit_in("N*m", lang));
        w.doc.say(w.word(T::DriveMomentAndPower));
        w.formula(&format!(
            "{} = {} = {} = {}{nm}",
            sym("M_{д}"),
            frac(&sym("A_{с}"), "2 π"),
            frac(&num(a, 5, lang), "2 π"),
            num(m, 5, lang),
        ));
        w.formula(&format!(
            "{} = {} {} = {} dot {} = {}{}",
            sym("N_{ср}"),
            sym("M_{д}"),
            sym("ω_{ср}"),
            num(m, 5, lang),
            num(d.w_avg, 5, lang),
            num(m * d.w_avg, 5, lang),
            unit(&unit_in("W", lang)),
        ));
    }
    w.doc.par(&[
        text(w.word(T::ExactFlywheel)),
        inline(&format!(
            "{} = {}{}, {} = {}{}, {} = {}{}",
            sym("J_{м}"),
            num(d.exact.j_fw, 5, lang),
            unit(&unit_in("kg*m^2", lang)),
            sym("ω_{max}"),
            num(d.exact.w_max.0, 5, lang),
            unit(&unit_in("rad/s", lang)),
            sym("ω_{min}"),
            num(d.exact.w_min.0, 5, lang),
            unit(&unit_in("rad/s", lang)),
        )),
    ]);
    let mass = format!(
        "{} = {}{}",
        sym("m"),
        num(d.size.mass, 4, lang),
        unit(&unit_in("kg", lang))
    );
    let dims = std::iter::once(mass).chain(d.size.dims.iter().map(|(name, x)| {
        format!(
            "{} = {}{}",
            sym(name),
            num(x * 1e3, 4, lang),
            unit(w.word(T::MmUnit))
        )
    }));
    let dims: Vec<String> = dims.collect();
    w.doc
        .par(&[text(w.word(T::FlywheelSize)), inline(&dims.join(", "))]);
    w.figures((PlateKind::Dynamics, None), |_| true, |own| own.to_string());
    Ok(())
}

/// Each group's vector equation of equilibrium at the `k`-th analysed position, in the order
/// the groups are solved (from the last attached), then the driving link's: the reactions of
/// its outer pairs, those of the links solved before it (R₄₋₃ = −R₃₋₄), the forces on its
/// links (a couple enters the moment equations only).
fn group_equations(w: &mut Writer<'_, '_>, k: usize) -> Result<(), NoteError> {
    let sc = w.session.kin_scales()?;
    let Some(&index) = w.session.force_positions()?.get(k) else {
        return Ok(());
    };
    let f = w.session.forces(&sc, index)?;
    let a = &f.analysis;
    let forces_on = |links: &[usize]| -> Vec<String> {
        a.loads
            .iter()
            .filter(|l| links.contains(&l.link) && l.force != crate::geom::DVec2::ZERO)
            .map(|l| l.name.clone())
            .collect()
    };
    let name = |from: usize, to: usize| format!("R_{{{from}-{to}}}");
    // The reactions solved so far, as (from, to).
    let mut solved: Vec<(usize, usize)> = Vec::new();
    let mut lines = Vec::new();
    let term = |links: &[usize], outer: Vec<(usize, usize)>, solved: &mut Vec<(usize, usize)>| {
        let mut terms: Vec<String> = outer.iter().map(|&(a, b)| name(a, b)).collect();
        // A link solved before acts back on this one.
        terms.extend(
            solved
                .iter()
                .filter(|(from, _)| links.contains(from))
                .map(|&(from, to)| name(to, from)),
        );
        terms.extend(forces_on(links));
        solved.extend(outer);
        terms
    };
    for (n, g) in a.polygons.groups.iter().enumerate() {
        let outer = g
            .reactions
            .iter()
            .take(2)
            .map(|r| (r.pair.from, r.pair.to))
            .collect();
        let terms = term(&g.links, outer, &mut solved);
        lines.push((
            format!(
                "{}. {} {}–{}:",
                n + 1,
                w.word(S::Group),
                g.links[0],
                g.links[1]
            ),
            format!("{} = 0", terms.join(" + ")),
        ));
    }
    let crank = w.session.mechanism("the explanatory note")?.crank.link as usize;
    let driver = &a.polygons.driver;
    let mut terms = term(
        &[crank],
        vec![(driver.reaction.pair.from, driver.reaction.pair.to)],
        &mut solved,
    );
    if driver.f_bal.is_some() {
        terms.push(quantity(Symbol::Force, "bal", w.lang));
    }
    lines.push((
        format!("{}. {}:", lines.len() + 1, w.word(S::DrivingLink)),
        format!("{} = 0", terms.join(" + ")),
    ));
    for (head, eq) in lines {
        w.doc.par(&[text(&head), label(&eq)]);
    }
    Ok(())
}

/// The power of every working resistance at the `k`-th analysed position `p`: N = F·V, the
/// force and its point's speed off the velocity plan (the seed's N = P·V beside N = M_у·ω₁).
fn resistance_power(w: &mut Writer<'_, '_>, k: usize, p: &str) -> Result<(), NoteError> {
    let lang = w.lang;
    let sc = w.session.kin_scales()?;
    let Some(&index) = w.session.force_positions()?.get(k) else {
        return Ok(());
    };
    let f = w.session.forces(&sc, index)?;
    let names = &w.session.positions(sc.l)?.program.names;
    let mut lines = Vec::new();
    for l in f.analysis.loads.iter().filter(|l| {
        l.kind == crate::forces::LoadKind::Resistance && l.force != crate::geom::DVec2::ZERO
    }) {
        let point = names
            .get(l.at)
            .map(|n| n.replace(['_', '{', '}'], ""))
            .unwrap_or_default();
        let Some(v) = row(&w.report.rows, &format!("v_{point}"), Method::Plan, Some(p)) else {
            continue;
        };
        let (force, speed) = (l.force.length(), v.graphical.abs());
        lines.push(format!(
            "{} = {} {} = {} dot {} = {}{}",
            sym("N_{пс}"),
            sym(&l.name),
            sym(&format!("V_{{{point}}}")),
            num(force, 5, lang),
            num(speed, 4, lang),
            num(force * speed, 5, lang),
            unit(&unit_in("W", lang))
        ));
    }
    if !lines.is_empty() {
        w.doc.say(w.word(T::ResistancePower));
        for l in lines {
            w.formula(&l);
        }
    }
    Ok(())
}
