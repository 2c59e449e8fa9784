//! The follower's motion at one cam angle in closed form: S, S′, S″ from the phase's law
//! (the rule at the ends of the phases: the phase side, not the dwell's), and the divisions'
//! points.

use super::{CamSpec, Given, Law};
use std::f64::consts::TAU;

/// The follower's displacement S and its analogues S′ = dS/dφ, S″ = d²S/dφ² at one angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FollowerMotion {
    /// S, m.
    pub s: f64,
    /// dS/dφ, m.
    pub ds: f64,
    /// d²S/dφ², m.
    pub d2s: f64,
}

/// A point of the diagrams and the inversion: its label, cam angle and, where the
/// acceleration analogue jumps, which side of the jump it belongs to.
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    /// `0`, `1`, … in order over the cycle (the rise's, then the return's).
    pub label: String,
    /// φ, rad.
    pub phi: f64,
    /// Take the piece after φ where the law jumps (the first point of a phase).
    pub after: bool,
    /// The phase: 0 rise, 2 return.
    pub phase: usize,
    /// The point's index within its phase (0 at its start).
    pub k: usize,
    /// The phase's last point (at its end).
    pub last: bool,
}

/// A knot of a law closer than this to a division point (in u, the share of the phase) is
/// on it: no extra division point is added for it.
pub(super) const KNOT_ON_NODE: f64 = 1e-9;

/// The division points of a moving phase of the law `law` over the angle `len`, rad from
/// its start: the scene's `divisions` equal intervals, and where the given acceleration
/// analogue breaks between them ([`Law::knots`]) a division point there too — the
/// textbook's rule for graphical integration: a division point on every break, so that the
/// given curve is smooth over each interval and the chord method's error is its own (second
/// order). A given S is smooth inside every phase (its breaks are the phases' ends): equal
/// intervals only.
pub fn divisions(spec: &CamSpec, law: Law, len: f64) -> Vec<f64> {
    let n = spec.divisions.max(1);
    let mut at: Vec<f64> = (0..=n).map(|k| len * k as f64 / n as f64).collect();
    if spec.given == Given::D2s {
        for b in law.knots() {
            let node = (b * n as f64).round() / n as f64;
            if b > 0.0 && b < 1.0 && (b - node).abs() > KNOT_ON_NODE {
                at.push(len * b);
            }
        }
        at.sort_by(f64::total_cmp);
    }
    at
}

/// The points of the diagrams: each moving phase's division points ([`divisions`]), the
/// rise's then the return's — with n equal intervals and no break between the nodes, n + 1
/// each (seed 000: 26).
///
/// The rule at the ends of a moving phase (the same for every law): a point belongs to its
/// phase, so its first point reports the phase's value just after the start (`after`) and
/// its last point the phase's value just before the end, never the dwell's. An inner jump of
/// the "+ −" law on a node reports the piece before it.
pub fn points(spec: &CamSpec) -> Vec<Point> {
    let st = spec.starts();
    let mut out = Vec::with_capacity(2 * spec.divisions + 10);
    for (phase, law, len) in [
        (0usize, spec.rise, spec.phases.rise),
        (2, spec.ret, spec.phases.ret),
    ] {
        let at = divisions(spec, law, len);
        let last = at.len() - 1;
        for (k, d) in at.into_iter().enumerate() {
            out.push(Point {
                label: out.len().to_string(),
                phi: if k == last {
                    st[phase + 1]
                } else {
                    st[phase] + d
                },
                after: k == 0,
                phase,
                k,
                last: k == last,
            });
        }
    }
    out
}

/// Angles closer than this to a phase boundary (or to a jump of a law, in u) are that
/// boundary, rad: the rounding of φ₀ + Φ·k/n never decides the side of a jump.
const SNAP: f64 = 1e-12;

/// The law at φ (any angle; wrapped into one turn), `after` picking the piece after a jump.
///
/// One rule at every boundary, for every law: at a phase boundary `after = false` gives the
/// phase that ends there (a moving phase's own end value, S′ and S″ of its law at u = 1),
/// `after = true` the phase that starts there (at u = 0); a dwell's values are the dwell's
/// only. φ within `SNAP` of a boundary is on it.
pub fn motion(spec: &CamSpec, phi: f64, after: bool) -> FollowerMotion {
    let (phase, u) = locate(spec, phi, after);
    motion_u(spec, phase, u, after)
}

/// Whether point `p` of a moving phase stands on a break of its law's d²S/dφ² inside the
/// phase ([`Law::breaks`](super::Law::breaks)): S″ jumps there, and so does the slope of any
/// curve drawn through the point against S′.
pub(super) fn on_break(spec: &CamSpec, p: &Point) -> bool {
    let st = spec.starts();
    let (law, len) = if p.phase == 0 {
        (spec.rise, spec.phases.rise)
    } else {
        (spec.ret, spec.phases.ret)
    };
    let u = if len > 0.0 {
        (p.phi - st[p.phase]) / len
    } else {
        0.0
    };
    law.breaks().iter().any(|b| (b - u).abs() <= KNOT_ON_NODE)
}

/// The phase (0 rise, 1 far dwell, 2 return, 3 near dwell) and u ∈ [0, 1] of φ, by the rule
/// of [`motion`].
pub fn locate(spec: &CamSpec, phi: f64, after: bool) -> (usize, f64) {
    let st = spec.starts();
    let p = &spec.phases;
    let lens = [p.rise, p.far, p.ret, p.near];
    let mut phi = if (0.0..=TAU).contains(&phi) {
        phi
    } else {
        phi.rem_euclid(TAU)
    };
    for b in st {
        if (phi - b).abs() <= SNAP {
            phi = b;
        }
    }
    if (TAU - phi).abs() <= SNAP {
        phi = st[4];
    }
    // The cycle's end is its start.
    if after && phi >= st[4] {
        phi = 0.0;
    } else if !after && phi <= 0.0 {
        phi = st[4];
    }
    for i in 0..4 {
        if lens[i] <= 0.0 {
            continue;
        }
        let inside = if after {
            phi >= st[i] && phi < st[i + 1]
        } else {
            phi > st[i] && phi <= st[i + 1]
        };
        if inside {
            return (i, ((phi - st[i]) / lens[i]).clamp(0.0, 1.0));
        }
    }
    // Between the phases' sum and 2π (the scene's rounding): the cycle's end or start.
    if after {
        (0, 0.0)
    } else {
        ((0..4).rev().find(|&i| lens[i] > 0.0).unwrap_or(3), 1.0)
    }
}

/// The law in phase `phase` (0 rise, 1 far dwell, 2 return, 3 near dwell) at u ∈ [0, 1],
/// `after` picking the piece after a jump of the law at u (u within `SNAP` of a jump is on
/// it).
pub fn motion_u(spec: &CamSpec, phase: usize, u: f64, after: bool) -> FollowerMotion {
    let h = spec.stroke;
    let eval = |law: Law, len: f64| {
        let mut u = u.clamp(0.0, 1.0);
        for b in law.breaks() {
            if (u - b).abs() <= SNAP {
                u = b;
            }
        }
        let (f, f1, f2) = law.eval(u, after);
        (f, f1 / len, f2 / (len * len))
    };
    match phase {
        0 => {
            let (f, f1, f2) = eval(spec.rise, spec.phases.rise);
            FollowerMotion {
                s: h * f,
                ds: h * f1,
                d2s: h * f2,
            }
        }
        2 => {
            let (f, f1, f2) = eval(spec.ret, spec.phases.ret);
            FollowerMotion {
                s: h * (1.0 - f),
                ds: -h * f1,
                d2s: -h * f2,
            }
        }
        1 => FollowerMotion {
            s: h,
            ds: 0.0,
            d2s: 0.0,
        },
        _ => FollowerMotion {
            s: 0.0,
            ds: 0.0,
            d2s: 0.0,
        },
    }
}

/// Where the drawing's neighbour of point `i` is, before it (`forward` false) or after it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Neighbour {
    /// A point of the law, by index.
    Point(usize),
    /// On a dwell: its angle and the dwell's S.
    Dwell {
        /// φ, rad.
        phi: f64,
        /// S, m.
        s: f64,
    },
}

/// The drawing's neighbour of point `i`: the next point of its phase; beyond a phase's end,
/// the drawn dwell one step on ([`end_step`]; the whole dwell if shorter); with no dwell
/// there, the other phase's end point.
pub fn neighbour(spec: &CamSpec, points: &[Point], i: usize, forward: bool) -> Neighbour {
    let p = &points[i];
    let j = if forward { i + 1 } else { i.wrapping_sub(1) };
    if points.get(j).is_some_and(|q| q.phase == p.phase) {
        return Neighbour::Point(j);
    }
    let dwell = match (p.phase, forward) {
        (0, true) | (2, false) => spec.phases.far,
        _ => spec.phases.near,
    };
    let d = end_step(points, i).min(dwell);
    if d <= 0.0 {
        return Neighbour::Point(j.wrapping_add(points.len()) % points.len());
    }
    Neighbour::Dwell {
        phi: if forward { p.phi + d } else { p.phi - d },
        s: if (p.phase == 0) == forward {
            spec.stroke
        } else {
            0.0
        },
    }
}

/// The step a drawing takes from point `i` at a phase's end onto the dwell beyond it: the
/// length of the phase's interval that ends (or starts) there.
pub fn end_step(points: &[Point], i: usize) -> f64 {
    let p = &points[i];
    let inner = if p.k == 0 { i + 1 } else { i.wrapping_sub(1) };
    points
        .get(inner)
        .filter(|q| q.phase == p.phase)
        .map_or(0.0, |q| (q.phi - p.phi).abs())
}
