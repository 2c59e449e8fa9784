//! Plate "Уравновешивание ротора" (lecture 19 of seed 001): the rotor drawn with its masses
//! and correcting masses, the polygon of static moments (and, for a long rotor, the polygon
//! of moments), the data and results, and a table of the corrections read off the polygons
//! against their analytic twin. The smallest landscape sheet from A3 up that holds it all.

use super::layout::{keyed, lay_out_smallest, results_table, Block, Column, Results};
use super::BuildError;
use crate::balancing::{Balancing, Correction, Plane};
use crate::check::{Row, Symbol};
use crate::plate::{Plate, SheetSize, TableBlock};
use crate::scale::{format_number, Key, Lang, Scale};
use crate::study::Session;
use crate::words::{unit_in, RotorText, Text};

/// The sheets tried, smallest first.
const SIZES: [SheetSize; 3] = [SheetSize::A3, SheetSize::A2, SheetSize::A1];
/// Text height of the data lines and the table, mm.
const TEXT_MM: f64 = 3.5;
const TABLE_MM: f64 = 2.5;

/// Build the sheet of the scene's rotor.
pub fn build(session: &Session<'_>, lang: Lang) -> Result<Vec<Plate>, BuildError> {
    let scene = session.scene();
    let b = session.balancing()?;
    let dynamic = matches!(b.spec.correction, Correction::Dynamic { .. });
    let mut blocks = rotor_blocks(&b, lang);
    if let (Some(fig), Some(mu)) = (&b.moments, b.scale_mrz) {
        let caption = format!(
            "{}, {}",
            RotorText::MomentsPolygon.get(lang),
            polygon_scale(mu, Symbol::UnbalanceMoment, lang)
        );
        blocks.push(Block::view(
            fig.clone(),
            caption,
            keyed(Key::BalancingScaleMrz, mu),
        ));
    }
    let caption = format!(
        "{}, {}",
        RotorText::StaticMomentsPolygon.get(lang),
        polygon_scale(b.scale_mr, Symbol::StaticMoment, lang)
    );
    blocks.push(Block::view(
        b.statics.clone(),
        caption,
        keyed(Key::BalancingScaleMr, b.scale_mr),
    ));
    let mut lines = data_lines(&b, lang);
    lines.push(String::new());
    lines.push(super::drafting_line(
        session.drafting(),
        super::Errs::Rounding,
        lang,
    ));
    blocks.push(Block::Text {
        lines,
        size_mm: TEXT_MM,
    });
    let read_mm = session.drafting().resolution_mm();
    blocks.push(Block::Table(table(&b, read_mm, lang)));
    let sheet_title = if dynamic {
        RotorText::Complete
    } else {
        RotorText::Static
    }
    .get(lang);
    let title = super::title_block(scene, sheet_title, Some(b.scale_l), lang);
    // The smallest sheet that holds everything on one page; A1 (over pages) otherwise.
    lay_out_smallest(&SIZES, blocks, "balancing", &title, lang)
}

/// The rotor's views with their captions: the end view of a thin rotor; the side view and
/// the end view of a long one.
fn rotor_blocks(b: &Balancing, lang: Lang) -> Vec<Block> {
    let mu = b.scale_l;
    let n = b.rotor.len();
    b.rotor
        .iter()
        .enumerate()
        .map(|(k, fig)| {
            let what = if k + 1 < n {
                RotorText::Rotor
            } else if n > 1 {
                RotorText::AlongAxis
            } else {
                RotorText::Disc
            }
            .get(lang);
            let caption = format!("{what}, {}", mu.caption(lang));
            Block::view(fig.clone(), caption, keyed(Key::BalancingScaleL, mu))
        })
        .collect()
}

/// A number of the sheet: [`super::digits::value`]; beyond 10⁶ or under 10⁻⁴ as `1,5·10^{7}`,
/// so that no value widens a line past the sheet.
fn num(x: f64, lang: Lang) -> String {
    let a = x.abs();
    if a != 0.0 && a.is_finite() && !(1e-4..1e6).contains(&a) {
        let e = a.log10().floor();
        format!(
            "{}·10^{{{}}}",
            super::digits::value(x / 10f64.powf(e), lang),
            e as i32
        )
        .replace("{-", "{−")
    } else {
        super::digits::value(x, lang)
    }
}

/// The data of the task and the correcting masses found, as text lines (label markup).
fn data_lines(b: &Balancing, lang: Lang) -> Vec<String> {
    let (kg, mm) = (unit_in("kg", lang), unit_in("mm", lang));
    let mut out = vec![Text::Data.get(lang).to_string()];
    let dynamic = matches!(b.spec.correction, Correction::Dynamic { .. });
    for (i, m) in b.spec.masses.iter().enumerate() {
        let k = i + 1;
        let mut line = format!(
            "m_{{{k}}} = {} {kg}, ρ_{{{k}}} = {} {mm}, α_{{{k}}} = {}°",
            num(m.mass, lang),
            num(m.radius * 1e3, lang),
            num(m.angle.to_degrees().rem_euclid(360.0), lang)
        );
        if dynamic {
            line.push_str(&format!(", z_{{{k}}} = {} {mm}", num(m.z * 1e3, lang)));
        }
        out.push(line);
    }
    match b.spec.correction {
        Correction::Static { radius } => {
            out.push(format!("ρ_{{у}} = {} {mm}", num(radius * 1e3, lang)))
        }
        Correction::Dynamic { planes, radii } => {
            out.push(format!(
                "z_{{I}} = {} {mm}, z_{{II}} = {} {mm}; ρ_{{уI}} = {} {mm}, ρ_{{уII}} = {} {mm}",
                num(planes[0] * 1e3, lang),
                num(planes[1] * 1e3, lang),
                num(radii[0] * 1e3, lang),
                num(radii[1] * 1e3, lang)
            ));
        }
    }
    if let Some(w) = b.spec.omega {
        out.push(format!("ω = {} {}", num(w, lang), unit_in("rad/s", lang)));
    }
    out.push(String::new());
    out.push(RotorText::CorrectingMasses.get(lang).into());
    let kgmm = unit_in(sheet_unit(Symbol::StaticMoment).0, lang);
    for c in &b.graphical {
        let idx = c.plane.index();
        let u = c.unbalance.length();
        let angle = c.angle().map_or_else(
            || super::digits::NO_VALUE.to_string(),
            |a| super::digits::degrees(a, lang),
        );
        out.push(format!(
            "m_{{{idx}}} = m_{{{idx}}}ρ_{{{idx}}}/ρ_{{{idx}}} = {} {kgmm}/{} {mm} = {} {kg}, α_{{{idx}}} = {}",
            num(u * sheet_unit(Symbol::StaticMoment).1, lang),
            num(c.radius * 1e3, lang),
            num(c.mass(), lang),
            angle
        ));
    }
    if let Some(w) = b.spec.omega {
        let n = unit_in("N", lang);
        for (i, m) in b.spec.masses.iter().enumerate() {
            let f = crate::balancing::inertia_force(m, w);
            let g = m.mass * crate::scale::G;
            out.push(format!(
                "F_{{и{k}}} = m_{{{k}}}ω^2ρ_{{{k}}} = {} {n}, F_{{и{k}}}/G_{{{k}}} = {}",
                num(f, lang),
                num(f / g, lang),
                k = i + 1
            ));
        }
    }
    out
}

/// The index of a plane's correcting mass from its report subject (`y`, `I`, `II`).
fn plane_index(subject: &str) -> &'static str {
    match subject {
        "I" => Plane::First.index(),
        "II" => Plane::Second.index(),
        _ => Plane::Disc.index(),
    }
}

/// A row's quantity in the textbook's notation (the correcting masses indexed by their
/// plane: `m_{уI}ρ_{уI}`; the inertia force and moment before and after correction) and its
/// unit.
fn quantity(r: &Row, lang: Lang) -> (String, String) {
    let idx = plane_index(&r.key.subject);
    let stage = if r.key.subject == "res" {
        RotorText::After
    } else {
        RotorText::Before
    }
    .get(lang);
    let unit = unit_in(sheet_unit(r.key.symbol).0, lang);
    match r.key.symbol {
        Symbol::StaticMoment => (format!("m_{{{idx}}}ρ_{{{idx}}}"), unit),
        Symbol::UnbalanceMoment => (format!("m_{{{idx}}}ρ_{{{idx}}}z_{{II}}"), unit),
        Symbol::Mass => (format!("m_{{{idx}}}"), unit),
        Symbol::Angle => (format!("α_{{{idx}}}"), "°".into()),
        Symbol::Force => (format!("F_{{и}} {stage}"), unit),
        Symbol::Moment => (format!("M_{{и}} {stage}"), unit),
        _ => (super::layout::quantity(r, lang), unit),
    }
}

/// The unit a row's value is printed in on the sheet and its factor from SI: an
/// unbalance in kg·mm (kg·mm² about a plane) as the rotor's radii are in mm, so that no
/// value runs into zeros (0,0085 кг·м is 8,5 кг·мм); an angle in degrees.
fn sheet_unit(symbol: Symbol) -> (&'static str, f64) {
    match symbol {
        Symbol::StaticMoment => ("kg*mm", 1e3),
        Symbol::UnbalanceMoment => ("kg*mm^2", 1e6),
        Symbol::Angle => ("deg", 180.0 / std::f64::consts::PI),
        s => (s.unit(), 1.0),
    }
}

/// The μ of a polygon of `symbol` in the unit the table gives its values in
/// ([`sheet_unit`]): μ_{mρz} = 20 кг·мм²/мм beside 1340 кг·мм², not 0,00002 кг·м²/мм.
fn polygon_scale(mu: Scale, symbol: Symbol, lang: Lang) -> String {
    let (unit, factor) = sheet_unit(symbol);
    format!(
        "μ_{{{}}} = {} {}/{}",
        mu.quantity.symbol(),
        format_number(mu.value() * factor, lang),
        unit_in(unit, lang),
        unit_in("mm", lang)
    )
}

/// The table graphical | analytic | error of the balancing's rows (angles in degrees,
/// unbalances in kg·mm, [`sheet_unit`]); a force or moment read to its step off a polygon
/// whose lengths are read to `read_mm` ([`Balancing::reading_step`]): the static rotor's
/// residual after balancing, read to 0,5 mm × 0,05 кг·мм/мм × (300 рад/с)² = 2,25 Н, is «1»,
/// not «0,9602».
fn table(b: &Balancing, read_mm: f64, lang: Lang) -> TableBlock {
    let rows = b.rows();
    let value = |r: &Row, x: f64, s: f64| {
        let k = sheet_unit(r.key.symbol).1;
        if crate::check::is_zero(x, s) {
            "0".to_string()
        } else {
            num(x * k, lang)
        }
    };
    results_table(
        &Results {
            title: Text::GraphicalAndAnalytic.get(lang).into(),
            columns: &[
                (Column::Quantity, 30.0),
                (Column::Unit, 14.0),
                (Column::Graphical, 26.0),
                (Column::Analytic, 28.0),
                (Column::Error, 16.0),
            ],
            name: &|r| quantity(r, lang).0,
            unit: &|r| quantity(r, lang).1,
            value: &value,
            graphical: &|r| {
                let k = sheet_unit(r.key.symbol).1;
                let step = b.reading_step(r, read_mm)?;
                Some(super::digits::read(r.graphical * k, Some(step * k), lang))
            },
            size_mm: TABLE_MM,
        },
        &rows,
        lang,
    )
}
