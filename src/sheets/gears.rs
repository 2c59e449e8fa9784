//! Plate "Зубчатые передачи" (seed 000 sheet 3, seed 002 PZ1–PZ3): the meshing picture with
//! all circles, lines and labels, the diagram of specific sliding, each wheel cut by the rack
//! with its rack positions (and undercut), the data and results, and the table of what was
//! read off the drawings against the analytic values. A1 landscape.

use super::layout::{lay_out_smallest, Block, ScaleKey};
use super::BuildError;
use crate::check::Row;
use crate::geom::DVec2;
use crate::plate::{Plate, SheetSize, TableBlock};
use crate::scale::{format_fixed, format_sig, Lang};
use crate::study::Session;

/// Text height of the data lines and the table, mm.
const TEXT_MM: f64 = 3.5;
const TABLE_MM: f64 = 2.5;

/// A word of the sheet in ru, uk, en.
fn tr(lang: Lang, ru: &'static str, uk: &'static str, en: &'static str) -> &'static str {
    lang.pick(ru, uk, en)
}

/// Build the gear sheet of the scene.
pub fn build(session: &Session<'_>, lang: Lang) -> Result<Vec<Plate>, BuildError> {
    let scene = session.scene();
    let g = session.gears()?;
    let mut blocks = Vec::new();
    let mut lines = vec![tr(
        lang,
        "Исходные данные и результаты",
        "Вихідні дані та результати",
        "Data and results",
    )
    .to_string()];
    let mut plan = None;
    if let Some((p, m)) = &g.pair {
        plan = Some(m.scale);
        let caption = format!(
            "{}, {}",
            tr(
                lang,
                "Картина зацепления",
                "Картина зачеплення",
                "Meshing picture"
            ),
            m.scale.caption(lang)
        );
        blocks.push(view(&m.figure, caption, "gears.scale_l", m.scale));
        let caption = format!(
            "{}: λ_1, λ_2 {} N_1N_2, λ = 1 ↔ {} {}",
            tr(
                lang,
                "Удельное скольжение",
                "Питоме ковзання",
                "Specific sliding"
            ),
            tr(lang, "вдоль", "уздовж", "along"),
            format_sig(crate::gears::mesh::LAMBDA_MM, 3, lang),
            tr(lang, "мм", "мм", "mm"),
        );
        blocks.push(view(&m.sliding, caption, "gears.scale_l", m.scale));
        let mm = |x: f64| format_sig(x * 1e3, 6, lang);
        lines.push(format!(
            "m = {} {u}, z_1 = {}, z_2 = {}, x_1 = {}, x_2 = {}",
            mm(p.spec.module),
            p.spec.z[0],
            p.spec.z[1],
            format_sig(p.spec.x[0], 4, lang),
            format_sig(p.spec.x[1], 4, lang),
            u = tr(lang, "мм", "мм", "mm"),
        ));
        lines.push(format!(
            "α_w = {}°, a_w = {}, y = {}, Δy = {}",
            format_sig(p.alpha_w.to_degrees(), 7, lang),
            mm(p.a_w),
            format_sig(p.y, 5, lang),
            format_sig(p.dy, 4, lang),
        ));
        lines.push(format!(
            "r_{{w1}} = {}, r_{{w2}} = {}, r_{{a1}} = {}, r_{{a2}} = {}, r_{{f1}} = {}, r_{{f2}} = {}",
            mm(p.rw[0]), mm(p.rw[1]), mm(p.ra[0]), mm(p.ra[1]), mm(p.rf[0]), mm(p.rf[1])
        ));
        lines.push(format!(
            "p = {}, p_b = {}, p_w = {}, s_{{a1}} = {}, s_{{a2}} = {}",
            mm(p.p),
            mm(p.p_b),
            mm(p.p_w),
            mm(p.sa[0]),
            mm(p.sa[1])
        ));
        lines.push(format!(
            "ε_α = B_1B_2/p_b = {}; ε′_α = {}",
            format_sig(p.eps, 5, lang),
            format_sig(m.eps, 5, lang)
        ));
    }
    for (name, r) in &g.racks {
        let c = &r.cutting;
        let caption = format!(
            "{} z = {}, x = {}, N = {}, {}{}",
            tr(
                lang,
                "Нарезание рейкой:",
                "Нарізання рейкою:",
                "Cut by the rack:"
            ),
            c.z,
            format_sig(c.x, 4, lang),
            r.steps,
            r.scale.caption(lang),
            if r.undercut {
                tr(
                    lang,
                    "; подрез заштрихован",
                    "; підріз заштриховано",
                    "; the undercut hatched",
                )
            } else {
                ""
            }
        );
        blocks.push(view(&r.figure, caption, "gears.rack.scale_l", r.scale));
        plan.get_or_insert(r.scale);
        lines.push(format!(
            "{name}: z = {}, x = {}, x_{{min}} = {}, s_a = {} {}{}{}",
            c.z,
            format_sig(c.x, 4, lang),
            format_sig(c.x_min(), 4, lang),
            format_sig(r.sa * 1e3, 4, lang),
            tr(lang, "мм", "мм", "mm"),
            if r.undercut {
                tr(lang, ", подрез", ", підріз", ", undercut")
            } else {
                ""
            },
            if r.pointed {
                tr(lang, ", заострение", ", загострення", ", pointed")
            } else {
                ""
            },
        ));
    }
    if let Some(t) = &g.train {
        let tri = &t.triangles;
        let caption = format!(
            "{}, {}, {}, H = {} {}",
            tr(
                lang,
                "Треугольники скоростей и план угловых скоростей",
                "Трикутники швидкостей і план кутових швидкостей",
                "Velocity triangles and the plan of angular velocities"
            ),
            tri.scale_l.caption(lang),
            tri.scale_v.caption(lang),
            format_sig(crate::gears::triangles::PLAN_H, 3, lang),
            tr(lang, "мм", "мм", "mm"),
        );
        blocks.push(view(&tri.figure, caption, "planetary.module", tri.scale_v));
        let tr_ = &t.spec.train;
        for (s, sup) in [(Some(t), ""), (t.required.as_deref(), "^{треб}")] {
            let Some(s) = s else { continue };
            lines.push(format!(
                "u_{{{}-{}}}{sup} = {} (Willis), {} ({})",
                tr_.shafts[tr_.input],
                tr_.shafts[tr_.output],
                format_sig(s.ratio, 6, lang),
                format_sig(s.triangles.ratio, 6, lang),
                tr(lang, "треугольники", "трикутники", "triangles"),
            ));
        }
        if let Some((k, a)) = t.spec.satellites.and_then(|k| Some((k, tr_.assembly(k)?))) {
            lines.push(format!(
                "k = {k}: {} {}",
                tr(
                    lang,
                    "условие сборки",
                    "умова складання",
                    "assembly condition"
                ),
                match (a.fits(), a.p) {
                    (true, Some(p)) => format!("p = {p}"),
                    (true, None) => tr(lang, "выполнено", "виконано", "holds").to_string(),
                    (false, _) => tr(lang, "не выполнено", "не виконано", "fails").to_string(),
                },
            ));
        }
    }
    lines.push(String::new());
    lines.push(super::drafting_line(session.drafting(), lang));
    blocks.push(Block::Text {
        lines,
        size_mm: TEXT_MM,
    });
    blocks.push(Block::Table(table(&g.rows(), lang)));
    let Some(plan) =
        plan.or_else(|| crate::scale::Scale::new(0.001, crate::scale::Quantity::Length))
    else {
        return Ok(Vec::new());
    };
    let title = super::title_block(
        scene,
        tr(lang, "Зубчатые передачи", "Зубчасті передачі", "Gears"),
        plan,
        lang,
    );
    // The course project's whole gear sheet is an A1; a practicum's part of it (a pair, a
    // cut wheel, a train) goes on the smallest sheet that holds it.
    lay_out_smallest(
        &[SheetSize::A3, SheetSize::A2, SheetSize::A1],
        blocks,
        "gears",
        &title,
        lang,
    )
}

/// A view of `figure` with its caption, sized by the scene key `key` at `scale`.
fn view(
    figure: &crate::construct::Figure,
    caption: String,
    key: &'static str,
    scale: crate::scale::Scale,
) -> Block {
    Block::view(figure.clone(), caption, Some(ScaleKey { key, scale }))
}

/// The table graphical | analytic | error of the rows.
fn table(rows: &[Row], lang: Lang) -> TableBlock {
    let errors = crate::check::rel_errors(rows);
    let body = rows
        .iter()
        .zip(errors)
        .map(|(r, e)| {
            let at = r.position().map_or_else(String::new, |p| format!(" ({p})"));
            let k = if r.key.symbol.unit() == "m" { 1e3 } else { 1.0 };
            let unit = if k == 1e3 {
                tr(lang, "мм", "мм", "mm")
            } else if r.key.symbol.unit() == "deg" {
                "°"
            } else {
                ""
            };
            vec![
                format!("{}{at}", r.key.symbol.markup(&r.key.subject)),
                r.method.name(lang).to_string(),
                unit.to_string(),
                format_sig(r.graphical * k, 7, lang),
                format_sig(r.analytic * k, 7, lang),
                e.map_or_else(|| "—".into(), |e| format_fixed(e * 100.0, 4, lang)),
            ]
        })
        .collect();
    TableBlock {
        at: DVec2::ZERO,
        title: tr(
            lang,
            "Графическое решение и аналитический расчёт",
            "Графічний розв'язок і аналітичний розрахунок",
            "Graphical against analytic",
        )
        .into(),
        columns: vec![
            (tr(lang, "величина", "величина", "quantity").into(), 26.0),
            (tr(lang, "метод", "метод", "method").into(), 36.0),
            (tr(lang, "ед.", "од.", "unit").into(), 10.0),
            (tr(lang, "графически", "графічно", "graphical").into(), 24.0),
            (
                tr(lang, "аналитически", "аналітично", "analytic").into(),
                26.0,
            ),
            ("δ, %".into(), 16.0),
        ],
        rows: body,
        size_mm: TABLE_MM,
    }
}
