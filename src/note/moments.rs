//! The moment equations of the kinetostatics written out as seed 000 §2 works them: the
//! equation with every load's moment (its force times the arm read off the drawing), then
//! the unknown it gives with the numbers substituted and the result — a group's tangential
//! or normal reaction, a guide reaction's arm, the driving link's balancing load, and
//! Zhukovsky's lever. Every number is the construction's own ([`MomentEquation`]).

use super::markup::{frac, label, num, sym, text};
use super::worked::{Printed, Worked};
use super::Writer;
use crate::forces::{Load, LoadKind, MomentEquation, MomentTerm, Unknown};
use crate::words::{MachinesMeaning as M, MachinesNote as N};

/// `template` with each `{key}` replaced by its value.
pub(super) fn fill(template: &str, pairs: &[(&str, String)]) -> String {
    pairs.iter().fold(template.to_string(), |t, (k, v)| {
        t.replace(&format!("{{{k}}}"), v)
    })
}

/// A vector in a formula: the symbol of label markup `markup` under an arrow.
pub(super) fn vector(markup: &str) -> String {
    format!("arrow({})", sym(markup))
}

/// The two links of a reaction's name `R_{a-b}` (`R^τ_{a-b}`).
fn pair_of(name: &str) -> Option<(String, String)> {
    let inner = name.split_once("_{")?.1.strip_suffix('}')?;
    let (a, b) = inner.split_once('-')?;
    Some((a.to_string(), b.to_string()))
}

/// The meaning of the symbol of a load, a reaction or the balancing load named `name`
/// (label markup), in the note's language; `loads` are the position's loads.
pub(super) fn meaning(w: &Writer<'_, '_>, name: &str, loads: &[Load]) -> String {
    if let Some(l) = loads.iter().find(|l| l.name == name) {
        let m = match l.kind {
            LoadKind::Weight => M::Weight,
            LoadKind::Inertia => M::InertiaForce,
            LoadKind::InertiaMoment => M::InertiaMoment,
            LoadKind::Resistance => M::Resistance,
            LoadKind::Driving => M::Driving,
            LoadKind::Reaction | LoadKind::Friction => M::Reaction,
        };
        return fill(w.word(m), &[("k", l.link.to_string())]);
    }
    if name.starts_with('R') {
        if let Some((a, b)) = pair_of(name) {
            let m = if name.contains('τ') {
                M::Tangential
            } else {
                M::Reaction
            };
            return fill(w.word(m), &[("a", a), ("b", b)]);
        }
    }
    if name.starts_with("M_{у") {
        return w.word(M::BalancingMoment).to_string();
    }
    if name.starts_with("F_{у") {
        return w.word(M::BalancingForce).to_string();
    }
    // A couple's force on the lever, F′_{иk}, F″_{иk}.
    let k: String = name.chars().filter(char::is_ascii_digit).collect();
    fill(w.word(M::CoupleForce), &[("k", k)])
}

/// Explains the symbols of `items` (markup, meaning, unit).
pub(super) fn explain_owned(w: &mut Writer<'_, '_>, items: &[(String, String, &str)]) {
    let refs: Vec<(&str, &str, &str)> = items
        .iter()
        .map(|(s, m, u)| (s.as_str(), m.as_str(), *u))
        .collect();
    w.explain(&refs);
}

/// `lhs = f₁ f₂ … = n₁ · n₂ · … = result` as one formula: a product in symbols
/// (formula markup), with its numbers, and its result with the unit.
pub(super) fn product(
    w: &mut Writer<'_, '_>,
    lhs: &str,
    factors: &[String],
    numbers: &[String],
    result: Printed,
) {
    w.worked(Worked::new(
        sym(lhs),
        factors.join(" "),
        numbers.join(" dot "),
        result,
    ));
}

/// The crank's angular velocity ω₁ (counter-clockwise positive), rad/s.
pub(super) fn crank_speed(w: &Writer<'_, '_>) -> Result<f64, super::NoteError> {
    Ok(w.session.mechanism("the explanatory note")?.crank.omega)
}

/// Explains the symbols of `items` (markup, the catalogue's meaning, unit).
pub(super) fn explain_words(w: &mut Writer<'_, '_>, items: &[(&str, M, &str)]) {
    let refs: Vec<(&str, &str, &str)> = items.iter().map(|&(s, m, u)| (s, w.word(m), u)).collect();
    w.explain(&refs);
}

/// How an equation's arms are shown: in metres with their symbols (a group's drawing) or
/// in millimetres read off the lever.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Arms {
    /// Metres, the arm as the moment's factor.
    Metres,
    /// Millimetres read off the drawing.
    Millimetres,
}

/// The arm's symbol of a term: its label on the drawing, else `h`.
fn arm_symbol(t: &MomentTerm) -> String {
    t.label.clone().unwrap_or_else(|| "h".into())
}

/// The terms of `e` with a moment, each `(sign, symbols, numbers)`; `negate` turns every
/// sign (the known side moved across).
fn terms(
    e: &MomentEquation,
    arms: Arms,
    factor: f64,
    w: &Writer<'_, '_>,
) -> Vec<(f64, String, String)> {
    let lang = w.lang;
    e.terms
        .iter()
        .filter(|t| t.moment != 0.0)
        .map(|t| {
            let s = factor * t.moment.signum();
            if t.couple {
                return (s, sym(&t.name), num(t.force.abs(), 5, lang));
            }
            let h = match arms {
                Arms::Metres => num(t.arm, 6, lang),
                Arms::Millimetres => num(t.arm_mm, 5, lang),
            };
            (
                s,
                format!("{} {}", sym(&t.name), sym(&arm_symbol(t))),
                format!("{} dot {h}", num(t.force, 5, lang)),
            )
        })
        .collect()
}

/// A signed sum `a − b + c` of pieces.
pub(super) fn sum(pieces: &[(f64, String)]) -> String {
    let mut out = String::new();
    for (k, (s, p)) in pieces.iter().enumerate() {
        match (k, *s < 0.0) {
            (0, true) => out.push_str(&format!("-{p}")),
            (0, false) => out.push_str(p),
            (_, true) => out.push_str(&format!(" - {p}")),
            (_, false) => out.push_str(&format!(" + {p}")),
        }
    }
    if out.is_empty() {
        out.push('0');
    }
    out
}

/// The explanations of an equation's symbols: its loads, its arms, its unknown.
fn explained(
    w: &Writer<'_, '_>,
    e: &MomentEquation,
    loads: &[Load],
    arm_unit: &'static str,
) -> Vec<(String, String, &'static str)> {
    let mut out = Vec::new();
    for t in e.terms.iter().filter(|t| t.moment != 0.0) {
        let u = if t.couple { "N*m" } else { "N" };
        out.push((t.name.clone(), meaning(w, &t.name, loads), u));
    }
    let arms = e.terms.iter().filter(|t| t.moment != 0.0 && !t.couple);
    // The arms h₁, h₂, … of every drawing under one symbol, explained once; a lever's
    // segment of the turned plan that is a force's arm (`pb`, a pair's `ab`) by its name.
    if arms.clone().any(|t| !plan_arm(t)) {
        out.push(("h_{i}".into(), w.word(M::Arm).to_string(), arm_unit));
    }
    let mut segments: Vec<String> = Vec::new();
    for t in arms.filter(|t| plan_arm(t)) {
        let s = arm_symbol(t);
        if !segments.contains(&s) {
            segments.push(s);
        }
    }
    if !segments.is_empty() {
        out.push((
            segments.join(", "),
            w.word(M::PlanArm).to_string(),
            arm_unit,
        ));
    }
    out
}

/// Whether a term's arm is a segment of the lever's turned plan (its label names the
/// segment by its ends, `pb`, `ab`), not an arm `h_{n}` drawn for it.
fn plan_arm(t: &MomentTerm) -> bool {
    t.label.as_ref().is_some_and(|l| !l.starts_with("h_"))
}

/// The equation `Σ … = 0` of `e` displayed with the unknown's term, and its symbols
/// explained; then the unknown worked out («откуда …»). `loads` name the symbols; `arms`
/// says in which unit the arms are shown. Returns the unknown's value as shown.
pub(super) fn worked_equation(
    w: &mut Writer<'_, '_>,
    e: &MomentEquation,
    loads: &[Load],
    arms: Arms,
    link_length: Option<usize>,
) {
    let arm_unit = if arms == Arms::Metres { "m" } else { "mm" };
    let known = terms(e, arms, 1.0, w);
    let mut pieces: Vec<(f64, String)> = known.iter().map(|(s, a, _)| (*s, a.clone())).collect();
    let mut items = explained(w, e, loads, arm_unit);
    // The unknown's own term and its symbol.
    let (lhs, unknown_unit, value) = match &e.unknown {
        Unknown::Force {
            name,
            arm,
            label: l,
            value,
            ..
        } => {
            let h = match (l, link_length) {
                (Some(l), _) => l.clone(),
                (None, Some(k)) => format!("l_{{{k}}}"),
                (None, None) => "h".into(),
            };
            pieces.push((arm.signum(), format!("{} {}", sym(name), sym(&h))));
            items.push((name.clone(), meaning(w, name, loads), "N"));
            match link_length {
                Some(k) if l.is_none() => {
                    let m = fill(w.word(M::LinkLength), &[("k", k.to_string())]);
                    items.push((h, m, arm_unit));
                }
                // A segment of the turned plan (`pa`) explained by its own name.
                _ if l.as_ref().is_some_and(|l| !l.starts_with("h_")) => {
                    items.push((h, w.word(M::PlanArm).to_string(), arm_unit));
                }
                _ => items.push(("h_{i}".into(), w.word(M::Arm).to_string(), arm_unit)),
            }
            (name.clone(), "N", *value)
        }
        Unknown::Arm {
            name,
            reaction,
            value,
            ..
        } => {
            pieces.push((1.0, format!("{} {}", sym(reaction), sym(name))));
            items.push((reaction.clone(), meaning(w, reaction, loads), "N"));
            let point = e.about.and_then(|p| point_name(w, p)).unwrap_or_default();
            let m = fill(
                w.word(M::GuideArm),
                &[("point", point), ("reaction", reaction.clone())],
            );
            items.push((name.clone(), m, "m"));
            (name.clone(), "m", *value)
        }
        Unknown::Couple { name, value } => {
            pieces.push((1.0, sym(name)));
            items.push((name.clone(), meaning(w, name, loads), "N*m"));
            (name.clone(), "N*m", *value)
        }
    };
    // On lines of its own, broken after a sign, where one line is too long.
    let broken = format!("& {} = 0", lines(&pieces).join(" \\ "));
    if visible(&sum(&pieces)) <= EQUATION_CHARS {
        w.formula_or(&format!("{} = 0", sum(&pieces)), &broken);
    } else {
        w.formula(&broken);
    }
    explain_owned(w, &items);
    w.doc.par(&[text(w.word(N::Whence))]);
    worked_unknown(w, e, (arms, link_length), &lhs, unknown_unit, value);
}

/// A worked sum shows about this many characters at most on one line with its fraction;
/// a longer one is set out on lines of its own ([`long_sum`]).
pub(super) const ONE_LINE_CHARS: usize = 60;

/// An equation `Σ … = 0` shows about this many characters at most on one line.
const EQUATION_CHARS: usize = 72;

/// The unknown of `e` worked: the known side moved across, divided by the unknown's
/// factor, `value` its result in `unknown_unit`. A long sum is first set out on lines of its
/// own (`X·h = a + b + … \ + …`) and its total carried into the fraction.
fn worked_unknown(
    w: &mut Writer<'_, '_>,
    e: &MomentEquation,
    (arms, link_length): (Arms, Option<usize>),
    lhs: &str,
    unknown_unit: &str,
    value: f64,
) {
    let lang = w.lang;
    let result = Printed::si(value, 5, unknown_unit, lang);
    // The factor of the known moments on the unknown's side, the divisor's symbol and
    // number, and the known moments' total in the shown units.
    let (factor, divisor, divisor_value, total) = match &e.unknown {
        Unknown::Force {
            arm,
            arm_mm,
            label: l,
            ..
        } => {
            let h = match (l, link_length) {
                (Some(l), _) => l.clone(),
                (None, Some(k)) => format!("l_{{{k}}}"),
                (None, None) => "h".into(),
            };
            let (hv, total) = match arms {
                Arms::Metres => (num(arm.abs(), 6, lang), e.known()),
                Arms::Millimetres => (
                    num(*arm_mm, 5, lang),
                    e.known() * arm_mm / arm.abs().max(f64::MIN_POSITIVE),
                ),
            };
            (-arm.signum(), sym(&h), hv, -arm.signum() * total)
        }
        Unknown::Arm {
            reaction, force, ..
        } => (-1.0, sym(reaction), num(*force, 5, lang), -e.known()),
        Unknown::Couple { .. } => (-1.0, String::new(), String::new(), -e.known()),
    };
    let moved = terms(e, arms, factor, w);
    let symbols = sum(&moved
        .iter()
        .map(|(s, a, _)| (*s, a.clone()))
        .collect::<Vec<_>>());
    let pieces: Vec<(f64, String)> = moved.iter().map(|(s, _, n)| (*s, n.clone())).collect();
    let x = sym(lhs);
    if visible(&sum(&pieces)) <= ONE_LINE_CHARS {
        let numbers = sum(&pieces);
        w.worked(if divisor.is_empty() {
            Worked::new(x, symbols, numbers, result)
        } else {
            Worked::new(
                x,
                frac(&symbols, &divisor),
                frac(&numbers, &divisor_value),
                result,
            )
        });
        return;
    }
    // The sum on lines of its own, then its total through the fraction.
    let left = if divisor.is_empty() {
        x.clone()
    } else {
        format!("{x} {divisor}")
    };
    let moment_unit = match arms {
        Arms::Metres => "N*m",
        Arms::Millimetres => "N*mm",
    };
    w.worked(long_sum(
        &left,
        &pieces,
        Printed::si(total, 6, moment_unit, lang),
    ));
    let by_total = frac(&num(total, 6, lang), &divisor_value);
    w.worked(if divisor.is_empty() {
        Worked::new(x, "", "", result)
    } else if visible(&symbols) <= ONE_LINE_CHARS {
        Worked::new(x, frac(&symbols, &divisor), by_total, result)
    } else {
        Worked::new(x, "", by_total, result)
    });
}

/// A long sum as one formula on lines as long as [`LINE_CHARS`], broken after a sign
/// (ГОСТ 2.105: the sign repeated on the next line), ending with its total `total`:
/// `left = a + b + … \ + … = total` ([`Worked::on_lines`]).
pub(super) fn long_sum(left: &str, pieces: &[(f64, String)], total: Printed) -> Worked {
    Worked::on_lines(left, &lines(pieces), total)
}

/// The lines of a long sum of `pieces`, each as long as [`LINE_CHARS`]: the first as it
/// is, each next aligned and starting with its sign.
fn lines(pieces: &[(f64, String)]) -> Vec<String> {
    let mut lines: Vec<Vec<(f64, String)>> = vec![Vec::new()];
    let mut room = 0;
    for piece in pieces {
        let width = visible(&piece.1) + 3;
        if room + width > LINE_CHARS && !lines.last().is_some_and(Vec::is_empty) {
            lines.push(Vec::new());
            room = 0;
        }
        room += width;
        if let Some(line) = lines.last_mut() {
            line.push(piece.clone());
        }
    }
    lines
        .iter()
        .enumerate()
        .map(|(k, chunk)| {
            let line = sum(chunk);
            if k == 0 {
                line
            } else if line.starts_with('-') {
                format!("& {line}")
            } else {
                format!("& + {line}")
            }
        })
        .collect()
}

/// The characters a line of a long sum holds (the text's width less the formula's left
/// side and number).
const LINE_CHARS: usize = 52;

/// About how many characters the Typst math `math` shows: its quotes, its symbols' markup
/// and its brackets left out, `dot` one character.
pub(super) fn visible(math: &str) -> usize {
    let shown = math
        .replace("#qs[#", "")
        .replace("#qu[#", "")
        .replace(" dot ", "·");
    shown
        .chars()
        .filter(|c| !matches!(c, '"' | '[' | ']' | '(' | ')' | '_' | '^' | ' '))
        .count()
}

/// The name of point `k` of the mechanism (label markup).
pub(super) fn point_name(w: &Writer<'_, '_>, k: usize) -> Option<String> {
    let sc = w.session.kin_scales().ok()?;
    let plan = w.session.positions(sc.l).ok()?;
    plan.program.names.get(k).cloned()
}

/// The paragraph that introduces a moment equation of `links` about `point`.
pub(super) fn moments_head(w: &mut Writer<'_, '_>, links: &[usize], point: &str) {
    let t = if links.len() > 1 {
        N::MomentsOfLinks
    } else {
        N::MomentsOfLink
    };
    let links: Vec<String> = links.iter().map(usize::to_string).collect();
    let s = fill(
        w.word(t),
        &[("links", links.join(", ")), ("point", point.to_string())],
    );
    w.doc.par(&[label(&s)]);
}

/// Zhukovsky's lever of a coupling drive: M_у = −μ_v·Σ(±F·h)/ω₁ with the lever's arms in
/// mm and its scale `mu_v`, the crank's `w1`; `value` the lever's balancing moment.
pub(super) fn lever_couple(
    w: &mut Writer<'_, '_>,
    e: &MomentEquation,
    loads: &[Load],
    (mu_v, w1): (f64, f64),
    value: f64,
) {
    let lang = w.lang;
    let moved = terms(e, Arms::Millimetres, -1.0, w);
    let symbols = sum(&moved
        .iter()
        .map(|(s, a, _)| (*s, a.clone()))
        .collect::<Vec<_>>());
    let numbers = sum(&moved
        .iter()
        .map(|(s, _, n)| (*s, n.clone()))
        .collect::<Vec<_>>());
    let name = "M_{у}";
    w.worked(Worked::new(
        sym(name),
        frac(&format!("{} ({symbols})", sym("μ_{v}")), &sym("ω_{1}")),
        frac(
            &format!("{} dot ({numbers})", num(mu_v, 4, lang)),
            &num(w1, 5, lang),
        ),
        Printed::si(value, 5, "N*m", lang),
    ));
    let mut items = explained(w, e, loads, "mm");
    items.push((name.into(), meaning(w, name, loads), "N*m"));
    items.push((
        "μ_{v}".into(),
        w.word(M::LeverScale).to_string(),
        "m/(s*mm)",
    ));
    items.push(("ω_{1}".into(), w.word(M::CrankSpeed).to_string(), "rad/s"));
    explain_owned(w, &items);
}
