//! The plan of positions of the note: the length scale worked from the crank, the drawn
//! length of every link as a table (seed 000: AB = 56, CD = 284, AC = 172 mm), the stroke,
//! the angle θ worked from the mechanism's geometry where it gives θ in closed form (a slotted
//! link through the crank's pin: sin(θ/2) = l_AB/l_AC) and the time ratio K worked from θ.

use super::markup::{frac, inline, label, num, sym, text, unit, Align};
use super::worked::{Printed, Worked};
use super::{NoteError, Writer};
use crate::check::is_zero;
use crate::linkage::{Dyad, Extremes, Mechanism, OutputCoord};
use crate::scale::{format_fixed, Lang};
use crate::scene::PlateKind;
use crate::sheets::data::{spans, Span};
use crate::words::{plain, KinematicsMeaning as M, KinematicsNote as K, NoteText as T, Text as S};
use std::f64::consts::PI;

/// The plan of positions: μ_l, the drawn lengths, the stroke, θ and K, the figure.
pub(super) fn positions(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let lang = w.lang;
    let sc = w.session.kin_scales()?;
    let kin = w.session.kinematics(&sc)?;
    let m = w.session.mechanism("the explanatory note")?;
    w.heading(2, S::PlanOfPositions);
    let l = sc.l.value();
    let crank = crank_length(m);
    let drawn = sym(&format!("{}{}", m.crank.centre, m.crank.pin));
    w.doc.par(&[text(w.word(T::LengthScale))]);
    w.worked(Worked::new(
        sym("μ_{l}"),
        frac(&sym(&crank), &drawn),
        frac(
            &format!(
                "{}{}",
                num(m.crank.length, 5, lang),
                unit(w.word(T::MetreUnit))
            ),
            &format!(
                "{}{}",
                num(m.crank.length / l, 4, lang),
                unit(w.word(T::MmUnit))
            ),
        ),
        Printed::new(l, 4, unit(sc.l.quantity.unit(lang)), 1.0, lang),
    ));
    let drawn_label = format!("{}{}", m.crank.centre, m.crank.pin);
    w.explain(&[
        ("μ_{l}", w.word(M::LengthScale), "m/mm"),
        (&crank, w.word(M::CrankLength), "m"),
        (&drawn_label, w.word(M::CrankDrawn), "mm"),
    ]);
    drawn_lengths(w, m, l);
    w.doc.say(w.word(T::PositionsConstruction));
    if let Some(ex) = &kin.plan.extremes {
        stroke(w, ex);
    }
    // A mechanism whose strokes take equal turns of the crank (θ = 0, an engine's central
    // slider-crank) has no time ratio to speak of.
    let uneven = kin
        .plan
        .extremes
        .as_ref()
        .filter(|ex| !is_zero(ex.theta, PI));
    // An extreme reached twice a turn: its two crank angles, the extreme position's first.
    let again = uneven.and_then(Extremes::reached_again);
    if let Some((second, first)) = again {
        let deg = |a: f64| format_fixed(a.to_degrees().rem_euclid(360.0), 2, lang);
        let twice = w
            .word(K::NoTimeRatio)
            .replace("{a}", &deg(first))
            .replace("{b}", &deg(second));
        w.doc.par(&[text(&twice)]);
    } else if let Some(ex) = uneven {
        theta(w, m, ex);
        w.doc.par(&[text(w.word(K::TimeRatio))]);
        let theta = ex.theta.to_degrees();
        w.worked(Worked::new(
            sym("K"),
            frac("180° + θ", "180° - θ"),
            frac(
                &format!("180° + {}°", num(theta, 5, lang)),
                &format!("180° - {}°", num(theta, 5, lang)),
            ),
            Printed::plain(ex.k, 5, lang),
        ));
        w.explain(&[
            ("K", w.word(M::TimeRatio), ""),
            ("θ", w.word(M::Overlap), "deg"),
        ]);
    }
    let plan = S::PlanOfPositions.get(lang);
    w.figures(
        (PlateKind::Kinematics, None),
        |own| own.starts_with(plan),
        |own| own.to_string(),
    );
    Ok(())
}

/// The crank's length symbol, the points' names without their markup: `l_{AB}`, `l_{O1A}`.
pub(super) fn crank_length(m: &Mechanism) -> String {
    format!("l_{{{}{}}}", plain(&m.crank.centre), plain(&m.crank.pin))
}

/// Every output's stroke as the study finds it between the extremes: a rocker's swing ψ, a
/// slider's travel H.
fn stroke(w: &mut Writer<'_, '_>, ex: &Extremes) {
    let lang = w.lang;
    let strokes: Vec<String> = ex
        .ranges
        .iter()
        .map(|r| {
            let travel = (r.max - r.min).abs();
            let (symbol, value, u) = match r.coord {
                OutputCoord::Rocker(link) => (format!("ψ_{{{link}}}"), travel.to_degrees(), "°"),
                OutputCoord::Slider(..) => ("H".to_string(), travel, w.word(T::MetreUnit)),
            };
            format!("{} = {}{}", sym(&symbol), num(value, 5, lang), unit(u))
        })
        .collect();
    w.doc
        .par(&[text(w.word(T::StrokeIs)), inline(&strokes.join(", "))]);
}

/// The slotted link of the mechanism whose extremes give θ in closed form: an RPR group
/// without offset whose block rides the crank's pin and whose link turns about a fixed
/// point; its pivot's name and the crank centre's distance to it (m).
fn slotted_pivot(m: &Mechanism) -> Option<(String, f64)> {
    let centre = m.fixed.iter().find(|f| f.name == m.crank.centre)?;
    m.groups.iter().find_map(|g| match &g.dyad {
        Dyad::Rpr { a, c, offset } if *a == m.crank.pin && *offset == 0.0 => {
            let pivot = m.fixed.iter().find(|f| f.name == *c)?;
            Some((c.clone(), (pivot.at - centre.at).length()))
        }
        _ => None,
    })
}

/// θ worked where the geometry gives it in closed form: for a slotted link through the
/// crank's pin the extremes are the slot's tangents to the crank's circle, so
/// sin(θ/2) = l_AB/l_AC; the result is the study's θ (found by the extremes' search), which
/// the closed form reproduces to the digits shown (seed 000 §1.1.2).
fn theta(w: &mut Writer<'_, '_>, m: &Mechanism, ex: &Extremes) {
    let lang = w.lang;
    let Some((pivot, l_ac)) = slotted_pivot(m) else {
        return;
    };
    let crank = crank_length(m);
    let between = format!("l_{{{}{}}}", plain(&m.crank.centre), plain(&pivot));
    w.doc.par(&[text(w.word(K::ThetaSlotted))]);
    let ratio = m.crank.length / l_ac;
    w.worked(Worked::new(
        format!("sin {}/2", sym("θ")),
        frac(&sym(&crank), &sym(&between)),
        frac(&num(m.crank.length, 5, lang), &num(l_ac, 5, lang)),
        Printed::plain(ratio, 5, lang),
    ));
    w.explain(&[
        ("θ", w.word(M::Overlap), "deg"),
        (&between, w.word(M::CentreDistance), "m"),
    ]);
    w.worked(Worked::new(
        sym("θ"),
        format!("2 arcsin {}", frac(&sym(&crank), &sym(&between))),
        format!("2 dot arcsin {}", num(ratio, 5, lang)),
        Printed::deg(ex.theta, lang),
    ));
}

/// One drawn length: the segment's name (label markup), what it is, its length (m).
type Length = (String, &'static str, f64);

/// The lengths of the mechanism a plan of positions lays off, as its data gives them
/// ([`crate::sheets::data::spans`]): the crank, the groups' links, the points of the links
/// from their link's origin, the distances between fixed points, the slide lines' heights.
fn lengths(m: &Mechanism, lang: Lang) -> Vec<Length> {
    spans(m)
        .into_iter()
        .map(|(what, a, b, l)| {
            let (name, meaning) = match what {
                Span::Crank => (format!("{a}{b}"), M::CrankLength),
                Span::Link => (format!("{a}{b}"), M::LinkLength),
                Span::Point => (format!("{a}{b}"), M::PointDistance),
                Span::Fixed => (format!("{a}{b}"), M::CentreDistance),
                Span::Height => (format!("h_{{{}}}", plain(&a)), M::Offset),
            };
            (name, meaning.get(lang), l)
        })
        .collect()
}

/// The drawn lengths as a table (seed 000: AB = l_AB/μ_l = 56 mm, …), after the rule.
fn drawn_lengths(w: &mut Writer<'_, '_>, m: &Mechanism, mu_l: f64) {
    let lang = w.lang;
    let rows: Vec<Vec<String>> = lengths(m, lang)
        .into_iter()
        .map(|(segment, what, length)| {
            vec![
                text(what),
                label(&segment),
                text(&format_fixed(length, 3, lang)),
                text(&format_fixed(length / mu_l, 1, lang)),
            ]
        })
        .collect();
    w.doc.par(&[text(w.word(K::DrawnLengths))]);
    w.formula(&format!(
        "{} = {}",
        sym(&format!("{}{}", m.crank.centre, m.crank.pin)),
        frac(&sym(&crank_length(m)), &sym("μ_{l}"))
    ));
    let header = [
        text(w.word(K::Dimension)),
        text(w.word(K::Segment)),
        label(&format!(
            "{}, {}",
            w.word(K::LengthWord),
            w.word(T::MetreUnit)
        )),
        label(&format!("{}, {}", w.word(K::OnDrawing), w.word(T::MmUnit))),
    ];
    let caption = w.word(K::DrawnLengthsTable);
    w.doc.table(
        caption,
        &[Align::Left, Align::Centre, Align::Centre, Align::Centre],
        &header,
        &rows,
    );
}
