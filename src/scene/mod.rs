//! Scene files (`constructions/*.toml`) → validated domain inputs.

mod balancing;
mod cam;
mod cam_layout;
mod cam_raw;
mod check;
mod drawing;
mod dynamics;
mod error;
mod follower;
mod forces;
mod friction;
mod friction_case;
mod gear_values;
mod gears;
mod genre;
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
mod source;
mod structure;
mod studies;
mod task;
mod text;
mod toml_error;
pub mod user_table;

pub use crate::kinematics::KinematicsSpec;
pub use error::{Problem, SceneError};
pub use genre::{Genre, Practicum};
#[cfg(test)]
pub(crate) use load::PARSES;
pub use load::{files_in, load, parse, read, MAX_SCENE_BYTES};
pub use model::{AnswerItem, PlateKind, PositionSpec, Scene, Section, Start, TitleInfo};
pub use raw::TaskText;
pub use rescale::RescaleError;
pub use source::Source;
pub use studies::{PlateRow, Study, STUDIES};

#[cfg(test)]
mod tests;
