//! The instructor's batch (`tmm batch`): the shipped shaper grid drawn as `tmm batch
//! --format png` draws it — every variant's sheets as PNG and its task sheet, on all cores —
//! and the progress bar's own cost: as many updates as the batch makes, drawn to a terminal
//! that discards them.

use super::{best_time, BenchError, BenchOptions, Reps};
use crate::batch;
use crate::construct::Drafting;
use crate::render::{Formats, Options};
use crate::scale::Lang;
use indicatif::{ProgressDrawTarget, TermLike};
use std::path::Path;
use std::time::Instant;

/// The variants drawn by a quick bench (the full bench draws the whole grid).
const QUICK_VARIANTS: usize = 2;

/// A terminal that takes every drawing of the bar and keeps none of it.
#[derive(Debug)]
struct Sink;

impl TermLike for Sink {
    fn width(&self) -> u16 {
        100
    }
    fn move_cursor_up(&self, _: usize) -> std::io::Result<()> {
        Ok(())
    }
    fn move_cursor_down(&self, _: usize) -> std::io::Result<()> {
        Ok(())
    }
    fn move_cursor_right(&self, _: usize) -> std::io::Result<()> {
        Ok(())
    }
    fn move_cursor_left(&self, _: usize) -> std::io::Result<()> {
        Ok(())
    }
    fn write_line(&self, s: &str) -> std::io::Result<()> {
        std::hint::black_box(s);
        Ok(())
    }
    fn write_str(&self, s: &str) -> std::io::Result<()> {
        std::hint::black_box(s);
        Ok(())
    }
    fn clear_line(&self) -> std::io::Result<()> {
        Ok(())
    }
    fn flush(&self) -> std::io::Result<()> {
        Ok(())
    }
}

/// What the batch bench measured.
pub(super) struct BatchTimes {
    /// Seconds to draw the variants.
    pub seconds: f64,
    /// Seconds the progress bar's updates took, drawn.
    pub bar_seconds: f64,
    /// Variants drawn.
    pub variants: usize,
}

/// The shaper grid of `opts.scenes` (`shaper.toml`, `variants/shaper.csv`) drawn into a
/// scratch folder (removed after), best of `reps`; and the bar's updates timed on their own.
pub(super) fn batch_times(opts: &BenchOptions, reps: Reps) -> Result<BatchTimes, BenchError> {
    let fail = |detail: String| BenchError::Plate {
        scene: "shaper".into(),
        plate: "batch".into(),
        detail,
    };
    let template = opts.scenes.join("shaper.toml");
    let grid = opts.scenes.join("variants").join("shaper.csv");
    let read = |p: &Path| crate::scene::read(p).map_err(|e| fail(e.to_string()));
    let mut variants = batch::read_grid(&read(&template)?, &read(&grid)?, &grid)
        .map_err(|e| fail(e.to_string()))?;
    if reps.best_of == 1 {
        variants.truncate(QUICK_VARIANTS);
    }
    let options = Options {
        lang: Lang::Ru,
        drafting: Drafting::EXACT,
        formats: Formats {
            svg: false,
            png: true,
            pdf: false,
            note: false,
            dxf: false,
        },
        dpi: super::PNG_DPI,
    };
    let out = std::env::temp_dir().join(format!("tmm-bench-batch-{}", std::process::id()));
    let seconds = best_time(reps.best_of.min(2), || {
        let outcomes = batch::run(&variants, &template, &out, &options, &[], &|_| {});
        match outcomes.iter().find_map(|o| o.result.as_ref().err()) {
            Some(why) => Err(fail(why.clone())),
            None => Ok(outcomes.len()),
        }
    });
    let _ = std::fs::remove_dir_all(&out);
    let seconds = seconds?;
    let bar = batch::progress_bar(
        variants.len(),
        ProgressDrawTarget::term_like(Box::new(Sink)),
    );
    let start = Instant::now();
    for v in &variants {
        bar.set_message(v.name.clone());
        bar.inc(1);
    }
    bar.finish_and_clear();
    Ok(BatchTimes {
        seconds,
        bar_seconds: start.elapsed().as_secs_f64(),
        variants: variants.len(),
    })
}
