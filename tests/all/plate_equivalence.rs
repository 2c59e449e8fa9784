//! The "≡" rule (issue 45), on every sheet of every scene in `constructions/`: a label that
//! joins names by "≡" names coincident points of one figure — `p ≡ b₃ ≡ d` on a plan,
//! `e ≡ s₅` on the lever — never different quantities (`R₁₋₂ ≡ R₂₋₃`, two reactions of 2359
//! and 2313 N; `F_и5 ≡ F_пс`, two loads; `s₃ ≡ h₇ ≡ h₈`, a point and two arms). Checked on
//! the plate's layout against the plate's model:
//! - every name joined is written for a step of the label's view whose label names a point;
//! - that point is a point of the step's item (a marked point, a pair, a block, an end of a
//!   line or vector), not a place along a line or on an arc;
//! - the named points coincide on the drawing: each within the drafting resolution (0,5 mm,
//!   [`resolution_mm`]) of every other (the tangent's `p ≡ a ≡ k` joined points 3,2 and
//!   1,6 mm apart);
//! - no name joined is a quantity's (a reaction `R₁₋₂`, a load with a Cyrillic subscript,
//!   an arm `h₇`);
//! - "≡" is written only by the joining of points (a label text with "≡" of one step is
//!   a quantity written as two).

use crate::plate_model::{
    self, every_sheet, named_point, names_point, on_sheet, resolution_mm, sheet, step, with_view,
};
use glam::DVec2;
use tmm::construct::{Item, Names, Step};
use tmm::plate::{layout, Layout, Plate, JOINT_SEPARATOR};

/// A name of a quantity rather than a point: a reaction's or a load's subscript (with a
/// dash, `R_{1-2}`, or a Cyrillic word, `F_{пс}`), or an arm `h_{7}`.
fn names_a_quantity(name: &str) -> bool {
    let sub = name.split_once('_').map_or("", |(_, s)| s);
    let cyrillic = |c: char| ('\u{0400}'..='\u{04FF}').contains(&c);
    sub.contains(['-', '–', '−']) || sub.chars().any(cyrillic) || name.starts_with("h_")
}

/// What is wrong with every "≡" of `plate`, described.
fn false_equivalences(plate: &Plate) -> Vec<String> {
    false_equivalences_in(plate, &layout(plate))
}

/// What is wrong with every "≡" of `plate` laid out as `l`, described.
fn false_equivalences_in(plate: &Plate, l: &Layout) -> Vec<String> {
    let mut out = Vec::new();
    for x in &l.labels {
        let names: Vec<&str> = x.text.split(JOINT_SEPARATOR).collect();
        if names.len() < 2 {
            continue;
        }
        let view = &plate.views[x.view];
        let say = |why: String| format!("view {} “{}”: {why}", x.view, x.text);
        if names.len() != x.steps.len() {
            out.push(say(format!(
                "{} names written for {} steps",
                names.len(),
                x.steps.len()
            )));
            continue;
        }
        let mut points = Vec::new();
        for (&id, name) in x.steps.iter().zip(&names) {
            let s = step(view, id);
            if !names_point(s) {
                out.push(say(format!(
                    "{name} names its item (step {:?}), not a point",
                    id
                )));
            }
            if names_a_quantity(name) {
                out.push(say(format!("{name} is a quantity's name")));
            }
            match named_point(s, resolution_mm()) {
                Some(p) => points.push(on_sheet(view, p)),
                None => out.push(say(format!(
                    "{name} is anchored off every point of its item ({:?})",
                    s.item
                ))),
            }
        }
        let apart = points.iter().enumerate().find_map(|(i, p)| {
            points[i + 1..]
                .iter()
                .find(|q| p.distance(**q) > resolution_mm() + 1e-9)
                .map(|q| (p, p.distance(*q)))
        });
        if let Some((p, d)) = apart {
            out.push(say(format!(
                "its point {p:?} is {d:.2} mm from another it is joined with"
            )));
        }
    }
    out
}

/// The rule holds on every sheet of every scene, and it has joint labels to check.
#[test]
fn labels_joined_by_equivalence_name_coincident_points() {
    let mut found = Vec::new();
    let mut checked = 0;
    for (name, plate) in every_sheet() {
        let l = layout(&plate);
        checked += l.labels.iter().filter(|x| x.steps.len() > 1).count();
        found.extend(
            false_equivalences(&plate)
                .into_iter()
                .map(|x| format!("{name}: {x}")),
        );
    }
    // The plans' poles and the lever's coincident images (p ≡ b₃ ≡ d, e ≡ s₅).
    assert!(checked > 30, "only {checked} joint labels");
    assert!(
        found.is_empty(),
        "{} false “≡”:\n  {}",
        found.len(),
        found.join("\n  ")
    );
}

/// A step drawn by hand: `item` with a label `text` at `anchor` naming `names`.
fn drawn(id: u32, item: Item, text: &str, anchor: DVec2, names: Names) -> Step {
    let mut s = plate_model::drawn(id, item, text, (anchor, DVec2::X));
    if let Some(l) = s.label.as_mut() {
        l.names = names;
    }
    s
}

/// The rule fails where it should: two reactions at a block labelled as the point at their
/// heads (the old drawing: `R₁₋₂ ≡ R₂₋₃`), two arms labelled as points at their middles
/// (`h₇ ≡ h₈`), and a quantity written with "≡" by hand.
#[test]
fn the_equivalence_rule_fails_on_a_plate_built_to_break_it() {
    let plate = sheet("shaper/forces");
    assert!(false_equivalences(&plate).is_empty());
    let x = DVec2::new(40.0, -40.0);
    let tip = x + DVec2::new(14.0, 0.0);
    let arm = |id, to: DVec2, text| {
        let s = tmm::geom::Segment::new(x, to);
        drawn(id, Item::Segment(s), text, x.lerp(to, 0.5), Names::Point)
    };
    let vector = Item::Vector { from: x, to: tip };
    let broken = with_view(
        plate,
        vec![
            // At their heads, a vector's label names its head by default: joined.
            drawn(0, vector.clone(), "R_{1-2}", tip, Names::of(&vector, tip)),
            drawn(1, vector.clone(), "R_{2-3}", tip, Names::of(&vector, tip)),
            arm(2, x + DVec2::new(0.0, 30.0), "h_{7}"),
            arm(3, x + DVec2::new(0.0, 30.0), "h_{8}"),
            drawn(
                4,
                Item::Vector {
                    from: x + DVec2::new(0.0, -40.0),
                    to: x + DVec2::new(20.0, -40.0),
                },
                "F_{и5} ≡ F_{пс}",
                x + DVec2::new(10.0, -40.0),
                Names::Item,
            ),
        ],
    );
    let found = false_equivalences(&broken).join("\n");
    for expected in [
        "R_{1-2} is a quantity's name",
        "R_{2-3} is a quantity's name",
        "h_{7} is anchored off every point of its item",
        "h_{8} is a quantity's name",
        "“F_{и5} ≡ F_{пс}”: 2 names written for 1 steps",
    ] {
        assert!(found.contains(expected), "{expected} not in:\n{found}");
    }
}

/// The tolerance fails where it should: a plan's image `a` 1,6 mm from the pole (a vector
/// 1,6 mm long, drawn as one, its head fitted) is written apart from `p` by the layout, and
/// the same two written as one label, `p ≡ a` (the old drawing: a vector shorter than its
/// arrowhead drawn as the point at its tail), are found.
#[test]
fn the_equivalence_tolerance_is_the_drafting_resolution() {
    let plate = sheet("tangent/kinematics");
    let x = DVec2::new(40.0, -40.0);
    let head = x + DVec2::new(1.6, 0.0);
    let vector = Item::Vector { from: x, to: head };
    let broken = with_view(
        plate,
        vec![
            drawn(0, Item::Point(x), "p", x, Names::Point),
            drawn(1, vector.clone(), "a", head, Names::of(&vector, head)),
        ],
    );
    let view = broken.views.len() - 1;
    let mut l = layout(&broken);
    let texts: Vec<&str> = l
        .labels
        .iter()
        .filter(|x| x.view == view)
        .map(|x| x.text.as_str())
        .collect();
    assert_eq!(texts, ["p", "a"]);
    assert!(false_equivalences_in(&broken, &l).is_empty());
    // Written as one, the old way.
    let at = l.labels.iter().position(|x| x.view == view).expect("p");
    let a = l.labels.remove(at + 1);
    l.labels[at].steps.extend(a.steps);
    l.labels[at].text = format!("p{JOINT_SEPARATOR}a");
    let found = false_equivalences_in(&broken, &l).join("\n");
    assert!(
        found.contains("“p ≡ a”: its point") && found.contains("is 1.60 mm from another"),
        "{found}"
    );
}
