//! Diagnostic errors of construction steps, carrying the numbers a student needs.

use thiserror::Error;

/// A construction step that cannot be carried out. Lengths are physical values in `unit`
/// (the figure's μ applied), so the message reads like the task sheet.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ConstructionError {
    /// Two compass arcs do not meet.
    #[error(
        "{step}: arcs from {a} (r = {ra:.5} {unit}) and {b} (r = {rb:.5} {unit}) do not meet: \
         centre distance {d:.5} {unit} {}",
        if d > &(ra + rb) { format!("> r₁ + r₂ = {:.5}", ra + rb) } else { format!("< |r₁ − r₂| = {:.5}", (ra - rb).abs()) }
    )]
    CirclesDoNotMeet {
        /// The step being carried out.
        step: String,
        /// Name of the first centre.
        a: String,
        /// Name of the second centre.
        b: String,
        /// First radius.
        ra: f64,
        /// Second radius.
        rb: f64,
        /// Centre distance.
        d: f64,
        /// Unit of the numbers.
        unit: &'static str,
    },
    /// Two compass arcs coincide: the point is not determined.
    #[error("{step}: arcs from {a} and {b} coincide (same centre and radius {r:.5} {unit}); the point is not determined")]
    CirclesCoincide {
        /// The step.
        step: String,
        /// First centre name.
        a: String,
        /// Second centre name.
        b: String,
        /// The common radius.
        r: f64,
        /// Unit.
        unit: &'static str,
    },
    /// An arc does not reach a straight line.
    #[error("{step}: the arc from {center} (r = {r:.5} {unit}) does not reach line {line}: its distance is {distance:.5} {unit}")]
    LineMissesCircle {
        /// The step.
        step: String,
        /// Arc centre name.
        center: String,
        /// Line name.
        line: String,
        /// Radius.
        r: f64,
        /// Distance from the centre to the line.
        distance: f64,
        /// Unit.
        unit: &'static str,
    },
    /// Two straight lines do not cross.
    #[error("{step}: lines {a} and {b} are parallel{}; no intersection",
        if *distance == 0.0 { " and coincide".to_string() } else { format!(" at distance {distance:.5} {unit}") })]
    LinesParallel {
        /// The step.
        step: String,
        /// First line name.
        a: String,
        /// Second line name.
        b: String,
        /// Distance between them (0: the same line).
        distance: f64,
        /// Unit.
        unit: &'static str,
    },
    /// A line or direction cannot be drawn through two coincident points.
    #[error("{step}: {what} is not defined: points {a} and {b} coincide")]
    CoincidentPoints {
        /// The step.
        step: String,
        /// What was to be drawn.
        what: String,
        /// First point.
        a: String,
        /// Second point.
        b: String,
    },
    /// The requested solution does not exist for this kind of intersection.
    #[error("{step}: solution `{pick}` does not apply to {what}")]
    BadPick {
        /// The step.
        step: String,
        /// The requested pick.
        pick: String,
        /// The intersection kind.
        what: &'static str,
    },
    /// Anything else, with its numbers in the message.
    #[error("{step}: {message}")]
    Other {
        /// The step.
        step: String,
        /// Explanation.
        message: String,
    },
}
