//! The kinematic sheet's first lines: the drafting model's errors and the plans' μ, with
//! the positions whose plans are drawn at a μ of their own.

use crate::scale::{Lang, Scale};
use crate::study::{KinScales, Kinematics, Session};
use crate::words::Text;

/// The sheet's first lines: the drafting model's errors, the plans' scales, and the
/// positions whose plans are drawn at a μ of their own (their captions state it too).
pub(super) fn head_lines(
    session: &Session<'_>,
    a: &Kinematics,
    sc: &KinScales,
    lang: Lang,
) -> (String, Vec<String>) {
    let drafting = super::drafting_line(
        session.drafting(),
        if a.diagrams.is_some() {
            super::Errs::PlansAndChords
        } else {
            super::Errs::Plans
        },
        lang,
    );
    let mut scales = vec![format!(
        "{}: {}; {}: {}",
        Text::VelocityPlans.get(lang),
        sc.v.caption(lang),
        Text::AccelerationPlans.get(lang),
        sc.a.caption(lang)
    )];
    let velocity = a
        .plan
        .positions
        .iter()
        .zip(a.velocity_plans())
        .filter_map(|(pos, vp)| Some((pos.label.as_str(), vp?.figure.scale)));
    let acceleration = a
        .acceleration
        .iter()
        .map(|(k, ap)| (a.plan.positions[*k].label.as_str(), ap.plan.figure.scale));
    scales.extend(own_scales(Text::VelocityPlans, sc.v, velocity, lang));
    scales.extend(own_scales(
        Text::AccelerationPlans,
        sc.a,
        acceleration,
        lang,
    ));
    (drafting, scales)
}

/// A line per μ other than `common` the plans `plans` (position's label, μ) are drawn at,
/// begun with a capital: «Планы скоростей пол. 3, 4, 9, 10: μ_v = 0,25 м/(с·мм)», «Планы
/// ускорений пол. 12: …».
fn own_scales<'a>(
    kind: Text,
    common: Scale,
    plans: impl Iterator<Item = (&'a str, Scale)>,
    lang: Lang,
) -> Vec<String> {
    let mut own: Vec<(Scale, Vec<&str>)> = Vec::new();
    for (label, s) in plans.filter(|(_, s)| *s != common) {
        match own.iter_mut().find(|(o, _)| *o == s) {
            Some((_, labels)) => labels.push(label),
            None => own.push((s, vec![label])),
        }
    }
    own.into_iter()
        .map(|(s, labels)| {
            crate::words::heading(&format!(
                "{} {} {}: {}",
                kind.get(lang),
                Text::Pos.get(lang).to_lowercase(),
                labels.join(", "),
                s.caption(lang)
            ))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::own_scales;
    use crate::scale::{Lang, Quantity, Scale};
    use crate::words::Text;

    /// Each line of plans at a μ of their own begins with a capital, the acceleration plans'
    /// too (their word is small after the common line's «;»), and names only those plans.
    #[test]
    fn a_line_of_plans_at_their_own_scale_begins_with_a_capital() {
        let mu = |v| Scale::new(v, Quantity::Acceleration).expect("μ_a");
        let plans = [("5", mu(1.0)), ("12", mu(0.2))];
        let lines = own_scales(
            Text::AccelerationPlans,
            mu(1.0),
            plans.into_iter(),
            Lang::Ru,
        );
        assert_eq!(lines.len(), 1, "{lines:?}");
        assert!(
            lines[0].starts_with("Планы ускорений пол. 12: "),
            "{}",
            lines[0]
        );
        let en = own_scales(
            Text::AccelerationPlans,
            mu(1.0),
            plans.into_iter(),
            Lang::En,
        );
        assert!(
            en[0].starts_with("Acceleration plans pos. 12: "),
            "{}",
            en[0]
        );
    }
}
