//! How finely a gear study's graphical readings are read: the step of the drafting model's
//! ruler on the figure each was read off, in the row's SI unit, so that a sheet prints a
//! length read off a 1:2 meshing picture to the millimetre, not to the micrometre.

use super::{GearStudy, LAMBDA_MM};
use crate::check::{Method, Row};
use crate::scale::Scale;
use crate::words::Symbol;

/// The step (m) to which a length is read off a figure drawn at `scale` when lengths are
/// read to `resolution_mm` on the drawing; `None` when they are read exactly.
pub fn length_step(scale: Scale, resolution_mm: f64) -> Option<f64> {
    (resolution_mm > 0.0).then(|| resolution_mm * scale.value())
}

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
                let length = length_step(m.meshing.scale, resolution_mm)?;
                Some(match symbol {
                    Symbol::SpecificSliding => resolution_mm / LAMBDA_MM,
                    Symbol::ContactRatio => length / m.pair.p_b,
                    _ => length,
                })
            }
            (Method::Envelope, Symbol::ToothThickness | Symbol::SpaceWidth) => {
                let (w, _) = self.cut_wheel_of(r)?;
                length_step(w.generation.scale, resolution_mm)
            }
            // ω of a shaft: its segment of the reading line of the plan of angular
            // velocities, at μ_ω.
            (Method::Triangles, Symbol::AngularVelocity) => {
                let t = self.train.as_ref()?;
                length_step(t.triangles.scale_w, resolution_mm)
            }
            _ => None,
        }
    }
}
