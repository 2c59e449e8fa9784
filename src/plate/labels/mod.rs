//! The plate's layout: where every text goes and what every item covers, in sheet mm.
//!
//! Labels are placed by the plate, not at a fixed offset from their point. Labels of one view
//! whose points coincide on the sheet (within [`COINCIDENT_MM`]) become one joint label written
//! as the textbook does, `p ≡ b₃ ≡ d` (the figure's order, the pole first) — labels of points
//! only ([`Names::Point`]): two forces, arms or couples drawn at one place are two labels,
//! never `R₁₋₂ ≡ R₂₋₃` (issue 45). A label of a line, a vector or an arc keeps nearer its own
//! item than any other line of its view where it can. Every label then
//! tries positions around its point — its preferred direction first, then sixteen directions
//! at five distances, a joint label also from each corner of its point — and keeps the one
//! that collides least with what is already placed (labels, captions, text blocks, tables)
//! and with the lines and symbols of the drawing (the main lines weigh most), never leaving
//! the frame nor entering the title block when it can help it. A label left away from its
//! object takes a leader line to it where one costs less ([`Leader`], ГОСТ 2.316). Crowded labels are placed first; the order is deterministic, so is the layout.
//! The SVG writer writes the texts from this layout, and the tests check its boxes.

use super::items::LABEL_GAP_MM;
use super::items::{short_vector, step_outlines, Outline, Shape, COINCIDENT_MM, JOINT_RADIUS_MM};
use super::path::Map;
use super::style::{Mark, Pen};
use super::table::table_marks;
use super::text::{measure, plain, Align, Extent, Placed};
use super::text::{CAPTION_HEIGHT_MM, LABEL_HEIGHT_MM};
use super::{Plate, Rect, TextBlock, View, CAPTION_BAND_MM};
use crate::construct::{Item, Label, Names, StepId};
use crate::geom::DVec2;
use std::f64::consts::{FRAC_PI_4, TAU};

/// How a joint label joins its names.
pub const JOINT_SEPARATOR: &str = " ≡ ";
/// Each further ring of candidate positions lies this much further from the point, mm.
pub const SECOND_RING_MM: f64 = 3.0;
/// Rings of candidate positions around a point: the outer ones (9 and 12 mm further) are
/// taken only when every nearer place is struck through by a line or covers another text (a
/// force's label in a crowded group: `R₃₋₄ ≡ R₄₋₅` among G₄, G₅ and F_и₄, issue 19 item 6).
const RINGS: usize = 5;
/// Clearance kept between a label and other texts while placing, mm.
const CLEARANCE_MM: f64 = 1.0;
/// Directions tried around a point.
const DIRECTIONS: usize = 16;

/// A label as placed on the sheet.
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedLabel {
    /// Index of its view in [`Plate::views`].
    pub view: usize,
    /// The steps whose labels it writes (several for a joint label), in the figure's order.
    pub steps: Vec<StepId>,
    /// The text in label markup (names joined by [`JOINT_SEPARATOR`]).
    pub text: String,
    /// The point it labels, sheet mm.
    pub anchor: DVec2,
    /// The box its text covers, sheet mm.
    pub rect: Rect,
    /// Its leader line, where it is written away from its object ([`Leader`]).
    pub leader: Option<Leader>,
    /// The text as written.
    pub(crate) placed: Placed,
}

/// A view as laid out.
#[derive(Debug, Clone, PartialEq)]
pub struct ViewLayout {
    /// The box of everything its figure draws (line widths and symbols included), sheet mm;
    /// `None` for an empty figure.
    pub drawn: Option<Rect>,
    /// The box of its caption.
    pub caption: Option<Rect>,
    /// The caption as written.
    pub(crate) caption_text: Option<Placed>,
}

/// A plate laid out: every placed text and every drawn item's box, sheet mm (y down).
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// The inner edge of the frame: everything is drawn inside it.
    pub frame: Rect,
    /// The main title block: nothing else is drawn over it.
    pub title_block: Rect,
    /// The rotated designation box in the frame's corner: nothing else is drawn over it.
    pub designation_box: Rect,
    /// The views, as [`Plate::views`].
    pub views: Vec<ViewLayout>,
    /// Every label of every view, in the order they are written.
    pub labels: Vec<PlacedLabel>,
    /// The boxes of the free text blocks, as [`Plate::texts`].
    pub texts: Vec<Rect>,
    /// The boxes of the tables (grid, title and texts), as [`Plate::tables`].
    pub tables: Vec<Rect>,
}

impl Layout {
    /// Every item's box on the sheet: the views' drawings and captions, the labels, the text
    /// blocks and the tables (the frame's title block and designation box are not items).
    pub fn boxes(&self) -> impl Iterator<Item = Rect> + '_ {
        let views = (self.views.iter()).flat_map(|v| v.drawn.into_iter().chain(v.caption));
        views
            .chain(self.labels.iter().map(|x| x.rect))
            .chain(self.texts.iter().copied())
            .chain(self.tables.iter().copied())
    }
}

/// Lay the plate out: its views' drawn boxes and captions, its text blocks and tables, and
/// every label placed (see the module documentation).
pub fn layout(plate: &Plate) -> Layout {
    let sheet = &plate.sheet;
    let outlines: Vec<Vec<Outline>> = plate.views.iter().map(view_outlines).collect();
    let views: Vec<ViewLayout> = plate
        .views
        .iter()
        .zip(&outlines)
        .map(|(v, o)| {
            let caption_text = caption(v);
            ViewLayout {
                drawn: drawn_bounds(o),
                caption: caption_text.as_ref().map(Placed::bounds),
                caption_text,
            }
        })
        .collect();
    let texts: Vec<Rect> = plate
        .texts
        .iter()
        .map(|b| {
            let lines = text_block_lines(b);
            Rect::around(lines.iter().flat_map(|p| corners(p.bounds())))
                .unwrap_or(Rect::new(b.at, b.at))
        })
        .collect();
    let tables: Vec<Rect> = plate
        .tables
        .iter()
        .map(|t| {
            let grid = Rect::new(t.at, t.at + t.size());
            table_marks(t)
                .iter()
                .filter_map(|m| match m {
                    Mark::Text(p) => Some(p.bounds()),
                    Mark::Path(..) => None,
                })
                .fold(grid, |r, b| r.union(&b))
        })
        .collect();
    let mut out = Layout {
        frame: sheet.frame().inflate(-Pen::MAIN.width * 0.5),
        title_block: sheet.title_block(),
        designation_box: sheet.designation_box(),
        views,
        labels: Vec::new(),
        texts,
        tables,
    };
    out.labels = Placer::new(&out, &outlines).place(plate);
    out
}

/// The outlines of everything a view draws, sheet mm.
pub(super) fn view_outlines(view: &View) -> Vec<Outline> {
    let map = Map::figure(view.origin);
    view.figure
        .steps
        .iter()
        .flat_map(|s| step_outlines(s, map))
        .collect()
}

/// The box of the outlines, grown by half the width of their lines.
fn drawn_bounds(outlines: &[Outline]) -> Option<Rect> {
    outlines
        .iter()
        .filter_map(|o| {
            let half = if o.main { Pen::MAIN } else { Pen::THIN }.width * 0.5;
            shape_box(&o.shape).map(|b| b.inflate(half))
        })
        .reduce(|a, b| a.union(&b))
}

fn shape_box(s: &Shape) -> Option<Rect> {
    match s {
        Shape::Line(a, b) => Rect::around([*a, *b]),
        Shape::Area(pts) => Rect::around(pts.iter().copied()),
    }
}

fn corners(r: Rect) -> [DVec2; 2] {
    [r.min, r.max]
}

/// A view's caption: centred under the figure's bounds, in the band kept for it.
fn caption(view: &View) -> Option<Placed> {
    let text = view.caption.as_ref()?;
    let (lo, hi) = view.figure.bounds()?;
    let bottom = view.to_sheet(DVec2::new((lo.x + hi.x) * 0.5, lo.y - view.caption_drop));
    let at = bottom + DVec2::new(0.0, CAPTION_BAND_MM - CAPTION_HEIGHT_MM);
    Some(Placed::centred(at, text, CAPTION_HEIGHT_MM, Align::Middle))
}

/// The lines of a text block, two text heights apart.
pub(crate) fn text_block_lines(block: &TextBlock) -> Vec<Placed> {
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

/// A label to place: one point's names (several for a joint label).
#[derive(Debug, Clone)]
struct Request {
    view: usize,
    steps: Vec<StepId>,
    names: Vec<String>,
    anchor: DVec2,
    /// Preferred direction on the sheet (unit, or zero: centred on the point).
    toward: DVec2,
    /// Least distance from the point to the text's box.
    gap: f64,
    /// The farthest the text's box may stand from the point ([`Label::within_mm`]).
    within: Option<f64>,
    /// The farthest the text's middle may stand left and right of the point
    /// ([`Label::column_mm`]).
    column: Option<[f64; 2]>,
    /// What it names: only names of points are joined.
    names_of: Names,
    /// The outlines of its own item (a label of an item is read as belonging to the line
    /// nearest to it), sheet mm; empty for a label of a point.
    own: Vec<Outline>,
}

impl Request {
    fn text(&self) -> String {
        self.names.join(JOINT_SEPARATOR)
    }
}

/// The tighter of two optional bounds (`least` of both where both bind, else the one that
/// does).
fn tighter<T>(a: Option<T>, b: Option<T>, least: impl Fn(T, T) -> T) -> Option<T> {
    match (a, b) {
        (Some(a), Some(b)) => Some(least(a, b)),
        (a, b) => a.or(b),
    }
}

/// A pole of a plan: written first in a joint label.
fn is_pole(name: &str) -> bool {
    matches!(plain(name).as_str(), "p" | "π")
}

/// A position number (`7`, `8′`) rather than a point's name: the two are not joined (the
/// crank pin at position 1 is `B` and `1`, not `1 ≡ B`).
fn is_number(name: &str) -> bool {
    plain(name).starts_with(|c: char| c.is_ascii_digit())
}

/// The labels of a view to place, coincident ones joined; and the fixed texts of its
/// dimensions, each clear of `lines` (the view's outlines) and of `texts` (the texts already
/// fixed on the sheet) where it can be.
fn requests(
    k: usize,
    view: &View,
    lines: &[Outline],
    texts: &[Rect],
) -> (Vec<Request>, Vec<PlacedLabel>) {
    let map = Map::figure(view.origin);
    let mut fixed = Vec::new();
    let mut single: Vec<Request> = Vec::new();
    for step in &view.figure.steps {
        let Some(Label {
            text,
            anchor,
            toward,
            within_mm,
            column_mm,
            names: names_of,
        }) = &step.label
        else {
            continue;
        };
        if let Item::Dimension { from, to, offset } = &step.item {
            let mut near: Vec<Rect> = texts.to_vec();
            near.extend(fixed.iter().map(|f: &PlacedLabel| f.rect));
            let dim = (*from, *to, *offset);
            let own = step_outlines(step, map);
            if let Some((placed, leader)) = dimension::placed(map, dim, text, (lines, &own), &near)
            {
                fixed.push(PlacedLabel {
                    view: k,
                    steps: vec![step.id],
                    text: text.clone(),
                    anchor: map.pt((*from + *to) * 0.5),
                    rect: placed.bounds(),
                    leader,
                    placed,
                });
            }
            continue;
        }
        let gap = match step.item {
            Item::Joint { .. } => LABEL_GAP_MM + JOINT_RADIUS_MM,
            _ => LABEL_GAP_MM,
        };
        // A vector drawn as the point at its tail (`short_vector`: an image nearer its tail
        // than the drafting resolution): the name of its head is written at that point
        // (`p ≡ b`).
        let anchor = match (names_of, short_vector(step)) {
            (Names::Point, Some(tail)) => tail,
            _ => *anchor,
        };
        let own = match names_of {
            Names::Point => Vec::new(),
            Names::Item => step_outlines(step, map),
        };
        single.push(Request {
            view: k,
            steps: vec![step.id],
            names: vec![text.clone()],
            anchor: map.pt(anchor),
            toward: map.dir(*toward).normalize_or_zero(),
            gap,
            within: *within_mm,
            column: *column_mm,
            names_of: *names_of,
            own,
        });
    }
    (join_coincident(single), fixed)
}

/// The length of `figure`'s lines inside the box `lo`–`hi` (figure mm, y up), mm (see
/// [`View::line_length_in`]).
pub(super) fn line_length_in(figure: &crate::construct::Figure, lo: DVec2, hi: DVec2) -> f64 {
    let map = Map::figure(DVec2::ZERO);
    // Sheet y runs down.
    let rect = Rect::new(DVec2::new(lo.x, -hi.y), DVec2::new(hi.x, -lo.y));
    figure
        .steps
        .iter()
        .flat_map(|s| step_outlines(s, map))
        .map(|o| match o.shape {
            Shape::Line(a, b) => clip::clipped_length(a, b, &rect),
            Shape::Area(_) => 0.0,
        })
        .sum()
}

/// The joint labels of `figure` (see [`View::joint_labels`]).
pub(super) fn joint_labels(
    figure: &crate::construct::Figure,
) -> Vec<(DVec2, String, DVec2, Vec<StepId>)> {
    let view = View {
        figure: figure.clone(),
        origin: DVec2::ZERO,
        caption: None,
        caption_drop: 0.0,
    };
    requests(0, &view, &[], &[])
        .0
        .into_iter()
        .filter(|r| r.names.len() > 1)
        .map(|r| {
            let text = r.text();
            let e = measure(&text, LABEL_HEIGHT_MM);
            let at = DVec2::new(r.anchor.x, -r.anchor.y);
            (at, text, e.max - e.min, r.steps)
        })
        .collect()
}

/// Join the labels of points whose points coincide (each within [`COINCIDENT_MM`] of every
/// other; names with names, position numbers with position numbers), keeping the figure's
/// order with the pole first; a name repeated at one point is written once. A label of an item
/// is never joined.
fn join_coincident(single: Vec<Request>) -> Vec<Request> {
    // Each label joins the first group (in the figure's order) whose every point lies within
    // `COINCIDENT_MM` of its own: no chain of near points joins two points farther apart.
    let mut joined: Vec<Request> = Vec::new();
    let mut members: Vec<Vec<DVec2>> = Vec::new();
    for r in single {
        let fits = |j: &Request, points: &Vec<DVec2>| {
            j.names_of == Names::Point
                && r.names_of == Names::Point
                && is_number(&j.names[0]) == is_number(&r.names[0])
                && points.iter().all(|p| p.distance(r.anchor) <= COINCIDENT_MM)
        };
        match joined.iter().zip(&members).position(|(j, m)| fits(j, m)) {
            None => {
                members.push(vec![r.anchor]);
                joined.push(r);
            }
            Some(at) => {
                members[at].push(r.anchor);
                let j = &mut joined[at];
                j.steps.extend(r.steps);
                j.gap = j.gap.max(r.gap);
                j.within = tighter(j.within, r.within, f64::min);
                j.column = tighter(j.column, r.column, |a, b| [a[0].min(b[0]), a[1].min(b[1])]);
                if j.toward == DVec2::ZERO {
                    j.toward = r.toward;
                }
                for name in r.names {
                    if !j.names.contains(&name) {
                        j.names.push(name);
                    }
                }
            }
        }
    }
    for j in &mut joined {
        if let Some(p) = j.names.iter().position(|s| is_pole(s)) {
            let pole = j.names.remove(p);
            j.names.insert(0, pole);
        }
    }
    joined
}

mod away;
mod candidates;
mod clip;
mod costs;
mod dimension;
mod leader;
mod misreadings;
mod phrase;
pub use dimension::struck_dimension_texts;
pub use leader::Leader;
mod place;
#[cfg(test)]
mod tests;

use place::Placer;
