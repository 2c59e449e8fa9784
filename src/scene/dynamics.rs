//! `[dynamics]` → [`DynamicsSpec`]: the mean speed and δ, the constant reduced inertias, the
//! links that count, the number of positions, the diagrams' scales, the flywheel's kind and
//! coefficients, and the seed's own numbers to check — each checked with its key path.

use super::check::{item, join, number, Checker};
use crate::dynamics::{
    ConstantInertia, ConstantMoment, DynamicsSpec, FlywheelKind, FlywheelSpec, SeedClaims,
};
use crate::forces::ForceSpec;
use crate::scale::{Key, Quantity, Scale};
use serde::Deserialize;

/// The lightest flywheel material a scene may give, kg/m³.
const MIN_RHO: f64 = 10.0;

/// The key path of the section.
const KEY: &str = "dynamics";
/// The most positions of the diagrams (one per degree).
const MAX_COUNT: i64 = 360;
/// The largest moment of inertia a scene may give, kg·m².
const MAX_J: f64 = 1e9;

/// `[dynamics]` as written.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawDynamics {
    pub omega_avg: Option<f64>,
    pub delta: Option<f64>,
    #[serde(default)]
    pub constant: Vec<RawConstant>,
    pub links: Option<Vec<i64>>,
    pub count: Option<i64>,
    pub scale_m: Option<f64>,
    pub scale_phi: Option<f64>,
    pub pole_h: Option<f64>,
    pub scale_j: Option<f64>,
    pub scale_t: Option<f64>,
    pub flywheel: Option<RawFlywheel>,
    pub seed: Option<RawSeed>,
    pub constant_moment: Option<String>,
}

/// `[[dynamics.constant]]`.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawConstant {
    pub name: Option<String>,
    pub inertia: Option<f64>,
}

/// `[dynamics.flywheel]`.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawFlywheel {
    pub kind: Option<String>,
    pub k_j: Option<f64>,
    pub k_m: Option<f64>,
    pub rho: Option<f64>,
}

/// `[dynamics.seed]`.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawSeed {
    pub flywheel: Option<f64>,
    #[serde(default)]
    pub j_red: Vec<f64>,
    pub expression: Option<Vec<f64>>,
}

/// `key` under `[dynamics]`.
fn key(k: &str) -> String {
    join(KEY, k)
}

/// Validate `[dynamics]` against `[forces]` (its links must have masses there).
pub(crate) fn dynamics(
    check: &mut Checker,
    raw: RawDynamics,
    forces: Option<&ForceSpec>,
    has_forces: bool,
) -> DynamicsSpec {
    if !has_forces {
        check.push(
            KEY,
            None,
            "[dynamics] reduces the loads of [forces]: expected a [forces] table with the masses and the resistance",
        );
    }
    let omega_avg = raw.omega_avg.map(|w| {
        check.in_range(
            &key("omega_avg"),
            w,
            1e6,
            "a mean angular velocity ω_ср > 0 rad/s (at most 1e6)",
        )
    });
    let delta = delta(check, raw.delta);
    let constant = constants(check, &raw.constant);
    let links = raw.links.as_ref().map(|ls| links(check, ls, forces));
    let count = raw.count.and_then(|n| {
        if (4..=MAX_COUNT).contains(&n) {
            u32::try_from(n).ok()
        } else {
            check.push(
                key("count"),
                Some(n.to_string()),
                format!("expected a number of positions from 4 to {MAX_COUNT}"),
            );
            None
        }
    });
    let [scale_m, scale_phi, scale_j, scale_t] = scales(check, &raw);
    // The pole distance of the work diagram's integration: a drawn length, within the
    // range of every graphical integration's pole.
    let pole_h = raw.pole_h;
    super::drawing::pole(check, &key("pole_h"), pole_h, "a pole distance H");
    let flywheel = flywheel(check, raw.flywheel.unwrap_or_default());
    let seed = raw.seed.map(|s| seed(check, s));
    let constant_moment = check.word_or_first(
        &key("constant_moment"),
        raw.constant_moment.as_ref(),
        &[
            ("driving", ConstantMoment::Driving),
            ("resisting", ConstantMoment::Resisting),
        ],
    );
    DynamicsSpec {
        constant_moment,
        omega_avg,
        delta,
        constant,
        links,
        count,
        scale_m,
        scale_phi,
        pole_h,
        scale_j,
        scale_t,
        flywheel,
        seed,
    }
}

/// The coefficient of irregularity δ, 0 < δ < 1.
fn delta(check: &mut Checker, v: Option<f64>) -> f64 {
    match check.required(
        &key("delta"),
        v,
        "the coefficient of irregularity δ, 0 < δ < 1",
    ) {
        Some(d) if d.is_finite() && d > 0.0 && d < 1.0 => d,
        Some(d) => {
            check.push(
                key("delta"),
                Some(number(d)),
                "expected the coefficient of irregularity δ, 0 < δ < 1 (1/15 is 0.0667)",
            );
            0.05
        }
        None => 0.05,
    }
}

/// `[[dynamics.constant]]`: the constant reduced inertias, each named (J1, J2, … unless
/// given).
fn constants(check: &mut Checker, raw: &[RawConstant]) -> Vec<ConstantInertia> {
    raw.iter()
        .enumerate()
        .map(|(i, c)| {
            let base = item(&key("constant"), i);
            let name = c.name.clone().unwrap_or_else(|| format!("J{}", i + 1));
            let inertia = match check.required(
                &join(&base, "inertia"),
                c.inertia,
                "a reduced moment of inertia ≥ 0 kg·m²",
            ) {
                Some(j) if j.is_finite() && (0.0..=MAX_J).contains(&j) => j,
                Some(j) => {
                    check.push(
                        join(&base, "inertia"),
                        Some(number(j)),
                        "expected a reduced moment of inertia ≥ 0 kg·m² (at most 1e9)",
                    );
                    0.0
                }
                None => 0.0,
            };
            ConstantInertia { name, inertia }
        })
        .collect()
}

/// `links`: the link numbers whose masses count, each with a `[[forces.link]]`.
fn links(check: &mut Checker, ls: &[i64], forces: Option<&ForceSpec>) -> Vec<u32> {
    let base = key("links");
    if ls.is_empty() {
        check.push(
            &base,
            Some("[]".into()),
            "expected the link numbers whose masses count ([3, 5])",
        );
    }
    ls.iter()
        .enumerate()
        .filter_map(|(i, &l)| {
            let k = item(&base, i);
            let l = check.link(&k, l, 1)?;
            if let Some(f) = forces {
                if !f.links.iter().any(|m| m.link == l) {
                    check.push(
                        k,
                        Some(l.to_string()),
                        "expected a link with a [[forces.link]] (its mass)",
                    );
                    return None;
                }
            }
            Some(l)
        })
        .collect()
}

/// The diagrams' scales μ_M, μ_φ (with its turn's axis), μ_J, μ_T.
fn scales(check: &mut Checker, raw: &RawDynamics) -> [Option<Scale>; 4] {
    let scale = |check: &mut Checker, k: Key, v: Option<f64>, q: Quantity, want: &str| {
        check.free_scale(k.path(), v, q, want)
    };
    let scale_m = scale(
        check,
        Key::DynamicsScaleM,
        raw.scale_m,
        Quantity::Moment,
        "a scale μ_M > 0 N·m/mm",
    );
    let scale_phi = scale(
        check,
        Key::DynamicsScalePhi,
        raw.scale_phi,
        Quantity::Angle,
        "a scale μ_φ > 0 rad/mm",
    );
    super::drawing::turn_axis(
        check,
        Key::DynamicsScalePhi.path(),
        scale_phi,
        "the crank's",
    );
    let scale_j = scale(
        check,
        Key::DynamicsScaleJ,
        raw.scale_j,
        Quantity::Inertia,
        "a scale μ_J > 0 kg·m²/mm",
    );
    let scale_t = scale(
        check,
        Key::DynamicsScaleT,
        raw.scale_t,
        Quantity::Work,
        "a scale μ_T > 0 J/mm",
    );
    [scale_m, scale_phi, scale_j, scale_t]
}

/// `[dynamics.flywheel]`: `kind` "rim" (the seed's coefficients by default) or "disc".
fn flywheel(check: &mut Checker, raw: RawFlywheel) -> FlywheelSpec {
    let key = |k: &str| join(&join(KEY, "flywheel"), k);
    let kind = check.word_or_first(
        &key("kind"),
        raw.kind.as_ref(),
        &[("rim", FlywheelKind::Rim), ("disc", FlywheelKind::Disc)],
    );
    let rho = raw.rho.map_or(FlywheelSpec::SEED_RIM.rho, |r| {
        // From cork to the densest metals (osmium 22 590 kg/m³), with room either side.
        if r.is_finite() && r < MIN_RHO {
            let want = "expected a density ρ in [10, 1e5] kg/m³";
            check.push(key("rho"), Some(number(r)), want);
            return 0.0;
        }
        check.in_range(&key("rho"), r, 1e5, "a density ρ in [10, 1e5] kg/m³")
    });
    let base = match kind {
        FlywheelKind::Rim => FlywheelSpec {
            rho,
            ..FlywheelSpec::SEED_RIM
        },
        FlywheelKind::Disc => FlywheelSpec::disc(rho),
    };
    let k_j = raw.k_j.map_or(base.k_j, |k| {
        check.in_range(&key("k_j"), k, 10.0, "a coefficient K_j > 0 (J = K_j·ρ·D⁵)")
    });
    let k_m = raw.k_m.map_or(base.k_m, |k| {
        check.in_range(&key("k_m"), k, 10.0, "a coefficient K_m > 0 (m = K_m·ρ·D³)")
    });
    FlywheelSpec { k_j, k_m, ..base }
}

/// `[dynamics.seed]`: the seed's flywheel, its J_пр table, its expression's numbers.
fn seed(check: &mut Checker, raw: RawSeed) -> SeedClaims {
    let key = |k: &str| join(&join(KEY, "seed"), k);
    let flywheel = raw
        .flywheel
        .map(|j| check.in_range(&key("flywheel"), j, MAX_J, "the seed's flywheel, kg·m² > 0"));
    for (i, &j) in raw.j_red.iter().enumerate() {
        check.in_range(
            &item(&key("j_red"), i),
            j,
            MAX_J,
            "a reduced moment of inertia > 0 kg·m²",
        );
    }
    let expression = raw.expression.and_then(|v| match v.as_slice() {
        [a, b, c, d] if v.iter().all(|x| x.is_finite()) => Some([*a, *b, *c, *d]),
        _ => {
            check.push(
                key("expression"),
                Some(super::check::numbers(&v[..])),
                "expected [μ_T J/mm, BD mm, J_b, J_d kg·m²]",
            );
            None
        }
    });
    SeedClaims {
        flywheel,
        j_red: raw.j_red,
        expression,
    }
}
