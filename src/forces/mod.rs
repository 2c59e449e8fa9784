//! Force analysis: kinetostatics of Assur groups by force polygons, the driving link,
//! Zhukovsky's lever and the friction in the pairs — each a construction, an analytic twin
//! and a check. (Friction as the lectures draw it and rotor balancing, which import nothing
//! of this and which this imports nothing of, are rooms of their own: [`crate::friction`],
//! [`crate::balancing`].)
//!
//! One position's force analysis ([`analyse`]) gives:
//! - the loads ([`loads`]) from the acceleration plan (graphical) and from the analytic twin;
//! - the force polygons of every group and the driving link (`polygons`);
//! - Zhukovsky's lever (`lever`) from the velocity plan;
//! - the analytic twin (`twin`): one linear solve of every link's equilibrium, and the
//!   balancing moment again from the power balance;
//! - rows `R_<i>_<j>`, `h_<i>_<j>` (a guide reaction's point), `M_bal`, `F_bal` and the
//!   inertia loads `F_in<l>`, `M_in<l>`, graphical against analytic.

mod arrows;
mod diagnose;
mod error;
mod exact;
mod indicator;
mod indicator_draw;
mod lever;
mod loads;
mod pair_friction;
mod polygons;
mod residual;
mod rows;
mod spec;
#[cfg(test)]
mod tests;
mod twin;

pub use spec::{Action, Drive, ForceSpec, GearDrive, LinkMass, Resistance, Stroke};

use diagnose::located;
pub use error::ForceError;
pub use indicator::{GasReading, Indicator};
pub use indicator_draw::{indicator_figure, Reading};
pub use loads::{
    arm, carrier, force_scale, loads, reach, Load, LoadKind, Phase, PositionMotion, ZERO_PART,
};
pub use pair_friction::{friction_loads, PairFriction, PairMotion};
pub(crate) use polygons::predicted as predicted_drawings;
pub use polygons::{
    letter_at, letter_toward, reaction_name, DriverPolygon, GroupPolygon, MomentEquation,
    MomentTerm, PolygonDetail, Polygons, Unknown,
};
pub use rows::notes;
use rows::{reaction_rows, row, rows, zero_references};
pub use twin::{power_balance, solve as solve_twin, Equilibrium, Pair, PairKind, Reaction};

use crate::check::{Method, Row, Symbol};
use crate::construct::{ConstructionError, Context};
use crate::geom::DVec2;
use crate::linkage::{KinPlan, PlanPosition, PlanSetup, PositionPlan, Program};
use crate::scale::{Quantity, Scale};
use std::f64::consts::TAU;

/// Preferred length of the largest force on a polygon, mm.
pub const POLYGON_MM: f64 = 200.0;

/// What every analysis of a position gives, without and with friction in the pairs: the
/// loads, the polygons, the lever and the twin.
#[derive(Debug, Clone, PartialEq)]
pub struct Analysis {
    /// The loads as the plans give them (with friction: the friction loads).
    pub loads: Vec<Load>,
    /// The loads as the analytic twin gives them (with friction: the friction loads).
    pub loads_exact: Vec<Load>,
    /// The polygons.
    pub polygons: Polygons,
    /// Zhukovsky's lever.
    pub lever: lever::Lever,
    /// The analytic twin.
    pub twin: Equilibrium,
    /// The balancing moment from the power balance (with friction: with the friction's
    /// power), N·m.
    pub m_power: f64,
}

/// One position's force analysis: the frictionless [`Analysis`], μ_F, the sliders and the
/// analysis with friction.
#[derive(Debug, Clone, PartialEq)]
pub struct PositionForces {
    /// The position's label.
    pub label: String,
    /// The frictionless analysis.
    pub analysis: Analysis,
    /// μ_F of the polygons.
    pub scale_f: Scale,
    /// The guides' reactions on sliders of known length, by the twin.
    pub sliders: Vec<SliderEnds>,
    /// The crank's sense of rotation, +1 counter-clockwise.
    pub sense: f64,
    /// The same position with friction in the pairs, when `[forces.friction]` asks for it.
    pub friction: Option<Box<WithFriction>>,
    /// The rows.
    pub rows: Vec<Row>,
    /// The equilibrium residuals (`residual`) of the polygons and of the twin, without and
    /// (when the scene has it) with friction in the pairs.
    pub residuals: Vec<Residual>,
    /// The motion as the plans give it, which the loads are formed from.
    pub drawn: PositionMotion,
    /// The stroke the position lies on (which resistances act there).
    pub phase: loads::Phase,
}

/// The equilibrium check of both routes of one analysis (`residual::residual`): every
/// body's equations and the power balance on the check's own picture and motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Residual {
    /// The analysis with friction in the pairs.
    pub friction: bool,
    /// The force polygons' reactions and balancing load.
    pub polygons: residual::Residuals,
    /// The linear solve's.
    pub twin: residual::Residuals,
}

pub use residual::Residuals;

impl PositionForces {
    /// The rows `equilibrium_residual` and `power_residual` (`_f` with friction): the
    /// polygons' residual as the graphical value, the linear solve's as the analytic one;
    /// both 0 for an exact equilibrium.
    pub fn residual_rows(&self) -> Vec<Row> {
        let mut rows = Vec::new();
        for r in &self.residuals {
            let sub = if r.friction { "f" } else { "" };
            for (symbol, of) in [
                (
                    Symbol::EquilibriumResidual,
                    (|v: &Residuals| v.equilibrium) as fn(&Residuals) -> f64,
                ),
                (Symbol::PowerResidual, |v: &Residuals| v.power),
            ] {
                rows.push(Row {
                    scale: 1.0,
                    ..row(
                        &self.label,
                        symbol,
                        sub.to_string(),
                        Method::Polygon,
                        of(&r.polygons),
                        of(&r.twin),
                    )
                });
            }
        }
        rows
    }
}

/// One position's force analysis with friction in the pairs (`pair_friction`): the
/// polygons, the lever and the twin of the loads plus the friction loads (its
/// [`Analysis`]), settled with the friction equations solved for the friction loads (`pair_friction::settle`).
#[derive(Debug, Clone, PartialEq)]
pub struct WithFriction {
    /// The analysis with the friction loads.
    pub analysis: Analysis,
    /// The power lost in the pairs (the twin's), W, ≤ 0.
    pub lost: f64,
    /// The analyses the polygons and the twin took to settle the friction.
    pub approximations: [usize; 2],
}

/// Where a guide's reaction acts on a slider of known length (seed 001 §7.2, Fig. 28): when
/// its point falls outside the slider, the reaction is a force at the slider's centre plus a
/// couple carried by the slider's two ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliderEnds {
    /// The pair (guide → slider).
    pub pair: Pair,
    /// The reaction's magnitude, N.
    pub force: f64,
    /// Its point's offset from the slider's centre along the guide, m.
    pub offset: f64,
    /// The slider's length, m.
    pub length: f64,
}

impl SliderEnds {
    /// The point falls outside the slider.
    pub fn outside(&self) -> bool {
        self.offset.abs() > self.length / 2.0
    }
    /// The loads on the slider's two ends, N: R/2 + R·h/l and R/2 − R·h/l (a negative load
    /// presses on the guide's other face).
    pub fn ends(&self) -> [f64; 2] {
        let couple = self.force * self.offset / self.length;
        [self.force / 2.0 + couple, self.force / 2.0 - couple]
    }
}

/// The stroke at crank angle `phi` of `plan`: on the working stroke strictly between its
/// extremes, on the return strictly after, `None` at an extreme or without extremes.
pub fn phase(plan: &PositionPlan, phi: f64, sense: f64) -> Phase {
    phase_at(plan.extremes.as_ref(), phi, sense)
}

/// The stroke at crank angle `phi` given the mechanism's extremes (see [`phase`]).
pub fn phase_at(extremes: Option<&crate::linkage::Extremes>, phi: f64, sense: f64) -> Phase {
    let e = extremes?;
    let travel = (sense * (phi - e.phi_start)).rem_euclid(TAU);
    let tol = 1e-9;
    if travel > tol && travel < e.work_travel - tol {
        Some(true)
    } else if travel > e.work_travel + tol && travel < TAU - tol {
        Some(false)
    } else {
        None
    }
}

/// The motion of position `k` as its plans give it: positions off the drawing, velocities
/// off the velocity plan, accelerations off the acceleration plan read to the drafting
/// resolution, ω and ε as the plans read them.
pub fn graphical_motion(
    plan: &PositionPlan,
    k: usize,
    mu_l: Scale,
    vp: &KinPlan,
    ap: &KinPlan,
    ctx: &Context,
) -> PositionMotion {
    let b = &plan.positions[k].built;
    let mu_v = vp.figure.scale.value();
    let mu_a = ap.figure.scale.value();
    PositionMotion {
        p: b.p.iter().map(|x| *x * mu_l.value()).collect(),
        v: vp.images.iter().map(|x| *x * mu_v).collect(),
        a: ap
            .images
            .iter()
            .map(|x| x.normalize_or_zero() * ctx.drafting.read(x.length()) * mu_a)
            .collect(),
        omega: vp.rate.clone(),
        eps: ap.rate.clone(),
    }
}

/// The force analysis of position `k` of `plan` from its velocity and acceleration plans.
#[allow(clippy::too_many_arguments)]
pub fn analyse(
    spec: &ForceSpec,
    plan: &PositionPlan,
    k: usize,
    mu_l: Scale,
    vp: &KinPlan,
    ap: &KinPlan,
    w1: f64,
    ctx: &Context,
) -> Result<PositionForces, ForceError> {
    let prog = &plan.program;
    let pos = &plan.positions[k];
    let sense = w1.signum();
    let ph = phase(plan, pos.phi, sense);
    let (exact, loads_exact, twin) =
        exact::at_position(spec, prog, (&pos.label, &pos.pose), ph, w1)?;
    let m_power = twin::power_balance(&loads_exact, &exact, w1);
    let drawn = graphical_motion(plan, k, mu_l, vp, ap, ctx);
    let loads = loads::loads(spec, prog, &drawn, ph)?;
    let scale_f = polygon_scale(spec, &twin)?;
    let board = polygons::Board {
        setup: PlanSetup {
            prog,
            built: &pos.built,
            mu_l,
            w1,
            ctx: *ctx,
        },
        mu_f: scale_f,
        own: own_scales(spec, prog, (&twin, &loads_exact), scale_f),
    };
    let polygons = polygons::polygons(&board, &loads, &spec.drive)
        .map_err(|e| polygon_error(&pos.label, e))?;
    let lever = lever::lever(&board.setup, vp, &loads, &spec.drive, polygons.arms);
    let friction = match &spec.friction {
        Some(fr) => {
            let route = Route {
                board: &board,
                vp,
                pose: &pos.pose,
                drawn: &drawn,
                exact: &exact,
                loads: &loads,
                loads_exact: &loads_exact,
                label: &pos.label,
            };
            Some(Box::new(with_friction(spec, fr, &route)?))
        }
        None => None,
    };
    let analysis = Analysis {
        loads,
        loads_exact,
        polygons,
        lever,
        twin,
        m_power,
    };
    let rows = position_rows(pos, prog, &analysis, friction.as_deref());
    let built_dir: Vec<DVec2> = pos
        .built
        .angle
        .iter()
        .map(|a| DVec2::from_angle(*a))
        .collect();
    let drawn_state = residual::State {
        motion: &drawn,
        dir: &built_dir,
        w1,
        phase: ph,
    };
    let exact_state = residual::State {
        motion: &exact,
        dir: &pos.pose.dir,
        ..drawn_state
    };
    let states = [&drawn_state, &exact_state];
    let residuals = residuals(spec, plan, states, &analysis, friction.as_deref());
    let sliders = sliders(spec, &analysis.twin);
    Ok(PositionForces {
        label: pos.label.clone(),
        analysis,
        scale_f,
        sliders,
        sense,
        friction,
        rows,
        residuals,
        drawn,
        phase: ph,
    })
}

/// μ_F of the polygons: the scene's, else the largest reaction at [`POLYGON_MM`] (any
/// scale without loads: every reaction is zero).
fn polygon_scale(spec: &ForceSpec, twin: &Equilibrium) -> Result<Scale, ForceError> {
    Ok(match spec.scale_f {
        Some(s) => s,
        // Without loads every reaction is zero: any scale draws the empty polygons.
        None if twin.largest() == 0.0 => {
            Scale::new(1.0, Quantity::Force).ok_or(ForceError::NoScale(0.0))?
        }
        None => Scale::round_for(twin.largest(), POLYGON_MM, Quantity::Force)
            .ok_or(ForceError::NoScale(twin.largest()))?,
    })
}

/// Each polygon's own μ_F (by group index, then the driving link's), as the textbook
/// chooses it for each plan of forces: the round scale that draws the largest force the
/// polygon lays off or reads (the twin's, as [`polygon_scale`] sizes the position's `mu_f`)
/// about [`POLYGON_MM`] long — a group whose forces are small against the position's largest
/// is not drawn a few millimetres long, its reactions read to a resolution far coarser than
/// the course's few per cent (issue 45: R₀₋₃ of the v-engine at position 6, 1,7 mm at the
/// position's μ_F, read 11,8 % short). Empty when the scene sets μ_F: one scale for all.
fn own_scales(
    spec: &ForceSpec,
    prog: &Program,
    (twin, loads): (&Equilibrium, &[Load]),
    mu_f: Scale,
) -> Vec<Scale> {
    if spec.scale_f.is_some() {
        return Vec::new();
    }
    let largest = |links: &[usize], extra: f64| {
        let reactions = twin
            .reactions
            .iter()
            .filter(|r| links.contains(&r.pair.from) || links.contains(&r.pair.to))
            .map(|r| r.force.length());
        let loads = loads
            .iter()
            .filter(|l| links.contains(&l.link))
            .map(|l| l.force.length());
        reactions.chain(loads).fold(extra, f64::max)
    };
    let mut parts: Vec<(usize, f64)> = prog
        .groups()
        .map(|g| (g.group, largest(&g.links, 0.0)))
        .collect();
    parts.sort_by_key(|&(group, _)| group);
    let crank = prog.crank_link as usize;
    let driver = largest(&[crank], twin.f_bal.map_or(0.0, f64::abs));
    parts
        .iter()
        .map(|&(_, f)| f)
        .chain(std::iter::once(driver))
        // A polygon without forces: the position's scale.
        .map(|f| Scale::round_for(f, POLYGON_MM, Quantity::Force).unwrap_or(mu_f))
        .collect()
}

/// The position's rows: the loads, the reactions (with friction also their rows `_f`), each
/// row's reference held to the mechanism's size ([`zero_references`]).
fn position_rows(
    pos: &PlanPosition,
    prog: &Program,
    analysis: &Analysis,
    friction: Option<&WithFriction>,
) -> Vec<Row> {
    let mut rows = rows(&pos.label, &analysis.loads, &analysis.loads_exact);
    rows.extend(reaction_rows(&pos.label, "", analysis));
    if let Some(f) = friction {
        rows.extend(reaction_rows(&pos.label, "_f", &f.analysis));
    }
    let size = pos
        .pose
        .p
        .iter()
        .map(|x| x.distance(pos.pose.p[prog.centre]))
        .fold(0.0, f64::max);
    zero_references(&mut rows, size);
    rows
}

/// The equilibrium residuals of the polygons (against the drawn motion, `states[0]`) and of
/// the twin (against the exact one, `states[1]`), without and with friction in the pairs.
fn residuals(
    spec: &ForceSpec,
    plan: &PositionPlan,
    [drawn_state, exact_state]: [&residual::State<'_>; 2],
    analysis: &Analysis,
    friction: Option<&WithFriction>,
) -> Vec<Residual> {
    let (m, prog) = (&plan.mechanism, &plan.program);
    let of = |a: &Analysis, fr: Option<&pair_friction::PairFriction>| {
        let driver = &a.polygons.driver;
        let graphical = residual::Reported {
            reactions: &a.polygons.reactions(),
            m_bal: driver.m_bal,
            f_bal: driver.f_bal,
        };
        let analytic = residual::Reported {
            reactions: &a.twin.reactions,
            m_bal: a.twin.m_bal,
            f_bal: a.twin.f_bal,
        };
        Residual {
            friction: fr.is_some(),
            polygons: residual::residual(spec, m, prog, drawn_state, &graphical, fr),
            twin: residual::residual(spec, m, prog, exact_state, &analytic, fr),
        }
    };
    let mut v = vec![of(analysis, None)];
    if let (Some(w), Some(fr)) = (friction, &spec.friction) {
        v.push(of(&w.analysis, Some(fr)));
    }
    v
}

/// The guides' reactions on sliders of known length, by the twin.
fn sliders(spec: &ForceSpec, twin: &Equilibrium) -> Vec<SliderEnds> {
    twin.reactions
        .iter()
        .filter_map(|r| {
            let length = spec
                .links
                .iter()
                .find(|l| l.link as usize == r.pair.to)?
                .length?;
            let is_guide = matches!(r.pair.kind, PairKind::Prismatic { .. });
            Some(SliderEnds {
                pair: r.pair,
                force: r.force.length(),
                offset: r.offset.filter(|_| is_guide)?,
                length,
            })
        })
        .collect()
}

/// What the approximations of one position start from: the polygons' board, the velocity
/// plan, the pose, both motions and both sets of loads.
struct Route<'a> {
    board: &'a polygons::Board<'a>,
    vp: &'a KinPlan,
    pose: &'a crate::linkage::Pose,
    drawn: &'a PositionMotion,
    exact: &'a PositionMotion,
    loads: &'a [Load],
    loads_exact: &'a [Load],
    label: &'a str,
}

/// The position with friction in the pairs: the twin and the polygons each settled by
/// [`pair_friction::settle`] (to 1e-12 of the largest reaction, or to two drafting
/// resolutions on the force polygon), the lever with the polygons' friction loads.
fn with_friction(
    spec: &ForceSpec,
    fr: &pair_friction::PairFriction,
    route: &Route<'_>,
) -> Result<WithFriction, ForceError> {
    use pair_friction::{friction_loads_of, friction_power, settle, PairMotion};
    let board = route.board;
    let prog = board.setup.prog;
    let w1 = board.setup.w1;
    let sense = w1.signum();
    let pose = route.pose;
    let label = format!("{} with friction", route.label);
    let exact = PairMotion {
        prog,
        dir: pose.dir.clone(),
        origin: &pose.origin,
        motion: route.exact,
    };
    let on = |name, absolute| pair_friction::FrictionRoute {
        prog,
        label: route.label,
        name,
        f: fr.f,
        relative: 1e-12,
        absolute,
    };
    let twin = settle(
        &on("the linear solve", 0.0),
        route.loads_exact,
        |l| {
            twin::solve(prog, pose, l, &spec.drive, sense)
                .map_err(|e| located(e, &label, prog, pose))
        },
        |t| t.reactions.clone(),
        |r, m| friction_loads_of(fr, &exact, r, m),
    )?;
    let drawn = PairMotion {
        prog,
        dir: board
            .setup
            .built
            .angle
            .iter()
            .map(|a| DVec2::from_angle(*a))
            .collect(),
        origin: &board.setup.built.origin,
        motion: route.drawn,
    };
    let resolution = board.setup.ctx.drafting.resolution_mm() * board.mu_f.value();
    let polygons = settle(
        &on("the force polygons", 2.0 * resolution),
        route.loads,
        |l| polygons::polygons(board, l, &spec.drive).map_err(|e| polygon_error(&label, e)),
        Polygons::reactions,
        |r, m| friction_loads_of(fr, &drawn, r, m),
    )?;
    let all: Vec<Load> = route.loads.iter().chain(&polygons.loads).cloned().collect();
    let lever = lever::lever(
        &board.setup,
        route.vp,
        &all,
        &spec.drive,
        polygons.solution.arms,
    );
    let lost = friction_power(&twin.loads, &exact);
    Ok(WithFriction {
        analysis: Analysis {
            m_power: twin::power_balance(route.loads_exact, route.exact, w1) - lost / w1,
            loads: polygons.loads,
            loads_exact: twin.loads,
            polygons: polygons.solution,
            lever,
            twin: twin.solution,
        },
        lost,
        approximations: [polygons.solves, twin.solves],
    })
}

/// A polygon that cannot be closed at position `label` (`g` = `usize::MAX`: the driving
/// link).
fn polygon_error(label: &str, (g, error): (usize, ConstructionError)) -> ForceError {
    ForceError::Polygon {
        position: label.to_string(),
        what: if g == usize::MAX {
            "the driving link".into()
        } else {
            format!("group {}", g + 1)
        },
        error: Box::new(error),
    }
}
