//! The `[forces]` section as the force analysis takes it: masses, centres of mass and
//! moments of inertia of the links, gravity, the working resistance with the stroke it acts
//! on, the drive of the crank and the positions to analyse. SI units.

use crate::geom::DVec2;
use crate::scale::Scale;

/// The mass properties of one link.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkMass {
    /// Link number.
    pub link: u32,
    /// Mass, kg (≥ 0).
    pub mass: f64,
    /// The point of the mechanism at the centre of mass (`S_3`; a pivot for a crank balanced
    /// about its axis).
    pub centre: String,
    /// Central moment of inertia I_S, kg·m² (≥ 0).
    pub inertia: f64,
    /// Length of a slider along its guide, m: where the guide's reaction may act.
    pub length: Option<f64>,
}

/// On which stroke a resistance acts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stroke {
    /// The working (slower) stroke only, extreme positions excluded — the cutting force of a
    /// shaper.
    Working,
    /// The return stroke only.
    Return,
    /// At every position.
    Always,
}

impl Stroke {
    /// Whether a resistance on this stroke acts at a position of `phase` (the
    /// [`Phase`](super::loads::Phase) of the position: `Some(true)` working, `Some(false)`
    /// return, `None` at an extreme).
    pub fn acts(self, phase: Option<bool>) -> bool {
        match self {
            Stroke::Always => true,
            Stroke::Working => phase == Some(true),
            Stroke::Return => phase == Some(false),
        }
    }
}

/// What a resistance is.
#[derive(Debug, Clone, PartialEq)]
pub enum Action {
    /// A force of `magnitude` N at `point`, along `dir` (radians) or, when `None`, against
    /// the point's velocity.
    Force {
        /// The point of application.
        point: String,
        /// The link the force acts on, as the scene names it (`link`); `None`: the link the
        /// point belongs to, the slider at a slider's joint ([`crate::forces::loads::carrier`]).
        link: Option<u32>,
        /// Magnitude, N (> 0).
        magnitude: f64,
        /// A fixed direction, radians; `None`: against the velocity.
        dir: Option<f64>,
    },
    /// A moment of `magnitude` N·m on `link`, against its angular velocity.
    Moment {
        /// The link.
        link: u32,
        /// Magnitude, N·m (> 0).
        magnitude: f64,
    },
}

impl Action {
    /// The symbol of the resistance in the Russian textbooks' markup: `F_{пс}`, `M_{пс}`.
    pub fn symbol(&self) -> &'static str {
        match self {
            Action::Force { .. } => "F_{пс}",
            Action::Moment { .. } => "M_{пс}",
        }
    }
}

/// A working resistance (сила полезного сопротивления).
#[derive(Debug, Clone, PartialEq)]
pub struct Resistance {
    /// The force or moment.
    pub action: Action,
    /// When it acts.
    pub stroke: Stroke,
}

/// How the crank is driven.
#[derive(Debug, Clone, PartialEq)]
pub enum Drive {
    /// Through a coupling: a balancing moment on the crank.
    Coupling,
    /// Through a gear pair: the wheel on the crank's shaft is driven by a pinion; the
    /// balancing force acts at the pitch point along the line of action.
    Gear(GearDrive),
}

/// The gear pair that drives the crank.
#[derive(Debug, Clone, PartialEq)]
pub struct GearDrive {
    /// Module, m.
    pub module: f64,
    /// Teeth of the wheel on the crank's shaft.
    pub teeth: u32,
    /// Teeth of the driving pinion (drawn when given).
    pub mate_teeth: Option<u32>,
    /// Pressure angle α_w, radians.
    pub pressure_angle: f64,
    /// Direction from the crank's centre to the pitch point (towards the pinion), radians.
    pub towards: f64,
}

impl GearDrive {
    /// Pitch radius of the crank's wheel r = m·z/2, m.
    pub fn radius(&self) -> f64 {
        self.module * f64::from(self.teeth) / 2.0
    }
    /// Pitch radius of the pinion, m.
    pub fn mate_radius(&self) -> Option<f64> {
        self.mate_teeth.map(|z| self.module * f64::from(z) / 2.0)
    }
}

/// The validated `[forces]` section.
#[derive(Debug, Clone, PartialEq)]
pub struct ForceSpec {
    /// g, m/s².
    pub g: f64,
    /// Direction of gravity, radians (−π/2: down the drawing).
    pub gravity_dir: f64,
    /// Labels of the positions to analyse (`3`, `10`).
    pub positions: Vec<String>,
    /// μ_F of the force polygons, N/mm; `None`: chosen the textbook way.
    pub scale_f: Option<Scale>,
    /// The links' masses.
    pub links: Vec<LinkMass>,
    /// The working resistances.
    pub resistances: Vec<Resistance>,
    /// The driving forces of indicator diagrams (`[[forces.indicator]]`).
    pub indicators: Vec<Indicator>,
    /// The drive.
    pub drive: Drive,
    /// η of the drive from the motor to the crank, in (0, 1], when given: the motor's power
    /// N = M_у·ω₁/η (seed 000 §2: N = P_ур·V/η).
    pub efficiency: Option<f64>,
    /// Friction in the pairs (`[forces.friction]`), analysed beside the frictionless case.
    pub friction: Option<PairFriction>,
    /// The seed's printed values to compare with (`[[forces.seed]]`).
    pub seed: Vec<crate::check::SeedValue>,
}

impl ForceSpec {
    /// The resistances that act at a position of `phase` ([`Stroke::acts`]).
    pub fn acting(&self, phase: Option<bool>) -> impl Iterator<Item = &Resistance> {
        self.resistances
            .iter()
            .filter(move |r| r.stroke.acts(phase))
    }

    /// The machine is an engine: the gas forces of its indicator diagrams drive it, and its
    /// balancing moment is the resisting moment on its shaft (the textbook's M_у of an
    /// engine: what the driven machine takes off the crank).
    pub fn engine(&self) -> bool {
        !self.indicators.is_empty()
    }

    /// The weight of a mass `m` (kg) as a vector, N: m·g along the scene's gravity.
    pub fn weight(&self, m: f64) -> DVec2 {
        DVec2::from_angle(self.gravity_dir) * (m * self.g)
    }
}

/// The indicator diagram of one cylinder.
#[derive(Debug, Clone, PartialEq)]
pub struct Indicator {
    /// The piston: the slider's joint of an RRP group.
    pub point: String,
    /// The bore d, m.
    pub bore: f64,
    /// The gas pressure (gauge) against the cycle angle: (θ rad, p Pa), θ increasing from 0
    /// to 2π, p ≥ 0; linear between the rows, periodic.
    pub pressure: Vec<(f64, f64)>,
    /// The crank angle at which the cylinder's cycle starts φ₀, radians.
    pub offset: f64,
}

/// Friction in the pairs of a mechanism (`[forces.friction]`), SI.
#[derive(Debug, Clone, PartialEq)]
pub struct PairFriction {
    /// The coefficient of sliding friction f, in the sliding pairs and the journals.
    pub f: f64,
    /// The journals' radius r, m (every revolute pair not in `radii`; 0: frictionless).
    pub radius: f64,
    /// Journals of their own radius, by point name, m.
    pub radii: Vec<(String, f64)>,
}
