//! Plate "Маховик" (seed 000 §5.7): the flywheel as a part drawing on a sheet of its own, at
//! the round scale that draws it whole (the seed's 1:4), on the smallest sheet from A3 up
//! that holds it at that scale or the next coarser one: the axial section and the front
//! view with the spokes' sections, every dimension from the J_м the dynamics sheet's
//! construction gives (Wittenbauer's tangents) — the flywheel a hand-in sizes — with the
//! exact J_м and the δ each gives, and the table of the dimensions with the proportions they
//! follow. A scene whose machine needs no flywheel has no such sheet.

use super::layout::{lay_out_smallest, Block, Part};
use super::BuildError;
use crate::construct::Figure;
use crate::dynamics::{Dynamics, FlywheelKind, FlywheelSpec};
use crate::geom::{DVec2, Rect};
use crate::plate::{layout, Layout, Plate, SheetSize, TableBlock};
use crate::scale::{format_fixed, format_number, format_sig, Lang};
use crate::study::Session;
use crate::words::{unit_in, DynamicsText};

/// The sheets tried, smallest first.
const SIZES: [SheetSize; 2] = [SheetSize::A3, SheetSize::A2];
/// Text height of the data lines and the table, mm.
const TEXT_MM: f64 = 3.5;

/// Build the flywheel's sheet; none when no flywheel is needed: the smallest format that
/// holds the part at its round scale or, failing that, at the next coarser one (an A3 at
/// 1:2,5 rather than an A2 at 1:2), else the larger format at the round scale.
pub fn build(session: &Session<'_>, lang: Lang) -> Result<Vec<Plate>, BuildError> {
    let d = session.dynamics()?;
    if d.wheels.iter().all(|w| w.steps.is_empty()) {
        return Ok(Vec::new());
    }
    // What no format holds on one sheet: the largest format at the round scale.
    let mut fallback = Ok(Vec::new());
    for size in SIZES {
        for (k, wheel) in d.wheels.iter().enumerate() {
            match sheet(&d, wheel, size, session, lang) {
                Ok(plates) if plates.len() == 1 => return Ok(plates),
                other if k == 0 => fallback = other,
                _ => {}
            }
        }
    }
    fallback
}

/// The flywheel's sheet drawing `wheel` on the format `size`: one plate when it holds all.
fn sheet(
    d: &Dynamics,
    wheel: &Figure,
    size: SheetSize,
    session: &Session<'_>,
    lang: Lang,
) -> Result<Vec<Plate>, BuildError> {
    let demands = requirements(lang);
    let blocks = vec![
        Block::Views {
            parts: vec![Part::new(in_lang(wheel, lang), DVec2::ZERO, None)],
            scale: None,
        },
        // The table beside the drawing, the technical requirements under it (then moved over
        // the title block), the data under the drawing.
        Block::Table(dimensions_table(d, lang)),
        Block::Text {
            lines: demands.clone(),
            size_mm: TEXT_MM,
        },
        Block::Text {
            lines: data_lines(d, lang),
            size_mm: TEXT_MM,
        },
    ];
    // A part drawing's title block names the part (ГОСТ 2.104 graph 1), not the machine.
    let mut title = super::title_block(session.scene(), "", Some(wheel.scale), lang);
    title.title = DynamicsText::Flywheel.get(lang).to_string();
    // A part drawing's title block gives its mass, kg, and its material.
    title.mass = format_sig(d.made.mass, 3, lang);
    let grade = if d.spec.flywheel.cast_iron() {
        DynamicsText::CastIronGrade
    } else {
        DynamicsText::SteelGrade
    };
    title.material = grade.get(lang).to_string();
    let mut plates = lay_out_smallest(&[size], blocks, "flywheel", &title, lang)?;
    for p in &mut plates {
        over_title_block(p, &demands);
        in_top_right_corner(p, &d.other_surfaces);
    }
    Ok(plates)
}

/// The gap between the technical requirements and the title block under them, mm.
const OVER_TITLE_MM: f64 = 5.0;
/// The technical requirements stand at least this clear of every other item there, mm.
const CLEAR_MM: f64 = 2.0;

/// The technical requirements (the text block of `lines`) moved over the title block, its
/// left edge on the block's, as ГОСТ 2.316 places them — where the place is free of every
/// other item of the sheet; else they stay where the packer put them.
fn over_title_block(plate: &mut Plate, lines: &[String]) {
    let Some(k) = plate.texts.iter().position(|t| t.lines == lines) else {
        return;
    };
    let l = layout(plate);
    let (was, tb) = (l.texts[k], l.title_block);
    let min = DVec2::new(tb.min.x, tb.min.y - OVER_TITLE_MM - was.height());
    // Every other item: the requirements' own box is left out.
    if free(&l, Rect::new(min, min + was.size()), Some(was)) {
        plate.texts[k].at += min - was.min;
    }
}

/// Whether the place `there` lies inside the frame, [`CLEAR_MM`] clear of every item of the
/// laid-out sheet `l` but the one whose box is `own`.
fn free(l: &Layout, there: Rect, own: Option<Rect>) -> bool {
    let clear = there.inflate(CLEAR_MM);
    let mut others = l.boxes().filter(|r| Some(*r) != own);
    l.frame.contains(&there) && others.all(|r| !r.intersects(&clear))
}

/// How far the roughness of the other surfaces stands from the frame's right and top edges,
/// mm.
const CORNER_MM: DVec2 = DVec2::new(5.0, 8.0);

/// The sign of the other surfaces' roughness (`sign`, drawn 1:1) placed in the sheet's top
/// right corner, as ГОСТ 2.309 places it, where nothing else of the sheet stands.
fn in_top_right_corner(plate: &mut Plate, sign: &Figure) {
    let Some((lo, hi)) = sign.bounds() else {
        return;
    };
    let l = layout(plate);
    let origin = DVec2::new(
        l.frame.max.x - CORNER_MM.x - hi.x,
        l.frame.min.y + CORNER_MM.y + hi.y,
    );
    // On the sheet (y down).
    let there = Rect::new(
        DVec2::new(origin.x + lo.x, origin.y - hi.y),
        DVec2::new(origin.x + hi.x, origin.y - lo.y),
    );
    if free(&l, there, None) {
        plate.views.push(crate::plate::View {
            figure: sign.clone(),
            origin,
            caption: None,
            caption_drop: 0.0,
        });
    }
}

/// `wheel` with its decimals (the keyway's depth, the roughness) written with the language's
/// decimal sign: the part drawing writes them with a point.
fn in_lang(wheel: &Figure, lang: Lang) -> Figure {
    let mut out = wheel.clone();
    for label in out.steps.iter_mut().filter_map(|s| s.label.as_mut()) {
        label.text = label.text.replace('.', &lang.decimal().to_string());
    }
    out
}

/// The technical requirements of the cast part: the numbered items, a line each piece of
/// theirs.
fn requirements(lang: Lang) -> Vec<String> {
    [
        DynamicsText::CastRadii,
        DynamicsText::Tolerances,
        DynamicsText::BalanceStatically,
    ]
    .iter()
    .flat_map(|w| w.get(lang).split('\n'))
    .map(str::to_string)
    .collect()
}

/// The flywheel's inertia by the construction and exactly, with the δ each gives; its
/// material and coefficients; D and m worked.
fn data_lines(d: &Dynamics, lang: Lang) -> Vec<String> {
    let (s, fw) = (&d.size, &d.spec.flywheel);
    let kgm2 = unit_in("kg*m^2", lang);
    let mm = unit_in("mm", lang);
    let delta = |x: f64| {
        format!(
            "δ = {} = 1/{}",
            format_sig(x, 4, lang),
            format_sig(1.0 / x, 3, lang)
        )
    };
    let material = if fw.cast_iron() {
        DynamicsText::CastIron
    } else {
        DynamicsText::Steel
    };
    let ratio = d
        .size
        .rule("b_{1}")
        .map(|(r, _)| format_number(r, lang))
        .unwrap_or_default();
    let mut lines = vec![
        DynamicsText::SizedFrom.get(lang).to_string(),
        format!(
            "J_{{м}} = μ_{{T}}·kl/(δω_{{ср}}^2) = {} {kgm2}, {}",
            format_sig(s.j, 4, lang),
            delta(d.delta_of[0]),
        ),
        format!(
            "J_{{м}} {} = {} {kgm2}, {}, D = {} {mm}",
            DynamicsText::Exact.get(lang),
            format_sig(d.exact.j_fw, 4, lang),
            delta(d.exact.delta()),
            format_fixed(d.exact_size.d * 1e3, 0, lang),
        ),
        format!(
            "{}: {}, ρ = {} {}; K_{{j}} = {}, K_{{m}} = {}",
            DynamicsText::Material.get(lang),
            material.get(lang),
            format_sig(fw.rho, 5, lang),
            unit_in("kg/m^3", lang),
            format_sig(fw.k_j, FlywheelSpec::COEFFICIENT_DIGITS, lang),
            format_sig(fw.k_m, FlywheelSpec::COEFFICIENT_DIGITS, lang),
        ),
        format!(
            "D = (J_{{м}}/(K_{{j}}ρ))^{{1/5}} = {} {mm}; {}",
            format_fixed(s.d * 1e3, 1, lang),
            DynamicsText::Taken
                .get(lang)
                .replace("{d}", &format_fixed(d.made.d * 1e3, 0, lang))
                .replace("{mm}", &mm),
        ),
        format!(
            "J = K_{{j}}ρD^5 = {} {kgm2}, m = K_{{m}}ρD^3 = {} {}",
            format_sig(d.made.j, 4, lang),
            format_sig(d.made.mass, 4, lang),
            unit_in("kg", lang),
        ),
    ];
    lines.extend(verdict(d, lang));
    if s.kind == FlywheelKind::Rim {
        lines.push(
            DynamicsText::SpokeSections
                .get(lang)
                .replace("{ratio}", &ratio),
        );
    }
    lines
}

/// The relative margin within which the δ a flywheel gives still meets the δ asked: the
/// printed 1/δ's last digit.
const DELTA_MARGIN: f64 = 1e-3;

/// The conclusion on the flywheel a hand-in draws (made from the construction's J_м, its
/// diameter rounded up): the δ it gives against the δ asked and, when it falls short, by how
/// much its J_м is under the exact one and the J_м and D that keep δ (lines of label markup;
/// the sheet writes a line each, the note one paragraph).
pub(crate) fn verdict(d: &Dynamics, lang: Lang) -> Vec<String> {
    let inverse = |x: f64| format!("1/{}", format_sig(1.0 / x, 3, lang));
    let (got, asked) = (d.delta_made, d.spec.delta);
    let met = got <= asked * (1.0 + DELTA_MARGIN);
    let first = DynamicsText::DeltaVerdict
        .get(lang)
        .replace("{got}", &inverse(got))
        .replace("{rel}", if met { "≤" } else { ">" })
        .replace("{asked}", &inverse(asked));
    if met {
        let met = DynamicsText::DeltaMet
            .get(lang)
            .replace("{d}", &format_fixed(d.made.d * 1e3, 0, lang))
            .replace("{mm}", &unit_in("mm", lang));
        return vec![first, met];
    }
    let short = 100.0 * (1.0 - d.made.j / d.exact.j_fw);
    vec![
        first,
        DynamicsText::DeltaShort
            .get(lang)
            .replace("{pct}", &format_fixed(short, 1, lang))
            .replace("{n}", &d.labels.len().to_string()),
        DynamicsText::DeltaNeeds
            .get(lang)
            .replace("{exact}", &format_sig(d.exact.j_fw, 4, lang))
            .replace("{kgm2}", &unit_in("kg*m^2", lang))
            .replace("{d}", &format_fixed(d.exact_size.d * 1e3, 0, lang))
            .replace("{mm}", &unit_in("mm", lang)),
    ]
}

/// Every dimension with the proportion it follows (`d_{1}` = 0,2D) and its value, mm.
fn dimensions_table(d: &Dynamics, lang: Lang) -> TableBlock {
    let rows = d
        .made
        .dims
        .iter()
        .map(|&(name, value)| {
            let rule = d.made.rule(name).map_or_else(
                // The D taken: the worked one rounded up.
                || "≥ (J_{м}/(K_{j}ρ))^{1/5}".to_string(),
                |(factor, of)| format!("{}{of}", format_number(factor, lang)),
            );
            vec![name.to_string(), rule, format_fixed(value * 1e3, 0, lang)]
        })
        .collect();
    super::layout::table(
        DynamicsText::Dimensions,
        &[
            (DynamicsText::Dimension, 26.0),
            (DynamicsText::Rule, 36.0),
            (DynamicsText::Millimetres, 16.0),
        ],
        rows,
        TEXT_MM,
        lang,
    )
}
