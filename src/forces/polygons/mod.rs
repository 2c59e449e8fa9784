//! Force polygons (планы сил) as drawing-board constructions, group by group from the group
//! farthest from the driving link, then the driving link. Every arm is measured on the
//! group's drawing at μ_l and every reaction read off its polygon at μ_F, both under the
//! drafting model.
//!
//! Per kind (i, j the group's links; A, C the outer pairs, B the inner):
//! * RRR — F^τ of each outer reaction from the moments of its link about B; the polygon
//!   F^τ_A, loads of i, loads of j, F^τ_C is closed by lines ∥ AB and ∥ CB; the inner
//!   reaction joins the end of i's loads to the closing point.
//! * RRP — F^τ_A as above; closed by the line ∥ AB and the normal to the guide; the guide's
//!   reaction acts at h = −ΣM_B(j)/R from B.
//! * RPR — the inner reaction (normal to the slide) from the moments of link j about its
//!   pivot with the block's moment carried over; each link's polygon closes on it.
//! * PRP — closed by the two guides' normals; each reaction's point from its link's moments.
//! * RPP — link j's polygon closed by the normals to the slide and to the guide; the block's
//!   triangle gives the outer reaction.
//!
//! The driving link: through a coupling the balancing moment M_у = −ΣM_O; through a gear the
//! balancing force along the line of action at the pitch point from ΣM_O = 0 (its arm
//! measured), and the frame's reaction closes the triangle.

use super::loads::{Load, LoadKind};
use super::spec::Drive;
use super::twin::{line_of_action, Pair, PairKind, Reaction};
use crate::construct::{ConstructionError, Figure, Item, Role};
use crate::geom::{Circle, DVec2, Segment};
use crate::linkage::{draw_links, name_points, Built, Part, PlanSetup};
use crate::scale::Scale;
use std::f64::consts::{PI, TAU};

mod detail;
mod driver;
mod equations;
mod extent;
mod kinds;
mod polygon;
mod scheme;
mod wall;
pub use detail::{letter_at, letter_toward, PolygonDetail};
use driver::driver;
pub use equations::{MomentEquation, MomentTerm, Unknown};
pub(crate) use extent::predicted;
use kinds::Work;
use polygon::Polygon;
use scheme::{show_reaction, Scheme};
#[cfg(test)]
pub(super) use {extent::drawings, scheme::ARROW_MM};

/// One group's force analysis as drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct GroupPolygon {
    /// Group index (file order).
    pub group: usize,
    /// Its links.
    pub links: [usize; 2],
    /// The group drawn apart at μ_l with its loads, reactions and measured arms.
    pub scheme: Figure,
    /// Its force polygon at μ_F.
    pub polygon: Figure,
    /// The polygon's small forces enlarged, when some are too short to read.
    pub details: Vec<PolygonDetail>,
    /// The reactions read off the polygon: the two outer pairs, then the inner.
    pub reactions: Vec<Reaction>,
    /// The moment equations the group's drawing works, in the order they are solved.
    pub equations: Vec<MomentEquation>,
}

/// The driving link's analysis as drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct DriverPolygon {
    /// The crank (with its wheel and line of action) at μ_l.
    pub scheme: Figure,
    /// Its force triangle at μ_F.
    pub polygon: Figure,
    /// The triangle's small forces enlarged, when some are too short to read.
    pub details: Vec<PolygonDetail>,
    /// The frame's reaction on the crank.
    pub reaction: Reaction,
    /// The balancing moment, N·m.
    pub m_bal: f64,
    /// The balancing force (gear drive), N.
    pub f_bal: Option<f64>,
    /// The balancing force's arm about the crank's centre, measured (gear drive), m.
    pub arm: Option<f64>,
    /// ΣM about the crank's centre, which gives the balancing load.
    pub equation: MomentEquation,
}

/// Everything one position's polygons give.
#[derive(Debug, Clone, PartialEq)]
pub struct Polygons {
    /// The groups, from the last attached to the first.
    pub groups: Vec<GroupPolygon>,
    /// The driving link.
    pub driver: DriverPolygon,
    /// The arms numbered on these drawings, `h_{1}` … `h_{arms}`: the lever numbers on.
    pub arms: usize,
}

impl Polygons {
    /// Every reaction read off the polygons: the groups' from the last to the first, then
    /// the frame's on the crank.
    pub fn reactions(&self) -> Vec<Reaction> {
        self.groups
            .iter()
            .rev()
            .flat_map(|g| g.reactions.iter().copied())
            .chain(std::iter::once(self.driver.reaction))
            .collect()
    }
}

/// What the polygons of a position start from: the position as every drawing of it does
/// ([`PlanSetup`]) and μ_F.
pub struct Board<'a> {
    /// The mechanism, the constructed position, μ_l, ω₁ and the context.
    pub setup: PlanSetup<'a>,
    /// μ_F of the position (its largest force's): every polygon's where `own` gives none.
    pub mu_f: Scale,
    /// Each polygon's own μ_F, the textbook's choice for each plan of forces (its own
    /// largest force about [`crate::forces::POLYGON_MM`] long): by group index (file order),
    /// then the driving link's; empty when the scene sets one μ_F for all.
    pub own: Vec<Scale>,
}

impl Board<'_> {
    /// μ_F of group `group`'s polygon (`None`: the driving link's).
    fn scale_of(&self, group: Option<usize>) -> Scale {
        let k = group.unwrap_or_else(|| self.setup.prog.groups().count());
        self.own.get(k).copied().unwrap_or(self.mu_f)
    }

    /// Point `k` of the position on the drawing, mm.
    fn point(&self, k: usize) -> DVec2 {
        self.setup.built.p[k]
    }

    /// The direction of link `l` on the drawing.
    fn dir(&self, l: usize) -> DVec2 {
        DVec2::from_angle(self.setup.built.angle[l])
    }

    /// The crank's sense, +1 counter-clockwise.
    fn sense(&self) -> f64 {
        self.setup.w1.signum()
    }
}

/// The markup name of the force of link `a` on link `b`.
pub fn reaction_name(a: usize, b: usize) -> String {
    format!("R_{{{a}-{b}}}")
}

fn revolute(from: usize, to: usize, k: usize, force: DVec2) -> Reaction {
    Reaction {
        pair: Pair {
            from,
            to,
            kind: PairKind::Revolute(k),
        },
        force,
        offset: None,
    }
}

fn prismatic(
    from: usize,
    to: usize,
    reference: usize,
    dir_link: usize,
    force: DVec2,
    offset: Option<f64>,
) -> Reaction {
    Reaction {
        pair: Pair {
            from,
            to,
            kind: PairKind::Prismatic {
                reference,
                dir_link,
            },
        },
        force,
        offset,
    }
}

/// The loads (and the reactions already found) on link `l`.
fn on(loads: &[Load], l: usize) -> Vec<&Load> {
    loads.iter().filter(|x| x.link == l).collect()
}

/// The offset `s` along the slide that makes the moment about the reference of `f` (its
/// magnitude N along the unit normal `n`) and `k` (N·m) vanish: N·s + k = 0 (`None`: N is
/// zero to the loads' scale `scale`, N).
fn offset(f: DVec2, n: DVec2, k: f64, scale: f64) -> Option<f64> {
    crate::forces::arm(f.dot(n), k, scale)
}

/// The polygons of every group, last first, then the driving link. `loads` are the
/// position's external loads.
pub fn polygons(
    board: &Board<'_>,
    loads: &[Load],
    drive: &Drive,
) -> Result<Polygons, (usize, ConstructionError)> {
    let prog = board.setup.prog;
    let b = board.setup.built;
    let mut applied: Vec<Load> = loads.to_vec();
    // The drawing's points are in mm: the reach in m.
    let reach = crate::forces::reach(&b.p) * board.setup.mu_l.value();
    let scale = crate::forces::force_scale(loads, reach);
    let mut groups = Vec::new();
    let mut arms = 0;
    for g in prog.groups().rev() {
        let (group, [i, j]) = (g.group, g.links);
        let title = format!("group {} ({}, {})", group + 1, i, j);
        let mut sch = Scheme::new(board, title.clone(), arms);
        draw_links(
            &mut sch.rec,
            prog,
            b,
            Role::Given,
            "group",
            Part::Group(group),
        );
        let li = on(&applied, i);
        let lj = on(&applied, j);
        for l in li.iter().chain(&lj) {
            sch.show(l);
        }
        let mut pol = Polygon::new(
            format!("force polygon of {title}"),
            board.scale_of(Some(group)),
            &board.setup.ctx,
        );
        let mut equations = Vec::new();
        let reactions = Work(&mut sch, &mut pol, &li, &lj, [i, j], scale, &mut equations)
            .reactions(g.pairs)
            .map_err(|e| (group, e))?;
        // The reactions on earlier links become their loads.
        for r in &reactions[..2] {
            if r.pair.from != 0 {
                let (at, shift) = point_of(r, drawn_dir(b));
                let mut l = Load::force(
                    r.pair.from,
                    LoadKind::Reaction,
                    reaction_name(r.pair.to, r.pair.from),
                    -r.force,
                    at,
                );
                l.shift = shift;
                applied.push(l);
            }
        }
        for (k, r) in reactions.iter().enumerate() {
            if on_scheme(k, r) {
                show_reaction(&mut sch, r);
            }
        }
        // The points' letters last: the loads' labels keep the places by their arrows.
        name_points(&mut sch.rec, prog, b, Part::Group(group), true);
        let (polygon, detail) = pol.finish();
        arms = sch.arms;
        groups.push(GroupPolygon {
            group,
            links: [i, j],
            scheme: sch.rec.finish(),
            polygon,
            details: detail,
            reactions,
            equations,
        });
    }
    let (driver, arms) = driver(board, &applied, drive, arms).map_err(|e| (usize::MAX, e))?;
    Ok(Polygons {
        groups,
        driver,
        arms,
    })
}

/// Whether the group's drawing shows reaction `r`, the `k`-th of the group's (the two outer
/// pairs', then the inner's): the outer ones always, the group's loads from the links beside
/// it; the inner one where its point is found on the drawing, a slide's (RPR, RPP). An inner
/// joint's reaction is a force between the group's own links, read off the polygon alone:
/// drawn on the group, beside the loads, it would stand as one more (the V engine's R₄₋₅
/// at C).
fn on_scheme(k: usize, r: &Reaction) -> bool {
    k < 2 || matches!(r.pair.kind, PairKind::Prismatic { .. })
}

/// Where a reaction acts: its pair's point, shifted along the slide (link `l`'s direction
/// `dir(l)`) by its offset.
fn point_of(r: &Reaction, dir: impl Fn(usize) -> DVec2) -> (usize, DVec2) {
    match r.pair.kind {
        PairKind::Revolute(k) => (k, DVec2::ZERO),
        PairKind::Prismatic {
            reference,
            dir_link,
        } => (reference, dir(dir_link) * r.offset.unwrap_or(0.0)),
    }
}

/// The direction of each link at the constructed position `b`.
fn drawn_dir(b: &Built) -> impl Fn(usize) -> DVec2 + '_ {
    |l| DVec2::from_angle(b.angle[l])
}
