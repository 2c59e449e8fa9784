//! The rocker with a flat face (seed 001 L1548–1552: the mechanisms of fig. 63–65 "may
//! have rockers for followers"): a rocker pivoted at O₂ whose working element is a straight
//! face — through O₂, or at a distance e from it — pressed against the cam turning about O₁.
//!
//! Frame: O₁ at the origin, O₂ at (a, 0); the cam turns counter-clockwise. The face is the
//! line at angle ψ whose distance from O₁ is h(ψ) = a·sin ψ − e (e > 0: the face shifted
//! from O₂ towards O₁). At the start of the rise it touches the base circle r₀: sin ψ₀ =
//! (r₀ + e)/a; the rocker turns by β = σ·S/L (S the arc of the law at the arm L), so that the
//! face always leaves O₁ on the rise. Turned back by −φ (the inversion) the face is the line
//! u(α)·p = h with the outward normal at α = ψ − 90° − φ; the profile is the envelope of
//! these lines.
//!
//! Two routes, sharing the law and the frame only:
//! * [`construct`]: the student's board. Each position's pivot is turned back about O₁ by a
//!   compass notch, its face line drawn at the turned angle ψᵢ − φᵢ and the given offset, and
//!   every line intersected with its neighbours (the drawn dwell's lines beyond a phase's
//!   ends); the contact point is the middle of the two crossings, the radius of the profile
//!   there the crossings' distance over the turn between the neighbours, and the pressure
//!   angle the arm's angle read at the contact (only S at the points is used).
//! * [`exact`]: the envelope in closed form, p = h·u + (dh/dα)·u′, with the radius of
//!   curvature ρ = h + d²h/dα² and tg λ = |e|/t (t the contact's distance along the face from
//!   the foot of O₂), from S, S′ and S″.
//!
//! A face that turns as fast as the cam (σ·S′/L ≥ 1) has no envelope; a base radius too
//! small makes the profile concave (ρ < 0) — both routes say so.

use super::follower::to_cam;
use super::inversion::cam_centre;
use super::motion::{motion, neighbour, points, Motion, Neighbour};
use super::{CamSpec, Follower, RockerSense};
use crate::construct::{ConstructionError, Context, Figure, Item, Recorder, Role};
use crate::geom::{rotate, Arc, Circle, DVec2, Line, Segment};
use crate::scale::Scale;
use std::f64::consts::FRAC_PI_2;
use thiserror::Error;

/// The flat-faced rocker's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlatRocker {
    /// a = O₁O₂, m.
    pub centres: f64,
    /// e: the face's distance from O₂, m (0: the face through O₂; > 0 towards O₁).
    pub face_offset: f64,
    /// r₀: the base circle the face touches on the near dwell, m.
    pub base: f64,
}

/// Why a flat-faced rocker cam cannot be made.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FlatRockerError {
    /// The follower of the law is not a rocker.
    #[error("flat-faced rocker: the law's follower is not a rocker (its arm L is needed)")]
    NotARocker,
    /// The base circle and the offset do not fit between the centres.
    #[error(
        "flat-faced rocker: r₀ + e = {reach:.5} m must lie between 0 and the centre distance \
         a = {centres:.5} m"
    )]
    Frame {
        /// r₀ + e, m.
        reach: f64,
        /// a, m.
        centres: f64,
    },
    /// The face turns as fast as the cam or faster: the lines have no envelope.
    #[error(
        "flat-faced rocker: at φ = {phi_deg:.2}° the face turns at σ·S′/L = {rate:.4} of the \
         cam's speed (≥ 1): its lines have no envelope"
    )]
    Outruns {
        /// φ, degrees.
        phi_deg: f64,
        /// σ·S′/L.
        rate: f64,
    },
    /// A construction step failed (neighbouring face lines parallel).
    #[error("flat-faced rocker: {0}")]
    Construction(#[from] ConstructionError),
}

/// The profile at one cam angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// φ, rad.
    pub phi: f64,
    /// The contact point in the cam's frame, m.
    pub point: DVec2,
    /// The profile's radius of curvature there, m (< 0: concave).
    pub rho: f64,
    /// The pressure angle λ, rad.
    pub lambda: f64,
}

/// The constructed profile.
#[derive(Debug, Clone, PartialEq)]
pub struct Construction {
    /// The drawing at μ_l.
    pub figure: Figure,
    /// The contacts at the points of the law (rise 0 … n, return n + 1 … 2n + 1).
    pub contacts: Vec<Contact>,
}

impl Construction {
    /// The smallest radius of curvature read off the drawing, m.
    pub fn rho_min(&self) -> f64 {
        self.contacts
            .iter()
            .map(|c| c.rho)
            .fold(f64::INFINITY, f64::min)
    }
}

/// The rocker's arm, sense and initial angle ψ₀, checked.
fn frame(spec: &CamSpec, r: &FlatRocker) -> Result<(f64, f64, f64), FlatRockerError> {
    let Follower::Rocker { arm, sense } = spec.follower else {
        return Err(FlatRockerError::NotARocker);
    };
    let reach = r.base + r.face_offset;
    if !(reach > 0.0 && reach < r.centres && arm > 0.0) {
        return Err(FlatRockerError::Frame {
            reach,
            centres: r.centres,
        });
    }
    let first = (reach / r.centres).asin();
    Ok(match sense {
        RockerSense::Same => (arm, 1.0, first),
        RockerSense::Opposite => (arm, -1.0, std::f64::consts::PI - first),
    })
}

/// The face's angle ψ at motion `m` (fixed frame), from the frame's (L, σ, ψ₀).
fn psi(r0: (f64, f64, f64), m: Motion) -> f64 {
    let (arm, sigma, psi0) = r0;
    psi0 + sigma * m.s / arm
}

/// The exact profile at φ (`after`: the piece after a jump of the law).
pub fn exact(
    spec: &CamSpec,
    r: &FlatRocker,
    phi: f64,
    after: bool,
) -> Result<Contact, FlatRockerError> {
    let f = frame(spec, r)?;
    let (arm, sigma, _) = f;
    let m = motion(spec, phi, after);
    let psi = psi(f, m);
    let (p1, p2) = (sigma * m.ds / arm, sigma * m.d2s / arm);
    let a1 = p1 - 1.0;
    if a1 >= 0.0 {
        return Err(FlatRockerError::Outruns {
            phi_deg: phi.to_degrees(),
            rate: p1,
        });
    }
    let a = r.centres;
    let (s, c) = psi.sin_cos();
    let h = a * s - r.face_offset;
    let h1 = a * c * p1;
    let h2 = a * (c * p2 - s * p1 * p1);
    let ha = h1 / a1;
    let haa = (h2 * a1 - h1 * p2) / (a1 * a1 * a1);
    let alpha = psi - FRAC_PI_2 - phi;
    let u = DVec2::from_angle(alpha);
    let point = u * h + u.perp() * ha;
    // The contact in the fixed frame, against the face's direction from the foot of O₂.
    let fixed = rotate(point, phi);
    let dir = DVec2::from_angle(psi);
    let t = (fixed - DVec2::new(a, 0.0)).dot(dir);
    Ok(Contact {
        phi,
        point,
        rho: h + haa,
        lambda: r.face_offset.abs().atan2(t.abs()),
    })
}

/// The face line at φ in the cam's frame (m): through the turned pivot's foot, along the
/// turned face.
fn face_line(a: f64, e: f64, psi: f64, phi: f64) -> (DVec2, DVec2) {
    let pivot = to_cam(DVec2::new(a, 0.0), phi);
    let dir = DVec2::from_angle(psi - phi);
    // The face's foot: from the pivot towards O₁ by e along the face's normal.
    let n = dir.perp();
    let toward = if n.dot(-pivot) >= 0.0 { n } else { -n };
    (pivot + toward * e, dir)
}

/// The profile on the drawing board at μ_l = `mu`.
pub fn construct(
    spec: &CamSpec,
    r: &FlatRocker,
    mu: Scale,
    ctx: &Context,
) -> Result<Construction, FlatRockerError> {
    let f = frame(spec, r)?;
    let (arm, sigma, _) = f;
    let mm = |p: DVec2| p / mu.value();
    let mut rec = Recorder::in_context("flat-faced rocker: profile by inversion", mu, ctx);
    let o1 = cam_centre(&mut rec);
    rec.draw(
        "base circle r_0",
        Item::Circle(Circle {
            center: DVec2::ZERO,
            radius: mu.to_mm(r.base),
        }),
        Role::Construction,
        &[o1],
    );
    let pts = points(spec);
    let line_at = |s: f64, phi: f64| {
        let psi = psi(
            f,
            Motion {
                s,
                ds: 0.0,
                d2s: 0.0,
            },
        );
        face_line(r.centres, r.face_offset, psi, phi)
    };
    let as_line = |(foot, dir): (DVec2, DVec2)| Line {
        point: mm(foot),
        direction: dir,
    };
    let mut lines = Vec::with_capacity(pts.len());
    for (i, p) in pts.iter().enumerate() {
        rec.set_group(i as u32 + 1);
        // S at the point as given (the S diagram's ordinate).
        let s = motion(spec, p.phi, p.after).s;
        let pivot = to_cam(DVec2::new(r.centres, 0.0), p.phi);
        let turned = rec.draw(
            format!("pivot O_2 turned back by φ_{i}"),
            Item::Arc(Arc::notch(DVec2::ZERO, mm(pivot), ctx.notch_mm)),
            Role::Construction,
            &[o1],
        );
        let (foot, dir) = line_at(s, p.phi);
        let half = mu.to_mm(0.6 * r.centres);
        rec.draw(
            format!("face at position {i}"),
            Item::Segment(Segment::new(mm(foot) - dir * half, mm(foot) + dir * half)),
            Role::Construction,
            &[turned],
        );
        if r.face_offset != 0.0 {
            rec.draw(
                format!("offset e of the face at {i}"),
                Item::Segment(Segment::new(mm(pivot), mm(foot))),
                Role::Construction,
                &[turned],
            );
        }
        lines.push((foot, dir));
    }
    // The neighbouring face line before (`forward` false) or after point i.
    let neighbour = |i: usize, forward: bool| match neighbour(spec, &pts, i, forward) {
        Neighbour::Point(j) => lines[j],
        Neighbour::Dwell { phi, s } => line_at(s, phi),
    };
    let mut contacts = Vec::with_capacity(pts.len());
    let mut profile = Vec::with_capacity(pts.len());
    for (i, p) in pts.iter().enumerate() {
        rec.set_group(i as u32 + 1);
        let (before, after) = (as_line(neighbour(i, false)), as_line(neighbour(i, true)));
        let this = as_line(lines[i]);
        let name = format!("face {i}");
        let (q0, _, _) = rec.meet_lines(
            &format!("contact {i}"),
            ("the face before", &before),
            (&name, &this),
        )?;
        let (q1, _, _) = rec.meet_lines(
            &format!("contact {i}"),
            (&name, &this),
            ("the face after", &after),
        )?;
        let point = (q0 + q1) * 0.5 * mu.value();
        // The turn between the neighbours' lines (their directions in the cam frame).
        let turn = after
            .direction
            .perp_dot(before.direction)
            .atan2(after.direction.dot(before.direction));
        if turn <= 0.0 {
            let s1 = motion(spec, p.phi, p.after).ds;
            return Err(FlatRockerError::Outruns {
                phi_deg: p.phi.to_degrees(),
                rate: sigma * s1 / arm,
            });
        }
        // Neighbours turned by δ either side cross this line about ρ·δ/2 from the contact,
        // the earlier one ahead along the face's direction (the profile runs clockwise in
        // the cam frame, against it): ρ = −2·(q₁ − q₀)·d / (δ_a + δ_b), < 0 where concave.
        let along = (q1 - q0).dot(this.direction);
        let rho = -2.0 * along * mu.value() / turn;
        // The pressure angle read at the contact: the face's normal against the arm O₂K's
        // perpendicular.
        let pivot = to_cam(DVec2::new(r.centres, 0.0), p.phi);
        let arm_dir = (point - pivot).normalize_or_zero();
        let lambda = this.direction.dot(arm_dir).abs().clamp(0.0, 1.0).acos();
        contacts.push(Contact {
            phi: p.phi,
            point,
            rho,
            lambda,
        });
        profile.push(mm(point));
    }
    rec.set_group(0);
    rec.draw(
        "practical profile: envelope of the face lines",
        Item::Polyline {
            points: profile,
            closed: true,
        },
        Role::Result,
        &[o1],
    );
    Ok(Construction {
        figure: rec.finish(),
        contacts,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cam::tests::seed000;
    use crate::cam::{Law, Phases};
    use crate::construct::Drafting;
    use crate::scale::Quantity;

    /// A rocker of arm 100 mm swinging 20° by the cosine law, rise and return over 120°.
    fn spec(n: usize) -> CamSpec {
        CamSpec {
            phases: Phases {
                rise: 120f64.to_radians(),
                far: 30f64.to_radians(),
                ret: 120f64.to_radians(),
                near: 90f64.to_radians(),
            },
            rise: Law::Cosine,
            ret: Law::Cosine,
            stroke: 0.1 * 20f64.to_radians(),
            follower: Follower::Rocker {
                arm: 0.1,
                sense: RockerSense::Same,
            },
            divisions: n,
            ..seed000()
        }
    }

    const FRAME: FlatRocker = FlatRocker {
        centres: 0.12,
        face_offset: 0.0,
        base: 0.04,
    };

    fn board(s: &CamSpec, r: &FlatRocker) -> Result<Construction, FlatRockerError> {
        let ctx = Context::for_model_size(300.0, Drafting::EXACT).expect("a context");
        let mu = Scale::new(0.0005, Quantity::Length).expect("a μ");
        construct(s, r, mu, &ctx)
    }

    /// The largest distance of the drawn contacts from the exact ones, m: within the
    /// phases, and at their ends (where the cosine law's S″ jumps, so does ρ: the middle of
    /// the crossings is off by (ρ₊ − ρ₋)·δ/4 there, first order).
    fn deviation(s: &CamSpec, r: &FlatRocker) -> (f64, f64) {
        let b = board(s, r).expect("the construction");
        let mut worst = (0.0_f64, 0.0_f64);
        for (p, c) in points(s).iter().zip(&b.contacts) {
            let e = exact(s, r, p.phi, p.after).expect("the envelope");
            let d = c.point.distance(e.point);
            if p.k == 0 || p.last {
                worst.1 = worst.1.max(d);
            } else {
                worst.0 = worst.0.max(d);
            }
        }
        worst
    }

    #[test]
    fn the_exact_profile_touches_every_face_line_and_turns_by_its_radius() {
        let s = spec(12);
        let (arm, sigma, psi0) = frame(&s, &FRAME).unwrap();
        for k in 1..40 {
            let phi = 0.05 + 0.12 * k as f64;
            let c = exact(&s, &FRAME, phi, false).unwrap();
            let m = motion(&s, phi, false);
            let (foot, dir) = face_line(FRAME.centres, 0.0, psi0 + sigma * m.s / arm, phi);
            assert!(
                (c.point - foot).perp_dot(dir).abs() < 1e-15,
                "on the line at {phi}"
            );
            // Along the profile the point moves along its face line, by ρ per radian of the
            // normal's turn (central differences).
            let d = 1e-5;
            let (a, b) = (
                exact(&s, &FRAME, phi - d, false).unwrap(),
                exact(&s, &FRAME, phi + d, false).unwrap(),
            );
            let chord = b.point - a.point;
            assert!(chord.perp_dot(dir).abs() < 1e-9 * chord.length().max(1e-12));
            let turn = {
                let ma = motion(&s, phi - d, false);
                let mb = motion(&s, phi + d, false);
                (sigma * (mb.s - ma.s) / arm) - 2.0 * d
            };
            let rho = chord.dot(dir) / turn;
            assert!(
                (rho - c.rho).abs() < 1e-6 * c.rho.abs().max(1e-3),
                "ρ at {phi}"
            );
            // The face through O₂: no pressure angle.
            assert!(c.lambda.abs() < 1e-12);
        }
    }

    #[test]
    fn the_board_agrees_with_the_envelope_to_second_order() {
        let errors: Vec<(f64, f64)> = [12, 24, 48]
            .iter()
            .map(|&n| deviation(&spec(n), &FRAME))
            .collect();
        assert!(errors[1].0 < 2e-3 * FRAME.centres, "{errors:?}");
        for w in errors.windows(2) {
            assert!(
                (w[0].0 / w[1].0).log2() > 1.8,
                "within the phases: {errors:?}"
            );
            assert!((w[0].1 / w[1].1).log2() > 0.9, "at the ends: {errors:?}");
        }
    }

    #[test]
    fn the_board_reads_the_radius_and_the_angle_of_an_offset_face() {
        let r = FlatRocker {
            face_offset: 0.015,
            ..FRAME
        };
        let s = spec(48);
        let b = board(&s, &r).unwrap();
        let mut worst = (0.0_f64, 0.0_f64);
        for (p, c) in points(&s).iter().zip(&b.contacts) {
            let e = exact(&s, &r, p.phi, p.after).unwrap();
            if p.k != 0 && !p.last {
                worst.0 = worst.0.max((c.rho - e.rho).abs() / e.rho.abs());
            }
            worst.1 = worst.1.max((c.lambda - e.lambda).abs());
            assert!(e.lambda > 0.05, "an offset face has a pressure angle");
        }
        assert!(worst.0 < 0.01 && worst.1 < 2e-3, "{worst:?}");
    }

    #[test]
    fn a_small_base_circle_is_concave_by_both_routes() {
        // The smallest ρ over a dense sampling against the board's at the points.
        let rho_min = |r: &FlatRocker| {
            (0..=3600)
                .map(|k| {
                    exact(
                        &spec(24),
                        r,
                        k as f64 * std::f64::consts::TAU / 3600.0,
                        false,
                    )
                })
                .map(|c| c.unwrap().rho)
                .fold(f64::INFINITY, f64::min)
        };
        let good = rho_min(&FRAME);
        assert!(good > 0.0);
        let board_good = board(&spec(48), &FRAME).unwrap().rho_min();
        assert!(
            (board_good - good).abs() < 0.02 * good,
            "{board_good} {good}"
        );
        let small = FlatRocker {
            base: 0.004,
            centres: 0.06,
            ..FRAME
        };
        assert!(rho_min(&small) < 0.0);
        assert!(board(&spec(48), &small).unwrap().rho_min() < 0.0);
    }

    #[test]
    fn a_face_that_outruns_the_cam_and_a_frame_that_does_not_fit_are_refused() {
        // A 60° swing of a short arm over 40°: the face turns faster than the cam.
        let fast = CamSpec {
            phases: Phases {
                rise: 40f64.to_radians(),
                far: 140f64.to_radians(),
                ret: 40f64.to_radians(),
                near: 140f64.to_radians(),
            },
            stroke: 0.1 * 60f64.to_radians(),
            ..spec(12)
        };
        let mid = 20f64.to_radians();
        assert!(matches!(
            exact(&fast, &FRAME, mid, false),
            Err(FlatRockerError::Outruns { .. })
        ));
        assert!(matches!(
            board(&fast, &FRAME),
            Err(FlatRockerError::Outruns { .. })
        ));
        let wide = FlatRocker {
            base: 0.13,
            ..FRAME
        };
        assert!(matches!(
            board(&spec(12), &wide),
            Err(FlatRockerError::Frame { .. })
        ));
        let translating = CamSpec {
            follower: Follower::Translating { offset: 0.0 },
            ..spec(12)
        };
        assert_eq!(
            exact(&translating, &FRAME, 0.1, false),
            Err(FlatRockerError::NotARocker)
        );
    }
}
