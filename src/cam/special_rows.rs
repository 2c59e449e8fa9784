//! The check of a flat-faced rocker's and a translating cam's construction: every value read
//! off the board against its module's closed form, and the notes (the law, the frame, the
//! hard cases).
//!
//! Flat-faced rocker: the pressure angle and the contact's radius vector per point, the
//! drawn profile's largest distance from the exact envelope, ρ_min of the profile. The
//! translating cam: the pressure angle per point, the profile's deviation, ρ_min of the
//! pitch curve, and the shortest travel X_min that keeps λ ≤ λ_max (constructed on the
//! combined diagram, [`super::travel`]; exact: 2π·max|S′|/tg λ_max).

use super::deviation::interval_samples;
use super::flat_rocker::{self, FlatRocker};
use super::rows::{diagram_rows, law_notes};
use super::sliding::{self, Sliding};
use super::special::{Special, SpecialProfile};
use super::CamError;
use crate::check::notes::cam::{CamNote, SpecialNote};
use crate::check::{self, At, Finding, Key, Method, Row, Symbol};
use crate::geom::{bezier_distance, DVec2};
use std::f64::consts::FRAC_PI_2;

fn row(symbol: Symbol, at: At, subject: &str, (graphical, exact): (f64, f64), scale: f64) -> Row {
    let key = Key {
        symbol,
        subject: subject.to_string(),
        at,
    };
    Row::new(key, Method::Inversion, graphical, exact, scale)
}

impl Special {
    /// The step a value of the results table is read to at `resolution_mm` off the
    /// profile's drawing (μ_l), m: ρ_min and the least travel; `None` when read exactly or
    /// not read (the profile's deviation is a comparison).
    pub fn reading_step(&self, r: &Row, resolution_mm: f64) -> Option<f64> {
        let read = matches!(r.key.symbol, Symbol::CurvatureRadius | Symbol::Length);
        let scene = r.key.at == At::Scene;
        self.scale
            .reading_step(resolution_mm)
            .filter(|_| read && scene)
    }

    /// λ_max = 90° − γ_min.
    pub fn lambda_max(&self) -> f64 {
        FRAC_PI_2 - self.spec.gamma_min
    }

    /// The exact pressure angle at every point, rad.
    pub fn angles_exact(&self) -> Result<Vec<f64>, CamError> {
        self.points
            .iter()
            .map(|p| {
                Ok(match &self.profile {
                    SpecialProfile::FlatRocker { frame, .. } => {
                        flat_rocker::exact(&self.spec, frame, p.phi, p.after)?.lambda
                    }
                    SpecialProfile::Sliding { frame, .. } => {
                        sliding::exact(&self.spec, frame, p.phi, p.after)?.lambda
                    }
                })
            })
            .collect()
    }

    /// The exact smallest radius of curvature: of the flat-faced rocker's profile (< 0:
    /// concave), of the translating cam's pitch curve (its convex crests; infinite if none).
    pub fn exact_rho_min(&self) -> Result<f64, CamError> {
        Ok(match &self.profile {
            SpecialProfile::FlatRocker { frame, .. } => {
                flat_rocker::exact_rho_min(&self.spec, frame)?
            }
            SpecialProfile::Sliding { frame, .. } => sliding::exact_rho_min(&self.spec, frame)?,
        })
    }

    /// The smallest radius of curvature read off the board (as [`Self::exact_rho_min`]).
    pub fn drawn_rho_min(&self) -> f64 {
        match &self.profile {
            SpecialProfile::FlatRocker { board, .. } => board.rho_min(),
            SpecialProfile::Sliding { board, .. } => board.rho_min(),
        }
    }

    /// The drawn profile's largest distance from the exact one, m: the flat-faced rocker's
    /// whole drawn curve (the French curve laid along the face line at each contact, the
    /// dwells' arcs) from the exact envelope along every moving interval — a contact found a
    /// little along its face line is on the profile all the same; the translating cam's
    /// drawn contacts from the exact ones at the points.
    pub fn profile_deviation(&self) -> Result<f64, CamError> {
        let mut worst = 0.0_f64;
        match &self.profile {
            SpecialProfile::FlatRocker { frame, board } => {
                let (start, pieces) = &board.profile;
                let starts = std::iter::once(*start).chain(pieces.iter().map(|p| p[2]));
                let drawn: Vec<(DVec2, [DVec2; 3])> = starts.zip(pieces.iter().copied()).collect();
                let off = |e: DVec2| {
                    (drawn.iter())
                        .map(|(a, piece)| bezier_distance(e, *a, piece))
                        .fold(f64::INFINITY, f64::min)
                };
                for (_, phi, after) in interval_samples(&self.points) {
                    let e = flat_rocker::exact(&self.spec, frame, phi, after)?;
                    worst = worst.max(off(e.point));
                }
            }
            SpecialProfile::Sliding { frame, board, .. } => {
                for (i, p) in self.points.iter().enumerate() {
                    let e = sliding::exact(&self.spec, frame, p.phi, p.after)?;
                    worst = worst.max(board.contacts[i].point.distance(e.point));
                }
            }
        }
        Ok(worst)
    }

    /// The shortest travel keeping λ ≤ λ_max where the scene checks it, m: constructed on
    /// the combined diagram (2π·X_min/2π read, [`super::travel`]) and exact; `None` for the
    /// flat-faced rocker.
    pub fn travel_min(&self) -> Option<(f64, f64)> {
        let SpecialProfile::Sliding { travel, .. } = &self.profile else {
            return None;
        };
        Some((
            travel.graphical,
            sliding::exact_travel_min(&self.spec, self.lambda_max()),
        ))
    }

    /// Every reading against its twin: S, dS/dφ, d²S/dφ² per point (integration), the
    /// pressure angle per point, the flat-faced rocker's contact radius vector per point,
    /// the profile's deviation, ρ_min and the translating cam's X_min (inversion).
    ///
    /// # Errors
    /// A twin that refuses the frame (the board accepted it: a defect).
    pub fn rows(&self) -> Result<Vec<Row>, CamError> {
        let mut out = diagram_rows(&self.spec, &self.points, &self.diagrams);
        let read = self.angles_read();
        let exact = self.angles_exact()?;
        for (i, p) in self.points.iter().enumerate() {
            let at = At::Position(p.label.clone());
            out.push(row(
                Symbol::PressureAngle,
                at,
                "",
                (read[i], exact[i]),
                FRAC_PI_2,
            ));
        }
        let size = match &self.profile {
            SpecialProfile::FlatRocker { frame, board } => {
                for (p, c) in self.points.iter().zip(&board.contacts) {
                    let e = flat_rocker::exact(&self.spec, frame, p.phi, p.after)?;
                    let at = At::Position(p.label.clone());
                    let pair = (c.point.length(), e.point.length());
                    out.push(row(Symbol::ProfileRadius, at, "", pair, frame.centres));
                }
                frame.centres
            }
            SpecialProfile::Sliding { frame, .. } => frame.travel,
        };
        let deviation = (self.profile_deviation()?, 0.0);
        out.push(row(
            Symbol::ProfileDeviation,
            At::Scene,
            "",
            deviation,
            size,
        ));
        let rho = self.exact_rho_min()?;
        if rho.is_finite() {
            let pair = (self.drawn_rho_min(), rho);
            out.push(row(
                Symbol::CurvatureRadius,
                At::Scene,
                "min",
                pair,
                rho.abs(),
            ));
        }
        if let Some((read, exact)) = self.travel_min() {
            out.push(row(
                Symbol::Length,
                At::Scene,
                "travel_min",
                (read, exact),
                exact,
            ));
        }
        Ok(out)
    }

    /// The verdicts of the notes.
    pub fn findings(&self) -> Result<Vec<Finding>, CamError> {
        Ok(check::notes::cam::findings(&self.noted()?))
    }

    /// The notes: the law and its diagrams, the frame, ρ_min exact and drawn, the largest
    /// pressure angle against λ_max, and the hard cases (a concave flat-faced profile, a
    /// roller larger than a crest's radius).
    pub fn noted(&self) -> Result<Vec<CamNote>, CamError> {
        let mut out = law_notes(&self.spec, &self.points, &self.diagrams);
        let rho = self.exact_rho_min()?;
        let drawn = self.drawn_rho_min();
        match &self.profile {
            SpecialProfile::FlatRocker { frame, .. } => {
                out.extend(self.flat_rocker_notes(frame, rho, drawn)?);
            }
            SpecialProfile::Sliding { frame, .. } => {
                out.extend(self.sliding_notes(frame, rho, drawn));
            }
        }
        Ok(out)
    }

    fn flat_rocker_notes(
        &self,
        r: &FlatRocker,
        rho: f64,
        drawn: f64,
    ) -> Result<Vec<CamNote>, CamError> {
        let psi0 = ((r.base + r.face_offset) / r.centres).asin();
        let mut out = vec![
            SpecialNote::RockerFrame {
                centres: r.centres,
                face_offset: r.face_offset,
                base: r.base,
                psi0,
            },
            SpecialNote::RockerCurvature {
                exact: rho,
                read: drawn,
                points: self.points.len(),
            },
        ];
        let worst = self.angles_exact()?.into_iter().fold(0.0, f64::max);
        out.push(SpecialNote::RockerAngle(worst));
        if rho < self.spec.rho_min {
            out.push(SpecialNote::Concave {
                rho,
                asked: self.spec.rho_min,
            });
        }
        Ok(out.into_iter().map(CamNote::Special).collect())
    }

    fn sliding_notes(&self, s: &Sliding, rho: f64, drawn: f64) -> Vec<CamNote> {
        let mut out = vec![CamNote::Special(SpecialNote::Sliding {
            travel: s.travel,
            roller: s.roller,
        })];
        let lambda_max = self.lambda_max();
        let worst = self
            .angles_exact()
            .map(|a| a.into_iter().fold(0.0, f64::max))
            .unwrap_or(f64::NAN);
        if let Some((read, exact)) = self.travel_min() {
            out.push(CamNote::Special(SpecialNote::SlidingAngle {
                worst,
                lambda_max,
                exact,
                read,
            }));
            if exact > s.travel * (1.0 + 1e-9) {
                out.push(CamNote::Special(SpecialNote::ShortTravel {
                    travel: s.travel,
                    x_min: exact,
                    lambda_max,
                }));
            }
        }
        if rho.is_finite() {
            out.push(CamNote::Special(SpecialNote::SlidingCurvature {
                exact: rho,
                read: drawn,
            }));
            if s.roller > rho {
                out.push(CamNote::Found(Finding::Undercut {
                    roller: s.roller,
                    rho_min: rho,
                }));
            }
        }
        out
    }
}
