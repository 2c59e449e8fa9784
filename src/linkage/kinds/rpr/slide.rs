//! RPR's slide line by compass and straightedge, the construction's own route: through the
//! pin and the pivot, or with an offset the tangent from the pin to the offset circle, or the
//! tangent to the pin's path when the pin stands on the pivot.

use crate::construct::{Compass, ConstructionError, Item, Pick, Recorder, Role};
use crate::geom::{DVec2, Segment};
use crate::linkage::built::heading;
use crate::linkage::compiled::Compiled;

/// The slide line of an RPR group (pin `a`, pivot `c`, `offset` m), its direction: the
/// tangent to the path of `a` when the pin stands on the pivot (`prev`: the previous
/// position's slide), else the line through the two points, or with an offset the
/// tangent from `a` to the offset circle of `c`, its foot T on the Thales circle on ca.
pub(super) fn slide_line(
    prog: &dyn Compiled,
    rec: &mut Recorder,
    s: &str,
    p: &[DVec2],
    (a, c): (usize, usize),
    offset: f64,
    prev: Option<f64>,
) -> Result<f64, ConstructionError> {
    if offset == 0.0
        && p[a].distance(p[c]) <= rec.tolerances().coincident
        && path_through_pivot(prog, a, c, p)
    {
        return slot_tangent(prog, rec, s, (a, c), p, prev);
    }
    if offset == 0.0 {
        let line = rec.line_through(
            &format!("{s}: slide line"),
            (&prog.names()[c], p[c]),
            (&prog.names()[a], p[a]),
        )?;
        return Ok(line.angle());
    }
    // Tangent from a to the offset circle of c: Thales circle on ca.
    let mid = (p[a] + p[c]) * 0.5;
    let thales = Compass {
        name: "the midpoint of the slide",
        center: mid,
        radius: p[a].distance(p[c]) * 0.5,
    };
    let off = prog.compass(p, c, offset.abs() / rec.scale().value());
    let side = if offset > 0.0 {
        Pick::Right
    } else {
        Pick::Left
    };
    let (t, _, _) = rec.meet_circles(&format!("{s}: foot of the slide line"), thales, off, side)?;
    Ok(rec
        .line_through(
            &format!("{s}: slide line"),
            ("T", t),
            (&prog.names()[a], p[a]),
        )?
        .angle())
}

/// Whether the path of the pin `a` passes through the pivot `c` (within the rounding of
/// the drawing's coordinates), so that the slot at their coincidence is the tangent to
/// that path: for a crank pin about a fixed pivot, the crank circle through `a` meets `c`.
/// A pin whose path misses the pivot, however closely, fixes the slot as the line through
/// the two points (a true, ill-conditioned direction). Other pins: assumed (the tangent is
/// then refused by [`slot_tangent`]).
fn path_through_pivot(prog: &dyn Compiled, a: usize, c: usize, p: &[DVec2]) -> bool {
    if !prog.on_frame_or_crank(a) || c >= prog.fixed_count() {
        return true;
    }
    let o = p[prog.centre()];
    let (ra, rc) = (p[a].distance(o), p[c].distance(o));
    let rounding = 8.0 * f64::EPSILON * (p[a].length() + p[c].length() + o.length() + ra);
    (ra - rc).abs() <= rounding
}

/// The slide line of an RPR group without offset when the pin `a` stands on the pivot
/// `c`: the two points no longer fix it, its limit is the tangent to the path of `a`
/// (for a crank pin: perpendicular to the crank, in the sense of increasing φ₁, or the
/// one nearest to the previous position's slide `prev`). Refused for a pin whose path's
/// tangent the drawing does not give (a point not on the crank, or a moving pivot).
fn slot_tangent(
    prog: &dyn Compiled,
    rec: &mut Recorder,
    s: &str,
    (a, c): (usize, usize),
    p: &[DVec2],
    prev: Option<f64>,
) -> Result<f64, ConstructionError> {
    if !prog.on_frame_or_crank(a) || c >= prog.fixed_count() {
        return Err(ConstructionError::Other {
            step: format!("{s}: slide line"),
            message: format!(
                "the pin {} stands on the pivot {} (|{}{}| = {:.3e} mm ≤ {:.3e} mm): the slide line is the tangent to the path of {}, which the drawing gives only for a point of the crank about a fixed pivot",
                prog.names()[a],
                prog.names()[c],
                prog.names()[c],
                prog.names()[a],
                p[a].distance(p[c]),
                rec.tolerances().coincident,
                prog.names()[a]
            ),
        });
    }
    let radius = p[a] - p[prog.centre()];
    let mut t = radius.perp().normalize_or(DVec2::X);
    if prev.is_some_and(|q| DVec2::from_angle(q).dot(t) < 0.0) {
        t = -t;
    }
    let reach = radius.length().max(1.0);
    rec.draw(
        format!(
            "{s}: slide line, tangent to the path of {} at {}",
            prog.names()[a],
            prog.names()[c]
        ),
        Item::Segment(Segment::new(p[c] - t * reach, p[c] + t * reach)),
        Role::Construction,
        &[],
    );
    Ok(heading(t))
}
