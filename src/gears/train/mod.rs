//! Gear trains, ordinary and planetary (seed 002 PZ2, seed 000's reducer): shafts carrying
//! wheels (external or internal), one carrier H whose satellites turn on it, one fixed shaft.
//!
//! * analytic twin — Willis: every mesh, seen from the frame of its axes (the carrier's
//!   frame when a satellite takes part, the ground's otherwise), gives
//!   z_i(ω_A − ω_ref) ± z_j(ω_B − ω_ref) = 0 (+ external, − internal); with ω_in = 1 and
//!   ω_fixed = 0 the linear system gives every shaft's ω ([`Train::willis`]);
//! * formula — the textbook's stage by stage product with u_aH^(f) = 1 − u_af^(H) for the
//!   planetary stage ([`Train::by_stages`]);
//! * construction — the velocity triangles (Smirnov / Kutzbach): the axes and the mesh poles
//!   at their heights at μ_l, the distribution line of each link through two known points
//!   (its axis, a pole shared with a known link), and the plan of angular velocities: rays
//!   from a pole at H parallel to the lines, their intercepts ∝ ω ([`triangles`](super::triangles::triangles)).

use thiserror::Error;

pub(super) mod layout;
mod notes;
mod rank;
pub(super) mod study;
#[cfg(test)]
pub(super) mod tests;

pub use layout::ClosedMesh;
pub use notes::SeedStage;
pub use study::{train_study, PlanetarySpec, TrainSeed, TrainStudy};

/// A wheel of a train.
#[derive(Debug, Clone, PartialEq)]
pub struct Wheel {
    /// Its name (`1`, `2'`).
    pub name: String,
    /// Teeth: whole in a scene's train; a fraction in the design stage the required ratio
    /// asks for before the tooth choice ([`Train::with_ratio`]).
    pub z: f64,
    /// The shaft it is fixed to (index into [`Train::shafts`]).
    pub shaft: usize,
    /// An internal (ring) gear.
    pub internal: bool,
    /// The module of its meshes when not the train's, m: a stage of another module (given,
    /// or the one [`Train::closing`] takes for a stage whose tooth sums do not close with one
    /// module, PZ2 examples 1 and 2).
    pub module: Option<f64>,
}

/// A mesh of two wheels (indices into [`Train::wheels`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mesh(pub usize, pub usize);

/// One stage of the textbook's route from the input to the output ([`Train::stages`]).
#[derive(Debug, Clone, PartialEq)]
pub enum Stage {
    /// Wheel `driving` turns wheel `driven` on fixed axes (indices into [`Train::wheels`]).
    Mesh {
        /// The driving wheel.
        driving: usize,
        /// The driven wheel.
        driven: usize,
    },
    /// The planetary stage from a central wheel to the carrier, the fixed wheel still: the
    /// meshes (x, y) from the central wheel through the satellites to the fixed wheel with
    /// the carrier stopped, u_aH^(f) = 1 − u_af^(H), u_af^(H) = Π u_xy.
    Planetary {
        /// The meshes in order, the first x the central wheel, the last y the fixed one.
        meshes: Vec<(usize, usize)>,
    },
}

/// A gear train.
#[derive(Debug, Clone, PartialEq)]
pub struct Train {
    /// The shafts (links) by name.
    pub shafts: Vec<String>,
    /// The wheels.
    pub wheels: Vec<Wheel>,
    /// The meshes.
    pub meshes: Vec<Mesh>,
    /// The input shaft.
    pub input: usize,
    /// The output shaft.
    pub output: usize,
    /// The fixed shaft (the support wheel's), if any.
    pub fixed: Option<usize>,
    /// The carrier H, if any.
    pub carrier: Option<usize>,
    /// The satellites' shafts (turning on the carrier).
    pub satellites: Vec<usize>,
    /// The module of the drawing's radii r = m z/2, m.
    pub module: f64,
    /// A differential's second input (W = 2): its shaft and its ω per unit ω_in.
    pub second: Option<(usize, f64)>,
}

/// The train's mobility by Chebyshev's formula (seed 002 (2.1)), W = 3n − 2p₅ − p₄: every
/// moving shaft (a wheel with its shaft, wheels on one shaft one link) a link turning in one
/// lower pair, every mesh a higher pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TrainMobility {
    /// n, the moving links.
    pub n: usize,
    /// p₅, the lower (turning) pairs.
    pub p5: usize,
    /// p₄, the higher pairs (meshes).
    pub p4: usize,
}

impl TrainMobility {
    /// W = 3n − 2p₅ − p₄.
    pub fn w(&self) -> i64 {
        let [n, p5, p4] = [self.n, self.p5, self.p4].map(|x| i64::try_from(x).unwrap_or(i64::MAX));
        3 * n - 2 * p5 - p4
    }
}

/// Why a train cannot be solved or drawn.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TrainError {
    /// The train's mobility is not the number of its given inputs.
    #[error("train: W = 3n − 2p₅ − p₄ = 3·{n} − 2·{p5} − {p4} = {w}, but {inputs} input(s) given: a train of mobility W needs W inputs (a differential, W = 2, its second input and speed)", n = .mobility.n, p5 = .mobility.p5, p4 = .mobility.p4, w = .mobility.w())]
    Mobility {
        /// n, p₅, p₄.
        mobility: TrainMobility,
        /// The inputs given (1, or 2 with a second input).
        inputs: usize,
    },
    /// Every motion the meshes and the fixed shaft allow holds the input at rest.
    #[error("train: the meshes hold the input shaft {input} at rest: it cannot turn, the ratio is 0{}", still(.moving))]
    InputLocked {
        /// The input shaft.
        input: String,
        /// The shafts that can still turn, with the input at rest.
        moving: Vec<String>,
    },
    /// The input turning does not fix every shaft's speed.
    #[error("train: with the input turning, shaft(s) {} still turn freely: the meshes do not fix their speeds", .0.join(", "))]
    Free(Vec<String>),
    /// The output does not turn.
    #[error("train: the output shaft does not turn")]
    OutputAtRest,
    /// A satellite mesh without a carrier.
    #[error("train: wheel {0} is on a satellite but the train has no carrier")]
    NoCarrier(String),
    /// The drafting resolution reads an intercept of the plan of angular velocities as 0.
    #[error("train: --drafting {resolution_mm} mm reads the intercept of shaft {shaft} on the plan of angular velocities ({drawn_mm:.3} mm drawn) as 0, so the ratio cannot be read off the triangles; a resolution below {limit:.3} mm reads it", limit = 2.0 * .drawn_mm, resolution_mm = crate::scale::format_plain(*resolution_mm))]
    Unreadable {
        /// The shaft (the input or the output).
        shaft: String,
        /// Its intercept as drawn, mm.
        drawn_mm: f64,
        /// The resolution, mm.
        resolution_mm: f64,
    },
    /// The scheme cannot be laid out.
    #[error("train: the scheme cannot be laid out: {0}")]
    Layout(String),
}

/// "; only … can turn, with the input still" for the shafts that can.
fn still(moving: &[String]) -> String {
    if moving.is_empty() {
        String::new()
    } else {
        format!(
            "; only {} can turn, with the input still",
            moving.join(", ")
        )
    }
}

impl Train {
    /// r = m z/2 of wheel `w` at its module, m.
    pub fn radius(&self, w: usize) -> f64 {
        self.wheel_module(w) * self.wheels[w].z / 2.0
    }

    /// The mobility by Chebyshev's formula: the shafts but the fixed one move, each in one
    /// turning pair (on the frame, or a satellite on the carrier), each mesh a higher pair.
    pub fn mobility(&self) -> TrainMobility {
        let n = self.shafts.len() - usize::from(self.fixed.is_some());
        TrainMobility {
            n,
            p5: n,
            p4: self.meshes.len(),
        }
    }

    /// The number of inputs given: 1, or 2 for a differential's second.
    pub fn inputs(&self) -> usize {
        1 + usize::from(self.second.is_some())
    }

    pub(super) fn is_satellite(&self, shaft: usize) -> bool {
        self.satellites.contains(&shaft)
    }

    /// The analytic twin: every shaft's ω for ω_in = 1 (Willis' relations solved together).
    ///
    /// # Errors
    /// [`TrainError::Mobility`], [`TrainError::InputLocked`], [`TrainError::Free`],
    /// [`TrainError::NoCarrier`].
    pub fn willis(&self) -> Result<Vec<f64>, TrainError> {
        let n = self.shafts.len();
        let mut rows: Vec<(Vec<f64>, f64)> = Vec::new();
        let unit = |k: usize, v: f64| {
            let mut r = vec![0.0; n];
            r[k] = 1.0;
            (r, v)
        };
        rows.push(unit(self.input, 1.0));
        if let Some((k, w)) = self.second {
            rows.push(unit(k, w));
        }
        if let Some(f) = self.fixed {
            rows.push(unit(f, 0.0));
        }
        for m in &self.meshes {
            let (a, b) = (&self.wheels[m.0], &self.wheels[m.1]);
            let sign = if a.internal || b.internal { -1.0 } else { 1.0 };
            let mut r = vec![0.0; n];
            r[a.shaft] += a.z;
            r[b.shaft] += sign * b.z;
            if self.is_satellite(a.shaft) || self.is_satellite(b.shaft) {
                let h = self
                    .carrier
                    .ok_or_else(|| TrainError::NoCarrier(a.name.clone()))?;
                r[h] -= a.z + sign * b.z;
            }
            rows.push((r, 0.0));
        }
        let mobility = self.mobility();
        // rows: the inputs, the fixed shaft and the meshes, one per shaft when W is the inputs.
        if mobility.w() != self.inputs() as i64 {
            return Err(TrainError::Mobility {
                mobility,
                inputs: self.inputs(),
            });
        }
        let relations: Vec<Vec<f64>> = rows[1..].iter().map(|r| r.0.clone()).collect();
        solve(rows).ok_or_else(|| self.why_singular(&relations))
    }

    /// u = ω_in/ω_out by Willis.
    ///
    /// # Errors
    /// As [`Train::willis`]; [`TrainError::OutputAtRest`].
    pub fn ratio(&self) -> Result<f64, TrainError> {
        let w = self.willis()?;
        let out = w[self.output];
        if out.abs() < 1e-300 {
            return Err(TrainError::OutputAtRest);
        }
        Ok(w[self.input] / out)
    }

    /// The textbook's route, stage by stage from the input: a fixed-axis mesh multiplies by
    /// −(±)z_driving/z_driven; at a central wheel a of the planetary stage the carrier turns
    /// at ω_a/u_aH with u_aH^(f) = 1 − u_af^(H), u_af^(H) the product of the mesh ratios from
    /// a through the satellites to the fixed wheel f with the carrier stopped. `None` when
    /// the train is not a chain of such stages.
    pub fn by_stages(&self) -> Option<f64> {
        let stages = self.stages()?;
        let u: f64 = stages.iter().map(|s| self.stage_ratio(s)).product();
        (u.is_finite() && u.abs() > 1e-300).then_some(u)
    }

    /// The stages of [`Train::by_stages`] from the input to the output, in that order.
    /// `None` when the train is not a chain of such stages.
    pub fn stages(&self) -> Option<Vec<Stage>> {
        let n = self.shafts.len();
        // The shafts reached, each with the shaft and the stage it was reached from.
        let mut known = vec![false; n];
        let mut from: Vec<Option<(usize, Stage)>> = vec![None; n];
        known[self.input] = true;
        if let Some(f) = self.fixed {
            known[f] = true;
        }
        for _ in 0..n + 2 {
            for m in &self.meshes {
                for (a, b) in [(m.0, m.1), (m.1, m.0)] {
                    let (sa, sb) = (self.wheels[a].shaft, self.wheels[b].shaft);
                    if self.is_satellite(sa) || self.is_satellite(sb) || !known[sa] || known[sb] {
                        continue;
                    }
                    known[sb] = true;
                    from[sb] = Some((
                        sa,
                        Stage::Mesh {
                            driving: a,
                            driven: b,
                        },
                    ));
                }
            }
            // The planetary stage: from a reached central shaft a to the fixed f.
            if let (Some(h), Some(f)) = (self.carrier, self.fixed) {
                if !known[h] {
                    let stage = (0..n)
                        .filter(|&a| a != f && a != h && !self.is_satellite(a) && known[a])
                        .find_map(|a| {
                            let meshes = self.stopped_path(a, f)?;
                            let stage = Stage::Planetary { meshes };
                            (self.stage_ratio(&stage).abs() > 1e-300).then_some((a, stage))
                        });
                    if let Some(reached) = stage {
                        known[h] = true;
                        from[h] = Some(reached);
                    }
                }
            }
        }
        let mut path = Vec::new();
        let mut at = self.output;
        while at != self.input {
            let (back, stage) = from[at].clone()?;
            path.push(stage);
            at = back;
            if path.len() > n {
                return None;
            }
        }
        path.reverse();
        Some(path)
    }

    /// u = ω_x/ω_y of wheel x driving wheel y: −z_y/z_x external, +z_y/z_x internal.
    pub fn mesh_ratio(&self, x: usize, y: usize) -> f64 {
        let (wx, wy) = (&self.wheels[x], &self.wheels[y]);
        let sign = if wx.internal || wy.internal {
            1.0
        } else {
            -1.0
        };
        sign * wy.z / wx.z
    }

    /// A stage's ratio ω_from/ω_to: the mesh's, or u_aH^(f) = 1 − u_af^(H).
    pub fn stage_ratio(&self, stage: &Stage) -> f64 {
        match stage {
            Stage::Mesh { driving, driven } => self.mesh_ratio(*driving, *driven),
            Stage::Planetary { meshes } => {
                1.0 - meshes
                    .iter()
                    .map(|&(x, y)| self.mesh_ratio(x, y))
                    .product::<f64>()
            }
        }
    }

    /// With the carrier stopped, the meshes (x, y) from shaft `a` through the satellites to
    /// shaft `f`, in order; `None` when a does not reach f through satellites.
    pub(super) fn stopped_path(&self, a: usize, f: usize) -> Option<Vec<(usize, usize)>> {
        let n = self.shafts.len();
        let mut from: Vec<Option<(usize, usize)>> = vec![None; n];
        let mut reached = vec![false; n];
        reached[a] = true;
        for _ in 0..n + 2 {
            for m in &self.meshes {
                for (x, y) in [(m.0, m.1), (m.1, m.0)] {
                    let (sx, sy) = (self.wheels[x].shaft, self.wheels[y].shaft);
                    let through = self.is_satellite(sx) || self.is_satellite(sy);
                    if through && reached[sx] && !reached[sy] {
                        reached[sy] = true;
                        from[sy] = Some((x, y));
                    }
                }
            }
        }
        let mut path = Vec::new();
        let mut at = f;
        while at != a {
            let (x, y) = from[at]?;
            path.push((x, y));
            at = self.wheels[x].shaft;
            if path.len() > n {
                return None;
            }
        }
        path.reverse();
        Some(path)
    }

    /// The first mesh between wheels on fixed axes (no satellite's), if any.
    pub fn fixed_axis_mesh(&self) -> Option<usize> {
        self.meshes.iter().position(|m| {
            !self.is_satellite(self.wheels[m.0].shaft) && !self.is_satellite(self.wheels[m.1].shaft)
        })
    }

    /// The same train with mesh `mesh`'s second wheel sized so that |u_in,out| = `ratio`:
    /// the stage the textbook solves for from the required ratio before it chooses whole
    /// teeth (seed 000: i₁₂ = U₁₋₈/(i₃H·i₇₈)).
    ///
    /// # Errors
    /// As [`Train::ratio`].
    pub fn with_ratio(&self, mesh: usize, ratio: f64) -> Result<Train, TrainError> {
        let mut t = self.clone();
        let w = self.meshes[mesh].1;
        t.wheels[w].z *= ratio / self.ratio()?.abs();
        Ok(t)
    }

    /// The assembly condition of `k` satellites spaced equally, between the central wheel a
    /// that meshes the satellites and the fixed central wheel b.
    ///
    /// The textbook's: turning the carrier by 2π(1 + kp)/k turns a by z_a·u_aH^(b)·(1 + kp)/k
    /// pitches, which must be whole for the next satellite to enter where the first did.
    /// That is sufficient, not necessary, for a block of two wheels g (meshing a) and f
    /// (meshing b): a block turned by 2πn/z_g still meshes a and shifts f by n·z_f/z_g of its
    /// pitch, so identical blocks enter at every 2πj/k exactly when
    /// z_a·u_aH^(b)·(z_f/gcd(z_g, z_f))/k is whole (for one wheel, g = f, both agree).
    /// `None` for fewer than two satellites, when the train has no such pair of central
    /// wheels or when its teeth are not whole.
    pub fn assembly(&self, k: u32) -> Option<Assembly> {
        if k < 2 {
            return None;
        }
        let (h, b) = (self.carrier?, self.fixed?);
        let whole = |z: f64| (z.fract() == 0.0 && z > 0.0 && z < 1e6).then_some(z as i128);
        let central = self.meshes.iter().find_map(|m| {
            [(m.0, m.1), (m.1, m.0)].into_iter().find_map(|(x, y)| {
                let sx = self.wheels[x].shaft;
                (self.is_satellite(self.wheels[y].shaft)
                    && !self.is_satellite(sx)
                    && sx != b
                    && sx != h)
                    .then_some(x)
            })
        })?;
        let a = self.wheels[central].shaft;
        // (ω − ω_H)/(ω_a − ω_H) as a fraction n/d.
        let (n, d) =
            self.stopped_path(a, b)?
                .into_iter()
                .try_fold((1_i128, 1_i128), |(n, d), (x, y)| {
                    let (wx, wy) = (&self.wheels[x], &self.wheels[y]);
                    let n = n.checked_mul(whole(wx.z)?)?;
                    let d = d.checked_mul(whole(wy.z)?)?;
                    Some(reduced(if wx.internal || wy.internal { n } else { -n }, d))
                })?;
        // u_ab^(H) = d/n, u_aH^(b) = 1 − d/n = (n − d)/n.
        let za = whole(self.wheels[central].z)?;
        let value = reduced(za.checked_mul(n - d)?, n.checked_mul(i128::from(k))?);
        // 1 + kp ≡ 0 (mod D): solvable when gcd(k, D) = 1, p = −k⁻¹ mod D.
        let den = value.1;
        let p = (gcd(i128::from(k), den) == 1).then(|| {
            let inv = inverse_mod(i128::from(k).rem_euclid(den), den);
            (den - inv).rem_euclid(den)
        });
        // The block: g meshes a; f, on g's shaft, meshes a wheel of b.
        let g = self.meshes.iter().find_map(|m| {
            (m.0 == central)
                .then_some(m.1)
                .or((m.1 == central).then_some(m.0))
        })?;
        let sat = self.wheels[g].shaft;
        let f = self.meshes.iter().find_map(|m| {
            [(m.0, m.1), (m.1, m.0)].into_iter().find_map(|(x, y)| {
                (self.wheels[x].shaft == sat && self.wheels[y].shaft == b).then_some(x)
            })
        });
        let block = match f {
            Some(f) => {
                let (zg, zf) = (whole(self.wheels[g].z)?, whole(self.wheels[f].z)?);
                Some(reduced(value.0.checked_mul(zf / gcd(zg, zf))?, value.1))
            }
            None => None,
        };
        Some(Assembly {
            central,
            k,
            value,
            p,
            block,
        })
    }

    /// The neighbour condition of `k` satellites: for every satellite wheel, the chord
    /// 2·a·sin(π/k) between neighbouring axes against its tip diameter d_a = m(z + 2), m.
    /// `None` for fewer than two satellites, without a carrier or a layout.
    pub fn neighbour(&self, k: u32) -> Option<Vec<(usize, f64, f64)>> {
        let h = self.carrier.filter(|_| k >= 2)?;
        let (ys, _) = self.layout().ok()?;
        let mut out = Vec::new();
        for &s in &self.satellites {
            let chord = 2.0 * (ys[s] - ys[h]).abs() * (std::f64::consts::PI / f64::from(k)).sin();
            for (w, _) in self.wheels.iter().enumerate().filter(|(_, w)| w.shaft == s) {
                out.push((w, chord, 2.0 * self.radius(w) + 2.0 * self.wheel_module(w)));
            }
        }
        Some(out)
    }

    /// Whether `k` satellites fit side by side and can be assembled spaced equally.
    pub fn admits(&self, k: u32) -> bool {
        self.neighbour(k)
            .is_some_and(|v| v.iter().all(|(_, chord, da)| chord > da))
            && self.assembly(k).is_some_and(|a| a.fits())
    }

    /// The inversion table (seed 002 Table 2.1): every shaft's ω before and after the
    /// carrier is stopped (ω − ω_H), for ω_in = 1.
    ///
    /// # Errors
    /// As [`Train::willis`].
    pub fn inversion(&self) -> Result<Vec<(String, f64, f64)>, TrainError> {
        let w = self.willis()?;
        let wh = self.carrier.map_or(0.0, |h| w[h]);
        Ok(self
            .shafts
            .iter()
            .zip(&w)
            .map(|(s, v)| (s.clone(), *v, v - wh))
            .collect())
    }
}

/// The assembly condition of k satellites ([`Train::assembly`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Assembly {
    /// The central wheel a (index into [`Train::wheels`]).
    pub central: usize,
    /// The number of satellites.
    pub k: u32,
    /// z_a·u_aH^(b)/k as a reduced fraction (numerator, denominator > 0).
    pub value: (i128, i128),
    /// The least p ≥ 0 making (1 + kp)·value whole (the textbook's condition); `None` when
    /// none does.
    pub p: Option<i128>,
    /// value·z_f/gcd(z_g, z_f) reduced, when the satellites are one block g–f between a and
    /// b: whole exactly when identical blocks fit at every 2πj/k.
    pub block: Option<(i128, i128)>,
}

impl Assembly {
    /// Whether k satellites can be assembled spaced equally: the block's exact condition,
    /// or the textbook's when the train is not a single block between a and b.
    pub fn fits(&self) -> bool {
        self.block.map_or(self.p.is_some(), |b| b.1 == 1)
    }
}

fn gcd(a: i128, b: i128) -> i128 {
    let (mut a, mut b) = (a.abs(), b.abs());
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// n/d in lowest terms with d > 0.
fn reduced(n: i128, d: i128) -> (i128, i128) {
    let g = gcd(n, d).max(1);
    let s = if d < 0 { -1 } else { 1 };
    (s * n / g, s * d / g)
}

/// x⁻¹ mod m for gcd(x, m) = 1 (extended Euclid); 0 when m = 1.
fn inverse_mod(x: i128, m: i128) -> i128 {
    let (mut r0, mut r1, mut s0, mut s1) = (m, x, 0_i128, 1_i128);
    while r1 != 0 {
        let q = r0 / r1;
        (r0, r1) = (r1, r0 - q * r1);
        (s0, s1) = (s1, s0 - q * s1);
    }
    s0.rem_euclid(m)
}

/// The system of (coefficients, right-hand side) rows, solved by the kernel's elimination.
fn solve(rows: Vec<(Vec<f64>, f64)>) -> Option<Vec<f64>> {
    crate::geom::solve_linear(
        rows.into_iter()
            .map(|(mut a, b)| {
                a.push(b);
                a
            })
            .collect(),
    )
}

/// The best tooth numbers (z₁, z₂) of a pair for the ratio `u` (z₂/z₁ > 0), z₁ from `z1_min`
/// to `z1_max`, by the relative error of z₂/z₁: the `count` best.
pub fn best_pairs(u: f64, z1_min: u32, z1_max: u32, count: usize) -> Vec<(u32, u32, f64)> {
    let mut all: Vec<(u32, u32, f64)> = (z1_min..=z1_max)
        .filter_map(|z1| {
            let z2 = (f64::from(z1) * u).round();
            (1.0..1e6).contains(&z2).then(|| {
                let z2 = z2 as u32;
                (z1, z2, (f64::from(z2) / f64::from(z1) - u) / u)
            })
        })
        .collect();
    all.sort_by(|a, b| a.2.abs().total_cmp(&b.2.abs()).then(a.0.cmp(&b.0)));
    all.truncate(count);
    all
}
