//! `[friction]` → the friction cases ([`FrictionCase`]): one `[[friction.case]]` per task,
//! its keys named by what they are (`angle` of an incline, `groove` of a wedge, `lead` and
//! `profile` of a screw), each checked with its key path and converted to SI (N, m, rad).

use super::check::{item, join, number, quoted, Checker};
use super::friction_case::{angle, coefficient, force, RawCase, MAX_FORCE};
use crate::friction::{
    CaseKind, FrictionCase, Incline, Journal, Motion, Rolling, Screw, Slider, Wedge,
};
use crate::scale::Quantity;
use serde::Deserialize;

/// The key path of the section.
const SECTION: &str = "friction.case";
/// The kinds, as written.
const KINDS: [(&str, Kind); 8] = [
    ("incline", Kind::Incline),
    ("wedge", Kind::Wedge),
    ("screw", Kind::Screw),
    ("journal", Kind::Journal),
    ("rolling", Kind::Rolling),
    ("slider", Kind::Slider),
    ("guide", Kind::Guide),
    ("pivot", Kind::Pivot),
];

/// The kind of a friction case a scene names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Incline,
    Wedge,
    Screw,
    Journal,
    Rolling,
    Slider,
    Guide,
    Pivot,
}

impl Kind {
    /// The kind as scenes write it.
    fn word(self) -> &'static str {
        KINDS
            .iter()
            .find(|(_, k)| *k == self)
            .map_or("", |(w, _)| w)
    }

    /// The keys the kind takes (besides `kind`, `name`, `scale_f`).
    fn keys(self) -> &'static [&'static str] {
        match self {
            Kind::Incline => &["load", "f", "angle", "force_angle", "motion"],
            Kind::Wedge => &["load", "f", "groove"],
            Kind::Screw => &["load", "f", "lead", "profile", "radius", "motion"],
            Kind::Journal => &["load", "f", "radius", "rotation"],
            Kind::Rolling => &["load", "roller_weight", "diameter", "k1", "k2", "f1", "f2"],
            Kind::Slider => &["load", "f", "f0", "angle"],
            Kind::Guide => &["load", "f", "angle", "length", "overhang"],
            Kind::Pivot => &["moment", "f", "angle", "arm", "diameter"],
        }
    }
}

/// `[friction]`.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawFriction {
    #[serde(default)]
    pub case: Vec<RawCase>,
}

/// Validate `[friction]`: every case, its keys by kind, unique names.
pub(crate) fn friction(check: &mut Checker, raw: Option<RawFriction>) -> Vec<FrictionCase> {
    let Some(raw) = raw else {
        return Vec::new();
    };
    if raw.case.is_empty() {
        let expected = "missing: expected at least one [[friction.case]] (kind = \"incline\", …)";
        check.push(SECTION, None, expected);
    }
    let mut out: Vec<FrictionCase> = Vec::new();
    for (i, c) in raw.case.iter().enumerate() {
        let base = item(SECTION, i);
        let Some(kind) = check.word(&join(&base, "kind"), c.kind.as_ref(), &KINDS) else {
            continue;
        };
        let word = kind.word();
        for key in c.present() {
            if !kind.keys().contains(&key) {
                let expected = format!(
                    "not a key of kind {}: expected {}",
                    quoted(word),
                    kind.keys().join(", ")
                );
                check.push(join(&base, key), None, expected);
            }
        }
        let name = case_name(check, &base, c.name.as_deref(), word, i, &out);
        let scale_f = check.free_scale(
            &join(&base, "scale_f"),
            c.scale_f,
            Quantity::Force,
            "a scale μ_F > 0 N/mm",
        );
        let kind = match kind {
            Kind::Incline => incline(check, &base, c),
            Kind::Wedge => CaseKind::Wedge(Wedge {
                load: force(check, &base, "load", c.load),
                f: coefficient(check, &base, "f", c.f),
                groove: groove(check, &base, c.groove),
            }),
            Kind::Screw => screw(check, &base, c),
            Kind::Journal => CaseKind::Journal(Journal {
                load: force(check, &base, "load", c.load),
                f: coefficient(check, &base, "f", c.f),
                radius: check.length(&join(&base, "radius"), c.radius),
                sense: check.word_or_first(
                    &join(&base, "rotation"),
                    c.rotation.as_ref(),
                    &[("ccw", 1.0), ("cw", -1.0)],
                ),
            }),
            Kind::Rolling => rolling(check, &base, c),
            Kind::Slider => slider(check, &base, c),
            Kind::Guide => super::follower::guide(check, &base, c),
            Kind::Pivot => super::follower::pivot(check, &base, c),
        };
        out.push(FrictionCase {
            name,
            kind,
            scale_f,
            scale_l: None,
        });
    }
    out
}

/// The case's name: as given (unique, a word of letters, digits, `-` and `_`) or the kind
/// with the case's number (`incline1`).
fn case_name(
    check: &mut Checker,
    base: &str,
    given: Option<&str>,
    kind: &str,
    i: usize,
    before: &[FrictionCase],
) -> String {
    let key = join(base, "name");
    let name = match given {
        Some(n) => {
            let word = !n.is_empty()
                && n.chars()
                    .all(|ch| ch.is_alphanumeric() || ch == '-' || ch == '_');
            if !word {
                let expected = "expected a name of letters, digits, `-` and `_`";
                check.push(&key, Some(quoted(n)), expected);
            }
            n.to_string()
        }
        None => format!("{kind}{}", i + 1),
    };
    if before.iter().any(|c| c.name == name) {
        let expected = "expected a name no other [[friction.case]] has";
        check.push(key, Some(quoted(&name)), expected);
    }
    name
}

/// A slider pressed at `angle` from the normal; f₀ (static) defaults to f and is not below it.
fn slider(check: &mut Checker, base: &str, c: &RawCase) -> CaseKind {
    let f = coefficient(check, base, "f", c.f);
    let f0 = match c.f0 {
        Some(v) => {
            let f0 = coefficient(check, base, "f0", Some(v));
            if f0 < f {
                let expected = format!(
                    "expected the static coefficient f₀ ≥ f = {} (a slider at rest holds at least as well as a sliding one)",
                    number(f)
                );
                check.push(join(base, "f0"), Some(number(v)), expected);
            }
            f0
        }
        None => f,
    };
    CaseKind::Slider(Slider {
        load: force(check, base, "load", c.load),
        f,
        f0,
        alpha: angle(check, base, "angle", c.angle, None, (0.0, 89.0), true),
    })
}

/// An inclined plane.
fn incline(check: &mut Checker, base: &str, c: &RawCase) -> CaseKind {
    let motion = motion(check, base, c.motion.as_ref());
    // Down the plane needs a slope; up it may be level (the friction cone's case).
    let alpha = angle(
        check,
        base,
        "angle",
        c.angle,
        None,
        (0.0, 89.0),
        motion == Motion::Up,
    );
    CaseKind::Incline(Incline {
        load: force(check, base, "load", c.load),
        f: coefficient(check, base, "f", c.f),
        alpha,
        beta: angle(
            check,
            base,
            "force_angle",
            c.force_angle,
            Some(0.0),
            (-89.0, 89.0),
            true,
        ),
        motion,
    })
}

/// A screw pair.
fn screw(check: &mut Checker, base: &str, c: &RawCase) -> CaseKind {
    CaseKind::Screw(Screw {
        load: force(check, base, "load", c.load),
        f: coefficient(check, base, "f", c.f),
        lead: angle(check, base, "lead", c.lead, None, (0.0, 89.0), false),
        profile: angle(
            check,
            base,
            "profile",
            c.profile,
            Some(0.0),
            (0.0, 170.0),
            true,
        ),
        radius: check.length(&join(base, "radius"), c.radius),
        motion: motion(check, base, c.motion.as_ref()),
    })
}

/// W3: a load on rollers.
fn rolling(check: &mut Checker, base: &str, c: &RawCase) -> CaseKind {
    let weight_key = join(base, "roller_weight");
    let weight = match c.roller_weight {
        None => 0.0,
        Some(g) if g.is_finite() && (0.0..=MAX_FORCE).contains(&g) => g,
        Some(g) => {
            let expected = "expected a roller weight ≥ 0 N and at most 1e9 N";
            check.push(weight_key, Some(number(g)), expected);
            0.0
        }
    };
    CaseKind::Rolling(Rolling {
        load: force(check, base, "load", c.load),
        roller_weight: weight,
        diameter: check.length(&join(base, "diameter"), c.diameter),
        k1: check.length(&join(base, "k1"), c.k1),
        k2: check.length(&join(base, "k2"), c.k2),
        f1: coefficient(check, base, "f1", c.f1),
        f2: coefficient(check, base, "f2", c.f2),
    })
}

/// A wedge's groove angle, degrees in (0°, 180°): at 180° the groove is a flat plane and the
/// wedge has no sides to press on.
fn groove(check: &mut Checker, base: &str, v: Option<f64>) -> f64 {
    match v {
        Some(deg) if deg >= 180.0 => {
            let want = "expected an angle in (0°, 180°) (at 180° the groove is flat: no wedge)";
            check.push(join(base, "groove"), Some(number(deg)), want);
            0.0
        }
        _ => angle(check, base, "groove", v, None, (0.0, 180.0), false),
    }
}

/// `motion = "up" | "down"` (default up).
fn motion(check: &mut Checker, base: &str, v: Option<&String>) -> Motion {
    let table = [("up", Motion::Up), ("down", Motion::Down)];
    check.word_or_first(&join(base, "motion"), v, &table)
}

#[cfg(test)]
mod tests {
    use crate::friction::CaseKind;
    use crate::scene::{load, parse, PlateKind};
    use std::path::Path;

    fn wanted(msg: &str, part: &str) {
        assert!(msg.contains(part), "wanted {part:?} in:\n{msg}");
    }

    fn problems(text: &str) -> String {
        match parse(text, Path::new("constructions/x.toml")) {
            Ok(_) => panic!("should be refused:\n{text}"),
            Err(e) => e.to_string(),
        }
    }

    #[test]
    fn the_friction_scene_loads_in_si_units() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("constructions/friction.toml");
        let s = load(&path).unwrap_or_else(|e| panic!("{e}"));
        assert!(s.mechanism.is_none());
        assert_eq!(s.plates, vec![PlateKind::Friction]);
        assert_eq!(s.friction.len(), 7);
        match s.friction[3].kind {
            CaseKind::Screw(c) => {
                assert!((c.radius - 0.009).abs() < 1e-15);
                assert!((c.profile - 60f64.to_radians()).abs() < 1e-15);
            }
            other => panic!("{other:?}"),
        }
        match s.friction[5].kind {
            CaseKind::Rolling(c) => {
                assert!((c.k1 - 0.05e-3).abs() < 1e-18 && (c.diameter - 0.1).abs() < 1e-15);
            }
            other => panic!("{other:?}"),
        }
        match s.friction[6].kind {
            CaseKind::Slider(c) => {
                assert_eq!((c.f, c.f0), (0.2, 0.5));
                assert!((c.alpha - 15f64.to_radians()).abs() < 1e-15);
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn bad_values_are_named_by_key() {
        let text = r#"
[[friction.case]]
kind = "incline"
load = 100.0
f = 0.1
angle = 10.0

[[friction.case]]
kind = "wedge"
load = -5.0
f = 0.1
groove = 0.0

[[friction.case]]
kind = "incline"
load = 100.0
f = 0.0
angle = 95.0
motion = "sideways"
groove = 30.0

[[friction.case]]
kind = "journal"
load = 10.0
f = nan
radius = 0.0
rotation = "left"

[[friction.case]]
kind = "spring"
"#;
        let msg = problems(text);
        for part in [
            "friction.case[1].load = -5: expected a force > 0 N",
            "friction.case[1].groove = 0: expected an angle in (0°, 180°]",
            "friction.case[2].f = 0: expected a coefficient of friction > 0",
            "friction.case[2].angle = 95",
            "friction.case[2].motion = \"sideways\"",
            "friction.case[2].groove: not a key of kind \"incline\"",
            "friction.case[3].f = nan",
            "friction.case[3].radius = 0",
            "friction.case[3].rotation = \"left\"",
            "friction.case[4].kind = \"spring\"",
        ] {
            wanted(&msg, part);
        }
    }

    #[test]
    fn missing_keys_duplicate_names_and_empty_sections_are_refused() {
        let msg = problems("[friction]\n");
        assert!(msg.contains("friction.case: missing"), "{msg}");
        let text = r#"
[[friction.case]]
kind = "screw"
name = "a"
f = 0.1
radius = 5.0

[[friction.case]]
kind = "rolling"
name = "a"
load = 1.0
"#;
        let msg = problems(text);
        for part in [
            "friction.case[0].load: missing",
            "friction.case[0].lead: missing",
            "friction.case[1].name = \"a\": expected a name no other",
            "friction.case[1].diameter: missing",
            "friction.case[1].f2: missing",
        ] {
            wanted(&msg, part);
        }
    }

    #[test]
    fn a_friction_plate_needs_a_friction_section() {
        let msg = problems("[plates]\nwanted = [\"friction\"]\n");
        assert!(
            msg.contains(
                "plates.wanted[0] = \"friction\": the friction plate draws from [friction]"
            ),
            "{msg}"
        );
    }
}
