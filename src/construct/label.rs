//! A step's label and what it names: a point of the figure, or the drawn item itself.
//!
//! The distinction decides how a sheet writes it. Names of one point are joined as the
//! textbook writes them, `p ≡ b₃ ≡ d`; a label of a line, a vector or an arc names a
//! quantity (a force, an arm, a couple), and two quantities that happen to be drawn at one
//! place are two labels, never `R₁₋₂ ≡ R₂₋₃` (issue 45).

use super::item::Item;
use crate::geom::{DVec2, Rect};

/// A digit of a number written as a label is about this wide at the labels' type (4,8 mm
/// boxes), sheet mm: what a drawing reserves for a number it places itself (a diagram's
/// position numbers on its φ axis).
pub const DIGIT_MM: f64 = 3.1;
/// Half a label's box across its line at the labels' type, sheet mm.
pub const HALF_BOX_MM: f64 = 2.4;
/// A number a drawing places beside its point on an axis stands at most this far across from
/// it, sheet mm, and on each side at most half the way to the next point less
/// [`NUMBER_CLEAR_MM`]: nearer its own point than the next.
pub const NUMBER_SIDE_MM: f64 = 3.0;
/// See [`NUMBER_SIDE_MM`], sheet mm.
pub const NUMBER_CLEAR_MM: f64 = 1.0;

/// The box a number `text` written as a label centred at `middle` takes, grown by `clear`
/// each way, mm: what a drawing tests against its lines before it writes the number there.
pub fn number_box(middle: DVec2, text: &str, clear: f64) -> Rect {
    let width = DIGIT_MM * text.chars().count() as f64;
    let half = DVec2::new(0.5 * width, HALF_BOX_MM) + clear;
    Rect::new(middle - half, middle + half)
}

/// A label's anchor this close to a point of its item is at that point, mm (figure mm: the
/// anchor is computed from the same numbers as the point, so only rounding parts them).
const AT_POINT_MM: f64 = 1e-6;

/// What a label names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Names {
    /// The point at its anchor: a marked point, a pair, a slider block's centre, the image
    /// at the head of a plan's ray, a pole. Names of coincident points are written as one.
    Point,
    /// Its step's item: a line, a vector, an arc, a circle, a curve, a free text. Written
    /// beside it and never joined with another label.
    Item,
}

impl Names {
    /// What a label anchored at `anchor` on `item` names when its construction does not say:
    /// a label of a point, a pair or a block, or one at an end of a line or vector (a plan's
    /// image, a position's pin) names that point; any other names the item (a force
    /// polygon's side labelled at its middle, an arm, a couple's arc).
    pub fn of(item: &Item, anchor: DVec2) -> Names {
        let at = |p: DVec2| p.distance(anchor) <= AT_POINT_MM;
        let point = match item {
            Item::Point(_) | Item::Joint { .. } | Item::Slider { .. } => true,
            Item::Segment(s) | Item::Guide { segment: s, .. } => at(s.from) || at(s.to),
            Item::Vector { from, to } => at(*from) || at(*to),
            _ => false,
        };
        if point {
            Names::Point
        } else {
            Names::Item
        }
    }
}

/// A textbook label. `text` uses the label markup: `_x` or `_{xy}` for a subscript,
/// `^x` or `^{xy}` for a superscript (`b_3`, `S_{3}`, `a^{k}`, `8′`).
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    /// The text, in label markup.
    pub text: String,
    /// The point the label belongs to.
    pub anchor: DVec2,
    /// Preferred direction from the anchor to the text (unit or zero for centred on the anchor).
    pub toward: DVec2,
    /// What it names: the point at `anchor` or its step's item.
    pub names: Names,
    /// The farthest the text may stand from its point, sheet mm (the nearest edge of its
    /// box): a point of a dense picture (the pole P among the teeth and circles of a
    /// meshing) keeps its name beside it, struck by a thin line rather than flown off to
    /// where no line runs; `None`: wherever the placer finds the most room.
    pub within_mm: Option<f64>,
    /// The farthest the text's middle may stand left and right of its point, sheet mm (its
    /// x): a division point's number on a diagram's φ axis stays in its point's column,
    /// nearer its point than the next — written over a line there rather than beside the
    /// next point, and never on a leader; `None`: no such bound.
    pub column_mm: Option<[f64; 2]>,
}

impl Label {
    /// A label of `item` anchored at `anchor`, naming what [`Names::of`] says.
    pub fn on(item: &Item, text: impl Into<String>, anchor: DVec2, toward: DVec2) -> Label {
        Label {
            text: text.into(),
            anchor,
            toward,
            names: Names::of(item, anchor),
            within_mm: None,
            column_mm: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::{Arc, Segment};

    #[test]
    fn a_label_at_a_point_names_it_and_one_along_a_line_names_the_line() {
        let (a, b) = (DVec2::new(1.0, 2.0), DVec2::new(11.0, 2.0));
        let v = Item::Vector { from: a, to: b };
        assert_eq!(Names::of(&v, b), Names::Point);
        assert_eq!(Names::of(&v, a), Names::Point);
        assert_eq!(Names::of(&v, a.lerp(b, 0.5)), Names::Item);
        let s = Item::Segment(Segment::new(a, b));
        assert_eq!(Names::of(&s, b + DVec2::new(0.0, 0.01)), Names::Item);
        assert_eq!(Names::of(&Item::Point(a), a + DVec2::X), Names::Point);
        let arc = Item::Angle(Arc {
            center: a,
            radius: 9.0,
            start: 0.0,
            sweep: 1.0,
        });
        assert_eq!(Names::of(&arc, a), Names::Item);
        assert_eq!(Names::of(&Item::Text(a), a), Names::Item);
    }
}
