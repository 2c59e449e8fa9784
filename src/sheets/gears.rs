//! Plate "Зубчатые передачи" (seed 000 sheet 3, seed 002 PZ1–PZ3): the meshing picture with
//! all circles, lines and labels, the diagram of specific sliding, each wheel cut by the rack
//! with its rack positions (and undercut), the data and results, and the table of what was
//! read off the drawings against the analytic values. A pair's own sheet (seed 002 PZ3: no
//! cut wheels, no train) also draws the pair's blocking contour with the scene's point and
//! the textbook's choices, and names them in its lines. A1 landscape.

use super::digits::read;
use super::layout::{
    drawn_value, lay_out_smallest, quantity, results_table, Block, Column, Results, ScaleKey,
};
use super::BuildError;
use crate::check::{Method, Row, Symbol};
use crate::construct::Figure;
use crate::gears::blocking::BlockingStudy;
use crate::gears::{DetailMark, GearStudy, DETAIL_LETTER};
use crate::plate::{Plate, SheetSize, TableBlock};
use crate::scale::{format_sig, Key, Lang, Scale};
use crate::study::Session;
use crate::words::{unit_in, GearText};

/// Text height of the data lines and the table, mm.
const TEXT_MM: f64 = 3.5;
const TABLE_MM: f64 = 2.5;

/// Build the gear sheet of the scene.
pub fn build(session: &Session<'_>, lang: Lang) -> Result<Vec<Plate>, BuildError> {
    let scene = session.scene();
    let g = session.gears()?;
    let mut sheet = Filling {
        lang,
        mm: unit_in("mm", lang),
        blocks: Vec::new(),
        details: Vec::new(),
        lines: vec![GearText::DataAndResults.get(lang).to_string()],
        plan: None,
        read_mm: session.drafting().resolution_mm(),
    };
    // The blocking contour on a pair's own sheet (seed 002 PZ3), and on any gear sheet
    // whose shifts the contour chose (`choose`): the choice is shown where it was made. The
    // course project's gear sheet of given shifts keeps it in the report's rows and notes.
    let contour = g
        .blocking
        .as_ref()
        .filter(|b| (g.racks.is_empty() && g.train.is_none()) || b.chosen.is_some());
    if let Some(crate::gears::MeshedPair {
        pair: p,
        meshing: m,
    }) = &g.pair
    {
        sheet.pair_views(p, (&m.figure, &m.sliding, m.scale), contour);
        sheet.pair_lines(p, (m.ab.value, m.scale));
        if let Some(b) = contour {
            sheet.contour_lines(b);
        }
    }
    // A sheet of cut wheels with no pair states the module and the rack they are cut with.
    if let (None, Some(first)) = (&g.pair, g.racks.first()) {
        sheet.rack_data(&first.generation.cutting);
    }
    for w in &g.racks {
        sheet.rack(&w.generation);
    }
    if let Some(t) = &g.train {
        sheet.train(t, g.pair.is_some());
    }
    let Filling {
        mut blocks,
        mut details,
        mut lines,
        plan,
        read_mm,
        ..
    } = sheet;
    blocks.append(&mut details);
    lines.push(String::new());
    let [_, rest] = g.rows_by_part();
    let computed = |symbol, method| {
        rest.iter()
            .any(|r| r.key.symbol == symbol && r.method == method)
    };
    if computed(Symbol::ShiftCoefficient, Method::Formula) {
        lines.push(GearText::XMinRule.get(lang).into());
    }
    lines.push(super::drafting_line(
        session.drafting(),
        super::Errs::Rounding,
        lang,
    ));
    blocks.push(Block::Text {
        lines,
        size_mm: TEXT_MM,
    });
    // Two tables, each finding its own room: what was read off the drawings (the meshing
    // picture, the envelope, the triangles) against the analytic values, and what was
    // computed by formula against another route — a formula's value is no graphical reading.
    let (read, computed) = tables_rows(&g);
    if !read.is_empty() {
        blocks.push(Block::Table(table(&read, &g, read_mm, lang)));
    }
    if !computed.is_empty() {
        blocks.push(Block::Table(formula_table(&computed, &g, lang)));
    }
    let Some(plan) =
        plan.or_else(|| crate::scale::Scale::new(0.001, crate::scale::Quantity::Length))
    else {
        return Ok(Vec::new());
    };
    let title = super::title_block(scene, GearText::Title.get(lang), Some(plan), lang);
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
    key: Key,
    scale: crate::scale::Scale,
) -> Block {
    Block::view(figure.clone(), caption, Some(ScaleKey { key, scale }))
}

/// The gear sheet's rows as its two tables hold them: those read off the drawings (under
/// "графически") and those computed ([`Row::is_read_off`]), each in the order of the parts.
pub(crate) fn tables_rows(g: &crate::gears::GearStudy) -> (Vec<Row>, Vec<Row>) {
    let [pair, rest] = g.rows_by_part();
    // x_min depends on z alone: once for the wheels of one z (PZ1 listed it for each).
    let mut minima = Vec::new();
    pair.into_iter()
        .chain(rest)
        .filter(|r| match g.cut_wheel_of(r) {
            Some((w, "min")) => {
                let z = w.generation.cutting.z;
                let first = !minima.contains(&z);
                minima.push(z);
                first
            }
            _ => r.key.symbol != Symbol::EnvelopeDeviation,
        })
        .partition(Row::is_read_off)
}

/// A row's quantity on the gear sheet ([`quantity`]); a cut wheel's by its own subscript and
/// the wheel as its picture's caption names it, `s_a (x = 0,6)`, with its z when the sheet's
/// cut wheels differ in it (x_min by its z only): the scene's name of the wheel («0», «1p»)
/// is no word of the sheet's, and a cut wheel's s_a is not the pair's s_a1 (the shaper's
/// sheet wrote s_a1 for both).
fn gear_quantity(g: &crate::gears::GearStudy, r: &Row, lang: Lang) -> String {
    cut_wheel_quantity(g, r, lang).unwrap_or_else(|| quantity(r, lang))
}

/// A cut wheel's row named as [`gear_quantity`] names it; `None` for a row of no cut wheel.
pub(crate) fn cut_wheel_quantity(
    g: &crate::gears::GearStudy,
    r: &Row,
    lang: Lang,
) -> Option<String> {
    let (w, bare) = g.cut_wheel_of(r)?;
    let name = crate::words::symbols::quantity(r.key.symbol, bare, lang);
    let c = &w.generation.cutting;
    let one_z = g.racks.iter().all(|o| o.generation.cutting.z == c.z);
    let x = format!("x = {}", format_sig(c.x, 4, lang));
    Some(match (bare, one_z) {
        ("min", true) => name,
        ("min", false) => format!("{name} (z = {})", c.z),
        (_, true) => format!("{name} ({x})"),
        (_, false) => format!("{name} (z = {}, {x})", c.z),
    })
}

/// Δy, and the indices of the blocking contour's points, to thousandths, as Kudryavtsev's
/// tables give the shifts and Δy (x₁ = 0,694, Δy = 0,160): «Δy = 0,160» in the pair's line,
/// the cut wheel's caption, at K and in the table alike.
fn thousandths(x: f64, lang: Lang) -> String {
    crate::scale::format_fixed(x, 3, lang)
}

/// The unit a row's value is written in and its factor from SI, one per quantity on the
/// sheet: a length in mm, the drawn envelope's deviation from the exact one in nm (each
/// wheel's, whatever its size); an angle in degrees; an angular velocity in rad/s.
fn table_unit(r: &Row) -> (&'static str, f64) {
    match crate::words::shown_unit(r.key.symbol) {
        (k, u @ ("mm" | "nm" | "deg" | "rad/s")) => (u, k),
        _ => ("", 1.0),
    }
}

/// The table of the rows read off the drawings (lengths read to `read_mm`): quantity |
/// method (the drawing read) | unit | graphical | analytic | error (lengths in mm).
fn table(rows: &[Row], g: &GearStudy, read_mm: f64, lang: Lang) -> TableBlock {
    values_table(
        rows,
        read_mm,
        g,
        GearText::ReadOff.get(lang).into(),
        &[
            (Column::Quantity, 26.0),
            (Column::Method, 36.0),
            (Column::Unit, 10.0),
            (Column::Graphical, 24.0),
            (Column::Analytic, 26.0),
            (Column::Error, 16.0),
        ],
        lang,
    )
}

/// The table of the rows computed — by formula (the textbook's chain), or from the
/// construction's points (the envelope's deviation) —: quantity | unit | computed | check (an
/// independent route, the exact value) | error.
fn formula_table(rows: &[Row], g: &GearStudy, lang: Lang) -> TableBlock {
    let mut t = values_table(
        rows,
        0.0,
        g,
        GearText::Computed.get(lang).into(),
        &[
            (Column::Quantity, 26.0),
            (Column::Unit, 10.0),
            (Column::Graphical, 26.0),
            (Column::Analytic, 26.0),
            (Column::Error, 16.0),
        ],
        lang,
    );
    t.columns[2].0 = GearText::ComputedValue.get(lang).into();
    t.columns[3].0 = GearText::OtherRoute.get(lang).into();
    t
}

/// The rows as a table of `columns` titled `title` (lengths in mm), their graphical values
/// read to the step of `read_mm` on the drawing read ([`GearStudy::reading_step`]).
fn values_table(
    rows: &[Row],
    read_mm: f64,
    g: &GearStudy,
    title: String,
    columns: &[(Column, f64)],
    lang: Lang,
) -> TableBlock {
    let cell = |r: &Row, x: f64, step: Option<f64>| match r.key.symbol {
        Symbol::EqualisingShift => thousandths(x, lang),
        _ => drawn_value(r, x, table_unit(r).1, step, lang),
    };
    results_table(
        &Results {
            title,
            columns,
            name: &|r| gear_quantity(g, r, lang),
            unit: &|r| match table_unit(r).0 {
                "" => String::new(),
                u => unit_in(u, lang),
            },
            value: &|r, x, _| cell(r, x, None),
            graphical: &|r| Some(cell(r, r.graphical, g.reading_step(r, read_mm))),
            size_mm: TABLE_MM,
        },
        rows,
        lang,
    )
}

/// The name of what the undercut's detail view shows.
fn detail_name(m: DetailMark, lang: Lang) -> String {
    match m {
        DetailMark::Involute => GearText::DetailInvolute.get(lang).into(),
        DetailMark::Junction => GearText::DetailJunction.get(lang).into(),
        DetailMark::Fillet => GearText::DetailFillet.get(lang).into(),
        DetailMark::Undercut => GearText::DetailUndercut.get(lang).into(),
        DetailMark::BaseCircle => "r_b".into(),
        DetailMark::RackTip => GearText::DetailRackTip.get(lang).into(),
    }
}

/// The criterion a pair's shifts were chosen by, in words.
fn criterion_words(c: crate::gears::blocking::Criterion, lang: Lang) -> String {
    use crate::gears::blocking::Criterion;
    match c {
        Criterion::LargestContactRatio => GearText::LargestContactRatio.get(lang).into(),
        Criterion::EqualSliding { x_sum } => format!(
            "{} {}",
            GearText::EqualSliding.get(lang),
            format_sig(x_sum, 4, lang)
        ),
        Criterion::GreatestSumWithTip { sa_min } => format!(
            "{} {}m",
            GearText::GreatestSum.get(lang),
            format_sig(sa_min, 3, lang)
        ),
    }
}

/// The gear sheet as it is filled: its views, the detail views (after the pictures), the
/// lines of its text block and the μ of its title block.
struct Filling {
    lang: Lang,
    /// The unit mm in the sheet's words.
    mm: String,
    blocks: Vec<Block>,
    details: Vec<Block>,
    lines: Vec<String>,
    plan: Option<crate::scale::Scale>,
    /// How finely lengths are read off the drawing, mm (0: exactly).
    read_mm: f64,
}

impl Filling {
    /// The pair's meshing picture and its diagram of specific sliding (both at the picture's
    /// μ_l), and the blocking contour when the sheet shows it.
    fn pair_views(
        &mut self,
        p: &crate::gears::GearPair,
        (figure, sliding, scale): (&Figure, &Figure, crate::scale::Scale),
        contour: Option<&BlockingStudy>,
    ) {
        let (lang, mm_) = (self.lang, &self.mm);
        self.plan = Some(scale);
        let caption = format!("{}, {}", GearText::Meshing.get(lang), scale.caption(lang));
        self.blocks
            .push(view(figure, caption, Key::GearsScaleL, scale));
        let caption = format!(
            "{}: λ_1, λ_2 {} N_1N_2, λ = 1 ↔ {} {}",
            GearText::Sliding.get(lang),
            GearText::Along.get(lang),
            format_sig(crate::gears::LAMBDA_MM, 3, lang),
            mm_,
        );
        self.blocks
            .push(view(sliding, caption, Key::GearsScaleL, scale));
        if let Some(b) = contour {
            let words = crate::gears::blocking::Words {
                interference: GearText::Interference.get(lang),
            };
            let caption = format!(
                "{} z_1 = {}, z_2 = {}",
                GearText::Blocking.get(lang),
                p.spec.z[0],
                p.spec.z[1]
            );
            self.blocks.push(
                Block::view(b.figure(scale, lang, words), caption, None).with_edge_label_room(),
            );
        }
    }

    /// The pair's data and results: m, z, x; α_w, a_w, y, Δy; the radii, the pitches and
    /// s_a; ε_α by formula and as drawn (B₁B₂ read off the meshing picture, `ab_drawn`, m).
    fn pair_lines(&mut self, p: &crate::gears::GearPair, (ab_drawn, mu): (f64, Scale)) {
        use super::digits::{degrees, mm, value};
        let lang = self.lang;
        let mm = |x: f64| mm(x, lang);
        self.lines.push(format!(
            "m = {}, z_1 = {}, z_2 = {}, x_1 = {}, x_2 = {}",
            mm(p.spec.module),
            p.spec.z[0],
            p.spec.z[1],
            value(p.spec.x[0], lang),
            value(p.spec.x[1], lang),
        ));
        self.lines.push(format!(
            "α_w = {}, a_w = {}, y = {}, Δy = {}",
            degrees(p.alpha_w, lang),
            mm(p.a_w),
            value(p.y, lang),
            thousandths(p.dy, lang),
        ));
        self.lines.push(format!(
            "r_{{w1}} = {}, r_{{w2}} = {}, r_{{a1}} = {}, r_{{a2}} = {}, r_{{f1}} = {}, r_{{f2}} = {}",
            mm(p.rw[0]), mm(p.rw[1]), mm(p.ra[0]), mm(p.ra[1]), mm(p.rf[0]), mm(p.rf[1])
        ));
        self.lines.push(format!(
            "p = {}, p_b = {}, p_w = {}, s_{{a1}} = {}, s_{{a2}} = {}",
            mm(p.p),
            mm(p.p_b),
            mm(p.p_w),
            mm(p.sa[0]),
            mm(p.sa[1])
        ));
        // B₁B₂ worked from the radii (the textbook's), then read off the meshing picture.
        let step = mu.reading_step(self.read_mm);
        self.lines.push(format!(
            "ε_α = (N_1B_2 + N_2B_1 − N_1N_2)/p_b = {}; {}",
            value(p.eps, lang),
            GearText::EpsDrawn
                .get(lang)
                .replace(
                    "{ab}",
                    &format!(
                        "{} {}",
                        read(ab_drawn * 1e3, step.map(|s| s * 1e3), lang),
                        self.mm
                    )
                )
                .replace("{pb}", &mm(p.p_b))
                .replace(
                    "{eps}",
                    &read(ab_drawn / p.p_b, step.map(|s| s / p.p_b), lang)
                ),
        ));
    }

    /// The blocking contour's points, each with its indices, and the criterion the scene's
    /// point was chosen by.
    fn contour_lines(&mut self, b: &BlockingStudy) {
        let lang = self.lang;
        let f = |x: f64| format_sig(x, 4, lang);
        let d3 = |x: f64| thousandths(x, lang);
        for (tag, ix) in b.points() {
            let name = crate::words::point_label(tag);
            let head = if tag == crate::words::POINT_TAGS[0] {
                format!("{}, {name}", GearText::Blocking.get(lang))
            } else {
                name.to_string()
            };
            self.lines.push(format!(
                "{head}: x_1 = {}, x_2 = {}, Δy = {}, ε_α = {}, s_{{a1}} = {}m, s_{{a2}} = {}m",
                d3(ix.x[0]),
                d3(ix.x[1]),
                d3(ix.dy),
                d3(ix.eps),
                d3(ix.sa[0]),
                d3(ix.sa[1]),
            ));
        }
        // The choices lie inside the hard limits by a margin (a supremum on a limit is a
        // pair that does not work): the ε_α = 1,05 of «x_Σ max» is that, not a limit unsaid.
        if b.points().len() > 1 {
            use crate::gears::blocking::CHOICE_MARGIN as M;
            self.lines.push(
                GearText::ChoiceMargin
                    .get(lang)
                    .replace("{m}", &f(M))
                    .replace("{eps}", &f(BlockingStudy::HARD.eps_min + M))
                    .replace("{sa}", &f(BlockingStudy::HARD.sa_min + M)),
            );
        }
        if let Some(c) = b.chosen {
            self.lines.push(format!(
                "{} {}",
                GearText::ChosenBy.get(lang),
                criterion_words(c, lang)
            ));
        }
    }

    /// The module and the basic rack of wheels cut with no pair of their own:
    /// «m = 10 мм, α = 20°, h_a* = 1, c* = 0,25».
    fn rack_data(&mut self, c: &crate::gears::Cutting) {
        let (lang, mm_) = (self.lang, &self.mm);
        self.lines.push(format!(
            "m = {} {mm_}, α = {}°, h_a* = {}, c* = {}",
            format_sig(c.module * 1e3, 4, lang),
            format_sig(c.rack.alpha.to_degrees(), 4, lang),
            format_sig(c.rack.ha, 4, lang),
            format_sig(c.rack.c, 4, lang),
        ));
    }

    /// A wheel cut by the rack: its view (and the undercut's detail view), its line.
    fn rack(&mut self, r: &crate::gears::Generation) {
        let (lang, mm_) = (self.lang, &self.mm);
        let c = &r.cutting;
        // A blank shortened by Δy (a pair's wheel) says so.
        let dy = c.shortening();
        let shortened = if dy.abs() > 1e-9 {
            format!(", Δy = {}", thousandths(dy, lang))
        } else {
            String::new()
        };
        // The undercut's detail view, named by its letter and scale (ГОСТ 2.305: «А (20:1)»),
        // after the pictures (a detail may stand anywhere on the sheet).
        let names = |m: DetailMark| detail_name(m, lang);
        let detail = r.detail_view(&names).zip(r.detail.map(|(_, scale)| scale));
        let undercut = match (&detail, r.undercut) {
            (_, false) => String::new(),
            (Some(_), true) => GearText::UndercutInDetail
                .get(lang)
                .replace("{letter}", DETAIL_LETTER),
            (None, true) => GearText::UndercutHatched.get(lang).into(),
        };
        let caption = format!(
            "{} z = {}, x = {}{shortened}, N = {} ({}), {}{undercut}",
            GearText::CutByRack.get(lang),
            c.z,
            format_sig(c.x, 4, lang),
            r.steps,
            GearText::PositionsDrawn
                .get(lang)
                .replace("{n}", &r.drawn.len().to_string()),
            r.scale.caption(lang),
        );
        self.blocks
            .push(view(&r.drawing(), caption, Key::GearsRackScaleL, r.scale));
        if let Some((detail, scale)) = detail {
            let caption = format!("{DETAIL_LETTER} ({})", super::gost_scale(scale, lang));
            self.details
                .push(view(&detail, caption, Key::GearsRackScaleL, r.scale));
        }
        self.plan.get_or_insert(r.scale);
        // Named by its z and x as its picture's caption names it (the scene's own name of
        // the wheel, «0», «1p», is no word of the sheet's); x_min is the table's, by the
        // textbook's rule against the exact one, not a third time here.
        self.lines.push(format!(
            "z = {}, x = {}: s_a = {} {}{}{}{}",
            c.z,
            format_sig(c.x, 4, lang),
            read(
                r.sa * 1e3,
                r.scale.reading_step(self.read_mm).map(|s| s * 1e3),
                lang
            ),
            mm_,
            // A pointed tip against the least the course admits.
            if r.pointed {
                format!(
                    " < {}m = {} {mm_}",
                    format_sig(crate::gears::MIN_TIP, 2, lang),
                    format_sig(crate::gears::MIN_TIP * c.module * 1e3, 4, lang)
                )
            } else {
                String::new()
            },
            if r.undercut {
                GearText::Undercut.get(lang)
            } else {
                ""
            },
            if r.pointed {
                GearText::Pointed.get(lang)
            } else {
                ""
            },
        ));
    }

    /// The train: the triangles of velocities with μ_ω, the mobility, the differential's and
    /// the closing's lines, the assembly of the satellites; its module named apart from a
    /// `pair`'s on the sheet.
    fn train(&mut self, t: &crate::gears::TrainStudy, pair: bool) {
        let lang = self.lang;
        // A sheet of a train alone is drawn at its triangles' μ_l (the title block read 1:1
        // over the differential's 2:1).
        self.plan.get_or_insert(t.triangles.scale_l);
        self.blocks
            .push(super::train_view::triangles_block(t, lang));
        self.lines.extend(super::train_lines::lines(t, pair, lang));
    }
}
