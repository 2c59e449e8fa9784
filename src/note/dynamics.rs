//! The dynamics section (seed 000 §5): the analytic input of the reduction (the seed's
//! Table 8) with M_пр and J_пр as formulas worked at one position, the reduced moments load
//! by load (Table 9) and the reduced inertias link by link with the links' kinetic energy
//! (Table 10, T_зв worked), the work diagram's scale μ_A = μ_M·μ_φ·H, ΔT, and the flywheel
//! ([`super::flywheel`]).

use super::markup::{frac, inline, num, sym, text, unit};
use super::moments::{
    crank_speed, explain_words, fill, long_sum, product, visible, ONE_LINE_CHARS,
};
use super::rows::{by_position, numbers, of_scene, quantities, Column};
use super::worked::{Printed, Worked};
use super::{NoteError, Writer};
use crate::check::{Key, Method, Symbol};
use crate::dynamics::{Breakdown, Dynamics, LinkShare};
use crate::scene::PlateKind;
use crate::words::{unit_in, MachinesMeaning as M, MachinesNote as N, NoteText as T};

/// The loads over the cycle (a resistance acts on the working stroke only) and the links
/// that count.
fn loads_and_links(d: &Dynamics) -> (Vec<String>, Vec<u32>) {
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
    (loads, links)
}

/// The dynamics: the tables, the reduction worked, the works, the flywheel.
pub(super) fn dynamics(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let d = w.session.dynamics()?;
    w.heading(1, T::Dynamics);
    w.doc.say(w.word(T::DynamicsIntro));
    input_table(w, &d);
    let at = worked_position(&d);
    if let Some(i) = at {
        reduced_moment(w, &d, i)?;
    }
    moment_table(w, &d);
    if let Some(i) = at {
        reduced_inertia(w, &d, i)?;
    }
    inertia_table(w, &d);
    if let Some(i) = at {
        links_energy(w, &d, i);
    }
    work_scale(w, &d);
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
                Method::Integration | Method::Wittenbauer | Method::Mertsalov
            )
    });
    super::flywheel::routes(w, &d);
    super::flywheel::drive(w, &d);
    super::flywheel::size(w, &d);
    // The flywheel's part drawing (a sheet of its own) beside its sizing, then the dynamics
    // sheet's diagrams: the section ends on a small figure, not on a page-high one floated
    // past the next heading.
    let part = w.word(crate::words::DynamicsText::Flywheel);
    w.figures((PlateKind::Flywheel, None), |_| true, |_| part.to_string());
    w.figures((PlateKind::Dynamics, None), |_| true, |own| own.to_string());
    Ok(())
}

/// The position whose reduced moment is largest: the worked example well away from a dead
/// point.
fn worked_position(d: &Dynamics) -> Option<usize> {
    d.tabled().map(|(i, _)| i).max_by(|&a, &b| {
        let m = |i: usize| d.analytic_shares[i].reduced().m().abs();
        m(a).total_cmp(&m(b))
    })
}

/// The tabled positions' labels and rows of `cols` (a row per position of the diagrams).
fn tabled(d: &Dynamics, cols: Vec<Column>) -> (Vec<String>, Vec<Column>) {
    let keep: Vec<usize> = d.tabled().map(|(i, _)| i).collect();
    let labels = keep.iter().map(|&i| d.labels[i].clone()).collect();
    let cols = cols
        .into_iter()
        .map(|c| Column {
            values: keep
                .iter()
                .map(|&i| c.values.get(i).copied().flatten())
                .collect(),
            ..c
        })
        .collect();
    (labels, cols)
}

/// Table 8: the analytic input: the speeds of the centres, the links' ω, the angles of
/// the loads to their points' velocities.
fn input_table(w: &mut Writer<'_, '_>, d: &Dynamics) {
    let lang = w.lang;
    let (loads, links) = loads_and_links(d);
    let load_of = |b: &Breakdown, name: &str| b.loads.iter().find(|l| l.name == name).cloned();
    let link_of = |b: &Breakdown, k: u32| b.links.iter().find(|l| l.link == k).copied();
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
    let (positions, cols) = tabled(d, cols);
    numbers(w, caption, &positions, &cols);
}

/// Table 9: the reduced moment of every load, Σ, and the plans' M_пр against it.
fn moment_table(w: &mut Writer<'_, '_>, d: &Dynamics) {
    let lang = w.lang;
    let (loads, _) = loads_and_links(d);
    let load_of = |b: &Breakdown, name: &str| b.loads.iter().find(|l| l.name == name).cloned();
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
    let (positions, cols) = tabled(d, cols);
    numbers(w, caption, &positions, &cols);
}

/// Table 10: the reduced moments of inertia by links (from the plans), their sum against
/// the twin's, and the links' kinetic energy T_зв = (J_пр − J_const)·ω_ср²/2.
fn inertia_table(w: &mut Writer<'_, '_>, d: &Dynamics) {
    let lang = w.lang;
    let (_, links) = loads_and_links(d);
    let link_of = |b: &Breakdown, k: u32| b.links.iter().find(|l| l.link == k).copied();
    let (an, gr) = (w.word(T::AnalyticShort), w.word(T::GraphicalShort));
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
    let (positions, cols) = tabled(d, cols);
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
}

/// M_пр = Σ F·V·cos α/ω₁ as a formula, then worked at position `i` with the analytic
/// reduction's numbers (the seed's example at its position 5).
fn reduced_moment(w: &mut Writer<'_, '_>, d: &Dynamics, i: usize) -> Result<(), NoteError> {
    let (lang, w1) = (w.lang, crank_speed(w)?.abs());
    let b = &d.analytic_shares[i];
    w.doc.say(w.word(N::ReducedMoment));
    w.formula(&format!(
        "{} = {}",
        sym("M_{пр}"),
        frac(
            &format!(
                "sum_(i) {} {} cos {}",
                sym("F_{i}"),
                sym("V_{i}"),
                sym("α_{i}")
            ),
            &sym("ω_{1}")
        )
    ));
    let items = [
        ("M_{пр}", M::ReducedMoment, "N*m"),
        ("F_{i}", M::LoadForce, "N"),
        ("V_{i}", M::LoadSpeed, "m/s"),
        ("α_{i}", M::LoadAngle, "deg"),
        ("ω_{1}", M::CrankSpeed, "rad/s"),
    ];
    explain_words(w, &items);
    let s = fill(w.word(N::ForPosition), &[("position", d.labels[i].clone())]);
    w.doc.say(&s);
    let mut numbers = Vec::new();
    // A load whose share is a rounding residue (a weight on a horizontal slide) is left out.
    let size: f64 = b.loads.iter().map(|l| l.m_red.abs()).sum();
    for l in b
        .loads
        .iter()
        .filter(|l| crate::scale::residue_to_zero(l.m_red, size) != 0.0)
    {
        match l.angle {
            Some(a) => {
                numbers.push(format!(
                    "{} dot {} dot cos {}°",
                    num(l.magnitude, 5, lang),
                    num(l.speed, 4, lang),
                    num(a.to_degrees(), 4, lang)
                ));
            }
            None => {
                numbers.push(format!(
                    "{} dot {}",
                    num(l.magnitude, 5, lang),
                    num(l.speed, 4, lang)
                ));
            }
        }
    }
    let value = b.reduced().m();
    let result = Printed::si(value, 5, "N*m", lang);
    let key = Key::at_position(Symbol::Moment, "red", &d.labels[i]);
    if visible(&numbers.join(" + ")) <= ONE_LINE_CHARS {
        let substituted = frac(&numbers.join(" + "), &num(w1, 5, lang));
        w.worked(Worked::new(sym("M_{пр}"), "", substituted, result).gives(key));
    } else {
        // The powers on lines of their own, then their total through ω₁.
        let pieces: Vec<(f64, String)> = numbers.into_iter().map(|n| (1.0, n)).collect();
        let power = value * w1;
        let left = format!("{} {}", sym("M_{пр}"), sym("ω_{1}"));
        w.worked(long_sum(&left, &pieces, Printed::si(power, 6, "W", lang)));
        let substituted = frac(&num(power, 6, lang), &num(w1, 5, lang));
        w.worked(Worked::new(sym("M_{пр}"), "", substituted, result).gives(key));
    }
    Ok(())
}

/// J_пр = J_const + Σ(m·(V_S/ω₁)² + J_S·(ω/ω₁)²) as a formula, then worked at position `i`.
fn reduced_inertia(w: &mut Writer<'_, '_>, d: &Dynamics, i: usize) -> Result<(), NoteError> {
    let (lang, w1) = (w.lang, crank_speed(w)?.abs());
    let b = &d.analytic_shares[i];
    w.doc.say(w.word(N::ReducedInertia));
    let ratio = |top: &str| format!("({})^2", frac(&sym(top), &sym("ω_{1}")));
    w.formula(&format!(
        "{} = {} + sum_(i) ({} {} + {} {})",
        sym("J_{пр}"),
        sym("J_{const}"),
        sym("m_{i}"),
        ratio("V_{S i}"),
        sym("J_{S i}"),
        ratio("ω_{i}")
    ));
    let items = [
        ("J_{пр}", M::ReducedInertia, "kg*m^2"),
        ("J_{const}", M::ConstantInertia, "kg*m^2"),
        ("m_{i}", M::LinkMass, "kg"),
        ("V_{S i}", M::CentreSpeed, "m/s"),
        ("J_{S i}", M::LinkInertia, "kg*m^2"),
        ("ω_{i}", M::LinkSpeed, "rad/s"),
    ];
    explain_words(w, &items);
    let s = fill(w.word(N::ForPosition), &[("position", d.labels[i].clone())]);
    w.doc.say(&s);
    let w1s = num(w1, 5, lang);
    let mut numbers = vec![num(b.j_const, 5, lang)];
    for l in &b.links {
        if l.mass > 0.0 && l.v_s != 0.0 {
            numbers.push(format!(
                "{} dot ({})^2",
                num(l.mass, 4, lang),
                frac(&num(l.v_s, 4, lang), &w1s)
            ));
        }
        if l.inertia > 0.0 && l.omega != 0.0 {
            numbers.push(format!(
                "{} dot ({})^2",
                num(l.inertia, 4, lang),
                frac(&num(l.omega.abs(), 4, lang), &w1s)
            ));
        }
    }
    let result = Printed::si(b.reduced().j, 5, "kg*m^2", lang);
    let key = Key::at_position(Symbol::Inertia, "red", &d.labels[i]);
    let row = if visible(&numbers.join(" + ")) <= ONE_LINE_CHARS {
        Worked::new(sym("J_{пр}"), "", numbers.join(" + "), result)
    } else {
        let pieces: Vec<(f64, String)> = numbers.into_iter().map(|n| (1.0, n)).collect();
        long_sum(&sym("J_{пр}"), &pieces, result)
    };
    w.worked(row.gives(key));
    Ok(())
}

/// T_зв = (J_пр − J_const)·ω_ср²/2 as the plans give it at position `i`, and how it
/// differs from the seed's T_зв = J_пр·ω_ср²/2.
fn links_energy(w: &mut Writer<'_, '_>, d: &Dynamics, i: usize) {
    let lang = w.lang;
    let Some(g) = d.graphical.get(i) else {
        return;
    };
    let j_const = d.graphical_shares.first().map_or(0.0, |b| b.j_const);
    w.doc.say(w.word(N::LinksEnergy));
    let t = (g.j - j_const) * d.w_avg * d.w_avg / 2.0;
    w.worked(Worked::new(
        sym("T_{зв}"),
        frac(
            &format!(
                "({} - {}) {}^2",
                sym("J_{пр}"),
                sym("J_{const}"),
                sym("ω_{ср}")
            ),
            "2",
        ),
        frac(
            &format!(
                "({} - {}) dot {}^2",
                num(g.j, 5, lang),
                num(j_const, 5, lang),
                num(d.w_avg, 5, lang)
            ),
            "2",
        ),
        Printed::si(t, 5, "J", lang),
    ));
    let items = [
        ("T_{зв}", M::LinksEnergy, "J"),
        ("ω_{ср}", M::MeanSpeed, "rad/s"),
    ];
    explain_words(w, &items);
    if j_const > 0.0 {
        w.doc.say(w.word(N::LinksEnergySeed));
    }
}

/// The work diagram's scale μ_A = μ_M·μ_φ·H, as the construction takes it.
fn work_scale(w: &mut Writer<'_, '_>, d: &Dynamics) {
    let lang = w.lang;
    let g = &d.diagrams;
    w.doc.say(w.word(N::WorkScale));
    product(
        w,
        "μ_{A}",
        &[sym("μ_{M}"), sym("μ_{φ}"), sym("H")],
        &[
            num(g.scale_m.value(), 4, lang),
            num(g.scale_phi.value(), 4, lang),
            num(g.pole_h, 4, lang),
        ],
        Printed::si(g.scale_a.value(), 5, "J/mm", lang),
    );
    let items = [
        ("μ_{A}", M::WorkScale, "J/mm"),
        ("μ_{M}", M::MomentScale, "N*m/mm"),
        ("μ_{φ}", M::AngleScale, "rad/mm"),
        ("H", M::PoleDistance, "mm"),
    ];
    explain_words(w, &items);
}
