//! The compiled program's directions and guides, their points as indices: what the
//! program, the construction, the twin and the group kinds all read.

/// A direction in the program.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum PDir {
    /// Frame direction, radians.
    Fixed(f64),
    /// Direction of `from → to` turned by `angle`.
    Along {
        /// Point index.
        from: usize,
        /// Point index.
        to: usize,
        /// Extra turn, radians.
        angle: f64,
    },
}

/// A guide line in the program.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct PGuide {
    /// Point index the line passes through (before the offset).
    pub through: usize,
    /// Its direction.
    pub dir: PDir,
    /// Shift to the left, m.
    pub offset: f64,
    /// The link that carries it (0 the frame), resolved once at compilation
    /// (`Program::resolve_carriers`).
    pub carrier: usize,
}

impl PGuide {
    /// True when the guide belongs to the frame.
    pub fn is_fixed(&self, fixed_count: usize) -> bool {
        self.through < fixed_count && matches!(self.dir, PDir::Fixed(_))
    }
}
