//! The pen a group draws its links with ([`Pen`]) and its two rules for a plan of positions:
//! a bar that joins two hinges of a link drawn as its contour is left out ([`covers`],
//! [`super::rigid`]), and a further position's line begins at its crowded pivot's clearance
//! ([`trim`], [`trim_contour`]; where the clearances come from: [`super::fan`]).

use crate::construct::{Item, Recorder, Role};
use crate::geom::{DVec2, Segment};

/// Hinges closer than this to a bar's end are its end, mm (the bar is drawn from the same
/// numbers: only rounding parts them); a pivot of the plan's fans likewise ([`super::fan`]).
pub(super) const AT_MM: f64 = 1e-6;

/// What a group draws its links with: the recorder, the drawing's role and note, and the
/// points it puts its link numbers at and the joints it draws.
pub(super) struct Pen<'r> {
    /// The recorder.
    pub rec: &'r mut Recorder,
    /// The role of every item.
    pub role: Role,
    /// The note every item's step starts with.
    pub note: &'r str,
    /// Per link number drawn, a point to put its number at.
    pub anchors: Vec<(u32, DVec2)>,
    /// The joints to draw.
    pub joints: Vec<usize>,
    /// The links drawn as their contour ([`super::rigid`]), each with its hinges' points:
    /// a bar between two of them is not drawn.
    pub rigid: Vec<(u32, Vec<DVec2>)>,
    /// The crowded fixed pivots and the radius their lines begin at ([`super::fan`]).
    pub clear: &'r [(DVec2, f64)],
}

impl Pen<'_> {
    /// Link `l` as a bar from `from` to `to` (nothing when it joins two hinges of a link
    /// drawn as its contour).
    pub fn link(&mut self, l: u32, from: DVec2, to: DVec2) {
        if covers(&self.rigid, l, (from, to)) {
            return;
        }
        let Some((from, to)) = trim(self.clear, from, to) else {
            return;
        };
        self.rec.draw(
            format!("{}: link {l}", self.note),
            Item::Segment(Segment::new(from, to)),
            self.role,
            &[],
        );
    }

    /// Link `l` as a slider at `at`, along `angle`.
    pub fn slider(&mut self, l: u32, at: DVec2, angle: f64) {
        self.rec.draw(
            format!("{}: slider {l}", self.note),
            Item::Slider { at, angle },
            self.role,
            &[],
        );
    }
}

/// Whether the bar `from`–`to` of link `l` joins two hinges of a link of `placed` (each link's
/// number and its hinges' points, [`super::rigid::RigidLink::placed`]): its contour draws it.
pub(super) fn covers(placed: &[(u32, Vec<DVec2>)], l: u32, (from, to): (DVec2, DVec2)) -> bool {
    let at = |points: &[DVec2], x: DVec2| points.iter().any(|p| p.distance(x) <= AT_MM);
    placed
        .iter()
        .any(|(link, points)| *link == l && at(points, from) && at(points, to))
}

/// The line `from`–`to` begun at its pivot's clearance (`clear`,
/// [`super::fan::clearances`]) at either end that is a cleared pivot; `None` when the line
/// is shorter than the clearance.
pub(super) fn trim(clear: &[(DVec2, f64)], from: DVec2, to: DVec2) -> Option<(DVec2, DVec2)> {
    let back = |at: DVec2, other: DVec2| match radius_at(clear, at) {
        Some(r) => (other - at).try_normalize().map(|u| at + u * r),
        None => Some(at),
    };
    let (a, b) = (back(from, to)?, back(to, from)?);
    ((b - a).dot(to - from) > 0.0).then_some((a, b))
}

/// A closed contour through `points` opened at a cleared pivot among them: the open line
/// from the clearance towards the next hinge, round the contour, to the clearance towards
/// the previous one. `None` when no vertex is a cleared pivot.
pub(super) fn trim_contour(clear: &[(DVec2, f64)], points: &[DVec2]) -> Option<Vec<DVec2>> {
    let n = points.len();
    let (i, r) = (0..n).find_map(|i| radius_at(clear, points[i]).map(|r| (i, r)))?;
    let v = points[i];
    let toward = |p: DVec2| v + (p - v).normalize_or_zero() * r.min(v.distance(p));
    let mut open = vec![toward(points[(i + 1) % n])];
    open.extend((1..n).map(|s| points[(i + s) % n]));
    open.push(toward(points[(i + n - 1) % n]));
    Some(open)
}

/// The clearance of the pivot at `at`, if it is a cleared one.
fn radius_at(clear: &[(DVec2, f64)], at: DVec2) -> Option<f64> {
    clear
        .iter()
        .find(|(p, _)| p.distance(at) <= AT_MM)
        .map(|(_, r)| *r)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_and_contours_begin_at_the_clearance() {
        let d = DVec2::new(10.0, 0.0);
        let clear = [(d, 4.0)];
        let (a, b) = trim(&clear, d, DVec2::new(10.0, -20.0)).expect("long enough");
        assert!((a - DVec2::new(10.0, -4.0)).length() < 1e-12);
        assert_eq!(b, DVec2::new(10.0, -20.0));
        // Reversed, the far end is the pivot's.
        let (a, b) = trim(&clear, DVec2::new(10.0, -20.0), d).expect("long enough");
        assert_eq!(a, DVec2::new(10.0, -20.0));
        assert!((b - DVec2::new(10.0, -4.0)).length() < 1e-12);
        assert!(trim(&clear, d, DVec2::new(12.0, 0.0)).is_none());
        assert_eq!(
            trim(&clear, DVec2::ZERO, DVec2::X),
            Some((DVec2::ZERO, DVec2::X))
        );
        let tri = [DVec2::new(0.0, -20.0), d, DVec2::new(20.0, -20.0)];
        let open = trim_contour(&clear, &tri).expect("D is a vertex");
        assert_eq!(open.len(), 4);
        assert_eq!(open[1], tri[2]);
        assert_eq!(open[2], tri[0]);
        assert!((open[0].distance(d) - 4.0).abs() < 1e-12);
        assert!((open[3].distance(d) - 4.0).abs() < 1e-12);
        assert!(trim_contour(&[], &tri).is_none());
    }
}
