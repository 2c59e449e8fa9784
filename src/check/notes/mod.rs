//! The notes of a report as typed values carrying their numbers, one kind per study; the
//! report's English of every one is written by `report` (its `notes` writer), so that no
//! study builds a sentence. The cam's and the dynamics' notes are [`Statement`]s: text with
//! their [`Finding`](super::Finding)s in place.

pub mod balancing;
pub mod forces;
pub mod friction;
pub mod gears;
pub mod kinematics;
pub mod seed;
pub mod train;

use super::finding::Note as Statement;

pub use balancing::BalancingNote;
pub use forces::ForcesNote;
pub use friction::FrictionNote;
pub use gears::GearsNote;
pub use kinematics::KinematicsNote;
pub use seed::SeedNote;
pub use train::{SeedStage, TrainNote};

/// A note of a report.
#[derive(Debug, Clone, PartialEq)]
pub enum Note {
    /// A cam's or the dynamics' note: text and findings.
    Stated(Statement),
    /// A gear pair's or a wheel cut by the rack's.
    Gears(GearsNote),
    /// A gear train's.
    Train(TrainNote),
    /// One position of the force analysis'.
    Forces(ForcesNote),
    /// A seed's printed value against the analysis.
    Seed(SeedNote),
    /// A balancing study's.
    Balancing(BalancingNote),
    /// A friction case's.
    Friction(FrictionNote),
    /// A kinematic study's.
    Kinematics(KinematicsNote),
    /// A note still written as English where it is found (the blocking contour's).
    Text(String),
}

/// `From` each study's note into [`Note`], by its variant.
macro_rules! note_from {
    ($($kind:ty => $variant:ident),* $(,)?) => {
        $(impl From<$kind> for Note {
            fn from(n: $kind) -> Note {
                Note::$variant(n)
            }
        })*
    };
}

note_from! {
    Statement => Stated,
    GearsNote => Gears,
    TrainNote => Train,
    ForcesNote => Forces,
    SeedNote => Seed,
    BalancingNote => Balancing,
    FrictionNote => Friction,
    KinematicsNote => Kinematics,
    String => Text,
}
