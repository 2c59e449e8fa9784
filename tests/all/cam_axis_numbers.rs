//! The numbers of a φ axis read clear of the lines about them (issue 45), on every cam sheet
//! of every cam scene in every language, as the sheet lays them out: no main line (the
//! diagram's curve, given or constructed) passes within [`CURVE_CLEAR_MM`] of a number's
//! box, and no thin line (a chord, a ray, a step of the step graph, its projection) runs
//! into it — but the step graph's vertical at the number's own point, which stands on its
//! tick as the tick does.

use crate::cam_diagrams::{every_cam_sheet, noted};
use crate::plate_model::lines;
use glam::DVec2;
use tmm::construct::Role;

/// The clearance kept from a main line, mm: nearer, an italic digit's foot touches it.
const CURVE_CLEAR_MM: f64 = 0.2;

/// A thin line within this of a number's point's abscissa at both ends runs along its tick,
/// mm.
const OWN_TICK_MM: f64 = 0.05;

/// Fails before, first on cam-cusp's 19 (the steep d²S of the return, issue 45) and, with
/// the curve kept clear, on cam-central's 6 (under the axis in the second row, moved down
/// onto the projection of the chord step 11).
#[test]
fn no_line_strikes_a_phi_axis_number() {
    let mut seen = 0;
    for (at, p, labels) in every_cam_sheet() {
        for l in labels.iter().filter(|l| noted(&p, l, "number of point ")) {
            seen += 1;
            let view = &p.views[l.view];
            let own = |a: DVec2, b: DVec2| {
                (a.x - l.anchor.x).abs() < OWN_TICK_MM && (b.x - l.anchor.x).abs() < OWN_TICK_MM
            };
            for s in view
                .figure
                .steps
                .iter()
                .filter(|s| !l.steps.contains(&s.id))
            {
                let main = matches!(s.role, Role::Given | Role::Result);
                let around = l.rect.inflate(if main { CURVE_CLEAR_MM } else { 0.0 });
                for (a, b) in lines(s) {
                    let (a, b) = (view.to_sheet(a), view.to_sheet(b));
                    assert!(
                        around.segment_inside(a, b).is_none() || (!main && own(a, b)),
                        "{at}: «{}» is struck by «{}»",
                        l.text,
                        s.note
                    );
                }
            }
        }
    }
    assert!(seen > 27 * 60, "{seen} numbers");
}

/// How far a graduation number's middle may stand from its tick's level, mm: the placer's
/// rounding, not a shift to another place.
const LEVEL_MM: f64 = 0.3;

/// The numbers of the γ(φ) or λ(φ) graph's angle axis stand level with their ticks, left of
/// the axis, on every cam sheet as it is laid out (issue 45: on cam-pz5, cam-shock and
/// cam-undercut, whose graph the packer put near the frame, the placer lifted them over their
/// ticks; the graph's block now keeps their room).
#[test]
fn every_angle_graduation_number_stands_level_with_its_tick() {
    let mut seen = 0;
    for (at, p, labels) in every_cam_sheet() {
        for l in labels.iter().filter(|l| noted(&p, l, "tick ")) {
            seen += 1;
            let middle = (l.rect.min + l.rect.max) * 0.5;
            assert!(
                (middle.y - l.anchor.y).abs() < LEVEL_MM && l.rect.max.x <= l.anchor.x,
                "{at}: «{}» at {:?}, its tick's end at {:?}",
                l.text,
                l.rect,
                l.anchor
            );
        }
    }
    assert!(seen >= 80, "{seen} numbers");
}
