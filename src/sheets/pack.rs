//! Laying views, texts and tables out on as many sheets as they need: each item goes to the
//! highest, then leftmost, free place of the current sheet, a place at most `LEVEL_MM` lower
//! counting as level (inside the frame, clear of the title block and the designation box, a
//! gap from everything placed); an item that fits
//! nowhere after the last one there takes a gap before it when it is no item of a series, and
//! starts a further sheet only when the page has no room for it at all. Items keep the order they are given in, so a sheet
//! reads like the textbook's: the plan of positions first, then the plans, diagrams, tables.
//! The items of a series (the velocity plans 1 … 12 with 8′ in its place) go in rows: each
//! to the right of the one before, on its row (level with it, or lower — not below its middle —
//! where a drawing placed before the series reaches into the row), or at the start of a new row
//! under it — never back into a gap left of an earlier one, so they read in their order.

use crate::construct::fit::overflow;
use crate::geom::DVec2;
use crate::plate::{Rect, Sheet, FIELD_MARGIN_MM as MARGIN_MM, ITEM_GAP_MM as GAP_MM};

/// The free space of one sheet and what is placed on it.
#[derive(Debug, Clone)]
struct Page {
    area: Rect,
    taken: Vec<Rect>,
    /// Where the first item goes: the frame's left edge under the designation box (a strip
    /// left of it would collect stray small items out of their order).
    first: DVec2,
    /// The top-left corner of the last item placed: the next one goes after it in reading
    /// order (lower, or level with it and to its right), so the plans follow their numbers.
    last: Option<DVec2>,
    /// The row of the series being placed: its series, its last item, and the lowest edge of
    /// its items on the row.
    row: Option<Row>,
}

/// The current row of a series of items on a page.
#[derive(Debug, Clone, Copy)]
struct Row {
    series: u8,
    last: Rect,
    bottom: f64,
}

impl Row {
    /// Whether a corner continues the row: to the right of its last item, its top level with
    /// the last item's or lower, but not below the last item's middle, so that the two still
    /// read side by side (lower where a drawing placed before reaches into the row); and no
    /// item of `taken` between the last item and an item `height` tall there, so that a row
    /// does not run on across another drawing (the plan of positions).
    fn continues(&self, c: DVec2, height: f64, taken: &[Rect]) -> bool {
        let (top, bottom) = (
            c.y.max(self.last.min.y),
            (c.y + height).min(self.last.max.y),
        );
        c.x >= self.last.max.x - EPS_MM
            && c.y >= self.last.min.y - EPS_MM
            && c.y <= (self.last.min.y + self.last.max.y) * 0.5 + EPS_MM
            && !taken.iter().any(|t| {
                t.min.x < c.x - EPS_MM
                    && t.max.x > self.last.max.x + EPS_MM
                    && t.min.y < bottom
                    && t.max.y > top
            })
    }

    /// A corner where the next item of the row's series may go: on its row
    /// ([`Row::continues`]), or under the whole row.
    fn allows(&self, c: DVec2, height: f64, taken: &[Rect]) -> bool {
        self.continues(c, height, taken) || c.y >= self.bottom + GAP_MM - EPS_MM
    }
}

/// Two places whose tops differ by less than this read as level: the left one is taken, mm.
const LEVEL_MM: f64 = 10.0;

/// Slack of the comparisons, mm.
const EPS_MM: f64 = 1e-9;

impl Page {
    fn new(sheet: &Sheet) -> Self {
        let f = sheet.frame();
        let m = DVec2::splat(MARGIN_MM);
        let area = Rect::new(f.min + m, f.max - m);
        let boxed = sheet.designation_box();
        Page {
            area,
            taken: vec![sheet.title_block(), boxed],
            first: DVec2::new(area.min.x, boxed.max.y + GAP_MM),
            last: None,
            row: None,
        }
    }

    fn free(&self, r: &Rect) -> bool {
        self.area.inflate(EPS_MM).contains(r)
            && self
                .taken
                .iter()
                .all(|t| !r.inflate(GAP_MM - EPS_MM).intersects(t))
    }

    /// The highest, then leftmost, free place of `size` after the last item; an item of a
    /// `series` with a row on the page goes on that row as far left as it can (nearest the
    /// last one, then as high), else starts a new row under it at the highest, then leftmost,
    /// place. Candidates are the area's corner and the corners just past each taken rectangle.
    fn place(&mut self, size: DVec2, series: Option<u8>) -> Option<Rect> {
        self.place_from(size, series, true)
    }

    /// [`Page::place`], or with `in_order` false anywhere the page has room, highest then
    /// leftmost, the reading position left where it was: an item that the page holds only in
    /// a gap before its last item goes there rather than alone onto a further sheet.
    fn place_from(&mut self, size: DVec2, series: Option<u8>, in_order: bool) -> Option<Rect> {
        let mut xs = vec![self.area.min.x];
        let mut ys = vec![self.area.min.y];
        for t in &self.taken {
            xs.push(t.max.x + GAP_MM);
            ys.push(t.max.y + GAP_MM);
        }
        xs.sort_by(f64::total_cmp);
        ys.sort_by(f64::total_cmp);
        let row = self.row.filter(|r| Some(r.series) == series);
        let after = |c: &DVec2| {
            !in_order
                || self.last.is_none_or(|l| {
                    c.y > l.y + EPS_MM || (c.y >= l.y - EPS_MM && c.x > l.x + EPS_MM)
                }) && row.is_none_or(|r| r.allows(*c, size.y, &self.taken))
        };
        let mut grid: Vec<DVec2> = ys
            .iter()
            .flat_map(|&y| xs.iter().map(move |&x| DVec2::new(x, y)))
            .filter(after)
            .collect();
        if let Some(r) = row {
            // On the row first, nearest the last item; the new row's places keep their order
            // (the sort is stable).
            let on = |c: &DVec2| r.continues(*c, size.y, &self.taken);
            grid.sort_by(|a, b| match (on(a), on(b)) {
                (true, true) => a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)),
                (true, false) => std::cmp::Ordering::Less,
                (false, true) => std::cmp::Ordering::Greater,
                (false, false) => std::cmp::Ordering::Equal,
            });
        }
        let start = self.last.is_none().then_some(self.first);
        let mut free = start
            .into_iter()
            .chain(grid)
            .map(|c| Rect::new(c, c + size))
            .filter(|r| self.free(r));
        let first = free.next()?;
        // Off a series' row, a place as high within LEVEL_MM and further left reads first
        // (the English friction sheet's case 4 went right of the row for 2 mm of height,
        // and cases 5 and 6 before it at the left).
        let r = if row.is_some() {
            first
        } else {
            free.take_while(|r| r.min.y <= first.min.y + LEVEL_MM)
                .fold(first, |a, r| if r.min.x < a.min.x { r } else { a })
        };
        let on_row = row.is_some_and(|w| w.continues(r.min, size.y, &self.taken));
        self.taken.push(r);
        if !in_order {
            return Some(r);
        }
        self.last = Some(r.min);
        self.row = series.map(|series| match row {
            Some(w) if on_row => Row {
                series,
                last: r,
                bottom: w.bottom.max(r.max.y),
            },
            _ => Row {
                series,
                last: r,
                bottom: r.max.y,
            },
        });
        Some(r)
    }
}

/// Where each item went: its sheet (0-based) and its rectangle (sheet mm, y down).
pub(super) type Placement = (usize, Rect);

/// Lay out items of the given sizes (mm) on sheets of format `sheet`, in order; the item `k`
/// of the series `series[k]` (if any; a missing entry is none) in that series' rows.
/// `Err(k)` names the first item that does not fit even an empty sheet.
pub(super) fn pack(
    sheet: &Sheet,
    sizes: &[DVec2],
    series: &[Option<u8>],
) -> Result<Vec<Placement>, usize> {
    let mut pages = vec![Page::new(sheet)];
    let mut out = Vec::with_capacity(sizes.len());
    for (k, &size) in sizes.iter().enumerate() {
        let of = series.get(k).copied().flatten();
        let last = pages.len() - 1;
        if let Some(r) = pages[last].place(size, of) {
            out.push((last, r));
            continue;
        }
        // An item outside a series (a text, a table, a diagram) fills a gap of the page
        // before a further sheet is begun.
        if of.is_none() {
            if let Some(r) = pages[last].place_from(size, None, false) {
                out.push((last, r));
                continue;
            }
        }
        let mut page = Page::new(sheet);
        let r = page.place(size, of).ok_or(k)?;
        pages.push(page);
        out.push((last + 1, r));
    }
    Ok(out)
}

/// How much lower than its plan ends a caption of a row is written, at most, to stand on
/// the line of the row's lowest caption, mm.
const CAPTION_LEVEL_MM: f64 = 10.0;

/// For each placement, how far its caption goes down to stand level with the lowest of its
/// row's (a row of a series whose tops are level): where its plan ends at most
/// [`CAPTION_LEVEL_MM`] higher and nothing placed is in the way; else 0. The plans stay
/// where they are.
pub(super) fn caption_drops(
    sheet: &Sheet,
    placed: &[Placement],
    series: &[Option<u8>],
) -> Vec<f64> {
    let of = |k: usize| series.get(k).copied().flatten();
    let mut drops = vec![0.0; placed.len()];
    let mut k = 0;
    while k < placed.len() {
        let (page, first) = placed[k];
        let level = |j: usize| {
            of(j) == of(k)
                && placed[j].0 == page
                && (placed[j].1.min.y - first.min.y).abs() < EPS_MM
        };
        let end = (k + 1..placed.len())
            .find(|&j| !level(j))
            .unwrap_or(placed.len());
        let bottom = (placed[k..end].iter()).fold(f64::MIN, |m, p| m.max(p.1.max.y));
        if of(k).is_some() && end - k > 1 {
            for j in k..end {
                let r = placed[j].1;
                let drop = bottom - r.max.y;
                // The page with everything placed on it but this plan.
                let mut others = Page::new(sheet);
                (others.taken).extend(
                    (placed.iter().enumerate())
                        .filter_map(|(i, p)| (i != j && p.0 == page).then_some(p.1)),
                );
                let longer = Rect::new(r.min, r.max + DVec2::new(0.0, drop));
                if drop > EPS_MM && drop <= CAPTION_LEVEL_MM && others.free(&longer) {
                    drops[j] = drop;
                }
            }
        }
        k = end;
    }
    drops
}

/// The largest rectangles an empty sheet of format `sheet` has free (beside or above the
/// title block, below or beside the designation box): an item fits an empty sheet when it
/// fits one of them.
pub(super) fn rooms(sheet: &Sheet) -> [DVec2; 4] {
    let p = Page::new(sheet);
    let (a, tb, d) = (p.area, sheet.title_block(), sheet.designation_box());
    let below_box = d.max.y + GAP_MM;
    let right_of_box = d.max.x + GAP_MM;
    let above_tb = tb.min.y - GAP_MM;
    let left_of_tb = tb.min.x - GAP_MM;
    [
        DVec2::new(a.max.x - a.min.x, above_tb - below_box),
        DVec2::new(left_of_tb - a.min.x, a.max.y - below_box),
        DVec2::new(a.max.x - right_of_box, above_tb - a.min.y),
        DVec2::new(left_of_tb - right_of_box, a.max.y - a.min.y),
    ]
}

/// How much an item of `size` overflows an empty sheet (≤ 1: it fits).
pub(super) fn sheet_overflow(sheet: &Sheet, size: DVec2) -> f64 {
    rooms(sheet)
        .iter()
        .map(|&r| overflow(size, r))
        .fold(f64::INFINITY, f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn a1() -> Sheet {
        Sheet::default()
    }

    #[test]
    fn items_fill_rows_and_spill_onto_a_further_sheet() {
        let s = a1();
        let sizes = vec![DVec2::new(300.0, 200.0); 7];
        let placed = pack(&s, &sizes, &[]).expect("fits");
        // Two rows of two on the first A1 sheet (the title block takes the bottom right).
        assert_eq!(placed.iter().filter(|p| p.0 == 0).count(), 4);
        assert!(placed.iter().any(|p| p.0 == 1));
        for (i, a) in placed.iter().enumerate() {
            let f = s.frame();
            assert!(a.1.min.x >= f.min.x && a.1.max.x <= f.max.x);
            assert!(a.1.min.y >= f.min.y && a.1.max.y <= f.max.y);
            for b in &placed[i + 1..] {
                let apart = a.0 != b.0
                    || a.1.max.x <= b.1.min.x
                    || b.1.max.x <= a.1.min.x
                    || a.1.max.y <= b.1.min.y
                    || b.1.max.y <= a.1.min.y;
                assert!(apart, "{a:?} overlaps {b:?}");
            }
        }
    }

    #[test]
    fn a_series_reads_in_rows_and_never_goes_back_into_a_gap() {
        let s = a1();
        // A tall item, then plans of varying height: without rows a short plan would drop
        // into the gap under a shorter one before it, left of the plans already placed.
        let mut sizes = vec![DVec2::new(300.0, 400.0)];
        let heights = [
            60.0, 120.0, 50.0, 90.0, 40.0, 110.0, 70.0, 60.0, 100.0, 50.0,
        ];
        sizes.extend(heights.iter().map(|&h| DVec2::new(110.0, h)));
        let series: Vec<Option<u8>> = std::iter::once(None)
            .chain(heights.iter().map(|_| Some(0)))
            .collect();
        let placed = pack(&s, &sizes, &series).expect("fits");
        let plans: Vec<Rect> = placed[1..].iter().map(|p| p.1).collect();
        let mut rows = 0;
        for w in plans.windows(2) {
            let (a, b) = (w[0], w[1]);
            let right = (b.min.y - a.min.y).abs() < 1e-9 && b.min.x > a.max.x;
            // A new row starts under every plan of the row before.
            let row_bottom = plans
                .iter()
                .filter(|p| (p.min.y - a.min.y).abs() < 1e-9)
                .map(|p| p.max.y)
                .fold(f64::MIN, f64::max);
            assert!(right || b.min.y >= row_bottom, "{a:?} then {b:?}");
            rows += usize::from(!right);
        }
        assert!(rows >= 1, "{plans:?}");
        // Without the series the same items fill a gap out of order.
        let free = pack(&s, &sizes, &[]).expect("fits");
        assert!(free[1..]
            .windows(2)
            .any(|w| w[1].1.min.y > w[0].1.min.y && w[1].1.min.y < w[0].1.max.y));
    }

    /// The v-engine's first sheet: a structural scheme and a plan of positions, then twelve
    /// plans 130 × 150 mm. The third plan starts a row under the scheme; the fourth goes on
    /// right beside it, under the plan of positions that reaches into the row, not across
    /// it at the far right; all twelve fit the sheet.
    #[test]
    fn a_row_goes_on_under_a_drawing_that_reaches_into_it() {
        let s = a1();
        let mut sizes = vec![DVec2::new(215.0, 70.0), DVec2::new(305.0, 210.0)];
        sizes.extend([DVec2::new(130.0, 150.0); 12]);
        let series: Vec<Option<u8>> = (0..sizes.len()).map(|k| (k >= 2).then_some(0)).collect();
        let placed = pack(&s, &sizes, &series).expect("fits");
        assert!(placed.iter().all(|p| p.0 == 0), "{placed:?}");
        let (plan, third, fourth) = (placed[1].1, placed[4].1, placed[5].1);
        assert!(third.max.x < plan.min.x, "{third:?} beside {plan:?}");
        assert!(
            (fourth.min.x - (third.max.x + GAP_MM)).abs() < 1e-9,
            "{fourth:?}"
        );
        assert!(
            fourth.min.y >= plan.max.y + GAP_MM - 1e-9,
            "{fourth:?} under {plan:?}"
        );
        assert!(fourth.min.y > third.min.y && fourth.min.y < third.max.y);
    }

    /// Two drawings side by side, the right one 10 mm shorter: the next item goes under the
    /// left one, not under the right one 10 mm higher, so that it reads after both.
    #[test]
    fn a_place_almost_as_high_and_further_left_reads_first() {
        let s = a1();
        let sizes = [
            DVec2::new(400.0, 200.0),
            DVec2::new(350.0, 192.0),
            DVec2::new(300.0, 50.0),
        ];
        let placed = pack(&s, &sizes, &[]).expect("fits");
        let (left, right, next) = (placed[0].1, placed[1].1, placed[2].1);
        assert!(
            right.min.x > left.max.x && right.min.y == left.min.y,
            "{right:?}"
        );
        assert_eq!(next.min.x, left.min.x, "{next:?}");
        assert!(
            (next.min.y - (left.max.y + GAP_MM)).abs() < 1e-9,
            "{next:?}"
        );
        // 12 mm higher is no longer level: the place under the right one is taken.
        let taller = [sizes[0], DVec2::new(350.0, 188.0 - LEVEL_MM), sizes[2]];
        let placed = pack(&s, &taller, &[]).expect("fits");
        assert_eq!(placed[2].1.min.x, placed[1].1.min.x, "{placed:?}");
    }

    /// The captions of a row whose plans end within 10 mm of its lowest go down to its line;
    /// a plan 30 mm shorter keeps its caption under it, and one with a drawing under it in
    /// the way keeps its own. No plan moves.
    #[test]
    fn nearly_level_captions_of_a_row_are_set_level() {
        let s = a1();
        let sizes = [100.0, 94.0, 70.0, 92.0].map(|h| DVec2::new(110.0, h));
        let series = [Some(0); 4];
        let placed = pack(&s, &sizes, &series).expect("fits");
        assert!(placed
            .iter()
            .all(|p| (p.1.min.y - placed[0].1.min.y).abs() < 1e-9));
        let drops = caption_drops(&s, &placed, &series);
        assert_eq!(drops, vec![0.0, 6.0, 0.0, 8.0], "{placed:?}");
        // A short item under the fourth plan, 3 mm below its end: its caption stays.
        let mut blocked = placed.clone();
        let r = placed[3].1;
        let low = DVec2::new(r.min.x, r.max.y + GAP_MM + 3.0);
        blocked.push((0, Rect::new(low, low + DVec2::new(50.0, 20.0))));
        let drops = caption_drops(&s, &blocked, &series);
        assert_eq!(drops, vec![0.0, 6.0, 0.0, 0.0, 0.0]);
    }

    #[test]
    fn nothing_goes_over_the_title_block() {
        let s = a1();
        let tb = s.title_block();
        let placed = pack(&s, &vec![DVec2::new(100.0, 100.0); 30], &[]).expect("fits");
        for (page, r) in placed {
            let clear = r.max.x <= tb.min.x || r.max.y <= tb.min.y;
            assert!(clear, "page {page}: {r:?}");
        }
    }

    #[test]
    fn an_item_larger_than_a_sheet_is_named() {
        let s = a1();
        let sizes = [DVec2::new(100.0, 100.0), DVec2::new(900.0, 100.0)];
        assert_eq!(pack(&s, &sizes, &[]), Err(1));
        assert!(sheet_overflow(&s, DVec2::new(900.0, 100.0)) > 1.0);
        assert!(sheet_overflow(&s, DVec2::new(600.0, 500.0)) <= 1.0);
        // Every room really is free on an empty sheet.
        for r in rooms(&s) {
            assert!(pack(&s, &[r - DVec2::splat(1e-6)], &[]).is_ok(), "{r:?}");
        }
    }
}
