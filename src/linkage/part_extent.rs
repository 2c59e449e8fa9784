//! What a part's drawing takes, predicted at any μ_l before it is drawn (the force sheets
//! size their μ_l by it): the points of its links and what [`super::draw_links`] draws a
//! fixed length from a point.

use super::analytic::state::Pose;
use super::part::Part;
use super::program::{Op, Program};
use crate::construct::fit::Extent;

impl Part {
    /// What its drawing ([`super::draw_links`]) takes at the position `pose`, at any μ_l,
    /// taken into `e`: the points of the links it draws (SI), and what is drawn a fixed
    /// length from a point (a kind's link run on past its pin, a slide line past its block).
    pub(crate) fn extent(self, prog: &Program, pose: &Pose, e: &mut Extent) {
        for (k, &p) in pose.p.iter().enumerate() {
            if prog.links_of(k).iter().any(|&l| self.draws(prog, l as u32)) {
                e.add(p);
            }
        }
        for op in &prog.ops {
            if let Op::Dyad { group, links, dyad } = op {
                if matches!(self, Part::All) || self == Part::Group(*group) {
                    for (at, off) in dyad.group().drawn_past(&pose.p, &pose.dir, *links) {
                        e.mark(at, off);
                    }
                }
            }
        }
        super::slide_lines::slide_extent(prog, &pose.p, self, e);
    }
}
