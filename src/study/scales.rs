//! The one decider of the kinematic study's scales. Each is decided once per session, before
//! anything is constructed, and every sheet and the report ask for it: the scene's as given;
//! else the textbook's choice — μ_l draws the crank about `CRANK_MM` (50 mm), μ_v and μ_a the crank
//! pin's vector at least 80 mm — raised along the round series until its drawing, predicted
//! from the analytic twin, fits its field (the plan of positions `POSITIONS_ROOM`, which an
//! empty A1 sheet also holds; every velocity or acceleration plan `VECTOR_PLAN_ROOM`, and the
//! plans of a kind together `PLANS_AREA_MM2`). A study whose drawings cannot share one sheet
//! with its tables takes two ([`KinSheets`]); its free μ_v and μ_a are then made finer while
//! the plans fit the room their sheet gives them (`TWO_SHEET_PLAN_ROOM`, the first sheet's
//! field beside the plan of positions for the velocity plans), and the displacement chart is
//! drawn as large as the second sheet's share allows (`LARGER_CHARTS`).

use super::*;
use crate::construct::fit::{finest_fitting, fit_scale, overflow, Extent, LABEL_MARGIN};
use crate::geom::DVec2;
use crate::kinematics::{self, drawn_points, ChartSize};
use crate::linkage::{guide_ends, GUIDE_MARGIN_MM};
use crate::plate::{Sheet, CAPTION_BAND_MM, FIELD_MARGIN_MM, ITEM_GAP_MM};
use crate::scale::Quantity;

/// Preferred drawn length of the crank when the scene gives no μ_l (textbook: 40–60 mm).
const CRANK_MM: f64 = 50.0;
/// The field of the plan of positions, mm: the right part of an A1 sheet, beside the
/// structural scheme on the positions sheet.
const POSITIONS_ROOM: DVec2 = DVec2::new(530.0, 502.0);
/// The field of a velocity or acceleration plan chosen the textbook way, mm: the crank pin's
/// vector drawn 80 mm, coarser when another vector would make the plan larger.
const VECTOR_PLAN_ROOM: DVec2 = DVec2::new(150.0, 150.0);
/// Allowance of a plan of positions: pivot symbols, slider blocks (its guides are marks).
const PLAN_ALLOWANCE: f64 = 1.0;
/// Allowance of a velocity or acceleration plan: direction lines drawn 6 mm past their
/// points, arrowheads.
const VECTOR_PLAN_ALLOWANCE: f64 = 6.0;

/// The extent of the plan of positions: every point at every position, the fixed points.
fn positions_extent(poses: &PlanPoses) -> Extent {
    let mut e = Extent::empty(PLAN_ALLOWANCE);
    for p in &poses.positions {
        for &x in &p.pose.p {
            e.add(x);
        }
    }
    for (at, dir) in guide_ends(poses) {
        e.mark(at, dir * GUIDE_MARGIN_MM);
    }
    e
}

/// The largest labelled size, at `mu`, of the plans of `kind` at the positions `ks`, each
/// drawn through its points (SI).
fn largest_plan(
    poses: &PlanPoses,
    ks: &[usize],
    w1: f64,
    kind: PlanKind,
) -> impl Fn(Scale) -> DVec2 {
    let extents: Vec<Extent> = ks
        .iter()
        .map(|&k| {
            let mut e = Extent::empty(VECTOR_PLAN_ALLOWANCE);
            drawn_points(poses, k, w1, kind)
                .into_iter()
                .for_each(|p| e.add(p));
            e
        })
        .collect();
    move |mu| {
        extents
            .iter()
            .fold(DVec2::ZERO, |m, e| m.max(e.labelled_size_at(mu)))
    }
}

/// The positions `ks` without those whose plans the scene draws at a μ of their own
/// (`own`, `kinematics.own_scale`): the plans the common μ of their kind is chosen for, one μ
/// for every plan of a sheet unless the scene gives more (issue 45: the tangent's two μ_v).
fn common_plans(ks: &[usize], own: &[usize]) -> Vec<usize> {
    ks.iter().copied().filter(|k| !own.contains(k)).collect()
}

/// The room all the velocity (or acceleration) plans of a sheet share, mm²: about a third of
/// an A1 sheet's drawing field, so that the plan of positions, the diagrams and the tables
/// keep theirs.
const PLANS_AREA_MM2: f64 = 175_000.0;

/// The labelled size of each plan of `kind` at the positions `ks` at `mu`, mm.
fn plan_sizes(poses: &PlanPoses, ks: &[usize], w1: f64, kind: PlanKind, mu: Scale) -> Vec<DVec2> {
    ks.iter()
        .map(|&k| largest_plan(poses, &[k], w1, kind)(mu))
        .collect()
}

/// The labelled area of the plans of `kind` at the positions `ks` at `mu`, summed, mm².
fn plans_area(poses: &PlanPoses, ks: &[usize], w1: f64, kind: PlanKind, mu: Scale) -> f64 {
    area_of(&plan_sizes(poses, ks, w1, kind, mu))
}

/// The summed area of `sizes`, mm².
fn area_of(sizes: &[DVec2]) -> f64 {
    sizes.iter().map(|s| s.x * s.y).sum()
}

/// `start` raised along the round series until the largest of the plans `ks` fits
/// `VECTOR_PLAN_ROOM` and all of them `PLANS_AREA_MM2`.
fn plans_fit(poses: &PlanPoses, ks: &[usize], w1: f64, kind: PlanKind, start: Scale) -> Scale {
    let largest = largest_plan(poses, ks, w1, kind);
    fit_scale(start, |mu| {
        let area = plans_area(poses, ks, w1, kind, mu) / PLANS_AREA_MM2;
        overflow(largest(mu), VECTOR_PLAN_ROOM).max(area.sqrt())
    })
    .unwrap_or(start)
}

/// The drawing field of the course's plate (an A1 sheet, landscape), mm²: inside its frame
/// (816 × 584 mm), its title block (185 × 55 mm) left out.
fn a1_field_mm2() -> f64 {
    let sheet = Sheet::default();
    let (frame, block) = (sheet.frame(), sheet.title_block());
    frame.width() * frame.height() - block.width() * block.height()
}

/// The share of an A1 field the kinematic drawings (the plan of positions, the velocity and
/// acceleration plans, the diagrams) may take on one sheet: the analytic tables, the texts,
/// the captions and the gaps between the blocks take the rest.
const ONE_SHEET_SHARE: f64 = 0.5;

/// The share of a field the blocks of a sheet take once laid out: the gaps between them and
/// the ragged ends of their rows take the rest.
const LAID_OUT_SHARE: f64 = 0.75;

/// The sizes, against the textbook's (along φ, up), the chart may be drawn at on the second of
/// two sheets, the largest first: 2π on 360 mm (1° a millimetre) with the diagrams 87,5, 70 or
/// 52,5 mm tall; 2π on 300 mm, 49 mm tall; 2π on 240 mm, 52,5 mm tall, which stands beside a
/// row of tall acceleration plans where the longer ones do not. Each is at least as tall
/// against its length as the textbook's: a longer chart of the same height takes a longer
/// pole distance, and its rays, within a few degrees of one another, print black at the pole
/// (the V engine's at 2π on 300 mm, 35 mm tall).
const LARGER_CHARTS: [(f64, f64); 5] =
    [(1.5, 2.5), (1.5, 2.0), (1.5, 1.5), (1.25, 1.4), (1.0, 1.5)];

/// Whether the second of two kinematic sheets holds its acceleration plans (labelled sizes
/// `plans`, mm) and the diagrams' stack (`stack`): the plans in a row above the stack, the
/// row under the designation box and each with its caption's band; or the plans and the
/// stack side by side. (The V engine's plans at 3 and 6, 234 mm tall, and its stack drawn
/// 308 mm tall at 2π on 300 mm need 594 mm of a 578 mm field, and 881 mm of an 810 mm one
/// side by side: the stack went to a third sheet.)
fn second_sheet_holds(plans: &[DVec2], stack: DVec2) -> bool {
    let sheet = Sheet::default();
    let (frame, boxed) = (sheet.frame(), sheet.designation_box());
    let field = frame.size() - DVec2::splat(2.0 * FIELD_MARGIN_MM);
    let captioned = |h: f64| h + CAPTION_BAND_MM;
    let tallest = plans.iter().map(|p| p.y).fold(0.0, f64::max);
    let row: f64 = plans.iter().map(|p| p.x + ITEM_GAP_MM).sum();
    let stacked = (boxed.height() - FIELD_MARGIN_MM + ITEM_GAP_MM)
        + captioned(tallest)
        + ITEM_GAP_MM
        + captioned(stack.y);
    stacked <= field.y || row + stack.x <= field.x
}

/// The field of a velocity or acceleration plan on a study of two sheets, mm: a sheet shared
/// with one other drawing (the plan of positions; the diagrams) holds plans up to a little
/// over the diagrams' own height, three across its width.
const TWO_SHEET_PLAN_ROOM: DVec2 = DVec2::new(250.0, 250.0);

/// How many A1 sheets the kinematic study's drawings take, decided with its scales: the
/// drawings at the textbook's μ predicted (the plan of positions, the common velocity and
/// acceleration plans) and measured (the diagrams), against [`ONE_SHEET_SHARE`] of the field.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KinSheets {
    /// Everything on one sheet: the plans keep the textbook's μ, within `VECTOR_PLAN_ROOM`
    /// and `PLANS_AREA_MM2`.
    One,
    /// The textbook's sheet 1 (the plan of positions and the velocity plans) and a second (the
    /// acceleration plans, the diagrams, the tables): a free μ_v or μ_a is made finer while the
    /// plans fit their sheet's room.
    Two,
}

/// The room of the plans of `kind` on a study of [`KinSheets::Two`]: each plan's field and the
/// area all of them take together, mm². The velocity plans share the first sheet's laid-out
/// field with the plan of positions (`positions_mm2`); the acceleration plans keep a third
/// of the second's (`PLANS_AREA_MM2`) beside the diagrams and the tables.
fn two_sheet_room(kind: PlanKind, positions_mm2: f64) -> (DVec2, f64) {
    let area = match kind {
        PlanKind::Velocity => LAID_OUT_SHARE * a1_field_mm2() - positions_mm2,
        PlanKind::Acceleration => PLANS_AREA_MM2,
    };
    (TWO_SHEET_PLAN_ROOM, area)
}

/// `start` made finer along the round series while the largest of the plans `ks` fits `room`
/// and all of them `area` mm², and `within` holds.
fn plans_finer(
    poses: &PlanPoses,
    ks: &[usize],
    w1: f64,
    kind: PlanKind,
    start: Scale,
    (room, area): (DVec2, f64),
    within: impl Fn(Scale) -> bool,
) -> Scale {
    let largest = largest_plan(poses, ks, w1, kind);
    let fits = |&mu: &Scale| {
        largest(mu).cmple(room).all() && plans_area(poses, ks, w1, kind, mu) <= area && within(mu)
    };
    finest_fitting(start, start, Some, fits)
}

/// `start` raised along the round series until `size(μ)` fits `room`.
fn raised_to_fit(start: Scale, room: DVec2, size: impl Fn(Scale) -> DVec2) -> Scale {
    fit_scale(start, |mu| overflow(size(mu), room)).unwrap_or(start)
}

/// μ_l of the plan of positions.
struct ScaleL;
impl Cache for ScaleL {
    type Key = ();
    type Value = Result<Scale, StudyError>;
}

/// How many sheets the kinematic study takes.
struct Sheets;
impl Cache for Sheets {
    type Key = ();
    type Value = Result<KinSheets, StudyError>;
}

/// Each plan's μ, by (kind, position).
struct PlanScales;
impl Cache for PlanScales {
    type Key = (PlanKind, usize);
    type Value = Result<Scale, StudyError>;
}

/// The kinematic study's scales.
struct Scales;
impl Cache for Scales {
    type Key = ();
    type Value = Result<KinScales, StudyError>;
}

impl<'s> Session<'s> {
    /// μ_l of every drawing of the plan of positions, decided once: the scene's, else the
    /// crank drawn about `CRANK_MM` (50 mm) and raised until the plan fits `POSITIONS_ROOM`.
    pub fn scale_l(&self) -> Result<Scale, StudyError> {
        self.caches.get::<ScaleL>((), || {
            if let Some(s) = self.scene.scale_l {
                return Ok(s);
            }
            let m = self.mechanism("the position diagram")?;
            let start = kinematics::round_scale(m.crank.length, CRANK_MM, Quantity::Length)?;
            let plan = positions_extent(&*self.poses()?);
            Ok(raised_to_fit(start, POSITIONS_ROOM, |mu| {
                plan.labelled_size_at(mu)
            }))
        })
    }

    /// The kinematic study's scales, decided once: μ_l ([`Session::scale_l`]); μ_v and μ_a the
    /// scene's, else the largest round ones the room allows: from the crank pin's vector drawn
    /// about 80 mm, raised until the largest plan fits `VECTOR_PLAN_ROOM` (a plan the scene
    /// draws at a μ of its own aside, [`Session::plan_scale`]), then made finer while the plans fit the
    /// room their sheet gives them ([`Session::kin_sheets`]: one sheet or two); the
    /// displacement chart's as the scene gives them (the rest chosen for the chart by the
    /// study).
    pub fn kin_scales(&self) -> Result<KinScales, StudyError> {
        self.caches.get::<Scales>((), || {
            let spec = self.spec();
            let (mut v, mut a) = self.textbook_plan_scales()?;
            if spec.scale_v.is_none() {
                v = self.largest_plans(PlanKind::Velocity, v, a)?;
            }
            if spec.scale_a.is_none() {
                a = self.largest_plans(PlanKind::Acceleration, v, a)?;
            }
            Ok(KinScales {
                l: self.scale_l()?,
                v,
                a,
                chart: self.sheet_chart(a)?,
            })
        })
    }

    /// The free μ of the plans of `kind` (`v` or `a`, the other kept), made finer along the
    /// round series while the common plans fit the room their sheet gives them: on one sheet
    /// `VECTOR_PLAN_ROOM` each and `PLANS_AREA_MM2` together, every drawing of the study
    /// within [`ONE_SHEET_SHARE`] of the field; on two, [`two_sheet_room`].
    fn largest_plans(&self, kind: PlanKind, v: Scale, a: Scale) -> Result<Scale, StudyError> {
        let (poses, w1) = (self.poses()?, self.w1()?);
        let (start, all) = match kind {
            PlanKind::Velocity => (v, (0..poses.positions.len()).collect()),
            PlanKind::Acceleration => (a, self.acceleration_positions()?),
        };
        let ks = common_plans(&all, &self.own_scale_positions(kind)?);
        Ok(match self.kin_sheets()? {
            KinSheets::One => {
                let room = (VECTOR_PLAN_ROOM, PLANS_AREA_MM2);
                let within = |mu: Scale| {
                    let (v, a) = match kind {
                        PlanKind::Velocity => (mu, a),
                        PlanKind::Acceleration => (v, mu),
                    };
                    self.drawn_mm2(v, a)
                        .is_ok_and(|d| d <= ONE_SHEET_SHARE * a1_field_mm2())
                };
                plans_finer(&poses, &ks, w1, kind, start, room, within)
            }
            KinSheets::Two => {
                let l = self.scale_l()?;
                let positions = positions_extent(&poses).labelled_size_at(l);
                let room = two_sheet_room(kind, positions.x * positions.y);
                plans_finer(&poses, &ks, w1, kind, start, room, |_| true)
            }
        })
    }

    /// The displacement chart's scales as the scene gives them, at the textbook's size.
    fn chart_scales(&self) -> ChartScales {
        let spec = self.spec();
        ChartScales {
            s: spec.scale_s,
            phi: spec.scale_phi,
            h1: spec.pole_h1,
            h2: spec.pole_h2,
            size: ChartSize::TEXTBOOK,
        }
    }

    /// μ_v and μ_a the textbook's way: the scene's, else the crank pin's vector drawn about
    /// 80 mm, raised until the largest common plan fits `VECTOR_PLAN_ROOM` and the common
    /// plans of a kind together `PLANS_AREA_MM2`.
    fn textbook_plan_scales(&self) -> Result<(Scale, Scale), StudyError> {
        let m = self.mechanism("the kinematic analysis")?;
        let spec = self.spec();
        let (mut v, mut a) = kinematics::plan_scales(&m.crank, spec)?;
        let (poses, w1) = (self.poses()?, self.w1()?);
        if spec.scale_v.is_none() {
            let all: Vec<usize> = (0..poses.positions.len()).collect();
            let ks = common_plans(&all, &self.own_scale_positions(PlanKind::Velocity)?);
            v = plans_fit(&poses, &ks, w1, PlanKind::Velocity, v);
        }
        if spec.scale_a.is_none() {
            let own = self.own_scale_positions(PlanKind::Acceleration)?;
            let ks = common_plans(&self.acceleration_positions()?, &own);
            a = plans_fit(&poses, &ks, w1, PlanKind::Acceleration, a);
        }
        Ok((v, a))
    }

    /// How many sheets the kinematic study's drawings take, decided once ([`KinSheets`]): two
    /// when the plan of positions, the common plans at the textbook's μ_v and μ_a (their
    /// labelled sizes predicted from the analytic twin) and the diagrams (constructed, as the
    /// sheet draws them) take more than [`ONE_SHEET_SHARE`] of an A1 field.
    pub fn kin_sheets(&self) -> Result<KinSheets, StudyError> {
        self.caches.get::<Sheets>((), || {
            let (v, a) = self.textbook_plan_scales()?;
            Ok(
                if self.drawn_mm2(v, a)? > ONE_SHEET_SHARE * a1_field_mm2() {
                    KinSheets::Two
                } else {
                    KinSheets::One
                },
            )
        })
    }

    /// The area the kinematic drawings take with the plans at `v` and `a`, mm²: the plan of
    /// positions and the common plans (their labelled sizes predicted from the analytic
    /// twin) and the diagrams (constructed, as the sheet draws them).
    fn drawn_mm2(&self, v: Scale, a: Scale) -> Result<f64, StudyError> {
        let (poses, w1, l) = (self.poses()?, self.w1()?, self.scale_l()?);
        let positions = positions_extent(&poses).labelled_size_at(l);
        let all: Vec<usize> = (0..poses.positions.len()).collect();
        let velocity = common_plans(&all, &self.own_scale_positions(PlanKind::Velocity)?);
        Ok(positions.x * positions.y
            + plans_area(&poses, &velocity, w1, PlanKind::Velocity, v)
            + self.acceleration_mm2(a)?
            + self.diagrams_mm2(l, self.chart_scales())?)
    }

    /// The labelled sizes of the common acceleration plans at `a`, mm.
    fn acceleration_sizes(&self, a: Scale) -> Result<Vec<DVec2>, StudyError> {
        let (poses, w1) = (self.poses()?, self.w1()?);
        let ks = common_plans(
            &self.acceleration_positions()?,
            &self.own_scale_positions(PlanKind::Acceleration)?,
        );
        Ok(plan_sizes(&poses, &ks, w1, PlanKind::Acceleration, a))
    }

    /// The labelled area of the common acceleration plans at `a`, summed, mm².
    fn acceleration_mm2(&self, a: Scale) -> Result<f64, StudyError> {
        Ok(area_of(&self.acceleration_sizes(a)?))
    }

    /// The labelled area of the displacement diagrams at `chart`, constructed as the sheet
    /// draws them, mm²: none when there is nothing to chart or they are refused (the sheet
    /// says why in a line).
    fn diagrams_mm2(&self, l: Scale, chart: ChartScales) -> Result<f64, StudyError> {
        let s = self.diagrams_size(l, chart)?;
        Ok(s.x * s.y)
    }

    /// The labelled size of the displacement diagrams' stack at `chart`, constructed as the
    /// sheet draws them, mm: zero when there is nothing to chart or they are refused.
    fn diagrams_size(&self, l: Scale, chart: ChartScales) -> Result<DVec2, StudyError> {
        let charted = super::kinematics::refusable(self.diagrams(l, chart), &mut Vec::new())?;
        Ok(charted
            .and_then(|d| {
                let second = d.second_figure.translated(d.second_at).bounds()?;
                let (lo, hi) = d.first_figure.bounds()?;
                Some((lo.min(second.0), hi.max(second.1)))
            })
            .map_or(DVec2::ZERO, |(lo, hi)| hi - lo + DVec2::splat(LABEL_MARGIN)))
    }

    /// The chart the sheets draw: the scene's scales at the textbook's size; on a study of two
    /// sheets, the largest of [`LARGER_CHARTS`] at which the second sheet's drawings (the
    /// common acceleration plans at `a` and the diagrams) take at most [`ONE_SHEET_SHARE`] of
    /// its field, as the first sheet's do — the room the velocity plans left there — and
    /// stand on it together ([`second_sheet_holds`]).
    fn sheet_chart(&self, a: Scale) -> Result<ChartScales, StudyError> {
        let textbook = self.chart_scales();
        if self.kin_sheets()? == KinSheets::One {
            return Ok(textbook);
        }
        let (l, sizes) = (self.scale_l()?, self.acceleration_sizes(a)?);
        let plans = area_of(&sizes);
        for (along, up) in LARGER_CHARTS {
            let chart = ChartScales {
                size: ChartSize::times(along, up),
                ..textbook
            };
            let stack = self.diagrams_size(l, chart)?;
            if plans + stack.x * stack.y <= ONE_SHEET_SHARE * a1_field_mm2()
                && second_sheet_holds(&sizes, stack)
            {
                return Ok(chart);
            }
        }
        Ok(textbook)
    }

    /// The field a single plan of `kind` has: `VECTOR_PLAN_ROOM`, or on two sheets
    /// `TWO_SHEET_PLAN_ROOM`.
    fn plan_room(&self) -> Result<DVec2, StudyError> {
        Ok(match self.kin_sheets()? {
            KinSheets::One => VECTOR_PLAN_ROOM,
            KinSheets::Two => TWO_SHEET_PLAN_ROOM,
        })
    }

    /// The μ of the plan of `kind` at position `k`: the common one of [`Session::kin_scales`]
    /// (the scene's, when it gives one), which every plan of the kind fits; or, for a position
    /// the scene draws at a μ of its own (`kinematics.own_scale`), the textbook's choice for
    /// that plan alone: the crank pin's vector drawn at least 80 mm, raised until the plan
    /// fits its field (`VECTOR_PLAN_ROOM`, on two sheets `TWO_SHEET_PLAN_ROOM`) — coarser for
    /// a plan near a singular position (the tangent's), finer for one whose images crowd
    /// near an extreme position (the six-bar's 10 and 11 at the seed's μ_v).
    pub fn plan_scale(&self, kind: PlanKind, k: usize) -> Result<Scale, StudyError> {
        self.caches.get::<PlanScales>((kind, k), || {
            let sc = self.kin_scales()?;
            if !self.own_scale_positions(kind)?.contains(&k) {
                return Ok(match kind {
                    PlanKind::Velocity => sc.v,
                    PlanKind::Acceleration => sc.a,
                });
            }
            let m = self.mechanism("the kinematic analysis")?;
            let (v, a) = kinematics::plan_scales(&m.crank, &KinematicsSpec::default())?;
            let start = match kind {
                PlanKind::Velocity => v,
                PlanKind::Acceleration => a,
            };
            let size = largest_plan(&*self.poses()?, &[k], self.w1()?, kind);
            Ok(raised_to_fit(start, self.plan_room()?, size))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether the common plans of `kind` at `mu` (the other kind at the session's μ) fit the
    /// room of their sheet: on two sheets the room each sheet gives them; on one
    /// `VECTOR_PLAN_ROOM` each, `PLANS_AREA_MM2` together, and every drawing of the study
    /// within `ONE_SHEET_SHARE` of an A1 field.
    fn fits_room(s: &Session<'_>, kind: PlanKind, mu: Scale) -> bool {
        let (poses, w1) = (s.poses().expect("poses"), s.w1().expect("ω₁"));
        let sc = s.kin_scales().expect("scales");
        let all: Vec<usize> = match kind {
            PlanKind::Velocity => (0..poses.positions.len()).collect(),
            PlanKind::Acceleration => s.acceleration_positions().expect("positions"),
        };
        let ks = common_plans(&all, &s.own_scale_positions(kind).expect("own"));
        let l = s.scale_l().expect("μ_l");
        let positions = positions_extent(&poses).labelled_size_at(l);
        let (room, area) = match s.kin_sheets().expect("sheets") {
            KinSheets::Two => two_sheet_room(kind, positions.x * positions.y),
            KinSheets::One => (VECTOR_PLAN_ROOM, PLANS_AREA_MM2),
        };
        let (v, a) = match kind {
            PlanKind::Velocity => (mu, sc.a),
            PlanKind::Acceleration => (sc.v, mu),
        };
        let one = s.kin_sheets().expect("sheets") == KinSheets::One;
        let drawn = s.drawn_mm2(v, a).expect("drawn");
        largest_plan(&poses, &ks, w1, kind)(mu).cmple(room).all()
            && plans_area(&poses, &ks, w1, kind, mu) <= area
            && (!one || drawn <= ONE_SHEET_SHARE * a1_field_mm2())
    }

    /// The second sheet's stack under or beside its plans, on the V engine's numbers: its
    /// plans at 3 and 6 (211 × 234 and 218 × 175 mm) leave 2π on 300 mm at 1,4 times the
    /// height (a stack 443 × 308 mm) 16 mm short under them and 71 mm too wide beside them,
    /// and 2π on 240 mm twice as tall (400 × 387 mm) 29 mm too wide; 2π on 240 mm 1,5 times
    /// as tall (366 × 321 mm) stands beside them, as a stack 451 × 257 mm under them; small
    /// plans leave a wide stack room beside them.
    #[test]
    fn the_second_sheet_holds_its_stack_under_or_beside_the_plans() {
        let plans = [DVec2::new(211.2, 233.7), DVec2::new(217.6, 175.2)];
        assert!(!second_sheet_holds(&plans, DVec2::new(442.5, 308.2)));
        assert!(!second_sheet_holds(&plans, DVec2::new(399.5, 386.5)));
        assert!(second_sheet_holds(&plans, DVec2::new(366.0, 321.4)));
        assert!(second_sheet_holds(&plans, DVec2::new(451.0, 257.0)));
        let small = [DVec2::new(100.0, 100.0)];
        assert!(second_sheet_holds(&small, DVec2::new(600.0, 500.0)));
        assert!(!second_sheet_holds(&small, DVec2::new(720.0, 500.0)));
        assert!(second_sheet_holds(&[], DVec2::ZERO));
    }

    /// Every free μ_v and μ_a is the largest round scale the room allows: its common plans
    /// fit the room their sheet gives them and one step finer they would not. The linkage
    /// scenes whose kinematic drawings share one sheet with their tables are at it from the
    /// textbook's start (measured one step finer: the slider-crank's velocity plans at 0,01
    /// take 223 000 mm², past `PLANS_AREA_MM2`, its acceleration plans at 0,4 are 167 mm tall;
    /// the four-bar's at 0,005 and 0,05 are 199 × 178 and 241 × 209 mm; the tangent's at
    /// 0,025 and 10 are 203 and 244 mm tall, past the 150 mm room). The v-engine's (a plan of
    /// positions 314 × 201 mm and the diagrams beside the twelve plans) take two sheets, and
    /// its free μ_v and μ_a are made finer than the textbook's — the velocity plans at 0,05
    /// (the pin's velocity 126 mm), the acceleration plans at 5 — one step finer would not fit.
    #[test]
    fn every_free_plan_scale_is_the_largest_its_room_allows() {
        for name in ["slider-crank", "four-bar", "tangent"] {
            super::super::with_scene(name, |s| {
                assert_eq!(s.kin_sheets().expect("sheets"), KinSheets::One, "{name}");
                let (v, a) = s.textbook_plan_scales().expect("textbook");
                let sc = s.kin_scales().expect("scales");
                assert_eq!((sc.v, sc.a), (v, a), "{name}");
            });
        }
        super::super::with_scene("v-engine", |s| {
            assert_eq!(s.kin_sheets().expect("sheets"), KinSheets::Two);
            let (v, a) = s.textbook_plan_scales().expect("textbook");
            let sc = s.kin_scales().expect("scales");
            assert_eq!((v.value(), a.value()), (0.1, 10.0));
            assert_eq!((sc.v.value(), sc.a.value()), (0.05, 5.0));
        });
        for name in ["slider-crank", "four-bar", "tangent", "v-engine"] {
            super::super::with_scene(name, |s| {
                let sc = s.kin_scales().expect("scales");
                for (kind, mu) in [(PlanKind::Velocity, sc.v), (PlanKind::Acceleration, sc.a)] {
                    assert!(fits_room(s, kind, mu), "{name} {kind:?}");
                    let finer = mu.finer().expect("finer");
                    assert!(
                        !fits_room(s, kind, finer),
                        "{name} {kind:?} at {}",
                        finer.value()
                    );
                }
            });
        }
        // A μ the scene fixes stands on two sheets too.
        super::super::with_scene("six-bar", |s| {
            let sc = s.kin_scales().expect("scales");
            assert_eq!((sc.v.value(), sc.a.value()), (0.026, 0.156));
        });
    }
}
