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
//! session's `memo::Caches`) and its part of the report, reached from its row of the
//! registration table (`scene::STUDIES`, which gives the report's order) by one `match`.
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
pub use forces::{ForceRoute, Unbalanced, EQUILIBRIUM_TOLERANCE};
pub use kinematics::{ChartScales, KinScales, Kinematics};
pub use scales::KinSheets;

use crate::balancing::{Balancing, BalancingError};
use crate::check::Row;
use crate::check::{Report, ReportNote, Table};
use crate::construct::{Context, Drafting, Figure};
use crate::forces::{ForceError, ForceSpec, PositionForces};
use crate::friction::{FrictionError, Solved};
use crate::kinematics::{
    acceleration_indices, position_indices, KinDiagrams, KinError, KinematicsSpec, RockerDiagram,
    Velocity,
};
use crate::linkage::{
    plain, plan_poses, plan_positions, KinPlan, LinkageError, Mechanism, PlanKind, PlanPoses,
    PlanRequest, PositionPlan,
};
use crate::scale::Scale;
use crate::scene::{Scene, Section, Start, STUDIES};
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
#[derive(Debug, Clone)]
pub struct Acceleration {
    /// The plan.
    pub plan: KinPlan,
    /// Its readings against their analytic twins.
    pub rows: Vec<Row>,
}

/// The hodograph of the scene's point.
#[derive(Debug, Clone, PartialEq)]
pub struct Hodograph {
    /// The point's name without markup (`S3`).
    pub point: String,
    /// The hodograph's figure.
    pub figure: Arc<Figure>,
}

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

/// One study's part of the report: what it adds.
type Part = fn(&Session<'_>, &mut Report) -> Result<(), StudyError>;

/// The part of the report of the study of `section`'s row of the registration table
/// ([`STUDIES`]); its caches and its part are declared in its own file.
fn part(section: Section) -> Part {
    match section {
        Section::Mechanism => kinematics::PART,
        Section::Forces => forces::PART,
        Section::Balancing => balancing::PART,
        Section::Friction => friction::PART,
        Section::Dynamics => dynamics::PART,
        Section::Gears => gears::PART,
        Section::Cam => cam::PART,
    }
}

/// What sessions over several scenes share: the results that are a function of a part of a
/// scene alone (the gear pair's blocking contour), so that a batch's variants, which mostly
/// share their gears, make each about once. A session made alone keeps its own.
#[derive(Default)]
pub struct Shared {
    /// The blocking contours, by pair and criterion.
    pub blocking: crate::gears::blocking::Studies,
}

/// The session over one scene.
pub struct Session<'s> {
    scene: &'s Scene,
    drafting: Drafting,
    ctx: Result<Context, StudyError>,
    caches: Caches,
    shared: Arc<Shared>,
    log: Mutex<Vec<Constructed>>,
}

impl<'s> Session<'s> {
    /// A session over `scene`, reading every length with `drafting`.
    pub fn new(scene: &'s Scene, drafting: Drafting) -> Self {
        Self::sharing(scene, drafting, Arc::default())
    }

    /// A session over `scene` (as [`Session::new`]) that takes what it shares with other
    /// sessions from `shared` and keeps it there.
    pub fn sharing(scene: &'s Scene, drafting: Drafting, shared: Arc<Shared>) -> Self {
        Self {
            scene,
            drafting,
            ctx: Context::for_model_size(FIGURE_MM, drafting).map_err(StudyError::from),
            caches: Caches::default(),
            shared,
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
            let m = self.mechanism("the position diagram")?;
            Ok(Arc::new(plan_poses(m, &self.plan_request())?))
        })
    }

    /// The plan of positions constructed at μ_l = `scale_l`.
    pub fn positions(&self, scale_l: Scale) -> Cached<PositionPlan> {
        self.caches.get::<Positions>(scale_l, || {
            let m = self.mechanism("the position diagram")?;
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

    /// The report of every study of the scene (each row of [`STUDIES`] the scene has, its
    /// rows and notes in that order). A scene with none is refused for want of a mechanism.
    pub fn report(&self) -> Result<Report, StudyError> {
        let mut rep = Report {
            scene: self.scene.stem.clone(),
            rows: Vec::new(),
            tables: Vec::new(),
            notes: Vec::new(),
        };
        let mut studies = STUDIES.iter().filter(|s| (s.has)(self.scene)).peekable();
        if studies.peek().is_none() {
            return Err(StudyError::NoMechanism("the report"));
        }
        for study in studies {
            part(study.section)(self, &mut rep)?;
        }
        let seed = crate::check::seed_notes(&self.scene.seed, &rep.rows);
        rep.notes.extend(seed.into_iter().map(ReportNote::from));
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
