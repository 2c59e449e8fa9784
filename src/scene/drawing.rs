//! The drawing ranges of the mechanism's and the kinematic study's scales and poles, checked
//! at load: a scale is refused when it draws its reference quantity — the crank (μ_l, μ_S),
//! the crank pin's velocity ω₁·r (μ_v) or acceleration ω₁²·r (μ_a) — shorter than
//! [`DRAWN_MM`]`.0` (an invisible plate: μ_l = 1e40 drew one, exit 0) or longer than
//! [`DRAWN_MM`]`.1` (no sheet holds it, and the construction's coordinates lose their
//! meaning long before 1e-300); the crank-angle axis 2π/μ_φ must lie in [`AXIS_MM`], a pole
//! distance in [`POLE_MM`]. Inside the ranges a drawing that does not fit its sheet is refused
//! when the sheet is laid out, naming the key and the value at which it fits.

use super::check::Checker;
use crate::kinematics::KinematicsSpec;
use crate::linkage::Mechanism;
use crate::scale::{format_sig, Lang, Scale};
use std::f64::consts::TAU;

/// The shortest and longest a scale may draw its reference quantity, mm.
pub(crate) const DRAWN_MM: (f64, f64) = (0.1, 1e4);
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
    let sig = short;
    let mut scale = |key: &str, s: Option<Scale>, what: &str, size: f64, unit: &str| {
        let Some(s) = s else { return };
        let drawn = size / s.value();
        if !within(drawn, DRAWN_MM) {
            check.push(
                key,
                Some(sig(s.value())),
                format!(
                    "expected a scale that draws {what} = {} between {} and {} mm: from {} to {} {unit} (it draws {} mm)",
                    sig(size),
                    sig(DRAWN_MM.0),
                    sig(DRAWN_MM.1),
                    sig(size / DRAWN_MM.1),
                    sig(size / DRAWN_MM.0),
                    sig(drawn)
                ),
            );
        }
    };
    scale("mechanism.scale_l", scale_l, "the crank r", r, "m/mm");
    scale(
        "kinematics.scale_v",
        spec.scale_v,
        "the crank pin's velocity ω₁·r",
        w * r,
        "(m/s)/mm",
    );
    scale(
        "kinematics.scale_a",
        spec.scale_a,
        "the crank pin's acceleration ω₁²·r",
        w * w * r,
        "(m/s²)/mm",
    );
    scale("kinematics.scale_s", spec.scale_s, "the crank r", r, "m/mm");
    if let Some(s) = spec.scale_phi {
        let axis = TAU / s.value();
        if !within(axis, AXIS_MM) {
            check.push(
                "kinematics.scale_phi",
                Some(sig(s.value())),
                format!(
                    "expected a scale that draws the crank turn 2π between {} and {} mm: from {} to {} rad/mm (it draws {} mm)",
                    sig(AXIS_MM.0),
                    sig(AXIS_MM.1),
                    sig(TAU / AXIS_MM.1),
                    sig(TAU / AXIS_MM.0),
                    sig(axis)
                ),
            );
        }
    }
    for (key, h) in [
        ("kinematics.pole_h1", spec.pole_h1),
        ("kinematics.pole_h2", spec.pole_h2),
    ] {
        if let Some(h) = h.filter(|&h| !within(h, POLE_MM)) {
            check.push(
                key,
                Some(sig(h)),
                format!(
                    "expected a pole distance from {} to {} mm",
                    sig(POLE_MM.0),
                    sig(POLE_MM.1)
                ),
            );
        }
    }
}

/// `x` in `[lo, hi]`, the ends with 1e-3 relative slack: a scale typed as the printed end of
/// its range (4 significant digits) is inside it.
fn within(x: f64, (lo, hi): (f64, f64)) -> bool {
    x >= lo * (1.0 - 1e-3) && x <= hi * (1.0 + 1e-3)
}

/// A number for a message: 4 significant digits, in exponent form beyond 1e6 or below 1e-4
/// (no 300-digit echo).
fn short(x: f64) -> String {
    if x != 0.0 && x.is_finite() && !(1e-4..1e6).contains(&x.abs()) {
        format!("{x:.3e}")
    } else {
        format_sig(x, 4, Lang::En)
    }
}
