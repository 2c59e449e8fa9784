//! The plate's layout: where every text goes and what every item covers, in sheet mm.
//!
//! Labels are placed by the plate, not at a fixed offset from their point. Labels of one view
//! whose points coincide on the sheet (within [`COINCIDENT_MM`]) become one joint label written
//! as the textbook does, `p ≡ b₃ ≡ d` (the figure's order, the pole first). Every label then
//! tries positions around its point — its preferred direction first, then sixteen directions
//! at two distances — and keeps the one that collides least with what is already placed
//! (labels, captions, text blocks, tables) and with the lines and symbols of the drawing (the
//! main lines weigh most), never leaving the frame nor entering the title block when it can
//! help it. Crowded labels are placed first; the order is deterministic, so is the layout.
//! The SVG writer writes the texts from this layout, and the tests check its boxes.

use super::items::{dimension_text, item_outlines, Outline, Shape, JOINT_RADIUS_MM};
use super::items::{LABEL_GAP_MM, LABEL_HEIGHT_MM};
use super::path::Map;
use super::style::{Mark, Pen};
use super::svg::CAPTION_HEIGHT_MM;
use super::table::table_marks;
use super::text::{measure, plain, Align, Extent, Placed};
use super::{Plate, Rect, TextBlock, View, CAPTION_BAND_MM};
use crate::construct::{Item, Label, StepId};
use crate::geom::DVec2;
use std::f64::consts::{FRAC_PI_4, TAU};

/// Label points closer than this on the sheet are one point: their labels are joined, mm.
pub const COINCIDENT_MM: f64 = 0.3;
/// How a joint label joins its names.
pub const JOINT_SEPARATOR: &str = " ≡ ";
/// The second ring of candidate positions lies this much further from the point, mm.
pub const SECOND_RING_MM: f64 = 3.0;
/// Clearance kept between a label and other texts while placing, mm.
const CLEARANCE_MM: f64 = 1.0;
/// Directions tried around a point.
const DIRECTIONS: usize = 16;

/// A label as placed on the sheet.
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedLabel {
    /// Index of its view in [`Plate::views`].
    pub view: usize,
    /// The steps whose labels it writes (several for a joint label), in the figure's order.
    pub steps: Vec<StepId>,
    /// The text in label markup (names joined by [`JOINT_SEPARATOR`]).
    pub text: String,
    /// The point it labels, sheet mm.
    pub anchor: DVec2,
    /// The box its text covers, sheet mm.
    pub rect: Rect,
    /// The text as written.
    pub(crate) placed: Placed,
}

/// A view as laid out.
#[derive(Debug, Clone, PartialEq)]
pub struct ViewLayout {
    /// The box of everything its figure draws (line widths and symbols included), sheet mm;
    /// `None` for an empty figure.
    pub drawn: Option<Rect>,
    /// The box of its caption.
    pub caption: Option<Rect>,
    /// The caption as written.
    pub(crate) caption_text: Option<Placed>,
}

/// A plate laid out: every placed text and every drawn item's box, sheet mm (y down).
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// The inner edge of the frame: everything is drawn inside it.
    pub frame: Rect,
    /// The main title block: nothing else is drawn over it.
    pub title_block: Rect,
    /// The rotated designation box in the frame's corner: nothing else is drawn over it.
    pub designation_box: Rect,
    /// The views, as [`Plate::views`].
    pub views: Vec<ViewLayout>,
    /// Every label of every view, in the order they are written.
    pub labels: Vec<PlacedLabel>,
    /// The boxes of the free text blocks, as [`Plate::texts`].
    pub texts: Vec<Rect>,
    /// The boxes of the tables (grid, title and texts), as [`Plate::tables`].
    pub tables: Vec<Rect>,
}

/// Lay the plate out: its views' drawn boxes and captions, its text blocks and tables, and
/// every label placed (see the module documentation).
pub fn layout(plate: &Plate) -> Layout {
    let sheet = &plate.sheet;
    let outlines: Vec<Vec<Outline>> = plate.views.iter().map(view_outlines).collect();
    let views: Vec<ViewLayout> = plate
        .views
        .iter()
        .zip(&outlines)
        .map(|(v, o)| {
            let caption_text = caption(v);
            ViewLayout {
                drawn: drawn_bounds(o),
                caption: caption_text.as_ref().map(Placed::bounds),
                caption_text,
            }
        })
        .collect();
    let texts: Vec<Rect> = plate
        .texts
        .iter()
        .map(|b| {
            let lines = text_block_lines(b);
            Rect::around(lines.iter().flat_map(|p| corners(p.bounds())))
                .unwrap_or(Rect::new(b.at, b.at))
        })
        .collect();
    let tables: Vec<Rect> = plate
        .tables
        .iter()
        .map(|t| {
            let grid = Rect::new(t.at, t.at + t.size());
            table_marks(t)
                .iter()
                .filter_map(|m| match m {
                    Mark::Text(p) => Some(p.bounds()),
                    Mark::Path(..) => None,
                })
                .fold(grid, |r, b| r.union(&b))
        })
        .collect();
    let mut out = Layout {
        frame: sheet.frame().inflate(-Pen::MAIN.width * 0.5),
        title_block: sheet.title_block(),
        designation_box: sheet.designation_box(),
        views,
        labels: Vec::new(),
        texts,
        tables,
    };
    out.labels = Placer::new(&out, &outlines).place(plate);
    out
}

/// The outlines of everything a view draws, sheet mm.
fn view_outlines(view: &View) -> Vec<Outline> {
    let map = Map::figure(view.origin);
    view.figure
        .steps
        .iter()
        .flat_map(|s| item_outlines(&s.item, s.role, map))
        .collect()
}

/// The box of the outlines, grown by half the width of their lines.
fn drawn_bounds(outlines: &[Outline]) -> Option<Rect> {
    outlines
        .iter()
        .filter_map(|o| {
            let half = if o.main { Pen::MAIN } else { Pen::THIN }.width * 0.5;
            shape_box(&o.shape).map(|b| b.inflate(half))
        })
        .reduce(|a, b| a.union(&b))
}

fn shape_box(s: &Shape) -> Option<Rect> {
    match s {
        Shape::Line(a, b) => Rect::around([*a, *b]),
        Shape::Area(pts) => Rect::around(pts.iter().copied()),
    }
}

fn corners(r: Rect) -> [DVec2; 2] {
    [r.min, r.max]
}

/// A view's caption: centred under the figure's bounds, in the band kept for it.
fn caption(view: &View) -> Option<Placed> {
    let text = view.caption.as_ref()?;
    let (lo, hi) = view.figure.bounds()?;
    let bottom = view.to_sheet(DVec2::new((lo.x + hi.x) * 0.5, lo.y));
    let at = bottom + DVec2::new(0.0, CAPTION_BAND_MM - CAPTION_HEIGHT_MM);
    Some(Placed::centred(at, text, CAPTION_HEIGHT_MM, Align::Middle))
}

/// The lines of a text block, two text heights apart.
pub(crate) fn text_block_lines(block: &TextBlock) -> Vec<Placed> {
    let h = block.size_mm;
    block
        .lines
        .iter()
        .enumerate()
        .map(|(i, line)| {
            Placed::new(
                block.at + DVec2::new(0.0, h * (1.0 + 2.0 * i as f64)),
                line,
                h,
                Align::Start,
            )
        })
        .collect()
}

/// A label to place: one point's names (several for a joint label).
#[derive(Debug, Clone)]
struct Request {
    view: usize,
    steps: Vec<StepId>,
    names: Vec<String>,
    anchor: DVec2,
    /// Preferred direction on the sheet (unit, or zero: centred on the point).
    toward: DVec2,
    /// Least distance from the point to the text's box.
    gap: f64,
}

impl Request {
    fn text(&self) -> String {
        self.names.join(JOINT_SEPARATOR)
    }
}

/// A pole of a plan: written first in a joint label.
fn is_pole(name: &str) -> bool {
    matches!(plain(name).as_str(), "p" | "π")
}

/// A position number (`7`, `8′`) rather than a point's name: the two are not joined (the
/// crank pin at position 1 is `B` and `1`, not `1 ≡ B`).
fn is_number(name: &str) -> bool {
    plain(name).starts_with(|c: char| c.is_ascii_digit())
}

/// The labels of a view to place, coincident ones joined; and the fixed texts of its
/// dimensions.
fn requests(k: usize, view: &View) -> (Vec<Request>, Vec<PlacedLabel>) {
    let map = Map::figure(view.origin);
    let mut fixed = Vec::new();
    let mut single: Vec<Request> = Vec::new();
    for step in &view.figure.steps {
        let Some(Label {
            text,
            anchor,
            toward,
        }) = &step.label
        else {
            continue;
        };
        if let Item::Dimension { from, to, offset } = &step.item {
            if let Some(placed) = dimension_text(map, *from, *to, *offset, text) {
                fixed.push(PlacedLabel {
                    view: k,
                    steps: vec![step.id],
                    text: text.clone(),
                    anchor: map.pt((*from + *to) * 0.5),
                    rect: placed.bounds(),
                    placed,
                });
            }
            continue;
        }
        let gap = match step.item {
            Item::Joint { .. } => LABEL_GAP_MM + JOINT_RADIUS_MM,
            _ => LABEL_GAP_MM,
        };
        single.push(Request {
            view: k,
            steps: vec![step.id],
            names: vec![text.clone()],
            anchor: map.pt(*anchor),
            toward: map.dir(*toward).normalize_or_zero(),
            gap,
        });
    }
    (join_coincident(single), fixed)
}

/// Join the requests whose points coincide (transitively; names with names, position
/// numbers with position numbers), keeping the figure's order with the pole first; a name
/// repeated at one point is written once.
fn join_coincident(single: Vec<Request>) -> Vec<Request> {
    let n = single.len();
    let mut root: Vec<usize> = (0..n).collect();
    fn find(root: &mut [usize], mut i: usize) -> usize {
        while root[i] != i {
            root[i] = root[root[i]];
            i = root[i];
        }
        i
    }
    for i in 0..n {
        for j in 0..i {
            let (a, b) = (&single[i], &single[j]);
            if a.anchor.distance(b.anchor) <= COINCIDENT_MM
                && is_number(&a.names[0]) == is_number(&b.names[0])
            {
                let (a, b) = (find(&mut root, i), find(&mut root, j));
                root[a.max(b)] = a.min(b);
            }
        }
    }
    let mut joined: Vec<Request> = Vec::new();
    let mut slot: Vec<Option<usize>> = vec![None; n];
    for (i, r) in single.into_iter().enumerate() {
        let g = find(&mut root, i);
        match slot[g] {
            None => {
                slot[g] = Some(joined.len());
                joined.push(r);
            }
            Some(at) => {
                let j = &mut joined[at];
                j.steps.extend(r.steps);
                j.gap = j.gap.max(r.gap);
                if j.toward == DVec2::ZERO {
                    j.toward = r.toward;
                }
                for name in r.names {
                    if !j.names.contains(&name) {
                        j.names.push(name);
                    }
                }
            }
        }
    }
    for j in &mut joined {
        if let Some(p) = j.names.iter().position(|s| is_pole(s)) {
            let pole = j.names.remove(p);
            j.names.insert(0, pole);
        }
    }
    joined
}

/// Places labels one by one against what is already on the sheet, then moves those still
/// colliding (alone, or together with a label in their way) while that lowers the collisions.
struct Placer<'a> {
    frame: Rect,
    forbidden: [Rect; 2],
    /// Boxes of the texts that do not move (captions, text blocks, tables, dimensions).
    fixed: Vec<Rect>,
    /// Every view's outlines.
    outlines: &'a [Vec<Outline>],
}

/// Cost of a box leaving the frame or entering the title block.
const OUTSIDE: f64 = 1e5;
/// Cost of a box over another text, plus its overlap area (mm²) times [`TEXT_AREA`].
const OVER_TEXT: f64 = 1e3;
const TEXT_AREA: f64 = 100.0;
/// Cost of covering another label's point.
const OVER_POINT: f64 = 60.0;
/// Cost per mm of a main line crossing the box; of a thin line.
const MAIN_LINE: f64 = 20.0;
const THIN_LINE: f64 = 4.0;
/// Cost of touching a main symbol (pair, block, arrowhead, dot), and per mm² of it covered;
/// the same for a thin one.
const MAIN_AREA: f64 = 40.0;
const THIN_AREA: f64 = 6.0;
/// Cost per rank of the candidate (the preferred position is rank 0).
const RANK: f64 = 0.5;
/// Rounds of moving the labels that still collide.
const REPAIR_ROUNDS: usize = 4;

/// A request with what lies near its point: its text, the outlines, the other labels' points.
struct Job<'a> {
    request: Request,
    text: String,
    extent: Extent,
    candidates: Vec<Rect>,
    near: Rect,
    lines: Vec<&'a Outline>,
    points: Vec<DVec2>,
}

/// Where a label is: its box and the rank of that candidate.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Slot {
    rect: Rect,
    rank: usize,
}

impl<'a> Placer<'a> {
    fn new(layout: &Layout, outlines: &'a [Vec<Outline>]) -> Self {
        let fixed = layout
            .views
            .iter()
            .filter_map(|v| v.caption)
            .chain(layout.texts.iter().copied())
            .chain(layout.tables.iter().copied())
            .collect();
        Placer {
            frame: layout.frame,
            forbidden: [layout.title_block, layout.designation_box],
            fixed,
            outlines,
        }
    }

    fn place(mut self, plate: &Plate) -> Vec<PlacedLabel> {
        let mut out = Vec::new();
        let mut todo = Vec::new();
        for (k, view) in plate.views.iter().enumerate() {
            let (r, f) = requests(k, view);
            out.extend(f);
            todo.extend(r);
        }
        self.fixed.extend(out.iter().map(|l| l.rect));
        let points: Vec<(usize, DVec2)> = todo.iter().map(|r| (r.view, r.anchor)).collect();
        let jobs: Vec<Job> = todo.into_iter().map(|r| self.job(r, &points)).collect();
        // The most crowded first: they have the fewest free places.
        let crowd = |j: &Job| {
            let r = &j.request;
            points
                .iter()
                .filter(|(v, p)| *v == r.view && p.distance(r.anchor) < 8.0)
                .count()
        };
        let mut order: Vec<(usize, usize, usize)> = jobs
            .iter()
            .enumerate()
            .map(|(i, j)| (j.request.view, usize::MAX - crowd(j), i))
            .collect();
        order.sort_unstable();
        let order: Vec<usize> = order.into_iter().map(|o| o.2).collect();
        let mut slots: Vec<Option<Slot>> = vec![None; jobs.len()];
        for &i in &order {
            slots[i] = Some(self.best(&jobs, &slots, i).0);
        }
        for _ in 0..REPAIR_ROUNDS {
            let mut moved = false;
            for &i in &order {
                moved |= self.repair(&jobs, &mut slots, i);
            }
            if !moved {
                break;
            }
        }
        out.extend(jobs.into_iter().zip(slots).filter_map(|(j, s)| {
            let rect = s?.rect;
            Some(PlacedLabel {
                view: j.request.view,
                steps: j.request.steps,
                anchor: j.request.anchor,
                placed: written(&j.text, &j.extent, rect),
                rect,
                text: j.text,
            })
        }));
        out
    }

    /// A request with its candidates and what lies near them.
    fn job(&self, request: Request, points: &[(usize, DVec2)]) -> Job<'a> {
        let text = request.text();
        let extent = measure(&text, LABEL_HEIGHT_MM);
        let candidates = candidates(&request, extent.max - extent.min);
        let near = candidates
            .iter()
            .fold(Rect::new(request.anchor, request.anchor), |r, c| r.union(c))
            .inflate(CLEARANCE_MM);
        let lines = self.outlines[request.view]
            .iter()
            .filter(|o| shape_box(&o.shape).is_some_and(|b| b.intersects(&near)))
            .collect();
        let points = points
            .iter()
            .filter(|(v, p)| {
                *v == request.view && *p != request.anchor && near.contains(&Rect::new(*p, *p))
            })
            .map(|(_, p)| *p)
            .collect();
        Job {
            request,
            text,
            extent,
            candidates,
            near,
            lines,
            points,
        }
    }

    /// The least colliding candidate of job `i` with the other labels where `slots` has them
    /// (the first of equals), and its cost.
    fn best(&self, jobs: &[Job], slots: &[Option<Slot>], i: usize) -> (Slot, f64) {
        let job = &jobs[i];
        let others = self.texts_near(jobs, slots, i);
        let mut best = (
            Slot {
                rect: job.candidates[0],
                rank: 0,
            },
            f64::INFINITY,
        );
        for (rank, &rect) in job.candidates.iter().enumerate() {
            let slot = Slot { rect, rank };
            let cost = self.cost(job, &slot, &others);
            if cost < best.1 {
                best = (slot, cost);
            }
        }
        best
    }

    /// The boxes of texts near job `i`: the fixed ones and the other placed labels.
    fn texts_near(&self, jobs: &[Job], slots: &[Option<Slot>], i: usize) -> Vec<Rect> {
        let near = jobs[i].near;
        let placed = slots
            .iter()
            .enumerate()
            .filter(|(j, _)| *j != i)
            .filter_map(|(_, s)| s.map(|s| s.rect));
        self.fixed
            .iter()
            .copied()
            .chain(placed)
            .filter(|t| t.intersects(&near))
            .collect()
    }

    /// Move label `i` if it collides with another text and a better place is found for it
    /// alone, or for it and one of the labels it collides with; true when something moved.
    fn repair(&self, jobs: &[Job], slots: &mut [Option<Slot>], i: usize) -> bool {
        let Some(now) = slots[i] else {
            return false;
        };
        let padded = now.rect.inflate(CLEARANCE_MM);
        let blockers: Vec<usize> = (0..slots.len())
            .filter(|&j| j != i && slots[j].is_some_and(|s| s.rect.intersects(&padded)))
            .collect();
        let against_fixed = self.fixed.iter().any(|f| f.intersects(&padded));
        if blockers.is_empty() && !against_fixed {
            return false;
        }
        let cost_now = self.cost(&jobs[i], &now, &self.texts_near(jobs, slots, i));
        let (alone, cost) = self.best(jobs, slots, i);
        if cost < cost_now - 1e-9 {
            slots[i] = Some(alone);
            return true;
        }
        for j in blockers {
            let before = cost_now + {
                let mut without = slots.to_vec();
                without[i] = None;
                let s = slots[j].expect("placed");
                self.cost(&jobs[j], &s, &self.texts_near(jobs, &without, j))
            };
            let mut trial = slots.to_vec();
            trial[i] = None;
            trial[j] = None;
            let (si, ci) = self.best(jobs, &trial, i);
            trial[i] = Some(si);
            let (sj, cj) = self.best(jobs, &trial, j);
            if ci + cj < before - 1e-9 {
                slots[i] = Some(si);
                slots[j] = Some(sj);
                return true;
            }
        }
        false
    }

    /// What placing `job` at `slot` costs among the texts `others`.
    fn cost(&self, job: &Job, slot: &Slot, others: &[Rect]) -> f64 {
        let rect = &slot.rect;
        let mut cost = slot.rank as f64 * RANK;
        if !self.frame.contains(rect) || self.forbidden.iter().any(|f| f.intersects(rect)) {
            cost += OUTSIDE;
        }
        let padded = rect.inflate(CLEARANCE_MM * 0.5);
        for t in others {
            let a = t.inflate(CLEARANCE_MM * 0.5).overlap(&padded);
            if a > 0.0 {
                cost += OVER_TEXT + TEXT_AREA * a;
            }
        }
        for p in &job.points {
            if padded.contains(&Rect::new(*p, *p)) {
                cost += OVER_POINT;
            }
        }
        for o in &job.lines {
            cost += match &o.shape {
                Shape::Line(a, b) => {
                    clipped_length(*a, *b, &padded) * if o.main { MAIN_LINE } else { THIN_LINE }
                }
                Shape::Area(pts) => {
                    let per = if o.main { MAIN_AREA } else { THIN_AREA };
                    let a = clipped_area(pts, &padded);
                    if a > 0.0 {
                        per * (1.0 + a)
                    } else {
                        0.0
                    }
                }
            };
        }
        cost
    }
}

/// The candidate boxes of a request in order of preference: centred on the point when it has
/// no preferred direction; then sixteen directions, the preferred one first and the others
/// alternating about it, at the request's gap and [`SECOND_RING_MM`] further.
fn candidates(r: &Request, size: DVec2) -> Vec<Rect> {
    let half = size * 0.5;
    let mut out = Vec::with_capacity(2 * DIRECTIONS + 1);
    let start = if r.toward == DVec2::ZERO {
        out.push(Rect::new(r.anchor - half, r.anchor + half));
        -FRAC_PI_4
    } else {
        r.toward.y.atan2(r.toward.x)
    };
    let step = TAU / DIRECTIONS as f64;
    for gap in [r.gap, r.gap + SECOND_RING_MM] {
        for k in 0..DIRECTIONS {
            // 0, +1, −1, +2, −2, …, +8.
            let turn = (k.div_ceil(2)) as f64 * if k % 2 == 1 { 1.0 } else { -1.0 };
            let t = DVec2::from_angle(start + turn * step);
            // From the centre to the box's edge along t.
            let reach = [(half.x, t.x), (half.y, t.y)]
                .iter()
                .filter(|(_, c)| c.abs() > 1e-9)
                .map(|(h, c)| h / c.abs())
                .fold(f64::INFINITY, f64::min);
            let c = r.anchor + t * (gap + reach);
            out.push(Rect::new(c - half, c + half));
        }
    }
    out
}

/// The text written so that its box is `rect`.
fn written(text: &str, e: &Extent, rect: Rect) -> Placed {
    Placed::new(rect.min - e.min, text, LABEL_HEIGHT_MM, Align::Start)
}

/// Length of the segment `a`–`b` inside `r` (Liang–Barsky clipping).
fn clipped_length(a: DVec2, b: DVec2, r: &Rect) -> f64 {
    let d = b - a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d.x, a.x - r.min.x),
        (d.x, r.max.x - a.x),
        (-d.y, a.y - r.min.y),
        (d.y, r.max.y - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return 0.0;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    if t1 > t0 {
        (t1 - t0) * d.length()
    } else {
        0.0
    }
}

/// Area of the convex polygon `pts` inside `r` (Sutherland–Hodgman clipping).
fn clipped_area(pts: &[DVec2], r: &Rect) -> f64 {
    let mut poly = pts.to_vec();
    let edges: [(usize, f64, f64); 4] = [
        (0, r.min.x, 1.0),
        (0, r.max.x, -1.0),
        (1, r.min.y, 1.0),
        (1, r.max.y, -1.0),
    ];
    for (axis, at, sign) in edges {
        let inside = |p: DVec2| (p[axis] - at) * sign >= 0.0;
        let mut next = Vec::with_capacity(poly.len() + 2);
        for (i, &p) in poly.iter().enumerate() {
            let q = poly[(i + 1) % poly.len()];
            if inside(p) {
                next.push(p);
            }
            if inside(p) != inside(q) {
                let t = (at - p[axis]) / (q[axis] - p[axis]);
                next.push(p + (q - p) * t);
            }
        }
        poly = next;
        if poly.is_empty() {
            return 0.0;
        }
    }
    let twice: f64 = (0..poly.len())
        .map(|i| poly[i].perp_dot(poly[(i + 1) % poly.len()]))
        .sum();
    twice.abs() * 0.5
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Rect {
        Rect::new(DVec2::new(x0, y0), DVec2::new(x1, y1))
    }

    #[test]
    fn clipping_measures_what_lies_inside() {
        let r = rect(0.0, 0.0, 10.0, 10.0);
        let l = clipped_length(DVec2::new(-5.0, 5.0), DVec2::new(15.0, 5.0), &r);
        assert!((l - 10.0).abs() < 1e-9);
        assert_eq!(
            clipped_length(DVec2::new(-5.0, 11.0), DVec2::new(15.0, 11.0), &r),
            0.0
        );
        let square = [
            DVec2::new(5.0, 5.0),
            DVec2::new(15.0, 5.0),
            DVec2::new(15.0, 15.0),
            DVec2::new(5.0, 15.0),
        ];
        assert!((clipped_area(&square, &r) - 25.0).abs() < 1e-9);
        assert_eq!(clipped_area(&square, &rect(20.0, 20.0, 30.0, 30.0)), 0.0);
    }

    #[test]
    fn rectangles_touching_do_not_intersect() {
        let a = rect(0.0, 0.0, 1.0, 1.0);
        assert!(!a.intersects(&rect(1.0, 0.0, 2.0, 1.0)));
        assert!(a.intersects(&rect(0.5, 0.5, 2.0, 2.0)));
        assert!(a.inflate(1.0).contains(&a));
    }

    fn request(name: &str, at: DVec2, step: u32) -> Request {
        Request {
            view: 0,
            steps: vec![StepId(step)],
            names: vec![name.into()],
            anchor: at,
            toward: DVec2::X,
            gap: LABEL_GAP_MM,
        }
    }

    #[test]
    fn coincident_labels_join_with_the_pole_first() {
        let o = DVec2::new(10.0, 10.0);
        let joined = join_coincident(vec![
            request("b_3", o, 1),
            request("c", o + DVec2::new(5.0, 0.0), 2),
            request("d", o + DVec2::new(0.2, 0.0), 3),
            request("p", o + DVec2::new(0.1, 0.1), 4),
            request("d", o, 5),
            request("1", o, 6),
        ]);
        assert_eq!(joined.len(), 3);
        assert_eq!(joined[0].text(), "p ≡ b_3 ≡ d");
        assert_eq!(joined[0].steps.len(), 4);
        assert_eq!(joined[1].text(), "c");
        assert_eq!(joined[2].text(), "1");
    }

    #[test]
    fn candidates_keep_the_gap_and_start_with_the_preferred_side() {
        let r = request("B", DVec2::new(50.0, 50.0), 0);
        let size = DVec2::new(3.0, 4.0);
        let c = candidates(&r, size);
        assert_eq!(c.len(), 2 * DIRECTIONS);
        assert!(
            (c[0].min.x - 50.0 - LABEL_GAP_MM).abs() < 1e-9,
            "{:?}",
            c[0]
        );
        assert!((c[0].center().y - 50.0).abs() < 1e-9);
        for b in &c {
            assert!((b.size() - size).length() < 1e-9);
            let gap = (b.min - r.anchor).max(r.anchor - b.max).max(DVec2::ZERO);
            assert!(gap.length() >= LABEL_GAP_MM * 0.7 - 1e-9, "{b:?}");
        }
    }
}
