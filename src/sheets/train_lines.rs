//! A train's lines on the gear sheet: its mobility with its module, a differential's output
//! speed, each mesh closed at a module of its own, and the satellites' assembly condition.

use crate::gears::{Assembly, Train, TrainStudy};
use crate::scale::Lang;
use crate::words::{unit_in, GearText};

/// The lines of the train `t` under the sheet's data; its module named as the reducer's
/// beside a `pair` on the sheet (the pair's m is the data line's).
pub(super) fn lines(t: &TrainStudy, pair: bool, lang: Lang) -> Vec<String> {
    let mut out = Vec::new();
    let tr_ = &t.spec.train;
    // The mobility; the ratio (by the formula and by the triangles, the required one too)
    // is the tables' (the line printed it a third and fourth time).
    // The train's module beside its mobility (the pair's, on a sheet that has one, is
    // the pair's data line's), where no mesh is closed at a module of its own (the
    // closing's line then gives both).
    let mut mobility = train_mobility_line(tr_);
    if t.closings.is_empty() {
        mobility.push_str(&format!("; {}", module_text(tr_, pair, lang)));
    }
    out.push(mobility);
    out.extend(differential_line(t, lang));
    out.extend(closing_lines(t, pair, lang));
    if let Some((k, a)) = t.spec.satellites.and_then(|k| Some((k, tr_.assembly(k)?))) {
        out.push(assembly_line(tr_, k, &a, lang));
    }
    out
}

/// The satellites' assembly condition as the textbook writes it, z_a·u_aH^(b)·(1 + k·p)/k
/// whole, with the least p that makes it so and the whole number it gives (seed 000's
/// reducer: `k = 2: условие сборки z_{3}·u_{3H}^{(6)}·(1 + k·p)/k = −145, p = 1`); where no
/// p does, whether identical blocks fit all the same, or not.
fn assembly_line(t: &Train, k: u32, a: &Assembly, lang: Lang) -> String {
    let shaft = |s: usize| t.shafts.get(s).map_or("", String::as_str);
    let (h, b) = (t.carrier.map_or("H", shaft), t.fixed.map_or("", shaft));
    let central = &t.wheels[a.central];
    let condition = format!(
        "z_{{{a}}}·u_{{{a}{h}}}^{{({b})}}·(1 + k·p)/k",
        a = central.name
    );
    // The whole number (1 + k·p)·z_a·u/k, written with the sheet's minus.
    let whole = |p: i128| {
        let n = a
            .value
            .0
            .checked_mul(i128::from(k).checked_mul(p)?.checked_add(1)?)?;
        (a.value.1 != 0).then(|| n / a.value.1)
    };
    let verdict = match (a.fits(), a.p) {
        (true, Some(p)) => match whole(p) {
            Some(n) if n < 0 => format!(" = −{}, p = {p}", n.unsigned_abs()),
            Some(n) => format!(" = {n}, p = {p}"),
            None => format!(", p = {p}"),
        },
        (true, None) => format!(": {}", GearText::Holds.get(lang)),
        (false, _) => format!(": {}", GearText::Fails.get(lang)),
    };
    format!(
        "k = {k}: {} {condition}{verdict}",
        GearText::Assembly.get(lang)
    )
}

/// A differential's output speed from its two given ones: `n_{3} = 1000 об/мин, n_{5} = 200
/// об/мин → n_{H} = 360 об/мин (формула Виллиса), 360 об/мин (треугольники)`.
fn differential_line(t: &TrainStudy, lang: Lang) -> Option<String> {
    let tr_ = &t.spec.train;
    let (second, w2) = tr_.second?;
    let n_in = t.spec.n_input?;
    let rpm = unit_in("rpm", lang);
    // A drawing's four digits (the triangles' 362,873 read as 362,9).
    let n = |x: f64| super::digits::value(x, lang);
    let by_triangles = crate::scale::to_rpm(t.triangles.omega[tr_.output]);
    let by_formula = t.formula.map_or(String::new(), |u| {
        format!("{} {rpm} ({}), ", n(n_in / u), GearText::Willis.get(lang))
    });
    Some(format!(
        "n_{{{}}} = {} {rpm}, n_{{{}}} = {} {rpm} → n_{{{}}} = {by_formula}{} {rpm} ({})",
        tr_.shafts[tr_.input],
        n(n_in),
        tr_.shafts[second],
        n(w2 * n_in),
        tr_.shafts[tr_.output],
        n(by_triangles),
        GearText::ByTriangles.get(lang),
    ))
}

/// Each mesh the train's module does not close, at the module it is drawn at, beside the
/// train's, with the decision only: `m = 1 мм, m_{3-4} = 2,833 мм (по соосности)` (why the
/// source's module does not serve is the note's to say).
fn closing_lines(t: &TrainStudy, pair: bool, lang: Lang) -> Vec<String> {
    let tr_ = &t.spec.train;
    let mm = unit_in("mm", lang);
    t.closings
        .iter()
        .map(|c| {
            let (s, w) = c.mesh;
            format!(
                "{}, m_{{{}-{}}} = {} {mm} ({})",
                module_text(tr_, pair, lang),
                tr_.wheels[s].name,
                tr_.wheels[w].name,
                super::digits::value(c.module * 1e3, lang),
                GearText::ForCoaxiality.get(lang),
            )
        })
        .collect()
}

/// The module the train's wheels are cut with: `m = 2 мм`; beside a `pair`'s module,
/// the reducer's: `m_{ред} = 2 мм (редуктор)`.
fn module_text(t: &Train, pair: bool, lang: Lang) -> String {
    let value = super::digits::value(t.module * 1e3, lang);
    let mm = unit_in("mm", lang);
    match crate::words::symbols::part("ред", lang).filter(|_| pair) {
        Some(part) => format!("m_{{ред}} = {value} {mm} ({part})"),
        None => format!("m = {value} {mm}"),
    }
}

/// The train's mobility as the textbook writes it: W = 3n − 2p₅ − p₄ = 3·4 − 2·4 − 3 = 1.
fn train_mobility_line(t: &Train) -> String {
    let m = t.mobility();
    format!(
        "W = 3n − 2p_{{5}} − p_{{4}} = 3·{} − 2·{} − {} = {}",
        m.n,
        m.p5,
        m.p4,
        m.w()
    )
}
