//! Where a ring's name goes on the scheme: beside its cup, clear of the other wheels' lines
//! and of the shafts.

use super::{overlaps, wheel_name, Room, WheelMark, BAR_MM};
use crate::gears::train::Train;
use crate::geom::DVec2;

/// Where a ring's name is tried, in order: (left of the cup, the fraction of the way up it).
const RING_NAME_PLACES: [(bool, f64); 8] = [
    (false, 0.5),
    (true, 0.5),
    (false, 0.35),
    (false, 0.65),
    (true, 0.35),
    (true, 0.65),
    (false, 0.2),
    (false, 0.8),
];
/// How clear of the other lines a ring's name is set, figure mm.
const NAME_CLEAR_MM: f64 = 1.5;

/// A ring's name goes to the first of [`RING_NAME_PLACES`] where its box, [`NAME_CLEAR_MM`]
/// about, meets no other wheel's line and no shaft (`shafts`): beside the cup's middle, level
/// with a satellite's axle or the end of a wheel inside it, it reads as theirs. Where none is
/// clear, the first.
pub(super) fn name_rings_clear(marks: &mut [WheelMark], train: &Train, shafts: &[Room]) {
    let lines: Vec<Room> = marks
        .iter()
        .map(|m| {
            let (lo, hi) = m.extent();
            let x = m.x + m.cup.unwrap_or(0.0);
            (DVec2::new(x - BAR_MM, lo), DVec2::new(x + BAR_MM, hi))
        })
        .collect();
    for (w, mark) in marks.iter_mut().enumerate() {
        if mark.cup.is_none() {
            continue;
        }
        let name = wheel_name(train, w);
        let clear = |m: &WheelMark| {
            let (lo, hi) = m.name_room(&name);
            let room = (
                lo - DVec2::splat(NAME_CLEAR_MM),
                hi + DVec2::splat(NAME_CLEAR_MM),
            );
            !(lines.iter().enumerate()).any(|(j, line)| j != w && overlaps(&room, line))
                && !shafts.iter().any(|shaft| overlaps(&room, shaft))
        };
        let place = RING_NAME_PLACES.into_iter().find(|&(left, up)| {
            (mark.name_left, mark.name_up) = (left, up);
            clear(mark)
        });
        (mark.name_left, mark.name_up) = place.unwrap_or(RING_NAME_PLACES[0]);
    }
}
