//! `[cam]` → [`CamSpec`]: the follower, the laws, the phases (degrees, summing to 360), the
//! stroke (mm, or a rocker's swing in degrees × its arm), the roller, the limits and the
//! scales, each checked with its key path and converted to SI.

use super::cam_raw::{key, RawCam, CAM};
use super::check::{item, join, number, Checker, MAX_MM};
use crate::cam::{
    CamLayout, CamSpec, Closure, Follower, Given, Law, Phases, RockerSense, Rotation,
};
use crate::scale::{Key, Quantity};

/// The followers, as written.
const FOLLOWERS: [(&str, Kind); 4] = [
    ("translating", Kind::Translating),
    ("rocker", Kind::Rocker),
    ("flat", Kind::Flat),
    ("flat_rocker", Kind::FlatRocker),
];
/// The laws a scene may name, each written as [`Law::key`] gives it (the "+ −" law's ratio
/// is the scene's `ratio`, set after).
const LAWS: [Law; 7] = [
    Law::Uniform,
    Law::ConstantAcceleration { ratio: 0.5 },
    Law::Cosine,
    Law::Sine,
    Law::Trapezoidal,
    Law::Polynomial345,
    Law::LinearBlended { blend: 0.1 },
];
/// The closures, as written: geometric (the whole cycle), force (spring, the rise only).
const CLOSURES: [(&str, Closure); 2] =
    [("geometric", Closure::Geometric), ("force", Closure::Force)];
/// The rocker's senses, as written: with the cam on the rise, or against it.
const SENSES: [(&str, RockerSense); 2] = [
    ("same", RockerSense::Same),
    ("opposite", RockerSense::Opposite),
];
/// What the diagrams are given by, as written: d²S/dφ² (integrated) or S (differentiated).
const GIVEN: [(&str, Given); 2] = [("d2s", Given::D2s), ("s", Given::S)];
/// The cam's rotation, as written: counter-clockwise or clockwise.
const ROTATIONS: [(&str, Rotation); 2] = [("ccw", Rotation::Ccw), ("cw", Rotation::Cw)];

/// The kind of follower a scene names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Translating,
    Rocker,
    Flat,
    /// A rocker with a flat face ([`crate::cam::flat_rocker`]).
    FlatRocker,
}
/// The most intervals per moving phase a scene may ask for.
const MAX_DIVISIONS: i64 = 720;
/// γ_min, degrees: below 10° the pressure angle may reach 80° and the cam shrinks to a point
/// (γ_min → 0 gives r_min → 0); above 80° r_min grows without bound.
const GAMMA_MIN_DEG: (f64, f64) = (10.0, 80.0);
/// The "+ −" law's share of positive acceleration: beyond it one acceleration is over 19
/// times the other and the diagrams cannot be drawn at one scale.
const RATIO: (f64, f64) = (0.1, 0.9);
/// The share of each blend of the "linear with blends" law: below 0.05 its acceleration
/// is over 20 times the uniform velocity's and the diagrams cannot be drawn at one scale.
const BLEND: (f64, f64) = (0.05, 0.5);
/// The pole distances H₁, H₂, mm: within a sheet.
const POLE_MM: (f64, f64) = (5.0, 200.0);
/// The shortest rise or return, degrees.
const MIN_MOVING_DEG: f64 = 1.0;

/// Validate `[cam]`.
pub(crate) fn cam(check: &mut Checker, raw: &RawCam) -> Option<CamSpec> {
    let before = check.problems.len();
    let kind = check.word(&key("follower"), raw.follower.as_ref(), &FOLLOWERS);
    let (rise, ret) = laws(check, raw);
    let phases = phases(check, raw.phases.as_deref());
    let (follower, stroke) = follower(check, raw, kind);
    let (roller, base_radius) = radii(check, raw, follower);
    let gamma_min = gamma_min(check, raw.gamma_min);
    let rho_min = rho_min(check, raw.rho_min);
    let divisions = divisions(check, raw.divisions);
    let poles = poles(check, raw.poles.as_deref());
    let closure = check.word_or_first(&key("closure"), raw.closure.as_ref(), &CLOSURES);
    let given = check.word_or_first(&key("given"), raw.given.as_ref(), &GIVEN);
    let rotation = check.word_or_first(&key("rotation"), raw.rotation.as_ref(), &ROTATIONS);
    let spec = CamSpec {
        phases,
        rise,
        ret,
        stroke,
        follower,
        roller,
        gamma_min,
        rho_min,
        base_radius,
        divisions,
        scale_s: check.scale(
            Key::CamScaleS.path(),
            raw.scale_s,
            Quantity::Length,
            "a scale μ_S > 0 m/mm",
        ),
        scale_l: check.scale(
            Key::CamScaleL.path(),
            raw.scale_l,
            Quantity::Length,
            "a scale μ_l > 0 m/mm",
        ),
        scale_phi: check.scale(
            Key::CamScalePhi.path(),
            raw.scale_phi,
            Quantity::Angle,
            "a scale μ_φ > 0 rad/mm",
        ),
        poles,
        law_assumed: raw.law_assumed.unwrap_or(false),
        quoted_r_min: raw
            .quoted_r_min
            .map(|mm| check.length(&key("quoted_r_min"), Some(mm))),
        closure,
        given,
        rotation,
        layout: CamLayout::Turning,
    };
    let spec = super::cam_layout::laid_out(check, raw, kind == Some(Kind::FlatRocker), spec);
    for (k, scale) in [
        (Key::CamScaleS, spec.scale_s),
        (Key::CamScaleL, spec.scale_l),
    ] {
        super::drawing::draws(check, k.path(), scale, "the stroke S_max", spec.stroke);
    }
    super::drawing::turn_axis(check, Key::CamScalePhi.path(), spec.scale_phi, "the cam's");
    (check.problems.len() == before).then_some(spec)
}

/// The laws of the rise and the return (the return's as the rise's unless given), with the
/// "+ −" law's `ratio`.
fn laws(check: &mut Checker, raw: &RawCam) -> (Law, Law) {
    let ratio = match raw.ratio {
        Some(r) if r.is_finite() && r >= RATIO.0 && r <= RATIO.1 => r,
        Some(r) => {
            check.push(
                key("ratio"),
                Some(number(r)),
                format!(
                    "expected the share of the phase with positive acceleration, {} ≤ ratio ≤ {}",
                    RATIO.0, RATIO.1
                ),
            );
            0.5
        }
        None => 0.5,
    };
    let blend = match raw.blend {
        Some(b) if b.is_finite() && b >= BLEND.0 && b <= BLEND.1 => b,
        Some(b) => {
            check.push(
                key("blend"),
                Some(number(b)),
                format!(
                    "expected the share of the phase each blend takes, {} ≤ blend ≤ {}",
                    BLEND.0, BLEND.1
                ),
            );
            0.1
        }
        None => 0.1,
    };
    let law_of = |check: &mut Checker, k: &str, v: Option<&String>| -> Law {
        match check.word(&key(k), v, &LAWS.map(|law| (law.key(), law))) {
            Some(Law::ConstantAcceleration { .. }) => Law::ConstantAcceleration { ratio },
            Some(Law::LinearBlended { .. }) => Law::LinearBlended { blend },
            Some(law) => law,
            None => Law::Cosine,
        }
    };
    let rise = law_of(check, "law", raw.law.as_ref());
    let ret = match raw.return_law.as_ref() {
        Some(v) => law_of(check, "return_law", Some(v)),
        None => rise,
    };
    (rise, ret)
}

/// The follower of `kind` (a rocker's arm and sense, the offset) and its stroke: in mm, or a
/// rocker's swing in degrees × its arm.
fn follower(check: &mut Checker, raw: &RawCam, kind: Option<Kind>) -> (Follower, f64) {
    let arm = match kind {
        Some(Kind::Rocker | Kind::FlatRocker) => Some(check.length(&key("arm"), raw.arm)),
        _ => {
            if raw.arm.is_some() || raw.swing.is_some() || raw.sense.is_some() {
                check.push(
                    key("arm"),
                    None,
                    "`arm`, `swing` and `sense` belong to a rocker: expected follower = \"rocker\" or \"flat_rocker\"",
                );
            }
            None
        }
    };
    let stroke = match (raw.stroke, raw.swing, arm) {
        (Some(_), Some(_), _) => {
            check.push(
                key("stroke"),
                None,
                "expected either `stroke` (mm) or a rocker's `swing` (degrees), not both",
            );
            0.0
        }
        (Some(mm), None, _) => check.length(&key("stroke"), Some(mm)),
        (None, Some(deg), Some(l)) => {
            if deg.is_finite() && deg > 0.0 && deg < 180.0 {
                l * deg.to_radians()
            } else {
                check.push(
                    key("swing"),
                    Some(number(deg)),
                    "expected a swing β_max from 0° to 180° (exclusive)",
                );
                0.0
            }
        }
        _ => {
            check.push(
                key("stroke"),
                None,
                "missing: expected the stroke S_max > 0 mm (or, for a rocker, `swing` in degrees)",
            );
            0.0
        }
    };
    let offset = check.distance(&key("offset"), raw.offset, 0.0);
    let sense = check.word_or_first(&key("sense"), raw.sense.as_ref(), &SENSES);
    let follower = match kind {
        Some(Kind::Rocker | Kind::FlatRocker) => Follower::Rocker {
            arm: arm.unwrap_or(0.0),
            sense,
        },
        Some(Kind::Flat) => Follower::Flat { offset },
        _ => Follower::Translating { offset },
    };
    (follower, stroke)
}

/// The roller's and the base circle's radii: the roller within the base circle, the base
/// circle beyond a translating follower's offset.
fn radii(check: &mut Checker, raw: &RawCam, follower: Follower) -> (Option<f64>, Option<f64>) {
    let roller = raw.roller.map(|mm| {
        if mm == 0.0 {
            0.0
        } else {
            check.length(&key("roller"), Some(mm))
        }
    });
    let base_radius = raw
        .base_radius
        .map(|mm| check.length(&key("base_radius"), Some(mm)));
    if let (Some(r), Some(b)) = (roller, base_radius) {
        if r >= b && b > 0.0 {
            check.push(
                key("roller"),
                Some(number(r * 1e3)),
                format!(
                    "expected a roller radius smaller than the base radius {} mm",
                    number(b * 1e3)
                ),
            );
        }
    }
    if let (Some(b), Follower::Translating { offset }) = (base_radius, follower) {
        if b > 0.0 && b <= offset.abs() {
            check.push(
                key("base_radius"),
                Some(number(b * 1e3)),
                "expected a base radius larger than |offset|",
            );
        }
    }
    (roller, base_radius)
}

/// γ_min, degrees in the file, radians here (60° unless given).
fn gamma_min(check: &mut Checker, v: Option<f64>) -> f64 {
    match v {
        Some(g) if g.is_finite() && g >= GAMMA_MIN_DEG.0 && g <= GAMMA_MIN_DEG.1 => g.to_radians(),
        Some(g) => {
            check.push(
                key("gamma_min"),
                Some(number(g)),
                format!(
                    "expected γ_min in degrees, {} ≤ γ_min ≤ {} (λ_max = 90° − γ_min)",
                    GAMMA_MIN_DEG.0, GAMMA_MIN_DEG.1
                ),
            );
            FRAC_60
        }
        None => FRAC_60,
    }
}

/// The profile's smallest radius of curvature ρ_min, mm in the file, m here (0 unless given).
fn rho_min(check: &mut Checker, v: Option<f64>) -> f64 {
    match v {
        Some(mm) if mm.is_finite() && (0.0..=MAX_MM).contains(&mm) => mm * 1e-3,
        Some(mm) => {
            check.push(
                key("rho_min"),
                Some(number(mm)),
                "expected the profile's smallest radius of curvature ρ_min ≥ 0 mm and at most 1e6 mm",
            );
            0.0
        }
        None => 0.0,
    }
}

/// The intervals per rise and return (12 unless given).
fn divisions(check: &mut Checker, v: Option<i64>) -> usize {
    match v.unwrap_or(12) {
        n if (2..=MAX_DIVISIONS).contains(&n) => n as usize,
        n => {
            check.push(
                key("divisions"),
                Some(n.to_string()),
                format!("expected from 2 to {MAX_DIVISIONS} intervals per rise and return"),
            );
            12
        }
    }
}

/// The pole distances [H₁, H₂], mm.
fn poles(check: &mut Checker, v: Option<&[f64]>) -> Option<[f64; 2]> {
    match v {
        None => None,
        Some([a, b]) if [*a, *b].iter().all(|h| (POLE_MM.0..=POLE_MM.1).contains(h)) => {
            Some([*a, *b])
        }
        Some(v) => {
            check.push(
                key("poles"),
                Some(super::check::numbers(v)),
                format!(
                    "expected the pole distances [H₁, H₂] from {} to {} mm",
                    POLE_MM.0, POLE_MM.1
                ),
            );
            None
        }
    }
}

/// 60°, the default γ_min.
const FRAC_60: f64 = std::f64::consts::FRAC_PI_3;

/// `phases = [rise, far dwell, return, near dwell]`, degrees, ≥ 0, rise and return > 0,
/// summing to 360.
fn phases(check: &mut Checker, v: Option<&[f64]>) -> Phases {
    const WANT: &str =
        "the phases [rise, far dwell, return, near dwell] in degrees, summing to 360";
    let key = join(CAM, "phases");
    let fallback = Phases {
        rise: 1.0,
        far: 1.0,
        ret: 1.0,
        near: std::f64::consts::TAU - 3.0,
    };
    let Some(v) = check.required(&key, v, WANT) else {
        return fallback;
    };
    let [a, b, c, d] = v else {
        check.push(
            &key,
            Some(super::check::numbers(v)),
            format!("expected {WANT}"),
        );
        return fallback;
    };
    let mut ok = true;
    for (i, (x, moving)) in [(*a, true), (*b, false), (*c, true), (*d, false)]
        .into_iter()
        .enumerate()
    {
        let bad = !x.is_finite() || x < 0.0 || (moving && x < MIN_MOVING_DEG);
        if bad {
            let want = if moving {
                "a rise or return angle ≥ 1°"
            } else {
                "a dwell angle ≥ 0°"
            };
            check.push(item(&key, i), Some(number(x)), format!("expected {want}"));
            ok = false;
        }
    }
    let sum = a + b + c + d;
    if ok && (sum - 360.0).abs() > 1e-6 {
        check.push(
            &key,
            Some(super::check::numbers(v)),
            format!(
                "expected phases summing to 360°, they sum to {}°",
                number(sum)
            ),
        );
        ok = false;
    }
    if !ok {
        return fallback;
    }
    Phases {
        rise: a.to_radians(),
        far: b.to_radians(),
        ret: c.to_radians(),
        near: d.to_radians(),
    }
}
