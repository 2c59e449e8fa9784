//! Graphical integration across a break of the law (issue 42, §5): the given d²S/dφ² of
//! "linear with blends", "+ −" and the trapezoidal law jumps (or turns a corner) between the
//! scene's equal division points; the construction puts a division point on every break, so
//! each interval is smooth and the chord method's error is its own.
//!
//! The bound tested (h: the largest interval, h ≤ Φ/N; f the normalised law, S = H·f(φ/Φ);
//! maxima over the law's smooth pieces):
//! * dS/dφ at the nodes (midpoint rule on S″): |ΔS′| ≤ Φ·h²/24·max|S⁗|;
//! * S at the nodes (the chord's middle, trapezoid rule on the drawn S′):
//!   |ΔS| ≤ Φ²·h²/24·max|S⁗| + Φ·h²/12·max|S‴| — at the end of the rise, relative to the
//!   stroke, ≤ C/N² with C = max|f⁗|/24 + max|f‴|/12 (0 for "+ −" and the blends, whose
//!   analogue is constant between the breaks; 128/3/12 for the trapezoidal law);
//! * r_min read at the points (the translating follower, s₀ = max(|S′ − e|·tan γ_min − S)):
//!   |Δs₀| ≤ tan γ_min·|ΔS′| + |ΔS| + h²/8·(tan γ_min·max|S‴| + max|S″|) (the last: a smooth
//!   maximum between two points), and |Δr_min| ≤ |Δs₀|;
//! * the cam built on that r_min: tan λ ≤ tan λ_max·s₀/(s₀ − |Δs₀|).
//!
//! Before the division points on the breaks (12 divisions, 130/50/130/50°, H = 30 mm,
//! e = 3 mm, γ_min = 60°, force closure) the rise ended at 26.04 mm (blends 0,2: −13.2 %),
//! 36.51 mm ("+ −" 0,3: +21.7 %, dS/dφ not back to 0) and 31.11 mm (trapezoidal: +3.7 %).

use proptest::prelude::*;
use std::f64::consts::FRAC_PI_2;
use tmm::cam::{build, Cam, CamSpec, Closure, Follower, Law};
use tmm::construct::{Context, Drafting};
use tmm::scale::{Quantity, Scale};

fn ctx() -> Context {
    Context::for_model_size(300.0, Drafting::EXACT).expect("context")
}

/// A translating roller follower (knife edge), H = 30 mm, e = 3 mm, γ_min = 60°: phases
/// [rise, far, return] in degrees (near: the rest), `n` divisions. μ_S is given (0,0004
/// m/mm, the round one the stroke takes), so that the diagrams are the chord method's own:
/// μ_S found from the stroke (seed 002 (4.2)) would put the rise's error into the analogues.
fn spec(law: Law, deg: [f64; 3], n: usize, closure: Closure) -> CamSpec {
    let follower = Follower::Translating { offset: 0.003 };
    let force = closure == Closure::Force;
    CamSpec {
        divisions: n,
        scale_s: Scale::new(0.0004, Quantity::Length),
        ..crate::cam_oracle::spec(deg, law, law, 0.030, follower, 60.0, force)
    }
}

/// The test's own breaks of each law's d²S/dφ² inside the phase (u).
fn knots(law: Law) -> Vec<f64> {
    match law {
        Law::LinearBlended { blend } if blend < 0.5 => vec![blend, 1.0 - blend],
        Law::LinearBlended { .. } => vec![0.5],
        Law::ConstantAcceleration { ratio } => vec![ratio],
        Law::Trapezoidal => vec![0.125, 0.375, 0.625, 0.875],
        _ => Vec::new(),
    }
}

/// max |f″|, |f‴|, |f⁗| over the law's smooth pieces: f″ from the closed form, its
/// derivatives by central differences inside each piece.
fn law_maxima(law: Law) -> [f64; 3] {
    let mut edges = vec![0.0];
    edges.extend(knots(law));
    edges.push(1.0);
    let f2 = |u: f64| law.eval(u, true).2;
    let mut m = [0.0f64; 3];
    let d = 1e-4;
    for w in edges.windows(2) {
        for j in 0..=200 {
            let u = w[0] + (w[1] - w[0]) * (0.02 + 0.96 * j as f64 / 200.0);
            let (a, b, c) = (f2(u - d), f2(u), f2(u + d));
            m[0] = m[0].max(b.abs());
            m[1] = m[1].max(((c - a) / (2.0 * d)).abs());
            m[2] = m[2].max(((c - 2.0 * b + a) / (d * d)).abs());
        }
    }
    // Central differences of a piecewise-linear f″ leave rounding noise in f⁗.
    if m[2] < 1e-3 * (1.0 + m[1]) {
        m[2] = 0.0;
    }
    m
}

/// The phases' index ranges of the points, the largest interval of each phase (rad).
fn phase_steps(cam: &Cam) -> [(usize, usize, f64); 2] {
    [0usize, 2].map(|phase| {
        let idx: Vec<usize> = (0..cam.points.len())
            .filter(|&i| cam.points[i].phase == phase)
            .collect();
        let h = idx
            .windows(2)
            .map(|w| cam.points[w[1]].phi - cam.points[w[0]].phi)
            .fold(0.0, f64::max);
        (idx[0], idx[idx.len() - 1], h)
    })
}

/// The bounds of the module's documentation for one cam: (|ΔS′|, |ΔS|, |Δs₀|) over the phases
/// it checks (the return's S carries the rise's error on).
fn bounds(cam: &Cam) -> (f64, f64, f64) {
    let s = &cam.spec;
    let t = s.gamma_min.tan();
    let [f2, f3, f4] = law_maxima(s.rise);
    let steps = phase_steps(cam);
    let mut out = (0.0f64, 0.0f64, 0.0f64);
    let mut carried = 0.0;
    for (p, len) in [(0usize, s.phases.rise), (1, s.phases.ret)] {
        let h = steps[p].2;
        let (d2, d3, d4) = (
            s.stroke * f2 / len.powi(2),
            s.stroke * f3 / len.powi(3),
            s.stroke * f4 / len.powi(4),
        );
        let dv = len * h * h / 24.0 * d4;
        let ds = carried + len * len * h * h / 24.0 * d4 + len * h * h / 12.0 * d3;
        carried = ds;
        let sampling = h * h / 8.0 * (t * d3 + d2);
        let binds = p == 0 || s.closure == Closure::Geometric;
        out.0 = out.0.max(dv);
        out.1 = out.1.max(ds);
        if binds {
            out.2 = out.2.max(t * dv + ds + sampling);
        }
    }
    out
}

/// What one cam shows: S at the end of the rise against the stroke (relative), the largest
/// node errors of S′ and S, r_min read against the exact one, the largest pressure angle of
/// the cam built on it, and the bounds.
struct Seen {
    rise_end: f64,
    ds: f64,
    s: f64,
    r_read: f64,
    r_exact: f64,
    worst: f64,
    bounds: (f64, f64, f64),
}

fn seen(spec: &CamSpec) -> Seen {
    let cam = build(spec, &ctx()).unwrap_or_else(|e| panic!("{e}"));
    let ex = cam.exact_motion();
    let [(_, rise_last, _), _] = phase_steps(&cam);
    let d = &cam.diagrams;
    let err = |got: &[f64], want: &dyn Fn(usize) -> f64| {
        got.iter()
            .enumerate()
            .map(|(i, g)| (g - want(i)).abs())
            .fold(0.0, f64::max)
    };
    Seen {
        rise_end: (d.s[rise_last] - spec.stroke) / spec.stroke,
        ds: err(&d.ds, &|i| ex[i].ds),
        s: err(&d.s, &|i| ex[i].s),
        r_read: cam.radius.graphical,
        r_exact: cam.exact_r_min(),
        worst: cam.worst_angle(),
        bounds: bounds(&cam),
    }
}

/// Every bound of the module's documentation holds for `spec`.
fn holds(spec: &CamSpec) -> Result<Seen, String> {
    let v = seen(spec);
    let (dv, ds, ds0) = v.bounds;
    let rounding = 1e-9;
    let what = format!("{:?} at N = {}", spec.rise, spec.divisions);
    if v.ds > dv + rounding * spec.stroke {
        return Err(format!("{what}: |ΔS′| = {:e} > {dv:e}", v.ds));
    }
    if v.s > ds + rounding * spec.stroke {
        return Err(format!("{what}: |ΔS| = {:e} > {ds:e}", v.s));
    }
    if (v.r_read - v.r_exact).abs() > ds0 + rounding * v.r_exact {
        return Err(format!(
            "{what}: r_min read {} against exact {}, bound {ds0:e}",
            v.r_read, v.r_exact
        ));
    }
    let e = spec.offset();
    let s0 = (v.r_exact * v.r_exact - e * e).sqrt();
    let lmax = FRAC_PI_2 - spec.gamma_min;
    // A bound as large as s₀ itself bounds nothing (two intervals over a short phase).
    let limit = if ds0 < s0 {
        (lmax.tan() * s0 / (s0 - ds0)).atan()
    } else {
        FRAC_PI_2
    };
    if v.worst > limit + 1e-9 {
        return Err(format!(
            "{what}: λ = {}° > {}°",
            v.worst.to_degrees(),
            limit.to_degrees()
        ));
    }
    Ok(v)
}

const PZ5: [f64; 3] = [130.0, 50.0, 130.0];

/// The issue's laws: "linear with blends" 0,2, "+ −" 0,3, trapezoidal.
const ISSUE_LAWS: [Law; 3] = [
    Law::LinearBlended { blend: 0.2 },
    Law::ConstantAcceleration { ratio: 0.3 },
    Law::Trapezoidal,
];

/// The issue's three laws at 12 divisions: the rise ends on the stroke (the blends and
/// "+ −" exactly: their analogue is constant between the breaks), r_min read is the exact
/// one, and the cam built on it keeps λ ≤ λ_max; the division points lie on the breaks.
#[test]
fn the_issues_laws_end_the_rise_on_the_stroke() {
    for law in ISSUE_LAWS {
        let s = spec(law, PZ5, 12, Closure::Force);
        let cam = build(&s, &ctx()).unwrap_or_else(|e| panic!("{e}"));
        for b in knots(law) {
            let phi = b * s.phases.rise;
            assert!(
                cam.points
                    .iter()
                    .any(|p| p.phase == 0 && (p.phi - phi).abs() < 1e-12),
                "{law:?}: no division point at u = {b}"
            );
        }
        let v = holds(&s).unwrap_or_else(|e| panic!("{e}"));
        eprintln!(
            "{law:?}, N = 12: rise end {:+.2e}, |ΔS′| {:.2e}, |ΔS| {:.2e} m, r_min {:.4} mm \
             (exact {:.4}), λ {:.3}°",
            v.rise_end,
            v.ds,
            v.s,
            v.r_read * 1e3,
            v.r_exact * 1e3,
            v.worst.to_degrees()
        );
        assert!(v.rise_end.abs() < 1e-9, "{law:?}: {}", v.rise_end);
        if !matches!(law, Law::Trapezoidal) {
            assert!(v.ds < 1e-12 && v.s < 1e-12, "{law:?}");
            assert!((v.r_read - v.r_exact).abs() < 1e-9, "{law:?}");
            assert!(v.worst <= 30f64.to_radians() + 1e-9, "{law:?}");
        }
    }
}

/// Where the scene's divisions already fall on the breaks no point is added: 10 divisions
/// put the "+ −" law's jump at 0,3 and the blends' at 0,2 and 0,8 on nodes.
#[test]
fn breaks_on_the_nodes_add_no_point() {
    for law in [
        Law::LinearBlended { blend: 0.2 },
        Law::ConstantAcceleration { ratio: 0.3 },
    ] {
        let cam = build(&spec(law, PZ5, 10, Closure::Force), &ctx()).expect("cam");
        assert_eq!(cam.points.len(), 22, "{law:?}");
    }
    let cam = build(&spec(Law::Trapezoidal, PZ5, 16, Closure::Force), &ctx()).expect("cam");
    assert_eq!(cam.points.len(), 34);
    // 12 divisions: the blends' two breaks, the jump, the trapezoid's four corners added.
    for (law, per) in [
        (Law::LinearBlended { blend: 0.2 }, 15),
        (Law::ConstantAcceleration { ratio: 0.3 }, 14),
        (Law::Trapezoidal, 17),
    ] {
        let cam = build(&spec(law, PZ5, 12, Closure::Force), &ctx()).expect("cam");
        assert_eq!(cam.points.len(), 2 * per, "{law:?}");
    }
}

/// The rise's end error over the division counts, × N²: within C for every N (the
/// trapezoidal law's C = 128/3/12 = 3.56; it is exact where its corners are nodes).
#[test]
fn the_rise_end_error_times_n_squared_stays_within_c() {
    for law in ISSUE_LAWS {
        let [_, f3, f4] = law_maxima(law);
        let c = f4 / 24.0 + f3 / 12.0;
        let mut worst: f64 = 0.0;
        for n in [2, 3, 5, 6, 7, 12, 13, 24, 31, 48] {
            let v = seen(&spec(law, PZ5, n, Closure::Geometric));
            let scaled = v.rise_end.abs() * (n * n) as f64;
            assert!(
                scaled <= c + 1e-9 * (n * n) as f64,
                "{law:?} N = {n}: {scaled} > {c}"
            );
            worst = worst.max(scaled);
        }
        eprintln!("{law:?}: max |ΔS_end|/H·N² = {worst:.2e} (C = {c:.3})");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Any blend, ratio or the trapezoidal law (and the smooth and uniform laws, with no
    /// break inside the phase), any phases and division count, either closure: S′ and S at
    /// the nodes, r_min read and the pressure angle of the cam built on it within the bounds
    /// of the module's documentation.
    #[test]
    fn across_the_breaks_the_error_is_the_methods_own(
        k in 0u8..7, p in 0.05f64..0.5, q in 0.1f64..0.9, n in 2usize..40,
        rise in 60f64..160.0, far in 0f64..40.0, ret in 60f64..160.0, geometric: bool,
    ) {
        let law = match k {
            0 | 1 => Law::LinearBlended { blend: p },
            2 | 3 => Law::ConstantAcceleration { ratio: q },
            4 => Law::Trapezoidal,
            5 => [Law::Cosine, Law::Sine][n % 2],
            _ => [Law::Uniform, Law::Polynomial345][n % 2],
        };
        let closure = if geometric { Closure::Geometric } else { Closure::Force };
        let s = spec(law, [rise, far, ret], n, closure);
        let v = holds(&s);
        prop_assert!(v.is_ok(), "{}", v.as_ref().err().cloned().unwrap_or_default());
        // Not only bounded: a piecewise-constant analogue divided at its breaks is exact.
        let piecewise_constant = matches!(
            law,
            Law::LinearBlended { .. } | Law::ConstantAcceleration { .. } | Law::Uniform
        );
        if let (Ok(v), true) = (v, piecewise_constant) {
            prop_assert!(v.rise_end.abs() < 1e-9, "{law:?} N = {n}: {}", v.rise_end);
        }
    }
}

/// Through a scene: PZ5's data with "linear with blends" (`blend = 0.2`) at 12 divisions —
/// the rows of S and dS/dφ equal the closed form at every point (30 of them: the blends'
/// ends added), r_min is the exact one, and no limit is exceeded.
#[test]
fn a_scene_with_blends_reads_the_closed_form() {
    use tmm::study::Session;
    let path =
        std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("constructions/cam-pz5.toml");
    let text = std::fs::read_to_string(&path).expect("scene");
    let text = text
        .replace("law = \"cosine\"", "law = \"linear-blended\"\nblend = 0.2")
        .replace("divisions = 8", "divisions = 12");
    let scene = tmm::scene::parse(&text, &path).unwrap_or_else(|e| panic!("{e}"));
    let session = Session::new(&scene, Drafting::EXACT);
    let report = session.report().unwrap_or_else(|e| panic!("{e}"));
    for q in ["s", "ds_dphi", "r_min"] {
        let rows: Vec<_> = report.rows.iter().filter(|r| r.quantity() == q).collect();
        assert!(!rows.is_empty(), "{q}");
        for r in rows {
            assert!(r.abs_error() < 1e-12, "{q} at {:?}: {r:?}", r.position());
        }
    }
    let points = report.rows.iter().filter(|r| r.quantity() == "s").count();
    assert_eq!(points, 30);
    let cam = session.cam().unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(cam.points.len(), 30);
    assert!(cam.worst_angle() <= 30f64.to_radians() + 1e-9);
}
