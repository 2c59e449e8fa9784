//! Scene files (`constructions/*.toml`) → validated domain inputs.

mod balancing;
mod cam;
mod cam_layout;
mod check;
mod drawing;
mod dynamics;
mod error;
mod follower;
mod forces;
mod friction;
mod gear_values;
mod gears;
mod groups;
mod indicator;
mod kinematics;
mod load;
mod model;
mod outputs;
mod planetary;
mod raw;
mod rescale;
mod seed;
mod structure;
mod studies;
mod task;
mod text;
mod toml_error;
pub mod user_table;

pub use crate::kinematics::KinematicsSpec;
pub use error::{Problem, SceneError};
#[cfg(test)]
pub(crate) use load::PARSES;
pub use load::{files_in, load, parse, read, MAX_SCENE_BYTES};
pub use model::{AnswerItem, PlateKind, PositionSpec, Scene, Section, Start, TitleInfo};
pub use rescale::{RescaleError, Source};
pub use studies::{PlateRow, Study, STUDIES};
pub use task::{Genre, Practicum, TaskText};

#[cfg(test)]
mod tests;
