//! Friction as the textbook draws it (seed 001, lectures 9–12): the friction angle and cone,
//! the total reaction turned from the normal by φ against the relative velocity, uniform
//! motion on an inclined plane, a slider's state against the static limit, the V-groove
//! (wedge) slider, the screw, the revolute pair with its friction circle, rolling friction
//! (worked example W3), and the friction that jams a cam's follower (lectures 15–16): a
//! translating follower in the guide of two bearings, a rocker in its pivot.
//!
//! Every case is three things side by side: a **construction** through the recorder (the
//! scheme with its loads, normal, friction cone or circle and reaction, and the force
//! triangle at μ_F, read off under the drafting model), a **closed-form twin** (the `*_twin`
//! functions of each case) and the **rows** comparing them ([`Solved::rows`]).
//!
//! Two helpers serve force analysis with friction elsewhere:
//! * [`tilt_reaction`] — the total reaction of a sliding pair from its normal reaction;
//! * [`friction_circle_tangent`] — the line of a revolute pair's reaction, tangent to the
//!   friction circle on the side that opposes the relative rotation.
//!
//! Errata of the seed reproduced against (see `docs/seed-001-digest.md` §10–13): the printed
//! inclined-plane result `P = Q·sin(α + φ)/cos(α + β + φ)` does not follow from its own steps;
//! the twin here is the explicit vector solution of `Q + P + R = 0`,
//! `P = Q·sin(α ± φ)/cos(α ± φ − β′)` with β′ the angle of P above the horizontal. In W3 the
//! seed writes the ground reaction as `R_n1`; it is `R_n2 = Q + 2G`.

mod draw;
mod guide;
mod incline;
mod journal;
mod pivot;
mod rolling;
mod screw;
mod slider;
#[cfg(test)]
mod tests;
mod wedge;

pub use guide::{guide_twin, GuideTwin};
pub use incline::MIN_CROSSING_DEG;
pub use incline::{incline_twin, InclineTwin};
pub use journal::{journal_twin, JournalTwin};
pub use pivot::{pivot_twin, PivotTwin};
pub use rolling::{rolling_twin, RollingTwin, Slide};
pub use screw::{screw_twin, ScrewTwin};
pub use slider::{slider_twin, SliderState, SliderTwin};
pub use wedge::{wedge_twin, WedgeTwin};

use crate::check::{Key, Method, Row, Symbol};
use crate::construct::{ConstructionError, Context, Figure, Recorder};
use crate::geom::{DVec2, Line};
use crate::scale::Scale;
use thiserror::Error;

/// The friction angle φ = arctg f, radians.
pub fn friction_angle(f: f64) -> f64 {
    f.atan()
}

/// The total reaction R = N + F of a sliding pair, turned from the normal by exactly the
/// friction angle φ = arctg `f` against the relative velocity.
///
/// `normal` is the normal reaction acting on the body (pointing into it), `velocity` the
/// body's velocity relative to the surface that exerts the reaction. The friction force is
/// `F = −f·|N|·t̂`, t̂ the unit tangential part of `velocity`, so R has the normal component
/// `normal` and makes the angle arctg f with it, on the side opposite to the motion.
/// Without a tangential velocity the pair does not slide and R = N.
///
/// `None` when `normal` is zero or not finite, or `f` is negative or not finite.
///
/// ```
/// use tmm::friction::tilt_reaction;
/// use tmm::geom::DVec2;
/// let r = tilt_reaction(DVec2::new(0.0, 100.0), DVec2::new(1.0, 0.0), 0.1).unwrap();
/// assert!((r - DVec2::new(-10.0, 100.0)).length() < 1e-12);
/// ```
pub fn tilt_reaction(normal: DVec2, velocity: DVec2, f: f64) -> Option<DVec2> {
    let n = normal.try_normalize()?;
    if !(f.is_finite() && f >= 0.0 && velocity.is_finite()) {
        return None;
    }
    let tangential = velocity - n * velocity.dot(n);
    match tangential.try_normalize() {
        Some(t) => Some(normal - t * (f * normal.length())),
        None => Some(normal),
    }
}

/// The line of action of a revolute pair's reaction with friction: parallel to `direction`
/// and tangent to the friction circle (radius `rho` about `centre`) on the side whose moment
/// about the centre opposes `omega_rel`.
///
/// `direction` is the direction of the reaction acting on the journal, `omega_rel` the
/// journal's angular velocity relative to the member exerting the reaction (counter-clockwise
/// positive). The returned line runs along `direction`; its distance from `centre` is `rho`.
/// Without relative rotation (`omega_rel == 0`) the line passes through the centre.
///
/// `None` when `direction` is zero or not finite, `centre` not finite, or `rho` negative or
/// not finite.
///
/// ```
/// use tmm::friction::friction_circle_tangent;
/// use tmm::geom::DVec2;
/// // A shaft turning counter-clockwise, its load carried upward: the reaction passes left
/// // of the centre, its moment clockwise.
/// let l = friction_circle_tangent(DVec2::ZERO, DVec2::Y, 1.0, 2.0).unwrap();
/// assert!((l.point - DVec2::new(-2.0, 0.0)).length() < 1e-12);
/// ```
pub fn friction_circle_tangent(
    centre: DVec2,
    direction: DVec2,
    omega_rel: f64,
    rho: f64,
) -> Option<Line> {
    if !(rho.is_finite() && rho >= 0.0 && centre.is_finite() && omega_rel.is_finite()) {
        return None;
    }
    let d = direction.try_normalize()?;
    // perp_dot(d.perp(), d) = −1: a force along d through centre + ρ·d.perp() turns
    // clockwise about the centre.
    let side = if omega_rel > 0.0 {
        1.0
    } else if omega_rel < 0.0 {
        -1.0
    } else {
        0.0
    };
    Line::new(centre + d.perp() * (rho * side), d)
}

/// Which way a body moves on an incline or a nut on its screw.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Motion {
    /// Up the plane / raising the load (screwing).
    Up,
    /// Down the plane / lowering the load (unscrewing).
    Down,
}

impl Motion {
    /// +1 up, −1 down: the sign of φ in the formulas.
    pub fn sign(self) -> f64 {
        match self {
            Motion::Up => 1.0,
            Motion::Down => -1.0,
        }
    }
}

/// Uniform motion on an inclined plane under a force P.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Incline {
    /// The weight Q, N (> 0).
    pub load: f64,
    /// The coefficient of sliding friction f (> 0).
    pub f: f64,
    /// The plane's inclination α, radians, in [0, π/2).
    pub alpha: f64,
    /// The angle β′ of P above the horizontal (toward the rise of the plane), radians.
    pub beta: f64,
    /// Up or down the plane.
    pub motion: Motion,
}

/// A V-groove (wedge) slider under a vertical load, pushed along the groove.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wedge {
    /// The load Q, N.
    pub load: f64,
    /// The coefficient of friction on the flanks.
    pub f: f64,
    /// The groove angle β, radians, in (0, π).
    pub groove: f64,
}

/// A screw pair: the nut under an axial load turned by a torque.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Screw {
    /// The axial load Q, N.
    pub load: f64,
    /// The coefficient of friction in the thread.
    pub f: f64,
    /// The lead angle λ, radians, in (0, π/2).
    pub lead: f64,
    /// The thread profile angle δ, radians: 0 for a rectangular thread, 60° metric.
    pub profile: f64,
    /// The mean thread radius r₁, m.
    pub radius: f64,
    /// Raising (screwing) or lowering (unscrewing) the load.
    pub motion: Motion,
}

/// A journal in its bearing (revolute pair), the clearance neglected.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Journal {
    /// The load Q on the shaft, N (vertical, downward).
    pub load: f64,
    /// The coefficient of friction.
    pub f: f64,
    /// The journal radius r, m.
    pub radius: f64,
    /// The shaft's angular velocity sense: +1 counter-clockwise, −1 clockwise.
    pub sense: f64,
}

/// A load on rollers (worked example W3 of seed 001).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rolling {
    /// The load Q, N.
    pub load: f64,
    /// The weight G of one roller, N.
    pub roller_weight: f64,
    /// The roller diameter d, m (the arm h of P).
    pub diameter: f64,
    /// Rolling friction load/rollers k₁, m.
    pub k1: f64,
    /// Rolling friction rollers/plane k₂, m.
    pub k2: f64,
    /// Sliding friction load/rollers f₁.
    pub f1: f64,
    /// Sliding friction rollers/plane f₂.
    pub f2: f64,
}

/// A slider on a plane pressed by a force at an angle from the normal (its weight on an
/// incline alike).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slider {
    /// The force P, N (> 0).
    pub load: f64,
    /// The coefficient of sliding friction f.
    pub f: f64,
    /// The coefficient of static friction f₀ (≥ f).
    pub f0: f64,
    /// The angle α of P from the plane's normal, radians, in [0, π/2).
    pub alpha: f64,
}

/// A translating follower pushed by its cam at the pressure angle λ against the resistance
/// Q along its axis, in a guide of two bearings (seed 001 lecture 15; the twin is
/// [`crate::cam::force`]'s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FollowerGuide {
    /// The resistance Q along the follower's axis, N.
    pub load: f64,
    /// The pressure angle λ, rad, in [0, π/2).
    pub angle: f64,
    /// The guide: its length b, the overhang l, f.
    pub guide: crate::cam::force::TranslatingGuide,
}

/// A rocker pushed by its cam at the pressure angle λ against the moment of resistance M_с,
/// turning in a pivot with friction (seed 001 lecture 16; the twin is
/// [`crate::cam::force`]'s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RockerPivot {
    /// The moment of resistance M_с on the rocker, N·m.
    pub moment: f64,
    /// The pressure angle λ, rad, in [0, π/2).
    pub angle: f64,
    /// The pivot: the arm L, the journal's diameter d, f.
    pub pivot: crate::cam::force::Pivot,
}

/// The kind of a friction case with its data (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CaseKind {
    /// An inclined plane.
    Incline(Incline),
    /// A V-groove slider.
    Wedge(Wedge),
    /// A screw pair.
    Screw(Screw),
    /// A revolute pair.
    Journal(Journal),
    /// Rolling friction (rollers).
    Rolling(Rolling),
    /// A slider's state: at rest, uniform, accelerating.
    Slider(Slider),
    /// A cam's translating follower in its guide.
    Guide(FollowerGuide),
    /// A cam's rocker in its pivot.
    Pivot(RockerPivot),
}

impl CaseKind {
    /// The scene word of the kind (`incline`, `wedge`, `screw`, `journal`, `rolling`,
    /// `slider`, `guide`, `pivot`).
    pub fn word(&self) -> &'static str {
        match self {
            CaseKind::Incline(_) => "incline",
            CaseKind::Wedge(_) => "wedge",
            CaseKind::Screw(_) => "screw",
            CaseKind::Journal(_) => "journal",
            CaseKind::Rolling(_) => "rolling",
            CaseKind::Slider(_) => "slider",
            CaseKind::Guide(_) => "guide",
            CaseKind::Pivot(_) => "pivot",
        }
    }
}

/// One case of a `[friction]` section.
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionCase {
    /// Its name (the subject of its rows: `F_P_<name>`).
    pub name: String,
    /// What it is.
    pub kind: CaseKind,
    /// μ_F of its force drawings; `None`: chosen the textbook way.
    pub scale_f: Option<Scale>,
    /// μ_l of its schemes drawn to scale (the screw's unrolled thread, the journal, the
    /// rollers); `None`: chosen the textbook way (the session chooses it from the sheet's room).
    pub scale_l: Option<Scale>,
}

/// Why a friction case cannot be constructed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FrictionError {
    /// The force cannot move the body uniformly: the lines of P and R are (nearly) parallel.
    #[error("friction case {case}: {why}")]
    Impossible {
        /// The case's name.
        case: String,
        /// The diagnosis with its numbers.
        why: String,
    },
    /// A construction step failed.
    #[error("friction case {case}: {error}")]
    Construction {
        /// The case's name.
        case: String,
        /// The step's error.
        error: Box<ConstructionError>,
    },
    /// No round drawing scale can be formed.
    #[error("friction case {case}: no drawing scale can be chosen for {value} {unit}", value = crate::scale::format_plain(*value))]
    NoScale {
        /// The case's name.
        case: String,
        /// The size.
        value: f64,
        /// Its unit.
        unit: &'static str,
    },
}

/// What a drawing of a case shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DrawingKind {
    /// The scheme: the body, the surface, the loads, the normal, the friction cone or circle
    /// and the reaction (not to scale unless it has a μ_l).
    Scheme,
    /// The force triangle (plan of forces) at μ_F.
    Polygon,
    /// The force triangle of the same motion without friction (for η).
    Frictionless,
    /// The flanks' normal forces of a V-groove slider in its cross-section.
    Flanks,
    /// The moment balance of a rolling body (the arms k magnified).
    Balance,
    /// The force triangle of sliding without rollers.
    Sliding,
}

/// One drawing of a case.
#[derive(Debug, Clone, PartialEq)]
pub struct Drawing {
    /// What it shows.
    pub kind: DrawingKind,
    /// The recorded figure.
    pub figure: Figure,
    /// Whether the figure's μ is a real scale of the drawing (a schematic is not to scale).
    pub scaled: bool,
    /// Further scales the drawing uses (the load at μ_F in a moment balance drawn at μ_P).
    pub also: Vec<Scale>,
}

/// A value read off a case's drawings with its textbook symbol.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseReading {
    /// The symbol in label markup (`P`, `R`, `η`, `φ′`, `ρ`, `M_{тр}`).
    pub symbol: &'static str,
    /// The row.
    pub row: Row,
}

/// A constructed case: its drawings and readings.
#[derive(Debug, Clone, PartialEq)]
pub struct Solved {
    /// The case as given.
    pub case: FrictionCase,
    /// Its drawings, in drawing order.
    pub drawings: Vec<Drawing>,
    /// Its readings against the twin.
    pub readings: Vec<CaseReading>,
    /// Notes (self-braking, the textbook's approximations, the seed's errata).
    pub notes: Vec<crate::check::notes::FrictionNote>,
}

impl Solved {
    /// The rows of its readings.
    pub fn rows(&self) -> Vec<Row> {
        self.readings.iter().map(|r| r.row.clone()).collect()
    }
}

/// Preferred drawn length of the largest force of a triangle, mm.
const POLYGON_MM: f64 = 60.0;

/// A reading of a case: graphical against analytic, the conditioning as a crossing angle in
/// degrees.
pub(crate) fn reading(
    symbol: &'static str,
    key: (Symbol, String),
    graphical: f64,
    analytic: f64,
    conditioning: Option<f64>,
) -> CaseReading {
    CaseReading {
        symbol,
        row: Row::new(
            Key::of_scene(key.0, key.1),
            Method::Polygon,
            graphical,
            analytic,
            analytic.abs(),
        )
        .conditioned(conditioning),
    }
}

/// The μ a case's drawing of `largest` (physical) takes: the scene's, or the round one that
/// draws it about `preferred_mm`.
pub(crate) fn choose_scale(
    case: &str,
    given: Option<Scale>,
    largest: f64,
    preferred_mm: f64,
    quantity: crate::scale::Quantity,
) -> Result<Scale, FrictionError> {
    match given {
        Some(s) => Ok(s),
        None => Scale::round_for(largest, preferred_mm, quantity).ok_or(FrictionError::NoScale {
            case: case.to_string(),
            value: largest,
            unit: quantity.si_unit(),
        }),
    }
}

/// Construct a case in the context `ctx` (its drafting model reads every length) and read
/// its values against the twin.
pub fn solve(case: &FrictionCase, ctx: &Context) -> Result<Solved, FrictionError> {
    let name = case.name.as_str();
    let wrap = |error| FrictionError::Construction {
        case: name.to_string(),
        error: Box::new(error),
    };
    match &case.kind {
        CaseKind::Incline(c) => incline::solve(case, c, ctx, &wrap),
        CaseKind::Wedge(c) => wedge::solve(case, c, ctx, &wrap),
        CaseKind::Screw(c) => screw::solve(case, c, ctx, &wrap),
        CaseKind::Journal(c) => journal::solve(case, c, ctx, &wrap),
        CaseKind::Rolling(c) => rolling::solve(case, c, ctx, &wrap),
        CaseKind::Slider(c) => slider::solve(case, c, ctx, &wrap),
        CaseKind::Guide(c) => guide::solve(case, c, ctx, &wrap),
        CaseKind::Pivot(c) => pivot::solve(case, c, ctx, &wrap),
    }
}

/// The subject of a reading: `<what>_<case>` (`P_up`), or the case alone.
pub(crate) fn subject(what: &str, case: &str) -> String {
    if what.is_empty() {
        case.to_string()
    } else {
        format!("{what}_{case}")
    }
}

impl FrictionCase {
    /// The recorder of one of the case's force triangles: at the scene's μ_F, or the round
    /// one that draws `largest` (N) about [`POLYGON_MM`].
    pub(crate) fn force_recorder(
        &self,
        largest: f64,
        ctx: &Context,
    ) -> Result<Recorder, FrictionError> {
        let mu = choose_scale(
            &self.name,
            self.scale_f,
            largest,
            POLYGON_MM,
            crate::scale::Quantity::Force,
        )?;
        Ok(Recorder::in_context(&self.name, mu, ctx))
    }

    /// The recorder of one of the case's schemes drawn to scale: at the case's μ_l, or the
    /// round one that draws `largest` (m) about `preferred_mm`.
    pub(crate) fn scheme_recorder(
        &self,
        largest: f64,
        preferred_mm: f64,
        ctx: &Context,
    ) -> Result<Recorder, FrictionError> {
        self.recorder_at(self.scale_l, largest, preferred_mm, ctx)
    }

    /// The recorder at μ_l = `given`, or the round one that draws `largest` (m) about
    /// `preferred_mm`.
    fn recorder_at(
        &self,
        given: Option<Scale>,
        largest: f64,
        preferred_mm: f64,
        ctx: &Context,
    ) -> Result<Recorder, FrictionError> {
        let mu = choose_scale(
            &self.name,
            given,
            largest,
            preferred_mm,
            crate::scale::Quantity::Length,
        )?;
        Ok(Recorder::in_context(&self.name, mu, ctx))
    }

    /// The recorder of a schematic drawing, at the nominal μ of 1 mm per mm (its lengths mean
    /// nothing, only its angles and ratios are read).
    pub(crate) fn schematic_recorder(&self, ctx: &Context) -> Result<Recorder, FrictionError> {
        self.recorder_at(None, 1.0, 1000.0, ctx)
    }
}
