//! Plate "План положений": structural scheme and analysis, the plan of positions with its
//! construction, trajectories and extreme positions, θ, H and K.

use super::{BuildError, RenderOptions};
use crate::geom::{DVec2, Tolerances};
use crate::linkage::{
    plan_positions, structure_figure, DyadKind, Mechanism, OutputCoord, PlanRequest, PositionPlan,
    Structure,
};
use crate::plate::{Plate, Rect, Sheet, SheetSize, TextBlock, View};
use crate::scale::{format_fixed, format_sig, Lang, Quantity, Scale};
use crate::scene::{Scene, Start};

/// Sheet A1 landscape: the field for the plan (right) and the left column.
const PLAN_REGION: (f64, f64, f64, f64) = (300.0, 12.0, 830.0, 528.0);
const SCHEME_REGION: (f64, f64, f64, f64) = (26.0, 12.0, 294.0, 300.0);
/// Preferred drawn length of the crank when the scene gives no μ_l (textbook: 40–60 mm).
const CRANK_MM: f64 = 50.0;
/// Preferred size of the structural scheme, mm.
const SCHEME_MM: f64 = 170.0;
/// Largest share of its field the plan may take when μ_l is chosen automatically.
const FILL: f64 = 0.9;

fn rect(r: (f64, f64, f64, f64)) -> Rect {
    Rect::new(DVec2::new(r.0, r.1), DVec2::new(r.2, r.3))
}

/// The positions a scene asks for.
pub fn request(scene: &Scene) -> PlanRequest {
    PlanRequest {
        count: scene.positions.count,
        start: match scene.positions.start {
            Start::WorkingStroke => None,
            Start::Angle(a) => Some(a),
        },
        other_extreme: scene.positions.other_extreme,
        continuity: scene.positions.continuity,
    }
}

/// Build the plate.
pub fn build(scene: &Scene, opts: &RenderOptions) -> Result<Plate, BuildError> {
    let m = &scene.mechanism;
    let req = request(scene);
    let region = rect(PLAN_REGION);
    let (scale, plan) = match scene.scale_l {
        Some(s) => (s, plan_positions(m, &req, s, opts.drafting)?),
        None => fitted_plan(m, &req, region, opts)?,
    };
    let lang = opts.lang;
    let st = Structure::analyse(m);
    let plan_caption = format!(
        "{}, {}",
        lang.pick(
            "План положений механизма",
            "План положень механізму",
            "Plan of positions"
        ),
        scale.caption(lang)
    );
    let mut views = vec![View::centred(
        plan.figure.clone(),
        region,
        Some(plan_caption),
    )?];
    let extent = plan
        .figure
        .bounds()
        .map_or(1.0, |(lo, hi)| (hi - lo).max_element())
        * scale.value();
    views.push(scheme_view(&plan, &st, scale, extent, lang)?);
    let mut lines = structure_lines(&st, m, lang);
    lines.push(String::new());
    lines.extend(extreme_lines(&plan, lang));
    let texts = vec![TextBlock {
        at: DVec2::new(28.0, 318.0),
        lines,
        size_mm: 3.5,
    }];
    Ok(Plate {
        name: "positions".into(),
        sheet: Sheet {
            size: SheetSize::A1,
            landscape: true,
        },
        title_block: super::title_block(
            scene,
            lang.pick("План положений", "План положень", "Plan of positions"),
            1,
            1,
        ),
        lang,
        views,
        texts,
        tables: Vec::new(),
    })
}

/// The plan at the finest round μ_l (1–2–2.5–4–5 series) at which it fills its field, as a
/// student chooses it: first a guess from the crank length, then rescaled to the field.
fn fitted_plan(
    m: &Mechanism,
    req: &PlanRequest,
    region: Rect,
    opts: &RenderOptions,
) -> Result<(Scale, PositionPlan), BuildError> {
    let room = DVec2::new(
        region.width(),
        region.height() - crate::plate::CAPTION_BAND_MM,
    );
    let mut scale = crank_scale(m)?;
    let mut plan = plan_positions(m, req, scale, opts.drafting)?;
    for _ in 0..6 {
        let size = plan.figure.bounds().map_or(DVec2::ONE, |(lo, hi)| hi - lo);
        let need = (size.x / room.x).max(size.y / room.y);
        let next = Scale::round_for(scale.value() * need, FILL, Quantity::Length)
            .ok_or_else(|| bad_scale(scale.value()))?;
        if next == scale {
            break;
        }
        scale = next;
        plan = plan_positions(m, req, scale, opts.drafting)?;
    }
    Ok((scale, plan))
}

/// The structural scheme at the finest round scale whose drawing fits its field.
fn scheme_view(
    plan: &PositionPlan,
    st: &Structure,
    plan_scale: Scale,
    extent: f64,
    lang: Lang,
) -> Result<View, BuildError> {
    let tol = Tolerances::for_model_size(SCHEME_MM)
        .map_err(|e| crate::linkage::LinkageError::Model(e.to_string()))?;
    let mut s_scale =
        Scale::round_for(extent, SCHEME_MM, Quantity::Length).ok_or_else(|| bad_scale(extent))?;
    let mut tries = 0;
    loop {
        let scheme = structure_figure(
            &plan.program,
            st,
            &plan.positions[0].built,
            plan_scale.value(),
            s_scale,
            tol,
        );
        let caption = format!(
            "{}, {}",
            lang.pick("Структурная схема", "Структурна схема", "Structural scheme"),
            s_scale.caption(lang)
        );
        match View::centred(scheme, rect(SCHEME_REGION), Some(caption)) {
            Ok(v) => return Ok(v),
            Err(e) if tries >= 6 => return Err(e.into()),
            Err(_) => {
                tries += 1;
                s_scale = Scale::round_for(s_scale.value() * 1.001, 1.0, Quantity::Length)
                    .ok_or_else(|| bad_scale(extent))?;
            }
        }
    }
}

/// μ_l chosen from the crank the textbook way (the crank drawn about 50 mm).
pub(super) fn crank_scale(m: &Mechanism) -> Result<Scale, BuildError> {
    Scale::round_for(m.crank.length, CRANK_MM, Quantity::Length)
        .ok_or_else(|| bad_scale(m.crank.length))
}

fn bad_scale(v: f64) -> BuildError {
    BuildError::Linkage(crate::linkage::LinkageError::Model(format!(
        "no drawing scale can be chosen for the size {v} m"
    )))
}

fn kind_name(k: DyadKind, lang: Lang) -> String {
    match lang {
        Lang::En => format!("kind {} ({})", k.number(), k.letters()),
        _ => format!(
            "{} {} ({})",
            lang.pick("вида", "виду", ""),
            k.number(),
            k.letters_ru()
        ),
    }
}

/// The structural analysis as text lines (label markup).
fn structure_lines(st: &Structure, m: &crate::linkage::Mechanism, lang: Lang) -> Vec<String> {
    let mut v = vec![lang
        .pick(
            "Структурный анализ",
            "Структурний аналіз",
            "Structural analysis",
        )
        .to_string()];
    v.push(format!("n = {}, p_5 = {}, p_4 = {}", st.n, st.p5, st.p4));
    v.push(format!(
        "W = 3n − 2p_5 − p_4 = 3·{} − 2·{} − {} = {}",
        st.n,
        st.p5,
        st.p4,
        minus(st.w)
    ));
    for r in &m.redundant {
        v.push(format!(
            "{} {}: p_5 = {}, W = 3·{} − 2·{} − {} = {}",
            lang.pick("С парой", "З парою", "With pair"),
            r.name,
            st.p5_all,
            st.n,
            st.p5_all,
            st.p4,
            minus(st.w_all)
        ));
        v.push(format!(
            "{} — {}: {}",
            r.name,
            lang.pick("избыточная пара", "надлишкова пара", "redundant pair"),
            r.reason
        ));
    }
    v.push(format!(
        "{}: {}",
        lang.pick("Формула строения", "Формула будови", "Structure formula"),
        st.formula()
    ));
    for g in &st.groups {
        let text = match lang {
            Lang::En => format!(
                "II({},{}): Assur group of class 2, order 2, {}",
                g.links[0],
                g.links[1],
                kind_name(g.kind, lang)
            ),
            Lang::Ru => format!(
                "II({},{}): группа Ассура 2 класса 2 порядка {}",
                g.links[0],
                g.links[1],
                kind_name(g.kind, lang)
            ),
            Lang::Uk => format!(
                "II({},{}): група Ассура 2 класу 2 порядку {}",
                g.links[0],
                g.links[1],
                kind_name(g.kind, lang)
            ),
        };
        v.push(text);
    }
    v.push(match lang {
        Lang::En => format!("The mechanism is of class {}", st.class),
        Lang::Ru => format!("Механизм {} класса", st.class),
        Lang::Uk => format!("Механізм {} класу", st.class),
    });
    v
}

fn minus(w: i32) -> String {
    if w < 0 {
        format!("−{}", -w)
    } else {
        w.to_string()
    }
}

/// Extreme positions, θ, ψ, H, K as text lines.
fn extreme_lines(plan: &PositionPlan, lang: Lang) -> Vec<String> {
    let Some(ex) = &plan.extremes else {
        return Vec::new();
    };
    let label = |phi: f64| {
        plan.positions
            .iter()
            .find(|p| (p.phi - phi).abs() < 1e-9)
            .map_or_else(String::new, |p| p.label.clone())
    };
    let deg = |a: f64| format_fixed(a.to_degrees().rem_euclid(360.0), 2, lang);
    let mut v = vec![format!(
        "{}: {} (φ_1 = {}°), {} (φ_1 = {}°)",
        lang.pick("Крайние положения", "Крайні положення", "Extreme positions"),
        label(ex.phi_start),
        deg(ex.phi_start),
        label(ex.phi_other),
        deg(ex.phi_other)
    )];
    v.push(format!(
        "{} {}°, {} {}°",
        lang.pick(
            "Рабочий ход: поворот кривошипа на",
            "Робочий хід: поворот кривошипа на",
            "Working stroke: crank turns"
        ),
        format_fixed(ex.work_travel.to_degrees(), 2, lang),
        lang.pick("холостой —", "холостий —", "return —"),
        format_fixed(360.0 - ex.work_travel.to_degrees(), 2, lang)
    ));
    for r in &ex.ranges {
        match r.coord {
            OutputCoord::Rocker(l) => v.push(format!(
                "{} {l}: {} = {}°",
                lang.pick("Угол размаха звена", "Кут розмаху ланки", "Swing of link"),
                if ((r.max - r.min).abs() - ex.theta.abs()).abs() < 1e-9 {
                    "θ"
                } else {
                    "ψ"
                },
                format_fixed((r.max - r.min).to_degrees(), 4, lang)
            )),
            OutputCoord::Slider(i, _) => v.push(format!(
                "{} {}: H = {} {}",
                lang.pick("Ход точки", "Хід точки", "Stroke of point"),
                plan.program.names[i],
                format_sig(r.max - r.min, 5, lang),
                lang.pick("м", "м", "m")
            )),
        }
    }
    v.push(format!(
        "θ = {}°, K = (180° + θ)/(180° − θ) = {}",
        format_fixed(ex.theta.to_degrees(), 4, lang),
        format_fixed(ex.k, 4, lang)
    ));
    v
}
