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
use super::inversion::{cam_centre, rotation};
use super::motion::{motion, neighbour, points, FollowerMotion, Neighbour, Point};
use super::{CamSpec, Follower, RockerSense};
use crate::construct::{ConstructionError, Context, Figure, Item, Recorder, Role, StepId};
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
pub struct RockerContact {
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
pub struct RockerConstruction {
    /// The drawing at μ_l.
    pub figure: Figure,
    /// The contacts at the points of the law (rise 0 … n, return n + 1 … 2n + 1).
    pub contacts: Vec<RockerContact>,
    /// The drawn profile, cam frame, m: its start and its cubic pieces (the French curve
    /// through the contacts along the face lines, the dwells' arcs).
    pub profile: (DVec2, Vec<[DVec2; 3]>),
}

impl RockerConstruction {
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
fn psi(r0: (f64, f64, f64), m: FollowerMotion) -> f64 {
    let (arm, sigma, psi0) = r0;
    psi0 + sigma * m.s / arm
}

/// The face line's support function at motion `m`: h = a·sin ψ − e, dh/dα and d²h/dα²
/// (α the face normal's angle in the cam's frame, dα/dφ = σ·S′/L − 1), with ψ and σ·S′/L;
/// `None` where the face turns as fast as the cam or faster (no envelope).
fn support(f: (f64, f64, f64), r: &FlatRocker, m: FollowerMotion) -> Option<Support> {
    let (arm, sigma, _) = f;
    let psi = psi(f, m);
    let (p1, p2) = (sigma * m.ds / arm, sigma * m.d2s / arm);
    let a1 = p1 - 1.0;
    if a1 >= 0.0 {
        return None;
    }
    let a = r.centres;
    let (s, c) = psi.sin_cos();
    let h = a * s - r.face_offset;
    let h1 = a * c * p1;
    let h2 = a * (c * p2 - s * p1 * p1);
    Some(Support {
        h,
        ha: h1 / a1,
        haa: (h2 * a1 - h1 * p2) / (a1 * a1 * a1),
        psi,
    })
}

/// The face line's support function and its derivatives over the normal's angle.
struct Support {
    h: f64,
    ha: f64,
    haa: f64,
    psi: f64,
}

/// The exact profile at φ (`after`: the piece after a jump of the law).
pub fn exact(
    spec: &CamSpec,
    r: &FlatRocker,
    phi: f64,
    after: bool,
) -> Result<RockerContact, FlatRockerError> {
    let f = frame(spec, r)?;
    let m = motion(spec, phi, after);
    let Some(Support { h, ha, haa, psi }) = support(f, r, m) else {
        return Err(FlatRockerError::Outruns {
            phi_deg: phi.to_degrees(),
            rate: f.1 * m.ds / f.0,
        });
    };
    let alpha = psi - FRAC_PI_2 - phi;
    let u = DVec2::from_angle(alpha);
    let point = u * h + u.perp() * ha;
    // The contact in the fixed frame, against the face's direction from the foot of O₂.
    let fixed = rotate(point, phi);
    let dir = DVec2::from_angle(psi);
    let t = (fixed - DVec2::new(r.centres, 0.0)).dot(dir);
    Ok(RockerContact {
        phi,
        point,
        rho: h + haa,
        lambda: r.face_offset.abs().atan2(t.abs()),
    })
}

/// The profile's smallest radius of curvature over the cycle, m (< 0: concave somewhere):
/// the largest −ρ = −(h + d²h/dα²) on every smooth piece of the law (split at its jumps,
/// each evaluated on its own side), dense samples each refined by golden section
/// ([`super::extremum::max_over`]) — the true minimum, not a sampled one. Refused where the
/// face outruns the cam (the fastest σ·S′/L found the same way).
pub fn exact_rho_min(spec: &CamSpec, r: &FlatRocker) -> Result<f64, FlatRockerError> {
    let f = frame(spec, r)?;
    let pieces = super::extremum::pieces(spec, false);
    let dense = super::exact::DENSE;
    let (rate, piece, u) = super::extremum::max_over(spec, &pieces, dense, |m| f.1 * m.ds / f.0);
    if rate >= 1.0 {
        return Err(FlatRockerError::Outruns {
            phi_deg: piece.phi(spec, u).to_degrees(),
            rate,
        });
    }
    let (worst, _, _) = super::extremum::max_over(spec, &pieces, dense, |m| {
        support(f, r, m).map_or(f64::INFINITY, |s| -(s.h + s.haa))
    });
    Ok(-worst)
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

/// The face lines in the inverted positions, each drawn from the foot of the turned pivot
/// O₂ (with the offset e to it) through its contact and a fifth beyond, so that every line
/// shows the rocker's face reaching the profile it envelopes.
fn draw_faces(
    rec: &mut Recorder,
    r: &FlatRocker,
    mu: Scale,
    pts: &[super::motion::Point],
    (lines, turned): (&[(DVec2, DVec2)], &[crate::construct::StepId]),
    contacts: &[RockerContact],
) {
    let mm = |p: DVec2| p / mu.value();
    for (i, p) in pts.iter().enumerate() {
        rec.set_group(i as u32 + 1);
        let (foot, dir) = lines[i];
        let reach = (contacts[i].point - foot).dot(dir);
        // At least a tenth of the centre distance either way, so a contact at the foot
        // still shows its line.
        let end = reach + reach.signum() * (0.2 * reach.abs()).max(0.1 * r.centres);
        let start = -reach.signum() * 0.1 * r.centres;
        rec.draw(
            format!("face at position {i}"),
            Item::Segment(Segment::new(mm(foot + dir * start), mm(foot + dir * end))),
            Role::Construction,
            &[turned[i]],
        );
        if r.face_offset != 0.0 {
            let pivot = to_cam(DVec2::new(r.centres, 0.0), p.phi);
            rec.draw(
                format!("offset e of the face at {i}"),
                Item::Segment(Segment::new(mm(pivot), mm(foot))),
                Role::Construction,
                &[turned[i]],
            );
        }
    }
}

/// What every step of the profile's construction reads: the scene's law, the rocker's frame
/// (L, σ, ψ₀) and the drawing's μ_l.
struct Board<'a> {
    spec: &'a CamSpec,
    r: &'a FlatRocker,
    frame: (f64, f64, f64),
    mu: Scale,
}

impl Board<'_> {
    /// A point of the cam's frame on the drawing, mm.
    fn mm(&self, p: DVec2) -> DVec2 {
        p / self.mu.value()
    }

    /// The face line (its foot and direction, m) at displacement `s` and cam angle `phi`.
    fn line_at(&self, s: f64, phi: f64) -> (DVec2, DVec2) {
        let psi = psi(
            self.frame,
            FollowerMotion {
                s,
                ds: 0.0,
                d2s: 0.0,
            },
        );
        face_line(self.r.centres, self.r.face_offset, psi, phi)
    }

    /// A face line on the drawing.
    fn as_line(&self, (foot, dir): (DVec2, DVec2)) -> Line {
        Line {
            point: self.mm(foot),
            direction: dir,
        }
    }

    /// The base circle r₀ and the circle the pivot O₂ runs round in the inverted motion
    /// (radius a = O₁O₂).
    fn circles(&self, rec: &mut Recorder, o1: StepId) {
        rec.draw(
            "base circle r_0",
            Item::Circle(Circle {
                center: DVec2::ZERO,
                radius: self.mu.to_mm(self.r.base),
            }),
            Role::Construction,
            &[o1],
        );
        rec.draw(
            "the circle of the pivot O_2 in the inverted motion",
            Item::Circle(Circle {
                center: DVec2::ZERO,
                radius: self.mu.to_mm(self.r.centres),
            }),
            Role::Axis,
            &[o1],
        );
    }

    /// The rocker's pivot O₂ where the frame has it (φ = 0), named below its notch's number.
    fn pivot(&self, rec: &mut Recorder, o1: StepId) {
        let at = self.mm(DVec2::new(self.r.centres, 0.0));
        let id = rec.draw(
            "the rocker's pivot O_2",
            Item::Joint { at, fixed: true },
            Role::Given,
            &[o1],
        );
        rec.label(id, "O_2", at, DVec2::new(0.0, -1.0));
    }

    /// The pivot O₂ turned back by each point's φ (notched on its circle and numbered), and
    /// the face line there: the lines and the notches.
    fn turned_back(
        &self,
        rec: &mut Recorder,
        o1: StepId,
        pts: &[Point],
        notch_mm: f64,
    ) -> (Vec<(DVec2, DVec2)>, Vec<StepId>) {
        let mut lines = Vec::with_capacity(pts.len());
        let mut turned = Vec::with_capacity(pts.len());
        for (i, p) in pts.iter().enumerate() {
            rec.set_group(i as u32 + 1);
            // S at the point as given (the S diagram's ordinate).
            let s = motion(self.spec, p.phi, p.after).s;
            let pivot = self.mm(to_cam(DVec2::new(self.r.centres, 0.0), p.phi));
            let notch = rec.draw(
                format!("pivot O_2 turned back by φ_{i}"),
                Item::Arc(Arc::notch(DVec2::ZERO, pivot, notch_mm)),
                Role::Construction,
                &[o1],
            );
            // Every position numbered outside the circle, as the textbook's inversion numbers
            // the pivot's positions O₂ⁱ.
            rec.label(notch, p.label.clone(), pivot, pivot.normalize_or_zero());
            turned.push(notch);
            lines.push(self.line_at(s, p.phi));
        }
        (lines, turned)
    }

    /// The neighbouring face line before (`forward` false) or after point `i`.
    fn neighbour(&self, pts: &[Point], lines: &[(DVec2, DVec2)], i: usize, forward: bool) -> Line {
        self.as_line(match neighbour(self.spec, pts, i, forward) {
            Neighbour::Point(j) => lines[j],
            Neighbour::Dwell { phi, s } => self.line_at(s, phi),
        })
    }

    /// The contact of face `i` (`this`) with its neighbours `before` and `after`: the middle
    /// of its two crossings, the radius of curvature from their spread, the pressure angle.
    fn contact(
        &self,
        rec: &mut Recorder,
        (i, p): (usize, &Point),
        [before, this, after]: [Line; 3],
    ) -> Result<RockerContact, FlatRockerError> {
        let mu = self.mu.value();
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
        let point = (q0 + q1) * 0.5 * mu;
        // The turn between the neighbours' lines (their directions in the cam frame).
        let turn = after
            .direction
            .perp_dot(before.direction)
            .atan2(after.direction.dot(before.direction));
        if turn <= 0.0 {
            let (arm, sigma, _) = self.frame;
            let s1 = motion(self.spec, p.phi, p.after).ds;
            return Err(FlatRockerError::Outruns {
                phi_deg: p.phi.to_degrees(),
                rate: sigma * s1 / arm,
            });
        }
        // Neighbours turned by δ either side cross this line about ρ·δ/2 from the contact,
        // the earlier one ahead along the face's direction (the profile runs clockwise in
        // the cam frame, against it): ρ = −2·(q₁ − q₀)·d / (δ_a + δ_b), < 0 where concave.
        let along = (q1 - q0).dot(this.direction);
        let rho = -2.0 * along * mu / turn;
        // The pressure angle read at the contact: the face's normal against the arm O₂K's
        // perpendicular.
        let pivot = to_cam(DVec2::new(self.r.centres, 0.0), p.phi);
        let arm_dir = (point - pivot).normalize_or_zero();
        let lambda = this.direction.dot(arm_dir).abs().clamp(0.0, 1.0).acos();
        Ok(RockerContact {
            phi: p.phi,
            point,
            rho,
            lambda,
        })
    }
}

/// The profile on the drawing board at μ_l = `mu`.
pub fn construct(
    spec: &CamSpec,
    r: &FlatRocker,
    mu: Scale,
    ctx: &Context,
) -> Result<RockerConstruction, FlatRockerError> {
    let board = Board {
        spec,
        r,
        frame: frame(spec, r)?,
        mu,
    };
    let mut rec = Recorder::in_context("flat-faced rocker: profile by inversion", mu, ctx);
    let o1 = cam_centre(&mut rec);
    rotation(&mut rec, o1, mu.to_mm(r.base));
    board.circles(&mut rec, o1);
    board.pivot(&mut rec, o1);
    let pts = points(spec);
    let (lines, turned) = board.turned_back(&mut rec, o1, &pts, ctx.notch_mm);
    let mut contacts = Vec::with_capacity(pts.len());
    for (i, p) in pts.iter().enumerate() {
        rec.set_group(i as u32 + 1);
        let (before, after) = (
            board.neighbour(&pts, &lines, i, false),
            board.neighbour(&pts, &lines, i, true),
        );
        let this = board.as_line(lines[i]);
        contacts.push(board.contact(&mut rec, (i, p), [before, this, after])?);
    }
    draw_faces(&mut rec, r, mu, &pts, (&lines, &turned), &contacts);
    rec.set_group(0);
    // The French curve through the contacts, laid along the face line at each (the line
    // touches the profile there), each dwell the arc about O₁.
    let points: Vec<DVec2> = contacts.iter().map(|c| c.point).collect();
    let tangents: Vec<DVec2> = lines.iter().map(|l| l.1).collect();
    let (start, pieces) = super::inversion::closed_profile(&pts, &points, &tangents);
    rec.draw(
        "practical profile: envelope of the face lines",
        Item::Bezier {
            start: board.mm(start),
            pieces: pieces.iter().map(|p| p.map(|q| board.mm(q))).collect(),
            closed: true,
        },
        Role::Result,
        &[o1],
    );
    Ok(RockerConstruction {
        figure: rec.finish(),
        contacts,
        profile: (start, pieces),
    })
}

#[cfg(test)]
mod tests;
