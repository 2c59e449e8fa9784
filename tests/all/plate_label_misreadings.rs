//! The label-to-object rule's misreadings (issue 45) on plates built to break it: a label of
//! a point past a line from its point, a label of a force with another label nearer its
//! arrow. Each is found when written so, and not when the placer writes it.

use crate::plate_label_objects::{labels_away, labels_away_in};
use crate::plate_model::{drawn, on_sheet, sheet, with_view};
use glam::DVec2;
use tmm::construct::Item;
use tmm::plate::{layout, Plate};

/// A figure point of `plate`'s first view (which [`with_view`] copies) given in sheet mm
/// from its origin.
fn in_sheet_mm(plate: &Plate) -> impl Fn(f64, f64) -> DVec2 {
    let first = &plate.views[0];
    let per_mm = 1.0 / (on_sheet(first, DVec2::X) - on_sheet(first, DVec2::ZERO)).length();
    move |x, y| DVec2::new(x, y) * per_mm
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
    let plate = with_view(plate, steps);
    let mut l = layout(&plate);
    let broken = plate.views.len() - 1;
    let point = on_sheet(&plate.views[broken], c);
    for x in l.labels.iter_mut() {
        if x.view == broken && x.text == "c" {
            let size = x.rect.max - x.rect.min;
            x.rect.min = point + DVec2::new(3.0, -size.y * 0.5);
            x.rect.max = x.rect.min + size;
            x.leader = None;
        }
    }
    let found: Vec<String> = labels_away_in(&plate, &l)
        .into_iter()
        .map(|x| x.1)
        .collect();
    assert!(
        found
            .iter()
            .any(|w| w.contains("“c”: 3.0 mm from its point, past [drawn by the test: pb]")),
        "{found:?}"
    );
    let placed: Vec<String> = labels_away(&plate).into_iter().map(|x| x.1).collect();
    assert!(!placed.iter().any(|w| w.contains("“c”")), "{placed:?}");
}

/// A label of a force written 5 mm from its arrow while another label stands 1 mm from that
/// arrow (the shaper's `R₂₋₃`, with `F_и3` nearer its arrow) is away from it; laid out by the
/// placer, it is not.
#[test]
fn a_label_another_stands_nearer_the_item_of_is_away() {
    let plate = sheet("friction/friction");
    let at = in_sheet_mm(&plate);
    let force = |id, from: DVec2, to: DVec2, text| {
        let toward = (to - from).perp().normalize();
        drawn(
            id,
            Item::Vector { from, to },
            text,
            (from.lerp(to, 0.5), toward),
        )
    };
    let steps = vec![
        force(0, at(0.0, 0.0), at(20.0, 0.0), "R_{2-3}"),
        force(1, at(0.0, 0.0), at(0.0, -20.0), "F_{и3}"),
    ];
    let plate = with_view(plate, steps);
    let mut l = layout(&plate);
    let broken = plate.views.len() - 1;
    let view = &plate.views[broken];
    let middle = on_sheet(view, at(10.0, 0.0));
    for x in l.labels.iter_mut().filter(|x| x.view == broken) {
        let size = x.rect.max - x.rect.min;
        // R₂₋₃ 5 mm over its arrow, F_и3 1 mm under it.
        let top = match x.text.as_str() {
            "R_{2-3}" => middle.y - 5.0 - size.y,
            _ => middle.y + 1.0,
        };
        x.rect.min = DVec2::new(middle.x - size.x * 0.5, top);
        x.rect.max = x.rect.min + size;
        x.leader = None;
    }
    let found: Vec<String> = labels_away_in(&plate, &l)
        .into_iter()
        .map(|x| x.1)
        .collect();
    assert!(
        found
            .iter()
            .any(|w| w.contains("“R_{2-3}”: 5.0 mm from its item, “F_{и3}” 1.0 mm from it")),
        "{found:?}"
    );
    let here = format!("view {broken} ");
    let placed: Vec<String> = labels_away(&plate).into_iter().map(|x| x.1).collect();
    assert!(placed.iter().all(|w| !w.starts_with(&here)), "{placed:?}");
}
