//! The smooth pieces of a cam's cycle and the extrema of a function over them, to rounding:
//! every moving phase split at its law's jumps, every dwell of non-zero length; a piece's
//! ends are evaluated on the piece's own side of a jump; the largest of a function over a
//! piece is found from dense samples, every sampled local maximum refined by golden section
//! (the value of a smooth maximum to a few ulps, whatever the sampling).

use super::motion::{self, FollowerMotion};
use super::{CamSpec, Closure};
use crate::geom::golden_max;

/// A smooth piece of the cycle: `phase` (0 rise, 1 far dwell, 2 return, 3 near dwell) from
/// u = `from` to u = `to` of that phase (a dwell: 0 to 1, the motion constant).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PhasePiece {
    /// The phase, 0…3.
    pub phase: usize,
    /// u at the piece's start.
    pub from: f64,
    /// u at the piece's end.
    pub to: f64,
}

impl PhasePiece {
    /// Whether the motion is constant over the piece (a dwell).
    pub fn dwell(&self) -> bool {
        self.phase % 2 == 1
    }
    /// The motion at u of the piece: its end (and u within 1e-12 of it, which the law
    /// takes as the end) on the side before it, elsewhere (its start included) the side
    /// after: every value is the piece's own.
    pub fn motion(&self, spec: &CamSpec, u: f64) -> FollowerMotion {
        motion::motion_u(spec, self.phase, u, self.after(u))
    }
    /// The side of a jump at u that belongs to the piece.
    pub fn after(&self, u: f64) -> bool {
        self.to - u > 1e-12
    }
    /// φ of u of the piece, rad.
    pub fn phi(&self, spec: &CamSpec, u: f64) -> f64 {
        let st = spec.starts();
        let len = [
            spec.phases.rise,
            spec.phases.far,
            spec.phases.ret,
            spec.phases.near,
        ][self.phase];
        if u >= 1.0 {
            st[self.phase + 1]
        } else {
            st[self.phase] + len * u
        }
    }
    /// The samples of the piece: `per_phase` intervals per whole phase (at least 8 per
    /// piece), both ends; a dwell: its start only.
    pub fn samples(&self, per_phase: usize) -> Vec<f64> {
        if self.dwell() {
            return vec![self.from];
        }
        let n = ((per_phase as f64 * (self.to - self.from)).ceil() as usize).max(8);
        (0..=n)
            .map(|i| {
                if i == n {
                    self.to
                } else {
                    self.from + (self.to - self.from) * i as f64 / n as f64
                }
            })
            .collect()
    }
}

/// The pieces of the whole cycle in order (`rise_only`: the rise's only).
pub fn pieces(spec: &CamSpec, rise_only: bool) -> Vec<PhasePiece> {
    let p = &spec.phases;
    let mut out = Vec::new();
    for (phase, len) in [(0usize, p.rise), (1, p.far), (2, p.ret), (3, p.near)] {
        if len <= 0.0 || (rise_only && phase != 0) {
            continue;
        }
        if phase % 2 == 1 {
            out.push(PhasePiece {
                phase,
                from: 0.0,
                to: 1.0,
            });
            continue;
        }
        let law = if phase == 0 { spec.rise } else { spec.ret };
        let mut cuts = vec![0.0];
        cuts.extend(law.breaks().into_iter().filter(|b| *b > 0.0 && *b < 1.0));
        cuts.push(1.0);
        for w in cuts.windows(2) {
            out.push(PhasePiece {
                phase,
                from: w[0],
                to: w[1],
            });
        }
    }
    out
}

/// The pieces the angle limit is checked on: the whole cycle, the rise only under force
/// closure (its ends on the rise's side).
pub fn checked_pieces(spec: &CamSpec) -> Vec<PhasePiece> {
    pieces(spec, spec.closure == Closure::Force)
}

/// The largest of `f` on [a, b] (ends included as `f` gives them) and where: `n` intervals
/// sampled, each sampled local maximum (the ends too) refined by golden section within its
/// two neighbouring intervals. `f` continuous on [a, b] and unimodal between samples.
pub fn max_on(a: f64, b: f64, n: usize, f: impl Fn(f64) -> f64) -> (f64, f64) {
    let n = n.max(1);
    let xs: Vec<f64> = (0..=n)
        .map(|i| {
            if i == n {
                b
            } else {
                a + (b - a) * i as f64 / n as f64
            }
        })
        .collect();
    let vs: Vec<f64> = xs.iter().map(|&x| f(x)).collect();
    let mut best = (f64::NEG_INFINITY, a);
    for (&x, &v) in xs.iter().zip(&vs) {
        if v > best.0 {
            best = (v, x);
        }
    }
    if b <= a {
        return best;
    }
    for i in 0..=n {
        let left = i == 0 || vs[i] > vs[i - 1];
        let right = i == n || vs[i] >= vs[i + 1];
        if left && right {
            let lo = xs[i.saturating_sub(1)];
            let hi = xs[(i + 1).min(n)];
            let found = golden_max(lo, hi, &f);
            if found.0 > best.0 {
                best = found;
            }
        }
    }
    best
}

/// The largest of `f(motion)` over `pieces` (dense per phase, refined) and where:
/// (value, piece, u).
pub fn max_over(
    spec: &CamSpec,
    pieces: &[PhasePiece],
    per_phase: usize,
    f: impl Fn(FollowerMotion) -> f64,
) -> (f64, PhasePiece, f64) {
    let mut best = (
        f64::NEG_INFINITY,
        PhasePiece {
            phase: 0,
            from: 0.0,
            to: 1.0,
        },
        0.0,
    );
    for p in pieces {
        let n = if p.dwell() {
            1
        } else {
            ((per_phase as f64 * (p.to - p.from)).ceil() as usize).max(8)
        };
        let (v, u) = max_on(p.from, p.to, n, |u| f(p.motion(spec, u)));
        if v > best.0 {
            best = (v, *p, u);
        }
    }
    best
}
