//! Involute gears (seed 000 §4, seed 002 PZ1–PZ3): the geometry of a shifted external pair
//! in closed form, the involute drawn by the compass, the meshing picture, rack generation
//! with undercut and pointing, and gear trains (ordinary and planetary) by Willis and by the
//! velocity triangles.
//!
//! As everywhere in `tmm`, each procedure exists twice: a **construction** through the
//! recorder (`mesh::meshing`, [`generate`], `triangles::triangles`) read off under
//! the drafting model, and an **analytic twin** ([`GearPair`], [`Cutting`], [`Train::willis`]);
//! `rows` compares them.
//!
//! Errata of the seeds reproduced against, never matched (`docs/seed-000-cases.md` §000.13,
//! `docs/seed-002-digest.md` §4.3): seed 000 takes r_b = r·cos α_w and the base pitch
//! πm·cos α_w, so its ε_α = 1.22 (exact 1.15524; 1.1550 with its Δy = 0.18); PZ3 reads cos 26.92° as 0.8836 and prints
//! a_w = 180.79 mm (exact 179.18) and ε_α = 1.14 (exact 1.1637), and lays off "p = 14.13 mm".

pub mod blocking;
mod detail;
mod differential;
mod generate;
mod involute;
mod mesh;
mod numbers;
mod pair;
mod rack;
mod reading;
mod rows;
mod scheme;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_closing;
#[cfg(test)]
mod tests_limits;
mod trace;
mod train;
mod triangles;
mod undercut;

pub use detail::{DetailMark, DETAIL_LETTER, DETAIL_NAME_WITHIN_MM};
pub use differential::Differential;
pub use generate::{generate, Generation};
pub use involute::{compass_involute, dms, inv, inv_inverse, CompassInvolute, TABLE_DIGITS};
pub use mesh::{LAMBDA_MM, NAME_WITHIN_MM};
pub use pair::{GearPair, PairSpec};
pub use rack::{
    uncuttable, x_for_tip, x_min, x_min_textbook, BasicRack, Cutting, RackPiece, States, ToolShape,
};
pub use rows::PairSeed;
pub use train::{
    train_study, Assembly, ClosedMesh, Mesh, PlanetarySpec, SeedStage, Stage, Train, TrainError,
    TrainMobility, TrainSeed, TrainStudy, Wheel,
};
pub use triangles::{SlowLinks, POLE_DISTANCE};

use crate::scale::Scale;
use thiserror::Error;

/// The least tip thickness of a sound tooth, × m (seed 002 PZ1: S_a ≥ 0.3m).
pub const MIN_TIP: f64 = 0.3;

/// Why a gear cannot be computed or constructed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum GearError {
    /// A datum out of its range.
    #[error("gears: {what} = {value}: expected {expected}", value = crate::scale::format_plain(*value))]
    Spec {
        /// The datum (`module`, `z1`).
        what: &'static str,
        /// Its value.
        value: f64,
        /// What was expected.
        expected: &'static str,
    },
    /// A coefficient of the basic rack out of its range.
    #[error("gears: the basic rack's {what} = {value}: expected {expected}", value = crate::scale::format_plain(*value))]
    Rack {
        /// The coefficient (`alpha`, `ha`, `c`, `rho_f`).
        what: &'static str,
        /// Its value.
        value: f64,
        /// What was expected.
        expected: String,
    },
    /// inv α⁻¹ of a value outside its domain.
    #[error("gears: inv α = {value} has no pressure angle in [0°, 90°)", value = crate::scale::format_plain(*value))]
    InvoluteDomain {
        /// The value.
        value: f64,
    },
    /// An involute through a point inside its base circle.
    #[error("gears: an involute of r_b = {rb} m cannot pass through a point {distance} m from the centre", rb = crate::scale::format_plain(*rb), distance = crate::scale::format_plain(*distance))]
    InvolutePoint {
        /// The point's distance from the centre, m.
        distance: f64,
        /// The base radius, m.
        rb: f64,
    },
    /// A centre distance the pair cannot have.
    #[error("gears: a centre distance a_w = {a_w} m is infeasible: {why} ({least} m)", a_w = crate::scale::format_plain(*a_w), least = crate::scale::format_plain(*least))]
    CentreDistance {
        /// The asked a_w, m.
        a_w: f64,
        /// The bound, m.
        least: f64,
        /// Why.
        why: &'static str,
    },
    /// The tip of a wheel passes the interference point of its mate.
    #[error("gears: interference: the tip of wheel {wheel} reaches {reach} m along the line of action, beyond N₁N₂ = {g} m (the tip digs into the mate's root)", reach = crate::scale::format_plain(*reach), g = crate::scale::format_plain(*g))]
    Interference {
        /// The wheel (1, 2).
        wheel: usize,
        /// N₁B₂ or N₂B₁, m.
        reach: f64,
        /// N₁N₂, m.
        g: f64,
    },
    /// The mate's tip meets a wheel's flank below the junction of its involute and fillet:
    /// the tip cuts into the fillet (interference with the transition curve).
    #[error("gears: interference with the fillet of wheel {wheel}: the mate's tip meets its flank at r = {contact_mm:.4} mm, {depth_mm:.4} mm below the junction of its involute and fillet (r = {junction_mm:.4} mm): the tip cuts into the fillet")]
    FilletInterference {
        /// The wheel (1, 2).
        wheel: usize,
        /// The radius at which the mate's tip meets the wheel's flank (B₁ or B₂), mm.
        contact_mm: f64,
        /// The radius of the junction of involute and fillet, mm.
        junction_mm: f64,
        /// How far below the junction, mm.
        depth_mm: f64,
    },
    /// A pointed tooth.
    #[error("gears: the tooth of wheel {wheel} is pointed: s_a = {sa} m (m = {module} m)", sa = crate::scale::format_plain(*sa), module = crate::scale::format_plain(*module))]
    Pointed {
        /// The wheel.
        wheel: usize,
        /// Its tip thickness, m.
        sa: f64,
        /// The module, m.
        module: f64,
    },
    /// A tip circle inside the base circle: the tooth has no involute flank.
    #[error("gears: the tip circle of wheel {wheel} (r_a = {ra_mm:.4} mm) falls below its base circle (r_b = {rb_mm:.4} mm): the tooth has no involute flank")]
    TipInsideBase {
        /// The wheel (1, 2).
        wheel: usize,
        /// Its tip radius, mm.
        ra_mm: f64,
        /// Its base radius, mm.
        rb_mm: f64,
    },
    /// A negative radial clearance.
    #[error(
        "gears: the tip of wheel {wheel} touches the mate's root circle: clearance {clearance} m"
    )]
    Clearance {
        /// The wheel.
        wheel: usize,
        /// The clearance, m.
        clearance: f64,
    },
    /// A contact ratio below 1.
    #[error("gears: the contact ratio ε_α = {eps} < 1: the mesh is not continuous", eps = crate::scale::format_plain(*eps))]
    ContactRatio {
        /// ε_α.
        eps: f64,
    },
    /// No round drawing scale for a size.
    #[error("gears: no drawing scale can be chosen for the size {size} m", size = crate::scale::format_plain(*size))]
    NoScale {
        /// The size, m.
        size: f64,
    },
    /// A step of the meshing construction cannot be carried out (boxed: a construction's
    /// error is large).
    #[error("gears: {0}")]
    Construction(Box<crate::construct::ConstructionError>),
    /// The line of action N–N has no direction (the pole's normal is zero).
    #[error("gears: N–N")]
    LineOfAction,
    /// The undercut cut from a generated tooth cannot be hatched.
    #[error("gears: the undercut's hatching: {0}")]
    UndercutHatching(#[from] crate::geom::HatchError),
    /// The planetary train cannot be solved or drawn (boxed: a train's error is large).
    #[error("gears: {0}")]
    Train(Box<TrainError>),
}

impl From<crate::construct::ConstructionError> for GearError {
    fn from(e: crate::construct::ConstructionError) -> Self {
        Self::Construction(Box::new(e))
    }
}

impl From<TrainError> for GearError {
    fn from(e: TrainError) -> Self {
        Self::Train(Box::new(e))
    }
}

/// The round μ_l drawing `size` (m) about `preferred_mm` long.
fn scale_for(size: f64, preferred_mm: f64) -> Result<Scale, GearError> {
    Scale::round_for(size, preferred_mm, crate::scale::Quantity::Length)
        .ok_or(GearError::NoScale { size })
}

/// The gear study a scene asks for (`[gears]`): a pair with its meshing picture and wheels
/// cut by the rack.
#[derive(Debug, Clone, PartialEq)]
pub struct GearsSpec {
    /// The pair (`[gears.pair]`).
    pub pair: Option<PairSpec>,
    /// The criterion the pair's shifts were chosen by on the blocking contour
    /// (`[gears.pair] choose`); `None`: the scene gives them.
    pub chosen: Option<blocking::Criterion>,
    /// What the source prints for the pair (`[gears.seed]`), checked in the notes.
    pub seed: Option<PairSeed>,
    /// μ_l of the meshing picture; `None`: chosen the textbook way.
    pub scale_l: Option<Scale>,
    /// The wheels cut by the rack (`[[gears.rack]]`).
    pub racks: Vec<RackSpec>,
    /// The train (`[planetary]`).
    pub planetary: Option<PlanetarySpec>,
}

/// A wheel cut by the rack, as a scene gives it.
#[derive(Debug, Clone, PartialEq)]
pub struct RackSpec {
    /// Its name in report keys (`1`: `s_a1`, `x_min`).
    pub name: String,
    /// The wheel.
    pub cutting: Cutting,
    /// The number of equal rack steps N.
    pub positions: usize,
    /// μ_l of its figure; `None`: chosen the textbook way.
    pub scale_l: Option<Scale>,
}

/// The default number of rack positions of a generation.
pub const DEFAULT_POSITIONS: usize = 90;

/// The pair of a gear study: its dimensions and its meshing picture.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshedPair {
    /// The pair's dimensions by formula.
    pub pair: GearPair,
    /// Its meshing picture and what was read off it.
    pub meshing: mesh::Meshing,
}

/// A wheel of a gear study cut by the rack.
#[derive(Debug, Clone, PartialEq)]
pub struct CutWheel {
    /// Its name in report keys (`1`: `s_a1`, `x_min`), as the scene gives it.
    pub name: String,
    /// Its generation by the rack.
    pub generation: generate::Generation,
    /// Its rows ([`rows::generation_rows`]), made once.
    pub rows: Vec<crate::check::Row>,
}

/// The gear study carried out: the pair with its meshing picture, the generated wheels.
#[derive(Debug, Clone, PartialEq)]
pub struct GearStudy {
    /// The pair and its meshing picture.
    pub pair: Option<MeshedPair>,
    /// What the source prints for the pair.
    pub seed: Option<PairSeed>,
    /// The generated wheels, in the scene's order.
    pub racks: Vec<CutWheel>,
    /// The train.
    pub train: Option<TrainStudy>,
    /// The pair's blocking contour with the scene's point placed and the textbook's
    /// choices (`None`: no pair, or no contour for it).
    pub blocking: Option<blocking::BlockingStudy>,
}

/// The round μ_l of a meshing picture: the whole of both wheels about 360 mm tall.
pub fn meshing_scale(p: &GearPair) -> Result<Scale, GearError> {
    scale_for(p.a_w + p.ra[0] + p.ra[1], 360.0)
}

/// The round μ_l of a generation: four pitches (the tooth, its spaces and the rack positions
/// about them) up to 400 mm wide, so that the tooth is large on the sheet (seed 002 PZ1
/// draws the rack-cut tooth on a disc of the tip diameter).
pub fn generation_scale(c: &Cutting) -> Result<Scale, GearError> {
    scale_for(4.0 * std::f64::consts::PI * c.module, 400.0)
}

/// Carry out `spec` in `ctx`, the pair's blocking contour through the caller's `studies`
/// (the one kept there, else traced and kept).
///
/// # Errors
/// A [`GearError`] from the pair's geometry or a construction.
pub fn study(
    spec: &GearsSpec,
    ctx: &crate::construct::Context,
    studies: &blocking::Studies,
) -> Result<GearStudy, GearError> {
    let pair = match &spec.pair {
        Some(ps) => {
            let p = GearPair::working(*ps)?;
            let scale = match spec.scale_l {
                Some(s) => s,
                None => meshing_scale(&p)?,
            };
            Some(MeshedPair {
                meshing: mesh::meshing(&p, scale, ctx)?,
                pair: p,
            })
        }
        None => None,
    };
    let racks = spec
        .racks
        .iter()
        .map(|r| {
            let scale = match r.scale_l {
                Some(s) => s,
                None => generation_scale(&r.cutting)?,
            };
            let generation = generate::generate(&r.cutting, r.positions, scale, ctx)?;
            Ok(CutWheel {
                name: r.name.clone(),
                rows: rows::generation_rows(&r.name, &generation),
                generation,
            })
        })
        .collect::<Result<Vec<_>, GearError>>()?;
    let train = match &spec.planetary {
        Some(p) => Some(train_study(p, ctx)?),
        None => None,
    };
    // The contour is of the pair's tooth numbers and rack; a pair too odd for it (its
    // point outside the formulas' domain) has none, and the notes say nothing of it.
    let blocking = spec
        .pair
        .as_ref()
        .and_then(|ps| studies.of(ps, spec.chosen).ok());
    Ok(GearStudy {
        pair,
        seed: spec.seed,
        racks,
        train,
        blocking,
    })
}

impl GearStudy {
    /// Every row: the pair's by formula and off the meshing picture, each wheel's generation,
    /// the blocking contour's points (the report's; the sheet's table is `rows_by_part`).
    pub fn rows(&self) -> Vec<crate::check::Row> {
        let mut out = self.rows_by_part().concat();
        if let Some(b) = &self.blocking {
            out.extend(b.rows());
        }
        out
    }

    /// The rows in two parts: the pair's (its formulas and its meshing picture), and the
    /// cut wheels' with the train's.
    pub fn rows_by_part(&self) -> [Vec<crate::check::Row>; 2] {
        let mut pair = Vec::new();
        if let Some(MeshedPair {
            pair: p,
            meshing: m,
        }) = &self.pair
        {
            pair.extend(rows::pair_rows(p));
            pair.extend(rows::meshing_rows(p, m));
        }
        let mut rest = Vec::new();
        for w in &self.racks {
            rest.extend(w.rows.iter().cloned());
        }
        if let Some(t) = &self.train {
            rest.extend(t.rows());
        }
        [pair, rest]
    }
    /// The generated wheel a row of [`Self::rows`] belongs to, with the row's subject
    /// without the wheel's name (`a` of `s_a` for the wheel's `a0`); `None` for a row of no
    /// generated wheel. A row is the wheel's by its key and its method: the shaper's cut
    /// wheel `1` has an `s_a1` off its envelope, the pair's wheel 1 one by formula.
    pub fn cut_wheel_of(&self, row: &crate::check::Row) -> Option<(&CutWheel, &'static str)> {
        self.racks.iter().find_map(|w| {
            let bare = rows::bare_subject(&row.key.subject, &w.name)?;
            w.rows
                .iter()
                .any(|r| r.key == row.key && r.method == row.method)
                .then_some((w, bare))
        })
    }

    /// The notes: the pair's (with the seeds' errata), each generation's.
    pub fn notes(&self) -> Vec<crate::check::ReportNote> {
        use crate::check::notes::GearsNote;
        use crate::check::ReportNote;
        let mut out: Vec<ReportNote> = Vec::new();
        if let Some(MeshedPair {
            pair: p,
            meshing: m,
        }) = &self.pair
        {
            out.extend(
                rows::pair_notes(p, self.seed.as_ref())
                    .into_iter()
                    .map(ReportNote::from),
            );
            out.push(ReportNote::from(GearsNote::Compass {
                deviation: m.compass.0,
                step: m.compass.1,
            }));
        }
        if let Some(b) = &self.blocking {
            out.extend(b.notes().into_iter().map(ReportNote::from));
        }
        for w in &self.racks {
            out.extend(
                rows::generation_notes(&w.name, &w.generation)
                    .into_iter()
                    .map(ReportNote::from),
            );
        }
        if let Some(t) = &self.train {
            out.extend(t.notes().into_iter().map(ReportNote::from));
        }
        out
    }
}
