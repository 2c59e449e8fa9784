//! `tmm bench`: speed against error. Each method's resolution is swept and its error against
//! the analytic twin is put beside its time; whole computations are timed as throughput.
//!
//! * **Chord method** — the displacement of the shaper's ram (point `E`, along x) and the
//!   four-bar's rocker angle (link 3) are charted over one crank turn at N equal steps from
//!   the analytic positions and differentiated twice by chords
//!   ([`differentiate_chords`], drafting exact). The abscissa is the angle the crank
//!   has turned through (it grows with time whatever the sense of ω₁), so the analogues turn
//!   into velocities and accelerations with |ω₁| and |ω₁|² and compare, signs included, with
//!   the analytic ω₁·dX/dφ₁ and ω₁²·d²X/dφ₁² at the nodes.
//! * **Analytic kernel** — [`Program::solve_into`] (positions, first and second analogues)
//!   over many crank angles on one core.
//! * **Construction route** — the recorded compass construction of a position with its
//!   velocity and acceleration plans.
//! * **Plates** — building a plate and writing it as SVG.
//!
//! Times are the best of several repetitions (the machine may be busy); they are reported,
//! never asserted.

use crate::calculus::{
    derivative_scale, differentiate_chords, pole_for, CalculusError, Derivative, Diagram, Layout,
    Scales,
};
use crate::construct::{Drafting, Recorder};
use crate::geom::{wrap_pi, DVec2, Tolerances};
use crate::linkage::{self, kin_plan, PlanKind, PlanSetup, Pose, Program};
use crate::report::{Bench, BenchRow, Throughput};
use crate::scale::{Lang, Quantity, Scale};
use crate::scene::{self, PlateKind, Scene};
use crate::sheets;
use crate::study::Session;
use std::f64::consts::TAU;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;
use thiserror::Error;

/// The resolutions of the chord-method sweep (positions per crank turn).
pub const CHORD_RESOLUTIONS: [usize; 6] = [12, 24, 48, 96, 192, 360];

/// The plates timed, by scene stem: one line per plate.
const PLATES: &[(&str, PlateKind)] = &[
    ("shaper", PlateKind::Positions),
    ("shaper", PlateKind::Kinematics),
];

/// What to run.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchOptions {
    /// The folder holding `shaper.toml` and `four-bar.toml`.
    pub scenes: PathBuf,
    /// Small repetition counts: checks the structure and the errors in well under a second
    /// of timing, the times themselves are rough.
    pub quick: bool,
}

impl Default for BenchOptions {
    fn default() -> Self {
        Self {
            scenes: PathBuf::from("constructions"),
            quick: false,
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

/// The best (least) wall time of `best_of` runs of `f`, seconds.
fn best_time<T, E>(best_of: usize, mut f: impl FnMut() -> Result<T, E>) -> Result<f64, E> {
    let mut best = f64::INFINITY;
    for _ in 0..best_of.max(1) {
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
        for k in 0..n {
            let phi = self.crank_angle(k as f64 * TAU / n as f64);
            self.prog
                .solve_into(phi, k > 0, &mut pose)
                .map_err(|u| self.fail(format!("group {}: {}", u.group + 1, u.detail)))?;
            out.push(pose.clone());
        }
        Ok(out)
    }
}

/// What the chord method charts: a coordinate of the mechanism with its two analogues.
struct Charted {
    /// Quantity names of the first and second derivative (`v_S5`, `a_S5`).
    names: [&'static str; 2],
    /// Their units.
    units: [&'static str; 2],
    /// Ordinate scales' quantities: the coordinate, its analogues.
    quantity: Quantity,
    /// The coordinate.
    coord: Coord,
}

/// A coordinate of the mechanism.
#[derive(Debug, Clone, Copy)]
enum Coord {
    /// The x coordinate of a point (program index).
    PointX(usize),
    /// The frame angle of a link.
    LinkAngle(usize),
}

impl Coord {
    /// Value, first and second analogue w.r.t. the crank angle at a pose.
    fn read(self, p: &Pose) -> [f64; 3] {
        match self {
            Coord::PointX(k) => [p.p[k].x, p.dp[k].x, p.ddp[k].x],
            Coord::LinkAngle(l) => [p.angle(l), p.dangle[l], p.ddangle[l]],
        }
    }
}

/// Differentiate `src` by chords at the textbook pole (steepest ray 40 mm up), recorder at
/// the derivative's scale.
fn chords_once(src: &Diagram, scales: Scales, q: Quantity) -> Result<Derivative, CalculusError> {
    let pole = pole_for(src, scales, 40.0)?;
    let mu = derivative_scale(scales.y, scales.x, pole, q)?;
    let tol = Tolerances::for_model_size(400.0)
        .map_err(|_| CalculusError::BadScale { value: mu.value() })?;
    let mut rec = Recorder::new("bench", mu, tol, Drafting::EXACT);
    let layout = Layout::new(DVec2::new(0.0, 150.0), DVec2::ZERO);
    differentiate_chords(&mut rec, src, scales, pole, &layout)
}

/// Both differentiations of one diagram.
fn chords_twice(
    src: &Diagram,
    mu_x: Scale,
    mu_y: Scale,
    q: Quantity,
) -> Result<(Derivative, Derivative), CalculusError> {
    let d1 = chords_once(src, Scales { x: mu_x, y: mu_y }, q)?;
    let d2 = chords_once(
        &d1.diagram()?,
        Scales {
            x: mu_x,
            y: d1.scale,
        },
        q,
    )?;
    Ok((d1, d2))
}

/// Max and mean |got − want|.
fn errors(got: &[f64], want: &[f64]) -> (f64, f64) {
    let n = got.len().min(want.len());
    if n == 0 || got.len() != want.len() {
        return (f64::NAN, f64::NAN);
    }
    let e = got.iter().zip(want).map(|(g, w)| (g - w).abs());
    let (max, sum) = e.fold((0.0f64, 0.0), |(m, s), x| (m.max(x), s + x));
    (max, sum / n as f64)
}

/// The chord-method rows of one charted coordinate at every resolution.
fn chord_rows(s: &Subject, c: &Charted, reps: Reps) -> Result<Vec<BenchRow>, BenchError> {
    let mut rows = Vec::new();
    let w = s.w1.abs();
    for n in CHORD_RESOLUTIONS {
        let calc = |source| BenchError::Calculus {
            scene: s.scene.stem.clone(),
            n,
            source,
        };
        let jets: Vec<[f64; 3]> = s.poses(n)?.iter().map(|p| c.coord.read(p)).collect();
        // The chart: the coordinate from its value at node 0, against the angle turned
        // (an angle unwrapped step by step).
        let mut y = Vec::with_capacity(n);
        for (k, j) in jets.iter().enumerate() {
            y.push(match (c.coord, k) {
                (_, 0) => 0.0,
                (Coord::LinkAngle(_), _) => y[k - 1] + wrap_pi(j[0] - jets[k - 1][0]),
                (Coord::PointX(_), _) => j[0] - jets[0][0],
            });
        }
        let src = Diagram::new(0.0, TAU / n as f64, y, true).map_err(calc)?;
        let span = src.y.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let mu_x = Scale::new(TAU / 180.0, Quantity::Angle);
        let mu_y = Scale::new(span.max(f64::MIN_POSITIVE) / 50.0, c.quantity);
        let (Some(mu_x), Some(mu_y)) = (mu_x, mu_y) else {
            return Err(calc(CalculusError::BadScale { value: span / 50.0 }));
        };
        let (d1, d2) = chords_twice(&src, mu_x, mu_y, c.quantity).map_err(calc)?;
        let time = best_time(reps.best_of, || {
            for _ in 0..reps.diagrams.max(1) {
                black_box(chords_twice(black_box(&src), mu_x, mu_y, c.quantity)?);
            }
            Ok::<_, CalculusError>(())
        })
        .map_err(calc)?
            / reps.diagrams.max(1) as f64;
        // d/dt = |ω₁|·d/d(turned) and, for the analytic twin, d/dt = ω₁·d/dφ₁.
        let got = [
            d1.node.iter().map(|v| v * w).collect::<Vec<_>>(),
            d2.node.iter().map(|a| a * w * w).collect(),
        ];
        let want = [
            jets.iter().map(|j| j[1] * s.w1).collect::<Vec<_>>(),
            jets.iter().map(|j| j[2] * s.w1 * s.w1).collect(),
        ];
        for k in 0..2 {
            let (max_error, mean_error) = errors(&got[k], &want[k]);
            rows.push(BenchRow {
                method: format!("chord N={n}"),
                resolution: n as u32,
                quantity: c.names[k].into(),
                max_error,
                mean_error,
                time_s: time,
                unit: c.units[k].into(),
            });
        }
    }
    Ok(rows)
}

/// Analytic positions per second (positions with both analogues).
fn kernel_rate(s: &Subject, reps: Reps) -> Result<f64, BenchError> {
    let count = reps.kernel.max(1);
    // The crank steps by 0.1° in its own sense, the angle kept within one turn.
    let step = s.crank_angle(TAU / 3600.0);
    let mut pose = Pose::default();
    s.prog
        .solve_into(0.0, false, &mut pose)
        .map_err(|u| s.fail(u.detail))?;
    let t = best_time(reps.best_of.max(3), || {
        let mut phi = 0.0f64;
        for _ in 0..count {
            phi += step;
            if phi.abs() >= TAU {
                phi = 0.0;
            }
            s.prog.solve_into(black_box(phi), true, &mut pose)?;
            black_box(&pose);
        }
        Ok(())
    })
    .map_err(|u: linkage::Unassembled| s.fail(u.detail))?;
    Ok(count as f64 / t)
}

/// The floor under the four-bar's kernel: its one transcendental call (the crank's sin and
/// cos) and its square roots (two link lengths, the joint's offset, the crossing's sine) per
/// second; link angles are carried as unit vectors, so no atan2 or acos remains.
fn libm_floor_rate(reps: Reps) -> f64 {
    let count = reps.kernel.max(1);
    let step = TAU / 3600.0;
    best_time(reps.best_of.max(3), || {
        let mut phi = 0.0f64;
        for _ in 0..count {
            phi += step;
            let (s, c) = black_box(phi).sin_cos();
            black_box((
                (s + 2.0).sqrt(),
                (c + 2.0).sqrt(),
                (s * c + 1.5).sqrt(),
                (1.0 - 0.25 * s * s).sqrt(),
            ));
        }
        Ok::<_, ()>(())
    })
    .map_or(f64::NAN, |t| count as f64 / t)
}

/// Constructed positions (with velocity and acceleration plans) per second.
fn construction_rate(s: &Subject, reps: Reps) -> Result<f64, BenchError> {
    let count = reps.constructed.max(1);
    let mu_l = s.scene.scale_l.map_or(0.002, |m| m.value());
    let r1 = s.mechanism.crank.length;
    let w = s.w1.abs();
    let scale = |v: f64, q| Scale::new(v, q).ok_or_else(|| s.fail(format!("bad scale {v}")));
    let mu = scale(mu_l, Quantity::Length)?;
    let mu_v = scale(w * r1 / 50.0, Quantity::Velocity)?;
    let mu_a = scale(w * w * r1 / 50.0, Quantity::Acceleration)?;
    let tol = Tolerances::for_model_size(1000.0).map_err(|e| s.fail(e.to_string()))?;
    let t = best_time(reps.best_of, || {
        let mut prev = None;
        for k in 0..count {
            let phi = s.crank_angle(k as f64 * TAU / count as f64);
            let mut rec = Recorder::new("bench", mu, tol, Drafting::EXACT);
            let built = s
                .prog
                .construct(&mut rec, phi, prev.as_ref(), "bench")
                .map_err(|f| s.fail(format!("group {}: {}", f.group + 1, f.error)))?;
            let setup = PlanSetup {
                prog: &s.prog,
                built: &built,
                mu_l,
                w1: s.w1,
                drafting: Drafting::EXACT,
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
fn plate_time(s: &Subject, kind: PlateKind, reps: Reps) -> Result<f64, BenchError> {
    best_time(reps.best_of, || {
        // A fresh session each run: the time includes every construction the sheet needs.
        let session = Session::new(&s.scene, Drafting::EXACT);
        let plate = sheets::build(&session, kind, Lang::Ru)?;
        Ok(crate::plate::to_svg(&plate))
    })
    .map_err(|e: sheets::BuildError| BenchError::Plate {
        scene: s.scene.stem.clone(),
        plate: kind.stem().into(),
        detail: e.to_string(),
    })
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

/// Run the bench.
///
/// # Errors
/// A scene that cannot be loaded, a mechanism that cannot be solved or constructed over the
/// turn, a failed differentiation or plate.
pub fn run(opts: &BenchOptions) -> Result<Bench, BenchError> {
    let reps = Reps::new(opts.quick);
    let shaper = Subject::load(opts, "shaper")?;
    let four_bar = Subject::load(opts, "four-bar")?;
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

    let mut throughput = Vec::new();
    for s in [&four_bar, &shaper] {
        let stem = &s.scene.stem;
        throughput.push(Throughput {
            name: format!("analytic {stem}"),
            per_second: kernel_rate(s, reps)?,
            note: "one position: every point and link with dX/dφ₁, d²X/dφ₁² (solve_into, 1 core)"
                .into(),
        });
    }
    throughput.push(Throughput {
        name: "libm floor four-bar".into(),
        per_second: libm_floor_rate(reps),
        note: "its transcendental and root calls alone: sin_cos + 4 sqrt".into(),
    });
    for s in [&four_bar, &shaper] {
        throughput.push(Throughput {
            name: format!("construction {}", s.scene.stem),
            per_second: construction_rate(s, reps)?,
            note: "one position: recorded compass construction + velocity plan + acceleration plan"
                .into(),
        });
    }
    for &(stem, kind) in PLATES {
        let loaded;
        let s = match [&shaper, &four_bar]
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
    fn errors_are_max_and_mean_or_nan_when_the_lengths_differ() {
        assert_eq!(errors(&[1.0, 2.0], &[1.5, 1.0]), (1.0, 0.75));
        assert!(errors(&[1.0], &[1.0, 2.0]).0.is_nan());
        assert!(errors(&[], &[]).1.is_nan());
    }

    #[test]
    fn a_missing_scene_is_an_error_naming_the_file() {
        let opts = BenchOptions {
            scenes: PathBuf::from("no-such-folder"),
            quick: true,
        };
        let e = run(&opts).expect_err("no scenes");
        assert!(e.to_string().contains("shaper.toml"), "{e}");
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
