//! The force sheets' drawings predicted from the twin (what sizes μ_l) against the drawings
//! constructed, over random mechanisms of every pair of dyad kinds with random loads.

use super::super::polygons::{drawings, polygons, ARROW_MM};
use super::{case, spec};
use crate::linkage::proptests::gen;
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, max_global_rejects: 1 << 20, ..ProptestConfig::default() })]

    /// Each group's drawing and the driving link's, predicted from the twin before any is
    /// constructed (what sizes μ_l), take the room the constructed drawing takes but for the
    /// arrows the construction moves past another at a point it finds crowded, each by one
    /// arrow's length: a drawn element missing from the prediction, or one it invents,
    /// differs by as much as the mechanism's size (hundreds of mm at μ_l 0,001).
    #[test]
    fn the_drawings_predicted_from_the_twin_take_the_room_of_the_constructed(
        (m, phi) in gen::mechanism(),
        masses in proptest::collection::vec((0.1..20.0f64, 0.0..0.5f64), 4),
        f5 in (1.0..500.0f64, -3.2..3.2f64),
        gear in proptest::option::of(-3.2..3.2f64),
    ) {
        let spec = spec(&masses, f5, gear);
        let c = case(&m, phi, &spec)?;
        let pol = polygons(&c.board(), &c.lg, &spec.drive)
            .map_err(|(g, e)| TestCaseError::fail(format!("group {g}: {e}")))?;
        let predicted = drawings(&c.prog, &c.pose, &c.le, &c.twin, &spec.drive);
        let drawn: Vec<_> = pol.groups.iter().map(|g| &g.scheme).chain([&pol.driver.scheme]).collect();
        prop_assert_eq!(drawn.len(), predicted.len());
        for (f, p) in drawn.into_iter().zip(&predicted) {
            let (lo, hi) = f.bounds().expect("a drawing");
            let size = p.size_at(c.mu_l);
            let off = (size - (hi - lo)).abs().max_element();
            prop_assert!(off <= 4.0 * ARROW_MM, "{}: drawn {} predicted {}", f.title, hi - lo, size);
        }
    }
}
