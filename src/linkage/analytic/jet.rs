//! Jets: points, angles and lines with their first and second derivatives with respect to the
//! crank angle, and the closed-form steps on them (heading, unit vector, carried point, meeting
//! lines).

use crate::geom::DVec2;

/// A point with its first and second derivatives.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(in crate::linkage) struct Jet {
    pub(in crate::linkage) p: DVec2,
    pub(in crate::linkage) d: DVec2,
    pub(in crate::linkage) dd: DVec2,
}

/// An angle with its first and second derivatives, and its unit vector `e` = (cos a, sin a)
/// (kept alongside so that no angle is turned back into a vector by sin and cos).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(in crate::linkage) struct AngleJet {
    pub(in crate::linkage) d: f64,
    pub(in crate::linkage) dd: f64,
    pub(in crate::linkage) e: DVec2,
}

impl AngleJet {
    /// The angle `a` with its rates, its unit vector from sin and cos.
    #[inline]
    pub(in crate::linkage) fn at(a: f64, d: f64, dd: f64) -> Self {
        Self {
            d,
            dd,
            e: DVec2::from_angle(a),
        }
    }

    /// Turned by the constant angle `by`.
    #[inline]
    pub(in crate::linkage) fn turned(self, by: f64) -> Self {
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
pub(in crate::linkage) struct LineJet {
    pub(in crate::linkage) g: Jet,
    pub(in crate::linkage) e: Jet,
    pub(in crate::linkage) t: AngleJet,
}

/// Relative slack with which a tangency survives rounding (a circle pair whose centre
/// distance misses r₁ ± r₂ by 1e-12 of the radii touches).
pub(in crate::linkage) const TANGENT_REL: f64 = 1e-12;

#[inline]
pub(in crate::linkage) fn cross(a: DVec2, b: DVec2) -> f64 {
    a.perp_dot(b)
}

/// The 2×2 system `[r0; r1] x = rhs`, checked once and solved for several right-hand sides.
#[derive(Clone, Copy)]
pub(in crate::linkage) struct Rows {
    pub(in crate::linkage) r0: DVec2,
    pub(in crate::linkage) r1: DVec2,
    pub(in crate::linkage) det: f64,
}

impl Rows {
    /// `None` when singular (a toggle position): |det| ≤ 1e-14·|r0|·|r1|, compared in
    /// squares (det² ≤ 1e-28·|r0|²·|r1|²) so that no square root stands in the kernel's chain.
    #[inline]
    pub(in crate::linkage) fn new(r0: DVec2, r1: DVec2) -> Option<Self> {
        let det = cross(r0, r1);
        let scale2 = r0.length_squared() * r1.length_squared();
        if scale2 == 0.0 || det * det <= 1e-28 * scale2 {
            return None;
        }
        Some(Self { r0, r1, det })
    }

    /// The solution for `rhs`.
    #[inline]
    pub(in crate::linkage) fn solve(&self, rhs: DVec2) -> DVec2 {
        adjugate(self.r0, self.r1, rhs) / self.det
    }
}

/// The solution of `[r0; r1] x = rhs` times the rows' determinant (the adjugate's product):
/// [`Rows::solve`] divides it by the determinant, a caller that solves several right-hand
/// sides may multiply it by the determinant's reciprocal.
#[inline]
pub(in crate::linkage) fn adjugate(r0: DVec2, r1: DVec2, rhs: DVec2) -> DVec2 {
    DVec2::new(rhs.x * r1.y - rhs.y * r0.y, r0.x * rhs.y - r1.x * rhs.x)
}

/// Angle of a vector jet with its rates; its unit vector is the vector over its length.
#[inline]
pub(in crate::linkage) fn heading(v: Jet) -> AngleJet {
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

/// Angle of a vector jet whose length is known to be `len` (a link between two of its
/// pairs): [`heading`] without its square root and division.
#[inline]
pub(in crate::linkage) fn heading_at(v: Jet, len: f64) -> AngleJet {
    let inv_len = 1.0 / len;
    let inv = inv_len * inv_len;
    let d = cross(v.p, v.d) * inv;
    let dd = (cross(v.p, v.dd) - 2.0 * d * v.p.dot(v.d)) * inv;
    AngleJet {
        d,
        dd,
        e: v.p * inv_len,
    }
}

/// The unit vector at an angle jet, as a jet.
#[inline]
pub(in crate::linkage) fn unit(t: AngleJet) -> Jet {
    let e = t.e;
    let n = e.perp();
    Jet {
        p: e,
        d: n * t.d,
        dd: n * t.dd - e * (t.d * t.d),
    }
}

#[inline]
pub(in crate::linkage) fn sub(a: Jet, b: Jet) -> Jet {
    Jet {
        p: a.p - b.p,
        d: a.d - b.d,
        dd: a.dd - b.dd,
    }
}

/// A point fixed in a link frame: origin + R(θ)·local.
#[inline]
pub(in crate::linkage) fn carried(o: Jet, t: AngleJet, local: DVec2) -> Jet {
    turned_with(o, t, t.e.rotate(local))
}

/// A point on a link frame's x-axis, `len` from its origin (the crank's pin): [`carried`]
/// without the across part, one product less before the pin is known.
#[inline]
pub(in crate::linkage) fn carried_along(o: Jet, t: AngleJet, len: f64) -> Jet {
    turned_with(o, t, t.e * len)
}

/// The point at `r` from origin `o`, `r` turning with the angle `t`.
#[inline]
fn turned_with(o: Jet, t: AngleJet, r: DVec2) -> Jet {
    Jet {
        p: o.p + r,
        d: o.d + r.perp() * t.d,
        dd: o.dd + r.perp() * t.dd - r * (t.d * t.d),
    }
}

/// Intersection of two moving lines with its rates and the sine of their crossing angle.
pub(in crate::linkage) fn meet(l1: LineJet, l2: LineJet) -> Option<(Jet, f64)> {
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
