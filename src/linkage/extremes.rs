//! Extreme (dead) positions of the output, found exactly as the zeros of its velocity
//! analogue, and the working stroke, the time ratio K and the angle θ.

use super::analytic::Pose;
use super::error::{LinkageError, ModelError};
use super::model::{Output, Sense};
use super::program::Program;
use crate::geom::{bisect, wrap_pi, DVec2, Midpoint, Tolerances};
use std::convert::Infallible;
use std::f64::consts::{PI, TAU};

/// An output coordinate of the program.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OutputCoord {
    /// A link angle (radians), by link number.
    Rocker(usize),
    /// A point's travel along a unit direction (m), by point index.
    Slider(usize, DVec2),
}

impl OutputCoord {
    /// Resolve an [`Output`] against a program.
    pub fn resolve(out: &Output, prog: &Program) -> Result<Self, LinkageError> {
        match out {
            Output::Rocker { link } => {
                if (*link as usize) < prog.link_count {
                    Ok(OutputCoord::Rocker(*link as usize))
                } else {
                    Err(ModelError::NoSuchRocker(*link).into())
                }
            }
            Output::Slider { point, dir } => prog
                .index(point)
                .map(|i| OutputCoord::Slider(i, DVec2::from_angle(*dir)))
                .ok_or_else(|| ModelError::NoSuchSlider(point.clone()).into()),
        }
    }
    /// Value (relative to `reference` for angles, so that it stays continuous) and dq/dφ₁.
    pub fn eval(&self, pose: &Pose, reference: f64) -> (f64, f64) {
        match *self {
            OutputCoord::Rocker(l) => (
                reference + wrap_pi(pose.angle(l) - reference),
                pose.dangle[l],
            ),
            OutputCoord::Slider(i, d) => (pose.p[i].dot(d), pose.dp[i].dot(d)),
        }
    }
}

/// The range of one output between its extremes.
#[derive(Debug, Clone, PartialEq)]
pub struct OutputRange {
    /// The output.
    pub coord: OutputCoord,
    /// Crank angle at the minimum, radians.
    pub phi_min: f64,
    /// Crank angle at the maximum.
    pub phi_max: f64,
    /// Minimum value (rad or m).
    pub min: f64,
    /// Maximum value.
    pub max: f64,
    /// The other crank angles at which it stands (radians in [0, 2π), ascending) with its
    /// value there: a local extreme, or a second arrival at an extreme position (a six-bar's
    /// slider that reaches its end, returns and reaches it again) — where dq/dφ₁ changes sign
    /// through zero, not at a toggle (a kink of q(φ₁)).
    pub stops: Vec<(f64, f64)>,
}

impl OutputRange {
    /// The crank angle of the extreme position at which the output's value is `q` (within
    /// the coincidence tolerance of its span), if `q` is an extreme's value.
    pub fn extreme_at(&self, q: f64) -> Option<f64> {
        let tol = Tolerances::for_model_size(self.max - self.min)
            .ok()?
            .coincident;
        [(self.min, self.phi_min), (self.max, self.phi_max)]
            .into_iter()
            .find(|e| (q - e.0).abs() <= tol)
            .map(|e| e.1)
    }

    /// The first stop at which the output stands in an extreme position again (the six-bar's
    /// slider reaches its end, returns and reaches it again): its crank angle, and the
    /// extreme position's.
    pub fn reached_again(&self) -> Option<(f64, f64)> {
        self.stops
            .iter()
            .find_map(|&(phi, q)| self.extreme_at(q).map(|e| (phi, e)))
    }
}

/// Extreme positions and the working stroke, from the first output.
#[derive(Debug, Clone, PartialEq)]
pub struct Extremes {
    /// Crank angle at the start of the working stroke, radians in [0, 2π).
    pub phi_start: f64,
    /// Crank angle at its end (the other extreme).
    pub phi_other: f64,
    /// Crank travel of the working stroke, radians.
    pub work_travel: f64,
    /// Time ratio K = travel of the working stroke / travel of the return stroke.
    pub k: f64,
    /// θ = work_travel − π: K = (180° + θ)/(180° − θ).
    pub theta: f64,
    /// Every output's range, in the order given.
    pub ranges: Vec<OutputRange>,
    /// The working stroke is the one from the outer dead centre (a driving slider, an
    /// engine's expansion stroke), not the slower one.
    pub from_outer: bool,
}

impl Extremes {
    /// Whether θ and K say anything: the first output reaches each extreme position once a
    /// turn. Reached twice, its strokes are no longer two (min → max, max → min), and which
    /// arrival ends the working stroke is a choice the mechanism does not make.
    pub fn ratio_defined(&self) -> bool {
        self.reached_again().is_none()
    }

    /// Where the first output stands in an extreme position again, if it does
    /// ([`OutputRange::reached_again`]): the stop's crank angle and the extreme position's.
    pub fn reached_again(&self) -> Option<(f64, f64)> {
        self.ranges.first()?.reached_again()
    }

    /// Whether the rocker's swing of `r` is θ itself (a crank-rocker's swing is the angle
    /// between the crank's extremes only where the rocker is the first output, θ defined):
    /// then it is named θ, not ψ, and θ is not drawn a second time.
    pub fn theta_is_swing(&self, r: &OutputRange) -> bool {
        matches!(r.coord, OutputCoord::Rocker(_))
            && self.ratio_defined()
            && ((r.max - r.min).abs() - self.theta.abs()).abs() < 1e-9
    }
}

/// Samples of a full crank turn for bracketing the zeros of dq/dφ.
const SAMPLES: usize = 720;

impl Program {
    /// Solve at `phi` (each assembly on the scene's side), or say which group stops the crank.
    fn solve_turning(&self, phi: f64) -> Result<Pose, LinkageError> {
        self.solve(phi, None).map_err(|u| LinkageError::CannotTurn {
            phi_deg: phi.to_degrees(),
            group: format!("{}", u.group + 1),
            detail: u.detail,
        })
    }

    /// Find the extreme positions of the outputs over a full turn of the crank, and the
    /// working stroke between the first output's: for a driving slider (`driving`, an
    /// engine's piston) the stroke away from its outer dead centre (the extreme farther from
    /// the crank centre), where the expansion begins, whatever the angles; otherwise the
    /// slower stroke (the larger turn of the crank), and for strokes of equal turns (θ = 0)
    /// the one from the output's minimum along its direction.
    pub fn extremes(
        &self,
        outputs: &[Output],
        sense: Sense,
        driving: bool,
    ) -> Result<Extremes, LinkageError> {
        let coords: Vec<OutputCoord> = outputs
            .iter()
            .map(|o| OutputCoord::resolve(o, self))
            .collect::<Result<_, _>>()?;
        if coords.is_empty() {
            return Err(ModelError::NoOutput.into());
        }
        let mut poses = Vec::with_capacity(SAMPLES + 1);
        for k in 0..=SAMPLES {
            let phi = TAU * k as f64 / SAMPLES as f64;
            poses.push(self.solve_turning(phi)?);
        }
        let ranges = coords
            .iter()
            .map(|c| self.range(*c, &poses, &outputs_name(c, self), sense))
            .collect::<Result<Vec<_>, _>>()?;
        let r0 = &ranges[0];
        // Travel from the minimum to the maximum in the sense of rotation.
        let s = sense.sign();
        let t_up = (s * (r0.phi_max - r0.phi_min)).rem_euclid(TAU);
        let t_down = TAU - t_up;
        let tie = (t_up - t_down).abs() <= 1e-9;
        let outer_max = match coords[0] {
            OutputCoord::Slider(i, _) if driving => Some(self.outer_is_max(i, r0)?),
            _ => None,
        };
        let up = outer_max.map_or(t_up > t_down || tie, |max| !max);
        let (phi_start, phi_other, work) = if up {
            (r0.phi_min, r0.phi_max, t_up)
        } else {
            (r0.phi_max, r0.phi_min, t_down)
        };
        let ret = TAU - work;
        Ok(Extremes {
            phi_start,
            phi_other,
            work_travel: work,
            k: work / ret,
            theta: work - PI,
            ranges,
            from_outer: outer_max.is_some(),
        })
    }

    /// True when the slider point `i` is farther from the crank centre at its maximum along
    /// its direction than at its minimum: the maximum is its outer dead centre.
    fn outer_is_max(&self, i: usize, r: &OutputRange) -> Result<bool, LinkageError> {
        let off = |phi: f64| -> Result<f64, LinkageError> {
            let pose = self.solve_turning(phi)?;
            Ok(pose.p[i].distance(pose.p[self.centre]))
        };
        Ok(off(r.phi_max)? > off(r.phi_min)?)
    }

    /// The extremes of one output over the sampled turn `poses` (φ₁ = 0 … 2π, the last
    /// repeating the first). An extreme is where dq/dφ₁ changes sign:
    /// - between two samples: bisected on the sign (a smooth extreme, or a toggle inside);
    /// - at a toggle sample (a dyad folded or stretched, e.g. a change-point crank-rocker
    ///   whose rocker stops against the stretched coupler): the toggle itself;
    /// - across a stand-still stretch (|dq/dφ₁| within the coincidence tolerance of the
    ///   output's span, e.g. a slider-crank with l = r waiting at the crank centre): one
    ///   extreme, where the output arrives at the stretch in the sense of rotation — the first
    ///   crank angle at which it stands in its extreme position, as for any extreme. A pause
    ///   between strokes of the same sign is no extreme.
    fn range(
        &self,
        c: OutputCoord,
        poses: &[Pose],
        name: &str,
        sense: Sense,
    ) -> Result<OutputRange, LinkageError> {
        let none = || {
            LinkageError::NoExtremes {
            output: name.to_string(),
            detail: "it has no extreme positions (it turns fully or stands still), so the working stroke is not defined; give `start` as an angle".into(),
        }
        };
        let reference = c.eval(&poses[0], 0.0).0;
        let n = poses.len() - 1;
        let q: Vec<(f64, f64)> = poses[..n].iter().map(|p| c.eval(p, reference)).collect();
        let (lo, hi) = q
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v.0), hi.max(v.0))
            });
        let still = Tolerances::for_model_size(hi - lo)
            .map_err(|_| none())?
            .coincident;
        // Sign of dq/dφ₁ per sample: 0 standing still, None at a toggle.
        let sign = |k: usize| -> Option<i8> {
            if poses[k].toggle.is_some() {
                None
            } else if q[k].1.abs() <= still {
                Some(0)
            } else {
                Some(if q[k].1 > 0.0 { 1 } else { -1 })
            }
        };
        let moving: Vec<(usize, i8)> = (0..n)
            .filter_map(|k| sign(k).filter(|s| *s != 0).map(|s| (k, s)))
            .collect();
        let step = TAU / n as f64;
        // (φ₁, q, whether q stands there smoothly rather than at a toggle).
        let mut roots: Vec<(f64, f64, bool)> = Vec::new();
        for (m, &(k1, s1)) in moving.iter().enumerate() {
            let (k2, s2) = moving[(m + 1) % moving.len()];
            if s1 == s2 {
                continue;
            }
            // Samples strictly between (cyclically), k2 unwrapped past k1.
            let k2u = if k2 > k1 { k2 } else { k2 + n };
            let gap: Vec<usize> = (k1 + 1..k2u).map(|k| k % n).collect();
            let phi1 = poses[k1].phi;
            let phi = if gap.len() <= 1 && gap.iter().all(|k| sign(*k) == Some(0)) {
                Some(self.bisect(c, &poses[k1], phi1 + step * (k2u - k1) as f64, reference))
            } else {
                let order: Vec<usize> = match sense {
                    Sense::CounterClockwise => gap.clone(),
                    Sense::Clockwise => gap.iter().rev().copied().collect(),
                };
                let toggle = order.iter().position(|k| sign(*k).is_none());
                let arrive = order.iter().position(|k| sign(*k) == Some(0));
                match (toggle, arrive) {
                    (Some(t), a) if a.is_none_or(|a| t <= a) => {
                        let p = poses[order[t]].phi;
                        if let Ok(pose) = self.solve(p, None) {
                            roots.push((p, c.eval(&pose, reference).0, false));
                        }
                        None
                    }
                    (_, Some(a)) => {
                        // Bisect between the last moving sample and the first still one.
                        let first = order[a];
                        let before = if a == 0 {
                            match sense {
                                Sense::CounterClockwise => k1,
                                Sense::Clockwise => k2,
                            }
                        } else {
                            order[a - 1]
                        };
                        Some(self.arrival(c, poses[before].phi, poses[first].phi, reference, still))
                    }
                    _ => continue,
                }
            };
            if let Some(phi) = phi {
                if let Ok(p) = self.solve(phi, None) {
                    roots.push((phi, c.eval(&p, reference).0, true));
                }
            }
        }
        // An extreme reached more than once a turn (within the coincidence tolerance of the
        // span, as a stand-still is judged): its position is the first in φ₁ ∈ [0, 2π), not
        // whichever arrival the rounding made the larger.
        let first_at = |v: f64| {
            roots
                .iter()
                .copied()
                .filter(|r| (r.1 - v).abs() <= still)
                .min_by(|a, b| a.0.rem_euclid(TAU).total_cmp(&b.0.rem_euclid(TAU)))
        };
        let top = roots.iter().map(|r| r.1).fold(f64::NEG_INFINITY, f64::max);
        let bottom = roots.iter().map(|r| r.1).fold(f64::INFINITY, f64::min);
        match (first_at(bottom), first_at(top)) {
            (Some(lo), Some(hi)) if hi.1 - lo.1 > 0.0 => {
                let mut stops: Vec<(f64, f64)> = roots
                    .iter()
                    .filter(|r| r.2 && r.0 != lo.0 && r.0 != hi.0)
                    .map(|r| (r.0.rem_euclid(TAU), r.1))
                    .collect();
                stops.sort_by(|a, b| a.0.total_cmp(&b.0));
                Ok(OutputRange {
                    coord: c,
                    phi_min: lo.0.rem_euclid(TAU),
                    phi_max: hi.0.rem_euclid(TAU),
                    min: lo.1,
                    max: hi.1,
                    stops,
                })
            }
            _ => Err(none()),
        }
    }

    /// The crank angle between `moving` and `still` (adjacent samples, either order) at
    /// which the output comes to stand (|dq/dφ₁| ≤ `tol`, or a toggle), by bisection.
    fn arrival(&self, c: OutputCoord, moving: f64, still: f64, reference: f64, tol: f64) -> f64 {
        // Adjacent samples across 0 = 2π: unwrap `still` next to `moving`.
        let still = moving + wrap_pi(still - moving);
        let Ok((_, stop)) = bisect(
            moving,
            still,
            80,
            |_, _| false,
            |mid| {
                let stands = self.solve(mid, None).map_or(true, |p| {
                    p.toggle.is_some() || c.eval(&p, reference).1.abs() <= tol
                });
                Ok::<_, Infallible>(if stands {
                    Midpoint::Second
                } else {
                    Midpoint::First
                })
            },
        );
        stop
    }

    /// Bisection on dq/dφ between `a.phi` (a solved pose) and `b_phi`: the sign change is
    /// bracketed, so this converges to the last bit without any derivative of dq/dφ.
    fn bisect(&self, c: OutputCoord, a: &Pose, b_phi: f64, reference: f64) -> f64 {
        let d_lo = c.eval(a, reference).1;
        let Ok((lo, hi)) = bisect(
            a.phi,
            b_phi,
            80,
            |_, _| false,
            |mid| {
                let Ok(p) = self.solve(mid, None) else {
                    return Ok::<_, Infallible>(Midpoint::Stop);
                };
                let d = c.eval(&p, reference).1;
                Ok(if d == 0.0 {
                    Midpoint::Root
                } else if (d > 0.0) == (d_lo > 0.0) {
                    Midpoint::First
                } else {
                    Midpoint::Second
                })
            },
        );
        0.5 * (lo + hi)
    }
}

fn outputs_name(c: &OutputCoord, prog: &Program) -> String {
    match *c {
        OutputCoord::Rocker(l) => format!("rocker {l}"),
        OutputCoord::Slider(i, _) => format!("slider {}", prog.names[i]),
    }
}
