//! The analytic twin: closed-form positions of every dyad kind with their first and second
//! derivatives with respect to the crank angle (velocity and acceleration analogues dX/dφ₁,
//! d²X/dφ₁²), by differentiating the vector loops — no numerical differentiation. With a
//! constant ω₁ the velocities are ω₁·dX/dφ₁ and the accelerations ω₁²·d²X/dφ₁².
//! Shares nothing with the construction but the program's index tables.

use super::model::Branch;
use super::program::{Op, PDir, PDyad, PGuide, Program};
use crate::geom::DVec2;

/// A solved position with its velocity and acceleration analogues.
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

/// A point with its first and second derivatives.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct Jet {
    p: DVec2,
    d: DVec2,
    dd: DVec2,
}

/// An angle with its first and second derivatives, and its unit vector `e` = (cos a, sin a)
/// (kept alongside so that no angle is turned back into a vector by sin and cos).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct AngleJet {
    d: f64,
    dd: f64,
    e: DVec2,
}

impl AngleJet {
    /// The angle `a` with its rates, its unit vector from sin and cos.
    #[inline]
    fn at(a: f64, d: f64, dd: f64) -> Self {
        Self {
            d,
            dd,
            e: DVec2::from_angle(a),
        }
    }

    /// Turned by the constant angle `by`.
    #[inline]
    fn turned(self, by: f64) -> Self {
        if by == 0.0 {
            return self;
        }
        Self {
            e: DVec2::from_angle(by).rotate(self.e),
            ..self
        }
    }
}

/// A line with its derivatives: point `g`, unit direction `e` (both as jets), and the
/// direction's angle `t`.
#[derive(Debug, Clone, Copy)]
struct LineJet {
    g: Jet,
    e: Jet,
    t: AngleJet,
}

/// Relative slack with which a tangency survives rounding (a circle pair whose centre
/// distance misses r₁ ± r₂ by 1e-12 of the radii touches).
const TANGENT_REL: f64 = 1e-12;

#[inline]
fn cross(a: DVec2, b: DVec2) -> f64 {
    a.perp_dot(b)
}

/// The 2×2 system `[r0; r1] x = rhs`, checked once and solved for several right-hand sides.
#[derive(Clone, Copy)]
struct Rows {
    r0: DVec2,
    r1: DVec2,
    det: f64,
}

impl Rows {
    /// `None` when singular (a toggle position): |det| ≤ 1e-14·|r0|·|r1|.
    #[inline]
    fn new(r0: DVec2, r1: DVec2) -> Option<Self> {
        let det = cross(r0, r1);
        let scale = r0.length() * r1.length();
        if scale == 0.0 || det.abs() <= 1e-14 * scale {
            return None;
        }
        Some(Self { r0, r1, det })
    }

    /// The solution for `rhs`.
    #[inline]
    fn solve(&self, rhs: DVec2) -> DVec2 {
        let Self { r0, r1, det } = *self;
        DVec2::new(rhs.x * r1.y - rhs.y * r0.y, r0.x * rhs.y - r1.x * rhs.x) / det
    }
}

/// Angle of a vector jet with its rates; its unit vector is the vector over its length.
#[inline]
fn heading(v: Jet) -> AngleJet {
    let q = v.p.length_squared();
    let inv = 1.0 / q;
    let d = cross(v.p, v.d) * inv;
    let dd = (cross(v.p, v.dd) - 2.0 * d * v.p.dot(v.d)) * inv;
    AngleJet {
        d,
        dd,
        e: v.p / q.sqrt(),
    }
}

/// The unit vector at an angle jet, as a jet.
#[inline]
fn unit(t: AngleJet) -> Jet {
    let e = t.e;
    let n = e.perp();
    Jet {
        p: e,
        d: n * t.d,
        dd: n * t.dd - e * (t.d * t.d),
    }
}

#[inline]
fn sub(a: Jet, b: Jet) -> Jet {
    Jet {
        p: a.p - b.p,
        d: a.d - b.d,
        dd: a.dd - b.dd,
    }
}

/// A point fixed in a link frame: origin + R(θ)·local.
#[inline]
fn carried(o: Jet, t: AngleJet, local: DVec2) -> Jet {
    let r = t.e.rotate(local);
    Jet {
        p: o.p + r,
        d: o.d + r.perp() * t.d,
        dd: o.dd + r.perp() * t.dd - r * (t.d * t.d),
    }
}

/// Intersection of two moving lines with its rates and the sine of their crossing angle.
fn meet(l1: LineJet, l2: LineJet) -> Option<(Jet, f64)> {
    let det = cross(l1.e.p, l2.e.p);
    if det.abs() <= 1e-12 {
        return None;
    }
    // Each line: n·x = n·g with n = perp(e). Differentiate twice.
    let n = |e: Jet| Jet {
        p: e.p.perp(),
        d: e.d.perp(),
        dd: e.dd.perp(),
    };
    let (n1, n2) = (n(l1.e), n(l2.e));
    let rows = Rows::new(n1.p, n2.p)?;
    let x = rows.solve(DVec2::new(n1.p.dot(l1.g.p), n2.p.dot(l2.g.p)));
    let rhs1 = |nn: Jet, g: Jet| nn.d.dot(g.p - x) + nn.p.dot(g.d);
    let v = rows.solve(DVec2::new(rhs1(n1, l1.g), rhs1(n2, l2.g)));
    let rhs2 = |nn: Jet, g: Jet| nn.dd.dot(g.p - x) + 2.0 * nn.d.dot(g.d - v) + nn.p.dot(g.dd);
    let a = rows.solve(DVec2::new(rhs2(n1, l1.g), rhs2(n2, l2.g)));
    Some((Jet { p: x, d: v, dd: a }, det.abs().min(1.0)))
}

/// Mutable state of one solve, borrowed from a [`Pose`].
struct State<'a> {
    pose: &'a mut Pose,
    /// The program's frame directions with their unit vectors.
    fixed_dirs: &'a [(f64, DVec2)],
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
        let n = self.names.len();
        let continuity = continuity && pose.p.len() == n;
        // Size the buffers once; a pose reused for the same program keeps them.
        if pose.p.len() != n || pose.dir.len() != self.link_count {
            for v in [&mut pose.p, &mut pose.dp, &mut pose.ddp] {
                v.resize(n, DVec2::ZERO);
            }
            for v in [&mut pose.dangle, &mut pose.ddangle] {
                v.resize(self.link_count, 0.0);
            }
            pose.dir.resize(self.link_count, DVec2::X);
            pose.origin.resize(self.link_count, 0);
        }
        pose.crossing_sin.clear();
        pose.toggle = None;
        pose.phi = phi;
        let mut st = State {
            pose,
            fixed_dirs: &self.fixed_dirs,
        };
        for (k, f) in self.fixed.iter().enumerate() {
            st.set(
                k,
                Jet {
                    p: *f,
                    ..Jet::default()
                },
            );
        }
        let crank = AngleJet::at(phi, 1.0, 0.0);
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
                Op::Dyad { group, links, dyad } => {
                    self.dyad(&mut st, group, links, &dyad, continuity)?
                }
            }
        }
        Ok(())
    }

    fn dyad(
        &self,
        st: &mut State<'_>,
        group: usize,
        links: [u32; 2],
        dyad: &PDyad,
        continuity: bool,
    ) -> Result<(), Unassembled> {
        let fail = |detail: String| Unassembled { group, detail };
        let (i, j) = (links[0] as usize, links[1] as usize);
        match *dyad {
            PDyad::Rrr {
                a,
                la,
                b,
                lb,
                joint,
                branch,
            } => {
                let (ja, jb) = (st.jet(a), st.jet(b));
                let ab = jb.p - ja.p;
                let d2 = ab.length_squared();
                let d = d2.sqrt();
                // A tangency lost to rounding is still a tangency (the change point).
                let slack = TANGENT_REL * (la + lb);
                if d > la + lb + slack || d < (la - lb).abs() - slack || d == 0.0 {
                    return Err(fail(format!(
                        "|{}{}| = {d:.6} m is outside [|{la} − {lb}|, {la} + {lb}] m",
                        self.names[a], self.names[b]
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
                let pick_left = if continuity {
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
            }
            PDyad::Rrp {
                a,
                la,
                guide,
                joint,
                branch,
            } => {
                let ja = st.jet(a);
                let gl = st.guide(&guide);
                let (g, e) = (gl.g, gl.e);
                let w = ja.p - g.p;
                let t0 = w.dot(e.p);
                let h = cross(e.p, w);
                if h.abs() > la * (1.0 + TANGENT_REL) {
                    return Err(fail(format!(
                        "{} is {:.6} m from the guide, more than the link length {la} m",
                        self.names[a],
                        h.abs()
                    )));
                }
                let half = (la * la - h * h).max(0.0).sqrt();
                let pick_fwd = if continuity {
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
                        format!(
                            "link {i} is perpendicular to the guide of link {j} (toggle position)"
                        ),
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
            }
            PDyad::Rpr { a, c, offset } => {
                let w = sub(st.jet(a), st.jet(c));
                let d = w.p.length();
                if d < offset.abs() || d == 0.0 {
                    return Err(fail(format!(
                        "{} is {d:.6} m from {}, less than the offset {} m of the slide line",
                        self.names[a],
                        self.names[c],
                        offset.abs()
                    )));
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
            }
            PDyad::Prp { gi, gj, joint } => {
                let (l1, l2) = (st.guide(&gi), st.guide(&gj));
                let (x, s) = meet(l1, l2)
                    .ok_or_else(|| fail(format!("the guides of links {i} and {j} are parallel")))?;
                st.set(joint, x);
                st.set_link(i, l1.t, joint);
                st.set_link(j, l2.t, joint);
                st.pose.crossing_sin.push(s);
            }
            PDyad::Rpp {
                a,
                slide,
                guide,
                joint,
            } => {
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
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The analogues agree with 5-point central differences of the positions (a consistency
    /// check of the differentiation, not the method: the twin itself never differentiates
    /// numerically). Truncation O(h⁴) at h = 2.5e-4 keeps the check's own error near 1e-10
    /// even where the analogues vary fast (the PRP case).
    #[test]
    fn analogues_match_finite_differences_for_every_kind() {
        let h = 2.5e-4;
        for m in crate::linkage::tests::one_of_each_kind() {
            let prog = Program::compile(&m).unwrap();
            for k in 0..24 {
                let phi = 0.1 + k as f64 * 0.26;
                let poses: Option<Vec<Pose>> = [-2.0, -1.0, 0.0, 1.0, 2.0]
                    .iter()
                    .map(|s| prog.solve(phi + s * h, None).ok())
                    .collect();
                let Some(q) = poses else { continue };
                let d5 = |f: &dyn Fn(&Pose) -> f64| {
                    (-f(&q[4]) + 8.0 * f(&q[3]) - 8.0 * f(&q[1]) + f(&q[0])) / (12.0 * h)
                };
                let dd5 = |f: &dyn Fn(&Pose) -> f64| {
                    (-f(&q[4]) + 16.0 * f(&q[3]) - 30.0 * f(&q[2]) + 16.0 * f(&q[1]) - f(&q[0]))
                        / (12.0 * h * h)
                };
                let close =
                    |got: f64, want: f64, tol: f64| (got - want).abs() <= tol * (1.0 + want.abs());
                for idx in 0..prog.names.len() {
                    for c in 0..2 {
                        let f = |p: &Pose| p.p[idx][c];
                        assert!(
                            close(d5(&f), q[2].dp[idx][c], 1e-8),
                            "{} at {phi}: d {} vs {}",
                            prog.names[idx],
                            d5(&f),
                            q[2].dp[idx][c]
                        );
                        assert!(
                            close(dd5(&f), q[2].ddp[idx][c], 1e-6),
                            "{} at {phi}: dd {} vs {}",
                            prog.names[idx],
                            dd5(&f),
                            q[2].ddp[idx][c]
                        );
                    }
                }
                for l in 1..prog.link_count {
                    // Unwrap the angles around the middle one.
                    let f =
                        |p: &Pose| q[2].angle(l) + crate::geom::wrap_pi(p.angle(l) - q[2].angle(l));
                    assert!(close(d5(&f), q[2].dangle[l], 1e-8), "link {l} at {phi}");
                    assert!(
                        close(dd5(&f), q[2].ddangle[l], 1e-6),
                        "link {l} at {phi}: {} vs {}",
                        dd5(&f),
                        q[2].ddangle[l]
                    );
                }
            }
        }
    }
}
