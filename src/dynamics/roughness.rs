//! The roughness of a machined surface on a part drawing (ГОСТ 2.309-73 as amended in 2003):
//! the sign of a surface machined by removing material — two legs at 60° to the horizontal,
//! the short one as high as the dimension numbers (h), the long one twice that, a line
//! across them at the short one's top (the removal of material), and a shelf from the long
//! one's top with the value written over it — standing on the shelf of a leader whose arrow
//! touches the surface.

use crate::construct::{Item, Recorder, Role};
use crate::geom::{Arc, Circle, DVec2, Segment};
use std::f64::consts::PI;

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

/// How much larger the sign of the other surfaces is than a surface's own (ГОСТ 2.309: about
/// one and a half times).
const OTHER_SCALE: f64 = 1.5;
/// The radius of the brackets round the basic sign, mm, and the half angle they span.
const BRACKET_MM: f64 = 6.0;
const BRACKET_HALF_DEG: f64 = 30.0;
/// The basic sign's short leg inside the brackets, mm.
const BASIC_MM: f64 = 2.5;
/// Between the sign and the first bracket, and between a bracket and the basic sign, mm.
const GAP_MM: f64 = 1.5;

/// The roughness of every surface a cast part's drawing does not mark (ГОСТ 2.309, the
/// sheet's top right corner): they stay as cast — the sign of a surface made without
/// removing material (its legs, a circle inscribed between them), at [`OTHER_SCALE`] times a
/// surface's sign, then the basic sign in brackets: «the others so, the marked ones as
/// marked». Figure mm, the sign's foot at (0, 0).
pub fn other_surfaces(rec: &mut Recorder) {
    let note = "roughness of the other surfaces: as cast";
    let tan30 = 30f64.to_radians().tan();
    let h = H_MM * OTHER_SCALE;
    let long = DVec2::new(LONG * h * tan30, LONG * h);
    let mut lines = vec![
        (DVec2::ZERO, DVec2::new(-h * tan30, h)),
        (DVec2::ZERO, long),
    ];
    // The basic sign, its legs only, between the brackets, all centred on the sign's
    // mid-height: a bracket is the arc of BRACKET_MM at ±BRACKET_HALF_DEG.
    let half = BRACKET_HALF_DEG.to_radians();
    let bulge = BRACKET_MM * (1.0 - half.cos());
    let left = long.x + GAP_MM;
    let (short_w, long_w) = (BASIC_MM * tan30, LONG * BASIC_MM * tan30);
    let basic = DVec2::new(left + bulge + GAP_MM + short_w, h - BASIC_MM);
    let right = basic.x + long_w + GAP_MM + bulge;
    lines.push((basic, basic + DVec2::new(-short_w, BASIC_MM)));
    lines.push((basic, basic + DVec2::new(long_w, LONG * BASIC_MM)));
    for (a, b) in lines {
        rec.draw(
            note,
            Item::Segment(Segment::new(a, b)),
            Role::Dimension,
            &[],
        );
    }
    // The circle inscribed in the legs' triangle of height h.
    let circle = Circle {
        center: DVec2::new(0.0, 2.0 * h / 3.0),
        radius: h / 3.0,
    };
    rec.draw(note, Item::Circle(circle), Role::Dimension, &[]);
    // "(" bulges left of its centre, ")" right of its.
    let brackets = [
        (DVec2::new(left + BRACKET_MM, h), PI - half),
        (DVec2::new(right - BRACKET_MM, h), -half),
    ];
    for (center, start) in brackets {
        let arc = Arc {
            center,
            radius: BRACKET_MM,
            start,
            sweep: 2.0 * half,
        };
        rec.draw(note, Item::Arc(arc), Role::Dimension, &[]);
    }
}
