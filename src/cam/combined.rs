//! The combined diagram's drawing, one for every construction that reads off it (the
//! minimum radius, the flat face's S(S″), the translating cam's travel): its points K (the
//! motion read off the diagrams at each drawn point), its S axis and the closed curve through
//! the points.

use super::diagrams::{read_motion, CamDiagrams};
use super::law::Shock;
use super::motion::{on_break, FollowerMotion, Point};
use super::CamSpec;
use crate::construct::{Item, Recorder, Role, StepId};
use crate::geom::DVec2;
use crate::scale::Scale;

/// The combined diagram's closed curve through the points K (one per drawn point, in their
/// order), drawn as a French curve follows them — smooth, where a polyline would show a
/// corner at every point — with a corner kept where the law makes one: at a point on a
/// break of d²S/dφ² ([`on_break`]; the slope dS/dS′ = S′/S″ changes sign there), and at a
/// phase's ends where dS/dφ jumps (a rigid shock), the jump drawn straight at its S.
pub(super) fn smooth_loop(
    rec: &mut Recorder,
    (spec, points): (&CamSpec, &[Point]),
    ks: &[DVec2],
    note: &str,
    deps: &[StepId],
) {
    // One point where two coincide on the paper (a phase's end and the next phase's start
    // at dS/dφ = 0): the curve passes it once, smoothly.
    let same = rec.tolerances().flatten_mm;
    let mut kept: Vec<(DVec2, bool)> = Vec::with_capacity(ks.len());
    for (k, p) in ks.iter().zip(points) {
        let law = if p.phase == 0 { spec.rise } else { spec.ret };
        let corner = on_break(spec, p) || (law.shock() == Shock::Rigid && (p.k == 0 || p.last));
        match kept.last_mut() {
            Some((q, c)) if q.distance(*k) <= same => *c |= corner,
            _ => kept.push((*k, corner)),
        }
    }
    if kept.len() > 1 && kept[0].0.distance(kept[kept.len() - 1].0) <= same {
        if let Some((_, c)) = kept.pop() {
            kept[0].1 |= c;
        }
    }
    let ks: Vec<DVec2> = kept.iter().map(|(k, _)| *k).collect();
    let corners: Vec<usize> = (0..kept.len()).filter(|&i| kept[i].1).collect();
    if corners.is_empty() {
        rec.draw(
            note,
            Item::Curve {
                points: ks,
                closed: true,
            },
            Role::Result,
            deps,
        );
        return;
    }
    // From each corner on round the loop to the next.
    for (j, &a) in corners.iter().enumerate() {
        let b = corners[(j + 1) % corners.len()];
        let len = (b + ks.len() - a - 1) % ks.len() + 1;
        let run: Vec<DVec2> = (0..=len).map(|k| ks[(a + k) % ks.len()]).collect();
        rec.draw(
            note,
            Item::Curve {
                points: run,
                closed: false,
            },
            Role::Result,
            deps,
        );
    }
}

/// The S axis of a combined diagram (a diagram's axis: thin and solid, as its abscissa
/// [`abscissa`]): from below the centre found on it (`depth` mm under
/// B₀: the drawn r_min) to above the stroke, labelled.
pub(super) fn s_axis(rec: &mut Recorder, spec: &CamSpec, mu: Scale, depth: f64) -> StepId {
    let top = DVec2::new(0.0, mu.to_mm(spec.stroke) + 12.0);
    let ax = rec.draw(
        "S axis",
        Item::Vector {
            from: DVec2::new(0.0, -depth - 10.0),
            to: top,
        },
        Role::Construction,
        &[],
    );
    rec.label(ax, "S", top, DVec2::new(1.0, 0.0));
    ax
}

/// The abscissa of a combined diagram through B₀ (S = 0), across the points `ks` with room
/// past them, labelled `name` at its arrow (dS/dφ: the diagram's other quantity, without
/// which the reader has a curve beside one axis).
pub(super) fn abscissa(rec: &mut Recorder, ks: &[DVec2], name: &str) -> StepId {
    let (lo, hi) = ks
        .iter()
        .fold((0.0f64, 0.0f64), |(lo, hi), k| (lo.min(k.x), hi.max(k.x)));
    let end = DVec2::new(hi + 12.0, 0.0);
    let ax = rec.draw(
        format!("{name} axis"),
        Item::Vector {
            from: DVec2::new(lo - 10.0, 0.0),
            to: end,
        },
        Role::Construction,
        &[],
    );
    rec.label(ax, name, end, DVec2::new(0.0, -1.0));
    ax
}

/// The points of a combined diagram: `at` of the motion read at each of the `n` points.
pub(super) fn combined(
    d: &CamDiagrams,
    n: usize,
    at: impl Fn(FollowerMotion) -> DVec2,
) -> Vec<DVec2> {
    (0..n).map(|i| at(read_motion(d, i))).collect()
}
