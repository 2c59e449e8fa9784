//! The kinematic diagrams of the note (seed 000 §1.2): μ_φ derived from the diagram's base,
//! μ_S′ and μ_S″ of the chords' derivatives with their units, one value worked off each
//! diagram (the seed's V = 45·0,00343·15,7), the seed's Table 1; the hodograph of a point's
//! velocity with the seed's Table 4 (the plan's segment and the hodograph's ray in mm).

use super::markup::{frac, num, sym, text, unit, Align};
use super::plan_reads::Plans;
use super::rows::{numbers, values_and_errors, Column};
use super::worked::{Printed, Worked};
use super::Writer;
use crate::check::{Method, Row, Symbol};
use crate::kinematics::KinDiagrams;
use crate::scale::format_fixed;
use crate::scene::PlateKind;
use crate::study::Kinematics;
use crate::words::{
    indexed, plain, quantity, unit_in, KinematicsMeaning as M, KinematicsNote as K, NoteText as T,
    Text as S,
};

/// The diagrams by the method of chords, when the study charts a point.
pub(super) fn diagrams(w: &mut Writer<'_, '_>, kin: &Kinematics, at: Option<&str>) {
    let lang = w.lang;
    let chords = super::rows::quantities(&w.report.rows, |r| r.method.is_diagram());
    let Some(d) = &kin.diagrams else { return };
    w.heading(2, T::KinematicDiagrams);
    w.doc.say(w.word(T::ChordMethod));
    scales(w, d);
    if !d.corners.is_empty() {
        let at = d.corners.join(", ");
        let (when, what) = (w.word(T::AtPositions), w.word(T::CornerOfS));
        w.doc.say(&format!("{when} {at} {what}"));
    }
    w.doc.say(w.word(T::DiagramValues));
    let w1 = kin.w1.abs();
    diagram_table(w, d, w1, &chords, at);
    // Every view of the kinematic sheets that is neither the scheme, the plan of positions,
    // a plan nor the hodograph: the diagrams.
    let shown = [
        S::StructuralScheme,
        S::PlanOfPositions,
        S::Pos,
        S::AccelerationPlanAt,
        S::Hodograph,
    ]
    .map(|t| t.get(lang));
    w.figures(
        (PlateKind::Kinematics, None),
        |own| !shown.iter().any(|s| own.starts_with(s)),
        |own| own.to_string(),
    );
}

/// The unit of μ_S′: the analogue dS/dφ (m/rad) per mm of the diagram.
const FIRST_UNIT: &str = "m/(rad*mm)";
/// The unit of μ_S″: d²S/dφ² (m/rad²) per mm.
const SECOND_UNIT: &str = "m/(rad^2*mm)";

/// μ_φ = 2π/L from the diagram's base L (mm: its intervals × their length), then
/// μ_S′ = μ_S/(μ_φ·H₁) and μ_S″ = μ_S′/(μ_φ·H₂).
fn scales(w: &mut Writer<'_, '_>, d: &KinDiagrams) {
    let lang = w.lang;
    let (mu_s, mu_phi) = (d.scales.y.value(), d.scales.x.value());
    let intervals = if d.first.periodic {
        d.first.x_node.len()
    } else {
        d.first.x_node.len().saturating_sub(1)
    };
    // The base in mm: the turn's intervals (rad) at μ_φ, as the chart lays them off.
    let base = d.scales.x.to_mm(d.first.dx * intervals as f64);
    w.doc.say(w.word(K::PhiScale));
    w.worked(Worked::new(
        sym("μ_{φ}"),
        frac("2 π", &sym("L")),
        frac(&num(std::f64::consts::TAU, 5, lang), &num(base, 5, lang)),
        Printed::new(mu_phi, 4, unit(d.scales.x.quantity.unit(lang)), 1.0, lang),
    ));
    w.explain(&[
        ("μ_{φ}", w.word(M::PhiScale), "rad/mm"),
        ("L", w.word(M::DiagramBase), "mm"),
    ]);
    let (h1, h2) = (d.first.pole_mm, d.second.pole_mm);
    let unit_of = |si: &str| unit(&unit_in(si, lang));
    w.worked(Worked::new(
        sym("μ_{S′}"),
        frac(&sym("μ_{S}"), &format!("{} {}", sym("μ_{φ}"), sym("H_{1}"))),
        frac(
            &num(mu_s, 4, lang),
            &format!("{} dot {}", num(mu_phi, 4, lang), num(h1, 4, lang)),
        ),
        Printed::new(d.first.scale.value(), 4, unit_of(FIRST_UNIT), 1.0, lang),
    ));
    w.explain(&[
        ("μ_{S′}", w.word(M::FirstScale), FIRST_UNIT),
        ("μ_{S}", w.word(M::DisplacementScale), "m/mm"),
        ("H_{1}", w.word(M::PoleFirst), "mm"),
    ]);
    w.worked(Worked::new(
        sym("μ_{S″}"),
        frac(
            &sym("μ_{S′}"),
            &format!("{} {}", sym("μ_{φ}"), sym("H_{2}")),
        ),
        frac(
            &num(d.first.scale.value(), 4, lang),
            &format!("{} dot {}", num(mu_phi, 4, lang), num(h2, 4, lang)),
        ),
        Printed::new(d.second.scale.value(), 4, unit_of(SECOND_UNIT), 1.0, lang),
    ));
    w.explain(&[
        ("μ_{S″}", w.word(M::SecondScale), SECOND_UNIT),
        ("H_{2}", w.word(M::PoleSecond), "mm"),
    ]);
}

/// The seed's Table 1: the charted point's displacement, velocity and acceleration at each
/// position as the diagrams give them, in the drawing's mm and in SI (mm = value over the
/// diagram's μ: μ_S, |ω₁|·μ_S′, ω₁²·μ_S″), one value of each worked at position `at`, then
/// their differences from the twin.
fn diagram_table(
    w: &mut Writer<'_, '_>,
    d: &KinDiagrams,
    w1: f64,
    chords: &[(String, Method)],
    at: Option<&str>,
) {
    let lang = w.lang;
    let mus = [
        d.scales.y.value(),
        w1 * d.first.scale.value(),
        w1 * w1 * d.second.scale.value(),
    ];
    let by_symbol = |s: Symbol| {
        chords
            .iter()
            .find(|(q, m)| {
                w.report
                    .rows
                    .iter()
                    .any(|r| r.quantity() == *q && r.method == *m && r.key.symbol == s)
            })
            .cloned()
    };
    let picked: Vec<(String, Method)> =
        [Symbol::Displacement, Symbol::Velocity, Symbol::Acceleration]
            .into_iter()
            .filter_map(by_symbol)
            .collect();
    if picked.len() < 3 {
        return values_and_errors(
            w,
            (w.word(T::DiagramTable), w.word(T::DiagramErrors)),
            chords,
        );
    }
    let positions = super::rows::positions_of(&w.report.rows, &picked);
    let mut cols = Vec::new();
    let mut worked = Vec::new();
    for (k, ((q, m), mu)) in picked.iter().zip(mus).enumerate() {
        let rows: Vec<Option<&Row>> = positions
            .iter()
            .map(|p| {
                w.report.rows.iter().find(|r| {
                    r.quantity() == *q && r.method == *m && r.position().as_ref() == Some(p)
                })
            })
            .collect();
        let Some(first) = rows.iter().flatten().next() else {
            continue;
        };
        let symbol = quantity(first.key.symbol, &first.key.subject, lang);
        if let Some(r) = rows
            .iter()
            .flatten()
            .find(|r| r.position().as_deref() == at)
        {
            let subject = (symbol.clone(), first.key.subject.clone());
            worked.push((k, subject, r.graphical / mu, r.graphical, r.unit()));
        }
        cols.push(
            Column::new(
                format!("{symbol}, {}", w.word(T::MmUnit)),
                rows.iter().map(|r| r.map(|r| r.graphical / mu)).collect(),
            )
            .against(first.scale / mu),
        );
        cols.push(
            Column::new(
                super::rows::head(w, first),
                rows.iter()
                    .map(|r| r.map(|r| super::rows::shown(r, r.graphical)))
                    .collect(),
            )
            .against(super::rows::shown(first, first.scale)),
        );
    }
    if let (Some(at), false) = (at, worked.is_empty()) {
        w.doc.say(&format!("{} {at}:", w.word(K::DiagramWorked)));
        for (k, symbol, mm, value, si) in worked {
            worked_value(w, d, w1, (k, &symbol.0, &symbol.1), (mm, value, si));
        }
    }
    let caption = w.word(T::DiagramTable);
    numbers(w, caption, &positions, &cols);
    let captions = (w.word(T::DiagramAll), w.word(T::DiagramErrors));
    values_and_errors(w, captions, chords);
}

/// One value read off diagram `k` (0 displacement, 1 its first, 2 its second derivative):
/// the ordinate in mm times the diagram's μ (and |ω₁| or ω₁²).
fn worked_value(
    w: &mut Writer<'_, '_>,
    d: &KinDiagrams,
    w1: f64,
    (k, symbol, point): (usize, &str, &str),
    (mm, value, si): (f64, f64, &str),
) {
    let lang = w.lang;
    let (y, mu, mu_value, power) = match k {
        0 => ("y_{S}", "μ_{S}", d.scales.y.value(), ""),
        1 => ("y_{S′}", "μ_{S′}", d.first.scale.value(), ""),
        _ => ("y_{S″}", "μ_{S″}", d.second.scale.value(), "^2"),
    };
    let omega = if k == 0 {
        (String::new(), String::new())
    } else {
        (
            format!(" {}{power}", sym("ω_{1}")),
            format!(" dot {}{power}", num(w1, 5, lang)),
        )
    };
    w.worked(Worked::new(
        sym(symbol),
        format!("{} {}{}", sym(y), sym(mu), omega.0),
        format!(
            "{} dot {}{}",
            num(mm, 4, lang),
            num(mu_value, 4, lang),
            omega.1
        ),
        Printed::si(value, 4, si, lang),
    ));
    let what = format!(
        "{} {point} {}",
        w.word([M::PointDisplacement, M::PointVelocity, M::PointAcceleration][k.min(2)]),
        w.word(M::OffDiagram)
    );
    w.explain(&[(symbol, &what, si), (y, w.word(M::Ordinate), "mm")]);
}

/// The hodograph of the velocity of a point (seed 000 §1.4) and the seed's Table 4: the
/// point's segment on the velocity plans at μ_v and the hodograph's ray at its own μ, in mm,
/// the positions as columns.
pub(super) fn hodograph(w: &mut Writer<'_, '_>, p: &Plans<'_>) {
    let lang = w.lang;
    let kin = p.kin;
    let Some(crate::study::Hodograph { point, figure }) = &kin.hodograph else {
        return;
    };
    w.heading(2, T::Hodograph);
    w.doc.say(w.word(T::HodographText));
    let plan_rows = |q: &str| -> Vec<Row> {
        let q = format!("v_{q}");
        w.report
            .rows
            .iter()
            .filter(|r| r.quantity() == q && r.method == Method::Plan)
            .cloned()
            .collect()
    };
    let rows = plan_rows(point);
    let far = far_point(p, point, lang).filter(|f| plan_rows(&f.far).len() == rows.len());
    if let Some(first) = rows.first() {
        let mu = figure.scale;
        let mu_v = kin.scales.v;
        let seg = format!("p{}", indexed(&point.to_lowercase()));
        w.doc.say(&format!(
            "{} {} {}; {} {}.",
            w.word(K::HodographScale),
            crate::scale::format_number(mu.value(), lang),
            mu.quantity.unit(lang),
            w.word(K::PlanSegments),
            mu_v.caption(lang)
        ));
        let line = |head: String, rows: &[Row], f: &dyn Fn(f64) -> f64, decimals: usize| {
            std::iter::once(super::markup::label(&head))
                .chain(
                    rows.iter()
                        .map(|r| text(&format_fixed(f(r.graphical.abs()), decimals, lang))),
                )
                .collect::<Vec<String>>()
        };
        let mm = w.word(T::MmUnit);
        let mut body = Vec::new();
        // The seed's Table 4: the far point's segment first, the point's by similarity.
        let own = match &far {
            Some(f) => {
                let far_seg = format!("p{}", indexed(&f.far.to_lowercase()));
                body.push(line(
                    format!("{far_seg}, {mm}"),
                    &plan_rows(&f.far),
                    &|v| mu_v.to_mm(v),
                    1,
                ));
                format!(
                    "{seg} = {far_seg}·{}/{}",
                    indexed(&f.near_len),
                    indexed(&f.far_len)
                )
            }
            None => seg,
        };
        body.extend([
            line(format!("{own}, {mm}"), &rows, &|v| mu_v.to_mm(v), 1),
            line(
                super::rows::head(w, first),
                &rows,
                &|v| super::rows::shown(first, v),
                3,
            ),
            line(
                format!("{}, {mm}", w.word(K::Ray)),
                &rows,
                &|v| mu.to_mm(v),
                1,
            ),
        ]);
        let mut header = vec![text(w.word(T::PositionShort))];
        header.extend(rows.iter().filter_map(|r| r.position()).map(|p| text(&p)));
        let mut align = vec![Align::Left];
        align.extend(vec![Align::Centre; header.len() - 1]);
        let caption = w.word(T::HodographTable);
        w.doc.table(caption, &align, &header, &body);
    }
    let word = S::Hodograph.get(lang);
    w.figures(
        (PlateKind::Kinematics, None),
        |own| own.starts_with(word),
        |own| own.to_string(),
    );
}

/// The charted point's link's point farthest from the fixed pivot the link turns about
/// (the rocker's end D for S₃): the seed lays off its segment first and the point's by
/// similarity, ps₃ = pd·CS₃/CD.
struct FarPoint {
    /// The far point's name as the report writes it (`D`).
    far: String,
    /// The pivot-to-point and pivot-to-far-point names (`CS3`, `CD`).
    near_len: String,
    far_len: String,
}

/// [`FarPoint`] of the charted `point` (as the report writes it), when its link turns about
/// a fixed pivot and has a point beyond it.
fn far_point(p: &Plans<'_>, point: &str, lang: crate::scale::Lang) -> Option<FarPoint> {
    let reach = |x: &crate::linkage::LinkPoint| x.along.hypot(x.across);
    let own = p.m.points.iter().find(|x| plain(&x.name) == point)?;
    let pivot = super::plan_worked::fixed_pivot(p, own.link, lang)?;
    let far =
        p.m.points
            .iter()
            .filter(|x| x.link == own.link && reach(x) > reach(own))
            .max_by(|a, b| reach(a).total_cmp(&reach(b)))?;
    let pivot = plain(&pivot);
    Some(FarPoint {
        far: plain(&far.name),
        near_len: format!("{pivot}{point}"),
        far_len: format!("{pivot}{}", plain(&far.name)),
    })
}
