//! A word label read on into another text: a name of a curve written right over another
//! (en PZ1's detail A: «involute» over «limit point», read "involute limit point"), or
//! beside a text on its row (PZ3's «интерференция 1» 2 mm before the axis's «0», read
//! «интерференция 10»). A symbol, a number or a formula is not read on into the next line;
//! a shelf under the upper text parts the two.

use super::costs::OVER_POINT;
use super::Rect;

/// The most a word stands under the text above it and still reads as the next line of it:
/// about a line of text (en PZ1's «limit point» 2,8 mm under «involute»), mm.
const LINE_GAP_MM: f64 = 4.0;
/// Across from each other over more than this share of the shorter of the two.
const ACROSS: f64 = 0.5;
/// The most a text stands after or before a word on its row and still reads on from it:
/// a digit's width (a word space is about 1 mm at the labels' height), mm.
pub(super) const SIDE_GAP_MM: f64 = 2.5;
/// What a place costs for each word it would read on from or into, and for each text beside
/// it on its row: what covering another label's point costs.
pub(super) const STACKED: f64 = OVER_POINT;

/// Whether a label's text (its markup) is words: letters, digits, spaces and hyphens only,
/// with a word of three letters or more — a curve's name («граничная точка», «интерференция
/// 1»), not a symbol (`F_{и5}`, `O₂`), a position number or a formula.
pub(super) fn is_words(text: &str) -> bool {
    let only = text
        .chars()
        .all(|c| c.is_alphanumeric() || c == ' ' || c == '-');
    let longest = text
        .split(|c: char| !c.is_alphabetic())
        .map(|w| w.chars().count())
        .max()
        .unwrap_or(0);
    only && longest >= 3
}

/// Whether a label's text names something: it holds a letter (`H_{2}`, `S_{2}`, `P_{2}`),
/// unlike a position's or a division's number. A text right beside it on its row reads on
/// as part of the name (the slider-crank's link number «2» 2,4 mm before «S₂» read «2S₂»).
pub(super) fn is_name(text: &str) -> bool {
    text.chars().any(char::is_alphabetic)
}

/// Whether a label's text is a chain of names of one point joined by «≡» (`d_{5}′ ≡ e′ ≡
/// s_{5}′`): a symbol right after or before it on its row reads as one more name of the
/// point (the shaper's «d₅′ ≡ e′ ≡ s₅′ b₃′», b₃′ the point 10 mm away).
pub(super) fn is_chain(text: &str) -> bool {
    text.contains('≡')
}

/// Whether the text box `lower` stands right under `upper` (its top within
/// [`LINE_GAP_MM`] under `upper`'s bottom, across from it over [`ACROSS`] of the shorter).
fn under(upper: &Rect, lower: &Rect) -> bool {
    let across = upper.max.x.min(lower.max.x) - upper.min.x.max(lower.min.x);
    let shorter = upper.width().min(lower.width());
    let gap = lower.min.y - upper.max.y;
    across > ACROSS * shorter && (0.0..=LINE_GAP_MM).contains(&gap)
}

/// Whether the text box `other` stands on the row of `rect` (across from it over half the
/// lower of the two) within [`SIDE_GAP_MM`] after or before it.
pub(super) fn beside(rect: &Rect, other: &Rect) -> bool {
    let row = rect.max.y.min(other.max.y) - rect.min.y.max(other.min.y);
    let gap = (other.min.x - rect.max.x).max(rect.min.x - other.max.x);
    row > ACROSS * rect.height().min(other.height()) && (0.0..=SIDE_GAP_MM).contains(&gap)
}

/// Whether a word label at `rect` (on a shelf: `shelf`) and another word at `other` (on a
/// shelf: `other_shelf`) read as one phrase: one right under the other, the upper without
/// a shelf.
pub(super) fn read_as_one(rect: &Rect, shelf: bool, other: &Rect, other_shelf: bool) -> bool {
    (!shelf && under(rect, other)) || (!other_shelf && under(other, rect))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::DVec2;

    fn rect(x: f64, y: f64, w: f64) -> Rect {
        Rect::new(DVec2::new(x, y), DVec2::new(x + w, y + 3.7))
    }

    #[test]
    fn words_are_names_not_symbols_numbers_or_formulas() {
        for w in [
            "involute",
            "limit point",
            "граничная точка",
            "интерференция 1",
        ] {
            assert!(is_words(w), "{w}");
        }
        for s in [
            "F_{и5}",
            "O₂",
            "12",
            "7′",
            "μ_{v} = 0,004",
            "Б",
            "s_{a1} = 0",
        ] {
            assert!(!is_words(s), "{s}");
        }
    }

    /// A name reads on into a text beside it; a position's or a division's number, a row
    /// of them along an axis, does not.
    #[test]
    fn names_hold_a_letter_numbers_do_not() {
        for n in ["S_{2}", "H_{2}", "P_{2}", "b_{3}′", "O", "φ"] {
            assert!(is_name(n), "{n}");
        }
        for n in ["2", "10′", "12", "0"] {
            assert!(!is_name(n), "{n}");
        }
    }

    /// en PZ1: «involute» 2,8 mm over «limit point», right-aligned: one phrase; beside it,
    /// a line further down or on a shelf of its own: two.
    #[test]
    fn a_word_right_under_another_reads_on_from_it() {
        let upper = rect(10.0, 0.0, 14.0);
        let lower = rect(5.0, 6.5, 19.0);
        assert!(read_as_one(&upper, false, &lower, false));
        assert!(read_as_one(&lower, false, &upper, false));
        assert!(!read_as_one(&upper, true, &lower, false));
        assert!(!read_as_one(&upper, false, &rect(5.0, 9.0, 19.0), false));
        assert!(!read_as_one(&upper, false, &rect(30.0, 6.5, 19.0), false));
    }

    /// PZ3: the axis's «0» 2 mm after «интерференция 1» on its row reads on from it; 3 mm
    /// after it, or a row lower, not.
    #[test]
    fn a_text_right_after_a_word_on_its_row_reads_on_from_it() {
        let word = rect(0.0, 0.0, 30.0);
        assert!(beside(&word, &rect(32.0, 0.5, 2.0)));
        assert!(beside(&rect(32.0, 0.5, 2.0), &word));
        assert!(!beside(&word, &rect(33.0, 0.5, 2.0)));
        assert!(!beside(&word, &rect(31.0, 3.0, 2.0)));
    }
}
