//! The basic rack of ГОСТ 13755 and the analytic twin of rack generation: the wheel's tooth
//! is the envelope of the rack's positions while the rack's pitch line rolls on the pitch
//! circle, i.e. the involute of r_b (from the straight flank) and the extended trochoid's
//! offset (from the tip rounding ρ_f), intersected exactly when the trochoid cuts the
//! involute (undercut).
//!
//! Frames: the wheel's centre O is the origin, the generated tooth is centred on +y. The
//! rack's own coordinates are (u along the rack, v away from the wheel), its mean (modular)
//! line at v = 0 lying at r + x·m from O. Moving the rack by `q` along +u turns the wheel by
//! φ = −q/r (pure rolling of the rack's pitch line on the pitch circle); in the wheel's frame
//! a rack point (u, v) is then at R(q/r)·(u + q, r + x m + v). The tool tooth that cuts the
//! space to the right of the tooth is centred at u₀ = πm/2; its left flank generates the
//! tooth's right flank, its left rounding the fillet, its tip line the root circle.

use super::involute::{inv, involute_point, origin_angle, pressure_angle, thickness_at};
use super::GearError;
use crate::geom::{bisect, rotate, wrap_pi, DVec2, Midpoint};
use std::convert::Infallible;
use std::f64::consts::{FRAC_PI_2, PI};

/// A basic rack (исходный контур): profile angle, addendum and clearance coefficients and the
/// tip rounding radius coefficient.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BasicRack {
    /// α, radians.
    pub alpha: f64,
    /// h_a*.
    pub ha: f64,
    /// c*.
    pub c: f64,
    /// ρ_f*.
    pub rho: f64,
}

impl BasicRack {
    /// ГОСТ 13755: α = 20°, h_a* = 1, c* = 0.25, ρ_f* = 0.38.
    pub const GOST_13755: BasicRack = BasicRack {
        alpha: 20.0 * PI / 180.0,
        ha: 1.0,
        c: 0.25,
        rho: 0.38,
    };

    /// Check the rack can be drawn: 0 < α < 45°, h_a* > 0, c* ≥ 0, the rounding fits between
    /// the flank and the tip line and the two roundings of a tooth do not overlap.
    ///
    /// # Errors
    /// [`GearError::Rack`] naming the coefficient.
    pub fn validate(&self) -> Result<(), GearError> {
        let bad = |what, value, expected: &str| {
            Err(GearError::Rack {
                what,
                value,
                expected: expected.to_string(),
            })
        };
        if !(self.alpha > 0.0 && self.alpha < PI / 4.0) {
            return bad("alpha", self.alpha.to_degrees(), "0° < α < 45°");
        }
        if !(self.ha.is_finite() && self.ha > 0.0 && self.ha <= 2.0) {
            return bad("ha", self.ha, "0 < h_a* ≤ 2");
        }
        if !(self.c.is_finite() && (0.0..=1.0).contains(&self.c)) {
            return bad("c", self.c, "0 ≤ c* ≤ 1");
        }
        if !(self.rho.is_finite() && self.rho >= 0.0) {
            return bad("rho_f", self.rho, "ρ_f* ≥ 0");
        }
        let depth = self.ha + self.c;
        let tip = PI / 4.0 - depth * self.alpha.tan();
        if tip < 0.0 {
            // The tool tooth's flanks meet above its tip line even without a rounding.
            return bad(
                "alpha",
                self.alpha.to_degrees(),
                &format!(
                    "a tool tooth with a tip: tg α·(h_a* + c*) ≤ π/4, i.e. α ≤ {:.4}° with h_a* + c* = {}",
                    (PI / 4.0 / depth).atan().to_degrees(),
                    depth
                ),
            );
        }
        let g = self.per_module();
        if g.uc < 0.0 || g.vj > 0.0 || g.vj < -depth {
            return bad(
                "rho_f",
                self.rho,
                &format!(
                    "a rounding that fits the tool tooth's tip: ρ_f* ≤ {:.4} with α = {}°, h_a* + c* = {}",
                    self.rho_max(),
                    crate::scale::format_sig(self.alpha.to_degrees(), 6, crate::scale::Lang::En),
                    depth
                ),
            );
        }
        Ok(())
    }

    /// The largest ρ_f* the tool tooth holds: the two roundings just meet on its centre
    /// line (u_c = 0) or reach its pitch line (v_j = 0), whichever comes first.
    pub fn rho_max(&self) -> f64 {
        let (sa, ca, ta) = (self.alpha.sin(), self.alpha.cos(), self.alpha.tan());
        let depth = self.ha + self.c;
        let meet = (PI / 4.0 - depth * ta) / (1.0 / ca - ta);
        meet.min(depth / (1.0 - sa))
    }

    /// The tool tooth's shape per unit module (see [`ToolShape`]).
    pub fn per_module(&self) -> ToolShape {
        let (sa, ca, ta) = (self.alpha.sin(), self.alpha.cos(), self.alpha.tan());
        let vt = -(self.ha + self.c);
        let vc = vt + self.rho;
        // Centre of the rounding: ρ inside the flank u = π/4 + v tg α (right flank of a tooth
        // centred on u = 0) and ρ above the tip line.
        let uc = PI / 4.0 + vc * ta - self.rho / ca;
        ToolShape {
            vt,
            vc,
            uc,
            vj: vc - self.rho * sa,
        }
    }
}

/// The tool tooth per unit module, in the rack's frame about the tooth's centre line: the
/// tip line at v = `vt`, the rounding centres at (±`uc`, `vc`), the straight flank ending at
/// v = `vj` (its tangency with the rounding).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToolShape {
    /// v of the tip line, −(h_a* + c*).
    pub vt: f64,
    /// v of the rounding centres.
    pub vc: f64,
    /// |u| of the rounding centres.
    pub uc: f64,
    /// v where the straight flank meets the rounding.
    pub vj: f64,
}

/// Which part of the rack touches the envelope.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum RackPiece {
    /// The straight flank: the involute.
    Flank,
    /// The tip rounding: the trochoidal fillet.
    Fillet,
    /// The tip line: the root circle.
    Root,
}

/// A wheel cut by a rack: the data and the analytic twin of its tooth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cutting {
    /// m, metres.
    pub module: f64,
    /// z.
    pub z: u32,
    /// x.
    pub x: f64,
    /// The rack.
    pub rack: BasicRack,
    /// The blank's (tip) radius, m.
    pub ra: f64,
}

impl Cutting {
    /// A wheel cut alone (no mate, Δy = 0): r_a = r + (h_a* + x)m.
    ///
    /// # Errors
    /// [`GearError::Spec`] for a module ≤ 0 or fewer than 5 teeth, [`GearError::Rack`].
    pub fn alone(module: f64, z: u32, x: f64, rack: BasicRack) -> Result<Self, GearError> {
        let ra = module * (f64::from(z) / 2.0 + rack.ha + x);
        Self::with_tip(module, z, x, rack, ra)
    }

    /// A wheel cut on a blank of tip radius `ra` (a pair's r_a, shortened by Δy).
    ///
    /// # Errors
    /// As [`Cutting::alone`]; [`GearError::Spec`] when the blank is not above the root circle.
    pub fn with_tip(
        module: f64,
        z: u32,
        x: f64,
        rack: BasicRack,
        ra: f64,
    ) -> Result<Self, GearError> {
        rack.validate()?;
        if !(module.is_finite() && module > 0.0) {
            return Err(GearError::Spec {
                what: "module",
                value: module,
                expected: "a module > 0",
            });
        }
        if z < 5 {
            return Err(GearError::Spec {
                what: "z",
                value: f64::from(z),
                expected: "at least 5 teeth",
            });
        }
        if !(x.is_finite() && x.abs() <= 3.0) {
            return Err(GearError::Spec {
                what: "x",
                value: x,
                expected: "a shift coefficient within ±3",
            });
        }
        let c = Self {
            module,
            z,
            x,
            rack,
            ra,
        };
        if !(ra.is_finite() && ra > c.rf()) {
            return Err(GearError::Spec {
                what: "tip radius",
                value: ra,
                expected: "a blank larger than the root circle",
            });
        }
        Ok(c)
    }

    /// r = m z/2.
    pub fn r(&self) -> f64 {
        self.module * f64::from(self.z) / 2.0
    }
    /// r_b = r cos α.
    pub fn rb(&self) -> f64 {
        self.r() * self.rack.alpha.cos()
    }
    /// r_f = r − (h_a* + c* − x)m.
    pub fn rf(&self) -> f64 {
        self.r() - (self.rack.ha + self.rack.c - self.x) * self.module
    }
    /// s = m(π/2 + 2x tg α).
    pub fn s(&self) -> f64 {
        self.module * (PI / 2.0 + 2.0 * self.x * self.rack.alpha.tan())
    }
    /// The tooth thickness on the tip circle.
    pub fn sa(&self) -> f64 {
        thickness_at(self.s(), self.r(), self.rack.alpha, self.ra)
    }
    /// Δy by which the blank's tip is shortened: r_a = r + (h_a* + x − Δy)m (0 for a blank
    /// of the full tip).
    pub fn shortening(&self) -> f64 {
        (self.r() + (self.rack.ha + self.x) * self.module - self.ra) / self.module
    }
    /// x_min = h_a* − z sin²α/2: the least shift without undercut (exact).
    pub fn x_min(&self) -> f64 {
        x_min(self.z, &self.rack)
    }
    /// Undercut by the analytic criterion: the straight flank's end is deeper below the
    /// pitch line than N (the foot of O on the line of action): (−v_j − x)m > r sin²α.
    pub fn undercut(&self) -> bool {
        let g = self.rack.per_module();
        (-g.vj - self.x) * self.module > self.r() * self.rack.alpha.sin().powi(2) * (1.0 + 1e-12)
    }
    /// The tool shape in metres.
    pub fn shape(&self) -> ToolShape {
        let g = self.rack.per_module();
        let m = self.module;
        ToolShape {
            vt: g.vt * m,
            vc: g.vc * m,
            uc: g.uc * m,
            vj: g.vj * m,
        }
    }
    /// The centre u₀ = πm/2 of the tool tooth that cuts the space right of the tooth.
    pub fn u0(&self) -> f64 {
        PI * self.module / 2.0
    }

    /// The states (rack displacements q) of the key moments: the flank's end touching
    /// (`q_j`), the flank touching at P (`q_p`), the flank touching the tip circle (`q_a`),
    /// the rounding's centre under P (`q_bottom`) and the space's centre under P (`q_space`).
    pub fn states(&self) -> States {
        let (sa, ca) = (self.rack.alpha.sin(), self.rack.alpha.cos());
        let m = self.module;
        let sh = self.shape();
        let q_p = -(PI * m / 4.0 + self.x * m * self.rack.alpha.tan());
        let t_j = (sh.vj + self.x * m) / sa;
        let rb = self.rb();
        let t_a = -self.r() * sa + (self.ra * self.ra - rb * rb).max(0.0).sqrt();
        States {
            q_j: q_p + t_j / ca,
            q_p,
            q_a: q_p + t_a / ca,
            q_bottom: -self.u0() + sh.uc,
            q_space: -self.u0(),
        }
    }

    /// The range of rack states that generates the right half of a tooth and its space.
    pub fn span(&self) -> (f64, f64) {
        let s = self.states();
        (s.q_j.min(s.q_space), s.q_a.max(s.q_bottom))
    }

    /// Twin: the polar angle of the origin of the tooth's right flank (counter-clockwise
    /// involute), θ₀ = π/2 − s/(2r) − inv α.
    pub fn theta0(&self) -> f64 {
        FRAC_PI_2 - self.s() / (2.0 * self.r()) - inv(self.rack.alpha)
    }

    /// Twin: the point of the right flank generated at the state `q` — the involute of r_b at
    /// the roll angle NK/r_b, NK = (q − q_P)cos α + r sin α (negative beyond N: the branch the
    /// fillet cuts away).
    pub fn involute_at(&self, q: f64) -> DVec2 {
        let st = self.states();
        let (sa, ca) = (self.rack.alpha.sin(), self.rack.alpha.cos());
        let nk = (q - st.q_p) * ca + self.r() * sa;
        involute_point(DVec2::ZERO, self.rb(), self.theta0(), nk / self.rb(), true)
    }

    /// Twin: the point of the right flank at the radius `ry` (r_b ≤ r_y), by the polar angle
    /// π/2 − (s/(2r) + inv α − inv α_y).
    pub fn involute_at_radius(&self, ry: f64) -> DVec2 {
        let a = FRAC_PI_2 - self.s() / (2.0 * self.r()) - inv(self.rack.alpha)
            + inv(pressure_angle(self.rb(), ry));
        DVec2::new(a.cos(), a.sin()) * ry
    }

    /// Twin: the fillet point generated at the state `q`: the extended trochoid of the
    /// rounding's centre, C(q) = R(q/r)·w(q), w = (u₀ − u_c + q, r + xm + v_c), offset by ρ
    /// along its normal (from the derivative dC/dq = R(q/r)·(w⊥/r + (1, 0))), on the side
    /// away from the wheel's pitch line.
    pub fn trochoid_at(&self, q: f64) -> DVec2 {
        let r = self.r();
        let sh = self.shape();
        let w = DVec2::new(self.u0() - sh.uc + q, r + self.x * self.module + sh.vc);
        let phi = q / r;
        let centre = rotate(w, phi);
        let d = DVec2::new(-w.y, w.x) / r + DVec2::X;
        // The normal in the rack's frame, turned toward the rack (negative v).
        let mut nrm = DVec2::new(-d.y, d.x);
        if nrm.y > 0.0 {
            nrm = -nrm;
        }
        centre + rotate(nrm.normalize_or_zero(), phi) * (self.rack.rho * self.module)
    }

    /// Twin: the root-circle point generated at the state `q` (the tip line under P).
    pub fn root_at(&self, q: f64) -> DVec2 {
        rotate(DVec2::new(0.0, self.rf()), q / self.r())
    }

    /// Twin: the junction of the involute and the fillet. Without undercut it is the point
    /// the flank's end generates (the curves meet tangentially); with undercut the fillet
    /// cuts the involute and the junction is their intersection, solved by bisection on the
    /// fillet's state. Returns (point, involute state, fillet state).
    pub fn junction(&self) -> (DVec2, f64, f64) {
        let st = self.states();
        if !self.undercut() {
            return (self.involute_at(st.q_j), st.q_j, st.q_j);
        }
        let rb = self.rb();
        let th0 = self.theta0();
        // g(q): the fillet point's side of the flank (> 0 inside the tooth), where it is
        // outside the base circle.
        let g = |q: f64| -> Option<f64> {
            let p = self.trochoid_at(q);
            origin_angle(DVec2::ZERO, rb, p, true).map(|a| wrap_pi(a - th0))
        };
        // The junction lies on the tooth, between the base and the tip circles: the fillet's
        // states there, from where it leaves the tip circle (q_ra) to where it leaves the
        // base circle (q_rb). Its radius grows monotonically from the root (q_bottom) out,
        // so each end is a bisection on it. (With a small profile angle the flank's end q_j
        // lies many pitch radii out, where the far branches cross the involute again.)
        let leaves = |radius: f64| {
            let (out, inside) = (st.q_j, st.q_bottom);
            if self.trochoid_at(out).length() < radius {
                return out;
            }
            if self.trochoid_at(inside).length() >= radius {
                return inside;
            }
            let Ok((out, _)) = bisect(
                out,
                inside,
                200,
                |_, _| false,
                |mid| {
                    Ok::<_, Infallible>(if self.trochoid_at(mid).length() >= radius {
                        Midpoint::First
                    } else {
                        Midpoint::Second
                    })
                },
            );
            out
        };
        let (a, b) = (leaves(self.ra), leaves(rb));
        let n = 4000;
        let mut prev: Option<(f64, f64)> = None;
        for i in 1..=n {
            let q = a + (b - a) * f64::from(i) / f64::from(n);
            let Some(v) = g(q) else {
                prev = None;
                continue;
            };
            if let Some((q0, v0)) = prev {
                if (v0 < 0.0) != (v < 0.0) {
                    let s0 = v0 < 0.0;
                    let narrow = |lo: f64, hi: f64| hi - lo <= 1e-17 * self.module.max(hi.abs());
                    let Ok((lo, hi)) = bisect(q0, q, 200, narrow, |mid| {
                        Ok::<_, Infallible>(match g(mid) {
                            Some(gm) if (gm < 0.0) == s0 => Midpoint::First,
                            _ => Midpoint::Second,
                        })
                    });
                    let qf = 0.5 * (lo + hi);
                    let p = self.trochoid_at(qf);
                    return (p, self.flank_state(p.length()), qf);
                }
            }
            prev = Some((q, v));
        }
        // No crossing found above the base circle: the flank's end.
        (self.involute_at(st.q_j), st.q_j, st.q_j)
    }

    /// Twin: the arc thickness of the generated tooth on the circle of radius `rho`: on the
    /// involute above the junction, s_y = 2ρ(s/2r + inv α − inv α_y); below it on the
    /// fillet, whose point at ρ is solved on the fillet's state by bisection (the undercut
    /// thins the tooth there below the involute's value); `None` outside r_f < ρ ≤ r_a.
    pub fn thickness_at_radius(&self, rho: f64) -> Option<f64> {
        if !(rho > self.rf() && rho <= self.ra) {
            return None;
        }
        let (junction, _, qf) = self.junction();
        if rho >= junction.length() {
            return Some(thickness_at(self.s(), self.r(), self.rack.alpha, rho));
        }
        // Down the fillet from the junction (qf) to the root (q_bottom) the radius falls.
        let off = |q: f64| self.trochoid_at(q).length() - rho;
        let (hi, lo) = (qf, self.states().q_bottom);
        if off(hi) < 0.0 || off(lo) > 0.0 {
            return None;
        }
        let Ok((hi, lo)) = bisect(
            hi,
            lo,
            100,
            |_, _| false,
            |mid| {
                Ok::<_, Infallible>(if off(mid) >= 0.0 {
                    Midpoint::First
                } else {
                    Midpoint::Second
                })
            },
        );
        let p = self.trochoid_at(0.5 * (hi + lo));
        Some(2.0 * rho * p.x.atan2(p.y))
    }

    /// The state at which the flank touches the circle of radius `ry` (on the involute's
    /// real branch).
    pub fn flank_state(&self, ry: f64) -> f64 {
        let rb = self.rb();
        let (sa, ca) = (self.rack.alpha.sin(), self.rack.alpha.cos());
        let nk = (ry * ry - rb * rb).max(0.0).sqrt();
        self.states().q_p + (nk - self.r() * sa) / ca
    }

    /// Twin: the right half of the real tooth profile, from the tip down the involute to the
    /// junction, along the fillet to the root and along the root circle to the space's
    /// centre, `per_piece` points on each piece.
    pub fn profile(&self, per_piece: usize) -> Vec<DVec2> {
        let st = self.states();
        let (_, qi, qf) = self.junction();
        let n = per_piece.max(2);
        let lerp = |a: f64, b: f64, i: usize| a + (b - a) * i as f64 / (n - 1) as f64;
        let mut out: Vec<DVec2> = (0..n)
            .map(|i| self.involute_at(lerp(st.q_a, qi, i)))
            .collect();
        out.extend((1..n).map(|i| self.trochoid_at(lerp(qf, st.q_bottom, i))));
        out.extend((1..n).map(|i| self.root_at(lerp(st.q_bottom, st.q_space, i))));
        out
    }
}

/// The key states of a generation (see [`Cutting::states`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct States {
    /// The flank's end touches.
    pub q_j: f64,
    /// The flank touches at P.
    pub q_p: f64,
    /// The flank touches the tip circle.
    pub q_a: f64,
    /// The rounding's centre is under P.
    pub q_bottom: f64,
    /// The space's centre is under P.
    pub q_space: f64,
}

/// x_min = h_a* − z sin²α/2, the least shift coefficient without undercut.
pub fn x_min(z: u32, rack: &BasicRack) -> f64 {
    rack.ha - f64::from(z) * rack.alpha.sin().powi(2) / 2.0
}

/// The textbook's x_min = (17 − z)/17 (h_a* = 1, α = 20°).
pub fn x_min_textbook(z: u32) -> f64 {
    (17.0 - f64::from(z)) / 17.0
}

/// The shift at which a wheel of `z` teeth cut alone (Δy = 0) is pointed, s_a = 0, by
/// bisection over `from`…`to` (s_a falls as x grows); `to` when it is not pointed there.
/// The tip's thickness in closed form, module 1: any tooth count, as the rack itself is
/// drawn only from five teeth.
pub(crate) fn pointed_alone(z: f64, rack: &BasicRack, (from, to): (f64, f64)) -> f64 {
    let sa = |x: f64| {
        let r = z / 2.0;
        let ra = r + rack.ha + x;
        let rb = r * rack.alpha.cos();
        if ra <= rb {
            return 1.0;
        }
        let s = PI / 2.0 + 2.0 * x * rack.alpha.tan();
        2.0 * ra * (s / (2.0 * r) + inv(rack.alpha) - inv((rb / ra).acos()))
    };
    if sa(to) > 0.0 {
        return to;
    }
    // s_a > 0 on the first end's side (it falls as x grows); 100 halvings.
    let Ok((_, pointed)) = bisect(
        from,
        to,
        100,
        |_, _| false,
        |mid| {
            Ok::<_, Infallible>(if sa(mid) > 0.0 {
                Midpoint::First
            } else {
                Midpoint::Second
            })
        },
    );
    pointed
}

/// A wheel of `z` teeth the rack cannot cut: undercut at every shift that leaves its tip
/// unpointed — x_min above the shift that points it cut alone (seed 002 PZ2 example 1's
/// z₃ = 4). `Some((x_min, x_pointed))` then, `None` for a wheel the rack cuts.
pub fn uncuttable(z: u32, rack: &BasicRack) -> Option<(f64, f64)> {
    let least = x_min(z, rack);
    let pointed = pointed_alone(f64::from(z), rack, (-1.0, least.max(-1.0) + 1.0));
    (least > pointed).then_some((least, pointed))
}

/// The shift coefficient at which a wheel cut alone has the tip thickness `sa_min` (× m):
/// the upper end of the feasible range x_min … x(s_a = 0.3m). Bisection on x in [−1, 3]
/// (s_a falls as x grows); `None` when no such x is there.
pub fn x_for_tip(z: u32, rack: &BasicRack, sa_min: f64) -> Option<f64> {
    let sa = |x: f64| {
        let c = Cutting::alone(1.0, z, x, *rack).ok()?;
        Some(c.sa() - sa_min)
    };
    let (lo, hi) = (-1.0, 3.0);
    let (flo, fhi) = (sa(lo)?, sa(hi)?);
    if flo < 0.0 || fhi > 0.0 {
        return None;
    }
    let (lo, hi) = bisect(
        lo,
        hi,
        200,
        |lo, hi| hi - lo < 1e-15,
        |mid| {
            Ok::<_, ()>(if sa(mid).ok_or(())? > 0.0 {
                Midpoint::First
            } else {
                Midpoint::Second
            })
        },
    )
    .ok()?;
    Some(0.5 * (lo + hi))
}
