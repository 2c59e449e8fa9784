//! Graphical integration (§15.3, Fig. 71): rays from the pole to the mid-interval ordinates,
//! chords parallel to them.

use super::read::{drawn, read};
use super::*;
use crate::scale::Quantity;

/// Where the integrand's samples sit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sampling {
    /// At the nodes `x0 + k·dx` (a [`Diagram`] as it is); the mid-interval ordinate is read
    /// from the curve (the cubic through the four nearest nodes).
    Nodes,
    /// At the interval midpoints `x0 + (k + ½)·dx`, k = 0..len (e.g. [`super::Derivative::mid`]);
    /// `len` intervals whatever `periodic` says.
    Midpoints,
}

/// A given diagram divided for graphical integration: the division points x₀ < x₁ < … < x_N
/// (equal intervals, or with a division point at every break of the curve so that the curve
/// is smooth over each interval — the intervals need not be equal) and the ordinate the
/// method takes at the middle of each interval.
#[derive(Debug, Clone, PartialEq)]
pub struct Divided {
    /// The division points, ascending (physical units).
    pub x: Vec<f64>,
    /// The ordinate at the middle of each interval (physical units), one per interval.
    pub mid: Vec<f64>,
}

impl Divided {
    /// A validated division.
    ///
    /// # Errors
    /// [`CalculusError::NonFinite`] for a value that is not finite,
    /// [`CalculusError::BadInterval`] for an interval that is not > 0,
    /// [`CalculusError::TooFewIntervals`] for fewer than 2 intervals,
    /// [`CalculusError::Ordinates`] when there is not one ordinate per interval.
    pub fn new(x: Vec<f64>, mid: Vec<f64>) -> Result<Self, CalculusError> {
        let all_finite = |what: &'static str, v: &[f64]| match v.iter().position(|v| !v.is_finite())
        {
            Some(index) => Err(CalculusError::NonFinite {
                what,
                index,
                value: v[index],
            }),
            None => Ok(()),
        };
        all_finite("division point x", &x)?;
        all_finite("mid-interval ordinate", &mid)?;
        if let Some(w) = x.windows(2).find(|w| w[1] <= w[0]) {
            return Err(CalculusError::BadInterval { dx: w[1] - w[0] });
        }
        let intervals = x.len().saturating_sub(1);
        if intervals < 2 {
            return Err(CalculusError::TooFewIntervals { intervals });
        }
        if mid.len() != intervals {
            return Err(CalculusError::Ordinates {
                intervals,
                ordinates: mid.len(),
            });
        }
        Ok(Self { x, mid })
    }

    /// The number of intervals N.
    pub fn intervals(&self) -> usize {
        self.mid.len()
    }
}

/// An integral diagram as constructed and read off the drawing.
#[derive(Debug, Clone, PartialEq)]
pub struct Integral {
    /// Its ordinate scale μ_y = μ_y′·H·μ_x.
    pub scale: Scale,
    /// The pole distance H, mm.
    pub pole_mm: f64,
    /// The pole P, figure mm (on the integrand's abscissa axis).
    pub pole: DVec2,
    /// Whether the pole and its rays are drawn: an integrand with no ordinate the drawing
    /// shows (a uniform law's d²S/dφ²) is integrated without them, its integral a line
    /// parallel to the abscissa from the start value ([`Integral::rays`] empty).
    pub pole_drawn: bool,
    /// Abscissae of the nodes 0..=N (the division points).
    pub x: Vec<f64>,
    /// Values at the nodes 0..=N, physical units, as read (node 0 is the start value).
    pub node: Vec<f64>,
    /// The recorded rays from the pole, one per interval.
    pub rays: Vec<StepId>,
    /// The recorded chords of the integral diagram, one per interval.
    pub chords: Vec<StepId>,
    /// The recorded smooth curve through the chord ends.
    pub curve: StepId,
}

/// The integral's ordinate scale μ_y = μ_y′·H·μ_x (the inverse of the derivative's).
///
/// # Errors
/// [`CalculusError::BadPole`] for H ≤ 0, [`CalculusError::BadScale`] if the result is not
/// a valid μ.
pub fn integral_scale(
    integrand: Scale,
    x: Scale,
    pole_mm: f64,
    quantity: Quantity,
) -> Result<Scale, CalculusError> {
    check_pole(pole_mm)?;
    let value = integrand.value() * pole_mm * x.value();
    Scale::new(value, quantity).ok_or(CalculusError::BadScale { value })
}

/// Integrate the integrand `src` (drawn at `scales`) graphically, recording on `rec`, whose
/// scale must be μ_y′·H·μ_x (see [`integral_scale`]): the integrand's curve and axes
/// (optional) at `layout.source_origin`; the pole P on its abscissa axis at H left of its
/// origin (or of [`DiagramLayout::ray_axis`]); for every interval the perpendicular at the middle
/// up to the curve, its horizontal projection to the ordinate axis and the ray from P to
/// that projection (thin); in the integral diagram at `layout.origin`, from `start`
/// (physical, default 0) onwards, a chord across each interval parallel to its ray,
/// starting where the previous one ended; the smooth curve through the chord ends (result).
/// Node values are the drawn ordinates measured with `Recorder::measure`.
///
/// # Errors
/// An invalid integrand, one with breaks ([`CalculusError::Broken`]), H ≤ 0, a recorder at
/// another scale, or values too large to draw.
pub fn integrate_chords(
    rec: &mut Recorder,
    src: &Diagram,
    sampling: Sampling,
    scales: Scales,
    pole_mm: f64,
    start: f64,
    layout: &DiagramLayout,
) -> Result<Integral, CalculusError> {
    integrate_chords_in(
        Figures::One(rec),
        src,
        sampling,
        scales,
        pole_mm,
        start,
        layout,
    )
}

/// [`integrate_chords`] into `figs`: the integrand's construction (its curve, the pole, the
/// perpendiculars, projections and rays) in the given diagram's figure, the chords and the
/// curve of the integral in the constructed one's, whose scale must be μ_y′·H·μ_x.
///
/// # Errors
/// As [`integrate_chords`].
pub fn integrate_chords_in(
    figs: Figures<'_>,
    src: &Diagram,
    sampling: Sampling,
    scales: Scales,
    pole_mm: f64,
    start: f64,
    layout: &DiagramLayout,
) -> Result<Integral, CalculusError> {
    if let Some(b) = src.breaks.first() {
        return Err(CalculusError::Broken { node: b.node });
    }
    let (n, means) = match sampling {
        Sampling::Nodes => {
            src.validate()?;
            let n = src.intervals();
            let means = (0..n)
                .map(|k| read(&src.y, 0.0, src.periodic, k as f64 + 0.5))
                .collect();
            (n, means)
        }
        Sampling::Midpoints => {
            // As many intervals as samples: validate as a cycle of that length.
            let as_cycle = Diagram {
                periodic: true,
                ..src.clone()
            };
            as_cycle.validate()?;
            (src.y.len(), src.y.clone())
        }
    };
    let run = scales.x.to_mm(src.dx);
    let so = layout.source_origin;
    // The integrand's curve as the draughtsman draws it through the nodes, at READ_PIECES
    // points an interval; every mean ordinate read above ends on it (read::drawn).
    let curve = match sampling {
        Sampling::Nodes => Some(
            (0..=n * READ_PIECES)
                .map(|j| {
                    let t = j as f64 / READ_PIECES as f64;
                    let y = drawn(&src.y, src.periodic, t);
                    at_mm(so, t * run, scales.y.to_mm(y))
                })
                .collect(),
        ),
        Sampling::Midpoints => None,
    };
    let drawn = Drawn {
        nodes_mm: (0..=n).map(|k| k as f64 * run).collect(),
        mids_mm: (0..n).map(|k| (k as f64 + 0.5) * run).collect(),
        means,
        curve,
    };
    let out = chords_through(figs, &drawn, scales, pole_mm, start, layout)?;
    Ok(out.into_integral((0..=n).map(|k| src.x(k)).collect(), pole_mm))
}

/// Integrate the division `src` (drawn at `scales`) graphically into `figs`, as
/// [`integrate_chords_in`] does, over its intervals as they are divided: the perpendicular
/// at the middle of each, the ray from the pole, the chord across it from the previous
/// chord's end to the ordinate at its division point. Over intervals on each of which the
/// integrand is smooth (a division point at every break) the error is the midpoint rule's,
/// ≤ Σ hᵢ³/24·max|y″| ≤ (x_N − x₀)·h_max²/24·max|y″| over the pieces
/// ([`midpoint_rule_bound`] with h_max).
///
/// # Errors
/// An invalid division, H ≤ 0, a recorder at another scale, or values too large to draw.
pub fn integrate_divided_in(
    figs: Figures<'_>,
    src: &Divided,
    scales: Scales,
    pole_mm: f64,
    start: f64,
    layout: &DiagramLayout,
) -> Result<Integral, CalculusError> {
    let src = Divided::new(src.x.clone(), src.mid.clone())?;
    let x0 = src.x[0];
    let nodes_mm: Vec<f64> = src.x.iter().map(|&x| scales.x.to_mm(x - x0)).collect();
    let drawn = Drawn {
        mids_mm: nodes_mm.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect(),
        nodes_mm,
        means: src.mid.clone(),
        curve: None,
    };
    let out = chords_through(figs, &drawn, scales, pole_mm, start, layout)?;
    Ok(out.into_integral(src.x, pole_mm))
}

/// The points an interval of the integrand's curve (from nodes) is drawn through, as near as
/// the plate's smooth curve through them follows [`drawn`]'s.
const READ_PIECES: usize = 8;

/// The integrand as the construction draws it, abscissae in mm from the origins.
struct Drawn {
    /// The division points.
    nodes_mm: Vec<f64>,
    /// The middles of the intervals.
    mids_mm: Vec<f64>,
    /// The ordinates at the middles (physical).
    means: Vec<f64>,
    /// The given curve to draw with its axes (figure mm); `None`: through the mid-interval
    /// points.
    curve: Option<Vec<DVec2>>,
}

/// What [`chords_through`] constructs.
struct Chords {
    scale: Scale,
    pole: DVec2,
    pole_drawn: bool,
    node: Vec<f64>,
    rays: Vec<StepId>,
    chords: Vec<StepId>,
    curve: StepId,
}

impl Chords {
    fn into_integral(self, x: Vec<f64>, pole_mm: f64) -> Integral {
        Integral {
            scale: self.scale,
            pole_mm,
            pole: self.pole,
            pole_drawn: self.pole_drawn,
            x,
            node: self.node,
            rays: self.rays,
            chords: self.chords,
            curve: self.curve,
        }
    }
}

/// The construction of [`integrate_chords_in`] over the intervals of `d`.
fn chords_through(
    mut figs: Figures<'_>,
    d: &Drawn,
    scales: Scales,
    pole_mm: f64,
    start: f64,
    layout: &DiagramLayout,
) -> Result<Chords, CalculusError> {
    if !start.is_finite() {
        return Err(CalculusError::NonFinite {
            what: "start value",
            index: 0,
            value: start,
        });
    }
    check_pole(pole_mm)?;
    let scale = check_scale(figs.built(), scales.y.value() * pole_mm * scales.x.value())?;
    let so = layout.source_origin;
    let m_pts = d
        .mids_mm
        .iter()
        .zip(&d.means)
        .map(|(&x, &m)| finite(at_mm(so, x, scales.y.to_mm(m)), "integrand"))
        .collect::<Result<Vec<_>, _>>()?;
    let extent = d.nodes_mm.last().copied().unwrap_or(0.0);
    let given = figs.given();
    if layout.draw_source {
        draw_diagram(
            given,
            so,
            vec![d.curve.clone().unwrap_or_else(|| m_pts.clone())],
            (pole_mm + 6.0, extent),
            (&layout.x_name, &layout.source_name),
            Role::Given,
        );
    }
    let axis_x = layout.ray_x(so);
    let pole = DVec2::new(axis_x - pole_mm, so.y);
    // An integrand whose every ordinate is under the drawing's coincidence has no ray to
    // draw: each would lie on the abscissa axis, the pole and its distance marking nothing.
    let flat = given.tolerances().coincident;
    let pole_drawn = m_pts.iter().any(|m| (m.y - so.y).abs() > flat);
    let pole_id = pole_drawn.then(|| draw_pole(given, pole, DVec2::new(axis_x, so.y), layout));
    let levels: Vec<f64> = m_pts.iter().map(|m| m.y).collect();
    if pole_drawn {
        ray_axis_line(given, layout, axis_x, so.y, &levels);
    }
    let o = layout.origin;
    let mut ends = vec![finite(at_mm(o, 0.0, scale.to_mm(start)), "start value")?];
    let mut rays = Vec::with_capacity(m_pts.len());
    let mut chords = Vec::with_capacity(m_pts.len());
    for (k, (&m, &x_end)) in m_pts.iter().zip(&d.nodes_mm[1..]).enumerate() {
        let q = DVec2::new(axis_x, m.y);
        let ray = pole_id.map(|pole_id| {
            let given = figs.given();
            let foot = DVec2::new(m.x, so.y);
            let perp = thin(given, format!("mean ordinate {k}"), foot, m, &[]);
            let proj = thin(given, format!("projection {k}"), m, q, &[perp]);
            let from = [pole_id, proj];
            thin(given, format!("ray {k} from the pole"), pole, q, &from)
        });
        let prev = ends[k];
        let along = Line::new(prev, q - pole).ok_or(CalculusError::Overflow { what: "chord" })?;
        let ordinate = Line::new(at_mm(o, x_end, 0.0), DVec2::Y)
            .ok_or(CalculusError::Overflow { what: "ordinate" })?;
        let built = figs.built();
        let end = match line_line(&along, &ordinate, built.tolerances()) {
            LineLine::Point { point, .. } => finite(point, "chord end")?,
            _ => {
                return Err(CalculusError::RayMisses {
                    interval: k,
                    what: "interval's end ordinate",
                })
            }
        };
        let from = figs.across(ray.as_slice());
        let note = match ray {
            Some(_) => format!("chord {k}–{} ∥ ray {k}", k + 1),
            None => format!("chord {k}–{} ∥ the abscissa: the integrand is zero", k + 1),
        };
        chords.push(thin(figs.built(), note, prev, end, &from));
        rays.extend(ray);
        ends.push(end);
    }
    let built = figs.built();
    if layout.draw_axes {
        axes_around(
            built,
            o,
            &ends,
            (6.0, extent),
            (&layout.x_name, &layout.name),
        );
    }
    let node: Vec<f64> = ends.iter().map(|&e| read_ordinate(built, o, e).1).collect();
    let curve = built.draw(
        format!("smooth curve {} through the chord ends", layout.name),
        Item::Curve {
            points: ends,
            closed: false,
        },
        Role::Result,
        &chords,
    );
    if !node.iter().all(|v| v.is_finite()) {
        return Err(CalculusError::Overflow {
            what: "integral values",
        });
    }
    Ok(Chords {
        scale,
        pole,
        pole_drawn,
        node,
        rays,
        chords,
        curve,
    })
}
