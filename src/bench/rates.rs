//! Throughput: analytic positions, the floor of their math calls, constructed positions and
//! plates per second.

use super::{best_time, BenchError, Reps, Subject, CONSTRUCTION_EXTENT_MM};
use crate::construct::{Context, Drafting, Recorder};
use crate::linkage::{self, kin_plan, PlanKind, PlanSetup, Pose};
use crate::render::{self, RenderError};
use crate::scale::{Lang, Quantity, Scale};
use crate::scene::{PlateKind, Scene};
use crate::sheets;
use crate::study::Session;
use std::f64::consts::TAU;
use std::hint::black_box;
use std::path::{Path, PathBuf};

/// Analytic positions per second (positions with both analogues), each angle solved on its
/// own.
pub(super) fn kernel_rate(s: &Subject, reps: Reps) -> Result<f64, BenchError> {
    let mut pose = Pose::default();
    s.prog
        .solve_into(0.0, false, &mut pose)
        .map_err(|u| s.fail(u.detail))?;
    per_angle_rate(s, reps, |phi| {
        s.prog.solve_into(phi, true, &mut pose)?;
        black_box(&pose);
        Ok(())
    })
    .map_err(|u: linkage::Unassembled| s.fail(u.detail))
}

/// Calls per second of `solve` at crank angles stepping by 0.1° in the crank's own sense (the
/// angle kept within one turn), `reps.kernel` calls a timing.
pub(super) fn per_angle_rate<E>(
    s: &Subject,
    reps: Reps,
    mut solve: impl FnMut(f64) -> Result<(), E>,
) -> Result<f64, E> {
    let count = reps.kernel.max(1);
    let step = s.crank_angle(TAU / TURN_STEPS as f64);
    let t = best_time(reps.best_of.max(3), || {
        let mut phi = 0.0f64;
        for _ in 0..count {
            phi += step;
            if phi.abs() >= TAU {
                phi = 0.0;
            }
            solve(black_box(phi))?;
        }
        Ok(())
    })?;
    Ok(count as f64 / t)
}

/// Crank positions of a turn in the kernel's rows: 0.1° steps, for a sweep and for the
/// angles solved one at a time alike.
pub(super) const TURN_STEPS: usize = 3600;

/// Analytic positions per second (positions with both analogues) by sweeps of one crank turn
/// at 0.1° steps ([`crate::linkage::Program::sweep`]: continuity kept, the crank's direction
/// turned from one step to the next), as many turns as make up the count.
pub(super) fn sweep_rate(s: &Subject, reps: Reps) -> Result<f64, BenchError> {
    let turns = reps.kernel.div_ceil(TURN_STEPS);
    let step = s.crank_angle(TAU / TURN_STEPS as f64);
    let mut pose = Pose::default();
    let t = best_time(reps.best_of.max(3), || {
        for _ in 0..turns {
            s.prog.sweep((0.0, step), TURN_STEPS, &mut pose, |_, p| {
                black_box(p);
            })?;
        }
        Ok(())
    })
    .map_err(|u: linkage::Unassembled| s.fail(u.detail))?;
    Ok((turns * TURN_STEPS) as f64 / t)
}

/// The floor under the four-bar's kernel: its one transcendental step (the crank's cos and
/// sin, [`crate::geom::unit_at`], as the kernel takes them) and its one square root (the RRR
/// group's t, twice the triangle's area) per second;
/// link angles are carried as unit vectors and the links' lengths are known, so no atan2,
/// acos or further root remains.
pub(super) fn math_floor_rate(reps: Reps) -> f64 {
    let count = reps.kernel.max(1);
    let step = TAU / 3600.0;
    best_time(reps.best_of.max(3), || {
        let mut phi = 0.0f64;
        for _ in 0..count {
            phi += step;
            let e = crate::geom::unit_at(black_box(phi));
            black_box((e.x * e.y + 1.5).sqrt());
        }
        Ok::<_, ()>(())
    })
    .map_or(f64::NAN, |t| count as f64 / t)
}

/// Constructed positions (with velocity and acceleration plans) per second.
pub(super) fn construction_rate(s: &Subject, reps: Reps) -> Result<f64, BenchError> {
    let count = reps.constructed.max(1);
    let mu_l = s.scene.scale_l.map_or(0.002, |m| m.value());
    let r1 = s.mechanism.crank.length;
    let w = s.w1.abs();
    let scale = |v: f64, q| Scale::new(v, q).ok_or_else(|| s.fail(format!("bad scale {v}")));
    let mu = scale(mu_l, Quantity::Length)?;
    let mu_v = scale(w * r1 / 50.0, Quantity::Velocity)?;
    let mu_a = scale(w * w * r1 / 50.0, Quantity::Acceleration)?;
    let ctx = Context::for_model_size(CONSTRUCTION_EXTENT_MM, Drafting::EXACT)?;
    let t = best_time(reps.best_of, || {
        let mut prev = None;
        for k in 0..count {
            let phi = s.crank_angle(k as f64 * TAU / count as f64);
            let mut rec = Recorder::in_context("bench", mu, &ctx);
            let built = s
                .prog
                .construct(&mut rec, phi, prev.as_ref(), "bench")
                .map_err(|f| s.fail(format!("group {}: {}", f.group + 1, f.error)))?;
            let setup = PlanSetup {
                prog: &s.prog,
                built: &built,
                mu_l: mu,
                w1: s.w1,
                ctx,
            };
            let plan_err = |(g, e)| s.fail(format!("plan, group {}: {e}", g + 1));
            let vp = kin_plan(&setup, PlanKind::Velocity, mu_v, None).map_err(plan_err)?;
            let ap = kin_plan(&setup, PlanKind::Acceleration, mu_a, Some(&vp)).map_err(plan_err)?;
            black_box((&vp, &ap, rec));
            prev = Some(built);
        }
        Ok::<_, BenchError>(())
    })?;
    Ok(count as f64 / t)
}

/// Seconds to build a plate and write it as SVG.
pub(super) fn plate_time(s: &Subject, kind: PlateKind, reps: Reps) -> Result<f64, BenchError> {
    best_time(reps.best_of, || {
        // A fresh session each run: the time includes every construction the sheet needs.
        let session = Session::new(&s.scene, Drafting::EXACT);
        let plates = sheets::build(&session, kind, Lang::Ru)?;
        Ok(plates.iter().map(crate::plate::to_svg).collect::<Vec<_>>())
    })
    .map_err(|e: sheets::BuildError| BenchError::Plate {
        scene: s.scene.stem.clone(),
        plate: kind.stem().into(),
        detail: e.to_string(),
    })
}

/// PNG resolution of the scene timing, dots per inch (the `render` default).
pub(super) const PNG_DPI: u32 = 150;

/// Seconds to turn every sheet of a scene, already written as SVG, into PNG at
/// [`PNG_DPI`], the sheets in parallel — what `tmm render` spends on PNGs — and the number
/// of sheets.
pub(super) fn png_time(s: &Subject, reps: Reps) -> Result<(f64, usize), BenchError> {
    let svgs = sheet_svgs(&s.scene)?;
    best_time(reps.best_of.min(3), || {
        crate::plate::to_png_dpi_all(&svgs, PNG_DPI as f32)
            .into_iter()
            .collect::<Result<Vec<_>, _>>()
    })
    .map(|t| (t, svgs.len()))
    .map_err(|e| png_error(&s.scene, e))
}

/// Seconds to write every sheet of a scene, already built, as DXF ([`crate::plate::to_dxf`])
/// on one core, and the number of sheets.
pub(super) fn dxf_time(s: &Subject, reps: Reps) -> Result<(f64, usize), BenchError> {
    let plates = render::plates(&s.scene, Lang::Ru, Drafting::EXACT)
        .map_err(|e| render_error(&s.scene, e))?;
    best_time(reps.best_of.min(3), || {
        plates
            .iter()
            .map(|(_, p)| crate::plate::to_dxf(p))
            .collect::<Result<Vec<_>, _>>()
    })
    .map(|t| (t, plates.len()))
    .map_err(|e| BenchError::Plate {
        scene: s.scene.stem.clone(),
        plate: "dxf".into(),
        detail: e.to_string(),
    })
}

/// Every sheet of `scene` (a fresh session) as SVG.
fn sheet_svgs(scene: &Scene) -> Result<Vec<String>, BenchError> {
    let plates =
        render::plates(scene, Lang::Ru, Drafting::EXACT).map_err(|e| render_error(scene, e))?;
    Ok(plates
        .iter()
        .map(|(_, p)| crate::plate::to_svg(p))
        .collect())
}

/// A sheet of `scene` that cannot be parsed or rasterised, as the bench's error.
fn png_error(scene: &Scene, e: crate::plate::PlateError) -> BenchError {
    BenchError::Plate {
        scene: scene.stem.clone(),
        plate: "png".into(),
        detail: e.to_string(),
    }
}

/// Seconds to build every sheet of `scene` (a fresh session) and write each as SVG and as
/// PNG at [`PNG_DPI`] — `tmm render --format svg,png` in memory ([`render::files`]), the
/// files but not written — and the number of sheets.
pub(super) fn scene_time(scene: &Scene, reps: Reps) -> Result<(f64, usize), BenchError> {
    let formats = render::Formats {
        svg: true,
        png: true,
        ..render::Formats::default()
    };
    let mut pngs = 0;
    let t = best_time(reps.best_of.min(3), || {
        let files = rendered(scene, formats)?;
        pngs = files
            .iter()
            .filter(|(p, _)| p.extension().is_some_and(|e| e == "png"))
            .count();
        Ok(files)
    })
    .map_err(|e| render_error(scene, e))?;
    Ok((t, pngs))
}

/// The rendering stack's own share of a scene's PNGs at [`PNG_DPI`]: for each sheet, seconds of
/// one core to parse its SVG (usvg, its text laid out) and to render it (resvg), each the best
/// of its runs. No change of ours goes below it: the pixels are theirs.
pub(super) fn stack_floor(scene: &Scene, reps: Reps) -> Result<StackFloor, BenchError> {
    let png = |e| png_error(scene, e);
    let mut sheets = Vec::new();
    for svg in sheet_svgs(scene)? {
        let parse = || crate::plate::ParsedSvg::new(&svg);
        let parse_seconds = best_time(reps.best_of.min(3), parse).map_err(png)?;
        let parsed = parse().map_err(png)?;
        let render_seconds = best_time(reps.best_of.min(3), || {
            crate::plate::render_only(&parsed, PNG_DPI as f32)
        })
        .map_err(png)?;
        sheets.push((parse_seconds, render_seconds));
    }
    Ok(StackFloor { sheets })
}

/// What usvg and resvg alone spend on a scene's sheets, one core ([`stack_floor`]).
#[derive(Debug, Clone)]
pub(super) struct StackFloor {
    /// Each sheet's (parse, render) seconds.
    pub sheets: Vec<(f64, f64)>,
}

impl StackFloor {
    /// Parsing every sheet, seconds of one core.
    pub fn parse_seconds(&self) -> f64 {
        self.sheets.iter().map(|s| s.0).sum()
    }

    /// Rendering every sheet, seconds of one core.
    pub fn render_seconds(&self) -> f64 {
        self.sheets.iter().map(|s| s.1).sum()
    }

    /// The least a scene's PNGs can take on `cores` cores: the whole shared out evenly, or
    /// the largest sheet, which one core renders alone, whichever is longer.
    pub fn on(&self, cores: usize) -> f64 {
        let largest = self.sheets.iter().map(|s| s.0 + s.1).fold(0.0, f64::max);
        ((self.parse_seconds() + self.render_seconds()) / cores.max(1) as f64).max(largest)
    }
}

/// Every file `tmm render` makes of `scene` in `formats` at [`PNG_DPI`], in memory.
fn rendered(
    scene: &Scene,
    formats: render::Formats,
) -> Result<Vec<(PathBuf, Vec<u8>)>, RenderError> {
    let options = render::Options {
        lang: Lang::Ru,
        drafting: Drafting::EXACT,
        formats,
        dpi: PNG_DPI,
    };
    render::files(std::slice::from_ref(scene), Path::new("bench"), &options)
}

/// A scene's sheets that cannot be built, as the bench's error.
fn render_error(scene: &Scene, e: RenderError) -> BenchError {
    let (plate, detail) = match e {
        RenderError::Build { kind, error, .. } => (kind.stem().into(), error.to_string()),
        e => ("png".into(), e.to_string()),
    };
    BenchError::Plate {
        scene: scene.stem.clone(),
        plate,
        detail,
    }
}

/// The force route of `s` at its first analysed position: (constructed, analytic) positions
/// per second. Constructed: the force polygons of every group and the driving link and
/// Zhukovsky's lever, from the position's plans (built once, outside the timing). Analytic:
/// the loads and one linear solve of every link's equilibrium, at positions around the turn.
pub(super) fn force_rates(s: &Subject, reps: Reps) -> Result<(f64, f64), BenchError> {
    let study = |e: crate::study::StudyError| s.fail(e.to_string());
    let forces = |e: crate::forces::ForceError| s.fail(e.to_string());
    let session = Session::new(&s.scene, Drafting::EXACT);
    let spec = session.force_spec("the bench").map_err(study)?;
    let sc = session.kin_scales().map_err(study)?;
    let k = *session
        .force_positions()
        .map_err(study)?
        .first()
        .ok_or_else(|| s.fail("no position to analyse"))?;
    let plan = session.positions(sc.l).map_err(study)?;
    let vel = session.velocity(&sc, k).map_err(study)?;
    let vp = vel.plan().ok_or_else(|| s.fail("no velocity plan"))?;
    let ap = session.acceleration(&sc, k).map_err(study)?;
    let ctx = Context::for_model_size(CONSTRUCTION_EXTENT_MM, Drafting::EXACT)?;
    let count = reps.constructed.max(1);
    let constructed = best_time(reps.best_of, || {
        for _ in 0..count {
            black_box(crate::forces::analyse(
                spec, &plan, k, sc.l, vp, &ap.plan, s.w1, &ctx,
            )?);
        }
        Ok(())
    })
    .map_err(forces)?;
    let poses = s.poses(360)?;
    let analytic = best_time(reps.best_of, || {
        for pose in &poses {
            let motion = crate::forces::PositionMotion::analytic(pose, s.w1);
            let loads = crate::forces::loads(spec, &s.prog, &motion, Some(true))?;
            black_box(crate::forces::solve_twin(
                &s.prog,
                pose,
                &loads,
                &spec.drive,
                s.w1.signum(),
            )?);
        }
        Ok(())
    })
    .map_err(forces)?;
    Ok((count as f64 / constructed, poses.len() as f64 / analytic))
}

/// The explanatory note of `s` in this process, best of the runs (each as cold as a fresh
/// process: [`super::best_time`] empties the typesetter's memo).
pub(super) struct NoteTimes {
    /// Composed, s: a fresh session, the sheets whose views it shows, the Typst source with
    /// its figures.
    pub composing: f64,
    /// Typeset, s: layout and PDF.
    pub typesetting: f64,
    /// Typeset, s, of the note's text set plain in its template ([`crate::note::plain_twin`]):
    /// the typesetter's floor for a note of this length.
    pub floor: f64,
    /// Pages of the note.
    pub pages: usize,
    /// Characters of its text.
    pub chars: usize,
}

/// The note of `s` alone, composed and typeset ([`NoteTimes`]) — what `tmm note` adds to
/// the sheets.
pub(super) fn note_times(s: &Subject, reps: Reps) -> Result<NoteTimes, BenchError> {
    let failed = |detail: String| BenchError::Plate {
        scene: s.scene.stem.clone(),
        plate: "note".into(),
        detail,
    };
    let compose = || {
        let session = Session::new(&s.scene, Drafting::HAND);
        crate::note::compose(&session, Lang::Ru).map_err(|e| e.to_string())
    };
    let composing = best_time(reps.best_of.min(3), compose).map_err(failed)?;
    let note = compose().map_err(failed)?;
    let typeset = |note: &crate::note::Note| {
        best_time(reps.best_of.min(3), || {
            crate::note::to_pdf(note).map_err(|e| e.to_string())
        })
    };
    let typesetting = typeset(&note).map_err(failed)?;
    let plain = crate::note::plain_twin(&note).map_err(|e| failed(e.to_string()))?;
    let floor = typeset(&plain).map_err(failed)?;
    let text = crate::note::to_text(&note).map_err(|e| failed(e.to_string()))?;
    Ok(NoteTimes {
        composing,
        typesetting,
        floor,
        pages: text.matches(crate::note::PAGE_BREAK).count(),
        chars: text
            .chars()
            .filter(|&c| c != crate::note::PAGE_BREAK)
            .count(),
    })
}

#[cfg(test)]
mod tests {
    use super::StackFloor;

    #[test]
    fn the_floor_is_the_even_share_or_the_largest_sheet() {
        let two = StackFloor {
            sheets: vec![(0.010, 0.030), (0.005, 0.015)],
        };
        assert!((two.parse_seconds() - 0.015).abs() < 1e-15);
        assert!((two.render_seconds() - 0.045).abs() < 1e-15);
        // One core does it all; two cannot beat the first sheet, which one of them draws.
        assert!((two.on(1) - 0.060).abs() < 1e-15);
        assert!((two.on(2) - 0.040).abs() < 1e-15);
        let seven = StackFloor {
            sheets: vec![(0.01, 0.03); 7],
        };
        assert!((seven.on(2) - 0.14).abs() < 1e-12);
        assert!((seven.on(0) - 0.28).abs() < 1e-12);
    }
}
