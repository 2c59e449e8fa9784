//! The exact cam centre of a rocker roller follower: the point O nearest A₀ from which every
//! common normal makes γ ≥ γ_min with the rocker, over the whole cycle (the rise only under
//! force closure), found without a grid of radii or directions.
//!
//! In the frame of the pivot O₂ (origin, A₀ at ψ₀ = 90°), each follower position gives the
//! point K (OK ∥ the common normal) and the rocker's direction e; O is admissible for it when
//! O − K lies in the double cone about the rocker's path J·e of half-angle 90° − γ_min. Along
//! a piece of the cycle where K moves continuously, O − K cannot pass from one cone to the
//! opposite one without leaving both, so each such group keeps one cone (σ = ±1), bounded by
//! two half-planes (O − K)·n ≥ 0 with n = σ·rot(J·e, ∓γ_min). For each choice of cones the
//! admissible region is the intersection of these half-planes (convex), and the nearest O is
//! the projection of A₀ onto it, found by cutting planes: the region is kept as a polygon,
//! A₀ projected onto it, the most violated constraint of each family over the continuum
//! (dense samples, every local minimum refined by golden section) cut off, until none is
//! violated beyond rounding. The answer is the nearest over the choices of cones.

use super::extremum::{checked_pieces, max_on, PhasePiece};
use super::follower::{rocker_of, Placement, REACH_ARMS};
use super::motion::motion_u;
use super::{CamSpec, Closure};
use crate::geom::{rotate, DVec2};
use std::f64::consts::FRAC_PI_2;

/// Samples per whole phase of the constraints' continuum (refined between them).
const PER_PHASE: usize = 2000;
/// Cutting-plane rounds at most (each cuts the worst violation of every family).
const ROUNDS: usize = 400;

/// One follower position's constraint data: K and the inward normals of the two
/// half-planes of the cone about +J·e (the other cone's are their opposites).
#[derive(Debug, Clone, Copy)]
struct Pos {
    k: DVec2,
    n: [DVec2; 2],
}

/// A group of pieces along which K moves continuously, with its samples.
struct Group {
    pieces: Vec<PhasePiece>,
    /// Per piece: its u samples and the positions there.
    samples: Vec<(Vec<f64>, Vec<Pos>)>,
}

/// The rocker's placement in the pivot frame.
fn placement(spec: &CamSpec) -> Placement {
    let (arm, sigma) = rocker_of(spec);
    Placement::Rocker {
        pivot: DVec2::ZERO,
        arm,
        psi0: FRAC_PI_2,
        sigma,
    }
}

fn pos(spec: &CamSpec, place: &Placement, piece: &PhasePiece, u: f64) -> Pos {
    let m = motion_u(spec, piece.phase, u, piece.after(u));
    let k = place.kin(m);
    let path = DVec2::new(-k.along.y, k.along.x);
    let g = spec.gamma_min;
    Pos {
        k: k.k,
        n: [rotate(path, -g), rotate(path, g)],
    }
}

/// The constraint's inward normal of family `j` (0, 1) for the cone σ.
fn normal(p: &Pos, sigma: f64, j: usize) -> DVec2 {
    p.n[j] * sigma
}

/// The pieces split into groups of continuous K (cyclic under geometric closure).
fn groups(spec: &CamSpec, place: &Placement, arm: f64) -> Vec<Group> {
    let pieces = checked_pieces(spec);
    let mut out: Vec<Vec<PhasePiece>> = Vec::new();
    let tol = 1e-9 * arm;
    for (i, p) in pieces.iter().enumerate() {
        let joined = i > 0 && {
            let prev = &pieces[i - 1];
            pos(spec, place, prev, prev.to)
                .k
                .distance(pos(spec, place, p, p.from).k)
                <= tol
        };
        match out.last_mut() {
            Some(g) if joined => g.push(*p),
            _ => out.push(vec![*p]),
        }
    }
    if spec.closure == Closure::Geometric && out.len() > 1 {
        let (first, last) = (pieces[0], pieces[pieces.len() - 1]);
        let cyclic = pos(spec, place, &last, last.to)
            .k
            .distance(pos(spec, place, &first, first.from).k)
            <= tol;
        if cyclic {
            if let Some(tail) = out.pop() {
                out[0].splice(0..0, tail);
            }
        }
    }
    out.into_iter()
        .map(|pieces| {
            let samples = pieces
                .iter()
                .map(|p| {
                    let us = p.samples(PER_PHASE);
                    let ps = us.iter().map(|&u| pos(spec, place, p, u)).collect();
                    (us, ps)
                })
                .collect();
            Group { pieces, samples }
        })
        .collect()
}

/// A half-plane n·x ≥ c.
type Cut = (DVec2, f64);

/// The polygon cut by the half-plane (Sutherland–Hodgman); empty when nothing remains.
fn clip(poly: &[DVec2], (n, c): Cut) -> Vec<DVec2> {
    let mut out = Vec::with_capacity(poly.len() + 1);
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        let (da, db) = (n.dot(a) - c, n.dot(b) - c);
        if da >= 0.0 {
            out.push(a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            let t = da / (da - db);
            out.push(a + (b - a) * t);
        }
    }
    out
}

/// The point of the convex polygon nearest `p`.
fn nearest(poly: &[DVec2], p: DVec2) -> DVec2 {
    let n = poly.len();
    let inside = (0..n).all(|i| (poly[(i + 1) % n] - poly[i]).perp_dot(p - poly[i]) >= 0.0);
    if inside {
        return p;
    }
    let mut best = (f64::INFINITY, p);
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let d = b - a;
        let t = if d.length_squared() > 0.0 {
            ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let q = a + d * t;
        let dist = q.distance(p);
        if dist < best.0 {
            best = (dist, q);
        }
    }
    best.1
}

/// The constraints of `group` violated at `o` beyond `tol` (the cone σ): every sampled local
/// minimum of each family's slack (O − K)·n over the continuum, refined, as a cut.
fn violated(
    spec: &CamSpec,
    place: &Placement,
    group: &Group,
    sigma: f64,
    o: DVec2,
    tol: f64,
    near: f64,
) -> Vec<Cut> {
    let mut cuts = Vec::new();
    for j in 0..2 {
        let slack = |p: &Pos| (o - p.k).dot(normal(p, sigma, j));
        for (piece, (us, ps)) in group.pieces.iter().zip(&group.samples) {
            let vs: Vec<f64> = ps.iter().map(slack).collect();
            let n = vs.len() - 1;
            for i in 0..=n {
                let left = i == 0 || vs[i] < vs[i - 1];
                let right = i == n || vs[i] <= vs[i + 1];
                if !(left && right) || vs[i] > near {
                    continue;
                }
                let (lo, hi) = (us[i.saturating_sub(1)], us[(i + 1).min(n)]);
                let (neg, u) = if n == 0 {
                    (-vs[i], us[i])
                } else {
                    max_on(lo, hi, 2, |u| -slack(&pos(spec, place, piece, u)))
                };
                if -neg < -tol {
                    let p = pos(spec, place, piece, u);
                    let nn = normal(&p, sigma, j);
                    cuts.push((nn, nn.dot(p.k)));
                }
            }
        }
    }
    cuts
}

/// The nearest admissible centre for one choice of cones, or `None` (empty or out of reach).
fn project(
    spec: &CamSpec,
    place: &Placement,
    groups: &[Group],
    sigmas: &[f64],
    a0: DVec2,
    arm: f64,
) -> Option<(f64, DVec2)> {
    let reach = REACH_ARMS * arm;
    let mut poly = vec![
        a0 + DVec2::new(-reach, -reach),
        a0 + DVec2::new(reach, -reach),
        a0 + DVec2::new(reach, reach),
        a0 + DVec2::new(-reach, reach),
    ];
    let tol = 1e-13 * arm;
    let near = 1e-2 * arm;
    let mut o = a0;
    for _ in 0..ROUNDS {
        let cuts: Vec<Cut> = groups
            .iter()
            .zip(sigmas)
            .flat_map(|(g, &s)| violated(spec, place, g, s, o, tol, near))
            .collect();
        if cuts.is_empty() {
            break;
        }
        for c in cuts {
            poly = clip(&poly, c);
            if poly.len() < 3 {
                return None;
            }
        }
        o = nearest(&poly, a0);
    }
    let r = o.distance(a0);
    (r < reach * (1.0 - 1e-9)).then_some((r, o))
}

/// The exact minimum base radius of a rocker cam over the whole cycle (the rise only under
/// force closure): the cam centre O nearest A₀ (frame of the pivot, A₀ = (0, L)) from which
/// every OK makes γ ≥ γ_min with the rocker. Returns (r₀, O), or `None` when no centre
/// within [`REACH_ARMS`] arms qualifies.
pub fn min_radius_rocker(spec: &CamSpec) -> Option<(f64, DVec2)> {
    let (arm, _) = rocker_of(spec);
    let place = placement(spec);
    let a0 = DVec2::new(0.0, arm);
    let groups = groups(spec, &place, arm);
    let mut best: Option<(f64, DVec2)> = None;
    for mask in 0..(1usize << groups.len()) {
        let sigmas: Vec<f64> = (0..groups.len())
            .map(|g| if mask >> g & 1 == 1 { -1.0 } else { 1.0 })
            .collect();
        if let Some((r, o)) = project(spec, &place, &groups, &sigmas, a0, arm) {
            if best.is_none_or(|(b, _)| r < b) {
                best = Some((r, o));
            }
        }
    }
    best
}
