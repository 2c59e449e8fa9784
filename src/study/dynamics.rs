//! The dynamics study of the session (`[dynamics]`): the flywheel by every route.

use super::*;
use crate::kinematics;

/// The dynamic study's part of the report.
pub(super) const PART: Part = |session, rep| session.report_dynamics(rep);

/// The dynamic study.
struct Flywheel;
impl Cache for Flywheel {
    type Key = ();
    type Value = Cached<crate::dynamics::Dynamics>;
}

impl<'s> Session<'s> {
    /// The dynamic study (`[dynamics]`) at the kinematic study's scales: the reduction over
    /// [`crate::dynamics::DynamicsSpec::positions`] from their velocity plans (the scene's
    /// drawn plans when they are as many; its own plan of positions otherwise), the diagrams,
    /// the exact energy equation and the flywheel.
    pub fn dynamics(&self) -> Cached<crate::dynamics::Dynamics> {
        self.caches.get::<Flywheel>((), || {
            let spec = self
                .scene
                .dynamics
                .as_ref()
                .ok_or(StudyError::NoDynamics("the dynamic study"))?;
            let forces = self.force_spec("the dynamic study")?;
            let sc = self.kin_scales()?;
            let w1 = self.w1()?;
            let ctx = self.ctx()?;
            let (count, step) = spec.positions(self.scene.positions.count);
            let mut d = if count == self.scene.positions.count {
                let plan = self.positions(sc.l)?;
                let vel = self.velocities(&sc)?;
                let vps: Vec<Option<&KinPlan>> = vel.iter().map(|v| v.plan()).collect();
                crate::dynamics::analyse(spec, forces, &plan, &vps, w1, &ctx)
                    .map_err(|e| self.dynamics_error(e))?
            } else {
                let m = self.mechanism("the dynamic study")?;
                let req = PlanRequest {
                    count,
                    other_extreme: false,
                    ..self.plan_request()
                };
                let plan = plan_positions(m, &req, sc.l, self.drafting)?;
                let vel = (0..plan.positions.len())
                    .map(|k| kinematics::velocity(&plan, k, sc.l.value(), w1, sc.v, &ctx))
                    .collect::<Result<Vec<_>, _>>()?;
                // Its own positions and plans, made once with the study (cached with it).
                for p in &plan.positions {
                    self.logged("dynamics position", &p.label, sc.l);
                    self.logged("dynamics velocity plan", &p.label, sc.v);
                }
                let vps: Vec<Option<&KinPlan>> = vel.iter().map(|v| v.plan()).collect();
                crate::dynamics::analyse(spec, forces, &plan, &vps, w1, &ctx)
                    .map_err(|e| self.dynamics_error(e))?
            };
            // The plans' positions among the diagrams' own: tabled under the plans' names.
            if let Some(step) = step.filter(|&s| s > 1) {
                let plan = self.positions(sc.l)?;
                let names: Vec<String> = kinematics::numbered(&plan)
                    .iter()
                    .map(|(_, p)| p.label.clone())
                    .collect();
                d.table_every(step as usize, &names);
            }
            d.number_axes(&ctx);
            self.logged("dynamics diagrams", "", d.diagrams.scale_a);
            Ok(Arc::new(d))
        })
    }

    /// A diagram whose every ordinate the drafting reads as 0 is said so, naming the
    /// drafting; the other errors pass as they are.
    fn dynamics_error(&self, e: crate::dynamics::DynamicsError) -> StudyError {
        let resolution_mm = self.drafting.resolution_mm();
        match e {
            crate::dynamics::DynamicsError::NoScale { what, value }
                if value == 0.0 && resolution_mm > 0.0 =>
            {
                StudyError::ReadAsZero {
                    what,
                    resolution_mm,
                }
            }
            e => e.into(),
        }
    }

    fn report_dynamics(&self, rep: &mut Report) -> Result<(), StudyError> {
        let d = self.dynamics()?;
        rep.rows.extend(crate::dynamics::rows(&d));
        rep.notes
            .extend(crate::dynamics::noted(&d).into_iter().map(ReportNote::from));
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::construct::Item;

    /// On the energy–mass diagram each tangent ends clear of the J axis (its name beside
    /// its end, not on the axis) and the axis runs on past both, that no tangent ends on
    /// its arrowhead (the shaper's ψ_min did, issue 45).
    #[test]
    fn the_tangents_of_the_energy_mass_diagram_end_clear_of_the_axis() {
        for scene in ["shaper", "v-engine"] {
            super::super::with_scene(scene, |s| {
                let d = s.dynamics().expect("dynamics");
                let steps = &d.diagrams.wittenbauer_figure.steps;
                let tip = steps
                    .iter()
                    .find_map(|st| match st.item {
                        Item::Vector { to, .. } if st.note.starts_with("abscissa axis") => Some(to),
                        _ => None,
                    })
                    .expect("the J axis");
                let ends: Vec<_> = steps
                    .iter()
                    .filter_map(|st| match st.item {
                        Item::Segment(seg) if st.note.starts_with("tangent ψ") => Some(seg.to),
                        _ => None,
                    })
                    .collect();
                assert_eq!(ends.len(), 2, "{scene}");
                for end in ends {
                    assert!(end.y.abs() >= 5.0 - 1e-9, "{scene}: {end} beside the axis");
                    assert!(
                        tip.x - end.x >= 14.0 - 1e-9,
                        "{scene}: {end}, the tip {tip}"
                    );
                }
            });
        }
    }
}
