//! The label-to-object rule (issue 45), on every sheet of every scene in `constructions/`
//! (Russian read exactly, and every language at the 0,5 mm `render` hands in), computed
//! from the plate's model and its layout (not from pixels):
//! - a label of a point is written within [`POINT_REACH_MM`] of its point (the point of its
//!   step's item: a marked point, a pair, a block, an end of a line or vector), and no nearer
//!   another labelled point, of its view or the next (the shaper's position 5's
//!   `d₅ ≡ e ≡ s₅` stood over position 6's p), nor a chain of names right over another
//!   labelled point as near as its own (the gear train's `0 ≡ 5` with its `5` over H's
//!   intercept), nor past a line of its view that does not run through the point (the
//!   tangent's `c`, on `pa`, written right of `pb`);
//! - a label of a line, a vector or an arc (a force, an arm, a couple, a dimension) is
//!   written within [`ITEM_REACH_MM`] of its own item, and nearer to it than to any other
//!   line, of its view or another (by [`NEARER_MM`]): a reader takes a label for the nearest line's, and
//!   a label far from every line for nobody's; no other label stands nearer its item by more
//!   than [`OUTNEARED_MM`] (the item is read as that label's);
//! - or it is written on a leader's shelf (ГОСТ 2.316) whose line ends on its object, within
//!   [`LEADER_AT_MM`]; no leader runs through another label or crosses another leader.
//!
//! The placer keeps these itself (it pays for a label beyond its reach or nearer another
//! line, and takes a leader where that costs less); where a crowded figure leaves it no place both clear and at its object, the
//! failure is listed in [`EXEMPT`] with the reason; every exemption must still be needed.

use crate::plate_model::{
    box_to_point, box_to_segment, drawn, every_sheet_in, lines, named_point, names_point, on_sheet,
    sheet, step, with_view,
};
use glam::DVec2;
use tmm::construct::{Drafting, Item, Names, StepId};
use tmm::plate::{layout, Layout, PlacedLabel, Plate, View};
use tmm::scale::Lang;

/// A label of a point is written at most this far from it, mm: the label's gap and two
/// further rings of places 3 mm apart, a pair's circle included — where a crowded plan
/// writes it. Ten millimetres and more is read as another point's (`B₂` 10 mm from its
/// dot, issue 45).
const POINT_REACH_MM: f64 = 7.5;

/// A label of a line, a vector or an arc is written at most this far from it, mm (as a
/// point's: the lever's `F_и5` 12 mm under its arrow, nothing else near, issue 45).
const ITEM_REACH_MM: f64 = POINT_REACH_MM;

/// A line this near a labelled point runs through it as the drawing reads (a label keeps
/// 1 mm from its point), mm: lines meeting at a point do not part it from its label.
const THROUGH_MM: f64 = 1.0;

/// Another label this much nearer an item than the item's own is read as its, mm (the
/// shaper's `F_и3` 1,8 mm from the arrow of `R₂₋₃`, written 4,3 mm from it, issue 45).
const OUTNEARED_MM: f64 = 2.0;

/// A leader ends on its object: within this of its point or its item's line (a thin line's
/// width: an arc is flattened to chords differently here and in the placer), mm.
const LEADER_AT_MM: f64 = 0.25;

/// A label of an item counts as nearer another line only by more than this, mm (two lines
/// of a polygon meeting at a vertex are as near as each other there).
const NEARER_MM: f64 = 0.5;

/// Failures known and stated: (sheet, the note of the label's step, why) — where the
/// placer, which pays for a label beyond its reach or nearer another line (and pays more
/// for a line striking through a label), finds no place both clear and at its object, on a
/// leader either. A failure matches an entry of its sheet and its step's note (the same in
/// every language).
const EXEMPT: &[(&str, &str, &str)] = &[(
    "six-bar/kinematics",
    "point S_3 of position 1",
    "the plan of positions draws links 3 and 4 in twelve positions across S₃'s path: every \
     place within reach of position 1's S₃ is past another position's link, and a leader out \
     of that web crosses more of them",
)];

/// Every label of `plate` away from its object: the note of its (first) step, and
/// `view N “text”: why`.
pub(crate) fn labels_away(plate: &Plate) -> Vec<(String, String)> {
    labels_away_in(plate, &layout(plate))
}

/// Every label of `plate` laid out as `l` away from its object (see [`labels_away`]).
pub(crate) fn labels_away_in(plate: &Plate, l: &Layout) -> Vec<(String, String)> {
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
        if let Some(l) = &x.leader {
            if let Some(d) = leader_miss(view, first, x.steps.len() > 1, l.to) {
                out.push(say(format!("its leader ends {d:.2} mm from its object")));
            }
            continue;
        }
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
            let rival = l
                .labels
                .iter()
                // Any view's: a label nearer the next plan's pole is read as that plan's.
                .filter(|o| o.anchor.distance(x.anchor) > 1e-6)
                .map(|o| (box_to_point(lo, hi, o.anchor), &o.text))
                .min_by(|a, b| a.0.total_cmp(&b.0));
            if let Some((r, other)) = rival.filter(|(r, _)| r + NEARER_MM < d) {
                out.push(say(format!(
                    "{d:.1} mm from its point, {r:.1} mm from “{other}”'s"
                )));
            }
            if let Some(other) = chain_over(l, x, d) {
                out.push(say(format!(
                    "a chain of names over “{other}”'s point, as near as its own"
                )));
            }
            if let Some(line) = line_between(view, on_sheet(view, p), (lo, hi)) {
                out.push(say(format!("{d:.1} mm from its point, past [{line}]")));
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
        if d_own > ITEM_REACH_MM {
            out.push(say(format!("{d_own:.1} mm from its item")));
        }
        if let Some((d, other)) = nearest_other(plate, (x.view, &x.steps), (lo, hi)) {
            if d + NEARER_MM < d_own {
                out.push(say(format!(
                    "{d_own:.1} mm from its item, {d:.1} mm from “{}”",
                    other
                )));
            }
        }
        if let Some((other, d)) = outneared(l, x, &own, d_own) {
            out.push(say(format!(
                "{d_own:.1} mm from its item, “{other}” {d:.1} mm from it"
            )));
        }
    }
    out
}

/// The label whose point stands right under (or over, or beside) the chain of names `x`
/// (`0 ≡ 5`), within [`POINT_REACH_MM`] and no farther than its own point (`own`, mm): a
/// reader takes that point for the name written over it (the gear train's «5» over H's
/// intercept, its own point under «≡»).
fn chain_over<'l>(l: &'l Layout, x: &PlacedLabel, own: f64) -> Option<&'l str> {
    if !x.text.contains('≡') {
        return None;
    }
    let (lo, hi) = (x.rect.min, x.rect.max);
    l.labels
        .iter()
        .filter(|o| o.anchor.distance(x.anchor) > 1e-6)
        .find(|o| {
            let p = o.anchor;
            let across = (lo.x..=hi.x).contains(&p.x) || (lo.y..=hi.y).contains(&p.y);
            let d = box_to_point(lo, hi, p);
            across && d <= POINT_REACH_MM && d <= own + NEARER_MM
        })
        .map(|o| o.text.as_str())
}

/// The note of a line of `view` running between the point `p` (sheet mm) and its label's
/// box `lo`–`hi`: a line not through the point (farther than [`THROUGH_MM`]) crossing the
/// way from the point to the box's nearest point. A label past a line is read as what lies
/// on its side (the tangent's `c`, on `pa`, written right of `pb`, issue 45).
fn line_between(view: &View, p: DVec2, (lo, hi): (DVec2, DVec2)) -> Option<String> {
    let q = p.clamp(lo, hi);
    // Which side of the line through `o` and `u` the point `x` is on (0 on it): the way
    // from the point to the box has its ends on two sides of the line (a line along the
    // way, or ending on the box, does not part them), and the line's ends are on two
    // sides of the way, or on it.
    let side = |o: DVec2, u: DVec2, x: DVec2| (u - o).perp_dot(x - o);
    let crosses = |a: DVec2, b: DVec2| {
        side(a, b, p) * side(a, b, q) < 0.0 && side(p, q, a) * side(p, q, b) <= 0.0
    };
    view.figure.steps.iter().find_map(|s| {
        let between = lines(s).into_iter().any(|(a, b)| {
            let (a, b) = (on_sheet(view, a), on_sheet(view, b));
            box_to_segment(p, p, a, b) > THROUGH_MM && crosses(a, b)
        });
        between.then(|| s.note.clone())
    })
}

/// Another label of the layout `l` nearer the item of `x` (its lines `own`, on the sheet)
/// than `x` itself (`mine`, mm) by more than [`OUTNEARED_MM`], with its distance: the item
/// is read as that label's.
fn outneared(
    l: &Layout,
    x: &PlacedLabel,
    own: &[(DVec2, DVec2)],
    mine: f64,
) -> Option<(String, f64)> {
    l.labels
        .iter()
        .filter(|y| !std::ptr::eq(*y, x))
        .map(|y| {
            let d = (own.iter())
                .map(|&(a, b)| box_to_segment(y.rect.min, y.rect.max, a, b))
                .fold(f64::INFINITY, f64::min);
            (y, d)
        })
        .find(|(_, d)| d + OUTNEARED_MM < mine)
        .map(|(y, d)| (y.text.clone(), d))
}

/// How far a leader ending at `to` (sheet mm) misses the object of the label of `step`
/// (`joint`: a joint label, which names a point; a step drawing no point or line names its
/// anchor), when by more than [`LEADER_AT_MM`].
fn leader_miss(view: &View, step: &tmm::construct::Step, joint: bool, to: DVec2) -> Option<f64> {
    let own = lines(step);
    let point = named_point(step, f64::INFINITY);
    let d = if (names_point(step) || joint) && point.is_some() {
        on_sheet(view, point?).distance(to)
    } else if !own.is_empty() {
        own.into_iter()
            .map(|(a, b)| box_to_segment(to, to, on_sheet(view, a), on_sheet(view, b)))
            .fold(f64::INFINITY, f64::min)
    } else {
        // A text item (a position's number, a curve's name in a detail) names what stands
        // at its anchor.
        on_sheet(view, step.label.as_ref()?.anchor).distance(to)
    };
    (d > LEADER_AT_MM).then_some(d)
}

/// The nearest line of any view of `plate` to the box `lo`–`hi` not drawn by the steps
/// `own` of view `k`, with the distance and the note of its step.
fn nearest_other(
    plate: &Plate,
    (k, own): (usize, &[StepId]),
    (lo, hi): (DVec2, DVec2),
) -> Option<(f64, String)> {
    plate
        .views
        .iter()
        .enumerate()
        .flat_map(|(v, view)| {
            view.figure
                .steps
                .iter()
                .filter(move |s| v != k || !own.contains(&s.id))
                .flat_map(move |s| {
                    lines(s).into_iter().map(move |(a, b)| {
                        let d = box_to_segment(lo, hi, on_sheet(view, a), on_sheet(view, b));
                        (d, s.note.clone())
                    })
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
/// merely anchored there, so its placed box is moved there; a position number written
/// past the next point, nearer it than its own; and a position number as the plan of
/// positions writes it (a text naming its crank pin) 10 mm from its pin (the four-bar's "8",
/// issue 45: a text's label was not measured).
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
    // Two position numbers 6 mm apart.
    let (p8, p9) = (DVec2::new(0.0, -60.0), DVec2::new(6.0, -60.0));
    let p10 = DVec2::new(0.0, -90.0);
    // A force alone, nothing else near it.
    let (f0, f1) = (DVec2::new(0.0, -130.0), DVec2::new(20.0, -130.0));
    let mut number = drawn(5, Item::Text(p10), "10", (p10, -DVec2::Y));
    if let Some(l) = number.label.as_mut() {
        l.names = Names::Point;
    }
    let steps = vec![
        point,
        side(1, o, a, "R_{4-3}", o.lerp(a, 0.5)),
        side(2, a, b, "R_{1-2}", a.lerp(b, 0.5)),
        drawn(3, Item::Point(p8), "8", (p8, -DVec2::Y)),
        drawn(4, Item::Point(p9), "9", (p9, -DVec2::Y)),
        number,
        side(6, f0, f1, "F_{и5}", f0.lerp(f1, 0.5)),
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
    // "8" written past point 9, within its reach of its own point but nearer 9.
    let past_nine = on_sheet(view, p9) + DVec2::new(2.5, 0.0);
    for x in l.labels.iter_mut() {
        if x.view == broken && x.text == "8" {
            let size = x.rect.max - x.rect.min;
            x.rect.min = past_nine - size * 0.5;
            x.rect.max = x.rect.min + size;
        }
    }
    // "10" written 10 mm to the right of its pin.
    let off_ten = on_sheet(view, p10) + DVec2::new(10.0, 0.0);
    for x in l.labels.iter_mut() {
        if x.view == broken && x.text == "10" {
            let size = x.rect.max - x.rect.min;
            x.rect.min = off_ten - DVec2::new(0.0, size.y * 0.5);
            x.rect.max = x.rect.min + size;
        }
    }
    // The force's label 12 mm under its arrow: nearer it than any other line, and read as
    // nobody's.
    let under = on_sheet(view, f0.lerp(f1, 0.5));
    for x in l.labels.iter_mut() {
        if x.view == broken && x.text == "F_{и5}" {
            let size = x.rect.max - x.rect.min;
            x.rect.min = under + DVec2::new(-size.x * 0.5, 12.0);
            x.rect.max = x.rect.min + size;
        }
    }
    let found: Vec<String> = labels_away_in(&plate, &l)
        .into_iter()
        .map(|x| x.1)
        .collect();
    assert!(found.len() >= before + 5, "{found:?}");
    assert!(
        found
            .iter()
            .any(|w| w.contains("“F_{и5}”: 12.0 mm from its item")),
        "{found:?}"
    );
    assert!(
        found
            .iter()
            .any(|w| w.contains("“10”: 10.0 mm from its point")),
        "{found:?}"
    );
    let all = found.join("\n");
    assert!(
        all.contains("“p_{P}”:") && all.contains("mm from its point"),
        "{all}"
    );
    assert!(
        all.contains("“R_{1-2}”:") && all.contains("R_{4-3}"),
        "{all}"
    );
    assert!(all.contains("“8”:") && all.contains("from “9”'s"), "{all}");
    // Laid out by the placer, the reaction's label is at its own side and "8" at its point.
    let placed: Vec<String> = labels_away(&plate).into_iter().map(|x| x.1).collect();
    let placed = placed.join("\n");
    assert!(
        !placed.contains("“R_{1-2}”:")
            && !placed.contains("“8”:")
            && !placed.contains("“10”:")
            && !placed.contains("“F_{и5}”:"),
        "{placed}"
    );
}

/// The rule reads a label against the other views' lines too: a force's label written 1 mm
/// from a line of the next drawing and about 5 mm from its own (11 mm away) is that
/// drawing's.
#[test]
fn the_object_rule_sees_another_views_line() {
    let plate = sheet("friction/friction");
    let vector = |from: DVec2, to: DVec2, text| {
        let toward = (to - from).perp().normalize();
        drawn(
            1,
            Item::Vector { from, to },
            text,
            (from.lerp(to, 0.5), toward),
        )
    };
    let (a0, a1) = (DVec2::ZERO, DVec2::new(40.0, 0.0));
    let (b0, b1) = (DVec2::new(0.0, -11.0), DVec2::new(40.0, -11.0));
    let plate = with_view(plate, vec![vector(a0, a1, "R_{1-2}")]);
    let plate = with_view(plate, vec![vector(b0, b1, "R_{4-3}")]);
    let (first, second) = (plate.views.len() - 2, plate.views.len() - 1);
    let mut l = layout(&plate);
    let (own, other) = (
        on_sheet(&plate.views[first], a0.lerp(a1, 0.5)),
        on_sheet(&plate.views[second], b0.lerp(b1, 0.5)),
    );
    // The label's box between the two lines, 1 mm from the other's.
    let toward = (other - own).normalize();
    for x in l.labels.iter_mut() {
        if x.view == first && x.text == "R_{1-2}" {
            let size = x.rect.max - x.rect.min;
            let edge = other - toward * 1.0;
            x.rect.min = edge - DVec2::new(size.x * 0.5, if toward.y > 0.0 { size.y } else { 0.0 });
            x.rect.max = x.rect.min + size;
        }
    }
    let found: Vec<String> = labels_away_in(&plate, &l)
        .into_iter()
        .map(|x| x.1)
        .collect();
    assert!(
        found
            .iter()
            .any(|w| w.contains("“R_{1-2}”:") && w.contains("R_{4-3}")),
        "{found:?}"
    );
}

/// A rule read off each sheet's layout, on every sheet in every configuration: its findings,
/// each prefixed with the configuration and the sheet, and how many labels `counted` takes
/// (so that a test sees the rule checked on real labels).
pub(crate) fn on_every_layout(
    rule: impl Fn(&Layout) -> Vec<String>,
    counted: impl Fn(&PlacedLabel) -> bool,
) -> (Vec<String>, usize) {
    let mut found = Vec::new();
    let mut count = 0;
    for (lang, drafting, said) in CONFIGURATIONS {
        for (name, plate) in every_sheet_in(lang, drafting) {
            let l = layout(&plate);
            count += l.labels.iter().filter(|x| counted(x)).count();
            found.extend(rule(&l).into_iter().map(|w| format!("{said}: {name}: {w}")));
        }
    }
    (found, count)
}
