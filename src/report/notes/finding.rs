//! The English of a verdict ([`Finding`]) as the report's notes state it (without the
//! note's domain prefix), and the number formats the cam's and the dynamics' notes share.

use super::sig;
use crate::check::{BaseUsed, Cusp, Finding, Limit, NoFlywheel, RadiusBasis};

/// A number in a cam's note: 5 significant digits.
pub(super) fn num(x: f64) -> String {
    sig(x, 5)
}
/// A number of the dynamics' notes: 6 significant digits.
pub(super) fn num6(x: f64) -> String {
    sig(x, 6)
}
/// A length in mm in a note.
pub(super) fn mm(x: f64) -> String {
    num(x * 1e3)
}
/// An angle in degrees in a note.
pub(super) fn deg(x: f64) -> String {
    sig(x.to_degrees(), 4)
}

/// Two lengths in mm in a note, with as many significant digits (5 to 15) as tell them
/// apart.
fn mm_pair(a: f64, b: f64) -> (String, String) {
    let at = |d| (sig(a * 1e3, d), sig(b * 1e3, d));
    (5..15)
        .map(at)
        .find(|(x, y)| x != y)
        .unwrap_or_else(|| at(15))
}

/// The criterion an r_min follows from, as the notes state it.
pub(super) fn basis(b: &RadiusBasis) -> String {
    match *b {
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

/// The base radius a limit was checked at.
fn base_used(b: &BaseUsed) -> String {
    match *b {
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

/// The finding in English.
pub(super) fn english(f: &Finding) -> String {
    match f {
        Finding::Erratum {
            quoted,
            exact,
            basis: b,
        } => format!(
            "ERRATUM of the source: it quotes r_min = {} mm, inconsistent with its data: with {} the minimum is {} mm (the quoted value is {}× too small) and is not used",
            mm(*quoted),
            basis(b),
            mm(*exact),
            num(exact / quoted)
        ),
        Finding::LimitExceeded { what, base, .. } => match what {
            Limit::PressureAngle => format!("EXCEEDED {}", base_used(base)),
            Limit::TransmissionAngle => format!("BELOW γ_min {}", base_used(base)),
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_undercut_writes_as_many_digits_as_tell_its_lengths_apart() {
        let text = english(&Finding::Undercut {
            roller: 0.015,
            rho_min: 0.0149999,
        });
        assert!(
            text.starts_with("UNDERCUT: the roller radius 15 mm"),
            "{text}"
        );
        // The digits grow until the two lengths differ.
        assert!(text.contains("radius of curvature 14.9999 mm"), "{text}");
        assert!(text.ends_with("just under 14.9999 mm"), "{text}");
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
            english(&at(BaseUsed::Given)),
            "EXCEEDED at the given base radius"
        );
        let read = at(BaseUsed::Read {
            points: 26,
            used: 0.0699,
            exact: 0.07,
        });
        assert_eq!(
            english(&read),
            "EXCEEDED at the base radius used (read off the combined diagram at its 26 points, 69.9 mm, below the exact 70 mm)"
        );
    }
}
