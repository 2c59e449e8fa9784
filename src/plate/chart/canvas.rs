//! The chart's drawing surface: lines, polylines, markers and texts appended to the SVG
//! document, and the placement of point labels.

use super::{BOTTOM, LEFT, POINT_H, RIGHT, TOP};
use crate::geom::DVec2;
use crate::plate::path::num;
use crate::plate::text::{approx_width, literal, Align, Placed};
use svg::node::element::{Circle, Element, Path, Polyline, Rectangle};
use svg::node::Blob;
use svg::{Document, Node};

/// The shape of a series' markers.
#[derive(Debug, Clone, Copy)]
pub(super) enum Marker {
    Circle,
    Square,
    Triangle,
    Diamond,
}

/// The chart's SVG document under construction, numbering the texts.
pub(super) struct Canvas {
    pub(super) doc: Document,
    pub(super) texts: usize,
}

impl Canvas {
    pub(super) fn line(&mut self, a: DVec2, b: DVec2, stroke: &str, width: f64) {
        let d = format!("M{} {}L{} {}", num(a.x), num(a.y), num(b.x), num(b.y));
        self.doc.append(
            Path::new()
                .set("d", d)
                .set("fill", "none")
                .set("stroke", stroke)
                .set("stroke-width", num(width)),
        );
    }

    pub(super) fn text(&mut self, placed: Placed) {
        self.texts += 1;
        let id = format!("chart-text-{}", self.texts);
        self.doc.append(Blob::new(placed.to_xml(&id)));
    }

    /// Plain text at `at`.
    pub(super) fn label(&mut self, at: DVec2, text: &str, height: f64, align: Align) {
        self.text(Placed::new(at, &literal(text), height, align));
    }

    pub(super) fn polyline(&mut self, pts: &[DVec2], colour: &str) {
        let points: Vec<String> = pts
            .iter()
            .map(|p| format!("{},{}", num(p.x), num(p.y)))
            .collect();
        self.doc.append(
            Polyline::new()
                .set("points", points.join(" "))
                .set("fill", "none")
                .set("stroke", colour)
                .set("stroke-width", num(0.35))
                .set("stroke-linejoin", "round"),
        );
    }

    pub(super) fn marker(&mut self, p: DVec2, marker: Marker, colour: &str) {
        let r = 0.9;
        let outline = |pts: &[(f64, f64)]| {
            let mut d = String::new();
            for (k, (x, y)) in pts.iter().enumerate() {
                d += &format!("{}{} {}", if k == 0 { 'M' } else { 'L' }, num(*x), num(*y));
            }
            Path::new().set("d", d + "Z")
        };
        let (x, y) = (p.x, p.y);
        let mut shape: Element = match marker {
            Marker::Circle => Circle::new()
                .set("cx", num(x))
                .set("cy", num(y))
                .set("r", num(r))
                .into(),
            Marker::Square => Rectangle::new()
                .set("x", num(x - r * 0.85))
                .set("y", num(y - r * 0.85))
                .set("width", num(r * 1.7))
                .set("height", num(r * 1.7))
                .into(),
            Marker::Triangle => outline(&[
                (x, y - r * 1.15),
                (x + r, y + r * 0.6),
                (x - r, y + r * 0.6),
            ])
            .into(),
            Marker::Diamond => {
                outline(&[(x, y - r * 1.2), (x + r, y), (x, y + r * 1.2), (x - r, y)]).into()
            }
        };
        shape.assign("fill", "#fff");
        shape.assign("stroke", colour);
        shape.assign("stroke-width", num(0.3));
        self.doc.append(shape);
    }
}

/// Places the labels of the points where they cover no marker and no other label.
pub(super) struct Labeller {
    /// Boxes already used, `(min, max)` in mm.
    taken: Vec<(DVec2, DVec2)>,
}

impl Labeller {
    /// Half the size of the box kept free around a marker, mm.
    const MARKER: f64 = 1.1;
    /// Gap between a point and its label, mm.
    const GAP: f64 = 1.3;

    /// A labeller with every marker's box taken.
    pub(super) fn around<'a>(points: impl Iterator<Item = &'a DVec2>) -> Self {
        let half = DVec2::splat(Self::MARKER);
        Self {
            taken: points.map(|&p| (p - half, p + half)).collect(),
        }
    }

    /// The label `text` (markup) of the point `p`: above right, below right, above left or
    /// below left, the first of these that is free and inside the plot area (above right
    /// when none is).
    pub(super) fn place(&mut self, p: DVec2, text: &str) -> Placed {
        let (w, h, g) = (approx_width(text, POINT_H), POINT_H, Self::GAP);
        let candidates = [
            (DVec2::new(p.x + g, p.y - g), Align::Start),
            (DVec2::new(p.x + g, p.y + g + h), Align::Start),
            (DVec2::new(p.x - g, p.y - g), Align::End),
            (DVec2::new(p.x - g, p.y + g + h), Align::End),
        ];
        let bbox = |(at, align): (DVec2, Align)| {
            let x0 = if align == Align::End { at.x - w } else { at.x };
            (DVec2::new(x0, at.y - h), DVec2::new(x0 + w, at.y))
        };
        let free = |b: &(DVec2, DVec2)| {
            b.0.x >= LEFT
                && b.1.x <= RIGHT
                && b.0.y >= TOP
                && b.1.y <= BOTTOM
                && self
                    .taken
                    .iter()
                    .all(|t| b.1.x <= t.0.x || b.0.x >= t.1.x || b.1.y <= t.0.y || b.0.y >= t.1.y)
        };
        let chosen = candidates
            .iter()
            .copied()
            .find(|&c| free(&bbox(c)))
            .unwrap_or(candidates[0]);
        self.taken.push(bbox(chosen));
        Placed::new(chosen.0, text, POINT_H, chosen.1)
    }
}
