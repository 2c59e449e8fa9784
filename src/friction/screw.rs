//! The screw pair (seed 001 §11): the nut element is a body on the unrolled thread, an
//! inclined plane of the lead angle λ, pushed by the tangential force P at the mean radius
//! r₁; a triangular or trapezoidal thread acts as a V-groove slider with the reduced
//! coefficient f′ = f/cos(δ/2). The wrench moment is M = P·r₁.

use super::draw::angle_mark;
use super::incline::{body_on_plane, eta_read, feasible, incline_twin, polygon, readings};
use super::{
    friction_angle, reading, subject, Drawing, DrawingKind, FrictionCase, FrictionError, Incline,
    Motion, Screw, Solved,
};
use crate::check::notes::FrictionNote;
use crate::check::Symbol;
use crate::construct::{ConstructionError, Context, Item, Role};
use crate::geom::{DVec2, Segment, Side};
use std::f64::consts::TAU;

/// Preferred drawn length of the unrolled turn 2πr₁, mm.
const UNROLLED_MM: f64 = 70.0;

/// The closed form of a screw pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScrewTwin {
    /// The reduced coefficient f′ = f/cos(δ/2) (f itself for a rectangular thread).
    pub f_reduced: f64,
    /// The reduced friction angle φ′ = arctg f′, rad.
    pub phi_reduced: f64,
    /// The tangential force at r₁, `Q·tg(λ ± φ′)`, N (negative: the load does not lower
    /// itself).
    pub p: f64,
    /// The wrench moment `M = Q·r₁·tg(λ ± φ′)`, N·m.
    pub moment: f64,
    /// The efficiency: `tg λ / tg(λ + φ′)` screwing, `tg(λ − φ′)/tg λ` unscrewing.
    pub eta: f64,
    /// Self-locking: λ ≤ φ′ (the load cannot turn the screw back).
    pub self_locking: bool,
}

/// The screw as an inclined plane: α = λ, P horizontal, f′ for the friction.
pub(super) fn as_incline(c: &Screw) -> Incline {
    Incline {
        load: c.load,
        f: c.f / (c.profile / 2.0).cos(),
        alpha: c.lead,
        beta: 0.0,
        motion: c.motion,
    }
}

/// The twin of a screw pair.
pub fn screw_twin(c: &Screw) -> ScrewTwin {
    let f_reduced = c.f / (c.profile / 2.0).cos();
    let phi = friction_angle(f_reduced);
    let s = c.motion.sign();
    let p = c.load * (c.lead + s * phi).tan();
    let eta = match c.motion {
        Motion::Up => c.lead.tan() / (c.lead + phi).tan(),
        Motion::Down => (c.lead - phi).tan() / c.lead.tan(),
    };
    ScrewTwin {
        f_reduced,
        phi_reduced: phi,
        p,
        moment: p * c.radius,
        eta,
        self_locking: c.lead <= phi,
    }
}

/// How far the turn's dimension line runs under the lowest thing drawn, mm: its text
/// (3,5 mm high, ГОСТ 2.304) over it and a gap of 6 mm over the text.
const DIMENSION_CLEAR_MM: f64 = 10.0;

/// The unrolled thread at μ_l: one turn 2πr₁ along the base, the lead over it, the nut
/// element on the helix with its loads, friction cone and reaction.
fn scheme(case: &FrictionCase, c: &Screw, ctx: &Context) -> Result<(Drawing, f64), FrictionError> {
    let turn = TAU * c.radius;
    let mut rec = case.scheme_recorder(turn, UNROLLED_MM, ctx)?;
    let mu = rec.scale();
    let base = mu.to_mm(turn);
    let start = DVec2::new(-base / 2.0, 0.0);
    let end = DVec2::new(base / 2.0, base * c.lead.tan());
    let corner = DVec2::new(base / 2.0, 0.0);
    rec.draw(
        "the unrolled helix at the mean radius",
        Item::Guide {
            segment: Segment::new(start, end),
            hatch: Side::Right,
        },
        Role::Given,
        &[],
    );
    // The development's base, one turn long: with the lead it closes the triangle whose
    // angle at its start is λ.
    rec.draw(
        "the base of the development: one turn",
        Item::Segment(Segment::new(start, corner)),
        Role::Construction,
        &[],
    );
    let lead = rec.draw(
        "the lead",
        Item::Segment(Segment::new(corner, end)),
        Role::Construction,
        &[],
    );
    rec.label(lead, "p_{h}", (corner + end) / 2.0, DVec2::X);
    angle_mark(&mut rec, "λ", start, 26.0, (DVec2::X, end - start), "λ");
    let phi_read = body_on_plane(&mut rec, &as_incline(c), (start + end) / 2.0);
    // The turn dimensioned under everything drawn, its text (over the line) clear of it too:
    // the load Q runs down past the base, and a dimension line across it, or a text under
    // its head, would read as part of the load.
    let low = rec.bounds().map_or(0.0, |(lo, _)| lo.y.min(0.0));
    let offset = low - DIMENSION_CLEAR_MM;
    let id = rec.draw(
        "one turn unrolled: πd₁",
        Item::Dimension {
            from: start,
            to: corner,
            offset,
        },
        Role::Dimension,
        &[],
    );
    rec.label(
        id,
        "πd_{1}",
        (start + corner) / 2.0 + DVec2::Y * offset,
        -DVec2::Y,
    );
    Ok((
        Drawing {
            kind: DrawingKind::Scheme,
            figure: rec.finish(),
            scaled: true,
            also: Vec::new(),
        },
        phi_read,
    ))
}

/// Construct the case and read it.
pub(super) fn solve(
    case: &FrictionCase,
    c: &Screw,
    ctx: &Context,
    wrap: &dyn Fn(ConstructionError) -> FrictionError,
) -> Result<Solved, FrictionError> {
    let twin = screw_twin(c);
    let plane = as_incline(c);
    let plane_twin = incline_twin(&plane);
    feasible(&case.name, &plane, twin.phi_reduced)?;
    let (scheme, phi_read) = scheme(case, c, ctx)?;
    let (poly, with, without) = polygon(case, &plane, &plane_twin, ctx, wrap)?;
    let eta = eta_read(c.motion, with.p, without.map(|t| t.p));
    let cond = Some(with.crossing_deg);
    let mut out = vec![reading(
        "φ′",
        (Symbol::Angle, subject("phi", &case.name)),
        phi_read,
        twin.phi_reduced,
        None,
    )];
    out.extend(readings(&case.name, &plane_twin, &with, eta));
    out.push(reading(
        "M",
        (Symbol::Moment, subject("", &case.name)),
        with.p * c.radius,
        twin.moment,
        cond,
    ));
    let mut notes = vec![FrictionNote::ScrewErratum {
        case: case.name.clone(),
        up: c.motion == Motion::Up,
    }];
    if twin.self_locking {
        notes.push(FrictionNote::SelfLocking {
            case: case.name.clone(),
            lead: c.lead,
            phi: twin.phi_reduced,
        });
    }
    Ok(Solved {
        case: case.clone(),
        drawings: vec![scheme, poly],
        readings: out,
        notes,
    })
}

#[cfg(test)]
mod tests {
    use super::super::{solve, CaseKind, DrawingKind, Motion, Screw};
    use super::DIMENSION_CLEAR_MM;
    use crate::construct::Item;

    /// The unrolled thread's turn πd₁ is dimensioned under the load Q, which runs down past
    /// the base, its text clear of Q's head: a dimension line across the load read as part
    /// of it (issue 45: Q's arrow through πd₁).
    #[test]
    fn the_turn_is_dimensioned_under_the_load() {
        let screw = Screw {
            load: 10_000.0,
            f: 0.15,
            lead: 2.5f64.to_radians(),
            profile: 60f64.to_radians(),
            radius: 0.009,
            motion: Motion::Up,
        };
        let case = crate::friction::tests::case("4", CaseKind::Screw(screw));
        let solved = solve(&case, &crate::friction::tests::ctx(0.0)).expect("solved");
        let scheme = solved
            .drawings
            .iter()
            .find(|d| d.kind == DrawingKind::Scheme)
            .expect("the scheme");
        let steps = &scheme.figure.steps;
        let q_low = steps
            .iter()
            .find_map(|st| match st.item {
                Item::Vector { from, to } if st.note == "the load" => Some(from.y.min(to.y)),
                _ => None,
            })
            .expect("Q");
        let line = steps
            .iter()
            .find_map(|st| match st.item {
                Item::Dimension { from, offset, .. } => Some(from.y + offset),
                _ => None,
            })
            .expect("πd₁");
        assert!(
            q_low - line >= DIMENSION_CLEAR_MM - 1e-9,
            "Q to {q_low}, πd₁ at {line}"
        );
    }
}
