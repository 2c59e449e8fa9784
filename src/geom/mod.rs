//! The geometry kernel: primitives on `glam::DVec2`, intersections as outcome enums,
//! explicit tolerances. Knows nothing of plates, scenes or mechanisms.

mod clip;
mod hatch;
mod intersect;
mod primitives;
mod rect;
mod solve;
mod tolerance;

pub use clip::{arc_in_circle, polyline_in_circle};
pub use glam::DVec2;
pub use hatch::{hatch, HatchError, MAX_HATCH_LINES};
pub use intersect::{circle_circle, line_circle, line_line, CircleCircle, LineCircle, LineLine};
pub use primitives::{
    french_curve, hermite, nearest, polygon_contains, rotate, wrap_pi, Arc, Circle, Line, Ray,
    Segment, Side,
};
pub use rect::Rect;
pub use solve::{bracketed_root, golden_max, illinois, solve_linear};
pub use tolerance::{InvalidTolerance, Tolerances};
