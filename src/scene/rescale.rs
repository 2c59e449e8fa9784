//! The scene at another scale. A drawing too large at a scale the scene gives is refitted
//! (`sheets::verified_fit`) by trying coarser values of the one scale key that sets it: each
//! value is set on the scene's [`Source`] — the file's values as it gave them, read once — and
//! the scene validated again, so that a value is refused exactly where the file written with
//! it would be (a scale's drawing range, the planetary train its module sets). No text is
//! written or read.

use super::check::Checker;
use super::error::SceneError;
use super::model::Scene;
use super::raw::RawScene;
use crate::scale::Key;
use thiserror::Error;

/// Why [`Scene::with_scale`] gives no scene.
#[derive(Debug, Error)]
pub enum RescaleError {
    /// The key is given per item (`gears.rack.scale_l` of each rack, `friction.case.scale_f`
    /// of each case), or its section is missing: the scene has no one value of it to set.
    #[error("{0}: the scene has no one value of it to set")]
    NotOne(Key),
    /// The scene refuses the value (outside the key's drawing range, or what it sets cannot
    /// be built).
    #[error(transparent)]
    Refused(#[from] SceneError),
}

impl Scene {
    /// This scene with the scale key `key` set to `value` (in the file's units: m/mm,
    /// (m/s)/mm, the planetary module in mm), validated as the file written with that value
    /// would be.
    ///
    /// # Errors
    /// [`RescaleError::NotOne`] when the scene has no one value of `key`;
    /// [`RescaleError::Refused`] when the scene refuses `value`.
    pub fn with_scale(&self, key: Key, value: f64) -> Result<Scene, RescaleError> {
        let mut raw = RawScene::clone(&self.source.0);
        raw.set_scale(key, value).ok_or(RescaleError::NotOne(key))?;
        Ok(super::load::validate(Checker::default(), raw, &self.path)?)
    }
}

impl RawScene {
    /// Set the value of the scale key `key` (creating its section as an empty one would be,
    /// except `[mechanism]`, which a value alone cannot make); `None` when the key is given
    /// per item or `[mechanism]` is missing.
    fn set_scale(&mut self, key: Key, value: f64) -> Option<()> {
        let v = Some(value);
        match key {
            Key::MechanismScaleL => self.mechanism.as_mut()?.scale_l = v,
            Key::KinematicsScaleS => {
                self.kinematics.get_or_insert_with(Default::default).scale_s = v
            }
            Key::KinematicsScaleV => {
                self.kinematics.get_or_insert_with(Default::default).scale_v = v
            }
            Key::KinematicsScaleA => {
                self.kinematics.get_or_insert_with(Default::default).scale_a = v
            }
            Key::KinematicsScalePhi => {
                self.kinematics
                    .get_or_insert_with(Default::default)
                    .scale_phi = v;
            }
            Key::ForcesScaleF => self.forces.get_or_insert_with(Default::default).scale_f = v,
            Key::CamScaleS => self.cam.get_or_insert_with(Default::default).scale_s = v,
            Key::CamScaleL => self.cam.get_or_insert_with(Default::default).scale_l = v,
            Key::CamScalePhi => self.cam.get_or_insert_with(Default::default).scale_phi = v,
            Key::GearsScaleL => self.gears.get_or_insert_with(Default::default).scale_l = v,
            Key::PlanetaryModule => self.planetary.get_or_insert_with(Default::default).module = v,
            Key::DynamicsScaleM => self.dynamics.get_or_insert_with(Default::default).scale_m = v,
            Key::DynamicsScalePhi => {
                self.dynamics.get_or_insert_with(Default::default).scale_phi = v;
            }
            Key::DynamicsScaleT => self.dynamics.get_or_insert_with(Default::default).scale_t = v,
            Key::DynamicsScaleJ => self.dynamics.get_or_insert_with(Default::default).scale_j = v,
            Key::BalancingScaleL => self.balancing.get_or_insert_with(Default::default).scale_l = v,
            Key::BalancingScaleMr => {
                self.balancing.get_or_insert_with(Default::default).scale_mr = v;
            }
            Key::BalancingScaleMrz => {
                self.balancing
                    .get_or_insert_with(Default::default)
                    .scale_mrz = v;
            }
            Key::GearsRackScaleL | Key::FrictionCaseScaleF => return None,
        }
        Some(())
    }
}
