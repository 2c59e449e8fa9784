//! Analytic oracles for the graphical calculus.

use super::*;
use crate::construct::{Context, Drafting, Recorder, Step};
use crate::geom::Line;
use crate::scale::Quantity;
use std::f64::consts::TAU;

pub(super) fn scale(v: f64, q: Quantity) -> Scale {
    Scale::new(v, q).expect("valid test scale")
}

/// μ_φ for a period drawn 180 mm long, μ_S = 0.01 per mm (sin drawn ±100 mm... 1/0.01).
fn sin_scales() -> Scales {
    Scales {
        x: scale(TAU / 180.0, Quantity::Angle),
        y: scale(0.02, Quantity::Length),
    }
}

pub(super) fn recorder(mu: f64, drafting: f64) -> Recorder {
    Recorder::in_context(
        "test",
        scale(mu, Quantity::Length),
        &Context::for_model_size(400.0, Drafting::new(drafting).expect("drafting"))
            .expect("tolerances"),
    )
}

pub(super) fn layout() -> DiagramLayout {
    DiagramLayout::new(DVec2::new(0.0, 150.0), DVec2::ZERO)
}

/// Differentiate by chords with a recorder at the right scale.
fn chords(src: &Diagram, sc: Scales, h: f64, drafting: f64) -> (Derivative, Recorder) {
    let mu = sc.y.value() / (h * sc.x.value());
    let mut rec = recorder(mu, drafting);
    let d = Derivation::Chords
        .differentiate(&mut rec, src, sc, h, &layout())
        .expect("chords");
    (d, rec)
}

fn sin_diagram(n: usize) -> Diagram {
    Diagram::sample(0.0, TAU, n, true, f64::sin).expect("sin")
}

fn max_err(xs: &[f64], got: &[f64], f: impl Fn(f64) -> f64) -> f64 {
    xs.iter()
        .zip(got)
        .map(|(&x, &g)| (g - f(x)).abs())
        .fold(0.0, f64::max)
}

/// N → max node error of the chord derivative of sin.
fn sin_errors() -> Vec<(usize, f64)> {
    [12, 24, 48, 96]
        .iter()
        .map(|&n| {
            let (d, _) = chords(&sin_diagram(n), sin_scales(), 40.0, 0.0);
            (n, max_err(&d.x_node, &d.node, f64::cos))
        })
        .collect()
}

#[test]
fn chord_derivative_of_sin_is_second_order() {
    let errs = sin_errors();
    for &(n, e) in &errs {
        let bound = chord_node_bound(&sin_diagram(n), 1.0, 1.0);
        eprintln!("N = {n:3}: max |dS/dφ − cos| = {e:.3e} (bound {bound:.3e})");
        assert!(e <= bound, "N = {n}: {e} > {bound}");
    }
    for w in errs.windows(2).skip(1) {
        let ratio = w[0].1 / w[1].1;
        assert!((3.0..=5.0).contains(&ratio), "{w:?}: ratio {ratio}");
    }
}

#[test]
fn chord_midpoints_are_the_difference_quotients() {
    for n in [12, 48] {
        let src = sin_diagram(n);
        let (d, _) = chords(&src, sin_scales(), 40.0, 0.0);
        let h = src.dx;
        for (k, (&x, &v)) in d.x_mid.iter().zip(&d.mid).enumerate() {
            let q = ((x + h / 2.0).sin() - (x - h / 2.0).sin()) / h;
            assert!((v - q).abs() < 1e-12, "N = {n}, k = {k}: {v} vs {q}");
            assert!((v - x.cos()).abs() <= chord_mid_bound(h, 1.0) + 1e-12);
        }
    }
}

#[test]
fn second_chord_derivative_approaches_minus_sin() {
    let mut last = f64::INFINITY;
    for n in [24, 48, 96] {
        let sc = sin_scales();
        let (d1, _) = chords(&sin_diagram(n), sc, 40.0, 0.0);
        let sc2 = Scales {
            x: sc.x,
            y: d1.scale,
        };
        let (d2, _) = chords(&d1.diagram().expect("first"), sc2, 40.0, 0.0);
        let e = max_err(&d2.x_node, &d2.node, |x| -x.sin());
        let h = TAU / n as f64;
        eprintln!("N = {n:3}: max |d²S/dφ² + sin| = {e:.3e}");
        assert!(e < 0.2 * h * h, "N = {n}: {e}");
        assert!(e < last);
        last = e;
    }
}

#[test]
fn tangent_method_is_the_central_difference() {
    let src = sin_diagram(24);
    let sc = sin_scales();
    let mu = sc.y.value() / (40.0 * sc.x.value());
    let mut rec = recorder(mu, 0.0);
    let d = Derivation::Tangents
        .differentiate(&mut rec, &src, sc, 40.0, &layout())
        .expect("tangents");
    let h = src.dx;
    assert_eq!(d.node.len(), 24);
    assert!(d.mid.is_empty());
    for (&x, &v) in d.x_node.iter().zip(&d.node) {
        let q = ((x + h).sin() - (x - h).sin()) / (2.0 * h);
        assert!((v - q).abs() < 1e-12);
        assert!((v - x.cos()).abs() <= h * h / 6.0);
    }
    assert_eq!(d.rays.len(), 24);
}

#[test]
fn seed_scale_arithmetic() {
    let mu_s = scale(0.005, Quantity::Length);
    let mu_phi = scale(0.052, Quantity::Angle);
    let v = derivative_scale(mu_s, mu_phi, 28.0, Quantity::Length).expect("μ_v′");
    assert!((v.value() - 0.003434).abs() < 1e-6, "{}", v.value());
    let a = derivative_scale(v, mu_phi, 7.5, Quantity::Length).expect("μ_a′");
    assert!((a.value() - 0.008805).abs() < 1e-6, "{}", a.value());
    // And back: integrating at H = 28 returns μ_s.
    let s = integral_scale(v, mu_phi, 28.0, Quantity::Length).expect("μ_s");
    assert!((s.value() - 0.005).abs() < 1e-15);
}

/// A periodic displacement-like curve with a rise and a return.
fn s_curve(x: f64) -> f64 {
    0.2 * (1.0 - x.cos()) + 0.05 * (2.0 * x).sin()
}

#[test]
fn integrating_the_chord_derivative_gives_the_curve_back() {
    let n = 24;
    let src = Diagram::sample(0.0, TAU, n, true, s_curve).expect("S");
    let sc = Scales {
        x: scale(TAU / 180.0, Quantity::Angle),
        y: scale(0.005, Quantity::Length),
    };
    let (d, _) = chords(&src, sc, 30.0, 0.0);
    let mid = Diagram::new(0.0, src.dx, d.mid.clone(), true).expect("mids");
    let back = |samples: &Diagram, sampling: Sampling| {
        let s = integral_scale(d.scale, sc.x, 30.0, Quantity::Length).expect("μ");
        let mut rec = recorder(s.value(), 0.0);
        let ys = Scales {
            x: sc.x,
            y: d.scale,
        };
        integrate_chords(&mut rec, samples, sampling, ys, 30.0, src.y[0], &layout())
            .expect("integral")
    };
    // From the mid-interval values the sum telescopes: exact.
    let i = back(&mid, Sampling::Midpoints);
    assert_eq!(i.node.len(), n + 1);
    for k in 0..=n {
        assert!((i.node[k] - src.at(k)).abs() < 1e-12, "k = {k}");
    }
    assert!((i.scale.value() - 0.005).abs() < 1e-15);
    // From the node values read off the curve: midpoint rule on an O(h²) integrand.
    let i = back(&d.diagram().expect("nodes"), Sampling::Nodes);
    let h = src.dx;
    // |S‴| ≤ 0.2 + 0.4, |S⁗| ≤ 0.2 + 0.8: bound from reading the curve + the midpoint rule.
    let bound = TAU * (chord_node_bound(&src, 0.6, 2.0) + h * h / 24.0 * 1.0);
    let e = (0..=n)
        .map(|k| (i.node[k] - src.at(k)).abs())
        .fold(0.0, f64::max);
    eprintln!("integral of the node values: max error {e:.3e}, bound {bound:.3e}");
    assert!(e <= bound, "{e} > {bound}");
}

#[test]
fn integrating_a_constant_draws_a_straight_line() {
    let c = Diagram::new(1.0, 0.25, vec![2.0; 9], false).expect("const");
    let sc = Scales {
        x: scale(0.01, Quantity::Angle),
        y: scale(0.1, Quantity::Length),
    };
    let mu = 0.1 * 20.0 * 0.01;
    let mut rec = recorder(mu, 0.0);
    let i = integrate_chords(&mut rec, &c, Sampling::Nodes, sc, 20.0, -0.5, &layout())
        .expect("integral");
    for (k, v) in i.node.iter().enumerate() {
        let want = -0.5 + 2.0 * 0.25 * k as f64;
        assert!((v - want).abs() < 1e-12, "k = {k}: {v} vs {want}");
    }
    assert_eq!(i.rays.len(), 8);
    assert_eq!(i.chords.len(), 8);
}

#[test]
fn drafting_changes_readings_by_at_most_half_the_resolution() {
    let src = sin_diagram(24);
    let sc = sin_scales();
    let (exact, _) = chords(&src, sc, 40.0, 0.0);
    let (drafted, _) = chords(&src, sc, 40.0, 0.5);
    let limit = 0.25 * exact.scale.value() * (1.0 + 1e-9);
    let pairs = exact.mid.iter().zip(&drafted.mid);
    for (a, b) in pairs.chain(exact.node.iter().zip(&drafted.node)) {
        assert!((a - b).abs() <= limit, "{a} vs {b}");
    }
    assert!(exact.mid.iter().zip(&drafted.mid).any(|(a, b)| a != b));
}

#[test]
fn non_periodic_diagram_and_its_ends() {
    // y = x³ on [0, 2]: y′ = 3x², y‴ = 6, y⁽⁵⁾ = 0.
    let src = Diagram::sample(0.0, 2.0, 16, false, |x| x * x * x).expect("cubic");
    let sc = Scales {
        x: scale(0.02, Quantity::Angle),
        y: scale(0.1, Quantity::Length),
    };
    let (d, _) = chords(&src, sc, 25.0, 0.0);
    assert_eq!(d.node.len(), 17);
    assert_eq!(d.mid.len(), 16);
    // The central difference of x³ is exact up to h²/4: 3m² + h²/4.
    let h = src.dx;
    for (&x, &v) in d.x_mid.iter().zip(&d.mid) {
        assert!((v - (3.0 * x * x + h * h / 4.0)).abs() < 1e-12);
    }
    let e = max_err(&d.x_node, &d.node, |x| 3.0 * x * x);
    assert!(e <= chord_node_bound(&src, 6.0, 0.0) + 1e-12, "{e}");
    // The cubic through midpoints of a quadratic + constant is exact: error h²/4 everywhere.
    assert!((e - h * h / 4.0).abs() < 1e-9, "{e}");
}

/// A tangent drawn at an end (DiagramLayout::tangents_at_ends) gives the node there from its ray:
/// y = x³ on [0, 2] with its tangent at x = 0 horizontal and at x = 2 of slope 12 (drawn
/// mm) gives y′ = 0 and 12 exactly at the ends, where the extended curve gives h²/4 too
/// much; the inner nodes and the mid-interval values are those of the plain method.
#[test]
fn an_end_tangent_gives_the_node_at_that_end() {
    let src = Diagram::sample(0.0, 2.0, 16, false, |x| x * x * x).expect("cubic");
    let sc = Scales {
        x: scale(0.02, Quantity::Angle),
        y: scale(0.1, Quantity::Length),
    };
    let h = 25.0;
    let (plain, _) = chords(&src, sc, h, 0.0);
    let mut rec = recorder(sc.y.value() / (h * sc.x.value()), 0.0);
    // The slope 12 in drawn mm: Δy/Δx = 12·μ_x/μ_y.
    let end = DVec2::new(1.0, 12.0 * sc.x.value() / sc.y.value());
    let lay = layout().tangents_at_ends(Some(DVec2::X), Some(end));
    let d = Derivation::Chords
        .differentiate(&mut rec, &src, sc, h, &lay)
        .expect("chords");
    assert!(d.node[0].abs() < 1e-12, "{}", d.node[0]);
    assert!((d.node[16] - 12.0).abs() < 1e-9, "{}", d.node[16]);
    assert!((plain.node[0] - src.dx * src.dx / 4.0).abs() < 1e-9);
    assert_eq!(d.mid, plain.mid);
    assert_eq!(d.node[1..16], plain.node[1..16]);
    let rays = rec
        .steps()
        .iter()
        .filter(|s| {
            s.note
                .starts_with("ray from the pole parallel to the tangent")
        })
        .count();
    assert_eq!(rays, 2);
}

#[test]
fn a_dwell_has_a_zero_derivative_exactly() {
    // Dwell (flat) on nodes 0..=6, then a rise.
    let y: Vec<f64> = (0..=16)
        .map(|k| {
            let t = (k as f64 - 6.0).max(0.0) / 10.0;
            0.3 * t * t * (3.0 - 2.0 * t)
        })
        .collect();
    let src = Diagram::new(0.0, 0.1, y, false).expect("dwell");
    let sc = Scales {
        x: scale(0.01, Quantity::Angle),
        y: scale(0.005, Quantity::Length),
    };
    let (d, _) = chords(&src, sc, 20.0, 0.5);
    for k in 0..6 {
        assert_eq!(d.mid[k], 0.0, "mid {k}");
    }
    for k in 0..=4 {
        assert_eq!(d.node[k], 0.0, "node {k}");
    }
    assert!(d.mid[8] > 0.0);
}

#[test]
fn bad_input_is_an_error_not_a_panic() {
    let sc = sin_scales();
    let mut rec = recorder(sc.y.value() / (40.0 * sc.x.value()), 0.0);
    let mut run =
        |src: Diagram, h: f64| Derivation::Chords.differentiate(&mut rec, &src, sc, h, &layout());
    let ok = sin_diagram(12);
    let nan = Diagram {
        y: vec![0.0, f64::NAN, 1.0],
        ..ok.clone()
    };
    assert!(matches!(
        run(nan, 40.0),
        Err(CalculusError::NonFinite { index: 1, .. })
    ));
    let one = Diagram {
        y: vec![0.0, 1.0],
        periodic: false,
        ..ok.clone()
    };
    assert!(matches!(
        run(one, 40.0),
        Err(CalculusError::TooFewIntervals { intervals: 1 })
    ));
    for dx in [0.0, -0.1, f64::INFINITY] {
        let bad = Diagram { dx, ..ok.clone() };
        assert!(matches!(
            run(bad, 40.0),
            Err(CalculusError::BadInterval { .. })
        ));
    }
    for h in [0.0, -5.0, f64::NAN] {
        assert!(matches!(
            run(ok.clone(), h),
            Err(CalculusError::BadPole { .. })
        ));
    }
    // Another H than the recorder's scale was made for.
    let e = run(ok.clone(), 30.0).expect_err("scale mismatch");
    assert!(e.to_string().contains("does not match"), "{e}");
    assert!(Diagram::new(0.0, 0.1, vec![1.0, f64::INFINITY, 0.0], false)
        .expect_err("inf")
        .to_string()
        .contains("inf"));
    // Values too large for the scales, a near-vertical chord: errors too.
    let huge = Diagram::new(0.0, 1e-300, vec![0.0, 1e300, 0.0], true).expect("valid data");
    assert!(run(huge, 40.0).is_err());
    let steep = Diagram::new(0.0, 1e-12, vec![0.0, 1e6, 0.0], false).expect("valid data");
    assert!(run(steep, 40.0).is_err());
    // Integration: bad start, too few midpoints, bad pole.
    let mut rec = recorder(0.02 * 40.0 * sc.x.value(), 0.0);
    let mids = Diagram::new(0.0, 0.1, vec![1.0], true);
    assert!(mids.is_err());
    let m = Diagram {
        y: vec![1.0],
        ..ok.clone()
    };
    assert!(integrate_chords(&mut rec, &m, Sampling::Midpoints, sc, 40.0, 0.0, &layout()).is_err());
    assert!(integrate_chords(
        &mut rec,
        &ok,
        Sampling::Nodes,
        sc,
        40.0,
        f64::NAN,
        &layout()
    )
    .is_err());
    assert!(integrate_chords(&mut rec, &ok, Sampling::Nodes, sc, -1.0, 0.0, &layout()).is_err());
    assert!(pole_for(&ok, sc, 0.0).is_err());
}

#[test]
fn pole_for_gives_the_preferred_size() {
    let src = sin_diagram(24);
    let sc = sin_scales();
    let h = pole_for(&src, sc, 50.0).expect("H");
    assert_eq!(h * 2.0, (h * 2.0).round());
    let (d, _) = chords(&src, sc, h, 0.0);
    let biggest = d
        .mid
        .iter()
        .map(|v| d.scale.to_mm(*v).abs())
        .fold(0.0, f64::max);
    assert!((biggest - 50.0).abs() < 1.0, "{biggest} mm at H = {h}");
    let flat = Diagram::new(0.0, 0.1, vec![1.0; 5], false).expect("flat");
    assert_eq!(pole_for(&flat, sc, 45.2).expect("H"), 45.0);
}

fn step(rec: &Recorder, id: StepId) -> &Step {
    &rec.steps()[id.0 as usize]
}

#[test]
fn every_ray_passes_through_the_pole_parallel_to_its_chord() {
    let src = sin_diagram(12);
    let (d, rec) = chords(&src, sin_scales(), 40.0, 0.0);
    assert_eq!(d.rays.len(), src.intervals());
    assert!((d.pole - DVec2::new(-40.0, 0.0)).length() < 1e-12);
    let chords: Vec<&Step> = rec
        .steps()
        .iter()
        .filter(|s| s.note.starts_with("chord "))
        .collect();
    assert_eq!(chords.len(), src.intervals());
    for (k, &id) in d.rays.iter().enumerate() {
        let Item::Segment(ray) = step(&rec, id).item else {
            panic!("ray {k} is not a segment");
        };
        let Item::Segment(chord) = chords[k].item else {
            panic!("chord {k} is not a segment");
        };
        assert!(ray.from.distance(d.pole) < 1e-12, "ray {k}");
        assert!(ray.to.x.abs() < 1e-9, "ray {k} ends on the ordinate axis");
        let (rd, cd) = (ray.to - ray.from, chord.to - chord.from);
        assert!(
            rd.perp_dot(cd).abs() < 1e-9 * rd.length() * cd.length(),
            "ray {k}"
        );
        let line = Line::through(ray.from, ray.to).expect("ray line");
        assert!(line.signed_distance(d.pole).abs() < 1e-12);
    }
    let labels: Vec<&str> = rec
        .steps()
        .iter()
        .filter_map(|s| s.label.as_ref().map(|l| l.text.as_str()))
        .collect();
    for l in ["P", "H", "φ", "S", "dS/dφ"] {
        assert!(labels.contains(&l), "label {l} missing: {labels:?}");
    }
    assert!(matches!(step(&rec, d.curve).item, Item::Curve { .. }));
    assert_eq!(step(&rec, d.curve).role, Role::Result);
    let mids = rec
        .steps()
        .iter()
        .filter(|s| s.role == Role::Result && matches!(s.item, Item::Point(_)))
        .count();
    assert_eq!(mids, src.intervals());
}

/// A construction split over two figures (the given diagram's and the constructed one's) and
/// with its pole moved along the abscissa (the rays to a vertical elsewhere than the ordinate
/// axis) reads the same values as in one figure: the rays keep their directions. The given
/// figure holds the pole, its dimension and the rays; the constructed one the chords or the
/// cuts and the curve.
#[test]
fn two_figures_and_a_moved_pole_read_the_same() {
    let src = sin_diagram(24);
    let sc = sin_scales();
    let (one, _) = chords(&src, sc, 40.0, 0.0);
    let mu = sc.y.value() / (40.0 * sc.x.value());
    let (mut given, mut built) = (recorder(sc.y.value(), 0.0), recorder(mu, 0.0));
    let moved = layout().rays_to(250.0).without_axes().with_source(false);
    let two = Derivation::Chords
        .differentiate_in(
            Figures::Two {
                given: &mut given,
                built: &mut built,
            },
            &src,
            sc,
            40.0,
            &moved,
        )
        .expect("chords in two figures");
    for (a, b) in one.node.iter().zip(&two.node) {
        assert!((a - b).abs() < 1e-12, "{a} against {b}");
    }
    assert_eq!(two.pole, DVec2::new(210.0, 0.0));
    let notes = |r: &Recorder| r.steps().iter().map(|s| s.note.clone()).collect::<Vec<_>>();
    let (g, b) = (notes(&given), notes(&built));
    assert!(g.iter().all(|n| n.starts_with("chord ")), "{g:?}");
    assert!(b.iter().any(|n| n.starts_with("pole P")), "{b:?}");
    assert!(
        b.iter().any(|n| n == "the vertical the rays run to"),
        "{b:?}"
    );
    assert!(!b.iter().any(|n| n.starts_with("ordinate axis")), "{b:?}");
    // Integrating the mid-interval values back, into two figures, the pole moved.
    let mid = Diagram::new(0.0, src.dx, two.mid.clone(), true).expect("mids");
    let (mut given, mut built) = (recorder(mu, 0.0), recorder(sc.y.value(), 0.0));
    let i = integrate_chords_in(
        Figures::Two {
            given: &mut given,
            built: &mut built,
        },
        &mid,
        Sampling::Midpoints,
        Scales {
            x: sc.x,
            y: two.scale,
        },
        40.0,
        src.y[0],
        &DiagramLayout::new(DVec2::ZERO, DVec2::new(0.0, -150.0))
            .with_source(false)
            .rays_to(-20.0),
    )
    .expect("integral in two figures");
    for k in 0..=24 {
        assert!((i.node[k] - src.at(k)).abs() < 1e-12, "k = {k}");
    }
    assert_eq!(i.pole, DVec2::new(-60.0, 0.0));
    let (g, b) = (notes(&given), notes(&built));
    assert!(g.iter().any(|n| n.starts_with("ray 0")) && !g.iter().any(|n| n.starts_with("chord")));
    assert!(
        b.iter().filter(|n| n.starts_with("chord ")).count() == 24,
        "{b:?}"
    );
}
