//! Scene files (`constructions/*.toml`) → validated domain inputs.

mod model;

pub use model::{PlateKind, PositionSpec, Scene, Start, TitleInfo};
