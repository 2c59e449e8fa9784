//! The minimum radius as a construction: the combined diagram S(dS/dφ) with the γ_min lines
//! and the zone (translating), dS/dφ laid along the rocker with the γ_min lines (rocker), the
//! S(d²S/dφ²) diagram with its 45° tangent (flat face). The profile is built on the r_min
//! read off this drawing (or the scene's base radius); the exact r_min over the whole cycle
//! is the twin's ([`super::exact`], compared in [`super::Cam::rows`]).

use super::diagrams::{read_motion, Diagrams};
use super::follower::{admits, rocker_of, Placement, REACH_ARMS};
use super::motion::{Motion, Point};
use super::{CamError, CamSpec, Closure, Follower};
use crate::construct::{Context, Figure, Item, Recorder, Role, StepId};
use crate::geom::{Arc, DVec2, Segment};
use crate::scale::Scale;
use std::f64::consts::FRAC_PI_2;

/// The minimum-radius construction.
#[derive(Debug, Clone, PartialEq)]
pub struct RadiusConstruction {
    /// The combined diagram (S–dS/dφ with the γ_min lines, the rocker's construction, or
    /// S–d²S/dφ² with the 45° tangent), at μ_S.
    pub figure: Figure,
    /// r_min as read off the drawing, m.
    pub graphical: f64,
    /// The flat face's max(−(S + S″)) as read at the 45° tangent, m.
    pub convexity: Option<f64>,
}

/// The minimum radius constructed at the drawn points, and the base radius and placement of
/// the follower for the profile: the scene's base radius, else the r_min read off the
/// drawing (translating: |O₁B₀|; rocker: O₁ found on the drawing, its direction and
/// distance from A₀; flat face: read at the 45° tangent, plus ρ_min).
pub(super) fn min_radius(
    spec: &CamSpec,
    points: &[Point],
    d: &Diagrams,
    ctx: &Context,
) -> Result<(RadiusConstruction, f64, Placement), CamError> {
    let mut rec = Recorder::in_context("combined", d.s_scale, ctx);
    let given = Given { spec, points, d };
    let read = match spec.follower {
        Follower::Translating { offset } => translating(&mut rec, &given, offset)?,
        Follower::Rocker { arm, .. } => rocker(&mut rec, &given, arm)?,
        Follower::Flat { offset } => flat(&mut rec, &given, offset)?,
    };
    Ok((
        RadiusConstruction {
            figure: rec.finish(),
            graphical: read.graphical,
            convexity: read.convexity,
        },
        read.base,
        read.placement,
    ))
}

/// What every follower's construction starts from: the cam, its drawn points and their
/// diagrams.
#[derive(Clone, Copy)]
struct Given<'a> {
    spec: &'a CamSpec,
    points: &'a [Point],
    d: &'a Diagrams,
}

/// What one follower's construction reads: r_min, the flat face's convexity, the base
/// radius the profile takes and the follower's placement.
struct Read {
    graphical: f64,
    convexity: Option<f64>,
    base: f64,
    placement: Placement,
}

/// The translating follower: the combined diagram S(dS/dφ), the γ_min lines and the zone
/// of admissible centres on the vertical x = −e.
fn translating(rec: &mut Recorder, given: &Given<'_>, offset: f64) -> Result<Read, CamError> {
    let Given { spec, points, d } = *given;
    let mu = d.s_scale;
    let gamma = spec.gamma_min;
    // Combined diagram: B₀ at the origin, the path vertical, K_i = B_i − (S′_i, 0).
    let ks = combined(d, points.len(), |m| {
        DVec2::new(-mu.to_mm(m.ds), mu.to_mm(m.s))
    });
    // O on the vertical x = −e: the highest point below every γ_min line.
    let ox = -mu.to_mm(offset);
    let t = gamma.tan();
    // Under force closure only the rise's points bind.
    let binds = |i: usize| spec.closure == Closure::Geometric || points[i].phase == 0;
    let below = |k: &DVec2| k.y - (k.x - ox).abs() * t;
    let best = ks
        .iter()
        .enumerate()
        .filter(|(i, _)| binds(*i))
        .map(|(_, k)| below(k))
        .fold(f64::INFINITY, f64::min);
    // The point whose line is drawn to O: the first that binds, points that bind equally (a
    // symmetric cam's rise and return) to the drawing's coincidence, not to rounding.
    let tie = rec.tolerances().coincident;
    let bind = (0..ks.len())
        .find(|&i| binds(i) && below(&ks[i]) <= best + tie)
        .unwrap_or(0);
    let o = DVec2::new(ox, best);
    let path = s_axis(rec, spec, mu, o.length());
    for (i, k) in ks.iter().enumerate() {
        let b = DVec2::new(0.0, k.y);
        rec.draw(
            format!("dS/dφ at point {i}"),
            Item::Segment(Segment::new(b, *k)),
            Role::Construction,
            &[],
        );
    }
    rec.draw(
        "combined diagram S(dS/dφ)",
        Item::Polyline {
            points: ks.clone(),
            closed: true,
        },
        Role::Result,
        &[path],
    );
    zone_lines(rec, &ks, o, gamma, bind);
    let bound: Vec<DVec2> = ks
        .iter()
        .enumerate()
        .filter(|(i, _)| binds(*i))
        .map(|(_, k)| *k)
        .collect();
    hatch_zone(rec, &bound, o, t);
    let oid = rec.point(
        "cam centre O_1",
        o,
        Role::Result,
        "O_1",
        DVec2::new(-1.0, -0.5),
        &[],
    );
    let r = rec.measure(o, DVec2::ZERO);
    rec.draw(
        "r_min",
        Item::Segment(Segment::new(o, DVec2::ZERO)),
        Role::Dimension,
        &[oid],
    );
    let base = spec.base_radius.unwrap_or(r.value);
    if base <= offset.abs() {
        return Err(CamError::BaseWithinOffset {
            base,
            offset: offset.abs(),
        });
    }
    let s0 = (base * base - offset * offset).sqrt();
    Ok(Read {
        graphical: r.value,
        convexity: None,
        base,
        placement: Placement::Translating { offset, s0 },
    })
}

/// The rocker: dS/dφ laid along the rocker at every point, the γ_min lines through the
/// points K and the centre below them all.
fn rocker(rec: &mut Recorder, given: &Given<'_>, arm: f64) -> Result<Read, CamError> {
    let Given { spec, points, d } = *given;
    let mu = d.s_scale;
    let gamma = spec.gamma_min;
    let (_, sigma) = rocker_of(spec);
    let l = mu.to_mm(arm);
    let pivot = DVec2::ZERO;
    let a0 = DVec2::new(0.0, l);
    let pid = rec.draw(
        "rocker pivot O_2",
        Item::Joint {
            at: pivot,
            fixed: true,
        },
        Role::Given,
        &[],
    );
    rec.label(pid, "O_2", pivot, DVec2::new(0.7, -0.7));
    let beta_max = spec.stroke / arm;
    rec.draw(
        "trajectory of A",
        Item::Arc(Arc {
            center: pivot,
            radius: l,
            start: FRAC_PI_2 - beta_max.max(0.0) - 0.05,
            sweep: 2.0 * beta_max + 0.1,
        }),
        Role::Construction,
        &[pid],
    );
    let mut cons = Vec::new();
    let mut ks = Vec::new();
    for (i, p) in points.iter().enumerate() {
        let m = read_motion(d, i);
        let psi = FRAC_PI_2 + sigma * m.s / arm;
        let e = DVec2::from_angle(psi);
        let a = pivot + e * l;
        let k = a - e * (sigma * mu.to_mm(m.ds));
        rec.draw(
            format!("rocker O_2A_{i}"),
            Item::Segment(Segment::new(pivot, a)),
            Role::Construction,
            &[pid],
        );
        ks.push(k);
        if spec.closure == Closure::Geometric || p.phase == 0 {
            cons.push((k, e));
        }
    }
    rec.draw(
        "curve of the points K",
        Item::Polyline {
            points: ks.clone(),
            closed: true,
        },
        Role::Result,
        &[],
    );
    let o = rocker_centre(&cons, a0, gamma).ok_or(CamError::NoCentre {
        gamma_deg: gamma.to_degrees(),
        searched: REACH_ARMS * arm,
    })?;
    rocker_lines(rec, &cons, o, gamma);
    hatch_rocker_zone(rec, &cons, o, gamma);
    let oid = rec.point(
        "cam centre O_1",
        o,
        Role::Result,
        "O_1",
        DVec2::new(1.0, 0.5),
        &[],
    );
    rec.draw(
        "r_min",
        Item::Segment(Segment::new(o, a0)),
        Role::Dimension,
        &[oid],
    );
    rec.draw(
        "centre distance",
        Item::Segment(Segment::new(o, pivot)),
        Role::Construction,
        &[oid, pid],
    );
    let r = rec.measure(o, a0);
    // The profile uses the centre found on the drawing: its direction from A₀ and its
    // distance read (or the given base radius along that direction).
    let dir = (o - a0).normalize_or_zero();
    let base = spec.base_radius.unwrap_or(r.value);
    let o_used = DVec2::new(0.0, arm) + dir * base;
    let pivot_cam = -o_used;
    Ok(Read {
        graphical: r.value,
        convexity: None,
        base,
        placement: Placement::Rocker {
            pivot: pivot_cam,
            arm,
            psi0: FRAC_PI_2,
            sigma,
        },
    })
}

/// The flat face: S(d²S/dφ²) with the 45° tangent; r_min from the convexity and ρ_min.
fn flat(rec: &mut Recorder, given: &Given<'_>, offset: f64) -> Result<Read, CamError> {
    let Given { spec, points, d } = *given;
    let mu = d.s_scale;
    // S vertical, S″ horizontal, both at μ_S; the 45° tangent on the negative side.
    let pts = combined(d, points.len(), |m| {
        DVec2::new(mu.to_mm(m.d2s), mu.to_mm(m.s))
    });
    // The 45° line touching the curve: the least S + S″ among the drawn points.
    let (i, c) = pts
        .iter()
        .enumerate()
        .map(|(i, p)| (i, p.x + p.y))
        .fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
    let oi = DVec2::new(0.0, c.min(0.0));
    let rho = mu.to_mm(spec.rho_min);
    let ax = s_axis(rec, spec, mu, rho - oi.y);
    let xs = pts.iter().fold(0.0f64, |a, p| a.max(p.x.abs()));
    let hx = rec.draw(
        "d²S/dφ² axis",
        Item::Vector {
            from: DVec2::new(-xs - 10.0, 0.0),
            to: DVec2::new(xs + 12.0, 0.0),
        },
        Role::Axis,
        &[],
    );
    rec.label(
        hx,
        "d^2S/dφ^2",
        DVec2::new(xs + 12.0, 0.0),
        DVec2::new(0.0, -1.0),
    );
    rec.draw(
        "combined diagram S(d²S/dφ²)",
        Item::Polyline {
            points: pts.clone(),
            closed: true,
        },
        Role::Result,
        &[ax, hx],
    );
    let touch = pts.get(i).copied().unwrap_or(DVec2::ZERO);
    rec.draw(
        "tangent at 45°",
        Item::Segment(Segment::new(
            oi + DVec2::new(-15.0, 15.0),
            touch + DVec2::new(15.0, -15.0),
        )),
        Role::Construction,
        &[],
    );
    rec.point("O_I", oi, Role::Result, "O_I", DVec2::new(1.0, -0.5), &[]);
    let o = DVec2::new(mu.to_mm(offset), oi.y - rho);
    rec.point(
        "cam centre O′_1 (with ρ_min)",
        o,
        Role::Result,
        "O′_1",
        DVec2::new(1.0, -0.5),
        &[],
    );
    let read_c = rec.measure(oi, DVec2::ZERO).value.copysign(-c);
    let graphical = read_c.max(0.0) + spec.rho_min;
    let base = spec.base_radius.unwrap_or(graphical);
    Ok(Read {
        graphical,
        convexity: Some(read_c),
        base,
        placement: Placement::Translating {
            offset: 0.0,
            s0: base,
        },
    })
}

/// The S axis of a combined diagram: from below the centre found on it (`depth` mm under
/// B₀: the drawn r_min) to above the stroke, labelled.
fn s_axis(rec: &mut Recorder, spec: &CamSpec, mu: Scale, depth: f64) -> StepId {
    let top = DVec2::new(0.0, mu.to_mm(spec.stroke) + 12.0);
    let ax = rec.draw(
        "S axis",
        Item::Vector {
            from: DVec2::new(0.0, -depth - 10.0),
            to: top,
        },
        Role::Axis,
        &[],
    );
    rec.label(ax, "S", top, DVec2::new(1.0, 0.0));
    ax
}

/// The points of a combined diagram: `at` of the motion read at each of the `n` points.
fn combined(d: &Diagrams, n: usize, at: impl Fn(Motion) -> DVec2) -> Vec<DVec2> {
    (0..n).map(|i| at(read_motion(d, i))).collect()
}

/// The γ_min lines of the translating follower's combined diagram: the two tangents through
/// the binding points (long), a short tick at every other point.
fn zone_lines(rec: &mut Recorder, ks: &[DVec2], o: DVec2, gamma: f64, bind: usize) {
    let (c, s) = (gamma.cos(), gamma.sin());
    for (i, k) in ks.iter().enumerate() {
        for dir in [DVec2::new(-c, -s), DVec2::new(c, -s)] {
            let towards_o = (o - *k).dot(dir) > 0.0 && (o.x - k.x) * dir.x >= 0.0;
            let len = if i == bind && towards_o {
                (o - *k).length() + 15.0
            } else {
                8.0
            };
            rec.draw(
                format!("γ_min line at point {i}"),
                Item::Segment(Segment::new(*k, *k + dir * len)),
                Role::Construction,
                &[],
            );
        }
    }
}

/// The admissible zone of the cam centre of a translating follower: its upper boundary
/// g(x) = min over the points of (K_y − |K_x − x|·tan γ_min) near the centre, hatched below.
fn hatch_zone(rec: &mut Recorder, ks: &[DVec2], o: DVec2, t: f64) {
    let g = |x: f64| {
        ks.iter()
            .map(|k| k.y - (k.x - x).abs() * t)
            .fold(f64::INFINITY, f64::min)
    };
    let half = 25.0;
    let pts: Vec<DVec2> = (0..=50)
        .map(|j| {
            let x = o.x - half + j as f64;
            DVec2::new(x, g(x))
        })
        .filter(|p| p.is_finite() && p.y > o.y - half)
        .collect();
    if pts.len() < 2 {
        return;
    }
    let edge = rec.draw(
        "boundary of the zone of the cam centre",
        Item::Polyline {
            points: pts.clone(),
            closed: false,
        },
        Role::Construction,
        &[],
    );
    for p in pts.iter().step_by(4) {
        rec.draw(
            "hatching of the zone",
            Item::Segment(Segment::new(*p, *p + DVec2::new(-3.0, -3.0))),
            Role::Hatch,
            &[edge],
        );
    }
}

/// The rocker's graphical centre: among the intersections of the γ_min lines and the feet
/// of the perpendiculars from A₀ onto them within [`REACH_ARMS`] arms (|O₂A₀|), the
/// admissible one nearest A₀.
fn rocker_centre(cons: &[(DVec2, DVec2)], a0: DVec2, gamma: f64) -> Option<DVec2> {
    let lines: Vec<(DVec2, DVec2)> = cons
        .iter()
        .flat_map(|&(k, e)| [1.0, -1.0].map(|s| (k, crate::geom::rotate(e, s * gamma))))
        .collect();
    let sin_g = gamma.sin();
    let mut cands = Vec::new();
    for (i, &(p, u)) in lines.iter().enumerate() {
        cands.push(p + u * (a0 - p).dot(u));
        for &(q, v) in &lines[i + 1..] {
            let den = u.perp_dot(v);
            if den.abs() > 1e-12 {
                let t = (q - p).perp_dot(v) / den;
                cands.push(p + u * t);
            }
        }
    }
    // Nearest first: the first admissible candidate is the centre (most fail at once).
    let reach = REACH_ARMS * a0.length();
    cands.retain(|c| c.is_finite() && c.distance(a0) < reach);
    cands.sort_by(|a, b| a.distance(a0).total_cmp(&b.distance(a0)));
    cands.into_iter().find(|c| admits(*c, cons, sin_g, 1e-9))
}

/// The rocker's γ_min lines: long through O where they bind, short ticks elsewhere.
fn rocker_lines(rec: &mut Recorder, cons: &[(DVec2, DVec2)], o: DVec2, gamma: f64) {
    for (i, &(k, e)) in cons.iter().enumerate() {
        for s in [1.0, -1.0] {
            let u = crate::geom::rotate(e, s * gamma);
            let off = (o - k).perp_dot(u).abs();
            let through = off < 1e-6 * (1.0 + (o - k).length());
            let (a, b) = if through {
                let t = (o - k).dot(u);
                (k - u * 10.0 * t.signum(), k + u * (t + 15.0 * t.signum()))
            } else {
                (k - u * 6.0, k + u * 6.0)
            };
            rec.draw(
                format!("γ_min line at K_{i}"),
                Item::Segment(Segment::new(a, b)),
                Role::Construction,
                &[],
            );
        }
    }
}

/// The admissible zone of a rocker cam's centre, hatched along its boundary near O: on every
/// γ_min line through O, at each step where one side admits the centre and the other does
/// not, a stroke into the admitted side, leaning away from O.
fn hatch_rocker_zone(rec: &mut Recorder, cons: &[(DVec2, DVec2)], o: DVec2, gamma: f64) {
    let sin_g = gamma.sin();
    let inside = |p: DVec2| admits(p, cons, sin_g, 0.0);
    for &(k, e) in cons {
        for s in [1.0, -1.0] {
            let u = crate::geom::rotate(e, s * gamma);
            if (o - k).perp_dot(u).abs() >= 1e-6 * (1.0 + (o - k).length()) {
                continue;
            }
            let n = u.perp();
            for j in (-ZONE_STEPS..=ZONE_STEPS).filter(|&j| j != 0) {
                let p = o + u * (f64::from(j) * ZONE_STEP_MM);
                // Leaning away from O, so no stroke crosses the zone's other side.
                let away = u * f64::from(j.signum());
                let side = match (inside(p + n * 0.3), inside(p - n * 0.3)) {
                    (true, false) => n,
                    (false, true) => -n,
                    _ => continue,
                };
                rec.draw(
                    "hatching of the zone",
                    Item::Segment(Segment::new(p, p + (side + away) * (3.0 / 2f64.sqrt()))),
                    Role::Hatch,
                    &[],
                );
            }
        }
    }
}

/// Steps each way along a boundary line of the rocker cam's zone, and their length, mm.
const ZONE_STEPS: i32 = 8;
const ZONE_STEP_MM: f64 = 2.0;
