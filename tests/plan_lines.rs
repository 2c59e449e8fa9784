//! The line types of the kinematic sheet, as a draughtsman draws them (ГОСТ 2.303, issue 19):
//! on a plan the vectors of the points nothing is built on (the centres of mass) thin, the
//! structural ones main lines, so that the vectors meeting at the pole stay apart; on the plan
//! of positions only position 1 (the one the letters name) in main lines; the pole distance
//! H of a chord-method diagram dimensioned under the fan of rays, clear of them.

use std::path::PathBuf;
use tmm::construct::{Drafting, Item, Role};
use tmm::geom::DVec2;
use tmm::plate::{Plate, View};
use tmm::scale::Lang;
use tmm::scene::PlateKind;
use tmm::study::Session;

fn sheets_of(scene: &str) -> Vec<Plate> {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("constructions/{scene}.toml"));
    let s = tmm::load(&path).unwrap_or_else(|e| panic!("{scene}: {e}"));
    let kind = PlateKind::parse("kinematics").expect("a plate kind");
    tmm::build(&Session::new(&s, Drafting::EXACT), kind, Lang::Ru)
        .unwrap_or_else(|e| panic!("{scene}: {e}"))
}

fn views(scene: &str) -> Vec<View> {
    sheets_of(scene).into_iter().flat_map(|p| p.views).collect()
}

fn captioned(views: &[View], start: &str) -> Vec<View> {
    views
        .iter()
        .filter(|v| v.caption.as_deref().is_some_and(|c| c.starts_with(start)))
        .cloned()
        .collect()
}

/// The role of the vector `image <label>` of a plan.
fn image_role(v: &View, label: &str) -> Option<Role> {
    let note = format!("image {label}");
    v.figure
        .steps
        .iter()
        .find(|s| s.note == note && matches!(s.item, Item::Vector { .. }))
        .map(|s| s.role)
}

#[test]
fn centres_of_mass_are_thin_vectors_and_the_structural_points_main_ones() {
    let all = views("six-bar");
    let plans: Vec<View> = [captioned(&all, "Пол. "), captioned(&all, "План ускорений")].concat();
    assert!(plans.len() >= 12, "{} plans", plans.len());
    for v in &plans {
        let caption = v.caption.clone().unwrap_or_default();
        let prime = if caption.starts_with("План") {
            "′"
        } else {
            ""
        };
        for s in ["s_2", "s_3", "s_4"] {
            let role = image_role(v, &format!("{s}{prime}"));
            assert_eq!(role, Some(Role::Construction), "{caption}: {s}");
        }
        // C carries group 4–5: a structural point, drawn with the main line.
        for p in ["a", "b", "c", "e"] {
            let role = image_role(v, &format!("{p}{prime}"));
            assert_eq!(role, Some(Role::Result), "{caption}: {p}");
        }
    }
}

#[test]
fn only_position_one_is_drawn_in_main_lines_on_the_plan_of_positions() {
    for scene in ["six-bar", "shaper", "four-bar"] {
        let all = views(scene);
        let plan = captioned(&all, "План положений");
        assert_eq!(plan.len(), 1, "{scene}");
        let links: Vec<_> = plan[0]
            .figure
            .steps
            .iter()
            .filter(|s| s.note.starts_with("position ") && s.note.ends_with(": crank"))
            .collect();
        assert!(links.len() >= 12, "{scene}: {} cranks", links.len());
        for s in links {
            let want = if s.note == "position 1: crank" {
                Role::Given
            } else {
                Role::Construction
            };
            assert_eq!(s.role, want, "{scene}: {}", s.note);
        }
    }
}

/// Whether the segments `a`–`b` and `c`–`d` cross.
fn cross(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let side = |p: DVec2, q: DVec2, r: DVec2| (q - p).perp_dot(r - p);
    side(a, b, c) * side(a, b, d) < 0.0 && side(c, d, a) * side(c, d, b) < 0.0
}

#[test]
fn the_pole_distance_is_dimensioned_clear_of_the_rays() {
    let mut checked = 0;
    for scene in ["shaper", "six-bar", "slider-crank", "v-engine", "four-bar"] {
        for v in views(scene) {
            let steps = &v.figure.steps;
            for dim in steps.iter().filter(|s| s.note.starts_with("pole distance")) {
                let Item::Dimension { from, to, offset } = dim.item else {
                    panic!("{scene}: {} is not a dimension", dim.note);
                };
                let n = (to - from).normalize().perp() * offset;
                let line = (from + n, to + n);
                // The rays of the pole the dimension belongs to start at `from`.
                let rays: Vec<_> = steps
                    .iter()
                    .filter_map(|s| match s.item {
                        Item::Segment(g) if s.note.starts_with("ray ") && g.from == from => Some(g),
                        _ => None,
                    })
                    .collect();
                assert!(rays.len() >= 6, "{scene}: {} rays", rays.len());
                for r in rays {
                    assert!(
                        !cross(line.0, line.1, r.from, r.to),
                        "{scene}: a ray crosses the dimension line of {}",
                        dim.note
                    );
                }
                // The text over the line (3.5 mm high) is clear of the fan too: the lowest
                // ray ends at least 5 mm above the dimension line.
                let lowest = steps
                    .iter()
                    .filter_map(|s| match s.item {
                        Item::Segment(g) if s.note.starts_with("ray ") && g.from == from => {
                            Some(g.to.y)
                        }
                        _ => None,
                    })
                    .fold(f64::INFINITY, f64::min);
                assert!(lowest - line.0.y >= 5.0, "{scene}: {}", dim.note);
                checked += 1;
            }
        }
    }
    // H₁ and H₂ of four diagrams, H_ω of the shaper's and the four-bar's rockers.
    assert!(checked >= 8, "{checked} pole distances");
}
