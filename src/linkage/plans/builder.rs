//! The plan builder: what a plan knows while it is drawn (images, link rates, readings) and
//! the drawing-board steps every group uses — direction lines and their intersection, laid
//! vectors, the similarity theorem, the Coriolis component, readings.

use super::names::{image_label, lower, plain};
use super::plan::{KinPlan, Measure, PlanKind, PlanReading};
use crate::construct::{ConstructionError, Item, Recorder, Role, THIN_HEAD_MM};
use crate::geom::{DVec2, Line, Segment};
use crate::linkage::built::Built;
use crate::linkage::compiled::Compiled;
use crate::linkage::indexed::PDir;

/// The values one plan needs from the velocity plan (for the acceleration plan).
pub(in crate::linkage) struct Known<'a> {
    pub(in crate::linkage) vel: Option<&'a KinPlan>,
    pub(in crate::linkage) mu_v: f64,
}

/// Per-link knowledge while a plan is built: points of the link (mechanism mm) with images.
pub(in crate::linkage) struct Links {
    pub(in crate::linkage) pts: Vec<Vec<(DVec2, DVec2)>>,
    pub(in crate::linkage) rate: Vec<Option<f64>>,
}

impl Links {
    pub(in crate::linkage) fn add(&mut self, link: usize, at: DVec2, img: DVec2) {
        self.pts[link].push((at, img));
    }
}

/// Everything the builder carries.
pub(in crate::linkage) struct Builder<'a> {
    pub(in crate::linkage) prog: &'a dyn Compiled,
    pub(in crate::linkage) b: &'a Built,
    pub(in crate::linkage) kind: PlanKind,
    pub(in crate::linkage) rec: Recorder,
    pub(in crate::linkage) mu_l: f64,
    pub(in crate::linkage) img: Vec<Option<DVec2>>,
    pub(in crate::linkage) links: Links,
    pub(in crate::linkage) readings: Vec<PlanReading>,
    pub(in crate::linkage) coincident: Vec<(String, DVec2)>,
    pub(in crate::linkage) known: Known<'a>,
    /// Crossing angle (radians) of the intersection that fixed each point's image.
    pub(in crate::linkage) cond: Vec<Option<f64>>,
    /// Crank speed ω₁, rad/s, signed counter-clockwise.
    pub(in crate::linkage) w1: f64,
}

impl<'a> Builder<'a> {
    pub(in crate::linkage) fn mu(&self) -> f64 {
        self.rec.scale().value()
    }
    /// Physical vector of a mechanism segment, m.
    pub(in crate::linkage) fn r(&self, from: usize, to: usize) -> DVec2 {
        (self.b.p[to] - self.b.p[from]) * self.mu_l
    }
    pub(in crate::linkage) fn name(&self, k: usize) -> &str {
        &self.prog.names()[k]
    }
    pub(in crate::linkage) fn image(&self, k: usize) -> DVec2 {
        self.img[k].unwrap_or(DVec2::ZERO)
    }
    /// Draw the vector from the pole to the image of point `k` and label it: a main line,
    /// or a thin one for a secondary point that no group is built on (a centre of mass,
    /// [`Compiled::is_leaf_point`]), so that the vectors meeting at the pole stay apart.
    pub(in crate::linkage) fn set_image(
        &mut self,
        k: usize,
        at: DVec2,
        from: &[crate::construct::StepId],
    ) {
        self.img[k] = Some(at);
        let label = image_label(self.name(k), self.kind);
        let role = if self.prog.is_leaf_point(k) {
            Role::Construction
        } else {
            Role::Result
        };
        let id = self.rec.draw(
            format!("image {label}"),
            Item::Vector {
                from: DVec2::ZERO,
                to: at,
            },
            role,
            from,
        );
        let toward = at.normalize_or(DVec2::Y);
        self.rec.label(id, label, at, toward);
    }
    /// The image of a point of a link at mechanism position `at` (similarity theorem).
    pub(in crate::linkage) fn image_on(&mut self, link: usize, at: DVec2, name: &str) -> DVec2 {
        if link == 0 {
            return DVec2::ZERO;
        }
        let pts = &self.links.pts[link];
        let pair = pts.iter().enumerate().find_map(|(k, o)| {
            pts[k + 1..]
                .iter()
                .find(|q| q.0.distance(o.0) > 1e-9)
                .map(|q| (*o, *q))
        });
        let img = match (pair, pts.first(), self.links.rate[link]) {
            // Two images: the similar, similarly oriented triangle on them.
            (Some(((o, oi), (q, qi))), _, _) => {
                let z = complex_div(at - o, q - o);
                oi + complex_mul(qi - oi, z)
            }
            // One image and the link's rate: turn and scale the radius vector.
            (None, Some(&(o, oi)), Some(w)) => {
                let r = (at - o) * self.mu_l;
                let v = match self.kind {
                    PlanKind::Velocity => r.perp() * w,
                    PlanKind::Acceleration => {
                        let wv = self.known.vel.map_or(0.0, |v| v.rate[link]);
                        r.perp() * w - r * (wv * wv)
                    }
                };
                oi + v / self.mu()
            }
            (None, Some(&(_, oi)), None) => oi,
            (None, None, _) => DVec2::ZERO,
        };
        let similarity = format!("similarity: {name} from {link}");
        match pair {
            // The link's image drawn whole, as the textbook draws it: the segment of its two
            // images (a′b′) run on to the new one when the point is on the link's line
            // (s₂′ on a′b′), else the similar triangle on them (d b c).
            Some(((o, oi), (q, qi))) => {
                let oq = q - o;
                let t = (at - o).dot(oq) / oq.length_squared();
                let off = (at - o).perp_dot(oq).abs() / oq.length();
                let sides = if off <= 1e-9 * oq.length() {
                    let end = |u: f64| oi + (qi - oi) * u;
                    vec![(end(t.min(0.0)), end(t.max(1.0)))]
                } else {
                    vec![(oi, qi), (oi, img), (qi, img)]
                };
                for (a, b) in sides {
                    self.rec.draw(
                        similarity.clone(),
                        Item::Segment(Segment::new(a, b)),
                        Role::Construction,
                        &[],
                    );
                }
            }
            _ => {
                if let Some(&(o, oi)) = self.links.pts[link].first() {
                    if o.distance(at) > 1e-9 {
                        self.rec.draw(
                            similarity,
                            Item::Segment(Segment::new(oi, img)),
                            Role::Construction,
                            &[],
                        );
                    }
                }
            }
        }
        img
    }
    /// A thin direction line through `through` along `dir`, drawn to `to` (and a little beyond).
    pub(in crate::linkage) fn dir_line(
        &mut self,
        note: &str,
        through: DVec2,
        dir: DVec2,
        to: DVec2,
    ) {
        let u = dir.normalize_or_zero();
        let (t0, t1) = (
            0.0f64.min((to - through).dot(u)),
            0.0f64.max((to - through).dot(u)),
        );
        self.rec.draw(
            note.to_string(),
            Item::Segment(Segment::new(
                through + u * (t0 - 6.0),
                through + u * (t1 + 6.0),
            )),
            Role::Construction,
            &[],
        );
    }
    /// Intersect two direction lines; record them; return the point and its crossing angle.
    pub(in crate::linkage) fn meet(
        &mut self,
        step: &str,
        a: (&str, DVec2, DVec2),
        b: (&str, DVec2, DVec2),
    ) -> Result<(DVec2, f64), ConstructionError> {
        let la = Line::new(a.1, a.2).ok_or_else(|| degenerate(step, a.0))?;
        let lb = Line::new(b.1, b.2).ok_or_else(|| degenerate(step, b.0))?;
        let (x, cr, _) = self.rec.meet_lines(step, (a.0, &la), (b.0, &lb))?;
        for (note, base, dir) in [a, b] {
            self.dir_line(note, base, dir, x);
            self.component(note, base, x);
        }
        Ok((x, cr))
    }
    /// The vector a direction line found, from its base to the crossing: the relative
    /// velocity (`b → b₃`, `d → d₅`) or the tangential or relative acceleration (`n₃ → b₃′`,
    /// `k → b₃′`), drawn as the textbook's polygon draws it. Not from the pole (the absolute
    /// vector is drawn there), nor to it (the image is the pole: the component is the base's
    /// own vector reversed, a double-headed line over it), nor shorter than its head
    /// ([`THIN_HEAD_MM`]: all head, a cluster of heads where a small plan's images crowd).
    fn component(&mut self, note: &str, base: DVec2, x: DVec2) {
        let pole = self.rec.tolerances().coincident;
        if base.length() <= pole || x.length() < THIN_HEAD_MM || base.distance(x) < THIN_HEAD_MM {
            return;
        }
        self.rec.draw(
            format!("{note}: component"),
            Item::Vector { from: base, to: x },
            Role::Construction,
            &[],
        );
    }
    /// Lay a known vector (a normal or Coriolis component) from `from`, label its end.
    pub(in crate::linkage) fn lay(
        &mut self,
        note: &str,
        from: DVec2,
        v: DVec2,
        label: &str,
    ) -> DVec2 {
        let to = from + v / self.mu();
        let id = self.rec.draw(
            note.to_string(),
            Item::Vector { from, to },
            Role::Construction,
            &[],
        );
        if !label.is_empty() {
            self.rec
                .label(id, label, to, (to - from).normalize_or(DVec2::X).perp());
        }
        to
    }
    /// Read a drawn segment as a physical magnitude.
    pub(in crate::linkage) fn read(&mut self, from: DVec2, to: DVec2) -> f64 {
        self.rec.measure(from, to).value
    }
    pub(in crate::linkage) fn reading(
        &mut self,
        quantity: String,
        what: Measure,
        value: f64,
        conditioning: Option<f64>,
    ) {
        self.readings.push(PlanReading {
            quantity,
            what,
            value,
            conditioning: conditioning.map(f64::to_degrees),
        });
    }
    /// The rate of a link from a relative image vector `rel` (plan mm) of a point at radius `r` (m):
    /// ω = r × v / |r|² (velocity plan) or ε from the tangential component (acceleration plan).
    pub(in crate::linkage) fn rate_from(&mut self, r: DVec2, from: DVec2, to: DVec2) -> f64 {
        let v = (to - from) * self.mu();
        let sign = r.perp_dot(v).signum();
        let mag = self.read(from, to);
        if r.length() == 0.0 {
            0.0
        } else {
            sign * mag / r.length()
        }
    }
    /// The normal component of the acceleration of a point at radius `r` about a centre on a
    /// link turning with the velocity-plan rate `w`: ω²·r toward the centre.
    pub(in crate::linkage) fn normal(&self, link: usize, r: DVec2) -> DVec2 {
        let w = self.known.vel.map_or(0.0, |v| v.rate[link]);
        -r * (w * w)
    }
    /// Where the line ⊥ to a turning link starts: the image `from` of its known point on the
    /// velocity plan; on the acceleration plan the end `n` of the normal component (radius
    /// `r` from that point) laid from it. The link's rate is read from the same point.
    pub(in crate::linkage) fn turning_base(
        &mut self,
        note: &str,
        link: usize,
        from: DVec2,
        r: DVec2,
    ) -> DVec2 {
        match self.kind {
            PlanKind::Velocity => from,
            PlanKind::Acceleration => self.lay(
                &format!("normal component, {note}"),
                from,
                self.normal(link, r),
                &format!("n_{link}"),
            ),
        }
    }

    /// The relative velocity of two images on the velocity plan, physical.
    pub(in crate::linkage) fn vel_between(&self, from: DVec2, to: DVec2) -> DVec2 {
        (to - from) * self.known.mu_v
    }
    pub(in crate::linkage) fn vel_image(&self, k: usize) -> DVec2 {
        self.known.vel.map_or(DVec2::ZERO, |v| v.images[k])
    }
    pub(in crate::linkage) fn vel_coincident(&self, name: &str) -> DVec2 {
        self.known
            .vel
            .and_then(|v| v.coincident.iter().find(|c| c.0 == name).map(|c| c.1))
            .unwrap_or(DVec2::ZERO)
    }
    pub(in crate::linkage) fn dir(&self, d: &PDir) -> DVec2 {
        match *d {
            PDir::Fixed(a) => DVec2::from_angle(a),
            PDir::Along { from, to, angle } => {
                DVec2::from_angle(angle).rotate((self.b.p[to] - self.b.p[from]).normalize_or_zero())
            }
        }
    }
    pub(in crate::linkage) fn rate(&self, link: usize) -> f64 {
        self.links.rate[link].unwrap_or(0.0)
    }
}

pub(in crate::linkage) fn degenerate(step: &str, what: &str) -> ConstructionError {
    ConstructionError::Other {
        step: step.into(),
        message: format!("the direction of {what} is not defined"),
    }
}

pub(in crate::linkage) fn complex_mul(a: DVec2, b: DVec2) -> DVec2 {
    DVec2::new(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x)
}

pub(in crate::linkage) fn complex_div(a: DVec2, b: DVec2) -> DVec2 {
    let d = b.length_squared();
    DVec2::new(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / d
}

impl Builder<'_> {
    /// The condition `cr` of a group's joint and its motion relative to `a` on link `i`.
    pub(in crate::linkage) fn joint_relative(
        &mut self,
        joint: usize,
        (a, i): (usize, usize),
        cr: f64,
    ) {
        let (x, ai) = (self.image(joint), self.image(a));
        self.cond[joint] = Some(cr);
        self.relative((joint, i), x, (a, i), ai, cr);
    }

    /// Record a link's new known images and its rate.
    pub(in crate::linkage) fn finish_link(
        &mut self,
        link: usize,
        pts: &[(usize, DVec2)],
        rate: f64,
    ) {
        for &(k, img) in pts {
            let at = self.b.p[k];
            if !self.links.pts[link]
                .iter()
                .any(|p| p.0.distance(at) <= 1e-9)
            {
                self.links.add(link, at, img);
            }
        }
        self.links.rate[link] = Some(rate);
    }

    /// Draw and label the image of the point of `link` under the point `point` (`b₃`).
    pub(in crate::linkage) fn coincident_image(
        &mut self,
        name: &str,
        point: usize,
        link: usize,
        x: DVec2,
    ) {
        let label = self.coincident_label(point, link);
        let id = self.rec.draw(
            format!("image {label}"),
            Item::Vector {
                from: DVec2::ZERO,
                to: x,
            },
            Role::Result,
            &[],
        );
        self.rec.label(id, label, x, x.normalize_or(DVec2::Y));
        self.coincident.push((name.to_string(), x));
        // Read as the seed's Table 2 reads V_B3: the pole to the image.
        let value = self.read(DVec2::ZERO, x);
        let quantity = match self.kind {
            PlanKind::Velocity => format!("v_{name}"),
            PlanKind::Acceleration => format!("a_{name}"),
        };
        self.reading(quantity, Measure::Carried(point, link), value, None);
    }

    /// The label of the image of the point of `link` under the point `point`: `b₃`, `b₃′`.
    fn coincident_label(&self, point: usize, link: usize) -> String {
        let prime = if self.kind == PlanKind::Acceleration {
            "′"
        } else {
            ""
        };
        format!("{}_{{{link}}}{prime}", lower(self.name(point)))
    }

    /// Mark and label the image `x` of the point of `link` under the point `point` (`b₁`)
    /// where the similarity line that found it ends: the absolute vector from the pole to it
    /// (pb₁, the velocity the relative one adds to), a main line as the shaper's pb₃, and no
    /// reading (nothing is asked of it but the line it starts); a dot where it vanishes.
    pub(in crate::linkage) fn mark_coincident(&mut self, point: usize, link: usize, x: DVec2) {
        let label = self.coincident_label(point, link);
        let toward = x.normalize_or(DVec2::Y);
        if x.length() <= self.rec.tolerances().coincident {
            let note = format!("image {label}");
            self.rec
                .point(note, x, Role::Construction, &label, toward, &[]);
            return;
        }
        let vector = Item::Vector {
            from: DVec2::ZERO,
            to: x,
        };
        let id = self
            .rec
            .draw(format!("image {label}"), vector, Role::Result, &[]);
        self.rec.label(id, label, x, toward);
    }

    /// The Coriolis component 2ω·v_r of a point moving relative to `link`, v_r read on the
    /// velocity plan from the image `rel_from` to `rel_to`, turned 90° in the sense of ω; laid
    /// from `from`. Returns its end `k` (`from` itself when it vanishes).
    pub(in crate::linkage) fn coriolis(
        &mut self,
        link: usize,
        rel_from: DVec2,
        rel_to: DVec2,
        from: DVec2,
    ) -> DVec2 {
        let w = self.known.vel.map_or(0.0, |v| v.rate[link]);
        let ak = self.vel_between(rel_from, rel_to).perp() * (2.0 * w);
        // Vanishes (no relative sliding, or the carrier does not turn) when it would be drawn
        // shorter than the figure's coincidence tolerance.
        if ak.length() / self.mu() <= self.rec.tolerances().coincident {
            return from;
        }
        self.lay("Coriolis component", from, ak, "k")
    }

    /// Reading of the velocity (acceleration) of `p` carried by link `p.1` relative to `q`
    /// carried by `q.1`: the plan segment from the image of `q` to the image of `p`.
    pub(in crate::linkage) fn relative(
        &mut self,
        p: (usize, usize),
        p_img: DVec2,
        q: (usize, usize),
        q_img: DVec2,
        cr: f64,
    ) {
        // Coincident points of a sliding pair carry their link's number (`B3_B1`).
        let tag = |(k, l): (usize, usize)| {
            let suffix = if p.0 == q.0 {
                l.to_string()
            } else {
                String::new()
            };
            format!("{}{suffix}", plain(&self.prog.names()[k]))
        };
        let pq = format!("{}_{}", tag(p), tag(q));
        let value = self.read(q_img, p_img);
        let quantity = match self.kind {
            PlanKind::Velocity => format!("v_{pq}"),
            PlanKind::Acceleration => format!("a_{pq}"),
        };
        self.cond_reading(quantity, Measure::Relative { p, q }, value, cr);
    }

    pub(in crate::linkage) fn cond_reading(
        &mut self,
        quantity: String,
        what: Measure,
        value: f64,
        cr: f64,
    ) {
        self.reading(quantity, what, value, Some(cr));
    }
}
