//! A driving force from an indicator diagram (`[[forces.indicator]]`): the gas pressure in a
//! cylinder as a function of the cycle angle (the indicator diagram unfolded against the
//! crank angle), acting on the piston along the cylinder's axis, away from the cylinder head —
//! towards the crank. The force is p·A with A = π·d²/4 of the bore.
//!
//! The cycle angle of a cylinder is θ = σ·(φ₁ − φ₀) mod 2π: φ₁ the crank angle, φ₀ the
//! cylinder's `offset` (the crank angle at which its cycle starts), σ = ±1 the sense of
//! rotation. One cycle is one turn of the crank (a two-stroke engine), so the dynamics'
//! cycle of one revolution holds.

use super::loads::{Load, LoadKind, PositionMotion};
pub use super::spec::Indicator;
use super::ForceError;
use crate::geom::DVec2;
use crate::linkage::Program;
use std::f64::consts::{PI, TAU};

/// What a cylinder's indicator diagram gives at a position, as a hand-in writes it: the
/// piston's link, the cycle angle θ (rad, in [0, 2π)), the pressure p there (Pa) and the
/// gas force p·πd²/4 (N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GasReading {
    /// The piston's link.
    pub slider: usize,
    /// The cycle angle θ, radians.
    pub theta: f64,
    /// The whole turns added to σ·(φ₁ − φ₀) to bring θ into [0, 2π) (−1, 0, 1 …).
    pub turns: f64,
    /// The pressure at θ, Pa.
    pub pressure: f64,
    /// The gas force on the piston, N.
    pub force: f64,
}

impl GasReading {
    /// The gas force's name (label markup, localised where it is written), as its arrow's.
    pub fn name(&self) -> String {
        gas_force_name(self.slider)
    }
}

/// The name of the gas force on the piston `slider`: `F_{д3}`.
fn gas_force_name(slider: usize) -> String {
    format!("F_{{д{slider}}}")
}

impl Indicator {
    /// The reading at crank angle `phi` turning in the sense `sense` (±1), the mechanism at
    /// `motion`; `None` when the point is not a piston.
    pub fn reading(
        &self,
        prog: &Program,
        motion: &PositionMotion,
        phi: f64,
        sense: f64,
    ) -> Option<GasReading> {
        let at = |i: usize| motion.p.get(i).copied().unwrap_or(DVec2::ZERO);
        let (_, slider) = prog.index(&self.point).and_then(|k| prog.piston(k, at))?;
        let theta = self.cycle_angle(phi, sense);
        let pressure = self.pressure_at(theta);
        let raw = sense * (phi - self.offset);
        Some(GasReading {
            slider,
            theta,
            turns: ((theta - raw) / TAU).round(),
            pressure,
            force: pressure * self.area(),
        })
    }

    /// The piston's area A = π·d²/4, m².
    pub fn area(&self) -> f64 {
        PI * self.bore * self.bore / 4.0
    }

    /// The gas pressure at cycle angle `theta` (any real; taken mod 2π), Pa.
    pub fn pressure_at(&self, theta: f64) -> f64 {
        let t = theta.rem_euclid(TAU);
        let rows = &self.pressure;
        let k = rows.partition_point(|r| r.0 <= t);
        match (k.checked_sub(1).and_then(|i| rows.get(i)), rows.get(k)) {
            (Some(&(t0, p0)), Some(&(t1, p1))) if t1 > t0 => p0 + (p1 - p0) * (t - t0) / (t1 - t0),
            (Some(&(_, p0)), _) => p0,
            (None, Some(&(_, p1))) => p1,
            (None, None) => 0.0,
        }
    }

    /// The cycle angle at crank angle `phi` turning in the sense `sense` (±1).
    pub fn cycle_angle(&self, phi: f64, sense: f64) -> f64 {
        (sense * (phi - self.offset)).rem_euclid(TAU)
    }

    /// The gas force on the piston at the position `motion`: p·A along the cylinder's axis
    /// towards the crank, on the piston's link. `None` when the pressure is zero.
    ///
    /// # Errors
    /// The point is not a piston (the slider's joint of an RRP group).
    pub fn load(
        &self,
        prog: &Program,
        motion: &PositionMotion,
    ) -> Result<Option<Load>, ForceError> {
        let k = prog.index(&self.point).ok_or_else(|| ForceError::NoPoint {
            key: "indicator.point",
            name: self.point.clone(),
        })?;
        let at = |i: usize| motion.p.get(i).copied().unwrap_or(DVec2::ZERO);
        let (axis, slider) = prog.piston(k, at).ok_or_else(|| ForceError::NotPiston {
            name: self.point.clone(),
        })?;
        let (centre, pin) = (at(prog.centre), at(prog.pin));
        let phi = (pin - centre).to_angle();
        let w = motion
            .omega
            .get(prog.crank_link as usize)
            .copied()
            .unwrap_or(0.0);
        let sense = if w < 0.0 { -1.0 } else { 1.0 };
        let p = self.pressure_at(self.cycle_angle(phi, sense));
        // Towards the crank: the axis turned to point from the piston to the crank's centre.
        let towards = if axis.dot(centre - at(k)) < 0.0 {
            -axis
        } else {
            axis
        };
        if p == 0.0 {
            return Ok(None);
        }
        Ok(Some(Load::force(
            slider,
            LoadKind::Driving,
            gas_force_name(slider),
            towards * (p * self.area()),
            k,
        )))
    }
}
