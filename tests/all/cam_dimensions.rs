//! Issue 45, the cam sheets' second review: the dimensions of a combined diagram (r_min of
//! every follower, the flat face's ρ_min, the sliding cam's X_min/2π) stand clear of the
//! diagram's lines, on every scene with a combined diagram, in ru/uk/en, read at 0,5 mm
//! and exactly, checked on the plate model:
//! - a dimension (its line and its extension lines, as the sheet draws them) crosses no line
//!   of its view, but the axis it ends on, that the piece it measures does not cross itself:
//!   where the piece must cross a line (O₁B₀ of an offset follower crosses the γ_min line
//!   O₁ lies below when the zone lies between O₁ and the S axis), the dimension is drawn on
//!   the piece; drawn beside it, it adds no crossing (the review's r_min across the zone's
//!   ray on cam-shock);
//! - its text is struck by no line of its view;
//! - the flat face's ρ_min is written with its value (ρ_min = 10 мм), as r_min is;
//! - a dimension's text on a leader (r_min's beside its line) has the leader end on the
//!   dimension's line clear of every other line of the view: ending where another crosses
//!   (cam-shock's e dimension, halfway down O₁B₀ where r_min's leader ended) it names both.
//!
//! Each rule also runs on a plate built to break it, and must fail there.

use crate::plate_model::{chords, lines, on_sheet};
use glam::DVec2;
use tmm::cam::{RHO_ADMITTED, RHO_MIN_NOTE, R_MIN_NOTE};
use tmm::construct::{Drafting, Figure, Item, Role, Step};
use tmm::geom::Segment;
use tmm::plate::{layout, struck_dimension_texts, Plate};
use tmm::scale::Lang;
use tmm::scene::PlateKind;
use tmm::study::Session;

/// Every scene whose cam sheet has a combined diagram, and whether its follower is a flat
/// face (a ρ_min dimension).
const SCENES: [(&str, bool); 8] = [
    ("shaper", false),
    ("cam-central", false),
    ("cam-cusp", true),
    ("cam-pz4", true),
    ("cam-pz5", false),
    ("cam-shock", false),
    ("cam-undercut", false),
    ("cam-sliding", false),
];

/// The titles of the combined diagrams' figures: a turning cam's, a sliding cam's.
const TITLES: [&str; 2] = ["combined", "travel"];

/// Two pieces meeting nearer than this to an end of either touch, they do not cross, mm.
const TOUCH_MM: f64 = 0.05;

/// A dimension's leader ends at least this far from every other line of its view, mm: two
/// lines' widths and a leader's dot, and a reader tells which line it ends on.
const LEADER_CLEAR_MM: f64 = 1.5;

/// The cam sheets of scene `name` in `lang`, read at `drafting` mm.
fn cam_sheets(name: &str, drafting: f64, lang: Lang) -> Vec<Plate> {
    let s = crate::support::scene(name);
    let d = Drafting::new(drafting).expect("a drafting resolution");
    tmm::build(&Session::new(&s, d), PlateKind::Cam, lang).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// The combined diagrams of `plates`: (sheet, view).
fn combined_views(plates: &[Plate]) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    for (p, plate) in plates.iter().enumerate() {
        for (v, view) in plate.views.iter().enumerate() {
            if TITLES.contains(&view.figure.title.as_str()) {
                out.push((p, v));
            }
        }
    }
    out
}

/// The strokes of the dimension of the piece `from`–`to` drawn `offset` mm to its left, figure
/// mm: its line and, beside the piece, its two extension lines 2 mm past it (ГОСТ 2.307).
fn strokes(from: DVec2, to: DVec2, offset: f64) -> Vec<(DVec2, DVec2)> {
    let n = (to - from).normalize_or_zero().perp();
    let (a, b) = (from + n * offset, to + n * offset);
    let mut out = vec![(a, b)];
    if offset != 0.0 {
        let beyond = n * (2.0 * offset.signum());
        out.extend([(from, a + beyond), (to, b + beyond)]);
    }
    out
}

/// The lines a step draws, figure mm (a dimension: its strokes; a smooth curve: the chords
/// of the points it passes through, where a dimension ending on the curve was computed to
/// end — the French curve's swing beside a point, under a tenth of a millimetre, is no
/// crossing a reader sees).
fn drawn(step: &Step) -> Vec<(DVec2, DVec2)> {
    match &step.item {
        Item::Dimension { from, to, offset } => strokes(*from, *to, *offset),
        Item::Curve { points, closed } => chords(points, *closed),
        _ => lines(step),
    }
}

/// Whether two pieces cross: at an angle, each through the other's inside more than
/// [`TOUCH_MM`] from its ends (pieces along one line, or meeting at an end, touch).
fn cross((p0, p1): (DVec2, DVec2), (q0, q1): (DVec2, DVec2)) -> bool {
    let (u, v) = (p1 - p0, q1 - q0);
    let (lu, lv) = (u.length(), v.length());
    if lu < TOUCH_MM || lv < TOUCH_MM {
        return false;
    }
    let den = u.perp_dot(v);
    if den.abs() < 1e-6 * lu * lv {
        return false;
    }
    let w = q0 - p0;
    let (t, s) = (w.perp_dot(v) / den, w.perp_dot(u) / den);
    let (et, es) = (TOUCH_MM / lu, TOUCH_MM / lv);
    t > et && t < 1.0 - et && s > es && s < 1.0 - es
}

/// Whether the piece `from`–`to` ends on the axis `step` (the S axis at B₀; a diagram's
/// axis, drawn thin and solid, or a centre line).
fn ends_on_axis(step: &Step, from: DVec2, to: DVec2) -> bool {
    (step.role == Role::Axis || step.note.ends_with(" axis"))
        && drawn(step).iter().any(|&(a, b)| {
            let on = |p: DVec2| tmm::geom::Segment::new(a, b).distance_to(p) < TOUCH_MM;
            on(from) || on(to)
        })
}

/// Every dimension of `f` crossing a line of its view that the piece it measures does not
/// cross, the axis it ends on aside: “dimension” crosses “line”.
fn dimensions_crossing(f: &Figure) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for d in &f.steps {
        let Item::Dimension { from, to, offset } = d.item else {
            continue;
        };
        let mine = strokes(from, to, offset);
        let others = f.steps.iter().filter(|s| s.id != d.id);
        for other in others.filter(|s| !ends_on_axis(s, from, to)) {
            let theirs = drawn(other);
            let hit =
                |ours: &[(DVec2, DVec2)]| ours.iter().any(|a| theirs.iter().any(|b| cross(*a, *b)));
            let say = format!("“{}” crosses “{}”", d.note, other.note);
            if hit(&mine) && !hit(&[(from, to)]) && !out.contains(&say) {
                out.push(say);
            }
        }
    }
    out
}

/// The number a dimension's text `text` writes after `symbol = ` (either decimal sign).
fn value_after(text: &str, symbol: &str) -> Option<f64> {
    let rest = text.strip_prefix(symbol)?.strip_prefix(" = ")?;
    rest.split(' ').next()?.replace(',', ".").parse().ok()
}

/// The flat face's ρ_min dimension written with the scene's ρ_min (`rho`, m) as the sheet
/// writes it to four significant digits.
fn rho_min_valued(f: &Figure, rho: f64) -> Result<(), String> {
    let dims: Vec<&Step> = f.steps.iter().filter(|s| s.note == RHO_MIN_NOTE).collect();
    let [dim] = dims[..] else {
        return Err(format!("{} ρ_min dimensions", dims.len()));
    };
    let text = dim.label.as_ref().map_or("", |l| l.text.as_str());
    match value_after(text, RHO_ADMITTED) {
        Some(v) if (v - rho * 1e3).abs() <= 5e-4 * (rho * 1e3).max(1.0) => Ok(()),
        _ => Err(format!(
            "the ρ_min dimension reads “{text}”, ρ_min = {rho} m"
        )),
    }
}

/// Every dimension's leader of view `v` of `plate` ending nearer than [`LEADER_CLEAR_MM`]
/// to another line of the view: “dimension”'s leader ends x mm from “line”.
fn leaders_at_crossings(plate: &Plate, v: usize) -> Vec<String> {
    let view = &plate.views[v];
    let mut out = Vec::new();
    for l in layout(plate).labels.iter().filter(|l| l.view == v) {
        // A dimension line run on under its text ends on its own arrow, not at a crossing.
        let Some(leader) = l.leader.filter(|l| !l.run_on) else {
            continue;
        };
        let dims = view.figure.steps.iter().filter(|s| l.steps.contains(&s.id));
        for d in dims.filter(|s| matches!(s.item, Item::Dimension { .. })) {
            for other in view.figure.steps.iter().filter(|s| s.id != d.id) {
                let near = drawn(other)
                    .into_iter()
                    .map(|(a, b)| {
                        Segment::new(on_sheet(view, a), on_sheet(view, b)).distance_to(leader.to)
                    })
                    .fold(f64::INFINITY, f64::min);
                if near < LEADER_CLEAR_MM {
                    out.push(format!(
                        "“{}”'s leader ends {near:.2} mm from “{}”",
                        d.note, other.note
                    ));
                }
            }
        }
    }
    out
}

/// What a combined diagram's dimensions break on sheet `plates[p]`, view `v`.
fn broken_rules(plates: &[Plate], (p, v): (usize, usize), flat: Option<f64>) -> Vec<String> {
    let f = &plates[p].views[v].figure;
    let mut out = dimensions_crossing(f);
    out.extend(leaders_at_crossings(&plates[p], v));
    for (view, text, mm) in struck_dimension_texts(&plates[p]) {
        if view == v {
            out.push(format!("“{text}” holds {mm:.2} mm of line"));
        }
    }
    if let Some(rho) = flat {
        out.extend(rho_min_valued(f, rho).err());
    }
    out
}

#[test]
fn the_combined_diagrams_dimensions_stand_clear_of_its_lines() {
    let mut failures = Vec::new();
    let mut views = 0;
    for (name, flat) in SCENES {
        let rho = flat
            .then(|| crate::support::scene(name))
            .and_then(|s| s.cam.map(|c| c.rho_min));
        for (drafting, lang) in [
            (0.5, Lang::Ru),
            (0.0, Lang::Ru),
            (0.5, Lang::Uk),
            (0.5, Lang::En),
        ] {
            let plates = cam_sheets(name, drafting, lang);
            for pv in combined_views(&plates) {
                views += 1;
                failures.extend(
                    broken_rules(&plates, pv, rho)
                        .into_iter()
                        .map(|e| format!("{name} ({drafting} mm, {lang:?}): {e}")),
                );
            }
        }
    }
    assert_eq!(views, 4 * SCENES.len(), "combined diagrams found");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn the_dimension_rules_fail_on_a_plate_built_to_break_them() {
    // cam-shock's r_min beside O₁B₀ past the S axis, as the review found it: across the
    // zone's ray and its hatching.
    let plates = cam_sheets("cam-shock", 0.5, Lang::Ru);
    let [pv] = combined_views(&plates)[..] else {
        panic!("one combined diagram");
    };
    assert_eq!(broken_rules(&plates, pv, None), Vec::<String>::new());
    let mut moved = plates.clone();
    for s in moved[pv.0].views[pv.1].figure.steps.iter_mut() {
        if let (Item::Dimension { offset, .. }, true) = (&mut s.item, s.note == R_MIN_NOTE) {
            *offset = -14.0;
        }
    }
    let crossing = dimensions_crossing(&moved[pv.0].views[pv.1].figure);
    assert!(!crossing.is_empty(), "the moved r_min crosses nothing");
    // e dimensioned halfway down O₁B₀ again, across r_min's line where its leader ends.
    let mut halfway = plates.clone();
    let f = &mut halfway[pv.0].views[pv.1].figure;
    let r_min = f.steps.iter().find_map(|s| match s.item {
        Item::Dimension { from, to, .. } if s.note == R_MIN_NOTE => Some((from, to)),
        _ => None,
    });
    let (o, b0) = r_min.expect("r_min's dimension");
    for s in f.steps.iter_mut().filter(|s| s.note == tmm::cam::E_NOTE) {
        let y = 0.5 * (o.y + b0.y);
        s.item = Item::Dimension {
            from: DVec2::new(b0.x, y),
            to: DVec2::new(o.x, y),
            offset: 0.0,
        };
    }
    let at = leaders_at_crossings(&halfway[pv.0], pv.1).join("\n");
    assert!(at.contains("dimension e"), "{at}");
    // The flat face's ρ_min without its value (the review's PZ4).
    let plates = cam_sheets("cam-pz4", 0.5, Lang::Ru);
    let [pv] = combined_views(&plates)[..] else {
        panic!("one combined diagram");
    };
    let rho = crate::support::scene("cam-pz4").cam.map(|c| c.rho_min);
    assert_eq!(broken_rules(&plates, pv, rho), Vec::<String>::new());
    let mut bare = plates[pv.0].views[pv.1].figure.clone();
    for s in bare.steps.iter_mut().filter(|s| s.note == RHO_MIN_NOTE) {
        if let Some(l) = s.label.as_mut() {
            l.text = RHO_ADMITTED.into();
        }
    }
    assert!(rho_min_valued(&bare, rho.expect("a flat face's ρ_min")).is_err());
}
