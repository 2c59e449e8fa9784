//! `[forces]` → [`ForceSpec`]: masses, centres of mass, moments of inertia, gravity, the
//! working resistance, the drive of the crank and the positions of the force analysis, each
//! checked with its key path and converted to SI.

use super::check::{item, join, number, quoted, Checker};
use super::kinematics::{point, point_names, position_labels};
use super::raw::{RawDrive, RawForces, RawLinkLoad, RawPairFriction, RawResistance};
use crate::forces::{carrier, PairFriction};
use crate::forces::{Action, Drive, ForceSpec, GearDrive, LinkMass, Resistance, Stroke};
use crate::linkage::{Mechanism, Program};
use crate::scale::{Key, Quantity};

/// The key path of the section.
const KEY: &str = "forces";
/// The most positions a scene may analyse (one sheet each).
const MAX_POSITIONS: usize = 4;
/// The largest mass a scene may give, kg.
const MAX_MASS: f64 = 1e6;
/// The largest force or moment a scene may give, N (N·m).
const MAX_LOAD: f64 = 1e9;
/// The largest number of teeth.
const MAX_TEETH: i64 = 10_000;

/// Validate `[forces]` against `mechanism` (names and links are not checked when the
/// mechanism is missing: that is reported already).
pub(crate) fn forces(
    check: &mut Checker,
    raw: RawForces,
    mechanism: Option<&Mechanism>,
    count: u32,
) -> ForceSpec {
    let key = |k: &str| join(KEY, k);
    let names = mechanism.map(point_names);
    let links: Option<Vec<u32>> = mechanism.map(|m| {
        std::iter::once(m.crank.link)
            .chain(m.groups.iter().flat_map(|g| g.links))
            .collect()
    });
    let program = mechanism.and_then(|m| Program::compile(m).ok());
    let count = if count == 0 { u32::MAX } else { count };
    let g = match raw.g {
        Some(g) => check.in_range(&key("g"), g, 1e3, "g > 0 m/s², at most 1000"),
        None => crate::scale::G,
    };
    let positions = match raw.positions {
        Some(labels) => position_labels(check, &key("positions"), &labels, count, MAX_POSITIONS),
        None => {
            check.push(
                key("positions"),
                None,
                "missing: expected the labels of the positions to analyse ([\"3\"])",
            );
            Vec::new()
        }
    };
    let mut masses: Vec<LinkMass> = Vec::new();
    for (i, l) in raw.link.iter().enumerate() {
        let base = item(&key("link"), i);
        if let Some(m) = link_mass(check, &base, l, names.as_deref(), links.as_deref()) {
            if masses.iter().any(|o| o.link == m.link) {
                check.push(
                    join(&base, "link"),
                    Some(m.link.to_string()),
                    "expected a link not listed before",
                );
            } else {
                masses.push(m);
            }
        }
    }
    let resistances = raw
        .resistance
        .iter()
        .enumerate()
        .filter_map(|(i, r)| {
            let base = item(&key("resistance"), i);
            resistance(
                check,
                &base,
                r,
                names.as_deref(),
                links.as_deref(),
                program.as_ref(),
            )
        })
        .collect();
    let indicators = raw
        .indicator
        .iter()
        .enumerate()
        .filter_map(|(i, r)| {
            let base = item(&key("indicator"), i);
            super::indicator::indicator(check, &base, r, mechanism)
        })
        .collect();
    let spec = ForceSpec {
        indicators,
        g,
        gravity_dir: check.angle(&key("gravity"), raw.gravity, -90.0),
        scale_f: check.scale(
            Key::ForcesScaleF.path(),
            raw.scale_f,
            Quantity::Force,
            "a scale μ_F > 0 N/mm",
        ),
        links: masses,
        resistances,
        efficiency: raw.drive.as_ref().and_then(|d| {
            let k = join(&key("drive"), "efficiency");
            let eta = d.efficiency?;
            let ok = check.in_range(&k, eta, 1.0, "an efficiency η in (0, 1]");
            (ok > 0.0).then_some(ok)
        }),
        drive: raw
            .drive
            .map_or(Drive::Coupling, |d| drive(check, &key("drive"), &d)),
        friction: raw
            .friction
            .map(|f| pair_friction(check, &key("friction"), f, names.as_deref())),
        seed: raw
            .seed
            .iter()
            .enumerate()
            .filter_map(|(i, s)| {
                super::seed::seed_value(check, &item(&key("seed"), i), s, Some(&positions))
            })
            .collect(),
        positions,
    };
    // μ_F is measured by the largest load the scene declares (a resistance, a weight).
    let resisting = spec.resistances.iter().map(|r| match r.action {
        crate::forces::Action::Force { magnitude, .. } => magnitude,
        crate::forces::Action::Moment { .. } => 0.0,
    });
    let weights = spec.links.iter().map(|l| l.mass * spec.g);
    let largest = resisting.chain(weights).fold(0.0, f64::max);
    let what = "the largest load it declares";
    super::drawing::draws(check, Key::ForcesScaleF.path(), spec.scale_f, what, largest);
    spec
}

/// `[forces.friction]`: f, the journals' radius and the journals of their own radius.
fn pair_friction(
    check: &mut Checker,
    base: &str,
    raw: RawPairFriction,
    names: Option<&[String]>,
) -> PairFriction {
    let k = |s: &str| join(base, s);
    let f = match check.required(&k("f"), raw.f, "a coefficient of friction f > 0") {
        Some(f) => check.in_range(&k("f"), f, 1.0, "a coefficient of friction 0 < f ≤ 1"),
        None => 0.0,
    };
    let radius = match raw.radius {
        Some(0.0) | None => 0.0,
        r => check.length(&k("radius"), r),
    };
    let radii = raw
        .radii
        .unwrap_or_default()
        .into_iter()
        .filter_map(|(name, r)| {
            let key = join(&k("radii"), &name);
            let r = check.length(&key, Some(r));
            let name = match names {
                Some(_) => point(check, &key, Some(name), names)?,
                None => name,
            };
            Some((name, r))
        })
        .collect();
    PairFriction { f, radius, radii }
}

/// A link number that must be a moving link of the mechanism.
fn moving_link(
    check: &mut Checker,
    key: &str,
    v: Option<i64>,
    links: Option<&[u32]>,
) -> Option<u32> {
    let v = check.required(key, v, "a link number")?;
    let l = check.link(key, v, 1)?;
    match links {
        Some(ls) if !ls.contains(&l) => {
            let list: Vec<String> = ls.iter().map(u32::to_string).collect();
            check.push(
                key,
                Some(l.to_string()),
                format!(
                    "expected a moving link of the mechanism ({})",
                    list.join(", ")
                ),
            );
            None
        }
        _ => Some(l),
    }
}

/// A required point name, one of `names` (any name when the mechanism is missing).
fn named(
    check: &mut Checker,
    key: &str,
    v: Option<&String>,
    names: Option<&[String]>,
    expected: &str,
) -> Option<String> {
    let name = check.required(key, v, expected)?.clone();
    match names {
        Some(_) => point(check, key, Some(name), names),
        None => Some(name),
    }
}

/// A non-negative finite number at most `max`, or a problem and 0.
fn non_negative(check: &mut Checker, key: &str, v: f64, max: f64, expected: &str) -> f64 {
    if v == 0.0 {
        0.0
    } else {
        check.in_range(key, v, max, expected)
    }
}

/// `[[forces.link]]`.
fn link_mass(
    check: &mut Checker,
    base: &str,
    raw: &RawLinkLoad,
    names: Option<&[String]>,
    links: Option<&[u32]>,
) -> Option<LinkMass> {
    let k = |s: &str| join(base, s);
    let link = moving_link(check, &k("link"), raw.link, links);
    let mass = match check.required(&k("mass"), raw.mass, "a mass ≥ 0 kg") {
        Some(m) => non_negative(
            check,
            &k("mass"),
            m,
            MAX_MASS,
            "a mass ≥ 0 kg, at most 1e6 kg",
        ),
        None => 0.0,
    };
    let centre = named(
        check,
        &k("centre"),
        raw.centre.as_ref(),
        names,
        "the point at the centre of mass (\"S_3\")",
    );
    let inertia = match (raw.inertia, raw.rod) {
        (Some(_), Some(_)) => {
            check.push(
                k("rod"),
                raw.rod.map(number),
                "expected either `inertia` or `rod`, not both",
            );
            0.0
        }
        (Some(i), None) => non_negative(
            check,
            &k("inertia"),
            i,
            MAX_MASS,
            "a moment of inertia ≥ 0 kg·m²",
        ),
        // A uniform rod of length l about its middle: I_S = m·l²/12.
        (None, Some(_)) => {
            let l = check.length(&k("rod"), raw.rod);
            mass * l * l / 12.0
        }
        (None, None) => 0.0,
    };
    let length = raw.length.map(|_| check.length(&k("length"), raw.length));
    Some(LinkMass {
        link: link?,
        mass,
        centre: centre?,
        inertia,
        length,
    })
}

/// `[[forces.resistance]]`.
fn resistance(
    check: &mut Checker,
    base: &str,
    raw: &RawResistance,
    names: Option<&[String]>,
    links: Option<&[u32]>,
    program: Option<&Program>,
) -> Option<Resistance> {
    let k = |s: &str| join(base, s);
    let stroke = match raw.stroke.as_deref() {
        None => Some(Stroke::Always),
        Some(_) => check.word(
            &k("stroke"),
            raw.stroke.as_ref(),
            &[
                ("working", Stroke::Working),
                ("return", Stroke::Return),
                ("always", Stroke::Always),
            ],
        ),
    };
    let action = match (raw.force, raw.moment) {
        (Some(f), None) => {
            let magnitude = check.in_range(&k("force"), f, MAX_LOAD, "a force > 0 N");
            let point = named(
                check,
                &k("point"),
                raw.point.as_ref(),
                names,
                "the point the force acts at",
            );
            let dir = raw.dir.map(|d| check.angle(&k("dir"), Some(d), 0.0));
            let link = match raw.link {
                Some(_) => Some(moving_link(check, &k("link"), raw.link, links)?),
                None => None,
            };
            if let (Some(prog), Some(name)) = (program, point.as_ref()) {
                if let Some(at) = prog.index(name) {
                    if let Err(why) = carrier(prog, at, link) {
                        let key = if link.is_some() { "link" } else { "point" };
                        check.push(k(key), Some(quoted(name)), why.to_string());
                    }
                }
            }
            point.map(|point| Action::Force {
                point,
                link,
                magnitude,
                dir,
            })
        }
        (None, Some(m)) => {
            let magnitude = check.in_range(&k("moment"), m, MAX_LOAD, "a moment > 0 N·m");
            moving_link(check, &k("link"), raw.link, links)
                .map(|link| Action::Moment { link, magnitude })
        }
        (Some(_), Some(_)) => {
            check.push(
                base,
                None,
                "expected either `force` (with `point`) or `moment` (with `link`), not both",
            );
            None
        }
        (None, None) => {
            check.push(
                base,
                None,
                "missing: expected `force` (with `point`) or `moment` (with `link`)",
            );
            None
        }
    };
    Some(Resistance {
        action: action?,
        stroke: stroke?,
    })
}

/// `[forces.drive]`.
fn drive(check: &mut Checker, base: &str, raw: &RawDrive) -> Drive {
    let k = |s: &str| join(base, s);
    let gear = check.word(
        &k("kind"),
        raw.kind.as_ref(),
        &[("coupling", false), ("gear", true)],
    );
    if gear != Some(true) {
        // A coupling (or a kind already refused) takes no gear data.
        let gear_keys = [
            ("module", raw.module.is_some()),
            ("teeth", raw.teeth.is_some()),
            ("mate_teeth", raw.mate_teeth.is_some()),
            ("pressure_angle", raw.pressure_angle.is_some()),
            ("towards", raw.towards.is_some()),
        ];
        for (name, _) in gear_keys
            .iter()
            .filter(|(_, present)| *present && gear == Some(false))
        {
            check.push(
                k(name),
                None,
                "expected no gear data for kind = \"coupling\"",
            );
        }
        return Drive::Coupling;
    }
    let teeth = |check: &mut Checker, key: &str, v: Option<i64>| -> Option<u32> {
        match v {
            Some(z) if (1..=MAX_TEETH).contains(&z) => u32::try_from(z).ok(),
            Some(z) => {
                check.push(
                    key,
                    Some(z.to_string()),
                    format!("expected a number of teeth from 1 to {MAX_TEETH}"),
                );
                None
            }
            None => None,
        }
    };
    let module = check.length(&k("module"), raw.module);
    let z = check.required(
        &k("teeth"),
        raw.teeth,
        "the number of teeth of the crank's wheel",
    );
    let z = teeth(check, &k("teeth"), z).unwrap_or(1);
    let mate = teeth(check, &k("mate_teeth"), raw.mate_teeth);
    let alpha = check.angle(&k("pressure_angle"), raw.pressure_angle, 20.0);
    if !(alpha > 0.0 && alpha < 45f64.to_radians()) {
        check.push(
            k("pressure_angle"),
            raw.pressure_angle.map(number),
            "expected a pressure angle between 0° and 45°",
        );
    }
    Drive::Gear(GearDrive {
        module,
        teeth: z,
        mate_teeth: mate,
        pressure_angle: alpha,
        towards: check.angle(&k("towards"), raw.towards, -90.0),
    })
}
