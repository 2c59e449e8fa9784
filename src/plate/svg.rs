//! The SVG writer: a plate as one deterministic SVG document printing 1:1 in millimetres.

use super::items::step_marks;
use super::path::{num, Map, PathData};
use super::sheet::{frame_marks, title_block_marks};
use super::style::{Mark, Paint, Pen};
use super::text::{Align, Placed};
use super::{Plate, TextBlock, View, CAPTION_BAND_MM};
use crate::geom::DVec2;
use svg::node::element::{Group, Path, Rectangle};
use svg::node::Blob;
use svg::Document;

/// The font family of every text; [`font_database`](super::font_database) maps it (and every
/// generic family) to the bundled DejaVu Sans.
pub const FONT_FAMILY: &str = "DejaVu Sans";
/// ГОСТ 2.304 size of view captions, mm.
pub const CAPTION_HEIGHT_MM: f64 = 5.0;

/// The plate as an SVG document: `width`/`height` in mm and a `viewBox` in mm, so it prints
/// 1:1. Deterministic: the same plate always gives the same bytes (stable element order,
/// stable ids `view-{k}-step-{id}`, coordinates rounded to 0.01 mm).
pub fn to_svg(plate: &Plate) -> String {
    let (w, h) = (num(plate.sheet.width_mm()), num(plate.sheet.height_mm()));
    let background = Rectangle::new()
        .set("id", "background")
        .set("x", 0)
        .set("y", 0)
        .set("width", w.clone())
        .set("height", h.clone())
        .set("fill", "#fff");
    let mut doc = Document::new()
        .set("width", format!("{w}mm"))
        .set("height", format!("{h}mm"))
        .set("viewBox", format!("0 0 {w} {h}"))
        .set("font-family", FONT_FAMILY)
        .set("font-style", "italic")
        .add(background)
        .add(group(
            "sheet",
            frame_marks(&plate.sheet, &plate.title_block),
        ))
        .add(group(
            "title-block",
            title_block_marks(&plate.sheet, &plate.title_block, plate.lang),
        ));
    for (k, view) in plate.views.iter().enumerate() {
        doc = doc.add(view_group(k, view));
    }
    let texts = plate
        .texts
        .iter()
        .flat_map(text_block)
        .map(Mark::Text)
        .collect();
    doc = doc.add(group("texts", texts));
    for (k, table) in plate.tables.iter().enumerate() {
        doc = doc.add(group(
            &format!("table-{k}"),
            super::table::table_marks(table),
        ));
    }
    format!("{doc}\n")
}

/// A group of marks with id `id`; texts get ids `{id}-text-{n}`.
fn group(id: &str, marks: Vec<Mark>) -> Group {
    let mut g = Group::new().set("id", id);
    let mut texts = 0;
    for mark in marks {
        g = match mark {
            Mark::Path(paint, d) => g.add(path(paint, d)),
            Mark::Text(t) => {
                texts += 1;
                g.add(Blob::new(t.to_xml(&format!("{id}-text-{texts}"))))
            }
        };
    }
    g
}

fn path(paint: Paint, d: PathData) -> Path {
    let p = Path::new().set("d", d.into_string());
    match paint {
        Paint::Stroke(pen) => pen_attrs(p.set("fill", "none"), pen),
        Paint::Opaque(pen) => pen_attrs(p.set("fill", "#fff"), pen),
        Paint::Solid => p.set("fill", "#000"),
    }
}

fn pen_attrs(p: Path, pen: Pen) -> Path {
    let p = p
        .set("stroke", "#000")
        .set("stroke-width", num(pen.width))
        .set("stroke-linejoin", "round");
    if pen.dash.is_empty() {
        p.set("stroke-linecap", "round")
    } else {
        let dash: Vec<String> = pen.dash.iter().map(|&x| num(x)).collect();
        p.set("stroke-dasharray", dash.join(" "))
    }
}

/// A view: one group per step (in order), then the caption under the figure's bounds.
fn view_group(k: usize, view: &View) -> Group {
    let map = Map::figure(view.origin);
    let mut g = Group::new().set("id", format!("view-{k}"));
    for step in &view.figure.steps {
        g = g.add(group(
            &format!("view-{k}-step-{}", step.id.0),
            step_marks(step, map),
        ));
    }
    if let (Some(caption), Some((lo, hi))) = (&view.caption, view.figure.bounds()) {
        let bottom = view.to_sheet(DVec2::new((lo.x + hi.x) * 0.5, lo.y));
        let at = bottom + DVec2::new(0.0, CAPTION_BAND_MM - CAPTION_HEIGHT_MM);
        g = g.add(group(
            &format!("view-{k}-caption"),
            vec![Mark::Text(Placed::centred(
                at,
                caption,
                CAPTION_HEIGHT_MM,
                Align::Middle,
            ))],
        ));
    }
    g
}

/// The lines of a text block, two text heights apart.
fn text_block(block: &TextBlock) -> Vec<Placed> {
    let h = block.size_mm;
    block
        .lines
        .iter()
        .enumerate()
        .map(|(i, line)| {
            Placed::new(
                block.at + DVec2::new(0.0, h * (1.0 + 2.0 * i as f64)),
                line,
                h,
                Align::Start,
            )
        })
        .collect()
}
