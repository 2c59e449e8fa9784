//! The blocking contour (блокирующий контур) of an external pair z₁, z₂ cut by a basic rack,
//! in the x₁–x₂ plane (seed 000 L1004–1008, seed 002 PZ3; issues 21 §1 and 42 §2): the
//! curves on which one quality index of the pair reaches its limit, and the admissible
//! region they bound, each traced from its definition on a grid of the plane — never read
//! from a table.
//!
//! The indices, per unit module (the contour does not depend on m), by the contour's own lean
//! formulas ([`Blocking::indices`]); the analytic twins are [`crate::gears::GearPair::new`] and
//! [`crate::gears::Cutting`] ([`twin_value`]: the tests and the rows evaluate each traced
//! point through them):
//! - undercut of wheel i: x_i = x_min,i with x_min = h_l* − z sin²α/2, where h_l* = −v_j* is
//!   the depth below the rack's mean line at which the tool's straight flank ends (its
//!   tangency with the tip rounding ρ_f*): the limit `Cutting::undercut` decides by; for the
//!   ГОСТ 13755 rack h_l* = 0.99997, 3·10⁻⁵ left of the textbook's h_a* − z sin²α/2;
//! - tooth pointing: s_a,i = 0, and the quality isolines s_a,i = 0.25 and 0.4 (× m), with the
//!   tip shortened by the exact Δy = x_Σ − y: r_a = r + (h_a* + x − Δy)m;
//! - the contact ratio ε_α = 1 and 1.2;
//! - interference with the transition curve of wheel i: the end of the active line nearer
//!   N_i (the mate's tip) falls short of the lower limit point of wheel i's involute, the point
//!   its flank's end generates, ρ_l,i = r_i sin α − (h_l* − x_i)m/sin α from N_i. The index:
//!   N_iB_i − ρ_l,i, its curve where it is 0;
//! - equal specific sliding at the ends of the active line: λ₁ at B₁ (where the root of
//!   wheel 1 works) equals λ₂ at B₂, λ₁ = 1 − ρ₂/(uρ₁), λ₂ = 1 − uρ₁/ρ₂.
//!
//! The files: `indices` (the formulas, the hard limits' margin, the twins), `plane` (the
//! zero sets of functions on a grid), `trace` (the curves and the region), `choose` (a point
//! placed, the textbook's choices), `study` (a scene's contour, its rows and notes),
//! `figure` (its drawing).

mod choose;
mod figure;
mod indices;
mod plane;
mod study;
#[cfg(test)]
mod tests;
mod trace;

pub use crate::check::notes::blocking::{Criterion, Kind};
pub use choose::{Choice, CurveSide, OnContour, CHOICE_MARGIN};
pub use figure::Words;
pub use indices::{twin_deviation, twin_margin, twin_pair, twin_rho_l, twin_value, Indices};
pub use plane::{distance_to, inside_rings};
pub use study::{criterion_tag, BlockingStudy, Studies};
pub use trace::{twin_check, Contour};

use super::involute::inv;
use super::rack::pointed_alone;
use super::{BasicRack, GearError};
use crate::geom::DVec2;

/// The quality isolines of the tip thickness, × m.
pub const TIP_LIMITS: [f64; 3] = [0.0, 0.25, 0.4];
/// The contact ratio's lines.
pub const EPS_LIMITS: [f64; 2] = [1.0, 1.2];
/// The grid's spacing (x per module): a piece of the region or of a curve narrower than
/// this may be missed; the chord between two points of a curve departs from it by about
/// h²/8ρ (2·10⁻⁴ where its radius of curvature ρ is 0.25).
pub const SPACING: f64 = 0.02;
/// A point's index is on a limit when within this of it (the grid's brackets end 10⁻¹³ away,
/// the corners' Newton steps 10⁻¹²).
pub(super) const ON_LIMIT: f64 = 1e-9;
/// Newton's steps stop when each index is this near its level.
pub(super) const NEWTON_TO: f64 = 1e-12;
/// The step of the central differences of Newton's steps (x per module).
pub(super) const DIFF_STEP: f64 = 1e-7;
/// The shifts the plane spans at most: |x| ≤ 3, what a scene accepts and a rack cuts.
pub const X_MAX: f64 = 3.0;

impl Kind {
    /// The index is at least its limit on the admissible side (`None`: a line, no side).
    pub fn good_above(self) -> Option<bool> {
        match self {
            Kind::EqualSliding => None,
            _ => Some(true),
        }
    }
}

/// One traced curve: its kind, its limit and its points (x₁, x₂) in order along it.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// What it bounds.
    pub kind: Kind,
    /// The index's value on it.
    pub limit: f64,
    /// The points (x₁, x₂).
    pub points: Vec<DVec2>,
}

/// The hard limits of the admissible region.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hard {
    /// The least tip thickness, × m.
    pub sa_min: f64,
    /// The least contact ratio.
    pub eps_min: f64,
    /// How far inside every limit a point must lie, in the index's own unit (x and lengths
    /// per module, s_a/m, ε_α): 0 for the region, [`CHOICE_MARGIN`] for a choice.
    pub inset: f64,
}

impl Default for Hard {
    /// s_a ≥ 0.25m, ε_α ≥ 1.2 (with no undercut and no interference).
    fn default() -> Self {
        Hard {
            sa_min: 0.25,
            eps_min: 1.2,
            inset: 0.0,
        }
    }
}

/// Why a contour cannot be traced or a choice made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BlockingError {
    /// The pair or the rack out of range.
    #[error("blocking contour: {0}")]
    Gear(#[from] GearError),
    /// A point not finite.
    #[error("blocking contour: the point ({x1}, {x2}) is not finite")]
    NotFinite {
        /// x₁.
        x1: f64,
        /// x₂.
        x2: f64,
    },
    /// The involute formulas have no value at the point.
    #[error("blocking contour: the pair has no geometry at x₁ = {x1}, x₂ = {x2} (no α_w or a tip inside the base circle)")]
    Domain {
        /// x₁.
        x1: f64,
        /// x₂.
        x2: f64,
    },
    /// No point of the plane meets every hard limit.
    #[error("blocking contour: no point of x₁ ∈ [{:.3}, {:.3}], x₂ ∈ [{:.3}, {:.3}] meets every hard limit {} inside (s_a ≥ {}m, ε_α ≥ {}, no undercut, no interference)", .x1[0], .x1[1], .x2[0], .x2[1], .hard.inset, .hard.sa_min, .hard.eps_min)]
    Empty {
        /// The plane's window: x₁ from, to.
        x1: [f64; 2],
        /// x₂ from, to.
        x2: [f64; 2],
        /// The hard limits, and how far inside them.
        hard: Hard,
    },
    /// The criterion's line misses the admissible region taken `inset` inside its limits:
    /// the line's x_Σ and its deepest point's margin (−∞: it misses the window).
    #[error("blocking contour: the line x₁ + x₂ = {x_sum} does not cross the admissible region {inset} inside its limits ({words})", words = deepest_words(*.deepest))]
    LineOutside {
        /// The line's x₁ + x₂.
        x_sum: f64,
        /// How far inside the limits the region was taken.
        inset: f64,
        /// Its deepest point's margin inside the limits (−∞: it misses the window).
        deepest: f64,
    },
}

/// How deep inside its limits a line gets, in words.
fn deepest_words(margin: f64) -> String {
    if margin.is_finite() {
        format!("its deepest point {margin:.3} inside them")
    } else {
        "it misses the plane's window".into()
    }
}

/// The contour's problem: the pair's tooth numbers and the rack.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Blocking {
    /// z₁, z₂.
    pub z: [u32; 2],
    /// The rack.
    pub rack: BasicRack,
    /// h_l* = −v_j*: the depth of the flank's end below the rack's mean line, × m.
    pub hl: f64,
    /// The plane's window: (x₁ min, x₂ min), (x₁ max, x₂ max).
    pub window: (DVec2, DVec2),
    /// The rack's sin α, cos α, tg α and inv α, for [`Self::indices`].
    trig: [f64; 4],
}

/// Every (kind, limit) the contour traces.
pub fn levels(rack: &BasicRack, z: [u32; 2]) -> Vec<(Kind, f64)> {
    let hl = -rack.per_module().vj;
    let sin2 = rack.alpha.sin().powi(2);
    let mut out = Vec::new();
    for (i, zi) in z.iter().enumerate() {
        out.push((Kind::Undercut(i), hl - f64::from(*zi) * sin2 / 2.0));
    }
    for i in 0..2 {
        for l in TIP_LIMITS {
            out.push((Kind::Tip(i), l));
        }
    }
    for l in EPS_LIMITS {
        out.push((Kind::ContactRatio, l));
    }
    out.push((Kind::Interference(0), 0.0));
    out.push((Kind::Interference(1), 0.0));
    out.push((Kind::EqualSliding, 0.0));
    out
}

impl Blocking {
    /// The problem of z₁, z₂ cut by `rack`; its window spans each x from 0.4 below the
    /// undercut limit to 1.5 beyond the shift that points the wheel cut alone (the pair's Δy
    /// shortens the tip and moves its pointing out by up to about that), within ±[`X_MAX`]
    /// (its upper ends moved in to a whole number of [`SPACING`]s): it holds the whole
    /// admissible region of those shifts.
    ///
    /// # Errors
    /// [`GearError::Spec`] for fewer than 5 teeth, [`GearError::Rack`].
    pub fn new(z: [u32; 2], rack: BasicRack) -> Result<Self, BlockingError> {
        rack.validate()?;
        for (i, zi) in z.iter().enumerate() {
            if *zi < 5 {
                return Err(GearError::Spec {
                    what: if i == 0 { "z1" } else { "z2" },
                    value: f64::from(*zi),
                    expected: "at least 5 teeth",
                }
                .into());
            }
        }
        let hl = -rack.per_module().vj;
        let sin2 = rack.alpha.sin().powi(2);
        let mut lo = [0.0; 2];
        let mut hi = [0.0; 2];
        for i in 0..2 {
            let zi = f64::from(z[i]);
            lo[i] = (hl - zi * sin2 / 2.0 - 0.4).max(-X_MAX);
            hi[i] = (pointed_alone(zi, &rack, (lo[i], X_MAX)) + 1.5).min(X_MAX);
            if hi[i] < lo[i] + 0.5 {
                hi[i] = (lo[i] + 0.5).min(X_MAX);
            }
            // A whole number of the grid's steps (the grid's last node its edge).
            hi[i] = lo[i] + ((hi[i] - lo[i]) / SPACING + 1e-9).floor() * SPACING;
        }
        let a = rack.alpha;
        Ok(Self {
            z,
            rack,
            hl,
            window: (DVec2::new(lo[0], lo[1]), DVec2::new(hi[0], hi[1])),
            trig: [a.sin(), a.cos(), a.tan(), inv(a)],
        })
    }

    /// x_min,i = h_l* − z_i sin²α/2.
    pub fn x_min(&self, i: usize) -> f64 {
        self.hl - f64::from(self.z[i]) * self.rack.alpha.sin().powi(2) / 2.0
    }
}
