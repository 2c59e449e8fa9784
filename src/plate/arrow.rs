//! How a vector is drawn: its line and its arrowhead, fitted to its length.

use super::items::stroke;
use super::path::{Map, PathData};
use super::style::{Mark, Paint, Pen};
use crate::construct::THIN_HEAD_MM;
use crate::geom::DVec2;

/// An arrowhead: length along the line and full width at its base, mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Arrow {
    pub(super) len: f64,
    width: f64,
}

impl Arrow {
    /// Arrowhead of a result vector (main line).
    pub(super) const MAIN: Arrow = Arrow {
        len: 4.0,
        width: 1.2,
    };
    /// Arrowhead of thin lines: dimensions, angle marks, construction vectors.
    pub(super) const THIN: Arrow = Arrow {
        len: THIN_HEAD_MM,
        width: 0.9,
    };

    pub(super) fn for_pen(pen: Pen) -> Arrow {
        if pen.is_main() {
            Arrow::MAIN
        } else {
            Arrow::THIN
        }
    }

    /// The filled head with its tip at `tip`, pointing along `dir` (any length); nothing for
    /// a zero direction.
    pub(super) fn head(self, map: Map, tip: DVec2, dir: DVec2) -> Option<Mark> {
        let u = dir.try_normalize()?;
        let mut d = PathData::new(map);
        d.polygon(&self.corners(tip, u));
        Mark::path(Paint::Solid, d)
    }

    /// The head of a vector `length` mm long: this one, or, on a vector shorter than it, one
    /// scaled down to the vector's length, so that its base does not overhang the tail.
    fn fitted(self, length: f64) -> Arrow {
        if length >= self.len {
            return self;
        }
        let k = length / self.len;
        Arrow {
            len: length,
            width: self.width * k,
        }
    }

    /// The head's triangle: the tip, then the two corners of the base (`u`: unit direction).
    pub(super) fn corners(self, tip: DVec2, u: DVec2) -> [DVec2; 3] {
        let base = tip - u * self.len;
        let side = u.perp() * (self.width * 0.5);
        [tip, base + side, base - side]
    }
}

/// A vector: the line stopped inside its arrowhead (so a thick line does not show past the
/// head's flanks), and the head.
pub(super) fn vector(
    map: Map,
    (pen, labelled): (Pen, bool),
    from: DVec2,
    to: DVec2,
    out: &mut Vec<Mark>,
) {
    let Some(u) = (to - from).try_normalize() else {
        return;
    };
    let (arrow, head_only) = vector_head(pen, labelled, from.distance(to));
    // An arc's arrowhead: its head whole, no line.
    let stop = if head_only {
        from
    } else {
        to - u * (arrow.len * 0.85)
    };
    out.extend(stroke(map, pen, |d| {
        d.segment(from, stop);
    }));
    out.extend(arrow.head(map, to, u));
}

/// The head of a vector `length` mm long drawn with `pen`, and whether it is an arc's arrowhead
/// (whole, no line: unlabelled, under [`DIRECTION_ONLY_MM`]); else fitted ([`Arrow::fitted`])
/// to the vector, or, for a labelled one (a plan's image, a force), to [`LABELLED_HEAD`] of
/// it.
pub(super) fn vector_head(pen: Pen, labelled: bool, length: f64) -> (Arrow, bool) {
    let arrow = Arrow::for_pen(pen);
    match (labelled, length >= DIRECTION_ONLY_MM) {
        (true, _) => (arrow.fitted(length * LABELLED_HEAD), false),
        (false, true) => (arrow.fitted(length), false),
        (false, false) => (arrow, true),
    }
}

/// The most of a labelled vector its head takes: a line as long as the head shows which way
/// it runs and where it starts (the tangent's `pa`, 3,2 mm, was drawn all head with `c`
/// inside it, issue 45).
const LABELLED_HEAD: f64 = 0.5;

/// An unlabelled vector shorter than this gives only its direction: an arc's arrowhead (the
/// cam's ω₁, 0,1 mm). A longer one is a vector (a train's velocity of a pole 2,5 mm long,
/// whose whole 4 mm head stood out behind the axis of heights), mm.
const DIRECTION_ONLY_MM: f64 = 1.0;
