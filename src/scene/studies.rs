//! The registration table of the studies: one row each, in the report's order. A row names
//! the scene table the study reads, how the loader tells that the scene has it, whether the
//! validated scene carries it out, its plates (which of them a scene without `[plates]`
//! gets) and the scale keys its sheets name. The scene loader (the plates a scene may ask
//! for, the default plates, what a plate draws from), the session (the report's parts, in
//! this order) and the keys read it; a test holds it against the enums [`Section`],
//! [`PlateKind`] and [`Key`] (every variant in exactly one row, the plates in the enum's
//! order). What a study does stays in its own files: the session's part of the report
//! (`study::report_part`) and the sheet builder (`sheets::build`) are chosen by an exhaustive
//! `match` on the row's section or plate, which the compiler checks (a table of function
//! pointers here would point from the scene up into the session and the sheets).

use super::model::{PlateKind, Scene, Section};
use super::raw::RawScene;
use crate::scale::Key;

/// A plate a study draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PlateRow {
    /// The plate.
    pub kind: PlateKind,
    /// Whether a scene that has the study and no `[plates]` table gets it.
    pub default: bool,
}

/// One study: its row of [`STUDIES`].
#[derive(Clone, Copy)]
pub struct Study {
    /// The scene table it reads (`[mechanism]`); the study is named by it.
    pub section: Section,
    /// Whether the file has the study's table (the loader's question, asked of the file as
    /// read, before validation: a plate asked for draws from a table the file has).
    pub(crate) present: fn(&RawScene) -> bool,
    /// Whether the validated scene carries the study out (it has a part of the report).
    pub has: fn(&Scene) -> bool,
    /// Its plates, in the order they are listed and drawn.
    pub plates: &'static [PlateRow],
    /// The scale keys of its drawings that a sheet names when a drawing does not fit.
    pub keys: &'static [Key],
}

impl std::fmt::Debug for Study {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Study")
            .field("section", &self.section)
            .field("plates", &self.plates)
            .field("keys", &self.keys)
            .finish_non_exhaustive()
    }
}

/// A plate of a row that a scene without `[plates]` gets.
const fn default(kind: PlateKind) -> PlateRow {
    PlateRow {
        kind,
        default: true,
    }
}

/// A plate of a row that only `[plates] wanted` asks for.
const fn wanted(kind: PlateKind) -> PlateRow {
    PlateRow {
        kind,
        default: false,
    }
}

/// Every study, in the report's order (its parts, then the plates in this order).
pub const STUDIES: &[Study] = &[
    Study {
        section: Section::Mechanism,
        present: |raw| raw.mechanism.is_some(),
        has: |scene| scene.mechanism.is_some(),
        plates: &[default(PlateKind::Positions), wanted(PlateKind::Kinematics)],
        keys: &[
            Key::MechanismScaleL,
            Key::KinematicsScaleS,
            Key::KinematicsScaleV,
            Key::KinematicsScaleA,
            Key::KinematicsScalePhi,
        ],
    },
    Study {
        section: Section::Forces,
        present: |raw| raw.forces.is_some(),
        has: |scene| scene.mechanism.is_some() && scene.forces.is_some(),
        plates: &[wanted(PlateKind::Forces)],
        keys: &[Key::ForcesScaleF],
    },
    Study {
        section: Section::Balancing,
        present: |raw| raw.balancing.is_some(),
        has: |scene| scene.balancing.is_some(),
        plates: &[default(PlateKind::Balancing)],
        keys: &[
            Key::BalancingScaleL,
            Key::BalancingScaleMr,
            Key::BalancingScaleMrz,
        ],
    },
    Study {
        section: Section::Friction,
        present: |raw| raw.friction.is_some(),
        has: |scene| !scene.friction.is_empty(),
        plates: &[default(PlateKind::Friction)],
        keys: &[Key::FrictionCaseScaleF],
    },
    Study {
        section: Section::Dynamics,
        present: |raw| raw.dynamics.is_some(),
        has: |scene| scene.dynamics.is_some(),
        plates: &[wanted(PlateKind::Dynamics), wanted(PlateKind::Flywheel)],
        keys: &[
            Key::DynamicsScaleM,
            Key::DynamicsScalePhi,
            Key::DynamicsScaleT,
            Key::DynamicsScaleJ,
        ],
    },
    Study {
        section: Section::Gears,
        present: |raw| raw.gears.is_some() || raw.planetary.is_some(),
        has: |scene| scene.gears.is_some(),
        plates: &[default(PlateKind::Gears)],
        keys: &[Key::GearsScaleL, Key::GearsRackScaleL, Key::PlanetaryModule],
    },
    Study {
        section: Section::Cam,
        present: |raw| raw.cam.is_some(),
        has: |scene| scene.cam.is_some(),
        plates: &[default(PlateKind::Cam)],
        keys: &[Key::CamScaleS, Key::CamScaleL, Key::CamScalePhi],
    },
];

impl PlateKind {
    /// Every plate, in the order of the registration table (`tmm list`, the plates a scene
    /// may ask for).
    pub fn all() -> impl Iterator<Item = PlateKind> {
        plates_of(STUDIES)
    }

    /// Parse a stem.
    pub fn parse(s: &str) -> Option<Self> {
        Self::all().find(|k| k.stem() == s)
    }

    /// The study that draws the plate: its row of [`STUDIES`] (every plate has one, as
    /// the table's test shows).
    pub fn study(self) -> Option<&'static Study> {
        study_of(STUDIES, self)
    }
}

/// The row of the study that draws `kind` in `table`.
pub(crate) fn study_of(table: &'static [Study], kind: PlateKind) -> Option<&'static Study> {
    table
        .iter()
        .find(|s| s.plates.iter().any(|p| p.kind == kind))
}

/// Every plate of `table`, in its order.
pub(crate) fn plates_of(table: &'static [Study]) -> impl Iterator<Item = PlateKind> {
    table.iter().flat_map(|s| s.plates.iter().map(|p| p.kind))
}

/// The plates a file without `[plates]` gets: the default plates of every study of `table`
/// whose table the file has (`present`).
pub(crate) fn default_plates(
    table: &'static [Study],
    present: impl Fn(Section) -> bool,
) -> Vec<PlateKind> {
    table
        .iter()
        .filter(|s| present(s.section))
        .flat_map(|s| s.plates.iter().filter(|p| p.default).map(|p| p.kind))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{default, plates_of, study_of, Study, STUDIES};
    use crate::scale::Key;
    use crate::scene::check::Checker;
    use crate::scene::model::{PlateKind, Section};
    use crate::scene::raw::RawPlates;

    /// Every variant of an enum, in declaration order, walked by `next`: each `next` below is
    /// an exhaustive `match`, so a new variant does not compile until it is put in the walk.
    fn every<T: Copy>(first: T, next: fn(T) -> Option<T>) -> Vec<T> {
        std::iter::successors(Some(first), |&t| next(t)).collect()
    }

    fn next_section(s: Section) -> Option<Section> {
        match s {
            Section::Balancing => Some(Section::Cam),
            Section::Cam => Some(Section::Dynamics),
            Section::Dynamics => Some(Section::Forces),
            Section::Forces => Some(Section::Friction),
            Section::Friction => Some(Section::Gears),
            Section::Gears => Some(Section::Mechanism),
            Section::Mechanism => None,
        }
    }

    fn next_plate(k: PlateKind) -> Option<PlateKind> {
        match k {
            PlateKind::Positions => Some(PlateKind::Kinematics),
            PlateKind::Kinematics => Some(PlateKind::Forces),
            PlateKind::Forces => Some(PlateKind::Balancing),
            PlateKind::Balancing => Some(PlateKind::Friction),
            PlateKind::Friction => Some(PlateKind::Dynamics),
            PlateKind::Dynamics => Some(PlateKind::Flywheel),
            PlateKind::Flywheel => Some(PlateKind::Gears),
            PlateKind::Gears => Some(PlateKind::Cam),
            PlateKind::Cam => None,
        }
    }

    fn next_key(k: Key) -> Option<Key> {
        match k {
            Key::MechanismScaleL => Some(Key::KinematicsScaleS),
            Key::KinematicsScaleS => Some(Key::KinematicsScaleV),
            Key::KinematicsScaleV => Some(Key::KinematicsScaleA),
            Key::KinematicsScaleA => Some(Key::KinematicsScalePhi),
            Key::KinematicsScalePhi => Some(Key::ForcesScaleF),
            Key::ForcesScaleF => Some(Key::CamScaleS),
            Key::CamScaleS => Some(Key::CamScaleL),
            Key::CamScaleL => Some(Key::CamScalePhi),
            Key::CamScalePhi => Some(Key::GearsScaleL),
            Key::GearsScaleL => Some(Key::GearsRackScaleL),
            Key::GearsRackScaleL => Some(Key::PlanetaryModule),
            Key::PlanetaryModule => Some(Key::DynamicsScaleM),
            Key::DynamicsScaleM => Some(Key::DynamicsScalePhi),
            Key::DynamicsScalePhi => Some(Key::DynamicsScaleT),
            Key::DynamicsScaleT => Some(Key::DynamicsScaleJ),
            Key::DynamicsScaleJ => Some(Key::BalancingScaleL),
            Key::BalancingScaleL => Some(Key::BalancingScaleMr),
            Key::BalancingScaleMr => Some(Key::BalancingScaleMrz),
            Key::BalancingScaleMrz => Some(Key::FrictionCaseScaleF),
            Key::FrictionCaseScaleF => None,
        }
    }

    #[test]
    fn every_section_has_exactly_one_row() {
        let sections = every(Section::Balancing, next_section);
        assert_eq!(sections.len(), 7);
        assert_eq!(STUDIES.len(), sections.len());
        for s in sections {
            let rows = STUDIES.iter().filter(|r| r.section == s).count();
            assert_eq!(rows, 1, "[{s}] has {rows} rows");
        }
    }

    #[test]
    fn every_plate_is_in_exactly_one_row_in_the_enums_order() {
        let kinds = every(PlateKind::Positions, next_plate);
        assert_eq!(kinds.len(), 9);
        assert_eq!(plates_of(STUDIES).collect::<Vec<_>>(), kinds);
        assert_eq!(PlateKind::all().collect::<Vec<_>>(), kinds);
        for k in kinds {
            assert_eq!(PlateKind::parse(k.stem()), Some(k));
            assert!(study_of(STUDIES, k).is_some());
        }
        let section = |k| study_of(STUDIES, k).map(|s| s.section);
        assert_eq!(section(PlateKind::Kinematics), Some(Section::Mechanism));
        assert_eq!(section(PlateKind::Flywheel), Some(Section::Dynamics));
    }

    #[test]
    fn every_key_is_in_exactly_one_row_with_a_path_of_its_own() {
        let keys = every(Key::MechanismScaleL, next_key);
        assert_eq!(keys.len(), 20);
        for (i, k) in keys.iter().enumerate() {
            let rows = STUDIES.iter().filter(|r| r.keys.contains(k)).count();
            assert_eq!(rows, 1, "{k} is in {rows} rows");
            assert!(keys[..i].iter().all(|o| o.path() != k.path()), "{k} twice");
        }
        let row = |k: Key| {
            STUDIES
                .iter()
                .find(|r| r.keys.contains(&k))
                .map(|r| r.section)
        };
        assert_eq!(row(Key::KinematicsScaleV), Some(Section::Mechanism));
        assert_eq!(row(Key::PlanetaryModule), Some(Section::Gears));
        assert_eq!(Key::FrictionCaseScaleF.path(), "friction.case.scale_f");
    }

    /// A toy study, registered in test code: the flywheel drawn by default as a study of its
    /// own over `[dynamics]`, beside the mechanism's row. Its row is all the loader reads:
    /// the plates a scene may ask for, the default plates and the table each plate draws
    /// from follow from it. A real study also touches, each pointed at by the compiler or by
    /// the tests above: its `Section`, `PlateKind` and `Key` variants (`name`, `stem`,
    /// `path` arms), its `RawScene` and `Scene` fields, its part of the report
    /// (`study::report_part`), its sheet builder (`sheets::build`), its words in the
    /// catalogue and its pixel test (docs/architecture.md, "To add a study").
    const TOY: &[Study] = &[
        STUDIES[0],
        Study {
            section: Section::Dynamics,
            present: |raw| raw.dynamics.is_some(),
            has: |scene| scene.dynamics.is_some(),
            plates: &[default(PlateKind::Flywheel)],
            keys: &[],
        },
    ];

    fn plates(wanted: Option<&[&str]>, present: &[Section]) -> Result<Vec<PlateKind>, String> {
        let mut check = Checker::default();
        let raw = wanted.map(|w| RawPlates {
            wanted: Some(w.iter().map(|s| s.to_string()).collect()),
        });
        let out = crate::scene::load::plates(&mut check, raw, TOY, |s| present.contains(&s));
        match check.problems.first() {
            Some(p) => Err(p.to_string()),
            None => Ok(out),
        }
    }

    #[test]
    fn a_toy_study_is_registered_by_its_row() {
        let both = [Section::Mechanism, Section::Dynamics];
        assert_eq!(
            plates(None, &both),
            Ok(vec![PlateKind::Positions, PlateKind::Flywheel])
        );
        assert_eq!(
            plates(None, &[Section::Dynamics]),
            Ok(vec![PlateKind::Flywheel])
        );
        assert_eq!(
            plates(Some(&["flywheel", "kinematics"]), &both),
            Ok(vec![PlateKind::Flywheel, PlateKind::Kinematics])
        );
        let unknown = plates(Some(&["cam"]), &both).unwrap_err();
        assert!(
            unknown.contains("expected a plate kind (positions, kinematics, flywheel)"),
            "{unknown}"
        );
        let absent = plates(Some(&["flywheel"]), &[Section::Mechanism]).unwrap_err();
        assert!(
            absent.contains("the flywheel plate draws from [dynamics]"),
            "{absent}"
        );
    }
}
