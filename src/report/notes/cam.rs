//! The English of a cam study's notes ([`CamNote`]).

use super::finding::{self, basis, deg, mm, num};
use crate::check::notes::cam::{AngleCheck, CamNote, CamPhase, LawName, Shocks, SpecialNote};
use crate::check::{Finding, Limit};

/// The note in English.
pub(super) fn english(note: &CamNote) -> String {
    let said = match note {
        CamNote::Mirrored => "it turns clockwise: constructed as its mirror image (counter-clockwise, the offset on the other side) and drawn mirrored back; the numbers are the same".to_string(),
        CamNote::Law {
            phase,
            from,
            to,
            law: name,
            shocks,
        } => law(*phase, (*from, *to), *name, *shocks),
        CamNote::Angle(a) => angle(a),
        CamNote::LawAssumed { rise, ret } => format!(
            "the source's diagrams are lost: the law of the rise ({rise}) and of the return ({ret}) is assumed"
        ),
        CamNote::EqualReturn { ends, top, stroke } => format!(
            "equal-return check: dS/dφ at the end of the rise = {} m, of the return = {} m (0 exact); S at the end of the rise y_max·μ_S = {} m against the stroke {} m",
            num(ends[0]), num(ends[1]), num(*top), num(*stroke)
        ),
        CamNote::RMin { exact, basis: b, read, points } => format!(
            "r_min = {} mm exact ({}); {} mm read off the combined diagram at its {points} points",
            mm(*exact),
            basis(b),
            mm(*read),
        ),
        CamNote::Found(f) => finding::english(f),
        CamNote::FlatConvexity { exact, read } => format!(
            "flat face: max(−(S + S″)) = {} mm exact, {} mm read at the 45° tangent",
            mm(*exact),
            mm(*read)
        ),
        CamNote::FlatHalfLength(half) => format!("flat face: the face's half-length from the follower's axis ≥ max|dS/dφ − e| = {} mm", mm(*half)),
        CamNote::Roller { base, drawn, exact, roller, given } => format!(
            "roller: 0.4·r₀ = {} mm, 0.8·ρ_min = {} mm (ρ_min of the drawn pitch curve {} mm, exact {} mm): r = {} mm ({})",
            mm(0.4 * base), mm(0.8 * drawn), mm(*drawn), mm(*exact), mm(*roller),
            if *given { "given" } else { "chosen" }
        ),
        CamNote::OffsetFree { r_min, offset, scene_offset, scene_r_min } => format!(
            "with the offset free the smallest cam (lecture 15: O₁ where the two γ_min tangents meet) has r_min = {} mm at e = {} mm; the scene's e = {} mm gives {} mm",
            mm(*r_min),
            mm(*offset),
            mm(*scene_offset),
            mm(*scene_r_min)
        ),
        CamNote::Special(n) => special(n),
    };
    format!("cam: {said}")
}

/// A phase's law with its shocks; rigid shocks are a verdict, written after the law.
fn law(phase: CamPhase, (from, to): (f64, f64), law: LawName, shocks: Shocks) -> String {
    let name = match phase {
        CamPhase::Rise => "rise",
        CamPhase::Return => "return",
    };
    let what = match law {
        LawName::ConstantAcceleration { ratio } => {
            format!("constant acceleration \"+ −\" (ratio {})", num(ratio))
        }
        LawName::Key(key) => key.to_string(),
    };
    let lead = format!("{name} {}°–{}°: law {what}; ", deg(from), deg(to));
    match shocks {
        Shocks::Rigid { jump } => lead + &finding::english(&Finding::RigidShock { from, to, jump }),
        Shocks::Soft => lead + "soft shocks: the acceleration jumps (finite)",
        Shocks::None => lead + "no shock",
    }
}

/// The worst angle against its limit, and the verdict where it passes it.
fn angle(a: &AngleCheck) -> String {
    let lead = match a.what {
        Limit::TransmissionAngle => format!(
            "the smallest transmission angle over the cycle is {}° (γ_min = {}°)",
            deg(a.worst),
            deg(a.limit)
        ),
        Limit::PressureAngle => format!(
            "the largest pressure angle {} is {}° (λ_max = {}°)",
            if a.on_rise {
                "on the rise (force closure)"
            } else {
                "over the cycle"
            },
            deg(a.worst),
            deg(a.limit)
        ),
    };
    match a.exceeded {
        Some(base) => {
            let f = Finding::LimitExceeded {
                what: a.what,
                worst: a.worst,
                limit: a.limit,
                base,
            };
            format!("{lead}: {}", finding::english(&f))
        }
        None => lead,
    }
}

/// The notes of the special profiles: a flat-faced rocker's, a translating cam's.
fn special(note: &SpecialNote) -> String {
    match *note {
        SpecialNote::RockerFrame { centres, face_offset, base, psi0 } => format!(
            "flat-faced rocker: a = {} mm, e = {} mm, r₀ = {} mm: the face starts at ψ₀ = arcsin((r₀ + e)/a) = {}°",
            mm(centres),
            mm(face_offset),
            mm(base),
            deg(psi0)
        ),
        SpecialNote::RockerCurvature { exact, read, points } => format!(
            "flat-faced rocker: the profile's smallest radius of curvature ρ = h + d²h/dα² is {} mm exact, {} mm read off the face lines' crossings at the {points} points",
            mm(exact),
            mm(read),
        ),
        SpecialNote::RockerAngle(worst) => format!(
            "flat-faced rocker: the largest pressure angle at the points is {}° (tg λ = e/t, t the contact's distance along the face from the foot of O₂)",
            deg(worst)
        ),
        SpecialNote::Concave { rho, asked } => format!(
            "CONCAVE: the flat-faced rocker's profile has ρ_min = {} mm below the {} mm asked (cam.rho_min): the face lines' envelope {}; a larger r₀ or centre distance is needed",
            mm(rho),
            mm(asked),
            if rho < 0.0 { "loops back (a cusp)" } else { "is too sharp" }
        ),
        SpecialNote::Sliding { travel, roller } => format!(
            "translating cam: the law's cycle laid along the travel X = {} mm (ξ = X·φ/2π), roller r = {} mm",
            mm(travel),
            mm(roller)
        ),
        SpecialNote::SlidingAngle { worst, lambda_max, exact, read } => format!(
            "translating cam: the largest pressure angle at the points is {}° (λ_max = {}°); the shortest travel keeping λ ≤ λ_max is X_min = 2π·max|dS/dφ|/tg λ_max = {} mm exact, {} mm from the drawn angles",
            deg(worst),
            deg(lambda_max),
            mm(exact),
            mm(read)
        ),
        SpecialNote::ShortTravel { travel, x_min, lambda_max } => format!(
            "EXCEEDED: the travel X = {} mm is shorter than X_min = {} mm: the pressure angle passes λ_max = {}°",
            mm(travel),
            mm(x_min),
            deg(lambda_max)
        ),
        SpecialNote::SlidingCurvature { exact, read } => format!(
            "translating cam: the pitch curve's smallest convex radius of curvature is {} mm exact, {} mm through three drawn roller centres; the roller must stay under it (0.8·ρ_min = {} mm)",
            mm(exact),
            mm(read),
            mm(0.8 * exact)
        ),
    }
}
