//! The geometry kernel: primitives on `glam::DVec2`, intersections as outcome enums,
//! explicit tolerances. Knows nothing of plates, scenes or mechanisms.

mod clip;
mod crossing;
pub mod curve;
mod fan;
mod golden;
mod hatch;
mod intersect;
mod linear;
mod newton;
mod primitives;
mod rect;
mod root;
mod sincos;
mod tolerance;

pub use clip::{arc_in_circle, polyline_in_circle};
pub use crossing::{pin_crossing, CurvePoint};
pub use fan::{fan_start, SPOT_MM};
pub use glam::DVec2;
pub use golden::{golden_max, golden_section, Golden, GoldenRule, Tie};
pub use hatch::{hatch, HatchError, MAX_HATCH_LINES};
pub use intersect::{circle_circle, line_circle, line_line, CircleCircle, LineCircle, LineLine};
pub use linear::{
    determinant, eliminate, null_space, smallest_pivot, solve_linear, solve_linear_above,
    solve_system, SINGULAR_REL,
};
pub use newton::{
    bracketed_newton, damped_newton, level_newton, plane_newton, NewtonEnd, PlaneNewton,
};
pub use primitives::{
    bezier_at, bezier_distance, bezier_points, french_curve, french_piece, hermite, nearest,
    polygon_contains, rotate, wrap_pi, Arc, Circle, Line, Ray, Segment, Side,
};
pub use rect::Rect;
pub use root::{bisect, bracketed_root, illinois, Midpoint};
pub use sincos::unit_at;
pub use tolerance::{InvalidTolerance, Tolerances};
