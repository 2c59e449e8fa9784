//! Force analysis: kinetostatics of Assur groups by force polygons, the driving link,
//! Zhukovsky's lever, friction and rotor balancing — each a construction, an analytic twin
//! and a check.
//!
//! One position's force analysis ([`analyse`]) gives:
//! - the loads ([`loads`]) from the acceleration plan (graphical) and from the analytic twin;
//! - the force polygons of every group and the driving link ([`polygons`]);
//! - Zhukovsky's lever ([`lever`]) from the velocity plan;
//! - the analytic twin ([`twin`]): one linear solve of every link's equilibrium, and the
//!   balancing moment again from the power balance;
//! - rows `R_<i>_<j>`, `h_<i>_<j>` (a guide reaction's point), `M_bal`, `F_bal` and the
//!   inertia loads `F_in<l>`, `M_in<l>`, graphical against analytic.

pub mod balancing;
pub mod friction;
pub mod lever;
pub mod loads;
pub mod polygons;
mod spec;
#[cfg(test)]
mod tests;
pub mod twin;

pub use spec::{Action, Drive, ForceSpec, GearDrive, LinkMass, Resistance, Stroke, G_STANDARD};

pub use loads::{Load, LoadKind, Motion, Phase};
pub use polygons::{DriverPolygon, GroupPolygon, Polygons};
pub use twin::{Equilibrium, Pair, PairKind, Reaction};

use crate::check::{Key, Method, Row, Symbol};
use crate::construct::{ConstructionError, Context};
use crate::linkage::{KinPlan, PositionPlan};
use crate::scale::{Quantity, Scale};
use std::f64::consts::TAU;
use thiserror::Error;

/// Preferred length of the largest force on a polygon, mm.
pub const POLYGON_MM: f64 = 100.0;

/// Why a force analysis cannot be carried out.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ForceError {
    /// A point named in `[forces]` is not a point of the mechanism.
    #[error("forces.{key}: there is no point `{name}`")]
    NoPoint {
        /// The key.
        key: &'static str,
        /// The name.
        name: String,
    },
    /// A centre of mass that is not on its link.
    #[error("forces.link: the centre of mass `{name}` is not a point of link {link}")]
    NotOnLink {
        /// The point.
        name: String,
        /// The link.
        link: usize,
    },
    /// The equilibrium equations do not match the unknowns (a group that is not a dyad).
    #[error(
        "the mechanism is not statically determinate: {equations} equations, {unknowns} unknowns"
    )]
    NotDeterminate {
        /// 3 × moving links.
        equations: usize,
        /// 2 × pairs + 1.
        unknowns: usize,
    },
    /// The equilibrium equations are singular (a group at its toggle position).
    #[error("the equilibrium equations are singular at this position (a group at a toggle or dead position)")]
    Singular,
    /// A polygon cannot be closed.
    #[error("position {position}: {what}: {error}")]
    Polygon {
        /// The position.
        position: String,
        /// The group or the driving link.
        what: String,
        /// The construction's diagnosis.
        error: Box<ConstructionError>,
    },
    /// A position to analyse that the plan does not have.
    #[error("forces.positions: there is no position {label}; the positions are {valid}")]
    NoSuchPosition {
        /// The label asked for.
        label: String,
        /// The plan's labels, compactly.
        valid: String,
    },
    /// No round μ_F can be formed.
    #[error("no force scale μ_F can be chosen for {0} N")]
    NoScale(f64),
}

/// One position's force analysis.
#[derive(Debug, Clone, PartialEq)]
pub struct PositionForces {
    /// The position's label.
    pub label: String,
    /// The loads as the plans give them.
    pub loads: Vec<Load>,
    /// The loads as the analytic twin gives them.
    pub loads_exact: Vec<Load>,
    /// The polygons.
    pub polygons: Polygons,
    /// Zhukovsky's lever.
    pub lever: lever::Lever,
    /// The analytic twin.
    pub twin: Equilibrium,
    /// The balancing moment from the power balance, N·m.
    pub m_power: f64,
    /// μ_F of the polygons.
    pub scale_f: Scale,
    /// The guides' reactions on sliders of known length, by the twin.
    pub sliders: Vec<SliderEnds>,
    /// The rows.
    pub rows: Vec<Row>,
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
) -> Motion {
    let b = &plan.positions[k].built;
    let mu_v = vp.figure.scale.value();
    let mu_a = ap.figure.scale.value();
    Motion {
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
    let exact = Motion::analytic(&pos.pose, w1);
    let loads_exact = loads::loads(spec, prog, &exact, ph)?;
    let twin = twin::solve(prog, &pos.pose, &loads_exact, &spec.drive, sense)?;
    let m_power = twin::power_balance(&loads_exact, &exact, w1);
    let drawn = graphical_motion(plan, k, mu_l, vp, ap, ctx);
    let loads = loads::loads(spec, prog, &drawn, ph)?;
    let scale_f = match spec.scale_f {
        Some(s) => s,
        None => {
            let big = twin
                .reactions
                .iter()
                .map(|r| r.force.length())
                .fold(0.0, f64::max);
            Scale::round_for(big, POLYGON_MM, Quantity::Force).ok_or(ForceError::NoScale(big))?
        }
    };
    let board = polygons::Board {
        prog,
        built: &pos.built,
        mu_l,
        mu_f: scale_f,
        ctx: *ctx,
        sense,
    };
    let polygons = polygons::polygons(&board, &loads, &spec.drive).map_err(|(g, error)| {
        ForceError::Polygon {
            position: pos.label.clone(),
            what: if g == usize::MAX {
                "the driving link".into()
            } else {
                format!("group {}", g + 1)
            },
            error: Box::new(error),
        }
    })?;
    let lever = lever::lever(prog, &pos.built, mu_l, vp, &loads, &spec.drive, w1, ctx);
    let rows = rows(&pos.label, &polygons, &lever, &twin, &loads, &loads_exact);
    let sliders = twin
        .reactions
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
        .collect();
    Ok(PositionForces {
        label: pos.label.clone(),
        loads,
        loads_exact,
        polygons,
        lever,
        twin,
        m_power,
        scale_f,
        sliders,
        rows,
    })
}

/// The rows of one position: inertia loads (read off the acceleration plan), reactions and
/// their points (polygons), the balancing moment and force (polygons and lever).
fn rows(
    label: &str,
    polygons: &Polygons,
    lever: &lever::Lever,
    twin: &Equilibrium,
    loads: &[Load],
    exact: &[Load],
) -> Vec<Row> {
    let mut rows = Vec::new();
    let mut push = |symbol: Symbol, subject: String, method: Method, g: f64, a: f64| {
        rows.push(Row {
            key: Key::at_position(symbol, subject, label),
            method,
            graphical: g,
            analytic: a,
            conditioning: None,
            scale: a.abs(),
        });
    };
    for e in exact
        .iter()
        .filter(|l| matches!(l.kind, LoadKind::Inertia | LoadKind::InertiaMoment))
    {
        let g = loads.iter().find(|l| l.kind == e.kind && l.link == e.link);
        let (g_f, g_m) = g.map_or((0.0, 0.0), |g| (g.force.length(), g.moment));
        match e.kind {
            LoadKind::Inertia => push(
                Symbol::Force,
                format!("in{}", e.link),
                Method::Plan,
                g_f,
                e.force.length(),
            ),
            _ => push(
                Symbol::Moment,
                format!("in{}", e.link),
                Method::Plan,
                g_m,
                e.moment,
            ),
        }
    }
    let graphical: Vec<&Reaction> = polygons
        .groups
        .iter()
        .rev()
        .flat_map(|g| g.reactions.iter())
        .chain(std::iter::once(&polygons.driver.reaction))
        .collect();
    for r in &twin.reactions {
        let Some(g) = graphical
            .iter()
            .find(|g| g.pair.from == r.pair.from && g.pair.to == r.pair.to)
        else {
            continue;
        };
        let subject = format!("{}_{}", r.pair.from, r.pair.to);
        push(
            Symbol::Reaction,
            subject.clone(),
            Method::Polygon,
            g.force.length(),
            r.force.length(),
        );
        if let (Some(gs), Some(s)) = (g.offset, r.offset) {
            push(Symbol::Length, subject, Method::Polygon, gs, s);
        }
    }
    push(
        Symbol::Moment,
        "bal".into(),
        Method::Polygon,
        polygons.driver.m_bal,
        twin.m_bal,
    );
    push(
        Symbol::Moment,
        "bal".into(),
        Method::Lever,
        lever.m_bal,
        twin.m_bal,
    );
    if let Some(f) = twin.f_bal {
        push(
            Symbol::Force,
            "bal".into(),
            Method::Polygon,
            polygons.driver.f_bal.unwrap_or(f64::NAN),
            f,
        );
        push(
            Symbol::Force,
            "bal".into(),
            Method::Lever,
            lever.f_bal.unwrap_or(f64::NAN),
            f,
        );
    }
    // A value's zero reference is the largest of its kind at the position (a guide
    // reaction's point on its reference point is zero against the other points).
    let largest = |s: Symbol, rows: &[Row]| {
        rows.iter()
            .filter(|r| r.key.symbol == s && r.analytic.is_finite())
            .fold(0.0f64, |m, r| m.max(r.analytic.abs()))
    };
    let scales: Vec<f64> = rows.iter().map(|r| largest(r.key.symbol, &rows)).collect();
    for (r, s) in rows.iter_mut().zip(scales) {
        r.scale = s;
    }
    rows
}

/// The notes of one position for the report: the polygon against the lever (the seed's
/// «погрешность»), and every slider whose guide reaction falls outside it.
pub fn notes(f: &PositionForces) -> Vec<String> {
    use crate::scale::{format_sig, Lang};
    let n = |x: f64| format_sig(x, 6, Lang::En);
    let (p, l) = (f.polygons.driver.m_bal, f.lever.m_bal);
    let mut out = vec![format!(
        "position {}: M_bal by the force polygons {} N·m, by Zhukovsky's lever {} N·m: they differ by {} % of the polygons' value",
        f.label,
        n(p),
        n(l),
        format_sig(if p != 0.0 { (p - l).abs() / p.abs() * 100.0 } else { 0.0 }, 3, Lang::En),
    )];
    for s in f.sliders.iter().filter(|s| s.outside()) {
        let [a, b] = s.ends();
        out.push(format!(
            "position {}: the reaction R_{}_{} = {} N acts {} m from the slider's centre, outside the slider (length {} m): a force at the centre and a couple on the ends, which carry {} N and {} N",
            f.label, s.pair.from, s.pair.to, n(s.force), n(s.offset), n(s.length), n(a), n(b)
        ));
    }
    out
}
