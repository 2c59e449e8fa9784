//! Issue 45: the cam sheets finish the constructions their captions promise, checked on the
//! plate model (the views' recorded figures and the cam's own numbers), never on pixels:
//! - r_min by the combined diagram: the two γ_min rays drawn from their points to their
//!   crossing, the zone of the centre hatched in the angle at it that holds O₁, and the r_min
//!   dimension from O₁ whose length, read as the sheet reads it, is the report's graphical
//!   r_min (translating and rocker followers);
//! - the flat face's 45° tangent from its touching point on the S(S″) curve to the S axis,
//!   each end on its line to a tolerance of the figure's size, with the r_min dimension.
//!
//! (γ(φ) without a step the law does not make: `cam_angle_steps`.) Each rule also runs on a plate built to break it, and must fail there.

use glam::DVec2;
use tmm::cam::{Cam, Follower, RAY_NOTE, R_MIN_NOTE, TANGENT_NOTE};
use tmm::construct::{Drafting, Figure, Item, Role, Step};
use tmm::geom::Segment;
use tmm::plate::Plate;
use tmm::scale::Lang;
use tmm::scene::PlateKind;
use tmm::study::Session;

/// Every scene whose cam turns (a combined diagram on its cam sheet).
const TURNING: [&str; 7] = [
    "shaper",
    "cam-central",
    "cam-cusp",
    "cam-pz4",
    "cam-pz5",
    "cam-shock",
    "cam-undercut",
];

/// The cam and its sheets in `lang`, read at `drafting` mm.
fn sheets(name: &str, drafting: f64, lang: Lang) -> (Cam, Vec<Plate>, Drafting) {
    let s = crate::support::scene(name);
    let d = Drafting::new(drafting).expect("a drafting resolution");
    let session = Session::new(&s, d);
    let cam = (*session.cam().unwrap_or_else(|e| panic!("{name}: {e}"))).clone();
    let plates = tmm::build(&session, PlateKind::Cam, lang).unwrap_or_else(|e| panic!("{e}"));
    (cam, plates, d)
}

/// The combined diagram's view: the figure the minimum radius is constructed on.
fn combined(plates: &[Plate]) -> Option<Figure> {
    plates
        .iter()
        .flat_map(|p| &p.views)
        .find(|v| v.figure.title == "combined")
        .map(|v| v.figure.clone())
}

/// A tolerance of the figure's size: a millionth of its extent, mm.
fn tol(f: &Figure) -> f64 {
    f.bounds()
        .map_or(1e-6, |(lo, hi)| 1e-6 * (hi - lo).length())
}

fn segments<'a>(f: &'a Figure, note: &str) -> Vec<(&'a Step, DVec2, DVec2)> {
    f.steps
        .iter()
        .filter(|s| s.note == note)
        .filter_map(|s| match &s.item {
            Item::Segment(g) => Some((s, g.from, g.to)),
            Item::Vector { from, to } => Some((s, *from, *to)),
            Item::Dimension { from, to, .. } => Some((s, *from, *to)),
            _ => None,
        })
        .collect()
}

fn distance_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    Segment::new(a, b).distance_to(p)
}

fn distance_to_polyline(p: DVec2, pts: &[DVec2], closed: bool) -> f64 {
    let mut all = pts.to_vec();
    if closed {
        all.extend(pts.first());
    }
    all.windows(2)
        .map(|w| distance_to_segment(p, w[0], w[1]))
        .fold(f64::INFINITY, f64::min)
}

/// The marked centre O₁ of a combined diagram.
fn centre(f: &Figure) -> Result<DVec2, String> {
    f.steps
        .iter()
        .find_map(|s| match (&s.item, &s.label) {
            (Item::Point(p), Some(l)) if l.text == "O_1" => Some(*p),
            _ => None,
        })
        .ok_or_else(|| "no centre O_1 marked".to_string())
}

/// The two rays and their crossing: each ray drawn from its point through the crossing.
fn rays_reach_their_crossing(f: &Figure) -> Result<(DVec2, [DVec2; 2]), String> {
    let rays = segments(f, RAY_NOTE);
    let [(_, a0, a1), (_, b0, b1)] = rays[..] else {
        return Err(format!("{} γ_min rays drawn, not two", rays.len()));
    };
    let (u, v) = ((a1 - a0).normalize(), (b1 - b0).normalize());
    let det = u.perp_dot(v);
    if det.abs() < 0.05 {
        return Err(format!("the rays are parallel (sin = {det:.3})"));
    }
    let t = (b0 - a0).perp_dot(v) / det;
    let c = a0 + u * t;
    for (k, (p, q)) in [(a0, a1), (b0, b1)].into_iter().enumerate() {
        let off = distance_to_segment(c, p, q);
        if off > tol(f) {
            return Err(format!("ray {k} stops {off:.3} mm short of the crossing"));
        }
    }
    Ok((c, [u, v]))
}

/// The zone hatched in one angle of the two rays at their crossing, the one holding O₁.
fn zone_hatched(f: &Figure) -> Result<(), String> {
    let (c, [u, v]) = rays_reach_their_crossing(f)?;
    let strokes: Vec<DVec2> = f
        .steps
        .iter()
        .filter(|s| s.role == Role::Hatch)
        .filter_map(|s| match &s.item {
            Item::Segment(g) => Some((g.from + g.to) * 0.5),
            _ => None,
        })
        .collect();
    if strokes.len() < 3 {
        return Err(format!("the zone has {} hatch strokes", strokes.len()));
    }
    // The angle the strokes fill: their centroid's; every stroke in it (to 1 µm: a stroke
    // at the apex may touch a ray).
    let mid = strokes.iter().fold(DVec2::ZERO, |a, p| a + *p) / strokes.len() as f64;
    let first = (u.perp_dot(mid - c).signum(), v.perp_dot(mid - c).signum());
    let within =
        |p: DVec2| u.perp_dot(p - c) * first.0 >= -1e-3 && v.perp_dot(p - c) * first.1 >= -1e-3;
    if let Some(p) = strokes.iter().find(|p| !within(**p)) {
        return Err(format!(
            "a hatch stroke at {p:?} lies outside the zone's angle"
        ));
    }
    let o = centre(f)?;
    let t = tol(f) * 1e3;
    let (su, sv) = (u.perp_dot(o - c), v.perp_dot(o - c));
    if su * first.0 < -t || sv * first.1 < -t {
        return Err(format!("O₁ at {o:?} lies outside the hatched angle"));
    }
    Ok(())
}

/// The r_min dimension from O₁, its length read at the sheet's drafting equal to `graphical`.
fn r_min_dimensioned(f: &Figure, graphical: f64, d: Drafting) -> Result<(), String> {
    let dims = segments(f, R_MIN_NOTE);
    let [(step, a, b)] = dims[..] else {
        return Err(format!("{} r_min dimensions", dims.len()));
    };
    if step.role != Role::Dimension || step.label.as_ref().is_none_or(|l| l.text != "r_{min}") {
        return Err("the r_min dimension is not a dimension labelled r_min".into());
    }
    let o = centre(f)?;
    if a.distance(o).min(b.distance(o)) > tol(f) {
        return Err("the r_min dimension does not start at O₁".into());
    }
    let read = f.scale.to_physical(d.read(a.distance(b)));
    if (read - graphical).abs() > 1e-9 * graphical.abs().max(1e-3) {
        return Err(format!(
            "r_min dimensioned {read} m, the report's {graphical} m"
        ));
    }
    Ok(())
}

/// The flat face's 45° tangent: from the S(S″) curve to the S axis, each end on its line.
fn tangent_touches(f: &Figure) -> Result<(), String> {
    let t = segments(f, TANGENT_NOTE);
    let [(_, a, b)] = t[..] else {
        return Err(format!("{} 45° tangents", t.len()));
    };
    let curve = f
        .steps
        .iter()
        .find_map(|s| match &s.item {
            Item::Polyline { points, closed } if s.role == Role::Result => {
                Some((points.clone(), *closed))
            }
            _ => None,
        })
        .ok_or("no S(S″) curve")?;
    let axis = segments(f, "S axis");
    let [(_, s0, s1)] = axis[..] else {
        return Err("no S axis".into());
    };
    let on_curve = distance_to_polyline(a, &curve.0, curve.1);
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

/// The final elements the combined diagram's caption promises.
fn finished(cam: &Cam, f: &Figure, d: Drafting) -> Result<(), String> {
    if matches!(cam.spec.follower, Follower::Flat { .. }) {
        tangent_touches(f)?;
    } else {
        zone_hatched(f)?;
    }
    r_min_dimensioned(f, cam.radius.graphical, d)
}

#[test]
fn every_combined_diagram_has_its_final_elements() {
    for name in TURNING {
        for (drafting, lang) in [(0.5, Lang::Ru), (0.0, Lang::Uk), (0.5, Lang::En)] {
            let (cam, plates, d) = sheets(name, drafting, lang);
            let f = combined(&plates).unwrap_or_else(|| panic!("{name}: no combined diagram"));
            if let Err(e) = finished(&cam, &f, d) {
                panic!("{name} ({drafting} mm, {lang:?}): {e}");
            }
        }
    }
}

/// A figure with `f` applied to the steps whose note is `note`.
fn broken(f: &Figure, note: &str, mut g: impl FnMut(&mut Step)) -> Figure {
    let mut out = f.clone();
    for s in out.steps.iter_mut().filter(|s| s.note == note) {
        g(s);
    }
    out
}

#[test]
fn each_rule_fails_on_a_plate_built_to_break_it() {
    let (cam, plates, d) = sheets("cam-pz5", 0.5, Lang::Ru);
    let f = combined(&plates).expect("a combined diagram");
    assert!(finished(&cam, &f, d).is_ok());
    // A ray stopped 5 mm short of the crossing (the ticks the review marked).
    let (c, _) = rays_reach_their_crossing(&f).expect("rays");
    let mut first = true;
    let short = broken(&f, RAY_NOTE, |s| {
        if let (Item::Segment(g), true) = (&mut s.item, first) {
            let u = (g.to - g.from).normalize();
            g.to = c - u * 5.0;
            first = false;
        }
    });
    assert!(rays_reach_their_crossing(&short).is_err());
    // No hatching; hatching on the wrong side of a ray.
    let mut bare = f.clone();
    bare.steps.retain(|s| s.role != Role::Hatch);
    assert!(zone_hatched(&bare).is_err());
    let mut flipped = f.clone();
    if let Some(s) = flipped.steps.iter_mut().find(|s| s.role == Role::Hatch) {
        if let Item::Segment(g) = &mut s.item {
            let m = (g.from + g.to) * 0.5;
            let (from, to) = (c * 2.0 - m + (g.from - m), c * 2.0 - m + (g.to - m));
            g.from = from;
            g.to = to;
        }
    }
    assert!(zone_hatched(&flipped).is_err());
    // A dimension 1 mm longer than the centre found; none at all.
    let long = broken(&f, R_MIN_NOTE, |s| {
        if let Item::Dimension { to, from, .. } = &mut s.item {
            *to += (*to - *from).normalize() * 1.0;
        }
    });
    assert!(r_min_dimensioned(&long, cam.radius.graphical, d).is_err());
    let mut none = f.clone();
    none.steps.retain(|s| s.note != R_MIN_NOTE);
    assert!(r_min_dimensioned(&none, cam.radius.graphical, d).is_err());

    // The flat face: the tangent floating 5 mm off both its lines (the review's PZ4).
    let (flat, plates, d) = sheets("cam-pz4", 0.5, Lang::Ru);
    let f = combined(&plates).expect("a combined diagram");
    assert!(finished(&flat, &f, d).is_ok());
    let floating = broken(&f, TANGENT_NOTE, |s| {
        if let Item::Segment(g) = &mut s.item {
            let u = (g.to - g.from).normalize();
            g.from += u * 5.0;
            g.to -= u * 5.0;
        }
    });
    assert!(tangent_touches(&floating).is_err());
}
