//! The label-to-object rule's misreadings (issue 45) on plates built to break it: a label of
//! a point past a line from its point, a label of a force with another label nearer its
//! arrow. Each is found when written so, and not when the placer writes it.

use crate::plate_label_objects::{labels_away, labels_away_in};
use crate::plate_model::{drawn, on_sheet, sheet, with_view};
use glam::DVec2;
use tmm::construct::{Item, Step};
use tmm::plate::{layout, Plate, View};

/// A figure point of `plate`'s first view (which [`with_view`] copies) given in sheet mm
/// from its origin.
fn in_sheet_mm(plate: &Plate) -> impl Fn(f64, f64) -> DVec2 {
    let first = &plate.views[0];
    let per_mm = 1.0 / (on_sheet(first, DVec2::X) - on_sheet(first, DVec2::ZERO)).length();
    move |x, y| DVec2::new(x, y) * per_mm
}

/// `plate` with a view drawing `steps`, laid out with each of its labels moved by `put`
/// (given the label's text and size, its box's top-left corner on the sheet, or `None` to
/// leave it) off its leader; the rule's findings there must include `what`, and laid out
/// by the placer that view must have none.
fn found_only_as_moved(
    plate: Plate,
    steps: Vec<Step>,
    put: impl Fn(&View, &str, DVec2) -> Option<DVec2>,
    what: &str,
) {
    let plate = with_view(plate, steps);
    let broken = plate.views.len() - 1;
    let view = &plate.views[broken];
    let mut l = layout(&plate);
    for x in l.labels.iter_mut().filter(|x| x.view == broken) {
        let size = x.rect.max - x.rect.min;
        if let Some(min) = put(view, &x.text, size) {
            x.rect = tmm::plate::Rect::new(min, min + size);
            x.leader = None;
        }
    }
    let found: Vec<String> = labels_away_in(&plate, &l)
        .into_iter()
        .map(|x| x.1)
        .collect();
    assert!(found.iter().any(|w| w.contains(what)), "{found:?}");
    let here = format!("view {broken} ");
    let placed: Vec<String> = labels_away(&plate).into_iter().map(|x| x.1).collect();
    assert!(placed.iter().all(|w| !w.starts_with(&here)), "{placed:?}");
}

/// A label of a point written past a line from its point (the tangent's `c`, on `pa`,
/// written right of `pb`) is away from it, though within reach; laid out by the placer, it
/// stands on its point's side.
#[test]
fn a_label_past_a_line_from_its_point_is_away() {
    let plate = sheet("friction/friction");
    let at = in_sheet_mm(&plate);
    let c = DVec2::ZERO;
    let line = Item::Segment(tmm::geom::Segment::new(at(2.0, -15.0), at(2.0, 15.0)));
    let steps = vec![
        drawn(0, Item::Point(c), "c", (c, DVec2::X)),
        drawn(1, line, "pb", (at(2.0, 15.0), DVec2::X)),
    ];
    // “c” 3 mm right of its point, past the line 2 mm right of it.
    let put = |view: &View, text: &str, size: DVec2| {
        (text == "c").then(|| on_sheet(view, c) + DVec2::new(3.0, -size.y * 0.5))
    };
    let what = "“c”: 3.0 mm from its point, past [drawn by the test: pb]";
    found_only_as_moved(plate, steps, put, what);
}

/// A label of a force written 5 mm from its arrow while another label stands 1 mm from that
/// arrow (the shaper's `R₂₋₃`, with `F_и3` nearer its arrow) is away from it; laid out by the
/// placer, it is not.
#[test]
fn a_label_another_stands_nearer_the_item_of_is_away() {
    let plate = sheet("friction/friction");
    let at = in_sheet_mm(&plate);
    let force = |id, to: DVec2, text| {
        let toward = to.perp().normalize();
        let item = Item::Vector {
            from: DVec2::ZERO,
            to,
        };
        drawn(id, item, text, (to * 0.5, toward))
    };
    let steps = vec![
        force(0, at(20.0, 0.0), "R_{2-3}"),
        force(1, at(0.0, -20.0), "F_{и3}"),
    ];
    // R₂₋₃ 5 mm over the middle of its arrow, F_и3 1 mm under it.
    let put = |view: &View, text: &str, size: DVec2| {
        let middle = on_sheet(view, at(10.0, 0.0));
        let top = match text {
            "R_{2-3}" => middle.y - 5.0 - size.y,
            _ => middle.y + 1.0,
        };
        Some(DVec2::new(middle.x - size.x * 0.5, top))
    };
    let what = "“R_{2-3}”: 5.0 mm from its item, “F_{и3}” 1.0 mm from it";
    found_only_as_moved(plate, steps, put, what);
}
