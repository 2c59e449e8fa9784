//! The force study of the session: the force analysis at each of `[forces] positions`.

use super::*;

/// The force analysis's part of the report (after the kinematic study's, whose plans it reads).
pub(super) const PART: Part = Part {
    has: |scene| scene.mechanism.is_some() && scene.forces.is_some(),
    add: |session, rep| session.report_forces(rep),
};

/// The force analysis by (μ_l, μ_v, μ_a, position).
struct Polygons;
impl Cache for Polygons {
    type Key = (Scale, Scale, Scale, usize);
    type Value = Cached<PositionForces>;
}

impl<'s> Session<'s> {
    /// The `[forces]` loads, for a study that needs them.
    pub fn force_spec(&self, study: &'static str) -> Result<&'s ForceSpec, StudyError> {
        self.scene
            .forces
            .as_ref()
            .ok_or(StudyError::NoForces(study))
    }

    /// The positions the force analysis asks for, as indices into the plan's positions.
    pub fn force_positions(&self) -> Result<Vec<usize>, StudyError> {
        let spec = self.force_spec("the force analysis")?;
        let poses = self.poses()?;
        let labels: Vec<String> = poses.positions.iter().map(|p| p.label.clone()).collect();
        spec.positions
            .iter()
            .map(|l| {
                labels.iter().position(|p| p == l).ok_or_else(|| {
                    ForceError::NoSuchPosition {
                        label: l.clone(),
                        valid: crate::kinematics::position_list(&labels),
                    }
                    .into()
                })
            })
            .collect()
    }

    /// The force analysis of position `k` at the kinematic scales `sc` (its velocity and
    /// acceleration plans at μ_v and μ_a).
    pub fn forces(&self, sc: &KinScales, k: usize) -> Cached<PositionForces> {
        self.caches.get::<Polygons>((sc.l, sc.v, sc.a, k), || {
            let spec = self.force_spec("the force analysis")?;
            let plan = self.positions(sc.l)?;
            let vel = self.velocity(sc, k)?;
            let position = plan.positions[k].label.clone();
            let vp = match vel.as_ref() {
                Velocity::Built { plan: vp, .. } => vp,
                Velocity::Refused(why) => {
                    return Err(KinError::ForcePosition {
                        position,
                        kind: PlanKind::Velocity,
                        why: why.clone(),
                    }
                    .into())
                }
            };
            // The acceleration plan of a force position is the force analysis's, not one of
            // `kinematics.acceleration_positions`: its failure names `forces.positions`.
            let ap = self.acceleration(sc, k).map_err(|e| match e {
                StudyError::Kinematics(e) => StudyError::from(KinError::ForcePosition {
                    position,
                    kind: PlanKind::Acceleration,
                    why: e.to_string(),
                }),
                other => other,
            })?;
            let w1 = self.w1()?;
            let f = crate::forces::analyse(spec, &plan, k, sc.l, vp, &ap.0, w1, &self.ctx()?)?;
            self.logged("force polygons", &plan.positions[k].label, f.scale_f);
            Ok(Arc::new(f))
        })
    }

    /// The rows and notes of the force analysis at each of `[forces] positions`, with the
    /// seed's comparison.
    fn report_forces(&self, rep: &mut Report) -> Result<(), StudyError> {
        let sc = self.kin_scales()?;
        let mut rows = Vec::new();
        for i in self.force_positions()? {
            let f = self.forces(&sc, i)?;
            rows.extend(f.rows.iter().cloned());
            rows.extend(f.residual_rows());
            rep.notes.extend(crate::forces::notes(&f));
        }
        let seed = &self.force_spec("the force analysis")?.seed;
        rep.notes.extend(crate::forces::seed_notes(seed, &rows));
        rep.rows.extend(rows);
        Ok(())
    }
}
