//! A validated scene: everything downstream may trust (finite, positive where required).

use crate::balancing::BalancingSpec;
use crate::friction::FrictionCase;
use crate::kinematics::KinematicsSpec;
use crate::linkage::Mechanism;
use crate::scale::Scale;
use std::path::PathBuf;

/// Where the numbered positions start.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Start {
    /// Position 1 is the extreme position that begins the working (slower) stroke, found exactly.
    WorkingStroke,
    /// Position 1 at this crank angle, radians counter-clockwise from +x.
    Angle(f64),
}

/// The positions to construct.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PositionSpec {
    /// Number of equally spaced crank positions (≥ 1; 12 by default).
    pub count: u32,
    /// Where position 1 is.
    pub start: Start,
    /// Add the other extreme position (labelled with a prime, e.g. `8′`), and the position
    /// where the output reaches an extreme position again, if it does (the six-bar's `4′`).
    pub other_extreme: bool,
    /// Take each two-solution dyad's point nearest to the previous position (`assembly =
    /// "continuity"`) instead of on the scene's side at every position (`"side"`, the
    /// default: the textbook's "on the same side as B₀").
    pub continuity: bool,
}

/// The plates a scene can ask for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum PlateKind {
    /// "План положений": structural scheme, positions, trajectories, extremes.
    Positions,
    /// Kinematic analysis: velocity and acceleration plans, the displacement chart and its
    /// graphical derivatives, a hodograph.
    Kinematics,
    /// Force analysis (one sheet per position): the groups with their loads, the force
    /// polygons, the driving link, Zhukovsky's lever.
    Forces,
    /// Balancing of a rotor: the rotor, the polygons of static moments (and of moments) and
    /// the corrections against their analytic twin.
    Balancing,
    /// Friction: each `[[friction.case]]`'s scheme and force triangle, with the error table.
    Friction,
    /// Machine dynamics: the reduced moment and the work diagrams, ΔT, J_пр, the energy–mass
    /// diagram, ω(φ) with the flywheel and Tables 9/10.
    Dynamics,
    /// The flywheel as a part drawing (a sheet of its own, seed 000's at 1:4): the rim, the
    /// hub, the spokes and their sections, every dimension from the J_м the dynamics sheet's
    /// construction gives; none when no flywheel is needed.
    Flywheel,
    /// Gears: the meshing picture, the specific sliding, the generated wheels, the tables.
    Gears,
    /// The cam sheet: the diagrams by graphical integration, the combined diagram with the
    /// zone, the profile by inversion, the angle graph and the data table.
    Cam,
}

/// A section of the scene that a plate draws from, spelled as the scene's table (in the
/// alphabet's order).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Section {
    /// `[balancing]`.
    Balancing,
    /// `[cam]`.
    Cam,
    /// `[dynamics]`.
    Dynamics,
    /// `[forces]`.
    Forces,
    /// `[friction]`.
    Friction,
    /// `[gears]` (or `[planetary]`).
    Gears,
    /// `[mechanism]`.
    Mechanism,
}

impl Section {
    /// The table's name (`mechanism`).
    pub fn name(self) -> &'static str {
        match self {
            Section::Balancing => "balancing",
            Section::Cam => "cam",
            Section::Dynamics => "dynamics",
            Section::Forces => "forces",
            Section::Friction => "friction",
            Section::Gears => "gears",
            Section::Mechanism => "mechanism",
        }
    }
}

impl std::fmt::Display for Section {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl PlateKind {
    /// File stem of the plate (`positions`). The study that draws it, and so the scene
    /// section it draws from, is its row of the registration table (`scene::STUDIES`).
    pub fn stem(self) -> &'static str {
        match self {
            PlateKind::Positions => "positions",
            PlateKind::Kinematics => "kinematics",
            PlateKind::Forces => "forces",
            PlateKind::Balancing => "balancing",
            PlateKind::Friction => "friction",
            PlateKind::Dynamics => "dynamics",
            PlateKind::Flywheel => "flywheel",
            PlateKind::Gears => "gears",
            PlateKind::Cam => "cam",
        }
    }
}

/// Text of the title block (основная надпись), as the student fills it.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TitleInfo {
    /// Name of the task / machine (`Поперечно-строгальный станок`).
    pub title: String,
    /// Designation (`ТММ.КП.000`).
    pub designation: String,
    /// Student (Разраб.).
    pub author: String,
    /// Instructor (Пров.).
    pub checked: String,
    /// The department (the title block's organisation cell, the title page).
    pub organisation: String,
    /// The university (the title page).
    pub university: String,
    /// The city (the title page, over the year).
    pub city: String,
    /// The student's group (the note's title page).
    pub group: String,
    /// The year (the note's title page).
    pub year: String,
    /// A remark on the task's source (a reconstructed layout, say); not drawn.
    pub note: String,
    /// The kind of work the scene is.
    pub genre: super::genre::Genre,
    /// The texts in other languages (`[task.uk]`, …): see [`TitleInfo::in_lang`].
    pub localised: Vec<(crate::scale::Lang, super::raw::TaskText)>,
}

/// A validated scene file.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// The file it came from.
    pub path: PathBuf,
    /// The file stem (`shaper`): the output folder name.
    pub stem: String,
    /// Title block text.
    pub title: TitleInfo,
    /// The mechanism (`[mechanism]`); `None` for a task without one (a cam, a gear pair).
    pub mechanism: Option<Mechanism>,
    /// μ_l of the plan of positions; `None`: chosen the textbook way from the crank length.
    pub scale_l: Option<Scale>,
    /// The positions.
    pub positions: PositionSpec,
    /// The plates wanted, in file order (none: the scene asks for nothing to construct).
    pub plates: Vec<PlateKind>,
    /// The `[kinematics]` choices (all `None` when the section is absent).
    pub kinematics: KinematicsSpec,
    /// The `[forces]` loads (`None` when the section is absent).
    pub forces: Option<crate::forces::ForceSpec>,
    /// The rotor to balance (`[balancing]`), when the scene has one.
    pub balancing: Option<BalancingSpec>,
    /// The `[[friction.case]]`s, in file order (none when `[friction]` is absent).
    pub friction: Vec<FrictionCase>,
    /// The `[dynamics]` section (`None` when absent).
    pub dynamics: Option<crate::dynamics::DynamicsSpec>,
    /// The gear study (`[gears]`), when the scene has one.
    pub gears: Option<crate::gears::GearsSpec>,
    /// The cam (`[cam]`), when the scene has one.
    pub cam: Option<crate::cam::CamSpec>,
    /// The values of the answer key of `tmm batch` (`[answer_key] values`), in file order.
    pub answer_key: Vec<AnswerItem>,
    /// The values the seed prints for rows of the report that the analysis does not
    /// reproduce (`[[seed]]`), in file order: flagged by the report, explained by the note.
    pub seed: Vec<crate::check::SeedValue>,
    /// What is read but does not do all it could (a `[kinematics]` section that no sheet
    /// draws): each a problem that does not refuse the scene, for the caller to warn of.
    pub warnings: Vec<super::Problem>,
    /// The file's values as it gave them, read once: the same scene at another scale is
    /// validated from them ([`Scene::with_scale`]), never from the text again.
    pub source: super::Source,
}

impl Scene {
    /// Whether the scene has a study to carry out (a report to give).
    pub fn has_study(&self) -> bool {
        self.mechanism.is_some()
            || self.balancing.is_some()
            || !self.friction.is_empty()
            || self.gears.is_some()
            || self.cam.is_some()
    }
}

/// One value of an answer key: a report row named as the report names it,
/// `quantity[@position][:method]` (`v_E@3`, `M_bal@3:lever`, `r_min`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AnswerItem {
    /// The report's quantity (`v_E`, `M_bal`, `eps_alpha`).
    pub quantity: String,
    /// The position's label, for a quantity read at a position.
    pub position: Option<String>,
    /// The method's key (`plan`, `polygon`, `lever`), when the quantity has several.
    pub method: Option<String>,
}

impl AnswerItem {
    /// The item as written in the scene.
    pub fn name(&self) -> String {
        let mut s = self.quantity.clone();
        if let Some(p) = &self.position {
            s.push('@');
            s.push_str(p);
        }
        if let Some(m) = &self.method {
            s.push(':');
            s.push_str(m);
        }
        s
    }

    /// Whether `row` is the one this item names.
    pub fn names(&self, row: &crate::check::Row) -> bool {
        row.quantity() == self.quantity
            && row.position() == self.position
            && self.method.as_deref().is_none_or(|m| row.method.key() == m)
    }
}
