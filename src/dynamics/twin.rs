//! The analytic twin of the machine's dynamics: the reduced moment and inertia over the whole
//! cycle from the analytic twin of the linkage, the work integrated exactly (Gauss–Legendre
//! on panels split at the extreme positions, where the working resistance switches), and the
//! equation of motion in energy form
//!
//! ```text
//! (J_пр(ψ) + J_м)·ω²/2 = T₀ + ΔT(ψ),   ΔT(ψ) = M_д·ψ + ∫₀^ψ M_пр dψ,
//! ```
//!
//! solved for the flywheel J_м that gives the required δ = (ω_max − ω_min)/ω_ср with
//! ω_ср = (ω_max + ω_min)/2: for each J_м the T₀ that gives ω_ср (ω rises with T₀), and J_м
//! from δ (δ falls as J_м grows), both as roots kept bracketed ([`crate::geom::bracketed_root`]). Between the nodes
//! ΔT and J are cubic Hermite interpolants of exact values and exact derivatives
//! (dΔT/dψ = M_д + M_пр, dJ/dψ from the analogues), so the extremes of ω are found to ~1e-11.

use super::reduce::Reducer;
use super::DynamicsError;
use crate::geom::{bracketed_root, golden_section, GoldenRule, Tie};
use std::f64::consts::TAU;

/// Panels of the cycle (at most 0.5° each).
pub const PANELS: usize = 720;

/// Gauss–Legendre nodes and weights on [−1, 1], 5 points.
const GL5: [(f64, f64); 5] = [
    (0.0, 0.568_888_888_888_888_9),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

/// The reduced quantities over one cycle, exactly.
#[derive(Debug, Clone, PartialEq)]
pub struct Cycle {
    /// Node travels ψ_k, 0 … 2π (the extreme positions are nodes).
    pub psi: Vec<f64>,
    /// ∫₀^ψ M_пр dψ at the nodes (work of every reduced force), J.
    pub work: Vec<f64>,
    /// M_пр at the nodes, N·m.
    pub m: Vec<f64>,
    /// J_пр at the nodes (constant part included), kg·m².
    pub j: Vec<f64>,
    /// dJ_пр/dψ at the nodes, kg·m²/rad.
    pub dj: Vec<f64>,
    /// Work of the working resistances over the cycle, J (positive).
    pub a_res: f64,
    /// The constant moment that balances the cycle, −∫M_пр/2π, N·m: the driving moment
    /// M_д = A_c(2π)/2π (> 0), or minus the resisting moment M_с = A_д(2π)/2π of an engine.
    pub m_drive: f64,
    /// Work of the driving forces (indicator diagrams) over the cycle, J (positive).
    pub a_drive: f64,
}

/// The flywheel found by the energy equation and the crank's motion with it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solution {
    /// The flywheel's moment of inertia, kg·m².
    pub j_fw: f64,
    /// The kinetic energy at ψ = 0, J.
    pub t0: f64,
    /// ω_max, rad/s, and where (travel, rad).
    pub w_max: (f64, f64),
    /// ω_min, rad/s, and where.
    pub w_min: (f64, f64),
}

impl Solution {
    /// δ = (ω_max − ω_min)/ω_ср with ω_ср = (ω_max + ω_min)/2.
    pub fn delta(&self) -> f64 {
        2.0 * (self.w_max.0 - self.w_min.0) / (self.w_max.0 + self.w_min.0)
    }
    /// ω_ср = (ω_max + ω_min)/2.
    pub fn omega_avg(&self) -> f64 {
        (self.w_max.0 + self.w_min.0) / 2.0
    }
}

impl Cycle {
    /// Integrate the reduced moments of `red` over one cycle on about `panels` panels.
    ///
    /// # Errors
    /// The mechanism cannot be assembled somewhere, or the work of resistance is not
    /// positive (no driving moment to find).
    pub fn new(red: &Reducer<'_>, panels: usize) -> Result<Self, DynamicsError> {
        let mut breaks = vec![0.0];
        if let Some(e) = &red.extremes {
            if e.work_travel > 1e-9 && e.work_travel < TAU - 1e-9 {
                breaks.push(e.work_travel);
            }
        }
        breaks.push(TAU);
        let h_max = TAU / panels.max(2) as f64;
        let mut psi = vec![0.0];
        for w in breaks.windows(2) {
            let n = ((w[1] - w[0]) / h_max).ceil().max(1.0) as usize;
            for i in 1..=n {
                psi.push(w[0] + (w[1] - w[0]) * i as f64 / n as f64);
            }
        }
        let (mut m, mut j, mut dj) = (Vec::new(), Vec::new(), Vec::new());
        for &p in &psi {
            let (r, d) = red.exact(p)?;
            m.push(r.m());
            j.push(r.j);
            dj.push(d);
        }
        let mut work = vec![0.0];
        let (mut res, mut drv) = (0.0, 0.0);
        for w in psi.windows(2) {
            let (a, b) = (w[0], w[1]);
            let (mid, half) = ((a + b) / 2.0, (b - a) / 2.0);
            let (mut s, mut sr, mut sd) = (0.0, 0.0, 0.0);
            for (x, wt) in GL5 {
                let (r, _) = red.exact(mid + half * x)?;
                s += wt * r.m();
                sr += wt * r.m_res;
                sd += wt * r.m_drv;
            }
            let last = work.last().copied().unwrap_or(0.0);
            work.push(last + s * half);
            res += sr * half;
            drv += sd * half;
        }
        let a_res = -res;
        let total = -work.last().copied().unwrap_or(0.0);
        if !(total != 0.0 && total.is_finite()) {
            return Err(DynamicsError::NoResistance { work: total });
        }
        Ok(Self {
            psi,
            work,
            m,
            j,
            dj,
            a_res,
            m_drive: total / TAU,
            a_drive: drv,
        })
    }

    /// The panel of `psi` (clamped to the cycle) and its local coordinate t ∈ [0, 1].
    fn panel(&self, psi: f64) -> (usize, f64, f64) {
        let n = self.psi.len() - 1;
        let psi = psi.clamp(0.0, TAU);
        let k = self.psi.partition_point(|&p| p <= psi).clamp(1, n) - 1;
        let h = self.psi[k + 1] - self.psi[k];
        (k, (psi - self.psi[k]) / h, h)
    }

    /// Cubic Hermite through (value, slope) at the ends of panel `k`.
    fn hermite(t: f64, h: f64, (y0, d0): (f64, f64), (y1, d1): (f64, f64)) -> f64 {
        let t2 = t * t;
        let t3 = t2 * t;
        (2.0 * t3 - 3.0 * t2 + 1.0) * y0
            + (t3 - 2.0 * t2 + t) * h * d0
            + (-2.0 * t3 + 3.0 * t2) * y1
            + (t3 - t2) * h * d1
    }

    /// ΔT(ψ) = M_д·ψ + ∫₀^ψ M_пр, J.
    pub fn delta_t(&self, psi: f64) -> f64 {
        let (k, t, h) = self.panel(psi);
        let w = Self::hermite(
            t,
            h,
            (self.work[k], self.m[k]),
            (self.work[k + 1], self.m[k + 1]),
        );
        self.m_drive * psi.clamp(0.0, TAU) + w
    }

    /// J_пр(ψ), kg·m².
    pub fn j_at(&self, psi: f64) -> f64 {
        let (k, t, h) = self.panel(psi);
        Self::hermite(
            t,
            h,
            (self.j[k], self.dj[k]),
            (self.j[k + 1], self.dj[k + 1]),
        )
    }

    /// M_пр(ψ) by linear interpolation of the nodes (for drawing), N·m.
    pub fn m_at(&self, psi: f64) -> f64 {
        let (k, t, _) = self.panel(psi);
        self.m[k] + (self.m[k + 1] - self.m[k]) * t
    }

    /// The extreme of `g` over the cycle: the best node, then golden-section search over its
    /// two panels. `(ψ, g(ψ))`.
    pub fn extremum(&self, g: impl Fn(f64) -> f64, maximize: bool) -> (f64, f64) {
        self.extremum_from(self.psi.iter().map(|&p| g(p)), &g, maximize)
    }

    /// [`Self::extremum`] with g's values at the nodes given (`nodes`, in order; the values
    /// g itself gives there).
    fn extremum_from(
        &self,
        nodes: impl Iterator<Item = f64>,
        g: impl Fn(f64) -> f64,
        maximize: bool,
    ) -> (f64, f64) {
        let s = if maximize { 1.0 } else { -1.0 };
        let n = self.psi.len() - 1;
        let (mut k, mut best) = (0, f64::NEG_INFINITY);
        for (i, g_i) in nodes.enumerate() {
            let v = s * g_i;
            if v > best {
                best = v;
                k = i;
            }
        }
        let (a, b) = (self.psi[k.saturating_sub(1)], self.psi[(k + 1).min(n)]);
        let narrow = |a: f64, b: f64| b - a < 1e-13;
        let rule = GoldenRule {
            steps: 80,
            tie: Tie::Upper,
            fresh: false,
        };
        let end = golden_section(a, b, rule, narrow, |x| s * g(x));
        let [(c, fc), (d, fd)] = end.inner;
        let (p, v) = if fc > fd { (c, fc) } else { (d, fd) };
        if v >= best {
            (p, s * v)
        } else {
            (self.psi[k], s * best)
        }
    }

    /// ω² at ψ with flywheel `j_fw` and initial energy `t0` (clamped at 0).
    fn w2(&self, psi: f64, j_fw: f64, t0: f64) -> f64 {
        Self::omega2(t0 + self.delta_t(psi), self.j_at(psi) + j_fw)
    }

    /// ω² = 2T/J from the kinetic energy `t` and the whole reduced inertia `j` (clamped at 0).
    fn omega2(t: f64, j: f64) -> f64 {
        (2.0 * t / j).max(0.0)
    }

    /// ω(ψ), rad/s, with flywheel `j_fw` and energy `t0` at ψ = 0.
    pub fn omega(&self, psi: f64, j_fw: f64, t0: f64) -> f64 {
        self.w2(psi, j_fw, t0).sqrt()
    }

    /// ε(ψ) = (M_д + M_пр − J′·ω²/2)/(J_пр + J_м), rad/s².
    pub fn epsilon(&self, psi: f64, j_fw: f64, t0: f64) -> f64 {
        let (k, t, h) = self.panel(psi);
        // dJ/dψ and M by the derivative of the Hermite interpolants.
        let dh = |y0: f64, d0: f64, y1: f64, d1: f64| {
            let t2 = t * t;
            ((6.0 * t2 - 6.0 * t) * y0 + (-6.0 * t2 + 6.0 * t) * y1) / h
                + (3.0 * t2 - 4.0 * t + 1.0) * d0
                + (3.0 * t2 - 2.0 * t) * d1
        };
        let dj = dh(self.j[k], self.dj[k], self.j[k + 1], self.dj[k + 1]);
        let m = dh(self.work[k], self.m[k], self.work[k + 1], self.m[k + 1]);
        let w2 = self.w2(psi, j_fw, t0);
        (self.m_drive + m - dj * w2 / 2.0) / (self.j_at(psi) + j_fw)
    }

    /// ω_max and ω_min with `j_fw` and `t0`, where they occur.
    pub fn extremes(&self, j_fw: f64, t0: f64) -> ((f64, f64), (f64, f64)) {
        // ω² at the nodes straight from their values (the interpolants meet them there
        // exactly), without looking up each node's panel.
        let at_nodes = || {
            (0..self.psi.len()).map(move |i| {
                let dt = self.m_drive * self.psi[i].clamp(0.0, TAU) + self.work[i];
                Self::omega2(t0 + dt, self.j[i] + j_fw)
            })
        };
        let (pa, a) = self.extremum_from(at_nodes(), |p| self.w2(p, j_fw, t0), true);
        let (pb, b) = self.extremum_from(at_nodes(), |p| self.w2(p, j_fw, t0), false);
        ((a.sqrt(), pa), (b.sqrt(), pb))
    }

    /// The T₀ that gives (ω_max + ω_min)/2 = `w_avg` with flywheel `j_fw` (the mean speed
    /// rises with T₀: a bracketed root).
    pub fn t0_for(&self, j_fw: f64, w_avg: f64) -> f64 {
        let dt_min = self.delta_t(self.extremum(|p| self.delta_t(p), false).0);
        let j_max = self.j.iter().fold(0.0f64, |m, &j| m.max(j)) + j_fw;
        let lo = -dt_min;
        let hi = 2.0 * w_avg * w_avg * j_max - dt_min;
        bracketed_root(
            |t0| {
                let ((a, _), (b, _)) = self.extremes(j_fw, t0);
                (a + b) / 2.0 - w_avg
            },
            lo,
            hi,
        )
    }

    /// The motion with flywheel `j_fw` at mean speed `w_avg`.
    pub fn with_flywheel(&self, j_fw: f64, w_avg: f64) -> Solution {
        let t0 = self.t0_for(j_fw, w_avg);
        let (w_max, w_min) = self.extremes(j_fw, t0);
        Solution {
            j_fw,
            t0,
            w_max,
            w_min,
        }
    }

    /// The flywheel that gives `delta` at mean speed `w_avg` (δ falls as J_м grows: a
    /// bracketed root; 0 when the machine runs within `delta` without one).
    ///
    /// # Errors
    /// No flywheel up to 1e12 kg·m² gives `delta`.
    pub fn flywheel(&self, w_avg: f64, delta: f64) -> Result<Solution, DynamicsError> {
        let none = self.with_flywheel(0.0, w_avg);
        if none.delta() <= delta {
            return Ok(none);
        }
        let (mut lo, mut hi) = (0.0, 1.0);
        while self.with_flywheel(hi, w_avg).delta() > delta {
            lo = hi;
            hi *= 4.0;
            if hi > 1e12 {
                return Err(DynamicsError::NoFlywheel { delta });
            }
        }
        let j_fw = bracketed_root(|j| self.with_flywheel(j, w_avg).delta() - delta, lo, hi);
        Ok(self.with_flywheel(j_fw, w_avg))
    }

    /// The time of one cycle with flywheel `j_fw` and energy `t0`: ∫ dψ/ω, s.
    pub fn cycle_time(&self, j_fw: f64, t0: f64) -> f64 {
        self.psi
            .windows(2)
            .map(|w| {
                let (mid, half) = ((w[0] + w[1]) / 2.0, (w[1] - w[0]) / 2.0);
                GL5.iter()
                    .map(|(x, wt)| wt / self.omega(mid + half * x, j_fw, t0))
                    .sum::<f64>()
                    * half
            })
            .sum()
    }

    /// Mertsalov's route on the continuous data: T_I = ΔT − ω_ср²·J_пр/2, J_I = ΔT_I/(δ·ω_ср²).
    /// Returns (J_I, ΔT_I, ψ of T_I max, ψ of T_I min).
    pub fn mertsalov(&self, w_avg: f64, delta: f64) -> (f64, f64, f64, f64) {
        let t1 = |p: f64| self.delta_t(p) - w_avg * w_avg * self.j_at(p) / 2.0;
        let (pa, a) = self.extremum(t1, true);
        let (pb, b) = self.extremum(t1, false);
        ((a - b) / (delta * w_avg * w_avg), a - b, pa, pb)
    }

    /// Wittenbauer's route on the continuous data with the tangents' slopes ω_max²/2 and
    /// ω_min²/2: J_м = (c_max − c_min)/((ω_max² − ω_min²)/2), c the tangents' intercepts.
    pub fn wittenbauer(&self, w_max: f64, w_min: f64) -> f64 {
        let (s1, s2) = (w_max * w_max / 2.0, w_min * w_min / 2.0);
        let c1 = self
            .extremum(|p| self.delta_t(p) - s1 * self.j_at(p), true)
            .1;
        let c2 = self
            .extremum(|p| self.delta_t(p) - s2 * self.j_at(p), false)
            .1;
        (c1 - c2) / (s1 - s2)
    }
}
