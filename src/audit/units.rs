//! The units a student writes, as the textbooks write them: each quantity's SI unit (the
//! report's) with the units of its kind a table may carry instead (`mm` for a length, `rpm`
//! for an angular velocity, `kgf` for a force, in Latin or Cyrillic letters).

use crate::scale::{KGF, RPM};

/// A unit of one kind: its name (as the audit writes it) and its factor to the SI unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unit {
    /// The name, normalised (`mm`, `rad/s`, `kgf*m`).
    pub name: &'static str,
    /// Value in this unit × `factor` = value in SI.
    pub factor: f64,
}

const fn u(name: &'static str, factor: f64) -> Unit {
    Unit { name, factor }
}

/// The units of the kind whose SI unit (as the report writes it) is `si`, the SI unit first;
/// empty for a unit the audit does not know.
pub fn kind(si: &str) -> &'static [Unit] {
    use std::f64::consts::PI;
    const K0: &[Unit] = &[u("m", 1.0), u("mm", 1e-3), u("cm", 1e-2)];
    const K1: &[Unit] = &[u("m/s", 1.0), u("mm/s", 1e-3), u("cm/s", 1e-2)];
    const K2: &[Unit] = &[u("m/s^2", 1.0), u("mm/s^2", 1e-3), u("cm/s^2", 1e-2)];
    const K3: &[Unit] = &[u("rad/s", 1.0), u("rpm", RPM), u("deg/s", PI / 180.0)];
    const K4: &[Unit] = &[u("rad/s^2", 1.0), u("deg/s^2", PI / 180.0)];
    const K5: &[Unit] = &[u("N", 1.0), u("kN", 1e3), u("kgf", KGF)];
    const K6: &[Unit] = &[
        u("N*m", 1.0),
        u("kN*m", 1e3),
        u("kgf*m", KGF),
        u("N*mm", 1e-3),
    ];
    const K7: &[Unit] = &[u("kg", 1.0), u("g", 1e-3)];
    const K8: &[Unit] = &[u("kg*m", 1.0), u("kg*mm", 1e-3), u("g*mm", 1e-6)];
    const K9: &[Unit] = &[u("kg*m^2", 1.0), u("kgf*m*s^2", KGF)];
    const K10: &[Unit] = &[u("J", 1.0), u("kJ", 1e3), u("kgf*m", KGF)];
    const K11: &[Unit] = &[u("W", 1.0), u("kW", 1e3)];
    const K12: &[Unit] = &[u("rad", 1.0), u("deg", PI / 180.0)];
    const K13: &[Unit] = &[u("deg", 1.0), u("rad", 180.0 / PI)];
    const K14: &[Unit] = &[u("1", 1.0), u("%", 1e-2)];
    match si {
        "m" => K0,
        "m/s" => K1,
        "m/s^2" => K2,
        "rad/s" => K3,
        "rad/s^2" => K4,
        "N" => K5,
        "N*m" => K6,
        "kg" => K7,
        "kg*m" => K8,
        "kg*m^2" => K9,
        "J" => K10,
        "W" => K11,
        "rad" => K12,
        "deg" => K13,
        "1" => K14,
        _ => &[],
    }
}

/// A unit as written, normalised: `·` and spaces to `*`, `²` to `^2`, a bare power
/// (`m/s2`) to `^2`, `°` to `deg`, `1/s` and `s^-1` to `rad/s`, Cyrillic names to Latin
/// (`м/с` → `m/s`, `кгс` → `kgf`, `об/мин` → `rpm`).
pub fn normalise(written: &str) -> String {
    let mut s: String = written
        .trim()
        .replace(['·', '⋅', '×'], "*")
        .replace('²', "^2")
        .replace('³', "^3")
        .replace('°', "deg")
        .replace('−', "-");
    for (from, to) in [("об/мин", "rpm"), ("об/хв", "rpm"), ("град", "deg")] {
        s = s.replace(from, to);
    }
    // The sheets' Cyrillic names, the longest first (кгс before кг, мм before м).
    let mut words = crate::words::UNIT_WORDS;
    words.sort_by_key(|(_, cyrillic)| std::cmp::Reverse(cyrillic.chars().count()));
    for (latin, cyrillic) in words {
        s = s.replace(cyrillic, latin);
    }
    let mut out = String::new();
    let chars: Vec<char> = s.chars().filter(|c| !c.is_whitespace()).collect();
    for (k, &c) in chars.iter().enumerate() {
        // A power written without its caret: m/s2, kg*m2.
        if c.is_ascii_digit() && k > 0 && matches!(chars[k - 1], 'm' | 's') {
            out.push('^');
        }
        out.push(c);
    }
    match out.as_str() {
        "1/s" | "s^-1" => "rad/s".into(),
        "1/s^2" | "s^-2" => "rad/s^2".into(),
        "Nm" | "N*m" => "N*m".into(),
        "" | "-" => "1".into(),
        _ => out,
    }
}

/// The SI units the audit knows, as the report writes them: the kinds of [`kind`].
const SI: [&str; 15] = [
    "m", "m/s", "m/s^2", "rad/s", "rad/s^2", "N", "N*m", "kg", "kg*m", "kg*m^2", "J", "W", "rad",
    "deg", "1",
];

/// The unit `written` names, of whatever kind (for a quantity the report lacks).
pub fn any(written: &str) -> Option<Unit> {
    let name = normalise(written);
    SI.iter()
        .flat_map(|si| kind(si))
        .copied()
        .find(|u| u.name == name)
}

/// The unit of the kind of `si` that `written` names, if any.
pub fn find(si: &str, written: &str) -> Option<Unit> {
    let name = normalise(written);
    kind(si).iter().copied().find(|u| u.name == name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_textbook_unit_is_read_in_either_alphabet() {
        assert_eq!(normalise("м/с²"), "m/s^2");
        assert_eq!(normalise("м/с2"), "m/s^2");
        assert_eq!(normalise("кгс·м"), "kgf*m");
        assert_eq!(normalise("1/с"), "rad/s");
        assert_eq!(normalise("об/мин"), "rpm");
        assert_eq!(normalise("кг·м²"), "kg*m^2");
        assert_eq!(normalise("Н·м"), "N*m");
        assert_eq!(normalise("°"), "deg");
        assert_eq!(find("N", "кгс").map(|u| u.factor), Some(KGF));
        assert_eq!(find("m", "мм").map(|u| u.factor), Some(1e-3));
        assert_eq!(find("m", "kgf"), None);
        assert_eq!(any("кгс").map(|u| u.factor), Some(KGF));
        assert_eq!(any("furlong"), None);
        // Every kind is reachable.
        assert!(SI.iter().all(|si| !kind(si).is_empty()));
    }
}
