//! Issue 45: the cam sheets finish the constructions their captions promise, checked on the
//! plate model (the views' recorded figures and the cam's own numbers), never on pixels:
//! - the combined diagram's two axes through B₀, each labelled (S and dS/dφ, or d²S/dφ² for
//!   a flat face), the abscissa across the whole curve (a translating follower);
//! - r_min by the combined diagram: the two γ_min rays drawn from their points to their
//!   crossing, the zone of the centre hatched in the angle at it that holds O₁, and the r_min
//!   dimension from O₁ whose length, read as the sheet reads it, is the report's graphical
//!   r_min (translating and rocker followers);
//! - the flat face's 45° tangent from its touching point on the S(S″) curve to the S axis,
//!   each end on its line to a tolerance of the figure's size, the zone of the centre
//!   hatched between it and the S axis down to O₁, with the r_min dimension;
//! - the r_min dimension written with its value (r_min = 69 мм), and, where the scene leaves
//!   r₀ to the construction, the data accepting it no smaller: «Принимаем r₀ = 70 мм ≥ r_min
//!   = 69 мм», the r₀ the profile is built on (and the twin's check that it keeps [γ]).
//!
//! (γ(φ) without a step the law does not make: `cam_angle_steps`.) Each rule also runs on a plate built to break it, and must fail there.

mod dimensions;
mod flat;
use flat::{flat_zone_hatched, tangent_touches};

use dimensions::{
    axes_drawn, chosen_r0_dimensioned, number_after, offset_line_drawn, r_min_dimensioned, read_as,
    written_as,
};
use glam::DVec2;
use tmm::cam::{Cam, Follower, E_LINE_NOTE, RAY_NOTE, R_MIN_NOTE, TANGENT_NOTE};
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

/// The zone hatched in one angle of the two rays at their crossing, the one holding O₁, and
/// only up to the rays' drawn ends: every stroke within the triangle the crossing and the
/// two ends on the zone's side close (a stroke past a ray's end reads as stray).
fn zone_hatched(f: &Figure) -> Result<(), String> {
    let (c, [u, v]) = rays_reach_their_crossing(f)?;
    let strokes: Vec<(DVec2, DVec2)> = f
        .steps
        .iter()
        .filter(|s| s.role == Role::Hatch)
        .flat_map(|s| s.item.hatch_strokes())
        .map(|g| (g.from, g.to))
        .collect();
    if strokes.len() < 3 {
        return Err(format!("the zone has {} hatch strokes", strokes.len()));
    }
    // The angle the strokes fill: their centroid's; every stroke in it (to 1 µm: a stroke
    // at the apex may touch a ray).
    let mid =
        strokes.iter().fold(DVec2::ZERO, |a, (p, q)| a + *p + *q) / (2 * strokes.len()) as f64;
    let first = (u.perp_dot(mid - c).signum(), v.perp_dot(mid - c).signum());
    let within =
        |p: DVec2| u.perp_dot(p - c) * first.0 >= -1e-3 && v.perp_dot(p - c) * first.1 >= -1e-3;
    if let Some(p) = strokes
        .iter()
        .map(|(p, q)| (*p + *q) * 0.5)
        .find(|p| !within(*p))
    {
        return Err(format!(
            "a hatch stroke at {p:?} lies outside the zone's angle"
        ));
    }
    // Each ray's drawn end on the zone's side: the end on the side of the other ray the
    // zone is on.
    let rays = segments(f, RAY_NOTE);
    let end = |k: usize, other: DVec2, sign: f64| {
        let (_, a, b) = rays[k];
        if other.perp_dot(a - c) * sign > other.perp_dot(b - c) * sign {
            a
        } else {
            b
        }
    };
    let (ea, eb) = (end(0, v, first.1), end(1, u, first.0));
    let inside = |p: DVec2| {
        let side = |a: DVec2, b: DVec2| {
            let o = (c + ea + eb) / 3.0;
            let n = (b - a).perp();
            n.dot(p - a) * n.dot(o - a).signum() >= -1e-3 * (b - a).length()
        };
        side(c, ea) && side(ea, eb) && side(eb, c)
    };
    let past = strokes
        .iter()
        .flat_map(|(p, q)| [*p, *q])
        .find(|p| !inside(*p));
    if let Some(p) = past {
        return Err(format!(
            "a hatch stroke ends at {p:?}, past the rays' drawn ends {ea:?}, {eb:?}"
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

/// The data's line of the base radius: when the scene gives none, r₀ accepted ≥ the r_min
/// read, both as the cam has them, r_min to its reading step at `d` (`Принимаем r_{0} = 70 мм
/// ≥ r_{min} = 69 мм`).
fn r0_accepted(cam: &Cam, plates: &[Plate], d: Drafting) -> Result<(), String> {
    if cam.spec.base_radius.is_some() {
        return Ok(());
    }
    let lines: Vec<&String> = plates
        .iter()
        .flat_map(|p| &p.texts)
        .flat_map(|t| &t.lines)
        .filter(|l| l.contains("r_{0} = ") && l.contains(" ≥ r_{min} = "))
        .collect();
    let [line] = lines[..] else {
        return Err(format!("{} lines accept r₀ ≥ r_min", lines.len()));
    };
    let (Some(r0), Some(r)) = (
        number_after(line, "r_{0} = "),
        number_after(line, " ≥ r_{min} = "),
    ) else {
        return Err(format!("no numbers in “{line}”"));
    };
    if r0 < r {
        return Err(format!("“{line}”: r₀ below the r_min read"));
    }
    let (r_min, step) = reading(cam, d);
    if !written_as(r0, cam.base) || !read_as(r, r_min, step) {
        return Err(format!(
            "“{line}”: the profile is built on r₀ = {} m from r_min = {} m",
            cam.base, cam.radius.graphical
        ));
    }
    Ok(())
}

/// The final elements the combined diagram's caption promises, and r₀ accepted from it.
/// r_min as read off the combined diagram, m, and the step it is read to at `d`.
fn reading(cam: &Cam, d: Drafting) -> (f64, Option<f64>) {
    (cam.radius.graphical, cam.r_min_step(d.resolution_mm()))
}

fn finished(cam: &Cam, f: &Figure, d: Drafting) -> Result<(), String> {
    if matches!(cam.spec.follower, Follower::Flat { .. }) {
        tangent_touches(f)?;
        flat_zone_hatched(f)?;
    } else {
        zone_hatched(f)?;
    }
    chosen_r0_dimensioned(f, cam, d)?;
    offset_line_drawn(f, cam)?;
    axes_drawn(f, cam)?;
    r_min_dimensioned(f, reading(cam, d), d)
}

#[test]
fn every_combined_diagram_has_its_final_elements() {
    for name in TURNING {
        for (drafting, lang) in [(0.5, Lang::Ru), (0.0, Lang::Uk), (0.5, Lang::En)] {
            let (cam, plates, d) = sheets(name, drafting, lang);
            let f = combined(&plates).unwrap_or_else(|| panic!("{name}: no combined diagram"));
            if let Err(e) = finished(&cam, &f, d).and_then(|()| r0_accepted(&cam, &plates, d)) {
                panic!("{name} ({drafting} mm, {lang:?}): {e}");
            }
        }
    }
}

/// The r₀ accepted from the reading keeps the limit the reading was made for: at least the
/// twin's exact r_min, and the twin's extreme angle over the whole cycle (between the points
/// too) within [γ] — every shipped turning cam whose scene leaves r₀ to the construction,
/// read by hand and exactly. The twin computes both itself; the construction never sees them.
#[test]
fn the_accepted_base_radius_keeps_the_angle_limit() {
    let mut checked = 0;
    for name in TURNING {
        for drafting in [0.5, 0.0] {
            let (cam, _, _) = sheets(name, drafting, Lang::Ru);
            if cam.spec.base_radius.is_some() {
                continue;
            }
            checked += 1;
            let exact = cam.exact_r_min();
            assert!(
                cam.base >= exact,
                "{name} ({drafting} mm): r₀ = {} m < exact r_min = {exact} m",
                cam.base
            );
            if matches!(cam.spec.follower, Follower::Flat { .. }) {
                continue;
            }
            let worst = cam.worst_angle();
            let gamma = cam.spec.gamma_min;
            let keeps = match cam.spec.follower {
                Follower::Rocker { .. } => worst >= gamma,
                _ => worst <= std::f64::consts::FRAC_PI_2 - gamma,
            };
            assert!(
                keeps,
                "{name} ({drafting} mm): the worst angle {}° breaks γ_min = {}°",
                worst.to_degrees(),
                gamma.to_degrees()
            );
        }
    }
    assert!(checked >= 10, "{checked} cams checked");
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
    // The abscissa taken off (the review's combined diagrams beside one axis).
    let mut one_axis = f.clone();
    one_axis.steps.retain(|s| s.note != "dS/dφ axis");
    assert!(axes_drawn(&one_axis, &cam).is_err());
    // The offset's line taken off (the review's pz5).
    let mut no_e = f.clone();
    no_e.steps.retain(|s| s.note != E_LINE_NOTE);
    assert!(offset_line_drawn(&no_e, &cam).is_err());
    // No hatching; hatching on the wrong side of a ray.
    let mut bare = f.clone();
    bare.steps.retain(|s| s.role != Role::Hatch);
    assert!(zone_hatched(&bare).is_err());
    let mut flipped = f.clone();
    // The hatched region turned half round the crossing, into the opposite angle.
    if let Some(s) = flipped.steps.iter_mut().find(|s| s.role == Role::Hatch) {
        if let Item::Hatching { outline, .. } = &mut s.item {
            for p in outline.iter_mut() {
                *p = c * 2.0 - *p;
            }
        }
    }
    assert!(zone_hatched(&flipped).is_err());
    // The strokes moved past the rays' drawn ends, still in their angle (the review's stray
    // stroke).
    let ends: Vec<DVec2> = f
        .steps
        .iter()
        .filter(|s| s.role == Role::Hatch)
        .flat_map(|s| s.item.hatch_strokes())
        .map(|g| g.from + g.to)
        .collect();
    let mid = ends.iter().fold(DVec2::ZERO, |a, p| a + *p) / (2 * ends.len()) as f64;
    let out = (mid - c).normalize() * 100.0;
    let stray = broken(&f, "hatching of the zone of the cam centre", |s| {
        if let Item::Hatching { outline, .. } = &mut s.item {
            for p in outline.iter_mut() {
                *p += out;
            }
        }
    });
    assert!(zone_hatched(&stray).is_err());
    // A dimension 1 mm longer than the centre found; none at all.
    let long = broken(&f, R_MIN_NOTE, |s| {
        if let Item::Dimension { to, from, .. } = &mut s.item {
            *to += (*to - *from).normalize() * 1.0;
        }
    });
    assert!(r_min_dimensioned(&long, reading(&cam, d), d).is_err());
    let mut none = f.clone();
    none.steps.retain(|s| s.note != R_MIN_NOTE);
    assert!(r_min_dimensioned(&none, reading(&cam, d), d).is_err());
    // The dimension without its value (the review's mark), or with another.
    for text in ["r_{min}", "r_{min} = 12,5 мм"] {
        let bare = broken(&f, R_MIN_NOTE, |s| {
            if let Some(l) = s.label.as_mut() {
                l.text = text.into();
            }
        });
        assert!(r_min_dimensioned(&bare, reading(&cam, d), d).is_err());
    }
    // r₀ taken at the r_min read off the drawing below the exact one (the review's
    // 69 < 69,4 мм), and no line accepting it at all.
    assert!(r0_accepted(&cam, &plates, d).is_ok());
    let under = |l: &String| {
        if l.contains(" ≥ r_{min} = ") {
            let r = number_after(l, " ≥ r_{min} = ").unwrap_or(0.0);
            format!("Принимаем r_{{0}} = {} мм ≥ r_{{min}} = {} мм", r - 1.0, r)
        } else {
            l.clone()
        }
    };
    let mut lowered = plates.clone();
    for t in lowered.iter_mut().flat_map(|p| p.texts.iter_mut()) {
        t.lines = t.lines.iter().map(under).collect();
    }
    assert!(r0_accepted(&cam, &lowered, d).is_err());
    let mut silent = plates.clone();
    for t in silent.iter_mut().flat_map(|p| p.texts.iter_mut()) {
        t.lines.retain(|l| !l.contains(" ≥ r_{min} = "));
    }
    assert!(r0_accepted(&cam, &silent, d).is_err());

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
    // The flat face's zone: no hatching; hatching turned into the angle right of the axis.
    let mut bare = f.clone();
    bare.steps.retain(|s| s.role != Role::Hatch);
    assert!(flat_zone_hatched(&bare).is_err());
    let mut mirrored = f.clone();
    for s in mirrored.steps.iter_mut().filter(|s| s.role == Role::Hatch) {
        if let Item::Hatching { outline, .. } = &mut s.item {
            for p in outline.iter_mut() {
                p.x = -p.x;
            }
        }
    }
    assert!(flat_zone_hatched(&mirrored).is_err());
}

/// Under force closure the angle's limit binds the rise only (seed 002 L1463): PZ5's return
/// reads past 30° on its graph, and its sheet says why, with the twin's largest angle there;
/// the same cam closed by a groove is built for the whole cycle, keeps the limit and says
/// nothing of it.
#[test]
fn a_return_past_the_limit_is_explained_under_force_closure_only() {
    let stated = |plates: &[Plate]| {
        plates
            .iter()
            .flat_map(|p| &p.texts)
            .flat_map(|t| &t.lines)
            .find(|l| l.starts_with("На фазе приближения"))
            .cloned()
    };
    let (cam, plates, _) = sheets("cam-pz5", 0.5, Lang::Ru);
    let read = cam
        .points
        .iter()
        .enumerate()
        .filter(|(_, p)| p.phase == 2)
        .map(|(i, _)| cam.angle_read(i).to_degrees().abs())
        .fold(0.0, f64::max);
    assert!(read > 31.0, "the return reads {read}°");
    let line = stated(&plates).expect("PZ5's sheet explains its return");
    let value = number_after(&line, "λ_{max} = ").expect(&line);
    // Read at 0,5 mm against the twin's exact angle (the points' table: 35,5° and 37,4°).
    assert!((value - read).abs() < 3.0, "{line} against {read}° read");
    assert!(
        line.contains("> 30°") && line.contains("силовое замыкание"),
        "{line}"
    );

    let text = std::fs::read_to_string(crate::support::root().join("constructions/cam-pz5.toml"))
        .expect("cam-pz5");
    let grooved = text.replace("closure = \"force\"", "closure = \"geometric\"");
    assert_ne!(grooved, text);
    let s = tmm::scene::parse(&grooved, std::path::Path::new("cam-pz5-groove.toml"))
        .unwrap_or_else(|e| panic!("{e}"));
    let session = Session::new(&s, Drafting::new(0.5).expect("0.5 mm"));
    let plates = tmm::build(&session, PlateKind::Cam, Lang::Ru).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(stated(&plates), None);
}

/// A rocker's profile by inversion numbers every position at its pivot O₂ⁱ turned back on
/// the pivot's circle about O₁, as the textbook does (the review saw only 0, 12, 13 and 25
/// numbered, at their pitch points); a translating follower numbers no pivot.
#[test]
fn a_rockers_profile_numbers_every_pivot_on_its_circle() {
    for name in ["shaper", "cam-central"] {
        let (cam, _, _) = sheets(name, 0.5, Lang::Ru);
        let f = &cam.inversion.figure;
        let pivots: Vec<(DVec2, String)> = f
            .steps
            .iter()
            .filter(|s| s.note.starts_with("pivot O_2 at position "))
            .filter_map(|s| match (&s.item, &s.label) {
                (Item::Point(p), Some(l)) => Some((*p, l.text.clone())),
                _ => None,
            })
            .collect();
        let tmm::cam::follower::Placement::Rocker { pivot, .. } = cam.placement else {
            assert!(
                pivots.is_empty(),
                "{name}: {} pivots numbered",
                pivots.len()
            );
            continue;
        };
        let radius = f.scale.to_mm(pivot.length());
        let labels: Vec<&str> = pivots.iter().map(|(_, l)| l.as_str()).collect();
        let want: Vec<&str> = cam.points.iter().map(|p| p.label.as_str()).collect();
        assert_eq!(labels, want, "{name}");
        for (p, l) in &pivots {
            assert!(
                (p.length() - radius).abs() < tol(f),
                "{name}: O₂ of {l} off its circle"
            );
        }
        assert!(
            f.steps.iter().any(|s| matches!(s.item, Item::Circle(c)
                if (c.radius - radius).abs() < tol(f) && c.center.length() < tol(f))),
            "{name}: the pivot's circle"
        );
    }
}

/// The profile by inversion dimensions the base circle it is drawn on: a radius r₀ from O₁
/// to the circle, labelled, clear of the turned followers and of the support (the shaper's
/// accepted r₀ = 71 mm stood on its sheet as an unnamed circle), on every cam in ru and en.
#[test]
fn the_profiles_base_circle_is_dimensioned_r0() {
    for name in TURNING {
        for lang in [Lang::Ru, Lang::En] {
            let (cam, _, _) = sheets(name, 0.0, lang);
            let f = &cam.inversion.figure;
            let radii: Vec<(DVec2, DVec2)> = f
                .steps
                .iter()
                .filter(|s| s.role == Role::Dimension)
                .filter(|s| s.label.as_ref().is_some_and(|l| l.text == "r_0"))
                .filter_map(|s| match s.item {
                    Item::Vector { from, to } => Some((from, to)),
                    _ => None,
                })
                .collect();
            assert_eq!(radii.len(), 1, "{name}: one r_0 radius");
            let (from, to) = radii[0];
            // O₁, the cam's centre, is the figure's origin (a joint labelled O₁).
            let o = DVec2::ZERO;
            assert!(f
                .steps
                .iter()
                .any(|s| matches!(s.item, Item::Joint { at, .. } if at == o)
                    && s.label.as_ref().is_some_and(|l| l.text == "O_1")));
            assert!(from.distance(o) < tol(f), "{name}: from O₁");
            let r0 = cam.inversion.scale.to_mm(cam.base);
            assert!(
                (to.distance(o) - r0).abs() < tol(f) * 10.0,
                "{name}: to the base circle"
            );
            // No follower's pitch point, as the figure draws it, lies within 10° of the radius.
            let dir = (to - o).normalize();
            let near = f
                .steps
                .iter()
                .filter(|s| s.note.starts_with("pitch point "))
                .filter_map(|s| match s.item {
                    Item::Point(p) => Some((p - o).normalize().angle_to(dir).abs().to_degrees()),
                    _ => None,
                })
                .fold(f64::INFINITY, f64::min);
            assert!(
                near > 10.0 && near.is_finite(),
                "{name}: a follower {near:.1}° from r_0"
            );
            // Nor through the support drawn under O₁.
            let down = dir.dot(DVec2::NEG_Y).acos().to_degrees();
            assert!(down > 55.0, "{name}: r_0 {down:.0}° from straight down");
        }
    }
}
