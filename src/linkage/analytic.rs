//! The analytic twin of the plan of positions: closed-form positions of every dyad kind and
//! their first derivatives with respect to the crank angle (velocity analogues, dX/dφ₁),
//! written from the vector-loop formulas. Shares nothing with the construction but the
//! program's index tables.

use super::model::Branch;
use super::program::{Op, PDir, PDyad, PGuide, Program};
use crate::geom::DVec2;

/// A solved position with its velocity analogues.
#[derive(Debug, Clone, PartialEq)]
pub struct Pose {
    /// Crank angle φ₁, radians.
    pub phi: f64,
    /// Point positions by program index, m.
    pub p: Vec<DVec2>,
    /// dp/dφ₁, m/rad.
    pub dp: Vec<DVec2>,
    /// Link frame angle by link number, radians.
    pub angle: Vec<f64>,
    /// dθ/dφ₁ by link number.
    pub dangle: Vec<f64>,
    /// Link frame origin (point index) by link number.
    pub origin: Vec<usize>,
    /// Per group: the acute crossing angle of its construction (radians; small = ill-conditioned).
    pub crossing: Vec<f64>,
    /// A dyad at its toggle (folded) position: the position exists but its velocity analogues
    /// are not determined; `dp` and `dangle` downstream of it are not meaningful.
    pub toggle: Option<Unassembled>,
}

/// Why a dyad cannot be assembled at this crank angle.
#[derive(Debug, Clone, PartialEq)]
pub struct Unassembled {
    /// Group index (file order).
    pub group: usize,
    /// What fails, with the numbers (m).
    pub detail: String,
}

fn cross(a: DVec2, b: DVec2) -> f64 {
    a.perp_dot(b)
}

/// Solve 2×2 `[r0; r1] x = rhs`; `None` when singular (a toggle position).
fn solve2(r0: DVec2, r1: DVec2, rhs: DVec2) -> Option<DVec2> {
    let det = cross(r0, r1);
    let scale = r0.length() * r1.length();
    if det.abs() <= 1e-14 * scale || scale == 0.0 {
        return None;
    }
    Some(DVec2::new(rhs.x * r1.y - rhs.y * r0.y, r0.x * rhs.y - r1.x * rhs.x) / det)
}

impl Program {
    fn dir(&self, d: &PDir, p: &[DVec2], dp: &[DVec2]) -> (f64, f64) {
        match *d {
            PDir::Fixed(a) => (a, 0.0),
            PDir::Along { from, to, angle } => {
                let v = p[to] - p[from];
                let dv = dp[to] - dp[from];
                (v.y.atan2(v.x) + angle, cross(v, dv) / v.length_squared())
            }
        }
    }

    /// Guide as (point on the line, unit direction, their derivatives).
    fn guide(&self, g: &PGuide, p: &[DVec2], dp: &[DVec2]) -> (DVec2, DVec2, DVec2, DVec2) {
        let (psi, dpsi) = self.dir(&g.dir, p, dp);
        let e = DVec2::from_angle(psi);
        let n = e.perp();
        let point = p[g.through] + n * g.offset;
        let dpoint = dp[g.through] - e * (g.offset * dpsi);
        (point, e, dpoint, n * dpsi)
    }

    /// Solve the mechanism at crank angle `phi` (radians, counter-clockwise from +x).
    /// `prev`: the previous position; when given, each two-solution dyad takes the solution
    /// nearest to it (continuity), otherwise the scene's branch.
    pub fn solve(&self, phi: f64, prev: Option<&Pose>) -> Result<Pose, Unassembled> {
        let n = self.names.len();
        let mut p = vec![DVec2::ZERO; n];
        let mut dp = vec![DVec2::ZERO; n];
        p[..self.fixed.len()].copy_from_slice(&self.fixed);
        let mut angle = vec![0.0; self.link_count];
        let mut dangle = vec![0.0; self.link_count];
        let mut origin = vec![0usize; self.link_count];
        let mut crossing = Vec::new();
        let mut toggle = None;
        let (s, c) = phi.sin_cos();
        let r = self.crank_length;
        p[self.pin] = p[self.centre] + DVec2::new(c, s) * r;
        dp[self.pin] = DVec2::new(-s, c) * r;
        let cl = self.crank_link as usize;
        angle[cl] = phi;
        dangle[cl] = 1.0;
        origin[cl] = self.centre;
        for op in &self.ops {
            match *op {
                Op::Point {
                    idx,
                    link,
                    along,
                    across,
                } => {
                    let l = link as usize;
                    let u = DVec2::from_angle(angle[l]);
                    let local = u * along + u.perp() * across;
                    p[idx] = p[origin[l]] + local;
                    dp[idx] = dp[origin[l]] + local.perp() * dangle[l];
                }
                Op::Dyad { group, links, dyad } => {
                    let near = |j: usize| prev.map(|q| q.p[j]);
                    let fail = |detail: String| Unassembled { group, detail };
                    let (i, j) = (links[0] as usize, links[1] as usize);
                    match dyad {
                        PDyad::Rrr {
                            a,
                            la,
                            b,
                            lb,
                            joint,
                            branch,
                        } => {
                            let ab = p[b] - p[a];
                            let d = ab.length();
                            if d > la + lb || d < (la - lb).abs() || d == 0.0 {
                                return Err(fail(format!(
                                    "|{}{}| = {d:.6} m is outside [|{la} − {lb}|, {la} + {lb}] m",
                                    self.names[a], self.names[b]
                                )));
                            }
                            // Law of cosines at a.
                            let cos_a =
                                ((la * la + d * d - lb * lb) / (2.0 * la * d)).clamp(-1.0, 1.0);
                            let alpha = cos_a.acos();
                            let u = ab / d;
                            let left = p[a] + DVec2::from_angle(alpha).rotate(u) * la;
                            let right = p[a] + DVec2::from_angle(-alpha).rotate(u) * la;
                            let pick_left = match near(joint) {
                                Some(q) => left.distance_squared(q) <= right.distance_squared(q),
                                None => branch != Branch::Right,
                            };
                            let jp = if pick_left { left } else { right };
                            p[joint] = jp;
                            let (ra, rb) = (jp - p[a], jp - p[b]);
                            let rhs = DVec2::new(ra.dot(dp[a]), rb.dot(dp[b]));
                            let v = solve2(ra, rb, rhs).unwrap_or_else(|| {
                                let why = format!(
                                    "links {i} and {j} are in line at {} (toggle position)",
                                    self.names[joint]
                                );
                                toggle.get_or_insert(fail(why));
                                DVec2::ZERO
                            });
                            dp[joint] = v;
                            angle[i] = ra.y.atan2(ra.x);
                            dangle[i] = cross(ra, v - dp[a]) / ra.length_squared();
                            angle[j] = rb.y.atan2(rb.x);
                            dangle[j] = cross(rb, v - dp[b]) / rb.length_squared();
                            origin[i] = a;
                            origin[j] = b;
                            let g = ((la * la + lb * lb - d * d) / (2.0 * la * lb))
                                .clamp(-1.0, 1.0)
                                .acos();
                            crossing.push(g.min(std::f64::consts::PI - g));
                        }
                        PDyad::Rrp {
                            a,
                            la,
                            guide,
                            joint,
                            branch,
                        } => {
                            let (g0, e, dg0, de) = self.guide(&guide, &p, &dp);
                            let w = p[a] - g0;
                            let t0 = w.dot(e);
                            let h = cross(e, w);
                            if h.abs() > la {
                                return Err(fail(format!("{} is {:.6} m from the guide, more than the link length {la} m", self.names[a], h.abs())));
                            }
                            let half = (la * la - h * h).sqrt();
                            let fwd = g0 + e * (t0 + half);
                            let bwd = g0 + e * (t0 - half);
                            let pick_fwd = match near(joint) {
                                Some(q) => fwd.distance_squared(q) <= bwd.distance_squared(q),
                                None => branch != Branch::Backward,
                            };
                            let t = if pick_fwd { t0 + half } else { t0 - half };
                            let jp = g0 + e * t;
                            p[joint] = jp;
                            let ra = jp - p[a];
                            let den = ra.dot(e);
                            let dt = if den.abs() <= 1e-14 * la {
                                toggle.get_or_insert(fail(format!("link {i} is perpendicular to the guide of link {j} (toggle position)")));
                                0.0
                            } else {
                                -ra.dot(dg0 + de * t - dp[a]) / den
                            };
                            let v = dg0 + e * dt + de * t;
                            dp[joint] = v;
                            angle[i] = ra.y.atan2(ra.x);
                            dangle[i] = cross(ra, v - dp[a]) / ra.length_squared();
                            angle[j] = e.y.atan2(e.x);
                            dangle[j] = cross(e, de);
                            origin[i] = a;
                            origin[j] = joint;
                            crossing.push((h.abs() / la).clamp(-1.0, 1.0).acos());
                        }
                        PDyad::Rpr { a, c, offset } => {
                            let w = p[a] - p[c];
                            let dw = dp[a] - dp[c];
                            let d = w.length();
                            if d < offset.abs() || d == 0.0 {
                                return Err(fail(format!("{} is {d:.6} m from {}, less than the offset {} m of the slide line", self.names[a], self.names[c], offset.abs())));
                            }
                            let beta = w.y.atan2(w.x);
                            let dbeta = cross(w, dw) / (d * d);
                            let gamma = (-offset / d).asin();
                            let dd = w.dot(dw) / d;
                            let cg = gamma.cos();
                            if cg <= 1e-14 {
                                return Err(fail(format!("{} lies on the offset circle of {}: the slide line is not determined", self.names[a], self.names[c])));
                            }
                            let dgamma = offset * dd / (d * d * cg);
                            let th = beta + gamma;
                            angle[i] = th;
                            angle[j] = th;
                            dangle[i] = dbeta + dgamma;
                            dangle[j] = dbeta + dgamma;
                            origin[i] = a;
                            origin[j] = c;
                            crossing.push(std::f64::consts::FRAC_PI_2);
                        }
                        PDyad::Prp { gi, gj, joint } => {
                            let (g1, e1, dg1, de1) = self.guide(&gi, &p, &dp);
                            let (g2, e2, dg2, de2) = self.guide(&gj, &p, &dp);
                            let (jp, v, s) =
                                meet(g1, e1, dg1, de1, g2, e2, dg2, de2).ok_or_else(|| {
                                    fail(format!("the guides of links {i} and {j} are parallel"))
                                })?;
                            p[joint] = jp;
                            dp[joint] = v;
                            angle[i] = e1.y.atan2(e1.x);
                            dangle[i] = cross(e1, de1);
                            angle[j] = e2.y.atan2(e2.x);
                            dangle[j] = cross(e2, de2);
                            origin[i] = joint;
                            origin[j] = joint;
                            crossing.push(s);
                        }
                        PDyad::Rpp {
                            a,
                            slide,
                            guide,
                            joint,
                        } => {
                            let (psi, dpsi) = self.dir(&slide, &p, &dp);
                            let e1 = DVec2::from_angle(psi);
                            let (g2, e2, dg2, de2) = self.guide(&guide, &p, &dp);
                            let (jp, v, s) =
                                meet(p[a], e1, dp[a], e1.perp() * dpsi, g2, e2, dg2, de2)
                                    .ok_or_else(|| {
                                        fail(format!(
                                    "the slide of link {i} is parallel to the guide of link {j}"
                                ))
                                    })?;
                            p[joint] = jp;
                            dp[joint] = v;
                            angle[i] = psi;
                            dangle[i] = dpsi;
                            angle[j] = e2.y.atan2(e2.x);
                            dangle[j] = cross(e2, de2);
                            origin[i] = a;
                            origin[j] = joint;
                            crossing.push(s);
                        }
                    }
                }
            }
        }
        Ok(Pose {
            phi,
            p,
            dp,
            angle,
            dangle,
            origin,
            crossing,
            toggle,
        })
    }
}

/// Intersection of two moving lines (point, unit direction, their rates) with its rate and
/// the sine of the crossing angle; `None` when parallel.
#[allow(clippy::too_many_arguments)]
fn meet(
    g1: DVec2,
    e1: DVec2,
    dg1: DVec2,
    de1: DVec2,
    g2: DVec2,
    e2: DVec2,
    dg2: DVec2,
    de2: DVec2,
) -> Option<(DVec2, DVec2, f64)> {
    let det = cross(e1, e2);
    if det.abs() <= 1e-12 {
        return None;
    }
    // Lines n·x = n·g with n = perp(e).
    let (n1, n2) = (e1.perp(), e2.perp());
    let x = solve2(n1, n2, DVec2::new(n1.dot(g1), n2.dot(g2)))?;
    let (dn1, dn2) = (de1.perp(), de2.perp());
    let rhs = DVec2::new(dn1.dot(g1 - x) + n1.dot(dg1), dn2.dot(g2 - x) + n2.dot(dg2));
    let v = solve2(n1, n2, rhs)?;
    Some((x, v, det.abs().min(1.0).asin()))
}
