//! The problem collector and the conversions of the file's units (mm, degrees) to SI, each
//! checked once with the key path it came from.

use super::error::Problem;
use crate::scale::{Quantity, Scale};

/// Metres per millimetre.
const M_PER_MM: f64 = 1e-3;

/// The largest length or coordinate a scene may give, mm (1 km): beyond it no drawing scale
/// can be formed and the constructions' tolerances lose their meaning.
pub(crate) const MAX_MM: f64 = 1e6;

/// The largest link number a scene may give: a mechanism of the course has about ten links,
/// and the per-link arrays of the analysis are sized by the largest number.
pub(crate) const MAX_LINK: u32 = 99;

/// The largest angle a scene may give, degrees (ten turns).
pub(crate) const MAX_DEG: f64 = 3600.0;

/// The range of a drawing scale μ the scene gives nothing to measure by, SI units per mm:
/// beyond it no figure of the course is visible or any fits a sheet. Scales with a reference
/// quantity in the scene are held to what they draw ([`super::drawing`]).
pub(crate) const MIN_SCALE: f64 = 1e-12;
/// See [`MIN_SCALE`].
pub(crate) const MAX_SCALE: f64 = 1e12;

/// `base.key`.
pub(crate) fn join(base: &str, key: &str) -> String {
    format!("{base}.{key}")
}

/// `base[index]`.
pub(crate) fn item(base: &str, index: usize) -> String {
    format!("{base}[{index}]")
}

/// A number the way TOML writes it (`nan`, `inf`, `-140`), exactly (the shortest text that
/// reads back as `v`) and compactly: in exponent form outside 1e-5 … 1e16 (`1e300`, not 301
/// digits; `-1e-300`, not 300 zeros).
pub(crate) fn number(v: f64) -> String {
    if v.is_nan() {
        "nan".into()
    } else if v.is_infinite() {
        if v > 0.0 { "inf" } else { "-inf" }.into()
    } else if v == 0.0 || (1e-5..1e16).contains(&v.abs()) {
        v.to_string()
    } else {
        format!("{v:e}")
    }
}

/// A derived value for a message (a range's ends, what a scale draws): 4 significant digits,
/// in exponent form outside 1e-4 … 1e6 with its zeros trimmed (`2.513e-5`, `1e40`).
pub(crate) fn short(x: f64) -> String {
    if x != 0.0 && x.is_finite() && !(1e-4..1e6).contains(&x.abs()) {
        let t = format!("{x:.3e}");
        let (mantissa, exp) = t.split_once('e').unwrap_or((&t, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        format!("{mantissa}e{exp}")
    } else {
        crate::scale::format_sig(x, 4, crate::scale::Lang::En)
    }
}

/// A list of numbers the way TOML writes it (`[nan, 1e300, 2.5]`), each by [`number`].
pub(crate) fn numbers(v: &[f64]) -> String {
    let items: Vec<String> = v.iter().map(|&x| number(x)).collect();
    format!("[{}]", items.join(", "))
}

/// A name quoted as in the file.
pub(crate) fn quoted(s: &str) -> String {
    format!("{s:?}")
}

/// Collects every problem of a scene; the conversions return a placeholder after reporting,
/// so that validation goes on and reports all problems at once.
#[derive(Debug, Default)]
pub(crate) struct Checker {
    /// The problems so far.
    pub problems: Vec<Problem>,
}

impl Checker {
    /// Report a problem.
    pub fn push(
        &mut self,
        key: impl Into<String>,
        value: Option<String>,
        expected: impl Into<String>,
    ) {
        self.problems.push(Problem {
            key: key.into(),
            value,
            expected: expected.into(),
        });
    }

    /// The value of a required key, or a "missing" problem.
    pub fn required<T>(&mut self, key: &str, v: Option<T>, expected: &str) -> Option<T> {
        if v.is_none() {
            self.push(key, None, format!("missing: expected {expected}"));
        }
        v
    }

    /// A required length in mm, finite, > 0 and at most [`MAX_MM`], in metres.
    pub fn length(&mut self, key: &str, v: Option<f64>) -> f64 {
        const WANT: &str = "a length > 0 mm and at most 1e6 mm (1 km)";
        match self.required(key, v, WANT) {
            Some(mm) if mm.is_finite() && mm > 0.0 && mm <= MAX_MM => mm * M_PER_MM,
            Some(mm) => self.bad(key, mm, WANT),
            None => 0.0,
        }
    }

    /// A signed distance in mm (may be 0 or negative, at most [`MAX_MM`] in size), in metres.
    pub fn distance(&mut self, key: &str, v: Option<f64>, default_mm: f64) -> f64 {
        self.bounded(
            key,
            v.unwrap_or(default_mm),
            MAX_MM,
            "a finite distance in mm, within ±1e6 mm",
        ) * M_PER_MM
    }

    /// A required signed coordinate in mm (at most [`MAX_MM`] in size), in metres.
    pub fn coordinate(&mut self, key: &str, mm: f64) -> f64 {
        self.bounded(key, mm, MAX_MM, "a finite coordinate in mm, within ±1e6 mm") * M_PER_MM
    }

    /// A number in (0, `max`], or a problem and 0.
    pub fn in_range(&mut self, key: &str, v: f64, max: f64, expected: &str) -> f64 {
        if v.is_finite() && v > 0.0 && v <= max {
            v
        } else {
            self.bad(key, v, expected)
        }
    }

    /// A finite number of magnitude at most `max`, or a problem and 0.
    pub fn bounded(&mut self, key: &str, v: f64, max: f64, expected: &str) -> f64 {
        if v.is_finite() && v.abs() <= max {
            v
        } else {
            self.bad(key, v, expected)
        }
    }

    /// An angle in degrees, finite and within ±[`MAX_DEG`] (beyond, the turns swamp the
    /// angle's digits: 1e30° is no direction), in radians.
    pub fn angle(&mut self, key: &str, v: Option<f64>, default_deg: f64) -> f64 {
        self.bounded(
            key,
            v.unwrap_or(default_deg),
            MAX_DEG,
            "a finite angle in degrees, within ±3600° (ten turns)",
        )
        .to_radians()
    }

    /// An optional scale μ of `quantity` (finite and > 0), or a problem and `None`;
    /// `expected` names it with its unit (`a scale μ_l > 0 m/mm`).
    pub fn scale(
        &mut self,
        key: &str,
        v: Option<f64>,
        quantity: Quantity,
        expected: &str,
    ) -> Option<Scale> {
        let v = v?;
        let scale = Scale::new(v, quantity);
        if scale.is_none() {
            self.bad(key, v, expected);
        }
        scale
    }

    /// A scale as [`Checker::scale`] that the scene gives nothing to measure by (the moments of
    /// the dynamics come out of the force analysis), within [`MIN_SCALE`] … [`MAX_SCALE`].
    pub fn free_scale(
        &mut self,
        key: &str,
        v: Option<f64>,
        quantity: Quantity,
        expected: &str,
    ) -> Option<Scale> {
        let scale = self.scale(key, v, quantity, expected)?;
        if (MIN_SCALE..=MAX_SCALE).contains(&scale.value()) {
            return Some(scale);
        }
        let unit = quantity.unit(crate::scale::Lang::En);
        let range = format!("{expected}, from {MIN_SCALE:e} to {MAX_SCALE:e} {unit}");
        self.bad(key, scale.value(), &range);
        None
    }

    /// An optional positive finite number (no unit conversion), or a problem and `None`.
    pub fn positive_opt(&mut self, key: &str, v: Option<f64>, expected: &str) -> Option<f64> {
        let v = v?;
        let ok = v.is_finite() && v > 0.0;
        if !ok {
            self.bad(key, v, expected);
        }
        ok.then_some(v)
    }

    /// Report `key = v: expected …` and return the placeholder 0.
    fn bad(&mut self, key: &str, v: f64, expected: &str) -> f64 {
        self.push(key, Some(number(v)), format!("expected {expected}"));
        0.0
    }

    /// A required name (non-empty).
    pub fn name(&mut self, key: &str, v: Option<&String>) -> String {
        match self.required(key, v, "a point name") {
            Some(s) if s.trim().is_empty() => {
                self.push(key, Some(quoted(s)), "expected a non-empty point name");
                String::new()
            }
            Some(s) => s.clone(),
            None => String::new(),
        }
    }

    /// A link number from `min` (0 is the frame) to [`MAX_LINK`], or a problem and `None`.
    /// Link numbers above [`MAX_LINK`] are refused: the per-link arrays are sized by the
    /// largest number (a link numbered 2e7 took 21 GB).
    pub fn link(&mut self, key: &str, v: i64, min: u32) -> Option<u32> {
        match u32::try_from(v) {
            Ok(l) if l >= min && l <= MAX_LINK => Some(l),
            _ => {
                let want = if min == 0 {
                    format!("a link number 0 … {MAX_LINK} (0: the frame)")
                } else {
                    format!("a link number 1 … {MAX_LINK}")
                };
                self.push(key, Some(v.to_string()), format!("expected {want}"));
                None
            }
        }
    }

    /// Two distinct link numbers ≥ `min` (`links = [i, j]`).
    pub fn link_pair(&mut self, key: &str, v: Option<&Vec<i64>>, min: u32) -> Option<[u32; 2]> {
        let v = self.required(key, v, "two link numbers [i, j]")?;
        let [i, j] = v.as_slice() else {
            self.push(
                key,
                Some(format!("{v:?}")),
                "expected two link numbers [i, j]",
            );
            return None;
        };
        let (i, j) = (self.link(key, *i, min)?, self.link(key, *j, min)?);
        if i == j {
            self.push(
                key,
                Some(format!("{v:?}")),
                "expected two different link numbers",
            );
            return None;
        }
        Some([i, j])
    }

    /// One of the words of `table`, matched case-insensitively: the value the table gives
    /// it. Every scene word is decoded through such a table (the word beside its meaning),
    /// never by its position in a list.
    pub fn word<T: Copy>(
        &mut self,
        key: &str,
        v: Option<&String>,
        table: &[(&str, T)],
    ) -> Option<T> {
        let words: Vec<&str> = table.iter().map(|(w, _)| *w).collect();
        let expected = one_of(&words);
        let s = self.required(key, v, &expected)?;
        let found = table
            .iter()
            .find(|(w, _)| w.to_lowercase() == s.to_lowercase())
            .map(|(_, t)| *t);
        if found.is_none() {
            self.push(key, Some(quoted(s)), format!("expected {expected}"));
        }
        found
    }

    /// An optional word of `table`: its value, the first entry's when the key is absent or
    /// refused.
    pub fn word_or_first<T: Copy>(
        &mut self,
        key: &str,
        v: Option<&String>,
        table: &[(&str, T)],
    ) -> T {
        let first = table[0].1;
        match v {
            None => first,
            Some(_) => self.word(key, v, table).unwrap_or(first),
        }
    }
}

/// `"a", "b" or "c"`.
pub(crate) fn one_of(words: &[&str]) -> String {
    let quoted: Vec<String> = words.iter().map(|w| quoted(w)).collect();
    match quoted.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
        Some((last, _)) => last.clone(),
        None => String::new(),
    }
}
