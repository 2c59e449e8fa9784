//! Why Willis' system of a train is singular: the motions its meshes (and the fixed shaft)
//! allow, as the null space of their relations, tell a locked input (every allowed motion
//! holds the input at rest: u = 0) from links left free (the input turning does not fix
//! them).

use super::{Train, TrainError};

/// A basis of the null space of the `rows` (each `n` long), by reduced row echelon form with
/// partial pivoting; a pivot below `1e-12` of the largest entry counts as zero.
pub(super) fn null_space(rows: &[Vec<f64>], n: usize) -> Vec<Vec<f64>> {
    let mut a: Vec<Vec<f64>> = rows.to_vec();
    let big = a
        .iter()
        .flat_map(|r| r.iter())
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    let tiny = 1e-12 * big.max(f64::MIN_POSITIVE);
    let mut pivots: Vec<usize> = Vec::new();
    let mut r = 0;
    for c in 0..n {
        if r == a.len() {
            break;
        }
        let Some(p) = (r..a.len()).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs())) else {
            break;
        };
        if a[p][c].abs() <= tiny {
            continue;
        }
        a.swap(r, p);
        let d = a[r][c];
        for v in &mut a[r] {
            *v /= d;
        }
        let pivot = a[r].clone();
        for (i, row) in a.iter_mut().enumerate() {
            if i != r && row[c] != 0.0 {
                let f = row[c];
                for (x, p) in row.iter_mut().zip(&pivot) {
                    *x -= f * p;
                }
            }
        }
        pivots.push(c);
        r += 1;
    }
    (0..n)
        .filter(|c| !pivots.contains(c))
        .map(|free| {
            let mut v = vec![0.0; n];
            v[free] = 1.0;
            for (i, &c) in pivots.iter().enumerate() {
                v[c] = -a[i][free];
            }
            v
        })
        .collect()
}

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
