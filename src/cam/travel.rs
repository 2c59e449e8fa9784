//! The shortest travel X_min of a translating cam (the cam slides along its guide, the
//! follower moves across it) as a construction at μ_S beside the diagrams — the combined
//! diagram of a turning cam (lecture 15, PZ5) with the centre at infinity.
//!
//! On a cam that travels X over the law's cycle the follower's axis stands at ξ = X·φ/2π, so
//! the pressure angle is tg λ = dS/dξ = S′/(X/2π): the travel over one radian of the law,
//! X/2π, stands where a turning central cam has its radius r₀ + S, and it is the same at
//! every S. So: the law's dS/dφ laid off across the S axis at every point (K_i), the combined
//! diagram S(dS/dφ) through them; from the point K farthest from the S axis (the largest
//! |dS/dφ| where the scene checks the angle: the rise only under force closure) the line at
//! γ_min to dS/dφ (λ_max to the S axis) meets the S axis at C, X_min/2π below that point's
//! B. The dimension BC, read, times 2π is X_min. The twin's is the closed form
//! ([`super::sliding::exact_travel_min`]), compared in the rows.

use super::combined::{abscissa, combined, s_axis, smooth_loop};
use super::diagrams::CamDiagrams;
use super::motion::Point;
use super::CamSpec;
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::{Arc, DVec2, Segment};
use std::f64::consts::TAU;

/// The note of the X_min/2π dimension's step (the sheet writes its value, the tests find it).
pub const TRAVEL_NOTE: &str = "dimension X_min/2π";
/// The note of the γ_min line from the steepest point to the S axis.
pub const TRAVEL_RAY_NOTE: &str = "γ_min line from the point of the largest dS/dφ";

/// The radius of the γ_min angle's arc at K, mm.
const ARC_MM: f64 = 12.0;

/// The construction of X_min.
#[derive(Debug, Clone, PartialEq)]
pub struct TravelConstruction {
    /// The combined diagram S(dS/dφ) with the γ_min line and the dimension X_min/2π, at μ_S.
    pub figure: Figure,
    /// The dimension X_min/2π as read, m.
    pub read: f64,
    /// X_min = 2π·(X_min/2π read), m.
    pub graphical: f64,
}

/// Construct X_min at the drawn points of `d`.
pub(super) fn travel_min(
    spec: &CamSpec,
    points: &[Point],
    d: &CamDiagrams,
    ctx: &Context,
) -> TravelConstruction {
    let mu = d.s_scale;
    let mut rec = Recorder::in_context("travel", mu, ctx);
    // K_i = B_i + (S′_i, 0): to the right on the rise, to the left on the return.
    let ks = combined(d, points.len(), |m| {
        DVec2::new(mu.to_mm(m.ds), mu.to_mm(m.s))
    });
    let binds = |i: usize| spec.binds(&points[i]);
    // The steepest point: the first of the largest |dS/dφ| among the checked points.
    let steep = (0..ks.len())
        .filter(|&i| binds(i))
        .fold(None, |a: Option<usize>, i| match a {
            Some(j) if ks[j].x.abs() >= ks[i].x.abs() => Some(j),
            _ => Some(i),
        })
        .map_or(DVec2::ZERO, |i| ks[i]);
    let b = DVec2::new(0.0, steep.y);
    let c = DVec2::new(0.0, steep.y - steep.x.abs() * spec.gamma_min.tan());
    let axis = s_axis(&mut rec, spec, mu, (-c.y).max(0.0));
    abscissa(&mut rec, &ks, "dS/dφ");
    for (i, k) in ks.iter().enumerate() {
        rec.draw(
            format!("dS/dφ at point {i}"),
            Item::Segment(Segment::new(DVec2::new(0.0, k.y), *k)),
            Role::Construction,
            &[],
        );
    }
    smooth_loop(
        &mut rec,
        (spec, points),
        &ks,
        "combined diagram S(dS/dφ)",
        &[axis],
    );
    let kid = rec.point(
        "the point of the largest dS/dφ",
        steep,
        Role::Construction,
        "K",
        DVec2::new(steep.x.signum(), 0.5),
        &[],
    );
    let ray = rec.draw(
        TRAVEL_RAY_NOTE,
        Item::Segment(Segment::new(steep, c)),
        Role::Construction,
        &[kid, axis],
    );
    // γ_min at K, between dS/dφ (towards the axis) and the line.
    let (along, to_c) = (
        (b - steep).normalize_or_zero(),
        (c - steep).normalize_or_zero(),
    );
    let arc = Arc::between(steep, ARC_MM.min(0.6 * steep.x.abs()), along, to_c);
    let aid = rec.draw("γ_min at K", Item::Angle(arc), Role::Dimension, &[ray]);
    let mid = (along + to_c).normalize_or_zero();
    rec.label(aid, "γ_{min}", steep + mid * (arc.radius + 1.0), mid);
    // C's name below it on K's side, clear of the dimension's text.
    let toward = DVec2::new(0.6 * steep.x.signum(), -1.0);
    rec.point("C", c, Role::Result, "C", toward, &[ray]);
    // B → C on the S axis itself, its text beside it: a line beside the axis would cross
    // the diagram and the dS/dφ segments away from K, or the γ_min line on K's side.
    rec.dimension(TRAVEL_NOTE, (b, c, 0.0), "X_{min}/2π");
    let read = rec.measure(b, c).value;
    TravelConstruction {
        figure: rec.finish(),
        read,
        graphical: TAU * read,
    }
}
