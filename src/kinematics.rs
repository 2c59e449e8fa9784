//! Kinematic analysis of a linkage, the graphical way and the analytic way side by side:
//! the plan of positions; a velocity plan for every position and acceleration plans for the
//! positions asked for; the displacement diagram of a point over a crank turn, differentiated
//! twice by the chord method; the hodograph of a point's velocity; and, for every value read
//! off a drawing, the analytic twin and the error (the rows of `tmm report`).

use crate::calculus::{self, Derivative, Diagram, Layout, Scales};
use crate::construct::{ConstructionError, Drafting, Figure, Item, Recorder, Role};
use crate::geom::{DVec2, Tolerances};
use crate::linkage::{
    kin_plan, plan_positions, KinPlan, LinkageError, Measure, Mechanism, Output, PlanKind,
    PlanRequest, PlanSetup, Pose, PositionPlan, Program,
};
use crate::report::{Column, Method, Row, Table};
use crate::scale::{Quantity, Scale};
use std::f64::consts::TAU;
use thiserror::Error;

/// Preferred drawn length of the crank pin's velocity and acceleration, mm (textbook 70–100).
const PLAN_MM: f64 = 70.0;
/// Preferred height of a diagram, mm.
const DIAGRAM_MM: f64 = 35.0;
/// Preferred peak ordinates of the rocker's ω diagram and its derivative, mm.
const ROCKER_MM: f64 = 22.0;
/// Abscissa of one crank turn on the rocker's ω diagram, mm.
const ROCKER_TURN_MM: f64 = 120.0;
/// Gap between stacked diagrams, mm.
const DIAGRAM_GAP: f64 = 16.0;
/// Length of the longest hodograph vector, mm.
const HODOGRAPH_MM: f64 = 45.0;
/// Abscissa of one crank turn on a diagram when μ_φ is not given, mm.
const TURN_MM: f64 = 240.0;

/// The `[kinematics]` section: scales and choices of the kinematic analysis. Every field is
/// optional; `None` leaves the choice to the analysis.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct KinematicsSpec {
    /// μ_v of the velocity plans, (m/s)/mm.
    pub scale_v: Option<Scale>,
    /// μ_a of the acceleration plans, (m/s²)/mm.
    pub scale_a: Option<Scale>,
    /// The positions whose acceleration plans are drawn, by label (`"3"`, `"8′"`); 1–4
    /// entries. A numbered label is at most the position count; a primed (extreme) label is
    /// checked against the plan of positions when it exists.
    pub acceleration_positions: Option<Vec<String>>,
    /// The point whose displacement S(φ₁) is charted and differentiated (`S_5`).
    pub diagram_point: Option<String>,
    /// μ_S of the displacement chart, m/mm.
    pub scale_s: Option<Scale>,
    /// μ_φ of the crank-angle axis of the charts, rad/mm.
    pub scale_phi: Option<Scale>,
    /// Pole distance H₁ of the first graphical differentiation, drawing mm.
    pub pole_h1: Option<f64>,
    /// Pole distance H₂ of the second graphical differentiation, drawing mm.
    pub pole_h2: Option<f64>,
    /// The point whose velocity hodograph is drawn (`S_3`).
    pub hodograph: Option<String>,
    /// Graphical differentiation by the method of tangents instead of chords
    /// (`differentiation = "tangents"`; default `"chords"`).
    pub tangents: bool,
}

/// What to analyse: the positions at μ_l, the scene's choices, the drafting model.
#[derive(Debug, Clone, PartialEq)]
pub struct KinRequest {
    /// The positions.
    pub positions: PlanRequest,
    /// μ_l of the plan of positions.
    pub scale_l: Scale,
    /// The scene's scales and choices (`None` fields are chosen the textbook way).
    pub spec: KinematicsSpec,
    /// The drafting model for every reading.
    pub drafting: Drafting,
}

/// Why the analysis cannot be carried out.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum KinError {
    /// The positions cannot be constructed.
    #[error(transparent)]
    Linkage(#[from] LinkageError),
    /// A plan cannot be constructed at a position.
    #[error("position {position}: {kind} plan, group {group}: {error}")]
    Plan {
        /// Position label.
        position: String,
        /// `velocity` or `acceleration`.
        kind: &'static str,
        /// The group (file order, 1-based).
        group: usize,
        /// The diagnostic.
        error: Box<crate::construct::ConstructionError>,
    },
    /// A diagram cannot be constructed.
    #[error("diagram of {what}: {error}")]
    Diagram {
        /// Which diagram.
        what: String,
        /// The diagnostic.
        error: calculus::CalculusError,
    },
    /// A request names something that does not exist.
    #[error("{0}")]
    Request(String),
}

/// The displacement diagram and its two chord-method derivatives.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagrams {
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
    /// dS/dφ₁ by chords.
    pub first: Derivative,
    /// d²S/dφ₁² by chords.
    pub second: Derivative,
    /// The displacement read off the plan at the numbered positions, m.
    pub s: Vec<f64>,
}

/// The whole analysis.
#[derive(Debug, Clone, PartialEq)]
pub struct Analysis {
    /// The plan of positions.
    pub plan: PositionPlan,
    /// ω₁, rad/s, signed counter-clockwise.
    pub w1: f64,
    /// μ_v.
    pub scale_v: Scale,
    /// μ_a.
    pub scale_a: Scale,
    /// One velocity plan per position of the plan, same order; `None` where it does not exist
    /// (a dyad at its toggle position, see `refused`).
    pub velocity: Vec<Option<KinPlan>>,
    /// Acceleration plans: (index into the positions, plan).
    pub acceleration: Vec<(usize, KinPlan)>,
    /// The diagrams, when the mechanism has a point to chart.
    pub diagrams: Option<Diagrams>,
    /// The angular-velocity diagram of the rocker from the velocity plans and its chord
    /// derivative (seed 000 §1.5): the link, its μ_ω, and the figure.
    pub rocker: Option<RockerDiagram>,
    /// The hodograph figure and its point's name.
    pub hodograph: Option<(String, Figure)>,
    /// Graphical against analytic, every reading.
    pub rows: Vec<Row>,
    /// The analytic table (the shape of seed 000 Table 5).
    pub table: Table,
    /// Positions whose velocity plan is refused, with the diagnosis.
    pub refused: Vec<(String, String)>,
}

fn tol() -> Tolerances {
    Tolerances::for_model_size(300.0).unwrap_or(Tolerances {
        coincident: 3e-8,
        parallel_sin: 2e-8,
        flatten_mm: 0.02,
        solver_accuracy: 1e-13,
    })
}

/// Velocity of the point `k` carried by link `l`, and its acceleration (m/s, m/s²).
fn carried(pose: &Pose, w1: f64, k: usize, l: usize) -> (DVec2, DVec2) {
    if l == 0 {
        return (DVec2::ZERO, DVec2::ZERO);
    }
    let o = pose.origin[l];
    let r = pose.p[k] - pose.p[o];
    let (w, e) = (pose.dangle[l], pose.ddangle[l]);
    let v = pose.dp[o] + r.perp() * w;
    let a = pose.ddp[o] + r.perp() * e - r * (w * w);
    (v * w1, a * (w1 * w1))
}

/// The analytic value of a reading.
fn analytic(pose: &Pose, w1: f64, what: Measure, kind: PlanKind) -> f64 {
    let vel = kind == PlanKind::Velocity;
    match what {
        Measure::Point(k) => {
            if vel {
                (pose.dp[k] * w1).length()
            } else {
                (pose.ddp[k] * (w1 * w1)).length()
            }
        }
        Measure::Rate(l) => {
            if vel {
                pose.dangle[l] * w1
            } else {
                pose.ddangle[l] * w1 * w1
            }
        }
        Measure::Relative { p, q } => {
            let (vp, ap) = carried(pose, w1, p.0, p.1);
            let (vq, aq) = carried(pose, w1, q.0, q.1);
            if vel {
                (vp - vq).length()
            } else {
                (ap - aq).length()
            }
        }
    }
}

/// The pole distance H (given, or chosen so the derivative's largest ordinate is about
/// `preferred` mm) and the derivative's scale μ_y/(H·μ_x).
fn pole_and_scale(
    given: Option<f64>,
    src: &Diagram,
    scales: Scales,
    preferred: f64,
    q: Quantity,
) -> Result<(f64, Scale), calculus::CalculusError> {
    let h = match given {
        Some(h) => h,
        None => calculus::pole_for(src, scales, preferred)?,
    };
    Ok((h, calculus::derivative_scale(scales.y, scales.x, h, q)?))
}

/// Lowest and highest drawn ordinate (mm) of physical values at scale `mu`, with 0 included.
fn extent<'a>(values: impl Iterator<Item = &'a f64>, mu: Scale) -> (f64, f64) {
    values.fold((0.0f64, 0.0f64), |(lo, hi), v| {
        (lo.min(v / mu.value()), hi.max(v / mu.value()))
    })
}

fn unit_of(quantity: &str) -> &'static str {
    match quantity.split('_').next() {
        Some("v") => "m/s",
        Some("a") => "m/s^2",
        Some("omega") => "rad/s",
        Some("eps") => "rad/s^2",
        _ => "m",
    }
}

/// Carry out the analysis.
pub fn analyse(m: &Mechanism, req: &KinRequest) -> Result<Analysis, KinError> {
    let plan = plan_positions(m, &req.positions, req.scale_l, req.drafting)?;
    let prog = &plan.program;
    let w1 = m.crank.sense.sign() * m.crank.omega;
    let (r, w) = (m.crank.length, m.crank.omega);
    let pick = |s: Option<Scale>, v: f64, q: Quantity| {
        s.or_else(|| Scale::round_for(v, PLAN_MM, q))
            .ok_or_else(|| KinError::Request(format!("no plan scale can be chosen for {v}")))
    };
    let scale_v = pick(req.spec.scale_v, w * r, Quantity::Velocity)?;
    let scale_a = pick(req.spec.scale_a, w * w * r, Quantity::Acceleration)?;
    let mu_l = req.scale_l.value();
    let mut velocity = Vec::with_capacity(plan.positions.len());
    let mut refused = Vec::new();
    let mut rows = Vec::new();
    for pos in &plan.positions {
        let setup = PlanSetup {
            prog,
            built: &pos.built,
            mu_l,
            w1,
            drafting: req.drafting,
        };
        match kin_plan(&setup, PlanKind::Velocity, scale_v, None) {
            Ok(vp) => {
                push_rows(&mut rows, &vp, &pos.pose, w1, &pos.label);
                velocity.push(Some(vp));
            }
            // A dyad at its toggle position: the plan does not exist; say why and go on.
            Err((group, error @ ConstructionError::LinesParallel { .. })) => {
                refused.push((pos.label.clone(), format!("group {}: {error}", group + 1)));
                velocity.push(None);
            }
            Err((group, error)) => {
                return Err(KinError::Plan {
                    position: pos.label.clone(),
                    kind: "velocity",
                    group: group + 1,
                    error: Box::new(error),
                })
            }
        }
    }
    let mut acceleration = Vec::new();
    for k in acceleration_indices(&plan, req)? {
        let pos = &plan.positions[k];
        let Some(vp) = &velocity[k] else {
            return Err(KinError::Request(format!(
                "acceleration_positions: position {} has no velocity plan (toggle position)",
                pos.label
            )));
        };
        let setup = PlanSetup {
            prog,
            built: &pos.built,
            mu_l,
            w1,
            drafting: req.drafting,
        };
        let ap = kin_plan(&setup, PlanKind::Acceleration, scale_a, Some(vp)).map_err(
            |(group, error)| KinError::Plan {
                position: pos.label.clone(),
                kind: "acceleration",
                group: group + 1,
                error: Box::new(error),
            },
        )?;
        push_rows(&mut rows, &ap, &pos.pose, w1, &pos.label);
        acceleration.push((k, ap));
    }
    let diagrams = diagrams(m, &plan, req, w1, &mut rows)?;
    let rocker = rocker_diagram(m, &plan, &velocity, req, w1, &mut rows)?;
    let hodograph = hodograph(&plan, &velocity, req, scale_v)?;
    let table = analytic_table(prog, &plan, w1);
    Ok(Analysis {
        plan,
        w1,
        scale_v,
        scale_a,
        velocity,
        acceleration,
        diagrams,
        hodograph,
        rocker,
        rows,
        table,
        refused,
    })
}

fn push_rows(rows: &mut Vec<Row>, plan: &KinPlan, pose: &Pose, w1: f64, label: &str) {
    for r in &plan.readings {
        rows.push(Row {
            quantity: r.quantity.clone(),
            position: label.to_string(),
            unit: unit_of(&r.quantity).to_string(),
            method: Method::Plan,
            graphical: r.value,
            analytic: analytic(pose, w1, r.what, plan.kind),
            conditioning: r.conditioning,
        });
    }
}

/// The positions that get an acceleration plan: as asked, or one in the middle of the
/// working stroke and one in the middle of the return.
fn acceleration_indices(plan: &PositionPlan, req: &KinRequest) -> Result<Vec<usize>, KinError> {
    if let Some(labels) = &req.spec.acceleration_positions {
        return labels
            .iter()
            .map(|l| {
                plan.positions
                    .iter()
                    .position(|p| &p.label == l)
                    .ok_or_else(|| {
                        KinError::Request(format!(
                            "acceleration_positions: there is no position `{l}`"
                        ))
                    })
            })
            .collect();
    }
    let work = plan
        .extremes
        .as_ref()
        .map_or(TAU / 2.0, |ex| ex.work_travel);
    let mut out = Vec::new();
    for target in [work / 2.0, work + (TAU - work) / 2.0] {
        let best = (0..plan.positions.len())
            .filter(|&k| !plan.positions[k].extreme)
            .min_by(|&a, &b| {
                angular(travel_of(plan, a), target).total_cmp(&angular(travel_of(plan, b), target))
            });
        if let Some(k) = best.filter(|k| !out.contains(k)) {
            out.push(k);
        }
    }
    Ok(out)
}

/// Crank travel from position 1 to position `k` in the sense of rotation, radians.
fn travel_of(plan: &PositionPlan, k: usize) -> f64 {
    let step = TAU
        / plan
            .positions
            .iter()
            .filter(|p| p.label.parse::<u32>().is_ok())
            .count()
            .max(1) as f64;
    match plan.positions[k].label.parse::<u32>() {
        Ok(n) => step * (n - 1) as f64,
        Err(_) => f64::INFINITY,
    }
}

fn angular(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

/// The charted point and the direction its displacement is measured along.
fn diagram_target(
    m: &Mechanism,
    prog: &Program,
    req: &KinRequest,
) -> Result<Option<(usize, DVec2)>, KinError> {
    let slider = m.outputs.iter().find_map(|o| match o {
        Output::Slider { point, dir } => Some((point.clone(), *dir)),
        Output::Rocker { .. } => None,
    });
    let name = match (&req.spec.diagram_point, &slider) {
        (Some(n), _) => n.clone(),
        (None, Some((n, _))) => n.clone(),
        (None, None) => return Ok(None),
    };
    let k = prog
        .index(&name)
        .ok_or_else(|| KinError::Request(format!("diagram: there is no point `{name}`")))?;
    let dir = slider.map_or(0.0, |s| s.1);
    Ok(Some((k, DVec2::from_angle(dir))))
}

/// S(φ₁) of the charted point read off the plan at the numbered positions, its two chord
/// derivatives, and their rows against the analytic values.
fn diagrams(
    m: &Mechanism,
    plan: &PositionPlan,
    req: &KinRequest,
    w1: f64,
    rows: &mut Vec<Row>,
) -> Result<Option<Diagrams>, KinError> {
    let prog = &plan.program;
    let Some((k, dir)) = diagram_target(m, prog, req)? else {
        return Ok(None);
    };
    let numbered: Vec<&crate::linkage::PlanPosition> = plan
        .positions
        .iter()
        .filter(|p| p.label.parse::<u32>().is_ok())
        .collect();
    if numbered.len() < 3 {
        return Ok(None);
    }
    let name = prog.names[k].clone();
    let fail = |what: &str, error| KinError::Diagram {
        what: format!("{what} of {name}"),
        error,
    };
    // S is read off the plan of positions: the distance from position 1, signed along the guide.
    let reader = Recorder::new("S", req.scale_l, tol(), req.drafting);
    let p1 = numbered[0].built.p[k];
    let s: Vec<f64> = numbered
        .iter()
        .map(|p| {
            let d = p.built.p[k] - p1;
            reader.measure(p1, p.built.p[k]).value * d.dot(dir).signum()
        })
        .collect();
    let n = numbered.len();
    let src = Diagram::new(0.0, TAU / n as f64, s.clone(), true).map_err(|e| fail("S", e))?;
    let span = s.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let scale_s = req
        .spec
        .scale_s
        .or_else(|| Scale::round_for(span.max(1e-9), DIAGRAM_MM, Quantity::Length))
        .ok_or_else(|| KinError::Request("no μ_s can be chosen".into()))?;
    let scale_phi = req
        .spec
        .scale_phi
        .or_else(|| Scale::new(TAU / TURN_MM, Quantity::Angle))
        .ok_or_else(|| KinError::Request("no μ_φ".into()))?;
    let scales = Scales {
        x: scale_phi,
        y: scale_s,
    };
    let (h1, mu1) = pole_and_scale(req.spec.pole_h1, &src, scales, DIAGRAM_MM, Quantity::Length)
        .map_err(|e| fail("dS/dφ", e))?;
    // The textbook's stack: S on top, dS/dφ under it, d²S/dφ² under that; the second
    // differentiation's chords are drawn on the dS/dφ curve itself (its figure's source axes
    // coincide with the first figure's result axes). A scratch run sizes each diagram.
    let scratch = |mu: Scale, d: &Diagram, sc: Scales, h: f64| -> Result<(f64, f64), KinError> {
        let mut r = Recorder::new("scratch", mu, tol(), Drafting::EXACT);
        let lay = Layout::new(DVec2::ZERO, DVec2::ZERO).with_source(false);
        let dv = calculus::differentiate_chords(&mut r, d, sc, h, &lay)
            .map_err(|e| fail("a diagram", e))?;
        Ok(extent(dv.mid.iter().chain(&dv.node), mu))
    };
    let (s_lo, _) = extent(s.iter(), scale_s);
    let (d1_lo, d1_hi) = scratch(mu1, &src, scales, h1)?;
    let mut rec1 = Recorder::new("dS/dφ", mu1, tol(), req.drafting);
    let lay1 = Layout::new(DVec2::ZERO, DVec2::new(0.0, s_lo - DIAGRAM_GAP - d1_hi))
        .pole_named("P_1", "H_1");
    let differentiate = if req.spec.tangents {
        calculus::differentiate_tangents
    } else {
        calculus::differentiate_chords
    };
    let first = differentiate(&mut rec1, &src, scales, h1, &lay1).map_err(|e| fail("dS/dφ", e))?;
    let d1 = first.diagram().map_err(|e| fail("dS/dφ", e))?;
    let scales2 = Scales {
        x: scale_phi,
        y: mu1,
    };
    let (h2, mu2) = pole_and_scale(req.spec.pole_h2, &d1, scales2, DIAGRAM_MM, Quantity::Length)
        .map_err(|e| fail("d²S/dφ²", e))?;
    let (_, d2_hi) = scratch(mu2, &d1, scales2, h2)?;
    let mut rec2 = Recorder::new("d²S/dφ²", mu2, tol(), req.drafting);
    let lay2 = Layout::new(DVec2::ZERO, DVec2::new(0.0, d1_lo - DIAGRAM_GAP - d2_hi))
        .with_source(false)
        .named("φ", "dS/dφ", "d²S/dφ²")
        .pole_named("P_2", "H_2");
    let second =
        differentiate(&mut rec2, &d1, scales2, h2, &lay2).map_err(|e| fail("d²S/dφ²", e))?;
    // Rows: S, v = |ω₁|·dS/dθ, a = ω₁²·d²S/dθ² at the numbered positions.
    let q = crate::linkage::plain(&name);
    for (idx, p) in numbered.iter().enumerate() {
        let pose = &p.pose;
        let s_an = (pose.p[k] - numbered[0].pose.p[k]).dot(dir);
        let v_an = (pose.dp[k] * w1).length();
        let a_an = (pose.ddp[k] * (w1 * w1)).length();
        let v_gr = (first.node[idx] * w1.abs()).abs();
        let a_gr = (second.node[idx] * w1 * w1).abs();
        for (quantity, unit, g, a) in [
            (format!("s_{q}"), "m", s[idx], s_an),
            (format!("v_{q}"), "m/s", v_gr, v_an),
            (format!("a_{q}"), "m/s^2", a_gr, a_an),
        ] {
            rows.push(Row {
                quantity,
                position: p.label.clone(),
                unit: unit.into(),
                method: Method::Diagram,
                graphical: g,
                analytic: a,
                conditioning: None,
            });
        }
    }
    Ok(Some(Diagrams {
        point: name,
        scales,
        first_figure: rec1.finish(),
        second_figure: rec2.finish(),
        second_at: lay1.origin,
        first,
        second,
        s,
    }))
}

/// The angular-velocity analogue of a rocker: ω(φ₁) charted from the velocity plans,
/// differentiated by chords into ε (seed 000 §1.5).
#[derive(Debug, Clone, PartialEq)]
pub struct RockerDiagram {
    /// The rocker's link number.
    pub link: usize,
    /// μ_ω of the chart, (rad/s)/mm.
    pub scale: Scale,
    /// μ_φ of the abscissa.
    pub scale_phi: Scale,
    /// The chord derivative dω/dφ₁ (its scale: (rad/s)/rad per mm).
    pub derivative: Derivative,
    /// The figure: the ω chart and its derivative.
    pub figure: Figure,
}

/// ω of the first rocker output at the numbered positions, read off the velocity plans, then
/// differentiated by chords: ε = |ω₁|·dω/dθ (θ the crank's travel). The seed's ε = 12·0.32
/// = 3.8 rad/s² (L574) forgets the factor ω₁; this does not.
fn rocker_diagram(
    m: &Mechanism,
    plan: &PositionPlan,
    velocity: &[Option<KinPlan>],
    req: &KinRequest,
    w1: f64,
    rows: &mut Vec<Row>,
) -> Result<Option<RockerDiagram>, KinError> {
    let Some(link) = m.outputs.iter().find_map(|o| match o {
        Output::Rocker { link } => Some(*link as usize),
        Output::Slider { .. } => None,
    }) else {
        return Ok(None);
    };
    let numbered: Vec<(usize, &crate::linkage::PlanPosition)> = plan
        .positions
        .iter()
        .enumerate()
        .filter(|(_, p)| p.label.parse::<u32>().is_ok())
        .collect();
    let omega: Option<Vec<f64>> = numbered
        .iter()
        .map(|(k, _)| velocity[*k].as_ref().map(|v| v.rate[link]))
        .collect();
    let (Some(omega), true) = (omega, numbered.len() >= 3) else {
        return Ok(None);
    };
    let fail = |error| KinError::Diagram {
        what: format!("ω_{link}"),
        error,
    };
    let n = numbered.len();
    let src = Diagram::new(0.0, TAU / n as f64, omega.clone(), true).map_err(fail)?;
    let peak = omega.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let scale = Scale::round_for(peak.max(1e-12), ROCKER_MM, Quantity::AngularVelocity)
        .ok_or_else(|| KinError::Request("no μ_ω".into()))?;
    let scale_phi = Scale::new(TAU / ROCKER_TURN_MM, Quantity::Angle)
        .ok_or_else(|| KinError::Request("no μ_φ".into()))?;
    let scales = Scales {
        x: scale_phi,
        y: scale,
    };
    let (h, mu) =
        pole_and_scale(None, &src, scales, ROCKER_MM, Quantity::AngularVelocity).map_err(fail)?;
    let (w_lo, _) = extent(omega.iter(), scale);
    let mut rec = Recorder::new("ω", mu, tol(), req.drafting);
    let lay = Layout::new(DVec2::ZERO, DVec2::new(0.0, w_lo - DIAGRAM_GAP - ROCKER_MM))
        .named("φ", &format!("ω_{{{link}}}"), &format!("dω_{{{link}}}/dφ"))
        .pole_named("P_{ω}", "H_{ω}");
    let derivative =
        calculus::differentiate_chords(&mut rec, &src, scales, h, &lay).map_err(fail)?;
    for (idx, (_, p)) in numbered.iter().enumerate() {
        rows.push(Row {
            quantity: format!("eps_{link}"),
            position: p.label.clone(),
            unit: "rad/s^2".into(),
            method: Method::Diagram,
            graphical: derivative.node[idx] * w1.abs(),
            analytic: p.pose.ddangle[link] * w1 * w1,
            conditioning: None,
        });
    }
    Ok(Some(RockerDiagram {
        link,
        scale,
        scale_phi,
        derivative,
        figure: rec.finish(),
    }))
}

/// The hodograph of a point's velocity: the velocity vectors of every position from one pole
/// (copied from the velocity plans), their ends joined by a smooth curve.
fn hodograph(
    plan: &PositionPlan,
    velocity: &[Option<KinPlan>],
    req: &KinRequest,
    scale_v: Scale,
) -> Result<Option<(String, Figure)>, KinError> {
    let prog = &plan.program;
    let name = match &req.spec.hodograph {
        Some(n) => n.clone(),
        None => match prog.ops.iter().find_map(|op| match op {
            crate::linkage::Op::Point { idx, .. } => Some(prog.names[*idx].clone()),
            _ => None,
        }) {
            Some(n) => n,
            None => return Ok(None),
        },
    };
    let k = prog
        .index(&name)
        .ok_or_else(|| KinError::Request(format!("hodograph: there is no point `{name}`")))?;
    // The hodograph has its own μ: the longest vector drawn about HODOGRAPH_MM.
    let longest = velocity
        .iter()
        .flatten()
        .map(|vp| vp.images[k].length())
        .fold(0.0, f64::max)
        * scale_v.value();
    let scale =
        Scale::round_for(longest.max(1e-12), HODOGRAPH_MM, Quantity::Velocity).unwrap_or(scale_v);
    let copy = scale_v.value() / scale.value();
    let mut rec = Recorder::new("hodograph", scale, tol(), req.drafting);
    rec.point(
        "pole",
        DVec2::ZERO,
        Role::Given,
        "p",
        DVec2::new(-0.7, -0.7),
        &[],
    );
    let mut ends = Vec::new();
    for (pos, vp) in plan
        .positions
        .iter()
        .zip(velocity)
        .filter_map(|(p, v)| v.as_ref().map(|v| (p, v)))
    {
        // The vector copied from the velocity plan, redrawn at the hodograph's μ.
        let end = vp.images[k] * copy;
        let id = rec.draw(
            format!("v of {name}, position {}", pos.label),
            Item::Vector {
                from: DVec2::ZERO,
                to: end,
            },
            Role::Construction,
            &[],
        );
        rec.label(id, pos.label.clone(), end, end.normalize_or(DVec2::Y));
        ends.push(end);
    }
    rec.draw(
        format!("hodograph of {name}"),
        Item::Curve {
            points: ends,
            closed: true,
        },
        Role::Result,
        &[],
    );
    Ok(Some((name, rec.finish())))
}

/// The analytic table in the shape of seed 000 Table 5: φ₁, and per group the angle, the
/// slide length (RPR), ω and ε of its links, then |v|, |a| of every named point.
fn analytic_table(prog: &Program, plan: &PositionPlan, w1: f64) -> Table {
    use crate::linkage::{Op, PDyad};
    let mut columns = vec![Column {
        name: "φ_1".into(),
        unit: "°".into(),
    }];
    type Col = Box<dyn Fn(&Pose) -> f64>;
    let mut cols: Vec<Col> = vec![Box::new(|p: &Pose| p.phi.to_degrees().rem_euclid(360.0))];
    for op in &prog.ops {
        let Op::Dyad { links, dyad, .. } = op else {
            continue;
        };
        let link_cols = |l: usize, columns: &mut Vec<Column>, cols: &mut Vec<Col>| {
            columns.push(Column {
                name: format!("φ_{l}"),
                unit: "°".into(),
            });
            cols.push(Box::new(move |p: &Pose| {
                p.angle(l).to_degrees().rem_euclid(360.0)
            }));
            columns.push(Column {
                name: format!("ω_{l}"),
                unit: "1/s".into(),
            });
            cols.push(Box::new(move |p: &Pose| p.dangle[l] * w1));
            columns.push(Column {
                name: format!("ε_{l}"),
                unit: "1/s²".into(),
            });
            cols.push(Box::new(move |p: &Pose| p.ddangle[l] * w1 * w1));
        };
        match *dyad {
            PDyad::Rpr { a, c, .. } => {
                let j = links[1] as usize;
                link_cols(j, &mut columns, &mut cols);
                columns.push(Column {
                    name: format!("L_{j}"),
                    unit: "m".into(),
                });
                cols.push(Box::new(move |p: &Pose| (p.p[a] - p.p[c]).length()));
                columns.push(Column {
                    name: format!(
                        "V_{a}{j}{a}{}",
                        crate::linkage::owner(prog, a),
                        a = crate::linkage::plain(&prog.names[a])
                    ),
                    unit: "m/s".into(),
                });
                cols.push(Box::new(move |p: &Pose| {
                    let r = p.p[a] - p.p[c];
                    r.dot(p.dp[a] - p.dp[c]) / r.length() * w1
                }));
            }
            PDyad::Rpp { .. } | PDyad::Prp { .. } => {}
            _ => {
                link_cols(links[0] as usize, &mut columns, &mut cols);
                link_cols(links[1] as usize, &mut columns, &mut cols);
            }
        }
    }
    for (k, name) in prog.names.iter().enumerate().skip(prog.fixed.len()) {
        let q = crate::linkage::plain(name);
        columns.push(Column {
            name: format!("V_{q}"),
            unit: "m/s".into(),
        });
        cols.push(Box::new(move |p: &Pose| (p.dp[k] * w1).length()));
        columns.push(Column {
            name: format!("a_{q}"),
            unit: "m/s²".into(),
        });
        cols.push(Box::new(move |p: &Pose| (p.ddp[k] * w1 * w1).length()));
    }
    let rows = plan
        .positions
        .iter()
        .map(|pos| {
            (
                pos.label.clone(),
                cols.iter().map(|c| Some(c(&pos.pose))).collect(),
            )
        })
        .collect();
    Table {
        title: "analytic".into(),
        columns,
        rows,
    }
}
