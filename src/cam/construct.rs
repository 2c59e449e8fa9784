//! The cam constructed: the diagrams ([`super::diagrams`]), the minimum radius
//! ([`super::radius`]) and the profile by inversion ([`super::inversion`]), all through the
//! recorder, with the pressure (transmission) angle graph.

use super::diagrams::{diagrams, read_motion, Diagrams};
use super::exact::{self, Kin, Motion, Placement, Point};
use super::inversion::{invert, Inversion};
use super::radius::{min_radius, RadiusConstruction};
use super::{CamError, CamSpec, Follower};
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::{DVec2, Segment};
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
    pub diagrams: Diagrams,
    /// The minimum radius.
    pub radius: RadiusConstruction,
    /// The base radius used for the profile, m.
    pub base: f64,
    /// The follower's placement (from the exact minimum or the given base radius).
    pub placement: Placement,
    /// The roller radius used, m (0: knife edge or flat face).
    pub roller: f64,
    /// The profile.
    pub inversion: Inversion,
    /// The pressure (transmission) angle over the cycle: read off the profile drawing at the
    /// points (marked) and the exact curve, at μ_φ and 1°/mm.
    pub angle_graph: Option<Figure>,
    /// The cam turns clockwise: `spec` is then its counter-clockwise mirror image (the offset
    /// on the other side), every number is the mirror image's, and the mechanism's drawings
    /// (the centre's construction, the profile) are mirrored back.
    pub clockwise: bool,
}

impl Cam {
    /// An offset of the counter-clockwise model as the scene gives it.
    pub fn scene_offset(&self, e: f64) -> f64 {
        if self.clockwise {
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
/// no drawing scale.
pub fn build(spec: &CamSpec, ctx: &Context) -> Result<Cam, CamError> {
    if spec.clockwise {
        // A clockwise cam is the mirror image of a counter-clockwise one whose offset lies on
        // the other side of the centre.
        let follower = match spec.follower {
            Follower::Translating { offset } => Follower::Translating { offset: -offset },
            Follower::Flat { offset } => Follower::Flat { offset: -offset },
            rocker @ Follower::Rocker { .. } => rocker,
        };
        let model = CamSpec {
            clockwise: false,
            follower,
            ..spec.clone()
        };
        let mut cam = build(&model, ctx)?;
        cam.clockwise = true;
        // The flat face's combined diagram S(S″) is no drawing of the mechanism.
        if !matches!(spec.follower, Follower::Flat { .. }) {
            cam.radius.figure = cam.radius.figure.mirrored_x();
        }
        cam.inversion.figure = cam.inversion.figure.mirrored_x();
        return Ok(cam);
    }
    let points = exact::points(spec);
    let diagrams = diagrams(spec, &points, ctx)?;
    let (radius, base, placement) = min_radius(spec, &points, &diagrams, ctx)?;
    let roller = match spec.follower {
        Follower::Flat { .. } => 0.0,
        _ => match spec.roller {
            Some(r) => r,
            None => {
                let (rho, _) = exact::pitch_rho_min(spec, &placement);
                (0.4 * base).min(0.8 * rho)
            }
        },
    };
    if roller >= base {
        return Err(CamError::RollerTooLarge { roller, base });
    }
    let read: Vec<Motion> = (0..points.len())
        .map(|i| read_motion(&diagrams, i))
        .collect();
    let inversion = invert(spec, &points, &read, &placement, base, roller, ctx)?;
    let angle_graph = match spec.follower {
        Follower::Flat { .. } => None,
        _ => Some(angle_graph(
            spec,
            &points,
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
        clockwise: false,
    })
}

/// The angle graph: the exact pressure (or transmission) angle over the cycle as a curve,
/// the values read off the profile drawing as marked points, at μ_φ and μ = 1°/mm.
fn angle_graph(
    spec: &CamSpec,
    points: &[Point],
    inv: &Inversion,
    place: &Placement,
    phi: Scale,
    ctx: &Context,
) -> Result<Figure, CamError> {
    let rocker = matches!(spec.follower, Follower::Rocker { .. });
    let mu = Scale::new(1f64.to_radians(), Quantity::Angle).ok_or(CamError::NoScale {
        what: "μ_γ",
        size: 1.0,
    })?;
    let mut rec = Recorder::in_context(if rocker { "γ(φ)" } else { "λ(φ)" }, mu, ctx);
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
        if rocker { "γ, °" } else { "λ, °" },
        DVec2::new(0.0, top + 10.0),
        DVec2::new(1.0, 0.2),
    );
    let limit = if rocker {
        spec.gamma_min
    } else {
        FRAC_PI_2 - spec.gamma_min
    };
    let lim = rec.draw(
        "limit",
        Item::Segment(Segment::new(
            DVec2::new(0.0, mu.to_mm(limit)),
            DVec2::new(width, mu.to_mm(limit)),
        )),
        Role::Axis,
        &[],
    );
    rec.label(
        lim,
        if rocker { "γ_{min}" } else { "λ_{max}" },
        DVec2::new(width, mu.to_mm(limit)),
        DVec2::new(1.0, 0.0),
    );
    let curve: Vec<DVec2> = exact::dense(spec, 120)
        .into_iter()
        .chain([(0.0, true), (spec.starts()[1], true), (TAU, false)])
        .map(|(p, a)| (p, value(&place.kin(exact::motion(spec, p, a)))))
        .collect::<Vec<_>>()
        .into_iter()
        .map(|(p, v)| DVec2::new(phi.to_mm(p), mu.to_mm(v)))
        .collect();
    let mut curve = curve;
    curve.sort_by(|a, b| a.x.total_cmp(&b.x));
    rec.draw(
        "the exact angle",
        Item::Polyline {
            points: curve,
            closed: false,
        },
        Role::Result,
        &[xa, ya],
    );
    for (i, p) in points.iter().enumerate() {
        let a = inv.angles.get(i).copied().unwrap_or(0.0);
        let a = if rocker { FRAC_PI_2 - a } else { a };
        rec.point(
            format!("read at point {i}"),
            DVec2::new(phi.to_mm(p.phi), mu.to_mm(a)),
            Role::Construction,
            "",
            DVec2::ZERO,
            &[],
        );
    }
    Ok(rec.finish())
}
