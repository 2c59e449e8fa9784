//! The notes of one position of the force analysis as typed values: the power balance
//! against the linear solve, the polygons against Zhukovsky's lever, a balancing moment that
//! opposes ω₁, a guide's reaction outside its slider, the friction in the pairs. Their
//! English is written by `report`.

/// The friction in the pairs at one position.
#[derive(Debug, Clone, PartialEq)]
pub struct PositionFriction {
    /// M_bal with friction (the linear solve), N·m.
    pub with: f64,
    /// M_bal without, N·m.
    pub without: f64,
    /// The power the pairs lose, W.
    pub lost: f64,
    /// M_bal with friction by the power balance, N·m.
    pub by_power: f64,
    /// The drawings of the force polygons and the linear solves the friction took.
    pub approximations: [usize; 2],
}

/// A note of one position of the force analysis.
#[derive(Debug, Clone, PartialEq)]
pub enum ForcesNote {
    /// M_bal by the power balance against the linear solve.
    PowerBalance {
        /// The position's label.
        label: String,
        /// By the power balance, N·m.
        power: f64,
        /// By the linear solve, N·m.
        solve: f64,
    },
    /// M_bal by the force polygons against Zhukovsky's lever.
    Lever {
        /// The position's label.
        label: String,
        /// By the polygons, N·m.
        polygons: f64,
        /// By the lever, N·m.
        lever: f64,
    },
    /// The balancing moment opposes ω₁: the pinion's other flank.
    Opposes {
        /// The position's label.
        label: String,
        /// M_bal, N·m.
        moment: f64,
        /// F_bal, N.
        force: f64,
    },
    /// A guide's reaction acts outside its slider.
    SliderOutside {
        /// The position's label.
        label: String,
        /// The pair's links (guide, slider).
        pair: (usize, usize),
        /// The reaction, N.
        force: f64,
        /// Its offset from the slider's centre, m.
        offset: f64,
        /// The slider's length, m.
        length: f64,
        /// The loads on its two ends, N.
        ends: [f64; 2],
    },
    /// The friction in the pairs.
    Friction {
        /// The position's label.
        label: String,
        /// Its numbers.
        friction: PositionFriction,
    },
}
