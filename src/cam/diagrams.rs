//! The diagrams by graphical integration: the given d²S/dφ² integrated twice, phase by
//! phase, with the chord/pole method of [`crate::calculus`] at the textbook's scales.

use super::motion::{motion, motion_u, Motion, Point};
use super::{CamError, CamSpec, Given};
use crate::calculus::{integrate_chords, Diagram, Layout, Sampling, Scales};
use crate::construct::{Context, Figure, Item, Recorder, Role};
use crate::geom::{DVec2, Segment};
use crate::scale::{Quantity, Scale};
use std::f64::consts::TAU;

/// Drawn length of the cycle on the diagrams' abscissa, mm (μ_φ = 2π / 180 mm).
const CYCLE_MM: f64 = 180.0;
/// Drawn stroke on the diagrams, mm.
const STROKE_MM: f64 = 60.0;
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

fn scale(v: f64, what: &'static str) -> Result<Scale, CamError> {
    Scale::new(v, Quantity::Length).ok_or(CamError::NoScale { what, size: v })
}

/// The diagrams: the given d²S/dφ² (closed form at the mid-interval points and the nodes)
/// integrated twice, phase by phase, with the poles H₁, H₂ left of each phase's origin.
pub(super) fn diagrams(
    spec: &CamSpec,
    points: &[Point],
    ctx: &Context,
) -> Result<Diagrams, CamError> {
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
    if spec.given == Given::S {
        let sc = [s_scale, ds_scale, d2s_scale];
        return differentiated(spec, points, phi, sc, [h1, h2], ctx);
    }
    let n = spec.divisions;
    let st = spec.starts();
    let mut first = Recorder::in_context("d^2S/dφ^2 → dS/dφ", ds_scale, ctx);
    let mut second = Recorder::in_context("dS/dφ → S", s_scale, ctx);
    // Figure 1: the given diagram above, dS/dφ below; figure 2: dS/dφ above, S below.
    let (v_max, a_max) = peaks(spec);
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
            .map(|k| motion(spec, st[phase] + (k as f64 + 0.5) * dx, true).d2s)
            .collect();
        // n mid-interval ordinates of n intervals (validated by the integration as such; a
        // diagram of nodes would count n − 1).
        let src = Diagram {
            x0: st[phase],
            dx,
            y: mids,
            periodic: false,
        };
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
        let v0 = motion(spec, st[phase], true).ds;
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
        let src2 = Diagram {
            x0: st[phase],
            dx,
            y: mids_v,
            periodic: false,
        };
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
            let m = motion(spec, p.phi, p.after);
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

/// The largest |dS/dφ| and |d²S/dφ²| of the given law over the cycle (the tallest ordinates
/// the diagrams must hold): each moving phase at 200 intervals, both sides of every jump.
fn peaks(spec: &CamSpec) -> (f64, f64) {
    const PER_PHASE: usize = 200;
    let mut out = (0.0f64, 0.0f64);
    for (phase, law) in [(0usize, spec.rise), (2, spec.ret)] {
        let nodes = (0..=PER_PHASE).map(|k| (k as f64 / PER_PHASE as f64, k < PER_PHASE));
        let jumps = law
            .breaks()
            .into_iter()
            .flat_map(|b| [(b, false), (b, true)]);
        for (u, after) in nodes.chain(jumps) {
            let m = motion_u(spec, phase, u, after);
            out = (out.0.max(m.ds.abs()), out.1.max(m.d2s.abs()));
        }
    }
    out
}

/// The pole distances a student chooses: H₂ = μ_S/(μ_S′·μ_φ) and H₁ = μ_S′/(μ_S″·μ_φ) with
/// μ_S′, μ_S″ drawing the analogues' peaks about 40 mm tall, rounded to whole millimetres.
fn chosen_poles(spec: &CamSpec, s: Scale, phi: Scale) -> [f64; 2] {
    let (v, a) = peaks(spec);
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
        let m = motion(spec, st + u * len, after);
        pts.push(o + DVec2::new(phi.to_mm(st + u * len), mu.to_mm(m.d2s)));
    }
    pts.push(o + DVec2::new(phi.to_mm(st + len), 0.0));
    pts
}

/// The motion as read off the diagrams at point `i`.
pub(super) fn read_motion(d: &Diagrams, i: usize) -> Motion {
    Motion {
        s: d.s.get(i).copied().unwrap_or(0.0),
        ds: d.ds.get(i).copied().unwrap_or(0.0),
        d2s: d.d2s.get(i).copied().unwrap_or(0.0),
    }
}

/// The diagrams when the scene gives S: the S diagram drawn from the law at the nodes of each
/// moving phase and differentiated twice by the method of chords (H₂: S → dS/dφ, H₁: dS/dφ →
/// d²S/dφ²), the values at the points read off the smooth curves; S itself read off the
/// given diagram.
fn differentiated(
    spec: &CamSpec,
    points: &[Point],
    phi: Scale,
    [s_scale, ds_scale, d2s_scale]: [Scale; 3],
    [h1, h2]: [f64; 2],
    ctx: &Context,
) -> Result<Diagrams, CamError> {
    use crate::calculus::Method as Calc;
    let (n, st) = (spec.divisions, spec.starts());
    let mut first = Recorder::in_context("S → dS/dφ", ds_scale, ctx);
    let mut second = Recorder::in_context("dS/dφ → d^2S/dφ^2", d2s_scale, ctx);
    let (v_max, a_max) = peaks(spec);
    let (v_mm, a_mm) = (ds_scale.to_mm(v_max), d2s_scale.to_mm(a_max));
    let s_top = DVec2::ZERO;
    let v_origin = DVec2::new(0.0, -(v_mm + GAP_MM));
    let v_top = DVec2::ZERO;
    let a_origin = DVec2::new(0.0, -(v_mm + a_mm + GAP_MM));
    let mut ds = vec![0.0; points.len()];
    let mut d2s = vec![0.0; points.len()];
    for (idx, (phase, len)) in [(0usize, spec.phases.rise), (2, spec.phases.ret)]
        .into_iter()
        .enumerate()
    {
        let dx = len / n as f64;
        let nodes: Vec<f64> = (0..=n)
            .map(|k| motion(spec, st[phase] + k as f64 * dx, k < n).s)
            .collect();
        let src = Diagram::new(st[phase], dx, nodes, false)?;
        let shift = DVec2::new(phi.to_mm(st[phase]), 0.0);
        let (p1, p2) = if idx == 0 {
            ("P_2", "P_1")
        } else {
            ("P_2′", "P_1′")
        };
        let layout = Layout::new(s_top + shift, v_origin + shift)
            .named("φ", "S", "dS/dφ")
            .pole_named(p1, "H_2");
        let scales = Scales { x: phi, y: s_scale };
        let v = Calc::Chords.differentiate(&mut first, &src, scales, h2, &layout)?;
        let layout2 = Layout::new(v_top + shift, a_origin + shift)
            .named("φ", "dS/dφ", "d^2S/dφ^2")
            .pole_named(p2, "H_1")
            .with_source(false);
        let scales2 = Scales {
            x: phi,
            y: ds_scale,
        };
        let a = Calc::Chords.differentiate(&mut second, &v.diagram()?, scales2, h1, &layout2)?;
        let base = idx * (n + 1);
        for k in 0..=n {
            if let Some(slot) = ds.get_mut(base + k) {
                *slot = v.node.get(k).copied().unwrap_or(0.0);
            }
            if let Some(slot) = d2s.get_mut(base + k) {
                *slot = a.node.get(k).copied().unwrap_or(0.0);
            }
        }
    }
    // The dwells: S = h on the far dwell, 0 on the near one; zero analogues.
    for (from, to, s) in [(st[1], st[2], spec.stroke), (st[3], st[4], 0.0)] {
        let (a, b) = (phi.to_mm(from), phi.to_mm(to));
        for (which, origin, y, role) in [
            (0, s_top, s_scale.to_mm(s), Role::Given),
            (0, v_origin, 0.0, Role::Result),
            (1, a_origin, 0.0, Role::Result),
        ] {
            let rec = if which == 0 { &mut first } else { &mut second };
            rec.draw(
                "dwell",
                Item::Segment(Segment::new(
                    origin + DVec2::new(a, y),
                    origin + DVec2::new(b, y),
                )),
                role,
                &[],
            );
        }
    }
    // S at the points, read off the given diagram.
    let s = points
        .iter()
        .map(|p| {
            let m = motion(spec, p.phi, p.after);
            let x = phi.to_mm(p.phi);
            let read = first.measure(
                s_top + DVec2::new(x, 0.0),
                s_top + DVec2::new(x, s_scale.to_mm(m.s)),
            );
            s_scale.to_physical(read.read_mm)
        })
        .collect();
    let ends = |i: usize| ds.get(i).copied().unwrap_or(0.0);
    Ok(Diagrams {
        first: first.finish(),
        second: second.finish(),
        s,
        ds_ends: [ends(n), ends(2 * n + 1)],
        ds,
        d2s,
        phi,
        s_scale,
        ds_scale,
        d2s_scale,
        poles: [h1, h2],
    })
}
