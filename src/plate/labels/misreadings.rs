//! The passes over the labels once each has its place, reading the layout as a reader
//! would: a label away from its object or struck through takes a leader, a shelf standing
//! over another text as a fraction's bar moves, a word read on into another is parted.

use super::away::{away, lines_between};
use super::leader;
use super::phrase;
use super::place::{struck, Job, Placer, Slot};
use super::*;

impl Placer<'_> {
    /// Every label whose place stands away from its object (beyond its reach, nearer another
    /// line, another text nearer its item) or is struck through by a line takes the best
    /// place on a leader instead where that costs less, in the placing order, each among the
    /// places and leaders the others have by then. A label kept near its point by its own bound keeps a place no line runs
    /// through nor parts from its point.
    pub(super) fn put_on_leaders(
        &self,
        jobs: &[Job],
        slots: &mut [Option<Slot>],
        order: &[usize],
        points: &[(usize, DVec2)],
    ) {
        for &i in order {
            let (job, Some(now)) = (&jobs[i], slots[i]) else {
                continue;
            };
            let bound = job.request.within.is_some();
            let others = self.others_near(job.near, slots, i);
            let clear = match bound {
                true => lines_between(job, &now.rect) == 0,
                false => away(job, &now.rect, &others.texts, 0.0) == 0.0,
            };
            // A number in its column stays there, struck or not: a leader would point at
            // its place, not at its point on the axis.
            if job.request.column.is_some() || (!struck(job, &now.rect) && clear) {
                continue;
            }
            let on_leader = self.leader_job(job.request.clone(), points);
            let cost_now = self.cost(job, &now, &others, f64::INFINITY);
            let (slot, cost) = self.best_below(&on_leader, slots, i, cost_now - 1e-9);
            if cost < cost_now - 1e-9 {
                slots[i] = Some(slot);
            }
        }
    }

    /// Every label on a shelf with another text right under it (read as a fraction, the
    /// shelf its bar: `0` over `O₂`) takes the best place on a leader paying for that, in the
    /// placing order.
    pub(super) fn lift_fractions(
        &self,
        jobs: &[Job],
        slots: &mut [Option<Slot>],
        order: &[usize],
        points: &[(usize, DVec2)],
    ) {
        for &i in order {
            let Some(Slot {
                leader: Some(now), ..
            }) = slots[i]
            else {
                continue;
            };
            let band = leader::under_shelf_band(&now).inflate(CLEARANCE_MM);
            let others = self.others_near(band, slots, i);
            if !others.texts.iter().any(|t| leader::under_shelf(&now, t)) {
                continue;
            }
            let mut on_leader = self.leader_job(jobs[i].request.clone(), points);
            on_leader.fractions = true;
            slots[i] = Some(self.best(&on_leader, slots, i).0);
        }
    }

    /// Every word label written right under or over another word label without a shelf
    /// between (read as one phrase: «involute» over «limit point»), and every name or chain
    /// of a point's names with a text right beside it on its row («интерференция 1» before
    /// the axis's «0», «d₅′ ≡ e′ ≡ s₅′» before «b₃′», «S₂» after the link number «2»),
    /// takes the best place, free or on a leader (a symbol: free), paying for each text it
    /// would read on from or into, in the placing order.
    pub(super) fn part_phrases(
        &self,
        jobs: &[Job],
        slots: &mut [Option<Slot>],
        order: &[usize],
        points: &[(usize, DVec2)],
    ) {
        let words = |i: usize| phrase::is_words(&jobs[i].text);
        // The words and chains first: a symbol moved off one first leaves it a hair past the
        // gap, still read on (the shaper's «d₅′ ≡ e′ ≡ s₅′» before «b₃′», b₃′ moved 1,4 mm).
        let is_phrase = |i: &usize| words(*i) || phrase::is_chain(&jobs[*i].text);
        let (mut readers, symbols): (Vec<usize>, Vec<usize>) = order
            .iter()
            .copied()
            .filter(|&i| phrase::is_name(&jobs[i].text) || phrase::is_chain(&jobs[i].text))
            .partition(is_phrase);
        readers.extend(symbols);
        for &i in &readers {
            let Some(now) = slots[i] else { continue };
            let others: Vec<(Rect, bool)> = readers
                .iter()
                .filter(|&&j| j != i && words(j))
                .filter_map(|&j| slots[j].map(|s| (s.rect, s.leader.is_some())))
                .collect();
            let shelf = now.leader.is_some();
            let stacked = words(i)
                && others
                    .iter()
                    .any(|(t, on)| phrase::read_as_one(&now.rect, shelf, t, *on));
            let near = self.others_near(now.rect.inflate(phrase::SIDE_GAP_MM), slots, i);
            if !stacked && !near.texts.iter().any(|t| phrase::beside(&now.rect, t)) {
                continue;
            }
            // The texts a place reads on into stand up to a gap beside it.
            let mut free = self.job(jobs[i].request.clone(), points);
            free.phrases = Some(others.clone());
            free.near = free.near.inflate(phrase::SIDE_GAP_MM);
            let mut on_leader = self.leader_job(jobs[i].request.clone(), points);
            on_leader.phrases = Some(others);
            on_leader.near = on_leader.near.inflate(phrase::SIDE_GAP_MM);
            on_leader.fractions = true;
            let (a, cost_a) = self.best(&free, slots, i);
            // A symbol takes a free place only: on a shelf it stands in a row of names as
            // well (the shaper's R₃₋₂ on a shelf before «G₂ R₁₋₂»).
            if !is_phrase(&i) {
                slots[i] = Some(a);
                continue;
            }
            let (b, cost_b) = self.best(&on_leader, slots, i);
            slots[i] = Some(if cost_a <= cost_b { a } else { b });
        }
    }
}
