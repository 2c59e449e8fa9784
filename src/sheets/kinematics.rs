//! Plate "Кинематический анализ" (the textbook's sheet 1): the plan of positions, a velocity
//! plan for every position, the acceleration plans, the displacement diagram with its two
//! chord-method derivatives, the hodograph, the analytic table and the error estimates.
//! Every group of views has its own field; its μ is raised along the textbook series until
//! the drawings fit (the captions state the μ actually used).

use super::captions::Text;
use super::fit::{self, figure_size, fit_scale, overflow, room, Extent, Fit};
use super::BuildError;
use crate::construct::Figure;
use crate::geom::DVec2;
use crate::kinematics::plans::drawn_points;
use crate::linkage::PlanKind;
use crate::plate::{Plate, Rect, Sheet, SheetSize, TableBlock, TextBlock, View, CAPTION_BAND_MM};
use crate::report::{Method, Report};
use crate::scale::{format_fixed, format_sig, Lang, Quantity, Scale};
use crate::study::{ChartScales, KinScales, Kinematics, Session};
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

fn rect(r: [f64; 4]) -> Rect {
    Rect::new(DVec2::new(r[0], r[1]), DVec2::new(r[2], r[3]))
}

fn field(r: [f64; 4]) -> DVec2 {
    let r = rect(r);
    r.max - r.min
}

/// How much a set of figures overflows cells of `cell` size (≤ 1: fits).
fn figures_overflow<'a>(figs: impl IntoIterator<Item = &'a Figure>, cell: DVec2) -> f64 {
    figs.into_iter()
        .map(|f| overflow(figure_size(f), room(cell)))
        .fold(0.0f64, f64::max)
}

/// The next round scale at least `ratio` times larger.
fn bump(s: Scale, ratio: f64) -> Scale {
    fit::raised(s, ratio).unwrap_or(s)
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

/// The largest of several predicted sizes, component-wise.
fn largest(extents: &[Extent], mu: Scale) -> DVec2 {
    extents
        .iter()
        .fold(DVec2::ZERO, |m, e| m.max(e.labelled_size_at(mu)))
}

/// The sheet's scales, chosen before anything is constructed: each view starts at the
/// scene's μ (or the textbook's) and is raised along the round series until its drawing,
/// predicted from the analytic twin, fits its field.
fn predicted_scales(session: &Session<'_>) -> Result<KinScales, BuildError> {
    let mut sc = session.kin_scales()?;
    let poses = session.poses()?;
    let m = session.mechanism("the kinematic sheet")?;
    let w1 = crate::kinematics::crank_rate(&m.crank);
    let plan = fit::positions_extent(&poses);
    let points = |k: usize, kind| fit::plan_extent(&drawn_points(&poses, k, w1, kind));
    sc.l = fit_scale(sc.l, room(field(PLAN)), Fit::Raise, |mu| {
        plan.labelled_size_at(mu)
    })
    .unwrap_or(sc.l);
    let vel: Vec<Extent> = (0..poses.positions.len())
        .map(|k| points(k, PlanKind::Velocity))
        .collect();
    let cell = room(vel_cell(vel.len()));
    sc.v = fit_scale(sc.v, cell, Fit::Raise, |mu| largest(&vel, mu)).unwrap_or(sc.v);
    let asked = session.acceleration_positions()?;
    let acc: Vec<Extent> = asked
        .iter()
        .map(|&k| points(k, PlanKind::Acceleration))
        .collect();
    let cell = room(acc_cell(acc.len()));
    sc.a = fit_scale(sc.a, cell, Fit::Raise, |mu| largest(&acc, mu)).unwrap_or(sc.a);
    Ok(sc)
}

/// The study at the sheet's scales. The scales are predicted first, so each position and
/// each plan is constructed once; should a constructed plan still overflow its field (the
/// prediction allows for its construction lines, not its labels), its μ is raised and the
/// plans are drawn again. The displacement chart is fitted to its field afterwards: it is
/// read off the plan of positions, which does not change.
fn fitted(session: &Session<'_>) -> Result<Kinematics, BuildError> {
    let mut sc = predicted_scales(session)?;
    for _ in 0..8 {
        let k = session.kinematics(&sc)?;
        let mut changed = false;
        let plan_over = figures_overflow([&k.plan.figure], field(PLAN));
        if plan_over > 1.0 {
            sc.l = bump(sc.l, plan_over);
            changed = true;
        }
        let vel = k.velocity_plans();
        let mut v_over =
            figures_overflow(vel.iter().flatten().map(|p| &p.figure), vel_cell(vel.len()));
        if let Some((_, h)) = &k.hodograph {
            v_over = v_over.max(figures_overflow([h.as_ref()], field(HODOGRAPH)));
        }
        if v_over > 1.0 {
            sc.v = bump(sc.v, v_over);
            changed = true;
        }
        let acc = k.acceleration.iter().map(|p| &p.1 .0.figure);
        let a_over = figures_overflow(acc, acc_cell(k.acceleration.len()));
        if a_over > 1.0 {
            sc.a = bump(sc.a, a_over);
            changed = true;
        }
        if let Some(d) = &k.diagrams {
            if let Some(chart) = refit_chart(d, &sc.chart) {
                sc.chart = chart;
                changed = true;
            }
        }
        if !changed {
            return Ok(k);
        }
    }
    Err(BuildError::NoFit("the kinematic sheet"))
}

/// New chart scales when the diagram stack overflows its field: the turn from the field's
/// width and μ_s from its height, poles chosen for them; or both raised if need be.
fn refit_chart(d: &crate::kinematics::Diagrams, chart: &ChartScales) -> Option<ChartScales> {
    let r = rect(DIAGRAMS);
    let (lo, hi) = d.bounds();
    let need = hi - lo + DVec2::splat(fit::LABEL_MARGIN);
    let over = overflow(need, room(r.max - r.min));
    if over <= 1.0 {
        return None;
    }
    let span = d.s.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let fresh = chart.h1.is_some()
        || chart
            .phi
            .is_none_or(|s| s.value() < TAU / (0.75 * r.width()));
    let (phi, s) = if fresh {
        (TAU / (0.7 * r.width()), span / (0.18 * r.height()))
    } else {
        (d.scales.x.value() * over, d.scales.y.value() * over)
    };
    Some(ChartScales {
        phi: Scale::new(phi, Quantity::Angle),
        s: Scale::round_for(s.max(1e-12), 1.0, Quantity::Length),
        h1: None,
        h2: None,
    })
}

/// Build the plate.
pub fn build(session: &Session<'_>, lang: Lang) -> Result<Plate, BuildError> {
    let scene = session.scene();
    let a = fitted(session)?;
    let req = &a.scales;
    let mut views = Vec::new();
    let caption = format!(
        "{}, {}",
        Text::PlanOfPositions.get(lang),
        req.l.caption(lang)
    );
    views.push(View::centred(
        a.plan.figure.clone(),
        rect(PLAN),
        Some(caption),
    )?);
    let velocity = a.velocity_plans();
    let n = velocity.len();
    let mut notes = Vec::new();
    for ((pos, vp), cell) in
        a.plan
            .positions
            .iter()
            .zip(&velocity)
            .zip(cells(rect(VELOCITY), n, VEL_COLUMNS))
    {
        let c = format!("{} {}", Text::Pos.get(lang), pos.label);
        match vp {
            Some(vp) => views.push(View::centred(vp.figure.clone(), cell, Some(c))?),
            None => notes.push(TextBlock {
                at: cell.min + DVec2::new(2.0, cell.height() * 0.4),
                lines: vec![
                    c,
                    Text::NoPlan.get(lang).into(),
                    Text::TogglePosition.get(lang).into(),
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
        let c = format!("{} {label}", Text::AccelerationPlanAt.get(lang));
        views.push(View::centred(ap.0.figure.clone(), cell, Some(c))?);
    }
    let mut lines = vec![format!(
        "{}: {}; {}: {}",
        Text::VelocityPlans.get(lang),
        req.v.caption(lang),
        Text::AccelerationPlans.get(lang),
        req.a.caption(lang)
    )];
    if let Some(d) = &a.diagrams {
        let r = rect(DIAGRAMS);
        let (lo, hi) = d.bounds();
        // Centre the stack in its field, leaving the caption band under it.
        let centre = (lo + hi) * 0.5;
        let field_centre = r.center() - DVec2::new(0.0, CAPTION_BAND_MM * 0.5);
        let origin = DVec2::new(field_centre.x - centre.x, field_centre.y + centre.y);
        let w = a.w1.abs();
        let dec = |x: f64| format_sig(x, 4, lang);
        let c2 = format!(
            "d²S/dφ²: H_{{2}} = {} {}",
            dec(d.second.pole_mm),
            Text::Millimetre.get(lang)
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
            Text::DiagramsOfPoint.get(lang),
            d.point,
            dec(d.scales.y.value()),
            Quantity::Length.unit(lang),
            dec(d.scales.x.value()),
            Quantity::Angle.unit(lang),
            dec(d.first.pole_mm),
            Text::Millimetre.get(lang),
            dec(d.first.scale.value() * w),
            Quantity::Velocity.unit(lang),
            dec(d.second.scale.value() * w * w),
            Quantity::Acceleration.unit(lang)
        ));
    }
    if let Some((name, h)) = &a.hodograph {
        let c = format!("{} v_{{{}}}", Text::Hodograph.get(lang), name);
        views.push(View::centred(h.as_ref().clone(), rect(HODOGRAPH), Some(c))?);
        lines.push(format!(
            "{} v_{{{}}}: {}",
            Text::Hodograph.get(lang),
            name,
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
                Text::Millimetre.get(lang)
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
            Text::KinematicAnalysis.get(lang),
            index as u32 + 1,
            scene.plates.len() as u32,
        ),
        lang,
        views,
        texts,
        tables,
    })
}

/// A table cell: 4 significant digits; what is zero to rounding against its column's
/// scale (the rule of the report, [`crate::check::is_zero`]) is written 0.
fn cell(x: f64, scale: f64, lang: Lang) -> String {
    if crate::check::is_zero(x, scale) {
        "0".into()
    } else {
        format_sig(x, 4, lang)
    }
}

/// The analytic table and the error estimates (section 1.6 of the seed), side by side, kept
/// left of the title block.
fn tables(a: &Kinematics, scene: &crate::scene::Scene, lang: Lang, y: f64) -> Vec<TableBlock> {
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
    // Each column's scale: its largest magnitude over the positions.
    let scales: Vec<f64> = (0..shown)
        .map(|c| {
            t.rows
                .iter()
                .filter_map(|(_, v)| v.get(c).copied().flatten())
                .filter(|x| x.is_finite())
                .fold(0.0f64, |m, x| m.max(x.abs()))
        })
        .collect();
    let rows = t
        .rows
        .iter()
        .map(|(label, vals)| {
            std::iter::once(label.clone())
                .chain(
                    vals.iter()
                        .zip(&scales)
                        .map(|(v, &sc)| v.map_or(String::new(), |x| cell(x, sc, lang))),
                )
                .collect()
        })
        .collect();
    let analytic = TableBlock {
        at: DVec2::new(TABLES_X, y),
        title: Text::AnalyticSolution.get(lang).into(),
        columns,
        rows,
        size_mm: size,
    };
    let report = Report {
        scene: scene.stem.clone(),
        // The displacement is a reading, not a derived quantity: it has no error estimate.
        rows: a
            .rows()
            .into_iter()
            .filter(|r| r.key.symbol != crate::check::Symbol::Displacement)
            .collect(),
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
    let mut entries: Vec<_> = summary.entries.iter().collect();
    entries.sort_by_key(|e| (e.method == Method::Plan, -shown_pct(e.max_abs_rel)));
    let err_rows: Vec<Vec<String>> = entries
        .into_iter()
        .take(room)
        .map(|e| {
            let worst = if shown_pct(e.max_abs_rel) > 0 {
                e.worst_position.clone().unwrap_or_default()
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
        title: Text::MethodErrors.get(lang).into(),
        columns: vec![
            (Text::Quantity.get(lang).into(), 24.0),
            (Text::Method.get(lang).into(), 20.0),
            ("δ ср., %".into(), 16.0),
            ("δ max, %".into(), 16.0),
            (Text::PosShort.get(lang).into(), 10.0),
        ],
        rows: err_rows,
        size_mm: size,
    };
    vec![analytic, errors]
}
