//! The minimum radius as a construction: the combined diagram S(dS/dφ) with the γ_min lines
//! and the zone (translating), dS/dφ laid along the rocker with the γ_min lines (rocker), the
//! S(d²S/dφ²) diagram with its 45° tangent (flat face). The profile is built on the r₀
//! accepted from the r_min read off this drawing ([`super::accept`]) or on the scene's base
//! radius; the exact r_min over the whole cycle is the twin's ([`super::exact`], compared in [`super::Cam::rows`]).

use super::accept::accepted;
use super::combined::{abscissa, combined, s_axis, smooth_loop};
use super::diagrams::{read_motion, CamDiagrams};
use super::follower::{admits, rocker_of, Placement, REACH_ARMS};
use super::motion::Point;
use super::zone;
use super::{CamError, CamSpec, Follower};
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::{fan_start, Arc, DVec2, Segment};
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
    /// The rocker's centre distance a_w = |O₁O₂| at r_min as read off the drawing, m.
    pub centre_distance: Option<f64>,
}

/// The minimum radius constructed at the drawn points, and the base radius and placement of
/// the follower for the profile: the scene's base radius, else the r₀ accepted from the r_min
/// read off the drawing (translating: |O₁B₀|; rocker: O₁ found on the drawing, r₀ along its
/// direction from A₀; flat face: read at the 45° tangent, plus ρ_min).
pub(super) fn min_radius(
    spec: &CamSpec,
    points: &[Point],
    d: &CamDiagrams,
    ctx: &Context,
    raise: f64,
) -> Result<(RadiusConstruction, f64, Placement), CamError> {
    let mut rec = Recorder::in_context("combined", d.s_scale, ctx);
    let given = Given {
        spec,
        points,
        d,
        raise,
    };
    let read = match spec.follower {
        Follower::Translating { offset } => translating(&mut rec, &given, offset)?,
        Follower::Rocker { arm, .. } => rocker(&mut rec, &given, arm)?,
        Follower::Flat { .. } => flat(&mut rec, &given)?,
    };
    if spec.base_radius.is_some_and(|r0| r0 < read.graphical) {
        zone::chosen_centre(&mut rec, read.placement);
    }
    Ok((
        RadiusConstruction {
            figure: rec.finish(),
            graphical: read.graphical,
            convexity: read.convexity,
            centre_distance: read.centre_distance,
        },
        read.base,
        read.placement,
    ))
}

/// What every follower's construction starts from: the cam, its drawn points and their
/// diagrams.
#[derive(Clone, Copy)]
struct Given<'a> {
    pub(super) spec: &'a CamSpec,
    pub(super) points: &'a [Point],
    pub(super) d: &'a CamDiagrams,
    /// What the profile's own check adds to the r₀ accepted from the reading, m: whole
    /// millimetres, 0 until the angle read off a profile exceeds its limit
    /// ([`super::construct`]).
    pub(super) raise: f64,
}

/// What one follower's construction reads: r_min, the flat face's convexity, the rocker's
/// centre distance, the base radius the profile takes and the follower's placement.
struct Read {
    graphical: f64,
    convexity: Option<f64>,
    centre_distance: Option<f64>,
    base: f64,
    placement: Placement,
}

/// The translating follower: the combined diagram S(dS/dφ), the γ_min lines and the zone
/// of admissible centres on the vertical x = −e.
fn translating(rec: &mut Recorder, given: &Given<'_>, offset: f64) -> Result<Read, CamError> {
    let Given {
        spec, points, d, ..
    } = *given;
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
    let binds = |i: usize| spec.binds(&points[i]);
    let below = |k: &DVec2| k.y - (k.x - ox).abs() * t;
    let best = ks
        .iter()
        .enumerate()
        .filter(|(i, _)| binds(*i))
        .map(|(_, k)| below(k))
        .fold(f64::INFINITY, f64::min);
    let o = DVec2::new(ox, best);
    let path = s_axis(rec, spec, mu, o.length());
    abscissa(rec, &ks, "dS/dφ");
    for (i, k) in ks.iter().enumerate() {
        let b = DVec2::new(0.0, k.y);
        rec.draw(
            format!("dS/dφ at point {i}"),
            Item::Segment(Segment::new(b, *k)),
            Role::Construction,
            &[],
        );
    }
    smooth_loop(
        rec,
        (spec, points),
        &ks,
        "combined diagram S(dS/dφ)",
        &[path],
    );
    let apex = translating_zone(rec, &ks, &binds, o, gamma);
    if offset != 0.0 {
        zone::offset_line(rec, o);
    }
    // O₁'s name outside the zone: on the side of the zone's edge it lies on.
    let toward = if apex.is_some_and(|a| o.x < a.x) {
        DVec2::new(-1.0, 0.0)
    } else {
        DVec2::new(1.0, 0.0)
    };
    zone::centre_and_r_min(rec, o, DVec2::ZERO, toward, r_min_offset(o, apex));
    let r = rec.measure(o, DVec2::ZERO);
    let base = base_radius(rec, given, r.value);
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
        centre_distance: None,
        base,
        placement: Placement::Translating { offset, s0 },
    })
}

/// The least distance from the pivot O₂ at which the rocker's later positions begin, mm:
/// beyond the hinge; further out where their rays still run together ([`fan_start`], up to a
/// third of the rocker).
const FAN_CLEAR_MM: f64 = 8.0;

/// The rocker: dS/dφ laid along the rocker at every point, the γ_min lines through the
/// points K and the centre below them all.
fn rocker(rec: &mut Recorder, given: &Given<'_>, arm: f64) -> Result<Read, CamError> {
    let Given {
        spec, points, d, ..
    } = *given;
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
    let psi_of = |s: f64| FRAC_PI_2 + sigma * s / arm;
    let later: Vec<f64> = (1..points.len())
        .map(|i| psi_of(read_motion(d, i).s))
        .collect();
    let begin = fan_start(later, (FAN_CLEAR_MM, l / 3.0)).max(FAN_CLEAR_MM);
    let mut cons = Vec::new();
    let mut ks = Vec::new();
    for (i, p) in points.iter().enumerate() {
        let m = read_motion(d, i);
        let psi = psi_of(m.s);
        let e = DVec2::from_angle(psi);
        let a = pivot + e * l;
        let k = a - e * (sigma * mu.to_mm(m.ds));
        // Each later position starts clear of the pivot: a dozen or more rays meeting at O₂
        // print as a black wedge there; the first, the rocker as given, runs from O₂.
        let from = if i == 0 {
            pivot
        } else {
            pivot + e * begin.min(l)
        };
        rec.draw(
            format!("rocker O_2A_{i}"),
            Item::Segment(Segment::new(from, a)),
            Role::Construction,
            &[pid],
        );
        ks.push(k);
        if spec.binds(p) {
            cons.push((k, e));
        }
    }
    smooth_loop(rec, (spec, points), &ks, "curve of the points K", &[]);
    let o = rocker_centre(&cons, a0, gamma).ok_or(CamError::NoCentre {
        gamma_deg: gamma.to_degrees(),
        searched: REACH_ARMS * arm,
    })?;
    rocker_zone(rec, &cons, o, gamma);
    let oid = zone::centre_and_r_min(rec, o, a0, DVec2::new(1.0, 0.5), 0.0);
    rec.draw(
        "centre distance",
        Item::Segment(Segment::new(o, pivot)),
        Role::Construction,
        &[oid, pid],
    );
    rec.dimension(A_W_NOTE, (o, pivot, 0.0), "a_w");
    let a_w = rec.measure(o, pivot).value;
    let r = rec.measure(o, a0);
    // The profile uses the centre found on the drawing: its direction from A₀ and its
    // distance read (or the given base radius along that direction).
    let dir = (o - a0).normalize_or_zero();
    let base = base_radius(rec, given, r.value);
    let o_used = DVec2::new(0.0, arm) + dir * base;
    let pivot_cam = -o_used;
    Ok(Read {
        graphical: r.value,
        convexity: None,
        centre_distance: Some(a_w),
        base,
        placement: Placement::Rocker {
            pivot: pivot_cam,
            arm,
            psi0: FRAC_PI_2,
            sigma,
        },
    })
}

/// The flat face: S(d²S/dφ²) with the 45° tangent from the curve to the S axis; the centre
/// O₁ ρ_min below where it meets the axis, r_min = |OO₁| (the offset does not change a flat
/// face's profile: the centre is drawn on the S axis).
fn flat(rec: &mut Recorder, given: &Given<'_>) -> Result<Read, CamError> {
    let Given {
        spec, points, d, ..
    } = *given;
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
    // The S axis runs on below O₁ for ρ_min's text past its arrow where the text has room
    // neither between the arrows nor above them, under the d²S/dφ² axis.
    let room = if rho < RHO_TEXT_MM && -oi.y < RHO_TEXT_MM {
        RHO_TEXT_MM
    } else {
        0.0
    };
    let ax = s_axis(rec, spec, mu, rho - oi.y + room);
    let xs = pts.iter().fold(0.0f64, |a, p| a.max(p.x.abs()));
    // The abscissa as wide each side as the curve's widest side: the 45° tangent runs left.
    let hx = abscissa(rec, &[DVec2::X * -xs, DVec2::X * xs], "d^2S/dφ^2");
    // Through the points K as a French curve follows them, as the other combined diagrams: a
    // polyline put a corner at each, and a spike where S″ is extreme, where the smooth law's
    // curve turns with a vertical tangent.
    smooth_loop(
        rec,
        (spec, points),
        &pts,
        "combined diagram S(d²S/dφ²)",
        &[ax, hx],
    );
    // The tangent from its touching point to its crossing with the S axis, at S = c.
    let touch = pts.get(i).copied().unwrap_or(DVec2::ZERO);
    let cross = DVec2::new(0.0, c);
    let tangent = rec.draw(
        TANGENT_NOTE,
        Item::Segment(Segment::new(touch, cross)),
        Role::Construction,
        &[ax],
    );
    rec.point(
        "the tangent's crossing with the S axis",
        cross,
        Role::Construction,
        "",
        DVec2::ZERO,
        &[],
    );
    // The centre ρ_min below where the tangent meets the axis (at O when it meets it above).
    let o = DVec2::new(0.0, oi.y - rho);
    // The zone of the centre (the textbook's hatching between the tangent and the S axis):
    // below the tangent, along it toward its touching point and down the axis to O₁.
    let up = (touch - cross)
        .try_normalize()
        .unwrap_or(DVec2::new(-1.0, 1.0).normalize());
    let down = cross.distance(o);
    zone::hatch_angle_between(
        rec,
        cross,
        (up, touch.distance(cross).min(zone::band_length(down))),
        (DVec2::NEG_Y, down),
        &[tangent, ax],
    );
    // ρ_min and r_min right of the S axis (the tangent comes from the left), one beside
    // the other, each with the room for its text left of its line.
    if oi.y < 0.0 {
        rec.dimension(RHO_MIN_NOTE, (oi, o, RHO_MIN_MM), RHO_ADMITTED);
    }
    zone::centre_and_r_min(rec, o, DVec2::ZERO, DVec2::new(-1.0, -0.5), -FLAT_R_MIN_MM);
    let read_c = rec.measure(oi, DVec2::ZERO).value.copysign(-c);
    let graphical = rec.measure(o, DVec2::ZERO).value;
    let base = base_radius(rec, given, graphical);
    Ok(Read {
        graphical,
        convexity: Some(read_c),
        centre_distance: None,
        base,
        placement: Placement::Translating {
            offset: 0.0,
            s0: base,
        },
    })
}

/// The translating follower's r_min dimension, drawn beside O₁B₀, stands clear of the S axis,
/// mm.
const R_MIN_CLEAR_MM: f64 = 4.0;

/// Where a translating follower's r_min dimension O₁B₀ is drawn (left of O₁ → B₀, mm), so that
/// it crosses no line of the diagram but the S axis it ends on: on the piece itself, its text
/// beside it (the textbook's way), for a central follower (the piece on the S axis) and where
/// the zone lies between O₁ and the S axis (its apex at `apex`: then the γ_min line O₁ lies
/// below separates O₁ from B₀, and any line beside the piece would cross the zone, its
/// other ray and the axis besides); else, the zone lying beyond O₁, past the S axis on the
/// side away from O₁ — the wedge between the piece and the zone's ray from B₀ is too narrow
/// for its text (with the value).
fn r_min_offset(o: DVec2, apex: Option<DVec2>) -> f64 {
    let beyond = apex.is_some_and(|a| (a.x - o.x) * o.x > 0.0);
    if o.x.abs() < 1e-9 || !beyond {
        0.0
    } else {
        o.x.signum() * (o.x.abs() + R_MIN_CLEAR_MM)
    }
}

/// The base radius the profile is built on: the scene's, else the one accepted from the r_min
/// `read` off this drawing ([`accepted`]) and raised as the profile's check asks.
fn base_radius(rec: &Recorder, given: &Given<'_>, read: f64) -> f64 {
    given
        .spec
        .base_radius
        .unwrap_or_else(|| accepted(read, rec.scale(), rec.drafting()) + given.raise)
}

/// The flat face's ρ_min dimension stands this far right of the S axis, mm: its text (with
/// the value) fits between the axis and its line.
const RHO_MIN_MM: f64 = 9.0;
/// The length ρ_min's text (with its value) takes beside the S axis, its gaps included, mm.
const RHO_TEXT_MM: f64 = 40.0;
/// The flat face's r_min dimension stands this far right of the S axis, mm: its text fits
/// between the ρ_min dimension (its line, its extension lines) and its own line.
const FLAT_R_MIN_MM: f64 = 20.0;

/// The note of the flat face's ρ_min dimension's step (the sheet writes its value).
pub const RHO_MIN_NOTE: &str = "dimension ρ_min";
/// The note of the rocker's centre distance a_w's dimension.
pub const A_W_NOTE: &str = "dimension a_w";

/// The symbol of the flat face's given margin over convexity, the least radius of curvature
/// the profile is admitted (r₀ ≥ max(−(S + S″)) + \[ρ\]): the admissible value's brackets
/// keep it apart from the profile's own ρ_min, which the tables compare.
pub const RHO_ADMITTED: &str = "[ρ]";

/// The note of the flat face's 45° tangent's step (the tests find it by it).
pub const TANGENT_NOTE: &str = "tangent at 45° from the diagram to the S axis";

/// The zone of the translating follower's centre: below every point's two γ_min lines,
/// g(x) = min over the points of (K_y − |K_x − x|·tan γ_min) = min(R(x), L(x)), a wedge whose
/// sides are the lowest line of each family (the tangents to the diagram at γ_min to its
/// dS/dφ axis). Its two rays are drawn from their points to their crossing and the wedge is
/// hatched along them; the centre `o` lies on its boundary. Returns the rays' crossing.
fn translating_zone(
    rec: &mut Recorder,
    ks: &[DVec2],
    binds: &impl Fn(usize) -> bool,
    o: DVec2,
    gamma: f64,
) -> Option<DVec2> {
    let t = gamma.tan();
    // The lowest line of a family: the least K_y ± K_x·tan γ (the first of equals).
    let lowest = |sign: f64| {
        (0..ks.len())
            .filter(|&i| binds(i))
            .map(|i| (i, ks[i].y + sign * ks[i].x * t))
            .fold(None, |a: Option<(usize, f64)>, b| match a {
                Some(a) if a.1 <= b.1 => Some(a),
                _ => Some(b),
            })
            .map(|(i, _)| ks[i])
    };
    let (kr, kl) = (lowest(1.0)?, lowest(-1.0)?);
    let (c, s) = (gamma.cos(), gamma.sin());
    let rays = [
        zone::Ray {
            k: kr,
            dir: DVec2::new(c, -s),
        },
        zone::Ray {
            k: kl,
            dir: DVec2::new(-c, -s),
        },
    ];
    let apex = zone::crossing(rec, rays[0], rays[1])?;
    let g = |x: f64| {
        ks.iter()
            .enumerate()
            .filter(|(i, _)| binds(*i))
            .map(|(_, k)| k.y - (k.x - x).abs() * t)
            .fold(f64::INFINITY, f64::min)
    };
    let reach = apex.distance(o) + 10.0;
    zone::draw_zone(rec, rays, apex, reach, |p| p.y < g(p.x));
    Some(apex)
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

/// The rocker's zone of the centre near `o`: its two bounding γ_min lines drawn from their
/// points K to their crossing and the zone hatched along them. Two lines through `o` cross
/// there; when one only passes through it (`o` the foot of the perpendicular from A₀), the
/// zone's corner is the nearest admissible crossing of that line with another.
fn rocker_zone(rec: &mut Recorder, cons: &[(DVec2, DVec2)], o: DVec2, gamma: f64) {
    let sin_g = gamma.sin();
    let lines: Vec<zone::Ray> = cons
        .iter()
        .flat_map(|&(k, e)| {
            [1.0, -1.0].map(|s| zone::Ray {
                k,
                dir: crate::geom::rotate(e, s * gamma),
            })
        })
        .collect();
    let through =
        |r: &zone::Ray| (o - r.k).perp_dot(r.dir).abs() < 1e-6 * (1.0 + (o - r.k).length());
    let at_o: Vec<zone::Ray> = lines.iter().copied().filter(through).collect();
    let apart = |a: &zone::Ray, b: &zone::Ray| a.dir.perp_dot(b.dir).abs() > 0.05;
    let pair = at_o
        .iter()
        .enumerate()
        .find_map(|(i, a)| {
            at_o[i + 1..]
                .iter()
                .find(|b| apart(a, b))
                .map(|b| ([*a, *b], o))
        })
        .or_else(|| {
            let first = *at_o.first()?;
            lines
                .iter()
                .filter(|b| apart(&first, b))
                .filter_map(|b| Some((*b, zone::crossing(rec, first, *b)?)))
                .filter(|(_, c)| admits(*c, cons, sin_g, 1e-9))
                .min_by(|x, y| x.1.distance(o).total_cmp(&y.1.distance(o)))
                .map(|(b, c)| ([first, b], c))
        });
    let Some((rays, c)) = pair else {
        return;
    };
    let reach = c.distance(o) + 10.0;
    zone::draw_zone(rec, rays, c, reach, |p| admits(p, cons, sin_g, 0.0));
}
