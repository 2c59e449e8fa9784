//! Plate "Синтез кулачкового механизма" (the textbook's sheet 4): the diagrams d²S/dφ²,
//! dS/dφ, S with their integration construction, the combined diagram with the zone of the
//! cam centre (or the flat face's 45° tangent), the profile by inversion with the roller
//! circles and both profiles, the angle graph, the data and the table of the points.

use super::layout::{lay_out, Block, ScaleKey};
use super::BuildError;
use crate::cam::{Cam, Follower, Law};
use crate::check::{rel_errors, Symbol};
use crate::geom::DVec2;
use crate::plate::{Plate, Sheet, SheetSize, TableBlock};
use crate::scale::{format_fixed, format_sig, Lang, Scale};
use crate::study::Session;

/// Text height of the data lines and the tables, mm.
const TEXT_MM: f64 = 3.5;
const TABLE_MM: f64 = 2.5;

fn tr(lang: Lang, ru: &'static str, uk: &'static str, en: &'static str) -> &'static str {
    lang.pick(ru, uk, en)
}

/// A scale's caption with its own symbol (`μ_{S′} = 0,00093 м/мм`).
fn mu(symbol: &str, s: Scale, lang: Lang) -> String {
    format!(
        "μ_{{{symbol}}} = {} {}",
        format_sig(s.value(), 4, lang),
        s.quantity.unit(lang)
    )
}

fn keyed(key: &'static str, scale: Scale) -> Option<ScaleKey> {
    Some(ScaleKey { key, scale })
}

/// Build the cam sheet.
pub fn build(session: &Session<'_>, lang: Lang) -> Result<Vec<Plate>, BuildError> {
    let scene = session.scene();
    let cam = session.cam()?;
    let d = &cam.diagrams;
    let mm = tr(lang, "мм", "мм", "mm");
    let h = |i: usize| format_sig(d.poles[i], 3, lang);
    // The two constructions of the diagrams with their scales: S given, differentiated
    // twice by chords; or d²S/dφ² given, integrated twice.
    let (first, second) = if cam.spec.from_s {
        (
            (
                format!(
                    "S → dS/dφ: {}, {}, H_2 = {} {mm}",
                    mu("S", d.s_scale, lang),
                    mu("S′", d.ds_scale, lang),
                    h(1),
                ),
                keyed("cam.scale_s", d.s_scale),
            ),
            (
                format!(
                    "dS/dφ → d^2S/dφ^2: {}, {}, H_1 = {} {mm}",
                    mu("φ", d.phi, lang),
                    mu("S″", d.d2s_scale, lang),
                    h(0),
                ),
                keyed("cam.scale_phi", d.phi),
            ),
        )
    } else {
        (
            (
                format!(
                    "d^2S/dφ^2 → dS/dφ: {}, {}, {}, H_1 = {} {mm}",
                    mu("φ", d.phi, lang),
                    mu("S″", d.d2s_scale, lang),
                    mu("S′", d.ds_scale, lang),
                    h(0),
                ),
                keyed("cam.scale_phi", d.phi),
            ),
            (
                format!(
                    "dS/dφ → S: {}, H_2 = {} {mm}",
                    mu("S", d.s_scale, lang),
                    h(1)
                ),
                keyed("cam.scale_s", d.s_scale),
            ),
        )
    };
    let mut blocks = vec![
        Block::view(d.first.clone(), first.0, first.1),
        Block::view(d.second.clone(), second.0, second.1),
    ];
    let combined = match cam.spec.follower {
        Follower::Flat { .. } => tr(
            lang,
            "Совмещённая диаграмма S(d^2S/dφ^2), касательная 45°",
            "Суміщена діаграма S(d^2S/dφ^2), дотична 45°",
            "Combined diagram S(d^2S/dφ^2), the 45° tangent",
        ),
        Follower::Rocker { .. } => tr(
            lang,
            "Определение r_{min}: dS/dφ по коромыслу, лучи γ_{min}",
            "Визначення r_{min}: dS/dφ уздовж коромисла, промені γ_{min}",
            "r_{min}: dS/dφ along the rocker, the γ_{min} lines",
        ),
        Follower::Translating { .. } => tr(
            lang,
            "Совмещённая диаграмма S(dS/dφ), зона центра",
            "Суміщена діаграма S(dS/dφ), зона центру",
            "Combined diagram S(dS/dφ), the centre's zone",
        ),
    };
    blocks.push(Block::view(
        cam.radius.figure.clone(),
        format!("{combined}, {}", mu("S", d.s_scale, lang)),
        keyed("cam.scale_s", d.s_scale),
    ));
    blocks.push(Block::view(
        cam.inversion.figure.clone(),
        format!(
            "{}, {}",
            tr(
                lang,
                "Профиль кулачка (обращение движения)",
                "Профіль кулачка (обернення руху)",
                "Cam profile by inversion"
            ),
            cam.inversion.scale.caption(lang)
        ),
        keyed("cam.scale_l", cam.inversion.scale),
    ));
    if let Some(g) = &cam.angle_graph {
        let what = if matches!(cam.spec.follower, Follower::Rocker { .. }) {
            tr(
                lang,
                "Угол передачи γ(φ)",
                "Кут передачі γ(φ)",
                "Transmission angle γ(φ)",
            )
        } else {
            tr(
                lang,
                "Угол давления λ(φ)",
                "Кут тиску λ(φ)",
                "Pressure angle λ(φ)",
            )
        };
        blocks.push(Block::view(
            g.clone(),
            format!(
                "{what}, {}, μ_{{γ}} = 1 °/{}",
                mu("φ", d.phi, lang),
                tr(lang, "мм", "мм", "mm")
            ),
            None,
        ));
    }
    let mut lines = data_lines(&cam, lang);
    lines.push(String::new());
    lines.push(super::drafting_line(session.drafting(), lang));
    blocks.push(Block::Text {
        lines,
        size_mm: TEXT_MM,
    });
    blocks.extend(points_table(&cam, lang).into_iter().map(Block::Table));
    blocks.push(Block::Table(results_table(&cam, lang)));
    let title = super::title_block(
        scene,
        tr(
            lang,
            "Синтез кулачкового механизма",
            "Синтез кулачкового механізму",
            "Cam mechanism synthesis",
        ),
        cam.inversion.scale,
        lang,
    );
    let sheet = Sheet {
        size: SheetSize::A1,
        landscape: true,
    };
    lay_out(sheet, blocks, "cam", &title, lang)
}

/// A law's name in `lang`.
fn law_name(law: Law, lang: Lang) -> String {
    match law {
        Law::Uniform => tr(
            lang,
            "равномерный (жёсткие удары)",
            "рівномірний (жорсткі удари)",
            "uniform (rigid shocks)",
        )
        .into(),
        Law::ConstantAcceleration { ratio } => format!(
            "«+ −» ({} {})",
            tr(lang, "доля разгона", "частка розгону", "ratio"),
            format_sig(ratio, 3, lang)
        ),
        Law::Cosine => tr(lang, "косинусоидальный", "косинусоїдальний", "cosine").into(),
        Law::Sine => tr(lang, "синусоидальный", "синусоїдальний", "sine (cycloidal)").into(),
        Law::Trapezoidal => tr(lang, "трапецеидальный", "трапецієподібний", "trapezoidal").into(),
        Law::Polynomial345 => tr(lang, "полином 3-4-5", "поліном 3-4-5", "3-4-5 polynomial").into(),
    }
}

/// The task's data and the results, as text lines.
fn data_lines(cam: &Cam, lang: Lang) -> Vec<String> {
    let s = &cam.spec;
    let mm = tr(lang, "мм", "мм", "mm");
    let n = |x: f64| format_sig(x * 1e3, 4, lang);
    let deg = |x: f64| format_sig(x.to_degrees(), 4, lang);
    let mut out = vec![tr(lang, "Исходные данные", "Вихідні дані", "Data").to_string()];
    let p = &s.phases;
    out.push(format!(
        "φ_{{у}} = {}°, φ_{{д.в.}} = {}°, φ_{{п}} = {}°, φ_{{б.в.}} = {}°",
        deg(p.rise),
        deg(p.far),
        deg(p.ret),
        deg(p.near)
    ));
    out.push(
        if cam.clockwise {
            tr(
                lang,
                "Кулачок вращается по часовой стрелке",
                "Кулачок обертається за годинниковою стрілкою",
                "The cam turns clockwise",
            )
        } else {
            tr(
                lang,
                "Кулачок вращается против часовой стрелки",
                "Кулачок обертається проти годинникової стрілки",
                "The cam turns counter-clockwise",
            )
        }
        .into(),
    );
    out.push(format!(
        "{}: {}; {}: {}",
        tr(lang, "закон удаления", "закон віддалення", "rise law"),
        law_name(s.rise, lang),
        tr(lang, "приближения", "наближення", "return"),
        law_name(s.ret, lang)
    ));
    if s.law_assumed {
        out.push(
            tr(
                lang,
                "Диаграммы источника утеряны: закон движения принят",
                "Діаграми джерела втрачено: закон руху прийнято",
                "The source's diagrams are lost: the law is assumed",
            )
            .into(),
        );
    }
    match s.follower {
        Follower::Rocker { arm, .. } => out.push(format!(
            "L = {} {mm}, β_{{max}} = {}°, S_{{max}} = Lβ_{{max}} = {} {mm}, γ_{{min}} = {}°",
            n(arm),
            deg(s.stroke / arm),
            n(s.stroke),
            deg(s.gamma_min)
        )),
        Follower::Translating { offset } => out.push(format!(
            "h = {} {mm}, e = {} {mm}, γ_{{min}} = {}°",
            n(s.stroke),
            n(cam.scene_offset(offset)),
            deg(s.gamma_min)
        )),
        Follower::Flat { offset } => out.push(format!(
            "h = {} {mm}, e = {} {mm}, ρ_{{min}} = {} {mm}",
            n(s.stroke),
            n(cam.scene_offset(offset)),
            n(s.rho_min)
        )),
    }
    out.push(String::new());
    out.push(format!(
        "r_{{min}} = {} {mm} ({}), {} {mm} ({})",
        n(cam.radius.graphical),
        tr(lang, "графически", "графічно", "graphical"),
        n(cam.exact_r_min()),
        tr(lang, "точно", "точно", "exact")
    ));
    if let Some(q) = s.quoted_r_min {
        out.push(format!(
            "{} r_{{min}} = {} {mm} {}",
            tr(lang, "В источнике", "У джерелі", "The source's"),
            n(q),
            tr(
                lang,
                "— не согласовано с γ_{min} (ошибка)",
                "— не узгоджено з γ_{min} (помилка)",
                "is inconsistent with γ_{min} (erratum)"
            )
        ));
    }
    out.push(format!("r_{{0}} = {} {mm}", n(cam.base)));
    if !matches!(s.follower, Follower::Flat { .. }) {
        let rho = cam.exact_rho_min();
        out.push(format!(
            "0,4·r_{{0}} = {} {mm}, 0,8·ρ_{{min}} = {} {mm} → r_{{р}} = {} {mm}",
            n(0.4 * cam.base),
            // The roller is chosen from the drawn pitch curve's ρ_min.
            n(0.8 * cam.inversion.rho_min),
            n(cam.roller)
        ));
        if cam.roller >= rho {
            out.push(format!(
                "{} ρ_{{min}} = {} {mm}",
                tr(
                    lang,
                    "ПОДРЕЗ: r_{р} >",
                    "ПІДРІЗ: r_{р} >",
                    "UNDERCUT: r_{р} >"
                ),
                n(rho)
            ));
        }
    } else if cam.exact_rho_min() < 0.0 {
        out.push(
            tr(
                lang,
                "ЗАОСТРЕНИЕ: профиль вогнутый, r_{0} + S + S″ < 0",
                "ЗАГОСТРЕННЯ: профіль угнутий, r_{0} + S + S″ < 0",
                "CUSP: the profile is concave, r_{0} + S + S″ < 0",
            )
            .into(),
        );
    }
    if matches!(s.rise.shock(), crate::cam::Shock::Rigid)
        || matches!(s.ret.shock(), crate::cam::Shock::Rigid)
    {
        out.push(
            tr(
                lang,
                "Жёсткие удары на границах фаз",
                "Жорсткі удари на межах фаз",
                "Rigid shocks at the phase ends",
            )
            .into(),
        );
    }
    if matches!(s.follower, Follower::Translating { offset } if offset < 0.0) {
        out.push(
            tr(
                lang,
                "Смещение e с неблагоприятной стороны",
                "Зміщення e з несприятливого боку",
                "The offset e is on the unfavourable side",
            )
            .into(),
        );
    }
    out
}

/// The most rows of one table of points; more continue in further tables (placed on further
/// sheets when a sheet is full).
const POINTS_PER_TABLE: usize = 40;

/// One row per point: φ, S, dS/dφ, d²S/dφ² (read), the angle read and exact, the profile's
/// radius vector; in tables of at most [`POINTS_PER_TABLE`] rows, each after the first
/// titled as continued.
fn points_table(cam: &Cam, lang: Lang) -> Vec<TableBlock> {
    let rocker = matches!(cam.spec.follower, Follower::Rocker { .. });
    let flat = matches!(cam.spec.follower, Follower::Flat { .. });
    let f = |x: f64, d: usize| format_fixed(x, d, lang);
    let rows = cam
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let mut r = vec![
                p.label.clone(),
                f(p.phi.to_degrees(), 1),
                f(cam.diagrams.s[i] * 1e3, 2),
                f(cam.diagrams.ds[i] * 1e3, 2),
                f(cam.diagrams.d2s[i] * 1e3, 2),
            ];
            if !flat {
                let g = cam.inversion.angles[i];
                let g = if rocker {
                    std::f64::consts::FRAC_PI_2 - g
                } else {
                    g
                };
                r.push(f(g.to_degrees(), 1));
                r.push(f(cam.angle_at(p.phi, p.after).to_degrees(), 1));
            }
            r.push(f(cam.inversion.profile[i].length() * 1e3, 2));
            r
        })
        .collect();
    let a = if rocker { "γ" } else { "λ" };
    let mut columns = vec![
        ("№".into(), 8.0),
        ("φ, °".into(), 14.0),
        ("S, мм".replace("мм", tr(lang, "мм", "мм", "mm")), 16.0),
        (format!("dS/dφ, {}", tr(lang, "мм", "мм", "mm")), 20.0),
        (format!("d^2S/dφ^2, {}", tr(lang, "мм", "мм", "mm")), 24.0),
    ];
    if !flat {
        columns.push((
            format!("{a} {}, °", tr(lang, "граф.", "граф.", "graph.")),
            18.0,
        ));
        columns.push((
            format!("{a} {}, °", tr(lang, "точно", "точно", "exact")),
            18.0,
        ));
    }
    columns.push((format!("R, {}", tr(lang, "мм", "мм", "mm")), 16.0));
    let title = tr(
        lang,
        "Точки диаграмм и профиля",
        "Точки діаграм і профілю",
        "Points of the diagrams and the profile",
    );
    let rows: Vec<Vec<String>> = rows;
    rows.chunks(POINTS_PER_TABLE)
        .enumerate()
        .map(|(i, chunk)| TableBlock {
            at: DVec2::ZERO,
            title: if i == 0 {
                title.into()
            } else {
                format!(
                    "{title} ({})",
                    tr(lang, "продолжение", "продовження", "continued")
                )
            },
            columns: columns.clone(),
            rows: chunk.to_vec(),
            size_mm: TABLE_MM,
        })
        .collect()
}

/// The values of the whole scene: graphical against exact.
fn results_table(cam: &Cam, lang: Lang) -> TableBlock {
    let rows: Vec<_> = cam
        .rows()
        .into_iter()
        .filter(|r| r.key.at == crate::check::At::Scene)
        .collect();
    let errors = rel_errors(&rows);
    let body = rows
        .iter()
        .zip(errors)
        .map(|(r, e)| {
            let name = match (r.key.symbol, r.key.subject.as_str()) {
                (Symbol::Radius, "min") => "r_{min}".to_string(),
                (Symbol::Radius, _) => "r_{р}".to_string(),
                (Symbol::CurvatureRadius, _) => "ρ_{min}".to_string(),
                (Symbol::ProfileDeviation, _) => {
                    "Δ_{проф}".replace("проф", tr(lang, "проф", "проф", "prof"))
                }
                (s, sub) => s.markup(sub),
            };
            vec![
                name,
                format_sig(r.graphical * 1e3, 5, lang),
                format_sig(r.analytic * 1e3, 5, lang),
                e.map_or_else(|| "—".into(), |e| format_fixed(e * 100.0, 3, lang)),
            ]
        })
        .collect();
    TableBlock {
        at: DVec2::ZERO,
        title: tr(
            lang,
            "Графически и точно, мм",
            "Графічно і точно, мм",
            "Graphical against exact, mm",
        )
        .into(),
        columns: vec![
            (tr(lang, "величина", "величина", "quantity").into(), 22.0),
            (tr(lang, "графически", "графічно", "graphical").into(), 26.0),
            (tr(lang, "точно", "точно", "exact").into(), 26.0),
            ("δ, %".into(), 16.0),
        ],
        rows: body,
        size_mm: TABLE_MM,
    }
}
