//! The notes of a report as typed values carrying their numbers, one kind per study; the
//! report's English of every one is written by `report` (its `notes` writer), so that no
//! study builds a sentence. A note that states a verdict carries it as a
//! [`Finding`](super::Finding) in its place.

pub mod balancing;
pub mod blocking;
pub mod cam;
pub mod dynamics;
pub mod forces;
pub mod friction;
pub mod gears;
pub mod kinematics;
pub mod seed;
pub mod train;

pub use balancing::BalancingNote;
pub use blocking::BlockingNote;
pub use cam::CamNote;
pub use dynamics::DynamicsNote;
pub use forces::ForcesNote;
pub use friction::FrictionNote;
pub use gears::GearsNote;
pub use kinematics::KinematicsNote;
pub use seed::SeedNote;
pub use train::{SeedStage, TrainNote};

/// A note of a report.
#[derive(Debug, Clone, PartialEq)]
pub enum ReportNote {
    /// A cam's.
    Cam(CamNote),
    /// The dynamics'.
    Dynamics(DynamicsNote),
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
    /// A blocking contour's.
    Blocking(BlockingNote),
}

/// `From` each study's note into [`ReportNote`], by its variant.
macro_rules! note_from {
    ($($kind:ty => $variant:ident),* $(,)?) => {
        $(impl From<$kind> for ReportNote {
            fn from(n: $kind) -> ReportNote {
                ReportNote::$variant(n)
            }
        })*
    };
}

note_from! {
    CamNote => Cam,
    DynamicsNote => Dynamics,
    GearsNote => Gears,
    TrainNote => Train,
    ForcesNote => Forces,
    SeedNote => Seed,
    BalancingNote => Balancing,
    FrictionNote => Friction,
    KinematicsNote => Kinematics,
    BlockingNote => Blocking,
}
