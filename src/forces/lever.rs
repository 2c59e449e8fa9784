//! Zhukovsky's lever (рычаг Жуковского) as a construction: the velocity plan turned 90°
//! clockwise, every force applied at the image of its point, every couple replaced by two
//! forces at two points of its link, the moments about the pole with their arms measured on
//! the drawing; the balancing moment (or force at the image of the pitch point) from
//! Σ M_p = 0. The lever's moment of a force is its power divided by μ_v, so the lever is the
//! power balance drawn.

use super::arrows::{arm_named, arrow, SAME_ARM_MM};
use super::loads::Load;
use super::polygons::{MomentEquation, MomentTerm, Unknown};
use super::spec::Drive;
use super::twin::line_of_action;
use crate::construct::{Figure, Item, Measured, Recorder, Role};
use crate::geom::{DVec2, Segment};
use crate::linkage::{image_label, Built, KinPlan, PlanKind, PlanSetup};
use crate::scale::Scale;

/// Length of a force's arrow on the lever, mm.
const ARROW_MM: f64 = 12.0;

/// The lever as drawn and what it gives.
#[derive(Debug, Clone, PartialEq)]
pub struct Lever {
    /// The turned plan with the forces and their arms, at μ_v.
    pub figure: Figure,
    /// The balancing moment, N·m.
    pub m_bal: f64,
    /// The balancing force, N: a gear drive's at the pitch point's image, a coupling's at
    /// the crank pin's (⊥ pa).
    pub f_bal: Option<f64>,
    /// The crank's length l_OA, m, that turns a coupling's balancing force at the pin into
    /// its balancing moment M_у = F_у·l_OA (`None` for a gear drive).
    pub crank_arm: Option<f64>,
    /// ΣM about the pole with every arm read off the lever (plan mm; the terms' moments
    /// are powers, W), which gives the balancing force (gear drive) or, through the
    /// power, the balancing moment.
    pub equation: MomentEquation,
}

/// See [`Board::roomier_onto`], mm.
const ROOM_MARGIN_MM: f64 = 1.0;

/// Where a couple on a link of one point puts its second force: this far along the link's
/// frame, drawing mm.
const SECOND_POINT_MM: f64 = 20.0;

/// The velocity plan's image of a drawing point `x` (mm) of link `l`, plan mm, by the
/// similarity of the link's images: the image of its origin plus ω × r.
fn image(b: &Built, vp: &KinPlan, l: usize, x: DVec2, mu_l: f64) -> DVec2 {
    let o = b.origin[l];
    let w = vp.rate.get(l).copied().unwrap_or(0.0);
    vp.images[o] + (x - b.p[o]).perp() * (w * mu_l / vp.figure.scale.value())
}

/// The name of the pitch point's image on the lever, where the balancing force of a gear
/// drive acts: the lever's points are named by the plan's small letters, and `p` is the pole.
const PITCH_IMAGE: &str = "p_{P}";

/// Turn a plan vector 90° clockwise.
fn turn(v: DVec2) -> DVec2 {
    DVec2::new(v.y, -v.x)
}

/// The lever's turned plan is drawn about this long (its longest ray), mm: a lever is read
/// by its arms, so it is drawn larger than the plan it turns.
const LEVER_PLAN_MM: f64 = 200.0;

/// The lever with everything on it (a balancing force's arm included) is drawn at most this
/// large, mm.
const LEVER_MAX_MM: f64 = 300.0;

/// Build the lever from the velocity plan `vp` of the position `setup` and its loads, at
/// the round μ_v that draws its turned plan about [`LEVER_PLAN_MM`] long and the whole lever
/// within [`LEVER_MAX_MM`] (never smaller than the plan): the lever balances powers, so its
/// scale is free, and a larger lever reads its arms more exactly. Its arms are numbered on
/// from `arms`, the arms the position's other drawings numbered (one sheet holds them all).
pub fn lever(
    setup: &PlanSetup<'_>,
    vp: &KinPlan,
    loads: &[Load],
    drive: &Drive,
    arms: usize,
) -> Lever {
    let mu_v = vp.figure.scale;
    let at_plan = lever_at(setup, vp, loads, drive, mu_v, arms);
    let ray = vp.images.iter().map(|x| x.length()).fold(0.0, f64::max);
    let reach = at_plan
        .figure
        .bounds()
        .map_or(0.0, |(lo, hi)| lo.abs().max(hi.abs()).length());
    let larger = [
        Scale::round_for(ray * mu_v.value(), LEVER_PLAN_MM, mu_v.quantity),
        Scale::round_for(reach * mu_v.value(), LEVER_MAX_MM, mu_v.quantity),
    ]
    .into_iter()
    .flatten()
    .max_by(|a, b| a.value().total_cmp(&b.value()));
    match larger {
        Some(mu) if mu.value() < mu_v.value() => lever_at(setup, vp, loads, drive, mu, arms),
        _ => at_plan,
    }
}

/// The lever drawn at `mu` (the plan `vp` enlarged by μ_v/μ), its arms numbered on from
/// `arms`.
fn lever_at(
    setup: &PlanSetup<'_>,
    vp: &KinPlan,
    loads: &[Load],
    drive: &Drive,
    mu: Scale,
    arms: usize,
) -> Lever {
    let enlarge = vp.figure.scale.value() / mu.value();
    let mut rec = Recorder::in_context("Zhukovsky's lever", mu, &setup.ctx);
    let names = turned_plan(&mut rec, setup.prog, vp, enlarge);
    let mut lb = Board {
        rec,
        arms,
        log: Vec::new(),
        names,
        turned: vp.images.iter().map(|x| turn(*x * enlarge)).collect(),
    };
    let mut power = 0.0;
    for l in loads {
        power += if l.is_couple() {
            lb.couple(setup, vp, l, enlarge)
        } else {
            lb.force(setup, vp, l, enlarge)
        };
    }
    let balance = match drive {
        Drive::Coupling => lb.crank_force(setup, power),
        Drive::Gear(g) => lb.tooth_force(setup, vp, g, power, enlarge),
    };
    Lever {
        figure: lb.rec.finish(),
        m_bal: balance.m_bal,
        f_bal: balance.f_bal,
        crank_arm: balance.crank_arm,
        equation: MomentEquation {
            about: None,
            links: Vec::new(),
            terms: lb.log,
            unknown: balance.unknown,
        },
    }
}

/// The turned plan: a ray from the pole to every point's image, each image named; returns
/// the names of the images (by point): a fixed point's, or one on the pole, is the pole `p`.
fn turned_plan(
    rec: &mut Recorder,
    prog: &crate::linkage::Program,
    vp: &KinPlan,
    enlarge: f64,
) -> Vec<String> {
    let pole = rec.pole(POLE);
    let mut names = vec![POLE.to_string(); prog.names.len()];
    for (k, name) in names.iter_mut().enumerate().skip(prog.fixed.len()) {
        let x = turn(vp.images[k] * enlarge);
        if x.length() > 0.5 {
            rec.draw(
                "turned plan",
                Item::Segment(Segment::new(DVec2::ZERO, x)),
                Role::Construction,
                &[pole],
            );
            let label = image_label(&prog.names[k], PlanKind::Velocity);
            let id = rec.draw("image", Item::Point(x), Role::Given, &[]);
            rec.label(id, label.clone(), x, x.normalize_or_zero());
            *name = label;
        }
    }
    names
}

/// The lever's pole.
const POLE: &str = "p";

/// Where a force acts on the lever: the image of its point, named or not.
#[derive(Debug, Clone, PartialEq)]
enum At {
    /// An image the turned plan draws and names, its ray from the pole drawn.
    Named(String),
    /// An image of no point of the mechanism (a couple's second point on a block).
    Unnamed,
    /// An image of no point of the plan that the lever draws and names, with its ray (the
    /// pitch point's).
    New(String),
}

/// What the lever gives for the drive: the balancing moment, N·m; the balancing force, N;
/// its equation's unknown; and the crank's length the force at its pin turns into the
/// moment (a coupling), m.
struct Balance {
    m_bal: f64,
    f_bal: Option<f64>,
    unknown: Unknown,
    crank_arm: Option<f64>,
}

/// The lever being drawn: its recorder, the arms numbered so far, the moments taken, the
/// names of the turned plan's images and the images turned (lever mm), by point.
struct Board {
    rec: Recorder,
    arms: usize,
    log: Vec<MomentTerm>,
    names: Vec<String>,
    turned: Vec<DVec2>,
}

impl Board {
    /// The image of point `k` as a force's place on the lever.
    fn at(&self, k: usize) -> At {
        self.names
            .get(k)
            .map_or(At::Unnamed, |n| At::Named(n.clone()))
    }

    /// A force of the loads at the image of its point; its moment about the pole (a power).
    fn force(&mut self, setup: &PlanSetup<'_>, vp: &KinPlan, l: &Load, enlarge: f64) -> f64 {
        let (prog, b, mu) = (setup.prog, setup.built, setup.mu_l.value());
        // A force at a point of another link (friction on a guide) acts on its own link.
        let (x, at) = if l.shift == DVec2::ZERO && prog.links_of(l.at).contains(&l.link) {
            (self.turned[l.at], self.at(l.at))
        } else {
            let x = image(b, vp, l.link, b.p[l.at] + l.shift / mu, mu);
            (turn(x * enlarge), At::Unnamed)
        };
        self.moment(x, l.force, &l.name, &at)
    }

    /// Whether a couple's force along `u` at the image `x` is drawn onto it rather than from
    /// it: its labelled free end goes where it stands farther from the lever's other images
    /// (by more than [`ROOM_MARGIN_MM`]) — a couple's force has no arrow of its own there to
    /// keep, and at a crowded image (the shaper's e ≡ s₅ beside d) a force drawn into the
    /// crowd takes the place of the labels of the forces already at it.
    fn roomier_onto(&self, x: DVec2, u: DVec2) -> bool {
        let room = |end: DVec2| {
            self.turned
                .iter()
                .filter(|y| y.distance(x) > ROOM_MARGIN_MM)
                .map(|y| y.distance(end))
                .fold(f64::INFINITY, f64::min)
        };
        room(x - u * ARROW_MM) > room(x + u * ARROW_MM) + ROOM_MARGIN_MM
    }

    /// A couple as two forces ⊥ to its link at the link's origin and its farthest point (a
    /// link of one point — a block — at a point 20 mm along its frame, imaged by the
    /// similarity of its images): on the lever both ⊥ to the segment between their images,
    /// which is the pair's arm — one moment F′·(ab), no arm about the pole.
    fn couple(&mut self, setup: &PlanSetup<'_>, vp: &KinPlan, l: &Load, enlarge: f64) -> f64 {
        let (prog, b, mu) = (setup.prog, setup.built, setup.mu_l.value());
        let o = b.origin[l.link];
        let far = (0..prog.names.len())
            .filter(|&k| prog.links_of(k).contains(&l.link))
            .max_by(|&x, &y| b.p[x].distance(b.p[o]).total_cmp(&b.p[y].distance(b.p[o])))
            .filter(|&f| b.p[f] != b.p[o]);
        let (p_far, x_far, at_far) = match far {
            Some(f) => (b.p[f], self.turned[f], self.at(f)),
            None => {
                let x = b.p[o] + DVec2::from_angle(b.angle[l.link]) * SECOND_POINT_MM;
                (x, turn(image(b, vp, l.link, x, mu) * enlarge), At::Unnamed)
            }
        };
        let len = self.rec.measure(b.p[o], p_far).read_mm * mu;
        if len.is_nan() || len <= 0.0 {
            return 0.0;
        }
        let e = (p_far - b.p[o]).normalize().perp();
        let f = e * (l.moment / len);
        // The couple's two forces, primed apart from the link's inertia force.
        let name = |prime: &str| l.name.replacen('M', &format!("F{prime}"), 1);
        let x_o = self.turned[o];
        let (first, second) = (name("′"), name("″"));
        for (x, force, n) in [(x_far, f, &first), (x_o, -f, &second)] {
            if let Some(u) = force.try_normalize() {
                let onto = self.roomier_onto(x, u);
                arrow(
                    &mut self.rec,
                    format!("{n} at its image"),
                    n,
                    (x, u, ARROW_MM),
                    onto,
                );
            }
        }
        // The pair's arm: the segment between the two images, each force ⊥ to it.
        let arm = self.rec.measure(x_o, x_far);
        let label = if arm.drawn_mm <= 0.5 {
            None
        } else {
            self.rec.draw(
                format!("{first}, {second}: the arm of the pair between their images"),
                Item::Segment(Segment::new(x_o, x_far)),
                Role::Construction,
                &[],
            );
            match (self.at(o), at_far) {
                (At::Named(a), At::Named(c)) => Some(format!("{a}{c}")),
                _ => Some(self.numbered_arm(&first, x_o, x_far)),
            }
        };
        let power = (x_far - x_o).perp_dot(f).signum() * f.length() * arm.value;
        self.log_force(first, f.length(), &arm, label, power)
    }

    /// The balancing force of a coupling (the textbook's F_у at the crank pin A ⊥ OA): on the
    /// lever at the pin's image a ⊥ pa, its arm the ray pa; the balancing moment
    /// M_у = F_у·l_OA. `power`: the loads' moments about the pole.
    fn crank_force(&mut self, setup: &PlanSetup<'_>, power: f64) -> Balance {
        let (prog, b, w1) = (setup.prog, setup.built, setup.w1);
        let m_power = -power / w1;
        let along = (b.p[prog.pin] - b.p[prog.centre]).normalize_or_zero();
        // F_у turns the crank the way M_у does (ω₁'s way when there is nothing to balance).
        let sense = if m_power == 0.0 { w1 } else { m_power }.signum();
        let d = along.perp() * sense;
        let unit = self.moment(self.turned[prog.pin], d, BALANCING, &self.at(prog.pin));
        if unit == 0.0 || !unit.is_finite() {
            // The pin's image on the pole (no speed): the power balance alone.
            self.log.pop();
            return Balance {
                m_bal: m_power,
                f_bal: None,
                unknown: Unknown::Couple {
                    name: "M_{у}".into(),
                    value: m_power * w1,
                },
                crank_arm: None,
            };
        }
        let f = -power / unit;
        let l_oa = prog.crank_length;
        Balance {
            m_bal: f * l_oa * sense,
            f_bal: Some(f),
            unknown: self.probe_unknown(f),
            crank_arm: Some(l_oa),
        }
    }

    /// The balancing force of a gear drive at the image of the pitch point, along the line
    /// of action; the balancing moment from the power.
    fn tooth_force(
        &mut self,
        setup: &PlanSetup<'_>,
        vp: &KinPlan,
        g: &crate::forces::GearDrive,
        power: f64,
        enlarge: f64,
    ) -> Balance {
        let (prog, b, w1, mu) = (setup.prog, setup.built, setup.w1, setup.mu_l.value());
        let o = b.p[prog.centre];
        let m_bal = -power / w1;
        // The tooth pushes on the flank that turns the crank the way M_у does.
        let flank = if m_bal == 0.0 { w1 } else { m_bal }.signum();
        let (p, d) = line_of_action(o, g.radius() / mu, g.towards, g.pressure_angle, flank);
        let crank = prog.crank_link as usize;
        let x = turn(image(b, vp, crank, p, mu) * enlarge);
        let unit = self.moment(x, d, BALANCING, &At::New(PITCH_IMAGE.into()));
        let f = -power / unit;
        Balance {
            m_bal,
            f_bal: Some(f),
            unknown: self.probe_unknown(f),
            crank_arm: None,
        }
    }

    /// The balancing force's own term, taken as the unknown's arm (`value` the force, N).
    fn probe_unknown(&mut self, value: f64) -> Unknown {
        let probe = self.log.pop();
        Unknown::Force {
            name: BALANCING.into(),
            arm: probe.as_ref().map_or(0.0, |t| t.moment),
            arm_mm: probe.as_ref().map_or(0.0, |t| t.arm_mm),
            label: probe.and_then(|t| t.label),
            value,
        }
    }

    /// A new arm's number `h_{n}`, the arm from `c` to `foot` drawn and labelled
    /// ([`crate::forces::arrows::arm`]).
    fn numbered_arm(&mut self, name: &str, c: DVec2, foot: DVec2) -> String {
        self.arms += 1;
        let label = format!("h_{{{}}}", self.arms);
        crate::forces::arrows::arm(&mut self.rec, format!("arm of {name}"), (c, foot), &label);
        label
    }

    /// The moment of `f` at `x` about the pole (a power, W), logged as a term; `at` names
    /// the image (a new one is drawn and labelled). The arm: none for a line through the
    /// pole; the ray from the pole to the image for a force ⊥ to it (`pb`); else the arm
    /// drawn once for every force on its line, `h_{n}`.
    fn moment(&mut self, x: DVec2, f: DVec2, name: &str, at: &At) -> f64 {
        let Some(e) = f.try_normalize() else {
            return 0.0;
        };
        let foot = x + e * (-x).dot(e);
        if let At::New(point) = at {
            // The image on the turned plan: its ray from the pole, as every point's.
            self.rec.draw(
                format!("{name}: the ray of its image"),
                Item::Segment(Segment::new(DVec2::ZERO, x)),
                Role::Construction,
                &[],
            );
            let id = self.rec.draw(
                format!("{name}: its image"),
                Item::Point(x),
                Role::Given,
                &[],
            );
            self.rec.label(id, point.as_str(), x, -e);
        }
        let id = arrow(
            &mut self.rec,
            format!("{name} at its image"),
            name,
            (x, e, ARROW_MM),
            false,
        );
        self.line_to_foot(id, name, foot);
        let arm = self.rec.measure(DVec2::ZERO, foot);
        let label = if arm.drawn_mm <= 0.5 {
            None
        } else if let (At::Named(p) | At::New(p), true) = (at, foot.distance(x) <= SAME_ARM_MM) {
            Some(format!("{POLE}{p}"))
        } else if let Some(same) = arm_named(&self.rec, DVec2::ZERO, foot) {
            Some(same)
        } else {
            Some(self.numbered_arm(name, DVec2::ZERO, foot))
        };
        // Moment about the pole in plan mm × N, turned into power with μ_v.
        let power = x.perp_dot(e).signum() * f.length() * arm.value;
        self.log_force(name.to_string(), f.length(), &arm, label, power)
    }

    /// Log a force's term of the lever's equation — its magnitude, N, its arm as read and
    /// labelled, its power — and return the power.
    fn log_force(
        &mut self,
        name: String,
        force: f64,
        arm: &Measured,
        label: Option<String>,
        power: f64,
    ) -> f64 {
        self.log.push(MomentTerm {
            name,
            force,
            arm: arm.value,
            arm_mm: arm.read_mm,
            label,
            moment: power,
            couple: false,
        });
        power
    }

    /// The line of action from the arrow `id` to the end of its arm, when the arm's foot is
    /// off the arrow.
    fn line_to_foot(&mut self, id: crate::construct::StepId, name: &str, foot: DVec2) {
        let rec = &mut self.rec;
        if let Some(Item::Vector { from, to }) = rec.steps().get(id.0 as usize).map(|s| &s.item) {
            let (from, to) = (*from, *to);
            let e = (to - from).normalize_or_zero();
            let along = (foot - from).dot(e);
            if along < -0.5 || along > (to - from).dot(e) + 0.5 {
                let near = if along < 0.0 { from } else { to };
                rec.draw(
                    format!("{name}: its line of action to the end of its arm"),
                    Item::Segment(Segment::new(near, foot)),
                    Role::Construction,
                    &[],
                );
            }
        }
    }
}

/// The balancing force's name.
const BALANCING: &str = "F_{у}";
