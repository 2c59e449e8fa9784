//! The scene file as written: serde structs in the file's units (mm, degrees, rpm), every key
//! optional so that a missing key is reported with its full path by the validator. Unknown
//! keys are refused by the TOML reader.

use super::check::number;
use serde::Deserialize;
use std::fmt;

/// The whole file.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawScene {
    pub task: Option<RawTask>,
    pub mechanism: Option<RawMechanism>,
    pub positions: Option<RawPositions>,
    pub plates: Option<RawPlates>,
    pub kinematics: Option<RawKinematics>,
    pub forces: Option<RawForces>,
    pub balancing: Option<RawBalancing>,
    pub friction: Option<super::friction::RawFriction>,
    pub dynamics: Option<super::dynamics::RawDynamics>,
    pub gears: Option<super::gears::RawGears>,
    pub planetary: Option<super::planetary::RawPlanetary>,
    pub cam: Option<super::cam_raw::RawCam>,
    pub answer_key: Option<RawAnswerKey>,
    pub seed: Option<Vec<RawSeedValue>>,
}

/// `[answer_key]`: the values an instructor checks over a class's variants (`tmm batch`).
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawAnswerKey {
    #[serde(default)]
    pub values: Vec<String>,
}

/// `[task]`: the title block.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawTask {
    pub title: Option<String>,
    pub designation: Option<String>,
    pub author: Option<String>,
    pub checked: Option<String>,
    pub organisation: Option<String>,
    pub group: Option<String>,
    pub year: Option<String>,
    pub note: Option<String>,
    pub university: Option<String>,
    pub city: Option<String>,
    pub genre: Option<String>,
    pub ru: Option<TaskText>,
    pub uk: Option<TaskText>,
    pub en: Option<TaskText>,
}

/// `[task.ru]`, `[task.uk]`, `[task.en]`: the texts of `[task]` a language replaces (each
/// `None`: the scene's own), read as written.
#[derive(Debug, Clone, PartialEq, Eq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TaskText {
    /// The title.
    pub title: Option<String>,
    /// The designation (English: else the scene's own in Latin letters).
    pub designation: Option<String>,
    /// The student.
    pub author: Option<String>,
    /// The instructor.
    pub checked: Option<String>,
    /// The department.
    pub organisation: Option<String>,
    /// The university.
    pub university: Option<String>,
    /// The city.
    pub city: Option<String>,
    /// The group.
    pub group: Option<String>,
}

/// `[mechanism]`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawMechanism {
    pub scale_l: Option<f64>,
    #[serde(default)]
    pub fixed: Vec<RawFixed>,
    pub crank: Option<RawCrank>,
    #[serde(default)]
    pub group: Vec<RawGroup>,
    #[serde(default)]
    pub point: Vec<RawPoint>,
    #[serde(default)]
    pub redundant: Vec<RawRedundant>,
    #[serde(default)]
    pub output: Vec<RawOutput>,
}

/// `[[mechanism.fixed]]`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawFixed {
    pub name: Option<String>,
    pub at: Option<Vec<f64>>,
}

/// `[mechanism.crank]`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawCrank {
    pub link: Option<i64>,
    pub centre: Option<String>,
    pub pin: Option<String>,
    pub length: Option<f64>,
    pub omega: Option<f64>,
    pub n: Option<f64>,
    pub sense: Option<String>,
}

/// `[[mechanism.group]]`: the union of the keys of all five kinds.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawGroup {
    pub kind: Option<String>,
    pub links: Option<Vec<i64>>,
    pub a: Option<String>,
    pub la: Option<f64>,
    pub b: Option<String>,
    pub lb: Option<f64>,
    pub c: Option<String>,
    pub offset: Option<f64>,
    pub guide: Option<RawGuide>,
    pub guide_i: Option<RawGuide>,
    pub guide_j: Option<RawGuide>,
    pub slide: Option<RawDir>,
    pub joint: Option<String>,
    pub branch: Option<String>,
}

/// A guide: `{ through = "C", dir = 0.0, offset = 745.0 }`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawGuide {
    pub through: Option<String>,
    pub dir: Option<RawDir>,
    pub offset: Option<f64>,
    pub link: Option<i64>,
}

/// A direction: degrees in the frame, or along two known points.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(
    untagged,
    expecting = "expected a direction: degrees, or { from = \"A\", to = \"B\", angle = 0.0 }"
)]
pub(crate) enum RawDir {
    /// A frame direction, degrees.
    Degrees(f64),
    /// `{ from = "A", to = "B", angle = 0.0 }`.
    Along(RawAlong),
}

/// The table form of a direction.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawAlong {
    pub from: Option<String>,
    pub to: Option<String>,
    pub angle: Option<f64>,
}

/// `[[mechanism.point]]`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPoint {
    pub name: Option<String>,
    pub link: Option<i64>,
    pub along: Option<f64>,
    pub across: Option<f64>,
}

/// `[[mechanism.redundant]]`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawRedundant {
    pub name: Option<String>,
    pub kind: Option<String>,
    pub links: Option<Vec<i64>>,
    pub reason: Option<String>,
}

/// `[[mechanism.output]]`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawOutput {
    pub rocker: Option<i64>,
    pub slider: Option<String>,
    pub dir: Option<f64>,
}

/// `[positions]`.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPositions {
    pub count: Option<i64>,
    pub start: Option<RawStart>,
    pub other_extreme: Option<bool>,
    pub assembly: Option<String>,
}

/// `start = "working-stroke"` or a crank angle in degrees.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(
    untagged,
    expecting = "expected \"working-stroke\" or a crank angle in degrees"
)]
pub(crate) enum RawStart {
    /// A word (only `working-stroke` is valid).
    Word(String),
    /// Degrees.
    Degrees(f64),
}

/// `[plates]`.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPlates {
    pub wanted: Option<Vec<String>>,
}

/// `[kinematics]`.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawKinematics {
    pub scale_v: Option<f64>,
    pub scale_a: Option<f64>,
    pub acceleration_positions: Option<Vec<String>>,
    pub own_scale: Option<Vec<String>>,
    pub own_scale_a: Option<Vec<String>>,
    pub diagram: Option<String>,
    pub scale_s: Option<f64>,
    pub scale_phi: Option<f64>,
    pub pole_h1: Option<f64>,
    pub pole_h2: Option<f64>,
    pub hodograph: Option<String>,
    pub differentiation: Option<String>,
}

/// `[balancing]`.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawBalancing {
    pub kind: Option<String>,
    pub omega: Option<f64>,
    pub radius: Option<f64>,
    pub radii: Option<Vec<f64>>,
    pub planes: Option<Vec<f64>>,
    pub scale_mr: Option<f64>,
    pub scale_mrz: Option<f64>,
    pub scale_l: Option<f64>,
    #[serde(default)]
    pub mass: Vec<RawMass>,
}

/// `[[balancing.mass]]`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawMass {
    pub mass: Option<f64>,
    pub radius: Option<f64>,
    pub angle: Option<f64>,
    pub z: Option<f64>,
}

impl fmt::Display for RawDir {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RawDir::Degrees(d) => write!(f, "{}", number(*d)),
            RawDir::Along(a) => {
                let from = a.from.as_deref().unwrap_or("?");
                let to = a.to.as_deref().unwrap_or("?");
                write!(
                    f,
                    "{{ from = {from:?}, to = {to:?}, angle = {} }}",
                    number(a.angle.unwrap_or(0.0))
                )
            }
        }
    }
}

impl fmt::Display for RawGuide {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let through = self.through.as_deref().unwrap_or("?");
        write!(f, "{{ through = {through:?}")?;
        if let Some(dir) = &self.dir {
            write!(f, ", dir = {dir}")?;
        }
        if let Some(offset) = self.offset {
            write!(f, ", offset = {}", number(offset))?;
        }
        if let Some(link) = self.link {
            write!(f, ", link = {link}")?;
        }
        write!(f, " }}")
    }
}

impl RawGroup {
    /// The keys present in this group with their values as written (`kind` excepted).
    pub fn present(&self) -> Vec<(&'static str, String)> {
        let mut out = Vec::new();
        let mut text = |key: &'static str, value: Option<String>| {
            if let Some(v) = value {
                out.push((key, v));
            }
        };
        text("links", self.links.as_ref().map(|l| format!("{l:?}")));
        text("a", self.a.as_ref().map(|s| format!("{s:?}")));
        text("la", self.la.map(number));
        text("b", self.b.as_ref().map(|s| format!("{s:?}")));
        text("lb", self.lb.map(number));
        text("c", self.c.as_ref().map(|s| format!("{s:?}")));
        text("offset", self.offset.map(number));
        text("guide", self.guide.as_ref().map(|g| g.to_string()));
        text("guide_i", self.guide_i.as_ref().map(|g| g.to_string()));
        text("guide_j", self.guide_j.as_ref().map(|g| g.to_string()));
        text("slide", self.slide.as_ref().map(|d| d.to_string()));
        text("joint", self.joint.as_ref().map(|s| format!("{s:?}")));
        text("branch", self.branch.as_ref().map(|s| format!("{s:?}")));
        out
    }
}

/// `[forces]`: the loads of the force analysis.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawForces {
    pub g: Option<f64>,
    pub gravity: Option<f64>,
    pub positions: Option<Vec<String>>,
    pub scale_f: Option<f64>,
    #[serde(default)]
    pub link: Vec<RawLinkLoad>,
    #[serde(default)]
    pub resistance: Vec<RawResistance>,
    #[serde(default)]
    pub indicator: Vec<RawIndicator>,
    pub drive: Option<RawDrive>,
    pub friction: Option<RawPairFriction>,
    #[serde(default)]
    pub seed: Vec<RawSeedValue>,
}

/// `[[forces.seed]]`: a value the seed prints for a row of the report.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawSeedValue {
    pub quantity: Option<String>,
    pub position: Option<String>,
    pub method: Option<String>,
    pub value: Option<f64>,
    pub unit: Option<String>,
    pub source: Option<String>,
    pub why: Option<RawLocalised>,
}

/// A text in each language: `{ ru = "…", uk = "…", en = "…" }`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawLocalised {
    pub ru: Option<String>,
    pub uk: Option<String>,
    pub en: Option<String>,
}

/// `[forces.friction]`: friction in the mechanism's pairs.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPairFriction {
    pub f: Option<f64>,
    pub radius: Option<f64>,
    pub radii: Option<std::collections::BTreeMap<String, f64>>,
}

/// `[[forces.link]]`: a link's mass, centre of mass and moment of inertia.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawLinkLoad {
    pub link: Option<i64>,
    pub mass: Option<f64>,
    pub centre: Option<String>,
    pub inertia: Option<f64>,
    pub rod: Option<f64>,
    pub length: Option<f64>,
}

/// `[[forces.resistance]]`: a force on a point or a moment on a link.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawResistance {
    pub point: Option<String>,
    pub force: Option<f64>,
    pub dir: Option<f64>,
    pub link: Option<i64>,
    pub moment: Option<f64>,
    pub stroke: Option<String>,
}

/// `[forces.drive]`: a coupling or a gear pair.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawDrive {
    pub kind: Option<String>,
    pub module: Option<f64>,
    pub teeth: Option<i64>,
    pub mate_teeth: Option<i64>,
    pub pressure_angle: Option<f64>,
    pub towards: Option<f64>,
    pub efficiency: Option<f64>,
}

/// `[[forces.indicator]]` as written.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawIndicator {
    pub point: Option<String>,
    pub bore: Option<f64>,
    pub offset: Option<f64>,
    pub pressure: Option<Vec<Vec<f64>>>,
}
