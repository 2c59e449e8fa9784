//! The notes of a gear train's study as typed values carrying their names and numbers: the
//! inversion table, the mobility, the ratio, a differential's formula, the module a
//! non-coaxial stage is drawn at, the source's printed values, the required ratio and the best
//! teeth, the neighbour and assembly conditions. Their English is written by `report`.

/// One mesh's ratio with the carrier stopped: −z_y/z_x or z_y/z_x.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshRatio {
    /// The ratio is negative (an external mesh).
    pub negative: bool,
    /// The driven wheel's teeth (the numerator).
    pub driven: f64,
    /// The driving wheel's teeth (the denominator).
    pub driving: f64,
}

/// The teeth across a mesh's centre distance: `z1 + z2`, or `z5 − z4` for a ring 5.
#[derive(Debug, Clone, PartialEq)]
pub struct Across {
    /// The first wheel's name (the ring's, when one is internal).
    pub first: String,
    /// The second wheel's name.
    pub second: String,
    /// One wheel is internal: the teeth are subtracted.
    pub ring: bool,
}

/// What Willis's ratio is compared with: the differential's formula or the stages'.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FormulaBy {
    /// Willis's formula of the differential.
    Differential,
    /// The textbook's stage by stage product.
    Stages,
}

/// Which shaft of a differential is its output, and so how its formula is solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SolvedFor {
    /// The carrier: n_H = (n_a − u·n_b)/(1 − u).
    Carrier,
    /// The central shaft a: n_a = n_H + u·(n_b − n_H).
    A,
    /// The central shaft b: n_b = n_H + (n_a − n_H)/u.
    B,
}

/// A fraction written in a note: whole, or n/d, parenthesised when negative.
pub type Fraction = (i128, i128);

/// What a printed ratio asks of the one planetary stage: its wheels a and f, the u_af^(H)
/// the printed ratio needs with the other stages as their teeth give, and the u_af^(H) the
/// teeth give.
#[derive(Debug, Clone, PartialEq)]
pub struct SeedStage {
    /// The central wheel a's name.
    pub a: String,
    /// The fixed wheel f's name.
    pub f: String,
    /// u_af^(H) the printed ratio needs.
    pub needed: f64,
    /// u_af^(H) of the teeth.
    pub teeth: f64,
}

/// A differential by Willis's formula: u_ab^(H) from the teeth, the output's speed.
#[derive(Debug, Clone, PartialEq)]
pub struct WillisDifferential {
    /// The central shafts' and the carrier's names.
    pub names: [String; 3],
    /// The meshes' ratios with the carrier stopped.
    pub meshes: Vec<MeshRatio>,
    /// u_ab^(H).
    pub u: f64,
    /// The output shaft.
    pub solved: SolvedFor,
    /// The output's speed, rpm.
    pub output: f64,
    /// n_a, n_b, n_H, rpm.
    pub speeds: [f64; 3],
}

/// A mesh whose tooth sums do not close at the train's module: the module it is drawn at.
#[derive(Debug, Clone, PartialEq)]
pub struct Closing {
    /// The mesh's wheels' names.
    pub mesh: (String, String),
    /// The mesh that sets the carrier's arm, its wheels' names.
    pub arm_mesh: (String, String),
    /// The train's module, m.
    pub module: f64,
    /// The teeth across the arm's mesh.
    pub arm_across: Across,
    /// The carrier's arm, m.
    pub arm: f64,
    /// The teeth across the mesh.
    pub across: Across,
    /// The teeth across the mesh (the centre distance it reaches is m·teeth/2).
    pub teeth: f64,
    /// The module the mesh is drawn at, m.
    pub closing: f64,
    /// The wheel brought onto the carrier's axis.
    pub wheel: String,
}

/// The teeth the first fixed-axis mesh needs for the required ratio.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshNeeds {
    /// The driving and the driven wheel's names.
    pub names: (String, String),
    /// z_driven/z_driving needed.
    pub want: f64,
    /// The best pairs: z_driving, z_driven, the relative error.
    pub best: Vec<(u32, u32, f64)>,
    /// n_out required, rpm.
    pub n_out: f64,
    /// The teeth now: z_driving, z_driven.
    pub now: (f64, f64),
}

/// The assembly condition of k satellites.
#[derive(Debug, Clone, PartialEq)]
pub struct SatelliteAssembly {
    /// The satellites.
    pub k: u32,
    /// The central wheel's name.
    pub central: String,
    /// The fixed shaft's name (empty for none).
    pub fixed: String,
    /// z_a·u_aH^(b)/k.
    pub value: Fraction,
    /// The least p making (1 + kp)·value whole.
    pub p: Option<i128>,
    /// The identical blocks' value, when the satellites are one block.
    pub block: Option<Fraction>,
    /// The satellites fit; else the k from 2 to 8 that do.
    pub fits: Result<(), Vec<u32>>,
}

/// A note of a train's study.
#[derive(Debug, Clone, PartialEq)]
pub enum TrainNote {
    /// The inversion table: every shaft's n before and after the carrier is stopped.
    Inversion {
        /// The input speed is given: the speeds are in rpm (else per unit input).
        rpm: bool,
        /// Per shaft: its name, n before and n − n_H after.
        cells: Vec<(String, f64, f64)>,
    },
    /// W = 3n − 2p₅ − p₄, with a differential's two inputs.
    Mobility {
        /// The moving links.
        n: usize,
        /// The lower pairs.
        p5: usize,
        /// The higher pairs.
        p4: usize,
        /// The mobility.
        w: i64,
        /// A differential's inputs: the two shafts' names and their speeds, rpm.
        inputs: Option<(String, String, f64, f64)>,
    },
    /// The ratio by Willis, and by the formula when there is one.
    Ratio {
        /// u by Willis.
        ratio: f64,
        /// u by the formula, and which formula.
        formula: Option<(f64, FormulaBy)>,
    },
    /// A differential by Willis's formula.
    Differential(WillisDifferential),
    /// A mesh whose tooth sums do not close at the train's module: the module it is drawn at.
    Closing(Closing),
    /// The seed's mobility reproduced.
    SeedMobility {
        /// W printed.
        w: i64,
    },
    /// The seed's mobility is an erratum.
    SeedMobilityErratum {
        /// W printed.
        printed: i64,
        /// The moving links.
        n: usize,
        /// The lower pairs.
        p5: usize,
        /// The higher pairs.
        p4: usize,
        /// W of the train.
        w: i64,
    },
    /// The seed's ratio reproduced.
    SeedRatio {
        /// `u_<in>_<out>`.
        name: String,
        /// The printed ratio.
        printed: f64,
        /// Willis's.
        ratio: f64,
    },
    /// The seed's ratio is an erratum.
    SeedRatioErratum {
        /// `u_<in>_<out>`.
        name: String,
        /// The printed ratio.
        printed: f64,
        /// Willis's.
        ratio: f64,
        /// The formula's, when there is one.
        formula: Option<f64>,
        /// The velocity triangles'.
        triangles: f64,
        /// What the printed ratio needs of the one planetary stage.
        stage: Option<SeedStage>,
    },
    /// The ratio required by the speeds against the teeth's.
    Required {
        /// |n_in|, rpm.
        n_in: f64,
        /// n_out required, rpm.
        n_out: f64,
        /// |u| required.
        required: f64,
        /// |u| of the teeth.
        ratio: f64,
    },
    /// The teeth the first fixed-axis mesh needs for the required ratio.
    MeshNeeds(MeshNeeds),
    /// The neighbour condition of one satellite wheel.
    Neighbour {
        /// The satellites.
        k: u32,
        /// 2·a·sin(π/k), m.
        chord: f64,
        /// The wheel's name.
        wheel: String,
        /// Its tip diameter, m.
        tip: f64,
    },
    /// The assembly condition.
    Assembly(SatelliteAssembly),
}
