//! What a step draws: a point, a pair, a line, a curve, a vector, a slider, a guide, a
//! dimension, an angle mark, a text or a hatched region, in figure millimetres (y up).

use crate::geom::{curve, Arc, Circle, DVec2, Segment, Side};

/// What a step draws, in figure millimetres (y up).
#[derive(Debug, Clone, PartialEq)]
pub enum Item {
    /// A marked point (a small dot).
    Point(DVec2),
    /// A revolute pair: a small circle; `fixed` adds the ground support symbol.
    Joint {
        /// Centre of the pair.
        at: DVec2,
        /// Attached to the frame.
        fixed: bool,
    },
    /// A straight piece: a link, a chord, a construction line.
    Segment(Segment),
    /// A full circle.
    Circle(Circle),
    /// An arc (compass notch, angle mark).
    Arc(Arc),
    /// A polyline through points.
    Polyline {
        /// Vertices.
        points: Vec<DVec2>,
        /// Join the last point to the first.
        closed: bool,
    },
    /// A smooth curve through points (trajectories, diagram curves).
    Curve {
        /// Points the curve passes through, in order.
        points: Vec<DVec2>,
        /// A closed curve.
        closed: bool,
    },
    /// A curve given piece by piece as cubic Bézier pieces from `start`, each its two
    /// control points and its end: the French curve between points whose tangents the
    /// construction knows (a cam's profile by inversion), drawn as it was computed.
    Bezier {
        /// Where the first piece starts.
        start: DVec2,
        /// The pieces: two control points and the end.
        pieces: Vec<[DVec2; 3]>,
        /// The last piece ends at `start`.
        closed: bool,
    },
    /// An arrowed vector (plans, forces).
    Vector {
        /// Tail.
        from: DVec2,
        /// Head.
        to: DVec2,
    },
    /// A slider block centred at `at`, its long side along `angle` (radians).
    Slider {
        /// Centre.
        at: DVec2,
        /// Direction of sliding.
        angle: f64,
    },
    /// A fixed guide: the line piece with hatching on one side.
    Guide {
        /// The guide line piece.
        segment: Segment,
        /// Side of `segment` (from → to) that carries the hatching.
        hatch: Side,
    },
    /// A linear dimension between two points, its line offset by `offset` mm to the left
    /// of `from → to`; the label is the dimension text.
    Dimension {
        /// First point.
        from: DVec2,
        /// Second point.
        to: DVec2,
        /// Offset of the dimension line, mm (positive: left of from → to).
        offset: f64,
    },
    /// An angle mark: arc with arrows at both ends; the label is the angle's name.
    Angle(Arc),
    /// A moment (a couple): an arc with one arrowhead, at its end, so that the sweep's sign
    /// is the sense of rotation; the label is the moment's name.
    Moment(Arc),
    /// Free text anchored at a point (the label carries the text).
    Text(DVec2),
    /// A region hatched with parallel thin lines (ГОСТ 2.306: a section of a part, a zone of
    /// a diagram), drawn as [`crate::geom::hatch`] strokes it; one step, so that a CAD
    /// drawing can hold it as one patterned hatch.
    Hatching {
        /// The closed outline (even-odd inside).
        outline: Vec<DVec2>,
        /// The lines' spacing, mm.
        spacing: f64,
        /// The lines' angle from +x, radians.
        angle: f64,
    },
}

/// The room a dimension's text takes beside its line, mm: the gap and a 3,5 mm label with
/// its subscript (`plate::dimension` writes it there).
pub const DIMENSION_TEXT_ROOM_MM: f64 = 6.5;

/// Chords of each piece of a smooth curve that stand for it where a drawing tests a place
/// against its lines ([`Item::straight_pieces`]).
pub const CURVE_CHORDS: usize = 8;

/// The length of a thin [`Item::Vector`]'s arrowhead (a construction's, a dimension's), mm: a
/// thin vector shorter than this is all head.
pub const THIN_HEAD_MM: f64 = 3.0;

impl Item {
    /// A slider block's half length along its slide and half width across it, mm: the block
    /// is drawn 10 × 6 mm whatever the scale.
    pub const SLIDER_HALF_MM: (f64, f64) = (5.0, 3.0);

    /// Each point that bounds what the item draws, mm, to `add`: a curve by its points (an
    /// arc by 17 along it, a Bézier by its control points, within whose hull it lies), a
    /// dimension by its line, a symbol by its centre.
    pub fn bounding_points(&self, mut add: impl FnMut(DVec2)) {
        match self {
            Item::Point(p) | Item::Text(p) => add(*p),
            Item::Joint { at, .. } | Item::Slider { at, .. } => add(*at),
            Item::Segment(seg) | Item::Guide { segment: seg, .. } => {
                add(seg.from);
                add(seg.to)
            }
            Item::Circle(c) => {
                add(c.center - DVec2::splat(c.radius));
                add(c.center + DVec2::splat(c.radius))
            }
            Item::Arc(a) | Item::Angle(a) | Item::Moment(a) => {
                for i in 0..=16 {
                    add(a.eval(f64::from(i) / 16.0));
                }
            }
            Item::Polyline { points, .. }
            | Item::Curve { points, .. }
            | Item::Hatching {
                outline: points, ..
            } => points.iter().for_each(|p| add(*p)),
            Item::Bezier { start, pieces, .. } => {
                add(*start);
                pieces.iter().flatten().for_each(|p| add(*p))
            }
            Item::Vector { from, to } => {
                add(*from);
                add(*to)
            }
            Item::Dimension { from, to, offset } => {
                // The line, and its text over it as read (left to right, bottom to top:
                // ГОСТ 2.307), y up.
                let u = (*to - *from).normalize_or_zero();
                let n = u.perp() * *offset;
                let read = if u.x > 0.0 || (u.x == 0.0 && u.y > 0.0) {
                    u
                } else {
                    -u
                };
                let over = read.perp() * DIMENSION_TEXT_ROOM_MM;
                for p in [*from + n, *to + n] {
                    add(p);
                    add(p + over);
                }
            }
        }
    }

    /// The straight pieces of the lines the item draws, mm, each to `add`: a segment, a
    /// vector, a dimension's line, a polyline's sides (a closed one's back to its first
    /// point), a smooth curve as drawn through its points ([`CURVE_CHORDS`] chords a piece);
    /// none of a symbol, a text, a circle, an arc or a hatching. What a drawing tests a place
    /// against before it puts its own mark there.
    pub fn straight_pieces(&self, mut add: impl FnMut(DVec2, DVec2)) {
        let mut sides = |points: &[DVec2]| points.windows(2).for_each(|w| add(w[0], w[1]));
        match self {
            Item::Segment(seg) => sides(&[seg.from, seg.to]),
            Item::Vector { from, to } => sides(&[*from, *to]),
            Item::Dimension { from, to, offset } => {
                let n = (*to - *from).normalize_or_zero().perp() * *offset;
                sides(&[*from + n, *to + n])
            }
            Item::Polyline { points, closed } => {
                sides(points);
                if let (true, Some(a), Some(b)) = (*closed, points.last(), points.first()) {
                    sides(&[*a, *b])
                }
            }
            Item::Curve { points, closed } => sides(&curve::points(points, *closed, CURVE_CHORDS)),
            _ => {}
        }
    }

    /// The strokes a hatching draws (none for any other item, or an outline the recorder
    /// would have refused: [`crate::construct::Recorder::hatching`]).
    pub fn hatch_strokes(&self) -> Vec<Segment> {
        match self {
            Item::Hatching {
                outline,
                spacing,
                angle,
            } => crate::geom::hatch(outline, *spacing, *angle).unwrap_or_default(),
            _ => Vec::new(),
        }
    }
}
