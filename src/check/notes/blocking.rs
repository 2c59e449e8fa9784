//! The notes of a gear pair's blocking contour as typed values carrying their numbers: the
//! contour traced and checked against the twins, the scene's point placed, the margin every
//! choice keeps, each criterion's choice. Their English is written by `report`. The kinds of
//! limit and the criteria of the choice are defined here, the notes' words for them, and
//! used by `gears::blocking` as its own.

/// What a curve of the contour bounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Kind {
    /// Undercut of wheel 0 or 1 (index x_i, limit x_min,i).
    Undercut(usize),
    /// The tip thickness of wheel i (index s_a,i/m).
    Tip(usize),
    /// The contact ratio ε_α.
    ContactRatio,
    /// Interference with the fillet of wheel i (index (N_iB_i − ρ_l,i)/m, limit 0).
    Interference(usize),
    /// Equal specific sliding (index λ₁(B₁) − λ₂(B₂), limit 0).
    EqualSliding,
}

/// A criterion of the choice of x₁, x₂ inside the contour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Criterion {
    /// Maximise ε_α over the admissible region.
    LargestContactRatio,
    /// On the line x₁ + x₂ = x_Σ, the point where λ₁ at B₁ equals λ₂ at B₂ (or, when that
    /// point is outside the admissible region, the admissible point of the line with the
    /// least |λ₁ − λ₂|).
    EqualSliding {
        /// x_Σ.
        x_sum: f64,
    },
    /// Maximise x₁ + x₂ (the stiffest, strongest teeth) with both tips s_a ≥ `sa_min`·m.
    GreatestSumWithTip {
        /// The least tip thickness, × m.
        sa_min: f64,
    },
}

/// A point of the plane with its quality indices, as the notes state them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanePoint {
    /// x₁, x₂.
    pub x: [f64; 2],
    /// α_w, rad.
    pub alpha_w: f64,
    /// y.
    pub y: f64,
    /// Δy.
    pub dy: f64,
    /// ε_α.
    pub eps: f64,
    /// s_a/m of each wheel.
    pub sa: [f64; 2],
    /// λ₁ at B₁ and λ₂ at B₂ (`None`: no sliding there).
    pub lambda: Option<[f64; 2]>,
}

/// A limit a point lies on or outside: its kind, its limit and how far inside it was taken
/// (0: the limit itself).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Level {
    /// What the curve bounds.
    pub kind: Kind,
    /// Its limit.
    pub limit: f64,
    /// How far inside (0: on the limit).
    pub inset: f64,
}

/// How the contour was traced and checked.
#[derive(Debug, Clone, PartialEq)]
pub struct Traced {
    /// z₁, z₂.
    pub z: [u32; 2],
    /// The grid's spacing (x per module).
    pub spacing: f64,
    /// The window: x₁ from, to; x₂ from, to.
    pub window: [[f64; 2]; 2],
    /// The curves traced.
    pub curves: usize,
    /// Their points.
    pub points: usize,
    /// The admissible region's rings.
    pub rings: usize,
    /// Their points.
    pub ring_points: usize,
    /// The points sampled against the twins.
    pub sampled: usize,
    /// The twins' largest deviation there.
    pub twin_deviation: f64,
    /// h_l* (the flank's end).
    pub hl: f64,
    /// x_min1, x_min2.
    pub x_min: [f64; 2],
}

/// A note of the blocking contour.
#[derive(Debug, Clone, PartialEq)]
pub enum BlockingNote {
    /// The contour traced and checked.
    Traced(Traced),
    /// The scene's point placed.
    Placed {
        /// The criterion it was chosen on the contour by (`None`: the scene gives it).
        chosen: Option<Criterion>,
        /// Its indices.
        point: PlanePoint,
        /// It is inside the admissible region.
        admissible: bool,
        /// The limits it is on the wrong side of.
        outside: Vec<Level>,
    },
    /// The margin every choice keeps inside the hard limits, and the ε_α it asks.
    Margin {
        /// The margin.
        margin: f64,
        /// ε_min + margin.
        eps: f64,
    },
    /// A criterion's choice: its point and the limits it is on, or why there is none (the
    /// error's own message).
    Choice {
        /// The criterion.
        criterion: Criterion,
        /// The point and the limits it is on, or the error's message.
        result: Result<(PlanePoint, Vec<Level>), String>,
    },
}
