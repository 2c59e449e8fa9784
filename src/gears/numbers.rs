//! The drawn rack positions' numbers (seed 000's rack generation, the textbook's figure):
//! each at the outer end of its position's outline, out of the blank; where the ends crowd
//! (a small wheel at a coarse μ_l), carried out on thin lines to a circle beyond them and
//! spread there in the positions' order, as a draftsman fans out leaders.

use crate::construct::{Item, Recorder, Role};
use crate::geom::{DVec2, Segment};

/// Two drawn positions' outer ends nearer than this cannot both carry their numbers there
/// in order (a number, its gap and the next number at the labels' height); the numbers are
/// then spread this far apart along their circle, mm.
const NUMBER_PITCH_MM: f64 = 4.0;
/// How far beyond the farthest end the circle of spread numbers runs, mm.
const NUMBER_OUT_MM: f64 = 6.0;

/// Where each drawn position's number stands, from its outline's outer end (sheet mm, in
/// `drawn`'s order; `None`: no outline drawn): at the end; or, where two ends stand nearer
/// than [`NUMBER_PITCH_MM`], every number on the circle [`NUMBER_OUT_MM`] beyond the
/// farthest end, [`NUMBER_PITCH_MM`] apart about the ends' mean direction, in the order of
/// the ends along the blank. Each with its end.
pub(super) fn places(ends: &[Option<DVec2>]) -> Vec<Option<(DVec2, DVec2)>> {
    let known: Vec<DVec2> = ends.iter().flatten().copied().collect();
    let crowded = known
        .windows(2)
        .any(|w| w[0].distance(w[1]) < NUMBER_PITCH_MM);
    let (Some(first), Some(last), true) = (known.first(), known.last(), crowded) else {
        return ends.iter().map(|e| e.map(|e| (e, e))).collect();
    };
    let radius = known.iter().map(|e| e.length()).fold(0.0, f64::max) + NUMBER_OUT_MM;
    let angle = |p: DVec2| p.y.atan2(p.x);
    // The ends' mean direction, and the way along the blank the positions run.
    let mean = known.iter().map(|e| e.normalize_or_zero()).sum::<DVec2>();
    let way = (angle(*last) - angle(*first)).signum();
    let step = way * NUMBER_PITCH_MM / radius;
    let middle = (known.len() as f64 - 1.0) / 2.0;
    let mut k = 0.0;
    ends.iter()
        .map(|e| {
            let e = (*e)?;
            let at = angle(mean) + (k - middle) * step;
            k += 1.0;
            Some((e, DVec2::from_angle(at) * radius))
        })
        .collect()
}

/// The number `k + 1` of drawn position `i` at `at`, its outline's outer end at `end`
/// (sheet mm, [`places`]): written at the end of a thin line from the end where it stands
/// apart from it.
pub(super) fn number(rec: &mut Recorder, i: usize, k: usize, (end, at): (DVec2, DVec2)) {
    let (item, role) = if at == end {
        (Item::Text(at), Role::Dimension)
    } else {
        (Item::Segment(Segment::new(end, at)), Role::Construction)
    };
    let id = rec.draw(
        format!("the number of rack position {}", i + 1),
        item,
        role,
        &[],
    );
    rec.label(id, (k + 1).to_string(), at, at.normalize_or_zero());
}
