//! The plan of positions as a drawing-board construction: every point of every position is
//! found by compass arcs and straightedge lines through the recorder, in drawing millimetres.

use super::program::{Op, PDir, PDyad, PGuide, Program};
use crate::construct::{Compass, ConstructionError, Item, Pick, Recorder, Role, StepId};
use crate::geom::{rotate, Arc, DVec2, Line};

/// What a group's construction gives besides its joint: the frames of its links i and j
/// (their angles and the points they start from) and the acute crossing angle of the
/// intersection that fixed it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Frames {
    /// The angles of links i, j, radians.
    pub angle: [f64; 2],
    /// The origins (point indices) of links i, j.
    pub origin: [usize; 2],
    /// The crossing angle, radians.
    pub crossing: f64,
}

/// One constructed position, in drawing mm.
///
/// It mirrors the analytic twin's [`Pose`](super::Pose) field for field on purpose: the
/// drawing and the twin answer the same questions, in drawing mm here and in metres there.
#[derive(Debug, Clone, PartialEq)]
pub struct Built {
    /// Crank angle φ₁, radians.
    pub phi: f64,
    /// Point positions by program index, drawing mm.
    pub p: Vec<DVec2>,
    /// Link frame angle by link number, radians (from the drawn points).
    pub angle: Vec<f64>,
    /// Link frame origin (point index) by link number.
    pub origin: Vec<usize>,
    /// Per group: the acute crossing angle of the intersection that fixed it.
    pub crossing: Vec<f64>,
    /// The recorded step that produced each point (`None` for fixed points).
    pub step: Vec<Option<StepId>>,
}

/// A failed group construction: which group, and the diagnostic from the recorder.
#[derive(Debug, Clone, PartialEq)]
pub struct Failed {
    /// Group index.
    pub group: usize,
    /// The diagnostic.
    pub error: ConstructionError,
}

pub(super) fn heading(v: DVec2) -> f64 {
    v.y.atan2(v.x)
}

impl Built {
    /// Record the joint a group's intersection found: its position and step; gives the point
    /// and the crossing angle.
    pub(super) fn place(
        &mut self,
        joint: usize,
        (x, crossing, id): (DVec2, f64, StepId),
    ) -> (DVec2, f64) {
        self.p[joint] = x;
        self.step[joint] = Some(id);
        (x, crossing)
    }
}

/// The solution a two-solution intersection takes: the one nearest to the previous
/// position's `joint` when there is one, else `first` (the scene's branch).
pub(super) fn pick(prev: Option<&Built>, joint: usize, first: Pick) -> Pick {
    match prev {
        Some(q) => Pick::Near(q.p[joint]),
        None => first,
    }
}

impl Program {
    /// A direction at the drawn points `p`, radians.
    pub(super) fn drawn_dir(&self, d: &PDir, p: &[DVec2]) -> f64 {
        match *d {
            PDir::Fixed(a) => a,
            PDir::Along { from, to, angle } => heading(p[to] - p[from]) + angle,
        }
    }

    /// A guide's line at the drawn points `p` (mm) at μ_l = `mu`.
    pub(super) fn drawn_guide(&self, g: &PGuide, p: &[DVec2], mu: f64) -> Option<Line> {
        let e = DVec2::from_angle(self.drawn_dir(&g.dir, p));
        Line::new(p[g.through], e).map(|l| l.offset(g.offset / mu))
    }

    /// How a step names a guide.
    pub(super) fn guide_name(&self, g: &PGuide) -> String {
        format!("guide through {}", self.names[g.through])
    }

    /// The compass set at point `k` with `radius` (drawing mm).
    pub(super) fn compass(&self, p: &[DVec2], k: usize, radius: f64) -> Compass<'_> {
        Compass {
            name: &self.names[k],
            center: p[k],
            radius,
        }
    }

    /// The step that finds a group's `joint`.
    pub(super) fn joint_step(&self, s: &str, joint: usize) -> String {
        format!("{s}: point {}", self.names[joint])
    }

    /// Construct the position at crank angle `phi` (radians). `mu` is μ_l (m/mm); `prev` the
    /// previous constructed position (continuity), `tag` names the position in diagnostics.
    pub fn construct(
        &self,
        rec: &mut Recorder,
        phi: f64,
        prev: Option<&Built>,
        tag: &str,
    ) -> Result<Built, Failed> {
        let mut pos = self.crank_divided(rec, phi, tag);
        for op in &self.ops {
            match *op {
                Op::Point {
                    idx,
                    link,
                    along,
                    across,
                } => self.step_off(rec, &mut pos, tag, (idx, link), DVec2::new(along, across)),
                Op::Dyad { group, links, dyad } => {
                    let s = format!("{tag}, group {} ({})", group + 1, dyad.kind().letters());
                    let links = links.map(|l| l as usize);
                    self.construct_group(rec, &mut pos, prev, &s, links, dyad)
                        .map_err(|error| Failed { group, error })?;
                }
            }
        }
        Ok(pos)
    }

    /// The fixed points, and the crank pin: the division of the crank circle at φ₁.
    fn crank_divided(&self, rec: &mut Recorder, phi: f64, tag: &str) -> Built {
        let mu = rec.scale().value();
        let n = self.names.len();
        let mut pos = Built {
            phi,
            p: vec![DVec2::ZERO; n],
            angle: vec![0.0; self.link_count],
            origin: vec![0usize; self.link_count],
            crossing: Vec::new(),
            step: vec![None; n],
        };
        for (k, f) in self.fixed.iter().enumerate() {
            pos.p[k] = *f / mu;
        }
        let pin = pos.p[self.centre] + DVec2::from_angle(phi) * (self.crank_length / mu);
        pos.p[self.pin] = pin;
        pos.step[self.pin] = Some(rec.draw(
            format!(
                "{tag}: crank circle divided at φ₁ = {:.4}°",
                phi.to_degrees()
            ),
            Item::Point(pin),
            Role::Result,
            &[],
        ));
        pos.angle[self.crank_link as usize] = phi;
        pos.origin[self.crank_link as usize] = self.centre;
        pos
    }

    /// A further point `idx` of a known link: its distance stepped off with dividers from
    /// the link's origin, `local` (along, across; m) in the link's frame.
    fn step_off(
        &self,
        rec: &mut Recorder,
        pos: &mut Built,
        tag: &str,
        (idx, link): (usize, u32),
        local: DVec2,
    ) {
        let mu = rec.scale().value();
        let l = link as usize;
        let o = pos.p[pos.origin[l]];
        let at = o + rotate(local / mu, pos.angle[l]);
        // Dividers: the distance is stepped off from the link's origin.
        let notch = rec.draw(
            format!(
                "{tag}: dividers from {} to {}",
                self.names[pos.origin[l]], self.names[idx]
            ),
            Item::Arc(Arc::notch(o, at, 2.5)),
            Role::Construction,
            &[],
        );
        pos.p[idx] = at;
        pos.step[idx] = Some(rec.draw(
            format!("{tag}: point {} of link {link}", self.names[idx]),
            Item::Point(at),
            Role::Result,
            &[notch],
        ));
    }

    /// One Assur group (step name `s`, links `i`, `j`): its joint by the intersection its
    /// kind calls for (RPR: its slide line), then the frames of its two links.
    fn construct_group(
        &self,
        rec: &mut Recorder,
        pos: &mut Built,
        prev: Option<&Built>,
        s: &str,
        [i, j]: [usize; 2],
        dyad: PDyad,
    ) -> Result<(), ConstructionError> {
        let Frames {
            angle: [ti, tj],
            origin: [oi, oj],
            crossing: cr,
        } = dyad.group().construct(self, rec, pos, prev, (s, j))?;
        pos.angle[i] = ti;
        pos.angle[j] = tj;
        pos.origin[i] = oi;
        pos.origin[j] = oj;
        pos.crossing.push(cr);
        Ok(())
    }

    /// A guide's line at the drawn points, or the step's failure naming it.
    pub(super) fn line_or_fail(
        &self,
        g: &PGuide,
        p: &[DVec2],
        mu: f64,
        s: &str,
    ) -> Result<Line, ConstructionError> {
        self.drawn_guide(g, p, mu)
            .ok_or_else(|| other(s, &self.guide_name(g)))
    }
}

/// A step that cannot go on: the direction of `what` is not defined.
pub(super) fn other(step: &str, what: &str) -> ConstructionError {
    ConstructionError::Other {
        step: step.into(),
        message: format!("the direction of the {what} is not defined (coincident points)"),
    }
}
