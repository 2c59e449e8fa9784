//! The quality indices of a point (x₁, x₂) of the contour's plane by the contour's own lean
//! formulas, the hard limits' least margin, and their analytic twins ([`GearPair::new`] and
//! [`Cutting`]), which check every traced point.

use super::{Blocking, Hard, Kind};
use crate::gears::involute::{inv_inverse_with_tan, inv_with_tan};
use crate::gears::{Cutting, GearError, GearPair, PairSpec};
use crate::geom::DVec2;
use std::f64::consts::PI;

/// The indices of a point (x₁, x₂), per unit module.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Indices {
    /// x₁, x₂.
    pub x: [f64; 2],
    /// α_w, rad.
    pub alpha_w: f64,
    /// y.
    pub y: f64,
    /// Δy = x_Σ − y.
    pub dy: f64,
    /// r_a/m.
    pub ra: [f64; 2],
    /// s_a/m.
    pub sa: [f64; 2],
    /// ε_α.
    pub eps: f64,
    /// N₁B₁ and N₂B₂ (/m): the ends of the active line from the centre-side N of each wheel.
    pub near_end: [f64; 2],
    /// ρ_l (/m): the lower limit points of the involutes from N₁ and N₂.
    pub rho_l: [f64; 2],
    /// λ₁ at B₁ and λ₂ at B₂ (`None` when B is at or beyond N: no sliding there).
    pub lambda: Option<[f64; 2]>,
}

impl Indices {
    /// The index a curve of `kind` is a level line of.
    pub fn of(&self, kind: Kind) -> Option<f64> {
        match kind {
            Kind::Undercut(i) => Some(self.x[i]),
            Kind::Tip(i) => Some(self.sa[i]),
            Kind::ContactRatio => Some(self.eps),
            Kind::Interference(i) => Some(self.near_end[i] - self.rho_l[i]),
            Kind::EqualSliding => self.lambda.map(|l| l[0] - l[1]),
        }
    }
}

impl Blocking {
    /// The indices at (x₁, x₂) by the lean formulas; `None` outside their domain (no α_w,
    /// a tip circle inside its base circle).
    pub fn indices(&self, x: DVec2) -> Option<Indices> {
        if !(x.x.is_finite() && x.y.is_finite()) {
            return None;
        }
        let (alpha_w, tan_w) = self.operating(x.x + x.y)?;
        self.indices_with(x, alpha_w, tan_w)
    }

    /// α_w and tg α_w of the sum x_Σ: inv α_w = 2x_Σ tg α/(z₁ + z₂) + inv α.
    pub(super) fn operating(&self, x_sum: f64) -> Option<(f64, f64)> {
        let [_, _, ta, inv_alpha] = self.trig;
        let zs = f64::from(self.z[0]) + f64::from(self.z[1]);
        inv_inverse_with_tan(2.0 * x_sum * ta / zs + inv_alpha).ok()
    }

    /// [`Self::indices`] with α_w and tg α_w of x₁ + x₂ given.
    pub(super) fn indices_with(&self, x: DVec2, alpha_w: f64, tan_w: f64) -> Option<Indices> {
        let ha = self.rack.ha;
        let [sa_, ca, ta, inv_alpha] = self.trig;
        let xs = [x.x, x.y];
        let zz = self.z.map(f64::from);
        let zs = zz[0] + zz[1];
        let x_sum = xs[0] + xs[1];
        // 1 / cos α_w = √(1 + tg²α_w).
        let y = zs / 2.0 * (ca * (1.0 + tan_w * tan_w).sqrt() - 1.0);
        let dy = x_sum - y;
        let r = zz.map(|z| z / 2.0);
        let rb = r.map(|r| r * ca);
        let ra = [0, 1].map(|i| r[i] + ha + xs[i] - dy);
        // A tip on or inside its base circle (or not a number): no involute flank.
        if ra
            .iter()
            .zip(rb)
            .any(|(a, b)| a.partial_cmp(&b) != Some(std::cmp::Ordering::Greater))
        {
            return None;
        }
        // The tip's roll: N_iB of the own tip, r_b tg α_a.
        let tip = [0, 1].map(|i| (ra[i] * ra[i] - rb[i] * rb[i]).sqrt());
        let sa = [0, 1].map(|i| {
            let aa = (rb[i] / ra[i]).acos();
            let half = (PI / 2.0 + 2.0 * xs[i] * ta) / (2.0 * r[i]);
            2.0 * ra[i] * (half + inv_alpha - inv_with_tan(aa, tip[i] / rb[i]))
        });
        // N₁N₂ from the base circles: (r_b1 + r_b2) tg α_w.
        let g = (rb[0] + rb[1]) * tan_w;
        let eps = (tip[0] + tip[1] - g) / (PI * ca);
        let near_end = [g - tip[1], g - tip[0]];
        let rho_l = [0, 1].map(|i| r[i] * sa_ - (self.hl - xs[i]) / sa_);
        let u = zz[1] / zz[0];
        let lambda = (near_end[0] > 0.0 && near_end[1] > 0.0).then(|| {
            [
                1.0 - tip[1] / (u * near_end[0]),
                1.0 - u * tip[0] / near_end[1],
            ]
        });
        Some(Indices {
            x: xs,
            alpha_w,
            y,
            dy,
            ra,
            sa,
            eps,
            near_end,
            rho_l,
            lambda,
        })
    }

    /// The hard limits as level lines, each `hard.inset` inside: at a point, the least of
    /// their indices less their limits is [`Self::margin`].
    pub fn hard_levels(&self, hard: Hard) -> [(Kind, f64); 7] {
        let d = hard.inset;
        [
            (Kind::ContactRatio, hard.eps_min + d),
            (Kind::Undercut(0), self.x_min(0) + d),
            (Kind::Undercut(1), self.x_min(1) + d),
            (Kind::Tip(0), hard.sa_min + d),
            (Kind::Tip(1), hard.sa_min + d),
            (Kind::Interference(0), d),
            (Kind::Interference(1), d),
        ]
    }

    /// The least margin of the hard limits at `x` (≥ 0: admissible), in the indices' own
    /// units (x and lengths per module, ε_α).
    pub fn margin(&self, x: DVec2, hard: Hard) -> Option<f64> {
        self.margin_of(&self.indices(x)?, hard)
    }

    /// [`Self::margin`] of the indices `ix`.
    pub(super) fn margin_of(&self, ix: &Indices, hard: Hard) -> Option<f64> {
        self.hard_levels(hard)
            .iter()
            .try_fold(f64::INFINITY, |m, (kind, limit)| {
                Some(m.min(ix.of(*kind)? - limit))
            })
    }
}

/// The pair of a point of the plane as [`GearPair::new`] computes it (module `module`, the
/// exact Δy): the analytic twin of [`Blocking::indices`].
///
/// # Errors
/// Those of [`GearPair::new`].
pub fn twin_pair(b: &Blocking, module: f64, x: DVec2) -> Result<GearPair, GearError> {
    GearPair::new(PairSpec {
        module,
        z: b.z,
        x: [x.x, x.y],
        rack: b.rack,
        dy_table: None,
    })
}

/// The lower limit point of wheel `i`'s involute from N_i, per module, by [`Cutting`]: the
/// roll of the junction of involute and fillet, √(|J|² − r_b²), on the blank of the pair's
/// r_a (the twin of [`Indices::rho_l`]); when the wheel is undercut, the roll of the state
/// the flank's end generates, negative beyond N (the junction moves up the fillet's cut).
///
/// # Errors
/// Those of [`Cutting::with_tip`].
pub fn twin_rho_l(p: &GearPair, i: usize) -> Result<f64, GearError> {
    let m = p.spec.module;
    let c = Cutting::with_tip(m, p.spec.z[i], p.spec.x[i], p.spec.rack, p.ra[i])?;
    let (sa, ca) = (c.rack.alpha.sin(), c.rack.alpha.cos());
    if c.undercut() {
        let st = c.states();
        return Ok(((st.q_j - st.q_p) * ca + c.r() * sa) / m);
    }
    let j = c.junction().0.length();
    let rb = c.rb();
    Ok(((j - rb) * (j + rb)).max(0.0).sqrt() / m)
}

/// The index of `kind` at `x` by the twins less `limit`, signed as the lean index less its
/// limit (≥ 0 on the admissible side); `None` where a twin has no value. The undercut's is
/// the roll from N of the state the flank's end generates ([`Cutting::states`]) times sin α
/// (the lean x − x_min, x per module); s_a and
/// lengths per m; ε_α; λ₁ − λ₂.
pub fn twin_value(b: &Blocking, module: f64, kind: Kind, limit: f64, x: DVec2) -> Option<f64> {
    value_of(b, &twin_pair(b, module, x).ok()?, kind, limit)
}

/// [`twin_value`] of the twin pair `p`.
fn value_of(b: &Blocking, p: &GearPair, kind: Kind, limit: f64) -> Option<f64> {
    let m = p.spec.module;
    let x = p.spec.x;
    Some(match kind {
        Kind::Undercut(i) => {
            // The flank's end's roll from N, (q_j − q_P) cos α + r sin α (0 at the limit,
            // signed), against the lean x − x_min − inset.
            let c = Cutting::with_tip(m, b.z[i], x[i], b.rack, p.ra[i]).ok()?;
            let st = c.states();
            let (sa, ca) = (c.rack.alpha.sin(), c.rack.alpha.cos());
            let roll = ((st.q_j - st.q_p) * ca + c.r() * sa) / m;
            roll * sa - (limit - b.x_min(i))
        }
        Kind::Tip(i) => p.sa[i] / m - limit,
        Kind::ContactRatio => p.eps - limit,
        Kind::Interference(i) => {
            let near = if i == 0 {
                p.active_ends()[0]
            } else {
                p.g - p.active_ends()[1]
            };
            near / m - twin_rho_l(p, i).ok()? - limit
        }
        Kind::EqualSliding => {
            let ends = p.active_ends();
            let (l1, l2) = (p.sliding(ends[0])[0], p.sliding(ends[1])[1]);
            l1 - l2 - limit
        }
    })
}

/// The index of `kind` at `x` by the twins off `limit` (see [`super::twin_check`]); `None` when a
/// twin has no value there.
pub fn twin_deviation(b: &Blocking, module: f64, kind: Kind, limit: f64, x: DVec2) -> Option<f64> {
    let v = twin_value(b, module, kind, limit, x)?;
    Some(match kind {
        Kind::EqualSliding => {
            let p = twin_pair(b, module, x).ok()?;
            let ends = p.active_ends();
            let (l1, l2) = (p.sliding(ends[0])[0], p.sliding(ends[1])[1]);
            v.abs() / l1.abs().max(l2.abs()).max(1.0)
        }
        _ => v.abs(),
    })
}

/// The least margin of `hard` at `x` by the twins (as [`Blocking::margin`] by the lean
/// formulas); `None` where a twin has no value.
pub fn twin_margin(b: &Blocking, module: f64, hard: Hard, x: DVec2) -> Option<f64> {
    let p = twin_pair(b, module, x).ok()?;
    b.hard_levels(hard)
        .iter()
        .try_fold(f64::INFINITY, |m, (kind, limit)| {
            Some(m.min(value_of(b, &p, *kind, *limit)?))
        })
}
