//! The constructions: the polygon of static moments (static balancing), and the polygon of
//! moments followed by the polygon of static moments (dynamic balancing), each vector laid
//! head to tail through the recorder and each closing vector read off the drawing.

use super::rotor;
use super::{analytic, BalancingError, BalancingSpec, Correction, Corrective, Mass, Plane};
use crate::construct::{Context, Figure, Item, Measured, Recorder, Role, StepId};
use crate::geom::DVec2;
use crate::scale::{Quantity, Scale};
use std::f64::consts::TAU;

/// The preferred largest extent of a polygon when its μ is chosen, mm (the textbook's
/// 80–120 mm: the finest round μ of the 1–2–2.5–4–5 series not drawing it larger).
pub(super) const POLYGON_MM: f64 = 120.0;

/// A closing vector read off a polygon.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosingVector {
    /// Its length as drawn, as read and the physical magnitude.
    pub measured: Measured,
    /// Its direction as read (from its two projections, each read under the drafting
    /// model), radians in [0, 2π).
    pub angle: f64,
    /// The vector as read, physical units (`measured.value` along `angle`).
    pub vector: DVec2,
}

/// A balanced rotor: the figures, the corrections read off them and their analytic twin.
#[derive(Debug, Clone, PartialEq)]
pub struct Balancing {
    /// The task.
    pub spec: BalancingSpec,
    /// μ_mρ of the polygon of static moments.
    pub scale_mr: Scale,
    /// μ_mρz of the polygon of moments (dynamic balancing).
    pub scale_mrz: Option<Scale>,
    /// μ_l of the rotor drawings.
    pub scale_l: Scale,
    /// The polygon of moments mᵢρᵢ(zᵢ − z_I) (dynamic balancing).
    pub moments: Option<Figure>,
    /// The polygon of static moments mᵢρᵢ.
    pub statics: Figure,
    /// The rotor: its end view (static), or its side view and end view (dynamic).
    pub rotor: Vec<Figure>,
    /// The correcting static moments as read off the polygons.
    pub graphical: Vec<Corrective>,
    /// Their analytic twin.
    pub analytic: Vec<Corrective>,
    /// The closing vector of the polygon of moments: U_II·(z_II − z_I) as read.
    pub moment_closing: Option<ClosingVector>,
    /// The main vector Σ mᵢρᵢ of the unbalanced rotor as read off the polygon of static
    /// moments (from the start of the first vector to the end of the last mass's), kg·m.
    pub unbalance_read: f64,
}

/// Carry out the balancing `spec` in the context `ctx` (its drafting model reads every
/// closing vector).
///
/// # Errors
/// [`BalancingError::NoMasses`] for a rotor without masses; [`BalancingError::NoScale`] when
/// no round scale can be formed for a polygon or the rotor.
pub fn balance(spec: &BalancingSpec, ctx: &Context) -> Result<Balancing, BalancingError> {
    if spec.masses.is_empty() {
        return Err(BalancingError::NoMasses);
    }
    let twin = analytic(spec);
    let statics: Vec<DVec2> = spec.masses.iter().map(Mass::static_moment).collect();
    let scale_l = match spec.scale_l {
        Some(s) => s,
        None => rotor::scale(spec)?,
    };
    let labels: Vec<String> = (1..=spec.masses.len())
        .map(|i| format!("m_{{{i}}}ρ_{{{i}}}"))
        .collect();
    let (moments, moment_closing, scale_mrz, known) = match spec.correction {
        Correction::Static { .. } => (None, None, None, Vec::new()),
        Correction::Dynamic { planes, .. } => {
            let arm = planes[1] - planes[0];
            let vectors: Vec<DVec2> = spec
                .masses
                .iter()
                .map(|m| m.static_moment() * (m.z - planes[0]))
                .collect();
            let sizing = vertices(&vectors);
            let scale = chosen(spec.scale_mrz, &sizing, Quantity::UnbalanceMoment, "μ_mρz")?;
            let names: Vec<String> = (1..=spec.masses.len())
                .map(|i| format!("m_{{{i}}}ρ_{{{i}}}z_{{{i}}}"))
                .collect();
            let mut p = Polygon::start("polygon of moments m·ρ·z", scale, ctx);
            p.lay_all(&vectors, &names, &sizing);
            let closing = p.close("m_{уII}ρ_{уII}z_{II}", &sizing);
            // U_II·(z_II − z_I) = closing: divide by the signed arm.
            let u2 = Corrective {
                plane: Plane::Second,
                z: planes[1],
                unbalance: closing.vector / arm,
                radius: twin[1].radius,
            };
            (Some(p.rec.finish()), Some(closing), Some(scale), vec![u2])
        }
    };
    // The polygon of static moments: the masses', then the known correction (plane II),
    // closing to the correction of the disc (static) or of plane I (dynamic).
    let count = statics.len();
    let mut vectors = statics;
    let mut names = labels;
    for k in &known {
        vectors.push(k.unbalance);
        names.push(format!("m_{{{0}}}ρ_{{{0}}}", k.plane.index()));
    }
    // The analytic twin lists the plane the polygon of static moments closes to first.
    let closing_plane = twin[0];
    let sizing = vertices(&vectors);
    let scale_mr = chosen(spec.scale_mr, &sizing, Quantity::StaticMoment, "μ_mρ")?;
    let mut p = Polygon::start("polygon of static moments m·ρ", scale_mr, ctx);
    p.lay_all(&vectors, &names, &sizing);
    let masses_end = sizing.get(count).copied().unwrap_or(DVec2::ZERO) / scale_mr.value();
    let unbalance_read = p.rec.measure(DVec2::ZERO, masses_end).value;
    let idx = closing_plane.plane.index();
    let closing = p.close(&format!("m_{{{idx}}}ρ_{{{idx}}}"), &sizing);
    let mut graphical = vec![Corrective {
        unbalance: closing.vector,
        ..closing_plane
    }];
    graphical.extend(known);
    let rotor = rotor::views(spec, &graphical, scale_l, ctx);
    Ok(Balancing {
        spec: spec.clone(),
        scale_mr,
        scale_mrz,
        scale_l,
        moments,
        statics: p.rec.finish(),
        rotor,
        graphical,
        analytic: twin,
        moment_closing,
        unbalance_read,
    })
}

/// The physical vertices of a polygon laid from the origin: the origin and the end of every
/// vector (the closing vector returns to the origin); they size the drawing.
fn vertices(vectors: &[DVec2]) -> Vec<DVec2> {
    std::iter::once(DVec2::ZERO)
        .chain(vectors.iter().scan(DVec2::ZERO, |at, v| {
            *at += *v;
            Some(*at)
        }))
        .collect()
}

/// The scene's μ, or the round μ that draws the polygon through `vertices` (physical)
/// at most [`POLYGON_MM`] across.
fn chosen(
    given: Option<Scale>,
    vertices: &[DVec2],
    quantity: Quantity,
    what: &'static str,
) -> Result<Scale, BalancingError> {
    if let Some(s) = given {
        return Ok(s);
    }
    let (lo, hi) = vertices.iter().fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let size = (hi - lo).max_element();
    // A polygon of zero size (every mass in the moment centre's plane) is drawn at the
    // scale of its largest term, zero: any round μ draws it; take the one for unit size.
    let size = if size > 0.0 { size } else { 1.0 };
    Scale::round_for(size, POLYGON_MM, quantity).ok_or(BalancingError::NoScale { what, size })
}

/// A polygon of vectors being laid head to tail from the origin.
struct Polygon {
    rec: Recorder,
    at: DVec2,
    ids: Vec<StepId>,
}

impl Polygon {
    fn start(title: &str, scale: Scale, ctx: &Context) -> Self {
        let mut rec = Recorder::in_context(title, scale, ctx);
        rec.point(
            "the pole of the polygon",
            DVec2::ZERO,
            Role::Given,
            "",
            DVec2::ZERO,
            &[],
        );
        Self {
            rec,
            at: DVec2::ZERO,
            ids: Vec::new(),
        }
    }

    /// The centre of the polygon, mm (its vertices' mean): labels go away from it.
    fn centre(&self, vertices: &[DVec2]) -> DVec2 {
        let mu = self.rec.scale().value();
        vertices.iter().map(|v| *v / mu).sum::<DVec2>() / vertices.len().max(1) as f64
    }

    /// Lay `vectors` (physical) head to tail, each labelled on the side away from the centre.
    fn lay_all(&mut self, vectors: &[DVec2], names: &[String], vertices: &[DVec2]) {
        let centre = self.centre(vertices);
        let mu = self.rec.scale().value();
        for (v, name) in vectors.iter().zip(names) {
            let to = self.at + *v / mu;
            if to.distance(self.at) > self.rec.tolerances().coincident {
                self.vector(
                    &format!("lay {name}"),
                    self.at,
                    to,
                    Role::Given,
                    name,
                    centre,
                );
            }
            self.at = to;
        }
    }

    /// Draw a vector of the polygon, labelled `name` at its middle on the side away from
    /// `centre`; it derives from every vector laid before it.
    fn vector(&mut self, note: &str, from: DVec2, to: DVec2, role: Role, name: &str, c: DVec2) {
        let id = self
            .rec
            .draw(note, Item::Vector { from, to }, role, &self.ids);
        self.rec
            .label(id, name, (from + to) * 0.5, outward(from, to, c));
        self.ids.push(id);
    }

    /// Draw the closing vector from the end of the last vector to the pole and read it: its
    /// length with the ruler, its direction from its two projections.
    fn close(&mut self, name: &str, vertices: &[DVec2]) -> ClosingVector {
        let (from, to) = (self.at, DVec2::ZERO);
        let measured = self.rec.measure(from, to);
        let d = to - from;
        let mut read = |dx: f64, dy: f64| self.rec.measure(DVec2::ZERO, DVec2::new(dx, dy)).read_mm;
        let (px, py) = (read(d.x, 0.0) * d.x.signum(), read(0.0, d.y) * d.y.signum());
        // A closing vector shorter than the coincidence tolerance is no vector: the polygon
        // closes by itself and no correction is needed.
        let drawn = measured.drawn_mm > self.rec.tolerances().coincident;
        let angle = if drawn && (px != 0.0 || py != 0.0) {
            py.atan2(px).rem_euclid(TAU)
        } else {
            0.0
        };
        let value = if drawn { measured.value } else { 0.0 };
        if drawn {
            let centre = self.centre(vertices);
            let note = format!("closing vector {name}");
            self.vector(&note, from, to, Role::Result, name, centre);
        }
        ClosingVector {
            measured,
            angle,
            vector: DVec2::from_angle(angle) * value,
        }
    }
}

/// The unit normal of `from → to` pointing away from `centre` (its left side when the
/// centre lies on the line).
fn outward(from: DVec2, to: DVec2, centre: DVec2) -> DVec2 {
    let n = (to - from).perp().normalize_or(DVec2::Y);
    if n.dot((from + to) * 0.5 - centre) < 0.0 {
        -n
    } else {
        n
    }
}
