//! Velocity and acceleration plans (планы скоростей и ускорений) as drawing-board
//! constructions: from the pole, each Assur group's two vector equations are drawn as
//! direction lines through known images and intersected; further points of a link follow by
//! the similarity theorem; every value is read off the drawing (drafting model applied) and
//! turned into a physical value with the plan's μ.
//!
//! Velocity plan (pole `p`): the crank pin's velocity ⊥ to the crank in the sense of ω₁;
//! RRR: ⊥ to each link through the outer images; RRP: ⊥ to the link and ∥ to the guide through
//! the image of the guide's coincident point; RPR: ⊥ to the line from the pivot and ∥ to the
//! slide through the block's image (the coincident point `b₃`); PRP: ∥ to each guide through the
//! coincident points of the carrying links; RPP: ∥ to the slide and ∥ to the guide.
//! Acceleration plan (pole `π`): the same equations with the normal components (ends `n`) laid
//! from the known images along the links and the Coriolis components (end `k`, 2ω·v_r turned
//! 90° in the sense of ω of the carrying link) laid before the direction lines.

use super::construction::Built;
use super::program::{Op, PDir, PDyad, PGuide, Program};
use crate::construct::{ConstructionError, Drafting, Figure, Item, Recorder, Role};
use crate::geom::{DVec2, Line, Segment, Tolerances};
use crate::scale::Scale;

/// Which plan.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlanKind {
    /// Velocities, pole `p`.
    Velocity,
    /// Accelerations, pole `π`.
    Acceleration,
}

/// A value read off a plan.
#[derive(Debug, Clone, PartialEq)]
pub struct Reading {
    /// Quantity name (`v_D`, `v_B3_B1`, `omega_3`, `a_S5`, `eps_3`).
    pub quantity: String,
    /// What was read, structurally (for the analytic twin).
    pub what: Measure,
    /// The physical value (magnitudes for point quantities; ω, ε signed, counter-clockwise
    /// positive).
    pub value: f64,
    /// Crossing angle of the intersection that fixed it, degrees (None: not an intersection).
    pub conditioning: Option<f64>,
}

/// What a reading measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Measure {
    /// The absolute velocity (acceleration) of a point, by program index: a magnitude.
    Point(usize),
    /// The angular velocity (acceleration) of a link, signed counter-clockwise.
    Rate(usize),
    /// The velocity (acceleration) of point `p.0` carried by link `p.1` relative to point
    /// `q.0` carried by link `q.1`: a magnitude.
    Relative {
        /// (point, link) of the moving point.
        p: (usize, usize),
        /// (point, link) of the reference point.
        q: (usize, usize),
    },
}

/// A constructed plan.
#[derive(Debug, Clone, PartialEq)]
pub struct KinPlan {
    /// Which plan.
    pub kind: PlanKind,
    /// The recorded figure (pole at the origin), at `scale`.
    pub figure: Figure,
    /// Image of every point by program index, plan mm.
    pub images: Vec<DVec2>,
    /// Images of coincident points of sliding pairs (`B3`: point of link 3 under B).
    pub coincident: Vec<(String, DVec2)>,
    /// Angular velocity (velocity plan) or acceleration (acceleration plan) of every link,
    /// as read off the plan, signed counter-clockwise.
    pub rate: Vec<f64>,
    /// The readings.
    pub readings: Vec<Reading>,
}

/// The values one plan needs from the velocity plan (for the acceleration plan).
struct Known<'a> {
    vel: Option<&'a KinPlan>,
    mu_v: f64,
}

/// Name of a point without markup (`S_3` → `S3`).
pub fn plain(name: &str) -> String {
    name.chars()
        .filter(|c| !matches!(c, '_' | '{' | '}' | '′'))
        .collect::<String>()
        + if name.contains('′') { "'" } else { "" }
}

fn lower(name: &str) -> String {
    let mut c = name.chars();
    c.next().map_or_else(String::new, |f| {
        f.to_lowercase().collect::<String>() + c.as_str()
    })
}

/// Label of an image: lower-case, primed on the acceleration plan.
fn image_label(name: &str, kind: PlanKind) -> String {
    match kind {
        PlanKind::Velocity => lower(name),
        PlanKind::Acceleration => format!("{}′", lower(name)),
    }
}

/// Per-link knowledge while a plan is built: points of the link (mechanism mm) with images.
struct Links {
    pts: Vec<Vec<(DVec2, DVec2)>>,
    rate: Vec<Option<f64>>,
}

impl Links {
    fn add(&mut self, link: usize, at: DVec2, img: DVec2) {
        self.pts[link].push((at, img));
    }
}

/// Everything the builder carries.
struct Builder<'a> {
    prog: &'a Program,
    b: &'a Built,
    kind: PlanKind,
    rec: Recorder,
    mu_l: f64,
    img: Vec<Option<DVec2>>,
    links: Links,
    readings: Vec<Reading>,
    coincident: Vec<(String, DVec2)>,
    known: Known<'a>,
    /// Crossing angle (radians) of the intersection that fixed each point's image.
    cond: Vec<Option<f64>>,
    /// Crank speed ω₁, rad/s, signed counter-clockwise.
    w1: f64,
}

impl<'a> Builder<'a> {
    fn mu(&self) -> f64 {
        self.rec.scale().value()
    }
    /// Physical vector of a mechanism segment, m.
    fn r(&self, from: usize, to: usize) -> DVec2 {
        (self.b.p[to] - self.b.p[from]) * self.mu_l
    }
    fn name(&self, k: usize) -> &str {
        &self.prog.names[k]
    }
    fn image(&self, k: usize) -> DVec2 {
        self.img[k].unwrap_or(DVec2::ZERO)
    }
    fn set_image(&mut self, k: usize, at: DVec2, from: &[crate::construct::StepId]) {
        self.img[k] = Some(at);
        let label = image_label(self.name(k), self.kind);
        let id = self.rec.draw(
            format!("image {label}"),
            Item::Vector {
                from: DVec2::ZERO,
                to: at,
            },
            Role::Result,
            from,
        );
        let toward = at.normalize_or(DVec2::Y);
        self.rec.label(id, label, at, toward);
    }
    /// The image of a point of a link at mechanism position `at` (similarity theorem).
    fn image_on(&mut self, link: usize, at: DVec2, name: &str) -> DVec2 {
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
        if let Some(&(o, oi)) = self.links.pts[link].first() {
            if o.distance(at) > 1e-9 {
                self.rec.draw(
                    format!("similarity: {name} from {}", link),
                    Item::Segment(Segment::new(oi, img)),
                    Role::Construction,
                    &[],
                );
            }
        }
        img
    }
    /// A thin direction line through `through` along `dir`, drawn to `to` (and a little beyond).
    fn dir_line(&mut self, note: &str, through: DVec2, dir: DVec2, to: DVec2) {
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
    fn meet(
        &mut self,
        step: &str,
        a: (&str, DVec2, DVec2),
        b: (&str, DVec2, DVec2),
    ) -> Result<(DVec2, f64), ConstructionError> {
        let la = Line::new(a.1, a.2).ok_or_else(|| degenerate(step, a.0))?;
        let lb = Line::new(b.1, b.2).ok_or_else(|| degenerate(step, b.0))?;
        let (x, cr, _) = self.rec.meet_lines(step, (a.0, &la), (b.0, &lb))?;
        self.dir_line(a.0, a.1, a.2, x);
        self.dir_line(b.0, b.1, b.2, x);
        Ok((x, cr))
    }
    /// Lay a known vector (a normal or Coriolis component) from `from`, label its end.
    fn lay(&mut self, note: &str, from: DVec2, v: DVec2, label: &str) -> DVec2 {
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
    fn read(&self, from: DVec2, to: DVec2) -> f64 {
        self.rec.measure(from, to).value
    }
    fn reading(&mut self, quantity: String, what: Measure, value: f64, conditioning: Option<f64>) {
        self.readings.push(Reading {
            quantity,
            what,
            value,
            conditioning: conditioning.map(f64::to_degrees),
        });
    }
    /// The rate of a link from a relative image vector `rel` (plan mm) of a point at radius `r` (m):
    /// ω = r × v / |r|² (velocity plan) or ε from the tangential component (acceleration plan).
    fn rate_from(&self, r: DVec2, from: DVec2, to: DVec2) -> f64 {
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
    fn normal(&self, link: usize, r: DVec2) -> DVec2 {
        let w = self.known.vel.map_or(0.0, |v| v.rate[link]);
        -r * (w * w)
    }
    /// The relative velocity of two images on the velocity plan, physical.
    fn vel_between(&self, from: DVec2, to: DVec2) -> DVec2 {
        (to - from) * self.known.mu_v
    }
    fn vel_image(&self, k: usize) -> DVec2 {
        self.known.vel.map_or(DVec2::ZERO, |v| v.images[k])
    }
    fn vel_coincident(&self, name: &str) -> DVec2 {
        self.known
            .vel
            .and_then(|v| v.coincident.iter().find(|c| c.0 == name).map(|c| c.1))
            .unwrap_or(DVec2::ZERO)
    }
    fn dir(&self, d: &PDir) -> DVec2 {
        match *d {
            PDir::Fixed(a) => DVec2::from_angle(a),
            PDir::Along { from, to, angle } => {
                DVec2::from_angle(angle).rotate((self.b.p[to] - self.b.p[from]).normalize_or_zero())
            }
        }
    }
    /// The link carrying a guide (0 for the frame).
    fn guide_link(&self, g: &PGuide) -> usize {
        self.prog.carrier(g)
    }
    fn rate(&self, link: usize) -> f64 {
        self.links.rate[link].unwrap_or(0.0)
    }
}

fn degenerate(step: &str, what: &str) -> ConstructionError {
    ConstructionError::Other {
        step: step.into(),
        message: format!("the direction of {what} is not defined"),
    }
}

fn complex_mul(a: DVec2, b: DVec2) -> DVec2 {
    DVec2::new(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x)
}

fn complex_div(a: DVec2, b: DVec2) -> DVec2 {
    let d = b.length_squared();
    DVec2::new(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / d
}

/// The link a known point belongs to (the first that carried it; 0 for fixed points):
/// [`Program::owner`].
pub fn owner(prog: &Program, k: usize) -> usize {
    prog.owner(k)
}

/// A constructed position and the crank speed: what every plan of that position starts from.
#[derive(Debug, Clone, Copy)]
pub struct PlanSetup<'a> {
    /// The compiled mechanism.
    pub prog: &'a Program,
    /// The constructed position (drawing mm).
    pub built: &'a Built,
    /// μ_l of the construction, m/mm.
    pub mu_l: f64,
    /// Crank speed ω₁, rad/s, signed counter-clockwise.
    pub w1: f64,
    /// The drafting model for readings.
    pub drafting: Drafting,
}

/// Build a plan of `kind` at plan scale `scale`. The acceleration plan needs the velocity
/// plan of the same position (`vel`). A failure names the group (file order) and the step.
pub fn kin_plan(
    setup: &PlanSetup<'_>,
    kind: PlanKind,
    scale: Scale,
    vel: Option<&KinPlan>,
) -> Result<KinPlan, (usize, ConstructionError)> {
    let PlanSetup {
        prog,
        built: b,
        mu_l,
        w1,
        drafting,
    } = *setup;
    let tol = Tolerances::for_model_size(200.0).map_err(|e| {
        (
            0,
            ConstructionError::Other {
                step: "plan".into(),
                message: e.to_string(),
            },
        )
    })?;
    let title = match kind {
        PlanKind::Velocity => "velocity plan",
        PlanKind::Acceleration => "acceleration plan",
    };
    let n = prog.names.len();
    let mut bl = Builder {
        prog,
        b,
        kind,
        rec: Recorder::new(title, scale, tol, drafting),
        mu_l,
        img: vec![None; n],
        links: Links {
            pts: vec![Vec::new(); prog.link_count],
            rate: vec![None; prog.link_count],
        },
        readings: Vec::new(),
        coincident: Vec::new(),
        cond: vec![None; n],
        w1,
        known: Known {
            vel: vel.filter(|_| kind == PlanKind::Acceleration),
            mu_v: vel.map_or(1.0, |v| v.figure.scale.value()),
        },
    };
    let pole = bl.rec.point(
        "pole",
        DVec2::ZERO,
        Role::Given,
        if kind == PlanKind::Velocity {
            "p"
        } else {
            "π"
        },
        DVec2::new(-0.7, -0.7),
        &[],
    );
    for k in 0..prog.fixed.len() {
        bl.img[k] = Some(DVec2::ZERO);
    }
    bl.links.rate[0] = Some(0.0);
    // The class-I mechanism.
    let cl = prog.crank_link as usize;
    let r = bl.r(prog.centre, prog.pin);
    let v_pin = match kind {
        PlanKind::Velocity => r.perp() * w1,
        PlanKind::Acceleration => -r * (w1 * w1),
    };
    let pin_img = v_pin / bl.mu();
    bl.set_image(prog.pin, pin_img, &[pole]);
    bl.links.rate[cl] = Some(if kind == PlanKind::Velocity { w1 } else { 0.0 });
    bl.links.add(cl, b.p[prog.centre], DVec2::ZERO);
    bl.links.add(cl, b.p[prog.pin], pin_img);
    for op in &prog.ops {
        match *op {
            Op::Point { idx, link, .. } => {
                let at = b.p[idx];
                let name = prog.names[idx].clone();
                let x = bl.image_on(link as usize, at, &name);
                bl.set_image(idx, x, &[]);
                bl.links.add(link as usize, at, x);
            }
            Op::Dyad { group, links, dyad } => bl.dyad(links, &dyad).map_err(|e| (group, e))?,
        }
    }
    // Readings: every moving point, every link rate.
    for k in prog.fixed.len()..n {
        let x = bl.image(k);
        let v = bl.read(DVec2::ZERO, x);
        let q = match kind {
            PlanKind::Velocity => format!("v_{}", plain(&prog.names[k])),
            PlanKind::Acceleration => format!("a_{}", plain(&prog.names[k])),
        };
        let cond = bl.cond[k];
        bl.reading(q, Measure::Point(k), v, cond);
    }
    for l in 1..prog.link_count {
        if let Some(w) = bl.links.rate[l] {
            let q = match kind {
                PlanKind::Velocity => format!("omega_{l}"),
                PlanKind::Acceleration => format!("eps_{l}"),
            };
            bl.reading(q, Measure::Rate(l), w, None);
        }
    }
    let rate = bl.links.rate.iter().map(|r| r.unwrap_or(0.0)).collect();
    let images = bl.img.iter().map(|i| i.unwrap_or(DVec2::ZERO)).collect();
    Ok(KinPlan {
        kind,
        figure: bl.rec.finish(),
        images,
        coincident: bl.coincident,
        rate,
        readings: bl.readings,
    })
}

impl Builder<'_> {
    fn dyad(&mut self, links: [u32; 2], dyad: &PDyad) -> Result<(), ConstructionError> {
        let (i, j) = (links[0] as usize, links[1] as usize);
        let vel = self.kind == PlanKind::Velocity;
        let step = format!("group ({i},{j})");
        match *dyad {
            PDyad::Rrr { a, b, joint, .. } => {
                let (ra, rb) = (self.r(a, joint), self.r(b, joint));
                let (ai, bi) = (self.image(a), self.image(b));
                let (x, cr) = if vel {
                    self.meet(
                        &format!("{step}: image of {}", self.name(joint)),
                        ("⊥ link i", ai, ra.perp()),
                        ("⊥ link j", bi, rb.perp()),
                    )?
                } else {
                    let n1 = self.lay(
                        "normal component, link i",
                        ai,
                        self.normal(i, ra),
                        &format!("n_{i}"),
                    );
                    let n2 = self.lay(
                        "normal component, link j",
                        bi,
                        self.normal(j, rb),
                        &format!("n_{j}"),
                    );
                    self.meet(
                        &format!("{step}: image of {}", self.name(joint)),
                        ("⊥ link i", n1, ra.perp()),
                        ("⊥ link j", n2, rb.perp()),
                    )?
                };
                self.set_image(joint, x, &[]);
                let (ri, rj) = if vel {
                    (self.rate_from(ra, ai, x), self.rate_from(rb, bi, x))
                } else {
                    let n1 = ai + self.normal(i, ra) / self.mu();
                    let n2 = bi + self.normal(j, rb) / self.mu();
                    (self.rate_from(ra, n1, x), self.rate_from(rb, n2, x))
                };
                self.finish_link(i, &[(a, ai), (joint, x)], ri);
                self.finish_link(j, &[(b, bi), (joint, x)], rj);
                let (x, ai) = (self.image(joint), self.image(a));
                self.cond[joint] = Some(cr);
                self.relative((joint, i), x, (a, i), ai, cr);
            }
            PDyad::Rrp {
                a, guide, joint, ..
            } => {
                let ra = self.r(a, joint);
                let ai = self.image(a);
                let k = self.guide_link(&guide);
                let e = self.dir(&guide.dir);
                let jk_name = format!("{}{k}", plain(self.name(joint)));
                let jk = self.image_on(k, self.b.p[joint], &jk_name);
                let (x, cr) = if vel {
                    self.meet(
                        &format!("{step}: image of {}", self.name(joint)),
                        ("⊥ link i", ai, ra.perp()),
                        ("∥ guide", jk, e),
                    )?
                } else {
                    let n1 = self.lay(
                        "normal component, link i",
                        ai,
                        self.normal(i, ra),
                        &format!("n_{i}"),
                    );
                    let kk =
                        self.coriolis(k, self.vel_coincident(&jk_name), self.vel_image(joint), jk);
                    self.meet(
                        &format!("{step}: image of {}", self.name(joint)),
                        ("⊥ link i", n1, ra.perp()),
                        ("∥ guide", kk, e),
                    )?
                };
                self.set_image(joint, x, &[]);
                self.coincident.push((jk_name, jk));
                let ri = if vel {
                    self.rate_from(ra, ai, x)
                } else {
                    self.rate_from(ra, ai + self.normal(i, ra) / self.mu(), x)
                };
                self.finish_link(i, &[(a, ai), (joint, x)], ri);
                let rk = self.rate(k);
                self.finish_link(j, &[(joint, x)], rk);
                let (x, ai) = (self.image(joint), self.image(a));
                self.cond[joint] = Some(cr);
                self.relative((joint, i), x, (a, i), ai, cr);
            }
            PDyad::Rpr { a, c, offset } => {
                let rc = self.r(c, a);
                let (ai, ci) = (self.image(a), self.image(c));
                let e = DVec2::from_angle(self.b.angle[j]);
                let an = format!("{}{j}", plain(self.name(a)));
                let limit = if offset == 0.0 {
                    self.slot_limit(&step, (a, c), j)?
                } else {
                    None
                };
                // At the pivot the radius c → a vanishes: the slotted link's line stands for it.
                let across = if limit.is_some() { e.perp() } else { rc.perp() };
                let (x, cr) = if vel {
                    self.meet(
                        &format!("{step}: image of {an}"),
                        ("⊥ to the slotted link", ci, across),
                        ("∥ slide", ai, e),
                    )?
                } else {
                    let n = self.lay(
                        "normal component, slotted link",
                        ci,
                        self.normal(j, rc),
                        &format!("n_{j}"),
                    );
                    let kk = self.coriolis(i, self.vel_image(a), self.vel_coincident(&an), ai);
                    self.meet(
                        &format!("{step}: image of {an}"),
                        ("⊥ to the slotted link", n, across),
                        ("∥ slide", kk, e),
                    )?
                };
                self.coincident_image(&an, a, j, x);
                let rj = match limit {
                    Some(rate) => rate,
                    None if vel => self.rate_from(rc, ci, x),
                    None => self.rate_from(rc, ci + self.normal(j, rc) / self.mu(), x),
                };
                self.finish_link(j, &[(c, ci)], rj);
                // Beside the pivot the image of the coincident point is no base for the
                // similarity: further points of the link follow from the rate.
                if limit.is_none() {
                    self.links.add(j, self.b.p[a], x);
                }
                self.finish_link(i, &[(a, ai)], rj);
                let owner_a = owner(self.prog, a);
                self.relative((a, j), x, (a, owner_a), ai, cr);
            }
            PDyad::Prp { gi, gj, joint } => {
                let (k1, k2) = (self.guide_link(&gi), self.guide_link(&gj));
                let (e1, e2) = (self.dir(&gi.dir), self.dir(&gj.dir));
                let n1 = format!("{}{k1}", plain(self.name(joint)));
                let n2 = format!("{}{k2}", plain(self.name(joint)));
                let at = self.b.p[joint];
                let (j1, j2) = (self.image_on(k1, at, &n1), self.image_on(k2, at, &n2));
                let (s1, s2) = if vel {
                    (j1, j2)
                } else {
                    let vj = self.vel_image(joint);
                    let (c1, c2) = (self.vel_coincident(&n1), self.vel_coincident(&n2));
                    (self.coriolis(k1, c1, vj, j1), self.coriolis(k2, c2, vj, j2))
                };
                let (x, cr) = self.meet(
                    &format!("{step}: image of {}", self.name(joint)),
                    ("∥ guide i", s1, e1),
                    ("∥ guide j", s2, e2),
                )?;
                self.set_image(joint, x, &[]);
                self.coincident.push((n1, j1));
                self.coincident.push((n2, j2));
                let (r1, r2) = (self.rate(k1), self.rate(k2));
                self.finish_link(i, &[(joint, x)], r1);
                self.finish_link(j, &[(joint, x)], r2);
                let _ = cr;
            }
            PDyad::Rpp {
                a,
                slide,
                guide,
                joint,
            } => {
                let k = self.guide_link(&guide);
                let (es, eg) = (self.dir(&slide), self.dir(&guide.dir));
                let ai = self.image(a);
                let rk0 = self.rate(k);
                self.links.rate[i] = Some(rk0);
                let an = format!("{}{j}", plain(self.name(a)));
                let ak_name = format!("{}{k}", plain(self.name(a)));
                let ak = self.image_on(k, self.b.p[a], &ak_name);
                self.coincident.push((ak_name.clone(), ak));
                let (s1, s2) = if vel {
                    (ai, ak)
                } else {
                    let va = self.vel_coincident(&an);
                    let (v_a, v_k) = (self.vel_image(a), self.vel_coincident(&ak_name));
                    (self.coriolis(i, v_a, va, ai), self.coriolis(k, v_k, va, ak))
                };
                let (x, cr) = self.meet(
                    &format!("{step}: image of {an}"),
                    ("∥ slide", s1, es),
                    ("∥ guide", s2, eg),
                )?;
                self.coincident_image(&an, a, j, x);
                let rk = self.rate(k);
                self.links.add(j, self.b.p[a], x);
                self.links.rate[j] = Some(rk);
                let jx = self.image_on(j, self.b.p[joint], self.prog.names[joint].as_str());
                self.set_image(joint, jx, &[]);
                self.finish_link(j, &[(joint, jx)], rk);
                self.finish_link(i, &[(a, ai)], rk);
                let owner_a = owner(self.prog, a);
                self.relative((a, j), x, (a, owner_a), ai, cr);
            }
        }
        Ok(())
    }

    /// The slotted link's rate when the pin `a` passes through its pivot `c` (RPR without
    /// offset): ω (velocity plan) or ε (acceleration plan) of link `j` as the limit of the
    /// rotation of the line c → a, from the relative motion of `a` about `c`: with Δv, Δa, Δj
    /// the relative velocity, acceleration and jerk, ω = [Δv × Δa]/(2|Δv|²) and
    /// ε = [Δv × Δj]/(3|Δv|²) − ω·(Δv·Δa)/|Δv|². `None` away from the pivot: where the
    /// crank travel h to the coincidence has h⁴ > 2δ/|w′| (δ the rounding of the positions,
    /// w′ = Δv/ω₁), the reading off the plan loses fewer digits than the limit's O(h).
    /// Refused where the relative motion is not known from the crank alone.
    fn slot_limit(
        &self,
        step: &str,
        (a, c): (usize, usize),
        j: usize,
    ) -> Result<Option<f64>, ConstructionError> {
        let (w1, mu_l) = (self.w1, self.mu_l);
        let dv = if self.kind == PlanKind::Velocity {
            (self.image(a) - self.image(c)) * self.mu()
        } else {
            self.vel_between(self.vel_image(c), self.vel_image(a))
        };
        let v2 = dv.length_squared() / (w1 * w1);
        let hp = self.r(c, a).length();
        let at = (self.b.p[a].length() + self.b.p[c].length()) * mu_l;
        let delta = f64::EPSILON * (at + v2.sqrt());
        if !(hp.powi(4) <= 2.0 * delta * v2 * v2.sqrt()) {
            return Ok(None);
        }
        let refuse = |why: String| ConstructionError::Other {
            step: format!("{step}: rate of the slotted link {j}"),
            message: format!(
                "the pin {} is {:.3e} m from the pivot {} (|v_{}{}| = {:.6} m/s): {why}",
                self.name(a),
                hp,
                self.name(c),
                plain(self.name(a)),
                plain(self.name(c)),
                dv.length()
            ),
        };
        if v2 == 0.0 {
            return Err(refuse("the line through them is not determined".into()));
        }
        // Acceleration and jerk of a point of the frame or the crank (constant ω₁).
        let motion = |k: usize| -> Option<(DVec2, DVec2)> {
            if k < self.prog.fixed.len() {
                Some((DVec2::ZERO, DVec2::ZERO))
            } else if self.prog.on_frame_or_crank(k) {
                let v = if self.kind == PlanKind::Velocity {
                    self.image(k) * self.mu()
                } else {
                    self.vel_image(k) * self.known.mu_v
                };
                Some((-self.r(self.prog.centre, k) * (w1 * w1), -v * (w1 * w1)))
            } else {
                None
            }
        };
        let (Some((aa, ja)), Some((ac, jc))) = (motion(a), motion(c)) else {
            return Err(refuse(format!(
                "the rate of link {j} is a limit that needs the relative acceleration and jerk, known only for points of the frame and the crank"
            )));
        };
        let dv2 = dv.length_squared();
        let da = aa - ac;
        let omega = dv.perp_dot(da) / (2.0 * dv2);
        Ok(Some(match self.kind {
            PlanKind::Velocity => omega,
            PlanKind::Acceleration => {
                let omega = self.known.vel.map_or(omega, |v| v.rate[j]);
                dv.perp_dot(ja - jc) / (3.0 * dv2) - omega * dv.dot(da) / dv2
            }
        }))
    }

    /// Record a link's new known images and its rate.
    fn finish_link(&mut self, link: usize, pts: &[(usize, DVec2)], rate: f64) {
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
    fn coincident_image(&mut self, name: &str, point: usize, link: usize, x: DVec2) {
        let prime = if self.kind == PlanKind::Acceleration {
            "′"
        } else {
            ""
        };
        let label = format!("{}_{{{link}}}{prime}", lower(self.name(point)));
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
    }

    /// The Coriolis component 2ω·v_r of a point moving relative to `link`, v_r read on the
    /// velocity plan from the image `rel_from` to `rel_to`, turned 90° in the sense of ω; laid
    /// from `from`. Returns its end `k` (`from` itself when it vanishes).
    fn coriolis(&mut self, link: usize, rel_from: DVec2, rel_to: DVec2, from: DVec2) -> DVec2 {
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
    fn relative(
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
            format!("{}{suffix}", plain(&self.prog.names[k]))
        };
        let pq = format!("{}_{}", tag(p), tag(q));
        let value = self.read(q_img, p_img);
        let quantity = match self.kind {
            PlanKind::Velocity => format!("v_{pq}"),
            PlanKind::Acceleration => format!("a_{pq}"),
        };
        self.cond_reading(quantity, Measure::Relative { p, q }, value, cr);
    }

    fn cond_reading(&mut self, quantity: String, what: Measure, value: f64, cr: f64) {
        self.reading(quantity, what, value, Some(cr));
    }
}
