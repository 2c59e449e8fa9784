//! The drawing ranges of the scene's scales and poles, checked at load: a scale is refused
//! when it draws its reference quantity in the scene — the crank (μ_l, μ_S), the crank pin's
//! velocity ω₁·r (μ_v) or acceleration ω₁²·r (μ_a), a cam's stroke, a rotor's largest m·ρ, the
//! largest declared load — shorter than [`DRAWN_MM`]`.0` (an invisible plate: μ_l = 1e40 drew
//! one, exit 0) or longer than [`DRAWN_MM`]`.1` (no sheet holds it, and the construction's
//! coordinates lose their meaning long before 1e-300); an angle axis 2π/μ_φ must lie in
//! [`AXIS_MM`], a pole distance in [`POLE_MM`]. Inside the ranges a drawing that does not fit
//! its sheet is refused when the sheet is laid out, naming the key and the value at which
//! every drawing it sets fits.

use super::check::{number, short, Checker};
use crate::kinematics::KinematicsSpec;
use crate::linkage::Mechanism;
use crate::scale::{Key, Lang, Scale, DRAWN_MM};
use std::f64::consts::TAU;

/// The shortest and longest crank-angle axis 2π/μ_φ of the charts, mm.
pub(crate) const AXIS_MM: (f64, f64) = (10.0, 1e4);
/// The smallest and largest pole distance of a graphical differentiation, mm.
pub(crate) const POLE_MM: (f64, f64) = (1.0, 500.0);

/// Check the given scales and poles of `[mechanism]` and `[kinematics]` against the
/// mechanism's crank (its length r and speed ω₁).
pub(crate) fn drawing_ranges(
    check: &mut Checker,
    m: &Mechanism,
    scale_l: Option<Scale>,
    spec: &KinematicsSpec,
) {
    let (r, w) = (m.crank.length, m.crank.omega);
    if !(r > 0.0 && w.is_finite() && w != 0.0) {
        // The crank itself was refused: nothing to measure the scales by.
        return;
    }
    let w = w.abs();
    draws(
        check,
        Key::MechanismScaleL.path(),
        scale_l,
        "the crank r",
        r,
    );
    let v = "the crank pin's velocity ω₁·r";
    draws(check, Key::KinematicsScaleV.path(), spec.scale_v, v, w * r);
    let a = "the crank pin's acceleration ω₁²·r";
    draws(
        check,
        Key::KinematicsScaleA.path(),
        spec.scale_a,
        a,
        w * w * r,
    );
    draws(
        check,
        Key::KinematicsScaleS.path(),
        spec.scale_s,
        "the crank r",
        r,
    );
    turn_axis(
        check,
        Key::KinematicsScalePhi.path(),
        spec.scale_phi,
        "the crank's",
    );
    for (key, h) in [
        ("kinematics.pole_h1", spec.pole_h1),
        ("kinematics.pole_h2", spec.pole_h2),
    ] {
        pole(check, key, h, "a pole distance");
    }
}

/// A given pole distance `h` of `key` (`what`, for the message) must lie in [`POLE_MM`].
pub(crate) fn pole(check: &mut Checker, key: &str, h: Option<f64>, what: &str) {
    if let Some(h) = h.filter(|&h| !within(h, POLE_MM)) {
        check.push(
            key,
            Some(number(h)),
            format!(
                "expected {what} from {} to {} mm",
                short(POLE_MM.0),
                short(POLE_MM.1)
            ),
        );
    }
}

/// A given scale `s` of `key` must draw `what` (of SI size `size`, > 0) between
/// [`DRAWN_MM`]`.0` and [`DRAWN_MM`]`.1`; a size that is not positive (nothing to measure
/// by: zero loads) checks nothing.
pub(crate) fn draws(check: &mut Checker, key: &str, s: Option<Scale>, what: &str, size: f64) {
    draws_within(check, key, s, what, size, DRAWN_MM);
}

/// [`draws`] within `range` (mm) instead of [`DRAWN_MM`].
pub(crate) fn draws_within(
    check: &mut Checker,
    key: &str,
    s: Option<Scale>,
    what: &str,
    size: f64,
    (lo, hi): (f64, f64),
) {
    let Some(s) = s else { return };
    if !(size.is_finite() && size > 0.0) {
        return;
    }
    let drawn = size / s.value();
    if !within(drawn, (lo, hi)) {
        let unit = s.quantity.unit(Lang::En);
        let si = s.quantity.si_unit();
        check.push(
            key,
            Some(number(s.value())),
            format!(
                "expected a scale that draws {what} = {} {si} between {} and {} mm: from {} to {} {unit} (it draws {} mm)",
                short(size),
                short(lo),
                short(hi),
                short(size / hi),
                short(size / lo),
                short(drawn)
            ),
        );
    }
}

/// A given scale of an angle axis must draw a whole turn 2π (of `what`: the crank, the cam)
/// within [`AXIS_MM`].
pub(crate) fn turn_axis(check: &mut Checker, key: &str, s: Option<Scale>, what: &str) {
    let Some(s) = s else { return };
    let axis = TAU / s.value();
    if !within(axis, AXIS_MM) {
        check.push(
            key,
            Some(number(s.value())),
            format!(
                "expected a scale that draws {what} turn 2π between {} and {} mm: from {} to {} rad/mm (it draws {} mm)",
                short(AXIS_MM.0),
                short(AXIS_MM.1),
                short(TAU / AXIS_MM.1),
                short(TAU / AXIS_MM.0),
                short(axis)
            ),
        );
    }
}

/// `x` in `[lo, hi]`, the ends with 1e-3 relative slack: a scale typed as the printed end of
/// its range (4 significant digits) is inside it.
fn within(x: f64, (lo, hi): (f64, f64)) -> bool {
    x >= lo * (1.0 - 1e-3) && x <= hi * (1.0 + 1e-3)
}
