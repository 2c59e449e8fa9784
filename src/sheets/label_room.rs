//! The room a view's labels take beside its figure, kept free in its block so that they are
//! not written over the next block: long joint labels ([`long_joint_labels`]) and labels
//! written outward at the figure's edge ([`edge_labels`]). Figure mm, y up.

use crate::construct::{Figure, StepId};
use crate::geom::DVec2;
use crate::plate::text::measure;
use crate::plate::{View, LABEL_GAP_MM, LABEL_HEIGHT_MM};

/// A joint label longer than this is given room beside its point in its block, mm (a shorter
/// one fits the block's label margin or the gap between blocks).
const LONG_LABEL_MM: f64 = 12.0;

/// Line length inside a label's box below which the box counts as clear, mm.
const CLEAR_OF_LINES_MM: f64 = 0.5;

/// `figure` with its long joint labels' rooms kept: each label is written on the side of its
/// point its room is on (its steps' labels point there: the placer tries that side first, the
/// six-bar's 10′ `p ≡ b ≡ c ≡ s₃ ≡ e ≡ s₄` written over the plan before it, issue 45), and the
/// box of the rooms ([`long_joint_labels`]).
pub(super) fn with_long_joint_labels(mut figure: Figure) -> (Figure, Option<(DVec2, DVec2)>) {
    let rooms = long_joint_labels(&figure);
    for (steps, side) in rooms.iter().flat_map(|(_, sides)| sides) {
        let toward = DVec2::new(*side, 0.0);
        for s in figure.steps.iter_mut().filter(|s| steps.contains(&s.id)) {
            if let Some(l) = s.label.as_mut() {
                l.toward = toward;
            }
        }
    }
    (figure, rooms.map(|(room, _)| room))
}

/// The steps of a long joint label and the side of its point its room is on (+1 right, −1
/// left).
type Side = (Vec<StepId>, f64);

/// The box of `figure`'s long joint labels, each on the side of its point that the
/// figure's lines leave clear, and of two clear sides (or two struck) the one where it
/// reaches least past the figure's bounds (figure mm, y up), with each label's side; `None`
/// when it has none. A label at a point near the figure's edge, with the figure's lines on
/// its inner side (the reactions `R₃₋₄ ≡ R₄₋₅` at the slide block, the load G₄ under it), is
/// given its room outside.
fn long_joint_labels(figure: &Figure) -> Option<((DVec2, DVec2), Vec<Side>)> {
    let (lo, hi) = figure.bounds()?;
    let gap = 2.0 * LABEL_GAP_MM;
    View::joint_labels(figure)
        .into_iter()
        .filter(|(_, _, size, _)| size.x > LONG_LABEL_MM)
        .map(|(at, _, size, steps)| {
            let half = size.y * 0.5 + LABEL_GAP_MM;
            let room = |x0: f64| {
                (
                    DVec2::new(x0, at.y - half),
                    DVec2::new(x0 + size.x, at.y + half),
                )
            };
            let (right, left) = (room(at.x + gap), room(at.x - gap - size.x));
            let struck =
                |(a, b): (DVec2, DVec2)| View::line_length_in(figure, a, b) > CLEAR_OF_LINES_MM;
            let past_right = (right.1.x - hi.x).max(0.0);
            let past_left = (lo.x - left.0.x).max(0.0);
            let (room, side) = match (struck(right), struck(left)) {
                (false, true) => (right, 1.0),
                (true, false) => (left, -1.0),
                _ if past_right <= past_left => (right, 1.0),
                _ => (left, -1.0),
            };
            (room, vec![(steps, side)])
        })
        .reduce(|((a, b), mut s), ((c, d), t)| {
            s.extend(t);
            ((a.min(c), b.max(d)), s)
        })
}

/// The box of every label of `figure` whose text `keep` takes, set beside its anchor in its
/// own direction, a label's gap from it (where the placer tries it first), where any such box
/// reaches past the figure's bounds; `None` when none does. A chart's axis numbers, written
/// left of their ticks, stand outside the drawing by their width.
pub(super) fn edge_labels(figure: &Figure, keep: impl Fn(&str) -> bool) -> Option<(DVec2, DVec2)> {
    let (lo, hi) = figure.bounds()?;
    let boxes: Vec<(DVec2, DVec2)> = figure
        .steps
        .iter()
        .filter_map(|s| s.label.as_ref())
        .filter(|l| keep(&l.text))
        .filter_map(|l| {
            let toward = l.toward.try_normalize()?;
            let e = measure(&l.text, LABEL_HEIGHT_MM);
            let half = (e.max - e.min) * 0.5;
            let reach = LABEL_GAP_MM + toward.x.abs() * half.x + toward.y.abs() * half.y;
            let centre = l.anchor + toward * reach;
            Some((centre - half, centre + half))
        })
        .collect();
    boxes
        .iter()
        .any(|(a, b)| a.cmplt(lo).any() || b.cmpgt(hi).any())
        .then(|| {
            boxes
                .into_iter()
                .fold((lo, hi), |(l, h), (a, b)| (l.min(a), h.max(b)))
        })
}
