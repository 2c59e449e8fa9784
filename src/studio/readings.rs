//! Where a report row's graphical value is read on the sheets: every segment a construction
//! measured ([`crate::construct::Reading`]) placed on its sheet through its view's own
//! transform ([`crate::plate::View::to_sheet`], what the SVG writer draws the view's steps
//! with), and each row matched to the reading that gave its value. A row computed by formula,
//! or one whose value is worked out from several readings, has none.

use crate::check::{is_zero, At, Row};
use crate::geom::DVec2;
use crate::plate::Plate;
use crate::scene::PlateKind;
use serde::Serialize;

/// Two values are the same reading when they differ by at most this fraction of the larger:
/// a row's graphical value is the reading itself, to the rounding of a sign or a copy.
pub const SAME_VALUE: f64 = 1e-9;

/// Where a row's value is read: the sheet and view, and the segment measured in sheet mm
/// (y down, the coordinates of the sheet's SVG `viewBox`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ReadAt {
    /// The sheet's index in the set.
    pub sheet: usize,
    /// The view's index on the sheet (`view-{k}` in the SVG).
    pub view: usize,
    /// One end of the segment, sheet mm.
    pub x1: f64,
    /// One end of the segment, sheet mm.
    pub y1: f64,
    /// The other end, sheet mm.
    pub x2: f64,
    /// The other end, sheet mm.
    pub y2: f64,
    /// The figure's μ: the value per millimetre read.
    pub mu: f64,
    /// The value read, SI.
    pub value: f64,
}

impl ReadAt {
    /// The segment's ends, sheet mm.
    pub fn ends(&self) -> (DVec2, DVec2) {
        (DVec2::new(self.x1, self.y1), DVec2::new(self.x2, self.y2))
    }
}

/// Every reading of every view of every sheet, in drawing order (sheet, view, reading).
pub fn placed(plates: &[(PlateKind, Plate)]) -> Vec<ReadAt> {
    let mut out = Vec::new();
    for (sheet, (_, plate)) in plates.iter().enumerate() {
        for (view, v) in plate.views.iter().enumerate() {
            for r in &v.figure.readings {
                let (a, b) = (v.to_sheet(r.from), v.to_sheet(r.to));
                out.push(ReadAt {
                    sheet,
                    view,
                    x1: a.x,
                    y1: a.y,
                    x2: b.x,
                    y2: b.y,
                    mu: v.figure.scale.value(),
                    value: r.value,
                });
            }
        }
    }
    out
}

/// True when `row` gives a value read off a drawing ([`Row::is_read_off`]: not computed by
/// formula nor from the construction's points).
pub fn is_graphical(row: &Row) -> bool {
    row.is_read_off()
}

/// True when the row's value is the reading's: its magnitude (a row may carry a sign the
/// drawing shows by direction) equal to the reading's value within [`SAME_VALUE`]; a zero
/// to rounding against the row's scale ([`is_zero`]) is never matched (a point read where it
/// lies shows no segment).
fn same(row: &Row, r: &ReadAt) -> bool {
    let (a, b) = (row.graphical.abs(), r.value.abs());
    a.is_finite() && !is_zero(a, row.scale) && (a - b).abs() <= SAME_VALUE * a.max(b)
}

/// A view (sheet, view) and how many rows of one position are read on it.
type ViewCount = ((usize, usize), usize);

/// Where each row's value is read, in row order; `None` for a row computed by formula or
/// not read as one segment.
///
/// A value equal to several readings is taken from the view where most of the rows of its
/// position (or angle) are read — a position's velocities are read off that position's plan,
/// not off another plan where a vector happens to read the same — and within that view from
/// the first reading in drawing order; a row of the whole scene takes the first in drawing
/// order.
pub fn read_at(rows: &[Row], plates: &[(PlateKind, Plate)]) -> Vec<Option<ReadAt>> {
    let all = placed(plates);
    // For each row, the views (sheet, view) holding a reading of its value, each once.
    let views: Vec<Vec<(usize, usize)>> = rows
        .iter()
        .map(|row| {
            let mut v: Vec<(usize, usize)> = Vec::new();
            if is_graphical(row) {
                for r in all.iter().filter(|r| same(row, r)) {
                    if !v.contains(&(r.sheet, r.view)) {
                        v.push((r.sheet, r.view));
                    }
                }
            }
            v
        })
        .collect();
    // For each position (or angle), how many of its rows are read on each view.
    let mut tally: Vec<(&At, Vec<ViewCount>)> = Vec::new();
    for (row, v) in rows.iter().zip(&views) {
        if row.key.at == At::Scene || v.is_empty() {
            continue;
        }
        let k = match tally.iter().position(|(a, _)| **a == row.key.at) {
            Some(k) => k,
            None => {
                tally.push((&row.key.at, Vec::new()));
                tally.len() - 1
            }
        };
        for view in v {
            match tally[k].1.iter_mut().find(|(w, _)| w == view) {
                Some(e) => e.1 += 1,
                None => tally[k].1.push((*view, 1)),
            }
        }
    }
    let score = |at: &At, view: (usize, usize)| match at {
        At::Scene => 0,
        at => tally
            .iter()
            .find(|(a, _)| *a == at)
            .and_then(|(_, c)| c.iter().find(|(w, _)| *w == view))
            .map_or(0, |e| e.1),
    };
    rows.iter()
        .zip(&views)
        .map(|(row, candidates)| {
            // The first of the best: `max_by_key` keeps the last of equals, so reversed.
            let best = candidates
                .iter()
                .rev()
                .max_by_key(|&&v| score(&row.key.at, v))?;
            all.iter()
                .find(|r| (r.sheet, r.view) == *best && same(row, r))
                .copied()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::{Method, Symbol};
    use crate::construct::Drafting;
    use crate::scale::Lang;
    use crate::studio::gallery;
    use crate::study::Session;

    /// Over every shipped scene, exact and read to 0,5 mm: each row matched to a reading is
    /// a segment of its sheet whose length, read under the drafting model and times its view's
    /// μ, gives the row's value back (recomputed from the sheet coordinates, not taken from
    /// the reading); a row computed by formula is matched to none; every velocity and
    /// acceleration read off a plan (a vector of the plan, not zero) is matched.
    #[test]
    fn every_row_read_off_a_sheet_is_a_segment_of_it_giving_its_value() {
        let (mut mapped, mut computed, mut derived) = (0, 0, 0);
        let mut missed: Vec<String> = Vec::new();
        for &(stem, _) in gallery::SHIPPED {
            let s = gallery::scene(stem).expect("a shipped scene");
            for drafting in [Drafting::EXACT, Drafting::HAND] {
                let session = Session::new(&s, drafting);
                let plates = crate::sheets::build_all(&session, Lang::Ru).expect("sheets");
                let Ok(report) = session.report() else {
                    continue;
                };
                let found = read_at(&report.rows, &plates);
                for (row, at) in report.rows.iter().zip(found) {
                    let name = format!(
                        "{stem} ({} mm) {} {:?} at {:?} = {}",
                        drafting.resolution_mm(),
                        row.quantity(),
                        row.method,
                        row.position(),
                        row.graphical
                    );
                    if !is_graphical(row) {
                        assert_eq!(at, None, "{name}");
                        computed += 1;
                        continue;
                    }
                    let Some(at) = at else {
                        let on_plan = row.method == Method::Plan
                            && matches!(row.key.symbol, Symbol::Velocity | Symbol::Acceleration)
                            && !is_zero(row.graphical, row.scale);
                        if on_plan {
                            missed.push(name);
                        }
                        derived += 1;
                        continue;
                    };
                    let view = &plates[at.sheet].1.views[at.view];
                    let (a, b) = at.ends();
                    let read = drafting.read(a.distance(b)) * view.figure.scale.value();
                    let want = row.graphical.abs();
                    assert!(
                        (read - want).abs() <= 1e-9 * want,
                        "{name}: the segment reads {read}, the row {want}"
                    );
                    mapped += 1;
                }
            }
        }
        eprintln!(
            "rows read off a sheet as one segment: {mapped}; computed by formula: {computed}; \
             graphical but worked out from readings (or read as zero): {derived}"
        );
        assert!(
            missed.is_empty(),
            "{} plan rows not found: {missed:#?}",
            missed.len()
        );
        assert!(mapped > 1000, "{mapped} rows read off a sheet");
    }
}
