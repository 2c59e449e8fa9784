//! Plate "Трение" (friction): every `[[friction.case]]` of the scene — its scheme (the body,
//! the plane, groove, thread, journal or rollers, the loads, the normal, the friction cone or
//! circle and the reaction) and its force triangle at μ_F — with the closed forms and the
//! table graphical | analytic | error. A2 landscape; further sheets when the cases need them.

use super::layout::{lay_out, Block, ScaleKey};
use super::BuildError;
use crate::check::Row;
use crate::forces::friction::{
    incline_twin, journal_twin, rolling_twin, screw_twin, wedge_twin, CaseKind, Drawing,
    DrawingKind, Motion, Solved,
};
use crate::geom::DVec2;
use crate::plate::{Plate, Sheet, SheetSize, TableBlock};
use crate::scale::{format_fixed, format_number, format_sig, Lang, Quantity};
use crate::study::Session;

/// Text height of the sheet's lines and table, mm.
const TEXT_MM: f64 = 3.5;
/// Text height of the table, mm.
const TABLE_MM: f64 = 2.5;

/// A word of the sheet in `lang`.
fn word(lang: Lang, ru: &'static str, uk: &'static str, en: &'static str) -> &'static str {
    lang.pick(ru, uk, en)
}

/// What a drawing shows, as its caption says.
fn what(kind: &CaseKind, d: DrawingKind, lang: Lang) -> &'static str {
    match (d, kind) {
        (DrawingKind::Scheme, CaseKind::Incline(_)) => word(
            lang,
            "наклонная плоскость",
            "похила площина",
            "inclined plane",
        ),
        (DrawingKind::Scheme, CaseKind::Wedge(_)) => word(
            lang,
            "клинчатый ползун, сечение",
            "клинчастий повзун, переріз",
            "V-groove slider, section",
        ),
        (DrawingKind::Scheme, CaseKind::Screw(_)) => word(
            lang,
            "развёртка резьбы",
            "розгортка різьби",
            "unrolled thread",
        ),
        (DrawingKind::Scheme, CaseKind::Journal(_)) => word(
            lang,
            "цапфа, круг трения",
            "цапфа, коло тертя",
            "journal, friction circle",
        ),
        (DrawingKind::Scheme, CaseKind::Rolling(_)) => word(
            lang,
            "груз на катках",
            "вантаж на котках",
            "load on rollers",
        ),
        (DrawingKind::Polygon | DrawingKind::Frictionless, _) => {
            word(lang, "план сил", "план сил", "force triangle")
        }
        (DrawingKind::Flanks, _) => word(
            lang,
            "план сил: N₁, N₂; вид сбоку",
            "план сил: N₁, N₂; вид збоку",
            "forces: N₁, N₂; side view",
        ),
        (DrawingKind::Balance, _) => word(
            lang,
            "равновесие моментов",
            "рівновага моментів",
            "moment balance",
        ),
        (DrawingKind::Sliding, _) => word(lang, "без катков", "без котків", "without rollers"),
    }
}

/// `μ_{x} = v unit` for a named μ.
fn mu(name: &str, value: f64, q: Quantity, lang: Lang) -> String {
    format!(
        "μ_{{{name}}} = {} {}",
        format_number(value, lang),
        q.unit(lang)
    )
}

/// The caption of a drawing: the case, what it shows, its scales.
fn caption(s: &Solved, d: &Drawing, lang: Lang) -> String {
    let head = format!("{}: {}", s.case.name, what(&s.case.kind, d.kind, lang));
    let scales = match (d.kind, d.also.as_slice()) {
        (DrawingKind::Balance, [f, k, l]) => format!(
            "{}, μ_{{k}} = {}, μ_{{d}} = {} {}",
            mu("F", f.value(), Quantity::Force, lang),
            format_sig(k.value(), 3, lang),
            format_sig(l.value(), 3, lang),
            Quantity::Length.unit(lang)
        ),
        _ if d.scaled => d.figure.scale.caption(lang),
        _ => return head,
    };
    format!("{head}, {scales}")
}

/// A number with 4 significant digits.
fn num(x: f64, lang: Lang) -> String {
    format_sig(x, 4, lang)
}

/// Degrees with two decimals.
fn deg(x: f64, lang: Lang) -> String {
    format!("{}°", format_fixed(x.to_degrees(), 2, lang))
}

/// A case's line, followed by its condition of self-braking when it holds.
fn locking(first: String, condition: Option<String>, lang: Lang) -> Vec<String> {
    let braking = word(lang, "самоторможение", "самогальмування", "self-braking");
    std::iter::once(first)
        .chain(condition.map(|c| format!("{c} — {braking}")))
        .collect()
}

/// The closed forms of a case with their values, in label markup.
fn lines(s: &Solved, lang: Lang) -> Vec<String> {
    let n = &s.case.name;
    let newton = word(lang, "Н", "Н", "N");
    let nm = word(lang, "Н·м", "Н·м", "N·m");
    let metre = word(lang, "м", "м", "m");
    let sign = |m: Motion| if m == Motion::Up { "+" } else { "−" };
    match &s.case.kind {
        CaseKind::Incline(c) => {
            let t = incline_twin(c);
            let first = format!(
                "{n}: φ = arctg f = {}; P = Q·sin(α {s} φ)/cos(α {s} φ − β′) = {} {newton}; η = {}",
                deg(t.phi, lang),
                num(t.p, lang),
                num(t.eta, lang),
                s = sign(c.motion)
            );
            locking(first, t.self_braking.then_some(format!("{n}: α ≤ φ")), lang)
        }
        CaseKind::Wedge(c) => {
            let t = wedge_twin(c);
            vec![format!(
                "{n}: N = Q/(2·sin(β/2)) = {} {newton}; f′ = f/sin(β/2) = {}; P = f·Q/sin(β/2) = {} {newton}",
                num(t.n, lang),
                num(t.f_reduced, lang),
                num(t.p, lang)
            )]
        }
        CaseKind::Screw(c) => {
            let t = screw_twin(c);
            let first = format!(
                "{n}: f′ = f/cos(δ/2) = {}, φ′ = {}; M = Q·r_{{1}}·tg(λ {s} φ′) = {} {nm}; η = {}",
                num(t.f_reduced, lang),
                deg(t.phi_reduced, lang),
                num(t.moment, lang),
                num(t.eta, lang),
                s = sign(c.motion)
            );
            locking(
                first,
                t.self_locking.then_some(format!("{n}: λ ≤ φ′")),
                lang,
            )
        }
        CaseKind::Journal(c) => {
            let t = journal_twin(c);
            vec![format!(
                "{n}: ρ = r·sin φ = {} {metre} (ρ ≈ f·r = {} {metre}); M_{{f}} = Q·ρ = {} {nm} (f·Q·r = {} {nm})",
                num(t.rho, lang),
                num(t.rho_textbook, lang),
                num(t.moment, lang),
                num(t.moment_textbook, lang)
            )]
        }
        CaseKind::Rolling(c) => {
            let t = rolling_twin(c);
            let lt = |ok: bool| if ok { "<" } else { "≥" };
            vec![
                format!(
                    "{n}: k_{{1}}/h = {} {} f_{{1}} = {}; k_{{2}}/h = {} {} f_{{2}} = {} — {}",
                    num(t.ratio1, lang),
                    lt(t.ratio1 < c.f1),
                    num(c.f1, lang),
                    num(t.ratio2, lang),
                    lt(t.ratio2 < c.f2),
                    num(c.f2, lang),
                    if t.pure {
                        word(lang, "чистое качение", "чисте кочення", "pure rolling")
                    } else {
                        word(lang, "катки скользят", "котки ковзають", "the rollers slide")
                    }
                ),
                format!(
                    "{n}: R_{{n1}} = Q, R_{{n2}} = Q + 2G; P = {} = {} {newton}; {}: P = Q·f_{{2}} = {} {newton}",
                    match t.slide {
                        None => "(Q·k_{1} + (Q + 2G)·k_{2})/d",
                        Some(crate::forces::friction::Slide::OnRollers) => "Q·f_{1}",
                        Some(crate::forces::friction::Slide::OnPlane) => "(Q + 2G)·f_{2}",
                    },
                    num(t.p, lang),
                    word(lang, "без катков", "без котків", "without rollers"),
                    num(t.p_sliding, lang)
                ),
            ]
        }
    }
}

/// A unit of the table in `lang`.
fn unit(r: &Row, lang: Lang) -> String {
    let u = r.unit();
    match (lang, u) {
        (_, "1") => String::new(),
        (_, "rad") => "°".into(),
        (Lang::En, _) => u.replace('*', "·"),
        (_, "N") => "Н".into(),
        (_, "N*m") => "Н·м".into(),
        (_, "m") => "м".into(),
        _ => u.into(),
    }
}

/// The table: case, quantity, graphical, analytic, error (angles in degrees).
fn table(solved: &[Solved], lang: Lang) -> TableBlock {
    let mut rows = Vec::new();
    for s in solved {
        for r in &s.readings {
            let row = &r.row;
            let shown = |x: f64| {
                if row.key.symbol == crate::check::Symbol::Angle {
                    num(x.to_degrees(), lang)
                } else {
                    num(x, lang)
                }
            };
            let unit = unit(row, lang);
            let symbol = if unit.is_empty() {
                r.symbol.to_string()
            } else {
                format!("{}, {unit}", r.symbol)
            };
            let error = row
                .rel_error(row.scale)
                .map_or("—".to_string(), |e| format_fixed(e * 100.0, 3, lang));
            rows.push(vec![
                s.case.name.clone(),
                symbol,
                shown(row.graphical),
                shown(row.analytic),
                error,
            ]);
        }
    }
    TableBlock {
        at: DVec2::ZERO,
        title: word(
            lang,
            "Графически и аналитически",
            "Графічно й аналітично",
            "Graphical against analytic",
        )
        .into(),
        columns: vec![
            (word(lang, "случай", "випадок", "case").into(), 18.0),
            (word(lang, "величина", "величина", "quantity").into(), 18.0),
            (
                word(lang, "графически", "графічно", "graphical").into(),
                22.0,
            ),
            (
                word(lang, "аналитически", "аналітично", "analytic").into(),
                22.0,
            ),
            ("δ, %".into(), 16.0),
        ],
        rows,
        size_mm: TABLE_MM,
    }
}

/// Build the sheets.
pub fn build(session: &Session<'_>, lang: Lang) -> Result<Vec<Plate>, BuildError> {
    let scene = session.scene();
    let solved = session.friction()?;
    let mut blocks = Vec::new();
    let mut text = vec![super::drafting_line(session.drafting(), lang)];
    for s in solved.iter() {
        for d in &s.drawings {
            let key = d.scaled.then_some(ScaleKey {
                key: "friction.case.scale_f",
                scale: d.figure.scale,
            });
            blocks.push(Block::view(d.figure.clone(), caption(s, d, lang), key));
        }
        text.extend(lines(s, lang));
    }
    // The drawings fill the first sheet; the closed forms and the table follow them.
    blocks.push(Block::Text {
        lines: text,
        size_mm: TEXT_MM,
    });
    blocks.push(Block::Table(table(&solved, lang)));
    let sheet = Sheet {
        size: SheetSize::A2,
        landscape: true,
    };
    let sheet_title = word(lang, "Трение", "Тертя", "Friction");
    // The drawings have a scale each (their captions): the sheet has none.
    let none = crate::scale::Scale::new(1e-3, Quantity::Length).ok_or(BuildError::NoScale(1e-3))?;
    let mut title = super::title_block(scene, sheet_title, none, lang);
    title.scale = String::new();
    lay_out(sheet, blocks, "friction", &title, lang)
}
