//! A link's image on the plans is drawn whole, as the textbook draws it (issue 45): a point
//! of the link found by similarity on the line of two images lies on their segment drawn end
//! to end (s₂ at the middle of ab, s₂′ of a′b′), not at the end of a segment from one of them.

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
