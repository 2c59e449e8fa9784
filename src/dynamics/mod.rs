//! Machine dynamics: reduction of forces and masses to the crank, the work and energy
//! diagrams, the flywheel — each a construction, an analytic twin and a check.
//!
//! - `reduce`: M_пр and J_пр at a position from its velocity plan (graphical) and from the
//!   analytic twin;
//! - `draw`: the diagrams as constructions through the recorder — M_с(φ) at μ_M, A_с by
//!   graphical integration (chords, pole distance H, μ_A = μ_M·μ_φ·H), A_д from
//!   A_д(2π) = A_с(2π) (constant driving moment) and M_д read back through the pole, ΔT =
//!   A_д − A_с, J_пр(φ), the energy–mass diagram (Wittenbauer) with its tangents at ψ_max,
//!   ψ_min, and Mertsalov's route T_I = ΔT − T_II, J_I = ΔT_I/(δ·ω_ср²) (the seed's);
//! - `twin`: the work integrated exactly and the equation of motion in energy form solved
//!   for the flywheel that gives δ, with ω(φ), ε(φ) and the cycle time;
//! - `flywheel`: the rim's or disc's size from its moment of inertia — the one the sheet's
//!   construction gives (Wittenbauer's tangents), as a hand-in sizes it; the twin sizes its
//!   own from the exact inertia;
//! - `part`: the flywheel as a part drawing, every dimension from its size;
//! - `phi_numbers`: the tabled positions' numbers on the diagrams' φ axes;
//! - rows `M_red`, `J_red`, `dT` per position; `A_res`, `M_drive`, `J_flywheel`, `delta`,
//!   and the flywheel's `h_flywheel` (D) and `m_flywheel` of the whole scene.

mod draw;
#[cfg(test)]
mod engine_tests;
mod flywheel;
mod keyway;
mod part;
mod phi_numbers;
mod reduce;
mod roughness;
mod rows;
mod scales;
mod spec;
#[cfg(test)]
mod tests;
mod twin;
mod work;

pub use draw::diagrams;
pub use flywheel::{diameter_step, Size};
pub use keyway::Keyway;
pub use part::PART_MM;
pub use reduce::{Breakdown, LinkShare, LoadShare, ReducedPosition, Reducer};
pub use rows::{findings, noted, rows};
pub use spec::{
    ConstantInertia, ConstantMoment, DynamicsSpec, FlywheelKind, FlywheelSpec, SeedClaims,
};
pub use twin::{Cycle, Solution, PANELS};

use crate::calculus::CalculusError;
use crate::construct::Context;
use crate::forces::{ForceError, ForceSpec};
use crate::linkage::{KinPlan, PositionPlan};
use crate::scale::residue_to_zero;
use std::f64::consts::TAU;
use thiserror::Error;

/// Why the dynamic study cannot be carried out.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DynamicsError {
    /// A link of `dynamics.links` has no mass in `[forces]`.
    #[error("dynamics.links: link {link} has no [[forces.link]] with its mass")]
    NoLinkMass {
        /// The link.
        link: u32,
    },
    /// The loads cannot be formed.
    #[error(transparent)]
    Forces(#[from] ForceError),
    /// The mechanism cannot be assembled at a crank angle of the cycle.
    #[error("the mechanism cannot be assembled at φ₁ = {phi_deg:.3}°: {detail}")]
    Unassembled {
        /// The crank angle, degrees.
        phi_deg: f64,
        /// Why.
        detail: String,
    },
    /// The resistances do no work over the cycle: no driving moment to find.
    #[error("the working resistances do {} J of work over the cycle: expected > 0 (a [[forces.resistance]] that acts; an engine, whose gas forces drive, takes [dynamics] constant_moment = \"resisting\")", crate::scale::format_plain(*work))]
    NoResistance {
        /// The work, J.
        work: f64,
    },
    /// The driving forces do no work over the cycle (`constant_moment = "resisting"`).
    #[error("the driving forces do {} J of work over the cycle: expected > 0 (a [[forces.indicator]] that acts)", crate::scale::format_plain(*work))]
    NoDriving {
        /// The work, J.
        work: f64,
    },
    /// No flywheel gives δ.
    #[error("dynamics.delta: no flywheel up to 1e12 kg·m² gives δ = {delta}", delta = crate::scale::format_plain(*delta))]
    NoFlywheel {
        /// The δ asked for.
        delta: f64,
    },
    /// A position has no velocity plan.
    #[error("position {position}: no velocity plan for the reduction: {why}")]
    NoPlan {
        /// The position.
        position: String,
        /// Why.
        why: String,
    },
    /// A diagram cannot be constructed.
    #[error("{what}: {error}")]
    Diagram {
        /// Which diagram.
        what: &'static str,
        /// Why.
        error: CalculusError,
    },
    /// A scale the scene gives draws its diagram too small or too large to be drawn.
    #[error("{key} = {}: draws the diagram's largest value {} as {} mm: expected {} … {} mm, a scale from {} to {}", crate::scale::format_plain(*scale), crate::scale::format_plain(*value), crate::scale::format_plain(*drawn_mm), crate::scale::format_plain(crate::scale::DRAWN_MM.0), crate::scale::format_plain(crate::scale::DRAWN_MM.1), crate::scale::format_plain(range.0), crate::scale::format_plain(range.1))]
    Drawn {
        /// The scene key.
        key: &'static str,
        /// The scale given.
        scale: f64,
        /// The diagram's largest value, SI.
        value: f64,
        /// Its drawn length, mm.
        drawn_mm: f64,
        /// The scales that draw it within range.
        range: (f64, f64),
    },
    /// A scale cannot be chosen.
    #[error("no scale can be chosen for {what} ({value})", value = crate::scale::format_plain(*value))]
    NoScale {
        /// What.
        what: &'static str,
        /// The value to draw.
        value: f64,
    },
}

/// The dynamic study of a scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Dynamics {
    /// The section.
    pub spec: DynamicsSpec,
    /// ω_ср, rad/s.
    pub w_avg: f64,
    /// The positions' labels.
    pub labels: Vec<String>,
    /// Every how many positions one is tabled ([`Dynamics::tabled`]).
    pub step: usize,
    /// The positions' travel from position 1, rad.
    pub travel: Vec<f64>,
    /// The reduction from the velocity plans.
    pub graphical: Vec<ReducedPosition>,
    /// The reduction by the analytic twin at the same positions.
    pub analytic: Vec<ReducedPosition>,
    /// The reduction from the velocity plans load by load and link by link.
    pub graphical_shares: Vec<Breakdown>,
    /// The analytic twin's, load by load and link by link (the seed's Table 8).
    pub analytic_shares: Vec<Breakdown>,
    /// The cycle, exactly.
    pub cycle: Cycle,
    /// The flywheel by the energy equation, exactly.
    pub exact: Solution,
    /// The cycle time with that flywheel, s.
    pub cycle_time: f64,
    /// The diagrams as constructed.
    pub diagrams: draw::DynamicsDiagrams,
    /// The δ each textbook route's flywheel really gives (Wittenbauer, Mertsalov).
    pub delta_of: [f64; 2],
    /// The flywheel's size from the inertia the sheet's construction gives (Wittenbauer's
    /// tangents): the flywheel a hand-in sizes and draws.
    pub size: flywheel::Size,
    /// The twin's flywheel: its size from the exact inertia.
    pub exact_size: flywheel::Size,
    /// The flywheel made from [`Self::size`], its diameter rounded up: the part drawn.
    pub made: flywheel::Size,
    /// The δ the flywheel made gives.
    pub delta_made: f64,
    /// ω(φ) with the flywheel.
    pub omega: crate::construct::Figure,
    /// The flywheel's part drawing ([`Self::made`]) at its round scale, then at the next
    /// coarser one ([`part::drawings`]); one empty figure when none is needed.
    pub wheels: Vec<crate::construct::Figure>,
    /// The roughness of the part's surfaces its drawing does not mark, for the sheet's top
    /// right corner ([`part::other_surfaces`]).
    pub other_surfaces: crate::construct::Figure,
}

impl Dynamics {
    /// The positions the tables give (index, label): every one, or the plans' among the
    /// diagrams' intermediate points ([`Self::table_every`]).
    pub fn tabled(&self) -> impl Iterator<Item = (usize, &String)> {
        self.labels.iter().enumerate().step_by(self.step.max(1))
    }

    /// Table the plans' positions `names` at every `step`-th position of the diagrams; those
    /// between are the diagrams' intermediate points, named by the two they stand between
    /// ("1–2"). Nothing changes unless there are `step` positions to each name.
    pub fn table_every(&mut self, step: usize, names: &[String]) {
        if step == 0 || names.len() * step != self.labels.len() {
            return;
        }
        for (k, label) in self.labels.iter_mut().enumerate() {
            let i = k / step;
            *label = if k % step == 0 {
                names[i].clone()
            } else {
                format!("{}–{}", names[i], names[(i + 1) % names.len()])
            };
        }
        self.step = step;
    }

    /// Number the φ axes of A (M_с's positions too), ΔT, J_пр, T_I and ω at the positions the
    /// tables give ([`Self::tabled`]), once their names are known.
    pub fn number_axes(&mut self, ctx: &Context) {
        let n = self.labels.len().max(1) as f64;
        let run = self.diagrams.scale_phi.to_mm(TAU / n);
        let marks: Vec<(f64, String)> = self
            .tabled()
            .map(|(i, label)| (run * i as f64, label.clone()))
            .collect();
        let d = &mut self.diagrams;
        for f in [
            &mut d.work,
            &mut d.energy,
            &mut d.inertia,
            &mut d.mertsalov_figure,
            &mut self.omega,
        ] {
            *f = phi_numbers::number(f.clone(), ctx, &marks);
        }
    }
}

/// Carry out the dynamic study over the numbered, equally spaced positions of `plan` with
/// their velocity plans `vps` (graphical) and the analytic twin.
///
/// # Errors
/// See [`DynamicsError`].
pub fn analyse(
    spec: &DynamicsSpec,
    forces: &ForceSpec,
    plan: &PositionPlan,
    vps: &[Option<&KinPlan>],
    w1: f64,
    ctx: &Context,
) -> Result<Dynamics, DynamicsError> {
    let mu_l = plan.figure.scale.value();
    let numbered = crate::kinematics::numbered(plan);
    let start = numbered.first().map_or(0.0, |(_, p)| p.phi);
    let red = Reducer::new(
        &plan.program,
        forces,
        spec.links.as_deref(),
        plan.extremes.clone(),
        (start, w1),
        spec.constant_inertia(),
    )?;
    let w_avg = spec.omega_avg.unwrap_or(w1.abs());
    let (mut labels, mut travel, mut graphical, mut analytic) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let (mut graphical_shares, mut analytic_shares) = (Vec::new(), Vec::new());
    for (k, pos) in &numbered {
        let vp = vps
            .get(*k)
            .copied()
            .flatten()
            .ok_or_else(|| DynamicsError::NoPlan {
                position: pos.label.clone(),
                why: "refused (a group at its toggle)".into(),
            })?;
        let motion = Reducer::plan_motion(vp, &pos.built.p, mu_l, ctx);
        let shares = red.breakdown(&motion, pos.phi)?;
        graphical.push(shares.reduced());
        graphical_shares.push(shares);
        let t = (red.sense() * (pos.phi - start)).rem_euclid(TAU);
        analytic.push(red.exact(t)?.0);
        let (pose, twin) = red.twin_motion(t)?;
        analytic_shares.push(red.breakdown(&twin, pose.phi)?);
        labels.push(pos.label.clone());
        travel.push(t);
    }
    let cycle = Cycle::new(&red, twin::PANELS)?;
    // The constant moment opposes the varying side: driving (> 0) or resisting (< 0).
    // The size of the cycle's works: a sum far below it is a rounding residue, printed as 0.
    // A residue of either sign is no work: no constant moment to find.
    let size = cycle
        .work
        .iter()
        .fold(cycle.a_res.max(cycle.a_drive), |m, w| m.max(w.abs()));
    let work = residue_to_zero(cycle.m_drive * TAU, size);
    match spec.constant_moment {
        ConstantMoment::Driving if work <= 0.0 => return Err(DynamicsError::NoResistance { work }),
        ConstantMoment::Resisting if work >= 0.0 => {
            return Err(DynamicsError::NoDriving { work: -work })
        }
        _ => {}
    }
    let exact = cycle.flywheel(w_avg, spec.delta)?;
    let cycle_time = cycle.cycle_time(exact.j_fw, exact.t0);
    let diagrams = draw::diagrams(spec, &graphical, w_avg, ctx)?;
    let delta_of = [diagrams.wittenbauer.j_fw, diagrams.mertsalov.j_fw]
        .map(|j| cycle.with_flywheel(j.max(0.0), w_avg).delta());
    // The flywheel as the sheet's construction finds it; the twin's from the exact inertia.
    let size = flywheel::size(&spec.flywheel, diagrams.wittenbauer.j_fw);
    let exact_size = flywheel::size(&spec.flywheel, exact.j_fw);
    let made = flywheel::made(&spec.flywheel, size.j);
    let delta_made = cycle.with_flywheel(made.j, w_avg).delta();
    let omega = draw::omega_figure(&cycle, &exact, diagrams.scale_phi, ctx)?;
    let wheels = part::drawings(&made, ctx)?;
    let other_surfaces = part::other_surfaces(ctx)?;
    Ok(Dynamics {
        spec: spec.clone(),
        w_avg,
        labels,
        step: 1,
        travel,
        graphical,
        analytic,
        graphical_shares,
        analytic_shares,
        cycle,
        exact,
        cycle_time,
        diagrams,
        delta_of,
        size,
        exact_size,
        made,
        delta_made,
        omega,
        wheels,
        other_surfaces,
    })
}
