//! Where a ring's disc stands on the scheme, and what may not run through it. A ring is drawn
//! as its rim in its plane and its disc set off the plane to one side, down to its hub; a
//! shaft on another axis — a satellite's axle, turning inside the ring — never runs through
//! the disc between its hub and its rim.

use super::{WheelMark, FIXING_MM};
use crate::gears::train::Train;

/// Whether a shaft at height `y` that reaches the x's where `reach` holds crosses ring `m`'s
/// disc set `cup` off its plane (clear of its hub by [`FIXING_MM`], where nested shafts pass).
fn crosses(m: &WheelMark, cup: f64, y: f64, reach: impl Fn(f64) -> bool) -> bool {
    let (lo, hi) = m.extent();
    lo + FIXING_MM < y && y < hi - FIXING_MM && reach(m.x + cup)
}

/// Whether shaft `k` at height `y`, reaching the x's where `reach` holds, runs through the
/// disc of a ring on another shaft.
pub(super) fn runs_through_ring(
    train: &Train,
    marks: &[WheelMark],
    k: usize,
    y: f64,
    reach: impl Fn(f64) -> bool,
) -> bool {
    (train.wheels.iter().zip(marks))
        .filter(|(w, _)| w.shaft != k)
        .any(|(_, m)| m.cup.is_some_and(|cup| crosses(m, cup, y, &reach)))
}

/// Each ring's disc set on the side of its plane that no other shaft runs through: the right,
/// else the left; the right where both are crossed. A shaft reaches from its external wheels'
/// planes to the carrier's arm, for the carrier and for the satellites' axles that run to it
/// (`arm`); each at its drawn height (`drawn_y`).
pub(super) fn set_cups(marks: &mut [WheelMark], train: &Train, arm: Option<f64>, drawn_y: &[f64]) {
    let reach: Vec<(f64, f64)> = (0..train.shafts.len())
        .map(|k| {
            let to_arm = train.carrier == Some(k) || train.is_satellite(k);
            (train.wheels.iter().zip(marks.iter()))
                .filter(|(w, m)| w.shaft == k && m.cup.is_none())
                .map(|(_, m)| m.x)
                .chain(arm.filter(|_| to_arm))
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
                    (l.min(x), h.max(x))
                })
        })
        .collect();
    for (w, mark) in marks.iter_mut().enumerate() {
        let Some(cup) = mark.cup else { continue };
        let crossed = |cup: f64| {
            (reach.iter().zip(drawn_y).enumerate())
                .filter(|(k, _)| *k != train.wheels[w].shaft)
                .any(|(_, (&(a, b), &y))| crosses(mark, cup, y, |x| a < x && x < b))
        };
        if crossed(cup) && !crossed(-cup) {
            mark.cup = Some(-cup);
        }
    }
}
