//! A link that carries three or more hinges — a ternary link, the six-bar's rocker DBC that
//! carries C for the next group — drawn as ГОСТ 2.770 and the textbook draw it: a closed
//! contour through its hinges, hatched in its corners, so that every hinge is seen to lie on
//! the one rigid body (a bar between two of them would leave the third floating). The rule
//! is one for every drawing of a mechanism (the structural scheme, the plan of positions,
//! the groups of the force analysis): [`rigid_links`] says which links, [`draw_rigid`] draws
//! one, and the bars a group would draw between two of its hinges are left out
//! ([`super::pen::covers`]).

use super::built::Built;
use super::pen::trim_contour;
use super::program::Program;
use crate::construct::{Item, Recorder, Role};
use crate::geom::{DVec2, Segment};

/// The size of a corner's hatching along each of its sides, mm.
const CORNER_MM: f64 = 5.0;
/// A corner's hatching takes at most this share of its shorter side.
const CORNER_SHARE: f64 = 0.3;
/// The strokes of a corner's hatching, as fractions of its size from the vertex: the first
/// clear of the hinge's circle.
const STROKES: [f64; 3] = [0.55, 0.775, 1.0];
/// A link with three or more hinges.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct RigidLink {
    /// Its number.
    pub link: u32,
    /// Its hinges (program point indices, ascending): the points where it is paired with
    /// another link or with the frame by a revolute pair.
    pub hinges: Vec<usize>,
}

impl RigidLink {
    /// Its number and its hinges' points in the position `b`.
    pub fn placed(&self, b: &Built) -> (u32, Vec<DVec2>) {
        (self.link, self.hinges.iter().map(|&k| b.p[k]).collect())
    }
}

/// The links of `prog` with three or more hinges, by link number: a hinge of a link is a
/// point it lies on together with another link or the frame ([`Program::links_of`]) — a
/// revolute pair; a centre of mass or a point of a guide's direction lies on one link only.
pub(super) fn rigid_links(prog: &Program) -> Vec<RigidLink> {
    let mut hinges: Vec<Vec<usize>> = vec![Vec::new(); prog.link_count.max(1)];
    for k in 0..prog.names.len() {
        let links = prog.links_of(k);
        if links.len() < 2 {
            continue;
        }
        for l in links.into_iter().filter(|l| *l != 0) {
            if let Some(h) = hinges.get_mut(l) {
                h.push(k);
            }
        }
    }
    hinges
        .into_iter()
        .enumerate()
        .filter(|(_, h)| h.len() >= 3)
        .map(|(l, hinges)| RigidLink {
            link: l as u32,
            hinges,
        })
        .collect()
}

/// The hinges' points in the order of the contour: about their centroid by angle (a convex
/// contour for three; a star-shaped one for more), or, when they lie on one line, along it.
fn contour(points: &[DVec2]) -> (Vec<DVec2>, bool) {
    let c = points.iter().fold(DVec2::ZERO, |s, p| s + *p) / points.len().max(1) as f64;
    let mut v = points.to_vec();
    v.sort_by(|a, b| (*a - c).to_angle().total_cmp(&(*b - c).to_angle()));
    let spread = v.iter().map(|p| p.distance(c)).fold(0.0, f64::max);
    let area2: f64 = (0..v.len())
        .map(|i| (v[i] - c).perp_dot(v[(i + 1) % v.len()] - c))
        .sum();
    if area2.abs() > 1e-6 * spread * spread {
        return (v, true);
    }
    // One line: the bar through them, from end to end.
    let e = v
        .iter()
        .map(|p| *p - c)
        .max_by(|a, b| a.length().total_cmp(&b.length()))
        .and_then(DVec2::try_normalize)
        .unwrap_or(DVec2::X);
    v.sort_by(|a, b| a.dot(e).total_cmp(&b.dot(e)));
    (v, false)
}

/// Draw `rigid` at the position `b` with `role` (its step notes start with `note`): the
/// closed contour through its hinges and, drawn with the main line (the scheme, position 1
/// of the plan, a group of the force analysis), the hatching of each corner (thin strokes
/// across the corner, [`CORNER_MM`] along its sides, at most [`CORNER_SHARE`] of the
/// shorter); the further positions of a plan, drawn thin, keep the contour alone (twelve
/// hatchings at a common pivot would print as a blot), opened at a crowded pivot of `clear`
/// ([`super::fan`]). Hinges on one line are drawn as the bar through them.
pub(super) fn draw_rigid(
    rec: &mut Recorder,
    rigid: &RigidLink,
    b: &Built,
    (role, note): (Role, &str),
    clear: &[(DVec2, f64)],
) {
    let points: Vec<DVec2> = rigid.hinges.iter().map(|&k| b.p[k]).collect();
    let (points, closed) = contour(&points);
    let l = rigid.link;
    let opened = closed.then(|| trim_contour(clear, &points)).flatten();
    let id = rec.draw(
        format!("{note}: link {l}"),
        Item::Polyline {
            closed: closed && opened.is_none(),
            points: opened.unwrap_or_else(|| points.clone()),
        },
        role,
        &[],
    );
    if !closed || role != Role::Given {
        return;
    }
    let n = points.len();
    for i in 0..n {
        let (v, prev, next) = (points[i], points[(i + n - 1) % n], points[(i + 1) % n]);
        let (Some(u1), Some(u2)) = ((prev - v).try_normalize(), (next - v).try_normalize()) else {
            continue;
        };
        let h = CORNER_MM.min(CORNER_SHARE * v.distance(prev).min(v.distance(next)));
        for t in STROKES {
            rec.draw(
                format!("{note}: link {l}: corner hatching"),
                Item::Segment(Segment::new(v + u1 * (h * t), v + u2 * (h * t))),
                Role::Hatch,
                &[id],
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hinges_on_one_line_make_a_bar_and_others_a_closed_contour() {
        let line = [
            DVec2::new(0.0, 0.0),
            DVec2::new(20.0, 10.0),
            DVec2::new(10.0, 5.0),
        ];
        let (v, closed) = contour(&line);
        assert!(!closed);
        assert_eq!(v, vec![line[0], line[2], line[1]]);
        let triangle = [
            DVec2::new(0.0, 0.0),
            DVec2::new(30.0, 0.0),
            DVec2::new(20.0, -12.0),
        ];
        let (v, closed) = contour(&triangle);
        assert!(closed);
        assert_eq!(v.len(), 3);
        // Counter-clockwise about the centroid: the signed area is positive.
        let area2: f64 = (0..3).map(|i| v[i].perp_dot(v[(i + 1) % 3])).sum();
        assert!((area2 - 360.0).abs() < 1e-9, "{area2}");
    }
}
