//! What a practical work's form asks at its end besides the errors (seed 002): the zero and
//! the positive wheel compared (work 1: «Підсумки зрівняння параметрів нульового і
//! додатного коліс»), the senses of rotation of the driving and the output wheel (work 2),
//! every number the session's.

use super::Writer;
use crate::scene::{Genre, Practicum};
use crate::words::{unit_in, GenreText as G};

/// The form's own summary of a practical work, before the table of errors.
pub(super) fn summary(w: &mut Writer<'_, '_>) {
    match w.genre() {
        Genre::Practicum(Practicum::RackGeneration) => wheels(w),
        Genre::Practicum(Practicum::PlanetaryTrain) => senses(w),
        _ => {}
    }
}

/// Each rack-cut wheel: its shift against x_min (undercut or not), its tooth on the pitch
/// circle and at the tip against 0,3m (pointed or not); then what the shift does.
fn wheels(w: &mut Writer<'_, '_>) {
    let Ok(study) = w.session.gears() else {
        return;
    };
    let lang = w.lang;
    let analytic = |q: String| {
        w.report
            .rows
            .iter()
            .find(|r| r.quantity() == q)
            .map(|r| r.analytic)
    };
    let mm = unit_in("mm", lang);
    let n = |x: f64| crate::scale::format_sig(x, 5, lang);
    let mut lines = Vec::new();
    for cut in &study.racks {
        let (name, g) = (&cut.name, &cut.generation);
        let c = &g.cutting;
        let (Some(x_min), Some(st), Some(sa)) = (
            analytic(format!("x_min_{name}")),
            analytic(format!("s_t{name}")),
            analytic(format!("s_a{name}")),
        ) else {
            continue;
        };
        let undercut = if c.x < x_min {
            G::Undercut
        } else {
            G::NotUndercut
        };
        let tip = if sa < 0.3 * c.module {
            G::Pointed
        } else {
            G::TipEnough
        };
        lines.push(format!(
            "{} (z = {}, x = {}, x_{{min}} = {}): {}; S_{{t}} = {} {mm}, s_{{a}} = {} {mm}, {}m = {} {mm}: {}.",
            w.word(G::Wheel),
            c.z,
            n(c.x),
            n(x_min),
            w.word(undercut),
            n(st * 1e3),
            n(sa * 1e3),
            n(0.3),
            n(0.3 * c.module * 1e3),
            w.word(tip),
        ));
    }
    if lines.len() > 1 {
        lines.push(w.word(G::ShiftEffect).to_string());
    }
    for l in lines {
        w.doc.say(&l);
    }
}

/// The train's ratio's sign: the driving and the output wheel turn the same way or not.
fn senses(w: &mut Writer<'_, '_>) {
    let Ok(study) = w.session.gears() else {
        return;
    };
    let Some(train) = &study.train else {
        return;
    };
    let t = &train.spec.train;
    let sense = if train.ratio > 0.0 {
        G::SameSense
    } else {
        G::OppositeSense
    };
    w.doc.say(&format!(
        "u_{{{}{}}} = {}: {}",
        t.shafts[t.input],
        t.shafts[t.output],
        crate::scale::format_sig(train.ratio, 5, w.lang),
        w.word(sense)
    ));
}
