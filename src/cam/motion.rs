//! The follower's motion at one cam angle in closed form: S, S′, S″ from the phase's law
//! (the rule at the ends of the phases: the phase side, not the dwell's), and the divisions'
//! points.

use super::{CamSpec, Law};
use std::f64::consts::TAU;

/// The follower's displacement S and its analogues S′ = dS/dφ, S″ = d²S/dφ² at one angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion {
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
    /// `0` … `2n + 1`.
    pub label: String,
    /// φ, rad.
    pub phi: f64,
    /// Take the piece after φ where the law jumps (the first point of a phase).
    pub after: bool,
    /// The phase: 0 rise, 2 return.
    pub phase: usize,
    /// The interval index within the phase (0 … n).
    pub k: usize,
}

/// The points of the diagrams: the rise's n + 1 and the return's n + 1 (seed 000: 26).
///
/// The rule at the ends of a moving phase (the same for every law): a point belongs to its
/// phase, so its first point reports the phase's value just after the start (`after`) and
/// its last point the phase's value just before the end, never the dwell's. An inner jump of
/// the "+ −" law on a node reports the piece before it.
pub fn points(spec: &CamSpec) -> Vec<Point> {
    let n = spec.divisions;
    let st = spec.starts();
    let mut out = Vec::with_capacity(2 * n + 2);
    for (phase, len) in [(0usize, spec.phases.rise), (2, spec.phases.ret)] {
        for k in 0..=n {
            out.push(Point {
                label: out.len().to_string(),
                phi: if k == n {
                    st[phase + 1]
                } else {
                    st[phase] + len * k as f64 / n as f64
                },
                after: k == 0,
                phase,
                k,
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
pub fn motion(spec: &CamSpec, phi: f64, after: bool) -> Motion {
    let (phase, u) = locate(spec, phi, after);
    motion_u(spec, phase, u, after)
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
pub fn motion_u(spec: &CamSpec, phase: usize, u: f64, after: bool) -> Motion {
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
            Motion {
                s: h * f,
                ds: h * f1,
                d2s: h * f2,
            }
        }
        2 => {
            let (f, f1, f2) = eval(spec.ret, spec.phases.ret);
            Motion {
                s: h * (1.0 - f),
                ds: -h * f1,
                d2s: -h * f2,
            }
        }
        1 => Motion {
            s: h,
            ds: 0.0,
            d2s: 0.0,
        },
        _ => Motion {
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
/// the drawn dwell one step on (the whole dwell if shorter); with no dwell there, the other
/// phase's end point.
pub fn neighbour(spec: &CamSpec, points: &[Point], i: usize, forward: bool) -> Neighbour {
    let p = &points[i];
    let j = if forward { i + 1 } else { i.wrapping_sub(1) };
    if points.get(j).is_some_and(|q| q.phase == p.phase) {
        return Neighbour::Point(j);
    }
    let len = if p.phase == 0 {
        spec.phases.rise
    } else {
        spec.phases.ret
    };
    let dwell = match (p.phase, forward) {
        (0, true) | (2, false) => spec.phases.far,
        _ => spec.phases.near,
    };
    let d = (len / spec.divisions as f64).min(dwell);
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
