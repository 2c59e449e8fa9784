//! The check of a cam: every value read off its constructions against the analytic twin,
//! the profile's deviation from the exact envelope, and the notes (shocks, the equal-return
//! check, the roller's choice, every hard case detected, a source's inconsistent r_min).

use super::construct::Cam;
use super::exact;
use super::follower::{flat_contact, to_cam, Placement};
use super::inversion::{invert, Inversion};
use super::motion::{motion, points, Motion, Point};
use super::{CamError, CamSpec, Closure, Follower, Given, Law, Rotation, Shock};
use crate::check::{At, Key, Method, Row, Symbol};
use crate::construct::Context;
use crate::geom::DVec2;
use crate::scale::{format_sig, Lang};
use std::f64::consts::FRAC_PI_2;

/// A number in a note: 5 significant digits.
fn num(x: f64) -> String {
    format_sig(x, 5, Lang::En)
}
/// A length in mm in a note.
fn mm(x: f64) -> String {
    format_sig(x * 1e3, 5, Lang::En)
}
/// Two lengths in mm in a note, with as many significant digits (5 to 15) as tell them
/// apart.
fn mm_pair(a: f64, b: f64) -> (String, String) {
    for digits in 5..15 {
        let (x, y) = (
            format_sig(a * 1e3, digits, Lang::En),
            format_sig(b * 1e3, digits, Lang::En),
        );
        if x != y {
            return (x, y);
        }
    }
    (
        format_sig(a * 1e3, 15, Lang::En),
        format_sig(b * 1e3, 15, Lang::En),
    )
}
/// An angle in degrees in a note.
fn deg(x: f64) -> String {
    format_sig(x.to_degrees(), 4, Lang::En)
}

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

/// The exact practical-profile point at φ (cam frame): the roller's tangency or the flat
/// face's contact.
pub fn exact_profile(
    spec: &CamSpec,
    place: &Placement,
    base: f64,
    roller: f64,
    phi: f64,
    after: bool,
) -> DVec2 {
    let m = motion(spec, phi, after);
    let q = if matches!(spec.follower, Follower::Flat { .. }) {
        flat_contact(base, m).0
    } else {
        place.kin(m).roller_point(roller)
    };
    to_cam(q, phi)
}

/// Distance from `p` to the segment [a, b].
fn to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let d = b - a;
    let t = if d.length_squared() > 0.0 {
        ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + d * t)
}

/// The largest and the mean normal distance between the drawn practical profile (the French
/// curve between its points within each moving phase; the dwells are exact arcs) and the
/// exact envelope, m.
pub fn deviation(
    cam_spec: &CamSpec,
    points: &[Point],
    inv: &Inversion,
    place: &Placement,
    base: f64,
    roller: f64,
) -> (f64, f64) {
    let (mut worst, mut sum, mut count) = (0.0f64, 0.0, 0usize);
    for i in 0..points.len().saturating_sub(1) {
        let (p, q) = (&points[i], &points[i + 1]);
        if p.phase != q.phase {
            continue;
        }
        let curve = crate::geom::french_curve(
            inv.profile[i],
            inv.tangents[i],
            inv.profile[i + 1],
            inv.tangents[i + 1],
            super::inversion::CURVE_PIECES,
        );
        for j in 0..=16 {
            let phi = p.phi + (q.phi - p.phi) * j as f64 / 16.0;
            let after = j == 0 && p.after;
            let e = exact_profile(cam_spec, place, base, roller, phi, after);
            let d = curve
                .windows(2)
                .map(|w| to_segment(e, w[0], w[1]))
                .fold(f64::INFINITY, f64::min);
            worst = worst.max(d);
            sum += d;
            count += 1;
        }
    }
    (worst, sum / count.max(1) as f64)
}

/// The profile by inversion at `n` intervals per moving phase (2n + 2 positions) from the
/// exact law, as read at drafting 0: the bench's sweep. Returns the task at that resolution,
/// its points and the inversion.
///
/// # Errors
/// As [`super::build`]'s inversion.
pub fn inversion_at(
    cam: &Cam,
    n: usize,
    ctx: &Context,
) -> Result<(CamSpec, Vec<Point>, Inversion), CamError> {
    let mut spec = cam.spec.clone();
    spec.divisions = n.max(2);
    let points = points(&spec);
    let read: Vec<Motion> = points
        .iter()
        .map(|p| motion(&spec, p.phi, p.after))
        .collect();
    let inv = invert(
        &spec,
        &points,
        &read,
        &cam.placement,
        cam.base,
        cam.roller,
        ctx,
    )?;
    Ok((spec, points, inv))
}

/// [`inversion_at`] and the largest deviation of its profile from the exact envelope, m.
///
/// # Errors
/// As [`inversion_at`].
pub fn deviation_at(cam: &Cam, n: usize, ctx: &Context) -> Result<(Inversion, f64), CamError> {
    let (spec, points, inv) = inversion_at(cam, n, ctx)?;
    let (dev, _) = deviation(&spec, &points, &inv, &cam.placement, cam.base, cam.roller);
    Ok((inv, dev))
}

impl Cam {
    /// Whether the follower is a rocker (transmission angles) or translating (pressure).
    fn rocker(&self) -> bool {
        matches!(self.spec.follower, Follower::Rocker { .. })
    }
    fn flat(&self) -> bool {
        matches!(self.spec.follower, Follower::Flat { .. })
    }

    /// The exact motion at every point.
    pub fn exact_motion(&self) -> Vec<Motion> {
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

    /// The exact pressure (translating) or transmission (rocker) angle at φ, rad.
    pub fn angle_at(&self, phi: f64, after: bool) -> f64 {
        let k = self.placement.kin(motion(&self.spec, phi, after));
        if self.rocker() {
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
        let rocker = self.rocker();
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

    /// The note's words for the base radius the profile is built on: the scene's, or the
    /// r_min read off the drawing against the twin's `exact`.
    fn base_used(&self, exact: f64) -> String {
        if self.spec.base_radius.is_some() {
            return "at the given base radius".into();
        }
        let how = if self.base < exact {
            "below"
        } else {
            "against"
        };
        let (used, exact) = mm_pair(self.base, exact);
        format!(
            "at the base radius used (read off the combined diagram at its {} points, {used} mm, {how} the exact {exact} mm)",
            self.points.len()
        )
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
        let mut out = Vec::new();
        let ex = self.exact_motion();
        let big = |f: fn(&Motion) -> f64| ex.iter().map(|m| f(m).abs()).fold(0.0, f64::max);
        let (ss, sv, sa) = (big(|m| m.s), big(|m| m.ds), big(|m| m.d2s));
        let d = &self.diagrams;
        // The diagrams integrated from d²S/dφ², or differentiated from S by chords.
        let method = if self.spec.given == Given::S {
            Method::DiagramChords
        } else {
            Method::Integration
        };
        for (i, p) in self.points.iter().enumerate() {
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
        if !self.flat() {
            let symbol = if self.rocker() {
                Symbol::TransmissionAngle
            } else {
                Symbol::PressureAngle
            };
            for (i, p) in self.points.iter().enumerate() {
                let g = self.inversion.angles[i];
                let g = if self.rocker() { FRAC_PI_2 - g } else { g };
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
        if !self.flat() {
            let g = (0.4 * r.graphical).min(0.8 * self.inversion.rho_min);
            let a = (0.4 * r_exact).min(0.8 * rho);
            out.push(subject(
                row(Symbol::Radius, At::Scene, Method::Inversion, g, a, a),
                "roller",
            ));
        }
        out
    }

    /// The notes: laws and shocks, the assumed law, the equal-return check, r_min against a
    /// quoted value, the roller's choice, and every hard case detected.
    pub fn notes(&self) -> Vec<String> {
        let s = &self.spec;
        let mut out = Vec::new();
        if self.rotation == Rotation::Cw {
            out.push(
                "cam: it turns clockwise: constructed as its mirror image (counter-clockwise, the offset on the other side) and drawn mirrored back; the numbers are the same".into(),
            );
        }
        let st = s.starts();
        for (name, law, from, to) in [
            ("rise", s.rise, st[0], st[1]),
            ("return", s.ret, st[2], st[3]),
        ] {
            let what = match law {
                Law::ConstantAcceleration { ratio } => {
                    format!("constant acceleration \"+ −\" (ratio {})", num(ratio))
                }
                other => other.key().to_string(),
            };
            let shock = match law.shock() {
                Shock::Rigid => format!(
                    "RIGID SHOCKS: the velocity jumps at φ = {}° and {}° (dS/dφ = ±{} m from 0), the acceleration is infinite there",
                    deg(from), deg(to), num(s.stroke / (to - from))
                ),
                Shock::Soft => "soft shocks: the acceleration jumps (finite)".to_string(),
                Shock::None => "no shock".to_string(),
            };
            out.push(format!(
                "cam: {name} {}°–{}°: law {what}; {shock}",
                deg(from),
                deg(to)
            ));
        }
        if s.law_assumed {
            out.push(format!(
                "cam: the source's diagrams are lost: the law of the rise ({}) and of the return ({}) is assumed",
                s.rise.key(),
                s.ret.key()
            ));
        }
        let d = &self.diagrams;
        let top = d.s.get(s.divisions).copied().unwrap_or(0.0);
        out.push(format!(
            "cam: equal-return check: dS/dφ at the end of the rise = {} m, of the return = {} m (0 exact); S at the end of the rise y_max·μ_S = {} m against the stroke {} m",
            num(d.ds_ends[0]), num(d.ds_ends[1]), num(top), num(s.stroke)
        ));
        let r = &self.radius;
        let r_exact = self.exact_r_min();
        let kind = if self.flat() {
            format!(
                "convexity r₀ ≥ max(−(S + S″)) + ρ_min, ρ_min = {} mm",
                mm(s.rho_min)
            )
        } else if s.closure == Closure::Force {
            format!("γ ≥ {}° on the rise (force closure)", deg(s.gamma_min))
        } else {
            format!("γ ≥ {}° over the whole cycle", deg(s.gamma_min))
        };
        out.push(format!(
            "cam: r_min = {} mm exact ({kind}); {} mm read off the combined diagram at its {} points",
            mm(r_exact), mm(r.graphical), self.points.len()
        ));
        if let Some(q) = s.quoted_r_min {
            out.push(format!(
                "cam: ERRATUM of the source: it quotes r_min = {} mm, inconsistent with its data: with {kind} the minimum is {} mm (the quoted value is {}× too small) and is not used",
                mm(q), mm(r_exact), num(r_exact / q)
            ));
        }
        if let Some(read) = r.convexity {
            let (_, worst) = exact::min_radius_flat(s);
            out.push(format!(
                "cam: flat face: max(−(S + S″)) = {} mm exact, {} mm read at the 45° tangent",
                mm(worst),
                mm(read)
            ));
            let half = exact::dense(s, 500)
                .into_iter()
                .map(|(p, a)| (motion(s, p, a).ds - s.offset()).abs())
                .fold(0.0, f64::max);
            out.push(format!("cam: flat face: the face's half-length from the follower's axis ≥ max|dS/dφ − e| = {} mm", mm(half)));
        }
        let rho = self.exact_rho_min();
        if self.flat() {
            if rho < 0.0 {
                out.push(format!(
                    "cam: CUSP: the flat-faced profile is concave (ρ = r₀ + S + S″ = {} mm < 0 at r₀ = {} mm): the face lines' envelope loops back and the follower cannot reproduce the law; r₀ must be at least {} mm",
                    mm(rho), mm(self.base), mm(r_exact)
                ));
            }
        } else {
            let worst = self.worst_angle();
            if self.rocker() {
                let below = if worst < s.gamma_min - 1e-9 {
                    format!(": BELOW γ_min {}", self.base_used(r_exact))
                } else {
                    String::new()
                };
                out.push(format!(
                    "cam: the smallest transmission angle over the cycle is {}° (γ_min = {}°){below}",
                    deg(worst),
                    deg(s.gamma_min)
                ));
            } else {
                let over = if worst > FRAC_PI_2 - s.gamma_min + 1e-9 {
                    format!(": EXCEEDED {}", self.base_used(r_exact))
                } else {
                    String::new()
                };
                out.push(format!(
                    "cam: the largest pressure angle {} is {}° (λ_max = {}°){over}",
                    if s.closure == Closure::Force {
                        "on the rise (force closure)"
                    } else {
                        "over the cycle"
                    },
                    deg(worst),
                    deg(FRAC_PI_2 - s.gamma_min)
                ));
            }
            let chosen = if s.roller.is_some() {
                "given"
            } else {
                "chosen"
            };
            let drawn = self.inversion.rho_min;
            out.push(format!(
                "cam: roller: 0.4·r₀ = {} mm, 0.8·ρ_min = {} mm (ρ_min of the drawn pitch curve {} mm, exact {} mm): r = {} mm ({chosen})",
                mm(0.4 * self.base), mm(0.8 * drawn), mm(drawn), mm(rho), mm(self.roller)
            ));
            if (self.roller - rho).abs() <= 1e-12 * rho {
                out.push(format!(
                    "cam: CUSP: the roller radius {} mm equals the pitch curve's smallest convex radius of curvature {} mm (to 1e-12): the practical profile comes to a point there; a smaller roller is needed",
                    mm(self.roller), mm(rho)
                ));
            } else if self.roller > rho {
                let (r, p) = mm_pair(self.roller, rho);
                out.push(format!(
                    "cam: UNDERCUT: the roller radius {r} mm exceeds the pitch curve's smallest convex radius of curvature {p} mm: the practical profile (the rollers' envelope) loops and is cut away; the largest admissible roller is just under {p} mm"
                ));
            }
        }
        if let Follower::Translating { offset } = s.follower {
            let (r_free, e_free) = exact::min_radius_free(s);
            out.push(format!(
                "cam: with the offset free the smallest cam (lecture 15: O₁ where the two γ_min tangents meet) has r_min = {} mm at e = {} mm; the scene's e = {} mm gives {} mm",
                mm(r_free),
                mm(self.scene_offset(e_free)),
                mm(self.scene_offset(offset)),
                mm(r_exact)
            ));
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
                out.push(format!(
                    "cam: OFFSET ON THE WRONG SIDE: e = {} mm raises the pressure angle on the rise to {}° (with e = {} mm on the other side of the centre it would be {}°)",
                    mm(self.scene_offset(offset)), deg(rise_max(&self.placement)), mm(self.scene_offset(-offset)), deg(rise_max(&mirrored))
                ));
            }
        }
        out
    }
}
