//! The involute function, its inverse (a bracketed, guaranteed-convergent solver, not a
//! table), points of an involute, the tooth thickness on any circle, and the textbook's
//! compass construction of an involute (base circle stepped in equal chords, tangents with
//! the unrolled lengths laid off) against the exact curve.

use super::GearError;
use crate::geom::{bracketed_newton, DVec2, NewtonEnd};
use std::f64::consts::FRAC_PI_2;

/// inv α = tg α − α (radians).
pub fn inv(alpha: f64) -> f64 {
    inv_small(alpha).unwrap_or_else(|| alpha.tan() - alpha)
}

/// inv α and tg α, the tangent computed once.
fn inv_and_tan(alpha: f64) -> (f64, f64) {
    let t = alpha.tan();
    (inv_with_tan(alpha, t), t)
}

/// inv α when tg α is known (`tan`; e.g. a roll over its base radius): tg α − α, or the
/// series where that cancels.
pub fn inv_with_tan(alpha: f64, tan: f64) -> f64 {
    inv_small(alpha).unwrap_or(tan - alpha)
}

/// inv α by its series where tg α − α cancels (|α| < 0.05 rad, where the series is exact to
/// f64); `None` above.
fn inv_small(alpha: f64) -> Option<f64> {
    (alpha.abs() < 0.05).then(|| {
        let a2 = alpha * alpha;
        let c = [
            1.0 / 3.0,
            2.0 / 15.0,
            17.0 / 315.0,
            62.0 / 2835.0,
            1382.0 / 155_925.0,
            21844.0 / 6_081_075.0,
        ];
        let s = c.iter().rev().fold(0.0, |acc, k| acc * a2 + k);
        alpha * a2 * s
    })
}

/// The largest angle the inverse returns: inv is finite on [0, π/2), and beyond this
/// angle (89.9999°) no tooth or mesh has a pressure angle.
const MAX_ANGLE: f64 = FRAC_PI_2 - 1e-6;

/// The inverse of the involute function: the α in [0, π/2) with inv α = `v`.
///
/// Safeguarded Newton iteration inside a bracket [0, MAX_ANGLE] that always contains the
/// root (inv is increasing; [`bracketed_newton`]): each Newton step that leaves the bracket
/// is replaced by bisection,
/// so the iteration converges for every admissible `v`. It starts from three terms of the
/// series and stops when the error Newton's step leaves (estimated from the step) or the
/// bracket is at the resolution of f64: two steps at a gear's pressure angles.
///
/// # Errors
/// [`GearError::InvoluteDomain`] for a negative, non-finite or too large `v`.
pub fn inv_inverse(v: f64) -> Result<f64, GearError> {
    inv_inverse_with_tan(v).map(|(alpha, _)| alpha)
}

/// [`inv_inverse`] with tg α: the last Newton step's tangent carried through the step,
/// tg(α + δ) = tg α + (1 + tg²α)·δ·(1 + tg α·δ) + O(δ³) (within an ulp for a step that lands
/// on the root).
///
/// # Errors
/// As [`inv_inverse`].
pub fn inv_inverse_with_tan(v: f64) -> Result<(f64, f64), GearError> {
    if !(v.is_finite() && v >= 0.0 && v <= inv(MAX_ANGLE)) {
        return Err(GearError::InvoluteDomain { value: v });
    }
    if v == 0.0 {
        return Ok((0.0, 0.0));
    }
    // inv α = α³/3 + 2α⁵/15 + 17α⁷/315 + …, so with q = (3 inv α)^⅓,
    // α = q − 2q³/15 + 3q⁵/175 + O(q⁷): a start inside the bracket (the series where it
    // helps, q < 1, below about 50°; 3e-6 of α at 20°).
    let q = (3.0 * v).cbrt();
    let q2 = q * q;
    let start = if q < 1.0 {
        q * (1.0 - q2 * (2.0 / 15.0 - q2 * (3.0 / 175.0)))
    } else {
        q
    };
    // inv′ α = tg²α; the tangent rides along as the evaluation's extra.
    let f = |a: f64| {
        let (inv_a, t) = inv_and_tan(a);
        (inv_a - v, t * t, t)
    };
    // Newton's error after a step δ is about δ²·inv″/(2 inv′) = δ²(1 + tg²)/tg: once that
    // is below a quarter of an ulp, the step has landed on the root.
    let landed = |a: f64, step: f64, &t: &f64| {
        step * step * (1.0 + t * t) <= 0.25 * f64::EPSILON * a * t
            || step.abs() <= 4.0 * f64::EPSILON * a
    };
    Ok(
        match bracketed_newton(f, (0.0, MAX_ANGLE), start, 200, landed) {
            NewtonEnd::Root(a, t) => (a, t),
            NewtonEnd::Landed { to, step, from: t } => {
                (to, t + (1.0 + t * t) * step * (1.0 + t * step))
            }
            NewtonEnd::Middle(a) | NewtonEnd::Spent(a) => (a, a.tan()),
        },
    )
}

/// The inverse by plain Newton iteration from (3v)^{1/3} (seed 002's recipe), the twin of
/// [`inv_inverse`]; `None` when it leaves [0, π/2) or does not settle.
pub fn inv_inverse_newton(v: f64) -> Option<f64> {
    let mut a = (3.0 * v).cbrt();
    for _ in 0..100 {
        let t = a.tan();
        let next = a - (t - a - v) / (t * t);
        if !(next.is_finite() && (0.0..FRAC_PI_2).contains(&next)) {
            return None;
        }
        if (next - a).abs() <= 1e-16 * a.max(1e-300) {
            return Some(next);
        }
        a = next;
    }
    Some(a)
}

/// Decimals of the textbook's inv table.
pub const TABLE_DIGITS: i32 = 6;

/// The textbook's route to α from inv α: the value written to [`TABLE_DIGITS`] decimals,
/// looked up in the inv table (a row every minute of arc, each rounded to
/// [`TABLE_DIGITS`] decimals), read linearly between the two rows that bracket it and
/// rounded to the second. Radians; `None` outside the table (0° … 60°).
pub fn alpha_by_table(v: f64) -> Option<f64> {
    let round = |x: f64| (x * 10f64.powi(TABLE_DIGITS)).round() / 10f64.powi(TABLE_DIGITS);
    let row = |k: i32| round(inv((f64::from(k) / 60.0).to_radians()));
    let v = round(v);
    if !(0.0..=row(3600)).contains(&v) {
        return None;
    }
    // The row at or below v, from the exact angle's minute (the rounded rows are monotone).
    let exact = inv_inverse(v).ok()?.to_degrees() * 60.0;
    let mut k = (exact.floor() as i32).clamp(0, 3599);
    while k > 0 && row(k) > v {
        k -= 1;
    }
    while k < 3599 && row(k + 1) <= v {
        k += 1;
    }
    let (lo, hi) = (row(k), row(k + 1));
    let minutes = f64::from(k) + if hi > lo { (v - lo) / (hi - lo) } else { 0.0 };
    Some(((minutes * 60.0).round() / 3600.0).to_radians())
}

/// An angle as degrees, minutes and seconds (`26°34′51″`, seconds to `decimals`).
pub fn dms(alpha: f64, decimals: usize) -> String {
    let total = alpha.to_degrees().abs() * 3600.0;
    let scale = 10f64.powi(decimals as i32);
    let total = (total * scale).round() / scale;
    let d = (total / 3600.0).floor();
    let m = ((total - d * 3600.0) / 60.0).floor();
    let s = total - d * 3600.0 - m * 60.0;
    format!(
        "{}{d}°{m:02}′{s:0w$.decimals$}″",
        if alpha < 0.0 { "−" } else { "" },
        w = if decimals > 0 { decimals + 3 } else { 2 }
    )
}

/// The pressure angle of an involute of the base radius `rb` at the radius `ry` ≥ `rb`.
pub fn pressure_angle(rb: f64, ry: f64) -> f64 {
    (rb / ry).clamp(-1.0, 1.0).acos()
}

/// The tooth thickness (arc) on the circle of radius `ry` of a tooth whose thickness on the
/// pitch circle `r` (pressure angle `alpha`) is `s`:
/// `s_y = 2·r_y·(s/(2r) + inv α − inv α_y)`, α_y = arccos(r_b/r_y). Negative: pointed below
/// `ry`.
pub fn thickness_at(s: f64, r: f64, alpha: f64, ry: f64) -> f64 {
    let rb = r * alpha.cos();
    2.0 * ry * (s / (2.0 * r) + inv(alpha) - inv(pressure_angle(rb, ry)))
}

/// A point of the involute of the base circle (`centre`, `rb`) whose origin on the base
/// circle is at the polar angle `theta0`, unwound counter-clockwise (`ccw`) or clockwise,
/// at the roll angle `t` ≥ 0 (the unrolled string has the length `rb·t`).
pub fn involute_point(centre: DVec2, rb: f64, theta0: f64, t: f64, ccw: bool) -> DVec2 {
    let k = if ccw { 1.0 } else { -1.0 };
    let th = theta0 + k * t;
    let radial = DVec2::new(th.cos(), th.sin());
    // The string leaves the base circle along the tangent, away from the origin.
    let tangent = DVec2::new(th.sin(), -th.cos()) * k;
    centre + radial * rb + tangent * (rb * t)
}

/// The polar angle (about the base circle's centre) of the origin of the involute of `rb`
/// through `q`, unwound counter-clockwise (`ccw`) or clockwise: the involutes of one base
/// circle are equidistant, so `rb·|Δθ₀|` is the distance between two of them along their
/// common normal. `None` inside the base circle.
pub fn origin_angle(centre: DVec2, rb: f64, q: DVec2, ccw: bool) -> Option<f64> {
    let d = q - centre;
    let rho = d.length();
    if rho < rb {
        return None;
    }
    let polar = d.y.atan2(d.x);
    let i = inv(pressure_angle(rb, rho));
    Some(if ccw { polar - i } else { polar + i })
}

/// The compass construction of an involute through `p` (outside the base circle `centre`,
/// `rb`), the textbook's way: the tangent from `p` touches the base circle at T (on the side
/// that unwinds counter-clockwise when `ccw`), PT is divided into `parts` equal segments b,
/// the compass opening b is stepped along the base circle from T `parts` times (chords, not
/// arcs) back to the origin 0, and on the tangent at the k-th notch k segments b are laid
/// off. `extra` more notches beyond T continue the curve past `p`.
#[derive(Debug, Clone, PartialEq)]
pub struct CompassInvolute {
    /// The notches on the base circle, from the origin 0 (index 0) through T (index
    /// `parts`) and beyond.
    pub notches: Vec<DVec2>,
    /// The points laid off on the tangents (index k: k segments from notch k); index 0 is
    /// the origin itself, index `parts` is `p`.
    pub points: Vec<DVec2>,
    /// The segment b = PT/parts.
    pub step: f64,
    /// The chord-vs-arc error of one step: b − chord angle·rb… as the arc the chord b
    /// subtends minus b, `rb·2·asin(b/(2rb)) − b` (> 0).
    pub arc_minus_chord: f64,
    /// The largest distance of a constructed point from the exact involute through `p`
    /// (along the common normal of the base circle's involutes).
    pub deviation: f64,
}

/// Carry out [`CompassInvolute`]'s construction.
///
/// # Errors
/// [`GearError::InvolutePoint`] when `p` is not outside the base circle or `parts` is 0.
pub fn compass_involute(
    centre: DVec2,
    rb: f64,
    p: DVec2,
    parts: u32,
    extra: u32,
    ccw: bool,
) -> Result<CompassInvolute, GearError> {
    let d = p - centre;
    let dist = d.length();
    if !(rb > 0.0 && dist > rb && parts > 0) {
        return Err(GearError::InvolutePoint { distance: dist, rb });
    }
    let k = if ccw { 1.0 } else { -1.0 };
    // The tangency point T: the string PT is tangent at T; for a counter-clockwise involute
    // the string leaves T in the direction (sin θ, −cos θ), so T is at θ_T with P − T along it.
    let len = (dist * dist - rb * rb).sqrt();
    let theta_t = d.y.atan2(d.x) + k * (len / rb).atan();
    let step = len / parts as f64;
    let chord_angle = 2.0 * (step / (2.0 * rb)).min(1.0).asin();
    let notch = |j: f64| {
        let th = theta_t + k * chord_angle * j;
        (th, centre + DVec2::new(th.cos(), th.sin()) * rb)
    };
    let mut notches = Vec::new();
    let mut points = Vec::new();
    for i in 0..=(parts + extra) {
        // Notch i counts from the origin: i = parts is T.
        let j = i as f64 - parts as f64;
        let (th, at) = notch(j);
        let tangent = DVec2::new(th.sin(), -th.cos()) * k;
        notches.push(at);
        points.push(at + tangent * (step * i as f64));
    }
    let exact = origin_angle(centre, rb, p, ccw).unwrap_or(0.0);
    let deviation = points
        .iter()
        .filter_map(|q| origin_angle(centre, rb, *q, ccw))
        .map(|a| rb * crate::geom::wrap_pi(a - exact).abs())
        .fold(0.0, f64::max);
    Ok(CompassInvolute {
        notches,
        points,
        step,
        arc_minus_chord: rb * chord_angle - step,
        deviation,
    })
}
