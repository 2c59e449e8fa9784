//! The English of the friction studies' notes ([`FrictionNote`]).

use crate::check::notes::friction::{FrictionNote, RollerMotion, SliderMotion};

/// + up, − down.
fn sign(up: bool) -> &'static str {
    if up {
        "+"
    } else {
        "−"
    }
}

/// A slider's motion in words.
fn motion(s: SliderMotion) -> &'static str {
    match s {
        SliderMotion::Rest => "at rest",
        SliderMotion::Uniform => "uniform motion",
        SliderMotion::Accelerating => "accelerating",
    }
}

/// The note in English.
pub(super) fn english(note: &FrictionNote) -> String {
    match note {
        FrictionNote::Guide {
            case,
            angle,
            lock,
            useful,
            across,
        } => format!(
            "{case}: the follower moves while λ = {:.2}° < λ_кр = {:.2}° (tg λ_кр = b/(f(2l + b))); \
             P·cos λ = {useful:.4} N = Q + f(N₁ + N₂), the useful part of P; P·sin λ = {across:.4} N loads the \
             guide",
            angle.to_degrees(),
            lock.to_degrees(),
        ),
        FrictionNote::InclineErratum { case, up } => format!(
            "{case}: twin P = Q·sin(α {} φ)/cos(α {} φ − β′) from the vector solution of Q + P + R = 0; \
             the seed's printed P = Q·sin(α + φ)/cos(α + β + φ) is an erratum (sin[π − x] is not cos x)",
            sign(*up),
            sign(*up),
        ),
        FrictionNote::SelfBraking { case, alpha, phi } => format!(
            "{case}: self-braking: α = {:.2}° ≤ φ = {:.2}°, the body must be pushed down (P < 0)",
            alpha.to_degrees(),
            phi.to_degrees()
        ),
        FrictionNote::Journal {
            case,
            rho,
            textbook,
            moment,
        } => format!(
            "{case}: the friction circle drawn and read is ρ = r·sin φ = {rho:.6} m; the textbook's \
             ρ = f·r = {textbook:.6} m (M_f = f·Q·r = {moment:.4} N·m) is {:.3}% larger",
            (textbook / rho - 1.0) * 100.0
        ),
        FrictionNote::Pivot {
            case,
            angle,
            lock,
            rho,
            lecture,
        } => format!(
            "{case}: the rocker moves while λ = {:.2}° < λ_кр = {:.2}° (cos λ_кр = ρ/L, ρ = (d/2)·sin φ \
             = {rho:.6} m); the lecture's M_тр = P^n·f·d/2 gives tg λ_кр = 2L/(f·d): λ_кр = {:.2}°",
            angle.to_degrees(),
            lock.to_degrees(),
            lecture.to_degrees()
        ),
        FrictionNote::Rolling {
            case,
            first,
            second,
            motion,
        } => rolling(case, *first, *second, *motion),
        FrictionNote::RollingErratum { case, r_n2, gain } => format!(
            "{case}: R_n1 = Q, R_n2 = Q + 2G = {r_n2} N (the seed misprints the second as R_n1); \
             without rollers P = Q·f₂ is {gain:.1} times larger"
        ),
        FrictionNote::ScrewErratum { case, up } => format!(
            "{case}: screw as an inclined plane of the lead angle, P = Q·tg(λ {} φ′), f′ = f/cos(δ/2); \
             the seed's substitution cos(λ + π/2 + φ) = cos(λ + φ) is false as written",
            sign(*up)
        ),
        FrictionNote::SelfLocking { case, lead, phi } => format!(
            "{case}: self-locking: λ = {:.2}° ≤ φ′ = {:.2}°",
            lead.to_degrees(),
            phi.to_degrees()
        ),
        FrictionNote::Slider {
            case,
            alpha,
            phi,
            phi0,
            by_angles,
            by_triangle,
            net,
        } => format!(
            "{case}: α = {:.2}°, φ = {:.2}°, φ₀ = {:.2}°: {} by the angles, {} by the triangle (ΔP = {net:.4} N read)",
            alpha.to_degrees(),
            phi.to_degrees(),
            phi0.to_degrees(),
            motion(*by_angles),
            motion(*by_triangle),
        ),
    }
}

/// Rollers: k/d against f at each contact, pure rolling or where they slide.
fn rolling(
    case: &str,
    (ratio1, f1): (f64, f64),
    (ratio2, f2): (f64, f64),
    m: RollerMotion,
) -> String {
    let verdict = |ratio: f64, f: f64| if ratio < f { "<" } else { "≥" };
    format!(
        "{case}: k₁/d = {ratio1:.3e} {} f₁ = {f1}, k₂/d = {ratio2:.3e} {} f₂ = {f2}: {}",
        verdict(ratio1, f1),
        verdict(ratio2, f2),
        match m {
            RollerMotion::Rolling => "pure rolling".to_string(),
            RollerMotion::OnRollers { p, rolling } => format!(
                "the rollers slide: the load slides on them, P = Q·f₁ = {p} N (rolling would take {rolling} N)"
            ),
            RollerMotion::OnPlane { p, rolling } => format!(
                "the rollers slide: the load slides on the plane with them, P = (Q + 2G)·f₂ = {p} N (rolling would take {rolling} N)"
            ),
        }
    )
}
