//! A link that carries three or more hinges is drawn as the closed contour through them,
//! hatched in its corners where it is drawn with the main line (ГОСТ 2.770; issue 45: the
//! six-bar's rocker DBC was drawn as the bar DB, C floating beside it) — on the plan of
//! positions, on the structural scheme and on the groups of the force analysis; a link with
//! two hinges stays a bar.

use crate::support::root;
use tmm::construct::{Context, Drafting, Figure, Item, Role};
use tmm::geom::DVec2;
use tmm::linkage::Structure;
use tmm::scale::{Quantity, Scale};
use tmm::scene;
use tmm::study::Session;

/// The contour of the step noted `note` of `f` (a closed polyline), if it is one.
fn contour<'a>(f: &'a Figure, note: &str) -> Option<&'a [DVec2]> {
    f.steps.iter().find_map(|s| match &s.item {
        Item::Polyline {
            points,
            closed: true,
        } if s.note == note => Some(points.as_slice()),
        _ => None,
    })
}

/// The contour of the step noted `note` opened at a crowded pivot (a further position of the
/// plan: begun `clear` mm out from the pivot on both sides): its hinges, the pivot put back
/// where the two ends point, and `clear`.
fn opened(f: &Figure, note: &str) -> Option<(Vec<DVec2>, f64)> {
    f.steps.iter().find_map(|s| match &s.item {
        Item::Polyline {
            points,
            closed: false,
        } if s.note == note && points.len() >= 4 => {
            let (a, b) = (points[0], points[points.len() - 1]);
            let (u, v) = (
                (a - points[1]).normalize(),
                (b - points[points.len() - 2]).normalize(),
            );
            // The pivot: where the two end pieces, carried on, meet.
            let t = (b - a).perp_dot(v) / u.perp_dot(v);
            let pivot = a + u * t;
            let mut hinges = points[1..points.len() - 1].to_vec();
            hinges.push(pivot);
            Some((hinges, pivot.distance(a)))
        }
        _ => None,
    })
}

/// How many strokes of `f` hatch the corners of the contour noted `note`.
fn hatching(f: &Figure, note: &str) -> usize {
    let hatch = format!("{note}: corner hatching");
    f.steps
        .iter()
        .filter(|s| s.note == hatch && s.role == Role::Hatch)
        .filter(|s| matches!(s.item, Item::Segment(_)))
        .count()
}

/// Whether `f` draws a bar (a segment) noted `note`.
fn bar(f: &Figure, note: &str) -> bool {
    f.steps
        .iter()
        .any(|s| s.note == note && matches!(s.item, Item::Segment(_)))
}

/// Whether the contour `points` runs through exactly the points `at`, in any order.
fn through(points: &[DVec2], at: &[DVec2]) -> bool {
    points.len() == at.len()
        && at
            .iter()
            .all(|a| points.iter().any(|p| p.distance(*a) < 1e-9))
}

#[test]
fn the_six_bar_rocker_is_the_triangle_dbc_wherever_it_is_drawn() {
    let s = scene::load(&root().join("constructions/six-bar.toml")).expect("six-bar");
    let session = Session::new(&s, Drafting::EXACT);
    let plan = session
        .positions(session.scale_l().expect("μ_l"))
        .expect("plan");
    let at = |k: usize, name: &str| {
        let i = plan.program.index(name).expect("a point of the six-bar");
        plan.positions[k].built.p[i]
    };
    let dbc = |k: usize| [at(k, "D"), at(k, "B"), at(k, "C")];
    // The plan of positions: every position's rocker a triangle, hatched at position 1 (the
    // main line) only; no bar D–B.
    // The further positions, drawn thin, begin 8 mm out from the crowded pivot D (both
    // sides of the triangle at D, as the rocker's fan does).
    for (k, p) in plan.positions.iter().enumerate() {
        let note = format!("position {}: link 3", p.label);
        let points = match contour(&plan.figure, &note) {
            Some(points) if k == 0 => points.to_vec(),
            _ => {
                let (hinges, clear) = opened(&plan.figure, &note)
                    .filter(|_| k > 0)
                    .unwrap_or_else(|| panic!("{note}"));
                assert!((clear - 8.0).abs() < 1e-9, "{note}: begun {clear} mm out");
                hinges
            }
        };
        assert!(through(&points, &dbc(k)), "{note}: {points:?}");
        assert!(!bar(&plan.figure, &note), "{note} is also a bar");
        let strokes = if k == 0 { 9 } else { 0 };
        assert_eq!(hatching(&plan.figure, &note), strokes, "{note}");
        // The coupler and the crank are bars.
        assert!(bar(&plan.figure, &format!("position {}: link 2", p.label)));
        assert!(contour(&plan.figure, &format!("position {}: link 2", p.label)).is_none());
    }
    // The structural scheme: the whole mechanism and the group II(2,3) apart.
    let st = Structure::analyse(&plan.mechanism);
    let ctx = Context::for_model_size(170.0, Drafting::EXACT).expect("context");
    let mu = Scale::new(0.01, Quantity::Length).expect("μ_l");
    let scheme = plan.scheme(Some(&st), mu, &ctx);
    for note in ["scheme: link 3", "II(2,3): link 3"] {
        let points = contour(&scheme, note).unwrap_or_else(|| panic!("{note}"));
        assert_eq!(points.len(), 3, "{note}");
        assert_eq!(hatching(&scheme, note), 9, "{note}");
        assert!(!bar(&scheme, note), "{note} is also a bar");
    }
    // The group II(4,5) takes C as its outer pair, not link 3 with it.
    assert!(contour(&scheme, "II(4,5): link 3").is_none());
    // The force analysis: the group (2, 3) drawn apart carries C on its triangle.
    let sc = session.kin_scales().expect("scales");
    let k = session.force_positions().expect("positions")[0];
    let forces = session.forces(&sc, k).expect("forces");
    let group = forces
        .analysis
        .polygons
        .groups
        .iter()
        .find(|g| contour(&g.scheme, "group: link 3").is_some())
        .expect("the group (2, 3) draws link 3 as its triangle");
    let points = contour(&group.scheme, "group: link 3").expect("triangle");
    assert_eq!(points.len(), 3);
    assert_eq!(hatching(&group.scheme, "group: link 3"), 9);
}

#[test]
fn a_link_with_two_hinges_stays_a_bar() {
    for stem in ["four-bar", "shaper", "v-engine", "slider-crank", "tangent"] {
        let s = scene::load(&root().join(format!("constructions/{stem}.toml"))).expect(stem);
        let session = Session::new(&s, Drafting::EXACT);
        let plan = session
            .positions(session.scale_l().expect("μ_l"))
            .expect("plan");
        let closed = plan
            .figure
            .steps
            .iter()
            .filter(|s| matches!(s.item, Item::Polyline { closed: true, .. }))
            .filter(|s| s.note.contains(": link "))
            .count();
        assert_eq!(closed, 0, "{stem}: a link drawn as a contour");
    }
}
