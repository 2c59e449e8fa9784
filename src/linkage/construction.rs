//! The plan of positions as a drawing-board construction: every point of every position is
//! found by compass arcs and straightedge lines through the recorder, in drawing millimetres.

use super::model::Branch;
use super::program::{Op, PDir, PDyad, PGuide, Program};
use crate::construct::{Compass, ConstructionError, Item, Pick, Recorder, Role, StepId};
use crate::geom::{rotate, Arc, DVec2, Line, Segment};

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

fn heading(v: DVec2) -> f64 {
    v.y.atan2(v.x)
}

impl Program {
    fn drawn_dir(&self, d: &PDir, p: &[DVec2]) -> f64 {
        match *d {
            PDir::Fixed(a) => a,
            PDir::Along { from, to, angle } => heading(p[to] - p[from]) + angle,
        }
    }

    fn drawn_guide(&self, g: &PGuide, p: &[DVec2], mu: f64) -> Option<Line> {
        let e = DVec2::from_angle(self.drawn_dir(&g.dir, p));
        Line::new(p[g.through], e).map(|l| l.offset(g.offset / mu))
    }

    fn guide_name(&self, g: &PGuide) -> String {
        format!("guide through {}", self.names[g.through])
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
        let mu = rec.scale().value();
        let n = self.names.len();
        let mut p = vec![DVec2::ZERO; n];
        let mut step = vec![None; n];
        for (k, f) in self.fixed.iter().enumerate() {
            p[k] = *f / mu;
        }
        let mut angle = vec![0.0; self.link_count];
        let mut origin = vec![0usize; self.link_count];
        let mut crossing = Vec::new();
        // Crank: the pin is the division of the crank circle at φ₁.
        let pin = p[self.centre] + DVec2::from_angle(phi) * (self.crank_length / mu);
        p[self.pin] = pin;
        step[self.pin] = Some(rec.draw(
            format!(
                "{tag}: crank circle divided at φ₁ = {:.4}°",
                phi.to_degrees()
            ),
            Item::Point(pin),
            Role::Result,
            &[],
        ));
        angle[self.crank_link as usize] = phi;
        origin[self.crank_link as usize] = self.centre;
        for op in &self.ops {
            match *op {
                Op::Point {
                    idx,
                    link,
                    along,
                    across,
                } => {
                    let l = link as usize;
                    let o = p[origin[l]];
                    let local = rotate(DVec2::new(along, across) / mu, angle[l]);
                    let at = o + local;
                    // Dividers: the distance is stepped off from the link's origin.
                    let notch = rec.draw(
                        format!(
                            "{tag}: dividers from {} to {}",
                            self.names[origin[l]], self.names[idx]
                        ),
                        Item::Arc(Arc::notch(o, at, 2.5)),
                        Role::Construction,
                        &[],
                    );
                    p[idx] = at;
                    step[idx] = Some(rec.draw(
                        format!("{tag}: point {} of link {link}", self.names[idx]),
                        Item::Point(at),
                        Role::Result,
                        &[notch],
                    ));
                }
                Op::Dyad { group, links, dyad } => {
                    let s = format!("{tag}, group {} ({})", group + 1, dyad.kind().letters());
                    let fail = |error: ConstructionError| Failed { group, error };
                    let (i, j) = (links[0] as usize, links[1] as usize);
                    match dyad {
                        PDyad::Rrr {
                            a,
                            la,
                            b,
                            lb,
                            joint,
                            branch,
                        } => {
                            let pick = match prev {
                                Some(q) => Pick::Near(q.p[joint]),
                                None if branch == Branch::Right => Pick::Right,
                                None => Pick::Left,
                            };
                            let ca = Compass {
                                name: &self.names[a],
                                center: p[a],
                                radius: la / mu,
                            };
                            let cb = Compass {
                                name: &self.names[b],
                                center: p[b],
                                radius: lb / mu,
                            };
                            let (x, cr, id) = rec
                                .meet_circles(
                                    &format!("{s}: point {}", self.names[joint]),
                                    ca,
                                    cb,
                                    pick,
                                )
                                .map_err(fail)?;
                            p[joint] = x;
                            step[joint] = Some(id);
                            angle[i] = heading(x - p[a]);
                            angle[j] = heading(x - p[b]);
                            origin[i] = a;
                            origin[j] = b;
                            crossing.push(cr);
                        }
                        PDyad::Rrp {
                            a,
                            la,
                            guide,
                            joint,
                            branch,
                        } => {
                            let line = self.line_or_fail(&guide, &p, mu, &s).map_err(fail)?;
                            let pick = match prev {
                                Some(q) => Pick::Near(q.p[joint]),
                                None if branch == Branch::Backward => Pick::Backward,
                                None => Pick::Forward,
                            };
                            let c = Compass {
                                name: &self.names[a],
                                center: p[a],
                                radius: la / mu,
                            };
                            let (x, cr, id) = rec
                                .meet_line_circle(
                                    &format!("{s}: point {}", self.names[joint]),
                                    (&self.guide_name(&guide), &line),
                                    c,
                                    pick,
                                )
                                .map_err(fail)?;
                            p[joint] = x;
                            step[joint] = Some(id);
                            angle[i] = heading(x - p[a]);
                            angle[j] = line.angle();
                            origin[i] = a;
                            origin[j] = joint;
                            crossing.push(cr);
                        }
                        PDyad::Rpr { a, c, offset } => {
                            let th = if offset == 0.0
                                && p[a].distance(p[c]) <= rec.tolerances().coincident
                                && self.path_through_pivot(a, c, &p)
                            {
                                let prev = prev.map(|q| q.angle[j]);
                                self.slot_tangent(rec, &s, (a, c), &p, prev).map_err(fail)?
                            } else if offset == 0.0 {
                                let line = rec
                                    .line_through(
                                        &format!("{s}: slide line"),
                                        (&self.names[c], p[c]),
                                        (&self.names[a], p[a]),
                                    )
                                    .map_err(fail)?;
                                line.angle()
                            } else {
                                // Tangent from a to the offset circle of c: Thales circle on ca.
                                let mid = (p[a] + p[c]) * 0.5;
                                let thales = Compass {
                                    name: "the midpoint of the slide",
                                    center: mid,
                                    radius: p[a].distance(p[c]) * 0.5,
                                };
                                let off = Compass {
                                    name: &self.names[c],
                                    center: p[c],
                                    radius: offset.abs() / mu,
                                };
                                let side = if offset > 0.0 {
                                    Pick::Right
                                } else {
                                    Pick::Left
                                };
                                let (t, _, _) = rec
                                    .meet_circles(
                                        &format!("{s}: foot of the slide line"),
                                        thales,
                                        off,
                                        side,
                                    )
                                    .map_err(fail)?;
                                rec.line_through(
                                    &format!("{s}: slide line"),
                                    ("T", t),
                                    (&self.names[a], p[a]),
                                )
                                .map_err(fail)?
                                .angle()
                            };
                            angle[i] = th;
                            angle[j] = th;
                            origin[i] = a;
                            origin[j] = c;
                            crossing.push(std::f64::consts::FRAC_PI_2);
                        }
                        PDyad::Prp { gi, gj, joint } => {
                            let l1 = self.line_or_fail(&gi, &p, mu, &s).map_err(fail)?;
                            let l2 = self.line_or_fail(&gj, &p, mu, &s).map_err(fail)?;
                            let (x, cr, id) = rec
                                .meet_lines(
                                    &format!("{s}: point {}", self.names[joint]),
                                    (&self.guide_name(&gi), &l1),
                                    (&self.guide_name(&gj), &l2),
                                )
                                .map_err(fail)?;
                            p[joint] = x;
                            step[joint] = Some(id);
                            angle[i] = l1.angle();
                            angle[j] = l2.angle();
                            origin[i] = joint;
                            origin[j] = joint;
                            crossing.push(cr);
                        }
                        PDyad::Rpp {
                            a,
                            slide,
                            guide,
                            joint,
                        } => {
                            let sl = Line::new(p[a], DVec2::from_angle(self.drawn_dir(&slide, &p)))
                                .ok_or_else(|| fail(other(&s, "slide direction")))?;
                            let g = self.line_or_fail(&guide, &p, mu, &s).map_err(fail)?;
                            let name = format!("slide line through {}", self.names[a]);
                            let (x, cr, id) = rec
                                .meet_lines(
                                    &format!("{s}: point {}", self.names[joint]),
                                    (&name, &sl),
                                    (&self.guide_name(&guide), &g),
                                )
                                .map_err(fail)?;
                            rec.draw(
                                format!("{s}: {name}"),
                                Item::Segment(Segment::new(p[a], x)),
                                Role::Construction,
                                &[id],
                            );
                            p[joint] = x;
                            step[joint] = Some(id);
                            angle[i] = sl.angle();
                            angle[j] = g.angle();
                            origin[i] = a;
                            origin[j] = joint;
                            crossing.push(cr);
                        }
                    }
                }
            }
        }
        Ok(Built {
            phi,
            p,
            angle,
            origin,
            crossing,
            step,
        })
    }

    /// The slide line of an RPR group without offset when the pin `a` stands on the pivot
    /// `c`: the two points no longer fix it, its limit is the tangent to the path of `a`
    /// (for a crank pin: perpendicular to the crank, in the sense of increasing φ₁, or the
    /// one nearest to the previous position's slide `prev`). Refused for a pin whose path's
    /// tangent the drawing does not give (a point not on the crank, or a moving pivot).
    /// Whether the path of the pin `a` passes through the pivot `c` (within the rounding of
    /// the drawing's coordinates), so that the slot at their coincidence is the tangent to
    /// that path: for a crank pin about a fixed pivot, the crank circle through `a` meets `c`.
    /// A pin whose path misses the pivot, however closely, fixes the slot as the line through
    /// the two points (a true, ill-conditioned direction). Other pins: assumed (the tangent is
    /// then refused by [`Self::slot_tangent`]).
    fn path_through_pivot(&self, a: usize, c: usize, p: &[DVec2]) -> bool {
        if !self.on_frame_or_crank(a) || c >= self.fixed.len() {
            return true;
        }
        let o = p[self.centre];
        let (ra, rc) = (p[a].distance(o), p[c].distance(o));
        let rounding = 8.0 * f64::EPSILON * (p[a].length() + p[c].length() + o.length() + ra);
        (ra - rc).abs() <= rounding
    }

    fn slot_tangent(
        &self,
        rec: &mut Recorder,
        s: &str,
        (a, c): (usize, usize),
        p: &[DVec2],
        prev: Option<f64>,
    ) -> Result<f64, ConstructionError> {
        if !self.on_frame_or_crank(a) || c >= self.fixed.len() {
            return Err(ConstructionError::Other {
                step: format!("{s}: slide line"),
                message: format!(
                    "the pin {} stands on the pivot {} (|{}{}| = {:.3e} mm ≤ {:.3e} mm): the slide line is the tangent to the path of {}, which the drawing gives only for a point of the crank about a fixed pivot",
                    self.names[a],
                    self.names[c],
                    self.names[c],
                    self.names[a],
                    p[a].distance(p[c]),
                    rec.tolerances().coincident,
                    self.names[a]
                ),
            });
        }
        let radius = p[a] - p[self.centre];
        let mut t = radius.perp().normalize_or(DVec2::X);
        if prev.is_some_and(|q| DVec2::from_angle(q).dot(t) < 0.0) {
            t = -t;
        }
        let reach = radius.length().max(1.0);
        rec.draw(
            format!(
                "{s}: slide line, tangent to the path of {} at {}",
                self.names[a], self.names[c]
            ),
            Item::Segment(Segment::new(p[c] - t * reach, p[c] + t * reach)),
            Role::Construction,
            &[],
        );
        Ok(heading(t))
    }

    fn line_or_fail(
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

fn other(step: &str, what: &str) -> ConstructionError {
    ConstructionError::Other {
        step: step.into(),
        message: format!("the direction of the {what} is not defined (coincident points)"),
    }
}
