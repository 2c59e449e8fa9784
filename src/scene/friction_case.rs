//! `[[friction.case]]` as the file writes it (the union of every kind's keys), and the checks
//! of the values the kinds share — a force, a coefficient of friction, an angle — each with
//! its key path, converted to SI: what the cases of [`super::friction`] and of the cam's
//! follower ([`super::follower`]) read.

use super::check::{join, number, Checker};
use serde::Deserialize;

/// The largest force a scene may give, N.
pub(super) const MAX_FORCE: f64 = 1e9;
/// The largest coefficient of friction a scene may give.
const MAX_F: f64 = 5.0;

/// `[[friction.case]]`: the union of the keys of every kind.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawCase {
    pub kind: Option<String>,
    pub name: Option<String>,
    pub load: Option<f64>,
    pub f: Option<f64>,
    pub f0: Option<f64>,
    pub scale_f: Option<f64>,
    pub angle: Option<f64>,
    pub force_angle: Option<f64>,
    pub motion: Option<String>,
    pub groove: Option<f64>,
    pub lead: Option<f64>,
    pub profile: Option<f64>,
    pub radius: Option<f64>,
    pub rotation: Option<String>,
    pub roller_weight: Option<f64>,
    pub diameter: Option<f64>,
    pub k1: Option<f64>,
    pub k2: Option<f64>,
    pub f1: Option<f64>,
    pub f2: Option<f64>,
    pub length: Option<f64>,
    pub overhang: Option<f64>,
    pub moment: Option<f64>,
    pub arm: Option<f64>,
}

impl RawCase {
    /// The keys present besides `kind`, `name` and `scale_f`, which every kind takes.
    pub(super) fn present(&self) -> Vec<&'static str> {
        let numbers = [
            ("load", self.load),
            ("f", self.f),
            ("f0", self.f0),
            ("angle", self.angle),
            ("force_angle", self.force_angle),
            ("groove", self.groove),
            ("lead", self.lead),
            ("profile", self.profile),
            ("radius", self.radius),
            ("roller_weight", self.roller_weight),
            ("diameter", self.diameter),
            ("k1", self.k1),
            ("k2", self.k2),
            ("f1", self.f1),
            ("f2", self.f2),
            ("length", self.length),
            ("overhang", self.overhang),
            ("moment", self.moment),
            ("arm", self.arm),
        ];
        let words = [("motion", &self.motion), ("rotation", &self.rotation)];
        numbers
            .iter()
            .filter(|(_, v)| v.is_some())
            .map(|(k, _)| *k)
            .chain(words.iter().filter(|(_, v)| v.is_some()).map(|(k, _)| *k))
            .collect()
    }
}

/// A required force in N, > 0 and at most [`MAX_FORCE`].
pub(super) fn force(check: &mut Checker, base: &str, key: &str, v: Option<f64>) -> f64 {
    let key = join(base, key);
    const WANT: &str = "a force > 0 N and at most 1e9 N";
    match check.required(&key, v, WANT) {
        Some(x) => check.in_range(&key, x, MAX_FORCE, WANT),
        None => 0.0,
    }
}

/// A required coefficient of friction, > 0 and at most [`MAX_F`].
pub(super) fn coefficient(check: &mut Checker, base: &str, key: &str, v: Option<f64>) -> f64 {
    let key = join(base, key);
    const WANT: &str = "a coefficient of friction > 0 and at most 5";
    match check.required(&key, v, WANT) {
        Some(x) => check.in_range(&key, x, MAX_F, WANT),
        None => 0.0,
    }
}

/// An angle in degrees within `(lo, hi)` (`lo` itself allowed when `closed`), in radians;
/// `default` when the key is optional.
pub(super) fn angle(
    check: &mut Checker,
    base: &str,
    key: &str,
    v: Option<f64>,
    default: Option<f64>,
    (lo, hi): (f64, f64),
    closed: bool,
) -> f64 {
    let key = join(base, key);
    let open = if closed { "[" } else { "(" };
    let want = format!("an angle in {open}{lo}°, {hi}°]");
    let Some(deg) = v.or(default) else {
        check.push(key, None, format!("missing: expected {want}"));
        return 0.0;
    };
    let above = if closed { deg >= lo } else { deg > lo };
    if deg.is_finite() && above && deg <= hi {
        deg.to_radians()
    } else {
        check.push(key, Some(number(deg)), format!("expected {want}"));
        0.0
    }
}
