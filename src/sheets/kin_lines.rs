//! The kinematic sheet's lines of text that read its plans and diagrams: the acceleration
//! plans' verdicts and what the chord diagrams give at a corner of S.

use super::digits;
use crate::check::{Row, Symbol};
use crate::kinematics::KinDiagrams;
use crate::scale::Lang;
use crate::words::{symbols, unit_in, Text};

/// The acceleration plans' verdict per position (seed 001 l. 686–689), as the plans give it:
/// «Положение 1: ускоренно вращаются звенья 3, 4; замедленно — 2».
pub(crate) fn verdict_lines(
    verdicts: &[crate::kinematics::LinkVerdict],
    lang: Lang,
) -> Vec<String> {
    let links = |l: &[&str]| {
        if l.is_empty() {
            Text::NoLinks.get(lang).to_string()
        } else {
            l.join(", ")
        }
    };
    crate::kinematics::by_position(verdicts)
        .into_iter()
        .map(|(p, [up, down, _])| {
            // «звено 2», «звенья 3, 4», or none at all.
            let accelerating = match up.as_slice() {
                [] => Text::NoneAccelerating.get(lang).to_string(),
                [one] => format!("{} {one}", Text::AcceleratingLink.get(lang)),
                many => format!("{} {}", Text::AcceleratingLinks.get(lang), many.join(", ")),
            };
            format!(
                "{} {p}: {accelerating}; {} {}",
                Text::Pos.get(lang),
                Text::DeceleratingLinks.get(lang),
                links(&down)
            )
        })
        .collect()
}

/// At each corner of S, the rates the diagrams give beside the limits of the branch past the
/// corner that they are compared with (the analytic table has no row there, the plan being
/// singular), so that the error table's δ there can be checked, and why it is large:
/// «Пол. 6, ветвь после излома, по диаграммам и предел: V_E = 4,024 и 3,059 м/с, …».
pub(crate) fn corner_lines(d: &KinDiagrams, lang: Lang) -> Vec<String> {
    let at = |label: &str, symbol: Symbol| {
        (d.rows.iter()).find(|r| r.key.symbol == symbol && r.position().as_deref() == Some(label))
    };
    let pair = |r: &Row| {
        format!(
            "{} = {} {} {} {}",
            symbols::quantity(r.key.symbol, &r.key.subject, lang),
            digits::value(r.graphical, lang),
            Text::And.get(lang),
            digits::value(r.analytic, lang),
            unit_in(r.unit(), lang)
        )
    };
    (d.corners.iter())
        .filter_map(|c| {
            let v = at(c, Symbol::Velocity)?;
            let a = at(c, Symbol::Acceleration)?;
            Some(format!(
                "{} {c}, {}: {}, {}; {}",
                Text::Pos.get(lang),
                Text::CornerBranchValues.get(lang),
                pair(v),
                pair(a),
                Text::ChordsRoughAtCorner.get(lang)
            ))
        })
        .collect()
}
