//! The flat face's combined diagram S(S″): its 45° tangent from the curve to the S axis,
//! and its zone hatched as the textbook hatches it.

use super::{centre, distance_to_polyline, distance_to_segment, segments, tol};
use glam::DVec2;
use tmm::cam::TANGENT_NOTE;
use tmm::construct::{Figure, Item, Role};

/// The flat face's 45° tangent: from the S(S″) curve to the S axis, each end on its line.
pub(super) fn tangent_touches(f: &Figure) -> Result<(), String> {
    let t = segments(f, TANGENT_NOTE);
    let [(_, a, b)] = t[..] else {
        return Err(format!("{} 45° tangents", t.len()));
    };
    // The curve drawn through its points K (a French curve, in pieces between its corners):
    // the tangent touches it at one of them.
    let pieces: Vec<(Vec<DVec2>, bool)> = f
        .steps
        .iter()
        .filter_map(|s| match &s.item {
            Item::Polyline { points, closed } | Item::Curve { points, closed }
                if s.role == Role::Result =>
            {
                Some((points.clone(), *closed))
            }
            _ => None,
        })
        .collect();
    if pieces.is_empty() {
        return Err("no S(S″) curve".into());
    }
    let axis = segments(f, "S axis");
    let [(_, s0, s1)] = axis[..] else {
        return Err("no S axis".into());
    };
    let on_curve = pieces
        .iter()
        .map(|(points, closed)| distance_to_polyline(a, points, *closed))
        .fold(f64::INFINITY, f64::min);
    let on_axis = distance_to_segment(b, s0, s1);
    if on_curve > tol(f) || on_axis > tol(f) {
        return Err(format!(
            "the tangent's ends are {on_curve:.3} mm off the curve and {on_axis:.3} mm off the axis"
        ));
    }
    let slope = (b - a).normalize();
    if (slope.x + slope.y).abs() > 1e-9 {
        return Err(format!("the tangent is not at 45°: {slope:?}"));
    }
    Ok(())
}

/// The flat face's zone hatched as the textbook hatches it: in the angle at the tangent's
/// crossing between the tangent (toward its touching point) and the S axis below, no stroke
/// past the tangent's drawn end nor below O₁, and the hatching reaching down to O₁.
pub(super) fn flat_zone_hatched(f: &Figure) -> Result<(), String> {
    let t = segments(f, TANGENT_NOTE);
    let [(_, touch, c)] = t[..] else {
        return Err(format!("{} 45° tangents", t.len()));
    };
    let o = centre(f)?;
    let (u, v) = ((touch - c).normalize(), DVec2::NEG_Y);
    let (lu, lv) = (touch.distance(c), c.y - o.y);
    let strokes: Vec<DVec2> = f
        .steps
        .iter()
        .filter(|s| s.role == Role::Hatch)
        .flat_map(|s| s.item.hatch_strokes())
        .flat_map(|g| [g.from, g.to])
        .collect();
    if strokes.len() < 6 {
        return Err(format!("the zone has {} hatch strokes", strokes.len() / 2));
    }
    let slack = 1e-3;
    for p in &strokes {
        let (along_u, along_v) = (u.dot(*p - c), v.dot(*p - c));
        let inside = u.perp_dot(*p - c) * u.perp_dot(v) >= -slack
            && v.perp_dot(*p - c) * v.perp_dot(u) >= -slack;
        if !inside || along_u > lu + slack || along_v > lv + slack {
            return Err(format!(
                "a hatch stroke ends at {p:?}, outside the angle of the tangent and the S axis \
                 down to O₁ {o:?}"
            ));
        }
    }
    let deepest = strokes.iter().map(|p| v.dot(*p - c)).fold(0.0, f64::max);
    if deepest < lv - 3.0 {
        return Err(format!(
            "the hatching stops {:.1} mm above O₁",
            lv - deepest
        ));
    }
    Ok(())
}
