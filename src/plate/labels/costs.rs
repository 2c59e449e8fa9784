//! The costs a label's place is weighed by that more than one rule of the placer takes: a
//! place, a leader past a point, a word read on into its neighbour, a text under a shelf.

/// Cost of covering another label's point.
pub(super) const OVER_POINT: f64 = 60.0;

/// Cost of a box over another text (the placer adds its overlap area).
pub(super) const OVER_TEXT: f64 = 1e3;
