//! The velocity and acceleration plans of the note: the crank pin's vector and the plan's
//! scale worked, each group's vector equations with the table of what is known, the values
//! read off the plan at the worked position (segment × μ), the similarity proportions of
//! the further points of a turning link (pd = pb₃·CD/CB), the links' rates
//! (ω = V/l, ε = aτ/l), the normal parts aⁿ = ω²·l and the Coriolis parts a^k = 2·ω·V_rel with
//! their direction rule; then the tables of the seed's shapes and the plans' figures.

use super::equations::{equations, velocity_equations, Kind};
use super::markup::{frac, num, sym, text, unit};
use super::plan_reads::{explain_one, segment, Plans};
use super::rows::{numbers, values_and_errors, Column, DIGITS};
use super::worked::{Printed, Worked};
use super::{NoteError, Writer};
use crate::check::{Method, Row, Symbol};
use crate::scene::PlateKind;
use crate::words::{
    plain, quantity, KinematicsMeaning as M, KinematicsNote as K, NoteText as T, Text as S,
};

/// The worked position: the first position with an acceleration plan, else the first one.
pub(super) fn worked_position(rows: &[Row]) -> Option<String> {
    rows.iter()
        .find(|r| r.method == Method::Plan && r.key.symbol == Symbol::Acceleration)
        .or_else(|| rows.iter().find(|r| r.method == Method::Plan))
        .and_then(|r| r.position())
}

/// The quantities of `symbol` read off the plans.
pub(super) fn plan_quantities(rows: &[Row], symbol: Symbol) -> Vec<(String, Method)> {
    super::rows::quantities(rows, |r| r.method == Method::Plan && r.key.symbol == symbol)
}

/// The plans' values of `symbol` by position and their differences from the twin, as the
/// two tables captioned `captions`; the differences alone without the first (the values
/// stand in the seed's Table 2).
fn plan_tables(w: &mut Writer<'_, '_>, symbol: Symbol, captions: (Option<T>, T)) {
    let quantities = plan_quantities(&w.report.rows, symbol);
    let captions = (captions.0.map_or("", |c| w.word(c)), w.word(captions.1));
    values_and_errors(w, captions, &quantities);
}

/// What a quantity of the plans is, for the «где» under its formula: «скорость точки B3»,
/// «скорость точки B3 относительно точки B1».
fn meaning(w: &Writer<'_, '_>, symbol: Symbol, subject: &str) -> String {
    let (what, relative) = match symbol {
        Symbol::Velocity => (M::PointVelocity, M::RelativeVelocity),
        _ => (M::PointAcceleration, M::RelativeAcceleration),
    };
    match subject.split_once('_') {
        Some((p, r)) => format!("{} {p} {} {r}", w.word(what), w.word(relative)),
        None => format!("{} {subject}", w.word(what)),
    }
}

/// The crank's pin, `crank` its length's symbol.
fn crank_pin<'a>(p: &'a Plans<'_>, crank: &'a str) -> CrankPin<'a> {
    CrankPin {
        name: &p.m.crank.pin,
        crank,
        w1: p.kin.w1.abs(),
        length: p.m.crank.length,
    }
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

impl CrankPin<'_> {
    /// `V_B = ω₁ l_AB = … m/s` (`a_B = ω₁² l_AB`, the crank turning uniformly), then the
    /// plan's scale from the pin's vector drawn from the pole: `μ = V_B/pb = …`.
    fn worked(&self, w: &mut Writer<'_, '_>, plan: Kind, scale: crate::scale::Scale) {
        let lang = w.lang;
        let (letter, power, si, words, mu, pole) = match plan {
            Kind::Velocity => (
                "V",
                "",
                "m/s",
                (T::CrankPinVelocity, T::VelocityScale),
                "μ_{v}",
                "p",
            ),
            Kind::Acceleration => (
                "a",
                "^2",
                "m/s^2",
                (T::CrankPinAcceleration, T::AccelerationScale),
                "μ_{a}",
                "π",
            ),
        };
        let value = match plan {
            Kind::Velocity => self.w1 * self.length,
            Kind::Acceleration => self.w1 * self.w1 * self.length,
        };
        let pin = format!("{letter}_{{{}}}", self.name);
        w.doc.par(&[text(w.word(words.0))]);
        w.worked(Worked::new(
            sym(&pin),
            format!("{}{power} {}", sym("ω_{1}"), sym(self.crank)),
            format!(
                "{}{power} dot {}",
                num(self.w1, 5, lang),
                num(self.length, 5, lang)
            ),
            Printed::si(value, 5, si, lang),
        ));
        let symbol = match plan {
            Kind::Velocity => Symbol::Velocity,
            Kind::Acceleration => Symbol::Acceleration,
        };
        let what = meaning(w, symbol, self.name);
        w.explain(&[("ω_{1}", w.word(M::CrankSpeed), "rad/s"), (&pin, &what, si)]);
        let segment = format!("{pole}{}", self.name.to_lowercase());
        w.doc.par(&[text(w.word(words.1))]);
        w.worked(Worked::new(
            sym(mu),
            frac(&sym(&pin), &sym(&segment)),
            frac(&num(value, 5, lang), &num(scale.to_mm(value), 4, lang)),
            Printed::new(scale.value(), 4, unit(scale.quantity.unit(lang)), 1.0, lang),
        ));
        let (scale_word, segment_word, mu_si) = match plan {
            Kind::Velocity => (M::VelocityScale, M::VelocitySegment, "m/(s*mm)"),
            Kind::Acceleration => (M::AccelerationScale, M::AccelerationSegment, "m/(s^2*mm)"),
        };
        let seg_meaning = format!("{} {}", w.word(segment_word), self.name);
        w.explain(&[
            (mu, w.word(scale_word), mu_si),
            (&segment, &seg_meaning, "mm"),
        ]);
    }
}

/// A plan's subsection up to its worked values: the heading, the crank pin's vector and the
/// plan's scale worked, each group's vector equations with the table of what is known.
fn opening(w: &mut Writer<'_, '_>, p: &Plans<'_>, kind: Kind) {
    let (heading, sentence) = match kind {
        Kind::Velocity => (T::VelocityPlans, T::VectorEquations),
        Kind::Acceleration => (T::AccelerationPlans, T::AccelerationEquations),
    };
    w.heading(2, heading);
    let crank = super::positions::crank_length(p.m);
    crank_pin(p, &crank).worked(w, kind, p.scale(kind));
    w.doc.say(w.word(sentence));
    equations(w, p.m, &p.s.groups, kind);
}

/// The velocity plans.
pub(super) fn velocities(w: &mut Writer<'_, '_>, p: &Plans<'_>) -> Result<(), NoteError> {
    let lang = w.lang;
    opening(w, p, Kind::Velocity);
    if let Some(at) = &p.at {
        worked(w, at, Symbol::Velocity, "p", p.scale(Kind::Velocity));
        super::plan_worked::similarity(w, p);
        super::plan_worked::rates(w, p, Kind::Velocity);
    }
    table_2(w, p);
    plan_tables(w, Symbol::Velocity, (None, T::VelocityErrors));
    let captions = (Some(T::AngularVelocitiesTable), T::AngularVelocityErrors);
    plan_tables(w, Symbol::AngularVelocity, captions);
    let worked_plan = p.at.as_ref().map(|at| format!("{} {at}", S::Pos.get(lang)));
    w.figures(
        (PlateKind::Kinematics, None),
        |own| Some(own) == worked_plan.as_deref(),
        |own| format!("{}, {}", T::VelocityPlanWord.get(lang), own.to_lowercase()),
    );
    Ok(())
}

/// The acceleration plans.
pub(super) fn accelerations(w: &mut Writer<'_, '_>, p: &Plans<'_>) -> Result<(), NoteError> {
    let lang = w.lang;
    if plan_quantities(&w.report.rows, Symbol::Acceleration).is_empty() {
        return Ok(());
    }
    opening(w, p, Kind::Acceleration);
    if let Some(at) = &p.at {
        super::plan_worked::normals(w, p);
        super::plan_worked::coriolis(w, p);
        worked(
            w,
            at,
            Symbol::Acceleration,
            "π",
            p.scale(Kind::Acceleration),
        );
        super::plan_worked::rates(w, p, Kind::Acceleration);
    }
    let captions = (Some(T::AccelerationsTable), T::AccelerationErrors);
    plan_tables(w, Symbol::Acceleration, captions);
    let captions = (
        Some(T::AngularAccelerationsTable),
        T::AngularAccelerationErrors,
    );
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
        (PlateKind::Kinematics, None),
        |own| own.starts_with(word),
        |own| own.to_string(),
    );
    Ok(())
}

/// Every value of `symbol` read off the plan at position `p`, worked: its segment, the
/// segment's length in mm and the value through μ.
fn worked(w: &mut Writer<'_, '_>, p: &str, symbol: Symbol, pole: &str, mu: crate::scale::Scale) {
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
        return;
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
    for r in rows {
        let seg = segment(pole, &r.key.subject);
        let mm = mu.to_mm(r.graphical.abs());
        let q = quantity(r.key.symbol, &r.key.subject, lang);
        w.worked(Worked::new(
            sym(&q),
            // Written together: a segment without an index (πb) and a space print apart.
            format!("{}{}", sym(&seg), sym(mu_name)),
            format!("{} dot {}", num(mm, 4, lang), num(mu.value(), 4, lang)),
            Printed::si(r.graphical.abs(), DIGITS, r.unit(), lang),
        ));
        let what = meaning(w, symbol, &r.key.subject);
        explain_one(w, &q, &what, r.unit());
    }
}

/// The seed's Table 2: the moduli of the velocities the plans give by position, its columns
/// in the seed's order — group by group, the slide's relative velocity, the group's point,
/// then the further points of its links from the pivot out (V_B3B1, V_B3, V_S3, V_D, V_D5D3,
/// V_D5); the crank's pin (known) and a point the plan draws at another's image
/// (d₅ ≡ e ≡ s₅) left out.
fn table_2(w: &mut Writer<'_, '_>, p: &Plans<'_>) {
    let lang = w.lang;
    let quantities = plan_quantities(&w.report.rows, Symbol::Velocity);
    let of = |q: &(String, Method)| -> Vec<Row> {
        w.report
            .rows
            .iter()
            .filter(|r| r.quantity() == q.0 && r.method == q.1)
            .cloned()
            .collect()
    };
    let subject = |q: &(String, Method)| of(q).first().map(|r| r.key.subject.clone());
    let mut order: Vec<String> = Vec::new();
    for g in &p.s.groups {
        let eqs = velocity_equations(g, lang);
        for e in &eqs {
            order.push(format!("{}_{}", e.point, e.reference));
        }
        if let Some(e) = eqs.first() {
            order.push(e.point.clone());
        }
        let mut points: Vec<_> =
            p.m.points
                .iter()
                .filter(|x| g.links.contains(&x.link))
                .collect();
        points.sort_by(|a, b| a.along.hypot(a.across).total_cmp(&b.along.hypot(b.across)));
        order.extend(points.iter().map(|x| plain(&x.name)));
    }
    let pin = plain(&p.m.crank.pin);
    let mut picked: Vec<(String, Method)> = Vec::new();
    for name in order.iter().chain(
        quantities
            .iter()
            .filter_map(&subject)
            .collect::<Vec<_>>()
            .iter(),
    ) {
        let Some(q) = quantities
            .iter()
            .find(|q| subject(q).as_deref() == Some(name.as_str()))
        else {
            continue;
        };
        if *name == pin || picked.contains(q) {
            continue;
        }
        let these = of(q);
        let same = picked.iter().any(|o| {
            let others = of(o);
            others.len() == these.len()
                && others
                    .iter()
                    .zip(&these)
                    .all(|(a, b)| a.graphical == b.graphical)
        });
        if !same {
            picked.push(q.clone());
        }
    }
    let positions = super::rows::positions_of(&w.report.rows, &picked);
    let cols: Vec<Column> = picked
        .iter()
        .filter_map(|q| {
            let these = of(q);
            let first = these.first()?;
            let values = positions
                .iter()
                .map(|p| {
                    these
                        .iter()
                        .find(|r| r.position().as_ref() == Some(p))
                        .map(|r| super::rows::shown(r, super::rows::value(r.graphical, r).abs()))
                })
                .collect();
            let zero = super::rows::shown(first, first.scale);
            Some(Column::new(super::rows::head(w, first), values).against(zero))
        })
        .collect();
    let caption = w.word(K::Table2);
    numbers(w, caption, &positions, &cols);
}
