//! The pressure (transmission) angle read off the profile drawing: at every drawn point of
//! the pitch curve its tangent, read through its neighbours, and the normal to it against
//! the follower's path in its inverted position.
//!
//! The tangent is read to the chord method's own (second-order) error everywhere, which
//! takes knowing where the law's S″ jumps: a chord that spans such a point takes one
//! curvature on one side and another on the other, and is only first order there (≈ 1° on
//! the seed's cam at φ = 113,6° and 2° at its «+ −» law's middle — a step in γ(φ) where the
//! law, and γ, are smooth). So:
//! - inside a phase, the chord through the neighbours where they lie equally far, else the
//!   tangent of the parabola through the three (in φ);
//! - on a break of the law inside a phase ([`Law::breaks`]), the mean of the two parabolas'
//!   tangents, one through the point and its two neighbours before, one through those after;
//! - at a phase's end where the law's S′ is continuous (no rigid shock: S′ = 0 there), the
//!   drawn curve runs on along the dwell arc about O₁ through the point — the French curve
//!   is laid tangent to it, as the pitch point moves only round O₁ while S stands — so the
//!   normal is the radius O₁B_i, the very line the dwell's angle is read along. Reading it
//!   through a dwell point at the exact S = h (or 0) instead, or through the phase's own
//!   points alone, tilts it by the drawn S's error over one step: 1,4–2,7° at drafting
//!   0,5 mm on the seed's cam, a step in γ(φ) at every dwell where γ is continuous;
//! - at a phase's end where S′ jumps (a rigid shock), the phase's own parabola through the
//!   end and its two next points — a velocity jump is then drawn as the jump it is, not
//!   smeared across a chord onto the dwell.

use super::follower::jay;
use super::law::Shock;
use super::motion::{on_break, Point};
use super::CamSpec;
use crate::geom::DVec2;

/// The drawing the angles are read on: the cam, its points and their pitch-curve points
/// (cam frame).
pub(super) struct Drawn<'a> {
    /// The cam.
    pub spec: &'a CamSpec,
    /// The drawn points.
    pub points: &'a [Point],
    /// The pitch curve's points, cam frame.
    pub centres: &'a [DVec2],
}

/// The angle between the normal read at every point and the follower's path there (`paths`,
/// cam frame), rad, signed by the side of the path the normal leans to (its magnitude the
/// pressure angle): an offset follower's angle changes side where S′ passes e, and the
/// graph of its magnitude touches nought there.
pub(super) fn read_leans(d: &Drawn<'_>, paths: &[DVec2]) -> Vec<f64> {
    (0..d.points.len())
        .map(|i| {
            let nrm = jay(tangent(d, i));
            let c = (nrm.dot(paths[i]).abs() / nrm.length()).clamp(0.0, 1.0);
            // The normal turned to run with the path, and the side it leans to.
            let along = nrm * nrm.dot(paths[i]).signum();
            if paths[i].perp_dot(along) < 0.0 {
                -c.acos()
            } else {
                c.acos()
            }
        })
        .collect()
}

/// The pitch curve's direction read at point `i`.
fn tangent(d: &Drawn<'_>, i: usize) -> DVec2 {
    let (points, c) = (d.points, d.centres);
    let p = &points[i];
    let law = if p.phase == 0 {
        d.spec.rise
    } else {
        d.spec.ret
    };
    let (lo, hi) = neighbours(points, i);
    let chord = || c[hi] - c[lo];
    if lo == i || hi == i {
        if law.shock() != Shock::Rigid {
            // Along the circle about O₁ through the point: ⊥ O₁B_i.
            return jay(c[i]);
        }
        return side(points, c, i, lo == i).unwrap_or_else(chord);
    }
    if on_break(d.spec, p) {
        let sides = (side(points, c, i, false), side(points, c, i, true));
        if let (Some(a), Some(b)) = sides {
            // Both run the way φ grows: their mean, each of unit length.
            return a.normalize_or_zero() + b.normalize_or_zero();
        }
    }
    tangent_through(
        (c[lo], p.phi - points[lo].phi),
        c[i],
        (c[hi], points[hi].phi - p.phi),
    )
}

/// The tangent at point `i` of the parabola (in φ) through it and its phase's next two
/// points on one side (`forward`: after it), oriented the way φ grows:
/// f′(φ₀) ≈ −(1/d₁ + 1/d₂)·c₀ + d₂/(d₁(d₂ − d₁))·c₁ − d₁/(d₂(d₂ − d₁))·c₂, d the signed
/// steps from φ₀; `None` when the phase has no two points there.
fn side(points: &[Point], c: &[DVec2], i: usize, forward: bool) -> Option<DVec2> {
    let p = &points[i];
    let at = |k: usize| {
        let j = if forward {
            i.checked_add(k)?
        } else {
            i.checked_sub(k)?
        };
        points
            .get(j)
            .filter(|q| q.phase == p.phase)
            .map(|q| (j, q.phi - p.phi))
    };
    let ((j1, d1), (j2, d2)) = (at(1)?, at(2)?);
    if d1 == 0.0 || d2 == 0.0 || d2 == d1 {
        return None;
    }
    Some(
        c[i] * -(1.0 / d1 + 1.0 / d2) + c[j1] * (d2 / (d1 * (d2 - d1)))
            - c[j2] * (d1 / (d2 * (d2 - d1))),
    )
}

/// The direction of the curve at `c` read through its neighbours `a` and `b`, `ha` and `hb`
/// before and after it (in φ): the chord a → b where the steps are equal or one neighbour
/// is the point itself, else the tangent at `c` of the parabola through the three,
/// ∝ ha²·(b − c) + hb²·(c − a).
fn tangent_through((a, ha): (DVec2, f64), c: DVec2, (b, hb): (DVec2, f64)) -> DVec2 {
    if ha <= 0.0 || hb <= 0.0 || ha == hb {
        return b - a;
    }
    (b - c) * (ha * ha) + (c - a) * (hb * hb)
}

/// The neighbours of point `i` within its phase (one-sided at the phase's ends).
fn neighbours(points: &[Point], i: usize) -> (usize, usize) {
    let same = |j: usize| points.get(j).is_some_and(|q| q.phase == points[i].phase);
    let lo = if i > 0 && same(i - 1) { i - 1 } else { i };
    let hi = if same(i + 1) { i + 1 } else { i };
    (lo, hi)
}
