//! The values of the plans worked at the worked position with their formulas: the
//! similarity proportions of the further points of a turning link (pd = pb₃·CD/CB), the
//! links' rates (ω = V/l, ε = aτ/l), the normal parts aⁿ = ω²·l and the Coriolis parts
//! a^k = 2·ω·V_rel with the rule of their direction.

use super::equations::{velocity_equations, Equation, Kind, Relative};
use super::markup::{frac, num, sym, unit};
use super::plan_reads::{explain_one, segment, Plans};
use super::worked::{Printed, Worked};
use super::Writer;
use crate::check::Symbol;
use crate::scale::Lang;
use crate::words::{plain, KinematicsMeaning as M, KinematicsNote as K, NoteText as T};

/// The similarity proportions of the further points of a link turning about a fixed pivot
/// at the worked position: px = pb·OX/OB, the images' lengths and the plan of positions'
/// segments as constructed (to 0,01 mm: a drawn segment, not a reading to the drafting's
/// 0,5 mm), the result the image the plan draws.
pub(super) fn similarity(w: &mut Writer<'_, '_>, p: &Plans<'_>) {
    let lang = w.lang;
    let Some(at) = p.at.as_deref() else { return };
    let Some(plan) = p
        .kin
        .plan
        .positions
        .iter()
        .position(|q| q.label == at)
        .and_then(|k| p.kin.velocity.get(k))
        .and_then(|v| v.plan())
    else {
        return;
    };
    let prog = &p.kin.plan.program;
    let mu_l = p.kin.scales.l.value();
    let mut lines = Vec::new();
    for g in &p.s.groups {
        for e in velocity_equations(g, lang) {
            let (point, pivot) = &e.names;
            if !turns_about_fixed(p, &e) {
                continue;
            }
            let image = plan
                .coincident
                .iter()
                .find(|c| c.0 == e.point)
                .map(|c| c.1)
                .or_else(|| prog.index(point).map(|k| plan.images[k]));
            let (Some(image), Some(ob)) = (image, p.drawn(pivot, point)) else {
                continue;
            };
            for x in p.m.points.iter().filter(|x| x.link == e.link) {
                let Some(k) = prog.index(&x.name) else {
                    continue;
                };
                let ox = x.along.hypot(x.across) / mu_l;
                if ox <= 0.0 {
                    continue;
                }
                lines.push((
                    (segment("p", &plain(&x.name)), segment("p", &e.point)),
                    (format!("{pivot}{}", x.name), format!("{pivot}{point}")),
                    (plan.images[k].length(), image.length(), ox, ob),
                    plain(&x.name),
                ));
            }
        }
    }
    if lines.is_empty() {
        return;
    }
    w.doc.say(w.word(K::Similarity));
    for ((px, pb), (ox_name, ob_name), (px_mm, pb_mm, ox, ob), x) in lines {
        w.worked(Worked::new(
            sym(&px),
            frac(
                &format!("{} dot {}", sym(&pb), sym(&ox_name)),
                &sym(&ob_name),
            ),
            frac(
                &format!("{} dot {}", num(pb_mm, 4, lang), num(ox, 4, lang)),
                &num(ob, 4, lang),
            ),
            Printed::new(px_mm, 4, unit(w.word(T::MmUnit)), 1e-3, lang),
        ));
        let seg_meaning = format!("{} {x}", w.word(M::VelocitySegment));
        w.explain(&[
            (&px, &seg_meaning, "mm"),
            (&ox_name, w.word(M::DrawnSegment), "mm"),
            (&ob_name, w.word(M::DrawnSegment), "mm"),
        ]);
    }
}

/// Whether `e` is the turn of its link about a fixed pivot: the similarity of its further
/// points holds about the pole.
fn turns_about_fixed(p: &Plans<'_>, e: &Equation) -> bool {
    e.relative == Relative::Turn && p.m.fixed.iter().any(|f| f.name == e.names.1)
}

/// The fixed pivot link `link` turns about, when a group turns it about one: the
/// mechanism's name (`C`).
pub(super) fn fixed_pivot(p: &Plans<'_>, link: u32, lang: Lang) -> Option<String> {
    p.s.groups
        .iter()
        .flat_map(|g| velocity_equations(g, lang))
        .find(|e| e.link == link && turns_about_fixed(p, e))
        .map(|e| e.names.1)
}

/// The rates of the links turning in a group at the worked position: ω = V/l from the
/// relative velocity of two of its points (velocity plan), ε = aτ/l from the tangential part
/// (acceleration plan; aτ is the plan's reading, the study's ε times l). l is the plan of
/// positions' segment at the position, in m.
pub(super) fn rates(w: &mut Writer<'_, '_>, p: &Plans<'_>, kind: Kind) {
    let lang = w.lang;
    let mu_l = p.kin.scales.l.value();
    let mut lines = Vec::new();
    for g in &p.s.groups {
        for e in velocity_equations(g, lang) {
            if e.relative != Relative::Turn {
                continue;
            }
            let (point, other) = &e.names;
            let fixed = p.m.fixed.iter().any(|f| f.name == *other);
            let rate = match kind {
                Kind::Velocity => Symbol::AngularVelocity,
                Kind::Acceleration => Symbol::AngularAcceleration,
            };
            let (Some(l), Some(r)) = (p.drawn(point, other), p.value(w, rate, &e.link.to_string()))
            else {
                continue;
            };
            let l = l * mu_l;
            let (term, value) = match kind {
                Kind::Velocity => {
                    let subject = if fixed {
                        e.point.clone()
                    } else {
                        format!("{}_{}", e.point, e.reference)
                    };
                    let v = p.value(w, Symbol::Velocity, &subject);
                    (format!("V_{{{}}}", e.pair()), v.map(f64::abs))
                }
                Kind::Acceleration => (format!("a^{{τ}}_{{{}}}", e.pair()), Some(r.abs() * l)),
            };
            let Some(value) = value else { continue };
            lines.push((e, term, value, l, r));
        }
    }
    for (e, term, value, l, r) in lines {
        let (letter, si, word) = match kind {
            Kind::Velocity => ("ω", "rad/s", M::AngularVelocity),
            Kind::Acceleration => ("ε", "rad/s^2", M::AngularAcceleration),
        };
        let rate = format!("{letter}_{{{}}}", e.link);
        let length = format!("l_{{{}{}}}", plain(&e.names.1), plain(&e.names.0));
        w.worked(Worked::new(
            sym(&rate),
            frac(&sym(&term), &sym(&length)),
            frac(&num(value, 4, lang), &num(l, 4, lang)),
            Printed::si(r.abs(), 4, si, lang),
        ));
        let what = format!("{} {}", w.word(word), e.link);
        let length_meaning = format!(
            "{} {} {} {}",
            w.word(M::LengthAt),
            plain(&e.names.1),
            w.word(M::ToPoint),
            plain(&e.names.0)
        );
        let t = format!("{} {}", w.word(M::Tangential), e.pair());
        let mut items = vec![(rate.as_str(), what.as_str(), si)];
        if kind == Kind::Acceleration {
            items.push((&term, &t, "m/s^2"));
        }
        items.push((&length, &length_meaning, "m"));
        w.explain(&items);
    }
}

/// The normal parts of the relative accelerations at the worked position: aⁿ = ω²·l with the
/// velocity plan's ω of the link and the plan of positions' l (the vector the plan lays off
/// along the link, towards the reference point).
pub(super) fn normals(w: &mut Writer<'_, '_>, p: &Plans<'_>) {
    let lang = w.lang;
    let mu_l = p.kin.scales.l.value();
    let mut shown = false;
    for g in &p.s.groups {
        for e in velocity_equations(g, lang) {
            if e.relative != Relative::Turn {
                continue;
            }
            let (point, other) = &e.names;
            let omega = p.value(w, Symbol::AngularVelocity, &e.link.to_string());
            let (Some(l), Some(omega)) = (p.drawn(point, other), omega) else {
                continue;
            };
            let l = l * mu_l;
            if !shown {
                w.doc.say(w.word(K::NormalWorked));
                shown = true;
            }
            let an = format!("a^{{n}}_{{{}}}", e.pair());
            let length = format!("l_{{{}{}}}", plain(other), plain(point));
            w.worked(Worked::new(
                sym(&an),
                format!("{}^2 {}", sym(&format!("ω_{{{}}}", e.link)), sym(&length)),
                format!("{}^2 dot {}", num(omega.abs(), 4, lang), num(l, 4, lang)),
                Printed::si(omega * omega * l, 4, "m/s^2", lang),
            ));
            let what = format!("{} {}", w.word(M::Normal), e.pair());
            explain_one(w, &an, &what, "m/s^2");
        }
    }
}

/// The Coriolis acceleration of every slide along a turning link at the worked position:
/// a^k = 2·ω·V_rel with the plan's ω of the guide's link and relative velocity, and the rule
/// of its direction.
pub(super) fn coriolis(w: &mut Writer<'_, '_>, p: &Plans<'_>) {
    let lang = w.lang;
    let mut lines: Vec<(Equation, f64, f64)> = Vec::new();
    for g in &p.s.groups {
        for e in velocity_equations(g, lang) {
            if e.relative != Relative::Slide {
                continue;
            }
            let subject = format!("{}_{}", e.point, e.reference);
            let (Some(omega), Some(v)) = (
                p.value(w, Symbol::AngularVelocity, &e.link.to_string()),
                p.value(w, Symbol::Velocity, &subject),
            ) else {
                continue;
            };
            lines.push((e, omega, v));
        }
    }
    if lines.is_empty() {
        return;
    }
    let at = p.at.clone().unwrap_or_default();
    w.doc.say(&format!("{} {at}:", w.word(T::CoriolisWorked)));
    for (e, omega, v) in lines {
        let ak = format!("a^{{k}}_{{{}}}", e.pair());
        w.worked(Worked::new(
            sym(&ak),
            format!(
                "2{} {}",
                sym(&format!("ω_{{{}}}", e.link)),
                sym(&format!("V_{{{}}}", e.pair()))
            ),
            format!(
                "2 dot {} dot {}",
                num(omega.abs(), 4, lang),
                num(v.abs(), 4, lang)
            ),
            Printed::si(2.0 * omega.abs() * v.abs(), 4, "m/s^2", lang),
        ));
        let what = format!("{} {}", w.word(M::Coriolis), e.pair());
        explain_one(w, &ak, &what, "m/s^2");
    }
    w.doc.say(w.word(K::CoriolisRule));
}
