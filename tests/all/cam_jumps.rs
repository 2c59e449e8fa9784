//! A rigid shock drawn as the jump it is (issue 45): where the uniform law's rise and return
//! meet the dwells, dS/dφ jumps between nought and ±h/Φ, and the diagram closes its
//! rectangle with a vertical there — at the rise's start and end, at the return's start and
//! end — drawn as the curve is. A law with no velocity jump (every other shipped cam) draws
//! none.

use std::path::PathBuf;
use tmm::construct::{Drafting, Figure, Item, Role};
use tmm::geom::DVec2;
use tmm::study::Session;

fn ds_view(name: &str) -> Figure {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("constructions")
        .join(format!("{name}.toml"));
    let s = tmm::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let cam = Session::new(&s, Drafting::EXACT).cam();
    let cam = cam.unwrap_or_else(|e| panic!("{name}: {e}"));
    cam.diagrams.ds_view.clone()
}

/// The jumps drawn on dS/dφ: (abscissa, the end's ordinate), mm.
fn jumps(fig: &Figure) -> Vec<(f64, f64)> {
    fig.steps
        .iter()
        .filter(|s| s.note.starts_with("jump of dS/dφ"))
        .map(|s| {
            assert_eq!(s.role, Role::Result, "{}", s.note);
            match &s.item {
                Item::Segment(seg) => {
                    assert!(seg.from.y.abs() < 1e-9, "from the abscissa: {seg:?}");
                    assert!((seg.from.x - seg.to.x).abs() < 1e-9, "vertical: {seg:?}");
                    (seg.to.x, seg.to.y)
                }
                other => panic!("{}: {other:?}", s.note),
            }
        })
        .collect()
}

#[test]
fn the_uniform_laws_velocity_jumps_close_its_rectangles() {
    let fig = ds_view("cam-shock");
    let got = jumps(&fig);
    // Phases 120°, 60°, 120°, 60°, h = 30 mm: dS/dφ = ±h/Φ = ±14,32 mm (per rad) at μ_S′
    // read off the figure's own scale; μ_φ from the rise's start at 0 to the return's end.
    let mu = fig.scale.value();
    let level = 0.030 / (120f64.to_radians()) / mu;
    let x_end_of_return = got.iter().map(|j| j.0).fold(0.0f64, f64::max);
    let mu_phi = 300f64.to_radians() / x_end_of_return;
    let expected = [
        (0.0, level),
        (120.0, level),
        (180.0, -level),
        (300.0, -level),
    ];
    assert_eq!(got.len(), 4, "{got:?}");
    for ((x, y), (deg, want)) in got.iter().zip(expected) {
        let at = (x * mu_phi).to_degrees();
        assert!((at - deg).abs() < 1e-6, "jump at {at}° (want {deg}°)");
        // The chord ends read to the drawing's own accuracy: the law's constant to 0,05 mm.
        assert!((y - want).abs() < 0.05, "{y} mm at {deg}° (want {want})");
    }
    // Each jump stands on the curve's end: a vertical of the drawn dS/dφ, not beside it.
    let curve_ends: Vec<DVec2> = fig
        .steps
        .iter()
        .filter(|s| s.note.starts_with("smooth curve dS/dφ"))
        .flat_map(|s| match &s.item {
            Item::Curve { points, .. } => vec![points[0], points[points.len() - 1]],
            _ => Vec::new(),
        })
        .collect();
    for (x, y) in &got {
        let end = DVec2::new(*x, *y);
        assert!(
            curve_ends.iter().any(|p| p.distance(end) < 1e-9),
            "{end:?} not at an end of the curve {curve_ends:?}"
        );
    }
}

#[test]
fn a_law_without_a_velocity_jump_draws_none() {
    for name in [
        "cam-central",
        "cam-pz4",
        "cam-pz5",
        "cam-undercut",
        "shaper",
    ] {
        assert!(jumps(&ds_view(name)).is_empty(), "{name}");
    }
}
