//! How finely a gear study's graphical readings are read: the step of the drafting model's
//! ruler on the figure each was read off, in the row's SI unit, so that a sheet prints a
//! length read off a 1:2 meshing picture to the millimetre, not to the micrometre.

use super::{GearStudy, LAMBDA_MM};
use crate::check::{Method, Row};
use crate::words::Symbol;

impl GearStudy {
    /// The step (SI) of the row `r`'s graphical value when lengths are read to
    /// `resolution_mm` on the drawing: a length on the meshing picture or on a cut wheel's
    /// figure to `resolution_mm` × its μ_l; ε_α = B₁B₂/p_b to that step over p_b; λ off its
    /// graph to `resolution_mm` of the [`LAMBDA_MM`] its unit is drawn; a shaft's ω off the
    /// plan of angular velocities to `resolution_mm` × μ_ω. `None` for a value not read as one
    /// length (the triangles' ratio, a formula's) or when lengths are read exactly.
    pub fn reading_step(&self, r: &Row, resolution_mm: f64) -> Option<f64> {
        match (r.method, r.key.symbol) {
            (Method::Meshing, symbol) => {
                let m = self.pair.as_ref()?;
                let length = m.meshing.scale.reading_step(resolution_mm)?;
                Some(match symbol {
                    Symbol::ContactRatio => length / m.pair.p_b,
                    _ => length,
                })
            }
            (Method::SlidingDiagram, _) => {
                self.pair.as_ref()?;
                (resolution_mm > 0.0).then_some(resolution_mm / LAMBDA_MM)
            }
            (Method::Envelope, Symbol::ToothThickness | Symbol::SpaceWidth) => {
                let (w, _) = self.cut_wheel_of(r)?;
                w.generation.scale.reading_step(resolution_mm)
            }
            // ω of a shaft: its segment of the reading line of the plan of angular
            // velocities, at μ_ω.
            (Method::Triangles, Symbol::AngularVelocity) => {
                let t = self.train.as_ref()?;
                t.triangles.scale_w.reading_step(resolution_mm)
            }
            _ => None,
        }
    }
}
