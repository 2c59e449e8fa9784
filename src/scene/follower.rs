//! The friction cases of a cam's follower (`kind = "guide"`, `kind = "pivot"`): the guide of
//! a translating follower (`load`, `f`, `angle`, `length`, `overhang`) and the pivot of a
//! rocker (`moment`, `f`, `angle`, `arm`, `diameter`), each refused with its key path when
//! the follower would jam (λ not below λ_кр by 2°), converted to SI.

use super::check::{join, number, Checker};
use super::friction_case::{angle, coefficient, force, RawCase};
use crate::cam::force::{rocker_locking, translating_locking, Pivot, TranslatingGuide};
use crate::friction::{CaseKind, FollowerGuide, RockerPivot, MIN_CROSSING_DEG};

/// The largest moment a scene may give, N·m.
const MAX_MOMENT: f64 = 1e9;

/// A cam's translating follower in its guide: the pressure angle below the jamming angle
/// tg λ_кр = b/(f(2l + b)) by at least 2° (a hand can still close the force triangle).
pub(super) fn guide(check: &mut Checker, base: &str, c: &RawCase) -> CaseKind {
    let guide = TranslatingGuide {
        length: check.length(&join(base, "length"), c.length),
        overhang: check.distance(&join(base, "overhang"), c.overhang, 0.0),
        f: coefficient(check, base, "f", c.f),
    };
    if guide.overhang < 0.0 {
        let expected = "expected the overhang l ≥ 0 mm from the contact to the nearer bearing";
        check.push(
            join(base, "overhang"),
            Some(number(guide.overhang * 1e3)),
            expected,
        );
    }
    let lock = if guide.length > 0.0 && guide.f > 0.0 && guide.overhang >= 0.0 {
        translating_locking(&guide)
    } else {
        std::f64::consts::FRAC_PI_2
    };
    let angle = pressure_angle(check, base, c.angle, lock, "tg λ_кр = b/(f(2l + b))");
    CaseKind::Guide(FollowerGuide {
        load: force(check, base, "load", c.load),
        angle,
        guide,
    })
}

/// A cam's rocker in its pivot: the pressure angle below the jamming angle
/// cos λ_кр = ρ/L, ρ = (d/2)·sin φ, by at least 2°.
pub(super) fn pivot(check: &mut Checker, base: &str, c: &RawCase) -> CaseKind {
    let key = join(base, "moment");
    const WANT: &str = "a moment of resistance > 0 N·m and at most 1e9 N·m";
    let moment = match check.required(&key, c.moment, WANT) {
        Some(x) => check.in_range(&key, x, MAX_MOMENT, WANT),
        None => 0.0,
    };
    let pivot = Pivot {
        arm: check.length(&join(base, "arm"), c.arm),
        diameter: check.length(&join(base, "diameter"), c.diameter),
        f: coefficient(check, base, "f", c.f),
    };
    if pivot.arm > 0.0 && pivot.diameter / 2.0 >= pivot.arm {
        let expected = "expected the pivot's radius d/2 smaller than the arm L";
        check.push(
            join(base, "diameter"),
            Some(number(pivot.diameter * 1e3)),
            expected,
        );
    }
    let lock = if pivot.arm > 0.0 && pivot.diameter > 0.0 && pivot.f > 0.0 {
        rocker_locking(&pivot)
    } else {
        std::f64::consts::FRAC_PI_2
    };
    let angle = pressure_angle(
        check,
        base,
        c.angle,
        lock,
        "cos λ_кр = ρ/L, ρ = (d/2)·sin φ",
    );
    CaseKind::Pivot(RockerPivot {
        moment,
        angle,
        pivot,
    })
}

/// A follower's pressure angle λ, degrees in [0°, λ_кр − 2°] (`lock` the jamming angle by
/// `rule`), in radians.
fn pressure_angle(check: &mut Checker, base: &str, v: Option<f64>, lock: f64, rule: &str) -> f64 {
    let top = lock.to_degrees() - MIN_CROSSING_DEG;
    let lambda = angle(check, base, "angle", v, None, (0.0, 89.0), true);
    if lambda.to_degrees() > top && v.is_some_and(|deg| (0.0..=89.0).contains(&deg)) {
        let expected = format!(
            "expected a pressure angle λ at least {MIN_CROSSING_DEG}° below the jamming angle \
             λ_кр = {:.2}° ({rule}): the follower jams",
            lock.to_degrees()
        );
        check.push(join(base, "angle"), v.map(number), expected);
    }
    lambda
}
