//! The structural and kinematic analysis: mobility by Chebyshev's formula, the Assur groups
//! and the structure formula; the plan of positions with the stroke, θ and K; the velocity
//! and acceleration plans (each group's two vector equations, worked with numbers at one
//! position, the Coriolis term included); the diagrams by the method of chords; the tables
//! of the seed's shapes and the comparison with the analytic twin.

use super::markup::{frac, inline, label, num, sym, text, unit, Align};
use super::rows::{fmt, numbers, values_and_errors, Column, DIGITS};
use super::{NoteError, Writer};
use crate::check::{is_zero, Method, Row, Symbol};
use crate::linkage::{DyadKind, GroupInfo, OutputCoord, Structure};
use crate::scale::Lang;
use crate::scene::PlateKind;
use crate::sheets::captions::{quantity, subscripted, unit_in, Meaning, NoteText as T, Text as S};
use crate::sheets::data::plain;

/// The structural analysis.
pub(super) fn structure(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let m = w.session.mechanism("the explanatory note")?;
    let s = Structure::analyse(m);
    let lang = w.lang;
    w.heading(1, T::StructureAndKinematics);
    w.heading(2, S::StructuralAnalysis);
    let redundant = s.pairs.iter().filter(|p| p.redundant).count() as u32;
    let n = |x: i64| num(x as f64, 6, lang);
    let chebyshev = |p5: u32, w_: i32| {
        format!(
            "{} = 3 {} - 2 {} - {} = 3 dot {} - 2 dot {} - {} = {}",
            sym("W"),
            sym("n"),
            sym("p_{5}"),
            sym("p_{4}"),
            n(s.n as i64),
            n(p5 as i64),
            n(s.p4 as i64),
            n(w_ as i64)
        )
    };
    w.doc.par(&[
        text(w.word(T::MobilityChebyshev)),
        text(&format!("n = {}, p₅ = {}, p₄ = {}:", s.n, s.p5, s.p4)),
    ]);
    w.formula(&chebyshev(s.p5, s.w));
    w.explain(&[
        ("W", w.word(Meaning::Mobility), ""),
        ("n", w.word(Meaning::MovingLinks), ""),
        ("p_{5}", w.word(Meaning::LowerPairs), ""),
        ("p_{4}", w.word(Meaning::HigherPairs), ""),
    ]);
    if redundant > 0 {
        let names: Vec<String> = s
            .pairs
            .iter()
            .filter(|p| p.redundant)
            .map(|p| p.name.clone())
            .collect();
        w.doc.par(&[label(&format!(
            "{} {}:",
            w.word(T::WithRedundantPairs),
            names.join(", ")
        ))]);
        w.formula(&chebyshev(s.p5_all, s.w_all));
        w.doc.say(w.word(T::RedundantPairExplained));
    }
    w.doc.say(w.word(T::AssurGroups));
    let header = [
        text(w.word(S::Group)),
        text(w.word(T::KindWord)),
        text(w.word(T::Pairs)),
        text(w.word(T::GroupMobility)),
    ];
    let mut rows = vec![vec![
        text(&format!("I (0, {})", s.crank_link)),
        text(w.word(S::DrivingLink)),
        label(&s.pairs[0].name),
        text("W = 3·1 − 2·1 = 1"),
    ]];
    for g in &s.groups {
        let kind = format!(
            "{} {} ({})",
            w.word(T::KindWord),
            g.kind.number(),
            if lang == Lang::En {
                g.kind.letters()
            } else {
                g.kind.letters_ru()
            }
        );
        let pairs: Vec<String> = g
            .pairs
            .iter()
            .map(|p| {
                format!(
                    "{} ({}–{}, {})",
                    p.name,
                    p.links[0],
                    p.links[1],
                    if p.prismatic {
                        w.word(T::Prismatic)
                    } else {
                        w.word(T::Revolute)
                    }
                )
            })
            .collect();
        rows.push(vec![
            text(&format!("II ({}, {})", g.links[0], g.links[1])),
            text(&kind),
            label(&pairs.join("; ")),
            text("W = 3·2 − 2·3 = 0"),
        ]);
    }
    let caption = w.word(T::GroupsTable);
    w.doc.table(
        caption,
        &[Align::Left, Align::Left, Align::Left, Align::Centre],
        &header,
        &rows,
    );
    w.doc.par(&[
        text(w.word(S::StructureFormula)),
        text(&s.formula()),
        text(&format!("; {} {}.", w.word(T::ClassOfMechanism), s.class)),
    ]);
    Ok(())
}

/// A point of link `link` as the plans name it: `B_{3}`; a point of one link keeps its name.
fn on(name: &str, link: u32, shared: bool) -> String {
    let plain = plain(name);
    if shared {
        format!("{}_{{{}{link}}}", &plain[..1], &plain[1..])
    } else {
        name.to_string()
    }
}

/// How the point of an equation moves relative to its reference point, which decides the
/// parts its relative acceleration splits into.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Relative {
    /// Both on one turning link: normal and tangential parts.
    Turn,
    /// Sliding along a moving link: Coriolis and relative parts.
    Slide,
    /// Sliding along the frame's guide: the relative part alone.
    SlideOnFrame,
}

/// One vector equation of a velocity plan: the point, the point it is referred to (plain
/// names, `B3`, `B1`), the line its relative term lies on or across (label markup), and how
/// that term moves.
struct Equation {
    point: String,
    reference: String,
    line: String,
    relative: Relative,
}

impl Equation {
    fn new(point: &str, reference: &str, line: String, relative: Relative) -> Self {
        Self {
            point: plain(point),
            reference: plain(reference),
            line,
            relative,
        }
    }

    /// `V_{B3} = V_{B1} + V_{B3B1}`.
    fn velocity(&self) -> String {
        let (p, r) = (&self.point, &self.reference);
        format!("V_{{{p}}} = V_{{{r}}} + V_{{{p}{r}}}")
    }

    /// The unknown term's direction: `V_{B3B1} ∥ CB`, `V_{B3C} ⊥ CB`.
    fn direction(&self) -> String {
        let sign = match self.relative {
            Relative::Turn => "⊥",
            Relative::Slide | Relative::SlideOnFrame => "∥",
        };
        format!(
            "V_{{{}{}}} {sign} {}",
            self.point, self.reference, self.line
        )
    }
}

/// The two vector equations of a group's velocity plan.
fn velocity_equations(g: &GroupInfo, lang: Lang) -> Vec<Equation> {
    let [p0, p1, p2] = &g.pairs;
    let [_, j] = g.links;
    let along = |link: u32| format!("{} {link}", T::AlongGuideOf.get(lang));
    let slide = |link: u32| match link {
        0 => Relative::SlideOnFrame,
        _ => Relative::Slide,
    };
    let turn = Relative::Turn;
    match g.kind {
        DyadKind::Rrr => {
            let (a, joint, b) = (&p0.name, &p1.name, &p2.name);
            vec![
                Equation::new(joint, a, format!("{a}{joint}"), turn),
                Equation::new(joint, b, format!("{b}{joint}"), turn),
            ]
        }
        DyadKind::Rrp => {
            let (a, joint) = (&p0.name, &p1.name);
            let guide = on(joint, p2.links[1], true);
            vec![
                Equation::new(joint, a, format!("{a}{joint}"), turn),
                Equation::new(joint, &guide, along(p2.links[1]), slide(p2.links[1])),
            ]
        }
        DyadKind::Rpr => {
            let (a, c) = (&p0.name, &p2.name);
            let (aj, ao) = (on(a, j, true), on(a, p0.links[0], true));
            vec![
                Equation::new(&aj, &ao, format!("{c}{a}"), slide(j)),
                Equation::new(&aj, c, format!("{c}{a}"), turn),
            ]
        }
        DyadKind::Prp => {
            let joint = &p1.name;
            let (gi, gj) = (on(joint, p0.links[0], true), on(joint, p2.links[1], true));
            vec![
                Equation::new(joint, &gi, along(p0.links[0]), slide(p0.links[0])),
                Equation::new(joint, &gj, along(p2.links[1]), slide(p2.links[1])),
            ]
        }
        DyadKind::Rpp => {
            let a = &p0.name;
            let (aj, ao) = (on(a, j, true), on(a, p0.links[0], true));
            let g0 = on(a, p2.links[1], true);
            vec![
                Equation::new(&aj, &ao, along(j), slide(j)),
                Equation::new(&aj, &g0, along(p2.links[1]), slide(p2.links[1])),
            ]
        }
    }
}

/// The acceleration's counterpart of a velocity equation: its relative term split into its
/// normal and tangential parts (one turning link), its Coriolis and relative parts (a slide
/// along a moving link) or its relative part alone (a slide along the frame).
fn acceleration_equation(e: &Equation) -> String {
    let (p, r) = (&e.point, &e.reference);
    let sub = format!("{{{p}{r}}}");
    let relative = match e.relative {
        Relative::Turn => format!("a^{{n}}_{sub} + a^{{τ}}_{sub}"),
        Relative::Slide => format!("a^{{k}}_{sub} + a^{{r}}_{sub}"),
        Relative::SlideOnFrame => format!("a^{{r}}_{sub}"),
    };
    format!("a_{{{p}}} = a_{{{r}}} + {relative}")
}

/// The worked position: the first position with an acceleration plan, else the first one.
fn worked_position(rows: &[Row]) -> Option<String> {
    rows.iter()
        .find(|r| r.method == Method::Plan && r.key.symbol == Symbol::Acceleration)
        .or_else(|| rows.iter().find(|r| r.method == Method::Plan))
        .and_then(|r| r.position())
}

/// The segment of the plan a velocity or acceleration is drawn as: `p b_{3}` (from the
/// pole) or `b_{1} b_{3}` (relative).
fn segment(pole: &str, subject: &str) -> String {
    let point = |p: &str| {
        let mut c = p.chars();
        let first = c
            .next()
            .map(|f| f.to_lowercase().to_string())
            .unwrap_or_default();
        let rest: String = c.collect();
        if rest.is_empty() {
            first
        } else {
            format!("{first}_{{{rest}}}")
        }
    };
    match subject.split_once('_') {
        Some((x, y)) => format!("{}{}", point(y), point(x)),
        None => format!("{pole}{}", point(subject)),
    }
}

/// The quantities of `symbol` read off the plans.
fn plan_quantities(rows: &[Row], symbol: Symbol) -> Vec<(String, Method)> {
    super::rows::quantities(rows, |r| r.method == Method::Plan && r.key.symbol == symbol)
}

/// The plans' values of `symbol` by position and their differences from the twin, as the
/// two tables captioned `captions`.
fn plan_tables(w: &mut Writer<'_, '_>, symbol: Symbol, captions: (T, T)) {
    let quantities = plan_quantities(&w.report.rows, symbol);
    let captions = (w.word(captions.0), w.word(captions.1));
    values_and_errors(w, captions, &quantities);
}

/// The crank's pin, whose velocity or acceleration opens its plan and sets its scale.
struct CrankPin<'a> {
    /// The pin's name (`B`).
    name: &'a str,
    /// The crank's length symbol (`l_{AB}`).
    crank: &'a str,
    /// |ω₁|, rad/s.
    w1: f64,
    /// l, m.
    length: f64,
}

/// The plan a [`CrankPin`] opens.
#[derive(Clone, Copy)]
enum Plan {
    Velocity,
    Acceleration,
}

impl CrankPin<'_> {
    /// `V_B = ω₁ l_AB = … m/s` (`a_B = ω₁² l_AB`, the crank turning uniformly), then the
    /// plan's scale from the pin's vector drawn from the pole: `μ = V_B/pb = …`.
    fn worked(&self, w: &mut Writer<'_, '_>, plan: Plan, scale: crate::scale::Scale) {
        let lang = w.lang;
        let (letter, power, si, words, mu, pole) = match plan {
            Plan::Velocity => (
                "V",
                "",
                "m/s",
                (T::CrankPinVelocity, T::VelocityScale),
                "μ_{v}",
                "p",
            ),
            Plan::Acceleration => (
                "a",
                "^2",
                "m/s^2",
                (T::CrankPinAcceleration, T::AccelerationScale),
                "μ_{a}",
                "π",
            ),
        };
        let value = match plan {
            Plan::Velocity => self.w1 * self.length,
            Plan::Acceleration => self.w1 * self.w1 * self.length,
        };
        let pin = sym(&format!("{letter}_{{{}}}", self.name));
        w.doc.par(&[text(w.word(words.0))]);
        w.formula(&format!(
            "{pin} = {}{power} {} = {}{power} dot {} = {}{}",
            sym("ω_{1}"),
            sym(self.crank),
            num(self.w1, 5, lang),
            num(self.length, 5, lang),
            num(value, 5, lang),
            unit(&unit_in(si, lang))
        ));
        w.doc.par(&[text(w.word(words.1))]);
        w.formula(&format!(
            "{} = {} = {} = {}{}",
            sym(mu),
            frac(&pin, &sym(&format!("{pole}{}", self.name.to_lowercase()))),
            frac(&num(value, 5, lang), &num(scale.to_mm(value), 4, lang)),
            num(scale.value(), 4, lang),
            unit(scale.quantity.unit(lang))
        ));
    }
}

/// The kinematic analysis.
pub(super) fn kinematics(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let lang = w.lang;
    let sc = w.session.kin_scales()?;
    let kin = w.session.kinematics(&sc)?;
    let m = w.session.mechanism("the explanatory note")?;
    let s = Structure::analyse(m);

    // The plan of positions.
    w.heading(2, S::PlanOfPositions);
    let l = sc.l.value();
    // The points' names inside the length's subscript without their own markup: l_{O1A}.
    let (centre, pin) = (plain(&m.crank.centre), plain(&m.crank.pin));
    let crank = format!("l_{{{centre}{pin}}}");
    w.doc.par(&[text(w.word(T::LengthScale))]);
    w.formula(&format!(
        "{} = {} = {} = {}{}",
        sym("μ_{l}"),
        frac(
            &sym(&crank),
            &sym(&format!("{}{}", m.crank.centre, m.crank.pin))
        ),
        frac(
            &format!(
                "{}{}",
                num(m.crank.length, 5, lang),
                unit(w.word(T::MetreUnit))
            ),
            &format!(
                "{}{}",
                num(m.crank.length / l, 4, lang),
                unit(w.word(T::MmUnit))
            )
        ),
        num(l, 4, lang),
        unit(sc.l.quantity.unit(lang))
    ));
    w.doc.say(w.word(T::PositionsConstruction));
    if let Some(ex) = &kin.plan.extremes {
        let theta = ex.theta.to_degrees();
        // Every output's stroke: a rocker's swing ψ, a slider's travel H.
        let strokes: Vec<String> = ex
            .ranges
            .iter()
            .map(|r| {
                let travel = (r.max - r.min).abs();
                let (symbol, value, u) = match r.coord {
                    OutputCoord::Rocker(link) => {
                        (format!("ψ_{{{link}}}"), travel.to_degrees(), "°")
                    }
                    OutputCoord::Slider(..) => ("H".to_string(), travel, w.word(T::MetreUnit)),
                };
                format!("{} = {}{}", sym(&symbol), num(value, 5, lang), unit(u))
            })
            .collect();
        w.doc
            .par(&[text(w.word(T::StrokeIs)), inline(&strokes.join(", "))]);
        w.doc.par(&[text(w.word(T::ThetaAndK))]);
        w.formula(&format!(
            "{} = {} = {} = {}",
            sym("K"),
            frac("180° + θ", "180° - θ"),
            frac(
                &format!("180° + {}°", num(theta, 5, lang)),
                &format!("180° - {}°", num(theta, 5, lang))
            ),
            num(ex.k, 5, lang)
        ));
    }
    let plan = S::PlanOfPositions.get(lang);
    w.figures(
        KINEMATICS,
        |own| own.starts_with(plan),
        |own| own.to_string(),
    );

    // The velocity plans.
    w.heading(2, T::VelocityPlans);
    let at = worked_position(&w.report.rows);
    let w1 = kin.w1.abs();
    let pin = CrankPin {
        name: &m.crank.pin,
        crank: &crank,
        w1,
        length: m.crank.length,
    };
    pin.worked(w, Plan::Velocity, sc.v);
    w.doc.say(w.word(T::VectorEquations));
    for g in &s.groups {
        w.doc.par(&[text(&format!(
            "{} ({}, {}):",
            w.word(S::Group),
            g.links[0],
            g.links[1]
        ))]);
        for e in velocity_equations(g, lang) {
            w.doc
                .par(&[label(&e.velocity()), text("—"), label(&e.direction())]);
        }
    }
    if let Some(p) = &at {
        worked(w, p, Symbol::Velocity, "p", sc.v)?;
    }
    plan_tables(w, Symbol::Velocity, (T::VelocitiesTable, T::VelocityErrors));
    let captions = (T::AngularVelocitiesTable, T::AngularVelocityErrors);
    plan_tables(w, Symbol::AngularVelocity, captions);
    let worked_plan = at.as_ref().map(|p| format!("{} {p}", S::Pos.get(lang)));
    w.figures(
        KINEMATICS,
        |own| Some(own) == worked_plan.as_deref(),
        |own| format!("{}, {}", T::VelocityPlanWord.get(lang), own.to_lowercase()),
    );

    // The acceleration plans.
    if !plan_quantities(&w.report.rows, Symbol::Acceleration).is_empty() {
        w.heading(2, T::AccelerationPlans);
        pin.worked(w, Plan::Acceleration, sc.a);
        w.doc.say(w.word(T::AccelerationEquations));
        for g in &s.groups {
            for e in velocity_equations(g, lang) {
                w.doc.par(&[label(&acceleration_equation(&e))]);
            }
        }
        if let Some(p) = &at {
            coriolis(w, p, &s)?;
            worked(w, p, Symbol::Acceleration, "π", sc.a)?;
        }
        let captions = (T::AccelerationsTable, T::AccelerationErrors);
        plan_tables(w, Symbol::Acceleration, captions);
        let captions = (T::AngularAccelerationsTable, T::AngularAccelerationErrors);
        plan_tables(w, Symbol::AngularAcceleration, captions);
        // Which links turn faster, which slower (seed 001 l. 686–689).
        let verdicts = crate::kinematics::verdicts(&w.report.rows);
        if !verdicts.is_empty() {
            w.doc.say(w.word(T::VerdictIntro));
            for line in crate::sheets::verdict_lines(&verdicts, lang) {
                w.doc.say(&line);
            }
        }
        let word = S::AccelerationPlanAt.get(lang);
        w.figures(
            KINEMATICS,
            |own| own.starts_with(word),
            |own| own.to_string(),
        );
    }

    // The diagrams.
    let chords = super::rows::quantities(&w.report.rows, |r| r.method.is_diagram());
    if let Some(d) = &kin.diagrams {
        w.heading(2, T::KinematicDiagrams);
        w.doc.say(w.word(T::ChordMethod));
        let (mu_s, mu_phi) = (d.scales.y.value(), d.scales.x.value());
        let (h1, h2) = (d.first.pole_mm, d.second.pole_mm);
        w.formula(&format!(
            "{} = {} = {} = {}, quad {} = {} = {} = {}",
            sym("μ_{S′}"),
            frac(&sym("μ_{S}"), &format!("{} {}", sym("μ_{φ}"), sym("H_{1}"))),
            frac(
                &num(mu_s, 4, lang),
                &format!("{} dot {}", num(mu_phi, 4, lang), num(h1, 4, lang))
            ),
            num(d.first.scale.value(), 4, lang),
            sym("μ_{S″}"),
            frac(
                &sym("μ_{S′}"),
                &format!("{} {}", sym("μ_{φ}"), sym("H_{2}"))
            ),
            frac(
                &num(d.first.scale.value(), 4, lang),
                &format!("{} dot {}", num(mu_phi, 4, lang), num(h2, 4, lang))
            ),
            num(d.second.scale.value(), 4, lang),
        ));
        w.doc.say(w.word(T::DiagramValues));
        diagram_table(w, d, kin.w1.abs(), &chords);
        // Every view of the kinematic sheets that is neither the scheme, the plan of
        // positions, a plan nor the hodograph: the diagrams.
        let shown = [
            S::StructuralScheme,
            S::PlanOfPositions,
            S::Pos,
            S::AccelerationPlanAt,
            S::Hodograph,
        ]
        .map(|t| t.get(lang));
        w.figures(
            KINEMATICS,
            |own| !shown.iter().any(|s| own.starts_with(s)),
            |own| own.to_string(),
        );
    }
    if let Some((point, figure)) = &kin.hodograph {
        w.heading(2, T::Hodograph);
        w.doc.say(w.word(T::HodographText));
        // The seed's Table 4: the hodograph's rays in mm at its own μ_v.
        let q = format!("v_{point}");
        let rows: Vec<Row> = w
            .report
            .rows
            .iter()
            .filter(|r| r.quantity() == q && r.method == Method::Plan)
            .cloned()
            .collect();
        if let Some(first) = rows.first() {
            let mu = figure.scale;
            let positions: Vec<String> = rows.iter().filter_map(|r| r.position()).collect();
            let symbol = quantity(first.key.symbol, &first.key.subject, lang);
            let cols = [
                Column::new(
                    super::rows::head(w, first),
                    rows.iter().map(|r| Some(r.graphical)).collect(),
                )
                .against(first.scale),
                Column::new(
                    format!("{symbol}, {} ({})", w.word(T::MmUnit), mu.caption(lang)),
                    rows.iter().map(|r| Some(mu.to_mm(r.graphical))).collect(),
                )
                .against(mu.to_mm(first.scale)),
            ];
            let caption = w.word(T::HodographTable);
            numbers(w, caption, &positions, &cols);
        }
        let word = S::Hodograph.get(lang);
        w.figures(
            KINEMATICS,
            |own| own.starts_with(word),
            |own| own.to_string(),
        );
    }

    // The analytic twin.
    w.heading(2, T::AnalyticMethod);
    w.doc.say(w.word(T::AnalyticText));
    for t in w.report.tables.clone() {
        let header: Vec<String> = std::iter::once(text(w.word(T::PositionShort)))
            .chain(t.columns.iter().map(|c| {
                let name = subscripted(&c.name);
                let u = unit_in(&c.unit, lang);
                label(&if u.is_empty() {
                    name
                } else {
                    format!("{name}, {u}")
                })
            }))
            .collect();
        // Each column's largest value is its scale: a residue against it is written 0.
        let scales: Vec<f64> = (0..t.columns.len())
            .map(|c| {
                t.rows
                    .iter()
                    .filter_map(|(_, vals)| vals.get(c).copied().flatten())
                    .fold(0.0, |m: f64, x| m.max(x.abs()))
            })
            .collect();
        let rows: Vec<Vec<String>> = t
            .rows
            .iter()
            .map(|(p, vals)| {
                std::iter::once(text(p))
                    .chain(vals.iter().zip(&scales).map(|(v, &scale)| {
                        let shown = |x: f64| if is_zero(x, scale) { 0.0 } else { x };
                        text(&v.map(|x| fmt(shown(x), DIGITS, lang)).unwrap_or_default())
                    }))
                    .collect()
            })
            .collect();
        let align = vec![Align::Centre; header.len()];
        // The seed's Table 5 is wide: its columns in two tables of at most nine.
        let caption = w.word(T::AnalyticTable);
        let cols = header.len() - 1;
        let halves = cols.div_ceil(8);
        for h in 0..halves {
            let range = (1 + h * cols / halves)..(1 + (h + 1) * cols / halves);
            let pick = |row: &Vec<String>| -> Vec<String> {
                std::iter::once(row[0].clone())
                    .chain(row[range.clone()].iter().cloned())
                    .collect()
            };
            let cap = if halves > 1 {
                format!("{caption} ({} {}/{halves})", w.word(T::Part), h + 1)
            } else {
                caption.to_string()
            };
            let body: Vec<Vec<String>> = rows.iter().map(pick).collect();
            w.doc
                .table(&cap, &align[..1 + range.len()], &pick(&header), &body);
        }
    }
    Ok(())
}

/// Every kinematic sheet.
const KINEMATICS: (PlateKind, Option<usize>) = (PlateKind::Kinematics, None);

/// Every value of `symbol` read off the plan at position `p`, worked: its segment, the
/// segment's length in mm and the value through μ.
fn worked(
    w: &mut Writer<'_, '_>,
    p: &str,
    symbol: Symbol,
    pole: &str,
    mu: crate::scale::Scale,
) -> Result<(), NoteError> {
    let lang = w.lang;
    let rows: Vec<Row> = w
        .report
        .rows
        .iter()
        .filter(|r| {
            r.method == Method::Plan && r.key.symbol == symbol && r.position().as_deref() == Some(p)
        })
        .cloned()
        .collect();
    if rows.is_empty() {
        return Ok(());
    }
    w.doc.say(&format!(
        "{} {p}:",
        match symbol {
            Symbol::Velocity => w.word(T::WorkedVelocities),
            _ => w.word(T::WorkedAccelerations),
        }
    ));
    let mu_name = if symbol == Symbol::Velocity {
        "μ_{v}"
    } else {
        "μ_{a}"
    };
    let mut lines = Vec::new();
    for r in rows {
        let seg = segment(pole, &r.key.subject);
        let mm = mu.to_mm(r.graphical.abs());
        lines.push(format!(
            "{} = {} {} = {} dot {} = {}{}",
            sym(&quantity(r.key.symbol, &r.key.subject, lang)),
            sym(&seg),
            sym(mu_name),
            num(mm, 4, lang),
            num(mu.value(), 4, lang),
            num(r.graphical.abs(), DIGITS, lang),
            unit(&unit_in(r.unit(), lang))
        ));
    }
    for l in lines {
        w.formula(&l);
    }
    Ok(())
}

/// The Coriolis acceleration of every slide at position `p`: a^k = 2·ω·V_rel with the plan's
/// ω of the guide's link and relative velocity.
fn coriolis(w: &mut Writer<'_, '_>, p: &str, s: &Structure) -> Result<(), NoteError> {
    let lang = w.lang;
    let value = |symbol: Symbol, subject: &str| {
        w.report
            .rows
            .iter()
            .find(|r| {
                r.method == Method::Plan
                    && r.key.symbol == symbol
                    && r.key.subject == subject
                    && r.position().as_deref() == Some(p)
            })
            .map(|r| r.graphical)
    };
    let mut lines = Vec::new();
    for g in &s.groups {
        // The slide of an RPR or RPP group turns with its link j (a translating link: no
        // Coriolis term).
        if !matches!(g.kind, DyadKind::Rpr | DyadKind::Rpp) {
            continue;
        }
        let [_, j] = g.links;
        let a = plain(&g.pairs[0].name);
        let own = g.pairs[0].links[0];
        let subject = format!("{a}{j}_{a}{own}");
        let (Some(omega), Some(v)) = (
            value(Symbol::AngularVelocity, &j.to_string()),
            value(Symbol::Velocity, &subject),
        ) else {
            continue;
        };
        let name = format!("{a}{j}{a}{own}");
        lines.push(format!(
            "{} = 2 {} {} = 2 dot {} dot {} = {}{}",
            sym(&format!("a^{{k}}_{{{name}}}")),
            sym(&format!("ω_{{{j}}}")),
            sym(&format!("V_{{{name}}}")),
            num(omega.abs(), 4, lang),
            num(v.abs(), 4, lang),
            num(2.0 * omega.abs() * v.abs(), 4, lang),
            unit(&unit_in("m/s^2", lang))
        ));
    }
    if !lines.is_empty() {
        w.doc.say(&format!("{} {p}:", w.word(T::CoriolisWorked)));
        for l in lines {
            w.formula(&l);
        }
    }
    Ok(())
}

/// The seed's Table 1: the charted point's displacement, velocity and acceleration at each
/// position as the diagrams give them, in the drawing's mm and in SI (mm = value over the
/// diagram's μ: μ_S, |ω₁|·μ_S′, ω₁²·μ_S″), then their differences from the twin.
fn diagram_table(
    w: &mut Writer<'_, '_>,
    d: &crate::kinematics::Diagrams,
    w1: f64,
    chords: &[(String, Method)],
) {
    let lang = w.lang;
    let mus = [
        d.scales.y.value(),
        w1 * d.first.scale.value(),
        w1 * w1 * d.second.scale.value(),
    ];
    let by_symbol = |s: Symbol| {
        chords
            .iter()
            .find(|(q, m)| {
                w.report
                    .rows
                    .iter()
                    .any(|r| r.quantity() == *q && r.method == *m && r.key.symbol == s)
            })
            .cloned()
    };
    let picked: Vec<(String, Method)> =
        [Symbol::Displacement, Symbol::Velocity, Symbol::Acceleration]
            .into_iter()
            .filter_map(by_symbol)
            .collect();
    if picked.len() < 3 {
        return values_and_errors(
            w,
            (w.word(T::DiagramTable), w.word(T::DiagramErrors)),
            chords,
        );
    }
    let positions = super::rows::positions_of(&w.report.rows, &picked);
    let mut cols = Vec::new();
    for ((q, m), mu) in picked.iter().zip(mus) {
        let rows: Vec<Option<&Row>> = positions
            .iter()
            .map(|p| {
                w.report.rows.iter().find(|r| {
                    r.quantity() == *q && r.method == *m && r.position().as_ref() == Some(p)
                })
            })
            .collect();
        let Some(first) = rows.iter().flatten().next() else {
            continue;
        };
        let symbol = quantity(first.key.symbol, &first.key.subject, lang);
        cols.push(
            Column::new(
                format!("{symbol}, {}", w.word(T::MmUnit)),
                rows.iter().map(|r| r.map(|r| r.graphical / mu)).collect(),
            )
            .against(first.scale / mu),
        );
        cols.push(
            Column::new(
                super::rows::head(w, first),
                rows.iter().map(|r| r.map(|r| r.graphical)).collect(),
            )
            .against(first.scale),
        );
    }
    let caption = w.word(T::DiagramTable);
    numbers(w, caption, &positions, &cols);
    let others: Vec<(String, Method)> = chords.to_vec();
    let captions = (w.word(T::DiagramAll), w.word(T::DiagramErrors));
    values_and_errors(w, captions, &others);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The shaper's groups: a slide along the turning rocker 3 has a Coriolis part, a slide
    /// along the frame's guide the relative part alone, a turn its normal and tangential
    /// parts.
    #[test]
    fn each_relative_acceleration_splits_by_how_its_point_moves() {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("constructions/shaper.toml");
        let scene = crate::scene::load(&path).expect("shaper");
        let m = scene.mechanism.as_ref().expect("mechanism");
        let s = Structure::analyse(m);
        let equations: Vec<String> = s
            .groups
            .iter()
            .flat_map(|g| velocity_equations(g, Lang::Ru))
            .map(|e| acceleration_equation(&e))
            .collect();
        assert_eq!(
            equations,
            [
                "a_{B3} = a_{B1} + a^{k}_{B3B1} + a^{r}_{B3B1}",
                "a_{B3} = a_{C} + a^{n}_{B3C} + a^{τ}_{B3C}",
                "a_{D5} = a_{D3} + a^{k}_{D5D3} + a^{r}_{D5D3}",
                "a_{D5} = a_{D0} + a^{r}_{D5D0}",
            ]
        );
    }
}
