//! The analytic twin: the closed-form law over the cycle, the pitch curve and its exact
//! envelope with curvature, the pressure / transmission angle, and the minimum radius over
//! the whole cycle (not only at the drawn points).

use super::{CamSpec, Follower, Law};
use crate::geom::{rotate, DVec2};
use std::f64::consts::{FRAC_PI_2, TAU};

/// Samples of each moving phase the whole-cycle minimisations use (plus every break).
pub const DENSE: usize = 2000;

/// The follower's displacement S and its analogues S′ = dS/dφ, S″ = d²S/dφ² at one angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion {
    /// S, m.
    pub s: f64,
    /// dS/dφ, m.
    pub ds: f64,
    /// d²S/dφ², m.
    pub d2s: f64,
}

/// A point of the diagrams and the inversion: its label, cam angle and, where the
/// acceleration analogue jumps, which side of the jump it belongs to.
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    /// `0` … `2n + 1`.
    pub label: String,
    /// φ, rad.
    pub phi: f64,
    /// Take the piece after φ where the law jumps (the first point of a phase).
    pub after: bool,
    /// The phase: 0 rise, 2 return.
    pub phase: usize,
    /// The interval index within the phase (0 … n).
    pub k: usize,
}

/// The points of the diagrams: the rise's n + 1 and the return's n + 1 (seed 000: 26).
pub fn points(spec: &CamSpec) -> Vec<Point> {
    let n = spec.divisions;
    let st = spec.starts();
    let mut out = Vec::with_capacity(2 * n + 2);
    for (phase, len) in [(0usize, spec.phases.rise), (2, spec.phases.ret)] {
        for k in 0..=n {
            out.push(Point {
                label: out.len().to_string(),
                phi: st[phase] + len * k as f64 / n as f64,
                after: k == 0,
                phase,
                k,
            });
        }
    }
    out
}

/// The law at φ (any angle; wrapped into one turn), `after` picking the piece after a jump.
pub fn motion(spec: &CamSpec, phi: f64, after: bool) -> Motion {
    let st = spec.starts();
    let phi = if (0.0..=TAU).contains(&phi) {
        phi
    } else {
        phi.rem_euclid(TAU)
    };
    let h = spec.stroke;
    let phase =
        |a: f64, b: f64| (phi > a || (phi == a && after)) && (phi < b || (phi == b && !after));
    let eval = |law: Law, from: f64, len: f64| {
        let u = ((phi - from) / len).clamp(0.0, 1.0);
        let (f, f1, f2) = law.eval(u, after);
        (f, f1 / len, f2 / (len * len))
    };
    if spec.phases.rise > 0.0 && phase(st[0], st[1]) {
        let (f, f1, f2) = eval(spec.rise, st[0], spec.phases.rise);
        Motion {
            s: h * f,
            ds: h * f1,
            d2s: h * f2,
        }
    } else if spec.phases.ret > 0.0 && phase(st[2], st[3]) {
        let (f, f1, f2) = eval(spec.ret, st[2], spec.phases.ret);
        Motion {
            s: h * (1.0 - f),
            ds: -h * f1,
            d2s: -h * f2,
        }
    } else if phi > st[1] - 1e-15 && phi < st[2] + 1e-15 {
        Motion {
            s: h,
            ds: 0.0,
            d2s: 0.0,
        }
    } else {
        Motion {
            s: 0.0,
            ds: 0.0,
            d2s: 0.0,
        }
    }
}

/// Dense samples of the cycle: every moving phase at [`DENSE`] intervals, both sides of
/// every jump, the dwells at their ends.
pub fn dense(spec: &CamSpec, per_phase: usize) -> Vec<(f64, bool)> {
    let st = spec.starts();
    let mut out = Vec::new();
    for (phase, len, law) in [
        (0usize, spec.phases.rise, spec.rise),
        (2, spec.phases.ret, spec.ret),
    ] {
        for k in 0..=per_phase {
            let u = k as f64 / per_phase as f64;
            out.push((st[phase] + len * u, k == 0));
        }
        for b in law.breaks() {
            out.push((st[phase] + len * b, false));
            out.push((st[phase] + len * b, true));
        }
        out.push((st[phase + 1], true));
    }
    out
}

/// The samples the angle limit is checked at: [`dense`], the rise only under force closure.
pub fn checked(spec: &CamSpec, per_phase: usize) -> Vec<(f64, bool)> {
    let end = spec.starts()[1];
    dense(spec, per_phase)
        .into_iter()
        .filter(|&(phi, after)| !spec.force_closure || phi < end || (phi == end && !after))
        .collect()
}

/// Where the follower is relative to the cam centre O (the origin) when φ = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Placement {
    /// A translating follower (roller centre, knife edge or the face's foot on the axis):
    /// axis x = e, lowest point at height s₀.
    Translating {
        /// e, m.
        offset: f64,
        /// s₀ = √(r₀² − e²), m.
        s0: f64,
    },
    /// A rocker: pivot O₂, arm L, initial angle ψ₀ of O₂A, sense σ = ±1 on the rise.
    Rocker {
        /// O₂, m.
        pivot: DVec2,
        /// L, m.
        arm: f64,
        /// ψ₀, rad.
        psi0: f64,
        /// σ: +1 counter-clockwise on the rise.
        sigma: f64,
    },
}

/// The follower's point B (roller centre) in the fixed frame with its φ-derivatives, the
/// direction of its motion, and the point K = B + J·B′ of the combined diagram (OK is
/// parallel to the common normal: the seed's "dS/dφ laid along the rocker").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kin {
    /// B, m.
    pub b: DVec2,
    /// dB/dφ.
    pub b1: DVec2,
    /// d²B/dφ².
    pub b2: DVec2,
    /// Unit direction of the follower's motion for S′ > 0.
    pub path: DVec2,
    /// The line dS/dφ is laid along (unit): ⊥ the path, along the rocker.
    pub along: DVec2,
    /// K, m.
    pub k: DVec2,
}

/// J: a quarter turn counter-clockwise.
pub fn jay(v: DVec2) -> DVec2 {
    DVec2::new(-v.y, v.x)
}

impl Placement {
    /// The follower at the motion `m` (fixed frame).
    pub fn kin(&self, m: Motion) -> Kin {
        let (b, b1, b2, path, along) = match *self {
            Placement::Translating { offset, s0 } => (
                DVec2::new(offset, s0 + m.s),
                DVec2::new(0.0, m.ds),
                DVec2::new(0.0, m.d2s),
                DVec2::Y,
                DVec2::X,
            ),
            Placement::Rocker {
                pivot,
                arm,
                psi0,
                sigma,
            } => {
                let psi = psi0 + sigma * m.s / arm;
                let e = DVec2::from_angle(psi);
                let je = jay(e);
                (
                    pivot + e * arm,
                    je * (sigma * m.ds),
                    je * (sigma * m.d2s) - e * (m.ds * m.ds / arm),
                    je * sigma,
                    e,
                )
            }
        };
        Kin {
            b,
            b1,
            b2,
            path,
            along,
            k: b + jay(b1),
        }
    }
}

impl Kin {
    /// The pressure angle λ: between the common normal (∥ OK) and the follower's motion, rad.
    pub fn pressure_angle(&self) -> f64 {
        let n = self.k;
        let c = (n.dot(self.path).abs() / n.length()).clamp(0.0, 1.0);
        c.acos()
    }
    /// The transmission angle γ = 90° − λ, rad.
    pub fn transmission_angle(&self) -> f64 {
        FRAC_PI_2 - self.pressure_angle()
    }
    /// The radius of curvature of the pitch curve, m: positive where convex (seen from O),
    /// negative where concave, infinite where straight.
    pub fn pitch_radius(&self) -> f64 {
        let u = self.b1 - jay(self.b);
        let w = self.b2 - jay(self.b1) * 2.0 - self.b;
        let cross = u.perp_dot(w);
        -u.length().powi(3) / cross
    }
    /// The outward unit normal of the pitch curve (fixed frame): along OK.
    pub fn normal(&self) -> DVec2 {
        self.k.normalize_or_zero()
    }
    /// The practical (roller) profile point in the fixed frame: B − r·n.
    pub fn roller_point(&self, r: f64) -> DVec2 {
        self.b - self.normal() * r
    }
}

/// A point of the fixed frame at cam angle φ in the cam's own frame (turned by −φ).
pub fn to_cam(p: DVec2, phi: f64) -> DVec2 {
    rotate(p, -phi)
}

/// The flat face's contact point (fixed frame) at r₀: (S′, r₀ + S), and its radius of
/// curvature r₀ + S + S″.
pub fn flat_contact(r0: f64, m: Motion) -> (DVec2, f64) {
    (DVec2::new(m.ds, r0 + m.s), r0 + m.s + m.d2s)
}

/// The exact minimum base radius of a translating roller / knife-edge follower with offset
/// e for λ ≤ 90° − γ_min over the whole cycle: s₀ = max(|S′ − e|·tan γ_min − S),
/// r₀ = √(e² + s₀²). Returns (r₀, s₀).
pub fn min_radius_translating(spec: &CamSpec, offset: f64) -> (f64, f64) {
    let t = spec.gamma_min.tan();
    let need = |phi: f64, after: bool| {
        let m = motion(spec, phi, after);
        (m.ds - offset).abs() * t - m.s
    };
    let s0 = refine_max(spec, checked(spec, DENSE), need).max(0.0);
    ((offset * offset + s0 * s0).sqrt(), s0)
}

/// The largest of `f` over the cycle: dense samples, then a golden-section refinement of
/// the best one's neighbourhood (f continuous within a phase).
fn refine_max(spec: &CamSpec, samples: Vec<(f64, bool)>, f: impl Fn(f64, bool) -> f64) -> f64 {
    let mut best = f64::NEG_INFINITY;
    let mut at = 0.0;
    for &(phi, after) in &samples {
        let v = f(phi, after);
        if v > best {
            best = v;
            at = phi;
        }
    }
    let step = spec.phases.rise.max(spec.phases.ret) / DENSE as f64;
    let (mut a, mut b) = (at - step, at + step);
    let g = 0.618_033_988_749_894_9;
    for _ in 0..80 {
        let (x1, x2) = (b - g * (b - a), a + g * (b - a));
        if f(x1, true) > f(x2, true) {
            b = x2;
        } else {
            a = x1;
        }
    }
    best.max(f(0.5 * (a + b), true))
}

/// The rocker's constraints: for each dense angle, K and the rocker's line direction in the
/// frame of the pivot O₂ (origin) with A₀ at ψ₀ = 90°.
pub fn rocker_constraints(spec: &CamSpec, per_phase: usize) -> Vec<(DVec2, DVec2)> {
    let (arm, sigma) = rocker_of(spec);
    let place = Placement::Rocker {
        pivot: DVec2::ZERO,
        arm,
        psi0: FRAC_PI_2,
        sigma,
    };
    checked(spec, per_phase)
        .into_iter()
        .map(|(phi, after)| {
            let k = place.kin(motion(spec, phi, after));
            (k.k, k.along)
        })
        .collect()
}

/// The rocker's arm and sense σ (+1: with the cam on the rise).
pub fn rocker_of(spec: &CamSpec) -> (f64, f64) {
    match spec.follower {
        Follower::Rocker { arm, same_sense } => (arm, if same_sense { 1.0 } else { -1.0 }),
        _ => (1.0, 1.0),
    }
}

/// True when a cam centre at `o` keeps γ ≥ γ_min at every constraint (K, rocker line), to a
/// relative slack `slack` of sin γ_min.
pub fn admits(o: DVec2, constraints: &[(DVec2, DVec2)], sin_g: f64, slack: f64) -> bool {
    constraints.iter().all(|&(k, e)| {
        let d = k - o;
        e.perp_dot(d).abs() >= (sin_g - slack) * d.length()
    })
}

/// The exact minimum base radius of a rocker cam over the whole cycle: the cam centre O
/// nearest A₀ (frame of the pivot, A₀ = (0, L)) from which every OK makes γ ≥ γ_min with
/// the rocker. Returns (r₀, O), or `None` when no centre within 20 arms qualifies.
pub fn min_radius_rocker(spec: &CamSpec) -> Option<(f64, DVec2)> {
    let (arm, _) = rocker_of(spec);
    let cons = rocker_constraints(spec, 400);
    let sin_g = spec.gamma_min.sin();
    let a0 = DVec2::new(0.0, arm);
    let limit = 20.0 * arm;
    let first = |theta: f64| -> Option<f64> {
        let dir = DVec2::from_angle(theta);
        let steps = 800;
        let mut prev = 0.0;
        for i in 1..=steps {
            let r = limit * (i as f64 / steps as f64).powi(2);
            if admits(a0 + dir * r, &cons, sin_g, 0.0) {
                let (mut lo, mut hi) = (prev, r);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if admits(a0 + dir * mid, &cons, sin_g, 0.0) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                return Some(hi);
            }
            prev = r;
        }
        None
    };
    let mut best: Option<(f64, f64)> = None;
    let coarse = 720;
    for i in 0..coarse {
        let th = TAU * i as f64 / coarse as f64;
        if let Some(r) = first(th) {
            if best.is_none_or(|(_, b)| r < b) {
                best = Some((th, r));
            }
        }
    }
    let (mut th, mut r) = best?;
    let mut span = TAU / coarse as f64;
    for _ in 0..12 {
        for j in -10..=10 {
            let t = th + span * j as f64 / 10.0;
            if let Some(rr) = first(t) {
                if rr < r {
                    r = rr;
                    th = t;
                }
            }
        }
        span /= 5.0;
    }
    Some((r, a0 + DVec2::from_angle(th) * r))
}

/// The flat face's exact minimum r₀ = max(−(S + S″)) + ρ_min over the whole cycle (never
/// below ρ_min), and max(−(S + S″)) itself.
pub fn min_radius_flat(spec: &CamSpec) -> (f64, f64) {
    let worst = refine_max(spec, dense(spec, DENSE), |phi, after| {
        let m = motion(spec, phi, after);
        -(m.s + m.d2s)
    });
    (worst.max(0.0) + spec.rho_min, worst)
}

/// The smallest radius of curvature of the convex parts of the pitch curve over the whole
/// cycle (the largest admissible roller is just below it), and the most concave one (its
/// smallest |ρ|, `None` when the pitch curve is convex everywhere).
pub fn pitch_rho_min(spec: &CamSpec, place: &Placement) -> (f64, Option<f64>) {
    let mut convex = f64::INFINITY;
    let mut concave: Option<f64> = None;
    for (phi, after) in dense(spec, DENSE) {
        let rho = place.kin(motion(spec, phi, after)).pitch_radius();
        if rho > 0.0 {
            convex = convex.min(rho);
        } else if rho < 0.0 {
            concave = Some(concave.map_or(-rho, |c: f64| c.min(-rho)));
        }
    }
    // The dwells are arcs about O of radius |OB|.
    for m in [
        motion(spec, 0.0, false),
        motion(spec, spec.starts()[1], true),
    ] {
        convex = convex.min(place.kin(m).b.length());
    }
    (convex, concave)
}

/// The smallest translating cam with the offset free (lecture 15's O₁, where the two γ_min
/// tangents meet): the e minimising r₀(e) = √(e² + s₀(e)²) over the whole cycle, by a scan
/// and a golden-section refinement. Returns (r₀, e).
pub fn min_radius_free(spec: &CamSpec) -> (f64, f64) {
    let span = dense(spec, 200)
        .into_iter()
        .map(|(p, a)| motion(spec, p, a).ds.abs())
        .fold(0.0, f64::max)
        .max(spec.stroke);
    let r = |e: f64| min_radius_translating(spec, e).0;
    let steps = 80;
    let (mut best_e, mut best_r) = (0.0, r(0.0));
    for i in 0..=steps {
        let e = -span + 2.0 * span * i as f64 / steps as f64;
        let v = r(e);
        if v < best_r {
            best_r = v;
            best_e = e;
        }
    }
    let h = 2.0 * span / steps as f64;
    let (mut a, mut b) = (best_e - h, best_e + h);
    let g = 0.618_033_988_749_894_9;
    for _ in 0..60 {
        let (x1, x2) = (b - g * (b - a), a + g * (b - a));
        if r(x1) < r(x2) {
            b = x2;
        } else {
            a = x1;
        }
    }
    let e = 0.5 * (a + b);
    let v = r(e);
    if v < best_r {
        (v, e)
    } else {
        (best_r, best_e)
    }
}
