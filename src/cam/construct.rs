//! The constructions of a cam: the diagrams by graphical integration, the minimum radius
//! (combined diagram with the γ_min lines, the rocker's construction, the flat face's 45°
//! tangent), the profile by inversion — all through the recorder.

use super::exact::{self, jay, to_cam, Kin, Motion, Placement, Point};
use super::{CamError, CamSpec, Follower};
use crate::calculus::{integrate_chords, Diagram, Layout, Sampling, Scales};
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::{Arc, Circle, DVec2, Segment};
use crate::scale::{Quantity, Scale};
use std::f64::consts::{FRAC_PI_2, TAU};

/// Drawn length of the cycle on the diagrams' abscissa, mm (μ_φ = 2π / 180 mm).
const CYCLE_MM: f64 = 180.0;
/// Drawn stroke on the diagrams, mm.
const STROKE_MM: f64 = 60.0;
/// Largest radius of the profile drawing, mm.
const PROFILE_MM: f64 = 120.0;
/// Gap between the stacked diagrams, mm.
const GAP_MM: f64 = 30.0;

/// The three diagrams: d²S/dφ² given, dS/dφ and S integrated by the chord/pole method.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagrams {
    /// d²S/dφ² → dS/dφ (drawn at μ_S′).
    pub first: Figure,
    /// dS/dφ → S (drawn at μ_S).
    pub second: Figure,
    /// μ_φ, rad/mm.
    pub phi: Scale,
    /// μ_S, m/mm.
    pub s_scale: Scale,
    /// μ_S′ = μ_S/(H₂·μ_φ).
    pub ds_scale: Scale,
    /// μ_S″ = μ_S′/(H₁·μ_φ).
    pub d2s_scale: Scale,
    /// The pole distances H₁, H₂, mm.
    pub poles: [f64; 2],
    /// S at the points, as read.
    pub s: Vec<f64>,
    /// dS/dφ at the points, as read.
    pub ds: Vec<f64>,
    /// d²S/dφ² at the points, as read off the given diagram.
    pub d2s: Vec<f64>,
    /// S′ at the end of the rise and of the return, as read (the equal-return check: 0).
    pub ds_ends: [f64; 2],
}

/// The minimum-radius construction.
#[derive(Debug, Clone, PartialEq)]
pub struct RadiusConstruction {
    /// The combined diagram (S–dS/dφ with the γ_min lines, the rocker's construction, or
    /// S–d²S/dφ² with the 45° tangent), at μ_S.
    pub figure: Figure,
    /// r_min as read off the drawing, m.
    pub graphical: f64,
    /// r_min over the whole cycle (the exact twin), m.
    pub exact: f64,
    /// The flat face's max(−(S + S″)) as read and exact, m.
    pub convexity: Option<(f64, f64)>,
}

/// The profile by inversion.
#[derive(Debug, Clone, PartialEq)]
pub struct Inversion {
    /// The drawing at μ_l.
    pub figure: Figure,
    /// μ_l.
    pub scale: Scale,
    /// The pitch-curve points (roller centres, knife edge, or the flat face's foot), cam frame.
    pub centres: Vec<DVec2>,
    /// The practical profile's points (roller tangency, face contact), cam frame.
    pub profile: Vec<DVec2>,
    /// The pressure (transmission) angle read off the drawing at every point, rad.
    pub angles: Vec<f64>,
    /// The smallest convex radius of curvature of the drawn pitch curve (or of the flat
    /// profile r₀ + S + S″ from the drawn values), m.
    pub rho_min: f64,
}

/// A cam constructed and its analytic twin at hand.
#[derive(Debug, Clone, PartialEq)]
pub struct Cam {
    /// The task.
    pub spec: CamSpec,
    /// The diagram points.
    pub points: Vec<Point>,
    /// The diagrams.
    pub diagrams: Diagrams,
    /// The minimum radius.
    pub radius: RadiusConstruction,
    /// The base radius used for the profile, m.
    pub base: f64,
    /// The follower's placement (from the exact minimum or the given base radius).
    pub placement: Placement,
    /// The roller radius used, m (0: knife edge or flat face).
    pub roller: f64,
    /// The profile.
    pub inversion: Inversion,
    /// The pressure (transmission) angle over the cycle: read off the profile drawing at the
    /// points (marked) and the exact curve, at μ_φ and 1°/mm.
    pub angle_graph: Option<Figure>,
}

/// Construct the cam of `spec`.
///
/// # Errors
/// A failed integration, no admissible centre, a roller not smaller than the base radius,
/// no drawing scale.
pub fn build(spec: &CamSpec, ctx: &Context) -> Result<Cam, CamError> {
    let points = exact::points(spec);
    let diagrams = diagrams(spec, &points, ctx)?;
    let (radius, base, placement) = min_radius(spec, &points, &diagrams, ctx)?;
    let roller = match spec.follower {
        Follower::Flat { .. } => 0.0,
        _ => match spec.roller {
            Some(r) => r,
            None => {
                let (rho, _) = exact::pitch_rho_min(spec, &placement);
                (0.4 * base).min(0.8 * rho)
            }
        },
    };
    if roller >= base {
        return Err(CamError::RollerTooLarge { roller, base });
    }
    let read: Vec<Motion> = (0..points.len())
        .map(|i| read_motion(&diagrams, i))
        .collect();
    let inversion = invert(spec, &points, &read, &placement, base, roller, ctx)?;
    let angle_graph = match spec.follower {
        Follower::Flat { .. } => None,
        _ => Some(angle_graph(
            spec,
            &points,
            &inversion,
            &placement,
            diagrams.phi,
            ctx,
        )?),
    };
    Ok(Cam {
        spec: spec.clone(),
        points,
        diagrams,
        radius,
        base,
        placement,
        roller,
        inversion,
        angle_graph,
    })
}

/// The angle graph: the exact pressure (or transmission) angle over the cycle as a curve,
/// the values read off the profile drawing as marked points, at μ_φ and μ = 1°/mm.
fn angle_graph(
    spec: &CamSpec,
    points: &[Point],
    inv: &Inversion,
    place: &Placement,
    phi: Scale,
    ctx: &Context,
) -> Result<Figure, CamError> {
    let rocker = matches!(spec.follower, Follower::Rocker { .. });
    let mu = Scale::new(1f64.to_radians(), Quantity::Angle).ok_or(CamError::NoScale {
        what: "μ_γ",
        size: 1.0,
    })?;
    let mut rec = Recorder::in_context(if rocker { "γ(φ)" } else { "λ(φ)" }, mu, ctx);
    let value = |k: &Kin| {
        if rocker {
            k.transmission_angle()
        } else {
            k.pressure_angle()
        }
    };
    let width = phi.to_mm(TAU);
    let top = mu.to_mm(FRAC_PI_2) * if rocker { 1.0 } else { 0.6 };
    let xa = rec.draw(
        "φ axis",
        Item::Vector {
            from: DVec2::ZERO,
            to: DVec2::new(width + 12.0, 0.0),
        },
        Role::Construction,
        &[],
    );
    rec.label(
        xa,
        "φ",
        DVec2::new(width + 12.0, 0.0),
        DVec2::new(0.3, -1.0),
    );
    let ya = rec.draw(
        "angle axis",
        Item::Vector {
            from: DVec2::ZERO,
            to: DVec2::new(0.0, top + 10.0),
        },
        Role::Construction,
        &[],
    );
    rec.label(
        ya,
        if rocker { "γ, °" } else { "λ, °" },
        DVec2::new(0.0, top + 10.0),
        DVec2::new(1.0, 0.2),
    );
    let limit = if rocker {
        spec.gamma_min
    } else {
        FRAC_PI_2 - spec.gamma_min
    };
    let lim = rec.draw(
        "limit",
        Item::Segment(Segment::new(
            DVec2::new(0.0, mu.to_mm(limit)),
            DVec2::new(width, mu.to_mm(limit)),
        )),
        Role::Axis,
        &[],
    );
    rec.label(
        lim,
        if rocker { "γ_{min}" } else { "λ_{max}" },
        DVec2::new(width, mu.to_mm(limit)),
        DVec2::new(1.0, 0.0),
    );
    let curve: Vec<DVec2> = exact::dense(spec, 120)
        .into_iter()
        .chain([(0.0, true), (spec.starts()[1], true), (TAU, false)])
        .map(|(p, a)| (p, value(&place.kin(exact::motion(spec, p, a)))))
        .collect::<Vec<_>>()
        .into_iter()
        .map(|(p, v)| DVec2::new(phi.to_mm(p), mu.to_mm(v)))
        .collect();
    let mut curve = curve;
    curve.sort_by(|a, b| a.x.total_cmp(&b.x));
    rec.draw(
        "the exact angle",
        Item::Polyline {
            points: curve,
            closed: false,
        },
        Role::Result,
        &[xa, ya],
    );
    for (i, p) in points.iter().enumerate() {
        let a = inv.angles.get(i).copied().unwrap_or(0.0);
        let a = if rocker { FRAC_PI_2 - a } else { a };
        rec.point(
            format!("read at point {i}"),
            DVec2::new(phi.to_mm(p.phi), mu.to_mm(a)),
            Role::Construction,
            "",
            DVec2::ZERO,
            &[],
        );
    }
    Ok(rec.finish())
}

fn scale(v: f64, what: &'static str) -> Result<Scale, CamError> {
    Scale::new(v, Quantity::Length).ok_or(CamError::NoScale { what, size: v })
}

/// The diagrams: the given d²S/dφ² (closed form at the mid-interval points and the nodes)
/// integrated twice, phase by phase, with the poles H₁, H₂ left of each phase's origin.
fn diagrams(spec: &CamSpec, points: &[Point], ctx: &Context) -> Result<Diagrams, CamError> {
    let phi = match spec.scale_phi {
        Some(s) => s,
        None => Scale::new(TAU / CYCLE_MM, Quantity::Angle).ok_or(CamError::NoScale {
            what: "μ_φ",
            size: TAU,
        })?,
    };
    let s_scale = match spec.scale_s {
        Some(s) => s,
        None => {
            Scale::round_for(spec.stroke, STROKE_MM, Quantity::Length).ok_or(CamError::NoScale {
                what: "μ_S",
                size: spec.stroke,
            })?
        }
    };
    let [h1, h2] = spec
        .poles
        .unwrap_or_else(|| chosen_poles(spec, s_scale, phi));
    let ds_scale = scale(s_scale.value() / (h2 * phi.value()), "μ_S′")?;
    let d2s_scale = scale(ds_scale.value() / (h1 * phi.value()), "μ_S″")?;
    let n = spec.divisions;
    let st = spec.starts();
    let mut first = Recorder::in_context("d^2S/dφ^2 → dS/dφ", ds_scale, ctx);
    let mut second = Recorder::in_context("dS/dφ → S", s_scale, ctx);
    // Figure 1: the given diagram above, dS/dφ below; figure 2: dS/dφ above, S below.
    let (mut v_max, mut a_max) = (0.0f64, 0.0f64);
    for (p, after) in exact::dense(spec, 200) {
        let m = exact::motion(spec, p, after);
        v_max = v_max.max(m.ds.abs());
        a_max = a_max.max(m.d2s.abs());
    }
    let (a_mm, v_mm) = (d2s_scale.to_mm(a_max), ds_scale.to_mm(v_max));
    let a_top = DVec2::ZERO;
    let v_origin = DVec2::new(0.0, -(a_mm + v_mm + GAP_MM));
    let v_top = DVec2::ZERO;
    let s_origin = DVec2::new(0.0, -(v_mm + GAP_MM));
    let mut ds_nodes = vec![0.0; points.len()];
    let mut s_nodes = vec![0.0; points.len()];
    let mut ds_ends = [0.0; 2];
    for (idx, (phase, len, s_start)) in [
        (0usize, spec.phases.rise, 0.0),
        (2, spec.phases.ret, spec.stroke),
    ]
    .into_iter()
    .enumerate()
    {
        let dx = len / n as f64;
        let mids: Vec<f64> = (0..n)
            .map(|k| exact::motion(spec, st[phase] + (k as f64 + 0.5) * dx, true).d2s)
            .collect();
        let src = Diagram::new(st[phase], dx, mids, false)?;
        let shift = DVec2::new(phi.to_mm(st[phase]), 0.0);
        let pole = if idx == 0 {
            ("P_1", "H_1")
        } else {
            ("P_1′", "H_1")
        };
        let layout = Layout::new(a_top + shift, v_origin + shift)
            .named("φ", "d^2S/dφ^2", "dS/dφ")
            .pole_named(pole.0, pole.1)
            .with_source(false);
        let scales = Scales {
            x: phi,
            y: d2s_scale,
        };
        // A uniform law starts at dS/dφ = h/Φ: the jump (a δ of acceleration, the rigid
        // shock) is no ordinate of the given diagram, so it is laid off as the start value.
        let v0 = exact::motion(spec, st[phase], true).ds;
        let v = integrate_chords(
            &mut first,
            &src,
            Sampling::Midpoints,
            scales,
            h1,
            v0,
            &layout,
        )?;
        // The given diagram itself: its curve through the nodes and both sides of a jump.
        let curve = given_curve(spec, phase, len, phi, d2s_scale, a_top);
        first.draw(
            format!("given d²S/dφ² of phase {phase}"),
            Item::Polyline {
                points: curve,
                closed: false,
            },
            Role::Given,
            &[],
        );
        ds_ends[idx] = *v.node.last().unwrap_or(&0.0);
        let base = idx * (n + 1);
        for (k, &val) in v.node.iter().enumerate() {
            if let Some(slot) = ds_nodes.get_mut(base + k) {
                *slot = val;
            }
        }
        // The second integration reads dS/dφ at the middle of each chord it has drawn.
        let mids_v: Vec<f64> = v.node.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
        let src2 = Diagram::new(st[phase], dx, mids_v, false)?;
        let layout2 = Layout::new(v_top + shift, s_origin + shift)
            .named("φ", "dS/dφ", "S")
            .pole_named(if idx == 0 { "P_2" } else { "P_2′" }, "H_2");
        let scales2 = Scales {
            x: phi,
            y: ds_scale,
        };
        let s = integrate_chords(
            &mut second,
            &src2,
            Sampling::Midpoints,
            scales2,
            h2,
            s_start,
            &layout2,
        )?;
        for (k, &val) in s.node.iter().enumerate() {
            if let Some(slot) = s_nodes.get_mut(base + k) {
                *slot = val;
            }
        }
    }
    // The dwells: zero analogues, S = h on the far dwell, 0 on the near one.
    for (from, to, s) in [(st[1], st[2], spec.stroke), (st[3], st[4], 0.0)] {
        let (a, b) = (phi.to_mm(from), phi.to_mm(to));
        for (rec, origin, y) in [
            (&mut first, v_origin, 0.0),
            (&mut second, s_origin, s_scale.to_mm(s)),
        ] {
            rec.draw(
                "dwell",
                Item::Segment(Segment::new(
                    origin + DVec2::new(a, y),
                    origin + DVec2::new(b, y),
                )),
                Role::Result,
                &[],
            );
        }
        first.draw(
            "dwell of the given diagram",
            Item::Segment(Segment::new(
                a_top + DVec2::new(a, 0.0),
                a_top + DVec2::new(b, 0.0),
            )),
            Role::Given,
            &[],
        );
    }
    // d²S/dφ² at the points, read off the given diagram.
    let d2s = points
        .iter()
        .map(|p| {
            let m = exact::motion(spec, p.phi, p.after);
            let x = phi.to_mm(p.phi);
            let top = a_top + DVec2::new(x, d2s_scale.to_mm(m.d2s));
            let read = first.measure(a_top + DVec2::new(x, 0.0), top);
            d2s_scale.to_physical(read.read_mm).copysign(m.d2s)
        })
        .collect();
    Ok(Diagrams {
        first: first.finish(),
        second: second.finish(),
        phi,
        s_scale,
        ds_scale,
        d2s_scale,
        poles: [h1, h2],
        s: s_nodes,
        ds: ds_nodes,
        d2s,
        ds_ends,
    })
}

/// The pole distances a student chooses: H₂ = μ_S/(μ_S′·μ_φ) and H₁ = μ_S′/(μ_S″·μ_φ) with
/// μ_S′, μ_S″ drawing the analogues' peaks about 40 mm tall, rounded to whole millimetres.
fn chosen_poles(spec: &CamSpec, s: Scale, phi: Scale) -> [f64; 2] {
    let (mut v, mut a) = (0.0f64, 0.0f64);
    for (p, after) in exact::dense(spec, 200) {
        let m = exact::motion(spec, p, after);
        v = v.max(m.ds.abs());
        a = a.max(m.d2s.abs());
    }
    let h2 = (s.value() / (v.max(1e-12) / 40.0 * phi.value()))
        .round()
        .clamp(5.0, 200.0);
    let mu_v = s.value() / (h2 * phi.value());
    let h1 = (mu_v / (a.max(1e-12) / 40.0 * phi.value()))
        .round()
        .clamp(5.0, 200.0);
    [h1, h2]
}

/// The given d²S/dφ² of one phase as drawn: the nodes with both sides of every jump.
fn given_curve(
    spec: &CamSpec,
    phase: usize,
    len: f64,
    phi: Scale,
    mu: Scale,
    o: DVec2,
) -> Vec<DVec2> {
    let st = spec.starts()[phase];
    let law = if phase == 0 { spec.rise } else { spec.ret };
    let mut us: Vec<(f64, bool)> = (0..=48).map(|k| (k as f64 / 48.0, true)).collect();
    for b in law.breaks() {
        us.push((b, false));
        us.push((b, true));
    }
    us.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    let mut pts = vec![o + DVec2::new(phi.to_mm(st), 0.0)];
    for (u, after) in us {
        let after = if u >= 1.0 { false } else { after };
        let m = exact::motion(spec, st + u * len, after);
        pts.push(o + DVec2::new(phi.to_mm(st + u * len), mu.to_mm(m.d2s)));
    }
    pts.push(o + DVec2::new(phi.to_mm(st + len), 0.0));
    pts
}

/// The motion as read off the diagrams at point `i`.
fn read_motion(d: &Diagrams, i: usize) -> Motion {
    Motion {
        s: d.s.get(i).copied().unwrap_or(0.0),
        ds: d.ds.get(i).copied().unwrap_or(0.0),
        d2s: d.d2s.get(i).copied().unwrap_or(0.0),
    }
}

/// The minimum radius: the construction at the drawn points and the exact twin over the
/// cycle; the placement of the follower for the profile.
fn min_radius(
    spec: &CamSpec,
    points: &[Point],
    d: &Diagrams,
    ctx: &Context,
) -> Result<(RadiusConstruction, f64, Placement), CamError> {
    let mu = d.s_scale;
    let mut rec = Recorder::in_context("combined", mu, ctx);
    let gamma = spec.gamma_min;
    match spec.follower {
        Follower::Translating { offset } => {
            let (exact_r, _) = exact::min_radius_translating(spec, offset);
            // Combined diagram: B₀ at the origin, the path vertical, K_i = B_i − (S′_i, 0).
            let path = rec.draw(
                "follower's path (S axis)",
                Item::Vector {
                    from: DVec2::new(0.0, -mu.to_mm(exact_r) - 10.0),
                    to: DVec2::new(0.0, mu.to_mm(spec.stroke) + 12.0),
                },
                Role::Axis,
                &[],
            );
            rec.label(
                path,
                "S",
                DVec2::new(0.0, mu.to_mm(spec.stroke) + 12.0),
                DVec2::new(1.0, 0.0),
            );
            let ks: Vec<DVec2> = (0..points.len())
                .map(|i| {
                    let m = read_motion(d, i);
                    DVec2::new(-mu.to_mm(m.ds), mu.to_mm(m.s))
                })
                .collect();
            for (i, k) in ks.iter().enumerate() {
                let b = DVec2::new(0.0, k.y);
                rec.draw(
                    format!("dS/dφ at point {i}"),
                    Item::Segment(Segment::new(b, *k)),
                    Role::Construction,
                    &[],
                );
            }
            rec.draw(
                "combined diagram S(dS/dφ)",
                Item::Polyline {
                    points: ks.clone(),
                    closed: true,
                },
                Role::Result,
                &[path],
            );
            // O on the vertical x = −e: the highest point below every γ_min line.
            let ox = -mu.to_mm(offset);
            let t = gamma.tan();
            let (mut best, mut bind) = (f64::INFINITY, 0);
            // Under force closure only the rise's points bind.
            let binds = |i: usize| !spec.force_closure || points[i].phase == 0;
            for (i, k) in ks.iter().enumerate().filter(|(i, _)| binds(*i)) {
                let y = k.y - (k.x - ox).abs() * t;
                if y < best {
                    best = y;
                    bind = i;
                }
            }
            let o = DVec2::new(ox, best);
            zone_lines(&mut rec, &ks, o, gamma, bind);
            let bound: Vec<DVec2> = ks
                .iter()
                .enumerate()
                .filter(|(i, _)| binds(*i))
                .map(|(_, k)| *k)
                .collect();
            hatch_zone(&mut rec, &bound, o, t);
            let oid = rec.point(
                "cam centre O_1",
                o,
                Role::Result,
                "O_1",
                DVec2::new(-1.0, -0.5),
                &[],
            );
            let r = rec.measure(o, DVec2::ZERO);
            rec.draw(
                "r_min",
                Item::Segment(Segment::new(o, DVec2::ZERO)),
                Role::Dimension,
                &[oid],
            );
            let base = spec.base_radius.unwrap_or(exact_r);
            if base <= offset.abs() {
                return Err(CamError::BaseWithinOffset {
                    base,
                    offset: offset.abs(),
                });
            }
            let s0 = (base * base - offset * offset).sqrt();
            Ok((
                RadiusConstruction {
                    figure: rec.finish(),
                    graphical: r.value,
                    exact: exact_r,
                    convexity: None,
                },
                base,
                Placement::Translating { offset, s0 },
            ))
        }
        Follower::Rocker { arm, .. } => {
            let (exact_r, o_exact) = exact::min_radius_rocker(spec).ok_or(CamError::NoCentre {
                gamma_deg: gamma.to_degrees(),
                searched: 20.0 * arm,
            })?;
            let (_, sigma) = exact::rocker_of(spec);
            let l = mu.to_mm(arm);
            let pivot = DVec2::ZERO;
            let a0 = DVec2::new(0.0, l);
            let pid = rec.draw(
                "rocker pivot O_2",
                Item::Joint {
                    at: pivot,
                    fixed: true,
                },
                Role::Given,
                &[],
            );
            rec.label(pid, "O_2", pivot, DVec2::new(0.7, -0.7));
            let beta_max = spec.stroke / arm;
            rec.draw(
                "trajectory of A",
                Item::Arc(Arc {
                    center: pivot,
                    radius: l,
                    start: FRAC_PI_2 - beta_max.max(0.0) - 0.05,
                    sweep: 2.0 * beta_max + 0.1,
                }),
                Role::Construction,
                &[pid],
            );
            let mut cons = Vec::new();
            let mut ks = Vec::new();
            for (i, p) in points.iter().enumerate() {
                let m = read_motion(d, i);
                let psi = FRAC_PI_2 + sigma * m.s / arm;
                let e = DVec2::from_angle(psi);
                let a = pivot + e * l;
                let k = a - e * (sigma * mu.to_mm(m.ds));
                rec.draw(
                    format!("rocker O_2A_{i}"),
                    Item::Segment(Segment::new(pivot, a)),
                    Role::Construction,
                    &[pid],
                );
                ks.push(k);
                if !spec.force_closure || p.phase == 0 {
                    cons.push((k, e));
                }
            }
            rec.draw(
                "curve of the points K",
                Item::Polyline {
                    points: ks.clone(),
                    closed: true,
                },
                Role::Result,
                &[],
            );
            let o = rocker_centre(&cons, a0, gamma).ok_or(CamError::NoCentre {
                gamma_deg: gamma.to_degrees(),
                searched: 20.0 * l,
            })?;
            rocker_lines(&mut rec, &cons, o, gamma);
            let oid = rec.point(
                "cam centre O_1",
                o,
                Role::Result,
                "O_1",
                DVec2::new(1.0, 0.5),
                &[],
            );
            rec.draw(
                "r_min",
                Item::Segment(Segment::new(o, a0)),
                Role::Dimension,
                &[oid],
            );
            rec.draw(
                "centre distance",
                Item::Segment(Segment::new(o, pivot)),
                Role::Construction,
                &[oid, pid],
            );
            let r = rec.measure(o, a0);
            // The profile uses the exact centre (or the given base radius along its direction).
            let dir = (o_exact - DVec2::new(0.0, arm)).normalize_or_zero();
            let base = spec.base_radius.unwrap_or(exact_r);
            let o_used = DVec2::new(0.0, arm) + dir * base;
            let pivot_cam = -o_used;
            Ok((
                RadiusConstruction {
                    figure: rec.finish(),
                    graphical: r.value,
                    exact: exact_r,
                    convexity: None,
                },
                base,
                Placement::Rocker {
                    pivot: pivot_cam,
                    arm,
                    psi0: FRAC_PI_2,
                    sigma,
                },
            ))
        }
        Follower::Flat { offset } => {
            let (exact_r, worst) = exact::min_radius_flat(spec);
            // S vertical, S″ horizontal, both at μ_S; the 45° tangent on the negative side.
            let ax = rec.draw(
                "S axis",
                Item::Vector {
                    from: DVec2::new(0.0, -mu.to_mm(exact_r) - 10.0),
                    to: DVec2::new(0.0, mu.to_mm(spec.stroke) + 12.0),
                },
                Role::Axis,
                &[],
            );
            rec.label(
                ax,
                "S",
                DVec2::new(0.0, mu.to_mm(spec.stroke) + 12.0),
                DVec2::new(1.0, 0.0),
            );
            let pts: Vec<DVec2> = (0..points.len())
                .map(|i| {
                    let m = read_motion(d, i);
                    DVec2::new(mu.to_mm(m.d2s), mu.to_mm(m.s))
                })
                .collect();
            let xs = pts.iter().fold(0.0f64, |a, p| a.max(p.x.abs()));
            let hx = rec.draw(
                "d²S/dφ² axis",
                Item::Vector {
                    from: DVec2::new(-xs - 10.0, 0.0),
                    to: DVec2::new(xs + 12.0, 0.0),
                },
                Role::Axis,
                &[],
            );
            rec.label(
                hx,
                "d^2S/dφ^2",
                DVec2::new(xs + 12.0, 0.0),
                DVec2::new(0.0, -1.0),
            );
            rec.draw(
                "combined diagram S(d²S/dφ²)",
                Item::Polyline {
                    points: pts.clone(),
                    closed: true,
                },
                Role::Result,
                &[ax, hx],
            );
            // The 45° line touching the curve: the least S + S″ among the drawn points.
            let (i, c) = pts
                .iter()
                .enumerate()
                .map(|(i, p)| (i, p.x + p.y))
                .fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
            let touch = pts.get(i).copied().unwrap_or(DVec2::ZERO);
            let oi = DVec2::new(0.0, c.min(0.0));
            rec.draw(
                "tangent at 45°",
                Item::Segment(Segment::new(
                    oi + DVec2::new(-15.0, 15.0),
                    touch + DVec2::new(15.0, -15.0),
                )),
                Role::Construction,
                &[],
            );
            rec.point("O_I", oi, Role::Result, "O_I", DVec2::new(1.0, -0.5), &[]);
            let rho = mu.to_mm(spec.rho_min);
            let o = DVec2::new(mu.to_mm(offset), oi.y - rho);
            rec.point(
                "cam centre O′_1 (with ρ_min)",
                o,
                Role::Result,
                "O′_1",
                DVec2::new(1.0, -0.5),
                &[],
            );
            let read_c = rec.measure(oi, DVec2::ZERO).value.copysign(-c);
            let graphical = read_c.max(0.0) + spec.rho_min;
            let base = spec.base_radius.unwrap_or(exact_r);
            Ok((
                RadiusConstruction {
                    figure: rec.finish(),
                    graphical,
                    exact: exact_r,
                    convexity: Some((read_c, worst)),
                },
                base,
                Placement::Translating {
                    offset: 0.0,
                    s0: base,
                },
            ))
        }
    }
}

/// The γ_min lines of the translating follower's combined diagram: the two tangents through
/// the binding points (long), a short tick at every other point.
fn zone_lines(rec: &mut Recorder, ks: &[DVec2], o: DVec2, gamma: f64, bind: usize) {
    let (c, s) = (gamma.cos(), gamma.sin());
    for (i, k) in ks.iter().enumerate() {
        for dir in [DVec2::new(-c, -s), DVec2::new(c, -s)] {
            let towards_o = (o - *k).dot(dir) > 0.0 && (o.x - k.x) * dir.x >= 0.0;
            let len = if i == bind && towards_o {
                (o - *k).length() + 15.0
            } else {
                8.0
            };
            rec.draw(
                format!("γ_min line at point {i}"),
                Item::Segment(Segment::new(*k, *k + dir * len)),
                Role::Construction,
                &[],
            );
        }
    }
}

/// The admissible zone of the cam centre of a translating follower: its upper boundary
/// g(x) = min over the points of (K_y − |K_x − x|·tan γ_min) near the centre, hatched below.
fn hatch_zone(rec: &mut Recorder, ks: &[DVec2], o: DVec2, t: f64) {
    let g = |x: f64| {
        ks.iter()
            .map(|k| k.y - (k.x - x).abs() * t)
            .fold(f64::INFINITY, f64::min)
    };
    let half = 25.0;
    let pts: Vec<DVec2> = (0..=50)
        .map(|j| {
            let x = o.x - half + j as f64;
            DVec2::new(x, g(x))
        })
        .filter(|p| p.is_finite() && p.y > o.y - half)
        .collect();
    if pts.len() < 2 {
        return;
    }
    let edge = rec.draw(
        "boundary of the zone of the cam centre",
        Item::Polyline {
            points: pts.clone(),
            closed: false,
        },
        Role::Construction,
        &[],
    );
    for p in pts.iter().step_by(4) {
        rec.draw(
            "hatching of the zone",
            Item::Segment(Segment::new(*p, *p + DVec2::new(-3.0, -3.0))),
            Role::Hatch,
            &[edge],
        );
    }
}

/// The rocker's graphical centre: among the intersections of the γ_min lines and the feet
/// of the perpendiculars from A₀ onto them, the admissible one nearest A₀.
fn rocker_centre(cons: &[(DVec2, DVec2)], a0: DVec2, gamma: f64) -> Option<DVec2> {
    let lines: Vec<(DVec2, DVec2)> = cons
        .iter()
        .flat_map(|&(k, e)| [1.0, -1.0].map(|s| (k, crate::geom::rotate(e, s * gamma))))
        .collect();
    let sin_g = gamma.sin();
    let mut cands = Vec::new();
    for (i, &(p, u)) in lines.iter().enumerate() {
        cands.push(p + u * (a0 - p).dot(u));
        for &(q, v) in &lines[i + 1..] {
            let den = u.perp_dot(v);
            if den.abs() > 1e-12 {
                let t = (q - p).perp_dot(v) / den;
                cands.push(p + u * t);
            }
        }
    }
    // Nearest first: the first admissible candidate is the centre (most fail at once).
    cands.retain(|c| c.is_finite());
    cands.sort_by(|a, b| a.distance(a0).total_cmp(&b.distance(a0)));
    cands
        .into_iter()
        .find(|c| exact::admits(*c, cons, sin_g, 1e-9))
}

/// The rocker's γ_min lines: long through O where they bind, short ticks elsewhere.
fn rocker_lines(rec: &mut Recorder, cons: &[(DVec2, DVec2)], o: DVec2, gamma: f64) {
    for (i, &(k, e)) in cons.iter().enumerate() {
        for s in [1.0, -1.0] {
            let u = crate::geom::rotate(e, s * gamma);
            let off = (o - k).perp_dot(u).abs();
            let through = off < 1e-6 * (1.0 + (o - k).length());
            let (a, b) = if through {
                let t = (o - k).dot(u);
                (k - u * 10.0 * t.signum(), k + u * (t + 15.0 * t.signum()))
            } else {
                (k - u * 6.0, k + u * 6.0)
            };
            rec.draw(
                format!("γ_min line at K_{i}"),
                Item::Segment(Segment::new(a, b)),
                Role::Construction,
                &[],
            );
        }
    }
}

/// The profile by inversion at μ_l.
pub(crate) fn invert(
    spec: &CamSpec,
    points: &[Point],
    read: &[Motion],
    place: &Placement,
    base: f64,
    roller: f64,
    ctx: &Context,
) -> Result<Inversion, CamError> {
    let reach = match *place {
        Placement::Rocker { pivot, arm, .. } => pivot.length() + arm,
        Placement::Translating { .. } => base + spec.stroke + spec.offset().abs(),
    };
    let mu = match spec.scale_l {
        Some(s) => s,
        None => Scale::round_for(reach, PROFILE_MM, Quantity::Length).ok_or(CamError::NoScale {
            what: "μ_l",
            size: reach,
        })?,
    };
    let mm = |p: DVec2| p / mu.value();
    let mut rec = Recorder::in_context("inversion", mu, ctx);
    let o = rec.draw(
        "cam centre O_1",
        Item::Joint {
            at: DVec2::ZERO,
            fixed: true,
        },
        Role::Given,
        &[],
    );
    rec.label(o, "O_1", DVec2::ZERO, DVec2::new(-0.7, -0.7));
    let flat = matches!(spec.follower, Follower::Flat { .. });
    rec.draw(
        "base circle r_0",
        Item::Circle(Circle {
            center: DVec2::ZERO,
            radius: mu.to_mm(base),
        }),
        Role::Construction,
        &[o],
    );
    if let Placement::Translating { offset, .. } = *place {
        if offset != 0.0 && !flat {
            rec.draw(
                "offset circle e",
                Item::Circle(Circle {
                    center: DVec2::ZERO,
                    radius: mu.to_mm(offset.abs()),
                }),
                Role::Construction,
                &[o],
            );
        }
    }
    let mut centres = Vec::with_capacity(points.len());
    let mut profile = Vec::with_capacity(points.len());
    let mut kins: Vec<Kin> = Vec::with_capacity(points.len());
    for (i, p) in points.iter().enumerate() {
        rec.set_group(i as u32 + 1);
        let m = read.get(i).copied().unwrap_or(Motion {
            s: 0.0,
            ds: 0.0,
            d2s: 0.0,
        });
        let kin = place.kin(m);
        let c = to_cam(kin.b, p.phi);
        // The compass arc about O₁ through B_i (radius O₁B_i), notched where it meets ray i.
        rec.draw(
            format!("arc about O_1 from B_{i} to ray {i}"),
            Item::Arc(Arc::notch(DVec2::ZERO, mm(c), 4.0)),
            Role::Construction,
            &[o],
        );
        // The follower in its inverted position.
        let fol = match *place {
            Placement::Rocker { pivot, .. } => Segment::new(mm(to_cam(pivot, p.phi)), mm(c)),
            Placement::Translating { offset, .. } if !flat => {
                Segment::new(mm(to_cam(DVec2::new(offset, 0.0), p.phi)), mm(c))
            }
            Placement::Translating { .. } => {
                let dir = to_cam(DVec2::X, p.phi);
                let half = mu.to_mm(spec.stroke.max(m.ds.abs()) * 0.6 + 0.002);
                let foot = mm(to_cam(DVec2::new(0.0, base + m.s), p.phi));
                Segment::new(foot - dir * half, foot + dir * half)
            }
        };
        rec.draw(
            format!("follower at position {i}"),
            Item::Segment(fol),
            Role::Construction,
            &[o],
        );
        let t = if flat {
            let (q, _) = exact::flat_contact(base, m);
            to_cam(q, p.phi)
        } else {
            if roller > 0.0 {
                rec.draw(
                    format!("roller at {i}"),
                    Item::Circle(Circle {
                        center: mm(c),
                        radius: mu.to_mm(roller),
                    }),
                    Role::Construction,
                    &[],
                );
            }
            to_cam(kin.roller_point(roller), p.phi)
        };
        let pid = rec.point(
            format!("pitch point {i}"),
            mm(c),
            Role::Construction,
            "",
            DVec2::ZERO,
            &[],
        );
        // The phases' ends are labelled (the textbook's 0, n, n + 1, 2n + 1).
        if p.k == 0 || p.k == spec.divisions {
            rec.label(pid, p.label.clone(), mm(c), mm(c).normalize_or_zero());
        }
        centres.push(c);
        profile.push(t);
        kins.push(kin);
    }
    rec.set_group(0);
    let dwell = |from: DVec2, to: DVec2| -> Vec<DVec2> {
        let a = Arc::between(DVec2::ZERO, from.length(), from, to);
        // The dwell is swept clockwise in the cam frame (the short way is right for < 180°).
        let sweep = if a.sweep > 0.0 {
            a.sweep - TAU
        } else {
            a.sweep
        };
        let n = 24;
        (1..n)
            .map(|j| DVec2::from_angle(a.start + sweep * j as f64 / n as f64) * from.length())
            .collect()
    };
    let n = spec.divisions;
    let closed = |pts: &[DVec2]| -> Vec<DVec2> {
        let mut out: Vec<DVec2> = pts[..=n].to_vec();
        out.extend(dwell(pts[n], pts[n + 1]));
        out.extend_from_slice(&pts[n + 1..]);
        out.extend(dwell(pts[2 * n + 1], pts[0]));
        out.into_iter().map(mm).collect()
    };
    if !flat {
        rec.draw(
            "pitch (theoretical) profile",
            Item::Polyline {
                points: closed(&centres),
                closed: true,
            },
            Role::Construction,
            &[o],
        );
    }
    rec.draw(
        if flat {
            "practical profile: envelope of the face lines"
        } else {
            "practical profile: envelope of the rollers"
        },
        Item::Polyline {
            points: closed(&profile),
            closed: true,
        },
        Role::Result,
        &[o],
    );
    // The angle read off the drawing: the normal to the chord through the neighbours against
    // the follower's direction in its inverted position.
    // At a phase's end the neighbour is read on the drawn dwell arc, one step on (the arc
    // about O of the dwell's radius), so every chord is central.
    let beyond = |i: usize, forward: bool| -> DVec2 {
        let p = &points[i];
        let step = if p.phase == 0 {
            spec.phases.rise
        } else {
            spec.phases.ret
        } / spec.divisions as f64;
        let dwell = match (p.phase, forward) {
            (0, true) => spec.phases.far,
            (0, false) | (2, true) => spec.phases.near,
            _ => spec.phases.far,
        };
        if dwell <= 0.0 {
            return centres[i];
        }
        let d = step.min(dwell);
        let phi = if forward { p.phi + d } else { p.phi - d };
        let s = if (p.phase == 0) == forward {
            spec.stroke
        } else {
            0.0
        };
        let m = Motion {
            s,
            ds: 0.0,
            d2s: 0.0,
        };
        to_cam(place.kin(m).b, phi)
    };
    let angles = (0..points.len())
        .map(|i| {
            let (lo, hi) = neighbours(points, i);
            let a = if lo == i {
                beyond(i, false)
            } else {
                centres[lo]
            };
            let b = if hi == i {
                beyond(i, true)
            } else {
                centres[hi]
            };
            let t = b - a;
            let nrm = jay(t);
            let path = to_cam(kins[i].path, points[i].phi);
            let c = (nrm.dot(path).abs() / nrm.length()).clamp(0.0, 1.0);
            c.acos()
        })
        .collect();
    let rho_min = if flat {
        read.iter()
            .map(|m| base + m.s + m.d2s)
            .fold(f64::INFINITY, f64::min)
    } else {
        drawn_rho_min(points, &centres)
    };
    Ok(Inversion {
        figure: rec.finish(),
        scale: mu,
        centres,
        profile,
        angles,
        rho_min,
    })
}

/// The neighbours of point `i` within its phase (one-sided at the phase's ends).
fn neighbours(points: &[Point], i: usize) -> (usize, usize) {
    let same = |j: usize| points.get(j).is_some_and(|q| q.phase == points[i].phase);
    let lo = if i > 0 && same(i - 1) { i - 1 } else { i };
    let hi = if same(i + 1) { i + 1 } else { i };
    (lo, hi)
}

/// The smallest radius of the circles through three consecutive drawn pitch points that
/// turn like the cam (convex), within each phase; the dwell arcs' radii too.
fn drawn_rho_min(points: &[Point], c: &[DVec2]) -> f64 {
    let mut best = f64::INFINITY;
    for i in 1..points.len().saturating_sub(1) {
        if points[i - 1].phase != points[i].phase || points[i + 1].phase != points[i].phase {
            continue;
        }
        let (a, b, d) = (c[i - 1], c[i], c[i + 1]);
        let cross = (b - a).perp_dot(d - b);
        // Clockwise turning is convex (the cam frame's curve runs clockwise).
        if cross < 0.0 {
            let r = a.distance(b) * b.distance(d) * d.distance(a) / (2.0 * cross.abs());
            best = best.min(r);
        }
    }
    for p in [
        c.first(),
        points
            .iter()
            .position(|p| p.phase == 2)
            .and_then(|j| c.get(j)),
    ]
    .into_iter()
    .flatten()
    {
        best = best.min(p.length());
    }
    best
}
