//! The analytic twin: closed-form positions of every dyad kind with their first and second
//! derivatives with respect to the crank angle (velocity and acceleration analogues dX/dφ₁,
//! d²X/dφ₁²), by differentiating the vector loops — no numerical differentiation. With a
//! constant ω₁ the velocities are ω₁·dX/dφ₁ and the accelerations ω₁²·d²X/dφ₁².
//! Shares nothing with the construction but the program's index tables.

use super::kinds::{Prp, Rpp, Rpr, Rrp, Rrr};
use super::model::Branch;
use super::program::{Op, PDir, PDyad, PGuide, Program};
use crate::geom::DVec2;
use crate::scale::format_plain;
use jet::{carried, cross, heading, meet, sub, unit, AngleJet, Jet, LineJet, Rows, TANGENT_REL};

mod jet;
mod slot;
use slot::Slot;

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

/// Mutable state of one solve, borrowed from a [`Pose`].
struct State<'a> {
    pose: &'a mut Pose,
    /// The program's frame directions with their unit vectors.
    fixed_dirs: &'a [(f64, DVec2)],
    /// Continuity: `pose` holds the previous position, and each two-solution dyad takes the
    /// solution nearest to its previous joint.
    continuity: bool,
}

impl State<'_> {
    #[inline]
    fn jet(&self, k: usize) -> Jet {
        Jet {
            p: self.pose.p[k],
            d: self.pose.dp[k],
            dd: self.pose.ddp[k],
        }
    }
    #[inline]
    fn set(&mut self, k: usize, j: Jet) {
        self.pose.p[k] = j.p;
        self.pose.dp[k] = j.d;
        self.pose.ddp[k] = j.dd;
    }
    #[inline]
    fn link(&self, l: usize) -> AngleJet {
        AngleJet {
            d: self.pose.dangle[l],
            dd: self.pose.ddangle[l],
            e: self.pose.dir[l],
        }
    }
    #[inline]
    fn set_link(&mut self, l: usize, t: AngleJet, origin: usize) {
        self.pose.dangle[l] = t.d;
        self.pose.ddangle[l] = t.dd;
        self.pose.dir[l] = t.e;
        self.pose.origin[l] = origin;
    }
    #[inline]
    fn dir(&self, d: &PDir) -> AngleJet {
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
    fn guide(&self, g: &PGuide) -> LineJet {
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
    fn toggle(&mut self, group: usize, detail: String) {
        self.pose
            .toggle
            .get_or_insert(Unassembled { group, detail });
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
    /// position of this program).
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
        for (k, f) in self.fixed.iter().enumerate() {
            pose.p[k] = *f;
            pose.dp[k] = DVec2::ZERO;
            pose.ddp[k] = DVec2::ZERO;
        }
        continuity && sized
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
                Op::Dyad { group, links, dyad } => self.dyad(&mut st, group, links, &dyad)?,
            }
        }
        Ok(())
    }

    /// One Assur group: its joint (RPR: its slide line) with the rates, by its kind.
    fn dyad(
        &self,
        st: &mut State<'_>,
        group: usize,
        links: [u32; 2],
        dyad: &PDyad,
    ) -> Result<(), Unassembled> {
        let fail = |detail: String| Unassembled { group, detail };
        let (i, j) = (links[0] as usize, links[1] as usize);
        match *dyad {
            PDyad::Rrr(Rrr {
                a,
                la,
                b,
                lb,
                joint,
                branch,
            }) => self.rrr(st, group, [i, j], [(a, la), (b, lb)], (joint, branch))?,
            PDyad::Rrp(Rrp {
                a,
                la,
                guide,
                joint,
                branch,
            }) => self.rrp(st, group, [i, j], (a, la), &guide, (joint, branch))?,
            PDyad::Rpr(Rpr { a, c, offset }) => self.rpr(st, group, [i, j], (a, c), offset)?,
            PDyad::Prp(Prp { gi, gj, joint }) => {
                let (l1, l2) = (st.guide(&gi), st.guide(&gj));
                let (x, s) = meet(l1, l2)
                    .ok_or_else(|| fail(format!("the guides of links {i} and {j} are parallel")))?;
                st.set(joint, x);
                st.set_link(i, l1.t, joint);
                st.set_link(j, l2.t, joint);
                st.pose.crossing_sin.push(s);
            }
            PDyad::Rpp(Rpp {
                a,
                slide,
                guide,
                joint,
            }) => {
                let ts = st.dir(&slide);
                let l1 = LineJet {
                    g: st.jet(a),
                    e: unit(ts),
                    t: ts,
                };
                let l2 = st.guide(&guide);
                let (x, s) = meet(l1, l2).ok_or_else(|| {
                    fail(format!(
                        "the slide of link {i} is parallel to the guide of link {j}"
                    ))
                })?;
                st.set(joint, x);
                st.set_link(i, ts, a);
                st.set_link(j, l2.t, joint);
                st.pose.crossing_sin.push(s);
            }
        }
        Ok(())
    }

    /// RRR: the joint where the circles of radius `la` about `a` and `lb` about `b` cross
    /// (law of cosines), its rates from |x − a|² = la², |x − b|² = lb².
    fn rrr(
        &self,
        st: &mut State<'_>,
        group: usize,
        [i, j]: [usize; 2],
        [(a, la), (b, lb)]: [(usize, f64); 2],
        (joint, branch): (usize, Branch),
    ) -> Result<(), Unassembled> {
        let fail = |detail: String| Unassembled { group, detail };
        let (ja, jb) = (st.jet(a), st.jet(b));
        let ab = jb.p - ja.p;
        let d2 = ab.length_squared();
        let d = d2.sqrt();
        // A tangency lost to rounding is still a tangency (the change point).
        let slack = TANGENT_REL * (la + lb);
        if d > la + lb + slack || d < (la - lb).abs() - slack || d == 0.0 {
            return Err(fail(format!(
                "|{}{}| = {} m is outside [|{} − {}|, {} + {}] m",
                self.names[a],
                self.names[b],
                format_plain(d),
                format_plain(la),
                format_plain(lb),
                format_plain(la),
                format_plain(lb)
            )));
        }
        // Law of cosines at a, in fractions of ab: the foot of the joint on ab at
        // la·cos α/d, the joint la·sin α/d across (to the left for the left branch).
        let inv = 1.0 / d2;
        let along = (la * la - lb * lb + d2) * 0.5 * inv;
        let across = (la * la * inv - along * along).max(0.0).sqrt();
        let foot = ja.p + ab * along;
        let left = foot + ab.perp() * across;
        let right = foot - ab.perp() * across;
        let pick_left = if st.continuity {
            let q = st.pose.p[joint];
            left.distance_squared(q) <= right.distance_squared(q)
        } else {
            branch != Branch::Right
        };
        let x = if pick_left { left } else { right };
        let (ra, rb) = (x - ja.p, x - jb.p);
        // |x − a|² = la², |x − b|² = lb², differentiated once and twice.
        let toggle = || {
            format!(
                "links {i} and {j} are in line at {} (toggle position)",
                self.names[joint]
            )
        };
        let acc = Rows::new(ra, rb).map(|rows| {
            let v = rows.solve(DVec2::new(ra.dot(ja.d), rb.dot(jb.d)));
            let rhs = DVec2::new(
                ra.dot(ja.dd) - (v - ja.d).length_squared(),
                rb.dot(jb.dd) - (v - jb.d).length_squared(),
            );
            (v, rows.solve(rhs))
        });
        let (v, w) = acc.unwrap_or_else(|| {
            st.toggle(group, toggle());
            (DVec2::ZERO, DVec2::ZERO)
        });
        let jx = Jet { p: x, d: v, dd: w };
        st.set(joint, jx);
        st.set_link(i, heading(sub(jx, ja)), a);
        st.set_link(j, heading(sub(jx, jb)), b);
        // The circles cross at the angle between the radii: cos g by the law of cosines.
        let cos_g = ((la * la + lb * lb - d2) / (2.0 * la * lb)).clamp(-1.0, 1.0);
        st.pose.crossing_sin.push((1.0 - cos_g * cos_g).sqrt());
        Ok(())
    }

    /// RRP: the joint where the circle of radius `la` about `a` crosses the guide, its rates
    /// from x = g + t·e with |x − a|² = la².
    fn rrp(
        &self,
        st: &mut State<'_>,
        group: usize,
        [i, j]: [usize; 2],
        (a, la): (usize, f64),
        guide: &PGuide,
        (joint, branch): (usize, Branch),
    ) -> Result<(), Unassembled> {
        let fail = |detail: String| Unassembled { group, detail };
        let ja = st.jet(a);
        let gl = st.guide(guide);
        let (g, e) = (gl.g, gl.e);
        let w = ja.p - g.p;
        let t0 = w.dot(e.p);
        let h = cross(e.p, w);
        if h.abs() > la * (1.0 + TANGENT_REL) {
            return Err(fail(format!(
                "{} is {} m from the guide, more than the link length {} m",
                self.names[a],
                format_plain(h.abs()),
                format_plain(la)
            )));
        }
        let half = (la * la - h * h).max(0.0).sqrt();
        let pick_fwd = if st.continuity {
            let q = st.pose.p[joint];
            (g.p + e.p * (t0 + half)).distance_squared(q)
                <= (g.p + e.p * (t0 - half)).distance_squared(q)
        } else {
            branch != Branch::Backward
        };
        let t = if pick_fwd { t0 + half } else { t0 - half };
        let x = g.p + e.p * t;
        let ra = x - ja.p;
        let den = ra.dot(e.p);
        // x = g + t·e with |x − a|² = la²: solve for t′, t″.
        let (dt, ddt) = if den.abs() <= 1e-14 * la {
            st.toggle(
                group,
                format!("link {i} is perpendicular to the guide of link {j} (toggle position)"),
            );
            (0.0, 0.0)
        } else {
            let dt = -ra.dot(g.d + e.d * t - ja.d) / den;
            let v = g.d + e.p * dt + e.d * t;
            let ddt = -((v - ja.d).length_squared()
                + ra.dot(g.dd + e.d * (2.0 * dt) + e.dd * t - ja.dd))
                / den;
            (dt, ddt)
        };
        let jx = Jet {
            p: x,
            d: g.d + e.p * dt + e.d * t,
            dd: g.dd + e.p * ddt + e.d * (2.0 * dt) + e.dd * t,
        };
        st.set(joint, jx);
        st.set_link(i, heading(sub(jx, ja)), a);
        st.set_link(j, gl.t, joint);
        st.pose.crossing_sin.push(half / la);
        Ok(())
    }

    /// RPR: the slide line through the pin `a` at `offset` from the pivot `c` (without
    /// offset at the pivot: the slot's limit), with its rates.
    fn rpr(
        &self,
        st: &mut State<'_>,
        group: usize,
        [i, j]: [usize; 2],
        (a, c): (usize, usize),
        offset: f64,
    ) -> Result<(), Unassembled> {
        let fail = |detail: String| Unassembled { group, detail };
        let w = sub(st.jet(a), st.jet(c));
        if offset == 0.0 {
            let prev = st.continuity.then(|| st.pose.dir[j]);
            let th = match self.slot(st.pose, (a, c), w, prev) {
                Slot::Direct => None,
                Slot::Limit(th) => Some(th),
                Slot::Undetermined { e, detail } => {
                    let e = e.ok_or_else(|| fail(detail.clone()))?;
                    st.toggle(group, detail);
                    Some(AngleJet { d: 0.0, dd: 0.0, e })
                }
            };
            if let Some(th) = th {
                st.set_link(i, th, a);
                st.set_link(j, th, c);
                st.pose.crossing_sin.push(1.0);
                return Ok(());
            }
        }
        let d = w.p.length();
        if d < offset.abs() || d == 0.0 {
            return Err(fail(format!(
                "{} is {d:.6} m from {}, less than the offset {} m of the slide line",
                self.names[a],
                self.names[c],
                offset.abs()
            )));
        }
        let speed = w.d.length();
        if offset == 0.0 && speed > NEAR_PIVOT_RATIO * d {
            st.pose.near_pivot.push(NearPivot {
                group,
                link: j,
                pin: a,
                pivot: c,
                distance: d,
                speed,
            });
        }
        let beta = heading(w);
        // γ = asin(u), u = −offset/d.
        let dd1 = w.p.dot(w.d) / d;
        let dd2 = (w.d.length_squared() + w.p.dot(w.dd) - dd1 * dd1) / d;
        let u = -offset / d;
        let du = offset * dd1 / (d * d);
        let ddu = offset * (dd2 / (d * d) - 2.0 * dd1 * dd1 / (d * d * d));
        let k = 1.0 - u * u;
        if k <= 1e-28 {
            return Err(fail(format!(
                "{} lies on the offset circle of {}: the slide line is not determined",
                self.names[a], self.names[c]
            )));
        }
        // sin γ = u, cos γ = √k.
        let sk = k.sqrt();
        let gamma = AngleJet {
            d: du / sk,
            dd: ddu / sk + u * du * du / (k * sk),
            e: DVec2::new(sk, u),
        };
        let th = AngleJet {
            d: beta.d + gamma.d,
            dd: beta.dd + gamma.dd,
            e: gamma.e.rotate(beta.e),
        };
        st.set_link(i, th, a);
        st.set_link(j, th, c);
        st.pose.crossing_sin.push(1.0);
        Ok(())
    }
}

#[cfg(test)]
mod tests;
