//! The scales a scene gives: the keys that name them outside the loader (the scales a sheet
//! asks the user to set when a drawing does not fit) and the lengths a given scale may draw
//! its reference quantity within ([`DRAWN_MM`]). Each key is spelled here once, in
//! [`Key::path`]; the loader reads the same key by it, the sheets' refusals and the
//! dynamics' checks name it by the variant, and each study lists its keys in its row of the
//! registration table (`scene::STUDIES`), whose test holds every key to one row and one path.

use std::fmt;

/// The shortest and longest a scale may draw its reference quantity, mm.
pub(crate) const DRAWN_MM: (f64, f64) = (0.1, 1e4);

/// A scene key a sheet names: the scale that sets a drawing's size.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Key {
    /// μ_l of the mechanism's positions (`mechanism.scale_l`).
    MechanismScaleL,
    /// μ_S of the slider's displacement diagram (`kinematics.scale_s`).
    KinematicsScaleS,
    /// μ_v of the velocity plans (`kinematics.scale_v`).
    KinematicsScaleV,
    /// μ_a of the acceleration plans (`kinematics.scale_a`).
    KinematicsScaleA,
    /// μ_φ of the kinematic diagrams (`kinematics.scale_phi`).
    KinematicsScalePhi,
    /// μ_F of the force polygons (`forces.scale_f`).
    ForcesScaleF,
    /// μ_S of the cam's diagrams (`cam.scale_s`).
    CamScaleS,
    /// μ_l of the cam's profile (`cam.scale_l`).
    CamScaleL,
    /// μ_φ of the cam's diagrams (`cam.scale_phi`).
    CamScalePhi,
    /// μ_l of the meshing (`gears.scale_l`).
    GearsScaleL,
    /// μ_l of a rack's generation (`gears.rack.scale_l`).
    GearsRackScaleL,
    /// What sets the planetary train's velocity triangles (`planetary.module`).
    PlanetaryModule,
    /// μ_M of the reduced moments (`dynamics.scale_m`).
    DynamicsScaleM,
    /// μ_φ of the dynamics diagrams (`dynamics.scale_phi`).
    DynamicsScalePhi,
    /// μ_T of the works and energies (`dynamics.scale_t`).
    DynamicsScaleT,
    /// μ_J of the reduced moment of inertia (`dynamics.scale_j`).
    DynamicsScaleJ,
    /// μ_l of the rotor (`balancing.scale_l`).
    BalancingScaleL,
    /// μ_mr of the static polygon (`balancing.scale_mr`).
    BalancingScaleMr,
    /// μ_mrz of the dynamic polygon (`balancing.scale_mrz`).
    BalancingScaleMrz,
    /// μ_F of a friction case's polygon (`friction.case.scale_f`).
    FrictionCaseScaleF,
}

impl Key {
    /// The dotted path in the scene (`kinematics.scale_v`). Which study's drawings the key
    /// scales is its row of the registration table (`scene::STUDIES`).
    pub fn path(self) -> &'static str {
        match self {
            Key::MechanismScaleL => "mechanism.scale_l",
            Key::KinematicsScaleS => "kinematics.scale_s",
            Key::KinematicsScaleV => "kinematics.scale_v",
            Key::KinematicsScaleA => "kinematics.scale_a",
            Key::KinematicsScalePhi => "kinematics.scale_phi",
            Key::ForcesScaleF => "forces.scale_f",
            Key::CamScaleS => "cam.scale_s",
            Key::CamScaleL => "cam.scale_l",
            Key::CamScalePhi => "cam.scale_phi",
            Key::GearsScaleL => "gears.scale_l",
            Key::GearsRackScaleL => "gears.rack.scale_l",
            Key::PlanetaryModule => "planetary.module",
            Key::DynamicsScaleM => "dynamics.scale_m",
            Key::DynamicsScalePhi => "dynamics.scale_phi",
            Key::DynamicsScaleT => "dynamics.scale_t",
            Key::DynamicsScaleJ => "dynamics.scale_j",
            Key::BalancingScaleL => "balancing.scale_l",
            Key::BalancingScaleMr => "balancing.scale_mr",
            Key::BalancingScaleMrz => "balancing.scale_mrz",
            Key::FrictionCaseScaleF => "friction.case.scale_f",
        }
    }
}

impl fmt::Display for Key {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.path())
    }
}
