//! The lines of the moving links that a group slides on (the tangent mechanism's crank,
//! along which its block slides), drawn with their link on every drawing of the mechanism.

use super::built::Built;
use super::compiled::Compiled;
use super::part::Part;
use super::program::Program;
use crate::construct::fit::Extent;
use crate::construct::{Item, Recorder, Role};
use crate::geom::{DVec2, Segment};

/// How far a moving link's slide line is drawn past the block that slides on it, mm.
pub const SLIDE_PAST_MM: f64 = 12.0;

/// A guide carried by a moving link, as drawn at one position: the group that slides on it,
/// the carrying link, the piece of its line from the carrier's point to the joint (and
/// [`SLIDE_PAST_MM`] past it), the joint, and the joint's foot on the line with the unit
/// direction the line runs on past it.
struct SlideLine {
    group: usize,
    carrier: u32,
    segment: Segment,
    joint: DVec2,
    end: (DVec2, DVec2),
}

/// The guides of the moving links at the points `p` at μ_l = `mu` (drawing mm; SI at 1):
/// the crank's line that the tangent mechanism's block slides on, a rocker's line carrying a
/// slider.
fn slide_lines(prog: &Program, p: &[DVec2], mu: f64) -> Vec<SlideLine> {
    let n = prog.fixed.len();
    let mut v = Vec::new();
    for (group, joint, g) in prog.dyad_guides() {
        if g.is_fixed(n) || g.carrier == 0 {
            continue;
        }
        let Some(line) = prog.drawn_guide(&g, p, mu) else {
            continue;
        };
        let (foot, end) = (line.project_t(p[g.through]), line.project_t(p[joint]));
        let past = if end >= foot {
            SLIDE_PAST_MM
        } else {
            -SLIDE_PAST_MM
        };
        v.push(SlideLine {
            group,
            carrier: g.carrier as u32,
            segment: Segment::new(p[g.through], line.eval(end + past)),
            joint: p[joint],
            end: (line.eval(end), line.direction * past.signum()),
        });
    }
    v
}

/// What the slide lines `part` draws take at the position `p` (SI), at any μ_l: a carried
/// line from its carrier's point to [`SLIDE_PAST_MM`] past its joint's foot, a free one
/// that far either side of its joint.
pub(super) fn slide_extent(prog: &Program, p: &[DVec2], part: Part, e: &mut Extent) {
    for s in slide_lines(prog, p, 1.0) {
        if part.draws(prog, s.carrier) {
            e.add(s.segment.from);
            e.mark(s.end.0, s.end.1 * SLIDE_PAST_MM);
        } else if part == Part::Group(s.group) {
            let u = s.end.1 * SLIDE_PAST_MM;
            e.mark(s.joint, -u);
            e.mark(s.joint, u);
        }
    }
}

/// The slide lines of the moving links that `part` draws, with `role`: every link a group
/// slides on is drawn to the block that slides on it, on every drawing of the mechanism. A
/// group drawn apart shows the line of the link it slides on (another part's) as its free
/// element, thin, across its joint.
pub(super) fn draw_slide_lines(
    rec: &mut Recorder,
    prog: &Program,
    b: &Built,
    (role, note): (Role, &str),
    part: Part,
) {
    let mu = rec.scale().value();
    for s in slide_lines(prog, &b.p, mu) {
        let carried = part.draws(prog, s.carrier);
        if carried {
            rec.draw(
                format!("{note}: link {}: slide line", s.carrier),
                Item::Segment(s.segment),
                role,
                &[],
            );
        } else if part == Part::Group(s.group) {
            let u = (s.segment.to - s.segment.from).normalize_or_zero() * SLIDE_PAST_MM;
            rec.draw(
                format!("{note}: free slide line of link {}", s.carrier),
                Item::Segment(Segment::new(s.joint - u, s.joint + u)),
                Role::Construction,
                &[],
            );
        }
    }
}
