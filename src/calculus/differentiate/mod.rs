//! Graphical differentiation: the methods of chords (Fig. 9) and of tangents (Fig. 8).

mod tangents;

use super::breaks::NodeReads;
use super::*;
use crate::scale::Quantity;

/// Which construction produced a derivative.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Derivation {
    /// Rays parallel to the chords; values at mid-interval points, nodes read off the curve.
    Chords,
    /// Rays parallel to the (draughtsman's) tangents at the nodes.
    Tangents,
}

impl Derivation {
    /// Differentiate `src` (drawn at `scales`) by this construction, the pole H = `pole_mm`
    /// left of `layout.origin`, recording on `rec`, whose scale must be μ_y/(H·μ_x) (see
    /// [`derivative_scale`]): [`Derivation::Chords`] or [`Derivation::Tangents`].
    ///
    /// # Errors
    /// As for the method of chords.
    pub fn differentiate(
        self,
        rec: &mut Recorder,
        src: &Diagram,
        scales: Scales,
        pole_mm: f64,
        layout: &DiagramLayout,
    ) -> Result<Derivative, CalculusError> {
        self.differentiate_in(Figures::One(rec), src, scales, pole_mm, layout)
    }

    /// [`Derivation::differentiate`] into `figs`: the given diagram (its curve, chords or
    /// tangents) in the given figure; the pole, the rays, the projections and the derivative's
    /// curve in the constructed one, whose scale must be μ_y/(H·μ_x).
    ///
    /// # Errors
    /// As [`Derivation::differentiate`].
    pub fn differentiate_in(
        self,
        mut figs: Figures<'_>,
        src: &Diagram,
        scales: Scales,
        pole_mm: f64,
        layout: &DiagramLayout,
    ) -> Result<Derivative, CalculusError> {
        let st = Start::new(&mut figs, src, scales, pole_mm, layout)?;
        match self {
            Derivation::Chords => chords(&mut figs, &st),
            Derivation::Tangents => tangents::tangents(&mut figs, &st),
        }
    }
}

/// A derivative diagram as constructed and read off the drawing.
#[derive(Debug, Clone, PartialEq)]
pub struct Derivative {
    /// The construction used.
    pub method: Derivation,
    /// Its ordinate scale μ_y′ = μ_y/(H·μ_x).
    pub scale: Scale,
    /// The pole distance H, mm.
    pub pole_mm: f64,
    /// The pole P, figure mm.
    pub pole: DVec2,
    /// Abscissa of node 0.
    pub x0: f64,
    /// Interval length.
    pub dx: f64,
    /// Abscissae of the interval midpoints (empty for the tangent method).
    pub x_mid: Vec<f64>,
    /// Values at the interval midpoints, physical units, as read (empty for tangents).
    pub mid: Vec<f64>,
    /// Abscissae of the nodes (node N of a periodic diagram is left out, as in the source).
    pub x_node: Vec<f64>,
    /// Values at the nodes, physical units, as read from the smooth curve (at a break of the
    /// source, the piece's after it).
    pub node: Vec<f64>,
    /// At every break of the source, the value the piece before it reaches there.
    pub breaks: Vec<Break>,
    /// The source was periodic.
    pub periodic: bool,
    /// The recorded rays from the pole, one per interval (chords) or node (tangents; two at
    /// a break, the piece's before it first).
    pub rays: Vec<StepId>,
    /// The recorded smooth curve (its last piece, when the source breaks).
    pub curve: StepId,
}

impl Derivative {
    /// The node values as a diagram (to differentiate again or integrate).
    ///
    /// # Errors
    /// See [`Diagram::validate`].
    pub fn diagram(&self) -> Result<Diagram, CalculusError> {
        Diagram::new(self.x0, self.dx, self.node.clone(), self.periodic)?
            .with_breaks(self.breaks.clone())
    }
}

/// The derivative's ordinate scale μ_y′ = μ_y / (H·μ_x) (eq. 5 and 6 of the textbook).
///
/// # Errors
/// [`CalculusError::BadPole`] for H ≤ 0, [`CalculusError::BadScale`] if the result is not
/// a valid μ.
pub fn derivative_scale(
    y: Scale,
    x: Scale,
    pole_mm: f64,
    quantity: Quantity,
) -> Result<Scale, CalculusError> {
    check_pole(pole_mm)?;
    let value = y.value() / (pole_mm * x.value());
    Scale::new(value, quantity).ok_or(CalculusError::BadScale { value })
}

/// The pole distance H chosen the textbook way: the steepest chord drawn from the pole
/// cuts the ordinate axis `preferred_mm` (e.g. 40–60 mm) from the origin, H rounded to
/// 0.5 mm (at least 0.5 mm). A flat diagram gets H = `preferred_mm` rounded. To override,
/// pass your own H to the constructions instead.
///
/// # Errors
/// An invalid diagram, or [`CalculusError::BadPreferred`].
pub fn pole_for(src: &Diagram, scales: Scales, preferred_mm: f64) -> Result<f64, CalculusError> {
    src.validate()?;
    if !(preferred_mm.is_finite() && preferred_mm > 0.0) {
        return Err(CalculusError::BadPreferred { mm: preferred_mm });
    }
    let run_mm = scales.x.to_mm(src.dx);
    let steepest = (0..src.intervals())
        .map(|k| (scales.y.to_mm(src.before(k + 1)) - scales.y.to_mm(src.at(k))).abs() / run_mm)
        .fold(0.0f64, f64::max);
    let h = if steepest > 0.0 && steepest.is_finite() {
        preferred_mm / steepest
    } else {
        preferred_mm
    };
    let h = ((h * 2.0).round() / 2.0).max(0.5);
    if h.is_finite() {
        Ok(h)
    } else {
        Err(CalculusError::BadPole { pole_mm: h })
    }
}

/// A point the given curve is drawn through between its nodes is left out nearer a node
/// than this, mm: two readings that close would turn the curve on their rounding.
const THROUGH_APART_MM: f64 = 1.0;

/// What both methods start from: the checked inputs and the given diagram.
struct Start<'a> {
    /// The given diagram.
    src: &'a Diagram,
    /// Where the given diagram and its derivative are drawn.
    layout: &'a DiagramLayout,
    /// The derivative's scale.
    scale: Scale,
    /// Intervals.
    n: usize,
    /// Interval length on the drawing, mm.
    run: f64,
    /// The given diagram's nodes 0..=N, figure mm (at a break, the piece's after it).
    pts: Vec<DVec2>,
    /// Where each interval's piece ends: node k + 1 of interval k (another point at a jump).
    ends: Vec<DVec2>,
    /// The pole distance H, mm.
    pole_mm: f64,
}

impl<'a> Start<'a> {
    /// Check the inputs, place the given diagram's nodes and draw its curve if asked.
    fn new(
        figs: &mut Figures<'_>,
        src: &'a Diagram,
        scales: Scales,
        pole_mm: f64,
        layout: &'a DiagramLayout,
    ) -> Result<Self, CalculusError> {
        src.validate()?;
        check_pole(pole_mm)?;
        let scale = check_scale(
            figs.built(),
            scales.y.value() / (pole_mm * scales.x.value()),
        )?;
        let n = src.intervals();
        let run = scales.x.to_mm(src.dx);
        let node = |k: usize, y: f64| {
            let p = at_mm(layout.source_origin, k as f64 * run, scales.y.to_mm(y));
            finite(p, "given diagram")
        };
        let pts = (0..=n)
            .map(|k| node(k, src.at(k)))
            .collect::<Result<Vec<_>, _>>()?;
        let ends = (1..=n)
            .map(|k| node(k, src.before(k)))
            .collect::<Result<Vec<_>, _>>()?;
        if layout.draw_source {
            let pieces = src
                .spans()
                .into_iter()
                .map(|(a, b)| {
                    let mut piece = pts[a..b].to_vec();
                    piece.push(ends[b - 1]);
                    // A point between the nodes joins the piece whose span holds it,
                    // unless it stands at one of its nodes.
                    let (lo, hi) = (piece[0].x, piece[piece.len() - 1].x);
                    let through: Vec<DVec2> = (layout.source_through.iter())
                        .map(|p| layout.source_origin + *p)
                        .filter(|p| p.x > lo && p.x < hi)
                        .filter(|p| piece.iter().all(|q| (q.x - p.x).abs() >= THROUGH_APART_MM))
                        .collect();
                    piece.extend(through);
                    piece.sort_by(|p, q| p.x.total_cmp(&q.x));
                    piece
                })
                .collect();
            draw_diagram(
                figs.given(),
                layout.source_origin,
                pieces,
                (6.0, run * n as f64),
                (&layout.x_name, &layout.source_name),
                Role::Given,
            );
        }
        Ok(Self {
            src,
            layout,
            scale,
            n,
            run,
            pts,
            ends,
            pole_mm,
        })
    }

    /// The derivative with its common fields filled and no values yet.
    fn derivative(&self, method: Derivation, pc: &PoleCut) -> Derivative {
        let src = self.src;
        let nodes = if src.periodic { self.n } else { self.n + 1 };
        Derivative {
            method,
            scale: self.scale,
            pole_mm: pc.pole_mm,
            pole: pc.pole,
            x0: src.x0,
            dx: src.dx,
            x_mid: Vec::new(),
            mid: Vec::new(),
            x_node: (0..nodes).map(|k| src.x(k)).collect(),
            node: Vec::with_capacity(nodes),
            breaks: Vec::new(),
            periodic: src.periodic,
            rays: Vec::with_capacity(nodes),
            curve: pc.pole_id,
        }
    }
}

/// The pole construction shared by both methods: for each direction, the point where the
/// ray from P parallel to it cuts the ordinate axis. Draws the axes, around the cuts and the
/// ordinates (figure mm) `curve` finds the derivative's curve reaching from them, and the
/// pole.
struct PoleCut {
    pole_mm: f64,
    pole: DVec2,
    pole_id: StepId,
    axis: Option<StepId>,
    /// The ordinate axis the rays are cut by.
    ordinate: Option<Line>,
    cuts: Vec<DVec2>,
}

fn pole_cuts(
    rec: &mut Recorder,
    layout: &DiagramLayout,
    pole_mm: f64,
    dirs: &[DVec2],
    extent: f64,
    curve: impl FnOnce(&[DVec2]) -> Vec<f64>,
) -> Result<PoleCut, CalculusError> {
    let o = layout.origin;
    let axis_x = layout.ray_x(o);
    let foot = DVec2::new(axis_x, o.y);
    let pole = foot - DVec2::new(pole_mm, 0.0);
    let axis = Line::new(foot, DVec2::Y);
    let cuts = dirs
        .iter()
        .enumerate()
        .map(|(k, &d)| cut(rec, Line::new(pole, d), axis, k, "ordinate axis"))
        .collect::<Result<Vec<_>, _>>()?;
    let axis_id = if layout.draw_axes {
        let mut reached = cuts.clone();
        reached.extend(curve(&cuts).into_iter().map(|y| DVec2::new(o.x, y)));
        Some(
            axes_around(
                rec,
                o,
                &reached,
                (pole_mm + 6.0, extent),
                (&layout.x_name, &layout.name),
            )
            .1,
        )
    } else {
        None
    };
    let levels: Vec<f64> = cuts.iter().map(|c| c.y).collect();
    ray_axis_line(rec, layout, axis_x, o.y, &levels);
    let pole_id = draw_pole(rec, pole, foot, layout);
    Ok(PoleCut {
        pole_mm,
        pole,
        pole_id,
        axis: axis_id,
        ordinate: axis,
        cuts,
    })
}

/// Draw the ray P → `cut`, project `cut` horizontally to abscissa `x` (figure mm) and mark
/// the result point there. `from`: the line the ray is parallel to, when it is a step of
/// this figure. Returns (ray id, the point).
fn ray_and_project(
    rec: &mut Recorder,
    pc: &PoleCut,
    k: usize,
    x: f64,
    from: &[StepId],
) -> (StepId, DVec2) {
    let cut = pc.cuts.get(k).copied().unwrap_or(pc.pole);
    let mut deps = vec![pc.pole_id];
    deps.extend_from_slice(from);
    deps.extend(pc.axis);
    let ray = thin(
        rec,
        format!("ray {k} from the pole parallel to line {k}"),
        pc.pole,
        cut,
        &deps,
    );
    let target = DVec2::new(x, cut.y);
    if (target.x - cut.x).abs() > rec.tolerances().coincident {
        thin(rec, format!("projection {k}"), cut, target, &[ray]);
    }
    (ray, target)
}

/// Differentiate `st.src` by the method of chords, recording the textbook
/// steps on `rec`, whose scale must be the derivative's μ_y/(H·μ_x) (see
/// [`derivative_scale`]):
/// the given curve (optional) and its chords (thin); the pole P at H left of
/// `layout.origin` with the dimension H; for every interval a ray from P parallel to the
/// chord, cut by the ordinate axis; the horizontal projection of the cut and the step graph
/// (thin); the mid-interval points on the steps and the smooth curve through them (result).
/// Mid-interval values are the drawn ordinates measured with `Recorder::measure`; node
/// values are read from the smooth curve (the cubic through the four nearest midpoints).
///
/// # Errors
/// An invalid diagram, H ≤ 0, a recorder at another scale, a vertical chord, or values
/// too large to draw.
fn chords(figs: &mut Figures<'_>, st: &Start) -> Result<Derivative, CalculusError> {
    let (n, run, pts) = (st.n, st.run, &st.pts);
    let (src, layout) = (st.src, st.layout);
    let chords: Vec<StepId> = (0..n)
        .map(|k| {
            thin(
                figs.given(),
                format!("chord {k}–{}", k + 1),
                pts[k],
                st.ends[k],
                &[],
            )
        })
        .collect();
    let chords = figs.across(&chords);
    let rec = figs.built();
    let dirs: Vec<DVec2> = (0..n).map(|k| st.ends[k] - pts[k]).collect();
    let o = layout.origin;
    // The nodes read off the curve through the cuts' heights (the mid-interval points stand
    // level with them): read once, for the axes' reach and for the nodes.
    let node_reads = |cuts: &[DVec2]| {
        let mids: Vec<f64> = cuts.iter().map(|c| c.y - o.y).collect();
        NodeReads::of(src, &mids)
    };
    let mut read = None;
    let curve = |cuts: &[DVec2]| {
        let reads = node_reads(cuts);
        let reach = (reads.right.iter().chain(&reads.left))
            .map(|y| o.y + y)
            .collect();
        read = Some(reads);
        reach
    };
    let pc = pole_cuts(rec, layout, st.pole_mm, &dirs, run * n as f64, curve)?;
    let reads = read.unwrap_or_else(|| node_reads(&pc.cuts));
    let mut d = st.derivative(Derivation::Chords, &pc);
    for k in 0..n {
        // The cut goes across to the end of its interval nearer the vertical it lies on.
        let (start, end) = (o.x + k as f64 * run, o.x + (k + 1) as f64 * run);
        let x = if pc.cuts.get(k).is_some_and(|c| c.x > end) {
            end
        } else {
            start
        };
        let (ray, _) = ray_and_project(rec, &pc, k, x, chords.get(k..=k).unwrap_or(&[]));
        d.rays.push(ray);
    }
    let steps: Vec<DVec2> = pc
        .cuts
        .iter()
        .enumerate()
        .flat_map(|(k, c)| {
            [
                DVec2::new(o.x + k as f64 * run, c.y),
                DVec2::new(o.x + (k + 1) as f64 * run, c.y),
            ]
        })
        .collect();
    let stair = rec.draw(
        "step graph: each cut projected across its interval",
        Item::Polyline {
            points: steps,
            closed: false,
        },
        Role::Construction,
        &d.rays,
    );
    let mut mid = Vec::with_capacity(n);
    let mut mid_pts = Vec::with_capacity(n);
    for (k, c) in pc.cuts.iter().enumerate() {
        let p = DVec2::new(o.x + (k as f64 + 0.5) * run, c.y);
        rec.draw(
            format!("mid-interval point {k}"),
            Item::Point(p),
            Role::Result,
            &[stair],
        );
        mid.push(read_ordinate(rec, o, p).1);
        mid_pts.push(p);
    }
    let curve = chord_nodes(figs, st, (&pc, &reads), &mid_pts, stair, &mut d)?;
    d.x_mid = (0..n).map(|k| src.x0 + (k as f64 + 0.5) * src.dx).collect();
    d.mid = mid;
    d.curve = curve;
    finish(d)
}

/// The chords' node values `reads`, read off the smooth curve through the mid-interval
/// points `mid_pts` (each piece's own, when the source breaks; an end the law's tangent fixes
/// from the ray parallel to it) into `d`, with the values before the breaks marked; the curve
/// drawn a piece a span. Returns the (last) curve step.
fn chord_nodes(
    figs: &mut Figures<'_>,
    st: &Start,
    (pc, reads): (&PoleCut, &NodeReads),
    mid_pts: &[DVec2],
    stair: StepId,
    d: &mut Derivative,
) -> Result<StepId, CalculusError> {
    let (n, run, src, layout) = (st.n, st.run, st.src, st.layout);
    let o = layout.origin;
    let at = |k: usize, y: f64| DVec2::new(o.x + k as f64 * run, o.y + y);
    let mut node_pts: Vec<DVec2> = (0..=n).map(|k| at(k, reads.right[k])).collect();
    // An end whose tangent the law fixes: the node there from the ray parallel to it.
    for (k, dir) in [(0, layout.end_tangents[0]), (n, layout.end_tangents[1])] {
        if let Some(dir) = dir {
            node_pts[k] = end_node(figs, st, pc, k, dir)?;
        }
    }
    let rec = figs.built();
    d.node = node_pts[..d.x_node.len()]
        .iter()
        .map(|&p| read_ordinate(rec, o, p).1)
        .collect();
    for (b, &left) in src.breaks.iter().zip(&reads.left) {
        let p = at(b.node, left);
        rec.draw(
            format!(
                "node point {} where the piece before the break ends",
                b.node
            ),
            Item::Point(p),
            Role::Result,
            &[stair],
        );
        d.breaks.push(Break {
            node: b.node,
            left: read_ordinate(rec, o, p).1,
        });
    }
    let mut curve = pc.pole_id;
    for (a, b) in src.spans() {
        let mut points = vec![node_pts[a]];
        points.extend_from_slice(&mid_pts[a..b]);
        points.push(reads.left_at(src, b).map_or(node_pts[b], |y| at(b, y)));
        curve = rec.draw(
            format!(
                "smooth curve {} through the mid-interval points",
                layout.name
            ),
            Item::Curve {
                points,
                closed: false,
            },
            Role::Result,
            &[stair],
        );
    }
    Ok(curve)
}

/// Half the length of a tangent drawn at a diagram's end, mm.
const END_TANGENT_MM: f64 = 8.0;

/// The derivative's node `k` at an end of the given diagram from the tangent there (direction
/// `dir`, figure mm): the tangent drawn through the node, the ray from the pole parallel to
/// it cut by the ordinate axis, the cut projected to the node's ordinate and marked.
fn end_node(
    figs: &mut Figures<'_>,
    st: &Start,
    pc: &PoleCut,
    k: usize,
    dir: DVec2,
) -> Result<DVec2, CalculusError> {
    let p = st.pts[k];
    let half = dir.normalize_or_zero() * END_TANGENT_MM;
    let tangent = thin(
        figs.given(),
        format!("tangent at node {k}, as the law fixes it"),
        p - half,
        p + half,
        &[],
    );
    let from = figs.across(&[tangent]);
    let rec = figs.built();
    let o = st.layout.origin;
    let c = cut(
        rec,
        Line::new(pc.pole, dir),
        pc.ordinate,
        k,
        "ordinate axis",
    )?;
    let mut deps = vec![pc.pole_id];
    deps.extend(from);
    let ray = thin(
        rec,
        format!("ray from the pole parallel to the tangent at node {k}"),
        pc.pole,
        c,
        &deps,
    );
    let at = DVec2::new(o.x + k as f64 * st.run, c.y);
    if (at.x - c.x).abs() > rec.tolerances().coincident {
        thin(
            rec,
            format!("projection of the tangent's cut {k}"),
            c,
            at,
            &[ray],
        );
    }
    rec.draw(
        format!("node point {k} from the tangent"),
        Item::Point(at),
        Role::Result,
        &[ray],
    );
    Ok(at)
}

/// Every value read must be finite.
fn finish(d: Derivative) -> Result<Derivative, CalculusError> {
    if d.mid.iter().chain(&d.node).all(|v| v.is_finite()) {
        Ok(d)
    } else {
        Err(CalculusError::Overflow {
            what: "derivative values",
        })
    }
}
