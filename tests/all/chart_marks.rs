//! The positions' numbers on the diagrams' φ axes: the numbered positions at their nodes and
//! the plan's extreme positions between them at their crank angles, the curves drawn through
//! them (issue 45).

use crate::kinematic_verdicts::with_kinematics;

/// The S chart is drawn through the extreme positions the plan draws between the numbered
/// ones, as the draughtsman plots them (issue 45): the six-bar's S reaches its stroke
/// H = 205,7 mm at 6′, between positions 6 and 7, where the curve through the numbered
/// positions alone stopped 1,7 mm lower on the sheet (7 mm of S), and touches 0 at 10′; both
/// are numbered under the φ axis, as is 4′, where the slider reaches 6′'s end again. The
/// shaper's 8′, 2,7 mm past position 8, is plotted and numbered over the axis: too near
/// position 8's number to stand beside it under the axis.
#[test]
fn the_s_chart_is_drawn_through_the_extreme_positions() {
    use tmm::construct::{Item, Role};
    for (scene, crest_between, marks) in [
        ("six-bar", (5.0, 6.0), &["4′", "6′", "10′"][..]),
        ("shaper", (7.0, 8.0), &["8′"][..]),
    ] {
        with_kinematics(scene, |_, _, study| {
            let chart = study.diagrams.as_ref().expect("the S chart");
            let (mu_s, mu_phi) = (chart.scales.y.value(), chart.scales.x.value());
            let points: Vec<tmm::geom::DVec2> = (chart.first_figure.steps.iter())
                .filter(|st| st.role == Role::Given)
                .flat_map(|st| match &st.item {
                    Item::Curve { points, .. } => points.clone(),
                    _ => Vec::new(),
                })
                .collect();
            let crest = points
                .iter()
                .copied()
                .max_by(|a, b| a.y.total_cmp(&b.y))
                .expect("a curve");
            // The stroke H: the charted slider's range.
            let ranges = &study.plan.extremes.as_ref().expect("extremes").ranges;
            assert!(
                (ranges.iter()).any(|r| (crest.y * mu_s - (r.max - r.min)).abs() < 1e-9),
                "{scene}: the crest {} m, not a stroke of {ranges:?}",
                crest.y * mu_s
            );
            let interval = TAU_OVER_12 / mu_phi;
            let at = crest.x / interval;
            assert!(
                at > crest_between.0 && at < crest_between.1,
                "{scene}: the crest at {at} intervals"
            );
            if scene == "six-bar" {
                let lowest = points.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
                assert!(lowest.abs() < 1e-9, "{scene}: S at 10′ {lowest} mm");
            }
            let primed: Vec<&tmm::construct::Label> = (chart.first_figure.steps.iter())
                .filter(|st| st.note.ends_with("on the φ axis"))
                .filter_map(|st| st.label.as_ref())
                .filter(|l| l.text.contains('′'))
                .collect();
            let labels: Vec<&str> = primed.iter().map(|l| l.text.as_str()).collect();
            assert_eq!(labels, marks, "{scene}");
            let over = scene == "shaper";
            for l in primed {
                assert_eq!(l.toward.y > 0.0, over, "{scene}: {} {:?}", l.text, l.toward);
            }
        });
    }
}

/// One of a crank turn's twelve intervals, rad.
const TAU_OVER_12: f64 = std::f64::consts::TAU / 12.0;

/// The rocker's ω diagram numbers its positions under its φ axis, as the S chart does and the
/// textbook's ω₃(φ) (seed 000 §1.5) is read: 1 … 12, each at its node (issue 45: the
/// four-bar's and the shaper's ω₃ axes had no numbers, so a reader could not say which
/// ordinate was which position's), and the plan's extreme between them (7′, 8′) at its
/// crank angle, where the curve is drawn through nought: the rocker stands there (issue 45:
/// «7» stood where ω₃ crosses nought, ω₃(7) being −0,594 rad/s).
#[test]
fn the_rocker_diagram_numbers_its_positions() {
    use tmm::construct::{Item, Role};
    for (scene, extreme, between) in [("four-bar", "7′", (6.0, 7.0)), ("shaper", "8′", (7.0, 8.0))]
    {
        with_kinematics(scene, |_, _, study| {
            let rocker = study.rocker.as_ref().expect("the ω diagram");
            let marks: Vec<(String, f64)> = (rocker.figure.steps.iter())
                .filter(|st| st.note.ends_with("on the φ axis"))
                .filter_map(|st| match (&st.item, &st.label) {
                    (Item::Text(at), Some(l)) => Some((l.text.clone(), at.x)),
                    _ => None,
                })
                .collect();
            let names: Vec<&str> = marks.iter().map(|(t, _)| t.as_str()).collect();
            let mut want: Vec<String> = (1..=12).map(|k| k.to_string()).collect();
            want.push(extreme.to_string());
            assert_eq!(names, want, "{scene}");
            let interval = TAU_OVER_12 / rocker.scale_phi.value();
            for (k, (text, x)) in marks.iter().take(12).enumerate() {
                assert!(
                    (x - k as f64 * interval).abs() < 1e-9,
                    "{scene}: {text} at {x} mm"
                );
            }
            // The extreme at its crank angle, strictly between its neighbours' nodes.
            let at = marks[12].1 / interval;
            assert!(
                at > between.0 && at < between.1,
                "{scene}: {extreme} at {at}"
            );
            let through = (rocker.figure.steps.iter())
                .filter(|st| st.role == Role::Given)
                .flat_map(|st| match &st.item {
                    Item::Curve { points, .. } => points.clone(),
                    _ => Vec::new(),
                })
                .any(|p| (p.x - marks[12].1).abs() < 1e-9 && p.y.abs() < 1e-6);
            assert!(
                through,
                "{scene}: the ω curve does not pass nought at {extreme}"
            );
        });
    }
}

/// Every derivative's φ axis numbers the positions as its diagram's does (issue 45: the
/// dS/dφ, d²S/dφ² and dω₃/dφ axes had no numbers, so a reader could not say which ordinate
/// was which position's): 1 … 12, each at its node, its middle off the axis on one side and
/// within half an interval of the node, never flown off among the chords' steps.
#[test]
fn every_derivative_axis_numbers_its_positions() {
    use tmm::construct::{Figure, Item};
    let numbers = |f: &Figure| -> Vec<(String, f64, tmm::geom::DVec2)> {
        (f.steps.iter())
            .filter(|st| st.note.ends_with("on the derivative's φ axis"))
            .filter_map(|st| match (&st.item, &st.label) {
                (Item::Text(at), Some(l)) => Some((l.text.clone(), at.x, l.anchor - *at)),
                _ => None,
            })
            .collect()
    };
    let want: Vec<String> = (1..=12).map(|k| k.to_string()).collect();
    for scene in ["four-bar", "shaper", "six-bar", "slider-crank", "v-engine"] {
        with_kinematics(scene, |_, _, study| {
            let mut axes = Vec::new();
            if let Some(d) = &study.diagrams {
                let interval = TAU_OVER_12 / d.scales.x.value();
                axes.push(("dS/dφ", numbers(&d.first_figure), interval));
                axes.push(("d²S/dφ²", numbers(&d.second_figure), interval));
            }
            if let Some(r) = &study.rocker {
                axes.push((
                    "dω/dφ",
                    numbers(&r.figure),
                    TAU_OVER_12 / r.scale_phi.value(),
                ));
            }
            assert!(!axes.is_empty(), "{scene}: no diagram");
            for (axis, marks, interval) in axes {
                let names: Vec<&str> = marks.iter().map(|m| m.0.as_str()).collect();
                assert_eq!(names, want, "{scene} {axis}");
                for (k, (text, x, off)) in marks.iter().enumerate() {
                    assert!(
                        (x - k as f64 * interval).abs() < 1e-9,
                        "{scene} {axis}: {text} at {x} mm"
                    );
                    assert!(
                        (2.0..=6.0).contains(&off.y.abs()) && off.x.abs() < 0.5 * interval,
                        "{scene} {axis}: {text} {off} mm from its node"
                    );
                }
            }
        });
    }
}
