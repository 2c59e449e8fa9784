//! The structural scheme: the mechanism at position 1 with its link numbers, and beside it
//! the decomposition into the class-I mechanism and the Assur groups, each drawn apart.

use super::built::Built;
use super::model::Sense;
use super::part::Part;
use super::positions_draw::{draw_guides, draw_links, draw_pivots, frame_guides, name_points};
use super::program::Program;
use super::structure::Structure;
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::{Arc, DVec2, Segment};
use crate::scale::Scale;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// Gap between the parts of the decomposition, mm.
const GAP_MM: f64 = 14.0;
/// Half-length of a guide piece on the scheme, beyond its joint, mm.
const GUIDE_MM: f64 = 12.0;

fn shifted(b: &Built, factor: f64, shift: DVec2) -> Built {
    let mut c = b.clone();
    c.p.iter_mut().for_each(|p| *p = *p * factor + shift);
    c
}

/// Bounds of the steps recorded from `start` on.
fn bounds_from(rec: &Recorder, start: usize) -> (DVec2, DVec2) {
    let f = Figure {
        title: String::new(),
        scale: rec.scale(),
        steps: rec.steps()[start..].to_vec(),
        readings: Vec::new(),
    };
    f.bounds().unwrap_or((DVec2::ZERO, DVec2::ZERO))
}

/// Draw the structural scheme of `prog` from its constructed position 1 (`first`, at μ_l =
/// `plan_mu`) at the scale `scale`: the whole mechanism with its link numbers and the frame's
/// guides, and to its right, given the structure `st`, the class-I mechanism and each Assur
/// group drawn apart (their outer pairs free), captioned with the terms of the structure
/// formula; without `st`, the kinematic scheme alone (a task gives the mechanism whole: its
/// groups are the student's to find).
pub fn structure_figure(
    prog: &Program,
    st: Option<&Structure>,
    (first, sense): (&Built, Sense),
    plan_mu: f64,
    scale: Scale,
    ctx: &Context,
) -> Figure {
    let factor = plan_mu / scale.value();
    let mut rec = Recorder::in_context("scheme", scale, ctx);
    let whole = shifted(first, factor, DVec2::ZERO);
    // The frame's guides under the sliders on them, as on the plan of positions.
    let guides = frame_guides(prog, &[&whole], GUIDE_MM);
    draw_guides(&mut rec, &guides);
    let anchors = draw_links(&mut rec, prog, &whole, Role::Given, "scheme", Part::All);
    draw_pivots(&mut rec, prog, &whole);
    crank_rotation(&mut rec, prog, &whole, sense);
    name_points(&mut rec, prog, &whole, Part::All, false);
    number_links(&mut rec, &anchors);
    let Some(st) = st else {
        return rec.finish();
    };
    let (_, hi0) = bounds_from(&rec, 0);
    let mut x = hi0.x + 2.0 * GAP_MM;
    let parts = std::iter::once((Part::Driver, format!("I(0,{})", st.crank_link))).chain(
        st.groups.iter().enumerate().map(|(g, gi)| {
            (
                Part::Group(g),
                format!("II({},{})", gi.links[0], gi.links[1]),
            )
        }),
    );
    for (part, caption) in parts {
        // Draw once to measure the part, then again in its place, top-aligned with the whole.
        let mut probe = Recorder::in_context("part", scale, ctx);
        draw_links(&mut probe, prog, &whole, Role::Given, "part", part);
        let (mut lo, mut hi) = bounds_from(&probe, 0);
        // The group's free guide element is drawn with it: the part's room holds it too
        // (the V engine's blocks 3 and 5 stood 3 mm apart, their guides crossing).
        for g in guides.iter().filter(|g| Part::Group(g.group) == part) {
            for p in [g.segment.from, g.segment.to] {
                (lo, hi) = (lo.min(p), hi.max(p));
            }
        }
        let shift = DVec2::new(x - lo.x, hi0.y - hi.y);
        let placed = shifted(first, factor, shift);
        let anchors = draw_links(&mut rec, prog, &placed, Role::Given, &caption, part);
        // The frame's guide of a group is its free element: drawn thin, without hatching.
        for g in guides.iter().filter(|g| Part::Group(g.group) == part) {
            let seg = Segment::new(g.segment.from + shift, g.segment.to + shift);
            rec.draw(
                format!("{caption}: free guide element"),
                Item::Segment(seg),
                Role::Construction,
                &[],
            );
        }
        number_links(&mut rec, &anchors);
        let cap_at = DVec2::new(x + (hi.x - lo.x) * 0.5, lo.y + shift.y - 7.0);
        let id = rec.draw(
            format!("caption {caption}"),
            Item::Text(cap_at),
            Role::Dimension,
            &[],
        );
        rec.label(id, caption, cap_at, DVec2::ZERO);
        x += (hi.x - lo.x).max(10.0) + GAP_MM;
    }
    rec.finish()
}

/// The radius of the crank's arc arrow ω₁ about its pivot on the scheme, mm.
const OMEGA_MM: f64 = 9.0;
/// The arc arrow's sweep, radians (about 90°).
const OMEGA_SWEEP: f64 = 1.6;

/// The crank's sense of rotation as the task gives it: an arc arrow ω₁ about its pivot, in
/// the wider of the two gaps between the crank and the pivot's support (drawn under it).
fn crank_rotation(rec: &mut Recorder, prog: &Program, at: &Built, sense: Sense) {
    let o = at.p[prog.centre];
    let crank = (at.p[prog.pin] - o).to_angle();
    let down = -FRAC_PI_2;
    // The middle of the gap running counter-clockwise from the crank to the support, or of
    // the other one, whichever is wider.
    let ccw = (down - crank).rem_euclid(TAU);
    let mid = if ccw >= PI {
        crank + 0.5 * ccw
    } else {
        crank - 0.5 * (TAU - ccw)
    };
    let sweep = sense.sign() * OMEGA_SWEEP;
    let arc = Arc {
        center: o,
        radius: OMEGA_MM,
        start: mid - 0.5 * sweep,
        sweep,
    };
    let name = format!("ω_{{{}}}", prog.crank_link);
    let id = rec.draw(
        format!("the crank's rotation {name}"),
        Item::Moment(arc),
        Role::Given,
        &[],
    );
    let out = DVec2::from_angle(mid);
    rec.label_item(id, &name, o + out * OMEGA_MM, out);
}

fn number_links(rec: &mut Recorder, anchors: &[(u32, DVec2)]) {
    for (l, at) in anchors {
        let id = rec.draw(
            format!("number of link {l}"),
            Item::Text(*at),
            Role::Dimension,
            &[],
        );
        rec.label(id, l.to_string(), *at, DVec2::new(-0.6, 0.8).normalize());
    }
}

impl super::positions::PositionPlan {
    /// The structural scheme of the plan's mechanism drawn at `scale` (see
    /// [`structure_figure`]) from the position that shows its links best: not an extreme
    /// position (where a crank and its rocker or slot fold into line), and of those the one
    /// whose construction crossed at the widest angle (first on a tie).
    pub fn scheme(&self, st: Option<&Structure>, scale: Scale, ctx: &Context) -> Figure {
        let plan_mu = self.figure.scale.value();
        let openness = |p: &&super::positions::PlanPosition| {
            p.built
                .crossing
                .iter()
                .copied()
                .fold(f64::INFINITY, f64::min)
        };
        let shown = self
            .positions
            .iter()
            .filter(|p| !p.extreme)
            .fold(
                None,
                |best: Option<&super::positions::PlanPosition>, p| match best {
                    Some(b) if openness(&b) >= openness(&p) => Some(b),
                    _ => Some(p),
                },
            )
            .or(self.positions.first());
        match shown {
            Some(first) => structure_figure(
                &self.program,
                st,
                (&first.built, self.mechanism.crank.sense),
                plan_mu,
                scale,
                ctx,
            ),
            None => Figure {
                title: String::new(),
                scale,
                steps: Vec::new(),
                readings: Vec::new(),
            },
        }
    }

    /// The name of point `k` (program index), in label markup; empty for no such point.
    pub fn point_name(&self, k: usize) -> &str {
        self.program.names.get(k).map_or("", String::as_str)
    }
}
