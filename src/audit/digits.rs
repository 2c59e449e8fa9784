//! A number as the student wrote it: its digits, how finely it is written, and the numbers
//! a slip of the pen would have made of another (digits swapped, dropped, added).

/// The significant digits a table's value carries: a dropped digit is put back only into a
/// number written with fewer (into one of three, any of ten digits at any of four places
/// makes too many numbers for one of them to mean anything).
const MOST_DIGITS: usize = 3;

/// A number as written: the text (sign, digits, a decimal point, an exponent) and its value.
#[derive(Debug, Clone, PartialEq)]
pub struct Written {
    /// The text with a decimal point (a decimal comma read as one).
    pub text: String,
    /// Its value.
    pub value: f64,
}

impl Written {
    /// The number written as `text` (`2.28`, `-7,8`, `1.5e-3`) with `decimal_comma` telling
    /// whether a comma is its decimal separator.
    ///
    /// # Errors
    /// [`NumberError::NotANumber`] for text that is not a number, [`NumberError::OutOfRange`]
    /// for one beyond what a double holds (`1e400`, or `1e-400`, whose digits are not 0 but
    /// whose value would be).
    pub fn parse(text: &str, decimal_comma: bool) -> Result<Self, NumberError> {
        let mut t = text.trim().replace(['\u{2212}', '–'], "-");
        if decimal_comma {
            t = t.replace(',', ".");
        }
        let t = t.trim_start_matches('+').to_string();
        let ok = !t.is_empty()
            && t.chars()
                .all(|c| c.is_ascii_digit() || matches!(c, '.' | '-' | 'e' | 'E'))
            && t.chars().any(|c| c.is_ascii_digit());
        let value: f64 = if ok {
            t.parse().map_err(|_| NumberError::NotANumber)?
        } else {
            return Err(NumberError::NotANumber);
        };
        let w = Self { text: t, value };
        let lost = value == 0.0 && w.parts().0.chars().any(|c| matches!(c, '1'..='9'));
        if !value.is_finite() || lost {
            return Err(NumberError::OutOfRange);
        }
        Ok(w)
    }

    /// Whether the number written is 0 (`0`, `0.00`, `-0`, `0e5`).
    pub fn is_zero(&self) -> bool {
        self.value == 0.0
    }

    /// The mantissa (digits and point, no sign) and the exponent written after it (one of
    /// more digits than an `i64` holds taken as the largest of its sign).
    fn parts(&self) -> (&str, i64) {
        let body = self.text.trim_start_matches('-');
        match body.split_once(['e', 'E']) {
            Some((m, e)) => {
                let far = if e.starts_with('-') {
                    i64::MIN
                } else {
                    i64::MAX
                };
                (m, e.parse().unwrap_or(far))
            }
            None => (body, 0),
        }
    }

    /// Half a unit of the last digit written: the rounding the text carries (`2.28` → 0.005,
    /// `130` → 0.5); its power of ten held to a double's range (`0e-2147483648` has a half
    /// unit of 0, `0e999` one of 5e306).
    pub fn half_unit(&self) -> f64 {
        let (m, e) = self.parts();
        let decimals = m.split_once('.').map_or(0, |(_, f)| f.len());
        let decimals = i64::try_from(decimals).unwrap_or(i64::MAX);
        let power = e.saturating_sub(decimals).clamp(-400, 307);
        // In the clamp's range the power fits an i32.
        0.5 * 10f64.powi(i32::try_from(power).unwrap_or(0))
    }

    /// The significant digits written (`0.0546` → 3, `7.8` → 2, `130` → 3).
    pub fn significant(&self) -> usize {
        let (m, _) = self.parts();
        m.chars()
            .filter(char::is_ascii_digit)
            .skip_while(|&c| c == '0')
            .count()
    }

    /// `x` cut to the digits written here (toward zero), and `x` rounded to them.
    pub fn cut_and_rounded(&self, x: f64) -> (f64, f64) {
        let unit = 2.0 * self.half_unit();
        if !(unit > 0.0 && (x / unit).is_finite()) {
            return (x, x);
        }
        ((x / unit).trunc() * unit, (x / unit).round() * unit)
    }

    /// Whether `x` is this number (to a thousandth of its last digit).
    pub fn is(&self, x: f64) -> bool {
        (x - self.value).abs() <= 2e-3 * self.half_unit()
    }

    /// The same number with the opposite sign.
    pub fn negated(&self) -> Self {
        let text = match self.text.strip_prefix('-') {
            Some(t) => t.to_string(),
            None => format!("-{}", self.text),
        };
        Self {
            text,
            value: -self.value,
        }
    }

    /// The numbers this one is a slip of the pen of: each the number meant, written as the
    /// student would have written it — two neighbouring digits swapped back, a digit the
    /// student dropped put back (any digit at any place), a digit too many taken out.
    pub fn edits(&self) -> Vec<(Edit, Written)> {
        let sign = if self.text.starts_with('-') { "-" } else { "" };
        let (m, e) = self.parts();
        let exp = if self.text.contains(['e', 'E']) {
            format!("e{e}")
        } else {
            String::new()
        };
        let chars: Vec<char> = m.chars().collect();
        let make = |c: &[char]| {
            let body: String = c.iter().collect();
            Written::parse(&format!("{sign}{body}{exp}"), false).ok()
        };
        let mut out: Vec<(Edit, Written)> = Vec::new();
        let mut push = |edit: Edit, w: Option<Written>| {
            if let Some(w) = w {
                if w.text.trim_start_matches('-') != m && !out.iter().any(|(_, o)| o.text == w.text)
                {
                    out.push((edit, w));
                }
            }
        };
        // The significant digits' places: a slip keeps the first of them (a number whose
        // leading digit is lost or doubled is not read as a slip of the pen).
        let digits: Vec<usize> = (0..chars.len())
            .filter(|&k| chars[k].is_ascii_digit())
            .skip_while(|&k| chars[k] == '0')
            .collect();
        let Some(&first) = digits.first() else {
            return out;
        };
        for pair in digits.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            if chars[a] != chars[b] {
                let mut c = chars.clone();
                c.swap(a, b);
                push(Edit::Transposed, make(&c));
            }
        }
        if self.significant() < MOST_DIGITS {
            for at in first + 1..=chars.len() {
                for d in '0'..='9' {
                    let mut c = chars.clone();
                    c.insert(at, d);
                    push(Edit::Dropped, make(&c));
                }
            }
        }
        for &at in digits.iter().skip(1) {
            let mut c = chars.clone();
            c.remove(at);
            if c.last() != Some(&'.') {
                push(Edit::Added, make(&c));
            }
        }
        out
    }
}

/// Why a field is not a number.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NumberError {
    /// Not a number at all.
    NotANumber,
    /// A number beyond the range of a double (its value infinite, or 0 though its digits
    /// are not).
    OutOfRange,
}

/// A slip of the pen on one number.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Edit {
    /// Two neighbouring digits swapped.
    Transposed,
    /// A digit dropped.
    Dropped,
    /// A digit too many.
    Added,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn w(t: &str) -> Written {
        Written::parse(t, true).expect("a number")
    }

    #[test]
    fn a_written_number_knows_its_digits() {
        assert_eq!(w("2,28").value, 2.28);
        assert_eq!(w("2.28").half_unit(), 0.005);
        assert_eq!(w("130").half_unit(), 0.5);
        assert_eq!(w("1.5e-3").half_unit(), 0.00005);
        assert_eq!(w("0.0546").significant(), 3);
        assert_eq!(w("-7.8").significant(), 2);
        assert_eq!(w("-7.8").negated().text, "7.8");
        assert_eq!(Written::parse("2.2.8", false), Err(NumberError::NotANumber));
        assert_eq!(Written::parse("abc", false), Err(NumberError::NotANumber));
        assert_eq!(Written::parse("", false), Err(NumberError::NotANumber));
        let (cut, rounded) = w("6.4").cut_and_rounded(6.466);
        assert!(w("6.4").is(cut) && !w("6.4").is(rounded));
    }

    #[test]
    fn exponents_at_the_ends_of_the_range_neither_overflow_nor_pass_as_numbers() {
        // An exponent of −2³¹ (and beyond an i64): the half unit is held to a double's range.
        for t in [
            "0e-2147483648",
            "0.0e-2147483648",
            "0e-99999999999999999999999",
        ] {
            let z = w(t);
            assert!(z.is_zero(), "{t}");
            assert_eq!(z.half_unit(), 0.0, "{t}");
            assert_eq!(z.cut_and_rounded(1.5), (1.5, 1.5), "{t}");
        }
        for t in ["0e2147483647", "0e99999999999999999999999"] {
            let z = w(t);
            assert!(
                z.is_zero() && (z.half_unit() / 5e306 - 1.0).abs() < 1e-12,
                "{t}: {}",
                z.half_unit()
            );
            assert_eq!(z.cut_and_rounded(1.5).0, 0.0, "{t}");
        }
        // A number whose digits are not 0 but whose value a double cannot hold is refused.
        for t in [
            "1e400",
            "-1e2147483648",
            "1e-400",
            "2.5e-2147483648",
            "1e99999999999999999999",
        ] {
            assert_eq!(
                Written::parse(t, false),
                Err(NumberError::OutOfRange),
                "{t}"
            );
        }
        assert!((w("1e-300").half_unit() / 0.5e-300 - 1.0).abs() < 1e-12);
        assert!(w("1e-300").value > 0.0);
        // Every slip of the pen of a number of huge or tiny exponent is a number of its own.
        for t in ["1.25e300", "1.25e-300", "4.5e-310", "9.9e307"] {
            let x = w(t);
            assert!(x.half_unit().is_finite(), "{t}");
            assert!(x.edits().iter().all(|(_, m)| m.value.is_finite()), "{t}");
        }
    }

    #[test]
    fn the_slips_of_the_pen_of_a_number_include_the_one_made() {
        let meant = |t: &str, edit: Edit, m: &str| {
            w(t).edits().iter().any(|(e, x)| *e == edit && x.text == m)
        };
        assert!(meant("7.8", Edit::Dropped, "7.18"));
        assert!(meant("-7.8", Edit::Dropped, "-7.18"));
        assert!(meant("4.583", Edit::Transposed, "4.538"));
        assert!(meant("4.5538", Edit::Added, "4.538"));
        // The leading digit is kept; a four-digit number has no digit dropped.
        assert!(!meant("3.8", Edit::Dropped, "73.8"));
        assert!(!meant("4.485", Edit::Dropped, "4.5485"));
        assert!(!meant("4.28", Edit::Dropped, "47.28"));
        assert!(meant("0.0625", Edit::Transposed, "0.0265"));
        assert!(!meant("0.0625", Edit::Transposed, "0.6025"));
        assert!(!meant("4.44", Edit::Transposed, "4.44"));
    }
}
