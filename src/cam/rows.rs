//! The check of a cam: every value read off its constructions against the analytic twin,
//! the profile's deviation from the exact envelope ([`super::deviation`]), and the notes
//! (shocks, the equal-return check, the roller's choice, every hard case detected, a
//! source's inconsistent r_min).

use super::construct::Cam;
use super::deviation::{deviation, exact_profile};
use super::diagrams::CamDiagrams;
use super::exact;
use super::follower::{to_cam, Placement};
use super::motion::Point;
use super::motion::{motion, FollowerMotion};
use super::{CamSpec, Closure, Follower, Given, Law, Rotation, Shock};
use crate::check::notes::cam::{AngleCheck, CamNote, CamPhase, LawName, Shocks};
use crate::check::{
    self, At, BaseUsed, Cusp, Finding, Key, Limit, Method, RadiusBasis, Row, Symbol,
};
use crate::geom::DVec2;
use std::f64::consts::FRAC_PI_2;

fn row(symbol: Symbol, at: At, method: Method, graphical: f64, analytic: f64, scale: f64) -> Row {
    let key = Key {
        symbol,
        subject: String::new(),
        at,
    };
    Row::new(key, method, graphical, analytic, scale)
}

fn subject(mut r: Row, s: &str) -> Row {
    r.key.subject = s.to_string();
    r
}

impl Cam {
    fn flat(&self) -> bool {
        matches!(self.spec.follower, Follower::Flat { .. })
    }

    /// The step a value of the results table is read to at `resolution_mm` on its drawing,
    /// m: r_min off the combined diagram (μ_S), ρ_min off the profile (μ_l); `None` when
    /// read exactly or not read (the roller is chosen by its rule, the profile's deviation
    /// is a comparison).
    pub fn reading_step(&self, r: &Row, resolution_mm: f64) -> Option<f64> {
        if r.key.at != At::Scene {
            return None;
        }
        match (r.method, r.key.symbol) {
            (Method::CombinedDiagram, _) => self.r_min_step(resolution_mm),
            (_, Symbol::CurvatureRadius) => self.rho_min_step(resolution_mm),
            _ => None,
        }
    }

    /// The step r_min is read to at `resolution_mm` off the combined diagram (μ_S), m;
    /// `None` when read exactly.
    pub fn r_min_step(&self, resolution_mm: f64) -> Option<f64> {
        self.diagrams.s_scale.reading_step(resolution_mm)
    }

    /// The step ρ_min is read to at `resolution_mm` off the profile (μ_l), m; `None` when
    /// read exactly.
    pub fn rho_min_step(&self, resolution_mm: f64) -> Option<f64> {
        self.inversion.scale.reading_step(resolution_mm)
    }

    /// The exact motion at every point.
    pub fn exact_motion(&self) -> Vec<FollowerMotion> {
        self.points
            .iter()
            .map(|p| motion(&self.spec, p.phi, p.after))
            .collect()
    }

    /// The exact pitch-curve points (cam frame).
    pub fn exact_centres(&self) -> Vec<DVec2> {
        self.points
            .iter()
            .map(|p| {
                to_cam(
                    self.placement.kin(motion(&self.spec, p.phi, p.after)).b,
                    p.phi,
                )
            })
            .collect()
    }

    /// The pressure (translating) or transmission (rocker) angle read off the drawing at
    /// point `i`, rad: the inversion reads the pressure angle, the transmission angle is its
    /// complement.
    pub fn angle_read(&self, i: usize) -> f64 {
        let pressure = self.inversion.angle(i);
        if self.spec.shows_transmission_angle() {
            FRAC_PI_2 - pressure
        } else {
            pressure
        }
    }

    /// The exact pressure (translating) or transmission (rocker) angle at φ, rad.
    pub fn angle_at(&self, phi: f64, after: bool) -> f64 {
        let k = self.placement.kin(motion(&self.spec, phi, after));
        if self.spec.shows_transmission_angle() {
            k.transmission_angle()
        } else {
            k.pressure_angle()
        }
    }

    /// The extreme angle over the whole cycle (the rise only under force closure): the
    /// largest pressure angle or the smallest transmission angle, rad, over every smooth
    /// piece, refined.
    pub fn worst_angle(&self) -> f64 {
        let pieces = super::extremum::checked_pieces(&self.spec);
        let rocker = self.spec.shows_transmission_angle();
        let (v, _, _) = super::extremum::max_over(&self.spec, &pieces, exact::DENSE, |m| {
            let k = self.placement.kin(m);
            if rocker {
                -k.transmission_angle()
            } else {
                k.pressure_angle()
            }
        });
        if rocker {
            -v
        } else {
            v
        }
    }

    /// The twin's minimum base radius over the whole cycle, m, from the closed forms (the
    /// construction's is read at its points, [`super::RadiusConstruction::graphical`]):
    /// translating, rocker (infinite when no centre within [`super::follower::REACH_ARMS`]
    /// arms qualifies), flat face (convexity plus ρ_min).
    pub fn exact_r_min(&self) -> f64 {
        match self.spec.follower {
            Follower::Translating { offset } => exact::min_radius_translating(&self.spec, offset).0,
            Follower::Rocker { .. } => {
                exact::min_radius_rocker(&self.spec).map_or(f64::INFINITY, |(r, _)| r)
            }
            Follower::Flat { .. } => exact::min_radius_flat(&self.spec).0,
        }
    }

    /// The twin's rocker centre distance a_w = |O₁O₂| at its exact r_min, m; `None` for
    /// another follower or when no centre qualifies.
    pub fn exact_centre_distance(&self) -> Option<f64> {
        match self.spec.follower {
            Follower::Rocker { .. } => {
                exact::min_radius_rocker(&self.spec).map(|(_, o)| o.length())
            }
            _ => None,
        }
    }

    /// The note's words for the base radius the profile is built on: the scene's, or the
    /// r_min read off the drawing against the twin's `exact`.
    fn base_used(&self, exact: f64) -> BaseUsed {
        if self.spec.base_radius.is_some() {
            return BaseUsed::Given;
        }
        BaseUsed::Read {
            points: self.points.len(),
            used: self.base,
            exact,
        }
    }

    /// What r_min follows from: the profile's convexity (flat face) or γ_min on the rise
    /// (force closure) or over the cycle.
    pub fn radius_basis(&self) -> RadiusBasis {
        let s = &self.spec;
        if self.flat() {
            RadiusBasis::Convexity { rho_min: s.rho_min }
        } else if s.closure == Closure::Force {
            RadiusBasis::AngleOnRise {
                gamma_min: s.gamma_min,
            }
        } else {
            RadiusBasis::AngleOverCycle {
                gamma_min: s.gamma_min,
            }
        }
    }

    /// The exact smallest convex radius of curvature, to rounding: of the pitch curve
    /// (roller, knife edge), of the profile r₀ + S + S″ (flat face).
    pub fn exact_rho_min(&self) -> f64 {
        if self.flat() {
            self.base - exact::min_radius_flat(&self.spec).1
        } else {
            exact::pitch_rho_min(&self.spec, &self.placement).0
        }
    }

    /// The profile's deviation from the exact envelope, m.
    pub fn profile_deviation(&self) -> f64 {
        deviation(
            &self.spec,
            &self.points,
            &self.inversion,
            &self.placement,
            self.base,
            self.roller,
        )
        .0
    }

    /// Every reading against its twin: S, dS/dφ, d²S/dφ² per point (integration), r_min
    /// (combined diagram), the pressure or transmission angle and the profile's radius
    /// vector per point, the profile deviation, ρ_min and the admissible roller (inversion).
    pub fn rows(&self) -> Vec<Row> {
        let mut out = diagram_rows(&self.spec, &self.points, &self.diagrams);
        let r = &self.radius;
        let r_exact = self.exact_r_min();
        out.push(subject(
            row(
                Symbol::Radius,
                At::Scene,
                Method::CombinedDiagram,
                r.graphical,
                r_exact,
                r_exact,
            ),
            "min",
        ));
        if let (Some(g), Some(a)) = (r.centre_distance, self.exact_centre_distance()) {
            out.push(subject(
                row(
                    Symbol::CentreDistance,
                    At::Scene,
                    Method::CombinedDiagram,
                    g,
                    a,
                    a,
                ),
                "w",
            ));
        }
        if !self.flat() {
            let symbol = if self.spec.shows_transmission_angle() {
                Symbol::TransmissionAngle
            } else {
                Symbol::PressureAngle
            };
            for (i, p) in self.points.iter().enumerate() {
                let g = self.angle_read(i);
                let a = self.angle_at(p.phi, p.after);
                out.push(row(
                    symbol,
                    At::Position(p.label.clone()),
                    Method::Inversion,
                    g,
                    a,
                    FRAC_PI_2,
                ));
            }
        }
        let scale = self.base + self.spec.stroke;
        for (i, p) in self.points.iter().enumerate() {
            let e = exact_profile(
                &self.spec,
                &self.placement,
                self.base,
                self.roller,
                p.phi,
                p.after,
            );
            out.push(row(
                Symbol::ProfileRadius,
                At::Position(p.label.clone()),
                Method::Inversion,
                self.inversion.profile[i].length(),
                e.length(),
                scale,
            ));
        }
        out.push(row(
            Symbol::ProfileDeviation,
            At::Scene,
            Method::Inversion,
            self.profile_deviation(),
            0.0,
            scale,
        ));
        let rho = self.exact_rho_min();
        out.push(subject(
            row(
                Symbol::CurvatureRadius,
                At::Scene,
                Method::Inversion,
                self.inversion.rho_min,
                rho,
                rho.abs(),
            ),
            "min",
        ));
        // The roller the drawing took (0.4·r₀ or 0.8·ρ_min read off the pitch curve) against
        // the same rule on the exact ρ_min, at the same r₀; a roller the scene gives is a
        // datum, not a result.
        if !self.flat() && self.spec.roller.is_none() {
            let a = super::roller_bound(self.base, rho);
            out.push(subject(
                row(
                    Symbol::Radius,
                    At::Scene,
                    Method::Inversion,
                    self.roller,
                    a,
                    a,
                ),
                "roller",
            ));
        }
        out
    }

    /// The verdicts of the notes.
    pub fn findings(&self) -> Vec<Finding> {
        check::notes::cam::findings(&self.noted())
    }

    /// The notes: laws and shocks, the assumed law, the equal-return check, r_min against a
    /// quoted value, the roller's choice, and every hard case detected.
    pub fn noted(&self) -> Vec<CamNote> {
        let s = &self.spec;
        let mut out = Vec::new();
        if self.rotation == Rotation::Cw {
            out.push(CamNote::Mirrored);
        }
        out.extend(law_notes(s, &self.points, &self.diagrams));
        let r_exact = self.exact_r_min();
        let basis = self.radius_basis();
        out.push(CamNote::RMin {
            exact: r_exact,
            basis,
            read: self.radius.graphical,
            points: self.points.len(),
        });
        if let Some(quoted) = s.quoted_r_min {
            out.push(CamNote::Found(Finding::Erratum {
                quoted,
                exact: r_exact,
                basis,
            }));
        }
        out.extend(self.flat_face_notes());
        out.extend(self.curvature_notes(r_exact));
        out.extend(self.offset_notes(r_exact));
        out
    }

    /// A flat face's notes: the convexity's worst value against the one read at the 45°
    /// tangent, and the face's half-length.
    fn flat_face_notes(&self) -> Vec<CamNote> {
        let s = &self.spec;
        let mut out = Vec::new();
        if let Some(read) = self.radius.convexity {
            let (_, worst) = exact::min_radius_flat(s);
            out.push(CamNote::FlatConvexity { exact: worst, read });
            let half = exact::dense(s, 500)
                .into_iter()
                .map(|(p, a)| (motion(s, p, a).ds - s.offset()).abs())
                .fold(0.0, f64::max);
            out.push(CamNote::FlatHalfLength(half));
        }
        out
    }

    /// The notes on the profile's curvature: a flat face's cusp; or the worst pressure
    /// (transmission) angle against its limit, the roller's choice, its cusp or undercut.
    fn curvature_notes(&self, r_exact: f64) -> Vec<CamNote> {
        let s = &self.spec;
        let mut out = Vec::new();
        let rho = self.exact_rho_min();
        if self.flat() {
            if rho < 0.0 {
                out.push(CamNote::from(Cusp::Flat {
                    rho,
                    base: self.base,
                    r_min: r_exact,
                }));
            }
        } else {
            let worst = self.worst_angle();
            let (what, limit, passed) = if self.spec.shows_transmission_angle() {
                (
                    Limit::TransmissionAngle,
                    s.gamma_min,
                    worst < s.gamma_min - 1e-9,
                )
            } else {
                (
                    Limit::PressureAngle,
                    s.angle_limit(),
                    worst > s.angle_limit() + 1e-9,
                )
            };
            out.push(CamNote::Angle(AngleCheck {
                what,
                on_rise: s.closure == Closure::Force,
                worst,
                limit,
                exceeded: passed.then(|| self.base_used(r_exact)),
            }));
            out.push(CamNote::Roller {
                base: self.base,
                drawn: self.inversion.rho_min,
                exact: rho,
                roller: self.roller,
                given: s.roller.is_some(),
            });
            let (roller, rho_min) = (self.roller, rho);
            if (roller - rho).abs() <= 1e-12 * rho {
                out.push(CamNote::from(Cusp::Roller { roller, rho_min }));
            } else if roller > rho {
                out.push(CamNote::Found(Finding::Undercut { roller, rho_min }));
            }
        }
        out
    }

    /// A translating follower's notes: the smallest cam with the offset free, and an offset
    /// on the wrong side.
    fn offset_notes(&self, r_exact: f64) -> Vec<CamNote> {
        let s = &self.spec;
        let st = s.starts();
        let mut out = Vec::new();
        if let Follower::Translating { offset } = s.follower {
            let (r_free, e_free) = exact::min_radius_free(s);
            out.push(CamNote::OffsetFree {
                r_min: r_free,
                offset: self.scene_offset(e_free),
                scene_offset: self.scene_offset(offset),
                scene_r_min: r_exact,
            });
            if offset < 0.0 {
                let mirrored = Placement::Translating {
                    offset: -offset,
                    s0: match self.placement {
                        Placement::Translating { s0, .. } => s0,
                        Placement::Rocker { .. } => 0.0,
                    },
                };
                let rise_max = |p: &Placement| {
                    exact::dense(s, 500)
                        .into_iter()
                        .filter(|&(phi, _)| phi <= st[1])
                        .map(|(phi, a)| p.kin(motion(s, phi, a)).pressure_angle())
                        .fold(0.0, f64::max)
                };
                out.push(CamNote::Found(Finding::WrongSide {
                    offset: self.scene_offset(offset),
                    rise_max: rise_max(&self.placement),
                    other_offset: self.scene_offset(-offset),
                    other_max: rise_max(&mirrored),
                }));
            }
        }
        out
    }
}

/// S, dS/dφ, d²S/dφ² per point read off the diagrams against the law (integrated from
/// d²S/dφ², or differentiated from S by chords), each against its largest exact value.
pub(super) fn diagram_rows(spec: &CamSpec, points: &[Point], d: &CamDiagrams) -> Vec<Row> {
    let ex: Vec<FollowerMotion> = points
        .iter()
        .map(|p| motion(spec, p.phi, p.after))
        .collect();
    let big = |f: fn(&FollowerMotion) -> f64| ex.iter().map(|m| f(m).abs()).fold(0.0, f64::max);
    let (ss, sv, sa) = (big(|m| m.s), big(|m| m.ds), big(|m| m.d2s));
    let method = if spec.given == Given::S {
        Method::DiagramChords
    } else {
        Method::Integration
    };
    let mut out = Vec::with_capacity(3 * points.len());
    for (i, p) in points.iter().enumerate() {
        let at = || At::Position(p.label.clone());
        let e = ex[i];
        out.push(row(Symbol::Displacement, at(), method, d.s[i], e.s, ss));
        out.push(row(
            Symbol::VelocityAnalogue,
            at(),
            method,
            d.ds[i],
            e.ds,
            sv,
        ));
        out.push(row(
            Symbol::AccelerationAnalogue,
            at(),
            method,
            d.d2s[i],
            e.d2s,
            sa,
        ));
    }
    out
}

/// The notes of the law and its diagrams: each phase's law and shocks, an assumed law, the
/// equal-return check read off the diagrams.
pub(super) fn law_notes(s: &CamSpec, points: &[Point], d: &CamDiagrams) -> Vec<CamNote> {
    let mut out = Vec::new();
    let st = s.starts();
    for (phase, law, from, to) in [
        (CamPhase::Rise, s.rise, st[0], st[1]),
        (CamPhase::Return, s.ret, st[2], st[3]),
    ] {
        let name = match law {
            Law::ConstantAcceleration { ratio } => LawName::ConstantAcceleration { ratio },
            other => LawName::Key(other.key()),
        };
        let shocks = match law.shock() {
            Shock::Rigid => Shocks::Rigid {
                jump: s.stroke / (to - from),
            },
            Shock::Soft => Shocks::Soft,
            Shock::None => Shocks::None,
        };
        out.push(CamNote::Law {
            phase,
            from,
            to,
            law: name,
            shocks,
        });
    }
    if s.law_assumed {
        out.push(CamNote::LawAssumed {
            rise: s.rise.key(),
            ret: s.ret.key(),
        });
    }
    let top = points
        .iter()
        .position(|p| p.last)
        .and_then(|i| d.s.get(i))
        .copied()
        .unwrap_or(0.0);
    out.push(CamNote::EqualReturn {
        ends: d.ds_ends,
        top,
        stroke: s.stroke,
    });
    out
}
