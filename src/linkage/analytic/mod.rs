//! The analytic twin: closed-form positions of every dyad kind with their first and second
//! derivatives with respect to the crank angle (velocity and acceleration analogues dX/dφ₁,
//! d²X/dφ₁²), by differentiating the vector loops — no numerical differentiation. With a
//! constant ω₁ the velocities are ω₁·dX/dφ₁ and the accelerations ω₁²·d²X/dφ₁².
//! Shares nothing with the construction but the program's index tables. Here: the run over
//! the program, the solve's state and the jets; each group kind's closed form is its own
//! (`GroupKind::solve`, in its file of `kinds/`).

use super::program::{Op, PDir, PGuide, Program};
use crate::geom::DVec2;
use jet::{carried, heading, sub, unit, AngleJet, Jet, LineJet};

pub(in crate::linkage) mod jet;

/// A solved position with its velocity and acceleration analogues.
///
/// It mirrors the construction's [`Built`](super::Built) field for field on purpose (φ₁, the
/// points, the links' frames, the crossings): the twin and the drawing answer the same
/// questions so that every reading can be set against its analytic value.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Pose {
    /// Crank angle φ₁, radians.
    pub phi: f64,
    /// Point positions by program index, m.
    pub p: Vec<DVec2>,
    /// dp/dφ₁, m/rad.
    pub dp: Vec<DVec2>,
    /// d²p/dφ₁², m/rad².
    pub ddp: Vec<DVec2>,
    /// dθ/dφ₁ by link number.
    pub dangle: Vec<f64>,
    /// d²θ/dφ₁² by link number.
    pub ddangle: Vec<f64>,
    /// The unit vector (cos θ, sin θ) of each link's frame angle, by link number.
    pub dir: Vec<DVec2>,
    /// Link frame origin (point index) by link number.
    pub origin: Vec<usize>,
    /// Per group: the sine of the acute crossing angle of its construction (small =
    /// ill-conditioned; 0 at a tangency).
    pub crossing_sin: Vec<f64>,
    /// A dyad at its toggle (folded) position: the position exists but its analogues are not
    /// determined; `dp`, `ddp` and the angle rates downstream of it are not meaningful.
    pub toggle: Option<Unassembled>,
    /// Slotted links whose pin passes close to their pivot here: true, ill-conditioned rates.
    pub near_pivot: Vec<NearPivot>,
}

/// |dCB/dφ₁| / |CB| above which a slotted link's pin counts as passing close to its pivot:
/// the link turns over a thousand times faster than the crank.
pub const NEAR_PIVOT_RATIO: f64 = 1e3;

/// A slotted link (RPR without offset) whose pin `a` passes close to its pivot `c`: the slot
/// turns at about |w′|/|w| times the crank's rate (w = a − c), a true value that a change of
/// |w| in a length of the mechanism changes by ~100 %.
#[derive(Debug, Clone, PartialEq)]
pub struct NearPivot {
    /// Group index (file order).
    pub group: usize,
    /// The slotted link's number.
    pub link: usize,
    /// The pin's point index.
    pub pin: usize,
    /// The pivot's point index.
    pub pivot: usize,
    /// |w|: the pin's distance from the pivot, m.
    pub distance: f64,
    /// |w′| = |d(a − c)/dφ₁|, m/rad.
    pub speed: f64,
}

impl Pose {
    /// The frame angle of link `l`, radians in (−π, π], from its unit vector.
    pub fn angle(&self, l: usize) -> f64 {
        let e = self.dir[l];
        e.y.atan2(e.x)
    }
}

/// Why a dyad cannot be assembled at this crank angle (or, in [`Pose::toggle`], why its
/// analogues are not determined).
#[derive(Debug, Clone, PartialEq)]
pub struct Unassembled {
    /// Group index (file order).
    pub group: usize,
    /// What fails, with the numbers (m).
    pub detail: String,
}

/// Steps of a [`Program::sweep`] between crank directions taken from sin and cos (between,
/// each is the one before turned through the step: rounding grows by about an ulp a step).
pub const SWEEP_ANCHOR: usize = 16;

/// Mutable state of one solve, borrowed from a [`Pose`]: what a kind's solve reads its
/// known points and links from and writes its joint and links to.
pub(in crate::linkage) struct State<'a> {
    /// The position being solved.
    pub(in crate::linkage) pose: &'a mut Pose,
    /// The program's frame directions with their unit vectors.
    fixed_dirs: &'a [(f64, DVec2)],
    /// Continuity: `pose` holds the previous position, and each two-solution dyad takes the
    /// solution nearest to its previous joint.
    pub(in crate::linkage) continuity: bool,
    /// The group being solved (file order).
    pub(in crate::linkage) group: usize,
}

impl State<'_> {
    /// Point `k` with its rates.
    #[inline]
    pub(in crate::linkage) fn jet(&self, k: usize) -> Jet {
        Jet {
            p: self.pose.p[k],
            d: self.pose.dp[k],
            dd: self.pose.ddp[k],
        }
    }
    /// Set point `k` with its rates.
    #[inline]
    pub(in crate::linkage) fn set(&mut self, k: usize, j: Jet) {
        self.pose.p[k] = j.p;
        self.pose.dp[k] = j.d;
        self.pose.ddp[k] = j.dd;
    }
    /// Link `l`'s frame angle with its rates.
    #[inline]
    pub(in crate::linkage) fn link(&self, l: usize) -> AngleJet {
        AngleJet {
            d: self.pose.dangle[l],
            dd: self.pose.ddangle[l],
            e: self.pose.dir[l],
        }
    }
    /// Set link `l`'s frame angle with its rates, and its frame origin.
    #[inline]
    pub(in crate::linkage) fn set_link(&mut self, l: usize, t: AngleJet, origin: usize) {
        self.pose.dangle[l] = t.d;
        self.pose.ddangle[l] = t.dd;
        self.pose.dir[l] = t.e;
        self.pose.origin[l] = origin;
    }
    /// A direction of the program with its rates.
    #[inline]
    pub(in crate::linkage) fn dir(&self, d: &PDir) -> AngleJet {
        match *d {
            PDir::Fixed(a) => match self
                .fixed_dirs
                .iter()
                .find(|f| f.0.to_bits() == a.to_bits())
            {
                Some(&(_, e)) => AngleJet { d: 0.0, dd: 0.0, e },
                None => AngleJet::at(a, 0.0, 0.0),
            },
            PDir::Along { from, to, angle } => {
                heading(sub(self.jet(to), self.jet(from))).turned(angle)
            }
        }
    }
    /// A guide of the program with its rates.
    pub(in crate::linkage) fn guide(&self, g: &PGuide) -> LineJet {
        let t = self.dir(&g.dir);
        let e = unit(t);
        let n = Jet {
            p: e.p.perp(),
            d: e.d.perp(),
            dd: e.dd.perp(),
        };
        let through = self.jet(g.through);
        let o = g.offset;
        LineJet {
            g: Jet {
                p: through.p + n.p * o,
                d: through.d + n.d * o,
                dd: through.dd + n.dd * o,
            },
            e,
            t,
        }
    }
    /// Record the group being solved at its toggle (unless one was met before), with what
    /// fails.
    pub(in crate::linkage) fn toggle(&mut self, detail: String) {
        let group = self.group;
        self.pose
            .toggle
            .get_or_insert(Unassembled { group, detail });
    }
    /// Why the group being solved cannot be assembled: `detail`, with the numbers.
    pub(in crate::linkage) fn fail(&self, detail: String) -> Unassembled {
        Unassembled {
            group: self.group,
            detail,
        }
    }
}

impl Program {
    /// Solve the mechanism at crank angle `phi` (radians, counter-clockwise from +x).
    /// `prev`: the previous position; when given, each two-solution dyad takes the solution
    /// nearest to it (continuity), otherwise the scene's branch.
    pub fn solve(&self, phi: f64, prev: Option<&Pose>) -> Result<Pose, Unassembled> {
        let mut pose = match prev {
            Some(p) => p.clone(),
            None => Pose::default(),
        };
        self.solve_into(phi, prev.is_some(), &mut pose)?;
        Ok(pose)
    }

    /// Solve into `pose`, reusing its buffers (no allocation once sized). With `continuity`,
    /// `pose` must hold the previous position: each two-solution dyad takes the solution
    /// nearest to its previous joint.
    pub fn solve_into(
        &self,
        phi: f64,
        continuity: bool,
        pose: &mut Pose,
    ) -> Result<(), Unassembled> {
        let continuity = self.prepare(continuity, pose);
        self.solve_at(phi, DVec2::from_angle(phi), continuity, pose)
    }

    /// Solve at the crank angles φ₀ + k·Δφ, k = 0 … n − 1, handing each position to `each`
    /// (k, pose) as it is solved; after the first, each position takes the solution nearest
    /// to the one before (continuity). The trigonometry is shared: the crank's direction
    /// advances by the rotation through Δφ and is taken afresh from sin and cos every
    /// [`SWEEP_ANCHOR`] steps, so that it stays within about that many ulps of
    /// [`Program::solve_into`]'s.
    /// Stops at the first position that cannot be assembled.
    pub fn sweep(
        &self,
        (phi0, step): (f64, f64),
        n: usize,
        pose: &mut Pose,
        mut each: impl FnMut(usize, &Pose),
    ) -> Result<(), Unassembled> {
        let turn = DVec2::from_angle(step);
        let mut e = DVec2::X;
        // The frame's points are set once: `each` sees the pose but cannot change it.
        self.prepare(false, pose);
        for k in 0..n {
            let phi = phi0 + k as f64 * step;
            e = if k % SWEEP_ANCHOR == 0 {
                DVec2::from_angle(phi)
            } else {
                turn.rotate(e)
            };
            self.solve_at(phi, e, k > 0, pose)?;
            each(k, pose);
        }
        Ok(())
    }

    /// Size `pose`'s buffers for this program (once: a pose reused for the same program keeps
    /// them) and set the frame's points; whether continuity can be kept (the pose held a
    /// position of this program, and with it the frame's points, which no solve changes).
    #[inline]
    fn prepare(&self, continuity: bool, pose: &mut Pose) -> bool {
        let n = self.names.len();
        let sized = pose.p.len() == n && pose.dir.len() == self.link_count;
        if !sized {
            for v in [&mut pose.p, &mut pose.dp, &mut pose.ddp] {
                v.resize(n, DVec2::ZERO);
            }
            for v in [&mut pose.dangle, &mut pose.ddangle] {
                v.resize(self.link_count, 0.0);
            }
            pose.dir.resize(self.link_count, DVec2::X);
            pose.origin.resize(self.link_count, 0);
        }
        if continuity && sized {
            return true;
        }
        for (k, f) in self.fixed.iter().enumerate() {
            pose.p[k] = *f;
            pose.dp[k] = DVec2::ZERO;
            pose.ddp[k] = DVec2::ZERO;
        }
        false
    }

    /// Solve at crank angle `phi` whose unit vector is `e` (`pose` prepared).
    fn solve_at(
        &self,
        phi: f64,
        e: DVec2,
        continuity: bool,
        pose: &mut Pose,
    ) -> Result<(), Unassembled> {
        pose.crossing_sin.clear();
        pose.toggle = None;
        pose.near_pivot.clear();
        pose.phi = phi;
        let mut st = State {
            pose,
            fixed_dirs: &self.fixed_dirs,
            continuity,
            group: 0,
        };
        let crank = AngleJet { d: 1.0, dd: 0.0, e };
        let pin = carried(
            st.jet(self.centre),
            crank,
            DVec2::new(self.crank_length, 0.0),
        );
        st.set(self.pin, pin);
        st.set_link(self.crank_link as usize, crank, self.centre);
        for op in &self.ops {
            match *op {
                Op::Point {
                    idx,
                    link,
                    along,
                    across,
                } => {
                    let l = link as usize;
                    let o = st.jet(st.pose.origin[l]);
                    let j = carried(o, st.link(l), DVec2::new(along, across));
                    st.set(idx, j);
                }
                // One Assur group: its joint (RPR: its slide line) with the rates, by its
                // kind's own solve (borrowed from the program, not copied).
                Op::Dyad {
                    group,
                    links,
                    ref dyad,
                } => {
                    st.group = group;
                    dyad.solve(self, &mut st, links.map(|l| l as usize))?;
                }
            }
        }
        Ok(())
    }
}

mod limit;
#[cfg(test)]
mod tests;
