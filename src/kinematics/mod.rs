//! Kinematic analysis of a linkage, the graphical way and the analytic way side by side,
//! as sub-studies the session ([`crate::study`]) asks for one at a time:
//! - the plans ([`velocity`], [`acceleration`]): a velocity plan at a position of the plan of
//!   positions, an acceleration plan from it, and their readings against the analytic twin;
//! - [`diagrams()`]: the displacement diagram of a point over a crank turn, differentiated
//!   twice by chords (or tangents);
//! - [`rocker_diagram`]: the rocker's ω diagram from the velocity plans, differentiated into ε;
//! - [`hodograph`]: the hodograph of a point's velocity;
//! - [`analytic_table`]: the analytic table in the shape of seed 000 Table 5.
//!
//! Every reading comes out as a typed [`Row`]: graphical against analytic.

mod axis;
mod diagrams;
mod hodograph;
mod plans;
mod rocker;
mod table;
mod verdict;

pub use diagrams::{diagrams, ChartSize, KinDiagrams};
pub use hodograph::{hodograph, hodograph_point};
pub use plans::{
    acceleration, acceleration_indices, drawn_points, position_indices, velocity, Velocity,
};
pub use rocker::{rocker_diagram, rocker_link, RockerDiagram};
pub use table::analytic_table;
pub use verdict::{by_position, verdict_notes, verdicts, LinkVerdict, Turning};

use crate::calculus::{self, Diagram, Scales};
use crate::check::notes::kinematics::{KinematicsNote, PinNearPivot};
use crate::check::Row;
use crate::construct::ConstructionError;
use crate::geom::{bisect, DVec2, Midpoint};
use crate::linkage::{LinkageError, PlanKind, PositionPlan};
use crate::scale::{Quantity, Scale};
use std::convert::Infallible;
use std::f64::consts::TAU;
use thiserror::Error;

/// Preferred drawn length of the crank pin's velocity and acceleration, mm (textbook 70–100).
pub const PLAN_MM: f64 = 80.0;
/// Preferred height of a diagram, mm.
const DIAGRAM_MM: f64 = 35.0;
/// Gap between stacked diagrams, mm: from the lowest ordinate of the diagram above to the
/// highest of the one below. The axis above runs 6 mm below its points and the one below 12 mm
/// above its own, with its title at the tip; the gap keeps that title clear of the row the
/// diagram above writes under its φ axis (the position numbers) and of its pole distance
/// H dimensioned 7 mm under its points.
const DIAGRAM_GAP: f64 = 30.0;

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
    /// The positions whose velocity and acceleration plans are drawn at a μ of their own,
    /// stated beside them, by label (a plan near a singular position, the tangent
    /// mechanism's v_B = 29,9 m/s beside v_A = 0,8 m/s); every other plan of a kind is drawn
    /// at the one common μ, and the default acceleration positions avoid these. Empty: one
    /// μ_v and one μ_a for every plan.
    pub own_scale: Vec<String>,
    /// The positions whose acceleration plans alone are drawn at a μ_a of their own, by
    /// label, each one of the acceleration positions (the shaper's 3, whose largest vector,
    /// a_B1 = 34,5 m/s², is 35 mm at the seed's μ_a = 1, which plan 10 needs); their velocity
    /// plans keep the common μ_v. Empty: as `own_scale` says.
    pub own_scale_a: Vec<String>,
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

/// Why a kinematic study cannot be carried out.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum KinError {
    /// The positions cannot be constructed.
    #[error(transparent)]
    Linkage(#[from] LinkageError),
    /// μ_l of the plans is not a scale (finite and > 0).
    #[error("μ_l = {0} m/mm is not a scale")]
    NoLengthScale(f64),
    /// A plan cannot be constructed at a position.
    #[error("position {position}: {} plan, group {group}: {error}", kind_name(*.kind))]
    Plan {
        /// Position label.
        position: String,
        /// Which plan.
        kind: PlanKind,
        /// The group (file order, 1-based).
        group: usize,
        /// The diagnostic.
        error: Box<ConstructionError>,
    },
    /// A diagram cannot be constructed.
    #[error("diagram of {what}: {error}")]
    Diagram {
        /// Which diagram.
        what: String,
        /// The diagnostic.
        error: calculus::CalculusError,
    },
    /// A scene key names a point the mechanism does not have.
    #[error("kinematics.{key}: there is no point `{name}`")]
    NoSuchPoint {
        /// The key (`diagram`, `hodograph`).
        key: &'static str,
        /// The name given.
        name: String,
    },
    /// A position label that the plan of positions does not have.
    #[error("kinematics.{key}: there is no position {label}; the positions are {}", position_list(.valid))]
    NoSuchPosition {
        /// The key (`acceleration_positions`, `own_scale`, `own_scale_a`).
        key: &'static str,
        /// The label given.
        label: String,
        /// The plan's labels.
        valid: Vec<String>,
    },
    /// A plan given a μ_a of its own at a position with no acceleration plan.
    #[error("kinematics.own_scale_a: position {label} has no acceleration plan; the acceleration plans are at {}", position_list(.drawn))]
    NoAccelerationPlan {
        /// The label given.
        label: String,
        /// The positions whose acceleration plans are drawn.
        drawn: Vec<String>,
    },
    /// An acceleration plan asked for at a position whose velocity plan does not exist.
    #[error("kinematics.acceleration_positions: position {position} has no velocity plan ({why})")]
    NoVelocityPlan {
        /// The position.
        position: String,
        /// Why its velocity plan was refused.
        why: String,
    },
    /// The force analysis asks for a position whose velocity or acceleration plan cannot be
    /// built (a change point, a toggle).
    #[error("forces.positions: position {position}: the force analysis needs its {} plan, which cannot be built: {why}", kind_name(*.kind))]
    ForcePosition {
        /// The position.
        position: String,
        /// Which plan.
        kind: PlanKind,
        /// Why the plan cannot be built.
        why: String,
    },
    /// No round scale can be chosen for a size.
    #[error("no round scale μ_{} can be chosen for the size {value}", .quantity.symbol(), value = crate::scale::format_plain(*value))]
    NoScale {
        /// What the scale measures.
        quantity: Quantity,
        /// The physical size it was chosen for.
        value: f64,
    },
    /// A diagram over the crank turn through an angle the mechanism cannot pass.
    #[error("the diagrams over a crank turn are refused: at φ₁ = {phi_deg:.2}° {detail}; the method of chords across it is meaningless")]
    NoFullTurn {
        /// The crank angle, degrees.
        phi_deg: f64,
        /// Why the mechanism cannot pass it.
        detail: String,
    },
    /// A diagram over the crank turn across a leap: a link turns by more than 45° between
    /// neighbouring samples of the turn (a slotted link whose pin passes through or close by
    /// its pivot), so the charted motion jumps between the positions.
    #[error("the diagrams over a crank turn are refused: at φ₁ = {phi_deg:.2}° {detail}; the method of chords across it is meaningless")]
    Leap {
        /// The crank angle of the leap, degrees.
        phi_deg: f64,
        /// Which links turn by how much, and the nearest position.
        detail: String,
    },
    /// A position index outside the plan of positions.
    #[error("there is no position number {index} (the plan has {count})")]
    NoIndex {
        /// The index asked for (0-based).
        index: usize,
        /// The plan's position count.
        count: usize,
    },
}

/// Position labels as a reader lists them: the numbered run `1…12`, then the others (`8′`).
pub fn position_list(labels: &[String]) -> String {
    let numbers: Vec<u32> = labels.iter().filter_map(|l| l.parse().ok()).collect();
    let run = numbers.len() > 2 && numbers.iter().zip(1..).all(|(&n, k)| n == k);
    let mut parts: Vec<String> = if run {
        vec![format!("1…{}", numbers.len())]
    } else {
        numbers.iter().map(u32::to_string).collect()
    };
    parts.extend(labels.iter().filter(|l| l.parse::<u32>().is_err()).cloned());
    parts.join(", ")
}

fn kind_name(kind: PlanKind) -> &'static str {
    match kind {
        PlanKind::Velocity => "velocity",
        PlanKind::Acceleration => "acceleration",
    }
}

/// The round scale that draws `value` about `preferred_mm` long (the textbook way).
pub fn round_scale(value: f64, preferred_mm: f64, quantity: Quantity) -> Result<Scale, KinError> {
    Scale::round_for(value, preferred_mm, quantity).ok_or(KinError::NoScale { quantity, value })
}

/// μ_v and μ_a: as the scene gives them, or the textbook's choice that draws the crank pin's
/// velocity and acceleration at least [`PLAN_MM`] long (the round scale next below).
pub fn plan_scales(
    crank: &crate::linkage::Crank,
    spec: &KinematicsSpec,
) -> Result<(Scale, Scale), KinError> {
    let (r, w) = (crank.length, crank.omega);
    let at_least = |value: f64, quantity: Quantity| {
        Scale::round_at_least(value, PLAN_MM, quantity).ok_or(KinError::NoScale { quantity, value })
    };
    let v = match spec.scale_v {
        Some(s) => s,
        None => at_least(w * r, Quantity::Velocity)?,
    };
    let a = match spec.scale_a {
        Some(s) => s,
        None => at_least(w * w * r, Quantity::Acceleration)?,
    };
    Ok((v, a))
}

/// ω₁ of the crank, rad/s, signed counter-clockwise.
pub fn crank_rate(crank: &crate::linkage::Crank) -> f64 {
    crank.sense.sign() * crank.omega
}

/// The numbered positions of a plan (the extreme positions `k′` left out), with their index.
pub fn numbered(plan: &PositionPlan) -> Vec<(usize, &crate::linkage::PlanPosition)> {
    plan.positions
        .iter()
        .enumerate()
        .filter(|(_, p)| p.label.parse::<u32>().is_ok())
        .collect()
}

/// The plan's other positions: its extremes `k′` between the numbered ones, each with its
/// index and the crank's travel from position 1, rad.
pub fn between(plan: &PositionPlan) -> Vec<(usize, f64, &crate::linkage::PlanPosition)> {
    let Some(first) = numbered(plan).first().map(|(_, p)| p.phi) else {
        return Vec::new();
    };
    let sense = plan.mechanism.crank.sense;
    (plan.positions.iter().enumerate())
        .filter(|(_, p)| p.label.parse::<u32>().is_err())
        .map(|(i, p)| (i, sense.travel(first, p.phi), p))
        .collect()
}

/// A note for every position where a slotted link's pin passes close to its pivot
/// ([`crate::linkage::NearPivot`]): the link's rate there is true but huge and ill-conditioned.
pub fn near_pivot_notes(plan: &PositionPlan, w1: f64) -> Vec<KinematicsNote> {
    let names = &plan.program.names;
    let mut out = Vec::new();
    for p in &plan.positions {
        for n in &p.pose.near_pivot {
            out.push(KinematicsNote::NearPivot(PinNearPivot {
                position: p.label.clone(),
                pin: names[n.pin].clone(),
                pivot: names[n.pivot].clone(),
                distance: n.distance,
                link: n.link,
                group: n.group,
                speed: n.speed,
                omega: p.pose.dangle[n.link] * w1,
            }));
        }
    }
    out
}

/// Samples of the crank turn checked before a quantity is charted over it.
const TURN_SAMPLES: usize = 720;

/// cos 45°: a link that turns more than this between neighbouring samples of the turn (over
/// 90 times the crank's rate) leaps where a chart through the positions sees it.
const LEAP_COS: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// A diagram over the crank turn is meaningful only if the mechanism passes every crank angle
/// and its links turn continuously: the first angle (of [`TURN_SAMPLES`]) where it cannot —
/// guides turned parallel, a slider run off to infinity — or where a link turns more than 45°
/// between neighbouring samples (a slotted link whose pin passes through its pivot flips by
/// 180°; one whose pin passes beside it whips round) refuses the chart with its diagnosis and
/// the position there.
fn full_turn(plan: &PositionPlan) -> Result<(), KinError> {
    let mut first: Option<crate::linkage::Pose> = None;
    let mut prev: Option<crate::linkage::Pose> = None;
    for i in 0..=TURN_SAMPLES {
        let phi = TAU * i as f64 / TURN_SAMPLES as f64;
        let pose = if i == TURN_SAMPLES {
            match first.take() {
                Some(p) => p,
                None => break,
            }
        } else {
            plan.program
                .solve(phi, None)
                .map_err(|u| KinError::NoFullTurn {
                    phi_deg: phi.to_degrees(),
                    detail: format!("group {}: {}", u.group + 1, u.detail),
                })?
        };
        if let Some(q) = &prev {
            let leaping: Vec<usize> = (1..pose.dir.len())
                .filter(|&l| q.dir[l].dot(pose.dir[l]) < LEAP_COS)
                .collect();
            if let Some(&l) = leaping.last() {
                let turns: Vec<String> = leaping
                    .iter()
                    .map(|&l| {
                        let turn = q.dir[l].angle_to(pose.dir[l]).abs().to_degrees();
                        format!("link {l} turns {turn:.1}°")
                    })
                    .collect();
                let step = 360.0 / TURN_SAMPLES as f64;
                let at = leap(
                    plan,
                    l,
                    (phi - TAU / TURN_SAMPLES as f64, q.dir[l]),
                    (phi, pose.dir[l]),
                )
                .rem_euclid(TAU);
                return Err(KinError::Leap {
                    phi_deg: at.to_degrees(),
                    detail: format!(
                        "{} within {step}° of the crank ({}): the charted motion jumps there",
                        turns.join(", "),
                        nearest_position(plan, at)
                    ),
                });
            }
        }
        if i == 0 {
            first = Some(pose.clone());
        }
        prev = Some(pose);
    }
    Ok(())
}

/// Where between crank angles `a` and `b` (with link `l`'s directions there) the link leaps:
/// the half-interval over which it turns more, halved down to the rounding.
fn leap(plan: &PositionPlan, l: usize, a: (f64, DVec2), b: (f64, DVec2)) -> f64 {
    // The directions at the bracket's ends, kept with them.
    let (mut at_a, mut at_b) = (a.1, b.1);
    let Ok((a, b)) = bisect(
        a.0,
        b.0,
        60,
        |_, _| false,
        |mid| {
            let Ok(p) = plan.program.solve(mid, None) else {
                return Ok::<_, Infallible>(Midpoint::Stop);
            };
            let m = p.dir[l];
            Ok(if at_a.dot(m) < m.dot(at_b) {
                at_b = m;
                Midpoint::Second
            } else {
                at_a = m;
                Midpoint::First
            })
        },
    );
    0.5 * (a + b)
}

/// The position of the plan nearest to crank angle `phi`, as "position 4 at φ₁ = 270°".
fn nearest_position(plan: &PositionPlan, phi: f64) -> String {
    let gap = |p: &&crate::linkage::PlanPosition| crate::geom::wrap_pi(p.pose.phi - phi).abs();
    plan.positions
        .iter()
        .min_by(|a, b| gap(a).total_cmp(&gap(b)))
        .map_or_else(String::new, |p| {
            format!(
                "nearest position {} at φ₁ = {:.2}°",
                p.label,
                p.pose.phi.to_degrees()
            )
        })
}

/// A periodic diagram over one crank turn through `values` at the numbered positions.
fn turn_diagram(values: Vec<f64>) -> Result<Diagram, calculus::CalculusError> {
    let n = values.len();
    Diagram::new(0.0, TAU / n as f64, values, true)
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

/// An analytic velocity or acceleration at `pose`: NaN (written `null`) where a group is at its
/// toggle and the analogues are not determined.
fn rate(pose: &crate::linkage::Pose, value: f64) -> f64 {
    if pose.toggle.is_some() {
        f64::NAN
    } else {
        value
    }
}

/// The largest magnitude of `values` (the scale of a quantity over the cycle).
fn peak(values: impl IntoIterator<Item = f64>) -> f64 {
    values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(0.0f64, |m, v| m.max(v.abs()))
}

/// All the rows of a set of studies, in report order: the velocity plans by position, the
/// acceleration plans, the displacement diagrams, the rocker's diagram.
pub fn rows<'a>(
    velocity: impl IntoIterator<Item = &'a [Row]>,
    acceleration: impl IntoIterator<Item = &'a [Row]>,
    diagrams: Option<&'a KinDiagrams>,
    rocker: Option<&'a RockerDiagram>,
) -> Vec<Row> {
    let mut out: Vec<Row> = Vec::new();
    for r in velocity.into_iter().chain(acceleration) {
        out.extend_from_slice(r);
    }
    if let Some(d) = diagrams {
        out.extend_from_slice(&d.rows);
    }
    if let Some(r) = rocker {
        out.extend_from_slice(&r.rows);
    }
    out
}
