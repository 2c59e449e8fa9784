//! Plate "План положений": structural scheme and analysis, the plan of positions with its
//! construction, trajectories and extreme positions, θ, H and K.

use super::digits::degrees;
use super::layout::{lay_out, Block, ScaleKey};
use super::BuildError;
use crate::check::is_zero;
use crate::construct::fit::{fit_scale, overflow};
use crate::construct::{Context, Drafting};
use crate::geom::DVec2;
use crate::linkage::{FourBar, OutputCoord, PositionPlan, Relation, Sense, Structure};
use crate::plate::{Plate, Sheet};
use crate::scale::{format_fixed, Key, Lang, Quantity, Scale};
use crate::study::Session;
use crate::words::{plain, Text};
use std::f64::consts::{PI, TAU};

/// The room of the structural scheme, mm: wide enough for a long mechanism's scheme with its
/// decomposition beside it at a scale its crank reads at (the six-bar, whose slider runs 1 m
/// from its crank: 285 mm at μ_l = 0,01 m/mm; in 268 mm it took 0,02, the crank 5 mm long and
/// its link numbers strayed from their links). Where the plan of positions does not fit
/// beside it, the sheet lays the plan under it.
const SCHEME_ROOM: DVec2 = DVec2::new(290.0, 274.0);
/// Preferred size of the structural scheme, mm.
const SCHEME_MM: f64 = 170.0;

/// Build the sheet: the structural scheme, the plan of positions and the analysis text.
pub fn build(session: &Session<'_>, lang: Lang) -> Result<Vec<Plate>, BuildError> {
    let scene = session.scene();
    // μ_l as the session decided it for every drawing of the plan (and the report).
    let scale = session.scale_l()?;
    let plan = session.positions(scale)?;
    let plan_caption = format!(
        "{}, {}",
        Text::PlanOfMechanism.get(lang),
        scale.caption(lang)
    );
    let (scheme, mut lines) = structure(session, lang)?;
    lines.push(String::new());
    lines.push(super::drafting_line(
        session.drafting(),
        super::Errs::Rounding,
        lang,
    ));
    let blocks = vec![
        scheme,
        Block::view(
            plan.figure.clone(),
            plan_caption,
            Some(ScaleKey {
                key: Key::MechanismScaleL,
                scale,
            }),
        ),
        Block::Text {
            lines,
            size_mm: 3.5,
        },
    ];
    let title = super::title_block(scene, Text::PlanOfPositions.get(lang), Some(scale), lang);
    lay_out(Sheet::default(), blocks, "positions", &title, lang)
}

/// What the plan of positions' sheet adds to the plan: the structural scheme (its Assur
/// groups apart) and the lines of the task's data ([`data_lines`]), the structural analysis,
/// the extreme positions, θ, H and K.
/// The kinematic sheet takes them when the scene wants both (the textbook's sheet 1).
pub(super) fn structure(
    session: &Session<'_>,
    lang: Lang,
) -> Result<(Block, Vec<String>), BuildError> {
    let m = session.mechanism("the position diagram")?;
    let scale = session.scale_l()?;
    let plan = session.positions(scale)?;
    let st = Structure::analyse(m);
    let mut lines = data_lines(m, lang);
    lines.push(String::new());
    lines.extend(structure_lines(&st, m, lang));
    lines.extend(grashof_lines(m, &plan, lang));
    let extremes = extreme_lines(&plan, lang);
    if !extremes.is_empty() {
        lines.push(String::new());
        lines.extend(extremes);
    }
    Ok((scheme_block(&plan, Some(&st), lang)?, lines))
}

/// The kinematic scheme of the session's mechanism as a task gives it: the mechanism whole
/// with its link numbers, not yet split into its Assur groups.
pub(super) fn kinematic_scheme(session: &Session<'_>, lang: Lang) -> Result<Block, BuildError> {
    let scale = session.scale_l()?;
    let plan = session.positions(scale)?;
    scheme_block(&plan, None, lang)
}

/// The structural scheme (the kinematic scheme without `st`) at the finest round scale
/// whose drawing fits its room.
fn scheme_block(
    plan: &PositionPlan,
    st: Option<&Structure>,
    lang: Lang,
) -> Result<Block, BuildError> {
    let ctx = Context::for_model_size(SCHEME_MM, Drafting::EXACT)?;
    // The mechanism's extent in the position the scheme shows, m (not the plan's: the
    // tangent's block runs 1,5 m along its guide over the turn, 0,25 m in that position).
    let mu = plan.figure.scale;
    let extent = plan
        .scheme(None, mu, &ctx)
        .bounds()
        .map_or(1.0, |(lo, hi)| (hi - lo).max_element())
        * mu.value();
    let scheme = |s: Scale| plan.scheme(st, s, &ctx);
    let start =
        Scale::round_for(extent, SCHEME_MM, Quantity::Length).ok_or(BuildError::NoScale(extent))?;
    // The scheme is a drawing of position 1 (no construction): drawn at each trial μ.
    let s_scale = fit_scale(start, |s| {
        let size = scheme(s).bounds().map_or(DVec2::ZERO, |(lo, hi)| hi - lo);
        overflow(size, SCHEME_ROOM)
    })
    .ok_or(BuildError::NoScale(extent))?;
    let name = match st {
        Some(_) => Text::StructuralScheme,
        None => Text::KinematicScheme,
    };
    let caption = format!("{}, {}", name.get(lang), s_scale.caption(lang));
    // The caption under the grounds of the fixed pivots, not over their hatching.
    Ok(Block::view(scheme(s_scale), caption, None))
}

/// A line of lengths in the data block holds at most this many characters as printed (the
/// width of the structural analysis' lines).
const DATA_LINE_CHARS: usize = 64;

/// The task's data as the sheet prints it (label markup): «Исходные данные», the lengths on
/// as few lines as [`DATA_LINE_CHARS`] allows, ω₁ and the crank's sense of rotation (drawn by
/// the arc arrow at its pivot on the scheme), and the frame's guides through fixed points.
fn data_lines(m: &crate::linkage::Mechanism, lang: Lang) -> Vec<String> {
    // The mechanism's data rows: its lengths, then ω₁.
    let rows = super::data::mechanism(m, lang);
    let written: Vec<String> = rows.iter().map(|r| super::data::written(r, lang)).collect();
    let (omega, lengths) = written
        .split_last()
        .map_or((None, &written[..]), |(o, l)| (Some(o), l));
    let mut v = vec![Text::Data.get(lang).to_string()];
    // As few lines as the width allows, the lengths shared evenly between them.
    let printed: usize = lengths.iter().map(|l| plain(l).chars().count() + 2).sum();
    let lines = printed.div_ceil(DATA_LINE_CHARS).max(1);
    v.extend(
        lengths
            .chunks(lengths.len().div_ceil(lines).max(1))
            .map(|c| c.join(", ")),
    );
    let sense = match m.crank.sense {
        Sense::CounterClockwise => Text::CrankCounterClockwise,
        Sense::Clockwise => Text::CrankClockwise,
    };
    v.extend(omega.map(|o| format!("{o}, {}", sense.get(lang))));
    let and = format!(" {} ", Text::And.get(lang));
    v.extend(
        super::data::guides_through(m)
            .into_iter()
            .map(|(joint, on)| {
                Text::GuideThrough
                    .get(lang)
                    .replace("{j}", joint)
                    .replace("{list}", &on.join(&and))
            }),
    );
    v
}

/// The structural analysis as text lines (label markup).
fn structure_lines(st: &Structure, m: &crate::linkage::Mechanism, lang: Lang) -> Vec<String> {
    let mut v = vec![Text::StructuralAnalysis.get(lang).to_string()];
    v.push(format!("n = {}, p_5 = {}, p_4 = {}", st.n, st.p5, st.p4));
    v.push(format!(
        "W = 3n − 2p_5 − p_4 = 3·{} − 2·{} − {} = {}",
        st.n,
        st.p5,
        st.p4,
        minus(st.w)
    ));
    for r in &m.redundant {
        v.push(format!(
            "{} {}: p_5 = {}, W = 3·{} − 2·{} − {} = {}",
            Text::WithPair.get(lang),
            r.name,
            st.p5_all,
            st.n,
            st.p5_all,
            st.p4,
            minus(st.w_all)
        ));
        v.push(format!(
            "{} — {}: {}",
            r.name,
            Text::RedundantPair.get(lang),
            crate::words::redundant_reason(&r.reason, lang)
        ));
    }
    v.push(format!(
        "{}: {}",
        Text::StructureFormula.get(lang),
        st.formula()
    ));
    for g in &st.groups {
        let letters = g.kind.letters_in(lang);
        v.push(crate::words::assur_group(
            g.links,
            (g.kind.number(), &letters),
            lang,
        ));
    }
    v.push(crate::words::mechanism_class(st.class, lang));
    v
}

/// Grashof's condition of each hinged four-bar of `m` as a student writes it: the condition,
/// the sums with the lengths and the verdict; with the equality, the change point and the
/// positions of `plan` where it falls (the velocity plan refused there).
fn grashof_lines(m: &crate::linkage::Mechanism, plan: &PositionPlan, lang: Lang) -> Vec<String> {
    let mut v = Vec::new();
    for f in FourBar::of(m) {
        let name = |b: &crate::linkage::Bar| {
            let plain: String = b
                .ends
                .concat()
                .chars()
                .filter(|c| !"_{}".contains(*c))
                .collect();
            format!("l_{{{plain}}}")
        };
        let mm = |x: f64| super::digits::value(x * 1e3, lang);
        let ([s, l], [p, q]) = f.ranked();
        let sum = |i: usize, j: usize| {
            let (a, b) = (&f.bars[i], &f.bars[j]);
            format!(
                "{} + {} = {} + {} = {}",
                name(a),
                name(b),
                mm(a.length),
                mm(b.length),
                super::digits::mm(a.length + b.length, lang)
            )
        };
        let [crank, coupler, rocker, _] = &f.bars;
        let points = [
            &crank.ends[0],
            &crank.ends[1],
            &coupler.ends[1],
            &rocker.ends[0],
        ]
        .map(String::as_str);
        v.push(format!(
            "{} ({}): l_{{min}} + l_{{max}} ≤ l′ + l″",
            Text::GrashofCondition.get(lang),
            points.join("–")
        ));
        let relation = f.relation();
        let sign = match relation {
            Relation::Less => "<",
            Relation::Equal => "=",
            Relation::Greater => ">",
        };
        let verdict = if f.crank_exists() {
            Text::CrankExists
        } else {
            Text::NoCrank
        };
        v.push(format!("{} {sign} {}", sum(s, l), sum(p, q)));
        v.push(verdict.get(lang).to_string());
        if relation == Relation::Equal {
            let at: Vec<&str> = plan
                .positions
                .iter()
                .filter(|x| x.pose.toggle.as_ref().is_some_and(|t| t.group == f.group))
                .map(|x| x.label.as_str())
                .collect();
            v.push(Text::ChangePoint.get(lang).to_string());
            if !at.is_empty() {
                v.push(format!(
                    "{} {}: {}",
                    Text::Pos.get(lang),
                    at.join(", "),
                    Text::NoVelocityPlanThere.get(lang)
                ));
            }
        }
    }
    v
}

fn minus(w: i32) -> String {
    if w < 0 {
        format!("−{}", -w)
    } else {
        w.to_string()
    }
}

/// Extreme positions, θ, ψ, H, K as text lines.
fn extreme_lines(plan: &PositionPlan, lang: Lang) -> Vec<String> {
    let Some(ex) = &plan.extremes else {
        return Vec::new();
    };
    let label = |phi: f64| {
        plan.positions
            .iter()
            .find(|p| (p.phi - phi).abs() < 1e-9)
            .map_or_else(String::new, |p| p.label.clone())
    };
    let deg = |a: f64| degrees(a.rem_euclid(TAU), lang);
    let mut v = vec![format!(
        "{}: {} (φ_1 = {}), {} (φ_1 = {})",
        Text::ExtremePositions.get(lang),
        label(ex.phi_start),
        deg(ex.phi_start),
        label(ex.phi_other),
        deg(ex.phi_other)
    )];
    // Strokes of equal turns (θ = 0, an engine's central slider-crank): 180°, θ = 0°, K = 1,
    // no digits that say nothing; which half is working is said by its ends and its rule.
    let even = is_zero(ex.theta, PI);
    let (start, other) = (label(ex.phi_start), label(ex.phi_other));
    let why = if ex.from_outer {
        format!(" ({})", Text::FromOuterDeadCentre.get(lang))
    } else if even {
        String::new()
    } else {
        format!(" ({})", Text::SlowerStroke.get(lang))
    };
    // An output that reaches an extreme twice a turn has no working stroke and return of two
    // halves: the line would contradict the one that says θ and K are not defined.
    if ex.ratio_defined() {
        v.push(format!(
            "{} {start} → {other}{why}: {}, {} — {}",
            Text::WorkingStroke.get(lang),
            degrees(ex.work_travel, lang),
            Text::Return.get(lang),
            degrees(TAU - ex.work_travel, lang)
        ));
    }
    for r in &ex.ranges {
        match r.coord {
            OutputCoord::Rocker(l) => v.push(format!(
                "{} {l}: {} = {}",
                Text::SwingOfLink.get(lang),
                // The swing is ψ; where it is θ as well (the shaper's slotted lever, square
                // to the crank at both extremes) it is said so, as seed 000 names it θ.
                if ex.theta_is_swing(r) {
                    "ψ = θ"
                } else {
                    "ψ"
                },
                degrees(r.max - r.min, lang)
            )),
            OutputCoord::Slider(i, _) => v.push(format!(
                "{} {}: H = {}",
                Text::StrokeOfPoint.get(lang),
                plan.point_name(i),
                super::digits::mm(r.max - r.min, lang)
            )),
        }
        // An output that stands more than twice a turn (the six-bar's slider reaches its
        // end, comes back and reaches it again): every other stop, with its position.
        if !r.stops.is_empty() {
            let v_of = match r.coord {
                OutputCoord::Rocker(l) => format!("ω_{{{l}}}"),
                OutputCoord::Slider(i, _) => format!("v_{{{}}}", plan.point_name(i)),
            };
            // A stop at the value of an extreme is that extreme position reached again.
            let again = |q: f64| {
                let phi = r.extreme_at(q)?;
                Some(Text::SameExtremeAs.get(lang).replace("{p}", &label(phi)))
            };
            let list: Vec<String> = r
                .stops
                .iter()
                .map(|&(phi, q)| {
                    let at = match label(phi) {
                        l if l.is_empty() => format!("φ_1 = {}", deg(phi)),
                        l => format!("{l}, φ_1 = {}", deg(phi)),
                    };
                    match again(q) {
                        Some(w) => format!("{at} ({w})"),
                        None => at,
                    }
                })
                .collect();
            v.push(
                Text::AlsoStands
                    .get(lang)
                    .replace("{v}", &v_of)
                    .replace("{list}", &list.join(", ")),
            );
        }
    }
    if !ex.ratio_defined() {
        v.push(Text::NoTimeRatio.get(lang).to_string());
        return v;
    }
    // θ stated once: as the rocker's swing when it is the swing, else beside K.
    let stated = ex.ranges.iter().any(|r| ex.theta_is_swing(r));
    let k = format!(
        "K = (180° + θ)/(180° − θ) = {}",
        format_fixed(ex.k, if even { 0 } else { 3 }, lang)
    );
    v.push(if stated {
        k
    } else {
        format!("θ = {}, {k}", degrees(ex.theta, lang))
    });
    v
}
