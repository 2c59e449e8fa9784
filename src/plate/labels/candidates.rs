//! Where a label may go: the candidate boxes about its point, in order of preference.
//!
//! A label of a point is read as the point's only near it (issue 45: `B₂` 10 mm from its
//! dot is read as another point's), so its places are dense within [`POINT_REACH_MM`] —
//! rings [`NEAR_RING_MM`] apart in thirty-two directions — and only two rings lie beyond,
//! taken at a cost (`away::BEYOND`) when every near place is struck or covers a text. A
//! label of an item (a force, an arm, an angle) is read as the nearest line's, so besides
//! the rings about its anchor it is tried along its own line, on both sides of it, where no
//! other line of its view is nearer (issue 45: `R₁₋₂` on the `R₄₋₃` line).

use super::*;

/// The farthest a label of a point stands from its point (its box's nearest edge), mm,
/// where a place is found: its gap and six further rings 1 mm apart.
pub(crate) const POINT_REACH_MM: f64 = 7.0;
/// The spacing of the rings of a label kept near its point, mm.
pub(super) const NEAR_RING_MM: f64 = 1.0;
/// The places along an item's own line, as fractions of its length: the middle first.
const ALONG: [f64; 7] = [0.5, 0.38, 0.62, 0.26, 0.74, 0.14, 0.86];
/// Distances of the places along an item's line beyond the label's gap, mm.
const ALONG_OFFSETS_MM: [f64; 2] = [0.0, 1.5];
/// An item's line shorter than this gets no places along it (its rings cover it), mm.
const ALONG_MIN_MM: f64 = 6.0;

/// How far from its point a request's label is kept in dense rings: its own bound
/// ([`Request::within`]) or, for a label of a point, [`POINT_REACH_MM`]; `None` for a
/// label of an item.
pub(super) fn near_bound(r: &Request) -> Option<f64> {
    match (r.within, r.names_of) {
        (Some(w), _) => Some(w),
        (None, Names::Point) => Some(POINT_REACH_MM),
        (None, Names::Item) => None,
    }
}

/// The candidate boxes of a request in order of preference: centred on the point when it has
/// no preferred direction; then rings about it, the preferred direction first and the others
/// alternating about it — for a label of a point rings [`NEAR_RING_MM`] apart out to its
/// bound ([`near_bound`]) in thirty-two directions and, unless the bound is its own, two
/// rings [`SECOND_RING_MM`] apart beyond; for a label of an item sixteen directions at its
/// gap, then places along its own line, then rings [`SECOND_RING_MM`] apart.
pub(super) fn candidates(r: &Request, size: DVec2) -> Vec<Rect> {
    let half = size * 0.5;
    let mut out = Vec::with_capacity(RINGS * 2 * DIRECTIONS + 1);
    let start = if r.toward == DVec2::ZERO {
        out.push(Rect::new(r.anchor - half, r.anchor + half));
        -FRAC_PI_4
    } else {
        r.toward.y.atan2(r.toward.x)
    };
    let far = |from: f64| {
        (0..RINGS)
            .map(|k| r.gap + k as f64 * SECOND_RING_MM)
            .filter(move |g| *g > from + 1e-9)
    };
    let rings: Vec<(f64, usize)> = match near_bound(r) {
        Some(bound) => {
            let near = (0..)
                .map(|k| r.gap + f64::from(k) * NEAR_RING_MM)
                .take_while(|g| *g <= bound + 1e-9);
            let beyond: Vec<f64> = match r.within {
                Some(_) => Vec::new(),
                None => far(bound).take(2).collect(),
            };
            near.map(|g| (g, 2 * DIRECTIONS))
                .chain(beyond.into_iter().map(|g| (g, DIRECTIONS)))
                .collect()
        }
        None => far(f64::NEG_INFINITY).map(|g| (g, DIRECTIONS)).collect(),
    };
    for (i, (gap, directions)) in rings.into_iter().enumerate() {
        ring(r, half, start, (gap, directions), &mut out);
        if i == 0 && r.names_of == Names::Item {
            out.extend(along_own_line(r, half));
        }
    }
    // A label kept near its point by its own bound keeps only the places that near (all of
    // them when none is: its gap is wider than the bound).
    if let Some(within) = r.within {
        let near: Vec<Rect> = out
            .iter()
            .copied()
            .filter(|c| box_distance(c, r.anchor) <= within + 1e-9)
            .collect();
        if !near.is_empty() {
            out = near;
        }
    }
    // A label kept in its point's column keeps the places whose middle stands that near left
    // and right, or, with none, its place at the point itself or, where the column leaves
    // the point (a number beside the curve through its point), the column's nearest.
    // After them, its places in its own row across the column, left to right: a ring
    // place beside the point stands above or below the row, where a construction's
    // horizontal may run (cam-central's `6` on the projection of a chord step).
    if let Some([left, right]) = r.column {
        out.retain(|c| {
            let across = (c.min.x + c.max.x) * 0.5 - r.anchor.x;
            -left - 1e-9 <= across && across <= right + 1e-9
        });
        if out.is_empty() {
            let at = r.anchor + DVec2::new(0.0f64.max(-left).min(right), 0.0);
            out.push(Rect::new(at - half, at + half));
        }
        out.extend(in_row(r.anchor, half, [left, right]));
    }
    out
}

/// Places in a column's row: [`ROW_PLACES`] boxes of half size `half` centred on the row of
/// `anchor`, evenly from the column's left end (`left` mm left of it) to its right end.
fn in_row(anchor: DVec2, half: DVec2, [left, right]: [f64; 2]) -> impl Iterator<Item = Rect> {
    (0..ROW_PLACES).map(move |k| {
        let t = k as f64 / (ROW_PLACES - 1) as f64;
        let x = -left + t * (left + right);
        let at = anchor + DVec2::new(x, 0.0);
        Rect::new(at - half, at + half)
    })
}

/// Places tried in a column's row (see [`in_row`]).
const ROW_PLACES: usize = 7;

/// One ring of places `gap` from the point in `directions` directions from `start`, and a
/// joint label's four corner places.
fn ring(
    r: &Request,
    half: DVec2,
    start: f64,
    (gap, directions): (f64, usize),
    out: &mut Vec<Rect>,
) {
    let step = TAU / directions as f64;
    for k in 0..directions {
        // 0, +1, −1, +2, −2, …
        let turn = (k.div_ceil(2)) as f64 * if k % 2 == 1 { 1.0 } else { -1.0 };
        let t = DVec2::from_angle(start + turn * step);
        let c = r.anchor + t * (gap + edge_reach(half, t));
        out.push(Rect::new(c - half, c + half));
    }
    // A joint label (`d₅ ≡ e ≡ s₅`) is also written from a corner, as a draughtsman
    // writes it: its box in one quadrant of the point, clear of both lines through it
    // (the direction lines of a plan), the quadrant nearest the preferred side first.
    if r.names.len() > 1 {
        let mut quadrants =
            [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)].map(|(x, y)| DVec2::new(x, y));
        let pref = DVec2::from_angle(start);
        quadrants.sort_by(|a, b| b.dot(pref).total_cmp(&a.dot(pref)));
        for q in quadrants {
            let corner = r.anchor + q * gap;
            let far = corner + q * half * 2.0;
            out.push(Rect::new(corner.min(far), corner.max(far)));
        }
    }
}

/// From the centre of a box of half size `half` to its edge along the unit `t`.
fn edge_reach(half: DVec2, t: DVec2) -> f64 {
    [(half.x, t.x), (half.y, t.y)]
        .iter()
        .filter(|(_, c)| c.abs() > 1e-9)
        .map(|(h, c)| h / c.abs())
        .fold(f64::INFINITY, f64::min)
}

/// The places along a label's own item (its lines as drawn): at the fractions [`ALONG`] of
/// its length, beside it on either side (the preferred side first) at the label's gap and
/// [`ALONG_OFFSETS_MM`] further — as a draughtsman writes a force at the middle of its
/// arrow's side.
fn along_own_line(r: &Request, half: DVec2) -> Vec<Rect> {
    let pieces: Vec<(DVec2, DVec2)> = r
        .own
        .iter()
        .filter_map(|o| match o.shape {
            Shape::Line(a, b) if a.distance(b) > 1e-9 => Some((a, b)),
            _ => None,
        })
        .collect();
    let total: f64 = pieces.iter().map(|(a, b)| a.distance(*b)).sum();
    if total < ALONG_MIN_MM {
        return Vec::new();
    }
    let mut out = Vec::with_capacity(ALONG.len() * ALONG_OFFSETS_MM.len() * 2);
    for f in ALONG {
        let Some((p, d)) = at_length(&pieces, f * total) else {
            continue;
        };
        let n = d.perp();
        let sides = match n.dot(r.toward) >= 0.0 {
            true => [n, -n],
            false => [-n, n],
        };
        for off in ALONG_OFFSETS_MM {
            for t in sides {
                let c = p + t * (r.gap + off + edge_reach(half, t));
                out.push(Rect::new(c - half, c + half));
            }
        }
    }
    out
}

/// The point `s` along the chain of `pieces` and the unit direction there.
fn at_length(pieces: &[(DVec2, DVec2)], s: f64) -> Option<(DVec2, DVec2)> {
    let mut left = s;
    for &(a, b) in pieces {
        let l = a.distance(b);
        if left <= l {
            return Some((a.lerp(b, left / l), (b - a) / l));
        }
        left -= l;
    }
    let &(a, b) = pieces.last()?;
    Some((b, (b - a).normalize_or_zero()))
}

/// The distance from `p` to the nearest point of the box `r` (0 inside it), mm.
pub(super) fn box_distance(r: &Rect, p: DVec2) -> f64 {
    let d = (r.min - p).max(p - r.max).max(DVec2::ZERO);
    d.length()
}
