//! The studio's edit: every shipped scene's text made into its sheets as SVG and its report
//! ([`crate::studio::redraw`], what `tmm serve` answers to an edit, without the HTTP around
//! it), as the median of several edits.

use super::{BenchError, Reps, Throughput};
use crate::studio::{gallery, redraw, Job};

/// Edits timed per scene (a quick bench: one).
const EDITS: usize = 7;

/// One row per shipped scene: the median edit → SVG time.
pub(super) fn edit_rows(reps: Reps) -> Result<Vec<Throughput>, BenchError> {
    let n = if reps.best_of == 1 { 1 } else { EDITS };
    let mut rows = Vec::new();
    for &(stem, text) in gallery::SHIPPED {
        let job = Job {
            toml: text.to_string(),
            stem: stem.to_string(),
            lang: "ru".into(),
            drafting: crate::construct::Drafting::HAND.resolution_mm(),
        };
        let mut times = Vec::with_capacity(n);
        let mut sheets = 0;
        for _ in 0..n {
            let r = redraw(&job);
            if let Some(p) = r.problems.first() {
                return Err(BenchError::Plate {
                    scene: stem.into(),
                    plate: "studio".into(),
                    detail: p.message.clone(),
                });
            }
            sheets = r.sheets.len();
            times.push(r.ms);
        }
        times.sort_by(f64::total_cmp);
        let median = times[n / 2];
        rows.push(Throughput {
            name: format!("studio edit {stem}"),
            per_second: 1e3 / median,
            note: format!(
                "median of {n}: {median:.0} ms from the scene's text to its {sheets} sheet{} as SVG and its report (`tmm serve`'s answer to an edit, no raster)",
                if sheets == 1 { "" } else { "s" }
            ),
        });
    }
    Ok(rows)
}
