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

/// A view (sheet, view) and how many rows of one key (a position, a quantity) are read on it.
type ViewCount = ((usize, usize), usize);

/// For each key (a row's position, or its quantity), how many of its rows are read on each
/// view: `keys` gives each row's key (`None`: not counted), `views` the views holding a
/// reading of its value.
fn tally<K: PartialEq>(
    keys: impl Iterator<Item = Option<K>>,
    views: &[Vec<(usize, usize)>],
) -> Vec<(K, Vec<ViewCount>)> {
    let mut out: Vec<(K, Vec<ViewCount>)> = Vec::new();
    for (key, v) in keys.zip(views) {
        let Some(key) = key.filter(|_| !v.is_empty()) else {
            continue;
        };
        let k = match out.iter().position(|(a, _)| *a == key) {
            Some(k) => k,
            None => {
                out.push((key, Vec::new()));
                out.len() - 1
            }
        };
        for view in v {
            match out[k].1.iter_mut().find(|(w, _)| w == view) {
                Some(e) => e.1 += 1,
                None => out[k].1.push((*view, 1)),
            }
        }
    }
    out
}

/// How many rows of `key` a [`tally`] counts on `view`.
fn count<K: PartialEq>(tally: &[(K, Vec<ViewCount>)], key: &K, view: (usize, usize)) -> usize {
    tally
        .iter()
        .find(|(a, _)| a == key)
        .and_then(|(_, c)| c.iter().find(|(w, _)| *w == view))
        .map_or(0, |e| e.1)
}

/// Where each row's value is read, in row order; `None` for a row computed by formula or
/// not read as one segment.
///
/// A value equal to several readings is taken from the view where most of the rows of its
/// position (or angle) are read — a position's velocities are read off that position's plan,
/// not off another plan where a vector happens to read the same; where as many are, from the
/// view whose rows are most of the row's quantity (the shaper's S at position 8 and its λ₂ at
/// B1 both read 0,46 at 0,5 mm: S is taken off the plan of positions, where the S rows are
/// read, λ₂ off the meshing picture); and within that view from the first reading in drawing
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
    let positions = tally(
        rows.iter()
            .map(|r| (r.key.at != At::Scene).then_some(&r.key.at)),
        &views,
    );
    let quantities = tally(rows.iter().map(|r| Some(r.key.symbol)), &views);
    let all_rows = tally(rows.iter().map(|_| Some(())), &views);
    // How many rows of the row's position a view reads, then what share of the rows it
    // reads are of the row's quantity.
    let score = |row: &Row, view: (usize, usize)| {
        let at = match row.key.at {
            At::Scene => 0,
            _ => count(&positions, &&row.key.at, view),
        };
        let of_kind = count(&quantities, &row.key.symbol, view) as f64;
        (at, of_kind / count(&all_rows, &(), view).max(1) as f64)
    };
    rows.iter()
        .zip(&views)
        .map(|(row, candidates)| {
            // The first of the best: `max_by` keeps the last of equals, so reversed.
            let best = candidates.iter().rev().max_by(|&&a, &&b| {
                let (a, b) = (score(row, a), score(row, b));
                a.0.cmp(&b.0).then(a.1.total_cmp(&b.1))
            })?;
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

    /// The displacement rows S of the kinematic diagrams (S(φ₁) of a slider or of the
    /// charted point) as the kinematic study gives them, and the title of the plan of
    /// positions they are read off; none for a scene without a kinematic study.
    fn diagram_s_rows(session: &Session<'_>) -> (Vec<Row>, String) {
        let Some(k) = session
            .kin_scales()
            .and_then(|sc| session.kinematics(&sc))
            .ok()
        else {
            return (Vec::new(), String::new());
        };
        let rows = k.diagrams.as_ref().map_or_else(Vec::new, |d| {
            d.rows
                .iter()
                .filter(|r| r.key.symbol == Symbol::Displacement)
                .cloned()
                .collect()
        });
        (rows, k.plan.figure.title.clone())
    }

    /// What the rows of the shipped scenes came to.
    #[derive(Default)]
    struct Counts {
        /// Rows read as one segment of a sheet.
        mapped: usize,
        /// Rows computed by formula.
        computed: usize,
        /// Graphical rows worked out from several readings, or read as zero.
        derived: usize,
        /// Plan rows (a velocity or acceleration, not zero) read as no segment.
        missed: Vec<String>,
        /// S rows of the kinematic diagrams: read as a segment of the plan of positions.
        s_mapped: usize,
        /// S rows that read zero (the start of the stroke: no segment).
        s_zero: usize,
        /// S rows not zero and read as no segment of the plan of positions.
        s_missed: Vec<String>,
        /// Other rows placed on the plan of positions, where only S is read (a value that
        /// reads the same there by chance).
        off_plan: Vec<String>,
    }

    /// Over every shipped scene, exact and read to 0,5 mm: each row matched to a reading is
    /// a segment of its sheet whose length, read under the drafting model and times its view's
    /// μ, gives the row's value back (recomputed from the sheet coordinates, not taken from
    /// the reading); a row computed by formula is matched to none; every velocity and
    /// acceleration read off a plan (a vector of the plan, not zero) is matched, and every
    /// displacement S of the kinematic diagrams (not zero) is matched to a segment of the
    /// plan of positions, where it is read — and no other row is (λ₂ at B1 of the shaper
    /// reads 0,46 as S at position 8 does).
    #[test]
    fn every_row_read_off_a_sheet_is_a_segment_of_it_giving_its_value() {
        let mut c = Counts::default();
        for &(stem, _) in gallery::SHIPPED {
            let s = gallery::scene(stem).expect("a shipped scene");
            for drafting in [Drafting::EXACT, Drafting::HAND] {
                let session = Session::new(&s, drafting);
                let plates = crate::sheets::build_all(&session, Lang::Ru).expect("sheets");
                let Ok(report) = session.report() else {
                    continue;
                };
                let (s_rows, plan_title) = diagram_s_rows(&session);
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
                    let s_row = s_rows.contains(row);
                    if !is_graphical(row) {
                        assert_eq!(at, None, "{name}");
                        c.computed += 1;
                        continue;
                    }
                    let Some(at) = at else {
                        let zero = is_zero(row.graphical, row.scale);
                        let on_plan = row.method == Method::Plan
                            && matches!(row.key.symbol, Symbol::Velocity | Symbol::Acceleration);
                        if on_plan && !zero {
                            c.missed.push(name);
                        } else if s_row && !zero {
                            c.s_missed.push(name);
                        } else if s_row {
                            c.s_zero += 1;
                        }
                        c.derived += 1;
                        continue;
                    };
                    let view = &plates[at.sheet].1.views[at.view];
                    let (a, b) = at.ends();
                    let mu = view.figure.scale.value();
                    let read = drafting.read(a.distance(b)) * mu;
                    let want = row.graphical.abs();
                    // A segment half-way between two readings (7,75 mm at 0,5 mm) reads as
                    // either once placed on the sheet: its other reading is the row's too.
                    let res = drafting.resolution_mm();
                    let tie = res > 0.0 && ((a.distance(b) / res).fract() - 0.5).abs() < 1e-6;
                    let either = [-1.0, 1.0].map(|k| (read + k * res * mu - want).abs());
                    assert!(
                        (read - want).abs() <= 1e-9 * want
                            || (tie && either.iter().any(|e| *e <= 1e-9 * want)),
                        "{name}: the segment reads {read}, the row {want}"
                    );
                    if s_row {
                        assert_eq!(view.figure.title, plan_title, "{name}: S off another view");
                        c.s_mapped += 1;
                    } else if view.figure.title == plan_title {
                        c.off_plan.push(name);
                    }
                    c.mapped += 1;
                }
            }
        }
        eprintln!(
            "rows read off a sheet as one segment: {}; computed by formula: {}; \
             graphical but worked out from readings (or read as zero): {}; \
             S of the kinematic diagrams: {} read off the plan of positions, {} zero, {} not found",
            c.mapped,
            c.computed,
            c.derived,
            c.s_mapped,
            c.s_zero,
            c.s_missed.len()
        );
        assert!(
            c.missed.is_empty(),
            "{} plan rows not found: {:#?}",
            c.missed.len(),
            c.missed
        );
        assert!(
            c.s_missed.is_empty(),
            "{} S rows not found on the plan of positions: {:#?}",
            c.s_missed.len(),
            c.s_missed
        );
        assert!(
            c.off_plan.is_empty(),
            "rows placed on the plan of positions: {:#?}",
            c.off_plan
        );
        assert!(c.mapped > 1000, "{} rows read off a sheet", c.mapped);
        // Four scenes chart a point over 12 positions, exact and at 0,5 mm: at most the
        // stroke's start reads zero in each.
        assert!(
            c.s_mapped >= 4 * 2 * 11,
            "{} S rows read off a plan",
            c.s_mapped
        );
    }
}
