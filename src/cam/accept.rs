//! The base radius a student accepts from the r_min read off the drawing (issue 45): a little
//! larger than the reading, rounded UP to a whole millimetre of the real size, with a margin
//! of at least the reading's resolution (never less than a hand reading's 0,5 mm) times the
//! drawing's μ — the reading's error — and at least [`METHOD_SHARE`] of the reading — the
//! drawn points' own error: the extreme between two points, the analogues' chord error — so
//! that neither puts r₀ under the true minimum over the whole cycle. The one rule of every
//! minimum-radius construction that takes r₀ from its reading (translating, rocker, flat
//! face); the sheet says it as «Принимаем r₀ = 70 мм ≥ r_min = 69 мм». It works from the
//! reading only: the twin's exact r_min checks it.

use crate::construct::Drafting;
use crate::scale::Scale;

/// A real size within this of a whole millimetre is that millimetre, mm (the rounding of
/// the reading × μ never adds a millimetre).
const WHOLE_MM: f64 = 1e-9;

/// The least margin as a share of the r_min read: the combined diagram at the textbook's
/// 8–12 intervals of a phase reads r_min up to about 3 % under the whole cycle's (the given S
/// differentiated by chords, 12 intervals of 90°: 42,88 against 43,77 мм; a flat face's 45°
/// tangent at a drawn point of the sine law's S(S″), 12 intervals of 120°: 29,3 against
/// 30,26 мм), which this margin and the rounding up to the millimetre cover between them.
const METHOD_SHARE: f64 = 0.03;

/// r₀ accepted for r_min `read` (m) off a drawing at `mu` read at `drafting`, m.
pub(super) fn accepted(read: f64, mu: Scale, drafting: Drafting) -> f64 {
    let reading = mu.to_physical(drafting.resolution_mm().max(Drafting::HAND.resolution_mm()));
    let least = (read + reading.max(METHOD_SHARE * read)) * 1e3;
    (least - WHOLE_MM).ceil() * 1e-3
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scale::Quantity;

    fn mu(v: f64) -> Scale {
        Scale::new(v, Quantity::Length).expect("a μ")
    }

    #[test]
    fn the_reading_is_taken_up_past_its_margin_to_a_whole_millimetre() {
        // The shaper's cam: 69 mm read at μ_S = 0,001 m/mm (69,4 exact): 69 + 2,07 → 72.
        let r = accepted(0.069, mu(0.001), Drafting::HAND);
        assert!((r - 0.072).abs() < 1e-12, "{r}");
        // 42,875 read at 0,00025 m/mm: the reading's margin 0,125 would end at 43 (under the
        // exact 43,77); the method's 1,29 takes it to 45.
        let r = accepted(0.042875, mu(0.00025), Drafting::HAND);
        assert!((r - 0.045).abs() < 1e-12, "{r}");
        // A coarse drawing's margin is the reading's: 19,0 + 0,5·0,004 m = 21 mm.
        let r = accepted(0.019, mu(0.004), Drafting::HAND);
        assert!((r - 0.021).abs() < 1e-12, "{r}");
        // Read exactly, the margin is still a hand reading's; a coarser reading's is its own:
        // 10 mm read at 0,001 m/mm to 2 mm, 10 + 2 → 12.
        let r = accepted(0.010, mu(0.001), Drafting::EXACT);
        assert!((r - 0.011).abs() < 1e-12, "{r}");
        let coarse = Drafting::new(2.0).expect("a resolution");
        let r = accepted(0.010, mu(0.001), coarse);
        assert!((r - 0.012).abs() < 1e-12, "{r}");
        // Always above the reading by at least both margins, by less than a millimetre more.
        for k in 0..400 {
            let read = 0.010 + 0.000_337 * k as f64;
            let r = accepted(read, mu(0.002), Drafting::HAND);
            let margin = 0.001f64.max(0.03 * read);
            assert!(r >= read + margin - 1e-12, "{read} {r}");
            assert!(r < read + margin + 0.001 + 1e-12, "{read} {r}");
            assert!(((r * 1e3) - (r * 1e3).round()).abs() < 1e-9, "{r}");
        }
    }
}
