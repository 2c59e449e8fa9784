//! Zhukovsky's lever (рычаг Жуковского) as a construction: the velocity plan turned 90°
//! clockwise, every force applied at the image of its point, every couple replaced by two
//! forces at two points of its link, the moments about the pole with their arms measured on
//! the drawing; the balancing moment (or force at the image of the pitch point) from
//! Σ M_p = 0. The lever's moment of a force is its power divided by μ_v, so the lever is the
//! power balance drawn.

use super::loads::Load;
use super::spec::Drive;
use super::twin::line_of_action;
use crate::construct::{Figure, Item, Recorder, Role};
use crate::geom::{DVec2, Segment};
use crate::linkage::{Built, KinPlan, PlanSetup};

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

/// Turn a plan vector 90° clockwise.
fn turn(v: DVec2) -> DVec2 {
    DVec2::new(v.y, -v.x)
}

/// Build the lever from the velocity plan `vp` of the position `setup` and its loads.
pub fn lever(setup: &PlanSetup<'_>, vp: &KinPlan, loads: &[Load], drive: &Drive) -> Lever {
    let (prog, b, w1) = (setup.prog, setup.built, setup.w1);
    let mu_v = vp.figure.scale;
    let mut rec = Recorder::in_context("Zhukovsky's lever", mu_v, &setup.ctx);
    let pole = rec.pole("p");
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
            let name = crate::linkage::plain(&prog.names[k]).to_lowercase();
            let id = rec.draw("image", Item::Point(x), Role::Given, &[]);
            rec.label(id, name, x, x.normalize_or_zero());
        }
    }
    let mut arms = 0;
    let mut moment = |rec: &mut Recorder, x: DVec2, f: DVec2, name: &str| -> f64 {
        let Some(e) = f.try_normalize() else {
            return 0.0;
        };
        let id = rec.draw(
            format!("{name} at its image"),
            Item::Vector {
                from: x,
                to: x + e * ARROW_MM,
            },
            Role::Result,
            &[],
        );
        rec.label(id, name, x + e * ARROW_MM, e);
        let foot = x + e * (-x).dot(e);
        let arm = rec.measure(DVec2::ZERO, foot);
        if arm.drawn_mm > 0.5 {
            arms += 1;
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
        x.perp_dot(e).signum() * f.length() * arm.value
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
            let len = rec.measure(b.p[o], p_far).read_mm * mu;
            if len.is_nan() || len <= 0.0 {
                continue;
            }
            let e = (p_far - b.p[o]).normalize().perp();
            let f = e * (l.moment / len);
            // The couple's two forces, primed apart from the link's inertia force.
            let name = |prime: &str| l.name.replacen('M', &format!("F{prime}"), 1);
            power += moment(&mut rec, turn(i_far), f, &name("′"));
            power += moment(&mut rec, turn(vp.images[o]), -f, &name("″"));
        } else {
            // A force at a point of another link (friction on a guide) acts on its own link.
            let x = if l.shift == DVec2::ZERO && prog.links_of(l.at).contains(&l.link) {
                vp.images[l.at]
            } else {
                image(b, vp, l.link, b.p[l.at] + l.shift / mu, mu)
            };
            power += moment(&mut rec, turn(x), l.force, &l.name);
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
            let unit = moment(&mut rec, x, d, "F_{у}");
            let f = -power / unit;
            (m_bal, Some(f))
        }
    };
    Lever {
        figure: rec.finish(),
        m_bal,
        f_bal,
    }
}
