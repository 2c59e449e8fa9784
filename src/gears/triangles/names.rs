//! Where a link's distribution line is named on the velocity triangles: beside the line, where
//! its name is clearest of the other lines. At its end, where the next link's line starts from
//! the pole's velocity, two names read as one point's («1 ≡ 2-3», PZ2); beside two lines that
//! run about 0,6 mm apart (PZ2's first example, 6 and 7) a name on the wrong side reads as the
//! other's.

use crate::geom::{DVec2, Segment};

/// The places tried along the line, as shares of its length from its faster end.
const ALONG: [f64; 5] = [0.2, 0.35, 0.5, 0.65, 0.8];

/// How far from the line a name's middle stands, mm: the label's gap and half its height.
const OUT_MM: f64 = 2.5;

/// A name's middle this far from every other line is clear of them, mm.
const CLEAR_MM: f64 = 6.0;

/// The anchor and the side of the name of the line `seg` (figure mm) among the `others` drawn
/// (the other links' lines, the poles' velocities): the first of the places [`ALONG`] it, on
/// the side away from the axis and then the other, whose name's middle ([`OUT_MM`] out) is
/// [`CLEAR_MM`] clear of every other line; where none is, the clearest. A link at rest (its
/// line on the axis, where the others start and cross): halfway, to its left.
pub(super) fn line_name((pa, pb): (DVec2, DVec2), others: &[(DVec2, DVec2)]) -> (DVec2, DVec2) {
    if pa.x == 0.0 && pb.x == 0.0 {
        return (0.5 * (pa + pb), DVec2::new(-1.0, 0.0));
    }
    let (top, low) = [(pa, pb), (pb, pa)][usize::from(pb.x.abs() >= pa.x.abs())];
    let across = (top - low).perp().normalize_or(DVec2::X);
    let away = across * (across.x * top.x).signum();
    let clear = |c: DVec2| {
        (others.iter())
            .map(|&(a, b)| Segment::new(a, b).distance_to(c))
            .fold(f64::INFINITY, f64::min)
    };
    let mut best = (f64::NEG_INFINITY, top, away);
    for t in ALONG {
        let at = top + (low - top) * t;
        for side in [away, -away] {
            let c = clear(at + side * OUT_MM);
            if c >= CLEAR_MM {
                return (at, side);
            }
            if c > best.0 {
                best = (c, at, side);
            }
        }
    }
    (best.1, best.2)
}
