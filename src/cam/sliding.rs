//! The translating cam (seed 001 L1537–1539, fig. 63): the cam slides along its guide and
//! lifts a roller follower that moves across the guide. The law is the rotating cam's, laid
//! along the cam's travel instead of round a turn: the cycle's 2π is the travel X, so the
//! follower's axis stands at ξ = X·φ/2π on the cam and dS/dξ = S′·2π/X.
//!
//! Frame: the cam's own, ξ along its guide (the cam moves towards −ξ, the follower's axis
//! sweeps it towards +ξ), the follower's roller centre at height S above the pitch line
//! η = 0. The pitch curve is B(ξ) = (ξ, S); the practical profile is B − r·n, n the unit
//! normal on the roller's side; the pressure angle is tg λ = |dS/dξ| (the follower moves
//! ⊥ the guide); the pitch curve's radius ρ = (1 + S_ξ²)^{3/2}/|S_ξξ|, and where it is
//! convex (a crest, S_ξξ < 0) the roller must be smaller than ρ or the profile loops
//! (the rotating cam's rule r_р ≤ 0,8·ρ_min).
//!
//! Two routes, sharing the law only:
//! * [`construct`]: the inversion on the board: the follower's axis at every point of the
//!   law, its roller centre at S (only S is used), the roller circles, and the tangency on
//!   each circle along the normal to the chord through the neighbouring centres (across a
//!   phase's end, the drawn dwell one step on); the pressure angle is that normal's angle
//!   to the axis, the pitch curve's radius the circle through three neighbouring centres.
//! * [`exact`]: the closed forms from S, S′ and S″.

use super::motion::{motion, neighbour, points, Neighbour, Point};
use super::CamSpec;
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::{Circle, DVec2, Segment};
use crate::scale::Scale;
use std::f64::consts::TAU;
use thiserror::Error;

/// The translating cam's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sliding {
    /// X: the cam's travel over the law's whole cycle, m.
    pub travel: f64,
    /// r_р: the roller's radius, m (0: a knife edge).
    pub roller: f64,
}

/// Why a translating cam cannot be made.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SlidingError {
    /// The travel or the roller is not a size.
    #[error(
        "translating cam: the travel X = {travel} m must be > 0 and the roller r = {roller} m \
         ≥ 0"
    )]
    Frame {
        /// X, m.
        travel: f64,
        /// r_р, m.
        roller: f64,
    },
}

/// The cam at one point of the law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlidingContact {
    /// ξ of the follower's axis on the cam, m.
    pub xi: f64,
    /// The roller's centre B, cam frame, m.
    pub centre: DVec2,
    /// The practical profile's point (the roller's tangency), cam frame, m.
    pub point: DVec2,
    /// The pressure angle λ, rad.
    pub lambda: f64,
    /// The pitch curve's radius of curvature, m: > 0 convex (a crest), < 0 concave,
    /// infinite where straight.
    pub rho: f64,
}

/// The constructed cam.
#[derive(Debug, Clone, PartialEq)]
pub struct SlidingConstruction {
    /// The drawing at μ_l.
    pub figure: Figure,
    /// The contacts at the law's points (rise 0 … n, return n + 1 … 2n + 1); a contact's ρ
    /// is infinite where the drawing gives no three centres of one phase.
    pub contacts: Vec<SlidingContact>,
}

impl SlidingConstruction {
    /// The smallest convex radius of the drawn pitch curve, m.
    pub fn rho_min(&self) -> f64 {
        convex_min(self.contacts.iter().map(|c| c.rho))
    }
}

/// The smallest of the positive radii (the convex ones); infinite if none.
fn convex_min(rho: impl Iterator<Item = f64>) -> f64 {
    rho.filter(|r| *r > 0.0).fold(f64::INFINITY, f64::min)
}

fn check(s: &Sliding) -> Result<f64, SlidingError> {
    if s.travel > 0.0 && s.travel.is_finite() && s.roller >= 0.0 && s.roller.is_finite() {
        Ok(TAU / s.travel)
    } else {
        Err(SlidingError::Frame {
            travel: s.travel,
            roller: s.roller,
        })
    }
}

/// The exact cam at φ of the law (`after`: the piece after a jump).
pub fn exact(
    spec: &CamSpec,
    s: &Sliding,
    phi: f64,
    after: bool,
) -> Result<SlidingContact, SlidingError> {
    let k = check(s)?;
    let m = motion(spec, phi, after);
    let (d1, d2) = (m.ds * k, m.d2s * k * k);
    let xi = phi / k;
    let centre = DVec2::new(xi, m.s);
    let n = DVec2::new(-d1, 1.0).normalize();
    let rho = if d2 == 0.0 {
        f64::INFINITY
    } else {
        -(1.0 + d1 * d1).powf(1.5) / d2
    };
    Ok(SlidingContact {
        xi,
        centre,
        point: centre - n * s.roller,
        lambda: d1.abs().atan(),
        rho,
    })
}

/// The pitch curve's signed curvature κ = −S_ξξ/(1 + S_ξ²)^{3/2} at motion `m` (> 0 convex,
/// a crest), with `k` = 2π/X the law's radians per metre of travel.
fn curvature(m: super::motion::FollowerMotion, k: f64) -> f64 {
    let (d1, d2) = (m.ds * k, m.d2s * k * k);
    -d2 / (1.0 + d1 * d1).powf(1.5)
}

/// The smallest convex radius of the pitch curve over the cycle, m (infinite where no piece
/// is convex): 1/κ_max, the largest curvature found on every smooth piece of the law (split
/// at its jumps, each evaluated on its own side) by dense samples, each sampled local maximum
/// refined by golden section ([`super::extremum::max_over`]) — the true minimum, not the
/// sampled one.
pub fn exact_rho_min(spec: &CamSpec, s: &Sliding) -> Result<f64, SlidingError> {
    let k = check(s)?;
    let pieces = super::extremum::pieces(spec, false);
    let (kappa, _, _) =
        super::extremum::max_over(spec, &pieces, super::exact::DENSE, |m| curvature(m, k));
    Ok(if kappa > 0.0 {
        1.0 / kappa
    } else {
        f64::INFINITY
    })
}

/// The shortest travel X_min that keeps the pressure angle within `lambda_max` where the
/// scene checks it (the rise only under force closure), m: tg λ = S′·2π/X, so X_min =
/// 2π·max|S′|/tg λ_max, with max|S′| the law's largest over every smooth piece, refined
/// ([`super::extremum::max_over`]).
pub fn exact_travel_min(spec: &CamSpec, lambda_max: f64) -> f64 {
    let pieces = super::extremum::checked_pieces(spec);
    let (v, _, _) = super::extremum::max_over(spec, &pieces, super::exact::DENSE, |m| m.ds.abs());
    TAU * v / lambda_max.tan()
}

/// The note of the cam's travel X dimensioned under its guide, labelled `X`; a sheet writes
/// its value.
pub const TRAVEL_X_NOTE: &str = "dimension X";

/// Under the guide at `low` mm: the travel X (`x_mm` long, from ξ = 0) dimensioned below the
/// phases' numbers, and left of the guide the arrow of the cam's motion V₁, against ξ (in the
/// inverted motion the follower runs along ξ).
fn travel_marks(rec: &mut Recorder, x_mm: f64, low: f64) {
    let start = DVec2::new(0.0, low);
    rec.dimension(
        TRAVEL_X_NOTE,
        (start, DVec2::new(x_mm, low), -X_DIMENSION_MM),
        "X",
    );
    let arrow = rec.draw(
        "the cam's motion V_1",
        Item::Vector {
            from: start - DVec2::X * MOTION_GAP_MM,
            to: start - DVec2::X * (MOTION_GAP_MM + MOTION_MM),
        },
        Role::Given,
        &[],
    );
    rec.label(
        arrow,
        "V_1",
        start - DVec2::X * (MOTION_GAP_MM + 0.5 * MOTION_MM),
        DVec2::Y,
    );
}

/// How far under the guide the travel X is dimensioned, mm (below the phases' numbers).
const X_DIMENSION_MM: f64 = 12.0;
/// The cam's motion arrow: its gap from the guide's start and its length, mm.
const MOTION_GAP_MM: f64 = 4.0;
const MOTION_MM: f64 = 20.0;

/// The cam on the drawing board at μ_l = `mu`.
pub fn construct(
    spec: &CamSpec,
    s: &Sliding,
    mu: Scale,
    ctx: &Context,
) -> Result<SlidingConstruction, SlidingError> {
    let k = check(s)?;
    let mm = |p: DVec2| p / mu.value();
    let mut rec = Recorder::in_context("translating cam: profile by inversion", mu, ctx);
    let low = -s.roller - 0.25 * spec.stroke;
    rec.draw(
        "the cam's guide",
        Item::Segment(Segment::new(
            mm(DVec2::new(0.0, low)),
            mm(DVec2::new(s.travel, low)),
        )),
        Role::Given,
        &[],
    );
    travel_marks(&mut rec, s.travel / mu.value(), mu.to_mm(low));
    let pts = points(spec);
    let centre_of = |p: &Point| DVec2::new(p.phi / k, motion(spec, p.phi, p.after).s);
    let centres: Vec<DVec2> = pts.iter().map(centre_of).collect();
    for (i, c) in centres.iter().enumerate() {
        rec.set_group(i as u32 + 1);
        let axis = rec.draw(
            format!("follower's axis at position {i}"),
            Item::Segment(Segment::new(
                mm(DVec2::new(c.x, low)),
                mm(*c + DVec2::Y * (s.roller + 0.1 * spec.stroke)),
            )),
            Role::Construction,
            &[],
        );
        // The phases' ends numbered under the guide, as the turning cam's rays are.
        let p = &pts[i];
        if p.k == 0 || p.last {
            rec.label(
                axis,
                p.label.clone(),
                mm(DVec2::new(c.x, low)),
                DVec2::NEG_Y,
            );
        }
        rec.point(
            format!("roller centre B_{i}"),
            mm(*c),
            Role::Construction,
            "",
            DVec2::ZERO,
            &[axis],
        );
        if s.roller > 0.0 {
            rec.draw(
                format!("roller at {i}"),
                Item::Circle(Circle {
                    center: mm(*c),
                    radius: mu.to_mm(s.roller),
                }),
                Role::Construction,
                &[axis],
            );
        }
    }
    // The neighbouring centre before (`forward` false) or after point i.
    let neighbour = |i: usize, forward: bool| match neighbour(spec, &pts, i, forward) {
        Neighbour::Point(j) => centres[j],
        Neighbour::Dwell { phi, s } => DVec2::new(phi / k, s),
    };
    let mut contacts = Vec::with_capacity(pts.len());
    let mut pitch = Vec::with_capacity(pts.len());
    let mut profile = Vec::with_capacity(pts.len());
    for (i, &c) in centres.iter().enumerate() {
        let (a, b) = (neighbour(i, false), neighbour(i, true));
        let chord = b - a;
        let n = DVec2::new(-chord.y, chord.x).normalize();
        let point = c - n * s.roller;
        let lambda = n.dot(DVec2::Y).abs().clamp(0.0, 1.0).acos();
        // The circle through three centres of one phase (the drawn dwell's at its ends).
        let cross = (c - a).perp_dot(b - c);
        let rho = if cross == 0.0 {
            f64::INFINITY
        } else {
            -a.distance(c) * c.distance(b) * b.distance(a) / (2.0 * cross)
        };
        contacts.push(SlidingContact {
            xi: c.x,
            centre: c,
            point,
            lambda,
            rho,
        });
        pitch.push(mm(c));
        profile.push(mm(point));
    }
    // The near dwell closes the cycle: the cam ends at ξ = X as it starts at ξ = 0.
    if let (Some(&p0), Some(&q0)) = (pitch.first(), profile.first()) {
        let end = DVec2::new(s.travel / mu.value(), 0.0);
        pitch.push(p0 + end);
        profile.push(q0 + end);
    }
    rec.set_group(0);
    draw_profiles(&mut rec, pitch, profile, mu.to_mm(low));
    Ok(SlidingConstruction {
        figure: rec.finish(),
        contacts,
    })
}

/// The pitch profile and the practical one (the rollers' envelope), and the cam's plate
/// closed: its ends down to the guide it slides on, at `low` mm.
fn draw_profiles(rec: &mut Recorder, pitch: Vec<DVec2>, profile: Vec<DVec2>, low: f64) {
    rec.draw(
        "pitch (theoretical) profile",
        Item::Polyline {
            points: pitch,
            closed: false,
        },
        Role::Construction,
        &[],
    );
    let ends = profile.first().zip(profile.last()).map(|(a, b)| [*a, *b]);
    let practical = rec.draw(
        "practical profile: envelope of the rollers",
        Item::Polyline {
            points: profile,
            closed: false,
        },
        Role::Result,
        &[],
    );
    for (k, end) in ends.into_iter().flatten().enumerate() {
        rec.draw(
            format!("the cam's end {}", k + 1),
            Item::Segment(Segment::new(end, DVec2::new(end.x, low))),
            Role::Result,
            &[practical],
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cam::tests::seed000;
    use crate::cam::{Follower, Law, Phases};
    use crate::construct::Drafting;
    use crate::scale::Quantity;

    /// A 30 mm rise and return by the sine law, each over 120 mm of a 360 mm travel.
    fn spec(n: usize) -> CamSpec {
        CamSpec {
            phases: Phases {
                rise: 120f64.to_radians(),
                far: 60f64.to_radians(),
                ret: 120f64.to_radians(),
                near: 60f64.to_radians(),
            },
            rise: Law::Sine,
            ret: Law::Sine,
            stroke: 0.030,
            follower: Follower::Translating { offset: 0.0 },
            divisions: n,
            ..seed000()
        }
    }

    const CAM: Sliding = Sliding {
        travel: 0.36,
        roller: 0.010,
    };

    fn board(s: &CamSpec, c: &Sliding) -> SlidingConstruction {
        let ctx = Context::for_model_size(400.0, Drafting::EXACT).expect("a context");
        let mu = Scale::new(0.001, Quantity::Length).expect("a μ");
        construct(s, c, mu, &ctx).expect("the construction")
    }

    #[test]
    fn the_exact_profile_is_the_rollers_envelope() {
        let s = spec(12);
        let d = 1e-6;
        for k in 1..60 {
            let phi = 0.1 * k as f64;
            let c = exact(&s, &CAM, phi, false).unwrap();
            assert!((c.point.distance(c.centre) - CAM.roller).abs() < 1e-15);
            // The tangency lies on the pitch curve's normal, and the profile runs parallel
            // to the pitch curve there (both by central differences).
            let (a, b) = (
                exact(&s, &CAM, phi - d, false).unwrap(),
                exact(&s, &CAM, phi + d, false).unwrap(),
            );
            let t = b.centre - a.centre;
            assert!(t.dot(c.point - c.centre).abs() < 1e-9 * t.length() * CAM.roller);
            assert!(t.perp_dot(b.point - a.point).abs() < 1e-9 * t.length_squared());
            assert!((c.lambda - (t.y / t.x).abs().atan()).abs() < 1e-8);
        }
    }

    #[test]
    fn the_board_agrees_with_the_closed_forms_to_second_order() {
        // Within the phases (the sine law's S″ is continuous at the ends too).
        let worst = |n: usize| {
            let s = spec(n);
            let b = board(&s, &CAM);
            let mut w = [0.0_f64; 3];
            for (p, c) in points(&s).iter().zip(&b.contacts) {
                let e = exact(&s, &CAM, p.phi, p.after).unwrap();
                w[0] = w[0].max(c.point.distance(e.point));
                w[1] = w[1].max((c.lambda - e.lambda).abs());
                if e.rho.is_finite() && e.rho.abs() < 1.0 {
                    w[2] = w[2].max((c.rho - e.rho).abs() / e.rho.abs());
                }
            }
            w
        };
        let (a, b) = (worst(24), worst(48));
        assert!(a[0] < 1e-4 && a[1] < 5e-3, "{a:?}");
        for q in 0..3 {
            assert!((a[q] / b[q]).log2() > 1.8, "{a:?} {b:?}");
        }
    }

    #[test]
    fn a_roller_larger_than_the_crests_radius_is_caught_by_both_routes() {
        let s = spec(48);
        let exact_min = exact_rho_min(&s, &CAM).unwrap();
        let drawn_min = board(&s, &CAM).rho_min();
        assert!(
            (drawn_min - exact_min).abs() < 0.01 * exact_min,
            "{drawn_min} {exact_min}"
        );
        // A steep short cam: its crests are sharper than the roller.
        let short = Sliding {
            travel: 0.09,
            ..CAM
        };
        assert!(exact_rho_min(&s, &short).unwrap() < short.roller);
        assert!(board(&s, &short).rho_min() < short.roller);
        assert!(exact_min > CAM.roller);
    }

    /// The true smallest convex radius against an independent dense evaluation. The
    /// trapezoidal law on a short travel: its crest's curvature peaks at a knot of S″ (a
    /// kink), which samples at 2000 per radian — the minimum this function once returned —
    /// reach only near. The evaluation: ρ = −(1 + S_ξ²)^{3/2}/S_ξξ restated from S′ and S″
    /// of the law at 1 600 000 intervals of each moving phase (every knot at k/8 on the
    /// grid), the smallest convex one.
    #[test]
    fn the_smallest_radius_is_the_true_minimum_not_a_sampled_one() {
        let s = CamSpec {
            rise: Law::Trapezoidal,
            ret: Law::Trapezoidal,
            ..spec(12)
        };
        let c = Sliding {
            travel: 0.09,
            ..CAM
        };
        let k = TAU / c.travel;
        let m = 1_600_000;
        let mut dense = f64::INFINITY;
        for phase in [0, 2] {
            for j in 0..=m {
                let d = crate::cam::motion::motion_u(&s, phase, j as f64 / m as f64, j < m);
                let (d1, d2) = (d.ds * k, d.d2s * k * k);
                if d2 < 0.0 {
                    dense = dense.min(-(1.0 + d1 * d1).powf(1.5) / d2);
                }
            }
        }
        let n = (TAU * 2000.0).ceil() as usize;
        let sampled = (0..=n)
            .map(|i| exact(&s, &c, TAU * i as f64 / n as f64, false).unwrap().rho)
            .filter(|r| *r > 0.0)
            .fold(f64::INFINITY, f64::min);
        let found = exact_rho_min(&s, &c).unwrap();
        assert!((found - dense).abs() < 1e-12 * dense, "{found} {dense}");
        // The sampled minimum is too high by ~1e-4 of it (6.3e-4 mm).
        let high = (sampled - found) / found;
        assert!(high > 5e-5 && high < 2e-4, "{high:e}");
        // A law without a crest (the uniform law's straights): no convex radius.
        let straight = CamSpec {
            rise: Law::Uniform,
            ret: Law::Uniform,
            ..spec(12)
        };
        assert_eq!(exact_rho_min(&straight, &CAM).unwrap(), f64::INFINITY);
    }

    /// The cam is a plate: its practical profile's two ends run down to the guide (the
    /// review saw the outline open at both ends).
    #[test]
    fn the_cams_plate_is_closed_down_to_its_guide() {
        let f = board(&spec(12), &CAM).figure;
        let item = |note: &str| {
            f.steps
                .iter()
                .find(|s| s.note == note)
                .map(|s| s.item.clone())
                .expect(note)
        };
        let (Item::Polyline { points, .. }, Item::Segment(guide)) = (
            item("practical profile: envelope of the rollers"),
            item("the cam's guide"),
        ) else {
            panic!("the profile and the guide");
        };
        for (k, end) in [points[0], points[points.len() - 1]].iter().enumerate() {
            let Item::Segment(e) = item(&format!("the cam's end {}", k + 1)) else {
                panic!("an end");
            };
            assert_eq!(e.from, *end);
            assert_eq!((e.to.x, e.to.y), (end.x, guide.from.y));
        }
    }

    #[test]
    fn a_travel_or_roller_that_is_not_a_size_is_refused() {
        for bad in [
            Sliding { travel: 0.0, ..CAM },
            Sliding {
                roller: -0.001,
                ..CAM
            },
            Sliding {
                travel: f64::NAN,
                ..CAM
            },
        ] {
            assert!(matches!(
                exact(&spec(12), &bad, 0.3, false),
                Err(SlidingError::Frame { .. })
            ));
        }
    }
}
