//! The train's geometry: the heights of its axes and mesh poles in the scheme (r = m z/2 of
//! each wheel at its module), the coaxiality of the carrier with the central wheels of its
//! satellites, and the module that closes a stage the source gives at one module although its
//! tooth sums do not close (seed 002 PZ2 examples 1 and 2: z₁ + z₂ = 136 against
//! z₃ + z₄ = 48) — the datum the source leaves out, taken so that the train can be drawn.

use super::{Train, TrainError};

/// A satellite's mesh with a central wheel taken at the module that brings the central wheel
/// onto the carrier's axis ([`Train::closing`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosedMesh {
    /// The mesh (index into [`Train::meshes`]): its satellite's wheel first, then the
    /// central wheel.
    pub mesh: (usize, usize),
    /// The mesh of a wheel of the same satellite with a central wheel on the carrier's axis,
    /// which sets the carrier's arm: satellite's wheel first.
    pub arm_mesh: (usize, usize),
    /// The carrier's arm a, the satellites' axis from the carrier's, m.
    pub arm: f64,
    /// The module the mesh is taken at, m′ = 2a/(z_c ± z_s).
    pub module: f64,
}

/// The teeth across a mesh's centre distance a = m·teeth/2: the sum of an external mesh, the
/// ring's less the other wheel's of an internal one (0 or less: no centre distance).
pub(in crate::gears) fn teeth_across(train: &Train, x: usize, y: usize) -> f64 {
    let (wx, wy) = (&train.wheels[x], &train.wheels[y]);
    match (wx.internal, wy.internal) {
        (true, _) => wx.z - wy.z,
        (_, true) => wy.z - wx.z,
        _ => wx.z + wy.z,
    }
}

impl Train {
    /// The module of wheel `w`'s meshes, m: its own, or the train's.
    pub fn wheel_module(&self, w: usize) -> f64 {
        self.wheels[w].module.unwrap_or(self.module)
    }

    /// Whether a height lies on the carrier's axis `axis` to the train's resolution.
    fn on_axis(&self, y: f64, axis: f64) -> bool {
        let off = (y - axis).abs();
        off <= 1e-9 * self.module.max(off)
    }

    /// The heights of the axes, each shaft placed from one already placed across a mesh (the
    /// input's at 0, each mesh pole above the driving wheel's axis, satellites inside rings,
    /// the carrier coaxial with the central wheels of its satellites, a central wheel reached
    /// from a satellite on the side of the carrier's axis), m; coaxiality is not checked.
    ///
    /// # Errors
    /// [`TrainError::Layout`] when a shaft cannot be placed.
    fn heights(&self) -> Result<Vec<f64>, TrainError> {
        let n = self.shafts.len();
        let mut y: Vec<Option<f64>> = vec![None; n];
        y[self.input] = Some(0.0);
        for pass in 0..2 * n + 2 {
            if let Some(h) = self.carrier {
                // The central wheels that mesh a satellite.
                let central: Vec<usize> = self
                    .meshes
                    .iter()
                    .flat_map(|m| [(m.0, m.1), (m.1, m.0)])
                    .map(|(a, b)| (self.wheels[a].shaft, self.wheels[b].shaft))
                    .filter(|&(sa, sb)| self.is_satellite(sb) && !self.is_satellite(sa) && sa != h)
                    .map(|(sa, _)| sa)
                    .collect();
                match y[h] {
                    // Coaxial with a placed central wheel that meshes a satellite.
                    None => y[h] = central.iter().find_map(|&c| y[c]),
                    // A carrier placed first (it is the input) sets the first central wheel
                    // on its axis; the satellites and the other central wheels follow.
                    Some(yh) => {
                        if let Some(&c) = central
                            .first()
                            .filter(|_| central.iter().all(|&c| y[c].is_none()))
                        {
                            y[c] = Some(yh);
                        }
                    }
                }
            }
            for m in &self.meshes {
                for (a, b) in [(m.0, m.1), (m.1, m.0)] {
                    let (wa, wb) = (&self.wheels[a], &self.wheels[b]);
                    // From a satellite to a central wheel once the carrier's axis is set
                    // (a later pass), unless nothing else sets it.
                    let to_central = self.is_satellite(wa.shaft) && !self.is_satellite(wb.shaft);
                    let carrier_unset = self.carrier.is_some_and(|h| y[h].is_none());
                    if to_central && carrier_unset && pass < n {
                        continue;
                    }
                    if let (Some(ya), None) = (y[wa.shaft], y[wb.shaft]) {
                        let (ra, rb) = (self.radius(a), self.radius(b));
                        // A ring's centre lies below the pole, as does a wheel inside a ring.
                        let up = if wb.internal || wa.internal {
                            ya + ra - rb
                        } else {
                            ya + ra + rb
                        };
                        // From a satellite to a central wheel: the side that sets it on the
                        // carrier's axis (the David train's second external mesh turns back).
                        let down = 2.0 * ya - up;
                        let axis = self.carrier.and_then(|h| y[h]).filter(|_| to_central);
                        y[wb.shaft] = Some(match axis {
                            Some(c) if (down - c).abs() < (up - c).abs() => down,
                            _ => up,
                        });
                    }
                }
            }
        }
        y.iter()
            .enumerate()
            .map(|(k, v)| {
                v.ok_or_else(|| {
                    TrainError::Layout(format!("shaft {} is not connected", self.shafts[k]))
                })
            })
            .collect()
    }

    /// The heights of the axes in the scheme ([`Train::heights`]), m, and of every mesh pole.
    ///
    /// # Errors
    /// [`TrainError::Layout`] when a shaft cannot be placed, a central wheel of a satellite
    /// is off the carrier's axis (the coaxiality condition) or two meshes disagree.
    pub fn layout(&self) -> Result<(Vec<f64>, Vec<f64>), TrainError> {
        let ys = self.heights()?;
        // Coaxiality: every central wheel of a satellite turns about the carrier's axis.
        if let Some(h) = self.carrier {
            for m in &self.meshes {
                for (a, b) in [(m.0, m.1), (m.1, m.0)] {
                    let (sa, sb) = (self.wheels[a].shaft, self.wheels[b].shaft);
                    if self.is_satellite(sb)
                        && !self.is_satellite(sa)
                        && !self.on_axis(ys[sa], ys[h])
                    {
                        return Err(TrainError::Layout(format!(
                            "wheel {} meshes a satellite but its axis is {} mm off the carrier's (the coaxiality condition fails)",
                            self.wheels[a].name,
                            (ys[sa] - ys[h]).abs() * 1e3
                        )));
                    }
                }
            }
        }
        let mut poles = Vec::new();
        for m in &self.meshes {
            let (wa, wb) = (&self.wheels[m.0], &self.wheels[m.1]);
            let (ya, yb) = (ys[wa.shaft], ys[wb.shaft]);
            let (ra, rb) = (self.radius(m.0), self.radius(m.1));
            let pole = [ya + ra, ya - ra]
                .into_iter()
                .find(|p| ((p - yb).abs() - rb).abs() <= 1e-9 * (ra + rb))
                .ok_or_else(|| {
                    TrainError::Layout(format!(
                        "wheels {} and {} are not coaxial with the rest (their axes are {} mm apart, their radii {} and {} mm)",
                        wa.name,
                        wb.name,
                        (ya - yb).abs() * 1e3,
                        ra * 1e3,
                        rb * 1e3
                    ))
                })?;
            poles.push(pole);
        }
        Ok((ys, poles))
    }

    /// The train as it can be drawn when its tooth sums do not close at one module: every
    /// mesh of a satellite with a central wheel that the train's module leaves off the
    /// carrier's axis is taken at the module that brings it there, m′ = 2a/(z_c ± z_s) (a
    /// the carrier's arm, which a mesh of the same satellite with a central wheel on the axis
    /// sets), with the meshes so taken. A mesh is taken so only when neither of its wheels
    /// has a module of its own or meshes another wheel; a coaxial train comes back as it is.
    ///
    /// # Errors
    /// As [`Train::layout`] for the train so taken: a stage that no module closes is still
    /// refused.
    pub fn closing(&self) -> Result<(Train, Vec<ClosedMesh>), TrainError> {
        let Some(h) = self.carrier else {
            self.layout()?;
            return Ok((self.clone(), Vec::new()));
        };
        let ys = self.heights()?;
        let mut closed = self.clone();
        let mut closings = Vec::new();
        let meshes_of = |w: usize| self.meshes.iter().filter(|m| m.0 == w || m.1 == w).count();
        for m in &self.meshes {
            for (s, c) in [(m.0, m.1), (m.1, m.0)] {
                let (ws, wc) = (&self.wheels[s], &self.wheels[c]);
                if !self.is_satellite(ws.shaft)
                    || self.is_satellite(wc.shaft)
                    || wc.shaft == h
                    || self.on_axis(ys[wc.shaft], ys[h])
                {
                    continue;
                }
                let arm = (ys[ws.shaft] - ys[h]).abs();
                let teeth = teeth_across(self, s, c);
                let own = ws.module.is_some() || wc.module.is_some();
                if own || meshes_of(s) > 1 || meshes_of(c) > 1 || teeth <= 0.0 {
                    continue;
                }
                // The mesh of the same satellite with a central wheel on the axis.
                let arm_mesh = self.meshes.iter().find_map(|n| {
                    [(n.0, n.1), (n.1, n.0)].into_iter().find(|&(x, y)| {
                        let (wx, wy) = (&self.wheels[x], &self.wheels[y]);
                        wx.shaft == ws.shaft
                            && !self.is_satellite(wy.shaft)
                            && self.on_axis(ys[wy.shaft], ys[h])
                    })
                });
                let Some(arm_mesh) = arm_mesh else {
                    continue;
                };
                let module = 2.0 * arm / teeth;
                for w in [s, c] {
                    closed.wheels[w].module = Some(module);
                }
                closings.push(ClosedMesh {
                    mesh: (s, c),
                    arm_mesh,
                    arm,
                    module,
                });
            }
        }
        closed.layout()?;
        Ok((closed, closings))
    }
}
