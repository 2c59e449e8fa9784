//! The displacement diagram S(φ₁) of a point read off the plan of positions, differentiated
//! twice graphically (chords, or tangents), and its rows against the analytic values.

use super::axis::{number_derivative_axis, number_phi_axis};
use super::{extent, numbered, pole_and_scale, turn_diagram, KinError, KinematicsSpec};
use super::{DIAGRAM_GAP, DIAGRAM_MM};
use crate::calculus::{self, Derivative, Diagram, DiagramLayout, Scales};
use crate::check::{Key, Method, Row, Symbol};
use crate::construct::{Context, Drafting, Figure, Recorder};
use crate::geom::DVec2;
use crate::linkage::{plain, Output, PositionPlan, Program, Sense};
use crate::scale::{Quantity, Scale};
use std::f64::consts::TAU;

/// Abscissa of one crank turn on a diagram when μ_φ is not given, mm.
const TURN_MM: f64 = 240.0;

/// The size the chart is drawn at where the scene leaves a scale or a pole distance to it:
/// one crank turn's abscissa (when μ_φ is free) and a diagram's ordinates (when μ_S, H₁ or H₂
/// is free), mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChartSize {
    /// One crank turn along φ, mm.
    pub turn_mm: f64,
    /// A diagram's height, mm.
    pub ordinate_mm: f64,
}

impl ChartSize {
    /// The textbook's chart: 2π on 240 mm, each diagram about 35 mm tall.
    pub const TEXTBOOK: Self = Self {
        turn_mm: TURN_MM,
        ordinate_mm: DIAGRAM_MM,
    };

    /// The textbook's chart drawn `along` times as long and `up` times as tall.
    pub fn times(along: f64, up: f64) -> Self {
        Self {
            turn_mm: TURN_MM * along,
            ordinate_mm: DIAGRAM_MM * up,
        }
    }
}

impl Default for ChartSize {
    fn default() -> Self {
        Self::TEXTBOOK
    }
}

/// The displacement diagram and its two graphical derivatives.
#[derive(Debug, Clone, PartialEq)]
pub struct KinDiagrams {
    /// The charted point's name.
    pub point: String,
    /// μ_φ, μ_s of the displacement diagram.
    pub scales: Scales,
    /// The displacement diagram and the first derivative, drawn together.
    pub first_figure: Figure,
    /// The second derivative; its figure's origin lies at `second_at` of the first figure
    /// (on the dS/dφ axes, where its chords are drawn).
    pub second_figure: Figure,
    /// Where the second figure's origin lies in the first figure's coordinates, mm.
    pub second_at: DVec2,
    /// dS/dφ₁.
    pub first: Derivative,
    /// d²S/dφ₁².
    pub second: Derivative,
    /// The displacement read off the plan at the numbered positions, m.
    pub s: Vec<f64>,
    /// The segments S is read off, from the start of the working stroke to the charted
    /// point at each numbered position (in that position's group), in the plan of positions'
    /// mm at its μ_l: a figure that draws nothing, whose readings the plan's figure takes
    /// where a sheet draws it ([`crate::study::Kinematics::plan_figure`]).
    pub readings: Figure,
    /// S, v = |ω₁|·dS/dφ₁, a = ω₁²·d²S/dφ₁² at the numbered positions against the twin.
    pub rows: Vec<Row>,
    /// The positions where S has a corner (a change point): each side differentiated alone.
    pub corners: Vec<String>,
}

/// The charted point (the scene's, or the first slider output) and the direction its
/// displacement is measured along.
pub fn target(
    plan: &PositionPlan,
    outputs: &[Output],
    spec: &KinematicsSpec,
) -> Result<Option<(usize, DVec2)>, KinError> {
    let slider = outputs.iter().find_map(|o| match o {
        Output::Slider { point, dir } => Some((point.clone(), *dir)),
        Output::Rocker { .. } => None,
    });
    let name = match (&spec.diagram_point, &slider) {
        (Some(n), _) => n.clone(),
        (None, Some((n, _))) => n.clone(),
        (None, None) => return Ok(None),
    };
    let k = plan.program.index(&name).ok_or(KinError::NoSuchPoint {
        key: "diagram",
        name,
    })?;
    let dir = slider.map_or(0.0, |s| s.1);
    Ok(Some((k, DVec2::from_angle(dir))))
}

/// The positions of the plan (indices) where the working stroke starts and ends: the first
/// output's extremes, when the plan draws both.
fn stroke_ends(plan: &PositionPlan) -> Option<(usize, usize)> {
    let ex = plan.extremes.as_ref()?;
    let at = |phi: f64| {
        plan.positions.iter().position(|p| {
            let d = (p.phi - phi).rem_euclid(TAU);
            d.min(TAU - d) < 1e-9
        })
    };
    Some((at(ex.phi_start)?, at(ex.phi_other)?))
}

/// The twin's origin of S and its direction: the charted slider's analytic extreme at the
/// start of the working stroke and the way it runs from there (its range: from the minimum
/// up, or from the maximum down), when the plan draws the stroke's ends; else position 1's
/// point and the scene's direction.
fn twin_origin(
    plan: &PositionPlan,
    outputs: &[Output],
    (k, dir): (usize, DVec2),
) -> (DVec2, DVec2) {
    let first = || {
        numbered(plan)
            .first()
            .map_or(DVec2::ZERO, |(_, p)| p.pose.p[k])
    };
    let (Some(ex), Some((start, end))) = (plan.extremes.as_ref(), stroke_ends(plan)) else {
        return (first(), dir);
    };
    let origin = plan.positions[start].pose.p[k];
    let slider = outputs.iter().find_map(|o| match o {
        Output::Slider { point, dir } if plan.program.index(point) == Some(k) => Some(*dir),
        _ => None,
    });
    let range = ex
        .ranges
        .iter()
        .find(|r| matches!(r.coord, crate::linkage::OutputCoord::Slider(i, _) if i == k));
    match (slider, range) {
        (Some(dir), Some(r)) => {
            let d = DVec2::from_angle(dir);
            let from_max = (origin.dot(d) - r.max).abs() < (origin.dot(d) - r.min).abs();
            (origin, if from_max { -d } else { d })
        }
        // Another point than the stroke's slider: the way it goes over the working stroke.
        _ => {
            let to = plan.positions[end].pose.p[k];
            (origin, dir * (to - origin).dot(dir).signum())
        }
    }
}

/// How far below the lowest level its rays reach the pole distance's dimension line is
/// drawn, mm: the rays fan out from the pole over the whole span of the derivative, so the
/// dimension H and its text (over the line) stand clear of them under the fan.
pub(super) const POLE_DIMENSION_MM: f64 = 7.0;
/// The pole's label: up and left of the pole, away from the rays (which run right).
pub(super) const POLE_LABEL: DVec2 = DVec2::new(-0.6, 1.0);

/// The chart's scales: μ_S and μ_φ as given, or chosen for the displacement's span and the
/// chart's `size`.
fn chart_scales(spec: &KinematicsSpec, s: &[f64], size: ChartSize) -> Result<Scales, KinError> {
    let span = super::peak(s.iter().copied());
    let y = match spec.scale_s {
        Some(s) => s,
        None => super::round_scale(span.max(1e-9), size.ordinate_mm, Quantity::Length)?,
    };
    let x = match spec.scale_phi {
        Some(s) => s,
        None => Scale::new(TAU / size.turn_mm, Quantity::Angle).ok_or(KinError::NoScale {
            quantity: Quantity::Angle,
            value: TAU,
        })?,
    };
    Ok(Scales { x, y })
}

/// S of point `k` read off the plan of positions (at μ_l = `scale_l`) at the `numbered`
/// positions: the distance from the start of the working stroke (position 1 when no extreme
/// is drawn), positive along the working stroke; at the plan's other positions (its extremes
/// between the numbered ones, S 0 at the stroke's start), each with its travel from
/// position 1 (rad); and the figure of the segments read, each in the group its
/// position is drawn in, m.
fn read_displacement(
    plan: &PositionPlan,
    numbered: &[(usize, &crate::linkage::PlanPosition)],
    (k, dir): (usize, DVec2),
    scale_l: Scale,
    ctx: &Context,
) -> Displacements {
    let mut reader = Recorder::in_context("S", scale_l, ctx);
    let ends = stroke_ends(plan);
    let (p1, read_dir) = match ends {
        Some((a, b)) => {
            let (pa, pb) = (plan.positions[a].built.p[k], plan.positions[b].built.p[k]);
            (pa, dir * (pb - pa).dot(dir).signum())
        }
        None => (numbered[0].1.built.p[k], dir),
    };
    let mut read = |i: usize, p: &crate::linkage::PlanPosition| {
        reader.set_group(i as u32 + 1);
        let d = p.built.p[k] - p1;
        reader.measure(p1, p.built.p[k]).value * d.dot(read_dir).signum()
    };
    let s = numbered.iter().map(|&(i, p)| read(i, p)).collect();
    let between = super::between(plan)
        .into_iter()
        .map(|(i, travel, p)| Extreme {
            travel,
            // The stroke's start is S's origin: nothing to read there.
            s: if ends.map(|e| e.0) == Some(i) {
                0.0
            } else {
                read(i, p)
            },
            label: p.label.clone(),
        })
        .collect();
    Displacements {
        s,
        between,
        figure: reader.finish(),
    }
}

/// An extreme position between the numbered ones, as the S chart plots it.
struct Extreme {
    /// The crank's travel from position 1, rad.
    travel: f64,
    /// S there, m.
    s: f64,
    /// Its label (`6′`).
    label: String,
}

/// What [`read_displacement`] reads off the plan of positions.
struct Displacements {
    /// S at the numbered positions, m.
    s: Vec<f64>,
    /// The other positions the plan draws: its extremes between the numbered ones.
    between: Vec<Extreme>,
    /// The segments read.
    figure: Figure,
}

/// S(φ₁) of the charted point read off the plan at the numbered positions (at μ_l =
/// `scale_l`), its two graphical derivatives at the chart's `size`, and their rows. `None`
/// when the mechanism has no point to chart or fewer than three numbered positions.
pub fn diagrams(
    plan: &PositionPlan,
    outputs: &[Output],
    (spec, size): (&KinematicsSpec, ChartSize),
    scale_l: Scale,
    w1: f64,
    ctx: &Context,
) -> Result<Option<KinDiagrams>, KinError> {
    let Some((k, dir)) = target(plan, outputs, spec)? else {
        return Ok(None);
    };
    let numbered = numbered(plan);
    if numbered.len() < 3 {
        return Ok(None);
    }
    super::full_turn(plan)?;
    let name = plan.program.names[k].clone();
    let fail = |what: &str, error| KinError::Diagram {
        what: format!("{what} of {name}"),
        error,
    };
    let Displacements {
        s,
        between,
        figure: reader,
    } = read_displacement(plan, &numbered, (k, dir), scale_l, ctx);
    let src = displacement(&numbered, s.clone()).map_err(|e| fail("S", e))?;
    let all_s: Vec<f64> = s
        .iter()
        .chain(between.iter().map(|b| &b.s))
        .copied()
        .collect();
    let scales = chart_scales(spec, &all_s, size)?;
    let (h1, mu1) = pole_and_scale(
        spec.pole_h1,
        &src,
        scales,
        size.ordinate_mm,
        Quantity::Length,
    )
    .map_err(|e| fail("dS/dφ", e))?;
    // The textbook's stack: S on top, dS/dφ under it, d²S/dφ² under that; the second
    // differentiation's chords are drawn on the dS/dφ curve itself (its figure's source axes
    // coincide with the first figure's result axes). Each diagram is placed from the
    // extent of its ordinates.
    let (construction, method) = if spec.tangents {
        (calculus::Derivation::Tangents, Method::DiagramTangents)
    } else {
        (calculus::Derivation::Chords, Method::DiagramChords)
    };
    let (s_lo, _) = extent(all_s.iter(), scales.y);
    let (d1_lo, d1_hi) = ordinates(&src, scales, h1, mu1, ctx).map_err(|e| fail("dS/dφ", e))?;
    let mut rec1 = Recorder::in_context("dS/dφ", mu1, ctx);
    // The extremes between the numbered positions are plotted too: the curve's crests.
    let through = (between.iter())
        .map(|b| DVec2::new(scales.x.to_mm(b.travel), scales.y.to_mm(b.s)))
        .collect();
    let lay1 = DiagramLayout::new(DVec2::ZERO, DVec2::new(0.0, s_lo - DIAGRAM_GAP - d1_hi))
        .source_through(through)
        .pole_named("P_1", "H_1")
        .pole_marks(d1_lo - POLE_DIMENSION_MM, POLE_LABEL);
    let first = construction
        .differentiate(&mut rec1, &src, scales, h1, &lay1)
        .map_err(|e| fail("dS/dφ", e))?;
    let d1 = first.diagram().map_err(|e| fail("dS/dφ", e))?;
    // The positions' numbers under the S diagram's φ axis, as on the plan of positions, and
    // the extremes' between them; the derivative's axis carries the numbers alone.
    let extremes: Vec<(f64, &String)> = between.iter().map(|b| (b.travel, &b.label)).collect();
    number_phi_axis(&mut rec1, (&src, &numbered), &extremes, scales.x);
    let at1 = (scales.x, lay1.origin.y, first.node.as_slice());
    number_derivative_axis(&mut rec1, (&src, &numbered), at1);
    let scales2 = Scales {
        x: scales.x,
        y: mu1,
    };
    let (h2, mu2) = pole_and_scale(
        spec.pole_h2,
        &d1,
        scales2,
        size.ordinate_mm,
        Quantity::Length,
    )
    .map_err(|e| fail("d²S/dφ²", e))?;
    let (d2_lo, d2_hi) = ordinates(&d1, scales2, h2, mu2, ctx).map_err(|e| fail("d²S/dφ²", e))?;
    let mut rec2 = Recorder::in_context("d²S/dφ²", mu2, ctx);
    let lay2 = DiagramLayout::new(DVec2::ZERO, DVec2::new(0.0, d1_lo - DIAGRAM_GAP - d2_hi))
        .with_source(false)
        .named("φ", "dS/dφ", "d²S/dφ²")
        .pole_named("P_2", "H_2")
        .pole_marks(d2_lo - POLE_DIMENSION_MM, POLE_LABEL);
    let second = construction
        .differentiate(&mut rec2, &d1, scales2, h2, &lay2)
        .map_err(|e| fail("d²S/dφ²", e))?;
    let at2 = (scales.x, lay2.origin.y, second.node.as_slice());
    number_derivative_axis(&mut rec2, (&src, &numbered), at2);
    let (p0, dir) = twin_origin(plan, outputs, (k, dir));
    let rows = rows(
        (&numbered, &plan.program, plan.mechanism.crank.sense),
        (k, &name, p0, dir),
        (&s, &first, &second),
        (w1, method),
    );
    Ok(Some(KinDiagrams {
        point: name,
        scales,
        first_figure: rec1.finish(),
        second_figure: rec2.finish(),
        second_at: lay1.origin,
        first,
        second,
        s,
        readings: reader,
        rows,
        corners: (src.breaks.iter())
            .map(|b| numbered[b.node].1.label.clone())
            .collect(),
    }))
}

/// The rows S, v = |ω₁|·dS/dθ, a = ω₁²·d²S/dθ² of point `k` (named `name`, S from `p0`
/// along `dir` on the twin) at the `numbered` positions: read `s` and off the derivatives,
/// against the twin. At a corner the derivatives are read off the piece that starts there,
/// so the twin's rates are the limit of the branch the crank turns onto (in its `sense`).
fn rows(
    (numbered, program, sense): (&[(usize, &crate::linkage::PlanPosition)], &Program, Sense),
    (k, name, p0, dir): (usize, &str, DVec2, DVec2),
    (s, first, second): (&[f64], &Derivative, &Derivative),
    (w1, method): (f64, Method),
) -> Vec<Row> {
    let q = plain(name);
    let analytic: Vec<[f64; 3]> = numbered
        .iter()
        .map(|(_, p)| {
            let beyond =
                (p.pose.toggle.as_ref()).and_then(|_| program.limit_beyond(p.phi, sense.sign()));
            let pose = beyond.as_ref().unwrap_or(&p.pose);
            [
                (pose.p[k] - p0).dot(dir),
                super::rate(pose, (pose.dp[k] * w1).length()),
                super::rate(pose, (pose.ddp[k] * (w1 * w1)).length()),
            ]
        })
        .collect();
    let scale = |j: usize| super::peak(analytic.iter().map(|a| a[j]));
    let (s_scale, v_scale, a_scale) = (scale(0), scale(1), scale(2));
    let mut rows = Vec::with_capacity(3 * numbered.len());
    for (idx, (_, p)) in numbered.iter().enumerate() {
        let v_gr = (first.node[idx] * w1.abs()).abs();
        let a_gr = (second.node[idx] * w1 * w1).abs();
        for (symbol, g, a, sc) in [
            (Symbol::Displacement, s[idx], analytic[idx][0], s_scale),
            (Symbol::Velocity, v_gr, analytic[idx][1], v_scale),
            (Symbol::Acceleration, a_gr, analytic[idx][2], a_scale),
        ] {
            rows.push(Row::new(
                Key::at_position(symbol, q.clone(), &p.label),
                method,
                g,
                a,
                sc,
            ));
        }
    }
    rows
}

/// S over the crank's turn at the `numbered` positions: a corner at every position where a
/// group's links lie on one line (a change point), which the mechanism leaves on its other
/// branch, so that each side is differentiated alone.
fn displacement(
    numbered: &[(usize, &crate::linkage::PlanPosition)],
    s: Vec<f64>,
) -> Result<Diagram, calculus::CalculusError> {
    let corners: Vec<usize> = (numbered.iter().enumerate())
        .filter(|(_, (_, p))| p.pose.toggle.is_some())
        .map(|(idx, _)| idx)
        .collect();
    turn_diagram(s)?.with_corners(&corners)
}

/// Lowest and highest drawn ordinate (mm) of the chord derivative of `d` at μ = `mu`, with 0
/// included: where the next diagram of the stack goes. The chords are worked out on a
/// scratch sheet that is not kept.
pub(super) fn ordinates(
    d: &Diagram,
    scales: Scales,
    h: f64,
    mu: Scale,
    ctx: &Context,
) -> Result<(f64, f64), calculus::CalculusError> {
    let mut r = Recorder::in_context("scratch", mu, &ctx.with_drafting(Drafting::EXACT));
    let lay = DiagramLayout::new(DVec2::ZERO, DVec2::ZERO).with_source(false);
    let dv = calculus::Derivation::Chords.differentiate(&mut r, d, scales, h, &lay)?;
    let left = dv.breaks.iter().map(|b| &b.left);
    Ok(extent(dv.mid.iter().chain(&dv.node).chain(left), mu))
}
