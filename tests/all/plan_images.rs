//! A link's image on the plans is drawn whole, as the textbook draws it (issue 45): a point
//! of the link found by similarity on the line of two images lies on their segment drawn end
//! to end (s₂ at the middle of ab, s₂′ of a′b′), not at the end of a segment from one of them;
//! and a component a direction line finds is drawn as the vector it is (b → b₃, k → b₃′).

use tmm::construct::Item;
use tmm::scale::Lang;
use tmm::scene::PlateKind;
use tmm::study::Session;
use tmm::Drafting;

#[test]
fn the_coupler_image_runs_from_a_to_b_with_its_centre_of_mass_at_the_middle() {
    // The six-bar's S₂ is the middle of its coupler AB: on every plan the similarity segment
    // of S₂ is a b whole, its middle the image s₂. Before, it ran from a to s₂ only (the
    // position-1 acceleration plan's a′ s₂′ with s₂′ b′ missing).
    let s = crate::support::scene("six-bar");
    let session = Session::new(&s, Drafting::EXACT);
    let plates = tmm::build(&session, PlateKind::Kinematics, Lang::Ru).expect("sheets");
    let mut plans = 0;
    for view in plates.iter().flat_map(|p| &p.views) {
        let steps = &view.figure.steps;
        let Some(segment) = steps.iter().find_map(|s| match &s.item {
            Item::Segment(g) if s.note.starts_with("similarity: S_2 ") => Some(*g),
            _ => None,
        }) else {
            continue;
        };
        let image = steps
            .iter()
            .filter_map(|s| s.label.as_ref())
            .find(|l| l.text.split(" ≡ ").any(|n| n.starts_with("s_2")))
            .map(|l| l.anchor)
            .unwrap_or_else(|| panic!("{}: no s₂", view.figure.title));
        let middle = (segment.from + segment.to) / 2.0;
        assert!(
            middle.distance(image) < 1e-9 * (1.0 + segment.length()),
            "{}: s₂ at {image}, the segment {:?}–{:?}",
            view.figure.title,
            segment.from,
            segment.to
        );
        plans += 1;
    }
    // Eleven velocity plans (none at position 6) and the acceleration plan of position 1.
    assert!(plans >= 12, "{plans} plans");
}

/// The anchor of the label naming `name` on a plan (alone or joined by "≡").
fn image_at(view: &tmm::plate::View, name: &str) -> Option<tmm::geom::DVec2> {
    (view.figure.steps.iter())
        .filter_map(|s| s.label.as_ref())
        .find(|l| l.text.split(" ≡ ").any(|n| n == name))
        .map(|l| l.anchor)
}

/// Whether the plan draws a vector from `from` to `to` (its tail and head within 1e-9 mm).
fn has_vector(view: &tmm::plate::View, from: tmm::geom::DVec2, to: tmm::geom::DVec2) -> bool {
    (view.figure.steps.iter()).any(|s| match s.item {
        Item::Vector { from: f, to: t } => f.distance(from) < 1e-9 && t.distance(to) < 1e-9,
        _ => false,
    })
}

#[test]
fn the_relative_components_are_vectors_from_their_base_to_the_image() {
    // The shaper's plans add up V_B3 = V_B2 + V_B3B2 and V_D5 = V_D + V_D5D (the polygon's
    // b → b₃ and d → d₅), a_B3 = a_n + a_τ = a_B2 + a_k + a_r (n₃ → b₃′ and k → b₃′), as the
    // seed draws them: each component an arrow to the image it finds. Before, the direction
    // lines through b, d, n₃ and k were drawn, their components not.
    let s = crate::support::scene("shaper");
    let session = Session::new(&s, Drafting::EXACT);
    let plates = tmm::build(&session, PlateKind::Kinematics, Lang::Ru).expect("sheets");
    let (mut velocity, mut acceleration) = (0, 0);
    for view in plates.iter().flat_map(|p| &p.views) {
        let caption = view.caption.clone().unwrap_or_default();
        let pairs: &[(&str, &str)] = if caption.starts_with("Пол.") {
            velocity += 1;
            &[("b", "b_{3}"), ("d", "d_{5}")]
        } else if caption.starts_with("План ускорений") {
            acceleration += 1;
            &[("n_3", "b_{3}′"), ("k", "b_{3}′"), ("d′", "d_{5}′")]
        } else {
            continue;
        };
        for (from, to) in pairs {
            let (Some(a), Some(b)) = (image_at(view, from), image_at(view, to)) else {
                panic!("{caption}: no {from} or {to}");
            };
            // A component shorter than its head, or ending at the pole, is not drawn.
            let head = tmm::construct::THIN_HEAD_MM;
            if a.distance(b) >= head && b.length() >= head {
                assert!(has_vector(view, a, b), "{caption}: no vector {from} → {to}");
            }
        }
    }
    assert!(
        (velocity, acceleration) >= (12, 2),
        "{velocity}, {acceleration}"
    );
}
