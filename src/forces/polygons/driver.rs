//! The driving link's polygon: the balancing moment (a coupling, drawn on the crank about
//! its centre) or the tooth force on the line of action (a gear drive), and the frame's
//! reaction.

use super::*;
use crate::forces::spec::GearDrive;

/// The longest piece of a pitch circle drawn about the pitch point, mm: a wheel larger than
/// its crank shows as an arc through P, not a circle filling the sheet.
const PITCH_ARC_MM: f64 = 80.0;

/// Half the length of the line of action drawn through the pitch point, mm.
const LINE_OF_ACTION_MM: f64 = 30.0;

/// A wheel's pitch circle about `c` of radius `r` (mm), whole when small, else the arc of
/// [`PITCH_ARC_MM`] centred on the direction `at` (radians) to the pitch point.
fn pitch_circle(c: DVec2, r: f64, at: f64) -> Option<Item> {
    let sweep = PITCH_ARC_MM / r;
    if sweep >= TAU * 0.5 {
        Circle::new(c, r).map(Item::Circle)
    } else {
        (r > 0.0).then(|| {
            Item::Arc(crate::geom::Arc {
                center: c,
                radius: r,
                start: at - sweep / 2.0,
                sweep,
            })
        })
    }
}

/// The gear drive as the driving link's drawing shows it (in the units [`wheel`] was given):
/// the crank's centre, its wheel's and the pinion's pitch radii, the direction to the pitch
/// point (radians), the pitch point and the line of action's unit direction.
pub(super) struct Wheel {
    pub(super) o: DVec2,
    pub(super) r: f64,
    pub(super) mate: Option<f64>,
    pub(super) towards: f64,
    pub(super) p: DVec2,
    pub(super) d: DVec2,
}

impl Wheel {
    /// What it draws, its units drawn `mu` to the mm (1 when they are mm), whose size
    /// depends on μ_l: the wheel's pitch circle or arc, the pinion's, the line of action
    /// through P (about the wheel's radius long, at most 2·[`LINE_OF_ACTION_MM`]).
    pub(super) fn items(&self, mu: f64) -> (Option<Item>, Option<Item>, Item) {
        let (o, r, p) = (self.o / mu, self.r / mu, self.p / mu);
        let u = DVec2::from_angle(self.towards);
        let pinion = self
            .mate
            .and_then(|rm| pitch_circle(o + u * (r + rm / mu), rm / mu, self.towards + PI));
        let half = (r * 0.6).min(LINE_OF_ACTION_MM);
        let action = Segment::new(p - self.d * half, p + self.d * half);
        (
            pitch_circle(o, r, self.towards),
            pinion,
            Item::Segment(action),
        )
    }
}

/// The driving link: the balancing moment (coupling) or force (gear) and the frame's reaction.
pub(super) fn driver(
    board: &Board<'_>,
    applied: &[Load],
    drive: &Drive,
    arms: usize,
) -> Result<(DriverPolygon, usize), ConstructionError> {
    let prog = board.setup.prog;
    let b = board.setup.built;
    let crank = prog.crank_link as usize;
    let mut sch = Scheme::new(board, format!("driving link {crank}"), arms);
    draw_links(&mut sch.rec, prog, b, Role::Given, "crank", Part::Driver);
    crate::linkage::name_points(&mut sch.rec, prog, b, Part::Driver, true);
    let loads = on(applied, crank);
    for l in &loads {
        sch.show(l);
    }
    let o = b.p[prog.centre];
    let k = sch.moments(o, &loads);
    let known = sch.drain();
    let mut pol = Polygon::new(
        format!("force triangle of link {crank}"),
        board.scale_of(None),
        &board.setup.ctx,
    );
    let p0 = pol.tip;
    pol.lay_all(&loads);
    let (m_bal, f_bal, unknown) = match drive {
        Drive::Coupling => {
            // The balancing moment drawn on the crank about O, the way it turns it.
            if k != 0.0 {
                crate::forces::arrows::couple(&mut sch.rec, "M_{у}", o, -k);
            }
            (
                -k,
                None,
                Unknown::Couple {
                    name: "M_{у}".into(),
                    value: -k,
                },
            )
        }
        Drive::Gear(g) => {
            let mu = board.setup.mu_l.value();
            // The tooth pushes on the flank that turns the crank the way M_bal = −k does.
            let flank = if k == 0.0 { board.sense() } else { -k.signum() };
            let wheel = wheel(o, mu, g, flank);
            let (p, d) = (wheel.p, wheel.d);
            let towards = DVec2::from_angle(g.towards);
            let (pitch, pinion, action) = wheel.items(1.0);
            for (what, item) in [
                ("pitch circle of the wheel", pitch),
                ("pitch circle of the pinion", pinion),
            ] {
                if let Some(item) = item {
                    sch.rec.draw(what, item, Role::Axis, &[]);
                }
            }
            sch.rec.draw(
                "line of centres",
                Item::Segment(Segment::new(o, p)),
                Role::Axis,
                &[],
            );
            let pid = sch
                .rec
                .point("pitch point", p, Role::Given, "P", towards, &[]);
            sch.rec
                .draw("line of action at α_w", action, Role::Axis, &[pid]);
            // The balancing force's arm about O, measured.
            let unit = Load::force(crank, LoadKind::Reaction, "F_{у}".into(), d, prog.centre);
            let unit = Load {
                shift: (p - o) * mu,
                ..unit
            };
            let arm = sch.moment(o, &unit);
            let f = -k / arm;
            let probe = sch.drain().pop();
            let unknown = Unknown::Force {
                name: "F_{у}".into(),
                arm,
                arm_mm: probe.as_ref().map_or(0.0, |t| t.arm_mm),
                label: probe.and_then(|t| t.label),
                value: f,
            };
            sch.show(&Load {
                force: d * f,
                ..unit
            });
            pol.lay("F_{у}", d * f);
            (-k, Some((f, arm.abs())), unknown)
        }
    };
    let e = pol.tip;
    let r01 = pol.read(&reaction_name(0, crank), e, p0);
    let reaction = revolute(0, crank, prog.centre, r01);
    show_reaction(&mut sch, &reaction);
    let (polygon, detail) = pol.finish();
    let arms = sch.arms;
    let driver = DriverPolygon {
        scheme: sch.rec.finish(),
        polygon,
        details: detail,
        reaction,
        m_bal,
        f_bal: f_bal.map(|(f, _)| f),
        arm: f_bal.map(|(_, arm)| arm),
        equation: MomentEquation {
            about: Some(prog.centre),
            links: vec![crank],
            terms: known,
            unknown,
        },
    };
    Ok((driver, arms))
}

/// The gear drive `g` of the crank whose centre is `o`, in units of `per` metres (mm at μ_l
/// on the drawing, 1 for SI), the tooth pushing on the flank that turns the crank in the
/// sense `flank` ([`line_of_action`]).
pub(super) fn wheel(o: DVec2, per: f64, g: &GearDrive, flank: f64) -> Wheel {
    let r = g.radius() / per;
    let (p, d) = line_of_action(o, r, g.towards, g.pressure_angle, flank);
    Wheel {
        o,
        r,
        mate: g.mate_radius().map(|rm| rm / per),
        towards: g.towards,
        p,
        d,
    }
}
