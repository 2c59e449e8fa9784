//! Zhukovsky's lever (рычаг Жуковского) as a construction: the velocity plan turned 90°
//! clockwise, every force applied at the image of its point, every couple replaced by two
//! forces at two points of its link, the moments about the pole with their arms measured on
//! the drawing; the balancing moment (or force at the image of the pitch point) from
//! Σ M_p = 0. The lever's moment of a force is its power divided by μ_v, so the lever is the
//! power balance drawn.

use super::arrows::{arm_named, arrow};
use super::loads::Load;
use super::polygons::{MomentEquation, MomentTerm, Unknown};
use super::spec::Drive;
use super::twin::line_of_action;
use crate::construct::{Figure, Item, Recorder, Role};
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
    /// The balancing force (gear drive), N.
    pub f_bal: Option<f64>,
    /// ΣM about the pole with every arm read off the lever (plan mm; the terms' moments
    /// are powers, W), which gives the balancing force (gear drive) or, through the
    /// power, the balancing moment.
    pub equation: MomentEquation,
}

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
/// scale is free, and a larger lever reads its arms more exactly.
pub fn lever(setup: &PlanSetup<'_>, vp: &KinPlan, loads: &[Load], drive: &Drive) -> Lever {
    let mu_v = vp.figure.scale;
    let at_plan = lever_at(setup, vp, loads, drive, mu_v);
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
        Some(mu) if mu.value() < mu_v.value() => lever_at(setup, vp, loads, drive, mu),
        _ => at_plan,
    }
}

/// The lever drawn at `mu` (the plan `vp` enlarged by μ_v/μ).
fn lever_at(
    setup: &PlanSetup<'_>,
    vp: &KinPlan,
    loads: &[Load],
    drive: &Drive,
    mu: Scale,
) -> Lever {
    let (prog, b, w1) = (setup.prog, setup.built, setup.w1);
    let enlarge = vp.figure.scale.value() / mu.value();
    let mut rec = Recorder::in_context("Zhukovsky's lever", mu, &setup.ctx);
    let pole = rec.pole("p");
    // The plan's images enlarged to the lever's μ, turned 90°.
    let turn = |v: DVec2| turn(v * enlarge);
    // The turned plan: a ray from the pole to every point's image.
    for k in prog.fixed.len()..prog.names.len() {
        let x = turn(vp.images[k]);
        if x.length() > 0.5 {
            rec.draw(
                "turned plan",
                Item::Segment(Segment::new(DVec2::ZERO, x)),
                Role::Construction,
                &[pole],
            );
            let name = image_label(&prog.names[k], PlanKind::Velocity);
            let id = rec.draw("image", Item::Point(x), Role::Given, &[]);
            rec.label(id, name, x, x.normalize_or_zero());
        }
    }
    let mut lb = Board {
        rec,
        arms: 0,
        log: Vec::new(),
    };
    let mu = setup.mu_l.value();
    let mut power = 0.0;
    for l in loads {
        if l.is_couple() {
            // A couple as two forces ⊥ to the link at its origin and its farthest point (a
            // link of one point — a block — at a point 20 mm along its frame, imaged by
            // the similarity of its images).
            let o = b.origin[l.link];
            let far = (0..prog.names.len())
                .filter(|&k| prog.links_of(k).contains(&l.link))
                .max_by(|&x, &y| b.p[x].distance(b.p[o]).total_cmp(&b.p[y].distance(b.p[o])))
                .filter(|&f| b.p[f] != b.p[o]);
            let (p_far, i_far) = match far {
                Some(f) => (b.p[f], vp.images[f]),
                None => {
                    let x = b.p[o] + DVec2::from_angle(b.angle[l.link]) * SECOND_POINT_MM;
                    (x, image(b, vp, l.link, x, mu))
                }
            };
            let len = lb.rec.measure(b.p[o], p_far).read_mm * mu;
            if len.is_nan() || len <= 0.0 {
                continue;
            }
            let e = (p_far - b.p[o]).normalize().perp();
            let f = e * (l.moment / len);
            // The couple's two forces, primed apart from the link's inertia force.
            let name = |prime: &str| l.name.replacen('M', &format!("F{prime}"), 1);
            power += lb.moment(turn(i_far), f, &name("′"), None);
            power += lb.moment(turn(vp.images[o]), -f, &name("″"), None);
        } else {
            // A force at a point of another link (friction on a guide) acts on its own link.
            let x = if l.shift == DVec2::ZERO && prog.links_of(l.at).contains(&l.link) {
                vp.images[l.at]
            } else {
                image(b, vp, l.link, b.p[l.at] + l.shift / mu, mu)
            };
            power += lb.moment(turn(x), l.force, &l.name, None);
        }
    }
    let crank = prog.crank_link as usize;
    let (m_bal, f_bal) = match drive {
        Drive::Coupling => (-power / w1, None),
        Drive::Gear(g) => {
            let o = b.p[prog.centre];
            let m_bal = -power / w1;
            // The tooth pushes on the flank that turns the crank the way M_у does.
            let flank = if m_bal == 0.0 { w1 } else { m_bal }.signum();
            let (p, d) = line_of_action(o, g.radius() / mu, g.towards, g.pressure_angle, flank);
            let x = turn(image(b, vp, crank, p, mu));
            let unit = lb.moment(x, d, "F_{у}", Some(PITCH_IMAGE));
            let f = -power / unit;
            (m_bal, Some(f))
        }
    };
    // The balancing force's own term (gear drive) is the unknown's arm.
    let unknown = match (f_bal, drive) {
        (Some(value), Drive::Gear(_)) => {
            let probe = lb.log.pop();
            Unknown::Force {
                name: "F_{у}".into(),
                arm: probe.as_ref().map_or(0.0, |t| t.moment),
                arm_mm: probe.as_ref().map_or(0.0, |t| t.arm_mm),
                label: probe.and_then(|t| t.label),
                value,
            }
        }
        _ => Unknown::Couple {
            name: "M_{у}".into(),
            value: m_bal * w1,
        },
    };
    Lever {
        figure: lb.rec.finish(),
        m_bal,
        f_bal,
        equation: MomentEquation {
            about: None,
            links: Vec::new(),
            terms: lb.log,
            unknown,
        },
    }
}

/// The lever being drawn: its recorder, the arms numbered so far and the moments taken.
struct Board {
    rec: Recorder,
    arms: usize,
    log: Vec<MomentTerm>,
}

impl Board {
    /// The moment of `f` at `x` about the pole; `image`: the name of its point's image when
    /// the turned plan has no such point (the pitch point's), drawn and labelled.
    fn moment(&mut self, x: DVec2, f: DVec2, name: &str, image: Option<&str>) -> f64 {
        let rec = &mut self.rec;
        let Some(e) = f.try_normalize() else {
            return 0.0;
        };
        let foot = x + e * (-x).dot(e);
        if let Some(point) = image {
            // The image on the turned plan: its ray from the pole, as every point's.
            rec.draw(
                format!("{name}: the ray of its image"),
                Item::Segment(Segment::new(DVec2::ZERO, x)),
                Role::Construction,
                &[],
            );
            let id = rec.draw(
                format!("{name}: its image"),
                Item::Point(x),
                Role::Given,
                &[],
            );
            rec.label(id, point, x, -e);
        }
        let id = arrow(
            rec,
            format!("{name} at its image"),
            name,
            (x, e, ARROW_MM),
            false,
        );
        // The line of action from the arrow to the end of its arm, when the arm's foot is
        // off the arrow.
        if let Some(Item::Vector { from, to }) = rec.steps().get(id.0 as usize).map(|s| &s.item) {
            let (from, to) = (*from, *to);
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
        let arm = rec.measure(DVec2::ZERO, foot);
        let mut label = None;
        if let Some(same) = arm_named(rec, DVec2::ZERO, foot) {
            label = Some(same);
        } else if arm.drawn_mm > 0.5 {
            self.arms += 1;
            let arms = self.arms;
            label = Some(format!("h_{{{arms}}}"));
            let id = rec.draw(
                format!("arm of {name}"),
                Item::Segment(Segment::new(DVec2::ZERO, foot)),
                Role::Construction,
                &[],
            );
            rec.label(
                id,
                format!("h_{{{arms}}}"),
                foot * 0.5,
                foot.perp().normalize_or_zero(),
            );
        }
        // Moment about the pole in plan mm × N, turned into power with μ_v.
        let power = x.perp_dot(e).signum() * f.length() * arm.value;
        self.log.push(MomentTerm {
            name: name.to_string(),
            force: f.length(),
            arm: arm.value,
            arm_mm: arm.read_mm,
            label,
            moment: power,
            couple: false,
        });
        power
    }
}
