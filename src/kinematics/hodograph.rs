//! The hodograph of a point's velocity: the velocity vectors of every position from one
//! pole (copied from the velocity plans), their ends joined by a smooth curve.

use super::KinError;
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::DVec2;
use crate::linkage::{KinPlan, PositionPlan};
use crate::scale::{Quantity, Scale};

/// The longest hodograph vector is drawn at most this long, mm (at the round μ, half to all
/// of it): a hodograph is read by its twelve ends and their numbers, which crowd about the
/// pole at 30–60 mm (the shaper's «1 ≡ 8′ 2 3 4 5» within 15 mm, the six-bar's «12 11 p 10′»).
const HODOGRAPH_MM: f64 = 100.0;

/// The point whose hodograph is drawn: the scene's, or the first point of a link.
pub fn hodograph_point(
    plan: &PositionPlan,
    asked: Option<&str>,
) -> Result<Option<usize>, KinError> {
    let prog = &plan.program;
    // By default the first link point that moves: a point at a pivot would be a blob.
    let moves = |k: usize| {
        plan.positions
            .iter()
            .any(|p| !crate::check::is_zero(p.pose.dp[k].length(), prog.crank_length))
    };
    let name = match asked {
        Some(n) => n.to_string(),
        None => match prog.placed_points().find(|&k| moves(k)) {
            Some(k) => prog.names[k].clone(),
            None => return Ok(None),
        },
    };
    prog.index(&name).map(Some).ok_or(KinError::NoSuchPoint {
        key: "hodograph",
        name,
    })
}

/// The hodograph of point `k` from the velocity plans (each at its own μ_v, the common one
/// `scale_v`; `None` where a plan is refused), at its own μ: the longest vector drawn at most
/// [`HODOGRAPH_MM`] long.
pub fn hodograph(
    plan: &PositionPlan,
    k: usize,
    velocity: &[Option<&KinPlan>],
    scale_v: Scale,
    ctx: &Context,
) -> Figure {
    let name = &plan.program.names[k];
    let longest = velocity
        .iter()
        .flatten()
        .map(|vp| vp.images[k].length() * vp.figure.scale.value())
        .fold(0.0, f64::max);
    let scale =
        Scale::round_for(longest.max(1e-12), HODOGRAPH_MM, Quantity::Velocity).unwrap_or(scale_v);
    let mut rec = Recorder::in_context("hodograph", scale, ctx);
    rec.pole("p");
    let mut ends = Vec::new();
    for (pos, vp) in plan
        .positions
        .iter()
        .zip(velocity)
        .filter_map(|(p, v)| v.map(|v| (p, v)))
    {
        // The vector copied from the velocity plan, redrawn at the hodograph's μ.
        let end = vp.images[k] * (vp.figure.scale.value() / scale.value());
        let id = rec.draw(
            format!("v of {name}, position {}", pos.label),
            Item::Vector {
                from: DVec2::ZERO,
                to: end,
            },
            Role::Construction,
            &[],
        );
        rec.label(id, pos.label.clone(), end, end.normalize_or(DVec2::Y));
        ends.push(end);
    }
    rec.draw(
        format!("hodograph of {name}"),
        Item::Curve {
            points: ends,
            closed: true,
        },
        Role::Result,
        &[],
    );
    rec.finish()
}
