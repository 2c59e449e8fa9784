//! The session over one scene: it computes each study on demand, once, and hands out
//! shared references (`Arc`). Sheets, the report, the bench and the command line all ask
//! the same session, so a plate that needs position 3's acceleration plan constructs
//! exactly that (and the velocity plan it starts from), and a second plate or the report
//! asking for it again gets the same one. "Model only what a scene needs" lives here.
//!
//! Each figure's scales are decided once, before anything is constructed ([`Session::scale_l`],
//! [`Session::kin_scales`]): every sheet and the report ask for them, so the report reads the
//! very constructions the plates draw.
//!
//! Each study lives in its own file: its caches (a `memo::Cache` marker each, kept in the
//! session's `memo::Caches`) and its part of the report, registered once in `PARTS`.
//!
//! Every construction the session carries out is logged ([`Session::constructions`]), so
//! a test can show that nothing is constructed twice.

mod balancing;
mod cam;
mod dynamics;
mod error;
mod forces;
mod friction;
mod gears;
mod kinematics;
mod memo;
mod scales;

pub use error::StudyError;
pub use forces::EQUILIBRIUM_TOLERANCE;
pub use kinematics::{ChartScales, KinScales, Kinematics};
pub use scales::KinSheets;

use crate::check::Row;
use crate::check::{Note, Report, Table};
use crate::construct::{Context, Drafting, Figure};
use crate::forces::balancing::{Balancing, BalancingError};
use crate::forces::friction::{FrictionError, Solved};
use crate::forces::{ForceError, ForceSpec, PositionForces};
use crate::kinematics::{
    acceleration_indices, Diagrams, KinError, KinematicsSpec, RockerDiagram, Velocity,
};
use crate::linkage::{
    plain, plan_poses, plan_positions, KinPlan, LinkageError, Mechanism, PlanKind, PlanPoses,
    PlanRequest, PositionPlan,
};
use crate::scale::Scale;
use crate::scene::{Scene, Start};
use memo::{Cache, Caches};
use std::sync::{Arc, Mutex};
use thiserror::Error;

/// The size, mm, of the plans and diagrams whose tolerances the session uses.
const FIGURE_MM: f64 = 300.0;

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

type Cached<T> = Result<Arc<T>, StudyError>;

type MaybeCached<T> = Result<Option<Arc<T>>, StudyError>;
/// An acceleration plan with its rows.
pub type Acceleration = (KinPlan, Vec<Row>);
/// The hodograph: its point's name without markup (`S3`) and its figure.
pub type Hodograph = (String, Arc<Figure>);

/// The positions solved analytically.
struct Poses;
impl Cache for Poses {
    type Key = ();
    type Value = Cached<PlanPoses>;
}

/// The plan of positions by μ_l.
struct Positions;
impl Cache for Positions {
    type Key = Scale;
    type Value = Cached<PositionPlan>;
}

/// One study's part of the report: whether the scene has the study, and what it adds.
struct Part {
    has: fn(&Scene) -> bool,
    add: fn(&Session<'_>, &mut Report) -> Result<(), StudyError>,
}

/// Every study's part of the report, in the report's order. A study registers here once; its
/// caches and its part are declared in its own file.
const PARTS: [Part; 7] = [
    kinematics::PART,
    forces::PART,
    balancing::PART,
    friction::PART,
    dynamics::PART,
    gears::PART,
    cam::PART,
];

/// The session over one scene.
pub struct Session<'s> {
    scene: &'s Scene,
    drafting: Drafting,
    ctx: Result<Context, StudyError>,
    caches: Caches,
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
            caches: Caches::default(),
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

    /// Every construction carried out so far, in the order each was finished: the sheets of
    /// a scene are built side by side ([`crate::sheets::build_all`]), so the constructions of
    /// different sheets interleave as their threads run; those of one study keep their order.
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
        self.caches.get::<Poses>((), || {
            let m = self.mechanism("the plan of positions")?;
            Ok(Arc::new(plan_poses(m, &self.plan_request())?))
        })
    }

    /// The plan of positions constructed at μ_l = `scale_l`.
    pub fn positions(&self, scale_l: Scale) -> Cached<PositionPlan> {
        self.caches.get::<Positions>(scale_l, || {
            let m = self.mechanism("the plan of positions")?;
            let plan = plan_positions(m, &self.plan_request(), scale_l, self.drafting)?;
            for p in &plan.positions {
                self.logged("position", &p.label, scale_l);
            }
            Ok(Arc::new(plan))
        })
    }

    fn ctx(&self) -> Result<Context, StudyError> {
        self.ctx.clone()
    }

    /// The report of every study of the scene (`PARTS`, each the scene has, rows and notes
    /// in that order). A scene with none is refused for want of a mechanism.
    pub fn report(&self) -> Result<Report, StudyError> {
        let mut rep = Report {
            scene: self.scene.stem.clone(),
            rows: Vec::new(),
            tables: Vec::new(),
            notes: Vec::new(),
        };
        let mut parts = PARTS.iter().filter(|p| (p.has)(self.scene)).peekable();
        if parts.peek().is_none() {
            return Err(StudyError::NoMechanism("the report"));
        }
        for part in parts {
            (part.add)(self, &mut rep)?;
        }
        let seed = crate::check::seed_notes(&self.scene.seed, &rep.rows);
        rep.notes.extend(seed.into_iter().map(Note::from));
        Ok(rep)
    }
}

/// Run `run` on a session over the scene `constructions/<name>.toml`, every length read
/// exactly (the studies' tests).
#[cfg(test)]
fn with_scene(name: &str, run: impl Fn(&Session<'_>)) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("constructions")
        .join(format!("{name}.toml"));
    let scene = crate::scene::load(&path).expect("scene");
    run(&Session::new(&scene, Drafting::EXACT));
}
