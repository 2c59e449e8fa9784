//! `tmm bench`: speed against error. Each method's resolution is swept and its error against
//! the analytic twin is put beside its time; whole computations are timed as throughput.
//!
//! * **Chord method** — the displacement of the shaper's ram (point `E`, along x) and the
//!   four-bar's rocker angle (link 3) are charted over one crank turn at N equal steps from
//!   the analytic positions and differentiated twice by chords
//!   ([`Derivation::Chords`](crate::calculus::Derivation::Chords), drafting exact). The
//!   abscissa is the angle the crank has turned through (it grows with time whatever the sense
//!   of ω₁), so the analogues turn into velocities and accelerations with |ω₁| and |ω₁|² and
//!   compare, signs included, with the analytic ω₁·dX/dφ₁ and ω₁²·d²X/dφ₁² at the nodes.
//! * **Analytic kernel** — positions with their first and second analogues on one core, by
//!   sweeps of a crank turn ([`Program::sweep`]) and each angle on its own
//!   ([`Program::solve_into`]); built with the `peer` feature, the `four-bar` crate's
//!   positions on the same crank-rocker beside them, with the ratio.
//! * **Construction route** — the recorded compass construction of a position with its
//!   velocity and acceleration plans.
//! * **Force route** — one position's force polygons and Zhukovsky's lever from its plans,
//!   against the analytic twin's loads and linear solve.
//! * **Cam inversion** — seed 000's cam profiled by inversion at N = 12 … 720 intervals per
//!   rise and return: the drawn profile's deviation from the exact envelope (falls as N⁻²)
//!   beside the time of the recorded inversion.
//! * **Plates** — building a plate and writing it as SVG; a scene's plates (already SVG)
//!   rasterised to PNG at 150 dpi, as `tmm render` does; the same plates written as DXF,
//!   the cost per sheet.
//!
//! * **Flywheel** — the shaper's flywheel (seed 000 §5) by Wittenbauer's tangents and by
//!   Mertsalov's route on diagrams of N = 12 … 360 positions, each against the energy equation
//!   integrated exactly, with the route's time and the exact solve's.
//! * **Rack generation** — the drawn tooth's deviation from the exact envelope (in modules)
//!   and the time of one tooth for N = 12 … 720 rack positions.
//! * **Class** — `tmm batch` over the four-bar's grid cycled to 3 000 variants and the
//!   shaper's to 1 000 (30 and 10 in a quick bench), with the run's peak memory beside a tenth
//!   of the class's.
//! * **Studio** — every shipped scene's edit in `tmm serve`: its text to its sheets as SVG and
//!   its report, the median of 7 edits.
//! * **Batch** — `tmm batch` over the shipped shaper grid (30 variants; 2 in a quick bench),
//!   every sheet as PNG, and its progress bar's updates timed on their own.
//!
//! Times are the best of several repetitions (the machine may be busy); they are reported,
//! never asserted.

mod batch;
mod cam;
mod chords;
mod class;
mod flywheel;
mod fresh;
mod peer;
mod plot;
mod rack;
mod rates;
#[cfg(test)]
pub(crate) mod sample;
mod studio;
mod table;
mod throughput;

use crate::calculus::CalculusError;
use crate::geom::InvalidTolerance;
use crate::linkage::{Pose, Program};
use crate::scale::Quantity;
use crate::scene::{self, PlateKind, Scene};
use chords::{chord_rows, Charted, Coord};
use rates::{
    construction_rate, dxf_time, force_rates, kernel_rate, math_floor_rate, plate_time, png_time,
    scene_time, stack_floor, sweep_rate, PNG_DPI, TURN_STEPS,
};
use std::f64::consts::TAU;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;
use thiserror::Error;

pub use table::{Bench, BenchRow, Throughput};

/// The resolutions of the chord-method sweep (positions per crank turn).
pub const CHORD_RESOLUTIONS: [usize; 6] = [12, 24, 48, 96, 192, 360];

/// The plates timed, by scene stem: one line per plate, each as `tmm render` writes it
/// (the shaper's plan of positions is on its kinematics sheet).
const PLATES: &[(&str, PlateKind)] = &[
    ("shaper", PlateKind::Kinematics),
    ("shaper", PlateKind::Forces),
    ("shaper", PlateKind::Cam),
];

/// Largest extent of a chord-method figure (the diagram and its pole), mm: the size its
/// tolerances are derived from.
const DIAGRAM_EXTENT_MM: f64 = 400.0;
/// Largest extent of a constructed position with its plans, mm.
const CONSTRUCTION_EXTENT_MM: f64 = 1000.0;

/// What to run.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchOptions {
    /// The folder holding `shaper.toml` and `four-bar.toml`.
    pub scenes: PathBuf,
    /// Small repetition counts: checks the structure and the errors in well under a second
    /// of timing, the times themselves are rough.
    pub quick: bool,
    /// Only the studio's edit rows (`tmm bench --studio`): nothing else is run.
    pub studio: bool,
}

impl Default for BenchOptions {
    fn default() -> Self {
        Self {
            scenes: PathBuf::from("constructions"),
            quick: false,
            studio: false,
        }
    }
}

/// Why the bench cannot run.
#[derive(Debug, Error)]
pub enum BenchError {
    /// A scene file cannot be used.
    #[error(transparent)]
    Scene(#[from] scene::SceneError),
    /// A mechanism cannot be compiled or solved.
    #[error("{scene}: {detail}")]
    Linkage {
        /// The scene stem.
        scene: String,
        /// What failed.
        detail: String,
    },
    /// A graphical differentiation failed.
    #[error("{scene}, chord method at N = {n}: {source}")]
    Calculus {
        /// The scene stem.
        scene: String,
        /// Positions per turn.
        n: usize,
        /// The diagnostic.
        source: CalculusError,
    },
    /// No tolerances can be derived for a figure of the given size.
    #[error("tolerances: {0}")]
    Tolerance(#[from] InvalidTolerance),
    /// A plate cannot be built.
    #[error("{scene}: plate `{plate}`: {detail}")]
    Plate {
        /// The scene stem.
        scene: String,
        /// The plate stem.
        plate: String,
        /// What failed.
        detail: String,
    },
}

/// Repetition counts.
#[derive(Debug, Clone, Copy)]
struct Reps {
    /// Repetitions of a timing (the best is kept).
    best_of: usize,
    /// Chord diagrams per timing.
    diagrams: usize,
    /// Analytic positions per timing.
    kernel: usize,
    /// Constructed positions (with both plans) per timing.
    constructed: usize,
}

impl Reps {
    fn new(quick: bool) -> Self {
        if quick {
            Self {
                best_of: 1,
                diagrams: 1,
                kernel: 20_000,
                constructed: 12,
            }
        } else {
            Self {
                best_of: 5,
                diagrams: 3,
                kernel: 2_000_000,
                constructed: 120,
            }
        }
    }
}

/// The best (least) wall time of `best_of` runs of `f`, seconds. Each run starts as a fresh
/// process does, with no image ([`crate::plate::to_png_dpi`]) and no typeset layout kept (a
/// blocking contour is kept by the session that traced it, and each run makes its own).
fn best_time<T, E>(best_of: usize, mut f: impl FnMut() -> Result<T, E>) -> Result<f64, E> {
    let mut best = f64::INFINITY;
    for _ in 0..best_of.max(1) {
        crate::plate::forget_pngs();
        // Nor the typesetter's memo, which would lay out a note again in a tenth of the time.
        comemo::evict(0);
        let t = Instant::now();
        black_box(f()?);
        best = best.min(t.elapsed().as_secs_f64());
    }
    Ok(best)
}

/// A loaded scene with its compiled program and signed crank speed.
struct Subject {
    scene: Scene,
    mechanism: crate::linkage::Mechanism,
    prog: Program,
    /// ω₁, rad/s, counter-clockwise positive.
    w1: f64,
}

impl Subject {
    fn load(opts: &BenchOptions, stem: &str) -> Result<Self, BenchError> {
        let scene = scene::load(&opts.scenes.join(format!("{stem}.toml")))?;
        let linkage = |detail: String| BenchError::Linkage {
            scene: stem.into(),
            detail,
        };
        let mechanism = scene
            .mechanism
            .clone()
            .ok_or_else(|| linkage("the scene has no [mechanism]".into()))?;
        let prog = Program::compile(&mechanism).map_err(|e| linkage(e.to_string()))?;
        let c = &mechanism.crank;
        let w1 = c.sense.sign() * c.omega;
        Ok(Self {
            scene,
            mechanism,
            prog,
            w1,
        })
    }

    fn fail(&self, detail: impl Into<String>) -> BenchError {
        BenchError::Linkage {
            scene: self.scene.stem.clone(),
            detail: detail.into(),
        }
    }

    /// Crank angle after the crank has turned through `turned` radians in its own sense.
    fn crank_angle(&self, turned: f64) -> f64 {
        turned * self.w1.signum()
    }

    /// The analytic poses at `n` equal steps of one crank turn, continuity kept.
    fn poses(&self, n: usize) -> Result<Vec<Pose>, BenchError> {
        let mut pose = Pose::default();
        let mut out = Vec::with_capacity(n);
        let step = self.crank_angle(TAU / n as f64);
        self.prog
            .sweep((0.0, step), n, &mut pose, |_, p| out.push(p.clone()))
            .map_err(|u| self.fail(format!("group {}: {}", u.group + 1, u.detail)))?;
        Ok(out)
    }
}

/// The machine: cores, CPU model (from /proc/cpuinfo when present), target, build profile.
pub fn machine() -> String {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|t| {
            t.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split_once(':'))
                .map(|(_, v)| v.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let profile = if cfg!(debug_assertions) {
        "debug"
    } else {
        "release"
    };
    format!(
        "{cpu}, {cores} core(s) available, {}-{}, {profile} build",
        std::env::consts::ARCH,
        std::env::consts::OS
    )
}

/// A department's class: thousands of variants in one run, the four-bar's and the shaper's.
/// Run first, in a fresh process: a peak of resident memory read after the other rows would
/// be theirs.
fn classes(opts: &BenchOptions) -> Result<Vec<Throughput>, BenchError> {
    let mut rows = Vec::new();
    let (four_bar, shaper_class) = if opts.quick { (30, 10) } else { (3000, 1000) };
    for (scene, n) in [("four-bar", four_bar), ("shaper", shaper_class)] {
        let c = class::class_run(opts, scene, n)?;
        let mb = |m: Option<f64>| m.map_or("n/a".to_string(), |m| format!("{m:.0} MB"));
        rows.push(Throughput {
            name: format!("class {} × {} (svg)", c.scene, c.variants),
            per_second: c.variants as f64 / c.seconds,
            note: format!(
                "`tmm batch` over the shipped grid cycled to {} variants (sheets as SVG and the task sheet): {:.0} s, {} not drawn; peak memory {} (a tenth of the class: {})",
                c.variants,
                c.seconds,
                c.failed,
                mb(c.peak_mb),
                mb(c.tenth_peak_mb)
            ),
        });
    }
    Ok(rows)
}

/// Run the bench.
///
/// # Errors
/// A scene that cannot be loaded, a mechanism that cannot be solved or constructed over the
/// turn, a failed differentiation or plate.
pub fn run(opts: &BenchOptions) -> Result<Bench, BenchError> {
    let reps = Reps::new(opts.quick);
    if opts.studio {
        return Ok(Bench {
            machine: machine(),
            rows: Vec::new(),
            throughput: studio::edit_rows(reps)?,
        });
    }
    let shaper = Subject::load(opts, "shaper")?;
    let four_bar = Subject::load(opts, "four-bar")?;
    let classes = classes(opts)?;
    let ram = shaper
        .prog
        .index("E")
        .ok_or_else(|| shaper.fail("no point `E` (the ram)"))?;
    let rocker = 3usize;
    if four_bar.prog.link_count <= rocker {
        return Err(four_bar.fail("no link 3 (the rocker)"));
    }
    let ram_x = Charted {
        names: ["v_S5", "a_S5"],
        units: ["m/s", "m/s^2"],
        quantity: Quantity::Length,
        coord: Coord::PointX(ram),
    };
    let rocker_angle = Charted {
        names: ["omega_3", "eps_3"],
        units: ["rad/s", "rad/s^2"],
        quantity: Quantity::Angle,
        coord: Coord::LinkAngle(rocker),
    };
    let mut rows = chord_rows(&shaper, &ram_x, reps)?;
    rows.extend(chord_rows(&four_bar, &rocker_angle, reps)?);
    rows.extend(rack::rack_rows(reps)?);

    let (fly, t_exact) = flywheel::flywheel_rows(&shaper, reps)?;
    rows.extend(fly);
    rows.extend(cam::inversion_rows(opts, reps)?);

    let mut throughput = Vec::new();
    throughput.push(Throughput {
        name: format!("flywheel {} (exact)", shaper.scene.stem),
        per_second: 1.0 / t_exact,
        note:
            "the work integrated on 720 panels and the energy equation solved for J_м (bracketed)"
                .into(),
    });
    throughput.extend(throughput::kernel(&four_bar, &shaper, reps)?);
    throughput.extend(throughput::drawing(opts, &shaper, &four_bar, reps)?);
    throughput.extend(studio::edit_rows(reps)?);
    throughput.extend(classes);
    Ok(Bench {
        machine: machine(),
        rows,
        throughput,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_missing_scene_is_an_error_naming_the_file() {
        let opts = BenchOptions {
            scenes: PathBuf::from("no-such-folder"),
            quick: true,
            studio: false,
        };
        let e = run(&opts).expect_err("no scenes");
        assert!(e.to_string().contains("shaper.toml"), "{e}");
    }

    /// `--studio`: a row for every shipped scene (the scenes are in the binary, no folder
    /// is read), each a time, and nothing else.
    #[test]
    fn the_studio_bench_times_every_shipped_scene_and_nothing_else() {
        let opts = BenchOptions {
            scenes: PathBuf::from("no-such-folder"),
            quick: true,
            studio: true,
        };
        let b = run(&opts).expect("the studio's rows");
        assert!(b.rows.is_empty());
        let names: Vec<&str> = b.throughput.iter().map(|t| t.name.as_str()).collect();
        let want: Vec<String> = crate::studio::gallery::SHIPPED
            .iter()
            .map(|(stem, _)| format!("studio edit {stem}"))
            .collect();
        assert_eq!(names, want);
        assert!(b
            .throughput
            .iter()
            .all(|t| t.per_second.is_finite() && t.per_second > 0.0));
    }

    #[test]
    fn the_machine_names_cores_and_profile() {
        let m = machine();
        assert!(
            m.contains("core(s) available") && m.contains("build"),
            "{m}"
        );
    }
}
