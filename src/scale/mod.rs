//! μ scales: physical units per drawing millimetre, with their unit, chosen the textbook way
//! and captioned per language.

use std::fmt::Write as _;

mod key;
mod latin;
mod localised;

pub use key::Key;
pub(crate) use key::DRAWN_MM;
pub use latin::latin;
pub use localised::Localised;

/// The acceleration of gravity the course computes weights with (G = m·g), m/s²: the
/// textbooks' 9,81 (seed 001), the default of `[forces] g`.
pub const G: f64 = 9.81;

/// One kilogram-force, N: a kilogram under the standard gravity 9,80665 m/s² (the unit the
/// older textbooks give forces and moments in, read in a seed's values and by the audit).
pub const KGF: f64 = 9.806_65;

/// One revolution per minute, rad/s (a shaft's speed n, rpm, as ω = πn/30).
pub const RPM: f64 = std::f64::consts::PI / 30.0;

/// A shaft's ω, rad/s, from its speed `n`, rpm: πn/30 (the scene's `n`, a train's input).
pub fn from_rpm(n: f64) -> f64 {
    std::f64::consts::PI * n / 30.0
}

/// A shaft's speed, rpm, from its ω `w`, rad/s: 30ω/π.
pub fn to_rpm(w: f64) -> f64 {
    w * 30.0 / std::f64::consts::PI
}

/// The label language of a plate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Lang {
    /// Russian (the textbooks' language; default).
    #[default]
    Ru,
    /// Ukrainian.
    Uk,
    /// English.
    En,
}

impl Lang {
    /// Parse `ru`, `uk` or `en`.
    pub fn parse(s: &str) -> Option<Self> {
        match s {
            "ru" => Some(Lang::Ru),
            "uk" => Some(Lang::Uk),
            "en" => Some(Lang::En),
            _ => None,
        }
    }
    /// Decimal separator: a comma in ru/uk, a point in en.
    pub fn decimal(self) -> char {
        match self {
            Lang::En => '.',
            _ => ',',
        }
    }
    /// Pick the text for this language.
    pub fn pick<'a>(self, ru: &'a str, uk: &'a str, en: &'a str) -> &'a str {
        match self {
            Lang::Ru => ru,
            Lang::Uk => uk,
            Lang::En => en,
        }
    }
}

/// What a scale measures, which fixes its SI unit per millimetre.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// Length, m/mm (μ_l).
    Length,
    /// Velocity, (m/s)/mm (μ_v).
    Velocity,
    /// Acceleration, (m/s²)/mm (μ_a).
    Acceleration,
    /// Angle, rad/mm (μ_φ).
    Angle,
    /// Time, s/mm (μ_t).
    Time,
    /// Force, N/mm (μ_F).
    Force,
    /// Moment, N·m/mm (μ_M).
    Moment,
    /// Work or energy, J/mm (μ_A).
    Work,
    /// Moment of inertia, kg·m²/mm (μ_J).
    Inertia,
    /// Angular velocity, (rad/s)/mm (μ_ω).
    AngularVelocity,
    /// Angular acceleration, (rad/s²)/mm (μ_ε).
    AngularAcceleration,
    /// Static moment of a mass m·ρ (an unbalance), kg·m/mm (μ_mρ, the textbook's K_mρ).
    StaticMoment,
    /// Moment of an unbalance about a plane m·ρ·z, kg·m²/mm (μ_mρz).
    UnbalanceMoment,
    /// The velocity analogue dS/dφ of a follower, m/(rad·mm) (μ_S′).
    VelocityAnalogue,
    /// The acceleration analogue d²S/dφ² of a follower, m/(rad²·mm) (μ_S″).
    AccelerationAnalogue,
    /// Pressure, Pa/mm (μ_p of an indicator diagram, written in MPa/mm).
    Pressure,
}

impl Quantity {
    /// The units of the quantity, one row per quantity: its SI unit (diagnostics, reports;
    /// plain text) and the unit of its μ — the SI unit per drawing millimetre, a pressure's
    /// MPa ([`Quantity::caption_multiple`]) — in captions
    /// (label markup), English and Cyrillic (ru and uk write it alike).
    fn units(self) -> Units {
        use Quantity::*;
        let (si, en, cyrillic) = match self {
            Length => ("m", "m/mm", "м/мм"),
            Velocity => ("m/s", "m/(s·mm)", "м/(с·мм)"),
            Acceleration => ("m/s²", "m/(s^2·mm)", "м/(с^2·мм)"),
            Angle => ("rad", "rad/mm", "рад/мм"),
            Time => ("s", "s/mm", "с/мм"),
            Force => ("N", "N/mm", "Н/мм"),
            Moment => ("N·m", "N·m/mm", "Н·м/мм"),
            Work => ("J", "J/mm", "Дж/мм"),
            Inertia => ("kg·m²", "kg·m^2/mm", "кг·м^2/мм"),
            AngularVelocity => ("rad/s", "rad/(s·mm)", "рад/(с·мм)"),
            AngularAcceleration => ("rad/s²", "rad/(s^2·mm)", "рад/(с^2·мм)"),
            StaticMoment => ("kg·m", "kg·m/mm", "кг·м/мм"),
            UnbalanceMoment => ("kg·m²", "kg·m^2/mm", "кг·м^2/мм"),
            VelocityAnalogue => ("m/rad", "m/(rad·mm)", "м/(рад·мм)"),
            AccelerationAnalogue => ("m/rad²", "m/(rad^2·mm)", "м/(рад^2·мм)"),
            Pressure => ("Pa", "MPa/mm", "МПа/мм"),
        };
        Units { si, en, cyrillic }
    }
    /// Unit of the scale as written in captions, per language. `/мм` is the drawing millimetre.
    pub fn unit(self, lang: Lang) -> &'static str {
        let u = self.units();
        match lang {
            Lang::En => u.en,
            Lang::Ru | Lang::Uk => u.cyrillic,
        }
    }
    /// The SI unit of the quantity itself, plain text (`m/s²`): the unit of the physical
    /// values in diagnostics.
    pub fn si_unit(self) -> &'static str {
        self.units().si
    }
    /// The SI units its μ's caption unit holds: a pressure's μ is written in MPa/mm, as the
    /// textbooks write an indicator diagram's; every other in SI units per mm.
    fn caption_multiple(self) -> f64 {
        match self {
            Quantity::Pressure => 1e6,
            _ => 1.0,
        }
    }
    /// The customary index of μ (`l`, `v`, `a`, `φ`, …).
    pub fn symbol(self) -> &'static str {
        use Quantity::*;
        match self {
            Length => "l",
            Velocity => "v",
            Acceleration => "a",
            Angle => "φ",
            Time => "t",
            Force => "F",
            Moment => "M",
            Work => "A",
            Inertia => "J",
            AngularVelocity => "ω",
            AngularAcceleration => "ε",
            StaticMoment => "mρ",
            UnbalanceMoment => "mρz",
            VelocityAnalogue => "S′",
            AccelerationAnalogue => "S″",
            Pressure => "p",
        }
    }
}

/// One row of the unit table ([`Quantity::units`]).
struct Units {
    /// The SI unit, plain text.
    si: &'static str,
    /// The unit of μ in English captions, label markup.
    en: &'static str,
    /// The unit of μ in Russian and Ukrainian captions, label markup.
    cyrillic: &'static str,
}

/// A drawing scale μ: `value` SI units of `quantity` per drawing millimetre.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scale {
    /// SI units per mm; finite and > 0.
    value: f64,
    /// What is measured.
    pub quantity: Quantity,
}

/// The textbook mantissas of a round scale: 1, 2, 2.5, 4, 5 × 10ⁿ.
const ROUND_MANTISSAS: [f64; 6] = [1.0, 2.0, 2.5, 4.0, 5.0, 10.0];

/// The exact scale `physical / preferred_mm` as its decade and its mantissa in [1, 10);
/// `None` unless finite and > 0.
fn decade_and_mantissa(physical: f64, preferred_mm: f64) -> Option<(f64, f64)> {
    let exact = physical.abs() / preferred_mm;
    if !(exact.is_finite() && exact > 0.0) {
        return None;
    }
    let decade = 10f64.powf(exact.log10().floor());
    Some((decade, exact / decade))
}

impl Scale {
    /// A scale of `value` SI units per mm; `None` unless finite and > 0.
    pub fn new(value: f64, quantity: Quantity) -> Option<Self> {
        (value.is_finite() && value > 0.0).then_some(Self { value, quantity })
    }

    /// The round scale a student would choose so that `physical` is drawn close to, and not
    /// longer than, `preferred_mm`: the smallest value of the 1–2–2.5–4–5 series that is ≥
    /// `physical / preferred_mm`. `None` for non-positive or non-finite inputs.
    pub fn round_for(physical: f64, preferred_mm: f64, quantity: Quantity) -> Option<Self> {
        let (decade, m) = decade_and_mantissa(physical, preferred_mm)?;
        // 1e-9 relative slack so that an exact round value stays itself.
        let mant = ROUND_MANTISSAS
            .iter()
            .copied()
            .find(|&r| r >= m * (1.0 - 1e-9))?;
        Self::new(round_sig(mant * decade), quantity)
    }

    /// The largest round scale (1, 2, 2,5, 4, 5 × 10ⁿ) that draws `physical` at least
    /// `preferred_mm` long: [`Scale::round_for`] rounds the other way (at most that long).
    pub fn round_at_least(physical: f64, preferred_mm: f64, quantity: Quantity) -> Option<Self> {
        let (decade, m) = decade_and_mantissa(physical, preferred_mm)?;
        let mant = ROUND_MANTISSAS
            .iter()
            .rev()
            .copied()
            .find(|&r| r <= m * (1.0 + 1e-9))?;
        Self::new(round_sig(mant * decade), quantity)
    }

    /// The next finer round scale along the series (it draws the same thing larger).
    pub fn finer(self) -> Option<Self> {
        Self::round_at_least(self.value * (1.0 - 1e-6), 1.0, self.quantity)
    }

    /// The next coarser round scale along the series (it draws the same thing smaller).
    pub fn coarser(self) -> Option<Self> {
        Self::round_for(self.value * (1.0 + 1e-6), 1.0, self.quantity)
    }

    /// SI units per mm.
    pub fn value(&self) -> f64 {
        self.value
    }
    /// Drawing millimetres for a physical value.
    pub fn to_mm(&self, physical: f64) -> f64 {
        physical / self.value
    }
    /// Physical value of a drawn length.
    pub fn to_physical(&self, mm: f64) -> f64 {
        mm * self.value
    }

    /// The step (SI) to which a value drawn at this scale is read when lengths are read to
    /// `resolution_mm` on the drawing; `None` when they are read exactly (0).
    pub fn reading_step(&self, resolution_mm: f64) -> Option<f64> {
        (resolution_mm > 0.0).then_some(resolution_mm * self.value)
    }

    /// The caption in label markup: `μ_{l} = 0,0025 м/мм` (ru/uk), `μ_{l} = 0.0025 m/mm` (en).
    pub fn caption(&self, lang: Lang) -> String {
        format!(
            "μ_{{{}}} = {} {}",
            self.quantity.symbol(),
            format_number(self.value / self.quantity.caption_multiple(), lang),
            self.quantity.unit(lang)
        )
    }
}

/// Round to 12 significant digits (removes the binary noise of `mant * 10^n`).
fn round_sig(x: f64) -> f64 {
    let s = format!("{x:.11e}");
    s.parse().unwrap_or(x)
}

/// Format a number the way the textbook writes it: up to 6 significant digits, no trailing
/// zeros, the language's decimal separator, a true minus sign.
pub fn format_number(x: f64, lang: Lang) -> String {
    format_sig(x, 6, lang)
}

/// Format with at most `sig` significant digits (trailing zeros removed).
pub fn format_sig(x: f64, sig: usize, lang: Lang) -> String {
    format_sig_from(x, sig, lang, -6)
}

/// [`format_sig`] with the exponent form from magnitude `least` down (`-6`: from 1e-7;
/// the note's `-3`: no run of more than two zeros after the decimal sign, 0,000724962 is
/// 7,24962e−4).
pub fn format_sig_from(x: f64, sig: usize, lang: Lang, least: i32) -> String {
    if x == 0.0 || !x.is_finite() {
        return if x.is_finite() {
            "0".into()
        } else {
            format!("{x}")
        };
    }
    let mag = x.abs().log10().floor() as i32;
    // Beyond 15 integer digits, below 1e-6 or beyond 15 decimals, the exponent form
    // (`1,73e−13`, `1e300`): never a long run of digits nor the significant digits cut off.
    if !(least..15).contains(&mag) || sig as i32 - 1 - mag > 15 {
        let sig = sig.max(1);
        let text = format!("{:.*e}", sig - 1, x);
        let (mantissa, exp) = text.split_once('e').unwrap_or((&text, "0"));
        let mantissa: f64 = mantissa.parse().unwrap_or(0.0);
        let exp = exp.replace('-', "−");
        return format!("{}e{exp}", format_sig_from(mantissa, sig, lang, least));
    }
    let decimals = (sig as i32 - 1 - mag).clamp(0, 15) as usize;
    let mut s = format!("{:.*}", decimals, x.abs());
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.pop();
        }
    }
    let mut out = String::new();
    if x < 0.0 && s.chars().any(|c| c.is_ascii_digit() && c != '0') {
        out.push('−');
    }
    let _ = write!(out, "{}", s.replace('.', &lang.decimal().to_string()));
    out
}

/// A value for a message or a note: at most 6 significant digits, ASCII (`.`, `-`), in
/// exponent form outside 1e-4 … 1e9 (`1e300`, `-2.5e-7`), never `-0`; `nan`, `inf`.
pub fn format_plain(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    // Rounded to 6 significant digits, then printed shortest.
    let r: f64 = format!("{x:.5e}").parse().unwrap_or(x);
    if (1e-4..1e9).contains(&r.abs()) {
        format!("{r}")
    } else {
        format!("{r:e}")
    }
}

/// `x`, or 0 when it is a rounding residue: at most `1e-9 × |reference|` (a sum of terms of
/// size `reference` that cancel).
pub fn residue_to_zero(x: f64, reference: f64) -> f64 {
    if x.abs() <= 1e-9 * reference.abs() {
        0.0
    } else {
        x
    }
}

/// Format with a fixed number of decimals, the language's separator and a true minus sign.
pub fn format_fixed(x: f64, decimals: usize, lang: Lang) -> String {
    let s = format!("{:.*}", decimals, x);
    let s = if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    };
    s.replace('-', "−")
        .replace('.', &lang.decimal().to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_at_least_draws_at_least_the_preferred_length() {
        let v = |x: f64| Scale::round_at_least(x, 70.0, Quantity::Velocity).map(|s| s.value());
        // The four-bar's crank pin, 0,8 m/s: 0,01 draws 80 mm (round_for's 0,02 draws 40).
        assert_eq!(v(0.8), Some(0.01));
        assert_eq!(v(2.199), Some(0.025));
        // A round value stays itself.
        assert_eq!(v(70.0 * 0.05), Some(0.05));
        for x in [0.8, 1.885, 6.3, 123.4] {
            let s = v(x).expect("scale");
            assert!(x / s >= 70.0 * (1.0 - 1e-9), "{x}: {s}");
            // The next round value coarser would draw it shorter than 70 mm.
            let up = Scale::round_for(x, 70.0, Quantity::Velocity).expect("round");
            assert!(up.value() >= s);
        }
        assert!(Scale::round_at_least(0.0, 70.0, Quantity::Velocity).is_none());
    }

    #[test]
    fn round_scale_follows_the_textbook_series() {
        // Crank 0.14 m drawn 56 mm: exactly 0.0025.
        let s = Scale::round_for(0.14, 56.0, Quantity::Length).unwrap();
        assert_eq!(s.value(), 0.0025);
        // 2.199 m/s drawn at most 70 mm → 0.0314 → 0.04.
        let s = Scale::round_for(2.199, 70.0, Quantity::Velocity).unwrap();
        assert_eq!(s.value(), 0.04);
        assert_eq!(
            Scale::round_for(0.71, 300.0, Quantity::Length)
                .unwrap()
                .value(),
            0.0025
        );
        assert!(Scale::round_for(0.0, 50.0, Quantity::Length).is_none());
        assert!(Scale::round_for(f64::NAN, 50.0, Quantity::Length).is_none());
    }

    #[test]
    fn significant_digits_never_run_long() {
        assert_eq!(format_sig(1e300, 4, Lang::Ru), "1e300");
        assert_eq!(format_sig(-2.2375e-14, 3, Lang::Ru), "−2,24e−14");
        assert_eq!(format_sig(1.5e-15, 6, Lang::En), "1.5e−15");
        assert_eq!(format_sig(123456.0, 4, Lang::En), "123456");
        assert_eq!(format_sig(0.000247487, 6, Lang::Ru), "0,000247487");
        // Below 1e-6 the exponent form, however few the digits (no run of ten zeros).
        assert_eq!(format_sig(1.73e-13, 3, Lang::Ru), "1,73e−13");
        assert_eq!(format_sig(1.2e-6, 3, Lang::En), "0.0000012");
        assert_eq!(format_sig(9.9e-7, 3, Lang::En), "9.9e−7");
        assert_eq!(format_sig(1e14, 6, Lang::En), "100000000000000");
    }

    #[test]
    fn plain_values_are_compact_and_residues_zero() {
        assert_eq!(format_plain(1e300), "1e300");
        assert_eq!(format_plain(-1e-300), "-1e-300");
        assert_eq!(format_plain(-2.237e-16), "-2.237e-16");
        assert_eq!(format_plain(-0.0), "0");
        assert_eq!(format_plain(1234.56789), "1234.57");
        assert_eq!(format_plain(0.1 + 0.2), "0.3");
        assert_eq!(format_plain(f64::NAN), "NaN");
        assert_eq!(residue_to_zero(-2.237e-16, 1200.0), 0.0);
        assert_eq!(residue_to_zero(-3.0, 1200.0), -3.0);
    }

    #[test]
    fn captions_per_language() {
        let s = Scale::new(0.0025, Quantity::Length).unwrap();
        assert_eq!(s.caption(Lang::Ru), "μ_{l} = 0,0025 м/мм");
        assert_eq!(s.caption(Lang::En), "μ_{l} = 0.0025 m/mm");
        assert_eq!(format_number(-1.5, Lang::Ru), "−1,5");
        assert_eq!(format_fixed(-0.0001, 2, Lang::En), "0.00");
        assert_eq!(format_fixed(38.0016, 2, Lang::Ru), "38,00");
    }
}
