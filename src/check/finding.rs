//! Findings: the verdicts a domain reaches about its scene — a source's erratum, a limit
//! exceeded, a cusp, an undercut, rigid shocks, an offset on the wrong side, no flywheel
//! needed — as typed values carrying their numbers. The domains produce them; `report` writes
//! them as English notes through [`Finding::english`] (the one place their English is
//! written), `sheets` as ru/uk/en lines through their word catalogue; tests match variants.
//!
//! A note is a [`Note`]: plain informative text with, where it states a verdict, the
//! [`Finding`] in its place in the sentence. All numbers are SI (m, rad, kg·m²).

use crate::scale::{format_sig, Lang};
use std::fmt;

/// A verdict with its numbers.
#[derive(Debug, Clone, PartialEq)]
pub enum Finding {
    /// The source quotes the cam's r_min, inconsistent with its data; not used.
    Erratum {
        /// The value the source quotes, m.
        quoted: f64,
        /// The value that follows from the data, m.
        exact: f64,
        /// What it follows from.
        basis: RadiusBasis,
    },
    /// The worst angle over the cycle passes its limit at the base radius used.
    LimitExceeded {
        /// The angle limited.
        what: Limit,
        /// Its worst value over the cycle, rad.
        worst: f64,
        /// Its limit (λ_max or γ_min), rad.
        limit: f64,
        /// The base radius it was checked at.
        base: BaseUsed,
    },
    /// The profile comes to a point or loops back.
    Cusp(Cusp),
    /// The roller exceeds the pitch curve's smallest convex radius of curvature: the
    /// practical profile is cut away.
    Undercut {
        /// The roller radius, m.
        roller: f64,
        /// The pitch curve's smallest convex radius of curvature, m.
        rho_min: f64,
    },
    /// The law's velocity jumps at the phase's ends: rigid shocks.
    RigidShock {
        /// The phase's start, rad of cam turn.
        from: f64,
        /// The phase's end, rad of cam turn.
        to: f64,
        /// The jump of dS/dφ from 0, m.
        jump: f64,
    },
    /// The follower's offset is on the side that raises the pressure angle on the rise.
    WrongSide {
        /// The offset as the scene gives it, m.
        offset: f64,
        /// The largest pressure angle on the rise with it, rad.
        rise_max: f64,
        /// The offset on the other side of the centre, m.
        other_offset: f64,
        /// The largest pressure angle on the rise with that one, rad.
        other_max: f64,
    },
    /// The machine runs within the δ asked without a flywheel.
    NoFlywheelNeeded(NoFlywheel),
}

/// What an r_min follows from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RadiusBasis {
    /// A flat face: the profile convex, r₀ ≥ max(−(S + S″)) + ρ_min.
    Convexity {
        /// The least radius of curvature of the profile asked, m.
        rho_min: f64,
    },
    /// The transmission angle γ ≥ γ_min on the rise only (force closure).
    AngleOnRise {
        /// γ_min, rad.
        gamma_min: f64,
    },
    /// The transmission angle γ ≥ γ_min over the whole cycle.
    AngleOverCycle {
        /// γ_min, rad.
        gamma_min: f64,
    },
}

/// The angle whose limit a cam passes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Limit {
    /// The pressure angle above λ_max (translating follower).
    PressureAngle,
    /// The transmission angle below γ_min (rocker).
    TransmissionAngle,
}

/// The base radius a limit was checked at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BaseUsed {
    /// The scene's base radius.
    Given,
    /// Read off the combined diagram.
    Read {
        /// The diagram's points.
        points: usize,
        /// The base radius read and used, m.
        used: f64,
        /// The exact r_min, m.
        exact: f64,
    },
}

/// Where a profile comes to a point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cusp {
    /// A flat face: the profile concave, ρ = r₀ + S + S″ < 0.
    Flat {
        /// The least ρ, m (negative).
        rho: f64,
        /// The base radius r₀ used, m.
        base: f64,
        /// The least r₀ with a convex profile, m.
        r_min: f64,
    },
    /// The roller radius equals the pitch curve's smallest convex radius of curvature to
    /// 1e-12.
    Roller {
        /// The roller radius, m.
        roller: f64,
        /// The pitch curve's smallest convex radius of curvature, m.
        rho_min: f64,
    },
}

/// How a flywheel was found unnecessary.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NoFlywheel {
    /// The energy equation integrated exactly keeps δ within the δ asked without one.
    Exact {
        /// δ without a flywheel.
        delta: f64,
        /// δ asked.
        asked: f64,
    },
    /// A textbook route reads J ≤ 0.
    Reads {
        /// The route.
        route: Route,
        /// The J read, kg·m².
        read: f64,
    },
    /// Merkin's route on the continuous exact data gives J ≤ 0.
    Continuous {
        /// The J it gives, kg·m².
        j: f64,
    },
}

/// A textbook route to the flywheel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Route {
    /// Wittenbauer's diagram and its tangents.
    Wittenbauer,
    /// Merkin's T_I diagram.
    Merkin,
}

/// A number in a note: 5 significant digits.
fn num(x: f64) -> String {
    format_sig(x, 5, Lang::En)
}
/// A number of the dynamics' notes: 6 significant digits.
fn num6(x: f64) -> String {
    format_sig(x, 6, Lang::En)
}
/// A length in mm in a note.
fn mm(x: f64) -> String {
    num(x * 1e3)
}
/// An angle in degrees in a note.
fn deg(x: f64) -> String {
    format_sig(x.to_degrees(), 4, Lang::En)
}

/// Two lengths in mm in a note, with as many significant digits (5 to 15) as tell them
/// apart.
pub fn mm_pair(a: f64, b: f64) -> (String, String) {
    let at = |d| {
        (
            format_sig(a * 1e3, d, Lang::En),
            format_sig(b * 1e3, d, Lang::En),
        )
    };
    (5..15)
        .map(at)
        .find(|(x, y)| x != y)
        .unwrap_or_else(|| at(15))
}

impl RadiusBasis {
    /// The criterion in English, as the notes state it.
    pub fn english(&self) -> String {
        match *self {
            RadiusBasis::Convexity { rho_min } => format!(
                "convexity r₀ ≥ max(−(S + S″)) + ρ_min, ρ_min = {} mm",
                mm(rho_min)
            ),
            RadiusBasis::AngleOnRise { gamma_min } => {
                format!("γ ≥ {}° on the rise (force closure)", deg(gamma_min))
            }
            RadiusBasis::AngleOverCycle { gamma_min } => {
                format!("γ ≥ {}° over the whole cycle", deg(gamma_min))
            }
        }
    }
}

impl BaseUsed {
    fn english(&self) -> String {
        match *self {
            BaseUsed::Given => "at the given base radius".into(),
            BaseUsed::Read {
                points,
                used,
                exact,
            } => {
                let how = if used < exact { "below" } else { "against" };
                let (used, exact) = mm_pair(used, exact);
                format!(
                    "at the base radius used (read off the combined diagram at its {points} points, {used} mm, {how} the exact {exact} mm)"
                )
            }
        }
    }
}

impl Finding {
    /// The finding as the report's notes state it (without the note's domain prefix).
    pub fn english(&self) -> String {
        match self {
            Finding::Erratum {
                quoted,
                exact,
                basis,
            } => format!(
                "ERRATUM of the source: it quotes r_min = {} mm, inconsistent with its data: with {} the minimum is {} mm (the quoted value is {}× too small) and is not used",
                mm(*quoted),
                basis.english(),
                mm(*exact),
                num(exact / quoted)
            ),
            Finding::LimitExceeded { what, base, .. } => match what {
                Limit::PressureAngle => format!("EXCEEDED {}", base.english()),
                Limit::TransmissionAngle => format!("BELOW γ_min {}", base.english()),
            },
            Finding::Cusp(Cusp::Flat { rho, base, r_min }) => format!(
                "CUSP: the flat-faced profile is concave (ρ = r₀ + S + S″ = {} mm < 0 at r₀ = {} mm): the face lines' envelope loops back and the follower cannot reproduce the law; r₀ must be at least {} mm",
                mm(*rho),
                mm(*base),
                mm(*r_min)
            ),
            Finding::Cusp(Cusp::Roller { roller, rho_min }) => format!(
                "CUSP: the roller radius {} mm equals the pitch curve's smallest convex radius of curvature {} mm (to 1e-12): the practical profile comes to a point there; a smaller roller is needed",
                mm(*roller),
                mm(*rho_min)
            ),
            Finding::Undercut { roller, rho_min } => {
                let (r, p) = mm_pair(*roller, *rho_min);
                format!(
                    "UNDERCUT: the roller radius {r} mm exceeds the pitch curve's smallest convex radius of curvature {p} mm: the practical profile (the rollers' envelope) loops and is cut away; the largest admissible roller is just under {p} mm"
                )
            }
            Finding::RigidShock { from, to, jump } => format!(
                "RIGID SHOCKS: the velocity jumps at φ = {}° and {}° (dS/dφ = ±{} m from 0), the acceleration is infinite there",
                deg(*from),
                deg(*to),
                num(*jump)
            ),
            Finding::WrongSide {
                offset,
                rise_max,
                other_offset,
                other_max,
            } => format!(
                "OFFSET ON THE WRONG SIDE: e = {} mm raises the pressure angle on the rise to {}° (with e = {} mm on the other side of the centre it would be {}°)",
                mm(*offset),
                deg(*rise_max),
                mm(*other_offset),
                deg(*other_max)
            ),
            Finding::NoFlywheelNeeded(NoFlywheel::Exact { delta, asked }) => format!(
                "no flywheel is needed: the energy equation integrated exactly gives δ = {} without one, within the δ = {} asked",
                num6(*delta),
                num6(*asked)
            ),
            Finding::NoFlywheelNeeded(NoFlywheel::Reads { read, .. }) => format!(
                "no flywheel is needed (it reads J = {} kg·m² ≤ 0)",
                num6(*read)
            ),
            Finding::NoFlywheelNeeded(NoFlywheel::Continuous { j }) => {
                format!("needs no flywheel (J = {} kg·m² ≤ 0)", num6(*j))
            }
        }
    }
}

/// One piece of a note: plain text, or a finding in its place in the sentence.
#[derive(Debug, Clone, PartialEq)]
pub enum Part {
    /// Plain informative text.
    Text(String),
    /// A verdict, written through [`Finding::english`].
    Finding(Finding),
}

/// A note of the report: text and findings in the order the sentence states them.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Note(pub Vec<Part>);

impl Note {
    /// A note of plain text.
    pub fn text(s: impl Into<String>) -> Note {
        Note(vec![Part::Text(s.into())])
    }
    /// A note: `lead`, then the finding.
    pub fn finding(lead: impl Into<String>, f: Finding) -> Note {
        Note(vec![Part::Text(lead.into()), Part::Finding(f)])
    }
    /// Appends text.
    pub fn then(mut self, s: impl Into<String>) -> Note {
        self.0.push(Part::Text(s.into()));
        self
    }
    /// Appends another note's parts.
    pub fn append(mut self, other: Note) -> Note {
        self.0.extend(other.0);
        self
    }
    /// Appends a finding.
    pub fn with(mut self, f: Finding) -> Note {
        self.0.push(Part::Finding(f));
        self
    }
    /// The findings this note states.
    pub fn findings(&self) -> impl Iterator<Item = &Finding> {
        self.0.iter().filter_map(|p| match p {
            Part::Finding(f) => Some(f),
            Part::Text(_) => None,
        })
    }
}

impl fmt::Display for Note {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for p in &self.0 {
            match p {
                Part::Text(s) => f.write_str(s)?,
                Part::Finding(x) => f.write_str(&x.english())?,
            }
        }
        Ok(())
    }
}

/// The findings of a list of notes, in order.
pub fn findings(notes: &[Note]) -> Vec<Finding> {
    notes.iter().flat_map(Note::findings).cloned().collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_note_writes_its_text_and_findings_in_order_and_lists_the_findings() {
        let undercut = Finding::Undercut {
            roller: 0.015,
            rho_min: 0.0149999,
        };
        let note = Note::finding("cam: ", undercut.clone()).then(".");
        let text = note.to_string();
        assert!(
            text.starts_with("cam: UNDERCUT: the roller radius 15 mm"),
            "{text}"
        );
        // The digits grow until the two lengths differ.
        assert!(text.contains("radius of curvature 14.9999 mm"), "{text}");
        assert!(text.ends_with("just under 14.9999 mm."), "{text}");
        let notes = [Note::text("plain"), note];
        assert_eq!(findings(&notes), vec![undercut]);
        assert_eq!(notes[0].to_string(), "plain");
    }

    #[test]
    fn a_limit_names_the_base_radius_it_was_checked_at() {
        let at = |base| Finding::LimitExceeded {
            what: Limit::PressureAngle,
            worst: 0.53,
            limit: 0.52,
            base,
        };
        assert_eq!(
            at(BaseUsed::Given).english(),
            "EXCEEDED at the given base radius"
        );
        let read = at(BaseUsed::Read {
            points: 26,
            used: 0.0699,
            exact: 0.07,
        });
        assert_eq!(
            read.english(),
            "EXCEEDED at the base radius used (read off the combined diagram at its 26 points, 69.9 mm, below the exact 70 mm)"
        );
    }
}
