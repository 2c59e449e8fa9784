//! The session over one scene: it computes each study on demand, once, and hands out
//! shared references (`Arc`). Sheets, the report, the bench and the command line all ask
//! the same session, so a plate that needs position 3's acceleration plan constructs
//! exactly that (and the velocity plan it starts from), and a second plate or the report
//! asking for it again gets the same one. "Model only what a scene needs" lives here.
//!
//! Every construction the session carries out is logged ([`Session::constructions`]), so
//! a test can show that nothing is constructed twice.

mod memo;

use crate::check::Row;
use crate::check::{Report, Table};
use crate::construct::{Context, Drafting, Figure};
use crate::forces::balancing::{self, Balancing, BalancingError};
use crate::forces::friction::{self, FrictionError, Solved};
use crate::forces::{ForceError, ForceSpec, PositionForces};
use crate::kinematics::{
    self, acceleration_indices, plans, Diagrams, KinError, KinematicsSpec, RockerDiagram, Velocity,
};
use crate::linkage::{
    plain, plan_poses, plan_positions, KinPlan, LinkageError, Mechanism, PlanKind, PlanPoses,
    PlanRequest, PositionPlan,
};
use crate::scale::{Quantity, Scale};
use crate::scene::{Scene, Start};
use memo::Memo;
use std::sync::{Arc, Mutex};
use thiserror::Error;

/// Preferred drawn length of the crank when the scene gives no μ_l (textbook: 40–60 mm).
const CRANK_MM: f64 = 50.0;
/// The size, mm, of the plans and diagrams whose tolerances the session uses.
const FIGURE_MM: f64 = 300.0;

/// Why a study cannot be carried out.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum StudyError {
    /// The scene has no `[mechanism]` and the study needs one.
    #[error("the scene has no [mechanism]: {0} needs one")]
    NoMechanism(&'static str),
    /// The linkage cannot be constructed.
    #[error(transparent)]
    Linkage(#[from] LinkageError),
    /// The kinematic study cannot be carried out.
    #[error(transparent)]
    Kinematics(#[from] KinError),
    /// The tolerances of the figures cannot be set up.
    #[error("tolerances: {0}")]
    Tolerances(String),
    /// The force analysis cannot be carried out.
    #[error(transparent)]
    Forces(#[from] ForceError),
    /// The scene has no `[forces]` and the study needs it.
    #[error("the scene has no [forces]: {0} needs the loads")]
    NoForces(&'static str),
    /// The scene has no `[dynamics]` and the study needs it.
    #[error("the scene has no [dynamics]: {0} needs it")]
    NoDynamics(&'static str),
    /// The dynamic study cannot be carried out.
    #[error(transparent)]
    Dynamics(#[from] crate::dynamics::DynamicsError),
    /// The scene has no `[balancing]` and the study needs one.
    #[error("the scene has no [balancing]: {0} needs one")]
    NoBalancing(&'static str),
    /// The balancing cannot be carried out.
    #[error(transparent)]
    Balancing(#[from] BalancingError),
    /// A friction case cannot be constructed.
    #[error(transparent)]
    Friction(#[from] FrictionError),
    /// The scene has no `[gears]` and the study needs it.
    #[error("the scene has no [gears]: {0} needs it")]
    NoGears(&'static str),
    /// The gear study cannot be carried out.
    #[error(transparent)]
    Gears(#[from] crate::gears::GearError),
    /// The scene has no `[cam]` and the study needs one.
    #[error("the scene has no [cam]: {0} needs one")]
    NoCam(&'static str),
    /// The cam cannot be constructed.
    #[error(transparent)]
    Cam(#[from] crate::cam::CamError),
}

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
}

/// One construction the session carried out.
#[derive(Debug, Clone, PartialEq)]
pub struct Constructed {
    /// What: `position`, `velocity plan`, `acceleration plan`.
    pub what: &'static str,
    /// At which position (its label).
    pub position: String,
    /// At which μ (of the drawing it was constructed in).
    pub scale: Scale,
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
    pub diagrams: Option<Arc<Diagrams>>,
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
    /// Every reading against its analytic twin, in report order.
    pub fn rows(&self) -> Vec<Row> {
        kinematics::rows(
            self.velocity.iter().map(|v| v.rows()),
            self.acceleration.iter().map(|(_, a)| a.1.as_slice()),
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

type Cached<T> = Result<Arc<T>, StudyError>;

/// A chart refused because the mechanism cannot pass part of the turn: no chart, a note.
fn refusable<T>(r: MaybeCached<T>, refusals: &mut Vec<KinError>) -> MaybeCached<T> {
    match r {
        Err(StudyError::Kinematics(e @ (KinError::NoFullTurn { .. } | KinError::Leap { .. }))) => {
            refusals.push(e);
            Ok(None)
        }
        other => other,
    }
}

type MaybeCached<T> = Result<Option<Arc<T>>, StudyError>;
/// An acceleration plan with its rows.
pub type Acceleration = (KinPlan, Vec<Row>);
/// The hodograph: its point's name without markup (`S3`) and its figure.
pub type Hodograph = (String, Arc<Figure>);

/// The session over one scene.
pub struct Session<'s> {
    scene: &'s Scene,
    drafting: Drafting,
    ctx: Result<Context, StudyError>,
    poses: Memo<(), Cached<PlanPoses>>,
    positions: Memo<Scale, Cached<PositionPlan>>,
    velocity: Memo<(Scale, Scale, usize), Cached<Velocity>>,
    acceleration: Memo<(Scale, Scale, Scale, usize), Cached<Acceleration>>,
    diagrams: Memo<(Scale, ChartScales), MaybeCached<Diagrams>>,
    rocker: Memo<(Scale, Scale), MaybeCached<RockerDiagram>>,
    hodograph: Memo<(Scale, Scale), Result<Option<Hodograph>, StudyError>>,
    table: Memo<Scale, Cached<Table>>,
    forces: Memo<(Scale, Scale, Scale, usize), Cached<PositionForces>>,
    balancing: Memo<(), Cached<Balancing>>,
    friction: Memo<(), Cached<Vec<Solved>>>,
    dynamics: Memo<(), Cached<crate::dynamics::Dynamics>>,
    gears: Memo<(), Cached<crate::gears::GearStudy>>,
    cam: Memo<(), Cached<crate::cam::Cam>>,
    log: Mutex<Vec<Constructed>>,
}

impl<'s> Session<'s> {
    /// A session over `scene`, reading every length with `drafting`.
    pub fn new(scene: &'s Scene, drafting: Drafting) -> Self {
        Self {
            scene,
            drafting,
            ctx: Context::for_model_size(FIGURE_MM, drafting)
                .map_err(|e| StudyError::Tolerances(e.to_string())),
            poses: Memo::default(),
            positions: Memo::default(),
            velocity: Memo::default(),
            acceleration: Memo::default(),
            diagrams: Memo::default(),
            rocker: Memo::default(),
            hodograph: Memo::default(),
            table: Memo::default(),
            forces: Memo::default(),
            balancing: Memo::default(),
            friction: Memo::default(),
            dynamics: Memo::default(),
            gears: Memo::default(),
            cam: Memo::default(),
            log: Mutex::new(Vec::new()),
        }
    }

    /// The scene.
    pub fn scene(&self) -> &'s Scene {
        self.scene
    }

    /// The drafting model of every reading.
    pub fn drafting(&self) -> Drafting {
        self.drafting
    }

    /// Every construction carried out so far, in order.
    pub fn constructions(&self) -> Vec<Constructed> {
        self.log.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    fn logged(&self, what: &'static str, position: &str, scale: Scale) {
        self.log
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .push(Constructed {
                what,
                position: position.to_string(),
                scale,
            });
    }

    /// The mechanism, for a study that needs it.
    pub fn mechanism(&self, study: &'static str) -> Result<&'s Mechanism, StudyError> {
        self.scene
            .mechanism
            .as_ref()
            .ok_or(StudyError::NoMechanism(study))
    }

    /// The positions the scene asks for.
    pub fn plan_request(&self) -> PlanRequest {
        let p = &self.scene.positions;
        PlanRequest {
            count: p.count,
            start: match p.start {
                Start::WorkingStroke => None,
                Start::Angle(a) => Some(a),
            },
            other_extreme: p.other_extreme,
            continuity: p.continuity,
        }
    }

    /// The positions solved analytically (nothing constructed): what sheets size by.
    pub fn poses(&self) -> Cached<PlanPoses> {
        self.poses.get((), || {
            let m = self.mechanism("the plan of positions")?;
            Ok(Arc::new(plan_poses(m, &self.plan_request())?))
        })
    }

    /// The plan of positions constructed at μ_l = `scale_l`.
    pub fn positions(&self, scale_l: Scale) -> Cached<PositionPlan> {
        self.positions.get(scale_l, || {
            let m = self.mechanism("the plan of positions")?;
            let plan = plan_positions(m, &self.plan_request(), scale_l, self.drafting)?;
            for p in &plan.positions {
                self.logged("position", &p.label, scale_l);
            }
            Ok(Arc::new(plan))
        })
    }

    /// μ_l as the scene gives it, or chosen from the crank the textbook way (the crank drawn
    /// about 50 mm).
    pub fn scale_l(&self) -> Result<Scale, StudyError> {
        match self.scene.scale_l {
            Some(s) => Ok(s),
            None => {
                let m = self.mechanism("the plan of positions")?;
                Ok(kinematics::round_scale(
                    m.crank.length,
                    CRANK_MM,
                    Quantity::Length,
                )?)
            }
        }
    }

    fn spec(&self) -> &KinematicsSpec {
        &self.scene.kinematics
    }

    fn w1(&self) -> Result<f64, StudyError> {
        Ok(kinematics::crank_rate(
            &self.mechanism("the kinematic analysis")?.crank,
        ))
    }

    fn ctx(&self) -> Result<Context, StudyError> {
        self.ctx.clone()
    }

    /// The kinematic study's scales as the scene gives them, the rest chosen the textbook way.
    pub fn kin_scales(&self) -> Result<KinScales, StudyError> {
        let m = self.mechanism("the kinematic analysis")?;
        let (v, a) = kinematics::plan_scales(&m.crank, self.spec())?;
        let spec = self.spec();
        Ok(KinScales {
            l: self.scale_l()?,
            v,
            a,
            chart: ChartScales {
                s: spec.scale_s,
                phi: spec.scale_phi,
                h1: spec.pole_h1,
                h2: spec.pole_h2,
            },
        })
    }

    /// The velocity plan at position `k` of the plan at μ_l = `l`, at μ_v = `v`.
    pub fn velocity(&self, l: Scale, v: Scale, k: usize) -> Cached<Velocity> {
        self.velocity.get((l, v, k), || {
            let plan = self.positions(l)?;
            let vel = plans::velocity(&plan, k, l.value(), self.w1()?, v, &self.ctx()?)?;
            self.logged("velocity plan", &plan.positions[k].label, v);
            Ok(Arc::new(vel))
        })
    }

    /// The velocity plans of every position.
    pub fn velocities(&self, l: Scale, v: Scale) -> Result<Vec<Arc<Velocity>>, StudyError> {
        let n = self.positions(l)?.positions.len();
        (0..n).map(|k| self.velocity(l, v, k)).collect()
    }

    /// The acceleration plan at position `k` (from its velocity plan) with its rows.
    pub fn acceleration(&self, sc: &KinScales, k: usize) -> Cached<Acceleration> {
        self.acceleration.get((sc.l, sc.v, sc.a, k), || {
            let plan = self.positions(sc.l)?;
            let vel = self.velocity(sc.l, sc.v, k)?;
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
            let ap = plans::acceleration(&plan, k, sc.l.value(), w1, vp, sc.a, &self.ctx()?)?;
            self.logged("acceleration plan", &plan.positions[k].label, sc.a);
            Ok(Arc::new(ap))
        })
    }

    /// The positions whose acceleration plans the scene asks for (or the textbook's two:
    /// mid working stroke, mid return), as indices into the plan's positions.
    pub fn acceleration_positions(&self) -> Result<Vec<usize>, StudyError> {
        let poses = self.poses()?;
        let labels: Vec<(&str, bool)> = poses
            .positions
            .iter()
            .map(|p| (p.label.as_str(), p.extreme))
            .collect();
        Ok(acceleration_indices(
            &labels,
            poses.extremes.as_ref().map(|ex| ex.work_travel),
            self.spec().acceleration_positions.as_deref(),
        )?)
    }

    /// The displacement diagrams read off the plan at μ_l = `l`, at the chart's scales.
    pub fn diagrams(&self, l: Scale, chart: ChartScales) -> MaybeCached<Diagrams> {
        self.diagrams.get((l, chart), || {
            let m = self.mechanism("the kinematic analysis")?;
            let plan = self.positions(l)?;
            let spec = KinematicsSpec {
                scale_s: chart.s,
                scale_phi: chart.phi,
                pole_h1: chart.h1,
                pole_h2: chart.h2,
                ..self.spec().clone()
            };
            let d = kinematics::diagrams::diagrams(
                &plan,
                &m.outputs,
                &spec,
                l,
                self.w1()?,
                &self.ctx()?,
            )?;
            Ok(d.map(Arc::new))
        })
    }

    /// The rocker's ω diagram from the velocity plans at (μ_l, μ_v).
    pub fn rocker(&self, l: Scale, v: Scale) -> MaybeCached<RockerDiagram> {
        self.rocker.get((l, v), || {
            let m = self.mechanism("the kinematic analysis")?;
            let Some(link) = kinematics::rocker::rocker_link(&m.outputs) else {
                return Ok(None);
            };
            let plan = self.positions(l)?;
            let vel = self.velocities(l, v)?;
            let plans: Vec<Option<&KinPlan>> = vel.iter().map(|v| v.plan()).collect();
            let r =
                kinematics::rocker::rocker_diagram(&plan, link, &plans, self.w1()?, &self.ctx()?)?;
            Ok(r.map(Arc::new))
        })
    }

    /// The hodograph of the scene's point from the velocity plans at (μ_l, μ_v).
    pub fn hodograph(&self, l: Scale, v: Scale) -> Result<Option<Hodograph>, StudyError> {
        self.hodograph.get((l, v), || {
            let plan = self.positions(l)?;
            let Some(k) =
                kinematics::hodograph::hodograph_point(&plan, self.spec().hodograph.as_deref())?
            else {
                return Ok(None);
            };
            let vel = self.velocities(l, v)?;
            let plans: Vec<Option<&KinPlan>> = vel.iter().map(|v| v.plan()).collect();
            let fig = kinematics::hodograph::hodograph(&plan, k, &plans, v, &self.ctx()?);
            Ok(Some((plain(plan.point_name(k)), Arc::new(fig))))
        })
    }

    /// The analytic table of the positions at μ_l = `l`.
    pub fn table(&self, l: Scale) -> Cached<Table> {
        self.table.get(l, || {
            let plan = self.positions(l)?;
            Ok(Arc::new(kinematics::table::analytic_table(
                &plan,
                self.w1()?,
            )))
        })
    }

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
        self.forces.get((sc.l, sc.v, sc.a, k), || {
            let spec = self.force_spec("the force analysis")?;
            let plan = self.positions(sc.l)?;
            let vel = self.velocity(sc.l, sc.v, k)?;
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

    /// The whole kinematic study at `sc`: every part the sheet and the report show.
    pub fn kinematics(&self, sc: &KinScales) -> Result<Kinematics, StudyError> {
        let plan = self.positions(sc.l)?;
        let velocity = self.velocities(sc.l, sc.v)?;
        let acceleration = self
            .acceleration_positions()?
            .into_iter()
            .map(|k| Ok((k, self.acceleration(sc, k)?)))
            .collect::<Result<_, StudyError>>()?;
        let mut refusals = Vec::new();
        let diagrams = refusable(self.diagrams(sc.l, sc.chart), &mut refusals)?;
        let rocker = refusable(self.rocker(sc.l, sc.v), &mut refusals)?;
        Ok(Kinematics {
            scales: *sc,
            w1: self.w1()?,
            diagrams,
            rocker,
            refusals,
            hodograph: self.hodograph(sc.l, sc.v)?,
            table: self.table(sc.l)?,
            plan,
            velocity,
            acceleration,
        })
    }

    /// The balancing of the scene's rotor (`[balancing]`), constructed once.
    pub fn balancing(&self) -> Cached<Balancing> {
        self.balancing.get((), || {
            let spec = self
                .scene
                .balancing
                .as_ref()
                .ok_or(StudyError::NoBalancing("the balancing of a rotor"))?;
            let b = balancing::balance(spec, &self.ctx()?)?;
            self.logged("polygon of static moments", "", b.scale_mr);
            Ok(Arc::new(b))
        })
    }

    /// Every `[[friction.case]]` of the scene constructed and read (empty without a
    /// `[friction]` section).
    pub fn friction(&self) -> Cached<Vec<Solved>> {
        self.friction.get((), || {
            let ctx = self.ctx()?;
            let solved = self
                .scene
                .friction
                .iter()
                .map(|c| friction::solve(c, &ctx))
                .collect::<Result<Vec<_>, _>>()?;
            for s in &solved {
                for d in &s.drawings {
                    self.logged("friction", &s.case.name, d.figure.scale);
                }
            }
            Ok(Arc::new(solved))
        })
    }

    /// The dynamic study (`[dynamics]`) at the kinematic study's scales: the reduction over
    /// the scene's numbered positions from their velocity plans (the same plans when
    /// `dynamics.count` is the scene's count; its own plan of positions otherwise), the
    /// diagrams, the exact energy equation and the flywheel.
    pub fn dynamics(&self) -> Cached<crate::dynamics::Dynamics> {
        self.dynamics.get((), || {
            let spec = self
                .scene
                .dynamics
                .as_ref()
                .ok_or(StudyError::NoDynamics("the dynamic study"))?;
            let forces = self.force_spec("the dynamic study")?;
            let sc = self.kin_scales()?;
            let w1 = self.w1()?;
            let ctx = self.ctx()?;
            let count = spec.count.unwrap_or(self.scene.positions.count);
            let d = if count == self.scene.positions.count {
                let plan = self.positions(sc.l)?;
                let vel = self.velocities(sc.l, sc.v)?;
                let vps: Vec<Option<&KinPlan>> = vel.iter().map(|v| v.plan()).collect();
                crate::dynamics::analyse(spec, forces, &plan, &vps, w1, &ctx)?
            } else {
                let m = self.mechanism("the dynamic study")?;
                let req = PlanRequest {
                    count,
                    other_extreme: false,
                    ..self.plan_request()
                };
                let plan = plan_positions(m, &req, sc.l, self.drafting)?;
                let vel = (0..plan.positions.len())
                    .map(|k| plans::velocity(&plan, k, sc.l.value(), w1, sc.v, &ctx))
                    .collect::<Result<Vec<_>, _>>()?;
                let vps: Vec<Option<&KinPlan>> = vel.iter().map(|v| v.plan()).collect();
                crate::dynamics::analyse(spec, forces, &plan, &vps, w1, &ctx)?
            };
            self.logged("dynamics diagrams", "", d.diagrams.scale_a);
            Ok(Arc::new(d))
        })
    }

    /// The gear study of the scene (`[gears]`): the pair's meshing picture and the wheels
    /// cut by the rack, constructed once.
    pub fn gears(&self) -> Cached<crate::gears::GearStudy> {
        self.gears.get((), || {
            let spec = self
                .scene
                .gears
                .as_ref()
                .ok_or(StudyError::NoGears("the gear study"))?;
            let g = crate::gears::study(spec, &self.ctx()?)?;
            if let Some((_, m)) = &g.pair {
                self.logged("meshing picture", "", m.scale);
            }
            for (name, r) in &g.racks {
                self.logged("rack generation", name, r.scale);
            }
            Ok(Arc::new(g))
        })
    }

    /// The scene's cam (`[cam]`): its diagrams, minimum radius and profile, constructed once.
    pub fn cam(&self) -> Cached<crate::cam::Cam> {
        self.cam.get((), || {
            let spec = self
                .scene
                .cam
                .as_ref()
                .ok_or(StudyError::NoCam("the cam sheet"))?;
            let c = crate::cam::build(spec, &self.ctx()?)?;
            self.logged("profile by inversion", "", c.inversion.scale);
            Ok(Arc::new(c))
        })
    }

    /// The report of every study of the scene: the kinematic study of its mechanism (with its
    /// force analysis), the balancing of its rotor and its friction cases, each that the scene
    /// has, rows and notes in that order. A scene with none is refused for want of a mechanism.
    pub fn report(&self) -> Result<Report, StudyError> {
        let mut rep = match self.scene.mechanism {
            Some(_) => self.kinematics_report()?,
            None if self.scene.balancing.is_none()
                && self.scene.friction.is_empty()
                && self.scene.gears.is_none()
                && self.scene.cam.is_none() =>
            {
                return Err(StudyError::NoMechanism("the report"))
            }
            None => Report {
                scene: self.scene.stem.clone(),
                rows: Vec::new(),
                tables: Vec::new(),
                notes: Vec::new(),
            },
        };
        if self.scene.balancing.is_some() {
            let b = self.balancing()?;
            rep.rows.extend(b.rows());
            rep.notes.extend(b.notes());
        }
        for s in self.friction()?.iter() {
            rep.rows.extend(s.rows());
            rep.notes.extend(s.notes.iter().cloned());
        }
        if self.scene.dynamics.is_some() {
            let d = self.dynamics()?;
            rep.rows.extend(crate::dynamics::rows(&d));
            rep.notes.extend(crate::dynamics::notes(&d));
        }
        if self.scene.gears.is_some() {
            let g = self.gears()?;
            rep.rows.extend(g.rows());
            rep.notes.extend(g.notes());
        }
        if self.scene.cam.is_some() {
            let c = self.cam()?;
            rep.rows.extend(c.rows());
            rep.notes.extend(c.notes());
        }
        Ok(rep)
    }

    /// The report of the kinematic study at the scene's scales: every reading against its
    /// analytic twin, the analytic table, the notes.
    fn kinematics_report(&self) -> Result<Report, StudyError> {
        let k = self.kinematics(&self.kin_scales()?)?;
        let mut notes: Vec<String> = k.refusals.iter().map(ToString::to_string).collect();
        // The diagrams and the rocker's diagram refused for one reason: one note.
        notes.dedup();
        notes.extend(
            k.refused()
                .into_iter()
                .map(|(pos, why)| format!("position {pos}: no velocity plan: {why}")),
        );
        notes.extend(k.plan.positions.iter().filter_map(|p| {
            p.pose.toggle.as_ref().map(|t| {
                format!(
                    "position {}: the analytic velocities and accelerations are not determined (group {} at its toggle): null",
                    p.label,
                    t.group + 1
                )
            })
        }));
        notes.extend(crate::kinematics::near_pivot_notes(&k.plan, k.w1));
        let mut rows = k.rows();
        if self.scene.forces.is_some() {
            for i in self.force_positions()? {
                let f = self.forces(&k.scales, i)?;
                rows.extend(f.rows.iter().cloned());
                rows.extend(f.residual_rows());
                notes.extend(crate::forces::notes(&f));
            }
            notes.extend(crate::forces::seed_notes(
                &self.force_spec("the force analysis")?.seed,
                &rows,
            ));
        }
        Ok(Report {
            scene: self.scene.stem.clone(),
            rows,
            tables: vec![k.table.as_ref().clone()],
            notes,
        })
    }
}
