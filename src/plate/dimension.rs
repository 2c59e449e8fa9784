//! A linear dimension's text as ГОСТ 2.307 writes it: beside its line, parallel to it,
//! readable; and where its extension lines run (the lines and arrows are drawn with the
//! items, [`super::items`]).

use super::path::Map;
use super::text::{Align, Placed, LABEL_HEIGHT_MM};
use crate::geom::DVec2;

/// Gap between a dimension line and its text, mm.
pub(crate) const DIMENSION_TEXT_GAP_MM: f64 = 1.0;

/// How far extension lines run past the dimension line, mm (ГОСТ 2.307: 1…5 mm).
const EXTENSION_PAST_MM: f64 = 2.0;

/// The extension lines of a dimension from `from` to `to` whose line is drawn `offset` off
/// them, as drawn: from each point to [`EXTENSION_PAST_MM`] past the dimension line; none
/// when the line runs through the points.
pub(crate) fn extension_lines(from: DVec2, to: DVec2, offset: f64) -> Vec<(DVec2, DVec2)> {
    let Some(u) = (to - from).try_normalize() else {
        return Vec::new();
    };
    if offset == 0.0 {
        return Vec::new();
    }
    let n = u.perp();
    let beyond = n * (EXTENSION_PAST_MM * offset.signum());
    vec![
        (from, from + n * offset + beyond),
        (to, to + n * offset + beyond),
    ]
}

/// Where a dimension text is written beside its line: `along` mm from the middle of the
/// dimension line in the text's reading direction, over the line or under it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct TextSpot {
    /// Distance from the middle of the dimension line, along it, mm.
    pub along: f64,
    /// Under the line (as read) instead of over it.
    pub under: bool,
}

impl TextSpot {
    /// Over the middle of the line: ГОСТ 2.307's place.
    pub(crate) const MIDDLE: TextSpot = TextSpot {
        along: 0.0,
        under: false,
    };
}

/// The dimension text at `spot` beside the dimension line, parallel to it, readable, its box
/// (subscripts included) [`DIMENSION_TEXT_GAP_MM`] clear of it.
pub(crate) fn dimension_text(
    map: Map,
    (from, to, offset): (DVec2, DVec2, f64),
    text: &str,
    spot: TextSpot,
) -> Option<Placed> {
    let u = (to - from).try_normalize()?;
    let mid = map.pt((from + to) * 0.5 + u.perp() * offset);
    let s = map.dir(u);
    let mut deg = s.y.atan2(s.x).to_degrees();
    // ГОСТ 2.307: horizontal texts read left to right, vertical ones bottom to top.
    if deg >= 90.0 {
        deg -= 180.0;
    } else if deg < -90.0 {
        deg += 180.0;
    }
    let (sin, cos) = deg.to_radians().sin_cos();
    let (read, up) = (DVec2::new(cos, sin), DVec2::new(sin, -cos));
    let mut placed = Placed::new(mid, text, LABEL_HEIGHT_MM, Align::Middle);
    placed.rotate = deg;
    // The text's box keeps the gap from the line: over it, the baseline (or the foot of a
    // subscript); under it, the capitals' top.
    let own = placed.own_box();
    let lift = if spot.under {
        -(DIMENSION_TEXT_GAP_MM - own.min.y)
    } else {
        DIMENSION_TEXT_GAP_MM + own.max.y.max(0.0)
    };
    placed.at = mid + up * lift + read * spot.along;
    Some(placed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dimension_text_is_readable_and_above_its_line() {
        let text = |dim: (DVec2, DVec2, f64), s: &str, spot: TextSpot| {
            dimension_text(Map::figure(DVec2::ZERO), dim, s, spot).expect("a text")
        };
        let (o, x50) = (DVec2::ZERO, DVec2::new(50.0, 0.0));
        let t = text((x50, o, 10.0), "50", TextSpot::MIDDLE);
        // Right to left with the offset below: the text still reads left to right, above.
        assert_eq!(t.rotate, 0.0);
        assert!((t.at.x - 25.0).abs() < 1e-9, "{:?}", t.at);
        assert!((t.bounds().max.y - 9.0).abs() < 1e-9, "{:?}", t.bounds());
        let v = text((o, DVec2::new(0.0, 40.0), 5.0), "40", TextSpot::MIDDLE);
        assert_eq!(v.rotate, -90.0);
        // Slid along and written under the line: the capitals' top the gap under it.
        let spot = TextSpot {
            along: 7.0,
            under: true,
        };
        let under = text((x50, o, 10.0), "50", spot);
        let b = under.bounds();
        assert!((under.at.x - 32.0).abs() < 1e-9, "{:?}", under.at);
        assert!(
            (b.min.y - (10.0 + DIMENSION_TEXT_GAP_MM)).abs() < 1e-9,
            "{b:?}"
        );
        // A subscript's foot keeps the gap over the line too.
        let z = text((o, x50, 0.0), "z_{1}", TextSpot::MIDDLE).bounds();
        assert!((z.max.y + DIMENSION_TEXT_GAP_MM).abs() < 1e-9, "{z:?}");
    }

    #[test]
    fn a_dimension_text_stays_in_the_room_its_item_keeps_for_it() {
        // The figure's bounds keep DIMENSION_TEXT_ROOM_MM over a dimension line
        // (`Item::bounding_points`): the text written there, subscript and all, fits it.
        let room = crate::construct::DIMENSION_TEXT_ROOM_MM;
        let (o, x50) = (DVec2::ZERO, DVec2::new(50.0, 0.0));
        let texts = [
            "a_{w}",
            "r_{min} = 15,2 мм",
            "H_{2}",
            "d^{2}S/dφ^{2}",
            "[ρ] = 10 мм",
        ];
        for s in texts {
            let t = dimension_text(Map::figure(DVec2::ZERO), (o, x50, 0.0), s, TextSpot::MIDDLE)
                .expect("a text");
            // The figure's y is down on the sheet: the text stands at negative y.
            let top = -t.bounds().min.y;
            assert!(top <= room, "{s}: its top {top} mm over the line");
        }
    }
}
