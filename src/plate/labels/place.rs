//! Placing labels: candidate boxes around each anchor, scored against text, points and
//! lines already on the view, in a fixed order with repair rounds.

use super::away::away;
use super::candidates::{candidates, near_bound, NEAR_RING_MM};
use super::clip::ink_inside;
use super::costs::{OVER_POINT, OVER_TEXT};
use super::leader::{self, Leader};
use super::phrase;
use super::*;

pub(super) struct Placer<'a> {
    frame: Rect,
    forbidden: [Rect; 2],
    /// Boxes of the texts that do not move (captions, text blocks, tables, dimensions).
    fixed: Vec<Rect>,
    /// The leaders of the dimensions' texts, which do not move either (a label under one's
    /// shelf reads as a fraction).
    fixed_leaders: Vec<Leader>,
    /// Every view's outlines (a label avoids the lines of every view).
    outlines: &'a [Vec<Outline>],
    /// Every view's outlines with their boxes and their view, taken once (a gear's profile
    /// is thousands of points, and every label looks for the lines near it).
    boxed: Vec<(Rect, usize, &'a Outline)>,
}

/// Cost of a box leaving the frame or entering the title block.
const OUTSIDE: f64 = 1e5;
/// How far inside the frame's line, and off the title block and the designation box, a label
/// keeps, mm: the V engine's R₄₋₅ 0,3 mm from the frame, touching the designation box, read
/// as written on them, and its F_и5 1,5 mm from the frame at the sheet's corner as crowded
/// against it (issue 45).
const FRAME_CLEAR_MM: f64 = 2.5;
/// A box over another text costs [`OVER_TEXT`] plus its overlap area (mm²) times this.
const TEXT_AREA: f64 = 100.0;
/// Cost per mm of a main line crossing the box; of a thin line (a label a ring further out is
/// cheaper than one struck through by a construction line).
const MAIN_LINE: f64 = 20.0;
pub(super) const THIN_LINE: f64 = 10.0;
/// Cost of any line running into a label's box at all, over its cost per mm: a label a
/// line runs through reads as struck out however short the piece (a long joint label such
/// as `d₅ ≡ e ≡ s₅` touched by the end of a direction line), so its corner places and the
/// outer rings of [`candidates`] are taken before it (issue 19, item 6).
pub(super) const STRUCK: f64 = 25.0;
/// Cost of touching a main symbol (pair, block, arrowhead, dot), and per mm² of it covered;
/// the same for a thin one.
const MAIN_AREA: f64 = 40.0;
const THIN_AREA: f64 = 6.0;
/// Cost per rank of the candidate (the preferred position is rank 0).
const RANK: f64 = 0.5;
/// Rounds of moving the labels that still collide.
const REPAIR_ROUNDS: usize = 4;

/// A request with what lies near its point: its text, the outlines, the other labels' points.
pub(super) struct Job<'a> {
    pub(super) request: Request,
    pub(super) text: String,
    extent: Extent,
    candidates: Vec<Rect>,
    /// The leader of each candidate, where its candidates are on leaders ([`leader`]).
    leaders: Vec<Leader>,
    pub(super) near: Rect,
    /// The outlines near it, with their boxes.
    pub(super) lines: Vec<(Rect, &'a Outline)>,
    /// The lines near it, of every view, that are not its item's (a label of an item keeps
    /// nearer its item than any of them).
    pub(super) rivals: Vec<(DVec2, DVec2)>,
    /// The other labelled points near it, of every view.
    pub(super) points: Vec<DVec2>,
    /// The cost per rank of its candidates.
    rank_cost: f64,
    /// Whether a place on a leader pays for each other text right under its shelf
    /// ([`leader::under_shelf`]): in [`Placer::lift_fractions`], once every label stands
    /// where it will (before, a text under a shelf may be one about to move).
    pub(super) fractions: bool,
    /// In [`Placer::part_phrases`] (once every label stands where it will), for a word
    /// label: the other word labels, each with whether it is on a shelf. A place pays for
    /// each it reads on from or into ([`phrase::read_as_one`]), for each text beside it
    /// on its row ([`phrase::beside`]) and for each shelf right over it
    /// ([`leader::under_shelf`]).
    pub(super) phrases: Option<Vec<(Rect, bool)>>,
}

/// Where a label is: its box and the rank of that candidate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Slot {
    pub(super) rect: Rect,
    pub(super) rank: usize,
    pub(super) leader: Option<Leader>,
}

/// The other texts near a label, and the other labels' leaders.
pub(super) struct Others {
    pub(super) texts: Vec<Rect>,
    leaders: Vec<Leader>,
}

impl<'a> Placer<'a> {
    pub(super) fn new(layout: &Layout, outlines: &'a [Vec<Outline>]) -> Self {
        let fixed = layout
            .views
            .iter()
            .filter_map(|v| v.caption)
            .chain(layout.texts.iter().copied())
            .chain(layout.tables.iter().copied())
            .collect();
        let boxed = outlines
            .iter()
            .enumerate()
            .flat_map(|(k, v)| v.iter().map(move |o| (k, o)))
            .filter_map(|(k, o)| Some((shape_box(&o.shape)?, k, o)))
            .collect();
        Placer {
            frame: layout.frame.inflate(-FRAME_CLEAR_MM),
            forbidden: [layout.title_block, layout.designation_box]
                .map(|r| r.inflate(FRAME_CLEAR_MM)),
            fixed,
            fixed_leaders: Vec::new(),
            outlines,
            boxed,
        }
    }

    pub(super) fn place(mut self, plate: &Plate) -> Vec<PlacedLabel> {
        let mut out = Vec::new();
        let mut todo = Vec::new();
        for (k, view) in plate.views.iter().enumerate() {
            let mut texts = self.fixed.clone();
            texts.extend(out.iter().map(|l: &PlacedLabel| l.rect));
            let (r, f) = requests(k, view, &self.outlines[k], &texts);
            out.extend(f);
            todo.extend(r);
        }
        self.fixed.extend(out.iter().map(|l| l.rect));
        self.fixed_leaders = out.iter().filter_map(|l| l.leader).collect();
        let points: Vec<(usize, DVec2)> = todo.iter().map(|r| (r.view, r.anchor)).collect();
        let jobs: Vec<Job> = todo.into_iter().map(|r| self.job(r, &points)).collect();
        // Labels of points first, the most crowded first: a point's label has a few places
        // about its point, an item's a whole line to sit along; among each, the most crowded
        // have the fewest free places.
        let crowd = |j: &Job| {
            let r = &j.request;
            points
                .iter()
                .filter(|(v, p)| *v == r.view && p.distance(r.anchor) < 8.0)
                .count()
        };
        let mut order: Vec<(usize, bool, usize, usize)> = jobs
            .iter()
            .enumerate()
            .map(|(i, j)| {
                let item = j.request.names_of == Names::Item;
                (j.request.view, item, usize::MAX - crowd(j), i)
            })
            .collect();
        order.sort_unstable();
        let order: Vec<usize> = order.into_iter().map(|o| o.3).collect();
        let mut slots: Vec<Option<Slot>> = vec![None; jobs.len()];
        for &i in &order {
            slots[i] = Some(self.best(&jobs[i], &slots, i).0);
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
        self.put_on_leaders(&jobs, &mut slots, &order, &points);
        self.lift_fractions(&jobs, &mut slots, &order, &points);
        self.part_phrases(&jobs, &mut slots, &order, &points);
        out.extend(jobs.into_iter().zip(slots).filter_map(|(j, s)| {
            let Slot { rect, leader, .. } = s?;
            Some(PlacedLabel {
                view: j.request.view,
                steps: j.request.steps,
                anchor: j.request.anchor,
                placed: written(&j.text, &j.extent, rect),
                rect,
                leader,
                text: j.text,
            })
        }));
        out
    }

    /// A request with its candidates and what lies near them.
    pub(super) fn job(&self, request: Request, points: &[(usize, DVec2)]) -> Job<'a> {
        let text = request.text();
        let extent = measure(&text, LABEL_HEIGHT_MM);
        let candidates = candidates(&request, extent.max - extent.min);
        self.job_at(request, points, text, extent, (candidates, Vec::new()))
    }

    /// The job of `request` on leaders: its places on a leader ([`leader::candidates`]).
    pub(super) fn leader_job(&self, request: Request, points: &[(usize, DVec2)]) -> Job<'a> {
        let text = request.text();
        let extent = measure(&text, LABEL_HEIGHT_MM);
        let (rects, leaders) = leader::candidates(&request, extent.max - extent.min)
            .into_iter()
            .unzip();
        let mut job = self.job_at(request, points, text, extent, (rects, leaders));
        job.rank_cost = leader::RANK;
        job
    }

    /// A job of `request` with its `candidates` (and their leaders, where they have any).
    fn job_at(
        &self,
        request: Request,
        points: &[(usize, DVec2)],
        text: String,
        extent: Extent,
        (candidates, leaders): (Vec<Rect>, Vec<Leader>),
    ) -> Job<'a> {
        // A near label's candidates are denser (see [`candidates`]): each costs less, so
        // that a millimetre further out costs what it costs any label.
        let rank_cost = if near_bound(&request).is_some() {
            RANK * 0.5 * NEAR_RING_MM / SECOND_RING_MM
        } else {
            RANK
        };
        let near = candidates
            .iter()
            .copied()
            .chain(leaders.iter().map(|l| Rect::new(l.to, l.to)))
            .fold(Rect::new(request.anchor, request.anchor), |r, c| {
                r.union(&c)
            })
            .inflate(CLEARANCE_MM);
        // Every view's lines: a long joint label must not run over the next plan either.
        let lines = self
            .boxed
            .iter()
            .filter(|(b, _, _)| b.touches(&near))
            .map(|&(b, _, o)| (b, o))
            .collect();
        // Any view's lines: a force's label nearer the next drawing's line reads as its.
        let rivals = match request.own.is_empty() {
            true => Vec::new(),
            false => self
                .boxed
                .iter()
                .filter(|(b, _, o)| b.touches(&near) && !request.own.contains(*o))
                .filter_map(|(_, _, o)| match o.shape {
                    Shape::Line(a, b) => Some((a, b)),
                    Shape::Area(_) => None,
                })
                .collect(),
        };
        // The labelled points of every view: a label written nearer the next plan's pole
        // than its own point is read as that plan's (issue 45: the shaper's position 5's
        // `d₅ ≡ e ≡ s₅` over position 6's p).
        let points = points
            .iter()
            .filter(|(_, p)| *p != request.anchor && near.contains(&Rect::new(*p, *p)))
            .map(|(_, p)| *p)
            .collect();
        Job {
            request,
            text,
            extent,
            candidates,
            leaders,
            near,
            lines,
            rivals,
            points,
            rank_cost,
            fractions: false,
            phrases: None,
        }
    }

    /// The least colliding candidate of `job`, label `i`, with the other labels where `slots`
    /// has them (the first of equals), and its cost.
    pub(super) fn best(&self, job: &Job, slots: &[Option<Slot>], i: usize) -> (Slot, f64) {
        self.best_below(job, slots, i, f64::INFINITY)
    }

    /// The cheapest place of `job` ([`best`](Self::best)) among those costing less than
    /// `bound`; a place costing no less, with the cost `bound`, when there is none.
    pub(super) fn best_below(
        &self,
        job: &Job,
        slots: &[Option<Slot>],
        i: usize,
        bound: f64,
    ) -> (Slot, f64) {
        let others = self.others_near(job.near, slots, i);
        let mut best = (
            Slot {
                rect: job.candidates[0],
                rank: 0,
                leader: job.leaders.first().copied(),
            },
            bound,
        );
        for (rank, &rect) in job.candidates.iter().enumerate() {
            let leader = job.leaders.get(rank).copied();
            let slot = Slot { rect, rank, leader };
            let cost = self.cost(job, &slot, &others, best.1);
            if cost < best.1 {
                best = (slot, cost);
            }
        }
        best
    }

    /// The boxes of texts within `near` — the fixed ones and the placed labels but `i` — and
    /// the other labels' leaders.
    pub(super) fn others_near(&self, near: Rect, slots: &[Option<Slot>], i: usize) -> Others {
        let placed = || {
            slots
                .iter()
                .enumerate()
                .filter(|(j, _)| *j != i)
                .filter_map(|(_, s)| *s)
        };
        Others {
            texts: self
                .fixed
                .iter()
                .copied()
                .chain(placed().map(|s| s.rect))
                .filter(|t| t.intersects(&near))
                .collect(),
            leaders: (self.fixed_leaders.iter().copied())
                .chain(placed().filter_map(|s| s.leader))
                .collect(),
        }
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
        let cost_now = self.cost(
            &jobs[i],
            &now,
            &self.others_near(jobs[i].near, slots, i),
            f64::INFINITY,
        );
        let (alone, cost) = self.best(&jobs[i], slots, i);
        if cost < cost_now - 1e-9 {
            slots[i] = Some(alone);
            return true;
        }
        for j in blockers {
            let before = cost_now + {
                let mut without = slots.to_vec();
                without[i] = None;
                let s = slots[j].expect("placed");
                self.cost(
                    &jobs[j],
                    &s,
                    &self.others_near(jobs[j].near, &without, j),
                    f64::INFINITY,
                )
            };
            let mut trial = slots.to_vec();
            trial[i] = None;
            trial[j] = None;
            let (si, ci) = self.best(&jobs[i], &trial, i);
            trial[i] = Some(si);
            let (sj, cj) = self.best(&jobs[j], &trial, j);
            if ci + cj < before - 1e-9 {
                slots[i] = Some(si);
                slots[j] = Some(sj);
                return true;
            }
        }
        false
    }

    /// What placing `job` at `slot` costs among the texts `others`; once the sum (of terms
    /// never negative) reaches `bound`, the sum so far (the slot cannot beat a slot of that
    /// cost).
    pub(super) fn cost(&self, job: &Job, slot: &Slot, others: &Others, bound: f64) -> f64 {
        let rect = &slot.rect;
        let mut cost = slot.rank as f64 * job.rank_cost;
        let drawn = slot.leader.map_or(*rect, |l| {
            rect.union(&Rect::new(l.knee.min(l.end), l.knee.max(l.end)))
        });
        if !self.frame.contains(&drawn) || self.forbidden.iter().any(|f| f.intersects(&drawn)) {
            cost += OUTSIDE;
        }
        if cost >= bound {
            return cost;
        }
        let padded = rect.inflate(CLEARANCE_MM * 0.5);
        for t in &others.texts {
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
        if let Some(words) = &job.phrases {
            let shelf = slot.leader.is_some();
            let read_on = words
                .iter()
                .filter(|(t, on)| phrase::read_as_one(rect, shelf, t, *on))
                .count()
                + others
                    .texts
                    .iter()
                    .filter(|t| phrase::beside(rect, t))
                    .count();
            cost += read_on as f64 * phrase::STACKED;
        }
        // Any label: not stood under another's shelf (a leader's, a dimension line's run on)
        // as the denominator of a fraction.
        let under = (others.leaders.iter())
            .filter(|l| leader::under_shelf(l, rect))
            .count();
        cost += under as f64 * phrase::STACKED;
        if cost >= bound {
            return cost;
        }
        cost = match slot.leader {
            // A text another label's leader runs through reads as struck (its cost as the
            // leader's through it: a label moved after the leaders were set).
            None => {
                let through = (others.leaders.iter())
                    .filter(|l| leader::runs_through(l, rect))
                    .count();
                away(job, rect, &others.texts, cost) + through as f64 * OVER_TEXT
            }
            Some(l) => {
                let fractions = if job.fractions {
                    others
                        .texts
                        .iter()
                        .filter(|t| leader::under_shelf(&l, t))
                        .count()
                } else {
                    0
                };
                cost + leader::cost(
                    &l,
                    rect,
                    &job.lines,
                    &job.points,
                    &others.texts,
                    &others.leaders,
                ) + fractions as f64 * leader::UNDER_SHELF
            }
        };
        for (bounds, o) in &job.lines {
            if cost >= bound {
                return cost;
            }
            // An outline whose box is clear of the label's adds nothing (its clipped length
            // or area is exactly 0).
            if !bounds.touches(&padded) {
                continue;
            }
            let inside = ink_inside(o, &padded);
            cost += match (&o.shape, inside > 0.0) {
                (_, false) => 0.0,
                (Shape::Line(..), true) => {
                    STRUCK + inside * if o.main { MAIN_LINE } else { THIN_LINE }
                }
                (Shape::Area(_), true) => {
                    (1.0 + inside) * if o.main { MAIN_AREA } else { THIN_AREA }
                }
            };
        }
        cost
    }
}

/// Whether a line or symbol of the view runs through the label at `rect` (within half the
/// clearance a label keeps).
pub(super) fn struck(job: &Job, rect: &Rect) -> bool {
    let padded = rect.inflate(CLEARANCE_MM * 0.5);
    job.lines
        .iter()
        .any(|(bounds, o)| bounds.touches(&padded) && ink_inside(o, &padded) > 0.0)
}

/// The text written so that its box is `rect`.
pub(super) fn written(text: &str, e: &Extent, rect: Rect) -> Placed {
    Placed::new(rect.min - e.min, text, LABEL_HEIGHT_MM, Align::Start)
}
