//! The force study of the session: the force analysis at each of `[forces] positions`.

use super::*;
use crate::construct::fit::finest_fitting;
use crate::geom::DVec2;

/// The force analysis's part of the report (after the kinematic study's, whose plans it reads).
pub(super) const PART: Part = |session, rep| session.report_forces(rep);

/// The force analysis by (μ_l of the groups, the kinematic μ_l, μ_v, μ_a, position).
struct Polygons;
/// The largest residual the equilibrium check allows an analysis at drafting 0 (both routes
/// hold to ~1e-15): beyond it a route made a decision the scene does not support.
pub const EQUILIBRIUM_TOLERANCE: f64 = 1e-9;

/// A route of the force analysis that fails its own equilibrium check at a position.
#[derive(Debug, Clone, PartialEq)]
pub struct Unbalanced {
    /// The position's label.
    pub position: String,
    /// The analysis with friction.
    pub friction: bool,
    /// The route.
    pub route: ForceRoute,
    /// The bodies' equations' residual.
    pub equilibrium: f64,
    /// The power balance's residual.
    pub power: f64,
}

/// A route of the force analysis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ForceRoute {
    /// The force polygons, group by group.
    Polygons,
    /// The linear solve of every body's equations at once (its twin).
    LinearSolve,
}

impl std::fmt::Display for Unbalanced {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let route = match self.route {
            ForceRoute::Polygons => "the force polygons",
            ForceRoute::LinearSolve => "the linear solve",
        };
        write!(
            f,
            "position {}{}: {route} fail the equilibrium check: bodies' equations {:.2e}, power balance {:.2e} (allowed {EQUILIBRIUM_TOLERANCE:.0e})",
            self.position,
            if self.friction { " with friction" } else { "" },
            self.equilibrium,
            self.power
        )
    }
}

impl Cache for Polygons {
    type Key = (Scale, Scale, Scale, Scale, usize);
    type Value = Cached<PositionForces>;
}

/// μ_l of the force sheets' drawings.
struct ForceScaleL;
impl Cache for ForceScaleL {
    type Key = ();
    type Value = Result<Scale, StudyError>;
}

/// The room of each drawing at μ_l on a force sheet (an Assur group with its loads,
/// reactions and arms; the driving link), mm: two groups side by side take less than the
/// A1 field's width, each with its polygon beside or under it.
const GROUP_ROOM: DVec2 = DVec2::new(GROUP_W, GROUP_H);
const GROUP_W: f64 = 300.0;
const GROUP_H: f64 = 300.0;

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

    /// μ_l of the force sheets' drawings (every group and the driving link, whose arms are
    /// measured on them), decided once, before any is constructed: the scene's μ_l; else
    /// the plan of positions' made finer along the round series while every such drawing at
    /// every analysed position, predicted from the analytic twin
    /// ([`crate::forces::predicted_drawings`]), fits [`GROUP_ROOM`]: the groups as large as
    /// their sheet holds them. A position the twin cannot solve keeps the plan's μ_l (its
    /// analysis then tells why).
    pub fn force_scale_l(&self) -> Result<Scale, StudyError> {
        self.caches.get::<ForceScaleL>((), || {
            let sc = self.kin_scales()?;
            if self.scene.scale_l.is_some() {
                return Ok(sc.l);
            }
            let spec = self.force_spec("the force analysis")?;
            let (poses, w1) = (self.poses()?, self.w1()?);
            let predicted: Result<Vec<_>, _> = self
                .force_positions()?
                .into_iter()
                .map(|k| crate::forces::predicted_drawings(spec, &poses, k, w1))
                .collect();
            let Ok(drawings) = predicted else {
                return Ok(sc.l);
            };
            let fits = |mu: &Scale| {
                drawings
                    .iter()
                    .flatten()
                    .all(|d| d.size_at(*mu).cmple(GROUP_ROOM).all())
            };
            Ok(finest_fitting(sc.l, sc.l, Some, fits))
        })
    }

    /// The force analysis of position `k` of `plan` (constructed at μ_l = `l`) from the
    /// velocity and acceleration plans at the kinematic scales `sc`.
    fn analysed(
        &self,
        plan: &PositionPlan,
        l: Scale,
        sc: &KinScales,
        k: usize,
    ) -> Result<PositionForces, StudyError> {
        let spec = self.force_spec("the force analysis")?;
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
        Ok(crate::forces::analyse(
            spec,
            plan,
            k,
            l,
            vp,
            &ap.plan,
            w1,
            &self.ctx()?,
        )?)
    }

    /// The force analysis of position `k`: its groups and driving link drawn on the plan of
    /// positions at [`Session::force_scale_l`], from the velocity and acceleration plans at
    /// the kinematic scales `sc`.
    pub fn forces(&self, sc: &KinScales, k: usize) -> Cached<PositionForces> {
        let l = self.force_scale_l()?;
        self.caches.get::<Polygons>((l, sc.l, sc.v, sc.a, k), || {
            let plan = self.positions(l)?;
            let f = self.analysed(&plan, l, sc, k)?;
            self.logged("force polygons", &plan.positions[k].label, f.scale_f);
            Ok(Arc::new(f))
        })
    }

    /// Where the force analysis fails its own check at drafting 0: at each force position,
    /// a route whose equilibrium or power residual exceeds [`EQUILIBRIUM_TOLERANCE`], with its
    /// numbers (none for a scene without `[forces]`).
    pub fn unbalanced(&self) -> Result<Vec<Unbalanced>, StudyError> {
        if self.scene.forces.is_none() || self.scene.mechanism.is_none() {
            return Ok(Vec::new());
        }
        let sc = self.kin_scales()?;
        let mut out = Vec::new();
        for i in self.force_positions()? {
            let f = self.forces(&sc, i)?;
            for r in &f.residuals {
                for (route, v) in [
                    (ForceRoute::Polygons, r.polygons),
                    (ForceRoute::LinearSolve, r.twin),
                ] {
                    if v.equilibrium > EQUILIBRIUM_TOLERANCE || v.power > EQUILIBRIUM_TOLERANCE {
                        out.push(Unbalanced {
                            position: f.label.clone(),
                            friction: r.friction,
                            route,
                            equilibrium: v.equilibrium,
                            power: v.power,
                        });
                    }
                }
            }
        }
        Ok(out)
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
            rep.notes
                .extend(crate::forces::notes(&f).into_iter().map(ReportNote::from));
        }
        let seed = &self.force_spec("the force analysis")?.seed;
        rep.notes.extend(
            crate::check::seed_notes(seed, &rows)
                .into_iter()
                .map(ReportNote::from),
        );
        rep.rows.extend(rows);
        Ok(())
    }
}

impl Session<'_> {
    /// An engine's indicator diagrams, one for each distinct pressure table, with the
    /// ordinate of every cylinder it serves at every position the force sheets analyse
    /// (labelled by the piston and the position, `B3`): the pistons each serves and its
    /// figure and its μ_θ. None without `[[forces.indicator]]`.
    ///
    /// # Errors
    /// The mechanism's or the force analysis's refusal.
    pub fn indicator_figures(&self) -> Result<Vec<(Vec<String>, Figure, Scale)>, StudyError> {
        let spec = self.force_spec("the indicator diagrams")?;
        if spec.indicators.is_empty() {
            return Ok(Vec::new());
        }
        let sense = self.mechanism("the indicator diagrams")?.crank.sense.sign();
        let poses = self.poses()?;
        let at: Vec<&crate::linkage::PosePosition> = self
            .force_positions()?
            .into_iter()
            .filter_map(|k| poses.positions.get(k))
            .collect();
        // The cylinders by their table: one diagram serves all that share it.
        let mut tables: Vec<(
            &crate::forces::Indicator,
            Vec<String>,
            Vec<crate::forces::Reading>,
        )> = Vec::new();
        for c in &spec.indicators {
            let letter = crate::words::plain(&c.point);
            let readings = at
                .iter()
                // The piston's point at the position, as the plan of positions names it: B₃.
                .map(|p| {
                    (
                        format!("{letter}_{{{}}}", p.label),
                        c.cycle_angle(p.phi, sense),
                    )
                });
            match tables.iter_mut().find(|t| t.0.pressure == c.pressure) {
                Some(t) => {
                    t.1.push(c.point.clone());
                    t.2.extend(readings);
                }
                None => tables.push((c, vec![c.point.clone()], readings.collect())),
            }
        }
        let ctx = self.ctx()?;
        let out = tables
            .into_iter()
            .filter_map(|(c, pistons, readings)| {
                let (f, mu_theta) = crate::forces::indicator_figure(c, &readings, &ctx)?;
                Some((pistons, f, mu_theta))
            })
            .collect();
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The drawings at μ_l of a position's force analysis: its groups and its driving link.
    fn drawn_at_l(f: &PositionForces) -> impl Iterator<Item = &Figure> {
        let p = &f.analysis.polygons;
        p.groups
            .iter()
            .map(|g| &g.scheme)
            .chain(std::iter::once(&p.driver.scheme))
    }

    /// The extents of the drawings at μ_l of every analysed position at μ_l = `mu`.
    fn sizes_at(s: &Session<'_>, mu: Scale) -> Vec<DVec2> {
        let sc = s.kin_scales().expect("scales");
        let m = s.mechanism("test").expect("mechanism");
        let plan = plan_positions(m, &s.plan_request(), mu, Drafting::EXACT).expect("plan");
        s.force_positions()
            .expect("positions")
            .into_iter()
            .flat_map(|k| {
                let f = s.analysed(&plan, mu, &sc, k).expect("forces");
                drawn_at_l(&f)
                    .filter_map(|g| g.bounds().map(|(lo, hi)| hi - lo))
                    .collect::<Vec<_>>()
            })
            .collect()
    }

    /// A free μ_l of the force sheets is the finest round one at which every group and the
    /// driving link of every analysed position fit their room (one step finer one would not):
    /// the v-engine's groups at 0,0005 m/mm, twice the plan of positions' 0,001; the drawings
    /// and the arms measured on them are at that μ_l. The shaper's μ_l, fixed by the scene,
    /// stands.
    #[test]
    fn a_free_force_scale_l_draws_the_groups_as_large_as_their_room_holds() {
        super::super::with_scene("v-engine", |s| {
            let l = s.force_scale_l().expect("μ_l");
            assert_eq!(l.value(), 0.0005);
            assert!(l.value() < s.scale_l().expect("plan's μ_l").value());
            let sizes = sizes_at(s, l);
            assert!(sizes.len() >= 6, "{sizes:?}");
            assert!(sizes.iter().all(|x| x.cmple(GROUP_ROOM).all()), "{sizes:?}");
            let finer = l.finer().expect("finer");
            assert!(
                sizes_at(s, finer)
                    .iter()
                    .any(|x| !x.cmple(GROUP_ROOM).all()),
                "μ_l could be {}",
                finer.value()
            );
            let sc = s.kin_scales().expect("scales");
            for k in s.force_positions().expect("positions") {
                let f = s.forces(&sc, k).expect("forces");
                for g in drawn_at_l(&f) {
                    assert_eq!(g.scale, l);
                }
            }
        });
        super::super::with_scene("shaper", |s| {
            assert_eq!(s.force_scale_l().expect("μ_l").value(), 0.0025);
        });
    }

    /// The drawings μ_l is sized from, predicted from the analytic twin, take the room the
    /// constructed drawings take at the plan's μ_l and three finer ones, on every shipped
    /// force scene: to a hundredth of a mm on the v-engine (whose μ_l is free); within 10 mm
    /// where the construction moves an arrow past another at a crowded point or dimensions
    /// an arm beside a line it nearly lies on at a coarse μ_l (the six-bar's group 4–5 and
    /// 2–3 at position 3).
    #[test]
    fn the_predicted_force_drawings_take_the_room_of_the_constructed() {
        for (scene, within) in [
            ("v-engine", 0.01),
            ("six-bar", 10.0),
            ("slider-crank", 10.0),
            ("shaper", 10.0),
        ] {
            super::super::with_scene(scene, |s| {
                let poses = s.poses().expect("poses");
                let spec = s.force_spec("test").expect("forces");
                let w1 = s.w1().expect("ω₁");
                let mut mu = s.scale_l().expect("μ_l");
                for _ in 0..4 {
                    let predicted: Vec<DVec2> = s
                        .force_positions()
                        .expect("positions")
                        .into_iter()
                        .flat_map(|k| {
                            crate::forces::predicted_drawings(spec, &poses, k, w1)
                                .expect("predicted")
                                .iter()
                                .map(|d| d.size_at(mu))
                                .collect::<Vec<_>>()
                        })
                        .collect();
                    let drawn = sizes_at(s, mu);
                    assert_eq!(predicted.len(), drawn.len(), "{scene}");
                    for (p, d) in predicted.iter().zip(&drawn) {
                        let off = (*p - *d).abs().max_element();
                        assert!(off <= within, "{scene} at {}: {p} against {d}", mu.value());
                    }
                    mu = mu.finer().expect("finer");
                }
            });
        }
    }

    /// Every shipped force scene passes its own check (no route unbalanced), and a route
    /// that fails it is told with its position, the route and its residuals against the
    /// tolerance, as `tmm check` prints it.
    #[test]
    fn an_unbalanced_route_is_told_with_its_numbers() {
        for scene in ["shaper", "v-engine"] {
            super::super::with_scene(scene, |s| {
                assert_eq!(s.unbalanced().expect("check"), Vec::new(), "{scene}");
            });
        }
        let u = Unbalanced {
            position: "3".into(),
            friction: true,
            route: ForceRoute::LinearSolve,
            equilibrium: 2.5e-6,
            power: 1e-12,
        };
        assert_eq!(
            u.to_string(),
            "position 3 with friction: the linear solve fail the equilibrium check: bodies' \
             equations 2.50e-6, power balance 1.00e-12 (allowed 1e-9)"
        );
    }
}
