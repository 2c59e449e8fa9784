//! Zhukovsky's lever worked with every arm (seed 000 §2.4), the balancing load by the two
//! routes compared, and the power (seed 000 §2.5: N = P·V/η; an engine's shaft power).

use super::machines::row;
use super::markup::{frac, label, num, sym};
use super::moments::{
    crank_speed, explain_owned, explain_words, fill, lever_couple, meaning, product,
    worked_equation, Arms,
};
use super::worked::{Printed, Worked};
use super::{NoteError, Writer};
use crate::check::{Key, Method, Symbol};
use crate::forces::{ForceSpec, LoadKind, PositionForces, Unknown};
use crate::geom::DVec2;
use crate::words::{
    KinematicsMeaning as K, MachinesMeaning as M, MachinesNote as N, NoteText as T,
};

/// Zhukovsky's lever: its moment equation about the pole with every arm in mm and the
/// balancing force (a gear drive) or moment (a coupling) it gives.
pub(super) fn lever(w: &mut Writer<'_, '_>, f: &PositionForces) -> Result<(), NoteError> {
    let lever = &f.analysis.lever;
    let e = &lever.equation;
    if e.terms.iter().all(|t| t.moment == 0.0) {
        return Ok(());
    }
    w.doc.say(w.word(N::LeverIntro));
    let loads = f.analysis.loads.clone();
    match e.unknown {
        Unknown::Force { value, .. } => {
            worked_equation(w, e, &loads, Arms::Millimetres, None);
            if let Some(l) = lever.crank_arm {
                crank_moment(w, value, l, (lever.m_bal, &f.label));
            }
        }
        Unknown::Arm { .. } | Unknown::Couple { .. } => {
            w.doc.say(w.word(N::LeverMoment));
            let w1 = crank_speed(w)?;
            let mu_v = lever.figure.scale.value();
            lever_couple(w, e, &loads, (mu_v, w1), lever.m_bal);
        }
    }
    Ok(())
}

/// A coupling's balancing moment from the lever's balancing force at the crank pin:
/// M_у = F_у·l_OA (`force`, N; the crank's length `l`, m; `moment` the lever's M_у, N·m, at
/// the position labelled `at`).
fn crank_moment(w: &mut Writer<'_, '_>, force: f64, l: f64, (moment, at): (f64, &str)) {
    let lang = w.lang;
    let (centre, pin) = crank_points(w);
    let crank = format!("l_{{{centre}{pin}}}");
    let sentence = fill(
        w.word(N::LeverCrankMoment),
        &[("pin", pin.clone()), ("centre", centre.clone())],
    );
    w.doc.par(&[label(&sentence)]);
    // The moment's sign is its sense (counter-clockwise positive), the force's magnitude.
    let sign = if moment < 0.0 { "-" } else { "" };
    w.worked(
        Worked::new(
            sym("M_{у}"),
            format!("{sign}{} {}", sym("F_{у}"), sym(&crank)),
            format!(
                "{sign}{} dot {}",
                num(force.abs(), 5, lang),
                num(l, 4, lang)
            ),
            Printed::si(moment, 5, "N*m", lang),
        )
        .gives_by(Key::at_position(Symbol::Moment, "bal", at), Method::Lever),
    );
    explain_owned(w, &[(crank, w.word(K::CrankLength).to_string(), "m")]);
}

/// The names of the crank's centre and pin (`O`, `A`; empty when the session has none).
fn crank_points(w: &Writer<'_, '_>) -> (String, String) {
    let names = w
        .session
        .kin_scales()
        .ok()
        .and_then(|sc| w.session.positions(sc.l).ok())
        .map(|plan| {
            let p = &plan.program;
            let name = |k: usize| p.names.get(k).cloned().unwrap_or_default();
            (name(p.centre), name(p.pin))
        });
    names.unwrap_or_default()
}

/// The balancing load by the polygons against the lever, and the power: the drive's
/// (N = |M_у|·ω₁, the motor's N/η, and the seed's N = P·V/η) or an engine's shaft power.
pub(super) fn balancing_and_power(
    w: &mut Writer<'_, '_>,
    spec: &ForceSpec,
    f: &PositionForces,
    p: &str,
) -> Result<(), NoteError> {
    let lang = w.lang;
    let w1 = crank_speed(w)?;
    let poly = &f.analysis.polygons.driver;
    let lever = &f.analysis.lever;
    if let (Some(a), Some(b)) = (poly.f_bal, lever.f_bal) {
        w.doc.say(w.word(N::CompareForces));
        difference(w, "F_{у}", a, b, true);
    }
    let m_poly = row(&w.report.rows, "M_bal", Method::Polygon, Some(p)).cloned();
    let m_lever = row(&w.report.rows, "M_bal", Method::Lever, Some(p)).cloned();
    let (Some(a), Some(b)) = (m_poly, m_lever) else {
        return Ok(());
    };
    w.doc.say(w.word(T::BalancingBothRoutes));
    difference(w, "M_{у}", a.graphical, b.graphical, true);
    let engine = spec.engine();
    let n = a.graphical.abs() * w1.abs();
    let (intro, meaning_n) = if engine {
        (w.word(N::EnginePower), M::ShaftPower)
    } else {
        (w.word(T::DrivePower), M::DrivePower)
    };
    w.doc.say(intro);
    product(
        w,
        "N",
        &[format!("|{}|", sym("M_{у}")), sym("ω_{1}")],
        &[num(a.graphical.abs(), 5, lang), num(w1.abs(), 5, lang)],
        Printed::si(n, 5, "W", lang),
    );
    explain_words(
        w,
        &[("N", meaning_n, "W"), ("ω_{1}", M::CrankSpeed, "rad/s")],
    );
    if engine {
        return Ok(());
    }
    if let Some(eta) = spec.efficiency {
        w.doc.say(w.word(T::MotorPower));
        w.worked(Worked::new(
            sym("N_{дв}"),
            frac(&sym("N"), &sym("η")),
            frac(&num(n, 5, lang), &num(eta, 3, lang)),
            Printed::si(n / eta, 5, "W", lang),
        ));
        let items = [("N_{дв}", M::MotorPower, "W"), ("η", M::Efficiency, "")];
        explain_words(w, &items);
    }
    resistance_power(w, spec, f, p)
}

/// The seed's N = P·V/η: each working resistance at the position, its point's speed off
/// the velocity plan and the drive's efficiency.
fn resistance_power(
    w: &mut Writer<'_, '_>,
    spec: &ForceSpec,
    f: &PositionForces,
    p: &str,
) -> Result<(), NoteError> {
    let lang = w.lang;
    let sc = w.session.kin_scales()?;
    let names = w.session.positions(sc.l)?.program.names.clone();
    let loads = f.analysis.loads.clone();
    let working = loads
        .iter()
        .filter(|l| l.kind == LoadKind::Resistance && l.force != DVec2::ZERO);
    let mut first = true;
    for l in working {
        let point = names.get(l.at).cloned().unwrap_or_default();
        let plain = point.replace(['_', '{', '}'], "");
        // The speed as the velocity plan reads it (the drawn motion where no row has it).
        let v = row(&w.report.rows, &format!("v_{plain}"), Method::Plan, Some(p))
            .map(|r| r.graphical.abs())
            .unwrap_or_else(|| f.drawn.v.get(l.at).map_or(0.0, |v| v.length()));
        let speed = format!("V_{{{plain}}}");
        if first {
            w.doc.say(w.word(N::PowerPV));
            first = false;
        }
        let force = l.force.length();
        let (top, value) = (
            format!("{} dot {}", num(force, 5, lang), num(v, 4, lang)),
            force * v,
        );
        w.worked(match spec.efficiency {
            Some(eta) => Worked::new(
                sym("N_{пс}"),
                frac(&format!("{} {}", sym(&l.name), sym(&speed)), &sym("η")),
                frac(&top, &num(eta, 3, lang)),
                Printed::si(value / eta, 5, "W", lang),
            ),
            None => Worked::new(
                sym("N_{пс}"),
                format!("{} {}", sym(&l.name), sym(&speed)),
                top,
                Printed::si(value, 5, "W", lang),
            ),
        });
        let items = [
            (
                "N_{пс}".to_string(),
                w.word(M::ResistancePower).to_string(),
                "W",
            ),
            (l.name.clone(), meaning(w, &l.name, &loads), "N"),
            (speed, w.word(M::PointSpeed).to_string(), "m/s"),
        ];
        explain_owned(w, &items);
    }
    Ok(())
}

/// The relative difference `|a − b|/|a|` of two values of one quantity `q` (label markup)
/// by the polygons and by the lever, worked.
fn difference(w: &mut Writer<'_, '_>, q: &str, a: f64, b: f64, explain_delta: bool) {
    let lang = w.lang;
    let diff = (a - b).abs() / a.abs().max(f64::MIN_POSITIVE);
    let pl = format!("{q}^{{{}}}", w.word(T::PolygonShort));
    let lv = format!("{q}^{{{}}}", w.word(T::LeverShort));
    w.worked(Worked::new(
        sym("Δ"),
        frac(
            &format!("|{} - {}|", sym(&pl), sym(&lv)),
            &format!("|{}|", sym(&pl)),
        ),
        frac(
            &format!("|{} - ({})|", num(a, 7, lang), num(b, 7, lang)),
            &num(a.abs(), 7, lang),
        ),
        Printed::new(
            crate::scale::residue_to_zero(diff, 1.0) * 100.0,
            3,
            " %".into(),
            0.01,
            lang,
        ),
    ));
    if explain_delta {
        let d = w.word(M::Difference).to_string();
        explain_owned(w, &[("Δ".into(), d, "")]);
    }
}
