//! Extreme (dead) positions of the output, found exactly as the zeros of its velocity
//! analogue, and the working stroke, the time ratio K and the angle θ.

use super::analytic::Pose;
use super::model::{Output, Sense};
use super::program::Program;
use super::LinkageError;
use crate::geom::{wrap_pi, DVec2};
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
                    Err(LinkageError::Model(format!(
                        "output rocker {link}: no such link"
                    )))
                }
            }
            Output::Slider { point, dir } => prog
                .index(point)
                .map(|i| OutputCoord::Slider(i, DVec2::from_angle(*dir)))
                .ok_or_else(|| {
                    LinkageError::Model(format!("output slider `{point}`: no such point"))
                }),
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
}

/// Extreme positions and the working stroke, from the first output.
#[derive(Debug, Clone, PartialEq)]
pub struct Extremes {
    /// Crank angle at the start of the working (slower) stroke, radians in [0, 2π).
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

    /// Find the extreme positions of the outputs over a full turn of the crank.
    pub fn extremes(&self, outputs: &[Output], sense: Sense) -> Result<Extremes, LinkageError> {
        let coords: Vec<OutputCoord> = outputs
            .iter()
            .map(|o| OutputCoord::resolve(o, self))
            .collect::<Result<_, _>>()?;
        if coords.is_empty() {
            return Err(LinkageError::Model("no output is given".into()));
        }
        let mut poses = Vec::with_capacity(SAMPLES + 1);
        for k in 0..=SAMPLES {
            let phi = TAU * k as f64 / SAMPLES as f64;
            poses.push(self.solve_turning(phi)?);
        }
        let ranges = coords
            .iter()
            .map(|c| self.range(*c, &poses, &outputs_name(c, self)))
            .collect::<Result<Vec<_>, _>>()?;
        let r0 = &ranges[0];
        // Travel from the minimum to the maximum in the sense of rotation.
        let s = sense.sign();
        let t_up = (s * (r0.phi_max - r0.phi_min)).rem_euclid(TAU);
        let t_down = TAU - t_up;
        let tie = (t_up - t_down).abs() <= 1e-9;
        let (phi_start, phi_other, work) = if t_up > t_down || tie {
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
        })
    }

    fn range(
        &self,
        c: OutputCoord,
        poses: &[Pose],
        name: &str,
    ) -> Result<OutputRange, LinkageError> {
        let reference = c.eval(&poses[0], 0.0).0;
        let mut roots: Vec<(f64, f64)> = Vec::new();
        for w in poses.windows(2) {
            if w[0].toggle.is_some() || w[1].toggle.is_some() {
                continue;
            }
            let (_, d0) = c.eval(&w[0], reference);
            let (_, d1) = c.eval(&w[1], reference);
            if d0 == 0.0 {
                roots.push((w[0].phi, c.eval(&w[0], reference).0));
            } else if d0 * d1 < 0.0 {
                let phi = self.bisect(c, &w[0], w[1].phi, reference);
                let pose = self.solve(phi, None).ok();
                if let Some(p) = pose {
                    roots.push((phi, c.eval(&p, reference).0));
                }
            }
        }
        let max = roots.iter().copied().max_by(|a, b| a.1.total_cmp(&b.1));
        let min = roots.iter().copied().min_by(|a, b| a.1.total_cmp(&b.1));
        match (min, max) {
            (Some(lo), Some(hi)) if hi.1 - lo.1 > 0.0 => Ok(OutputRange { coord: c, phi_min: lo.0.rem_euclid(TAU), phi_max: hi.0.rem_euclid(TAU), min: lo.1, max: hi.1 }),
            _ => Err(LinkageError::NoExtremes { output: name.to_string(), detail: "it has no extreme positions (it turns fully or stands still), so the working stroke is not defined; give `start` as an angle".into() }),
        }
    }

    /// Bisection on dq/dφ between `a.phi` (a solved pose) and `b_phi`: the sign change is
    /// bracketed, so this converges to the last bit without any derivative of dq/dφ.
    fn bisect(&self, c: OutputCoord, a: &Pose, b_phi: f64, reference: f64) -> f64 {
        let (mut lo, mut hi) = (a.phi, b_phi);
        let d_lo = c.eval(a, reference).1;
        for _ in 0..80 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            let Ok(p) = self.solve(mid, None) else {
                break;
            };
            let d = c.eval(&p, reference).1;
            if d == 0.0 {
                return mid;
            }
            if (d > 0.0) == (d_lo > 0.0) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }
}

fn outputs_name(c: &OutputCoord, prog: &Program) -> String {
    match *c {
        OutputCoord::Rocker(l) => format!("rocker {l}"),
        OutputCoord::Slider(i, _) => format!("slider {}", prog.names[i]),
    }
}
