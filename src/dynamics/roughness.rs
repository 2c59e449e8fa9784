//! The roughness of a machined surface on a part drawing (ГОСТ 2.309-73 as amended in 2003):
//! the sign of a surface machined by removing material — two legs at 60° to the horizontal,
//! the short one as high as the dimension numbers (h), the long one twice that, a line
//! across them at the short one's top (the removal of material), and a shelf from the long
//! one's top with the value written over it — standing on the shelf of a leader whose arrow
//! touches the surface.

use crate::construct::{Item, Recorder, Role};
use crate::geom::{DVec2, Segment};

/// The height of the dimension numbers h, mm (ГОСТ 2.304 size 3,5): the short leg's height.
const H_MM: f64 = 3.5;
/// The long leg's height, in h (ГОСТ 2.309: 1,5 … 5).
const LONG: f64 = 2.0;
/// The sign's shelf, mm: long enough for `Ra 1,6` at h.
const SIGN_SHELF_MM: f64 = 11.0;
/// The leader's shelf beyond the sign's foot, mm.
const SHELF_MM: f64 = 4.0;

/// The roughness `value` (`Ra 1,6`) of the surface at `surface`, on a leader from there to
/// `bend` (figure mm): the leader's shelf runs from `bend` to the right, or to the left when
/// `leftward`, and the sign stands on it, its value over the sign's own shelf.
pub fn on_leader(rec: &mut Recorder, surface: DVec2, bend: DVec2, leftward: bool, value: &str) {
    let note = format!("roughness {value}");
    let leader = Item::Vector {
        from: bend,
        to: surface,
    };
    rec.draw(note.clone(), leader, Role::Dimension, &[]);
    // The sign is as wide as its legs and shelf; the leader's shelf carries it whole.
    let tan30 = 30f64.to_radians().tan();
    let width = H_MM * tan30 + LONG * H_MM * tan30 + SIGN_SHELF_MM;
    let run = width + SHELF_MM;
    let (from, to) = if leftward {
        (bend - DVec2::X * run, bend)
    } else {
        (bend, bend + DVec2::X * run)
    };
    rec.draw(
        note.clone(),
        Item::Segment(Segment::new(from, to)),
        Role::Dimension,
        &[],
    );
    // The sign's foot: its short leg's top over the leader's shelf start, clear of the bend.
    let foot = from + DVec2::new(H_MM * tan30 + SHELF_MM / 2.0, 0.0);
    let short = foot + DVec2::new(-H_MM * tan30, H_MM);
    let long = foot + DVec2::new(LONG * H_MM * tan30, LONG * H_MM);
    let shelf_end = long + DVec2::X * SIGN_SHELF_MM;
    let across = foot + DVec2::new(H_MM * tan30, H_MM);
    for (a, b) in [
        (foot, short),
        (foot, long),
        (short, across),
        (long, shelf_end),
    ] {
        rec.draw(
            note.clone(),
            Item::Segment(Segment::new(a, b)),
            Role::Dimension,
            &[],
        );
    }
    let at = (long + shelf_end) / 2.0;
    let id = rec.draw(note, Item::Text(at), Role::Dimension, &[]);
    rec.label_item(id, value, at, DVec2::Y);
}
