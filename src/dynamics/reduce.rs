//! Reduction to the crank: the reduced moment of the forces M_пр = Σ(F·v + M·ω)/|ω₁| (the
//! power balance, the same number Zhukovsky's lever gives) and the reduced moment of inertia
//! J_пр = J_const + Σ(m·v_S² + J_S·ω²)/ω₁², from the motion of a position as one route knows
//! it (a velocity plan, or the analytic twin).
//!
//! Sign convention: M_пр is positive when it drives the crank in its sense of rotation (a
//! resisting moment is negative); the force analysis' balancing moment M_у (counter-clockwise)
//! satisfies M_у·sign(ω₁) = −M_пр of the same loads.

use super::DynamicsError;
use crate::construct::Context;
use crate::forces::{loads, power_balance, Load, LoadKind, PositionMotion};
use crate::forces::{phase_at, ForceSpec};
use crate::geom::DVec2;
use crate::linkage::{Extremes, KinPlan, Pose, Program};

/// The reduced quantities of one position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReducedPosition {
    /// The reduced moment of the working resistances, N·m (driving positive).
    pub m_res: f64,
    /// The reduced moment of the weights, N·m.
    pub m_grav: f64,
    /// The reduced moment of the driving forces (indicator diagrams), N·m.
    pub m_drv: f64,
    /// The reduced moment of inertia, constant part included, kg·m².
    pub j: f64,
}

impl ReducedPosition {
    /// The reduced moment of every force, N·m.
    pub fn m(&self) -> f64 {
        self.m_res + self.m_grav + self.m_drv
    }
}

/// One load's share of the reduced moment at a position (the seed's Table 8 and 9: the
/// force, the speed of its point, the angle between them).
#[derive(Debug, Clone, PartialEq)]
pub struct LoadShare {
    /// Its label (markup): `F_{пс}`, `G_{3}`.
    pub name: String,
    /// What it is.
    pub kind: LoadKind,
    /// |F|, N, or the couple's |M|, N·m.
    pub magnitude: f64,
    /// The speed of its point, m/s, or its link's |ω|, rad/s, for a couple.
    pub speed: f64,
    /// The angle from the force to its point's velocity, rad in [0, π] (`None`: a couple, or
    /// a point at rest).
    pub angle: Option<f64>,
    /// Its reduced moment F·v·cos α/|ω₁| (M·ω/|ω₁|), N·m (driving positive).
    pub m_red: f64,
}

/// One link's share of the reduced moment of inertia: m·v_S²/ω₁² + J_S·ω²/ω₁² (the seed's
/// Table 10 by links).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkShare {
    /// The link.
    pub link: u32,
    /// Its mass, kg.
    pub mass: f64,
    /// The speed of its centre of mass, m/s.
    pub v_s: f64,
    /// Its moment of inertia about the centre of mass, kg·m².
    pub inertia: f64,
    /// Its angular velocity, rad/s (counter-clockwise).
    pub omega: f64,
    /// Its reduced moment of inertia, kg·m².
    pub j_red: f64,
}

/// The reduction of one position load by load and link by link.
#[derive(Debug, Clone, PartialEq)]
pub struct Breakdown {
    /// The loads of the links that count (weights, resistances, driving forces).
    pub loads: Vec<LoadShare>,
    /// The links' reduced inertias.
    pub links: Vec<LinkShare>,
    /// The constant reduced inertias (the reducer, the gearbox), kg·m².
    pub j_const: f64,
}

impl Breakdown {
    /// The sums: the reduced moments by kind and the reduced moment of inertia.
    pub fn reduced(&self) -> ReducedPosition {
        let of = |kind: LoadKind| {
            self.loads
                .iter()
                .filter(|l| l.kind == kind)
                .map(|l| l.m_red)
                .sum()
        };
        ReducedPosition {
            m_res: of(LoadKind::Resistance),
            m_grav: of(LoadKind::Weight),
            m_drv: of(LoadKind::Driving),
            j: self.j_const + self.links.iter().map(|l| l.j_red).sum::<f64>(),
        }
    }
}

/// The reduced moment of `loads` moving as `motion` with the crank at |ω₁| = `w`:
/// Σ(F·v + M·ω)/|ω₁|, N·m (driving positive).
pub fn reduce_loads(loads: &[Load], motion: &PositionMotion, w: f64) -> f64 {
    // The power balance's M_bal at a crank turning counter-clockwise at w, with its sign
    // turned: the moment the loads exert.
    -power_balance(loads, motion, w)
}

/// What the reduction needs: the mechanism, the loads of the links that count, the strokes.
#[derive(Debug, Clone)]
pub struct Reducer<'a> {
    /// The compiled mechanism.
    pub prog: &'a Program,
    /// The `[forces]` loads restricted to the links that count.
    pub forces: ForceSpec,
    /// The extreme positions (where the strokes change).
    pub extremes: Option<Extremes>,
    /// Crank angle of position 1 (travel 0), radians.
    pub start: f64,
    /// ω₁, rad/s, signed counter-clockwise.
    pub w1: f64,
    /// The constant reduced inertias, kg·m².
    pub j_const: f64,
}

impl<'a> Reducer<'a> {
    /// The reducer of `forces` restricted to `links` (every link when `None`).
    ///
    /// # Errors
    /// A link named in `links` without a mass in `[forces]`.
    pub fn new(
        prog: &'a Program,
        forces: &ForceSpec,
        links: Option<&[u32]>,
        extremes: Option<Extremes>,
        (start, w1): (f64, f64),
        j_const: f64,
    ) -> Result<Self, DynamicsError> {
        let mut f = forces.clone();
        if let Some(ls) = links {
            if let Some(&l) = ls
                .iter()
                .find(|l| !forces.links.iter().any(|m| m.link == **l))
            {
                return Err(DynamicsError::NoLinkMass { link: l });
            }
            f.links.retain(|m| ls.contains(&m.link));
        }
        Ok(Self {
            prog,
            forces: f,
            extremes,
            start,
            w1,
            j_const,
        })
    }

    /// The sense of rotation, ±1.
    pub fn sense(&self) -> f64 {
        if self.w1 < 0.0 {
            -1.0
        } else {
            1.0
        }
    }

    /// The crank angle at `travel` (radians turned from position 1 in the sense of rotation).
    pub fn phi(&self, travel: f64) -> f64 {
        self.start + self.sense() * travel
    }

    /// The reduced moments and inertia of `motion` at crank angle `phi`.
    ///
    /// # Errors
    /// A load's point that is not a point of the mechanism.
    pub fn at(&self, motion: &PositionMotion, phi: f64) -> Result<ReducedPosition, DynamicsError> {
        Ok(self.breakdown(motion, phi)?.reduced())
    }

    /// The reduction of `motion` at crank angle `phi` load by load and link by link.
    ///
    /// # Errors
    /// A load's point that is not a point of the mechanism.
    pub fn breakdown(&self, motion: &PositionMotion, phi: f64) -> Result<Breakdown, DynamicsError> {
        let ph = phase_at(self.extremes.as_ref(), phi, self.sense());
        let all = loads(&self.forces, self.prog, motion, ph)?;
        let w = self.w1.abs();
        let counted = [LoadKind::Resistance, LoadKind::Weight, LoadKind::Driving];
        let loads = all
            .iter()
            .filter(|l| counted.contains(&l.kind))
            .map(|l| {
                let v = motion.v.get(l.at).copied().unwrap_or(DVec2::ZERO);
                let om = motion.omega.get(l.link).copied().unwrap_or(0.0);
                let couple = l.force == DVec2::ZERO && l.moment != 0.0;
                LoadShare {
                    name: l.name.clone(),
                    kind: l.kind,
                    magnitude: if couple {
                        l.moment.abs()
                    } else {
                        l.force.length()
                    },
                    speed: if couple { om.abs() } else { v.length() },
                    angle: (!couple && v != DVec2::ZERO && l.force != DVec2::ZERO)
                        .then(|| l.force.angle_to(v).abs()),
                    m_red: reduce_loads(std::slice::from_ref(l), motion, w),
                }
            })
            .collect();
        let links = self
            .forces
            .links
            .iter()
            .map(|lm| {
                let s = self.prog.index(&lm.centre).unwrap_or(0);
                let v = motion.v.get(s).copied().unwrap_or(DVec2::ZERO);
                let om = motion.omega.get(lm.link as usize).copied().unwrap_or(0.0);
                LinkShare {
                    link: lm.link,
                    mass: lm.mass,
                    v_s: v.length(),
                    inertia: lm.inertia,
                    omega: om,
                    j_red: (lm.mass * v.length_squared() + lm.inertia * om * om) / (w * w),
                }
            })
            .collect();
        Ok(Breakdown {
            loads,
            links,
            j_const: self.j_const,
        })
    }

    /// The analytic twin's pose at `travel`.
    ///
    /// # Errors
    /// The mechanism cannot be assembled there.
    pub fn pose(&self, travel: f64) -> Result<Pose, DynamicsError> {
        let phi = self.phi(travel);
        self.prog
            .solve(phi, None)
            .map_err(|u| DynamicsError::Unassembled {
                phi_deg: phi.to_degrees(),
                detail: u.detail,
            })
    }

    /// The analytic twin's pose and motion at `travel` (no accelerations: the reduction
    /// needs none).
    ///
    /// # Errors
    /// The mechanism cannot be assembled there.
    pub fn twin_motion(&self, travel: f64) -> Result<(Pose, PositionMotion), DynamicsError> {
        let pose = self.pose(travel)?;
        let motion = PositionMotion {
            a: vec![DVec2::ZERO; pose.p.len()],
            eps: vec![0.0; pose.dangle.len()],
            ..PositionMotion::analytic(&pose, self.w1)
        };
        Ok((pose, motion))
    }

    /// The analytic twin at `travel`: the reduced quantities and dJ/dψ (ψ the travel).
    ///
    /// # Errors
    /// The mechanism cannot be assembled, or a load's point is unknown.
    pub fn exact(&self, travel: f64) -> Result<(ReducedPosition, f64), DynamicsError> {
        let (pose, motion) = self.twin_motion(travel)?;
        let r = self.at(&motion, pose.phi)?;
        let mut dj = 0.0;
        for lm in &self.forces.links {
            let s = self.prog.index(&lm.centre).unwrap_or(0);
            let l = lm.link as usize;
            let (dp, ddp) = (pose.dp[s], pose.ddp[s]);
            let (da, dda) = (
                pose.dangle.get(l).copied().unwrap_or(0.0),
                pose.ddangle.get(l).copied().unwrap_or(0.0),
            );
            dj += 2.0 * (lm.mass * dp.dot(ddp) + lm.inertia * da * dda);
        }
        Ok((r, self.sense() * dj))
    }

    /// The motion of a position as its velocity plan gives it: velocities off the plan at
    /// μ_v, the links' ω as the plan reads them (no accelerations: the reduction needs none).
    /// Every velocity is read to the drafting resolution of `ctx`.
    pub fn plan_motion(
        vp: &KinPlan,
        built_p: &[DVec2],
        mu_l: f64,
        ctx: &Context,
    ) -> PositionMotion {
        let mu_v = vp.figure.scale.value();
        PositionMotion {
            p: built_p.iter().map(|x| *x * mu_l).collect(),
            v: vp
                .images
                .iter()
                .map(|x| x.normalize_or_zero() * ctx.drafting.read(x.length()) * mu_v)
                .collect(),
            a: vec![DVec2::ZERO; vp.images.len()],
            omega: vp.rate.clone(),
            eps: vec![0.0; vp.rate.len()],
        }
    }
}
