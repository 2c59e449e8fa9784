//! Plate "Кинематический анализ" (the textbook's sheet 1): the plan of positions, a velocity
//! plan for every position, the acceleration plans, the displacement diagram with its two
//! chord-method derivatives, the hodograph, the analytic table and the error estimates.
//! Every group of views has its own field; its μ is raised along the textbook series until
//! the drawings fit (the captions state the μ actually used).

use super::{kin_request, BuildError, RenderOptions};
use crate::construct::Figure;
use crate::geom::DVec2;
use crate::kinematics::{analyse, Analysis, KinError, KinRequest};
use crate::plate::{Plate, Rect, Sheet, SheetSize, TableBlock, TextBlock, View, CAPTION_BAND_MM};
use crate::report::{Method, Report};
use crate::scale::{format_fixed, format_sig, Lang, Quantity, Scale};
use crate::scene::Scene;
use std::f64::consts::TAU;

/// The fields of the A1 sheet, sheet mm (x0, y0, x1, y1), y down.
const PLAN: [f64; 4] = [25.0, 22.0, 290.0, 272.0];
const VELOCITY: [f64; 4] = [295.0, 22.0, 560.0, 420.0];
const DIAGRAMS: [f64; 4] = [565.0, 22.0, 832.0, 372.0];
const ACCELERATION: [f64; 4] = [565.0, 377.0, 832.0, 528.0];
const HODOGRAPH: [f64; 4] = [25.0, 277.0, 120.0, 420.0];
const ROCKER: [f64; 4] = [122.0, 277.0, 292.0, 420.0];
const TEXT_AT: (f64, f64) = (28.0, 423.0);
const TABLES_X: f64 = 28.0;
/// The tables end above this line (the title block starts at 534 mm).
const TABLES_END: f64 = 584.0;
/// Right edge of the tables' field (the title block starts at x = 651 mm).
const TABLES_RIGHT: f64 = 560.0;
/// Columns of velocity plans.
const VEL_COLUMNS: usize = 3;
/// Room around a plan's drawing for its labels, mm.
const LABEL_MARGIN: f64 = 8.0;

fn rect(r: [f64; 4]) -> Rect {
    Rect::new(DVec2::new(r[0], r[1]), DVec2::new(r[2], r[3]))
}

fn size_of(f: &Figure) -> DVec2 {
    f.bounds().map_or(DVec2::ZERO, |(lo, hi)| hi - lo) + DVec2::splat(LABEL_MARGIN)
}

/// How much a set of figures overflows cells of `cell` size (≤ 1: fits).
fn overflow(figs: &[&Figure], cell: DVec2) -> f64 {
    let room = cell - DVec2::new(0.0, CAPTION_BAND_MM);
    figs.iter()
        .map(|f| size_of(f))
        .fold(0.0f64, |m, s| m.max(s.x / room.x).max(s.y / room.y))
}

/// The next round scale at least `ratio` times larger.
fn bump(s: Scale, ratio: f64) -> Option<Scale> {
    Scale::round_for(s.value() * ratio.max(1.0001), 1.0, s.quantity)
}

/// Grid cells of `n` views in `r` with `cols` columns.
fn cells(r: Rect, n: usize, cols: usize) -> Vec<Rect> {
    let cols = cols.max(1);
    let rows = n.div_ceil(cols).max(1);
    let (w, h) = (r.width() / cols as f64, r.height() / rows as f64);
    (0..n)
        .map(|k| {
            let (c, row) = ((k % cols) as f64, (k / cols) as f64);
            Rect::new(
                r.min + DVec2::new(c * w, row * h),
                r.min + DVec2::new((c + 1.0) * w, (row + 1.0) * h),
            )
        })
        .collect()
}

fn vel_cell(n: usize) -> DVec2 {
    let r = rect(VELOCITY);
    let rows = n.div_ceil(VEL_COLUMNS).max(1);
    DVec2::new(r.width() / VEL_COLUMNS as f64, r.height() / rows as f64)
}

fn acc_cell(n: usize) -> DVec2 {
    let r = rect(ACCELERATION);
    DVec2::new(r.width() / n.max(1) as f64, r.height())
}

/// Run the analysis, raising the scales of whatever does not fit its field.
fn fitted(
    m: &crate::linkage::Mechanism,
    mut req: KinRequest,
) -> Result<(KinRequest, Analysis), BuildError> {
    let fail = |e: KinError| BuildError::Kinematics(Box::new(e));
    for _ in 0..8 {
        let a = analyse(m, &req).map_err(fail)?;
        let mut changed = false;
        let plan_over = overflow(&[&a.plan.figure], rect(PLAN).max - rect(PLAN).min);
        if plan_over > 1.0 {
            req.scale_l = bump(req.scale_l, plan_over).unwrap_or(req.scale_l);
            changed = true;
        }
        let vel: Vec<&Figure> = a.velocity.iter().flatten().map(|p| &p.figure).collect();
        let mut v_over = overflow(&vel, vel_cell(vel.len()));
        if let Some((_, h)) = &a.hodograph {
            v_over = v_over.max(overflow(&[h], rect(HODOGRAPH).max - rect(HODOGRAPH).min));
        }
        if v_over > 1.0 {
            req.spec.scale_v = bump(a.scale_v, v_over);
            changed = true;
        }
        let acc: Vec<&Figure> = a.acceleration.iter().map(|p| &p.1.figure).collect();
        let a_over = overflow(&acc, acc_cell(acc.len()));
        if a_over > 1.0 {
            req.spec.scale_a = bump(a.scale_a, a_over);
            changed = true;
        }
        if let Some(d) = &a.diagrams {
            let r = rect(DIAGRAMS);
            let (lo, hi) = stack_bounds(d);
            let need = hi - lo + DVec2::splat(LABEL_MARGIN);
            let room = r.max - r.min - DVec2::new(0.0, CAPTION_BAND_MM);
            let over = (need.x / room.x).max(need.y / room.y);
            if over > 1.0 {
                // The scene's diagram scales do not fit: take the turn from the field's width
                // and μ_s from its height, poles chosen for them; then raise both if need be.
                let span = d.s.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                let fresh = req.spec.pole_h1.is_some()
                    || req
                        .spec
                        .scale_phi
                        .is_none_or(|s| s.value() < TAU / (0.75 * r.width()));
                let (phi, s) = if fresh {
                    (TAU / (0.7 * r.width()), span / (0.18 * r.height()))
                } else {
                    (d.scales.x.value() * over, d.scales.y.value() * over)
                };
                req.spec.scale_phi = Scale::new(phi, Quantity::Angle);
                req.spec.scale_s = Scale::round_for(s.max(1e-12), 1.0, Quantity::Length);
                req.spec.pole_h1 = None;
                req.spec.pole_h2 = None;
                changed = true;
            }
        }
        if !changed {
            return Ok((req, a));
        }
    }
    Err(BuildError::Kinematics(Box::new(KinError::Request(
        "the kinematic sheet cannot be fitted on A1".into(),
    ))))
}

/// Bounds of the diagram stack in the first figure's coordinates.
fn stack_bounds(d: &crate::kinematics::Diagrams) -> (DVec2, DVec2) {
    let (lo1, hi1) = d.first_figure.bounds().unwrap_or_default();
    let (lo2, hi2) = d
        .second_figure
        .bounds()
        .map_or((lo1, hi1), |(lo, hi)| (lo + d.second_at, hi + d.second_at));
    (lo1.min(lo2), hi1.max(hi2))
}

/// Build the plate.
pub fn build(scene: &Scene, opts: &RenderOptions) -> Result<Plate, BuildError> {
    let lang = opts.lang;
    let (req, a) = fitted(&scene.mechanism, kin_request(scene, opts.drafting)?)?;
    let mut views = Vec::new();
    let cap = |ru: &str, uk: &str, en: &str, s: Scale| {
        format!("{}, {}", lang.pick(ru, uk, en), s.caption(lang))
    };
    views.push(View::centred(
        a.plan.figure.clone(),
        rect(PLAN),
        Some(cap(
            "План положений",
            "План положень",
            "Plan of positions",
            req.scale_l,
        )),
    )?);
    let n = a.velocity.len();
    let mut notes = Vec::new();
    for ((pos, vp), cell) in
        a.plan
            .positions
            .iter()
            .zip(&a.velocity)
            .zip(cells(rect(VELOCITY), n, VEL_COLUMNS))
    {
        let c = format!("{} {}", lang.pick("Пол.", "Пол.", "Pos."), pos.label);
        match vp {
            Some(vp) => views.push(View::centred(vp.figure.clone(), cell, Some(c))?),
            None => notes.push(TextBlock {
                at: cell.min + DVec2::new(2.0, cell.height() * 0.4),
                lines: vec![
                    c,
                    lang.pick("план не существует:", "план не існує:", "no plan:")
                        .into(),
                    lang.pick("особое положение", "особливе положення", "toggle position")
                        .into(),
                ],
                size_mm: 3.5,
            }),
        }
    }
    for ((k, ap), cell) in a.acceleration.iter().zip(cells(
        rect(ACCELERATION),
        a.acceleration.len(),
        a.acceleration.len(),
    )) {
        let label = &a.plan.positions[*k].label;
        let c = format!(
            "{} {label}",
            lang.pick(
                "План ускорений, пол.",
                "План прискорень, пол.",
                "Acceleration plan, pos."
            )
        );
        views.push(View::centred(ap.figure.clone(), cell, Some(c))?);
    }
    let mut lines = vec![format!(
        "{}: {}; {}: {}",
        lang.pick("Планы скоростей", "Плани швидкостей", "Velocity plans"),
        a.scale_v.caption(lang),
        lang.pick("планы ускорений", "плани прискорень", "acceleration plans"),
        a.scale_a.caption(lang)
    )];
    if let Some(d) = &a.diagrams {
        let r = rect(DIAGRAMS);
        let (lo, hi) = stack_bounds(d);
        // Centre the stack in its field, leaving the caption band under it.
        let centre = (lo + hi) * 0.5;
        let field_centre = r.center() - DVec2::new(0.0, CAPTION_BAND_MM * 0.5);
        let origin = DVec2::new(field_centre.x - centre.x, field_centre.y + centre.y);
        let w = a.w1.abs();
        let dec = |x: f64| format_sig(x, 4, lang);
        let c2 = format!(
            "d²S/dφ²: H_{{2}} = {} {}",
            dec(d.second.pole_mm),
            unit(lang, "мм", "mm")
        );
        views.push(View {
            figure: d.first_figure.clone(),
            origin,
            caption: None,
        });
        views.push(View {
            figure: d.second_figure.clone(),
            origin: origin + DVec2::new(d.second_at.x, -d.second_at.y),
            caption: Some(c2),
        });
        lines.push(format!(
            "{} {}: μ_{{S}} = {} {}, μ_{{φ}} = {} {}, H_{{1}} = {} {}; μ_{{v}} = μ_{{S}}·ω_{{1}}/(H_{{1}}·μ_{{φ}}) = {} {}, μ_{{a}} = {} {}",
            lang.pick("Диаграммы точки", "Діаграми точки", "Diagrams of point"),
            d.point,
            dec(d.scales.y.value()),
            unit(lang, "м/мм", "m/mm"),
            dec(d.scales.x.value()),
            unit(lang, "рад/мм", "rad/mm"),
            dec(d.first.pole_mm),
            unit(lang, "мм", "mm"),
            dec(d.first.scale.value() * w),
            Quantity::Velocity.unit(lang),
            dec(d.second.scale.value() * w * w),
            Quantity::Acceleration.unit(lang)
        ));
    }
    if let Some((name, h)) = &a.hodograph {
        let c = format!(
            "{} v_{{{}}}",
            lang.pick("Годограф", "Годограф", "Hodograph"),
            crate::linkage::plain(name)
        );
        views.push(View::centred(h.clone(), rect(HODOGRAPH), Some(c))?);
        lines.push(format!(
            "{} v_{{{}}}: {}",
            lang.pick("Годограф", "Годограф", "Hodograph"),
            crate::linkage::plain(name),
            h.scale.caption(lang)
        ));
    }
    if let Some(r) = &a.rocker {
        let c = format!("ω_{{{l}}}(φ), dω_{{{l}}}/dφ", l = r.link);
        // Drawn where it fits; its rows are in the report either way.
        if let Ok(v) = View::centred(r.figure.clone(), rect(ROCKER), Some(c)) {
            views.push(v);
            lines.push(format!(
                "ω_{{{}}}(φ): {}, {}, H_{{ω}} = {} {}; ε = |ω_{{1}}|·dω/dφ",
                r.link,
                r.scale.caption(lang),
                r.scale_phi.caption(lang),
                format_sig(r.derivative.pole_mm, 3, lang),
                unit(lang, "мм", "mm")
            ));
        }
    }
    let mut texts = vec![TextBlock {
        at: DVec2::new(TEXT_AT.0, TEXT_AT.1),
        lines,
        size_mm: 3.5,
    }];
    texts.extend(notes);
    let tables_y = TEXT_AT.1 + texts[0].lines.len() as f64 * 7.0 + 6.0;
    let tables = tables(&a, scene, lang, tables_y);
    let index = scene
        .plates
        .iter()
        .position(|k| *k == crate::scene::PlateKind::Kinematics)
        .unwrap_or(0);
    Ok(Plate {
        name: "kinematics".into(),
        sheet: Sheet {
            size: SheetSize::A1,
            landscape: true,
        },
        title_block: super::title_block(
            scene,
            lang.pick(
                "Кинематический анализ",
                "Кінематичний аналіз",
                "Kinematic analysis",
            ),
            index as u32 + 1,
            scene.plates.len() as u32,
        ),
        lang,
        views,
        texts,
        tables,
    })
}

fn unit(lang: Lang, ru: &'static str, en: &'static str) -> &'static str {
    lang.pick(ru, ru, en)
}

/// A table cell: 4 significant digits; what is zero to rounding is written 0.
fn cell(x: f64, lang: Lang) -> String {
    if x.abs() < 1e-9 {
        "0".into()
    } else {
        format_sig(x, 4, lang)
    }
}

/// The analytic table and the error estimates (section 1.6 of the seed), side by side, kept
/// left of the title block.
fn tables(a: &Analysis, scene: &Scene, lang: Lang, y: f64) -> Vec<TableBlock> {
    let size = 2.5;
    let errors_w = 86.0;
    let t = &a.table;
    let pos_w = 9.0;
    let avail = TABLES_RIGHT - TABLES_X - errors_w - 8.0;
    let col_w = ((avail - pos_w) / t.columns.len().max(1) as f64).clamp(12.0, 22.0);
    let shown = (((avail - pos_w) / col_w) as usize).min(t.columns.len());
    let mut columns = vec![("№".to_string(), pos_w)];
    columns.extend(
        t.columns
            .iter()
            .take(shown)
            .map(|c| (format!("{}, {}", c.name, c.unit), col_w)),
    );
    let rows = t
        .rows
        .iter()
        .map(|(label, vals)| {
            std::iter::once(label.clone())
                .chain(
                    vals.iter()
                        .take(shown)
                        .map(|v| v.map_or(String::new(), |x| cell(x, lang))),
                )
                .collect()
        })
        .collect();
    let analytic = TableBlock {
        at: DVec2::new(TABLES_X, y),
        title: lang
            .pick(
                "Аналитический расчёт",
                "Аналітичний розрахунок",
                "Analytic solution",
            )
            .into(),
        columns,
        rows,
        size_mm: size,
    };
    let report = Report {
        scene: scene.stem.clone(),
        rows: a.rows.clone(),
        tables: Vec::new(),
        notes: Vec::new(),
    };
    let summary = report.summary();
    let method = |m: Method| m.name(lang).to_string();
    let room = (((TABLES_END - y) / (size * 2.0)) as usize).saturating_sub(1);
    // The diagrams first (the textbook's comparison), then the plans' largest errors.
    // Diagrams first (the textbook's comparison), then by the error as displayed (0.01 %),
    // ties in report order: rounding noise must not reorder the table.
    let shown_pct = |x: f64| (x * 1e4).round() as i64;
    let mut entries: Vec<_> = summary
        .entries
        .iter()
        .filter(|e| !e.quantity.starts_with("s_"))
        .collect();
    entries.sort_by_key(|e| (e.method == Method::Plan, -shown_pct(e.max_abs_rel)));
    let err_rows: Vec<Vec<String>> = entries
        .into_iter()
        .take(room)
        .map(|e| {
            let worst = if shown_pct(e.max_abs_rel) > 0 {
                e.worst_position.clone()
            } else {
                "—".into()
            };
            vec![
                e.quantity.replace('_', " "),
                method(e.method),
                format_fixed(e.mean_abs_rel * 100.0, 2, lang),
                format_fixed(e.max_abs_rel * 100.0, 2, lang),
                worst,
            ]
        })
        .collect();
    let errors = TableBlock {
        at: DVec2::new(TABLES_RIGHT - errors_w, y),
        title: lang
            .pick(
                "Погрешность графических методов",
                "Похибка графічних методів",
                "Errors of the graphical methods",
            )
            .into(),
        columns: vec![
            (lang.pick("величина", "величина", "quantity").into(), 24.0),
            (lang.pick("метод", "метод", "method").into(), 20.0),
            ("δ ср., %".into(), 16.0),
            ("δ max, %".into(), 16.0),
            (lang.pick("пол.", "пол.", "pos.").into(), 10.0),
        ],
        rows: err_rows,
        size_mm: size,
    };
    vec![analytic, errors]
}
