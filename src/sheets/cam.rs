//! Plate "Синтез кулачкового механизма" (the textbook's sheet 4): the diagrams d²S/dφ²,
//! dS/dφ, S with their integration construction, the combined diagram with the zone of the
//! cam centre (or the flat face's 45° tangent), the profile by inversion with the roller
//! circles and both profiles, the angle graph, the data and the table of the points.

use super::layout::{keyed, lay_out, quantity, Block, Column, Part, Results};
use super::BuildError;
use super::{cam_marks, digits};
use crate::cam::{
    Analogue, Cam, CamDiagrams, CamLayout, CamSpec, Closure, Follower, Law, Rotation,
    ANGLE_LIMIT_NOTE, A_W_NOTE, R0_NOTE, RHO_ADMITTED, RHO_MIN_NOTE, R_MIN_NOTE,
};
use crate::check::{Cusp, Finding, Row, Symbol};
use crate::geom::DVec2;
use crate::plate::{Plate, Sheet, SheetSize, TableBlock, CAPTION_BAND_MM};
use crate::scale::{format_fixed, format_sig, Key, Lang, Scale};
use crate::study::Session;
use crate::words::{unit_in, CamText, Text};
use std::f64::consts::FRAC_PI_2;

/// Text height of the data lines and the tables, mm.
const TEXT_MM: f64 = 3.5;
const TABLE_MM: f64 = 2.5;
/// Gap between a diagram's caption and the diagram under it, mm.
const STACK_GAP_MM: f64 = 8.0;

/// A scale's caption with its own symbol (`μ_{S′} = 0,00093 м/мм`).
pub(super) fn mu(symbol: &str, s: Scale, lang: Lang) -> String {
    format!(
        "μ_{{{symbol}}} = {} {}",
        format_sig(s.value(), 4, lang),
        s.quantity.unit(lang)
    )
}

/// μ_S as the S diagram's caption gives it: found from the stroke where it was
/// (`μ_S = h/y_max = 0,038/94,00 = 0,0004043 м/мм`, seed 002 (4.2)), else its value.
fn s_scale(d: &CamDiagrams, spec: &CamSpec, lang: Lang) -> String {
    let Some(y) = d.y_max else {
        return mu("S", d.s_scale, lang);
    };
    format!(
        "μ_{{S}} = {h}/y_{{max}} = {}/{} = {} {}",
        format_sig(spec.stroke, 4, lang),
        format_sig(y, 4, lang),
        format_sig(d.s_scale.value(), 4, lang),
        d.s_scale.quantity.unit(lang),
        h = spec.stroke_symbol(),
    )
}

/// Build the cam sheet of a turning cam with a translating or rocking follower (a flat-faced
/// rocker's and a translating cam's is [`super::cam_special`]'s).
pub fn build(session: &Session<'_>, lang: Lang) -> Result<Vec<Plate>, BuildError> {
    let scene = session.scene();
    let cam = session.cam()?;
    let d = &cam.diagrams;
    let mm = unit_in("mm", lang);
    let mut blocks = vec![diagram_block(d, &cam.spec, lang)];
    let combined = match cam.spec.follower {
        Follower::Flat { .. } => CamText::FlatCombined,
        Follower::Rocker { .. } => CamText::RockerCombined,
        Follower::Translating { .. } => CamText::TranslatingCombined,
    }
    .get(lang);
    let read_mm = session.drafting().resolution_mm();
    let r_min_step = cam.r_min_step(read_mm);
    let r_min = format!("r_{{min}} = {}", cam_marks::r_min(&cam, r_min_step, lang));
    let rho_min = cam_marks::valued(RHO_ADMITTED, cam.spec.rho_min, lang);
    let radius = cam_marks::relabelled(&cam.radius.figure, R_MIN_NOTE, &r_min);
    let radius = cam_marks::relabelled(&radius, RHO_MIN_NOTE, &rho_min);
    let radius = match cam.radius.centre_distance {
        Some(a) => {
            let a_w = format!("a_{{w}} = {}", cam_marks::read_mm(a, r_min_step, lang));
            cam_marks::relabelled(&radius, A_W_NOTE, &a_w)
        }
        None => radius,
    };
    let r0 = cam_marks::valued("r_{0}", cam.base, lang);
    blocks.push(Block::view(
        cam_marks::relabelled(&radius, R0_NOTE, &r0),
        format!("{combined}, {}", mu("S", d.s_scale, lang)),
        keyed(Key::CamScaleS, d.s_scale),
    ));
    blocks.push(Block::view(
        cam.inversion.figure.clone(),
        format!(
            "{}, {}",
            CamText::Profile.get(lang),
            cam.inversion.scale.caption(lang)
        ),
        keyed(Key::CamScaleL, cam.inversion.scale),
    ));
    if let Some(g) = &cam.angle_graph {
        let what = if cam.spec.shows_transmission_angle() {
            CamText::TransmissionAngle
        } else {
            CamText::PressureAngle
        }
        .get(lang);
        blocks.push(
            Block::view(
                cam_marks::relabelled(
                    g,
                    ANGLE_LIMIT_NOTE,
                    &cam_marks::angle_limit(&cam.spec, lang),
                ),
                format!(
                    "{what}, {}, μ_{{{}}} = 1 °/{}",
                    mu("φ", d.phi, lang),
                    cam.spec.angle_symbol(),
                    mm
                ),
                None,
            )
            // The graduation's numbers, left of the angle axis, kept clear of the frame and the
            // block beside it (they were pushed up over their ticks).
            .with_edge_label_room_of(|t| t.parse::<u32>().is_ok()),
        );
    }
    let drawings = blocks.len();
    let mut lines = data_lines(&cam, read_mm, lang);
    lines.push(String::new());
    lines.extend(legend(CamText::RadiusVector, lang));
    lines.push(super::drafting_line(
        session.drafting(),
        super::Errs::Diagrams,
        lang,
    ));
    blocks.push(Block::Text {
        lines,
        size_mm: TEXT_MM,
    });
    blocks.extend(
        points_table(&cam, read_mm, lang)
            .into_iter()
            .map(Block::Table),
    );
    let step = |r: &Row| cam.reading_step(r, read_mm);
    blocks.push(Block::Table(results_table(&cam.rows(), &step, lang)));
    let title = super::title_block(
        scene,
        CamText::Title.get(lang),
        Some(cam.inversion.scale),
        lang,
    );
    let sheet = Sheet {
        size: SheetSize::A1,
        landscape: true,
    };
    one_sheet(sheet, blocks, drawings, &title, lang)
}

/// The diagrams stacked as the construction runs through them, each with its axes and its
/// caption: the analogue, μ_φ, its μ and the pole distance of the pole it carries; the
/// phases under the displacement diagram's φ axis in `lang`.
pub(super) fn diagram_block(d: &CamDiagrams, spec: &CamSpec, lang: Lang) -> Block {
    let mm = unit_in("mm", lang);
    let h = |i: usize| format_sig(d.poles[i], 3, lang);
    let mut parts: Vec<Part> = Vec::with_capacity(3);
    let mut bottom = 0.0;
    for (which, figure) in d.stack(spec.given) {
        // A d²S/dφ² with no ordinate drawn (P₁ not drawn) states no scale of ordinates.
        let (name, scale, pole) = match which {
            Analogue::D2s => (
                CamText::AccelerationAnalogue,
                d.drawn_poles[0].then(|| mu("S″", d.d2s_scale, lang)),
                d.drawn_poles[0].then(|| ("H_1", h(0))),
            ),
            Analogue::Ds => (
                CamText::VelocityAnalogue,
                Some(mu("S′", d.ds_scale, lang)),
                d.drawn_poles[1].then(|| ("H_2", h(1))),
            ),
            Analogue::S => (CamText::Displacement, Some(s_scale(d, spec, lang)), None),
        };
        let mut caption = format!("{}: {}", name.get(lang), mu("φ", d.phi, lang));
        if let Some(scale) = scale {
            caption.push_str(&format!(", {scale}"));
        }
        if let Some((symbol, value)) = pole {
            caption.push_str(&format!(", {symbol} = {value} {mm}"));
        }
        let Some((lo, hi)) = figure.bounds() else {
            continue;
        };
        // Under the one above, clear of its caption.
        let at = if parts.is_empty() {
            DVec2::ZERO
        } else {
            DVec2::new(0.0, bottom - CAPTION_BAND_MM - STACK_GAP_MM - hi.y)
        };
        let figure = if which == Analogue::S {
            cam_marks::phases_marked(figure, spec, lang)
        } else {
            figure.clone()
        };
        let part = Part::new(figure, at, Some(caption));
        bottom = at.y + lo.y - part.caption_drop;
        parts.push(part);
    }
    // The poles' labels stand left of the diagrams' poles, outside their drawings.
    Block::Views {
        parts,
        scale: keyed(Key::CamScalePhi, d.phi),
    }
    .with_edge_label_room_of(|t| crate::cam::POLES.iter().flatten().any(|p| *p == t))
}

/// The cam's blocks laid out on one sheet if some order of them fits one, else in the
/// construction's order on as many as they need. `blocks` are the diagrams, the combined
/// diagram, the profile, the angle graph if `drawings` is 4 (the first `drawings` blocks),
/// then the text and the tables. The diagrams always go first, top left; the orders tried:
/// the construction's; the text and the tables before the drawings they would otherwise be
/// left under; the profile before the combined diagram. When none fits one sheet, the orders
/// again with the angle graph's room for its numbers given up (the fourth drawing's), a
/// sheet rather than that room.
pub(super) fn one_sheet(
    sheet: Sheet,
    blocks: Vec<Block>,
    drawings: usize,
    title: &crate::plate::TitleBlock,
    lang: Lang,
) -> Result<Vec<Plate>, BuildError> {
    let in_order = |blocks: &[Block]| -> Result<(Vec<Plate>, bool), BuildError> {
        let words = blocks[drawings.min(blocks.len())..].to_vec();
        let figures = &blocks[..drawings.min(blocks.len())];
        let mut swapped = figures.to_vec();
        if swapped.len() > 2 {
            swapped.swap(1, 2);
        }
        let mut words_first = figures[..1.min(figures.len())].to_vec();
        words_first.extend(words.iter().cloned());
        words_first.extend(figures.iter().skip(1).cloned());
        let orders = [
            blocks.to_vec(),
            words_first,
            swapped.into_iter().chain(words.iter().cloned()).collect(),
        ];
        let mut first = None;
        for ordered in orders {
            let plates = lay_out(sheet, ordered, "cam", title, lang)?;
            if plates.len() == 1 {
                return Ok((plates, true));
            }
            first.get_or_insert(plates);
        }
        Ok((first.unwrap_or_default(), false))
    };
    let (first, one) = in_order(&blocks)?;
    if one || drawings < 4 {
        return Ok(first);
    }
    let mut bare = blocks;
    if let Block::Views { parts, .. } = &mut bare[3] {
        for p in parts {
            p.label_room = None;
        }
    }
    match in_order(&bare)? {
        (plates, true) => Ok(plates),
        _ => Ok(first),
    }
}

/// A law's name in `lang`.
pub(super) fn law_name(law: Law, lang: Lang) -> String {
    let word = match law {
        Law::ConstantAcceleration { ratio } => {
            return format!(
                "{} ({} {})",
                CamText::PlusMinus.get(lang),
                CamText::Ratio.get(lang),
                format_sig(ratio, 3, lang)
            )
        }
        Law::LinearBlended { blend } => {
            return format!(
                "{} ({} {})",
                CamText::LinearBlended.get(lang),
                CamText::Blend.get(lang),
                format_sig(blend, 3, lang)
            )
        }
        Law::Uniform => CamText::Uniform,
        Law::Cosine => CamText::Cosine,
        Law::Sine => CamText::Sine,
        Law::Trapezoidal => CamText::Trapezoidal,
        Law::Polynomial345 => CamText::Polynomial,
    };
    word.get(lang).into()
}

/// The data's heading and the law's lines: the phases, the cam's sense (its motion for a
/// translating cam), the laws. That the source lost its law is the note's (a remark on the
/// source), not the sheet's.
pub(super) fn law_lines(s: &CamSpec, rotation: Rotation, lang: Lang) -> Vec<String> {
    let mut out = vec![Text::Data.get(lang).to_string()];
    out.push(cam_marks::phases_line(s, lang));
    let sense = match (s.layout, rotation) {
        (CamLayout::Sliding(_), _) => CamText::Slides,
        (_, Rotation::Cw) => CamText::Clockwise,
        _ => CamText::CounterClockwise,
    };
    out.push(sense.get(lang).into());
    out.push(format!(
        "{}: {}; {}: {}",
        CamText::RiseLaw.get(lang),
        law_name(s.rise, lang),
        CamText::ReturnLaw.get(lang),
        law_name(s.ret, lang)
    ));
    out
}

/// The task's data and the results, as text lines, each reading to its step at `read_mm`.
fn data_lines(cam: &Cam, read_mm: f64, lang: Lang) -> Vec<String> {
    let r_min_step = cam.r_min_step(read_mm);
    let s = &cam.spec;
    let mm = unit_in("mm", lang);
    let n = |x: f64| format_sig(x * 1e3, 4, lang);
    let deg = |x: f64| format_sig(x.to_degrees(), 4, lang);
    let h = s.stroke_symbol();
    let mut out = law_lines(s, cam.rotation, lang);
    match s.follower {
        Follower::Rocker { arm, .. } => out.push(format!(
            "L = {} {mm}, β_{{max}} = {}°, {h} = Lβ_{{max}} = {} {mm}, γ_{{min}} = {}°",
            n(arm),
            deg(s.stroke / arm),
            n(s.stroke),
            deg(s.gamma_min)
        )),
        Follower::Translating { offset } => out.push(format!(
            "{h} = {} {mm}, e = {} {mm}, γ_{{min}} = {}°",
            n(s.stroke),
            n(cam.scene_offset(offset)),
            deg(s.gamma_min)
        )),
        Follower::Flat { offset } => out.push(format!(
            "{h} = {} {mm}, e = {} {mm}, {RHO_ADMITTED} = {} {mm}",
            n(s.stroke),
            n(cam.scene_offset(offset)),
            n(s.rho_min)
        )),
    }
    out.push(String::new());
    // r_min, and a rocker's centre distance at it, read off the combined diagram beside the
    // twin's.
    let read_and_exact = |symbol: &str, read: f64, exact: f64| {
        format!(
            "{symbol} = {} ({}), {} {mm} ({})",
            cam_marks::read_mm(read, r_min_step, lang),
            Text::Graphical.get(lang),
            n(exact),
            Text::Exact.get(lang)
        )
    };
    out.push(read_and_exact(
        "r_{min}",
        cam.radius.graphical,
        cam.exact_r_min(),
    ));
    if let (Some(g), Some(e)) = (cam.radius.centre_distance, cam.exact_centre_distance()) {
        out.push(read_and_exact("a_{w}", g, e));
    }
    // A source's erratum is the note's (its conclusions), not the student's sheet's.
    let found = cam.findings();
    let stated =
        |p: fn(&Finding) -> bool| found.iter().find(|f| p(f)).and_then(|f| verdict(f, lang));
    out.extend(cam_marks::base_lines(cam, r_min_step, lang));
    if !matches!(s.follower, Follower::Flat { .. }) {
        // The rule's two bounds, ρ_min the drawn pitch curve's as the table reads it; they
        // choose the roller unless the task gives it.
        let step_mm = cam.rho_min_step(read_mm).map(|s| s * 1e3);
        let rho = digits::carried(cam.inversion.rho_min * 1e3, step_mm) * 1e-3;
        // ρ_min read off the drawing is named as such: the undercut's verdict below states
        // the exact one.
        let k = format_sig(0.8, 1, lang);
        let bounds = format!(
            "{}·r_{{0}} = {} {mm}, {k}·ρ_{{min}} = {k}·{} ({}) = {} {mm}",
            format_sig(0.4, 1, lang),
            n(0.4 * cam.base),
            n(rho),
            Text::Graphical.get(lang),
            n(0.8 * rho),
        );
        // A given roller is set against the bound the rule concludes (cam-undercut's 15 mm
        // against r_р ≤ 8,8 mm); a chosen one is the bound.
        out.push(match s.roller {
            Some(_) => format!(
                "r_{{р}} = {} {mm} ({}); {bounds} → r_{{р}} ≤ {} {mm}",
                n(cam.roller),
                CamText::Given.get(lang),
                n(crate::cam::roller_bound(cam.base, rho))
            ),
            None => format!("{bounds} → r_{{р}} = {} {mm}", n(cam.roller)),
        });
    }
    out.extend(stated(|f| {
        matches!(f, Finding::Undercut { .. } | Finding::Cusp(_))
    }));
    out.extend(stated(|f| matches!(f, Finding::RigidShock { .. })));
    out.extend(stated(|f| matches!(f, Finding::WrongSide { .. })));
    out.extend(return_line(cam, lang));
    out
}

/// Under force closure the angle's limit holds on the rise only (seed 002 L1463: the spring
/// returns the follower, nothing jams): where the return's angle passes it — λ over
/// 90° − γ_min, or a rocker's γ under γ_min — the sheet says why its graph may cross the
/// limit's line. None for a flat face (its angle is 0).
fn return_line(cam: &Cam, lang: Lang) -> Option<String> {
    let s = &cam.spec;
    if s.closure != Closure::Force || matches!(s.follower, Follower::Flat { .. }) {
        return None;
    }
    let on_return = cam
        .points
        .iter()
        .filter(|p| p.phase == 2)
        .map(|p| cam.angle_at(p.phi, p.after).abs());
    let (angle, value, rel, limit, passes) = if s.shows_transmission_angle() {
        let least = on_return.fold(f64::INFINITY, f64::min);
        let limit = s.gamma_min;
        ("γ_{min}", least, "<", limit, least < limit - 1e-9)
    } else {
        let most = on_return.fold(0.0, f64::max);
        let limit = FRAC_PI_2 - s.gamma_min;
        ("λ_{max}", most, ">", limit, most > limit + 1e-9)
    };
    passes.then(|| {
        CamText::ReturnUnlimited
            .get(lang)
            .replace("{angle}", angle)
            .replace("{value}", &digits::value(value.to_degrees(), lang))
            .replace("{rel}", rel)
            .replace("{limit}", &digits::value(limit.to_degrees(), lang))
    })
}

/// A verdict of the cam's check as a data line in `lang`; none for those the sheet does not
/// state (the angle's limit is in the table of the points; a source's erratum is the note's).
fn verdict(f: &Finding, lang: Lang) -> Option<String> {
    let mm = unit_in("mm", lang);
    let n = |x: f64| format_sig(x * 1e3, 4, lang);
    // The exact ρ_min, named so beside the drawing's in the roller's bounds above.
    let with_rho = |t: CamText, rho: f64| {
        format!(
            "{} ρ_{{min}} = {} {mm} ({})",
            t.get(lang),
            n(rho),
            Text::Exact.get(lang)
        )
    };
    Some(match *f {
        Finding::Undercut { rho_min, .. } => with_rho(CamText::Undercut, rho_min),
        Finding::Cusp(Cusp::Roller { rho_min, .. }) => with_rho(CamText::RollerCusp, rho_min),
        Finding::Cusp(Cusp::Flat { .. }) => CamText::Cusp.get(lang).into(),
        Finding::RigidShock { .. } => CamText::RigidShocks.get(lang).into(),
        Finding::WrongSide { .. } => CamText::WrongSide.get(lang).into(),
        _ => return None,
    })
}

/// The most rows of one table of points; more continue in further tables (placed on further
/// sheets when a sheet is full).
const POINTS_PER_TABLE: usize = 40;

/// One row per point: φ, S, dS/dφ, d²S/dφ² (each as read off its diagram, to the step its
/// scale reads `read_mm` to, or to 0,01 mm read exactly; ±∞ at a rigid shock), the angle
/// read and exact, the profile's radius vector (read off the profile likewise); in tables
/// of at most [`POINTS_PER_TABLE`] rows, each after the first titled as continued.
fn points_table(cam: &Cam, read_mm: f64, lang: Lang) -> Vec<TableBlock> {
    let flat = matches!(cam.spec.follower, Follower::Flat { .. });
    let f = |x: f64, d: usize| format_fixed(x, d, lang);
    let d = &cam.diagrams;
    // A value read off the diagram drawn at `scale`, m, written in mm.
    let read = |x: f64, scale: Scale| match scale.reading_step(read_mm) {
        Some(step) => super::digits::read(x * 1e3, Some(step * 1e3), lang),
        None => f(x * 1e3, 2),
    };
    let rows = cam
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let mut r = vec![
                p.label.clone(),
                f(p.phi.to_degrees(), 1),
                read(d.s[i], d.s_scale),
                read(d.ds[i], d.ds_scale),
                // A rigid shock's ±∞, as its arrow on the diagram points.
                match (p.k == 0 || p.last).then(|| cam.spec.shock_up(p.phase, p.k == 0)) {
                    Some(Some(up)) => if up { "+∞" } else { "−∞" }.into(),
                    _ => read(d.d2s[i], d.d2s_scale),
                },
            ];
            if !flat {
                r.push(f(cam.angle_read(i).to_degrees(), 1));
                r.push(f(cam.angle_at(p.phi, p.after).to_degrees(), 1));
            }
            r.push(read(cam.inversion.profile[i].length(), cam.inversion.scale));
            r
        })
        .collect();
    let a = cam.spec.angle_symbol();
    let mm = unit_in("mm", lang);
    let mut columns = vec![
        (Text::Number.get(lang).into(), 8.0),
        ("φ, °".into(), 14.0),
        (format!("S, {mm}"), 16.0),
        (format!("dS/dφ, {mm}"), 20.0),
        (format!("d^2S/dφ^2, {mm}"), 24.0),
    ];
    if !flat {
        columns.push((format!("{a} {}, °", CamText::Read.get(lang)), 18.0));
        columns.push((format!("{a} {}, °", Text::Exact.get(lang)), 18.0));
    }
    columns.push((format!("R, {mm}"), 16.0));
    points_tables(columns, rows, lang)
}

/// What the tables' letters mean, a line each: the points table's last column (`last`), and
/// Δ_проф of the results table.
pub(super) fn legend(last: CamText, lang: Lang) -> [String; 2] {
    [last, CamText::DeviationRule].map(|t| t.get(lang).to_string())
}

/// The table of the points in tables of at most [`POINTS_PER_TABLE`] rows, each after the
/// first titled as continued.
pub(super) fn points_tables(
    columns: Vec<(String, f64)>,
    rows: Vec<Vec<String>>,
    lang: Lang,
) -> Vec<TableBlock> {
    let title = CamText::Points.get(lang);
    rows.chunks(POINTS_PER_TABLE)
        .enumerate()
        .map(|(i, chunk)| TableBlock {
            at: DVec2::ZERO,
            title: if i == 0 {
                title.into()
            } else {
                format!("{title} {}", Text::Continued.get(lang))
            },
            columns: columns.clone(),
            rows: chunk.to_vec(),
            size_mm: TABLE_MM,
        })
        .collect()
}

/// The values of the whole scene: graphical, each to the `step` it was read to (m), against
/// exact, mm.
pub(super) fn results_table(
    rows: &[Row],
    step: &dyn Fn(&Row) -> Option<f64>,
    lang: Lang,
) -> TableBlock {
    let rows: Vec<Row> = rows
        .iter()
        .filter(|r| r.key.at == crate::check::At::Scene)
        .cloned()
        .collect();
    super::layout::results_table(
        &Results {
            title: CamText::Results.get(lang).into(),
            columns: &[
                (Column::Quantity, 22.0),
                (Column::Graphical, 26.0),
                (Column::Exact, 26.0),
                (Column::Error, 16.0),
            ],
            name: &|r| quantity(r, lang),
            unit: &|_| String::new(),
            value: &|_, x, _| super::digits::value(x * 1e3, lang),
            graphical: &|r| {
                let x = r.graphical * 1e3;
                Some(if r.key.symbol == Symbol::ProfileDeviation {
                    // A comparison, not a reading: two digits, as an error is written.
                    format_sig(x, 2, lang)
                } else {
                    super::digits::read(x, step(r).map(|s| s * 1e3), lang)
                })
            },
            size_mm: TABLE_MM,
        },
        &rows,
        lang,
    )
}
