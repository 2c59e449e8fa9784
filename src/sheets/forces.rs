//! Plate "Силовой анализ" (the textbook's sheet 2): one A1 sheet for every position the
//! scene's `[forces]` analyses. On it: every Assur group drawn apart at the force sheets' μ_l
//! ([`Session::force_scale_l`]: as large as the sheet holds it) with its loads,
//! reactions and measured arms, next to its force polygon at μ_F; the driving link with its
//! gear and its force triangle; Zhukovsky's lever on the turned velocity plan at μ_v; the
//! table of inertia loads and reactions (graphical | analytic | error) and the balancing
//! moment by the polygon against the lever.

use super::layout::{lay_out, results_table, sheet_name, Block, Column, Results, ScaleKey};
use super::BuildError;
use crate::check::{Method, Row, Symbol};
use crate::construct::Figure;
use crate::forces::{letter_at, letter_toward, ForceSpec, PolygonDetail, PositionForces};
use crate::forces::{Phase, Stroke};
use crate::linkage::Structure;
use crate::plate::{Plate, Sheet, TableBlock};
use crate::scale::{format_fixed, format_sig, Key, Lang, Scale};
use crate::study::Session;
use crate::words::{plain, symbols, unit_in, Text};

/// Height of the sheet's text and table, mm.
const TEXT_MM: f64 = 3.5;
/// Height of the table's text, mm.
const TABLE_MM: f64 = 3.0;

/// Build the sheets: one per analysed position, named `forces`, `forces-2`, … in the order
/// of `[forces] positions` (a position whose views need more room continues on the next
/// name).
pub fn build(
    session: &Session<'_>,
    lang: Lang,
    indicators: bool,
) -> Result<Vec<Plate>, BuildError> {
    let sc = session.kin_scales()?;
    let m = session.mechanism("the force analysis")?;
    let st = Structure::analyse(m);
    let plan = session.positions(sc.l)?;
    let mut plates = Vec::new();
    for (n, k) in session.force_positions()?.into_iter().enumerate() {
        let f = session.forces(&sc, k)?;
        let pos = &plan.positions[k];
        let phi = pos.phi.to_degrees().rem_euclid(360.0);
        plates.extend(position_sheet(
            session,
            &st,
            (&f, indicators && n == 0),
            (phi, &plan.program.names),
            lang,
        )?);
    }
    for (n, p) in plates.iter_mut().enumerate() {
        p.name = sheet_name("forces", n);
    }
    Ok(plates)
}

/// A view captioned "`what`, μ = …" at `scale`, set by the scene key `key`; the caption
/// under what the figure's symbols draw below its points (the ground of the crank's pivot).
fn view(figure: &Figure, what: String, (key, scale): (Key, Scale), lang: Lang) -> Block {
    let caption = format!("{what}, {}", scale.caption(lang));
    Block::view(figure.clone(), caption, Some(ScaleKey { key, scale })).with_label_room()
}

/// The letters of a sheet's detail views (ГОСТ 2.316: capitals, without Й, О, Х, Ъ, Ы, Ь),
/// in order, but any that reads as the initial of a name: of the mechanism's `points` (A, B,
/// C, S₃, drawn or not) or on the sheet's `figures` (the loads F, G, M): a detail «В» beside
/// the point «B» is read as that point. Never empty.
fn detail_letters<'a>(
    points: &[String],
    figures: impl IntoIterator<Item = &'a Figure>,
    lang: Lang,
) -> Vec<char> {
    // Each Cyrillic capital with the Latin one it looks like, if any.
    const CYRILLIC: [(char, Option<char>); 22] = [
        ('А', Some('A')),
        ('Б', None),
        ('В', Some('B')),
        ('Г', None),
        ('Д', None),
        ('Е', Some('E')),
        ('Ж', None),
        ('И', None),
        ('К', Some('K')),
        ('Л', None),
        ('М', Some('M')),
        ('Н', Some('H')),
        ('П', None),
        ('Р', Some('P')),
        ('С', Some('C')),
        ('Т', Some('T')),
        ('У', Some('Y')),
        ('Ф', None),
        ('Ш', None),
        ('Э', None),
        ('Ю', None),
        ('Я', None),
    ];
    let initials: Vec<char> = (figures.into_iter())
        .flat_map(|f| f.steps.iter().filter_map(|s| s.label.as_ref()))
        .map(|l| &l.text)
        .chain(points)
        .filter_map(|t| t.chars().next())
        .collect();
    let free = |c: char| !initials.contains(&c);
    let letters: Vec<char> = match lang {
        Lang::En => ('A'..='Z')
            .filter(|&c| !matches!(c, 'I' | 'O' | 'Q') && free(c))
            .collect(),
        Lang::Ru | Lang::Uk => (CYRILLIC.iter())
            .filter(|(_, latin)| latin.is_none_or(free))
            .map(|&(c, _)| c)
            .collect(),
    };
    // A scene whose names take every letter still letters its details.
    if letters.is_empty() {
        return ('A'..='Z').collect();
    }
    letters
}

/// A force polygon's view captioned `what` at its μ_F, and its details' views (each zone
/// circled on the polygon and lettered, each detail captioned by its letter and μ_F); the
/// letters run through the sheet's details in order (`lettered` counts them).
fn polygon_views(
    blocks: &mut Vec<Block>,
    (polygon, details): (&Figure, &[PolygonDetail]),
    what: String,
    (letters_of_sheet, lettered): (&[char], &mut usize),
    lang: Lang,
) {
    let corner = letter_toward();
    let mut marked = polygon.clone();
    let mut views = Vec::new();
    let mut letters: Vec<String> = Vec::new();
    for d in details {
        let letter = letters_of_sheet[*lettered % letters_of_sheet.len()].to_string();
        *lettered += 1;
        marked = marked.with_text(
            "the detail's letter",
            letter_at(&d.zone),
            letter.clone(),
            corner,
        );
        // A finer detail's zone circled on this one takes its letter here too.
        let mut figure = d.figure.clone();
        for (at, l) in (d.finer.iter()).filter_map(|&(i, at)| Some((at, letters.get(i)?))) {
            figure = figure.with_text("a finer detail's letter", at, l.clone(), corner);
        }
        letters.push(letter.clone());
        let scale = (Key::ForcesScaleF, d.figure.scale);
        views.push(view(&figure, letter, scale, lang));
    }
    blocks.push(view(
        &marked,
        what,
        (Key::ForcesScaleF, polygon.scale),
        lang,
    ));
    blocks.extend(views);
}

/// The sheet (or sheets) of one position at the crank angle `phi` of the mechanism whose
/// points are named `points`; the first carries an engine's indicator diagrams when `first`
/// (no dynamics sheet does).
fn position_sheet(
    session: &Session<'_>,
    st: &Structure,
    (f, first): (&PositionForces, bool),
    (phi, points): (f64, &[String]),
    lang: Lang,
) -> Result<Vec<Plate>, BuildError> {
    let scene = session.scene();
    let mut blocks = Vec::new();
    let mut lettered = 0;
    let drawn = &f.analysis.polygons;
    let schemes = (drawn.groups.iter().map(|g| &g.scheme)).chain([&drawn.driver.scheme]);
    let letters = detail_letters(points, schemes, lang);
    for g in &f.analysis.polygons.groups {
        let [i, j] = g.links;
        let kind = st
            .groups
            .get(g.group)
            .map(|x| x.kind.letters_in(lang))
            .unwrap_or_default();
        blocks.push(view(
            &g.scheme,
            format!("{} {i}–{j} ({kind})", Text::Group.get(lang)),
            (Key::MechanismScaleL, g.scheme.scale),
            lang,
        ));
        let what = format!("{} {i}–{j}", Text::ForcePolygonOfGroup.get(lang));
        polygon_views(
            &mut blocks,
            (&g.polygon, &g.details),
            what,
            (&letters, &mut lettered),
            lang,
        );
    }
    if first {
        blocks.extend(super::indicator::views(session, lang)?);
    }
    let d = &f.analysis.polygons.driver;
    let driving = format!("{} {}", Text::DrivingLink.get(lang), st.crank_link);
    blocks.push(view(
        &d.scheme,
        driving,
        (Key::MechanismScaleL, d.scheme.scale),
        lang,
    ));
    let triangle = Text::ForcePolygonOfDriver.get(lang).to_string();
    polygon_views(
        &mut blocks,
        (&d.polygon, &d.details),
        triangle,
        (&letters, &mut lettered),
        lang,
    );
    let lever = &f.analysis.lever.figure;
    let zhukovsky = Text::ZhukovskyLever.get(lang).to_string();
    blocks.push(view(
        lever,
        zhukovsky,
        (Key::KinematicsScaleV, lever.scale),
        lang,
    ));
    // The sheet's name names its position; the angle is the sheet's data, written in its
    // text block (the title block's name field holds the document's name, ГОСТ 2.104).
    let title = format!(
        "{}, {} {}",
        Text::ForceAnalysis.get(lang),
        Text::Position.get(lang),
        f.label
    );
    let mut lines = vec![
        format!(
            "{title}, φ_{{1}} = {}",
            super::digits::degrees(phi.to_radians(), lang)
        ),
        super::drafting_line(session.drafting(), super::Errs::Plans, lang),
    ];
    let spec = session.force_spec("the force sheets")?;
    lines.extend(balance_lines(&f.rows, spec.engine(), lang));
    lines.extend(resting_lines(spec, f.phase, lang));
    lines.extend(gas_lines(session, spec, f, phi, lang)?);
    blocks.push(Block::Text {
        lines,
        size_mm: TEXT_MM,
    });
    blocks.push(Block::Text {
        lines: data_lines(spec, lang),
        size_mm: TEXT_MM,
    });
    blocks.push(Block::Table(loads_table(&f.rows, lang)));
    let tb = super::title_block(scene, &title, Some(session.force_scale_l()?), lang);
    lay_out(Sheet::default(), blocks, "forces", &tb, lang)
}

/// The data the loads come from, under their heading: the links' masses and moments of
/// inertia, the working resistances, an engine's cylinders ([`super::data::force_units`]);
/// a link's or a cylinder's together, as many to a line as [`DATA_PER_LINE`] items allow.
fn data_lines(spec: &ForceSpec, lang: Lang) -> Vec<String> {
    let mut lines = vec![Text::Data.get(lang).to_string()];
    let mut line: Vec<String> = Vec::new();
    for unit in super::data::force_units(spec, lang) {
        if !line.is_empty() && line.len() + unit.len() > DATA_PER_LINE {
            lines.push(std::mem::take(&mut line).join(", "));
        }
        line.extend(unit.iter().map(|r| super::data::written(r, lang)));
    }
    if !line.is_empty() {
        lines.push(line.join(", "));
    }
    lines
}

/// A line for every resistance of the data that does not act at the position (a shaper's
/// cutting force on the return stroke): absent from the drawings, said to be nought.
fn resting_lines(spec: &ForceSpec, phase: Phase, lang: Lang) -> Vec<String> {
    (spec.resistances.iter())
        .filter(|r| !r.stroke.acts(phase))
        .filter_map(|r| {
            let text = match r.stroke {
                Stroke::Working => Text::ActsOnWorkingOnly,
                Stroke::Return => Text::ActsOnReturnOnly,
                Stroke::Always => return None,
            };
            Some(text.get(lang).replace("{f}", r.action.symbol()))
        })
        .collect()
}

/// The most data items on one line of a force sheet's data (a unit of more stands alone).
const DATA_PER_LINE: usize = 4;

/// A value: 4 significant digits, an undefined one a dash.
fn value(x: f64, lang: Lang) -> String {
    if x.is_finite() {
        format_sig(x, 4, lang)
    } else {
        super::digits::NO_VALUE.into()
    }
}

/// A table cell: a value, or 0 when it is zero to rounding against `scale`
/// ([`crate::check::is_zero`]).
fn cell(x: f64, scale: f64, lang: Lang) -> String {
    if x.is_finite() {
        super::digits::cell(x, scale, lang)
    } else {
        value(x, lang)
    }
}

/// The table of the inertia loads, reactions, their points and the balancing load:
/// quantity | method | graphical | analytic | error, %.
fn loads_table(rows: &[Row], lang: Lang) -> TableBlock {
    // The rows carry their zero references (the largest of their kind at the position).
    results_table(
        &Results {
            title: Text::LoadsAndReactions.get(lang).into(),
            columns: &[
                (Column::Quantity, 26.0),
                (Column::Method, 42.0),
                (Column::Graphical, 32.0),
                (Column::Analytic, 34.0),
                (Column::Error, 36.0),
            ],
            name: &|r| {
                let name = symbols::quantity(r.key.symbol, &r.key.subject, lang);
                format!("{name}, {}", unit_in(r.key.symbol.unit(), lang))
            },
            unit: &|_| String::new(),
            value: &|_, x, scale| cell(x, scale, lang),
            graphical: &|_| None,
            size_mm: TABLE_MM,
        },
        rows,
        lang,
    )
}

/// An engine's gas forces at this position, one line a cylinder: the cycle angle θ from the
/// crank's φ₁ and the cylinder's φ₀, the pressure the indicator diagram gives at θ and the
/// force p·πd²/4 on the piston (named as its arrow is).
fn gas_lines(
    session: &Session<'_>,
    spec: &ForceSpec,
    f: &PositionForces,
    phi: f64,
    lang: Lang,
) -> Result<Vec<String>, BuildError> {
    if spec.indicators.is_empty() {
        return Ok(Vec::new());
    }
    let poses = session.poses()?;
    let (mpa, newton) = (unit_in("MPa", lang), unit_in("N", lang));
    let mut lines = Vec::new();
    for c in &spec.indicators {
        let Some(r) = c.reading(&poses.program, &f.drawn, phi.to_radians(), f.sense) else {
            continue;
        };
        let piston = plain(&c.point);
        // θ as the crank turns: from φ₀ in the sense of rotation, plus the whole turns
        // that bring it into [0°, 360°).
        let mut difference = if f.sense < 0.0 {
            format!("φ_{{0 {piston}}} − φ_{{1}}")
        } else {
            format!("φ_{{1}} − φ_{{0 {piston}}}")
        };
        if r.turns != 0.0 {
            let sign = if r.turns > 0.0 { "+" } else { "−" };
            let turn = format_fixed(360.0 * r.turns.abs(), 0, lang);
            difference.push_str(&format!(" {sign} {turn}°"));
        }
        lines.push(format!(
            "θ_{{{piston}}} = {difference} = {}, p_{{{piston}}} = {} {mpa} ({}), \
             {} = p_{{{piston}}}·πd_{{{piston}}}^2/4 = {} {newton}",
            super::digits::degrees(r.theta, lang),
            format_sig(r.pressure * 1e-6, 3, lang),
            Text::ByIndicator.get(lang),
            r.name(),
            value(r.force, lang),
        ));
    }
    Ok(lines)
}

/// The balancing load by the polygon against the lever (the seed's «погрешность»):
/// "M_у: по плану сил …, по рычагу Жуковского …, расхождение … %", and F_у likewise
/// through a gear; an engine's M_у named for what it is, the resisting moment on its shaft.
fn balance_lines(rows: &[Row], engine: bool, lang: Lang) -> Vec<String> {
    [Symbol::Moment, Symbol::Force]
        .into_iter()
        .filter_map(|symbol| {
            let of = |m: Method| {
                rows.iter()
                    .find(|r| r.key.symbol == symbol && r.key.subject == "bal" && r.method == m)
                    .map(|r| r.graphical)
            };
            let (p, l) = (of(Method::Polygon)?, of(Method::Lever)?);
            let unit = unit_in(symbol.unit(), lang);
            // Of the two values as printed (issue 45: a reader checking the line finds it).
            let (p_text, l_text) = (value(p, lang), value(l, lang));
            let unrounded = (l != 0.0 && p.is_finite() && l.is_finite()).then(|| (p - l) / l.abs());
            let diff = super::digits::printed_error(&p_text, &l_text, unrounded, lang).map_or_else(
                || super::digits::NO_VALUE.into(),
                |e| super::digits::error_pct(e.abs(), lang),
            );
            let name = symbols::quantity(symbol, "bal", lang);
            let name = if engine && symbol == Symbol::Moment {
                format!("{name} ({})", Text::ShaftResistance.get(lang))
            } else {
                name
            };
            Some(format!(
                "{name}: {} {} {unit}, {} {} {unit}, {} {diff} %",
                Text::ByPolygon.get(lang),
                p_text,
                Text::ByLever.get(lang),
                l_text,
                Text::Difference.get(lang),
            ))
        })
        .collect()
}
