//! Plate "Трение" (friction): every `[[friction.case]]` of the scene — its scheme (the body,
//! the plane, groove, thread, journal or rollers, the loads, the normal, the friction cone or
//! circle and the reaction) and its force triangle at μ_F — with the closed forms and the
//! table graphical | analytic | error. On one sheet: A2 landscape, A1 when the cases need more
//! room; further sheets only when an A1 cannot hold them.

use super::digits::{degrees as deg, mm, value as num};
use super::layout::{lay_out_smallest, Block, ScaleKey};
use super::BuildError;
use crate::check::Row;
use crate::friction::{
    guide_twin, incline_twin, journal_twin, pivot_twin, rolling_twin, screw_twin, slider_twin,
    wedge_twin, CaseKind, Drawing, DrawingKind, Motion, Rolling, Slider, SliderState, Solved,
};
use crate::plate::{Plate, SheetSize, TableBlock};
use crate::scale::{format_number, format_sig, Key, Lang, Quantity};
use crate::study::Session;
use crate::words::{unit_in, FrictionText, Text};

/// Text height of the sheet's lines and table, mm.
const TEXT_MM: f64 = 3.5;
/// Text height of the table, mm.
const TABLE_MM: f64 = 2.5;
/// The formats tried, smallest first: the cases, their closed forms and the table on one
/// sheet (on A2 the last drawing and the table spilled onto a second, nearly empty one).
const SIZES: [SheetSize; 2] = [SheetSize::A2, SheetSize::A1];

/// What a drawing shows, as its caption says: the case's kind (and the sense of its motion),
/// or the construction drawn.
fn what(kind: &CaseKind, d: DrawingKind, lang: Lang) -> String {
    let sense = |m: Motion| match m {
        Motion::Up => FrictionText::Up,
        Motion::Down => FrictionText::Down,
    };
    let (word, motion) = match (d, kind) {
        (DrawingKind::Scheme, CaseKind::Incline(c)) => (FrictionText::Incline, Some(c.motion)),
        (DrawingKind::Scheme, CaseKind::Wedge(_)) => (FrictionText::Wedge, None),
        (DrawingKind::Scheme, CaseKind::Screw(c)) => (FrictionText::Screw, Some(c.motion)),
        (DrawingKind::Scheme, CaseKind::Journal(_)) => (FrictionText::Journal, None),
        (DrawingKind::Scheme, CaseKind::Rolling(_)) => (FrictionText::Rolling, None),
        (DrawingKind::Scheme, CaseKind::Slider(_)) => (FrictionText::Slider, None),
        (DrawingKind::Scheme, CaseKind::Guide(_)) => (FrictionText::Guide, None),
        (DrawingKind::Scheme, CaseKind::Pivot(_)) => (FrictionText::Pivot, None),
        (DrawingKind::Polygon | DrawingKind::Frictionless, _) => (FrictionText::Triangle, None),
        (DrawingKind::Flanks, _) => (FrictionText::Flanks, None),
        (DrawingKind::Balance, _) => (FrictionText::Balance, None),
        (DrawingKind::Sliding, _) => (FrictionText::Sliding, None),
    };
    match motion {
        Some(m) => format!("{}, {}", word.get(lang), sense(m).get(lang)),
        None => word.get(lang).to_string(),
    }
}

/// A case in words, as its scheme's caption names it (`наклонная плоскость, подъём`).
pub(crate) fn case_name(kind: &CaseKind, lang: Lang) -> String {
    what(kind, DrawingKind::Scheme, lang)
}

/// `μ_{x} = v unit` for a named μ.
fn mu(name: &str, value: f64, q: Quantity, lang: Lang) -> String {
    format!(
        "μ_{{{name}}} = {} {}",
        format_number(value, lang),
        q.unit(lang)
    )
}

/// The caption of a drawing of the case number `n`: the case, what it shows, its scales.
fn caption(n: usize, s: &Solved, d: &Drawing, lang: Lang) -> String {
    let head = format!(
        "{} {n}: {}",
        FrictionText::Case.get(lang),
        what(&s.case.kind, d.kind, lang)
    );
    let scales = match (d.kind, d.also.as_slice()) {
        // μ_k in millimetres of k per drawing millimetre: the arm is magnified (0,004 мм/мм,
        // not 0,000004 м/мм); the forces P₁, P₂ cut off at the drawing's own μ_P =
        // μ_F·μ_k/μ_d.
        (DrawingKind::Balance, [f, k, l]) => format!(
            "{}, μ_{{k}} = {} {}, μ_{{d}} = {} {}, {}",
            mu("F", f.value(), Quantity::Force, lang),
            format_sig(k.value() * 1e3, 3, lang),
            unit_in("mm/mm", lang),
            format_sig(l.value(), 3, lang),
            Quantity::Length.unit(lang),
            mu("P", d.figure.scale.value(), Quantity::Force, lang),
        ),
        _ if d.scaled => d.figure.scale.caption(lang),
        _ => return head,
    };
    format!("{head}, {scales}")
}

/// A case's line, followed by its condition of self-braking when it holds.
fn locking(first: String, condition: Option<String>, lang: Lang) -> Vec<String> {
    let braking = FrictionText::SelfBraking.get(lang);
    std::iter::once(first)
        .chain(condition.map(|c| format!("{c} — {braking}")))
        .collect()
}

/// The data of the case number `n` as the scene gives them (what its closed forms take), in
/// label markup: `1: Q = 1000 Н, f = 0,15, α = 20°, β′ = 10°`.
fn data_line(n: usize, kind: &CaseKind, lang: Lang) -> String {
    let newton = unit_in("N", lang);
    let q = |x: f64| format!("{} {newton}", num(x, lang));
    let a = |x: f64| given_deg(x, lang);
    let f = |x: f64| num(x, lang);
    let given: Vec<(&str, String)> = match kind {
        CaseKind::Incline(c) => vec![
            ("Q", q(c.load)),
            ("f", f(c.f)),
            ("α", a(c.alpha)),
            ("β′", a(c.beta)),
        ],
        CaseKind::Wedge(c) => vec![("Q", q(c.load)), ("f", f(c.f)), ("β", a(c.groove))],
        CaseKind::Screw(c) => vec![
            ("Q", q(c.load)),
            ("f", f(c.f)),
            ("λ", a(c.lead)),
            ("δ", a(c.profile)),
            ("r_{1}", mm(c.radius, lang)),
        ],
        CaseKind::Journal(c) => vec![("Q", q(c.load)), ("f", f(c.f)), ("r", mm(c.radius, lang))],
        CaseKind::Rolling(c) => vec![
            ("Q", q(c.load)),
            ("G", q(c.roller_weight)),
            ("d", mm(c.diameter, lang)),
            ("k_{1}", mm(c.k1, lang)),
            ("k_{2}", mm(c.k2, lang)),
            ("f_{1}", f(c.f1)),
            ("f_{2}", f(c.f2)),
        ],
        CaseKind::Slider(c) => vec![
            ("P", q(c.load)),
            ("f", f(c.f)),
            ("f_{0}", f(c.f0)),
            ("α", a(c.alpha)),
        ],
        CaseKind::Guide(c) => vec![
            ("Q", q(c.load)),
            ("λ", a(c.angle)),
            ("b", mm(c.guide.length, lang)),
            ("l", mm(c.guide.overhang, lang)),
            ("f", f(c.guide.f)),
        ],
        CaseKind::Pivot(c) => vec![
            (
                "M_{с}",
                format!("{} {}", num(c.moment, lang), unit_in("N*m", lang)),
            ),
            ("λ", a(c.angle)),
            ("L", mm(c.pivot.arm, lang)),
            ("d", mm(c.pivot.diameter, lang)),
            ("f", f(c.pivot.f)),
        ],
    };
    let list: Vec<String> = given.iter().map(|(k, v)| format!("{k} = {v}")).collect();
    format!("{n}: {}", list.join(", "))
}

/// A given angle as the data give it (`α = 15°`; a computed one: [`deg`], `26,57°`).
fn given_deg(radians: f64, lang: Lang) -> String {
    format!("{}°", num(radians.to_degrees(), lang))
}

/// The closed forms of the case number `n` with their values, in label markup.
fn lines(n: usize, s: &Solved, lang: Lang) -> Vec<String> {
    let newton = unit_in("N", lang);
    let nm = unit_in("N*m", lang);
    let sign = |m: Motion| if m == Motion::Up { "+" } else { "−" };
    match &s.case.kind {
        CaseKind::Incline(c) => {
            let t = incline_twin(c);
            let first = format!(
                "{n}: φ = arc{tg} f = {}; P = Q·sin(α {s} φ)/cos(α {s} φ − β′) = {} {newton}; η = {}",
                deg(t.phi, lang),
                num(t.p, lang),
                num(t.eta, lang),
                s = sign(c.motion),
                tg = tangent(lang),
            );
            locking(first, t.self_braking.then_some(format!("{n}: α ≤ φ")), lang)
        }
        CaseKind::Slider(c) => slider_lines(n, c, lang),
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
                "{n}: f′ = f/cos(δ/2) = {}, φ′ = {}; M = Q·r_{{1}}·{tg}(λ {s} φ′) = {} {nm}; η = {}",
                num(t.f_reduced, lang),
                deg(t.phi_reduced, lang),
                num(t.moment, lang),
                num(t.eta, lang),
                s = sign(c.motion),
                tg = tangent(lang),
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
                "{n}: ρ = r·sin φ = {} (ρ ≈ f·r = {}); M_{{тр}} = Q·ρ = {} {nm} (f·Q·r = {} {nm})",
                mm(t.rho, lang),
                mm(t.rho_textbook, lang),
                num(t.moment, lang),
                num(t.moment_textbook, lang)
            )]
        }
        CaseKind::Guide(c) => guide_lines(n, c, lang),
        CaseKind::Pivot(c) => pivot_lines(n, c, lang),
        CaseKind::Rolling(c) => rolling_lines(n, c, lang),
    }
}

/// The closed forms of a slider on an incline (case `n`): the forces along and across it,
/// rest, uniform motion or acceleration against the cone of friction.
fn slider_lines(n: usize, c: &Slider, lang: Lang) -> Vec<String> {
    let newton = unit_in("N", lang);
    let t = slider_twin(c);
    let (cmp, state) = match t.state {
        SliderState::Rest => ("<", FrictionText::AtRest),
        SliderState::Uniform => ("=", FrictionText::Uniform),
        SliderState::Accelerating => (">", FrictionText::Accelerating),
    };
    // At rest the static cone, the static friction's reserve and the reaction that
    // acts (−P) below the cone's limit; sliding, the reaction on the generator.
    let (phi, f, r) = if t.state == SliderState::Rest {
        (
            format!("φ_{{0}} = {}", deg(t.phi0, lang)),
            "f_{0}",
            format!(
                "R = P = {} {newton} < R_{{0}} = N/cos φ_{{0}} = {} {newton}",
                num(t.r, lang),
                num(t.r_limit, lang)
            ),
        )
    } else {
        (
            format!("φ = {}", deg(t.phi, lang)),
            "f",
            format!("R = N/cos φ = {} {newton}", num(t.r, lang)),
        )
    };
    vec![
        format!(
            "{n}: N = P·cos α = {} {newton}, P_{{1}} = P·sin α = {} {newton}; ΔP = P_{{1}} − {f}·N = {} {newton}",
            num(t.n, lang),
            num(t.p1, lang),
            num(t.net, lang),
        ),
        format!(
            "{n}: α = {} {cmp} {phi} — {}; {r}",
            given_deg(c.alpha, lang),
            state.get(lang)
        ),
    ]
}

/// The closed forms of rollers between a load and a plane (case `n`): pure rolling or
/// sliding, and the force that moves the load.
fn rolling_lines(n: usize, c: &Rolling, lang: Lang) -> Vec<String> {
    let newton = unit_in("N", lang);
    let t = rolling_twin(c);
    let lt = |ok: bool| if ok { "<" } else { "≥" };
    vec![
        format!(
            "{n}: k_{{1}}/d = {} {} f_{{1}} = {}; k_{{2}}/d = {} {} f_{{2}} = {} — {}",
            num(t.ratio1, lang),
            lt(t.ratio1 < c.f1),
            num(c.f1, lang),
            num(t.ratio2, lang),
            lt(t.ratio2 < c.f2),
            num(c.f2, lang),
            if t.pure {
                FrictionText::PureRolling
            } else {
                FrictionText::RollersSlide
            }
            .get(lang)
        ),
        format!(
            "{n}: R_{{n1}} = Q, R_{{n2}} = Q + 2G; P = {} = {} {newton}; {}: P_{{ск}} = Q·f_{{2}} = {} {newton}",
            match t.slide {
                None => "(Q·k_{1} + (Q + 2G)·k_{2})/d",
                Some(crate::friction::Slide::OnRollers) => "Q·f_{1}",
                Some(crate::friction::Slide::OnPlane) => "(Q + 2G)·f_{2}",
            },
            num(t.p, lang),
            FrictionText::Sliding.get(lang),
            num(t.p_sliding, lang)
        ),
    ]
}

/// The closed forms of a cam's follower in its guide (case `n`): P and the bearings'
/// reactions, the jamming angle against λ.
fn guide_lines(n: usize, c: &crate::friction::FollowerGuide, lang: Lang) -> Vec<String> {
    let newton = unit_in("N", lang);
    let Some(t) = guide_twin(c) else {
        return Vec::new();
    };
    vec![
        format!(
            "{n}: P = Q/(cos λ − f·sin λ·(2l + b)/b) = {} {newton}; N_{{1}} = P·sin λ·(l + b)/b = {} {newton}, N_{{2}} = P·sin λ·l/b = {} {newton}; R = N·√(1 + f^2)",
            num(t.p, lang),
            num(t.n[0], lang),
            num(t.n[1], lang)
        ),
        format!(
            "{n}: {tg} λ_{{кр}} = b/(f·(2l + b)): λ_{{кр}} = {} > λ = {} — {}",
            deg(t.lock, lang),
            given_deg(c.angle, lang),
            FrictionText::Moves.get(lang),
            tg = tangent(lang),
        ),
    ]
}

/// The closed forms of a cam's rocker in its pivot (case `n`): the friction circle, the
/// couple's arm, P and the jamming angle against λ.
fn pivot_lines(n: usize, c: &crate::friction::RockerPivot, lang: Lang) -> Vec<String> {
    let newton = unit_in("N", lang);
    let Some(t) = pivot_twin(c) else {
        return Vec::new();
    };
    vec![
        format!(
            "{n}: ρ = (d/2)·sin φ = {}; h = L·cos λ − ρ = {}; P = M_{{с}}/h = {} {newton}",
            mm(t.rho, lang),
            mm(t.h, lang),
            num(t.p, lang)
        ),
        format!(
            "{n}: cos λ_{{кр}} = ρ/L: λ_{{кр}} = {} > λ = {} — {} ({} {tg} λ_{{кр}} = 2L/(f·d): {})",
            deg(t.lock, lang),
            given_deg(c.angle, lang),
            FrictionText::Moves.get(lang),
            FrictionText::Approximately.get(lang),
            deg(t.lock_lecture, lang),
            tg = tangent(lang),
        ),
    ]
}

/// The tangent's name in `lang`: tg in the Russian and Ukrainian courses, tan in English.
fn tangent(lang: Lang) -> &'static str {
    lang.pick("tg", "tg", "tan")
}

/// A unit of the table in `lang`.
fn unit(r: &Row, lang: Lang) -> String {
    match r.unit() {
        "1" => String::new(),
        "rad" => "°".into(),
        // Lengths in millimetres, as the drawings are read (no 0,007184 м).
        "m" => unit_in("mm", lang),
        u => unit_in(u, lang),
    }
}

/// The table: case, quantity, graphical, analytic, error (angles in degrees).
fn table(solved: &[Solved], lang: Lang) -> TableBlock {
    let mut rows = Vec::new();
    for (n, s) in solved.iter().enumerate() {
        for r in &s.readings {
            let row = &r.row;
            let shown = |x: f64| match row.unit() {
                "rad" => num(x.to_degrees(), lang),
                "m" => num(x * 1e3, lang),
                _ => num(x, lang),
            };
            let unit = unit(row, lang);
            let symbol = if unit.is_empty() {
                r.symbol.to_string()
            } else {
                format!("{}, {unit}", r.symbol)
            };
            let (graphical, analytic) = (shown(row.graphical), shown(row.analytic));
            let error =
                super::digits::printed_error(&graphical, &analytic, row.rel_error(row.scale), lang)
                    .map_or(super::digits::NO_VALUE.to_string(), |e| {
                        super::digits::error_pct(e, lang)
                    });
            rows.push(vec![
                (n + 1).to_string(),
                symbol,
                graphical,
                analytic,
                error,
            ]);
        }
    }
    super::layout::table(
        Text::GraphicalAndAnalytic,
        &[
            (Text::Case, 18.0),
            (Text::Quantity, 18.0),
            (Text::Graphical, 22.0),
            (Text::Analytic, 22.0),
            (Text::RelativeError, 16.0),
        ],
        rows,
        TABLE_MM,
        lang,
    )
}

/// Build the sheets.
pub fn build(session: &Session<'_>, lang: Lang) -> Result<Vec<Plate>, BuildError> {
    let scene = session.scene();
    let solved = session.friction()?;
    let mut blocks = Vec::new();
    // The data each case is given, then how lengths were read, then the closed forms.
    let mut text = vec![Text::Data.get(lang).to_string()];
    text.extend(
        solved
            .iter()
            .enumerate()
            .map(|(n, s)| data_line(n + 1, &s.case.kind, lang)),
    );
    text.push(String::new());
    text.push(super::drafting_line(
        session.drafting(),
        super::Errs::Plans,
        lang,
    ));
    for (n, s) in solved.iter().enumerate() {
        for d in &s.drawings {
            let key = d.scaled.then_some(ScaleKey {
                key: Key::FrictionCaseScaleF,
                scale: d.figure.scale,
            });
            blocks.push(Block::view(
                d.figure.clone(),
                caption(n + 1, s, d, lang),
                key,
            ));
        }
        text.extend(lines(n + 1, s, lang));
    }
    // The drawings fill the first sheet; the closed forms and the table follow them.
    blocks.push(Block::Text {
        lines: text,
        size_mm: TEXT_MM,
    });
    blocks.push(Block::Table(table(&solved, lang)));
    let sheet_title = FrictionText::Title.get(lang);
    // The drawings have a scale each (their captions); the sheet has the one its length
    // drawings share, none where they differ.
    let mut lengths = (solved.iter().flat_map(|s| &s.drawings))
        .filter(|d| d.scaled && d.figure.scale.quantity == Quantity::Length)
        .map(|d| d.figure.scale);
    let first = lengths.next();
    let shared = first.filter(|f| lengths.all(|l| l.value() == f.value()));
    let title = super::title_block(scene, sheet_title, shared, lang);
    lay_out_smallest(&SIZES, blocks, "friction", &title, lang)
}
