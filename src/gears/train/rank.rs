//! Why Willis' system of a train is singular: the motions its meshes (and the fixed shaft)
//! allow, as the null space of their relations, tell a locked input (every allowed motion
//! holds the input at rest: u = 0) from links left free (the input turning does not fix
//! them).

use super::{Train, TrainError};
use crate::geom::null_space;

impl Train {
    /// The diagnosis of a singular Willis system whose relations other than the input's are
    /// `relations`: [`TrainError::InputLocked`] when every motion they allow holds the input
    /// at rest, [`TrainError::Free`] (the shafts that turn with the input held) otherwise.
    pub(super) fn why_singular(&self, relations: &[Vec<f64>]) -> TrainError {
        let n = self.shafts.len();
        let allowed = null_space(relations, n);
        let size = |v: &Vec<f64>| v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        let moving = |v: &Vec<f64>| -> Vec<String> {
            let s = size(v);
            (0..n)
                .filter(|&k| v[k].abs() > 1e-9 * s)
                .map(|k| self.shafts[k].clone())
                .collect()
        };
        if allowed
            .iter()
            .all(|v| v[self.input].abs() <= 1e-9 * size(v))
        {
            let mut turning: Vec<String> = allowed.iter().flat_map(moving).collect();
            turning.sort();
            turning.dedup();
            return TrainError::InputLocked {
                input: self.shafts[self.input].clone(),
                moving: turning,
            };
        }
        // With the input held as well: what still turns.
        let mut held = relations.to_vec();
        let mut unit = vec![0.0; n];
        unit[self.input] = 1.0;
        held.push(unit);
        let mut free: Vec<String> = null_space(&held, n).iter().flat_map(moving).collect();
        free.sort();
        free.dedup();
        TrainError::Free(free)
    }
}
