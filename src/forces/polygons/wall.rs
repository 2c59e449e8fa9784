//! The wall of a slider's guide a group's drawing hatches and stands the frame's reaction on.

use crate::geom::DVec2;

/// The unit normal from a slider's axis (through `axis`, along the unit `u`) to the guide's
/// wall a group's drawing hatches and stands the frame's reaction on: the side away from the
/// mechanism, from the crank's `centre`; where the guide runs through the centre (the V
/// engine's cylinders through O), the wall that pushes the block (the frame's reaction
/// `force` on it), so that no reaction presses the block onto that wall from the open side;
/// with no push across it either, away from the mechanism's `points` together. One decision
/// for the drawing and its predicted room: a centre on the line, decided by the rounding,
/// put the two, and positions 3 and 6, on opposite sides.
pub(super) fn guide_wall(
    u: DVec2,
    axis: DVec2,
    force: DVec2,
    (centre, points): (DVec2, &[DVec2]),
) -> DVec2 {
    let n = u.perp();
    let side = |p: DVec2| u.perp_dot(p - axis);
    let reach = points.iter().map(|p| p.distance(axis)).fold(0.0, f64::max);
    let push = force.dot(n);
    let s = if side(centre).abs() > reach * 1e-9 {
        side(centre)
    } else if push.abs() > force.length() * 1e-9 {
        // The wall behind the push: a force along +n comes from the wall at −n.
        push
    } else {
        points.iter().map(|&p| side(p)).sum()
    };
    if s > 0.0 {
        -n
    } else {
        n
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A guide's wall is away from the crank's centre; where the guide runs through it (the V
    /// engine's cylinders through O), the wall that pushes the block, and with no push
    /// across it, away from the mechanism's points, whatever the rounding leaves of the
    /// centre's side.
    #[test]
    fn a_guides_wall_is_away_from_the_centre_or_the_one_that_pushes() {
        let u = DVec2::new(-1.0, 1.0).normalize();
        let axis = DVec2::new(-0.1367, 0.1367);
        let (up, down) = (DVec2::ONE.normalize(), -DVec2::ONE.normalize());
        // The other cylinder's block and the crank pin on the (1, 1) side of the line.
        let points = [
            DVec2::ZERO,
            axis,
            DVec2::new(0.12, 0.12),
            DVec2::new(0.01, 0.03),
        ];
        let wall = |f: DVec2, c: DVec2| guide_wall(u, axis, f, (c, &points));
        for noise in [-1e-17, 0.0, 1e-17] {
            let c = DVec2::new(noise, -noise);
            // A push towards (1, 1) comes from the wall on the other side, and the other way.
            assert!(wall(up * 500.0, c).abs_diff_eq(down, 1e-12), "{noise}");
            assert!(wall(down * 500.0 + u, c).abs_diff_eq(up, 1e-12), "{noise}");
            let t = wall(DVec2::ZERO, c);
            assert!(t.abs_diff_eq(down, 1e-12), "{noise}: {t}");
        }
        // Off the line, the centre decides, whatever the reaction.
        for f in [up * 500.0, down * 500.0] {
            let t = guide_wall(u, axis + up * 0.07, f, (DVec2::ZERO, &points));
            assert!(t.abs_diff_eq(up, 1e-12), "{t}");
        }
    }
}
