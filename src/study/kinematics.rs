//! The kinematic study of the session: the scales of the plans and diagrams, each velocity
//! and acceleration plan, the diagrams over the turn, the rocker's, the hodograph and the
//! analytic table, and the kinematics report.

use super::*;

/// The kinematic study's part of the report.
pub(super) const PART: Part = |session, rep| session.report_kinematics(rep);
use crate::check::notes::KinematicsNote;
use crate::kinematics::{self, ChartSize};

/// The scales of the kinematic study, all chosen: μ_l of the plan of positions, μ_v and μ_a
/// of the plans, and the displacement chart's scales and poles (`None`: chosen for the
/// chart by the study).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KinScales {
    /// μ_l.
    pub l: Scale,
    /// μ_v.
    pub v: Scale,
    /// μ_a.
    pub a: Scale,
    /// μ_S, μ_φ, H₁, H₂ of the displacement chart.
    pub chart: ChartScales,
}

/// The displacement chart's scales and pole distances; `None` leaves the choice to the chart.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ChartScales {
    /// μ_S, m/mm.
    pub s: Option<Scale>,
    /// μ_φ, rad/mm.
    pub phi: Option<Scale>,
    /// H₁, mm.
    pub h1: Option<f64>,
    /// H₂, mm.
    pub h2: Option<f64>,
    /// The size the chart chooses a free scale or pole distance for.
    pub size: ChartSize,
}

/// The kinematic study of a scene at one set of scales, assembled from the session's parts.
#[derive(Debug, Clone)]
pub struct Kinematics {
    /// The scales.
    pub scales: KinScales,
    /// ω₁, rad/s, signed counter-clockwise.
    pub w1: f64,
    /// The plan of positions.
    pub plan: Arc<PositionPlan>,
    /// The velocity plan of every position, in the plan's order.
    pub velocity: Vec<Arc<Velocity>>,
    /// The acceleration plans: (index into the positions, plan and rows).
    pub acceleration: Vec<(usize, Arc<Acceleration>)>,
    /// The displacement diagrams, when the mechanism has a point to chart.
    pub diagrams: Option<Arc<KinDiagrams>>,
    /// The rocker's ω diagram, when the mechanism has a rocker output.
    pub rocker: Option<Arc<RockerDiagram>>,
    /// The hodograph: its point's name without markup (`S3`) and its figure.
    pub hodograph: Option<Hodograph>,
    /// The analytic table (the shape of seed 000 Table 5).
    pub table: Arc<Table>,
    /// What was refused and why (a diagram across an angle the mechanism cannot pass).
    pub refusals: Vec<KinError>,
}

impl Kinematics {
    /// The velocity plans, `None` where refused.
    pub fn velocity_plans(&self) -> Vec<Option<&KinPlan>> {
        self.velocity.iter().map(|v| v.plan()).collect()
    }
    /// The plan of positions as the kinematic sheet draws it: its figure, with the segments
    /// the displacement S of the diagrams is read off ([`KinDiagrams::readings`]) when a point
    /// is charted — they draw nothing, and travel with the figure wherever it is placed.
    pub fn plan_figure(&self) -> Figure {
        let plan = self.plan.figure.clone();
        match &self.diagrams {
            Some(d) => plan.joined(d.readings.clone()),
            None => plan,
        }
    }
    /// Every reading against its analytic twin, in report order.
    pub fn rows(&self) -> Vec<Row> {
        kinematics::rows(
            self.velocity.iter().map(|v| v.rows()),
            self.acceleration.iter().map(|(_, a)| a.rows.as_slice()),
            self.diagrams.as_deref(),
            self.rocker.as_deref(),
        )
    }
    /// The positions whose velocity plan is refused, with the diagnosis.
    pub fn refused(&self) -> Vec<(String, String)> {
        self.plan
            .positions
            .iter()
            .zip(&self.velocity)
            .filter_map(|(p, v)| match v.as_ref() {
                Velocity::Refused(why) => Some((p.label.clone(), why.clone())),
                Velocity::Built { .. } => None,
            })
            .collect()
    }
}

/// A chart refused because the mechanism cannot pass part of the turn: no chart, a note.
pub(super) fn refusable<T>(r: MaybeCached<T>, refusals: &mut Vec<KinError>) -> MaybeCached<T> {
    match r {
        Err(StudyError::Kinematics(e @ (KinError::NoFullTurn { .. } | KinError::Leap { .. }))) => {
            refusals.push(e);
            Ok(None)
        }
        other => other,
    }
}

/// The velocity plans by (μ_l, μ_v, position).
struct VelocityPlans;
impl Cache for VelocityPlans {
    type Key = (Scale, Scale, usize);
    type Value = Cached<Velocity>;
}

/// The acceleration plans by (μ_l, μ_v, μ_a, position).
struct AccelerationPlans;
impl Cache for AccelerationPlans {
    type Key = (Scale, Scale, Scale, usize);
    type Value = Cached<Acceleration>;
}

/// The displacement diagrams by (μ_l, the chart's scales).
struct MotionDiagrams;
impl Cache for MotionDiagrams {
    type Key = (Scale, ChartScales);
    type Value = MaybeCached<KinDiagrams>;
}

/// The rocker's ω diagram by (μ_l, μ_v).
struct RockerDiagrams;
impl Cache for RockerDiagrams {
    type Key = (Scale, Scale);
    type Value = MaybeCached<RockerDiagram>;
}

/// The hodograph by (μ_l, μ_v).
struct Hodographs;
impl Cache for Hodographs {
    type Key = (Scale, Scale);
    type Value = Result<Option<Hodograph>, StudyError>;
}

/// The analytic table by μ_l.
struct AnalyticTables;
impl Cache for AnalyticTables {
    type Key = Scale;
    type Value = Cached<Table>;
}

impl<'s> Session<'s> {
    pub(super) fn spec(&self) -> &KinematicsSpec {
        &self.scene.kinematics
    }

    pub(super) fn w1(&self) -> Result<f64, StudyError> {
        Ok(kinematics::crank_rate(
            &self.mechanism("the kinematic analysis")?.crank,
        ))
    }

    /// The velocity plan at position `k` of the plan at μ_l = `sc.l`, at its μ_v
    /// ([`Session::plan_scale`]: the common `sc.v`, or its own for a plan far larger).
    pub fn velocity(&self, sc: &KinScales, k: usize) -> Cached<Velocity> {
        let (l, v) = (sc.l, self.plan_scale(PlanKind::Velocity, k)?);
        self.caches.get::<VelocityPlans>((l, v, k), || {
            let plan = self.positions(l)?;
            let vel = kinematics::velocity(&plan, k, l.value(), self.w1()?, v, &self.ctx()?)?;
            self.logged("velocity plan", &plan.positions[k].label, v);
            Ok(Arc::new(vel))
        })
    }

    /// The velocity plans of every position.
    pub fn velocities(&self, sc: &KinScales) -> Result<Vec<Arc<Velocity>>, StudyError> {
        let n = self.positions(sc.l)?.positions.len();
        (0..n).map(|k| self.velocity(sc, k)).collect()
    }

    /// The acceleration plan at position `k` (from its velocity plan) with its rows, at its
    /// μ_a ([`Session::plan_scale`]).
    pub fn acceleration(&self, sc: &KinScales, k: usize) -> Cached<Acceleration> {
        let v = self.plan_scale(PlanKind::Velocity, k)?;
        let a = self.plan_scale(PlanKind::Acceleration, k)?;
        self.caches.get::<AccelerationPlans>((sc.l, v, a, k), || {
            let plan = self.positions(sc.l)?;
            let vel = self.velocity(sc, k)?;
            let vp = match vel.as_ref() {
                Velocity::Built { plan: vp, .. } => vp,
                Velocity::Refused(why) => {
                    return Err(KinError::NoVelocityPlan {
                        position: plan.positions[k].label.clone(),
                        why: why.clone(),
                    }
                    .into())
                }
            };
            let w1 = self.w1()?;
            let (ap, rows) =
                kinematics::acceleration(&plan, k, sc.l.value(), w1, vp, a, &self.ctx()?)?;
            self.logged("acceleration plan", &plan.positions[k].label, a);
            Ok(Arc::new(Acceleration { plan: ap, rows }))
        })
    }

    /// The positions whose acceleration plans the scene asks for; else those of its force
    /// analysis, whose inertia forces are read off these plans (the textbook draws them for
    /// the positions it analyses); else the textbook's two: mid working stroke, mid return,
    /// none of those whose plans take a μ of their own. As indices into the plan's positions.
    pub fn acceleration_positions(&self) -> Result<Vec<usize>, StudyError> {
        let poses = self.poses()?;
        let labels = position_labels(&poses);
        let own = self.own_scale_positions(PlanKind::Velocity)?;
        let forces = self.scene.forces.as_ref().map(|f| f.positions.as_slice());
        let asked = self
            .spec()
            .acceleration_positions
            .as_deref()
            .or(forces.filter(|p| !p.is_empty()));
        Ok(acceleration_indices(
            &labels,
            poses.extremes.as_ref().map(|ex| ex.work_travel),
            (asked, &own),
            |a, b| same_configuration(&poses, a, b),
        )?)
    }

    /// The positions whose plans of `kind` the scene draws at a μ of their own, as indices into
    /// the plan's positions: `kinematics.own_scale` (both kinds of plan), and for the
    /// acceleration plans `kinematics.own_scale_a`, each of which must be an acceleration
    /// position.
    pub fn own_scale_positions(&self, kind: PlanKind) -> Result<Vec<usize>, StudyError> {
        let poses = self.poses()?;
        let labels = position_labels(&poses);
        let spec = self.spec();
        let mut own = position_indices(&labels, &spec.own_scale, "own_scale")?;
        if kind == PlanKind::Acceleration && !spec.own_scale_a.is_empty() {
            let drawn = self.acceleration_positions()?;
            for k in position_indices(&labels, &spec.own_scale_a, "own_scale_a")? {
                if !drawn.contains(&k) {
                    return Err(kinematics::KinError::NoAccelerationPlan {
                        label: labels[k].0.to_string(),
                        drawn: drawn.iter().map(|&d| labels[d].0.to_string()).collect(),
                    }
                    .into());
                }
                if !own.contains(&k) {
                    own.push(k);
                }
            }
        }
        Ok(own)
    }

    /// The displacement diagrams read off the plan at μ_l = `l`, at the chart's scales.
    pub fn diagrams(&self, l: Scale, chart: ChartScales) -> MaybeCached<KinDiagrams> {
        self.caches.get::<MotionDiagrams>((l, chart), || {
            let m = self.mechanism("the kinematic analysis")?;
            let plan = self.positions(l)?;
            let spec = KinematicsSpec {
                scale_s: chart.s,
                scale_phi: chart.phi,
                pole_h1: chart.h1,
                pole_h2: chart.h2,
                ..self.spec().clone()
            };
            let d = kinematics::diagrams(
                &plan,
                &m.outputs,
                (&spec, chart.size),
                l,
                self.w1()?,
                &self.ctx()?,
            )?;
            Ok(d.map(Arc::new))
        })
    }

    /// The rocker's ω diagram from the velocity plans at `sc`.
    pub fn rocker(&self, sc: &KinScales) -> MaybeCached<RockerDiagram> {
        self.caches.get::<RockerDiagrams>((sc.l, sc.v), || {
            let m = self.mechanism("the kinematic analysis")?;
            let Some(link) = kinematics::rocker_link(&m.outputs) else {
                return Ok(None);
            };
            let plan = self.positions(sc.l)?;
            let vel = self.velocities(sc)?;
            let plans: Vec<Option<&KinPlan>> = vel.iter().map(|v| v.plan()).collect();
            let rate = (self.w1()?, self.spec().scale_phi);
            let r = kinematics::rocker_diagram(&plan, link, &plans, rate, &self.ctx()?)?;
            Ok(r.map(Arc::new))
        })
    }

    /// The hodograph of the scene's point from the velocity plans at `sc`.
    pub fn hodograph(&self, sc: &KinScales) -> Result<Option<Hodograph>, StudyError> {
        self.caches.get::<Hodographs>((sc.l, sc.v), || {
            let plan = self.positions(sc.l)?;
            let Some(k) = kinematics::hodograph_point(&plan, self.spec().hodograph.as_deref())?
            else {
                return Ok(None);
            };
            let vel = self.velocities(sc)?;
            let plans: Vec<Option<&KinPlan>> = vel.iter().map(|v| v.plan()).collect();
            let fig = kinematics::hodograph(&plan, k, &plans, sc.v, &self.ctx()?);
            Ok(Some(Hodograph {
                point: plain(plan.point_name(k)),
                figure: Arc::new(fig),
            }))
        })
    }

    /// The analytic table of the positions at μ_l = `l`.
    pub fn table(&self, l: Scale) -> Cached<Table> {
        self.caches.get::<AnalyticTables>(l, || {
            let plan = self.positions(l)?;
            Ok(Arc::new(kinematics::analytic_table(&plan, self.w1()?)))
        })
    }

    /// The whole kinematic study at `sc`: every part the sheet and the report show.
    pub fn kinematics(&self, sc: &KinScales) -> Result<Kinematics, StudyError> {
        let plan = self.positions(sc.l)?;
        let velocity = self.velocities(sc)?;
        let acceleration = self
            .acceleration_positions()?
            .into_iter()
            .map(|k| Ok((k, self.acceleration(sc, k)?)))
            .collect::<Result<_, StudyError>>()?;
        let mut refusals = Vec::new();
        let diagrams = refusable(self.diagrams(sc.l, sc.chart), &mut refusals)?;
        let rocker = refusable(self.rocker(sc), &mut refusals)?;
        Ok(Kinematics {
            scales: *sc,
            w1: self.w1()?,
            diagrams,
            rocker,
            refusals,
            hodograph: self.hodograph(sc)?,
            table: self.table(sc.l)?,
            plan,
            velocity,
            acceleration,
        })
    }

    /// The kinematic study's part of the report, at the scene's scales: every reading against
    /// its analytic twin, the analytic table, the notes.
    fn report_kinematics(&self, rep: &mut Report) -> Result<(), StudyError> {
        let k = self.kinematics(&self.kin_scales()?)?;
        let mut notes: Vec<KinematicsNote> = k
            .refusals
            .iter()
            .map(|e| KinematicsNote::Refused(e.to_string()))
            .collect();
        // The diagrams and the rocker's diagram refused for one reason: one note.
        notes.dedup();
        notes.extend(
            k.refused()
                .into_iter()
                .map(|(position, why)| KinematicsNote::NoPlan { position, why }),
        );
        notes.extend(k.plan.positions.iter().filter_map(|p| {
            p.pose.toggle.as_ref().map(|t| KinematicsNote::Toggle {
                position: p.label.clone(),
                group: t.group,
            })
        }));
        notes.extend(crate::kinematics::near_pivot_notes(&k.plan, k.w1));
        let rows = k.rows();
        notes.extend(crate::kinematics::verdict_notes(
            &crate::kinematics::verdicts(&rows),
        ));
        rep.rows.extend(rows);
        rep.tables.push(k.table.as_ref().clone());
        rep.notes.extend(notes.into_iter().map(ReportNote::from));
        Ok(())
    }
}

/// Whether positions `a` and `b` show the mechanism in one configuration: every point off
/// the crank where it was (to 1e-9 of the mechanism's size), the crank alone turned.
fn same_configuration(poses: &PlanPoses, a: usize, b: usize) -> bool {
    let (pa, pb) = (&poses.positions[a].pose.p, &poses.positions[b].pose.p);
    let size = pa.iter().map(|p| p.length()).fold(0.0, f64::max);
    let crank = poses.program.crank_link as usize;
    (0..pa.len())
        .filter(|&k| poses.program.owner(k) != crank)
        .all(|k| pa[k].distance(pb[k]) <= 1e-9 * size)
}

/// Each position's label and whether it is an extreme one, in the plan's order.
fn position_labels(poses: &PlanPoses) -> Vec<(&str, bool)> {
    poses
        .positions
        .iter()
        .map(|p| (p.label.as_str(), p.extreme))
        .collect()
}
