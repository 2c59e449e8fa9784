//! The rack against the wheel at one state of the rolling: its outline in runs inside the
//! blank, the points where it touches the envelope (where its normal passes through the
//! pole), and the crossing of the drawn fillet and involute that marks undercut, refined on
//! the traced pieces.

use super::rack::{Cutting, RackPiece};
use crate::geom::{pin_crossing, rotate, CurvePoint, DVec2, Segment};
use std::f64::consts::PI;

/// Points per rounding arc of a drawn rack outline.
const ARC_POINTS: usize = 24;

/// The rack's outline at the state `q` in the fixed frame (before turning into the wheel's
/// frame), in runs inside the blank (slightly enlarged, so the outline is seen to enter it).
fn outline_runs(c: &Cutting, q: f64) -> Vec<Vec<DVec2>> {
    let m = c.module;
    let sh = c.shape();
    let ta = c.rack.alpha.tan();
    let base = c.r() + c.x * m;
    let top = c.rack.ha * m;
    let mut pts = Vec::new();
    // Tool teeth centred at u₀ + kπm, k = −1, 0 (cutting both spaces beside the tooth).
    for k in [-1.0, 0.0] {
        let uc0 = c.u0() + k * PI * m;
        let flank = |v: f64| PI * m / 4.0 + v * ta;
        pts.push(DVec2::new(uc0 - flank(top), top));
        pts.push(DVec2::new(uc0 - flank(sh.vj), sh.vj));
        let (lc, rc) = (
            DVec2::new(uc0 - sh.uc, sh.vc),
            DVec2::new(uc0 + sh.uc, sh.vc),
        );
        let rho = c.rack.rho * m;
        let a0 = PI + c.rack.alpha;
        for i in 1..=ARC_POINTS {
            let a = a0 + (1.5 * PI - a0) * i as f64 / ARC_POINTS as f64;
            pts.push(lc + DVec2::from_angle(a) * rho);
        }
        for i in 0..ARC_POINTS {
            let a = 1.5 * PI + (2.0 * PI - c.rack.alpha - 1.5 * PI) * i as f64 / ARC_POINTS as f64;
            pts.push(rc + DVec2::from_angle(a) * rho);
        }
        pts.push(DVec2::new(uc0 + flank(sh.vj), sh.vj));
        pts.push(DVec2::new(uc0 + flank(top), top));
    }
    let fixed: Vec<DVec2> = pts
        .into_iter()
        .map(|p| DVec2::new(p.x + q, base + p.y))
        .collect();
    // Traced on the paper blank, whose edge is the tip circle (seed 002 PZ1, L259): every
    // run ends on r_a (the tool's own ends lie outside it), none in the air beside the
    // wheel. A run shorter than a thousandth of the module is the tool's root line grazing
    // r_a.
    let blank = crate::geom::Circle {
        center: DVec2::ZERO,
        radius: c.ra,
    };
    let mut runs = crate::geom::polyline_in_circle(&fixed, &blank);
    runs.retain(|r| r.windows(2).map(|w| w[0].distance(w[1])).sum::<f64>() > 1e-3 * m);
    runs
}

/// The points of the rack at the state `q` whose normal passes through the pole P, in the
/// fixed frame (the wheel turned back by q/r): on the left flank, the left rounding and the
/// tip line of the tool tooth at u₀, each where it is part of the tool and inside the blank.
pub(super) fn touching(c: &Cutting, q: f64) -> Vec<(RackPiece, DVec2)> {
    let m = c.module;
    let sh = c.shape();
    let alpha = c.rack.alpha;
    let base = c.r() + c.x * m;
    let p = DVec2::new(0.0, c.r());
    let u0 = c.u0();
    let mut out = Vec::new();
    let slack = 1e-12 * m;
    // The straight flank: the foot of the perpendicular from P.
    let f0 = DVec2::new(u0 - PI * m / 4.0 + q, base);
    let e = DVec2::new(-alpha.sin(), alpha.cos());
    let k = f0 + e * (p - f0).dot(e);
    let v = k.y - base;
    if v >= sh.vj - slack && v <= c.rack.ha * m && k.length() <= c.ra + slack {
        out.push((RackPiece::Flank, k));
    }
    // The rounding: its centre, the point on the ray from P through it.
    let centre = DVec2::new(u0 - sh.uc + q, base + sh.vc);
    if let Some(d) = (centre - p).try_normalize() {
        let a = d.y.atan2(d.x).rem_euclid(2.0 * PI);
        if a >= PI + alpha - 1e-12 && a <= 1.5 * PI + 1e-12 {
            let k = centre + d * (c.rack.rho * m);
            if k.length() <= c.ra + slack {
                out.push((RackPiece::Fillet, k));
            }
        }
    }
    // The tip line under P.
    if (q + u0).abs() <= sh.uc + slack {
        out.push((RackPiece::Root, DVec2::new(0.0, base + sh.vt)));
    }
    out
}

/// The rack's outline at the state `q` ([`outline_runs`]) turned into the wheel's frame and
/// drawn at `mu` (m per mm): its runs, sheet mm.
pub(super) fn drawn_outline(c: &Cutting, q: f64, mu: f64) -> Vec<Vec<DVec2>> {
    let turn = q / c.r();
    outline_runs(c, q)
        .into_iter()
        .map(|run| run.into_iter().map(|p| rotate(p, turn) / mu).collect())
        .collect()
}

/// The first crossing of polyline `a` (walked from its start) with polyline `b`: the point
/// and the indices of the segments of `a` and `b` that cross.
pub(super) fn polyline_crossing(a: &[DVec2], b: &[DVec2]) -> Option<(DVec2, usize, usize)> {
    for (i, wa) in a.windows(2).enumerate() {
        for (j, wb) in b.windows(2).enumerate() {
            if let Some(p) = Segment::new(wa[0], wa[1]).crossing(&Segment::new(wb[0], wb[1])) {
                // A shared end point (the tangential junction) is not a crossing.
                if (p - wa[0]).length() > 1e-12 && (p - wb[0]).length() > 1e-12 {
                    return Some((p, i, j));
                }
            }
        }
    }
    None
}

/// A state and the touching point of one piece there (wheel frame, m).
pub(super) type Traced = CurvePoint;

/// Pin the crossing of the fillet step `f` with the flank step `l`: set the rack at the
/// middle of each step, trace the touching points there, keep the halves that cross; until
/// the steps shrink to rounding ([`pin_crossing`]).
pub(super) fn refine(c: &Cutting, f: [Traced; 2], l: [Traced; 2]) -> Option<DVec2> {
    let at = |piece: RackPiece| {
        move |q: f64| {
            touching(c, q)
                .into_iter()
                .find(|(p, _)| *p == piece)
                .map(|(_, k)| rotate(k, q / c.r()))
        }
    };
    // Steps of 1e-10·m: their chords are the curves to ~1e-20·m, and shorter ones would
    // meet at the mercy of rounding (the fillet crosses the involute at a shallow angle).
    pin_crossing(
        (at(RackPiece::Fillet), at(RackPiece::Flank)),
        [f, l],
        80,
        1e-10 * c.module,
    )
}
