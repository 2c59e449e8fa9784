//! A department's class in one run (`tmm batch` over thousands of variants): the four-bar's
//! grid and the shaper's cycled to 3 000 and 1 000 variants (30 and 10 in a quick bench),
//! each variant's sheets as SVG and its task sheet, and the peak memory of the run beside
//! that of a tenth of the class — a batch holds a few variants at a time, whatever the count.

use super::{BenchError, BenchOptions};
use crate::batch;
use crate::construct::Drafting;
use crate::render::{Formats, Options};
use crate::scale::Lang;
use std::time::Instant;

/// What one class measured.
pub(super) struct ClassRun {
    /// The template's name.
    pub scene: String,
    /// Variants drawn (the grid's rows cycled, each named anew).
    pub variants: usize,
    /// Variants not drawn (their diagnoses).
    pub failed: usize,
    /// Seconds for the class.
    pub seconds: f64,
    /// Peak resident memory of the class's run, MB (`None` without `/proc`).
    pub peak_mb: Option<f64>,
    /// The same for a tenth of the class.
    pub tenth_peak_mb: Option<f64>,
}

/// The resident memory's high-water mark of this process, MB, after which it is reset (Linux:
/// `VmHWM` of `/proc/self/status`, reset by writing 5 to `/proc/self/clear_refs`).
fn peak_mb_reset() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let kb: f64 = status
        .lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))?
        .trim()
        .trim_end_matches("kB")
        .trim()
        .parse()
        .ok()?;
    std::fs::write("/proc/self/clear_refs", "5").ok()?;
    Some(kb / 1000.0)
}

/// The rows of `grid` (a variant grid's text) cycled to `n` rows named `c00001`, ….
fn cycled(grid: &str, n: usize) -> String {
    let mut lines = grid.lines().filter(|l| !l.trim().is_empty());
    let header = lines.next().unwrap_or_default();
    let rows: Vec<&str> = lines.collect();
    let mut out = format!("{header}\n");
    for (k, row) in rows.iter().cycle().take(n).enumerate() {
        let rest = row.split_once(',').map_or("", |(_, rest)| rest);
        out += &format!("c{:05},{rest}\n", k + 1);
    }
    out
}

/// The class of `scene` (`<scenes>/<scene>.toml`, grid `<scenes>/variants/<scene>.csv`)
/// cycled to `n` variants, drawn as SVG into a scratch folder (removed after): a tenth of
/// it, then all of it, each run's peak memory read.
pub(super) fn class_run(
    opts: &BenchOptions,
    scene: &str,
    n: usize,
) -> Result<ClassRun, BenchError> {
    let fail = |detail: String| BenchError::Plate {
        scene: scene.into(),
        plate: "class".into(),
        detail,
    };
    let template = opts.scenes.join(format!("{scene}.toml"));
    let grid = opts.scenes.join("variants").join(format!("{scene}.csv"));
    let read = |p: &std::path::Path| crate::scene::read(p).map_err(|e| fail(e.to_string()));
    let (text, rows) = (read(&template)?, read(&grid)?);
    let options = Options {
        lang: Lang::Ru,
        drafting: Drafting::EXACT,
        formats: Formats {
            svg: true,
            png: false,
            pdf: false,
            note: false,
            dxf: false,
        },
        dpi: super::PNG_DPI,
    };
    let out = std::env::temp_dir().join(format!("tmm-bench-class-{}", std::process::id()));
    let draw = |count: usize| -> Result<(usize, f64, Option<f64>), BenchError> {
        let variants = batch::read_grid(&text, &cycled(&rows, count), &grid)
            .map_err(|e| fail(e.to_string()))?;
        peak_mb_reset();
        let start = Instant::now();
        let outcomes = batch::run(&variants, &template, &out, &options, &[], &|_| {});
        let seconds = start.elapsed().as_secs_f64();
        let _ = std::fs::remove_dir_all(&out);
        let failed = outcomes.iter().filter(|o| o.result.is_err()).count();
        Ok((failed, seconds, peak_mb_reset()))
    };
    let (_, _, tenth_peak_mb) = draw((n / 10).max(1))?;
    let (failed, seconds, peak_mb) = draw(n)?;
    Ok(ClassRun {
        scene: scene.into(),
        variants: n,
        failed,
        seconds,
        peak_mb,
        tenth_peak_mb,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_grid_is_cycled_with_new_names() {
        let g = cycled("variant,a\n01,1\n02,2\n\n", 5);
        assert_eq!(
            g,
            "variant,a\nc00001,1\nc00002,2\nc00003,1\nc00004,2\nc00005,1\n"
        );
    }
}
