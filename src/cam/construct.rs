//! The cam constructed: the diagrams ([`super::diagrams`]), the minimum radius
//! ([`super::radius`]) and the profile by inversion ([`super::inversion`]), all through the
//! recorder, with the pressure (transmission) angle graph. The construction works from the
//! scene (the given law, [`super::motion`]) and its own drawing; it shares the follower's
//! primitives ([`super::follower`]) with the twin and never asks the twin ([`super::exact`]).

use super::diagrams::{diagrams, read_motion, CamDiagrams};
use super::follower::{to_cam, Kin, Placement};
use super::inversion::{drawn_rho_min, invert, Inversion};
use super::motion::{points, FollowerMotion, Point};
use super::radius::{min_radius, RadiusConstruction};
use super::{CamError, CamSpec, Follower, Rotation, Shock};
use crate::construct::{Context, Figure, Item, Recorder, Role, StepId};
use crate::geom::{french_curve, DVec2, Segment};
use crate::scale::{Quantity, Scale};
use std::f64::consts::{FRAC_PI_2, TAU};

/// A cam constructed and its analytic twin at hand.
#[derive(Debug, Clone, PartialEq)]
pub struct Cam {
    /// The task.
    pub spec: CamSpec,
    /// The diagram points.
    pub points: Vec<Point>,
    /// The diagrams.
    pub diagrams: CamDiagrams,
    /// The minimum radius.
    pub radius: RadiusConstruction,
    /// The base radius used for the profile, m.
    pub base: f64,
    /// The follower's placement (from the graphical minimum or the given base radius).
    pub placement: Placement,
    /// The roller radius used, m (0: knife edge or flat face).
    pub roller: f64,
    /// The profile.
    pub inversion: Inversion,
    /// The pressure (transmission) angle over the cycle: read off the profile drawing at the
    /// points (marked) and the curve drawn through them, at μ_φ and 1°/mm.
    pub angle_graph: Option<Figure>,
    /// The r₀ first accepted from the reading when the angle read off its profile broke the
    /// limit, and r₀ was taken up a millimetre at a time until it held (or
    /// [`MAX_RAISE_MM`] were added).
    pub raised: Option<Raised>,
    /// The cam's sense. Clockwise: `spec` is then its counter-clockwise mirror image (the
    /// offset on the other side), every number is the mirror image's, and the mechanism's
    /// drawings (the centre's construction, the profile) are mirrored back.
    pub rotation: Rotation,
}

/// The profile's check that took r₀ up: the r₀ first accepted, the point where the angle
/// read off its profile broke the limit most, and that angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Raised {
    /// The base radius first accepted, m.
    pub base: f64,
    /// The drawn point.
    pub at: usize,
    /// The angle read there (pressure angle; a rocker's transmission angle), rad.
    pub angle: f64,
}

impl Cam {
    /// An offset of the counter-clockwise model as the scene gives it.
    pub fn scene_offset(&self, e: f64) -> f64 {
        if self.rotation == Rotation::Cw {
            -e
        } else {
            e
        }
    }
}

/// Construct the cam of `spec`.
///
/// # Errors
/// A failed integration, no admissible centre, a roller not smaller than the base radius,
/// no drawing scale, a layout other than the turning cam's.
pub fn build(spec: &CamSpec, ctx: &Context) -> Result<Cam, CamError> {
    if spec.layout != super::CamLayout::Turning {
        return Err(CamError::Layout(
            "the flat-faced rocker and the translating cam are built by build_special",
        ));
    }
    if spec.rotation == Rotation::Cw {
        // A clockwise cam is the mirror image of a counter-clockwise one whose offset lies on
        // the other side of the centre.
        let follower = match spec.follower {
            Follower::Translating { offset } => Follower::Translating { offset: -offset },
            Follower::Flat { offset } => Follower::Flat { offset: -offset },
            rocker @ Follower::Rocker { .. } => rocker,
        };
        let model = CamSpec {
            rotation: Rotation::Ccw,
            follower,
            ..spec.clone()
        };
        let mut cam = build(&model, ctx)?;
        cam.rotation = Rotation::Cw;
        // The flat face's combined diagram S(S″) is no drawing of the mechanism.
        if !matches!(spec.follower, Follower::Flat { .. }) {
            cam.radius.figure = cam.radius.figure.mirrored_x();
        }
        cam.inversion.figure = cam.inversion.figure.mirrored_x();
        return Ok(cam);
    }
    let points = points(spec);
    let diagrams = diagrams(spec, &points, ctx)?;
    let read: Vec<FollowerMotion> = (0..points.len())
        .map(|i| read_motion(&diagrams, i))
        .collect();
    let mut raised = None;
    let mut raise = 0;
    let (radius, base, placement, roller, inversion) = loop {
        let (radius, base, placement) =
            min_radius(spec, &points, &diagrams, ctx, f64::from(raise) * 1e-3)?;
        let roller = match spec.follower {
            Follower::Flat { .. } => 0.0,
            _ => spec
                .roller
                .unwrap_or_else(|| chosen_roller(&points, &read, &placement, base)),
        };
        if roller >= base {
            return Err(CamError::RollerTooLarge { roller, base });
        }
        let inversion = invert(spec, &points, &read, &placement, (base, roller), ctx)?;
        match over_limit(spec, &points, &inversion) {
            Some((at, angle)) if spec.base_radius.is_none() && raise < MAX_RAISE_MM => {
                raised.get_or_insert(Raised { base, at, angle });
                raise += 1;
            }
            _ => break (radius, base, placement, roller, inversion),
        }
    };
    let angle_graph = match spec.follower {
        Follower::Flat { .. } => None,
        _ => Some(angle_graph(
            spec,
            (&points, &read),
            &inversion,
            &placement,
            diagrams.phi,
            ctx,
        )?),
    };
    Ok(Cam {
        spec: spec.clone(),
        points,
        diagrams,
        radius,
        base,
        placement,
        roller,
        inversion,
        angle_graph,
        raised,
        rotation: Rotation::Ccw,
    })
}

/// The most whole millimetres the profile's check adds to the accepted r₀ before it leaves
/// the angle over its limit to the check's verdict.
const MAX_RAISE_MM: u8 = 10;

/// The point whose angle, read off the profile drawing, is furthest past the limit, with
/// that angle (the pressure angle, or a rocker's transmission angle): `None` when every
/// point that binds keeps it (under force closure the rise's; else all).
fn over_limit(spec: &CamSpec, points: &[Point], inv: &Inversion) -> Option<(usize, f64)> {
    if matches!(spec.follower, Follower::Flat { .. }) {
        return None;
    }
    let most = FRAC_PI_2 - spec.gamma_min;
    // The first of the largest.
    let (at, worst) = (0..inv.leans.len())
        .map(|i| (i, inv.angle(i)))
        .filter(|&(i, _)| spec.binds(&points[i]))
        .reduce(|w, x| if x.1 > w.1 { x } else { w })?;
    (worst > most + ANGLE_SLACK).then(|| {
        let angle = if spec.shows_transmission_angle() {
            FRAC_PI_2 - worst
        } else {
            worst
        };
        (at, angle)
    })
}

/// An angle read within this of its limit keeps it, rad.
const ANGLE_SLACK: f64 = 1e-9;

/// The roller a student chooses when the scene gives none: r = min(0.4·r₀, 0.8·ρ_min), with
/// r₀ the base radius used and ρ_min found on the drawing — the circle fitted where the
/// pitch (theoretical) curve, drawn as a French curve, is most convex ([`drawn_rho_min`]);
/// the pitch points and their tangents from the motion read off the diagrams at the
/// follower's placement.
fn chosen_roller(points: &[Point], read: &[FollowerMotion], place: &Placement, base: f64) -> f64 {
    let (pitch, tangents): (Vec<DVec2>, Vec<DVec2>) = points
        .iter()
        .zip(read)
        .map(|(p, m)| {
            let kin = place.kin(*m);
            (to_cam(kin.b, p.phi), to_cam(kin.normal().perp(), p.phi))
        })
        .unzip();
    roller_bound(base, drawn_rho_min(points, &pitch, &tangents))
}

/// The textbook's rule for the roller's radius: r_р ≤ 0,4·r₀ and r_р ≤ 0,8·ρ_min, m.
pub(crate) fn roller_bound(base: f64, rho_min: f64) -> f64 {
    (0.4 * base).min(0.8 * rho_min)
}

/// The angle graph: the pressure (or transmission) angle read off the profile drawing at
/// the points, marked, and a curve drawn through those read values ([`read_curve`]), at μ_φ
/// and μ = 1°/mm. Only the construction's own values are drawn; the exact angle stays in the
/// check's rows.
fn angle_graph(
    spec: &CamSpec,
    (points, motions): (&[Point], &[FollowerMotion]),
    inv: &Inversion,
    place: &Placement,
    phi: Scale,
    ctx: &Context,
) -> Result<Figure, CamError> {
    let rocker = spec.shows_transmission_angle();
    let mu = Scale::new(1f64.to_radians(), Quantity::Angle).ok_or(CamError::NoScale {
        what: "μ_γ",
        size: 1.0,
    })?;
    let symbol = spec.angle_symbol();
    let mut rec = Recorder::in_context(format!("{symbol}(φ)"), mu, ctx);
    let value = |k: &Kin| {
        if rocker {
            k.transmission_angle()
        } else {
            k.pressure_angle()
        }
    };
    let width = phi.to_mm(TAU);
    let top = mu.to_mm(FRAC_PI_2) * if rocker { 1.0 } else { 0.6 };
    let xa = rec.draw(
        "φ axis",
        Item::Vector {
            from: DVec2::ZERO,
            to: DVec2::new(width + 12.0, 0.0),
        },
        Role::Construction,
        &[],
    );
    rec.label(
        xa,
        "φ",
        DVec2::new(width + 12.0, 0.0),
        DVec2::new(0.3, -1.0),
    );
    let ya = rec.draw(
        "angle axis",
        Item::Vector {
            from: DVec2::ZERO,
            to: DVec2::new(0.0, top + 10.0),
        },
        Role::Construction,
        &[],
    );
    rec.label(
        ya,
        format!("{symbol}, °"),
        DVec2::new(0.0, top + 10.0),
        DVec2::new(1.0, 0.2),
    );
    graduate(&mut rec, ya, mu, top);
    let limit = spec.angle_limit();
    let lim = rec.draw(
        ANGLE_LIMIT_NOTE,
        Item::Segment(Segment::new(
            DVec2::new(0.0, mu.to_mm(limit)),
            DVec2::new(width, mu.to_mm(limit)),
        )),
        Role::Axis,
        &[],
    );
    rec.label(
        lim,
        spec.angle_limit_symbol(),
        DVec2::new(width, mu.to_mm(limit)),
        DVec2::new(1.0, 0.0),
    );
    // The values read off the profile drawing, marked at their points.
    let read: Vec<DVec2> = points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let a = inv.angle(i);
            let a = if rocker { FRAC_PI_2 - a } else { a };
            DVec2::new(phi.to_mm(p.phi), mu.to_mm(a))
        })
        .collect();
    for (i, q) in read.iter().enumerate() {
        rec.point(
            format!("read at point {i}"),
            *q,
            Role::Construction,
            "",
            DVec2::ZERO,
            &[],
        );
    }
    // The pressure angle's curve through the readings signed by their side of the path, its
    // magnitude drawn: where an offset follower's angle changes side it touches nought.
    let through: Vec<DVec2> = if rocker {
        read.clone()
    } else {
        read.iter()
            .zip(&inv.leans)
            .map(|(q, a)| DVec2::new(q.x, mu.to_mm(*a)))
            .collect()
    };
    let curve = read_curve(
        spec,
        (points, motions),
        &through,
        place,
        |k| mu.to_mm(value(k)),
        phi,
    );
    rec.draw(
        "the angle read off the profile",
        Item::Polyline {
            points: magnitude(&curve),
            closed: false,
        },
        Role::Result,
        &[xa, ya],
    );
    Ok(rec.finish())
}

/// The graph of the magnitude of a signed curve: every vertex folded over the axis, and where
/// a chord crosses it, its crossing inserted, so that the curve touches nought there (a jump,
/// at one φ, stays a jump between the two magnitudes).
fn magnitude(curve: &[DVec2]) -> Vec<DVec2> {
    let mut out = Vec::with_capacity(curve.len() + 4);
    for (k, &q) in curve.iter().enumerate() {
        if let Some(&p) = k.checked_sub(1).and_then(|j| curve.get(j)) {
            if p.y * q.y < 0.0 && p.x != q.x {
                out.push(DVec2::new(p.x + (q.x - p.x) * p.y / (p.y - q.y), 0.0));
            }
        }
        out.push(DVec2::new(q.x, q.y.abs()));
    }
    out
}

/// The angle axis at `mu` graduated every [`GRADUATION_DEG`] up to `top` mm: a tick to the
/// left of the axis with its degrees.
fn graduate(rec: &mut Recorder, axis: StepId, mu: Scale, top: f64) {
    let mut deg = GRADUATION_DEG;
    while mu.to_mm(deg.to_radians()) <= top + 1e-9 {
        let y = mu.to_mm(deg.to_radians());
        let tick = rec.draw(
            format!("tick {deg}°"),
            Item::Segment(Segment::new(DVec2::new(-TICK_MM, y), DVec2::new(0.0, y))),
            Role::Construction,
            &[axis],
        );
        rec.label(
            tick,
            format!("{deg}"),
            DVec2::new(-TICK_MM, y),
            DVec2::new(-1.0, 0.0),
        );
        deg += GRADUATION_DEG;
    }
}

/// The note of the angle graph's limit line (γ_min or λ_max), labelled by its symbol; a
/// sheet writes its value.
pub const ANGLE_LIMIT_NOTE: &str = "limit";

/// The angle graph's graduation, degrees.
const GRADUATION_DEG: f64 = 10.0;
/// A graduation tick's length, mm.
const TICK_MM: f64 = 2.0;

/// The curve of the angle graph, drawn through the read values only: the French curve
/// through each moving phase's points (tangents along the chords through the neighbours),
/// and on each dwell, where the pitch curve is the arc about O₁ drawn through the phase's
/// end and the normal is its radius, the angle between O₁B and the follower's path,
/// constant — at the drawn dwell's S (`motions`, read off the S diagram at the phase's last
/// point), where the profile has it, not at the exact h or 0. Where the law's S′ is
/// continuous the reading at the phase's end is that same angle ([`super::reading`]), so the
/// curve runs on without a step; where S′ jumps (a rigid shock) so does the angle, drawn at
/// φ = 0 too. The twin's
/// exact curve is not drawn: the check compares them in the rows.
fn read_curve(
    spec: &CamSpec,
    (points, motions): (&[Point], &[FollowerMotion]),
    read: &[DVec2],
    place: &Placement,
    angle_mm: impl Fn(&Kin) -> f64,
    phi: Scale,
) -> Vec<DVec2> {
    let st = spec.starts();
    let dwell = |i: usize| {
        angle_mm(&place.kin(FollowerMotion {
            s: motions.get(i).map_or(0.0, |m| m.s),
            ds: 0.0,
            d2s: 0.0,
        }))
    };
    let mut out = Vec::with_capacity(read.len() * 9 + 5);
    // A rise that starts with a velocity jump starts from the near dwell's level, where the
    // cycle's end leaves it; a smooth one from its first reading (the same angle).
    if spec.rise.shock() == Shock::Rigid {
        let last = points.len().saturating_sub(1);
        out.push(DVec2::new(0.0, dwell(last).copysign(read[last].y)));
    }
    for phase in [0usize, 2] {
        let idx: Vec<usize> = (0..points.len())
            .filter(|&i| points[i].phase == phase)
            .collect();
        let (Some(&first), Some(&last)) = (idx.first(), idx.last()) else {
            continue;
        };
        let tangent = |j: usize| {
            let (lo, hi) = (j.saturating_sub(1), (j + 1).min(idx.len() - 1));
            read[idx[hi]] - read[idx[lo]]
        };
        out.push(read[first]);
        for j in 0..idx.len().saturating_sub(1) {
            let (a, b) = (read[idx[j]], read[idx[j + 1]]);
            out.extend_from_slice(&french_curve(a, tangent(j), b, tangent(j + 1), 8)[1..]);
        }
        // The dwell after the phase, at the S its last point is drawn at (on the side of the
        // path its reading leans to: the curve may be drawn through signed readings).
        let y = dwell(last).copysign(read[last].y);
        out.push(DVec2::new(phi.to_mm(st[phase + 1]), y));
        out.push(DVec2::new(phi.to_mm(st[phase + 2]), y));
    }
    out
}
