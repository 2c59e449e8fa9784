//! The drafting model: how a length is read off the drawing before μ converts it.

/// The drafting model: a length read off the drawing is rounded to `resolution_mm`
/// before μ converts it (0 = exact), after a reading error `bias_mm` is added to it (0 for
/// every drawing; `tmm audit` reads each construction once with every length 0.5 mm long
/// and once 0.5 mm short, to learn what a hand reading's error does to each value).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Drafting {
    resolution_mm: f64,
    bias_mm: f64,
}

impl Drafting {
    /// Exact reading.
    pub const EXACT: Drafting = Drafting {
        resolution_mm: 0.0,
        bias_mm: 0.0,
    };

    /// A hand construction read with dividers and a ruler: every length to 0.5 mm, the
    /// default of `render` and `note` (what a student hands in).
    pub const HAND: Drafting = Drafting {
        resolution_mm: 0.5,
        bias_mm: 0.0,
    };

    /// `None` unless finite and ≥ 0.
    pub fn new(resolution_mm: f64) -> Option<Self> {
        (resolution_mm.is_finite() && resolution_mm >= 0.0).then_some(Self {
            resolution_mm,
            bias_mm: 0.0,
        })
    }
    /// The same model with every length read `bias_mm` longer (shorter when negative; a
    /// length is never read below 0). `None` unless `bias_mm` is finite.
    pub fn biased(self, bias_mm: f64) -> Option<Self> {
        bias_mm.is_finite().then_some(Self { bias_mm, ..self })
    }
    /// The resolution, mm.
    pub const fn resolution_mm(&self) -> f64 {
        self.resolution_mm
    }
    /// A length as read with this resolution (and bias).
    pub fn read(&self, mm: f64) -> f64 {
        let mm = if self.bias_mm == 0.0 {
            mm
        } else {
            (mm + self.bias_mm).max(0.0)
        };
        if self.resolution_mm > 0.0 {
            (mm / self.resolution_mm).round() * self.resolution_mm
        } else {
            mm
        }
    }
}

/// A measured segment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measured {
    /// Its exact drawn length, mm.
    pub drawn_mm: f64,
    /// The length as read under the drafting model, mm.
    pub read_mm: f64,
    /// The physical value: `read_mm × μ`.
    pub value: f64,
}
