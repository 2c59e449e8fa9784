//! The `[dynamics]` section as the dynamic study takes it: the mean speed and the coefficient
//! of irregularity δ, the constant reduced inertias, which links count, the number of
//! positions, the diagrams' scales and the flywheel's kind with its coefficients. SI units.

use crate::scale::Scale;

/// A constant reduced moment of inertia (a reducer, a gearbox, the crank's own wheel).
#[derive(Debug, Clone, PartialEq)]
pub struct ConstantInertia {
    /// What it is (`reducer`, `gearbox`).
    pub name: String,
    /// Its moment of inertia reduced to the crank, kg·m² (≥ 0).
    pub inertia: f64,
}

/// The shape of the flywheel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FlywheelKind {
    /// A rim with spokes and a hub (the seed's: J = K_j·ρ·D⁵, m = K_m·ρ·D³).
    Rim,
    /// A disc of width b = ψ·D with its bore d₁ = β·D (J = π·ψ·ρ·D⁵·(1 − β⁴)/32).
    Disc,
}

/// The flywheel's kind and the coefficients that give its size from its inertia.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlywheelSpec {
    /// Rim or disc.
    pub kind: FlywheelKind,
    /// K_j in J = K_j·ρ·D⁵.
    pub k_j: f64,
    /// K_m in m = K_m·ρ·D³.
    pub k_m: f64,
    /// Density ρ, kg/m³.
    pub rho: f64,
}

impl FlywheelSpec {
    /// The seed's rim (000 §5, L1454–1468): K_j = 0.0076, K_m = 0.0452, cast iron ρ = 7540.
    pub const SEED_RIM: FlywheelSpec = FlywheelSpec {
        kind: FlywheelKind::Rim,
        k_j: 0.0076,
        k_m: 0.0452,
        rho: 7540.0,
    };
    /// The significant digits K_j and K_m are written with on the sheet and in the note:
    /// enough that J = K_j·ρ·D⁵ recomputed from them gives the J printed beside it (a disc's
    /// K_j = 0,019604).
    pub const COEFFICIENT_DIGITS: usize = 5;
    /// Width of a disc as a fraction of its diameter, b = ψ·D.
    pub const DISC_WIDTH: f64 = 0.2;
    /// The bore of a disc (for the shaft) as a fraction of its diameter, d₁ = β·D.
    pub const DISC_BORE: f64 = 0.2;
    /// A disc of width 0.2·D with its bore of 0.2·D: J = π·ψ·ρ·D⁵·(1 − β⁴)/32, m =
    /// π·ψ·ρ·D³·(1 − β²)/4 (the bore takes 4 % of the mass, 0.16 % of the inertia).
    pub fn disc(rho: f64) -> FlywheelSpec {
        let (psi, beta) = (Self::DISC_WIDTH, Self::DISC_BORE);
        FlywheelSpec {
            kind: FlywheelKind::Disc,
            k_j: std::f64::consts::PI * psi * (1.0 - beta.powi(4)) / 32.0,
            k_m: std::f64::consts::PI * psi * (1.0 - beta * beta) / 4.0,
            rho,
        }
    }
}

/// The validated `[dynamics]` section.
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicsSpec {
    /// The mean angular velocity ω_ср of the crank, rad/s; `None`: the mechanism's ω₁.
    pub omega_avg: Option<f64>,
    /// The coefficient of irregularity δ = (ω_max − ω_min)/ω_ср (0 < δ < 1).
    pub delta: f64,
    /// The constant reduced inertias.
    pub constant: Vec<ConstantInertia>,
    /// The links whose masses count (`None`: every link of `[forces]`).
    pub links: Option<Vec<u32>>,
    /// Number of equally spaced positions of the diagrams, tabled each (`None`: the plans'
    /// and those between them, [`Self::positions`]).
    pub count: Option<u32>,
    /// μ_M of the diagram of reduced moments, N·m/mm.
    pub scale_m: Option<Scale>,
    /// μ_φ of the diagrams' abscissa, rad/mm.
    pub scale_phi: Option<Scale>,
    /// The pole distance H of the graphical integration, mm.
    pub pole_h: Option<f64>,
    /// μ_J of the reduced inertia, kg·m²/mm.
    pub scale_j: Option<Scale>,
    /// μ_T of the energy diagrams, J/mm.
    pub scale_t: Option<Scale>,
    /// The flywheel.
    pub flywheel: FlywheelSpec,
    /// The seed's own numbers, to be checked and flagged (`[dynamics.seed]`).
    pub seed: Option<SeedClaims>,
    /// Which side of the machine has the constant moment (`constant_moment`).
    pub constant_moment: ConstantMoment,
}

/// Which side of the machine has the constant moment: the other varies with φ and is
/// integrated graphically.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ConstantMoment {
    /// A constant driving moment M_д = A_с(2π)/2π against varying resistances (a machine
    /// driven by an electric motor: the shaper).
    #[default]
    Driving,
    /// A constant resisting moment M_с = A_д(2π)/2π against varying driving forces (an
    /// engine driving a generator: the V engine).
    Resisting,
}

impl ConstantMoment {
    /// The factor of −M_пр in the varying side's diagram: +1 draws M_с = −M_пр, −1 draws
    /// M_д = M_пр.
    pub fn sign(self) -> f64 {
        match self {
            ConstantMoment::Driving => 1.0,
            ConstantMoment::Resisting => -1.0,
        }
    }
}

/// What a seed (a student's project) claims, checked by the report: its flywheel, its table
/// of reduced inertias and the numbers of its expression for the flywheel.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SeedClaims {
    /// The flywheel's moment of inertia it gives, kg·m².
    pub flywheel: Option<f64>,
    /// Its reduced inertias J_пр at its equally spaced positions from the first (its Table
    /// 10), kg·m².
    pub j_red: Vec<f64>,
    /// Its expression J_м = μ_T·BD/(δ·ω²) − (J_b + J_d)/2: [μ_T (J/mm), BD (mm), J_b, J_d
    /// (kg·m²)].
    pub expression: Option<[f64; 4]>,
}

impl SeedClaims {
    /// The seed's expression evaluated: μ_T·BD/(δ·ω²) − (J_b + J_d)/2.
    pub fn expression_value(&self, delta: f64, w: f64) -> Option<f64> {
        self.expression
            .map(|[mu, bd, jb, jd]| mu * bd / (delta * w * w) - (jb + jd) / 2.0)
    }

    /// Its J_пр, each with the index of the same angle among `count` equally spaced
    /// positions; none when its positions are not among them.
    pub fn j_red_among(&self, count: usize) -> Vec<(usize, f64)> {
        let n = self.j_red.len();
        if n == 0 || count % n != 0 {
            return Vec::new();
        }
        let step = count / n;
        self.j_red
            .iter()
            .enumerate()
            .map(|(i, &j)| (i * step, j))
            .collect()
    }
}

impl DynamicsSpec {
    /// The fewest positions the diagrams take when the scene names none: every 15°. At the
    /// plans' 12 the energy–mass curve's tangent points fall between its points, and
    /// Wittenbauer's J_м comes out 15 % short of the exact one on seed 000's shaper (4 % on
    /// the V engine); at 24, within 1 %.
    pub const FEWEST_POSITIONS: u32 = 24;

    /// The positions of the diagrams for a scene of `plans` numbered positions: how many and,
    /// when the plans' positions are among them, every how many of them is one (`None`:
    /// numbered on their own). The scene's `count`, numbered on their own unless they are
    /// the plans'; else the fewest multiple of `plans` from [`Self::FEWEST_POSITIONS`] on,
    /// the plans' among them.
    pub fn positions(&self, plans: u32) -> (u32, Option<u32>) {
        match self.count {
            Some(n) => (n, (n == plans).then_some(1)),
            None => {
                let step = Self::FEWEST_POSITIONS.div_ceil(plans.max(1));
                (plans.max(1) * step, Some(step))
            }
        }
    }

    /// The sum of the constant reduced inertias, kg·m².
    pub fn constant_inertia(&self) -> f64 {
        self.constant.iter().map(|c| c.inertia).sum()
    }
}
