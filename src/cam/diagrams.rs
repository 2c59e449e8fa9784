//! The diagrams by graphical integration: the given d²S/dφ² integrated twice, phase by
//! phase, with the chord/pole method of [`crate::calculus`] at the textbook's scales (or the
//! given S differentiated twice by chords).
//!
//! Each diagram is its own figure (its own view on the sheet, with its axes): d²S/dφ²,
//! dS/dφ and S over the whole cycle, φ = 0 at each figure's origin. A construction runs
//! from one diagram into the next — the pole, the mid-interval ordinates and the rays in
//! the integrand's figure, the chords and the curve in the integral's — and each phase has
//! its own: the rise's pole H left of the ordinate axis, the return's past the end of the
//! return ([`FAN_GAP_MM`]), its rays running to a vertical H further right, so that the
//! return's construction never lies over the rise's. The integration goes on across the
//! dwells as the textbook's does: the far dwell is drawn at the S the rise's chords reached
//! and the return starts from there, so S has no step where a phase meets a dwell.
//!
//! Each phase is integrated over its points' intervals ([`super::motion::divisions`]): the
//! scene's equal ones, and a division point on every jump or corner of the given d²S/dφ²
//! between them, so that the diagram is smooth over each interval and the mid-interval
//! ordinate stands for it to the chord method's own (second-order) error. A jump inside an
//! interval would be taken from one side over the whole interval: with "linear with
//! blends" (0,2) at 12 equal intervals the rise ended 13 % short of the stroke.

use super::law::Shock;
use super::motion::{motion, motion_u, FollowerMotion, Point};
use super::{CamError, CamSpec, Given};
use crate::calculus::{
    integrate_divided_in, Derivation, Derivative, Diagram, DiagramLayout, Divided, Figures,
    Integral, Scales,
};
use crate::construct::{Context, Figure, Item, Recorder, Role, StepId};
use crate::geom::{DVec2, Segment};
use crate::scale::Scale;
use std::f64::consts::TAU;

mod differentiated;
mod phi_axis;
mod scales;
mod shocks;
use differentiated::differentiated;
pub use phi_axis::{PHASE_NOTES, TICK_NOTE};
use scales::scales;
use shocks::{shock_arrows, velocity_jumps};

/// The names of the poles and pole distances of the two constructions: between d²S/dφ² and
/// dS/dφ (the rise's pole, the return's, the distance), and between dS/dφ and S.
pub const POLES: [[&str; 3]; 2] = [["P_1", "P_1′", "H_1"], ["P_2", "P_2′", "H_2"]];

/// The return's pole lies this far past the end of the return, mm.
const FAN_GAP_MM: f64 = 12.0;
/// The pole distance's dimension line lies this far below the lowest ray and below the φ
/// axis's numbers, mm.
const POLE_DIMENSION_MM: f64 = 8.0;
/// The three diagrams, each its own figure: d²S/dφ² given and dS/dφ, S integrated by the
/// chord/pole method (or S given and differentiated twice by chords).
#[derive(Debug, Clone, PartialEq)]
pub struct CamDiagrams {
    /// d²S/dφ² (drawn at μ_S″): given, with the poles P₁, P₁′ and their rays; or constructed.
    pub d2s_view: Figure,
    /// dS/dφ (drawn at μ_S′): constructed, with the poles P₂, P₂′ of the next construction.
    pub ds_view: Figure,
    /// S (drawn at μ_S): constructed, or given with its chords.
    pub s_view: Figure,
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
    /// Whether each pole is drawn on some phase: a given d²S/dφ² with no ordinate on either
    /// phase (the uniform law's, its rigid shocks only at the phases' ends) is integrated
    /// without P₁, and its μ_S″ and H₁ are stated nowhere.
    pub drawn_poles: [bool; 2],
    /// S at the points, as read.
    pub s: Vec<f64>,
    /// dS/dφ at the points, as read.
    pub ds: Vec<f64>,
    /// d²S/dφ² at the points, as read off the given diagram.
    pub d2s: Vec<f64>,
    /// S′ at the end of the rise and of the return, as read (the equal-return check: 0).
    pub ds_ends: [f64; 2],
    /// The S diagram's largest ordinate as read, mm, when μ_S = h / y_max was found from it
    /// (d²S/dφ² integrated at a μ_S the scene does not give; seed 002 (4.2)).
    pub y_max: Option<f64>,
}

/// Which diagram a figure of [`CamDiagrams`] is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Analogue {
    /// d²S/dφ².
    D2s,
    /// dS/dφ.
    Ds,
    /// S.
    S,
}

impl CamDiagrams {
    /// The figures in the order a construction runs through them, top to bottom on the
    /// sheet: d²S/dφ², dS/dφ, S when d²S/dφ² is given; S, dS/dφ, d²S/dφ² when S is.
    pub fn stack(&self, given: Given) -> [(Analogue, &Figure); 3] {
        let (a, v, s) = (
            (Analogue::D2s, &self.d2s_view),
            (Analogue::Ds, &self.ds_view),
            (Analogue::S, &self.s_view),
        );
        match given {
            Given::D2s => [a, v, s],
            Given::S => [s, v, a],
        }
    }
}

/// The three recorders of the diagrams.
struct Views {
    a: Recorder,
    v: Recorder,
    s: Recorder,
}

impl Views {
    fn new(sc: [Scale; 3], ctx: &Context) -> Self {
        let [s, v, a] = sc;
        Self {
            a: Recorder::in_context("d^2S/dφ^2", a, ctx),
            v: Recorder::in_context("dS/dφ", v, ctx),
            s: Recorder::in_context("S", s, ctx),
        }
    }

    /// Tag what follows: 1 the rise's construction, 2 the return's, 0 the rest.
    fn group(&mut self, g: u32) {
        for r in [&mut self.a, &mut self.v, &mut self.s] {
            r.set_group(g);
        }
    }

    /// The dwells: on the abscissa of d²S/dφ² (given or constructed) and dS/dφ, on S at the
    /// level `s_mm[i]` the curve has reached (far dwell, near dwell).
    fn dwells(&mut self, spec: &CamSpec, phi: Scale, given: Given, s_mm: [f64; 2]) {
        let st = spec.starts();
        self.group(0);
        let (a_role, s_role) = match given {
            Given::D2s => (Role::Given, Role::Result),
            Given::S => (Role::Result, Role::Given),
        };
        for (k, (from, to)) in [(st[1], st[2]), (st[3], st[4])].into_iter().enumerate() {
            let (x0, x1) = (phi.to_mm(from), phi.to_mm(to));
            if x1 - x0 <= 0.0 {
                continue;
            }
            let name = if k == 0 { "far dwell" } else { "near dwell" };
            let flat = |y: f64| Item::Segment(Segment::new(DVec2::new(x0, y), DVec2::new(x1, y)));
            self.a.draw(name, flat(0.0), a_role, &[]);
            self.v.draw(name, flat(0.0), Role::Result, &[]);
            self.s.draw(name, flat(s_mm[k]), s_role, &[]);
        }
    }

    /// Each figure's axes, around what it draws, its φ axis marked ([`phi_axis::mark`]:
    /// the numbers of `points` on the side away from the figure's `values` — d²S/dφ², dS/dφ,
    /// S at the points — and the phases on the displacement diagram).
    fn finish(
        mut self,
        (spec, points): (&CamSpec, &[Point]),
        phi: Scale,
        values: [&[f64]; 3],
    ) -> [Figure; 3] {
        let cycle = phi.to_mm(TAU);
        for (k, (rec, name)) in [
            (&mut self.a, "d^2S/dφ^2"),
            (&mut self.v, "dS/dφ"),
            (&mut self.s, "S"),
        ]
        .into_iter()
        .enumerate()
        {
            axes(rec, cycle, name);
            rec.set_group(0);
            phi_axis::mark(rec, spec, points, phi, values[k], k == 2);
        }
        [self.a.finish(), self.v.finish(), self.s.finish()]
    }
}

/// The axes of a diagram over the cycle (`cycle` mm): the abscissa from the leftmost point
/// it draws (the rise's pole lies on it) to 12 mm past the cycle's end or the return's
/// construction, the ordinate at φ = 0 from 6 mm below to 12 mm above the diagram.
fn axes(rec: &mut Recorder, cycle: f64, name: &str) {
    let mut lo = DVec2::new(0.0, 0.0);
    let mut hi = DVec2::new(cycle, 0.0);
    let figure = Figure {
        title: String::new(),
        scale: rec.scale(),
        steps: rec
            .steps()
            .iter()
            .filter(|s| s.role != Role::Dimension)
            .cloned()
            .collect(),
        readings: Vec::new(),
    };
    if let Some((a, b)) = figure.bounds() {
        lo = lo.min(a);
        hi = hi.max(b);
    }
    crate::calculus::draw_axes(
        rec,
        DVec2::ZERO,
        (lo.x.min(-6.0), hi.x + 12.0),
        (lo.y - 6.0, hi.y + 12.0),
        ("φ", name),
    );
}

/// Where a phase's constructions lie.
#[derive(Debug, Clone, Copy)]
struct Lie {
    /// 0 the rise, 1 the return.
    idx: usize,
    /// The phase's start on the diagrams (its origin there), and its end's abscissa, mm.
    at: (DVec2, f64),
}

impl Lie {
    /// The rise (`idx` 0, phase 0) or the return (1, phase 2) of `spec` at μ_φ `phi`.
    fn of(spec: &CamSpec, phi: Scale, idx: usize) -> Self {
        let st = spec.starts();
        let phase = 2 * idx;
        Lie {
            idx,
            at: (
                DVec2::new(phi.to_mm(st[phase]), 0.0),
                phi.to_mm(st[phase + 1]),
            ),
        }
    }

    /// Its construction with the pole distance `h`, the axes' `names` and the `poles`' names.
    fn pass<'a>(self, h: f64, names: [&'a str; 3], poles: [&'a str; 3]) -> Pass<'a> {
        Pass {
            idx: self.idx,
            at: self.at,
            h,
            names,
            poles,
        }
    }
}

/// One construction of one phase, from the diagram it is given into the one it builds.
struct Pass<'a> {
    /// 0 the rise, 1 the return.
    idx: usize,
    /// The phase's start on the diagrams (its origin there), and its end's abscissa, mm.
    at: (DVec2, f64),
    /// The pole distance, mm.
    h: f64,
    /// The abscissa's, the given diagram's and the built diagram's names.
    names: [&'a str; 3],
    /// The pole's name for the rise and for the return, and the distance's name.
    poles: [&'a str; 3],
}

impl Pass<'_> {
    /// The layout: the diagrams at the phase's start in their figures; the rise's pole H
    /// left of the ordinate axis; the return's [`FAN_GAP_MM`] past the return's end, its
    /// rays running to the vertical H further right; the dimension H [`POLE_DIMENSION_MM`]
    /// below the lowest level the rays reach (`levels`, mm) and the φ axis's numbers.
    fn layout(&self, levels: &[f64]) -> DiagramLayout {
        let lowest = levels.iter().fold(-phi_axis::NUMBERS_MM, |m, &y| m.min(y));
        let [rise, ret, distance] = self.poles;
        let (shift, end_x) = self.at;
        let [x, given, built] = self.names;
        let lay = DiagramLayout::new(shift, shift)
            .named(x, given, built)
            .pole_named(if self.idx == 0 { rise } else { ret }, distance)
            .with_source(false)
            .without_axes()
            // The label up and left, clear of the rays (which run right) and of the abscissa.
            .pole_marks(lowest - POLE_DIMENSION_MM, DVec2::new(-1.0, 1.0));
        if self.idx == 0 {
            lay
        } else {
            lay.rays_to(end_x + FAN_GAP_MM + self.h)
        }
    }

    /// Integrate the division `src` (its mid-interval ordinates) drawn in `given` at
    /// `scales` into `built`, from `start`.
    fn integrate(
        &self,
        (given, built): (&mut Recorder, &mut Recorder),
        src: &Divided,
        scales: Scales,
        start: f64,
    ) -> Result<Integral, CamError> {
        let levels: Vec<f64> = src.mid.iter().map(|&m| scales.y.to_mm(m)).collect();
        let figs = Figures::Two { given, built };
        let layout = self.layout(&levels);
        Ok(integrate_divided_in(
            figs, src, scales, self.h, start, &layout,
        )?)
    }

    /// Differentiate the nodes `src` drawn in `given` at `scales` by chords into `built`; at
    /// an end whose tangent the law makes horizontal (`flat`: the first, the last) the node
    /// is taken from that tangent.
    fn differentiate(
        &self,
        (given, built): (&mut Recorder, &mut Recorder),
        src: &Diagram,
        scales: Scales,
        flat: bool,
    ) -> Result<Derivative, CamError> {
        let run = scales.x.to_mm(src.dx);
        let levels = cut_levels(&src.y, scales.y, run, self.h);
        let figs = Figures::Two { given, built };
        let tangent = flat.then_some(DVec2::X);
        let layout = self.layout(&levels).tangents_at_ends(tangent, tangent);
        Ok(Derivation::Chords.differentiate_in(figs, src, scales, self.h, &layout)?)
    }
}

/// The points the curve recorded as `id` is drawn through, figure mm.
fn drawn_points(rec: &Recorder, id: StepId) -> &[DVec2] {
    match rec.steps().get(id.0 as usize).map(|s| &s.item) {
        Some(Item::Curve { points, .. } | Item::Polyline { points, .. }) => points,
        _ => &[],
    }
}

/// Where the curve recorded as `id` ends, figure mm.
fn drawn_end(rec: &Recorder, id: StepId) -> Option<DVec2> {
    drawn_points(rec, id).last().copied()
}

/// The diagrams: the given d²S/dφ² (closed form at the mid-interval points and the nodes)
/// integrated twice, phase by phase, with the poles H₁, H₂ (see the module's documentation);
/// or the given S differentiated twice. Integrated at a μ_S the scene does not give, the
/// law's shape is drawn and integrated once, and read at the scales μ_S = h / y_max gives
/// ([`scales::fitted`]): the drawing is the same, its values are the fitted scales'.
pub(super) fn diagrams(
    spec: &CamSpec,
    points: &[Point],
    ctx: &Context,
) -> Result<CamDiagrams, CamError> {
    let (phi, sc, poles) = scales(spec, points)?;
    if spec.given == Given::S {
        return differentiated(spec, points, phi, sc, poles, ctx);
    }
    let drawn = integrated(spec, (points, ctx), (phi, sc, poles), 1.0)?;
    if spec.scale_s.is_some() {
        return Ok(drawn);
    }
    let s_max = drawn.s.iter().fold(0.0f64, |m, &s| m.max(s));
    match scales::fitted(sc, spec.stroke, s_max) {
        Some((k, fit)) => {
            let d = integrated(spec, (points, ctx), (phi, fit, poles), k)?;
            Ok(CamDiagrams {
                y_max: Some(sc[0].to_mm(s_max)),
                ..d
            })
        }
        None => Ok(drawn),
    }
}

/// The diagrams integrated from the given d²S/dφ² at the scales `sc`, the law's values
/// taken `k` times (the law's shape drawn at `sc` / `k`).
fn integrated(
    spec: &CamSpec,
    (points, ctx): (&[Point], &Context),
    (phi, sc, poles): (Scale, [Scale; 3], [f64; 2]),
    k: f64,
) -> Result<CamDiagrams, CamError> {
    let [s_scale, ds_scale, d2s_scale] = sc;
    let [h1, h2] = poles;
    let st = spec.starts();
    let mut views = Views::new(sc, ctx);
    let mut ds_nodes = vec![0.0; points.len()];
    let mut s_nodes = vec![0.0; points.len()];
    let mut ds_ends = [0.0; 2];
    // Where the S curve has got to, mm: the far dwell and the return go on from there.
    let mut level = [0.0; 2];
    let mut s_start = 0.0;
    let mut drawn_poles = [false; 2];
    for (idx, phase) in [0usize, 2].into_iter().enumerate() {
        views.group(idx as u32 + 1);
        // The phase's division points: equal intervals and one on every break of the given
        // diagram (motion::divisions), so that it is smooth over each interval.
        let at: Vec<usize> = (0..points.len())
            .filter(|&i| points[i].phase == phase)
            .collect();
        let x: Vec<f64> = at.iter().map(|&i| points[i].phi).collect();
        let mids: Vec<f64> = x
            .windows(2)
            .map(|w| k * motion(spec, 0.5 * (w[0] + w[1]), true).d2s)
            .collect();
        // The given diagram itself: its curve through the nodes, the mid-interval points and
        // both sides of a jump.
        let curve = given_curve(spec, phase, &x, phi, d2s_scale, k);
        views.a.draw(
            format!("given d²S/dφ² of phase {phase}"),
            Item::Polyline {
                points: curve,
                closed: false,
            },
            Role::Given,
            &[],
        );
        shock_arrows(&mut views.a, spec, phase, phi);
        let src = Divided::new(x.clone(), mids)?;
        let lie = Lie::of(spec, phi, idx);
        // A uniform law starts at dS/dφ = h/Φ: the jump (a δ of acceleration, the rigid
        // shock) is no ordinate of the given diagram, so it is laid off as the start value.
        let v0 = k * motion(spec, st[phase], true).ds;
        let v = lie
            .pass(h1, ["φ", "d^2S/dφ^2", "dS/dφ"], POLES[0])
            .integrate(
                (&mut views.a, &mut views.v),
                &src,
                Scales {
                    x: phi,
                    y: d2s_scale,
                },
                v0,
            )?;
        ds_ends[idx] = *v.node.last().unwrap_or(&0.0);
        velocity_jumps(&mut views.v, v.curve);
        drawn_poles[0] |= v.pole_drawn;
        for (&i, &val) in at.iter().zip(&v.node) {
            ds_nodes[i] = val;
        }
        // The second integration reads dS/dφ at the middle of each chord it has drawn.
        let mids_v: Vec<f64> = v.node.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
        let s = lie.pass(h2, ["φ", "dS/dφ", "S"], POLES[1]).integrate(
            (&mut views.v, &mut views.s),
            &Divided::new(x, mids_v)?,
            Scales {
                x: phi,
                y: ds_scale,
            },
            s_start,
        )?;
        drawn_poles[1] |= s.pole_drawn;
        for (&i, &val) in at.iter().zip(&s.node) {
            s_nodes[i] = val;
        }
        // The dwell after the phase, and the next phase, go on from the curve's drawn end.
        let end = drawn_end(&views.s, s.curve).map_or(0.0, |p| p.y);
        level[idx] = end;
        s_start = s_scale.to_physical(end);
    }
    views.dwells(spec, phi, Given::D2s, level);
    // d²S/dφ² at the points, read off the given diagram.
    let d2s: Vec<f64> = points
        .iter()
        .map(|p| {
            let m = motion(spec, p.phi, p.after);
            let x = phi.to_mm(p.phi);
            let top = DVec2::new(x, d2s_scale.to_mm(k * m.d2s));
            let read = views.a.measure(DVec2::new(x, 0.0), top);
            d2s_scale.to_physical(read.read_mm).copysign(m.d2s)
        })
        .collect();
    let [d2s_view, ds_view, s_view] =
        views.finish((spec, points), phi, [&d2s, &ds_nodes, &s_nodes]);
    Ok(CamDiagrams {
        d2s_view,
        ds_view,
        s_view,
        phi,
        s_scale,
        ds_scale,
        d2s_scale,
        poles,
        drawn_poles,
        s: s_nodes,
        ds: ds_nodes,
        d2s,
        ds_ends,
        y_max: None,
    })
}

/// The given d²S/dφ² of one phase as drawn (its values `k` times the law's): from the abscissa up the jump at its start,
/// through the nodes, the middles of the intervals between the division points `x` (the
/// tops of the mid-interval ordinates lie on it) and both sides of every jump, down to the
/// abscissa at its end.
fn given_curve(
    spec: &CamSpec,
    phase: usize,
    x: &[f64],
    phi: Scale,
    mu: Scale,
    k: f64,
) -> Vec<DVec2> {
    let st = spec.starts()[phase];
    let (law, len) = if phase == 0 {
        (spec.rise, spec.phases.rise)
    } else {
        (spec.ret, spec.phases.ret)
    };
    let mut us: Vec<(f64, bool)> = (0..=48).map(|k| (k as f64 / 48.0, true)).collect();
    us.extend(
        x.windows(2)
            .map(|w| ((0.5 * (w[0] + w[1]) - st) / len, true)),
    );
    for b in law.breaks() {
        us.push((b, false));
        us.push((b, true));
    }
    us.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    us.dedup();
    let mut pts = vec![DVec2::new(phi.to_mm(st), 0.0)];
    for (u, after) in us {
        let after = if u >= 1.0 { false } else { after };
        let m = motion_u(spec, phase, u, after);
        pts.push(DVec2::new(phi.to_mm(st + u * len), mu.to_mm(k * m.d2s)));
    }
    pts.push(DVec2::new(phi.to_mm(st + len), 0.0));
    pts
}

/// The motion as read off the diagrams at point `i`.
pub(super) fn read_motion(d: &CamDiagrams, i: usize) -> FollowerMotion {
    FollowerMotion {
        s: d.s.get(i).copied().unwrap_or(0.0),
        ds: d.ds.get(i).copied().unwrap_or(0.0),
        d2s: d.d2s.get(i).copied().unwrap_or(0.0),
    }
}

/// The levels (mm) where rays from a pole H (mm) parallel to the chords of `nodes`
/// (physical, drawn at `mu`, `run` mm apart) cut the ordinate axis.
fn cut_levels(nodes: &[f64], mu: Scale, run: f64, h: f64) -> Vec<f64> {
    nodes
        .windows(2)
        .map(|w| h * (mu.to_mm(w[1]) - mu.to_mm(w[0])) / run)
        .collect()
}
