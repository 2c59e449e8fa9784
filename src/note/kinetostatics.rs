//! The kinetostatics section (seed 000 §2): at each analysed position the inertia loads
//! worked (F_и = m·a_S, M_и = J_S·ε) with their points of application; for every group, from
//! the last attached, its vector equation of equilibrium, its moment equations worked with
//! the arms read off its drawing and the force polygon at μ_F; the driving link's ΣM = 0;
//! Zhukovsky's lever with every arm; the balancing load by both routes and the power.

use super::machines::row;
use super::markup::{label, num, sym};
use super::moments::{
    explain_owned, fill, meaning, moments_head, point_name, vector, worked_equation, Arms,
};
use super::rows::{of_scene, DIGITS};
use super::worked::{Printed, Worked};
use super::{NoteError, Writer};
use crate::check::{Method, Row, Symbol};
use crate::forces::{ForceSpec, LoadKind, PositionForces, Unknown};
use crate::geom::DVec2;
use crate::scale::{format_sig, Lang};
use crate::scene::PlateKind;
use crate::words::{plain, quantity, MachinesMeaning as M, MachinesNote as N, NoteText as T};

/// The kinetostatics: every analysed position in turn.
pub(super) fn kinetostatics(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let spec = w.session.force_spec("the explanatory note")?;
    let sc = w.session.kin_scales()?;
    let indices = w.session.force_positions()?;
    w.heading(1, T::Kinetostatics);
    w.doc.say(w.word(T::KinetostaticsIntro));
    for (k, &index) in indices.iter().enumerate() {
        let f = w.session.forces(&sc, index)?;
        let p = f.label.clone();
        w.doc
            .heading(2, &format!("{} {p}", w.word(T::LoadsAtPosition)));
        inertia(w, spec, &f, &p);
        gas(w, spec, &f, index)?;
        groups(w, &f)?;
        of_scene_at(w, &p);
        super::zhukovsky::lever(w, &f)?;
        super::zhukovsky::balancing_and_power(w, spec, &f, &p)?;
        // The position's sheet: its groups, polygons and lever.
        w.figures(
            (PlateKind::Forces, Some(k)),
            |_| true,
            |own| own.to_string(),
        );
    }
    Ok(())
}

/// The inertia force and moment of every link with a mass, worked from its centre's
/// acceleration and its angular acceleration off the acceleration plan.
fn inertia(w: &mut Writer<'_, '_>, spec: &ForceSpec, f: &PositionForces, p: &str) {
    let lang = w.lang;
    w.doc.say(w.word(N::InertiaIntro));
    let Ok(sc) = w.session.kin_scales() else {
        return;
    };
    let Ok(plan) = w.session.positions(sc.l) else {
        return;
    };
    let names = plan.program.names.clone();
    let mut points = Vec::new();
    for link in &spec.links {
        let k = link.link;
        let at = names.iter().position(|n| *n == link.centre);
        let centre = link.centre.replace(['_', '{', '}'], "");
        let a = at
            .and_then(|i| f.drawn.a.get(i))
            .map_or(0.0, |a| a.length());
        let force = row(&w.report.rows, &format!("F_in{k}"), Method::Plan, Some(p));
        if let Some(force) = force.filter(|r| r.graphical != 0.0) {
            // In the loads' own notation, as every symbol of the source: its scripts are
            // localised once, at the end, and a symbol is explained once whatever the language.
            let fi = quantity(Symbol::Force, &format!("in{k}"), Lang::Ru);
            let (m, acc) = (format!("m_{{{k}}}"), format!("a_{{{centre}}}"));
            w.worked(Worked::new(
                sym(&fi),
                format!("{} {}", sym(&m), sym(&acc)),
                format!("{} dot {}", num(link.mass, 4, lang), num(a, DIGITS, lang)),
                Printed::si(force.graphical.abs(), DIGITS, "N", lang),
            ));
            let ks = [("k", k.to_string())];
            explain_owned(
                w,
                &[
                    (fi, fill(w.word(M::InertiaForce), &ks), "N"),
                    (m, fill(w.word(M::Mass), &ks), "kg"),
                    (acc, fill(w.word(M::CentreAcceleration), &ks), "m/s^2"),
                ],
            );
            points.push(centre.clone());
        }
        let eps = f.drawn.eps.get(k as usize).copied().unwrap_or(0.0);
        let moment = row(&w.report.rows, &format!("M_in{k}"), Method::Plan, Some(p));
        if let (Some(mi), true) = (moment, link.inertia > 0.0) {
            if mi.graphical == 0.0 {
                continue;
            }
            let mq = quantity(Symbol::Moment, &format!("in{k}"), Lang::Ru);
            let (j, e) = (format!("J_{{S{k}}}"), format!("ε_{{{k}}}"));
            w.worked(Worked::new(
                sym(&mq),
                format!("{} {}", sym(&j), sym(&e)),
                format!(
                    "{} dot {}",
                    num(link.inertia, 4, lang),
                    num(eps.abs(), DIGITS, lang)
                ),
                Printed::si(mi.graphical.abs(), DIGITS, "N*m", lang),
            ));
            let ks = [("k", k.to_string())];
            explain_owned(
                w,
                &[
                    (mq, fill(w.word(M::InertiaMoment), &ks), "N*m"),
                    (j, fill(w.word(M::CentralInertia), &ks), "kg*m^2"),
                    (e, fill(w.word(M::AngularAcceleration), &ks), "rad/s^2"),
                ],
            );
        }
    }
    if !points.is_empty() {
        let s = fill(w.word(N::InertiaApplied), &[("points", points.join(", "))]);
        w.doc.par(&[label(&s)]);
    }
}

/// An engine's gas forces at the position `index`: for each cylinder its cycle angle, the
/// pressure its indicator diagram gives there and F_д = p·πd²/4 on its piston.
fn gas(
    w: &mut Writer<'_, '_>,
    spec: &ForceSpec,
    f: &PositionForces,
    index: usize,
) -> Result<(), NoteError> {
    if spec.indicators.is_empty() {
        return Ok(());
    }
    let lang = w.lang;
    let poses = w.session.poses()?;
    let Some(phi) = poses.positions.get(index).map(|p| p.phi) else {
        return Ok(());
    };
    w.doc.say(w.word(N::GasForces));
    for c in &spec.indicators {
        let Some(r) = c.reading(&poses.program, &f.drawn, phi, f.sense) else {
            continue;
        };
        let piston = plain(&c.point);
        let fd = r.name();
        let (ps, ds) = (format!("p_{{{piston}}}"), format!("d_{{{piston}}}"));
        w.worked(Worked::new(
            sym(&fd),
            format!("{} pi {}^2 / 4", sym(&ps), sym(&ds)),
            format!(
                "{} dot 10^6 dot pi dot {}^2 / 4",
                num(r.pressure * 1e-6, 4, lang),
                num(c.bore, 4, lang)
            ),
            Printed::si(r.force, DIGITS, "N", lang),
        ));
        let theta = format!("{}°", format_sig(r.theta.to_degrees(), 4, lang));
        explain_owned(
            w,
            &[
                (
                    fd,
                    fill(w.word(M::GasForce), &[("k", r.slider.to_string())]),
                    "N",
                ),
                (
                    ps,
                    fill(
                        w.word(M::GasPressure),
                        &[("p", piston.clone()), ("theta", theta)],
                    ),
                    "Pa",
                ),
                (ds, fill(w.word(M::Bore), &[("p", piston)]), "m"),
            ],
        );
    }
    Ok(())
}

/// Each group from the last attached, then the driving link: its vector equation with the
/// reactions of its outer pairs, those of the links solved before it and its loads; its
/// moment equations worked; its polygon's scale.
fn groups(w: &mut Writer<'_, '_>, f: &PositionForces) -> Result<(), NoteError> {
    let a = &f.analysis;
    let loads = a.loads.clone();
    let forces_on = |links: &[usize]| -> Vec<String> {
        a.loads
            .iter()
            .filter(|l| links.contains(&l.link) && l.force != DVec2::ZERO)
            .map(|l| l.name.clone())
            .collect()
    };
    let name = |from: usize, to: usize| format!("R_{{{from}-{to}}}");
    // The reactions solved so far, as (from, to).
    let mut solved: Vec<(usize, usize)> = Vec::new();
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
    for g in &a.polygons.groups {
        let outer = g
            .reactions
            .iter()
            .take(2)
            .map(|r| (r.pair.from, r.pair.to))
            .collect();
        let terms = term(&g.links, outer, &mut solved);
        let head = fill(
            w.word(N::GroupEquation),
            &[("links", format!("{}–{}", g.links[0], g.links[1]))],
        );
        w.doc.par(&[label(&head)]);
        vector_equation(w, &terms, &loads);
        for e in &g.equations {
            if e.terms.iter().all(|t| t.moment == 0.0) {
                continue;
            }
            let point = e.about.and_then(|p| point_name(w, p)).unwrap_or_default();
            moments_head(w, &e.links, &point);
            let length = match &e.unknown {
                Unknown::Force { label: None, .. } => e.links.first().copied(),
                _ => None,
            };
            worked_equation(w, e, &loads, Arms::Metres, length);
            if let Unknown::Force { value, .. } = e.unknown {
                if value < 0.0 {
                    w.doc.say(w.word(N::OppositeSign));
                }
            }
        }
        polygon_scale(w, f, (&g.links, g.polygon.scale.value()));
    }
    let crank = w.session.mechanism("the explanatory note")?.crank.link as usize;
    let driver = &a.polygons.driver;
    let mut terms = term(
        &[crank],
        vec![(driver.reaction.pair.from, driver.reaction.pair.to)],
        &mut solved,
    );
    if driver.f_bal.is_some() {
        terms.push(quantity(Symbol::Force, "bal", Lang::Ru));
    }
    let head = fill(w.word(N::DriverEquation), &[("link", crank.to_string())]);
    w.doc.par(&[label(&head)]);
    vector_equation(w, &terms, &loads);
    let e = &driver.equation;
    let point = e.about.and_then(|p| point_name(w, p)).unwrap_or_default();
    let s = fill(w.word(N::DriverMoments), &[("point", point)]);
    w.doc.par(&[label(&s)]);
    worked_equation(w, e, &loads, Arms::Metres, None);
    polygon_scale(w, f, (&[crank], driver.polygon.scale.value()));
    Ok(())
}

/// `Σ F⃗ = 0` of the forces named `terms` (label markup), each new symbol explained.
fn vector_equation(w: &mut Writer<'_, '_>, terms: &[String], loads: &[crate::forces::Load]) {
    let vectors: Vec<String> = terms.iter().map(|t| vector(t)).collect();
    w.formula(&format!("{} = 0", vectors.join(" + ")));
    let items: Vec<(String, String, &str)> = terms
        .iter()
        .map(|t| (t.clone(), meaning(w, t, loads), "N"))
        .collect();
    explain_owned(w, &items);
}

/// The polygon's μ_F `mu`, shown by the largest load on `links` drawn at it.
fn polygon_scale(w: &mut Writer<'_, '_>, f: &PositionForces, (links, mu): (&[usize], f64)) {
    let lang = w.lang;
    let largest = f
        .analysis
        .loads
        .iter()
        .filter(|l| links.contains(&l.link) && l.force != DVec2::ZERO)
        .filter(|l| l.kind != LoadKind::Reaction)
        .max_by(|a, b| a.force.length().total_cmp(&b.force.length()));
    let Some(l) = largest else {
        return;
    };
    let value = l.force.length();
    let s = fill(
        w.word(N::PolygonScale),
        &[
            ("mu", crate::scale::format_sig(mu, 4, lang)),
            ("force", l.name.clone()),
            ("value", crate::scale::format_sig(value, 5, lang)),
            ("mm", crate::scale::format_sig(value / mu, 4, lang)),
        ],
    );
    w.doc.par(&[label(&s)]);
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
