//! The notes of a gear study as typed values: the pair (its indices, the inv table's route,
//! the tables' route), the source's printed values it does not reproduce, the compass
//! involute, and each wheel cut by the rack (undercut, the feasible shift, the junction of
//! the involute and the fillet, the tip). Their English is written by `report`.

/// The pair's indices (SI).
#[derive(Debug, Clone, PartialEq)]
pub struct PairIndices {
    /// The teeth.
    pub z: [u32; 2],
    /// The shifts.
    pub x: [f64; 2],
    /// α_w, rad.
    pub alpha_w: f64,
    /// a_w, m.
    pub a_w: f64,
    /// y.
    pub y: f64,
    /// Δy.
    pub dy: f64,
    /// ε_α.
    pub eps: f64,
    /// The radial clearances, m.
    pub clearance: [f64; 2],
    /// c*·m, m.
    pub nominal: f64,
}

/// A wheel cut by the rack: the undercut on the drawing and by the criterion.
#[derive(Debug, Clone, PartialEq)]
pub struct Cut {
    /// The wheel's name.
    pub wheel: String,
    /// Its teeth.
    pub z: u32,
    /// Its shift.
    pub x: f64,
    /// The rack's positions.
    pub steps: usize,
    /// The drawing shows an undercut (the fillet crosses the involute).
    pub drawn: bool,
    /// Undercut by the criterion.
    pub undercut: bool,
    /// The flank's end below the pitch line, m.
    pub depth: f64,
    /// The limit r·sin²α, m.
    pub limit: f64,
}

/// Where the involute meets the fillet, drawn and exact.
#[derive(Debug, Clone, PartialEq)]
pub struct Junction {
    /// The wheel's name.
    pub wheel: String,
    /// The radius on the drawing, m.
    pub drawn: f64,
    /// The exact radius, m.
    pub exact: f64,
    /// Undercut by the criterion (else the curves meet tangentially).
    pub undercut: bool,
    /// The two points apart, in modules.
    pub apart: f64,
    /// The touching points off the exact curves, in modules.
    pub touch: f64,
}

/// The seed's ε_α from the base radii r·cos α_w.
#[derive(Debug, Clone, PartialEq)]
pub struct WrongBase {
    /// ε_α printed.
    pub printed: f64,
    /// r·cos α_w of each wheel, m.
    pub radii: [f64; 2],
    /// πm·cos α_w, m.
    pub pitch: f64,
    /// ε_α from them.
    pub eps_from: f64,
    /// The base pitch πm·cos α, m.
    pub p_b: f64,
    /// ε_α.
    pub eps: f64,
}

/// A note of a gear study.
#[derive(Debug, Clone, PartialEq)]
pub enum GearsNote {
    /// The pair's indices and clearances.
    Pair(PairIndices),
    /// α_w by the inv table, and a printed α_w off its reading.
    InvTable {
        /// inv α_w.
        inv: f64,
        /// α_w read in the table, rad.
        table: f64,
        /// α_w exact, rad.
        exact: f64,
        /// α_w printed, rad, when off the table's reading.
        printed: Option<f64>,
    },
    /// y and a_w by the tables' Δy.
    Tables {
        /// Δy of the table.
        dy: f64,
        /// y = x_Σ − Δy.
        y: f64,
        /// a_w of the tables, m.
        a_w: f64,
        /// a_w exact, m.
        exact: f64,
        /// y exact.
        y_exact: f64,
    },
    /// The seed's ε_α from the base radii r·cos α_w.
    EpsFromWrongBase(WrongBase),
    /// The seed's ε_α is not reproducible.
    EpsNotReproduced {
        /// Printed.
        printed: f64,
        /// ε_α.
        eps: f64,
    },
    /// A misread cos α_w and the a_w it gives.
    CosMisread {
        /// cos α_w read.
        read: f64,
        /// a_w it gives, m.
        a_w_read: f64,
        /// a_w printed, m.
        printed: Option<f64>,
        /// cos α_w.
        cos: f64,
        /// a_w, m.
        a_w: f64,
    },
    /// The seed's a_w is not reproducible.
    AwNotReproduced {
        /// Printed, m.
        printed: f64,
        /// a_w, m.
        a_w: f64,
    },
    /// The printed pitch is not πm.
    Pitch {
        /// Printed, m.
        printed: f64,
        /// πm, m.
        pitch: f64,
    },
    /// The compass involute against the exact one.
    Compass {
        /// The largest deviation, m.
        deviation: f64,
        /// The chord-vs-arc error of one step, m.
        step: f64,
    },
    /// A wheel cut by the rack.
    Cut(Cut),
    /// x_min and the feasible shift.
    Shift {
        /// The wheel's name.
        wheel: String,
        /// x_min.
        x_min: f64,
        /// The textbook's (17 − z)/17, where its rule holds.
        textbook: Option<f64>,
        /// The shift with s_a = 0.3m, if any.
        pointing: Option<f64>,
    },
    /// Where the involute meets the fillet.
    Junction(Junction),
    /// The tip's thickness.
    Tip {
        /// The wheel's name.
        wheel: String,
        /// Read, m.
        read: f64,
        /// The module, m.
        module: f64,
        /// Exact, m.
        exact: f64,
        /// Pointed (s_a < 0.3m).
        pointed: bool,
    },
}
