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

/// The point whose hodograph is drawn: the scene's, or the first point of a link after the
/// crank that moves; none when the mechanism has no such point.
pub fn hodograph_point(
    plan: &PositionPlan,
    asked: Option<&str>,
) -> Result<Option<usize>, KinError> {
    let prog = &plan.program;
    // By default the first link point that moves (a point at a pivot would be a blob) and is
    // not the crank's: the crank turns uniformly, and its point's hodograph is a circle about
    // the pole that tells nothing the crank's ω₁ does not (the tangent mechanism's v_C drew
    // one 200 mm across).
    let moves = |k: usize| {
        plan.positions
            .iter()
            .any(|p| !crate::check::is_zero(p.pose.dp[k].length(), prog.crank_length))
    };
    let on_crank = |k: usize| prog.links_of(k).contains(&(prog.crank_link as usize));
    let name = match asked {
        Some(n) => n.to_string(),
        None => match prog.placed_points().find(|&k| moves(k) && !on_crank(k)) {
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
    // The ends in the order of the positions, `None` where a position has no plan (a
    // special position, where the velocity jumps or is not determined).
    let mut ends: Vec<Option<DVec2>> = Vec::with_capacity(plan.positions.len());
    for (pos, vp) in plan.positions.iter().zip(velocity) {
        let Some(vp) = vp else {
            ends.push(None);
            continue;
        };
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
        ends.push(Some(end));
    }
    for (points, closed) in pieces(&ends) {
        rec.draw(
            format!("hodograph of {name}"),
            Item::Curve { points, closed },
            Role::Result,
            &[],
        );
    }
    rec.finish()
}

/// The hodograph's curve through `ends` (a turn's positions in order, `None` where no plan
/// is drawn): closed round the turn when every position has its end; else a piece from each
/// gap to the next, not drawn across a position without a plan, whose velocity the curve
/// would make up (the six-bar's change point, where v_S3 jumps). A piece of one end is none.
fn pieces(ends: &[Option<DVec2>]) -> Vec<(Vec<DVec2>, bool)> {
    let Some(gap) = ends.iter().position(Option::is_none) else {
        return vec![(ends.iter().flatten().copied().collect(), true)];
    };
    // Round the turn from the first gap: every run of ends between two gaps is a piece.
    let n = ends.len();
    let mut out = Vec::new();
    let mut run: Vec<DVec2> = Vec::new();
    for k in 1..=n {
        match ends[(gap + k) % n] {
            Some(p) => run.push(p),
            None => {
                if run.len() > 1 {
                    out.push((std::mem::take(&mut run), false));
                }
                run.clear();
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_hodograph_is_not_drawn_across_a_position_without_a_plan() {
        let p = |x: f64| Some(DVec2::new(x, 0.0));
        // Every position: one closed curve.
        let all = pieces(&[p(1.0), p(2.0), p(3.0)]);
        assert_eq!(
            all,
            vec![(vec![DVec2::X, DVec2::X * 2.0, DVec2::X * 3.0], true)]
        );
        // A gap at the third of six: one open piece from the fourth round to the second.
        let one = pieces(&[p(1.0), p(2.0), None, p(4.0), p(5.0), p(6.0)]);
        let xs: Vec<f64> = one[0].0.iter().map(|v| v.x).collect();
        assert_eq!(
            (one.len(), xs, one[0].1),
            (1, vec![4.0, 5.0, 6.0, 1.0, 2.0], false)
        );
        // Two gaps, one end between them: that end is no piece.
        let two = pieces(&[p(1.0), None, p(3.0), None, p(5.0), p(6.0)]);
        let xs: Vec<Vec<f64>> = two
            .iter()
            .map(|(v, _)| v.iter().map(|v| v.x).collect())
            .collect();
        assert_eq!(xs, vec![vec![5.0, 6.0, 1.0]]);
    }
}
