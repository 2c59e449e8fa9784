//! The final elements of a minimum-radius construction, drawn as the textbook finishes it:
//! the two γ_min rays that bound the zone of the cam's centre, each from its point to their
//! crossing (and a little past it), the zone hatched along them inside (ГОСТ 2.306) up to
//! the chord between their ends, the centre chosen marked and r_min dimensioned from it.
//! The rays, the zone and the centre are the construction's own (its points and its
//! decision); this file only draws them. The flat face's zone, between its 45° tangent and
//! the S axis, is hatched by the same band.

use super::follower::Placement;
use crate::construct::{Item, Recorder, Role, StepId};
use crate::geom::{line_line, DVec2, Line, LineLine, Segment};
use std::f64::consts::PI;

/// The hatched band along the zone's two sides is this wide, mm.
const BAND_MM: f64 = 5.0;
/// The band runs at least this far from the crossing along each side, mm (and 10 mm past
/// the centre chosen).
const BAND_MIN_MM: f64 = 20.0;
/// Hatch spacing, mm (ГОСТ 2.306: 1…10 mm by the area).
const HATCH_MM: f64 = 2.0;
/// A zone whose bands along its two sides would leave unhatched less than this share of
/// its size (the inner triangle's scale is 1 − w/l_p − w/l_q) is hatched whole.
const WHOLE_BEYOND: f64 = 0.5;
/// Probe distance from the crossing when telling which of its four angles is the zone, mm.
const PROBE_MM: f64 = 0.5;

/// The note of a bounding ray's step (the tests find the rays by it).
pub const RAY_NOTE: &str = "γ_min ray bounding the zone of the cam centre";
/// The note of the r_min dimension's step.
pub const R_MIN_NOTE: &str = "dimension r_min";
/// The note of the dimension r₀ of a base radius the scene chose under r_min.
pub const R0_NOTE: &str = "dimension r_0 of the base radius chosen";
/// The note of the line x = −e on which an offset follower's cam centre is chosen.
pub const E_LINE_NOTE: &str = "the line x = −e of the cam centre";
/// The note of the offset e's dimension.
pub const E_NOTE: &str = "dimension e";

/// A bounding ray: its point K and its direction from K through the crossing.
#[derive(Debug, Clone, Copy)]
pub(super) struct Ray {
    /// The point of the diagram the ray is drawn from.
    pub k: DVec2,
    /// Its direction (any length).
    pub dir: DVec2,
}

/// The crossing of two rays' lines; `None` for parallel ones.
pub(super) fn crossing(rec: &Recorder, a: Ray, b: Ray) -> Option<DVec2> {
    let (la, lb) = (Line::new(a.k, a.dir)?, Line::new(b.k, b.dir)?);
    match line_line(&la, &lb, rec.tolerances()) {
        LineLine::Point { point, .. } => Some(point),
        _ => None,
    }
}

/// Draw the two rays from their points through their crossing `c`, and hatch the zone: the
/// angle at `c` between them where `inside` holds, as a band [`BAND_MM`] wide along its two
/// sides out to `reach` mm from `c` (at least [`BAND_MIN_MM`]), the rays drawn as far.
/// Returns the rays' steps.
pub(super) fn draw_zone(
    rec: &mut Recorder,
    rays: [Ray; 2],
    c: DVec2,
    reach: f64,
    inside: impl Fn(DVec2) -> bool,
) -> Vec<StepId> {
    let mut ids = Vec::with_capacity(2);
    for r in rays {
        let Some(u) = (c - r.k).try_normalize() else {
            continue;
        };
        ids.push(rec.draw(
            RAY_NOTE,
            Item::Segment(Segment::new(r.k, c + u * band_length(reach))),
            Role::Construction,
            &[],
        ));
    }
    let (Some(a), Some(b)) = (rays[0].dir.try_normalize(), rays[1].dir.try_normalize()) else {
        return ids;
    };
    // The zone is the one of the four angles at the crossing where the centre is admitted.
    let sides = [(a, b), (a, -b), (-a, b), (-a, -b)]
        .into_iter()
        .find(|(p, q)| {
            (*p + *q)
                .try_normalize()
                .is_some_and(|m| inside(c + m * PROBE_MM))
        });
    if let Some((p, q)) = sides {
        let len = band_length(reach);
        hatch_angle_between(rec, c, (p, len), (q, len), &ids);
    }
    ids
}

/// Hatch the band along the two sides of an angle at its apex `c`, inside it: side `p` (unit)
/// `lp` mm long, side `q` `lq` mm; [`BAND_MM`] wide along each side, its two ends cut along
/// the chord between the sides' ends — no stroke stands past the lines that bound it. Where
/// the sides are too short for the band to leave half the triangle they close unhatched,
/// that triangle is hatched whole ([`WHOLE_BEYOND`]).
pub(super) fn hatch_angle_between(
    rec: &mut Recorder,
    c: DVec2,
    (p, lp): (DVec2, f64),
    (q, lq): (DVec2, f64),
    from: &[StepId],
) {
    let angle = p.angle_to(q).abs();
    if angle <= 2e-3 || angle >= PI - 2e-3 || lp <= 0.0 || lq <= 0.0 {
        return;
    }
    let (a, b) = (c + p * lp, c + q * lq);
    // A point c + s·p + t·q lies on the band's inner edge parallel to q at s = w, to p at
    // t = w, on the chord a–b at s/lp + t/lq = 1.
    let w = BAND_MM / angle.sin();
    let outline = if w / lp + w / lq >= WHOLE_BEYOND {
        // The band fills the triangle the sides' ends close, or leaves inside it a sliver
        // that reads as a gap in the hatching rather than as the zone's inside.
        vec![a, c, b]
    } else {
        vec![
            a,
            c,
            b,
            c + p * w + q * (lq * (1.0 - w / lp)),
            c + (p + q) * w,
            c + p * (lp * (1.0 - w / lq)) + q * w,
        ]
    };
    let angle = hatch_angle(&[p, q]);
    // The outline is finite (its points are the drawing's) and a band a few spacings wide:
    // the hatcher refuses neither.
    let _ = rec.hatching(
        "hatching of the zone of the cam centre",
        outline,
        (HATCH_MM, angle),
        from,
    );
}

/// How far from the crossing the band (and the rays) run for a zone `reach` mm long, mm.
pub(super) fn band_length(reach: f64) -> f64 {
    reach.max(BAND_MIN_MM)
}

/// The hatch's angle (ГОСТ 2.306): 45°, else the first of 135°, 30°, 150°, 60°, 120° at
/// least 20° off every side's direction.
fn hatch_angle(sides: &[DVec2]) -> f64 {
    let off = |a: f64, d: DVec2| {
        let x = (a - d.y.atan2(d.x)).rem_euclid(PI);
        x.min(PI - x)
    };
    [45.0f64, 135.0, 30.0, 150.0, 60.0, 120.0]
        .into_iter()
        .map(f64::to_radians)
        .find(|&a| sides.iter().all(|d| off(a, *d) >= 20f64.to_radians()))
        .unwrap_or(PI / 4.0)
}

/// Mark the centre chosen at `o` and dimension r_min from it to `to` (the start of the
/// rise), the dimension line on the piece itself (offset 0) or `offset` mm to its left.
pub(super) fn centre_and_r_min(
    rec: &mut Recorder,
    o: DVec2,
    to: DVec2,
    toward: DVec2,
    offset: f64,
) -> StepId {
    let oid = rec.point("cam centre O_1", o, Role::Result, "O_1", toward, &[]);
    rec.dimension(R_MIN_NOTE, (o, to, offset), "r_{min}");
    oid
}

/// A chosen base radius's r₀ dimension stands this far left of the S axis (r_min's and
/// ρ_min's stand right of it), mm.
const R0_MM: f64 = 9.0;

/// Mark the centre of a base radius the scene chose under r_min (a hard case), where the
/// translating follower's `placement` puts it (e left of the S axis, s₀ below B₀ at the
/// figure's μ) — inside the zone no centre may take, which is why its profile comes out
/// pointed or too steep — and dimension r₀ from it to B₀, beside the r_min constructed.
/// Nothing for a rocker.
pub(super) fn chosen_centre(rec: &mut Recorder, placement: Placement) {
    let Placement::Translating { offset, s0 } = placement else {
        return;
    };
    let mu = rec.scale();
    let at = DVec2::new(-mu.to_mm(offset), -mu.to_mm(s0));
    rec.point(
        "the centre O_1′ of the base radius chosen",
        at,
        Role::Result,
        "O_1′",
        DVec2::new(-1.0, 0.0),
        &[],
    );
    rec.dimension(R0_NOTE, (at, DVec2::ZERO, R0_MM), "r_0");
}

/// The line x = −e runs this far under the centre chosen on it, mm.
const E_BELOW_MM: f64 = 5.0;

/// e is dimensioned this share of the way from B₀'s level down to the centre, clear of the
/// middle of r_min's dimension line (O₁ to B₀), where r_min's text or its leader stands
/// (halfway, e crossed r_min's line where r_min's leader ended: cam-shock); there r_min's
/// line passes near the middle of e's and e's text goes past its arrow.
const E_AT: f64 = 0.35;

/// An offset follower's centre `o` is chosen on the line x = −e, parallel to the S axis
/// (the follower's path): that line drawn from under the centre up to B₀'s level, and e
/// dimensioned between it and the S axis [`E_AT`] of the way down (under the centre lies the
/// zone's hatching, at it the centre's name).
pub(super) fn offset_line(rec: &mut Recorder, o: DVec2) {
    let (top, bottom) = (DVec2::new(o.x, 0.0), DVec2::new(o.x, o.y - E_BELOW_MM));
    rec.draw(
        E_LINE_NOTE,
        Item::Segment(Segment::new(bottom, top)),
        Role::Construction,
        &[],
    );
    let y = E_AT * o.y;
    rec.dimension(E_NOTE, (DVec2::new(0.0, y), DVec2::new(o.x, y), 0.0), "e");
}
