//! Graphical calculus: differentiation and integration of diagrams the way a student does it
//! on the drawing board (ТММ, methods of chords and tangents, graphical integration).
//!
//! A [`Diagram`] is a function y(x) sampled over equal intervals of x (x is usually the crank
//! angle φ, rad; y a displacement or one of its analogues), drawn at an abscissa scale μ_x and
//! an ordinate scale μ_y. Every construction here is recorded step by step on a
//! [`Recorder`] whose scale is the ordinate scale of the diagram
//! being constructed; the numbers come out of the drawing through `Recorder::measure`, so the
//! drafting model applies to them.
//!
//! * [`Derivation::Chords`] — the method of chords (Fig. 9): the pole P at distance H left of
//!   the new origin, rays from P parallel to the chords, the step graph, the smooth curve
//!   through the mid-interval points. New scale **μ_y′ = μ_y / (H·μ_x)**.
//! * [`Derivation::Tangents`] — the method of tangents (Fig. 8), with the draughtsman's
//!   tangent (parallel to the chord through the two neighbouring nodes).
//! * [`integrate_chords`] — graphical integration (§15.3): rays from the pole to the
//!   mid-interval ordinates, chords parallel to them. New scale **μ_y = μ_y′·H·μ_x**.
//!   [`integrate_divided_in`] integrates over intervals that need not be equal (a
//!   [`Divided`] diagram: a division point at every break of the integrand, so that it is
//!   smooth over each interval).
//!
//! # Method error
//! The chord value read at a mid-interval point is the central difference
//! `(y(x+h/2) − y(x−h/2))/h = y′(x) + h²/24·y‴(ξ)`: second order, bounded by h²/24·max|y‴|.
//! Node values are read from the smooth curve through the mid-interval points (a cubic
//! through the four nearest ones): the cubic carries the h² error of its data (its weights
//! sum to 1, absolute sum Λ = 1.25 between midpoints) plus its own O(h⁴) interpolation
//! error, so node values are second order too: the error falls about 4× when the intervals
//! are halved. [`chord_node_bound`] evaluates the bound. The tangent method at interior
//! nodes is the central difference over 2h (error h²/6·y‴); at the ends of a non-periodic
//! diagram it falls back to the one-sided chord (first order). Graphical integration with
//! mid-interval ordinates is the midpoint rule: error ≤ (x − x₀)·h²/24·max|y″| of the
//! integrand ([`midpoint_rule_bound`]); integrating the chord derivative's own mid-interval
//! values gives the original node values back exactly (the sum telescopes). The bound holds
//! only where the integrand is smooth over every interval: across a jump J inside an
//! interval the mid-interval ordinate takes one side for the whole interval, an error up to
//! |J|·h/2 that no finer division removes from that interval (first order), so a division
//! point belongs on every jump (the intervals need not then be equal).

mod bounds;
mod breaks;
mod differentiate;
mod integrate;
mod layout;
mod read;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_breaks;
#[cfg(test)]
mod tests_divided;

pub use bounds::{chord_mid_bound, chord_node_bound, midpoint_rule_bound};
pub use breaks::Break;
pub use differentiate::{derivative_scale, pole_for, Derivation, Derivative};
pub use integrate::{
    integral_scale, integrate_chords, integrate_chords_in, integrate_divided_in, Divided, Integral,
    Sampling,
};
pub use layout::DiagramLayout;

use crate::construct::{Item, Recorder, Role, StepId};
use crate::geom::{line_line, DVec2, Line, LineLine, Segment};
use crate::scale::Scale;
use thiserror::Error;

/// A function sampled over equal intervals: node k at `x0 + k·dx` carries `y[k]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagram {
    /// Abscissa of node 0 (physical units, e.g. rad).
    pub x0: f64,
    /// Interval length (physical units); > 0.
    pub dx: f64,
    /// Ordinates at the nodes (physical units).
    pub y: Vec<f64>,
    /// `y` is one full cycle: node N ≡ node 0 is not stored and the intervals wrap around
    /// (N = `y.len()` intervals); otherwise N = `y.len() − 1`.
    pub periodic: bool,
    /// Nodes where the curve has a corner or a jump, in node order (none: smooth throughout).
    pub breaks: Vec<Break>,
}

/// Why a graphical-calculus construction cannot be carried out.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CalculusError {
    /// A break outside the diagram's inner nodes, or given twice.
    #[error("a break at node {node} lies outside the diagram's inner nodes or is given twice")]
    BadBreak {
        /// The node given.
        node: usize,
    },
    /// Graphical integration over equal intervals of a diagram that breaks.
    #[error(
        "the integrand breaks at node {node}: integrate it over a division with a division \
         point at every break (integrate_divided_in)"
    )]
    Broken {
        /// The first break.
        node: usize,
    },
    /// A given number is NaN or infinite.
    #[error("{what} [{index}] is not a finite number: {value}", value = crate::scale::format_plain(*value))]
    NonFinite {
        /// What the number is.
        what: &'static str,
        /// Its index.
        index: usize,
        /// The value.
        value: f64,
    },
    /// The interval length is not positive.
    #[error("the interval Δx = {dx} must be finite and > 0", dx = crate::scale::format_plain(*dx))]
    BadInterval {
        /// The given interval.
        dx: f64,
    },
    /// Fewer than two intervals.
    #[error("a diagram needs at least 2 intervals, got {intervals}")]
    TooFewIntervals {
        /// Intervals given.
        intervals: usize,
    },
    /// A division's mid-interval ordinates do not match its intervals.
    #[error(
        "a division of {intervals} intervals needs as many mid-interval ordinates, got {ordinates}"
    )]
    Ordinates {
        /// Intervals of the division.
        intervals: usize,
        /// Ordinates given.
        ordinates: usize,
    },
    /// The pole distance is not positive.
    #[error("the pole distance H = {pole_mm} mm must be finite and > 0", pole_mm = crate::scale::format_plain(*pole_mm))]
    BadPole {
        /// The given distance, mm.
        pole_mm: f64,
    },
    /// A preferred drawing size is not positive.
    #[error("the preferred ordinate {mm} mm must be finite and > 0", mm = crate::scale::format_plain(*mm))]
    BadPreferred {
        /// The given size, mm.
        mm: f64,
    },
    /// A derived scale is not a valid μ.
    #[error("the derived scale μ = {value} is not finite and positive", value = crate::scale::format_plain(*value))]
    BadScale {
        /// The derived value.
        value: f64,
    },
    /// The recorder does not draw at the scale the construction produces.
    #[error(
        "the recorder's scale μ = {recorder} does not match the constructed diagram's \
         μ = {expected} (= μ_y/(H·μ_x) or μ_y′·H·μ_x)"
    )]
    ScaleMismatch {
        /// The recorder's μ.
        recorder: f64,
        /// The μ the construction gives.
        expected: f64,
    },
    /// A ray from the pole does not cut the line it must cut (a vertical chord).
    #[error("interval {interval}: the line does not cut the {what}")]
    RayMisses {
        /// The interval (or node) index.
        interval: usize,
        /// What it should cut.
        what: &'static str,
    },
    /// A drawing coordinate overflowed (values too large for the scales).
    #[error("{what}: the drawing coordinate is not finite (values too large for the scales)")]
    Overflow {
        /// Where.
        what: &'static str,
    },
}

impl Diagram {
    /// A validated diagram.
    ///
    /// # Errors
    /// See [`Diagram::validate`].
    pub fn new(x0: f64, dx: f64, y: Vec<f64>, periodic: bool) -> Result<Self, CalculusError> {
        let d = Self {
            x0,
            dx,
            y,
            periodic,
            breaks: Vec::new(),
        };
        d.validate()?;
        Ok(d)
    }

    /// Sample `f` at `intervals` equal intervals from `x0` to `x1` (the node at `x1` is left
    /// out of a periodic diagram).
    ///
    /// # Errors
    /// See [`Diagram::validate`].
    pub fn sample(
        x0: f64,
        x1: f64,
        intervals: usize,
        periodic: bool,
        f: impl Fn(f64) -> f64,
    ) -> Result<Self, CalculusError> {
        let dx = (x1 - x0) / intervals as f64;
        let nodes = if periodic { intervals } else { intervals + 1 };
        let y = (0..nodes).map(|k| f(x0 + k as f64 * dx)).collect();
        Self::new(x0, dx, y, periodic)
    }

    /// Finite values, `dx > 0`, at least 2 intervals, breaks at inner nodes.
    ///
    /// # Errors
    /// [`CalculusError::NonFinite`], [`CalculusError::BadInterval`],
    /// [`CalculusError::TooFewIntervals`], [`CalculusError::BadBreak`].
    pub fn validate(&self) -> Result<(), CalculusError> {
        if !self.x0.is_finite() {
            return Err(CalculusError::NonFinite {
                what: "x0",
                index: 0,
                value: self.x0,
            });
        }
        if !(self.dx.is_finite() && self.dx > 0.0) {
            return Err(CalculusError::BadInterval { dx: self.dx });
        }
        if let Some((index, &value)) = self.y.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(CalculusError::NonFinite {
                what: "ordinate y",
                index,
                value,
            });
        }
        if self.intervals() < 2 {
            return Err(CalculusError::TooFewIntervals {
                intervals: self.intervals(),
            });
        }
        self.validate_breaks()
    }

    /// Number of intervals N.
    pub fn intervals(&self) -> usize {
        if self.periodic {
            self.y.len()
        } else {
            self.y.len().saturating_sub(1)
        }
    }

    /// Abscissa of node k.
    pub fn x(&self, k: usize) -> f64 {
        self.x0 + k as f64 * self.dx
    }

    /// Ordinate of node k, 0 ≤ k ≤ N (node N of a periodic diagram is node 0).
    pub fn at(&self, k: usize) -> f64 {
        let n = self.y.len().max(1);
        self.y
            .get(k)
            .or_else(|| self.y.get(k % n))
            .copied()
            .unwrap_or(0.0)
    }
}

/// The pair of scales a diagram is drawn at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scales {
    /// μ_x, abscissa units per mm.
    pub x: Scale,
    /// μ_y, ordinate units per mm.
    pub y: Scale,
}

/// Where a construction is recorded: one figure that holds the given diagram and the
/// constructed one, or each diagram its own figure (its own view on the sheet).
#[derive(Debug)]
pub enum Figures<'a> {
    /// Both diagrams in one figure.
    One(&'a mut Recorder),
    /// The given diagram's steps in `given`, the constructed diagram's in `built`.
    Two {
        /// The figure of the given diagram (the integrand, or the diagram differentiated).
        given: &'a mut Recorder,
        /// The figure of the constructed diagram.
        built: &'a mut Recorder,
    },
}

impl Figures<'_> {
    /// The figure of the given diagram.
    pub fn given(&mut self) -> &mut Recorder {
        match self {
            Figures::One(r) => r,
            Figures::Two { given, .. } => given,
        }
    }

    /// The figure of the constructed diagram.
    pub fn built(&mut self) -> &mut Recorder {
        match self {
            Figures::One(r) => r,
            Figures::Two { built, .. } => built,
        }
    }

    /// Steps of the given figure as the provenance of a step of the constructed one: they
    /// are, in one figure; a step of another figure is no step of this one.
    fn across(&self, ids: &[StepId]) -> Vec<StepId> {
        match self {
            Figures::One(_) => ids.to_vec(),
            Figures::Two { .. } => Vec::new(),
        }
    }
}

/// Figure point of node-space abscissa `t` (in intervals) and ordinate `mm` from `origin`.
fn at_mm(origin: DVec2, t_mm: f64, y_mm: f64) -> DVec2 {
    origin + DVec2::new(t_mm, y_mm)
}

/// `Ok(p)` when `p` is finite.
fn finite(p: DVec2, what: &'static str) -> Result<DVec2, CalculusError> {
    if p.is_finite() {
        Ok(p)
    } else {
        Err(CalculusError::Overflow { what })
    }
}

/// The recorder must draw at `expected`.
fn check_scale(rec: &Recorder, expected: f64) -> Result<Scale, CalculusError> {
    let s = Scale::new(expected, rec.scale().quantity)
        .ok_or(CalculusError::BadScale { value: expected })?;
    let have = rec.scale().value();
    if ((have - expected) / expected).abs() > 1e-9 {
        return Err(CalculusError::ScaleMismatch {
            recorder: have,
            expected,
        });
    }
    Ok(s)
}

/// The pole distance must be positive.
fn check_pole(pole_mm: f64) -> Result<(), CalculusError> {
    if pole_mm.is_finite() && pole_mm > 0.0 {
        Ok(())
    } else {
        Err(CalculusError::BadPole { pole_mm })
    }
}

/// Signed ordinate of a drawn point `p` above the abscissa through `origin`, as read:
/// (read mm, physical value) through `Recorder::measure`.
fn read_ordinate(rec: &mut Recorder, origin: DVec2, p: DVec2) -> (f64, f64) {
    let foot = DVec2::new(p.x, origin.y);
    let m = rec.measure(foot, p);
    let sign = if p.y < origin.y { -1.0 } else { 1.0 };
    (sign * m.read_mm, sign * m.value)
}

/// Draw a pair of arrowed axes at `origin`: the abscissa from `x_from` to `x_to` (mm from
/// the origin), the ordinate from `y_from` to `y_to`, labelled.
pub(crate) fn draw_axes(
    rec: &mut Recorder,
    origin: DVec2,
    (x_from, x_to): (f64, f64),
    (y_from, y_to): (f64, f64),
    (x_name, y_name): (&str, &str),
) -> (StepId, StepId) {
    let xa = at_mm(origin, x_from, 0.0);
    let xb = at_mm(origin, x_to, 0.0);
    let ya = at_mm(origin, 0.0, y_from);
    let yb = at_mm(origin, 0.0, y_to);
    let ax = rec.draw(
        format!("abscissa axis {x_name}"),
        Item::Vector { from: xa, to: xb },
        Role::Construction,
        &[],
    );
    rec.label(ax, x_name, xb, DVec2::new(0.3, -1.0));
    let ay = rec.draw(
        format!("ordinate axis {y_name}"),
        Item::Vector { from: ya, to: yb },
        Role::Construction,
        &[],
    );
    rec.label(ay, y_name, yb, DVec2::new(1.0, 0.2));
    (ax, ay)
}

/// Draw the axes of a diagram whose drawn points are `points`: the abscissa from
/// `left_mm` left of `origin` to 12 mm past `extent`, the ordinate 6 mm below and 12 mm
/// above the points.
fn axes_around(
    rec: &mut Recorder,
    origin: DVec2,
    points: &[DVec2],
    (left_mm, extent): (f64, f64),
    names: (&str, &str),
) -> (StepId, StepId) {
    let (lo, hi) = points.iter().fold((0.0f64, 0.0f64), |(lo, hi), p| {
        (lo.min(p.y - origin.y), hi.max(p.y - origin.y))
    });
    draw_axes(
        rec,
        origin,
        (-left_mm, extent + 12.0),
        (lo - 6.0, hi + 12.0),
        names,
    )
}

/// The point where `line` cuts `target` (interval `k`, for the diagnostic).
fn cut(
    rec: &Recorder,
    line: Option<Line>,
    target: Option<Line>,
    k: usize,
    what: &'static str,
) -> Result<DVec2, CalculusError> {
    let (Some(line), Some(target)) = (line, target) else {
        return Err(CalculusError::Overflow { what });
    };
    match line_line(&line, &target, rec.tolerances()) {
        LineLine::Point { point, .. } => finite(point, what),
        _ => Err(CalculusError::RayMisses { interval: k, what }),
    }
}

/// Draw a diagram's curve, a piece through each run of `pieces` (figure mm; one run unless
/// the curve breaks), with its axes; `extent` is the abscissa length in mm.
fn draw_diagram(
    rec: &mut Recorder,
    origin: DVec2,
    pieces: Vec<Vec<DVec2>>,
    span: (f64, f64),
    names: (&str, &str),
    role: Role,
) {
    let all: Vec<DVec2> = pieces.iter().flatten().copied().collect();
    let (ax, ay) = axes_around(rec, origin, &all, span, names);
    // The division ordinates are implied by the nodes; the curve itself:
    for points in pieces {
        rec.draw(
            format!("curve {}", names.1),
            Item::Curve {
                points,
                closed: false,
            },
            role,
            &[ax, ay],
        );
    }
}

/// Draw the pole at `pole` with its label and the dimension H to `origin` (the foot of the
/// vertical the rays run to).
fn draw_pole(rec: &mut Recorder, pole: DVec2, origin: DVec2, layout: &DiagramLayout) -> StepId {
    let id = rec.point(
        format!(
            "pole {} at H = {:.3} mm",
            layout.pole_name,
            origin.x - pole.x
        ),
        pole,
        Role::Construction,
        &layout.pole_name,
        layout.pole_label_toward,
        &[],
    );
    let dim = rec.draw(
        format!("pole distance {}", layout.pole_distance_name),
        Item::Dimension {
            from: pole,
            to: origin,
            offset: layout.pole_dimension_mm,
        },
        Role::Dimension,
        &[id],
    );
    rec.label(
        dim,
        &layout.pole_distance_name,
        (pole + origin) * 0.5,
        DVec2::ZERO,
    );
    id
}

/// The vertical at `x` the rays from a pole run to, when the layout puts it elsewhere than
/// an ordinate axis ([`DiagramLayout::ray_axis`]): a thin line from the abscissa level `base`
/// through every level in `ys`. Nothing when the rays run to the origin's ordinate axis.
fn ray_axis_line(rec: &mut Recorder, layout: &DiagramLayout, x: f64, base: f64, ys: &[f64]) {
    if layout.ray_axis.is_none() {
        return;
    }
    let (lo, hi) = ys
        .iter()
        .fold((base, base), |(lo, hi), &y| (lo.min(y), hi.max(y)));
    if hi - lo > rec.tolerances().coincident {
        thin(
            rec,
            "the vertical the rays run to".into(),
            DVec2::new(x, lo),
            DVec2::new(x, hi),
            &[],
        );
    }
}

/// A thin construction segment.
pub(crate) fn thin(
    rec: &mut Recorder,
    note: String,
    a: DVec2,
    b: DVec2,
    from: &[StepId],
) -> StepId {
    rec.draw(
        note,
        Item::Segment(Segment::new(a, b)),
        Role::Construction,
        from,
    )
}
