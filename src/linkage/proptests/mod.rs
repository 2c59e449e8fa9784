//! Property tests of the linkage constructions over random valid mechanisms (DESIGN §8):
//! the plan of positions keeps every constraint and equals the analytic twin; the velocity and
//! acceleration plans equal the twin's analogues times ω₁, ω₁²; their polygons close; and
//! everything moves with the scene under a rigid motion.
//!
//! Crate-internal on purpose: the tests reach the compiled program and the built positions,
//! which need not stay on the public surface.

use super::*;
use crate::construct::{ConstructionError, Context, Drafting, Recorder};
use crate::geom::DVec2;
use crate::scale::{Quantity, Scale};
use proptest::prelude::*;
use std::f64::consts::PI;

pub(crate) mod gen;
mod plans;
mod positions;

/// Length scale of the drawings, m/mm.
const MU: f64 = 0.001;

/// Construct one position; `None` when it cannot be assembled (outside the property's domain).
pub(crate) fn build(m: &Mechanism, phi: f64) -> Option<(Program, Built, Pose)> {
    let prog = Program::compile(m).ok()?;
    let mut rec = Recorder::in_context(
        "p",
        Scale::new(MU, Quantity::Length)?,
        &Context::for_model_size(1000.0, Drafting::EXACT).ok()?,
    );
    let built = prog.construct(&mut rec, phi, None, "p").ok()?;
    let pose = prog.solve(phi, None).ok()?;
    Some((prog, built, pose))
}

/// The context the plans of these tests are drawn in: plan figures about 200 mm across.
pub(crate) fn plan_context() -> crate::construct::Context {
    crate::construct::Context::for_model_size(200.0, crate::construct::Drafting::EXACT)
        .expect("a positive model size")
}
