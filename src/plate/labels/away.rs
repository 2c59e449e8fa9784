//! What a label standing away from its object costs the placer: a label of a point beyond
//! its reach, nearer another labelled point or past lines from it; a label of an item beyond
//! its reach from its line, nearer another line, or farther from it than another text is
//! (issue 45).

use super::candidates::{box_distance, POINT_REACH_MM};
use super::clip::{own_distance, rect_segment_distance};
use super::phrase;
use super::place::{Job, STRUCK, THIN_LINE};
use super::*;
use crate::geom::Segment;

/// Cost of a label of an item (a force, an arm) nearer to another line of its view than to
/// its own, or of a point nearer another labelled point: it would be read as that line's or
/// that point's (issue 45); plus [`WRONG_LINE_MM`] per mm. More
/// than a line grazing the label's corner, less than a line striking through it
/// ([`STRUCK`] and `place::MAIN_LINE` over a millimetre): a struck label cannot be read at
/// all.
const WRONG_LINE: f64 = 30.0;
const WRONG_LINE_MM: f64 = 15.0;
/// Cost of a label of a point standing further than [`POINT_REACH_MM`] from its point: it
/// would be read as another point's (issue 45); plus [`BEYOND_MM`] per mm beyond. As
/// [`WRONG_LINE`], less than a line striking through the label.
const BEYOND: f64 = 30.0;
const BEYOND_MM: f64 = 15.0;
/// The farthest a label of an item (a force, an arm) stands from its own line before it
/// costs [`BEYOND`] (and [`BEYOND_MM`] per mm beyond), mm: as far as a point's label
/// ([`POINT_REACH_MM`]). Nearer than every other line is not enough: a label 12 mm under an
/// arrow, with nothing else near, is read as nobody's (issue 45: the lever's `F_и5`).
const ITEM_REACH_MM: f64 = POINT_REACH_MM;
/// The most a label away from its object costs ([`WRONG_LINE`], [`BEYOND`]): what a thin
/// line striking through 2 mm of it costs (a main one through 1 mm), so that a label struck
/// through stays the worst (`h₄` on the V engine's lever struck by an arm 3,8 mm rather
/// than written 2 mm nearer another arm than its own).
const AWAY_MAX: f64 = STRUCK + 2.0 * THIN_LINE;

/// A label of an item counts as nearer another line only when it is this much nearer, mm.
pub(crate) const NEARER_MM: f64 = 0.5;

/// `cost` and what a label at `rect` costs for standing away from its object: a label of a
/// point beyond [`POINT_REACH_MM`] from it, nearer another labelled point, of any view (the
/// position number "8" written nearer point 9, issue 45), or past lines from it
/// ([`lines_between`]); a label of an item beyond [`ITEM_REACH_MM`] from its own line,
/// nearer another line, of any view, than its own (nothing at its object), or farther from
/// it than one of the other `texts` ([`outneared`]).
pub(super) fn away(job: &Job, rect: &Rect, texts: &[Rect], mut cost: f64) -> f64 {
    cost += over_rival(job, rect);
    if job.request.names_of == Names::Point {
        let own = box_distance(rect, job.request.anchor);
        let rival = (job.points.iter())
            .map(|p| box_distance(rect, *p))
            .fold(f64::INFINITY, f64::min);
        cost += off_object(own, POINT_REACH_MM, rival);
        let past = lines_between(job, rect);
        if past > 0 {
            cost += (WRONG_LINE * past as f64).min(AWAY_MAX);
        }
    }
    if let Some(own) = own_distance(&job.request.own, rect) {
        let rival = (job.rivals.iter())
            .map(|(a, b)| rect_segment_distance(rect, *a, *b))
            .fold(f64::INFINITY, f64::min);
        cost += off_object(own, ITEM_REACH_MM, rival) + outneared(job, own, texts);
    }
    cost
}

/// What a label `own` mm from its object costs, its reach `reach` and the nearest other
/// labelled point or line `rival` mm from it: [`BEYOND`] past its reach, [`WRONG_LINE`]
/// nearer the rival, each more per mm and at most [`AWAY_MAX`].
fn off_object(own: f64, reach: f64, rival: f64) -> f64 {
    let mut cost = 0.0;
    let beyond = own - reach;
    if beyond > 1e-9 {
        cost += (BEYOND + BEYOND_MM * beyond).min(AWAY_MAX);
    }
    if rival + NEARER_MM < own {
        cost += (WRONG_LINE + WRONG_LINE_MM * (own - rival)).min(AWAY_MAX);
    }
    cost
}

/// Another text this much nearer a label's item than the label is read as the item's, mm
/// (the shaper's `F_и3` 1,8 mm from the arrow of `R₂₋₃`, written 4,3 mm from it, issue 45).
const OUTNEARED_MM: f64 = 2.0;

/// What a label of an item `mine` mm from it costs when one of the other `texts` stands
/// nearer its item by more than [`OUTNEARED_MM`]: [`WRONG_LINE`], as a label nearer another
/// line.
fn outneared(job: &Job, mine: f64, texts: &[Rect]) -> f64 {
    let own = &job.request.own;
    let nearer = |t: &Rect| own_distance(own, t).is_some_and(|d| d + OUTNEARED_MM < mine);
    match texts.iter().any(nearer) {
        true => WRONG_LINE,
        false => 0.0,
    }
}

/// A line this near a labelled point runs through it as the drawing reads (a label keeps
/// 1 mm from its point), mm: the lines meeting at a point do not part it from its label.
const THROUGH_MM: f64 = 1.0;

/// How many lines of the views run between a point and its label at `rect`: those not through
/// the point ([`THROUGH_MM`]) crossing the way from the point to the box's nearest point. A
/// label past a line is read as what lies on its side (the tangent's `c`, on `pa`, written
/// right of `pb`; the six-bar's `s₄` beyond `bc`, issue 45).
pub(super) fn lines_between(job: &Job, rect: &Rect) -> usize {
    let p = job.request.anchor;
    let q = p.clamp(rect.min, rect.max);
    let reach = Segment::new(p, q);
    let between = |o: &Outline| match o.shape {
        Shape::Line(a, b) => {
            let line = Segment::new(a, b);
            line.distance_to(p) > THROUGH_MM && reach.crossing(&line).is_some()
        }
        Shape::Area(_) => false,
    };
    job.lines.iter().filter(|(_, o)| between(o)).count()
}

/// What a chain of a point's names at `rect` costs for standing over another labelled
/// point no farther than its own: a point right under (or over, or beside) the chain and
/// near it is read as the one its name there is (the gear train's «0 ≡ 5» with its «5» over
/// H's intercept, its own point under «≡»). A single name is placed by its distances alone
/// ([`away`]): among a crowd of points every place near its own faces another.
fn over_rival(job: &Job, rect: &Rect) -> f64 {
    if !phrase::is_chain(&job.text) {
        return 0.0;
    }
    let own = box_distance(rect, job.request.anchor);
    let facing = |p: &DVec2| {
        let across =
            (p.x >= rect.min.x && p.x <= rect.max.x) || (p.y >= rect.min.y && p.y <= rect.max.y);
        let d = box_distance(rect, *p);
        across && d <= POINT_REACH_MM && d <= own + NEARER_MM
    };
    if job.points.iter().any(facing) {
        WRONG_LINE
    } else {
        0.0
    }
}
