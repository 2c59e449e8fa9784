//! The label-to-object rule (issue 45), on every sheet of every scene in `constructions/`
//! (Russian read exactly, and every language at the 0,5 mm `render` hands in), computed
//! from the plate's model and its layout (not from pixels):
//! - a label of a point is written within [`POINT_REACH_MM`] of its point (the point of its
//!   step's item: a marked point, a pair, a block, an end of a line or vector);
//! - a label of a line, a vector or an arc (a force, an arm, a couple, a dimension) is
//!   nearer to its own item than to any other line of its view (by [`NEARER_MM`]): a reader
//!   takes a label for the nearest line's.
//!
//! The placer keeps both itself (it pays for a label beyond its reach or nearer another
//! line); where a crowded figure leaves it no place both clear and at its object, the
//! failure is listed in [`EXEMPT`] with the reason; every exemption must still be needed.

use crate::plate_model::{
    box_to_point, box_to_segment, drawn, every_sheet_in, lines, named_point, names_point, on_sheet,
    sheet, step, with_view,
};
use glam::DVec2;
use tmm::construct::{Drafting, Item, StepId};
use tmm::plate::{layout, Layout, Plate, View};
use tmm::scale::Lang;

/// A label of a point is written at most this far from it, mm: the label's gap and two
/// further rings of places 3 mm apart, a pair's circle included — where a crowded plan
/// writes it. Ten millimetres and more is read as another point's (`B₂` 10 mm from its
/// dot, issue 45).
const POINT_REACH_MM: f64 = 7.5;

/// A label of an item counts as nearer another line only by more than this, mm (two lines
/// of a polygon meeting at a vertex are as near as each other there).
const NEARER_MM: f64 = 0.5;

/// Failures known and stated: (sheet, the note of the label's step, why) — where the
/// placer, which pays for a label beyond its reach or nearer another line (and pays more
/// for a line striking through a label), finds no place both clear and at its object. A
/// failure matches an entry of its sheet and its step's note (the same in every language).
const EXEMPT: &[(&str, &str, &str)] = &[
    // Labels of points in a fan of lines: the placer's nearest clear place is beyond reach.
    ("tangent/kinematics", "fixed pivot O", FAN_POINT),
    ("six-bar/kinematics", "image s_4", FAN_POINT),
    ("six-bar/kinematics-2", "image s_4′", FAN_POINT),
    ("cam-pz5/cam", "cam centre O_1", FAN_POINT),
    ("friction-follower/friction", "the pivot O₂", FAN_POINT),
    ("six-bar/kinematics", "fixed pivot O", FAN_POINT),
    (
        "slider-crank/kinematics",
        "point S_2 of position 1",
        FAN_POINT,
    ),
    ("tangent/kinematics", "pole", PLANS),
    // Labels of items among other lines nearer than their own at every clear place.
    (
        "four-bar/kinematics",
        "angle θ between the crank's extreme positions",
        ANGLES,
    ),
    (
        "v-engine/kinematics",
        "angle θ between the crank's extreme positions",
        ANGLES,
    ),
    ("six-bar/kinematics", "swing angle of the rocker", ANGLES),
    ("shaper/dynamics", "pole distance H", DYNAMICS),
    ("gears-pz3/gears", "the curve s_a1 ≥ 0.25m", CONTOUR),
    ("gears-pz3/gears", "the curve s_a2 ≥ 0.25m", CONTOUR),
    (
        "friction/friction",
        "one turn unrolled: πd₁",
        FRICTION_SCHEMES,
    ),
    (
        "friction/friction",
        "α, P from the normal",
        FRICTION_SCHEMES,
    ),
    ("shaper/forces", "F_{и4} at its image", LEVER_RAYS),
    ("shaper/forces", "F′_{и3} at its image", LEVER_RAYS),
    ("shaper/forces", "G_{3} at its image", LEVER_RAYS),
    ("shaper/forces", "arm of G_{4}", LEVER_RAYS),
    ("v-engine/forces", "F′_{и2} at its image", LEVER_RAYS),
    ("v-engine/forces", "F′_{и4} at its image", LEVER_RAYS),
    ("v-engine/forces", "arm of G_{4}", LEVER_RAYS),
    ("v-engine/forces", "arm of F″_{и2}", LEVER_RAYS),
    ("v-engine/forces-2", "F′_{и2} at its image", LEVER_RAYS),
    ("shaper/forces", "detail: read R_{3-4}", DETAIL_ZONE),
    ("shaper/forces", "lay off F_{и3}", DETAIL_ZONE),
    ("shaper/forces-2", "lay off G_{3}", DETAIL_ZONE),
    ("v-engine/forces", "lay off R^τ_{1-4}", DETAIL_ZONE),
    ("v-engine/forces-2", "detail: lay off F_{д3}", DETAIL_ZONE),
    ("v-engine/forces-2", "lay off F_{и2}", DETAIL_ZONE),
    ("v-engine/forces-2", "detail: read R_{1-2}", DETAIL_ZONE),
];

const FAN_POINT: &str = "a point inside a fan or ring of lines drawn about it (the crank's \
    twelve positions as spokes about O, the connecting rod's positions about S₂, the \
    direction lines through a plan's image, the circle and support about a pivot): every place within the reach is struck through by \
    one of them or covers another label, so the placer pays the reach's cost and writes the \
    label at the nearest clear place, 8–11 mm out; the fix is a leader from the point to the \
    label (ГОСТ 2.316), not made in this round";
const PLANS: &str = "the pole of a crowded plan (its images and their direction lines \
    within 10 mm at the scene's μ_v): every place within the reach is struck or covers \
    another label (the plans' scales are other work of issue 45)";
const ANGLES: &str = "an angle's label on the plan of positions (θ, ψ) between its arc and \
    the trajectories and link positions crossing it: every place beside the arc is struck \
    or nearer one of them by 0,6–2,4 mm (the kinematic sheets' scales are other work of \
    issue 45)";
const DYNAMICS: &str = "the pole distance H of the energy–mass fan written between the rays \
    it measures, 0,7 mm nearer ray 11 than the distance's own line";
const CONTOUR: &str = "a blocking-contour curve's text (s_a ≥ 0,25m) where the curves, the \
    axes x₁, x₂ and the isolines cross every 5–10 mm: written beside its curve but across \
    an axis";
const LEVER_RAYS: &str = "on Zhukovsky's lever a force's or an arm's label among the rays \
    of the turned plan, the arms and the lines of action converging on the pole and the \
    images (a dozen lines within 10 mm): every clear place is 0,5–2 mm nearer another of \
    them (an arm a few millimetres long at the pole, 10 mm)";
const DETAIL_ZONE: &str = "a polygon's short force beside its detail's zone circle (the \
    circle drawn round the forces the detail enlarges), or in the detail among its closing \
    lines: its clear places are nearer the circle or a closing line by 0,5–4 mm";
const FRICTION_SCHEMES: &str = "a scheme's label 0,5–1 mm nearer a thin line of the \
    scheme than its own (the thread's development beside the load, the cone at φ₀)";

/// Every label of `plate` away from its object: the note of its (first) step, and
/// `view N “text”: why`.
fn labels_away(plate: &Plate) -> Vec<(String, String)> {
    labels_away_in(plate, &layout(plate))
}

/// Every label of `plate` laid out as `l` away from its object (see [`labels_away`]).
fn labels_away_in(plate: &Plate, l: &Layout) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for x in &l.labels {
        let view = &plate.views[x.view];
        let first = step(view, x.steps[0]);
        let say = |why: String| {
            (
                first.note.clone(),
                format!("view {} “{}”: {why}", x.view, x.text),
            )
        };
        let (lo, hi) = (x.rect.min, x.rect.max);
        if names_point(first) || x.steps.len() > 1 {
            let Some(p) = named_point(first, f64::INFINITY) else {
                out.push(say("names a point its item does not have".into()));
                continue;
            };
            let d = box_to_point(lo, hi, on_sheet(view, p));
            if d > POINT_REACH_MM {
                out.push(say(format!("{d:.1} mm from its point")));
            }
            continue;
        }
        let own: Vec<(DVec2, DVec2)> = lines(first)
            .into_iter()
            .map(|(a, b)| (on_sheet(view, a), on_sheet(view, b)))
            .collect();
        if own.is_empty() {
            continue;
        }
        let d_own = own
            .iter()
            .map(|&(a, b)| box_to_segment(lo, hi, a, b))
            .fold(f64::INFINITY, f64::min);
        if let Some((d, other)) = nearest_other(view, &x.steps, (lo, hi)) {
            if d + NEARER_MM < d_own {
                out.push(say(format!(
                    "{d_own:.1} mm from its item, {d:.1} mm from “{}”",
                    other
                )));
            }
        }
    }
    out
}

/// The nearest line of `view` to the box `lo`–`hi` not drawn by the steps `own`, with the
/// distance and the note of its step.
fn nearest_other(view: &View, own: &[StepId], (lo, hi): (DVec2, DVec2)) -> Option<(f64, String)> {
    view.figure
        .steps
        .iter()
        .filter(|s| !own.contains(&s.id))
        .flat_map(|s| {
            lines(s).into_iter().map(move |(a, b)| {
                let d = box_to_segment(lo, hi, on_sheet(view, a), on_sheet(view, b));
                (d, s.note.clone())
            })
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
}

/// The languages and draftings the rule is checked in: the tests' exact reading in
/// Russian, and what `render` hands in by default (0,5 mm) in every language — the texts'
/// widths differ, and so do the places found.
const CONFIGURATIONS: [(Lang, Drafting, &str); 4] = [
    (Lang::Ru, Drafting::EXACT, "ru exact"),
    (Lang::Ru, Drafting::HAND, "ru 0,5"),
    (Lang::Uk, Drafting::HAND, "uk 0,5"),
    (Lang::En, Drafting::HAND, "en 0,5"),
];

/// The failures of every sheet in every configuration, with the exemptions they use.
fn failures() -> (Vec<String>, Vec<usize>) {
    let mut found = Vec::new();
    let mut used = Vec::new();
    for (lang, drafting, said) in CONFIGURATIONS {
        for (name, plate) in every_sheet_in(lang, drafting) {
            for (note, why) in labels_away(&plate) {
                let exempt = EXEMPT
                    .iter()
                    .position(|(sheet, n, _)| *sheet == name && note == *n);
                match exempt {
                    Some(k) => used.push(k),
                    None => found.push(format!("{said}: {name}: {why} [{note}]")),
                }
            }
        }
    }
    (found, used)
}

/// The rule holds on every sheet of every scene, every exemption still needed.
#[test]
fn every_label_is_at_its_object() {
    let (found, used) = failures();
    assert!(
        found.is_empty(),
        "{} labels away from their objects:\n  {}",
        found.len(),
        found.join("\n  ")
    );
    let stale: Vec<String> = EXEMPT
        .iter()
        .enumerate()
        .filter(|(k, _)| !used.contains(k))
        .map(|(_, (sheet, note, why))| format!("{sheet} [{note}] ({why})"))
        .collect();
    assert!(
        stale.is_empty(),
        "exempt but holding:\n  {}",
        stale.join("\n  ")
    );
}

/// The rule fails where it should: a point's label anchored 30 mm from its point (the
/// lever's image of P labelled at its force's arrow), and a reaction's label written on
/// another side of its polygon (`R₁₋₂` on the `R₄₋₃` line) — the placer would move a label
/// merely anchored there, so its placed box is moved there.
#[test]
fn the_object_rule_fails_on_a_plate_built_to_break_it() {
    let plate = sheet("friction/friction");
    let before = labels_away(&plate).len();
    let (o, a, b) = (DVec2::ZERO, DVec2::new(60.0, 0.0), DVec2::new(60.0, -40.0));
    let mut point = drawn(0, Item::Point(o), "p_{P}", (o, DVec2::Y));
    if let Some(l) = point.label.as_mut() {
        l.anchor = o + DVec2::new(30.0, 0.0);
    }
    let side = |id, from: DVec2, to: DVec2, text, at: DVec2| {
        let toward = (to - from).perp().normalize();
        drawn(id, Item::Vector { from, to }, text, (at, toward))
    };
    let steps = vec![
        point,
        side(1, o, a, "R_{4-3}", o.lerp(a, 0.5)),
        side(2, a, b, "R_{1-2}", a.lerp(b, 0.5)),
    ];
    let plate = with_view(plate, steps);
    let mut l = layout(&plate);
    let broken = plate.views.len() - 1;
    let view = &plate.views[broken];
    // R₁₋₂'s label written just above the middle of R₄₋₃.
    let on = on_sheet(view, o.lerp(a, 0.5));
    for x in l.labels.iter_mut() {
        if x.view == broken && x.text == "R_{1-2}" {
            let size = x.rect.max - x.rect.min;
            x.rect.min = on + DVec2::new(-size.x * 0.5, -size.y - 0.5);
            x.rect.max = x.rect.min + size;
        }
    }
    let found: Vec<String> = labels_away_in(&plate, &l)
        .into_iter()
        .map(|x| x.1)
        .collect();
    assert!(found.len() >= before + 2, "{found:?}");
    let all = found.join("\n");
    assert!(
        all.contains("“p_{P}”:") && all.contains("mm from its point"),
        "{all}"
    );
    assert!(
        all.contains("“R_{1-2}”:") && all.contains("R_{4-3}"),
        "{all}"
    );
    // Laid out by the placer, the reaction's label is at its own side.
    let placed: Vec<String> = labels_away(&plate).into_iter().map(|x| x.1).collect();
    assert!(!placed.join("\n").contains("“R_{1-2}”:"), "{placed:?}");
}
