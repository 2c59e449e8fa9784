//! Plate "Кинематический анализ" (the textbook's sheet 1): the plan of positions, a velocity
//! plan for every position, the acceleration plans, the displacement diagram with its two
//! chord-method derivatives, the hodograph, the analytic table and the error estimates.
//! The scales are the session's ([`Session::kin_scales`]: decided once, each fitted to its
//! field), so the sheet draws the very plans the report reads.

use super::digits;
use super::layout::{keyed, lay_out_in_rows, sheet_name, split_table, table, Block};
use super::BuildError;
use crate::check::Method;
use crate::geom::DVec2;
use crate::linkage::KinPlan;
use crate::plate::{Plate, Sheet, TableBlock};
use crate::scale::{format_fixed, format_sig, Key, Lang, Quantity, Scale};
use crate::study::{KinScales, Kinematics, Session};
use crate::words::{symbols, unit_in, Text};

/// The widest an analytic table may be drawn, mm (the A1 frame's width less margins); its
/// columns are narrowed to 12 mm before any is left out.
const TABLES_WIDTH_MM: f64 = 800.0;

/// The series of the velocity plans and of the acceleration plans: each read in rows.
const VELOCITY: Option<u8> = Some(0);
const ACCELERATION: Option<u8> = Some(1);

/// Blocks in the order a sheet reads them, each with its series ([`lay_out_in_rows`]).
type Run = Vec<(Block, Option<u8>)>;

/// Build the sheets: as many A1 sheets as the views need at the sheet's scales. With
/// `structure` (the scene wants the plan of positions too) the sheet is the textbook's sheet 1:
/// the structural scheme and analysis, the plan of positions with its extreme positions, the
/// plans and the diagrams; what one A1 does not hold goes on a second in reading order
/// (structure, positions and velocity plans; then acceleration plans, diagrams, tables).
pub fn build(session: &Session<'_>, lang: Lang, structure: bool) -> Result<Vec<Plate>, BuildError> {
    let mut plates = sheets(session, lang, structure)?;
    for p in &mut plates {
        super::scale_of_the_mechanism(p);
    }
    Ok(plates)
}

/// The sheets [`build`] lays out, each with the plan's scale in its title block.
fn sheets(session: &Session<'_>, lang: Lang, structure: bool) -> Result<Vec<Plate>, BuildError> {
    let scene = session.scene();
    let sheet = Sheet::default();
    let sc = session.kin_scales()?;
    let a = session.kinematics(&sc)?;
    let caption = format!(
        "{}, {}",
        Text::PlanOfPositions.get(lang),
        sc.l.caption(lang)
    );
    let plan = Block::view(a.plan_figure(), caption, keyed(Key::MechanismScaleL, sc.l));
    let plan: Run = vec![(plan, None)];
    // The structural scheme before the plan, the task's data and the structural analysis
    // after the plans.
    let (scheme, analysis): (Run, Run) = if structure {
        let (scheme, lines) = super::positions::structure(session, lang)?;
        let text = Block::Text {
            lines,
            size_mm: 3.5,
        };
        (vec![(scheme, None)], vec![(text, None)])
    } else {
        (Vec::new(), Vec::new())
    };
    let (drafting, scales) = super::plan_scales::head_lines(session, &a, &sc, lang);
    let verdicts = super::kin_lines::verdict_lines(&crate::kinematics::verdicts(&a.rows()), lang);
    let mut lines = Vec::new();
    let diagrams = diagram_views(&a, lang, &mut lines);
    let plans = Plans {
        a: &a,
        sc: &sc,
        lang,
    };
    let (velocity, acceleration) = (plans.velocity(false), plans.acceleration(false));
    let views = rest_views(&a, lang, &mut lines);
    // The analytic table has a row per position: continued on further sheets when long.
    let analytic: Run = tables(&a, lang)
        .into_iter()
        .flat_map(|t| split_table(&sheet, t, lang))
        .map(|t| (Block::Table(t), None))
        .collect();
    // The rest: the diagrams' views, the text (`head` before the diagrams' lines), the tables.
    let rest_with = |head: Vec<String>| -> Run {
        let text = Block::Text {
            lines: head.into_iter().chain(lines.iter().cloned()).collect(),
            size_mm: 3.5,
        };
        views
            .iter()
            .cloned()
            .chain([(text, None)])
            .chain(analytic.iter().cloned())
            .collect()
    };
    let head = std::iter::once(drafting.clone())
        .chain(scales)
        .chain(verdicts.clone());
    let rest = rest_with(head.collect());
    let title = super::title_block(scene, Text::KinematicAnalysis.get(lang), Some(sc.l), lang);
    let lay = |run: Run| {
        let (blocks, series): (Vec<Block>, Vec<Option<u8>>) = run.into_iter().unzip();
        lay_out_in_rows(sheet, blocks, &series, "kinematics", &title, lang)
    };
    // One sheet when it holds everything: the plan of positions, the diagrams beside it, the
    // plans, the rest (the structural scheme first, or where it finds room).
    let orders = [
        [
            &scheme,
            &plan,
            &diagrams,
            &velocity,
            &acceleration,
            &analysis,
            &rest,
        ],
        [
            &plan,
            &diagrams,
            &velocity,
            &acceleration,
            &scheme,
            &analysis,
            &rest,
        ],
        [
            &plan,
            &scheme,
            &diagrams,
            &velocity,
            &acceleration,
            &analysis,
            &rest,
        ],
    ];
    for order in orders {
        let one: Run = order.into_iter().flatten().cloned().collect();
        let plates = lay(one)?;
        if plates.len() == 1 {
            return Ok(plates);
        }
    }
    // Else the textbook's order over two sheets: what the positions give (the scheme, the
    // plan, the velocity plans), then what is derived (acceleration plans, diagrams, tables);
    // the acceleration plans go on the first when it holds them, the structural analysis
    // when the two are then filled more evenly ([`two_sheets`]). Never a table alone on a
    // sheet: the second always holds the diagrams or the acceleration plans. Each plan then
    // states its μ, and the plans' verdicts follow the acceleration plans, on their sheet
    // (the second sheet, holding no plan, stated them).
    let head: Run = scheme.into_iter().chain(plan).collect();
    let (velocity, mut acceleration) = (plans.velocity(true), plans.acceleration(true));
    if !verdicts.is_empty() {
        let text = Block::Text {
            lines: verdicts,
            size_mm: 3.5,
        };
        acceleration.push((text, None));
    }
    let rest = rest_with(vec![drafting]);
    two_sheets(
        &lay,
        [head, velocity, acceleration, analysis, diagrams, rest],
    )
}

/// The displacement diagram stacked on its two derivatives (a view), with its line of
/// scales and poles added to `lines`.
fn diagram_views(a: &Kinematics, lang: Lang, lines: &mut Vec<String>) -> Run {
    let mut diagrams: Run = Vec::new();
    if let Some(d) = &a.diagrams {
        let w = a.w1.abs();
        let dec = |x: f64| digits::value(x, lang);
        // The second differentiation's chords are drawn on the first derivative's curve: one
        // drawing, one view.
        let stack = d
            .first_figure
            .clone()
            .joined(d.second_figure.translated(d.second_at));
        diagrams.push((
            Block::view(
                stack,
                // The stack's caption names its three diagrams (the S and dS/dφ had none);
                // each H with its unit, so that no list comma stands beside a decimal comma
                // («H₁ = 28, H₂ = 7,5 мм» read as three numbers).
                format!(
                    "S, dS/dφ, d²S/dφ²: H_{{1}} = {} {mm}, H_{{2}} = {} {mm}",
                    dec(d.first.pole_mm),
                    dec(d.second.pole_mm),
                    mm = Text::Millimetre.get(lang)
                ),
                keyed(Key::KinematicsScaleS, d.scales.y),
            ),
            None,
        ));
        lines.push(format!(
            "{} {}: μ_{{S}} = {} {}, μ_{{φ}} = {} {}, H_{{1}} = {} {}; μ_{{v}} = μ_{{S}}·ω_{{1}}/(H_{{1}}·μ_{{φ}}) = {} {}, μ_{{a}} = {} {}",
            Text::DiagramsOfPoint.get(lang),
            d.point,
            dec(d.scales.y.value()),
            Quantity::Length.unit(lang),
            dec(d.scales.x.value()),
            Quantity::Angle.unit(lang),
            dec(d.first.pole_mm),
            Text::Millimetre.get(lang),
            dec(d.first.scale.value() * w),
            Quantity::Velocity.unit(lang),
            dec(d.second.scale.value() * w * w),
            Quantity::Acceleration.unit(lang)
        ));
        if !d.corners.is_empty() {
            lines.push(format!(
                "{} {}: {}",
                Text::Pos.get(lang),
                d.corners.join(", "),
                Text::CornerOfS.get(lang)
            ));
        }
        lines.extend(super::kin_lines::corner_lines(d, lang));
    }
    diagrams
}

/// The velocity and acceleration plans' views of a sheet, in their series: each plan's
/// caption states its μ when `stated` (a plan at its own μ always states it). On two sheets
/// the plans' scales are stated on the sheet that draws them — μ_v under the first velocity
/// plan, μ_a under each acceleration plan — as the sheet's text, which states them on one
/// sheet, goes onto the second.
struct Plans<'a> {
    a: &'a Kinematics,
    sc: &'a KinScales,
    lang: Lang,
}

impl Plans<'_> {
    /// The velocity plans' views, a text in place of a plan the position has none of.
    fn velocity(&self, stated: bool) -> Run {
        let (a, sc, lang) = (self.a, self.sc, self.lang);
        let mut run = Vec::new();
        for (pos, vp) in a.plan.positions.iter().zip(a.velocity_plans()) {
            let c = format!("{} {}", Text::Pos.get(lang), pos.label);
            let first = run.is_empty();
            run.push((
                match vp {
                    Some(vp) => {
                        plan_view(vp, c, (Key::KinematicsScaleV, sc.v), stated && first, lang)
                    }
                    None => Block::Text {
                        lines: vec![
                            c,
                            Text::NoPlan.get(lang).into(),
                            Text::TogglePosition.get(lang).into(),
                        ],
                        size_mm: 3.5,
                    },
                },
                VELOCITY,
            ));
        }
        run
    }

    /// The acceleration plans' views.
    fn acceleration(&self, stated: bool) -> Run {
        let (a, sc, lang) = (self.a, self.sc, self.lang);
        a.acceleration
            .iter()
            .map(|(k, ap)| {
                let label = &a.plan.positions[*k].label;
                let c = format!("{} {label}", Text::AccelerationPlanAt.get(lang));
                let scale = (Key::KinematicsScaleA, sc.a);
                (plan_view(&ap.plan, c, scale, stated, lang), ACCELERATION)
            })
            .collect()
    }
}

/// The rocker's diagram and the hodograph (views, their lines added to `lines`), and the
/// diagrams refused (a line each).
fn rest_views(a: &Kinematics, lang: Lang, lines: &mut Vec<String>) -> Run {
    let mut rest: Run = Vec::new();
    if let Some(r) = &a.rocker {
        let c = format!("ω_{{{l}}}(φ), dω_{{{l}}}/dφ", l = r.link);
        rest.push((Block::view(r.figure.clone(), c, None), None));
        // μ_φ stated once on a sheet: with the displacement diagram's when they share it.
        let phi = match &a.diagrams {
            Some(d) if d.scales.x == r.scale_phi => String::new(),
            _ => format!(", {}", digits::caption(r.scale_phi, lang)),
        };
        // The derivative's scale as the displacement diagram's μ_a is stated: ε is read off
        // dω/dφ's ordinates at μ_ε = |ω₁|·μ_ω/(H_ω·μ_φ).
        let l = r.link;
        lines.push(format!(
            "ω_{{{l}}}(φ): {}{phi}, H_{{ω}} = {} {}; ε_{{{l}}} = |ω_{{1}}|·dω_{{{l}}}/dφ, μ_{{ε}} = |ω_{{1}}|·μ_{{ω}}/(H_{{ω}}·μ_{{φ}}) = {} {}",
            r.scale.caption(lang),
            format_sig(r.derivative.pole_mm, 3, lang),
            Text::Millimetre.get(lang),
            format_sig(r.derivative.scale.value() * a.w1.abs(), 4, lang),
            Quantity::AngularAcceleration.unit(lang)
        ));
    }
    if let Some(crate::study::Hodograph {
        point: name,
        figure: h,
    }) = &a.hodograph
    {
        // Where no velocity plan is drawn (a special position), the curve breaks: said there.
        let gaps: Vec<&str> = (a.plan.positions.iter().zip(a.velocity_plans()))
            .filter(|(_, v)| v.is_none())
            .map(|(p, _)| p.label.as_str())
            .collect();
        let mut c = format!("{} v_{{{}}}", Text::Hodograph.get(lang), name);
        if !gaps.is_empty() {
            c = format!(
                "{c}, {} {}",
                Text::HodographBroken.get(lang),
                gaps.join(", ")
            );
        }
        rest.push((Block::view(h.as_ref().clone(), c, None), None));
        lines.push(format!(
            "{} v_{{{}}}: {}",
            Text::Hodograph.get(lang),
            name,
            h.scale.caption(lang)
        ));
    }
    for r in &a.refusals {
        let (text, phi_deg) = match r {
            crate::kinematics::KinError::NoFullTurn { phi_deg, .. } => (Text::NoDiagrams, phi_deg),
            crate::kinematics::KinError::Leap { phi_deg, .. } => (Text::NoDiagramsLeap, phi_deg),
            _ => continue,
        };
        let line = format!(
            "{} φ_{{1}} = {}",
            text.get(lang),
            super::digits::degrees(phi_deg.to_radians(), lang)
        );
        // The diagrams and the rocker's diagram refused for one reason: one line.
        if !lines.contains(&line) {
            lines.push(line);
        }
    }
    rest
}

/// The blocks over two sheets, `groups` in the textbook's order (the head, the velocity
/// plans, the acceleration plans, the structural analysis, the diagrams, the rest): the
/// first sheet takes the first two groups and the acceleration plans when it holds them (a
/// sheet is filled before the next is begun, and the plans read together); the structural
/// analysis too when it holds it and the two sheets are then filled more evenly; then each
/// table the first sheet holds moves up.
fn two_sheets(
    lay: &dyn Fn(Run) -> Result<Vec<Plate>, BuildError>,
    groups: [Run; 6],
) -> Result<Vec<Plate>, BuildError> {
    let area = |run: &[(Block, Option<u8>)]| -> f64 {
        run.iter()
            .map(|(b, _)| {
                let s = b.size();
                s.x * s.y
            })
            .sum()
    };
    let split = |k: usize| -> (Run, Run) {
        let first = groups[..k].iter().flatten().cloned().collect();
        let second = groups[k..].iter().flatten().cloned().collect();
        (first, second)
    };
    let analysis = groups[3].clone();
    let (mut first, mut second) = split(2);
    for k in 3..=4 {
        let (f, s) = split(k);
        let drawn = s.iter().any(|b| matches!(b.0, Block::Views { .. }));
        // The acceleration plans (k = 3) whenever the first holds them; the analysis only
        // for a more even pair.
        let even = k == 3 || area(&f).min(area(&s)) > area(&first).min(area(&second));
        if drawn && even && lay(f.clone())?.len() == 1 {
            (first, second) = (f, s);
        }
    }
    // The first sheet filled before the second is begun: each table of the second, in their
    // order, moves up when the first holds it (into the band the plans leave free); the
    // drawings and the text that states their scales stay together on the second.
    let mut left: Run = Vec::new();
    for next in second {
        let mut f = first.clone();
        f.push(next.clone());
        if matches!(next.0, Block::Table(_)) && lay(f.clone())?.len() == 1 {
            first = f;
        } else {
            left.push(next);
        }
    }
    let mut plates = lay(first.clone())?;
    if plates.len() > 1 {
        // The first sheet's drawings run onto a further page: the second's go on after them
        // there, not on a page of their own (a page holding the last two velocity plans alone).
        return Ok(renamed(lay(first.into_iter().chain(left).collect())?));
    }
    if !left.is_empty() {
        let mut rest = lay(left.clone())?;
        if rest.len() > 1 {
            // The structural analysis after the drawings and tables, in the room they leave,
            // rather than a table run onto a page of its own.
            let (analysis, others): (Run, Run) =
                left.into_iter().partition(|b| analysis.contains(b));
            let after = lay(others.into_iter().chain(analysis).collect())?;
            if after.len() < rest.len() {
                rest = after;
            }
        }
        plates.extend(rest);
    }
    Ok(renamed(plates))
}

/// The sheets named `kinematics`, `kinematics-2`, … in order.
fn renamed(plates: Vec<Plate>) -> Vec<Plate> {
    plates
        .into_iter()
        .enumerate()
        .map(|(k, p)| Plate {
            name: sheet_name("kinematics", k),
            ..p
        })
        .collect()
}

/// A velocity or acceleration plan's view: at the common μ (`common`, set by the scene key
/// `key`), its caption stating it when `stated`; or at its own, stated in its caption.
fn plan_view(
    plan: &KinPlan,
    caption: String,
    (key, common): (Key, Scale),
    stated: bool,
    lang: Lang,
) -> Block {
    let own = plan.figure.scale;
    let scale = (own == common).then(|| keyed(key, common)).flatten();
    let caption = if own == common && !stated {
        caption
    } else {
        format!("{caption}, {}", own.caption(lang))
    };
    Block::view(plan.figure.clone(), caption, scale).with_label_room()
}

/// A quantity of the error table in the textbook's notation (`ω_{1}`, `V_{B3B1}`), from the
/// key of its first row.
fn symbol_of(rows: &[crate::check::Row], quantity: &str, lang: Lang) -> String {
    rows.iter().find(|r| r.quantity() == quantity).map_or_else(
        || quantity.to_string(),
        |r| symbols::quantity(r.key.symbol, &r.key.subject, lang),
    )
}

/// The analytic table and the error estimates (section 1.6 of the seed), side by side, kept
/// left of the title block.
fn tables(a: &Kinematics, lang: Lang) -> Vec<TableBlock> {
    let size = 2.5;
    let t = &a.table;
    let pos_w = 9.0;
    let avail = TABLES_WIDTH_MM;
    let col_w = ((avail - pos_w) / t.columns.len().max(1) as f64).clamp(12.0, 22.0);
    let shown = (((avail - pos_w) / col_w) as usize).min(t.columns.len());
    let mut columns = vec![(Text::Number.get(lang).to_string(), pos_w)];
    columns.extend(t.columns.iter().take(shown).map(|c| {
        let name = symbols::subscripted(&c.name);
        (format!("{name}, {}", unit_in(&c.unit, lang)), col_w)
    }));
    // Each column's precision from its largest magnitude over the positions; the angles'
    // columns (φ₁, φ₂, φ₄ …) to one precision, that of their largest (45,0 beside 45,00
    // read as two kinds of angle).
    let angle = |c: usize| t.columns[c].unit == "°";
    let values = |keep: &dyn Fn(usize) -> bool| {
        digits::Column::of(t.rows.iter().flat_map(|(_, v)| {
            v.iter()
                .enumerate()
                .filter(|(k, _)| keep(*k))
                .filter_map(|(_, x)| *x)
        }))
    };
    let angles = values(&|k| k < shown && angle(k));
    let precision: Vec<digits::Column> = (0..shown)
        .map(|c| {
            if angle(c) {
                angles
            } else {
                values(&|k| k == c)
            }
        })
        .collect();
    let rows = t
        .rows
        .iter()
        .map(|(label, vals)| {
            std::iter::once(label.clone())
                .chain(
                    vals.iter()
                        .zip(&precision)
                        .map(|(v, c)| v.map_or(digits::NO_VALUE.into(), |x| c.cell(x, lang))),
                )
                .collect()
        })
        .collect();
    let analytic = TableBlock {
        at: DVec2::ZERO,
        title: Text::AnalyticSolution.get(lang).into(),
        columns,
        rows,
        size_mm: size,
    };
    // The displacement is a reading, not a derived quantity: it has no error estimate; the
    // crank's ω₁ and ε₁ are given, not found (the report keeps them for the audit).
    let crank = a.plan.program.crank_link.to_string();
    let given = |r: &crate::check::Row| {
        use crate::check::Symbol::{AngularAcceleration, AngularVelocity};
        matches!(r.key.symbol, AngularVelocity | AngularAcceleration) && r.key.subject == crank
    };
    let read: Vec<_> = a
        .rows()
        .into_iter()
        .filter(|r| r.key.symbol != crate::check::Symbol::Displacement && !given(r))
        .collect();
    let summary = crate::check::Summary::of(&read);
    let method = |m: Method| m.name(lang).to_string();
    // Diagrams first (the textbook's comparison), then by the error as displayed (0.01 %),
    // ties in report order: rounding noise must not reorder the table.
    let shown_pct = |x: f64| (x * 1e4).round() as i64;
    let mut entries: Vec<_> = summary.entries.iter().collect();
    entries.sort_by_key(|e| (e.method == Method::Plan, -shown_pct(e.max_abs_rel)));
    // A diagram's worst error at a corner of S says so: the chords there are rough, the
    // sheet's corner line says why (the six-bar's a_E, 110,76 % at position 6).
    let corners: &[String] = a.diagrams.as_ref().map_or(&[], |d| &d.corners);
    let err_rows: Vec<Vec<String>> = entries
        .into_iter()
        .map(|e| {
            let worst = match &e.worst_position {
                _ if shown_pct(e.max_abs_rel) == 0 => super::digits::NO_VALUE.into(),
                Some(p)
                    if matches!(e.method, Method::DiagramChords | Method::DiagramTangents)
                        && corners.contains(p) =>
                {
                    format!("{p}, {}", Text::AtCorner.get(lang))
                }
                p => p.clone().unwrap_or_default(),
            };
            vec![
                symbol_of(&read, &e.quantity, lang),
                method(e.method),
                format_fixed(e.mean_abs_rel * 100.0, 2, lang),
                format_fixed(e.max_abs_rel * 100.0, 2, lang),
                worst,
            ]
        })
        .collect();
    let errors = table(
        Text::MethodErrors,
        &[
            (Text::Quantity, 24.0),
            (Text::Method, 20.0),
            (Text::MeanError, 16.0),
            (Text::MaxError, 16.0),
            (Text::PosShort, if corners.is_empty() { 10.0 } else { 16.0 }),
        ],
        err_rows,
        size,
        lang,
    );
    vec![analytic, errors]
}
