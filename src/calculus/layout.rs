//! Where a graphical-calculus construction draws its diagrams, and what it calls them.

use crate::geom::DVec2;

/// Where the diagrams go and what their axes are called.
#[derive(Debug, Clone, PartialEq)]
pub struct DiagramLayout {
    /// Origin of the constructed diagram (figure mm, y up): the point (x₀, 0).
    pub origin: DVec2,
    /// Origin of the given diagram (figure mm).
    pub source_origin: DVec2,
    /// Draw the given diagram's curve and axes (its chords or mid-interval ordinates, which
    /// are part of the construction, are drawn anyway).
    pub draw_source: bool,
    /// Abscissa name (`φ`).
    pub x_name: String,
    /// Ordinate name of the given diagram (`S`).
    pub source_name: String,
    /// Ordinate name of the constructed diagram (`dS/dφ`).
    pub name: String,
    /// Label of the pole (`P`, `P_1`).
    pub pole_name: String,
    /// Label of the pole distance (`H`, `H_1`).
    pub pole_distance_name: String,
    /// The vertical the rays from the pole run to, figure mm (its abscissa); the pole lies H
    /// left of it on the abscissa axis of the diagram that carries it (the given diagram's
    /// when integrating, the constructed one's when differentiating). `None`: that diagram's
    /// own origin. Drawn thin where it is not the ordinate axis.
    pub ray_axis: Option<f64>,
    /// Draw the constructed diagram's axes.
    pub draw_axes: bool,
    /// Offset of the pole distance's dimension line from the abscissa axis, mm (negative:
    /// below it).
    pub pole_dimension_mm: f64,
    /// The preferred direction of the pole's label from the pole.
    pub pole_label_toward: DVec2,
    /// The tangents to the given curve at its first and last node that the draughtsman
    /// draws where the law fixes them (a cam's phase meeting a dwell without a shock:
    /// horizontal), figure mm directions. The method of chords then takes the derivative
    /// there from the ray parallel to the tangent instead of extending the smooth curve past
    /// the last mid-interval point. `None`: extended.
    pub end_tangents: [Option<DVec2>; 2],
    /// Points between the nodes that the given curve is drawn through as well (figure mm
    /// from the given diagram's origin): where the draughtsman has a value the nodes do not
    /// show, as a mechanism's extreme position read off its plan, the curve's crest there.
    pub source_through: Vec<DVec2>,
}

impl DiagramLayout {
    /// The given diagram at `source_origin`, the constructed one at `origin`, axes named
    /// `φ`, `S`, `dS/dφ`, pole `P`, distance `H`.
    pub fn new(source_origin: DVec2, origin: DVec2) -> Self {
        Self {
            origin,
            source_origin,
            draw_source: true,
            x_name: "φ".into(),
            source_name: "S".into(),
            name: "dS/dφ".into(),
            pole_name: "P".into(),
            pole_distance_name: "H".into(),
            ray_axis: None,
            draw_axes: true,
            pole_dimension_mm: -7.0,
            pole_label_toward: DVec2::new(-0.3, 1.0),
            end_tangents: [None, None],
            source_through: Vec::new(),
        }
    }

    /// The tangents to the given curve at its first and last node, where they are known
    /// (see [`DiagramLayout::end_tangents`]).
    pub fn tangents_at_ends(mut self, first: Option<DVec2>, last: Option<DVec2>) -> Self {
        self.end_tangents = [first, last];
        self
    }

    /// The given curve drawn through `points` too (see [`DiagramLayout::source_through`]).
    pub fn source_through(mut self, points: Vec<DVec2>) -> Self {
        self.source_through = points;
        self
    }

    /// The rays run to the vertical at abscissa `x` (figure mm), the pole H left of it.
    pub fn rays_to(mut self, x: f64) -> Self {
        self.ray_axis = Some(x);
        self
    }

    /// Leave the axes to the caller (a diagram drawn phase by phase has one pair of axes).
    pub fn without_axes(mut self) -> Self {
        self.draw_axes = false;
        self
    }

    /// The pole distance's dimension line `mm` from the abscissa axis (negative: below);
    /// the pole's label toward `label` from the pole.
    pub fn pole_marks(mut self, mm: f64, label: DVec2) -> Self {
        self.pole_dimension_mm = mm;
        self.pole_label_toward = label;
        self
    }

    /// The abscissa of the vertical the rays run to, for a pole carried by the diagram
    /// whose origin is `origin`.
    pub(super) fn ray_x(&self, origin: DVec2) -> f64 {
        self.ray_axis.unwrap_or(origin.x)
    }

    /// Rename the axes: abscissa, given ordinate, constructed ordinate.
    pub fn named(mut self, x: &str, source: &str, result: &str) -> Self {
        self.x_name = x.into();
        self.source_name = source.into();
        self.name = result.into();
        self
    }

    /// Rename the pole and its distance (`P_1`, `H_1`).
    pub fn pole_named(mut self, pole: &str, distance: &str) -> Self {
        self.pole_name = pole.into();
        self.pole_distance_name = distance.into();
        self
    }

    /// Whether to draw the given diagram's curve and axes.
    pub fn with_source(mut self, draw: bool) -> Self {
        self.draw_source = draw;
        self
    }
}
