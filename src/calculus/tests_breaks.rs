//! A diagram that breaks: each piece differentiated on its own gives both one-sided values at
//! the break and second-order values beside it, where one smooth curve across the corner is
//! off by the corner's size; a break is refused outside the diagram and by the integration.

use super::tests::{layout, recorder, scale};
use super::*;
use crate::scale::Quantity;
use std::f64::consts::{PI, TAU};

/// |sin x| over one turn in 24 intervals: corners at nodes 0 (≡ 24) and 12.
fn rectified(corners: &[usize]) -> Diagram {
    Diagram::sample(0.0, TAU, 24, true, |x| x.sin().abs())
        .and_then(|d| d.with_corners(corners))
        .expect("|sin x|")
}

/// μ_x: a turn on 240 mm; μ_y: 1 on 50 mm; H = 40 mm.
fn scales() -> Scales {
    Scales {
        x: scale(TAU / 240.0, Quantity::Angle),
        y: scale(0.02, Quantity::Length),
    }
}

/// Differentiate `src` by `method` with a recorder at the derivative's scale: the
/// derivative and the number of curves drawn.
fn differentiate(method: Derivation, src: &Diagram, sc: Scales) -> (Derivative, usize) {
    let h = 40.0;
    let mut rec = recorder(sc.y.value() / (h * sc.x.value()), 0.0);
    let d = method
        .differentiate(&mut rec, src, sc, h, &layout())
        .expect("derivative");
    let curves = (rec.steps().iter())
        .filter(|s| matches!(s.item, crate::construct::Item::Curve { .. }))
        .count();
    (d, curves)
}

/// The largest error of `d`'s node values (after each break) and of its values before the
/// breaks against the one-sided derivative `after(x)` and `before(x)`.
fn worst(d: &Derivative, after: impl Fn(f64) -> f64, before: impl Fn(f64) -> f64) -> f64 {
    let nodes = d
        .x_node
        .iter()
        .zip(&d.node)
        .map(|(&x, &v)| (v - after(x)).abs());
    let left = d
        .breaks
        .iter()
        .map(|b| (b.left - before(d.x0 + b.node as f64 * d.dx)).abs());
    nodes.chain(left).fold(0.0, f64::max)
}

/// d|sin x|/dx: cos x on (0, π), −cos x on (π, 2π); at a corner the piece starting there.
fn slope_after(x: f64) -> f64 {
    if x.rem_euclid(TAU) < PI - 1e-9 {
        x.cos()
    } else {
        -x.cos()
    }
}

/// The slope the piece ending at `x` reaches there.
fn slope_before(x: f64) -> f64 {
    -slope_after(x)
}

#[test]
fn a_corner_is_differentiated_a_piece_on_each_side() {
    // Chords: second order (0.004 here); tangents: the one-sided chord at a piece's end, h²/6
    // off for sin (0.011).
    for (method, bound) in [(Derivation::Chords, 0.006), (Derivation::Tangents, 0.015)] {
        let (d, curves) = differentiate(method, &rectified(&[0, 12]), scales());
        let err = worst(&d, slope_after, slope_before);
        assert!(err < bound, "{method:?}: {err}");
        assert_eq!(
            d.breaks.iter().map(|b| b.node).collect::<Vec<_>>(),
            vec![0, 12]
        );
        // Two pieces of the given curve and two of the derivative's.
        assert_eq!(curves, 4, "{method:?}");
        // Across the corners as one smooth curve: the chords' cubics read the nodes beside
        // them a tenth of the slope off, the tangents' central chords the corners themselves
        // wholly.
        let (smooth, _) = differentiate(method, &rectified(&[]), scales());
        let nodes: &[usize] = match method {
            Derivation::Chords => &[1, 11, 13, 23],
            Derivation::Tangents => &[0, 12],
        };
        let off = (nodes.iter())
            .map(|&k| (smooth.node[k] - slope_after(smooth.x_node[k])).abs())
            .fold(0.0, f64::max);
        assert!(off > 10.0 * err, "{method:?}: {off} against {err}");
    }
}

#[test]
fn a_jump_is_differentiated_again_a_piece_on_each_side() {
    let (d1, _) = differentiate(Derivation::Chords, &rectified(&[0, 12]), scales());
    let d1 = d1.diagram().expect("dy/dx with its jumps");
    assert_eq!(d1.breaks.len(), 2);
    assert!((d1.before(12) + 1.0).abs() < 0.02 && (d1.at(12) - 1.0).abs() < 0.02);
    let sc = Scales {
        x: scales().x,
        y: scale(0.02 / (40.0 * scales().x.value()), Quantity::Length),
    };
    let (d2, _) = differentiate(Derivation::Chords, &d1, sc);
    // d²|sin x|/dx² = −|sin x| on both pieces, 0 either side of each corner.
    let curvature = |x: f64| -x.sin().abs();
    let err = worst(&d2, curvature, curvature);
    assert!(err < 0.02, "{err}");
}

#[test]
fn a_break_must_lie_inside_the_diagram_once_and_is_not_integrated_over_equal_intervals() {
    let open = Diagram::sample(0.0, 1.0, 4, false, |x| x).expect("y = x");
    for nodes in [&[0][..], &[4], &[2, 2]] {
        assert!(
            matches!(
                open.clone().with_corners(nodes),
                Err(CalculusError::BadBreak { .. })
            ),
            "{nodes:?}"
        );
    }
    let nan = Break {
        node: 2,
        left: f64::NAN,
    };
    assert!(matches!(
        open.clone().with_breaks(vec![nan]),
        Err(CalculusError::NonFinite { index: 2, .. })
    ));
    let broken = open.with_corners(&[2]).expect("corner at node 2");
    assert_eq!(broken.pieces(), vec![(0, 2), (2, 4)]);
    assert_eq!(rectified(&[12]).pieces(), vec![(12, 36)]);
    assert_eq!(rectified(&[12]).spans(), vec![(0, 12), (12, 24)]);
    let sc = Scales {
        x: scale(0.01, Quantity::Angle),
        y: scale(0.05, Quantity::Length),
    };
    let mut rec = recorder(0.05 * 25.0 * 0.01, 0.0);
    assert!(matches!(
        integrate_chords(&mut rec, &broken, Sampling::Nodes, sc, 25.0, 0.0, &layout()),
        Err(CalculusError::Broken { node: 2 })
    ));
}
