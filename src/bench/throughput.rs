//! The bench's throughput rows past the methods' sweeps: the analytic kernel against its
//! peer and its floor, the recorded construction and the force analysis (`kernel`); the
//! plates, the PNGs, every scene's sheets, the whole project, the note and a batch
//! (`drawing`). Each row is the best of its runs; times are never asserted.

use super::*;

/// The kernel's rows: the analytic sweep and single angles of the four-bar and the shaper
/// (beside the `four-bar` crate's, when built with it), the floor of its math calls, the
/// recorded construction of a position, and the shaper's force analysis constructed and
/// analytic.
pub(super) fn kernel(
    four_bar: &Subject,
    shaper: &Subject,
    reps: Reps,
) -> Result<Vec<Throughput>, BenchError> {
    let mut throughput = Vec::new();
    let peer = peer::measure(four_bar, reps)?;
    for s in [four_bar, shaper] {
        let stem = &s.scene.stem;
        // Each kernel row of the four-bar beside the peer's rate of the same run.
        let against = |rate: f64| match &peer {
            Some(p) if s.scene.stem == four_bar.scene.stem => format!(
                "; {:.2}× the `four-bar` crate's positions alone, same run",
                rate / p.rate
            ),
            _ => String::new(),
        };
        let rate = sweep_rate(s, reps)?;
        throughput.push(Throughput {
            name: format!("analytic {stem}"),
            per_second: rate,
            note: format!("one position: every point and link with dX/dφ₁, d²X/dφ₁², in sweeps of a turn at {TURN_STEPS} steps (sweep, 1 core){}", against(rate)),
        });
        let rate = kernel_rate(s, reps)?;
        throughput.push(Throughput {
            name: format!("analytic {stem} (one angle)"),
            per_second: rate,
            note: format!(
                "the same, each angle solved on its own (solve_into, 1 core){}",
                against(rate)
            ),
        });
    }
    throughput.push(peer::row(peer.as_ref(), four_bar));
    throughput.push(Throughput {
        name: "math floor four-bar".into(),
        per_second: math_floor_rate(reps),
        note: "its transcendental and root calls alone: the crank's direction (cos, sin by `geom::unit_at`) + 1 sqrt".into(),
    });
    for s in [four_bar, shaper] {
        throughput.push(Throughput {
            name: format!("construction {}", s.scene.stem),
            per_second: construction_rate(s, reps)?,
            note: "one position: recorded compass construction + velocity plan + acceleration plan"
                .into(),
        });
    }
    let (constructed, analytic) = force_rates(shaper, reps)?;
    throughput.push(Throughput {
        name: format!("forces {} (construction)", shaper.scene.stem),
        per_second: constructed,
        note: "one position from its plans: the force polygons of every group and the driving link with measured arms, and Zhukovsky's lever".into(),
    });
    throughput.push(Throughput {
        name: format!("forces {} (analytic)", shaper.scene.stem),
        per_second: analytic,
        note: "one position: the loads and one linear solve of every link's equilibrium (1 core)"
            .into(),
    });
    Ok(throughput)
}

/// The drawing's rows: a plate of each kind built and written as SVG, the shaper's sheets as
/// PNG, every scene's sheets as SVG and PNG, the whole project, the note and a batch.
pub(super) fn drawing(
    opts: &BenchOptions,
    shaper: &Subject,
    four_bar: &Subject,
    reps: Reps,
) -> Result<Vec<Throughput>, BenchError> {
    let mut throughput = Vec::new();
    for &(stem, kind) in PLATES {
        let loaded;
        let s = match [shaper, four_bar]
            .into_iter()
            .find(|s| s.scene.stem == stem)
        {
            Some(s) => s,
            None => {
                loaded = Subject::load(opts, stem)?;
                &loaded
            }
        };
        throughput.push(Throughput {
            name: format!("plate {stem}/{}", kind.stem()),
            per_second: 1.0 / plate_time(s, kind, reps)?,
            note: "a fresh study::Session + sheets::build + plate::to_svg".into(),
        });
    }
    let (png_seconds, sheets) = png_time(shaper, reps)?;
    throughput.push(Throughput {
        name: format!("png {} at {PNG_DPI} dpi", shaper.scene.stem),
        per_second: 1.0 / png_seconds,
        note: format!(
            "every sheet of the scene ({sheets}), SVG → PNG in parallel, as `tmm render` writes them"
        ),
    });
    let (dxf_seconds, dxf_sheets) = dxf_time(shaper, reps)?;
    throughput.push(Throughput {
        name: format!("dxf {}", shaper.scene.stem),
        per_second: dxf_sheets as f64 / dxf_seconds,
        note: format!(
            "{:.1} ms per sheet: every sheet of the scene ({dxf_sheets}), already built, written as DXF (plate::to_dxf) on one core, as `tmm render --format dxf` does",
            dxf_seconds * 1e3 / dxf_sheets.max(1) as f64
        ),
    });
    // Every scene of the folder (a quick bench: the shaper alone), its whole set of sheets.
    let files = if opts.quick {
        vec![opts.scenes.join("shaper.toml")]
    } else {
        scene::files_in(&opts.scenes).map_err(|e| BenchError::Plate {
            scene: opts.scenes.display().to_string(),
            plate: "scenes".into(),
            detail: e.to_string(),
        })?
    };
    for file in files {
        let scene = scene::load(&file)?;
        let (seconds, sheets) = scene_time(&scene, reps)?;
        let floor = stack_floor(&scene, reps)?;
        let (parse, render) = (floor.parse_seconds(), floor.render_seconds());
        let cores = rayon::current_num_threads();
        throughput.push(Throughput {
            name: format!("scene {} (svg+png)", scene.stem),
            per_second: 1.0 / seconds,
            note: format!(
                "{:.0} ms: every sheet ({sheets}) of a fresh session as SVG and as PNG at {PNG_DPI} dpi, in memory, on all cores; usvg and resvg alone take {:.0} ms of one core (parse {:.0}, render {:.0}), {:.0} ms on {cores} core{} at best",
                seconds * 1e3,
                (parse + render) * 1e3,
                parse * 1e3,
                render * 1e3,
                floor.on(cores) * 1e3,
                if cores == 1 { "" } else { "s" }
            ),
        });
    }
    throughput.extend(waits(opts, shaper, sheets, reps)?);
    let b = batch::batch_times(opts, reps)?;
    throughput.push(Throughput {
        name: format!("batch {} × {} (png)", shaper.scene.stem, b.variants),
        per_second: 1.0 / b.seconds,
        note: format!(
            "`tmm batch` over constructions/variants/shaper.csv: every variant's sheets as PNG at {PNG_DPI} dpi and its task sheet, on all cores ({:.2} s per variant); its progress bar's {} updates drawn: {:.0} µs ({:.4} % of the batch)",
            b.seconds / b.variants as f64,
            b.variants,
            b.bar_seconds * 1e6,
            100.0 * b.bar_seconds / b.seconds
        ),
    });
    Ok(throughput)
}

/// The rows of what a student waits for: the whole project and the note from fresh
/// processes (medians), the note's composing and typesetting in this process, and the
/// typesetter's floor for a note of its length.
fn waits(
    opts: &BenchOptions,
    shaper: &Subject,
    sheets: usize,
    reps: Reps,
) -> Result<Vec<Throughput>, BenchError> {
    let ms = |s: f64| format!("{:.0} ms", s * 1e3);
    let stem = &shaper.scene.stem;
    let runs = if opts.quick { 1 } else { 7 };
    let fresh = fresh::note_and_project(shaper, &opts.scenes, runs)?;
    let n = rates::note_times(shaper, reps)?;
    let inside = format!(
        "in this process: composed {} (a fresh session, the sheets it shows, the Typst source and its figures), typeset {} (the `typst` crate: layout and PDF); Typst's floor, the note's {} characters set as plain text in its template: {}",
        ms(n.composing),
        ms(n.typesetting),
        n.chars,
        ms(n.floor)
    );
    // A command's row: its runs' medians, then what it made.
    let command = |name: &str, command: &str, w: &fresh::Waited, made: &str| Throughput {
        name: format!("{name} {stem} (fresh process)"),
        per_second: 1.0 / w.wall,
        note: format!(
            "{} of `tmm {command} constructions/{stem}.toml`: {} wall, {}{made}",
            match w.runs {
                1 => "one run".to_string(),
                k => format!("median of {k} runs"),
            },
            ms(w.wall),
            w.cpu
                .map_or("CPU not read".into(), |c| format!("{} of CPU", ms(c)))
        ),
    };
    let rows = match fresh {
        Some((note, project)) => vec![
            command(
                "project",
                "render",
                &project,
                &format!(" with `--format svg,png,pdf,note` — every sheet ({sheets}) as SVG and PNG at {PNG_DPI} dpi, the PDF set and the explanatory note"),
            ),
            command(
                "note",
                "note",
                &note,
                &format!(" ({} pages, ru, read to 0,5 mm); {inside}", n.pages),
            ),
        ],
        None => vec![Throughput {
            name: format!("note {stem}"),
            per_second: 1.0 / (n.composing + n.typesetting),
            note: format!("{} pages, ru, read to 0,5 mm (not run as a command: this process is not `tmm`); {inside}", n.pages),
        }],
    };
    Ok(rows)
}
