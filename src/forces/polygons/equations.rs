//! The moment equations the drawings of a position work: each load's moment about the moment
//! centre with the arm read off the drawing, and what the equation gives (a reaction's
//! part, a reaction's arm, the balancing load) — what the explanatory note writes out with
//! its numbers. The equations are records of the constructions' own arithmetic: every term
//! is the moment the construction summed.

use crate::geom::DVec2;

/// A load's moment about a centre, as the construction measured it.
#[derive(Debug, Clone, PartialEq)]
pub struct MomentTerm {
    /// The load's name (label markup).
    pub name: String,
    /// Its magnitude: a force, N; a couple's moment, N·m.
    pub force: f64,
    /// Its arm as read off the drawing in the drawing's quantity (m on a group's drawing,
    /// m/s on Zhukovsky's lever); 0 for a couple.
    pub arm: f64,
    /// The arm as read off the drawing, mm.
    pub arm_mm: f64,
    /// The arm's label on the drawing (`h_{2}`), when it is drawn.
    pub label: Option<String>,
    /// The moment (counter-clockwise positive): N·m, on the lever N·m/s (a power, W).
    pub moment: f64,
    /// Whether the load is a couple (its moment enters as it is).
    pub couple: bool,
}

/// What a moment equation gives.
#[derive(Debug, Clone, PartialEq)]
pub enum Unknown {
    /// A force of known line, `Σ + value·arm = 0`: a reaction's tangential part (arm: the
    /// link's length, signed), a reaction normal to a slide or the balancing force (arm
    /// measured, signed).
    Force {
        /// Its name (label markup).
        name: String,
        /// Its signed arm: the moment of a unit force along it, m (m/s on the lever).
        arm: f64,
        /// The arm as read, mm.
        arm_mm: f64,
        /// The arm's label on the drawing (`h_{3}`), when it is drawn; `None` for a
        /// link's length.
        label: Option<String>,
        /// The force, N.
        value: f64,
    },
    /// The arm of a reaction known from the polygon, `Σ + force·value = 0` (where a
    /// slider's guide reaction acts).
    Arm {
        /// The arm's name (`h_{0-5}`).
        name: String,
        /// The reaction's name.
        reaction: String,
        /// The reaction's component normal to the slide, N (signed).
        force: f64,
        /// The arm, m.
        value: f64,
    },
    /// A couple, `Σ + value = 0`: the balancing moment of a coupling.
    Couple {
        /// Its name.
        name: String,
        /// The moment, N·m.
        value: f64,
    },
}

/// One moment equation of a drawing.
#[derive(Debug, Clone, PartialEq)]
pub struct MomentEquation {
    /// The moment centre: a point of the mechanism (its index), `None` for the lever's pole.
    pub about: Option<usize>,
    /// The links whose loads it sums.
    pub links: Vec<usize>,
    /// The known loads' moments.
    pub terms: Vec<MomentTerm>,
    /// What it gives.
    pub unknown: Unknown,
}

impl MomentEquation {
    /// The sum of the known moments.
    pub fn known(&self) -> f64 {
        self.terms.iter().map(|t| t.moment).sum()
    }

    /// What is left of the equation with its unknown put in: zero up to rounding.
    pub fn residue(&self) -> f64 {
        self.known()
            + match &self.unknown {
                Unknown::Force { arm, value, .. } => arm * value,
                Unknown::Arm { force, value, .. } => force * value,
                Unknown::Couple { value, .. } => *value,
            }
    }
}

impl super::Scheme<'_> {
    /// The moments taken since the last call, in order.
    pub(super) fn drain(&mut self) -> Vec<MomentTerm> {
        std::mem::take(&mut self.log)
    }

    /// The equation of the moments taken since the last [`Self::drain`] about point
    /// `about` of `links`, giving `unknown`.
    pub(super) fn equation(
        &mut self,
        about: usize,
        links: &[usize],
        unknown: Unknown,
    ) -> MomentEquation {
        MomentEquation {
            about: Some(about),
            links: links.to_vec(),
            terms: self.drain(),
            unknown,
        }
    }

    /// The tangential part `value` (N) of the reaction `(from, to)` at `a` on a link of
    /// length AB (drawing points `a`, `b`, mm): its moment about B is −value·AB.
    pub(super) fn tangential(
        &mut self,
        a: DVec2,
        b: DVec2,
        (from, to): (usize, usize),
        value: f64,
    ) -> Unknown {
        let m = self.rec.measure(a, b);
        Unknown::Force {
            name: format!("R^τ_{{{from}-{to}}}"),
            arm: -m.value,
            arm_mm: m.read_mm,
            label: None,
            value,
        }
    }

    /// The equation of the moments taken since the last drain about point `about` of link
    /// `link` that places the reaction `(from, to)` of normal component `force` (N) at its
    /// arm `arm` (m); `None` when the reaction vanishes (it has no arm).
    pub(super) fn arm_equation(
        &mut self,
        about: usize,
        link: usize,
        (from, to): (usize, usize),
        force: f64,
        arm: Option<f64>,
    ) -> Option<MomentEquation> {
        let terms = self.drain();
        arm.map(|value| MomentEquation {
            about: Some(about),
            links: vec![link],
            terms,
            unknown: Unknown::Arm {
                name: format!("h_{{{from}-{to}}}"),
                reaction: format!("R_{{{from}-{to}}}"),
                force,
                value,
            },
        })
    }

    /// The equation about `about` of links `[i, j]` (their moments `known`) giving the
    /// reaction of `i` on `j` normal to the slide, `value` (N), whose unit force's moment
    /// is the last taken.
    pub(super) fn normal(
        &mut self,
        about: usize,
        [i, j]: [usize; 2],
        known: Vec<MomentTerm>,
        value: f64,
    ) -> MomentEquation {
        let probe = self.drain().pop();
        MomentEquation {
            about: Some(about),
            links: vec![i, j],
            terms: known,
            unknown: Unknown::Force {
                name: super::reaction_name(i, j),
                arm: probe.as_ref().map_or(0.0, |t| t.moment),
                arm_mm: probe.as_ref().map_or(0.0, |t| t.arm_mm),
                label: probe.and_then(|t| t.label),
                value,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_equation_with_its_unknown_put_in_balances() {
        let t = MomentTerm {
            name: "G_{3}".into(),
            force: 100.0,
            arm: 0.2,
            arm_mm: 80.0,
            label: Some("h_{1}".into()),
            moment: -20.0,
            couple: false,
        };
        let e = MomentEquation {
            about: Some(2),
            links: vec![3],
            terms: vec![t],
            unknown: Unknown::Force {
                name: "R".into(),
                arm: -0.4,
                arm_mm: 160.0,
                label: None,
                value: -50.0,
            },
        };
        assert_eq!(e.known(), -20.0);
        assert!(e.residue().abs() < 1e-12);
    }
}
