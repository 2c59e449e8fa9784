//! The SVG writer: a plate as one deterministic SVG document printing 1:1 in millimetres.

use super::items::{hinges_last, step_marks};
use super::labels::{layout, text_block_lines, Layout, Leader};
use super::path::{num, Map, PathData};
use super::sheet::{frame_marks, title_block_marks};
use super::style::{Mark, Paint, Pen};
use super::View;
use svg::node::element::{Group, Path, Rectangle};
use svg::node::Blob;
use svg::Document;

/// The font family of every text; [`font_database`](super::font_database) maps it (and every
/// generic family) to the bundled DejaVu Sans.
pub const FONT_FAMILY: &str = "DejaVu Sans";

/// The plate as an SVG document: `width`/`height` in mm and a `viewBox` in mm, so it prints
/// 1:1. Deterministic: the same plate always gives the same bytes (stable element order,
/// stable ids `view-{k}-step-{id}`, coordinates rounded to 0.01 mm). The texts are written
/// where [`layout`](super::layout) places them.
pub fn to_svg(plate: &super::Plate) -> String {
    let laid = layout(plate);
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
        doc = doc.add(view_group(k, view, &laid, true));
    }
    let texts = plate
        .texts
        .iter()
        .flat_map(text_block_lines)
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

/// One view of a plate alone, as a figure of a document (the explanatory note): its SVG
/// holds the view's lines and labels, without its caption, cut to their box with a margin,
/// in millimetres at the plate's size.
#[derive(Debug, Clone, PartialEq)]
pub struct ViewSvg {
    /// The SVG document.
    pub svg: String,
    /// Its width, mm.
    pub width_mm: f64,
    /// Its height, mm.
    pub height_mm: f64,
}

/// Margin around a view cut out of its plate, mm.
const VIEW_MARGIN_MM: f64 = 2.0;

/// Every view of `plate` alone ([`ViewSvg`]), in order; `None` for a view that draws nothing.
pub fn view_svgs(plate: &super::Plate) -> Vec<Option<ViewSvg>> {
    let laid = layout(plate);
    plate
        .views
        .iter()
        .enumerate()
        .map(|(k, view)| {
            let labels = laid.labels.iter().filter(|l| l.view == k).map(|l| l.rect);
            let (min, max) = labels
                .chain(laid.views[k].drawn)
                .reduce(|a, b| a.union(&b))
                .map(|r| r.inflate(VIEW_MARGIN_MM))
                .map(|r| (r.min, r.max))?;
            let (w, h) = (max.x - min.x, max.y - min.y);
            let alone = view_group(k, view, &laid, false).set("id", "view");
            let doc = Document::new()
                .set("width", format!("{}mm", num(w)))
                .set("height", format!("{}mm", num(h)))
                .set(
                    "viewBox",
                    format!("{} {} {} {}", num(min.x), num(min.y), num(w), num(h)),
                )
                .set("font-family", FONT_FAMILY)
                .set("font-style", "italic")
                .add(alone);
            Some(ViewSvg {
                svg: format!("{doc}\n"),
                width_mm: w,
                height_mm: h,
            })
        })
        .collect()
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

/// A leader as drawn ([`Leader::marks`]): its line and shelf, and its dot on an item's line.
fn leader_group(l: &Leader) -> Group {
    l.marks()
        .into_iter()
        .fold(Group::new(), |g, mark| match mark {
            Mark::Path(paint, d) => g.add(path(paint, d)),
            Mark::Text(_) => g,
        })
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

/// A view: one group per step (hinges last, [`hinges_last`]), its labels, then its caption
/// when `captioned`.
fn view_group(k: usize, view: &View, laid: &Layout, captioned: bool) -> Group {
    let map = Map::figure(view.origin);
    let mut g = Group::new().set("id", format!("view-{k}"));
    for step in hinges_last(&view.figure.steps) {
        g = g.add(group(
            &format!("view-{k}-step-{}", step.id.0),
            step_marks(step, map),
        ));
    }
    let id = format!("view-{k}-labels");
    let mut labels = Group::new().set("id", id.as_str());
    let mut written = 0;
    for l in laid.labels.iter().filter(|l| l.view == k) {
        written += 1;
        if let Some(leader) = &l.leader {
            labels = labels.add(leader_group(leader).set("id", format!("{id}-leader-{written}")));
        }
        labels = labels.add(Blob::new(l.placed.to_xml(&format!("{id}-text-{written}"))));
    }
    if written > 0 {
        g = g.add(labels);
    }
    if let Some(caption) = laid.views[k].caption_text.as_ref().filter(|_| captioned) {
        g = g.add(group(
            &format!("view-{k}-caption"),
            vec![Mark::Text(caption.clone())],
        ));
    }
    g
}
