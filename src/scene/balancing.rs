//! `[balancing]` → [`BalancingSpec`]: the masses of a rotor (kg, mm, degrees), the kind of
//! balancing, the correction planes and radii (mm) and the scales, each checked with its key
//! path and converted to SI.

use super::check::{item, join, number, Checker};
use super::raw::{RawBalancing, RawMass};
use crate::balancing::{BalancingSpec, Correction, Mass};
use crate::scale::{Key, Quantity};

/// The key path of the section.
const BAL: &str = "balancing";
/// The kinds of balancing, as written.
const KINDS: [(&str, bool); 2] = [("static", false), ("dynamic", true)];
/// The heaviest mass a scene may give, kg.
const MAX_KG: f64 = 1e6;
/// The most masses a rotor may have: the balancing plate gives every mass a line of its data
/// (and, with `omega`, of its inertia force) and lays out all polygons' labels, so 37 with
/// `omega` no longer fit an A1 sheet, and the work of laying the labels out grows as n².
pub const MAX_MASSES: usize = 36;
/// The fastest rotor a scene may give, rad/s.
const MAX_OMEGA: f64 = 1e6;

/// Validate `[balancing]`.
pub(crate) fn balancing(check: &mut Checker, raw: &RawBalancing) -> Option<BalancingSpec> {
    let key = |k: &str| join(BAL, k);
    let dynamic = check.word_or_first(&key("kind"), raw.kind.as_ref(), &KINDS);
    let before = check.problems.len();
    if raw.mass.is_empty() {
        check.push(
            key("mass"),
            None,
            "missing: expected at least one [[balancing.mass]] (mass, radius, angle)",
        );
    }
    if raw.mass.len() > MAX_MASSES {
        check.push(
            key("mass"),
            Some(format!("{} masses", raw.mass.len())),
            format!(
                "expected 1 to {MAX_MASSES} [[balancing.mass]] (what the balancing plate holds)"
            ),
        );
        return None;
    }
    let masses: Vec<Mass> = raw
        .mass
        .iter()
        .enumerate()
        .map(|(i, m)| mass(check, &item(&key("mass"), i), m, dynamic))
        .collect();
    let omega = raw.omega.map(|w| {
        check.in_range(
            &key("omega"),
            w,
            MAX_OMEGA,
            "an angular velocity ω > 0 rad/s (at most 1e6)",
        )
    });
    let largest = masses.iter().map(|m| m.radius).fold(0.0, f64::max);
    let correction = if dynamic {
        let planes = planes(check, raw.planes.as_deref());
        let radii = radii(check, raw, largest);
        Correction::Dynamic { planes, radii }
    } else {
        for (k, present) in [
            ("planes", raw.planes.is_some()),
            ("radii", raw.radii.is_some()),
        ] {
            if present {
                let expected = format!(
                    "a thin rotor has one correcting mass in its own plane: expected no `{k}` \
                     unless kind = \"dynamic\""
                );
                check.push(key(k), None, expected);
            }
        }
        Correction::Static {
            radius: radius(check, &key("radius"), raw.radius, largest),
        }
    };
    let spec = BalancingSpec {
        masses,
        correction,
        omega,
        scale_mr: check.scale(
            Key::BalancingScaleMr.path(),
            raw.scale_mr,
            Quantity::StaticMoment,
            "a scale μ_mρ > 0 kg·m/mm",
        ),
        scale_mrz: check.scale(
            Key::BalancingScaleMrz.path(),
            raw.scale_mrz,
            Quantity::UnbalanceMoment,
            "a scale μ_mρz > 0 kg·m²/mm",
        ),
        scale_l: check.scale(
            Key::BalancingScaleL.path(),
            raw.scale_l,
            Quantity::Length,
            "a scale μ_l > 0 m/mm",
        ),
    };
    let largest = |f: fn(&Mass) -> f64| spec.masses.iter().map(f).fold(0.0, f64::max);
    let draws = super::drawing::draws;
    let mr = largest(|m| m.mass * m.radius);
    draws(
        check,
        Key::BalancingScaleMr.path(),
        spec.scale_mr,
        "the largest m·ρ",
        mr,
    );
    let mrz = largest(|m| (m.mass * m.radius * m.z).abs());
    draws(
        check,
        Key::BalancingScaleMrz.path(),
        spec.scale_mrz,
        "the largest m·ρ·z",
        mrz,
    );
    let rho = largest(|m| m.radius);
    draws(
        check,
        Key::BalancingScaleL.path(),
        spec.scale_l,
        "the largest radius ρ",
        rho,
    );
    (check.problems.len() == before).then_some(spec)
}

/// One `[[balancing.mass]]`: kg, mm, degrees; `z` (mm) required exactly for a dynamic
/// balancing.
fn mass(check: &mut Checker, base: &str, raw: &RawMass, dynamic: bool) -> Mass {
    let key = |k: &str| join(base, k);
    let kg = match check.required(&key("mass"), raw.mass, "a mass > 0 kg") {
        Some(v) => check.in_range(&key("mass"), v, MAX_KG, "a mass > 0 kg (at most 1e6 kg)"),
        None => 0.0,
    };
    let radius = check.length(&key("radius"), raw.radius);
    let angle = match check.required(&key("angle"), raw.angle, "an angle in degrees") {
        Some(deg) => check.angle(&key("angle"), Some(deg), 0.0),
        None => 0.0,
    };
    let z = match (dynamic, raw.z) {
        (true, Some(z)) => check.coordinate(&key("z"), z),
        (true, None) => {
            let expected = "missing: expected the axial position z of the mass's plane, mm \
                            (kind = \"dynamic\")";
            check.push(key("z"), None, expected);
            0.0
        }
        (false, Some(z)) => {
            let expected = "a thin rotor's masses lie in one plane: expected no `z` unless \
                            kind = \"dynamic\"";
            check.push(key("z"), Some(number(z)), expected);
            0.0
        }
        (false, None) => 0.0,
    };
    Mass {
        mass: kg,
        radius,
        angle,
        z,
    }
}

/// A correction radius in mm (default: the largest radius of a mass), in metres.
fn radius(check: &mut Checker, key: &str, v: Option<f64>, largest: f64) -> f64 {
    match v {
        Some(_) => check.length(key, v),
        None => largest,
    }
}

/// `planes = [z_I, z_II]`, mm, two distinct finite values, in metres.
fn planes(check: &mut Checker, v: Option<&[f64]>) -> [f64; 2] {
    const WANT: &str = "the axial positions [z_I, z_II] of the two correction planes, mm";
    let key = join(BAL, "planes");
    let Some(v) = check.required(&key, v, WANT) else {
        return [0.0, 1.0];
    };
    let [a, b] = v else {
        check.push(
            &key,
            Some(super::check::numbers(v)),
            format!("expected {WANT}"),
        );
        return [0.0, 1.0];
    };
    let (a, b) = (
        check.coordinate(&item(&key, 0), *a),
        check.coordinate(&item(&key, 1), *b),
    );
    if a == b {
        check.push(
            &key,
            Some(super::check::numbers(v)),
            "expected two distinct planes: the correction of plane II is the moment about plane I \
             divided by their distance",
        );
    }
    [a, b]
}

/// The radii of the correcting masses of planes I and II: `radius` for both or
/// `radii = [ρ_I, ρ_II]` (mm), not both; default the largest radius of a mass.
fn radii(check: &mut Checker, raw: &RawBalancing, largest: f64) -> [f64; 2] {
    let key = join(BAL, "radii");
    match (&raw.radii, raw.radius) {
        (Some(_), Some(_)) => {
            check.push(
                &key,
                None,
                "expected either `radius` (both planes) or `radii = [ρ_I, ρ_II]`, not both",
            );
            [largest; 2]
        }
        (Some(v), None) => match v.as_slice() {
            [a, b] => [
                check.length(&item(&key, 0), Some(*a)),
                check.length(&item(&key, 1), Some(*b)),
            ],
            _ => {
                check.push(
                    &key,
                    Some(super::check::numbers(v)),
                    "expected two radii [ρ_I, ρ_II], mm",
                );
                [largest; 2]
            }
        },
        (None, v) => [radius(check, &join(BAL, "radius"), v, largest); 2],
    }
}
