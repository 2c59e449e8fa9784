//! The notes of a train study: the inversion table, the mobility, the ratio, a differential's
//! formula, the module a non-coaxial stage is drawn at (what the source leaves out), what the
//! source prints against what the teeth give, the required ratio and the best teeth, the
//! neighbour and assembly conditions — typed ([`TrainNote`]), their English written by
//! `report`.

use super::layout::teeth_across;
use super::study::{TrainSeed, TrainStudy};
use super::{best_pairs, Stage, Train};
pub use crate::check::notes::train::SeedStage;
use crate::check::notes::train::{
    Across, Closing, FormulaBy, MeshNeeds, MeshRatio, SatelliteAssembly, SolvedFor, TrainNote,
    WillisDifferential,
};

/// One mesh's ratio with the carrier stopped: (−30/20).
fn mesh_ratio(t: &Train, x: usize, y: usize) -> MeshRatio {
    MeshRatio {
        negative: t.mesh_ratio(x, y) < 0.0,
        driven: t.wheels[y].z,
        driving: t.wheels[x].z,
    }
}

/// The teeth across mesh (x, y)'s centre distance: `z1 + z2`, or `z5 − z4` for a ring 5.
fn across(t: &Train, x: usize, y: usize) -> Across {
    let (wx, wy) = (&t.wheels[x], &t.wheels[y]);
    let (first, second) = if wy.internal && !wx.internal {
        (wy, wx)
    } else {
        (wx, wy)
    };
    Across {
        first: first.name.clone(),
        second: second.name.clone(),
        ring: wx.internal || wy.internal,
    }
}

impl TrainStudy {
    /// The notes: the inversion table, the mobility, the ratio, the differential's formula,
    /// the closed stages, the source's printed values, the required ratio and the best tooth
    /// numbers of the first mesh for it, the neighbour and assembly conditions.
    pub fn notes(&self) -> Vec<TrainNote> {
        let mut out = vec![];
        out.extend(self.inversion_note());
        out.push(self.mobility_note());
        out.push(TrainNote::Ratio {
            ratio: self.ratio,
            formula: self.formula.map(|s| {
                let by = if self.spec.train.second.is_some() {
                    FormulaBy::Differential
                } else {
                    FormulaBy::Stages
                };
                (s, by)
            }),
        });
        out.extend(self.differential_note());
        out.extend(self.closing_notes());
        out.extend(self.seed_notes());
        out.extend(self.required_notes());
        out.extend(self.satellite_notes());
        out
    }

    /// The inversion table (seed 002 Table 2.1).
    fn inversion_note(&self) -> Option<TrainNote> {
        let n_in = self.spec.n_input.unwrap_or(1.0);
        let inv = self.spec.train.inversion().ok()?;
        Some(TrainNote::Inversion {
            rpm: self.spec.n_input.is_some(),
            cells: inv
                .into_iter()
                .map(|(s, w, r)| (s, w * n_in, r * n_in))
                .collect(),
        })
    }

    /// W = 3n − 2p₅ − p₄, with a differential's two inputs.
    fn mobility_note(&self) -> TrainNote {
        let t = &self.spec.train;
        let n_in = self.spec.n_input.unwrap_or(1.0);
        let m = t.mobility();
        TrainNote::Mobility {
            n: m.n,
            p5: m.p5,
            p4: m.p4,
            w: m.w(),
            inputs: t.second.map(|(k, w)| {
                (
                    t.shafts[t.input].clone(),
                    t.shafts[k].clone(),
                    n_in,
                    w * n_in,
                )
            }),
        }
    }

    /// A differential by Willis's formula: u_ab^(H) from the teeth, the output's speed.
    fn differential_note(&self) -> Option<TrainNote> {
        let t = &self.spec.train;
        let d = t.differential()?;
        let h = t.carrier?;
        let n_in = self.spec.n_input.unwrap_or(1.0);
        let solved = if t.output == h {
            SolvedFor::Carrier
        } else if t.output == d.a {
            SolvedFor::A
        } else {
            SolvedFor::B
        };
        let out = [d.a, d.b, h].iter().position(|&k| k == t.output)?;
        Some(TrainNote::Differential(WillisDifferential {
            names: [d.a, d.b, h].map(|k| t.shafts[k].clone()),
            meshes: d.meshes.iter().map(|&(x, y)| mesh_ratio(t, x, y)).collect(),
            u: d.u,
            solved,
            output: d.omega[out] * n_in,
            speeds: [d.omega[0], d.omega[1], d.omega[2]].map(|w| w * n_in),
        }))
    }

    /// Each mesh taken at the module that closes the carrier's arm: the datum the source
    /// leaves out.
    fn closing_notes(&self) -> Vec<TrainNote> {
        let t = &self.spec.train;
        let name = |x: usize, y: usize| (t.wheels[x].name.clone(), t.wheels[y].name.clone());
        self.closings
            .iter()
            .map(|c| {
                let ((s, w), (sa, wa)) = (c.mesh, c.arm_mesh);
                TrainNote::Closing(Closing {
                    mesh: name(s, w),
                    arm_mesh: name(wa, sa),
                    module: t.module,
                    arm_across: across(t, wa, sa),
                    arm: c.arm,
                    across: across(t, s, w),
                    teeth: teeth_across(t, s, w),
                    closing: c.module,
                    wheel: t.wheels[w].name.clone(),
                })
            })
            .collect()
    }

    /// What a printed ratio needs of the train's one planetary stage, the other stages as
    /// their teeth give; `None` without a printed ratio or such a stage.
    pub fn seed_stage(&self) -> Option<SeedStage> {
        let t = &self.spec.train;
        let printed = self.spec.seed.u?;
        let stages = t.stages()?;
        let mut planetary = stages.iter().filter_map(|s| match s {
            Stage::Planetary { meshes } => Some(meshes),
            Stage::Mesh { .. } => None,
        });
        let meshes = planetary.next()?;
        if planetary.next().is_some() {
            return None;
        }
        let others: f64 = stages
            .iter()
            .filter(|s| matches!(s, Stage::Mesh { .. }))
            .map(|s| t.stage_ratio(s))
            .product();
        let teeth: f64 = meshes.iter().map(|&(x, y)| t.mesh_ratio(x, y)).product();
        let (first, last) = (meshes.first()?, meshes.last()?);
        Some(SeedStage {
            a: t.wheels[first.0].name.clone(),
            f: t.wheels[last.1].name.clone(),
            needed: 1.0 - printed / others,
            teeth,
        })
    }

    /// The source's printed mobility and ratio against the train's.
    fn seed_notes(&self) -> Vec<TrainNote> {
        let t = &self.spec.train;
        let seed = self.spec.seed;
        let mut out = Vec::new();
        let m = t.mobility();
        if let Some(w) = seed.w {
            out.push(if w == m.w() {
                TrainNote::SeedMobility { w }
            } else {
                TrainNote::SeedMobilityErratum {
                    printed: w,
                    n: m.n,
                    p5: m.p5,
                    p4: m.p4,
                    w: m.w(),
                }
            });
        }
        let Some(u) = seed.u else {
            return out;
        };
        let name = format!("u_{}_{}", t.shafts[t.input], t.shafts[t.output]);
        out.push(if TrainSeed::reproduces(u, self.ratio) {
            TrainNote::SeedRatio {
                name,
                printed: u,
                ratio: self.ratio,
            }
        } else {
            TrainNote::SeedRatioErratum {
                name,
                printed: u,
                ratio: self.ratio,
                formula: self.formula,
                triangles: self.triangles.ratio,
                stage: self.seed_stage(),
            }
        });
        out
    }

    /// With the input's and the required output speed: the required ratio, the first
    /// fixed-axis mesh's teeth for it.
    fn required_notes(&self) -> Vec<TrainNote> {
        let t = &self.spec.train;
        let (Some(n1), Some(n_out)) = (self.spec.n_input, self.spec.n_output) else {
            return Vec::new();
        };
        let required = (n1 / n_out).abs();
        let mut out = vec![TrainNote::Required {
            n_in: n1.abs(),
            n_out,
            required,
            ratio: self.ratio.abs(),
        }];
        if let Some(m) = t.fixed_axis_mesh().map(|k| t.meshes[k]) {
            let (a, b) = (&t.wheels[m.0], &t.wheels[m.1]);
            let want = b.z / a.z * required / self.ratio.abs();
            out.push(TrainNote::MeshNeeds(MeshNeeds {
                names: (a.name.clone(), b.name.clone()),
                want,
                best: best_pairs(want, 17, 40, 4),
                n_out,
                now: (a.z, b.z),
            }));
        }
        out
    }

    /// With the number of satellites: the neighbour and the assembly conditions.
    fn satellite_notes(&self) -> Vec<TrainNote> {
        let t = &self.drawn;
        let Some(k) = self.spec.satellites else {
            return Vec::new();
        };
        let mut out: Vec<TrainNote> = t
            .neighbour(k)
            .unwrap_or_default()
            .into_iter()
            .map(|(w, chord, tip)| TrainNote::Neighbour {
                k,
                chord,
                wheel: t.wheels[w].name.clone(),
                tip,
            })
            .collect();
        let Some(a) = t.assembly(k) else {
            return out;
        };
        out.push(TrainNote::Assembly(SatelliteAssembly {
            k,
            central: t.wheels[a.central].name.clone(),
            fixed: t.fixed.map_or(String::new(), |f| t.shafts[f].clone()),
            value: a.value,
            p: a.p,
            block: a.block,
            fits: if a.fits() {
                Ok(())
            } else {
                Err((2..=8).filter(|&j| t.admits(j)).collect())
            },
        }));
        out
    }
}
