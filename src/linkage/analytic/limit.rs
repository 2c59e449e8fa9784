//! The rates at a toggle, where the closed form leaves them undetermined (a change point:
//! the group's links lie on one line and the mechanism passes onto its other branch): the
//! limit of the branch the mechanism takes as the crank leaves the toggle on one side.

use super::state::Pose;
use crate::linkage::program::Program;
use std::ops::{Add, Mul, Sub};

/// The crank's offsets from the toggle the limit is extrapolated from, radians: δ, δ/2, δ/4.
/// Each branch is smooth through the toggle, so a rate is a power series in the offset; the
/// extrapolation removes its first two terms and leaves O(δ³) (about 1e-6 of the rate on the
/// six-bar at δ = 0,01), while the solves stay well conditioned this far from the toggle
/// (their rounding grows as the offset shrinks: 1e-4 of the acceleration at δ = 1e-5).
const OFFSET: f64 = 1e-2;

impl Program {
    /// The pose at `phi` with the rates (dp, ddp, the links' angle rates) of the branch the
    /// mechanism takes as φ₁ leaves `phi` on the side of `side` (+1: increasing, −1:
    /// decreasing), each solved with the scene's assembly. `None` when a solve beside the
    /// toggle fails or is itself a toggle.
    pub fn limit_beyond(&self, phi: f64, side: f64) -> Option<Pose> {
        let at = |k: f64| {
            self.solve(phi + side * OFFSET / k, None)
                .ok()
                .filter(|p| p.toggle.is_none())
        };
        let (p1, p2, p4) = (at(1.0)?, at(2.0)?, at(4.0)?);
        let mut pose = self.solve(phi, None).ok()?;
        pose.dp = mix(&p1.dp, &p2.dp, &p4.dp);
        pose.ddp = mix(&p1.ddp, &p2.ddp, &p4.ddp);
        pose.dangle = mix(&p1.dangle, &p2.dangle, &p4.dangle);
        pose.ddangle = mix(&p1.ddangle, &p2.ddangle, &p4.ddangle);
        pose.toggle = None;
        Some(pose)
    }
}

/// Richardson's second extrapolation to the offset 0 of the values at δ, δ/2, δ/4:
/// (8 f(δ/4) − 6 f(δ/2) + f(δ)) / 3, element by element.
fn mix<T>(d1: &[T], d2: &[T], d4: &[T]) -> Vec<T>
where
    T: Copy + Mul<f64, Output = T> + Add<Output = T> + Sub<Output = T>,
{
    (d1.iter().zip(d2).zip(d4))
        .map(|((&x1, &x2), &x4)| (x4 * 8.0 - x2 * 6.0 + x1) * (1.0 / 3.0))
        .collect()
}
