//! The rotor drawings: the end view (a thin disc with the masses at their radius vectors and
//! the correcting masses) and, for a long rotor, the side view with the planes of the masses,
//! the correction planes I and II and their axial dimensions.

use super::{BalancingError, BalancingSpec, Correction, Corrective, Mass};
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::{Circle, DVec2, Segment};
use crate::scale::{Quantity, Scale};

/// The preferred diameter of a thin rotor's end view, mm.
const DISC_MM: f64 = 80.0;
/// The preferred length of a long rotor's side view, mm.
const SIDE_MM: f64 = 160.0;
/// The disc's radius over the largest radius of a mass.
const DISC_OVER: f64 = 1.25;
/// How far the axes run past the drawing, mm.
const AXIS_OVERRUN_MM: f64 = 6.0;
/// Radius of the circle that draws a mass, mm.
const MASS_MM: f64 = 2.0;
/// Spacing of the dimension lines under the side view, mm.
const DIMENSION_STEP_MM: f64 = 8.0;

/// The largest radius of a mass or a correcting mass, m.
fn largest_radius(spec: &BalancingSpec) -> f64 {
    let corrections = match spec.correction {
        Correction::Static { radius } => [radius, 0.0],
        Correction::Dynamic { radii, .. } => radii,
    };
    spec.masses
        .iter()
        .map(|m| m.radius)
        .chain(corrections)
        .fold(0.0, f64::max)
}

/// The axial span of a long rotor: (first, last) plane of a mass or a correction, m.
fn span(spec: &BalancingSpec, planes: [f64; 2]) -> (f64, f64) {
    spec.masses
        .iter()
        .map(|m| m.z)
        .chain(planes)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), z| {
            (lo.min(z), hi.max(z))
        })
}

/// μ_l of the rotor drawings chosen the textbook way: the disc about [`DISC_MM`] across;
/// a long rotor's side view about [`SIDE_MM`] long (its disc no larger than that).
pub(super) fn scale(spec: &BalancingSpec) -> Result<Scale, BalancingError> {
    let disc = 2.0 * DISC_OVER * largest_radius(spec);
    let (size, room) = match spec.correction {
        Correction::Static { .. } => (disc, DISC_MM),
        Correction::Dynamic { planes, .. } => {
            let (lo, hi) = span(spec, planes);
            ((hi - lo).max(disc), SIDE_MM)
        }
    };
    Scale::round_for(size, room, Quantity::Length)
        .ok_or(BalancingError::NoScale { what: "μ_l", size })
}

/// The rotor's views at μ_l = `scale`: its end view (and before it, for a long rotor, its
/// side view), with the correcting masses `corrections` as read off the polygons.
pub(super) fn views(
    spec: &BalancingSpec,
    corrections: &[Corrective],
    scale: Scale,
    ctx: &Context,
) -> Vec<Figure> {
    let mut out = Vec::new();
    if let Correction::Dynamic { planes, .. } = spec.correction {
        out.push(side_view(spec, corrections, planes, scale, ctx));
    }
    out.push(end_view(spec, corrections, scale, ctx));
    out
}

/// A mass drawn as a small circle with its label, and its radius vector from the axis.
fn mass(rec: &mut Recorder, m: &Mass, name: &str, radius: &str, role: Role) {
    let mu = rec.scale().value();
    let dir = DVec2::from_angle(m.angle);
    let at = dir * (m.radius / mu);
    let seg = Segment::new(DVec2::ZERO, at - dir * MASS_MM);
    let id = rec.draw(
        format!("radius vector {radius}"),
        Item::Segment(seg),
        role,
        &[],
    );
    rec.label(id, radius, seg.eval(0.5), dir.perp());
    if let Some(c) = Circle::new(at, MASS_MM) {
        let id = rec.draw(format!("mass {name}"), Item::Circle(c), role, &[]);
        rec.label(id, name, at + dir * MASS_MM, dir);
    }
}

/// The two centre lines through the axis, `reach` mm each way.
fn cross(rec: &mut Recorder, reach: f64) {
    for d in [DVec2::X, DVec2::Y] {
        let seg = Segment::new(-d * reach, d * reach);
        rec.draw("centre line", Item::Segment(seg), Role::Axis, &[]);
    }
}

/// The end view: the disc, its centre lines, every mass at its radius vector and the
/// correcting masses.
fn end_view(
    spec: &BalancingSpec,
    corrections: &[Corrective],
    scale: Scale,
    ctx: &Context,
) -> Figure {
    let mut rec = Recorder::in_context("rotor, end view", scale, ctx);
    let r = DISC_OVER * largest_radius(spec) / scale.value();
    cross(&mut rec, r + AXIS_OVERRUN_MM);
    if let Some(c) = Circle::new(DVec2::ZERO, r) {
        rec.draw("the disc", Item::Circle(c), Role::Given, &[]);
    }
    for (i, m) in spec.masses.iter().enumerate() {
        let k = i + 1;
        mass(
            &mut rec,
            m,
            &format!("m_{{{k}}}"),
            &format!("ρ_{{{k}}}"),
            Role::Given,
        );
    }
    for c in corrections.iter().filter(|c| c.angle().is_some()) {
        let idx = c.plane.index();
        let (name, radius) = (format!("m_{{{idx}}}"), format!("ρ_{{{idx}}}"));
        mass(&mut rec, &c.as_mass(), &name, &radius, Role::Result);
    }
    rec.finish()
}

/// The side view of a long rotor: its axis along z (to the right), the body's outline, the
/// plane of every mass and the correction planes I and II, the masses and correcting masses
/// projected on the drawing's plane (ρ·sin α up), and the axial distance of every plane from
/// plane I dimensioned under the rotor.
fn side_view(
    spec: &BalancingSpec,
    corrections: &[Corrective],
    planes: [f64; 2],
    scale: Scale,
    ctx: &Context,
) -> Figure {
    let mut rec = Recorder::in_context("rotor, side view", scale, ctx);
    let mu = scale.value();
    let r = DISC_OVER * largest_radius(spec) / mu;
    let (lo, hi) = span(spec, planes);
    let (lo, hi) = (lo / mu - MASS_MM * 3.0, hi / mu + MASS_MM * 3.0);
    let axis = Segment::new(
        DVec2::new(lo - AXIS_OVERRUN_MM, 0.0),
        DVec2::new(hi + AXIS_OVERRUN_MM, 0.0),
    );
    rec.draw("axis of rotation", Item::Segment(axis), Role::Axis, &[]);
    let outline = vec![
        DVec2::new(lo, -r),
        DVec2::new(hi, -r),
        DVec2::new(hi, r),
        DVec2::new(lo, r),
    ];
    rec.draw(
        "the rotor's outline",
        Item::Polyline {
            points: outline,
            closed: true,
        },
        Role::Given,
        &[],
    );
    let plane = |rec: &mut Recorder, z: f64, name: &str| {
        let x = z / mu;
        let seg = Segment::new(DVec2::new(x, -r - 2.0), DVec2::new(x, r + 2.0));
        let id = rec.draw(format!("plane {name}"), Item::Segment(seg), Role::Axis, &[]);
        if !name.is_empty() {
            rec.label(id, name, seg.to, DVec2::Y);
        }
    };
    plane(&mut rec, planes[0], "I");
    plane(&mut rec, planes[1], "II");
    let projected = |m: &Mass| DVec2::new(m.z / mu, m.radius * m.angle.sin() / mu);
    for (i, m) in spec.masses.iter().enumerate() {
        plane(&mut rec, m.z, "");
        if let Some(c) = Circle::new(projected(m), MASS_MM) {
            let id = rec.draw(
                format!("mass m{}", i + 1),
                Item::Circle(c),
                Role::Given,
                &[],
            );
            rec.label(
                id,
                format!("m_{{{}}}", i + 1),
                c.center,
                DVec2::new(1.0, 1.0),
            );
        }
    }
    for c in corrections.iter().filter(|c| c.angle().is_some()) {
        if let Some(circle) = Circle::new(projected(&c.as_mass()), MASS_MM) {
            let idx = c.plane.index();
            let id = rec.draw(
                format!("correcting mass {idx}"),
                Item::Circle(circle),
                Role::Result,
                &[],
            );
            rec.label(
                id,
                format!("m_{{{idx}}}"),
                circle.center,
                DVec2::new(1.0, -1.0),
            );
        }
    }
    // Axial distances from plane I, one dimension line per plane, stacked under the rotor.
    let z0 = planes[0] / mu;
    let mut dims: Vec<(f64, String)> = spec
        .masses
        .iter()
        .enumerate()
        .map(|(i, m)| (m.z / mu, format!("z_{{{}}}", i + 1)))
        .collect();
    dims.push((planes[1] / mu, "z_{II}".to_string()));
    dims.sort_by(|a, b| (a.0 - z0).abs().total_cmp(&(b.0 - z0).abs()));
    let mut level = 0.0;
    for (x, name) in dims {
        if (x - z0).abs() <= rec.tolerances().coincident {
            continue;
        }
        level += DIMENSION_STEP_MM;
        let (a, b) = (x.min(z0), x.max(z0));
        let (from, to) = (DVec2::new(a, -r), DVec2::new(b, -r));
        let item = Item::Dimension {
            from,
            to,
            offset: -level,
        };
        let id = rec.draw(format!("dimension {name}"), item, Role::Dimension, &[]);
        rec.label(
            id,
            &name,
            (from + to) * 0.5 - DVec2::new(0.0, level),
            -DVec2::Y,
        );
    }
    rec.finish()
}
