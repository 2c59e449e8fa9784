//! The geometry of an external involute pair with profile shift, in closed form (seed 000
//! §4, seed 002 PZ3 (3.2)–(3.20)): α_w from the shifts by the involute function, the
//! centre-distance coefficient y and the equalising shift Δy, every radius, the tooth
//! thicknesses (on the pitch and tip circles), the radial clearances, the pitches, the
//! theoretical and practical lines of action, the contact ratio and the interference checks.

use super::involute::{inv, inv_inverse, inv_inverse_newton, pressure_angle, thickness_at};
use super::{BasicRack, Cutting, GearError};
use std::f64::consts::PI;

/// An external pair as given: module, tooth numbers and shift coefficients.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairSpec {
    /// The module m, m.
    pub module: f64,
    /// z₁ (pinion), z₂ (wheel).
    pub z: [u32; 2],
    /// The shift coefficients x₁, x₂.
    pub x: [f64; 2],
    /// The basic rack the wheels are cut by.
    pub rack: BasicRack,
    /// The equalising shift Δy as the textbook takes it from Kudryavtsev's table A (seed 002
    /// PZ3: 0.160 for z₁ = 13); `None`: the exact Δy = x_Σ − y.
    pub dy_table: Option<f64>,
}

/// The pair's geometry, SI (m, rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GearPair {
    /// The pair as given.
    pub spec: PairSpec,
    /// inv α_w = 2 x_Σ tg α/(z₁ + z₂) + inv α.
    pub inv_w: f64,
    /// α_w, the operating pressure angle (the bracketed inverse).
    pub alpha_w: f64,
    /// α_w by Newton's iteration from (3v)^{1/3} (the twin of the bracketed inverse).
    pub alpha_w_newton: f64,
    /// y, the centre-distance coefficient.
    pub y: f64,
    /// Δy = x_Σ − y, the equalising shift coefficient (or the table's, when given).
    pub dy: f64,
    /// a = m(z₁ + z₂)/2, the standard centre distance.
    pub a: f64,
    /// a_w = m((z₁ + z₂)/2 + y).
    pub a_w: f64,
    /// Pitch radii r = m z/2.
    pub r: [f64; 2],
    /// Base radii r_b = r cos α.
    pub rb: [f64; 2],
    /// Operating radii r_w = r(1 + 2y/(z₁ + z₂)).
    pub rw: [f64; 2],
    /// Root radii r_f = r − (h_a* + c* − x) m.
    pub rf: [f64; 2],
    /// Tip radii r_a = r + (h_a* + x − Δy) m.
    pub ra: [f64; 2],
    /// Tooth thicknesses on the pitch circles s = m(π/2 + 2 x tg α).
    pub s: [f64; 2],
    /// Tooth thicknesses on the tip circles.
    pub sa: [f64; 2],
    /// Pressure angles at the tips, α_a = arccos(r_b/r_a).
    pub alpha_a: [f64; 2],
    /// Radial clearances a_w − r_a1 − r_f2 and a_w − r_a2 − r_f1.
    pub clearance: [f64; 2],
    /// p = πm.
    pub p: f64,
    /// p_b = πm cos α.
    pub p_b: f64,
    /// p_w = πm cos α / cos α_w.
    pub p_w: f64,
    /// N₁N₂ = a_w sin α_w, the theoretical line of action.
    pub g: f64,
    /// N₁B₂ = √(r_a1² − r_b1²) and N₂B₁ = √(r_a2² − r_b2²).
    pub tip_reach: [f64; 2],
    /// B₁B₂, the practical (active) line of action.
    pub ab: f64,
    /// ε_α = B₁B₂/p_b.
    pub eps: f64,
    /// ε_α by the textbook's (3.20), [z₁ tg α_a1 + z₂ tg α_a2 − (z₁+z₂) tg α_w]/(2π).
    pub eps_formula: f64,
    /// a_w from the base radii, (r_b1 + r_b2)/cos α_w (the twin of `a_w`).
    pub a_w_base: f64,
    /// The exact Δy = x_Σ − y.
    pub dy_exact: f64,
}

impl PairSpec {
    /// x_Σ = x₁ + x₂.
    pub fn x_sum(&self) -> f64 {
        self.x[0] + self.x[1]
    }
    /// The gear ratio u = z₂/z₁.
    pub fn ratio(&self) -> f64 {
        f64::from(self.z[1]) / f64::from(self.z[0])
    }
    /// x₂ for a required centre distance `a_w` (given x₁): inv α_w from cos α_w = a cos α/a_w,
    /// x_Σ = (inv α_w − inv α)(z₁ + z₂)/(2 tg α).
    ///
    /// # Errors
    /// [`GearError::CentreDistance`] when a_w ≤ r_b1 + r_b2 (no line of action) or the shift
    /// it asks for is beyond ±3.
    pub fn x2_for_centre_distance(&self, a_w: f64) -> Result<f64, GearError> {
        let zs = f64::from(self.z[0] + self.z[1]);
        let a = self.module * zs / 2.0;
        let alpha = self.rack.alpha;
        let least = a * alpha.cos();
        if !(a_w.is_finite() && a_w > least) {
            return Err(GearError::CentreDistance {
                a_w,
                least,
                why: "it must exceed r_b1 + r_b2 = a·cos α",
            });
        }
        let alpha_w = (least / a_w).acos();
        let x_sum = (inv(alpha_w) - inv(alpha)) * zs / (2.0 * alpha.tan());
        let x2 = x_sum - self.x[0];
        if x2.abs() > 3.0 {
            return Err(GearError::CentreDistance {
                a_w,
                least,
                why: "the shift x₂ it asks for is beyond ±3",
            });
        }
        Ok(x2)
    }
}

impl GearPair {
    /// The geometry of `spec`.
    ///
    /// # Errors
    /// [`GearError::Spec`] for a non-positive module or fewer than 5 teeth;
    /// [`GearError::InvoluteDomain`] for shifts that give no α_w.
    pub fn new(spec: PairSpec) -> Result<Self, GearError> {
        spec.rack.validate()?;
        let m = spec.module;
        if !(m.is_finite() && m > 0.0) {
            return Err(GearError::Spec {
                what: "module",
                value: m,
                expected: "a module > 0",
            });
        }
        for (i, z) in spec.z.iter().enumerate() {
            if *z < 5 {
                return Err(GearError::Spec {
                    what: if i == 0 { "z1" } else { "z2" },
                    value: f64::from(*z),
                    expected: "at least 5 teeth",
                });
            }
        }
        let BasicRack { alpha, ha, c, .. } = spec.rack;
        let [z1, z2] = spec.z.map(f64::from);
        let zs = z1 + z2;
        let inv_w = 2.0 * spec.x_sum() * alpha.tan() / zs + inv(alpha);
        let alpha_w = inv_inverse(inv_w)?;
        let alpha_w_newton = inv_inverse_newton(inv_w).unwrap_or(f64::NAN);
        let y = zs / 2.0 * (alpha.cos() / alpha_w.cos() - 1.0);
        let dy = spec.dy_table.unwrap_or(spec.x_sum() - y);
        let a = m * zs / 2.0;
        let a_w = m * (zs / 2.0 + y);
        let r = [m * z1 / 2.0, m * z2 / 2.0];
        let rb = r.map(|r| r * alpha.cos());
        let rw = r.map(|r| r * (1.0 + 2.0 * y / zs));
        let rf = [0, 1].map(|i| r[i] - (ha + c - spec.x[i]) * m);
        let ra = [0, 1].map(|i| r[i] + (ha + spec.x[i] - dy) * m);
        let s = spec.x.map(|x| m * (PI / 2.0 + 2.0 * x * alpha.tan()));
        let sa = [0, 1].map(|i| thickness_at(s[i], r[i], alpha, ra[i]));
        let alpha_a = [0, 1].map(|i| pressure_angle(rb[i], ra[i]));
        let clearance = [a_w - ra[0] - rf[1], a_w - ra[1] - rf[0]];
        let p = PI * m;
        let p_b = p * alpha.cos();
        let p_w = p_b / alpha_w.cos();
        let g = a_w * alpha_w.sin();
        let tip_reach = [0, 1].map(|i| (ra[i] * ra[i] - rb[i] * rb[i]).max(0.0).sqrt());
        let ab = tip_reach[0] + tip_reach[1] - g;
        let eps = ab / p_b;
        let eps_formula =
            (z1 * alpha_a[0].tan() + z2 * alpha_a[1].tan() - zs * alpha_w.tan()) / (2.0 * PI);
        Ok(Self {
            spec,
            inv_w,
            alpha_w,
            alpha_w_newton,
            y,
            dy,
            a,
            a_w,
            r,
            rb,
            rw,
            rf,
            ra,
            s,
            sa,
            alpha_a,
            clearance,
            p,
            p_b,
            p_w,
            g,
            tip_reach,
            ab,
            eps,
            eps_formula,
            a_w_base: (rb[0] + rb[1]) / alpha_w.cos(),
            dy_exact: spec.x_sum() - y,
        })
    }

    /// The geometry of `spec`, refused when the pair cannot work: a tip circle inside the
    /// base circle (a Δy too large: no involute flank), a tip that passes the
    /// interference point of the other wheel (the practical line of action leaves N₁N₂), a
    /// pointed tooth (s_a ≤ 0), a contact ratio below 1, a negative radial clearance, or a
    /// tip that cuts into the mate's fillet ([`GearPair::fillet_clear`]).
    ///
    /// # Errors
    /// Those of [`GearPair::new`], [`GearError::TipInsideBase`], [`GearError::Interference`],
    /// [`GearError::Pointed`], [`GearError::ContactRatio`], [`GearError::Clearance`],
    /// [`GearError::FilletInterference`].
    pub fn working(spec: PairSpec) -> Result<Self, GearError> {
        let p = Self::new(spec)?;
        for i in 0..2 {
            if p.ra[i] <= p.rb[i] {
                return Err(GearError::TipInsideBase {
                    wheel: i + 1,
                    ra_mm: p.ra[i] * 1e3,
                    rb_mm: p.rb[i] * 1e3,
                });
            }
        }
        for i in 0..2 {
            if p.sa[i] <= 0.0 {
                return Err(GearError::Pointed {
                    wheel: i + 1,
                    sa: p.sa[i],
                    module: spec.module,
                });
            }
        }
        for i in 0..2 {
            // The tip of wheel i reaches N of the other wheel: the active line leaves N₁N₂.
            if p.tip_reach[i] > p.g {
                return Err(GearError::Interference {
                    wheel: i + 1,
                    reach: p.tip_reach[i],
                    g: p.g,
                });
            }
        }
        for i in 0..2 {
            if p.clearance[i] < 0.0 {
                return Err(GearError::Clearance {
                    wheel: i + 1,
                    clearance: p.clearance[i],
                });
            }
        }
        if p.eps < 1.0 {
            return Err(GearError::ContactRatio { eps: p.eps });
        }
        for i in 0..2 {
            p.fillet_clear(i)?;
        }
        Ok(p)
    }

    /// The mate's tip meets wheel `i`'s flank at B_i (N₁B₁ from N₁ for wheel 1, N₂B₂ from N₂
    /// for wheel 2) no lower than the junction of its involute and fillet, which the rack
    /// that cut it on the pair's blank generates ([`Cutting::junction`]: the flank's end, or
    /// where an undercut's fillet crosses the involute). A wheel the rack cannot cut (|x| >
    /// 3) is not checked.
    ///
    /// # Errors
    /// [`GearError::FilletInterference`] with the radii of contact and junction.
    pub fn fillet_clear(&self, i: usize) -> Result<(), GearError> {
        let s = &self.spec;
        let Ok(c) = Cutting::with_tip(s.module, s.z[i], s.x[i], s.rack, self.ra[i]) else {
            return Ok(());
        };
        let ends = self.active_ends();
        let near = if i == 0 { ends[0] } else { self.g - ends[1] };
        let rb = self.rb[i];
        let contact = (rb * rb + near * near).sqrt();
        let junction = c.junction().0.length();
        if contact < junction * (1.0 - 1e-12) {
            return Err(GearError::FilletInterference {
                wheel: i + 1,
                contact_mm: contact * 1e3,
                junction_mm: junction * 1e3,
                depth_mm: (junction - contact) * 1e3,
            });
        }
        Ok(())
    }

    /// The distance of the pitch point P from N₁ along N₁N₂: r_w1 sin α_w.
    pub fn pole(&self) -> f64 {
        self.rw[0] * self.alpha_w.sin()
    }
    /// The ends of the active line from N₁: B₁ (tip of wheel 2) and B₂ (tip of wheel 1).
    pub fn active_ends(&self) -> [f64; 2] {
        [self.g - self.tip_reach[1], self.tip_reach[0]]
    }
    /// The specific sliding λ₁, λ₂ at the distance `xk` from N₁ along N₁N₂:
    /// λ₁ = 1 − ρ₂/(u ρ₁), λ₂ = 1 − u ρ₁/ρ₂ with ρ₁ = N₁K, ρ₂ = N₂K, u = z₂/z₁
    /// (−∞ at N₁ for λ₁ and at N₂ for λ₂; 0 at the pole, not the residue of 1 − 1).
    pub fn sliding(&self, xk: f64) -> [f64; 2] {
        use crate::scale::residue_to_zero;
        let u = self.spec.ratio();
        let (r1, r2) = (xk, self.g - xk);
        let l1 = if r1 > 0.0 {
            residue_to_zero(1.0 - r2 / (u * r1), 1.0)
        } else {
            f64::NEG_INFINITY
        };
        let l2 = if r2 > 0.0 {
            residue_to_zero(1.0 - u * r1 / r2, 1.0)
        } else {
            f64::NEG_INFINITY
        };
        [l1, l2]
    }
}
