//! A differential (W = 2, seed 002 L419–L423) by Willis's formula, the textbook's route: the
//! two central shafts a and b joined through the satellites, u_ab^(H) = (ω_a − ω_H)/(ω_b − ω_H)
//! the product of the mesh ratios with the carrier stopped; of ω_a, ω_b and ω_H the two inputs
//! are given and the formula gives the third, the output.

use super::train::Train;

/// A differential's formula ([`Train::differential`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Differential {
    /// The central shaft a (index into [`Train::shafts`]).
    pub a: usize,
    /// The central shaft b.
    pub b: usize,
    /// The meshes (x, y) from a through the satellites to b, in order (indices into
    /// [`Train::wheels`]).
    pub meshes: Vec<(usize, usize)>,
    /// u_ab^(H), the product of their ratios with the carrier stopped.
    pub u: f64,
    /// ω_a, ω_b and ω_H per unit ω of the first input: the two inputs as given, the output by
    /// the formula.
    pub omega: [f64; 3],
}

impl Train {
    /// Willis's formula of a differential whose inputs and output are its carrier and two
    /// central shafts joined through the satellites: a and b the central ones among the
    /// input, the second input and the output, in that order. `None` for a train of one
    /// input, one not of that shape, or one whose formula does not fix the output
    /// (u_ab^(H) = 1 or 0).
    pub fn differential(&self) -> Option<Differential> {
        let (second, w2) = self.second?;
        let h = self.carrier?;
        let ends = [self.input, second, self.output];
        if !ends.contains(&h) || ends[0] == ends[2] || ends[1] == ends[2] {
            return None;
        }
        let central: Vec<usize> = ends.into_iter().filter(|&k| k != h).collect();
        let [a, b] = central[..] else {
            return None;
        };
        let meshes = self.stopped_path(a, b)?;
        let u: f64 = meshes.iter().map(|&(x, y)| self.mesh_ratio(x, y)).product();
        if !u.is_finite() || u.abs() < 1e-300 || (u - 1.0).abs() < 1e-12 {
            return None;
        }
        // The inputs' ω as given, by shaft.
        let given = |k: usize| {
            if k == self.input {
                Some(1.0)
            } else {
                (k == second).then_some(w2)
            }
        };
        let omega = match (given(a), given(b), given(h)) {
            (Some(wa), Some(wb), None) => [wa, wb, (wa - u * wb) / (1.0 - u)],
            (None, Some(wb), Some(wh)) => [wh + u * (wb - wh), wb, wh],
            (Some(wa), None, Some(wh)) => [wa, wh + (wa - wh) / u, wh],
            _ => return None,
        };
        omega.iter().all(|w| w.is_finite()).then_some(Differential {
            a,
            b,
            meshes,
            u,
            omega,
        })
    }

    /// u = ω_in/ω_out of a differential by Willis's formula ([`Train::differential`]);
    /// `None` when the output stands still or the train is not such a differential.
    pub fn by_differential(&self) -> Option<f64> {
        let d = self.differential()?;
        let out = [d.a, d.b, self.carrier?]
            .iter()
            .position(|&k| k == self.output)?;
        let w = d.omega[out];
        (w.abs() > 1e-300).then(|| 1.0 / w)
    }
}
