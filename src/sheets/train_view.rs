//! A train's view on the gear sheet: its velocity triangles with the plan's μ_ω written past
//! the left end of the plan's reading line, over the scheme, and, when that plan cannot read
//! the output ([`crate::gears::SlowLinks`]), the slow links' own picture beside the first at
//! the same heights, its heading over its plan: its links, its μ_v and its μ_ω, the scales
//! of the picture together. The second picture stands as close to the first as their
//! drawings, names and texts allow ([`SLOW_GAP_MM`] apart at every height they share): its
//! plan, no higher than the first's, takes the room right of the first's plan. The view's
//! block keeps the room the texts take, so that the next block is not set over them.

use super::layout::{keyed, Block, Part};
use crate::construct::fit::LABEL_MARGIN;
use crate::construct::{Figure, Item, StepId};
use crate::gears::{SlowLinks, TrainStudy, POLE_DISTANCE};
use crate::geom::DVec2;
use crate::plate::{text::measure, View, LABEL_GAP_MM, LABEL_HEIGHT_MM};
use crate::scale::{format_sig, Key, Lang, Scale};
use crate::words::{unit_in, GearText};

/// The least gap between what the first picture and the slow links' own draw and write at
/// the heights they share, mm.
const SLOW_GAP_MM: f64 = 20.0;

/// The pitch of the two lines of the slow links' heading, mm: a label's box (its
/// descenders and subscripts below the capitals) and the placer's clearance between texts.
const HEADING_PITCH_MM: f64 = 6.5;

/// Two boxes closer in height than this share their heights, mm.
const SHARED_HEIGHT_MM: f64 = 3.0;

/// A box in figure mm (min, max), y up.
type Room = (DVec2, DVec2);

/// The union of `room` and the box `b`.
fn grow(room: Option<Room>, b: Room) -> Option<Room> {
    Some(room.map_or(b, |(lo, hi)| (lo.min(b.0), hi.max(b.1))))
}

/// `figure` with `text` written at `at` toward `toward` (a step noted `note`; [`DVec2::ZERO`]
/// centres it there), and the box it takes pushed onto `texts`.
fn written(
    figure: Figure,
    (note, at, text): (&str, DVec2, String),
    toward: DVec2,
    texts: &mut Vec<Room>,
) -> Figure {
    let size = label_size(&text);
    // Its box: centred on `at`, or beside it past the label's gap.
    let centre = at + toward * (0.5 * size.x + LABEL_GAP_MM);
    texts.push((centre - 0.5 * size, centre + 0.5 * size));
    figure.with_text(note, at, text, toward)
}

/// The room the texts' boxes `texts` take beyond the label margin the block keeps about its
/// drawing on every side (half of [`LABEL_MARGIN`]): a text within it needs no more.
fn beyond_margin(texts: &[Room]) -> Option<Room> {
    let m = DVec2::splat(0.5 * LABEL_MARGIN);
    texts
        .iter()
        .fold(None, |r, (lo, hi)| grow(r, (*lo + m, *hi - m)))
}

/// The size of a label's box as the plate measures it, mm.
fn label_size(text: &str) -> DVec2 {
    let e = measure(text, LABEL_HEIGHT_MM);
    e.max - e.min
}

/// A plan's μ_ω as the textbook writes it: `μ_{ω} = μ_{v}/(μ_{l}·h) = 0,02 рад/(с·мм)`.
fn scale_w_text(scale_w: Scale, lang: Lang) -> String {
    format!(
        "μ_{{ω}} = μ_{{v}}/(μ_{{l}}·{POLE_DISTANCE}) = {} {}",
        super::digits::value(scale_w.value(), lang),
        scale_w.quantity.unit(lang),
    )
}

/// The train's view: the triangles of velocities with μ_ω by the plan, the slow links'
/// picture beside the first when there is one, captioned with the first's μ_l, μ_v and h.
pub(super) fn triangles_block(t: &TrainStudy, lang: Lang) -> Block {
    let tri = &t.triangles;
    let caption = format!(
        "{}, {}, {}, {POLE_DISTANCE} = {} {}",
        GearText::Triangles.get(lang),
        tri.scale_l.caption(lang),
        tri.scale_v.caption(lang),
        format_sig(tri.plan_h, 3, lang),
        unit_in("mm", lang),
    );
    let mut texts = Vec::new();
    let mut figure = written(
        tri.figure.clone(),
        (
            "μ_ω of the plan of angular velocities",
            tri.scale_w_at,
            scale_w_text(tri.scale_w, lang),
        ),
        -DVec2::X,
        &mut texts,
    );
    if let Some(slow) = &tri.slow {
        let mut own = Vec::new();
        let second = slow_picture(t, slow, lang, &mut own);
        let dx = beside(&taken(&figure, &texts), &taken(&second, &own));
        let shift = DVec2::new(dx, 0.0);
        texts.extend(own.iter().map(|(a, b)| (*a + shift, *b + shift)));
        figure = figure.joined(second.translated(shift));
    }
    Block::Views {
        parts: vec![Part {
            label_room: beyond_margin(&texts),
            ..Part::new(figure, DVec2::ZERO, Some(caption))
        }],
        scale: keyed(Key::PlanetaryModule, tri.scale_v),
    }
}

/// The slow links' picture with its heading over its plan in two lines: `Звенья 2-3, 4, 5, H
/// (ω_{2-3} с первого плана)` over `μ_v = 0,0001 м/(с·мм), μ_ω = μ_v/(μ_l·h) = 0,004
/// рад/(с·мм)` (μ_l and h are the first picture's); the boxes its texts take pushed onto
/// `texts`.
fn slow_picture(t: &TrainStudy, slow: &SlowLinks, lang: Lang, texts: &mut Vec<Room>) -> Figure {
    let shafts = &t.spec.train.shafts;
    let links: Vec<&str> = slow.links.iter().map(|k| shafts[*k].as_str()).collect();
    let heading = GearText::SlowLinks
        .get(lang)
        .replace("{links}", &links.join(", "))
        .replace("{pivot}", &shafts[slow.pivot]);
    let scales = format!(
        "{}, {}",
        slow.scale_v.caption(lang),
        scale_w_text(slow.scale_w, lang)
    );
    let lines = [
        ("μ_ω of the slow links' plan, after their μ_v", scales),
        ("the slow links' picture: its links", heading),
    ];
    let mut figure = slow.figure.clone();
    for (k, (note, text)) in lines.into_iter().enumerate() {
        let at = slow.heading_at + DVec2::new(0.0, k as f64 * HEADING_PITCH_MM);
        figure = written(figure, (note, at, text), DVec2::ZERO, texts);
    }
    figure
}

/// The boxes `figure` takes: each step's drawing, each name about its point (as wide as
/// its text on every side: the plate picks the side; names of coinciding points joined as
/// the plate joins them), and its `texts`.
fn taken(figure: &Figure, texts: &[Room]) -> Vec<Room> {
    let about = |p: DVec2, size: DVec2| {
        let pad = size + DVec2::splat(LABEL_GAP_MM);
        (p - pad, p + pad)
    };
    let joints = View::joint_labels(figure);
    let joined: Vec<StepId> = joints.iter().flat_map(|j| j.3.iter().copied()).collect();
    let names = figure
        .steps
        .iter()
        .filter(|s| !joined.contains(&s.id) && !matches!(s.item, Item::Text(_)))
        .filter_map(|s| s.label.as_ref())
        .map(|l| about(l.anchor, label_size(&l.text)));
    figure
        .steps
        .iter()
        .filter_map(View::step_bounds)
        .chain(joints.iter().map(|(p, _, size, _)| about(*p, *size)))
        .chain(names)
        .chain(texts.iter().copied())
        .collect()
}

/// How far right the boxes `second` go to stand [`SLOW_GAP_MM`] right of the boxes `first` at
/// every height they share (right of all of them when they share none), mm.
fn beside(first: &[Room], second: &[Room]) -> f64 {
    let shared =
        |a: &Room, b: &Room| a.0.y < b.1.y + SHARED_HEIGHT_MM && b.0.y < a.1.y + SHARED_HEIGHT_MM;
    let right = |boxes: &[Room]| boxes.iter().fold(f64::NEG_INFINITY, |m, b| m.max(b.1.x));
    let left = |boxes: &[Room]| boxes.iter().fold(f64::INFINITY, |m, b| m.min(b.0.x));
    let clear = first
        .iter()
        .flat_map(|a| {
            second
                .iter()
                .filter(|b| shared(a, b))
                .map(|b| a.1.x - b.0.x)
        })
        .fold(f64::NEG_INFINITY, f64::max);
    let clear = if clear.is_finite() {
        clear
    } else {
        right(first) - left(second)
    };
    if clear.is_finite() {
        clear + SLOW_GAP_MM
    } else {
        0.0
    }
}
