//! `[kinematics]` → [`KinematicsSpec`]: the scales and choices of the kinematic analysis, each
//! optional and checked with its key path.

use super::check::{item, quoted, Checker};
use super::raw::RawKinematics;
use crate::kinematics::KinematicsSpec;
use crate::linkage::Mechanism;
use crate::scale::{Key, Quantity};

/// The key path of the section.
const KIN: &str = "kinematics";
/// The most acceleration plans a scene may ask for.
const MAX_ACCELERATION_POSITIONS: usize = 4;
/// The prime of an extreme position's label (`8′`).
const PRIME: char = '′';

/// Validate `[kinematics]`. Point names are checked against `mechanism` (skipped when the
/// mechanism itself is missing: that is reported already), numbered position labels against
/// `count` (skipped when the count is invalid: reported already).
pub(crate) fn kinematics(
    check: &mut Checker,
    raw: RawKinematics,
    mechanism: Option<&Mechanism>,
    count: u32,
) -> KinematicsSpec {
    let key = |k: &str| format!("{KIN}.{k}");
    let names = mechanism.map(point_names);
    // An invalid count is reported already; do not refuse every label because of it.
    let count = if count == 0 { u32::MAX } else { count };
    KinematicsSpec {
        scale_v: check.scale(
            Key::KinematicsScaleV.path(),
            raw.scale_v,
            Quantity::Velocity,
            "a scale μ_v > 0 (m/s)/mm",
        ),
        scale_a: check.scale(
            Key::KinematicsScaleA.path(),
            raw.scale_a,
            Quantity::Acceleration,
            "a scale μ_a > 0 (m/s²)/mm",
        ),
        acceleration_positions: raw.acceleration_positions.map(|labels| {
            let key = key("acceleration_positions");
            position_labels(check, &key, &labels, count, MAX_ACCELERATION_POSITIONS)
        }),
        own_scale: raw
            .own_scale
            .map(|labels| {
                let key = key("own_scale");
                position_labels(check, &key, &labels, count, count as usize)
            })
            .unwrap_or_default(),
        own_scale_a: raw
            .own_scale_a
            .map(|labels| {
                let key = key("own_scale_a");
                position_labels(check, &key, &labels, count, MAX_ACCELERATION_POSITIONS)
            })
            .unwrap_or_default(),
        diagram_point: point(check, &key("diagram"), raw.diagram, names.as_deref()),
        scale_s: check.scale(
            Key::KinematicsScaleS.path(),
            raw.scale_s,
            Quantity::Length,
            "a scale μ_S > 0 m/mm",
        ),
        scale_phi: check.scale(
            Key::KinematicsScalePhi.path(),
            raw.scale_phi,
            Quantity::Angle,
            "a scale μ_φ > 0 rad/mm",
        ),
        pole_h1: check.positive_opt(&key("pole_h1"), raw.pole_h1, "a pole distance H₁ > 0 mm"),
        pole_h2: check.positive_opt(&key("pole_h2"), raw.pole_h2, "a pole distance H₂ > 0 mm"),
        hodograph: point(check, &key("hodograph"), raw.hodograph, names.as_deref()),
        tangents: match raw.differentiation.as_deref() {
            None | Some("chords") => false,
            Some("tangents") => true,
            Some(other) => {
                check.push(
                    key("differentiation"),
                    Some(quoted(other)),
                    "expected \"chords\" or \"tangents\"",
                );
                false
            }
        },
    }
}

/// Every point name of the mechanism: fixed points, the crank pin, the joints, link points.
pub(super) fn point_names(m: &Mechanism) -> Vec<String> {
    let joints = m.groups.iter().filter_map(|g| g.dyad.joint());
    m.fixed
        .iter()
        .map(|f| f.name.as_str())
        .chain(std::iter::once(m.crank.pin.as_str()))
        .chain(joints)
        .chain(m.points.iter().map(|p| p.name.as_str()))
        .map(str::to_string)
        .collect()
}

/// An optional point name that must be one of `names` (unchecked when `names` is `None`).
pub(super) fn point(
    check: &mut Checker,
    key: &str,
    v: Option<String>,
    names: Option<&[String]>,
) -> Option<String> {
    let name = v?;
    let names = names?;
    if names.contains(&name) {
        Some(name)
    } else {
        let expected = format!("expected a point of the mechanism ({})", names.join(", "));
        check.push(key, Some(quoted(&name)), expected);
        None
    }
}

/// A list of 1–`max` distinct labels `k` or `k′` (an ASCII `'` becomes `′`) with
/// 1 ≤ k ≤ `count`. Whether an extreme `k′` exists is known only once the plan is built.
pub(super) fn position_labels(
    check: &mut Checker,
    key: &str,
    labels: &[String],
    count: u32,
    max: usize,
) -> Vec<String> {
    if !(1..=max).contains(&labels.len()) {
        let expected = format!("expected 1 to {max} position labels (\"3\", \"8′\")");
        check.push(key, Some(format!("{labels:?}")), expected);
    }
    let mut out: Vec<String> = Vec::new();
    for (i, label) in labels.iter().enumerate() {
        let key = item(key, i);
        let Some(label) = position_label(label, count) else {
            let expected = format!(
                "expected a position label from \"1\" to \"{count}\", or an extreme \"k′\" with k \
                 in that range"
            );
            check.push(&key, Some(quoted(label)), expected);
            continue;
        };
        if out.contains(&label) {
            check.push(
                &key,
                Some(quoted(&label)),
                "expected a label not listed before",
            );
        } else {
            out.push(label);
        }
    }
    out
}

/// The normalised label (`8'` → `8′`) when it is `k` or `k′` with 1 ≤ k ≤ `count`.
fn position_label(label: &str, count: u32) -> Option<String> {
    let trimmed = label.trim();
    let (number, prime) = match trimmed.strip_suffix(['\'', PRIME]) {
        Some(n) => (n, true),
        None => (trimmed, false),
    };
    if number.is_empty() || !number.chars().all(|c| c.is_ascii_digit()) {
        return None;
    }
    let k: u32 = number.parse().ok()?;
    (1..=count).contains(&k).then(|| {
        let mut s = k.to_string();
        if prime {
            s.push(PRIME);
        }
        s
    })
}

#[cfg(test)]
mod tests {
    use super::position_label;

    #[test]
    fn labels_are_normalised_and_bounded() {
        assert_eq!(position_label("3", 12).as_deref(), Some("3"));
        assert_eq!(position_label("8'", 12).as_deref(), Some("8′"));
        assert_eq!(position_label("8′", 12).as_deref(), Some("8′"));
        assert_eq!(position_label("13", 12), None);
        assert_eq!(position_label("0", 12), None);
        assert_eq!(position_label("′", 12), None);
        assert_eq!(position_label("+3", 12), None);
        assert_eq!(position_label("99999999999999", 12), None);
    }
}
