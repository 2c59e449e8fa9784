//! The undercut on the generated tooth: the outline the fillet removed (the involute down to
//! the base circle and the radial line below it) drawn thin and the material removed hatched
//! on both flanks, and the zone of its detail view at a ГОСТ 2.302 enlargement.

use super::detail::{DetailMark, DETAIL_LETTER, DETAIL_MM};
use super::rack::Cutting;
use super::GearError;
use crate::construct::{Item, Recorder, Role};
use crate::geom::{Circle, DVec2};
use crate::scale::Scale;
use std::f64::consts::PI;

/// Spacing of the undercut's hatching where it is read (its detail view, or the figure
/// when there is none), mm.
const UNDERCUT_HATCH_MM: f64 = 1.0;

/// The enlargements of ГОСТ 2.302 (n:1), the smallest first.
const ENLARGEMENTS: [f64; 9] = [2.0, 2.5, 4.0, 5.0, 10.0, 20.0, 40.0, 50.0, 100.0];

/// The zone of the detail view: the circle about the undercut's extent, this much wider.
const DETAIL_MARGIN: f64 = 1.4;

/// The detail view's zone and scale (when the undercut is drawn again enlarged) and the
/// points its names stand at.
type Detail = (Option<(Circle, Scale)>, Vec<(DetailMark, DVec2)>);

/// Draw the undercut of `c` (picture at μ_l = `mu`): `lost` the involute's touching points
/// below the junction (m), the fillet's drawn points from the root up `fi` of which the first
/// `fil_to` are kept below the junction, and the rack states of the drawn positions.
pub(super) fn undercut(
    rec: &mut Recorder,
    (c, mu): (&Cutting, f64),
    lost: &[DVec2],
    (junction, fi, fil_to): (DVec2, &[DVec2], usize),
    drawn_states: &[f64],
) -> Result<Detail, GearError> {
    let mm = |p: DVec2| p / mu;
    let mut detail = None;
    let mut detail_marks = Vec::new();
    // The undercut: uncut, the tooth would follow the involute down to the base circle
    // and the radial line below it; the fillet cuts into that outline from the junction
    // down to where it comes back to the radial line. That outline is drawn thin and
    // the material removed hatched, on both flanks.
    let off_axis = |p: DVec2| p.x.atan2(p.y);
    let edge = off_axis(lost.first().copied().unwrap_or(junction));
    let mut cut = Vec::new();
    let down: Vec<DVec2> = fi[..fil_to].iter().rev().copied().collect();
    for w in down.windows(2) {
        cut.push(w[0]);
        let (a, b) = (off_axis(w[0]), off_axis(w[1]));
        if b >= edge {
            let t = if b > a { (edge - a) / (b - a) } else { 1.0 };
            cut.push(w[0].lerp(w[1], t.clamp(0.0, 1.0)));
            break;
        }
    }
    let mut uncut = vec![junction];
    uncut.extend(lost.iter().rev());
    uncut.extend(cut.last());
    let region: Vec<DVec2> = uncut.iter().chain(cut.iter().rev()).copied().collect();
    // The undercut is a sliver: it is drawn again enlarged, as a detail view of the zone
    // about the right flank's, at the round scale that makes the zone about DETAIL_MM
    // across; the hatching is spaced for the scale it is read at.
    let (lo, hi) = region.iter().fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let radius = 0.5 * (hi - lo).length() * DETAIL_MARGIN;
    let zone = Circle::new(mm(0.5 * (lo + hi)), radius / mu).filter(|z| z.radius > 0.0);
    let enlarged = detail_scale(2.0 * radius).filter(|d| d.value() < mu);
    let mut spacing = UNDERCUT_HATCH_MM;
    if let (Some(zone), Some(scale_d)) = (zone, enlarged) {
        spacing *= scale_d.value() / mu;
        let id = rec.draw(
            "the zone of the undercut's detail view",
            Item::Circle(zone),
            Role::Construction,
            &[],
        );
        let at = zone.center + DVec2::new(1.0, 1.0).normalize() * zone.radius;
        rec.label(id, DETAIL_LETTER, at, DVec2::new(1.0, 1.0));
        detail = Some((zone, scale_d));
        detail_marks = super::detail::marks(c, mu, &zone, junction, fi, &region, drawn_states);
    }
    for side in [1.0, -1.0] {
        let flip = |p: DVec2| mm(DVec2::new(side * p.x, p.y));
        let edge = rec.draw(
            "the outline the undercut removed: the involute to r_b, the radial line",
            Item::Polyline {
                points: uncut.iter().map(|p| flip(*p)).collect(),
                closed: false,
            },
            Role::Construction,
            &[],
        );
        let outline: Vec<DVec2> = region.iter().map(|p| flip(*p)).collect();
        rec.hatching(
            "hatching of the undercut",
            outline,
            // Across the flank (the strokes at ∓45°, short over the narrow region).
            (spacing, -side * PI / 4.0),
            &[edge],
        )?;
    }
    Ok((detail, detail_marks))
}

/// The largest ГОСТ 2.302 enlargement n:1 that draws `size` (m) at most [`DETAIL_MM`] wide,
/// as μ_l = 0.001/n m/mm; `None` when even 2:1 draws it wider.
fn detail_scale(size: f64) -> Option<Scale> {
    ENLARGEMENTS
        .iter()
        .rev()
        .find(|n| size * 1e3 * *n <= DETAIL_MM)
        .and_then(|n| Scale::new(1e-3 / n, crate::scale::Quantity::Length))
}
