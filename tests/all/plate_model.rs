//! What the label rules of issue 45 read off a plate's model: every sheet of every shipped
//! scene, and the geometry of a step as the sheet draws it (its point, its lines), computed
//! here from the recorded items — not from the label placer's own outlines — so that a
//! rule tests the placer instead of repeating it.

use std::path::PathBuf;
use tmm::construct::{Drafting, Item, Names, Role, Step};
use tmm::geom::{Arc, DVec2};
use tmm::plate::{Plate, View};
use tmm::scale::Lang;
use tmm::study::Session;

/// The drafting resolution, mm: a length is read off the drawing to 0,5 mm, so points
/// nearer than this coincide on it and a plan's image this near its tail is drawn as the
/// point there (issue 45: `p ≡ a ≡ k` may not join points 3,2 and 1,6 mm apart).
pub fn resolution_mm() -> f64 {
    Drafting::HAND.resolution_mm()
}

/// A force shorter than its arrowhead is drawn as the point at its tail: the arrowhead of a
/// main line (a given or resulting vector) is 4 mm long, of a thin one 3 mm
/// (`docs/STYLE.md`).
pub fn arrowhead_mm(role: Role) -> f64 {
    match role {
        Role::Given | Role::Result => 4.0,
        _ => 3.0,
    }
}

/// Whether a step is a vector drawn as the point at its tail: a plan's image (a label naming
/// a point) shorter than the drafting resolution, a force (a label naming its item) shorter
/// than its arrowhead; an unlabelled one is an arc's arrowhead.
fn short(step: &Step) -> bool {
    let Item::Vector { from, to } = step.item else {
        return false;
    };
    let shorter = match step.label.as_ref().map(|l| l.names) {
        Some(Names::Point) => resolution_mm(),
        Some(Names::Item) => arrowhead_mm(step.role),
        None => return false,
    };
    from.distance(to) < shorter
}

/// Every sheet of every plate of every scene in `constructions/`, in Russian, named
/// `scene/sheet`.
pub fn every_sheet() -> Vec<(String, Plate)> {
    every_sheet_in(Lang::Ru, Drafting::EXACT)
}

/// Every sheet of every plate of every scene in `constructions/`, in `lang` under
/// `drafting`, named `scene/sheet`.
pub fn every_sheet_in(lang: Lang, drafting: Drafting) -> Vec<(String, Plate)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("constructions");
    let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("constructions/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    let mut out = Vec::new();
    for path in paths {
        let s = tmm::scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        let session = Session::new(&s, drafting);
        let all = tmm::sheets::build_all(&session, lang)
            .unwrap_or_else(|(k, e)| panic!("{}/{}: {e}", s.stem, k.stem()));
        out.extend(
            all.into_iter()
                .map(|(_, p)| (format!("{}/{}", s.stem, p.name), p)),
        );
    }
    out
}

/// The sheet `name` (`scene/sheet`) of [`every_sheet`].
pub fn sheet(name: &str) -> Plate {
    every_sheet()
        .into_iter()
        .find(|(n, _)| n == name)
        .map(|(_, p)| p)
        .unwrap_or_else(|| panic!("no sheet {name}"))
}

/// The step `id` of a view's figure.
pub fn step(view: &View, id: tmm::construct::StepId) -> &Step {
    view.figure
        .steps
        .iter()
        .find(|s| s.id == id)
        .expect("a placed label's step is in its view")
}

/// The point a label of a point names, figure mm: the point of its step's item nearest its
/// anchor (a marked point, a pair, a block, an end of a line or vector; the tail of a
/// vector drawn as a point; a text's anchor when its label names a point). `None` when the item has no point there (within `reach`).
pub fn named_point(step: &Step, reach: f64) -> Option<DVec2> {
    let label = step.label.as_ref()?;
    let a = label.anchor;
    let points: Vec<DVec2> = match &step.item {
        Item::Point(p) => vec![*p],
        Item::Joint { at, .. } | Item::Slider { at, .. } => vec![*at],
        Item::Segment(s) | Item::Guide { segment: s, .. } => vec![s.from, s.to],
        Item::Vector { from, to } => vec![*from, *to],
        // A text that names a point (a position's number at its crank pin) names its anchor.
        Item::Text(p) if names_point(step) => vec![*p],
        _ => Vec::new(),
    };
    let at = points
        .into_iter()
        .filter(|p| p.distance(a) <= reach)
        .min_by(|p, q| p.distance(a).total_cmp(&q.distance(a)))?;
    match (&step.item, short(step)) {
        // Either end names the one point drawn, at the tail.
        (Item::Vector { from, .. }, true) => Some(*from),
        _ => Some(at),
    }
}

/// Whether a step's label names a point.
pub fn names_point(step: &Step) -> bool {
    step.label.as_ref().is_some_and(|l| l.names == Names::Point)
}

/// Points along an arc, about 5° apart.
fn arc_points(a: &Arc) -> Vec<DVec2> {
    let n = ((a.sweep.abs() / 5f64.to_radians()).ceil() as usize).clamp(1, 72);
    (0..=n).map(|i| a.eval(i as f64 / n as f64)).collect()
}

/// The chords between successive `pts`, and back to the first when `closed`.
pub fn chords(pts: &[DVec2], closed: bool) -> Vec<(DVec2, DVec2)> {
    let mut v: Vec<(DVec2, DVec2)> = pts.windows(2).map(|w| (w[0], w[1])).collect();
    if closed && pts.len() > 2 {
        v.push((pts[pts.len() - 1], pts[0]));
    }
    v
}

/// Chords of each piece of a smooth curve as the model reads it.
const CURVE_CHORDS: usize = 8;

/// The lines a step draws, figure mm, as pieces: its links, vectors, guides' lines,
/// circles, arcs, polylines and curves (through their points, smooth as drawn), and a
/// dimension's line. A vector drawn as a point, a point, a pair, a block and a text draw
/// none.
pub fn lines(step: &Step) -> Vec<(DVec2, DVec2)> {
    match &step.item {
        Item::Segment(s) | Item::Guide { segment: s, .. } => vec![(s.from, s.to)],
        Item::Vector { from, to } if !short(step) => vec![(*from, *to)],
        Item::Circle(c) => chords(
            &arc_points(&Arc {
                center: c.center,
                radius: c.radius,
                start: 0.0,
                sweep: std::f64::consts::TAU,
            }),
            false,
        ),
        Item::Arc(a) | Item::Angle(a) | Item::Moment(a) => chords(&arc_points(a), false),
        Item::Polyline { points, closed } => chords(points, *closed),
        // As drawn: smooth through its points, not their chords.
        Item::Curve { points, closed } if points.len() >= 3 => chords(
            &tmm::geom::curve::points(points, *closed, CURVE_CHORDS),
            false,
        ),
        Item::Curve { points, closed } => chords(points, *closed),
        Item::Dimension { from, to, offset } => {
            let n = (*to - *from).normalize_or_zero().perp() * *offset;
            vec![(*from + n, *to + n)]
        }
        _ => Vec::new(),
    }
}

/// A step drawn by hand: `item` labelled `text` at `anchor`, toward `toward` (naming what
/// [`tmm::construct::Names::of`] says).
pub fn drawn(id: u32, item: Item, text: &str, (anchor, toward): (DVec2, DVec2)) -> Step {
    Step {
        id: tmm::construct::StepId(id),
        note: format!("drawn by the test: {text}"),
        label: Some(tmm::construct::Label::on(&item, text, anchor, toward)),
        item,
        role: Role::Result,
        from: Vec::new(),
        group: 0,
    }
}

/// `plate` with one more view, a copy of its first view's place drawing the figure `steps`:
/// a plate built to break a rule.
pub fn with_view(mut plate: Plate, steps: Vec<Step>) -> Plate {
    let mut view = plate.views[0].clone();
    view.figure = tmm::construct::Figure {
        title: "broken".into(),
        scale: view.figure.scale,
        steps,
        readings: Vec::new(),
    };
    view.caption = None;
    plate.views.push(view);
    plate
}

/// The sheet position (mm, y down) of a figure point of `view`.
pub fn on_sheet(view: &View, p: DVec2) -> DVec2 {
    view.to_sheet(p)
}

/// The distance from the box `lo`–`hi` (sheet mm) to the point `p`, 0 inside.
pub fn box_to_point(lo: DVec2, hi: DVec2, p: DVec2) -> f64 {
    (p - p.clamp(lo, hi)).length()
}

/// Whether the segment `a`–`b` meets the box `lo`–`hi` (clipped by the box's four sides).
fn meets(lo: DVec2, hi: DVec2, a: DVec2, b: DVec2) -> bool {
    let d = b - a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d.x, a.x - lo.x),
        (d.x, hi.x - a.x),
        (-d.y, a.y - lo.y),
        (d.y, hi.y - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else if p < 0.0 {
            t0 = t0.max(q / p);
        } else {
            t1 = t1.min(q / p);
        }
    }
    t0 <= t1
}

/// The distance from `p` to the segment `a`–`b`.
fn point_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    tmm::geom::Segment::new(a, b).distance_to(p)
}

/// The distance from the box `lo`–`hi` to the segment `a`–`b` (sheet mm), 0 when they meet:
/// apart, the nearest pair is an end of the segment and the box, or a corner of the box and
/// the segment.
pub fn box_to_segment(lo: DVec2, hi: DVec2, a: DVec2, b: DVec2) -> f64 {
    if meets(lo, hi, a, b) {
        return 0.0;
    }
    let corners = [lo, hi, DVec2::new(lo.x, hi.y), DVec2::new(hi.x, lo.y)];
    corners
        .into_iter()
        .map(|c| point_to_segment(c, a, b))
        .chain([box_to_point(lo, hi, a), box_to_point(lo, hi, b)])
        .fold(f64::INFINITY, f64::min)
}
