//! Checks: every value read off a construction beside its analytic twin, as a typed row.
//!
//! A [`Row`] names what was measured by a typed [`Key`] — the textbook symbol ([`Symbol`],
//! which fixes the physical quantity and its SI unit), the subject (a point, a link, a pair
//! of points, a gear) and where it was read ([`At`]: a position of the plan, a crank angle,
//! or the whole scene) — and the textbook procedure that produced the graphical value
//! ([`Method`]). Every domain module (kinematics, forces, dynamics, cams, gears) emits these
//! rows; `report` writes them and `sheets` tabulates them, neither parses names.
//!
//! Relative errors need a zero that knows the quantity's scale: a value is zero to rounding
//! when its magnitude is at most [`ZERO_FRACTION`] × the quantity's scale (its largest
//! magnitude over the cycle, [`Row::scale`]). The same rule serves the report, its summary
//! and the sheets ([`is_zero`]).

pub mod finding;
pub mod notes;
mod report;
mod seed;
mod summary;
#[cfg(test)]
mod tests;

/// The textbook symbol a row is named by; it lives with the words (`crate::words`).
pub use crate::words::Symbol;
pub use finding::{BaseUsed, Cusp, Finding, Limit, NoFlywheel, RadiusBasis, Route};
pub use notes::ReportNote;
pub use report::{Column, Report, Table};
pub use seed::{seed_notes, SeedValue};
pub use summary::{Summary, SummaryEntry};

use crate::scale::Lang;
use serde::Serialize;

/// A value is zero to rounding when its magnitude is at most this fraction of its
/// quantity's scale: f64 arithmetic on values of that scale leaves residues of ~1e-15 of it.
pub const ZERO_FRACTION: f64 = 1e-12;

/// True when `value` is zero to rounding against `scale` (the quantity's largest magnitude):
/// |value| ≤ [`ZERO_FRACTION`] · |scale|. A non-finite value is never zero.
pub fn is_zero(value: f64, scale: f64) -> bool {
    value.is_finite() && value.abs() <= ZERO_FRACTION * scale.abs()
}

/// Where a value was read.
#[derive(Debug, Clone, PartialEq)]
pub enum At {
    /// At a position of the plan, by its label (`1` … `12`, `8′`).
    Position(String),
    /// At a crank angle, radians (a diagram read between the plan's positions).
    Angle(f64),
    /// A quantity of the whole scene (a minimum radius, a contact ratio, a flywheel inertia).
    Scene,
}

impl At {
    /// The label a report writes: the position label, the angle in degrees, or `None`.
    pub fn label(&self) -> Option<String> {
        match self {
            At::Position(p) => Some(p.clone()),
            At::Angle(a) => Some(format!(
                "{}°",
                crate::scale::format_sig(a.to_degrees(), 6, Lang::En)
            )),
            At::Scene => None,
        }
    }
}

/// What a row measures: symbol, subject, where.
#[derive(Debug, Clone, PartialEq)]
pub struct Key {
    /// The symbol.
    pub symbol: Symbol,
    /// The subject without markup: a point (`D`, `S5`), a link number (`3`), a pair of
    /// points (`B3_B1`: B of link 3 relative to B of link 1).
    pub subject: String,
    /// Where.
    pub at: At,
}

impl Key {
    /// A key of the whole scene.
    pub fn of_scene(symbol: Symbol, subject: impl Into<String>) -> Self {
        Self {
            symbol,
            subject: subject.into(),
            at: At::Scene,
        }
    }
    /// A key at a position of the plan.
    pub fn at_position(symbol: Symbol, subject: impl Into<String>, label: &str) -> Self {
        Self {
            symbol,
            subject: subject.into(),
            at: At::Position(label.to_string()),
        }
    }
    /// The quantity's name in reports: `v_D`, `omega_3`, `v_B3_B1`, `s_S5`; the symbol
    /// alone for a subject-less quantity (`dT`, `delta`).
    /// The quantity's name in reports: `v_D`, `omega_3`, `v_B3_B1`, `s_S5`; the symbol alone
    /// when the subject is empty (a cam's `s`, `ds_dphi`).
    pub fn quantity(&self) -> String {
        if self.subject.is_empty() {
            return self.symbol.key().to_string();
        }
        format!("{}_{}", self.symbol.key(), self.subject)
    }
    /// The same quantity (symbol and subject), wherever it was read.
    pub fn same_quantity(&self, other: &Key) -> bool {
        self.symbol == other.symbol && self.subject == other.subject
    }
}

/// The textbook procedure that produced a graphical value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Method {
    /// A velocity or acceleration plan (vector polygon) at one position.
    Plan,
    /// A kinematic diagram differentiated by the method of chords.
    DiagramChords,
    /// A kinematic diagram differentiated by the method of tangents.
    DiagramTangents,
    /// A diagram obtained by graphical integration.
    Integration,
    /// A force polygon (kinetostatics).
    Polygon,
    /// Zhukovsky's lever.
    Lever,
    /// A cam profile by inversion.
    Inversion,
    /// A tooth profile as the envelope of rack positions.
    Envelope,
    /// The method of triangles (plans of planetary trains).
    Triangles,
    /// The energy–mass diagram with its tangents (Wittenbauer).
    Wittenbauer,
    /// The flywheel from the range of T_I = ΔT − T_II (Mertsalov).
    Mertsalov,
    /// The textbook's formula chain against an independent closed form (gear geometry).
    Formula,
    /// Read off the meshing picture.
    Meshing,
    /// Read off the diagram of specific sliding λ₁, λ₂ along N₁N₂.
    SlidingDiagram,
    /// A cam's combined diagram (S against dS/dφ or d²S/dφ²) with its γ_min lines.
    CombinedDiagram,
}

impl Method {
    /// Every method, in report order.
    pub const ALL: [Method; 15] = [
        Method::Plan,
        Method::DiagramChords,
        Method::DiagramTangents,
        Method::Integration,
        Method::Polygon,
        Method::Lever,
        Method::Inversion,
        Method::Envelope,
        Method::Triangles,
        Method::Wittenbauer,
        Method::Mertsalov,
        Method::Formula,
        Method::Meshing,
        Method::SlidingDiagram,
        Method::CombinedDiagram,
    ];

    /// The name in JSON and CSV: `plan`, `diagram-chords`, `diagram-tangents`, …; every
    /// diagram's name starts with `diagram`, so a filter on that prefix keeps working.
    pub fn key(self) -> &'static str {
        match self {
            Method::Plan => "plan",
            Method::DiagramChords => "diagram-chords",
            Method::DiagramTangents => "diagram-tangents",
            Method::Integration => "integration",
            Method::Polygon => "polygon",
            Method::Lever => "lever",
            Method::Inversion => "inversion",
            Method::Envelope => "envelope",
            Method::Triangles => "triangles",
            Method::Wittenbauer => "wittenbauer",
            Method::Mertsalov => "mertsalov",
            Method::Formula => "formula",
            Method::Meshing => "meshing",
            Method::SlidingDiagram => "sliding-diagram",
            Method::CombinedDiagram => "combined-diagram",
        }
    }

    /// The method named by `key`, or by a prefix of one (`diagram` is the chord method, the
    /// name reports used before the methods of differentiation were told apart).
    pub fn parse(key: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|m| m.key() == key)
            .or_else(|| Self::ALL.into_iter().find(|m| m.key().starts_with(key)))
    }

    /// A diagram (chords or tangents).
    pub fn is_diagram(self) -> bool {
        self.key().starts_with("diagram")
    }

    /// The method's short name in `lang`, as the error tables of the sheets print it.
    pub fn name(self, lang: Lang) -> &'static str {
        use crate::words::MethodName as N;
        match self {
            Method::Plan => N::Plan,
            Method::DiagramChords => N::DiagramChords,
            Method::DiagramTangents => N::DiagramTangents,
            Method::Integration => N::Integration,
            Method::Polygon => N::Polygon,
            Method::Lever => N::Lever,
            Method::Inversion => N::Inversion,
            Method::Envelope => N::Envelope,
            Method::Triangles => N::Triangles,
            Method::Wittenbauer => N::Wittenbauer,
            Method::Mertsalov => N::Mertsalov,
            Method::Formula => N::Formula,
            Method::Meshing => N::Meshing,
            Method::SlidingDiagram => N::SlidingDiagram,
            Method::CombinedDiagram => N::CombinedDiagram,
        }
        .get(lang)
    }
}

impl Serialize for Method {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.key())
    }
}

/// One checked value: graphical against analytic.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// What was measured.
    pub key: Key,
    /// How the graphical value was obtained.
    pub method: Method,
    /// The value read from the construction, SI.
    pub graphical: f64,
    /// The analytic twin's value, SI.
    pub analytic: f64,
    /// How well the construction fixed the value, e.g. the crossing angle (degrees) of the
    /// lines that fixed it; small means ill-conditioned.
    pub conditioning: Option<f64>,
    /// The quantity's scale: its largest analytic magnitude over the cycle (the zero
    /// reference of [`Row::rel_error`]); the row's own |analytic| when nothing larger is known.
    pub scale: f64,
}

impl Row {
    /// A row of `key` read by `method`: graphical against analytic, `scale` its zero reference
    /// ([`Row::rel_error`]); no conditioning.
    pub fn new(key: Key, method: Method, graphical: f64, analytic: f64, scale: f64) -> Self {
        Self {
            key,
            method,
            graphical,
            analytic,
            conditioning: None,
            scale,
        }
    }
    /// The same row with the conditioning of the construction that fixed it.
    pub fn conditioned(self, conditioning: Option<f64>) -> Self {
        Self {
            conditioning,
            ..self
        }
    }
    /// The quantity's name (`v_D`).
    pub fn quantity(&self) -> String {
        self.key.quantity()
    }
    /// The position label, `None` for a quantity of the whole scene.
    pub fn position(&self) -> Option<String> {
        self.key.at.label()
    }
    /// The SI unit.
    pub fn unit(&self) -> &'static str {
        self.key.symbol.unit()
    }
    /// True when the graphical value comes off a drawing: a length measured on it ÷ μ, or a
    /// value worked out from such readings only. False for a value computed: by formula, or
    /// from the construction's points at full precision — the drawn envelope's deviation from
    /// the exact one, fractions of a micrometre no drawing read to 0,5 mm shows. The one place
    /// that decides whether a row stands under "графически".
    pub fn is_read_off(&self) -> bool {
        self.method != Method::Formula && self.key.symbol != Symbol::EnvelopeDeviation
    }
    /// |graphical − analytic|, in the row's unit.
    pub fn abs_error(&self) -> f64 {
        (self.graphical - self.analytic).abs()
    }
    /// (graphical − analytic) / |analytic|, signed, as a fraction; `None` when the analytic
    /// value is zero to rounding against `scale` ([`is_zero`]) or is not finite.
    pub fn rel_error(&self, scale: f64) -> Option<f64> {
        let a = self.analytic;
        (a.is_finite() && a != 0.0 && !is_zero(a, scale)).then(|| (self.graphical - a) / a.abs())
    }
}

/// The zero reference of every row: its own scale or, when larger, the largest finite
/// |analytic| among the rows of the same quantity.
pub fn scales(rows: &[Row]) -> Vec<f64> {
    // The largest finite |analytic| of each quantity, in one pass.
    let mut largest: Vec<(&Key, f64)> = Vec::new();
    for r in rows.iter().filter(|r| r.analytic.is_finite()) {
        match largest.iter_mut().find(|(k, _)| k.same_quantity(&r.key)) {
            Some((_, m)) => *m = m.max(r.analytic.abs()),
            None => largest.push((&r.key, r.analytic.abs())),
        }
    }
    rows.iter()
        .map(|r| {
            let column = largest
                .iter()
                .find(|(k, _)| k.same_quantity(&r.key))
                .map_or(0.0, |q| q.1);
            r.scale.abs().max(column)
        })
        .collect()
}

/// The relative error of every row against its zero reference ([`scales`]), in row order.
pub fn rel_errors(rows: &[Row]) -> Vec<Option<f64>> {
    rows.iter()
        .zip(scales(rows))
        .map(|(r, s)| r.rel_error(s))
        .collect()
}
