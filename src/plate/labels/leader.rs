//! A leader line (ГОСТ 2.316, линия-выноска): a label that finds no clear place at its object
//! — a point inside a fan of spokes, a force among the lever's rays — is written further out
//! on a shelf, and a thin line runs from the shelf's near end to its object (the point
//! itself, or the point of its item's line nearest the label's anchor). A draughtsman takes it
//! only where the label written beside its object would be read as another's: the placer
//! tries the leader's places after every label has its place, for those whose place is beyond
//! their reach or nearer another line than their own, and keeps the leader where it costs less.

use super::*;
use crate::geom::Segment;

/// A label's leader: from its object to the shelf under its text, and along the shelf.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Leader {
    /// Its object's point: the labelled point, or the point of the labelled item's line it
    /// ends on (with a dot), sheet mm.
    pub to: DVec2,
    /// Where the drawn line starts: at the item's line, or a label's gap short of its point
    /// (a leader does not strike through the point it names).
    pub from: DVec2,
    /// True when it ends on an item's line, with a dot.
    pub dot: bool,
    /// The shelf's end the line from the object comes to.
    pub knee: DVec2,
    /// The shelf's other end.
    pub end: DVec2,
    /// A dimension line run on past its arrow under its text (ГОСТ 2.307), drawn as a shelf
    /// from the arrow's tip: no line comes to it from an object (`from` = `knee` = `to`).
    pub run_on: bool,
}

impl Leader {
    /// Its two pieces as drawn: from the object to the knee, and the shelf.
    pub fn pieces(&self) -> [Segment; 2] {
        [
            Segment::new(self.from, self.knee),
            Segment::new(self.knee, self.end),
        ]
    }

    /// Its marks as drawn: the thin line through the knee to the shelf's end, then its dot
    /// on an item's line (where it ends on one).
    pub(crate) fn marks(&self) -> Vec<Mark> {
        use crate::plate::path::PathData;
        use crate::plate::style::Paint;
        let mut line = PathData::new(Map::SHEET);
        line.polyline(&[self.from, self.knee, self.end]);
        let mut out: Vec<Mark> = Mark::path(Paint::Stroke(Pen::THIN), line)
            .into_iter()
            .collect();
        if self.dot {
            let mut dot = PathData::new(Map::SHEET);
            dot.circle(self.to, LEADER_DOT_MM);
            out.extend(Mark::path(Paint::Solid, dot));
        }
        out
    }
}

/// The radius of a leader's dot on an item's line, mm.
const LEADER_DOT_MM: f64 = 0.35;

/// Between the text's box and its shelf, mm.
const SHELF_GAP_MM: f64 = 0.6;
/// The shelf runs this far past the text at either end, mm.
const SHELF_OVERHANG_MM: f64 = 0.5;
/// Lengths of the line from the object to the shelf tried, mm: the shortest first.
const LENGTHS_MM: [f64; 5] = [6.0, 9.0, 12.0, 16.0, 20.0];
/// Its angles from the shelf tried, degrees: never along it (ГОСТ 2.316 — not parallel to the
/// lines it crosses where it can help it, and a leader along its shelf reads as one line).
const ANGLES_DEG: [f64; 9] = [45.0, 60.0, 30.0, 75.0, 52.5, 37.5, 67.5, 22.5, 82.5];

/// Where a label's leader touches its object: its point, or, for a label of an item, the
/// point of the item's lines nearest its anchor.
pub(super) fn target(r: &Request) -> DVec2 {
    r.own
        .iter()
        .filter_map(|o| match o.shape {
            Shape::Line(a, b) => Some(Segment::new(a, b).closest(r.anchor)),
            Shape::Area(_) => None,
        })
        .min_by(|a, b| a.distance(r.anchor).total_cmp(&b.distance(r.anchor)))
        .unwrap_or(r.anchor)
}

/// The places of a label of box size `size` on a leader, in order of preference: the
/// shortest leader first, the quadrant of the preferred direction first.
pub(super) fn candidates(r: &Request, size: DVec2) -> Vec<(Rect, Leader)> {
    let to = target(r);
    let dot = r.names_of == Names::Item;
    let mut quadrants =
        [(1.0, -1.0), (-1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)].map(|(x, y)| DVec2::new(x, y));
    if r.toward != DVec2::ZERO {
        quadrants.sort_by(|a, b| b.dot(r.toward).total_cmp(&a.dot(r.toward)));
    }
    let mut out = Vec::with_capacity(LENGTHS_MM.len() * ANGLES_DEG.len() * 4);
    for length in LENGTHS_MM {
        for q in quadrants {
            for deg in ANGLES_DEG {
                let (s, c) = deg.to_radians().sin_cos();
                let knee = to + DVec2::new(q.x * c, q.y * s) * length;
                let from = match dot {
                    true => to,
                    false => to + (knee - to) * (r.gap / length),
                };
                out.push(on_shelf(
                    Leader {
                        to,
                        from,
                        dot,
                        knee,
                        end: knee,
                        run_on: false,
                    },
                    q.x,
                    size,
                ));
            }
        }
    }
    out
}

/// The text of box size `size` on the leader's shelf from its knee towards `side` (+1 right,
/// −1 left).
fn on_shelf(leader: Leader, side: f64, size: DVec2) -> (Rect, Leader) {
    let knee = leader.knee;
    let shelf = size.x + 2.0 * SHELF_OVERHANG_MM;
    let end = knee + DVec2::new(side * shelf, 0.0);
    let left = knee.x.min(end.x) + SHELF_OVERHANG_MM;
    let bottom = knee.y - SHELF_GAP_MM;
    let rect = Rect::new(
        DVec2::new(left, bottom - size.y),
        DVec2::new(left + size.x, bottom),
    );
    (rect, Leader { end, ..leader })
}

/// Cost of a leader at all: less than a label beyond its reach or nearer another line
/// (`away::BEYOND`, `away::WRONG_LINE`), more than a clear place at the object; and per mm
/// of the line from the object.
const LEADER: f64 = 12.0;
const LEADER_MM: f64 = 0.5;
/// Cost per rank of a place on a leader: its order only breaks ties (its length is paid by
/// [`LEADER_MM`]).
pub(super) const RANK: f64 = 0.01;
/// Cost of the leader or its shelf crossing a main line of the drawing, a thin one.
const CROSS_MAIN: f64 = 6.0;
const CROSS_THIN: f64 = 3.0;
/// Cost of crossing another leader; of passing this near another label's point (mm), which
/// costs what covering it does (`costs::OVER_POINT`): the leader would be read as that
/// point's. Crossing a text costs what covering it does (`costs::OVER_TEXT`).
const OVER_LEADER: f64 = 200.0;
const PAST_POINT_MM: f64 = 1.0;
/// Lines through the object itself are not crossings: within this of it, mm.
const AT_OBJECT_MM: f64 = 1.0;
/// A leader (or its shelf) within this of a line of the drawing and within [`ALONG_DEG`] of
/// its direction runs along it and is lost in it, mm: it is sampled every [`ALONG_STEP_MM`]
/// from [`ALONG_FROM_MM`] of its object on (where the lines through a point converge), and
/// each sample on such a line costs [`ALONG_LINE`].
const ALONG_MM: f64 = 1.0;
const ALONG_DEG: f64 = 20.0;
const ALONG_STEP_MM: f64 = 0.5;
const ALONG_FROM_MM: f64 = 1.5;
const ALONG_LINE: f64 = 10.0;

/// A text this near under a shelf, across from it over at least [`UNDER_SHELF_ACROSS`] of
/// the shorter of the two, reads as the denominator of a fraction whose bar is the shelf
/// (the flat rocker's position number `0` on a shelf right over `O₂`, issue 45), mm; and
/// what that costs (`place::Placer::lift_fractions`), as a leader passing another label's
/// point. A text beside the shelf's end, across from a corner of it, reads as its own.
const UNDER_SHELF_MM: f64 = 2.5;
const UNDER_SHELF_ACROSS: f64 = 0.5;
pub(super) const UNDER_SHELF: f64 = costs::OVER_POINT;

/// Where a text right under the shelf of `l` stands (see [`under_shelf`]): the band
/// [`UNDER_SHELF_MM`] deep under it.
pub(super) fn under_shelf_band(l: &Leader) -> Rect {
    let (lo, hi) = (l.knee.x.min(l.end.x), l.knee.x.max(l.end.x));
    Rect::new(
        DVec2::new(lo, l.knee.y),
        DVec2::new(hi, l.knee.y + UNDER_SHELF_MM),
    )
}

/// Whether the text box `t` stands right under the shelf of `l` (see [`UNDER_SHELF_MM`]).
pub(super) fn under_shelf(l: &Leader, t: &Rect) -> bool {
    let (lo, hi) = (l.knee.x.min(l.end.x), l.knee.x.max(l.end.x));
    let across = hi.min(t.max.x) - lo.max(t.min.x);
    let shorter = (hi - lo).min(t.max.x - t.min.x);
    let below = t.min.y - l.knee.y;
    across > UNDER_SHELF_ACROSS * shorter && (0.0..=UNDER_SHELF_MM).contains(&below)
}

/// What the leader `l` of a label at `rect` costs among the drawing's `lines`, the other
/// labels' `points`, the other `texts` and the other `leaders`.
pub(super) fn cost(
    l: &Leader,
    rect: &Rect,
    lines: &[(Rect, &Outline)],
    points: &[DVec2],
    texts: &[Rect],
    leaders: &[Leader],
) -> f64 {
    let [line, shelf] = l.pieces();
    let mut cost = LEADER + LEADER_MM * line.length();
    // A line whose box stays clear of the leader's crosses it nowhere.
    let reach = Rect::around([line.from, line.to, shelf.from, shelf.to]);
    let near = |b: &Rect| reach.is_some_and(|r| r.touches(b));
    for (_, o) in lines.iter().filter(|(b, _)| near(b)) {
        let Shape::Line(a, b) = o.shape else { continue };
        let other = Segment::new(a, b);
        for piece in [&line, &shelf] {
            if piece
                .crossing(&other)
                .is_some_and(|p| p.distance(l.to) > AT_OBJECT_MM)
            {
                cost += if o.main { CROSS_MAIN } else { CROSS_THIN };
            }
        }
    }
    cost +=
        ALONG_LINE * (along_lines(&line, l.to, lines) + along_lines(&shelf, l.to, lines)) as f64;
    for p in points {
        if line.distance_to(*p) < PAST_POINT_MM {
            cost += costs::OVER_POINT;
        }
    }
    for t in texts {
        if [&line, &shelf]
            .iter()
            .any(|s| clip::clipped_length(s.from, s.to, t) > 0.0)
        {
            cost += costs::OVER_TEXT;
        }
    }
    for other in leaders {
        let crossed = runs_through(other, rect)
            || (other.pieces().iter())
                .any(|o| [&line, &shelf].iter().any(|s| s.crossing(o).is_some()));
        if crossed {
            cost += OVER_LEADER;
        }
    }
    cost
}

/// Whether the leader `l` (its line or its shelf) runs through the box `rect`.
pub(super) fn runs_through(l: &Leader, rect: &Rect) -> bool {
    (l.pieces().iter()).any(|o| clip::clipped_length(o.from, o.to, rect) > 0.0)
}

/// How many samples of `piece` beyond [`ALONG_FROM_MM`] of the object `to` lie within
/// [`ALONG_MM`] of a line of the drawing running within [`ALONG_DEG`] of its direction.
fn along_lines(piece: &Segment, to: DVec2, lines: &[(Rect, &Outline)]) -> usize {
    let d = (piece.to - piece.from).normalize_or_zero();
    // A line whose box is farther than ALONG_MM from the piece's runs beside it nowhere.
    let reach = Rect::around([piece.from, piece.to]).map(|r| r.inflate(ALONG_MM));
    let beside: Vec<Segment> = lines
        .iter()
        .filter(|(b, _)| reach.is_some_and(|r| r.touches(b)))
        .filter_map(|(_, o)| match o.shape {
            Shape::Line(a, b) => Some(Segment::new(a, b)),
            Shape::Area(_) => None,
        })
        .filter(|s| {
            let e = (s.to - s.from).normalize_or_zero();
            e != DVec2::ZERO && e.perp_dot(d).abs() < ALONG_DEG.to_radians().sin()
        })
        .collect();
    let n = (piece.length() / ALONG_STEP_MM).floor() as usize;
    (0..=n)
        .map(|k| piece.eval(k as f64 / n.max(1) as f64))
        .filter(|p| p.distance(to) > ALONG_FROM_MM)
        .filter(|p| beside.iter().any(|s| s.distance_to(*p) < ALONG_MM))
        .count()
}
