//! The analytic twin: closed-form positions of every dyad kind with their first and second
//! derivatives with respect to the crank angle (velocity and acceleration analogues dX/dφ₁,
//! d²X/dφ₁²), by differentiating the vector loops — no numerical differentiation. With a
//! constant ω₁ the velocities are ω₁·dX/dφ₁ and the accelerations ω₁²·d²X/dφ₁².
//! Shares nothing with the construction but the program's index tables. Here: the run over
//! the program, the solve's state and the jets; each group kind's closed form is its own
//! (`GroupKind::solve`, in its file of `kinds/`).

use super::program::{Op, Program};
use crate::geom::{unit_at, DVec2};
use jet::{carried, carried_along, AngleJet};

pub(in crate::linkage) mod jet;
pub(in crate::linkage) mod state;

pub(in crate::linkage) use state::State;
pub use state::{NearPivot, Pose, Unassembled, NEAR_PIVOT_RATIO};

/// Steps of a [`Program::sweep`] between crank directions taken from sin and cos (between,
/// each is the one before turned through the step: rounding grows by about an ulp a step).
pub const SWEEP_ANCHOR: usize = 16;

impl Program {
    /// Solve the mechanism at crank angle `phi` (radians, counter-clockwise from +x).
    /// `prev`: the previous position; when given, each two-solution dyad takes the solution
    /// nearest to it (continuity), otherwise the scene's branch.
    pub fn solve(&self, phi: f64, prev: Option<&Pose>) -> Result<Pose, Unassembled> {
        let mut pose = match prev {
            Some(p) => p.clone(),
            None => Pose::default(),
        };
        self.solve_into(phi, prev.is_some(), &mut pose)?;
        Ok(pose)
    }

    /// Solve into `pose`, reusing its buffers (no allocation once sized). With `continuity`,
    /// `pose` must hold the previous position: each two-solution dyad takes the solution
    /// nearest to its previous joint.
    pub fn solve_into(
        &self,
        phi: f64,
        continuity: bool,
        pose: &mut Pose,
    ) -> Result<(), Unassembled> {
        let continuity = self.prepare(continuity, pose);
        self.solve_at(phi, unit_at(phi), continuity, pose)
    }

    /// Solve at the crank angles φ₀ + k·Δφ, k = 0 … n − 1, handing each position to `each`
    /// (k, pose) as it is solved; after the first, each position takes the solution nearest
    /// to the one before (continuity). The trigonometry is shared: the crank's direction
    /// advances by the rotation through Δφ and is taken afresh from sin and cos every
    /// [`SWEEP_ANCHOR`] steps, so that it stays within about that many ulps of
    /// [`Program::solve_into`]'s.
    /// Stops at the first position that cannot be assembled.
    pub fn sweep(
        &self,
        (phi0, step): (f64, f64),
        n: usize,
        pose: &mut Pose,
        mut each: impl FnMut(usize, &Pose),
    ) -> Result<(), Unassembled> {
        let turn = DVec2::from_angle(step);
        let mut e = DVec2::X;
        // The frame's points are set once: `each` sees the pose but cannot change it.
        self.prepare(false, pose);
        for k in 0..n {
            let phi = phi0 + k as f64 * step;
            e = if k % SWEEP_ANCHOR == 0 {
                unit_at(phi)
            } else {
                turn.rotate(e)
            };
            self.solve_at(phi, e, k > 0, pose)?;
            each(k, pose);
        }
        Ok(())
    }

    /// Size `pose`'s buffers for this program (once: a pose reused for the same program keeps
    /// them) and set the frame's points; whether continuity can be kept (the pose held a
    /// position of this program, and with it the frame's points, which no solve changes).
    #[inline(always)]
    fn prepare(&self, continuity: bool, pose: &mut Pose) -> bool {
        let n = self.names.len();
        let sized = pose.p.len() == n && pose.dir.len() == self.link_count;
        if !sized {
            for v in [&mut pose.p, &mut pose.dp, &mut pose.ddp] {
                v.resize(n, DVec2::ZERO);
            }
            for v in [&mut pose.dangle, &mut pose.ddangle] {
                v.resize(self.link_count, 0.0);
            }
            pose.dir.resize(self.link_count, DVec2::X);
            pose.origin.resize(self.link_count, 0);
        }
        if continuity && sized {
            return true;
        }
        for (k, f) in self.fixed.iter().enumerate() {
            pose.p[k] = *f;
            pose.dp[k] = DVec2::ZERO;
            pose.ddp[k] = DVec2::ZERO;
        }
        false
    }

    /// Solve at crank angle `phi` whose unit vector is `e` (`pose` prepared).
    fn solve_at(
        &self,
        phi: f64,
        e: DVec2,
        continuity: bool,
        pose: &mut Pose,
    ) -> Result<(), Unassembled> {
        pose.crossing_sin.clear();
        pose.toggle = None;
        pose.near_pivot.clear();
        pose.phi = phi;
        let mut st = State {
            pose,
            fixed_dirs: &self.fixed_dirs,
            continuity,
            group: 0,
        };
        let crank = AngleJet { d: 1.0, dd: 0.0, e };
        let pin = carried_along(st.jet(self.centre), crank, self.crank_length);
        st.set(self.pin, pin);
        st.set_link(self.crank_link as usize, crank, self.centre);
        for op in &self.ops {
            match *op {
                Op::Point {
                    idx,
                    link,
                    along,
                    across,
                } => {
                    let l = link as usize;
                    let o = st.jet(st.pose.origin[l]);
                    let j = carried(o, st.link(l), DVec2::new(along, across));
                    st.set(idx, j);
                }
                // One Assur group: its joint (RPR: its slide line) with the rates, by its
                // kind's own solve (borrowed from the program, not copied).
                Op::Dyad {
                    group,
                    links,
                    ref dyad,
                } => {
                    st.group = group;
                    dyad.solve(self, &mut st, links.map(|l| l as usize))?;
                }
            }
        }
        Ok(())
    }
}

mod limit;
#[cfg(test)]
mod tests;
