//! The kinematic sheet's conclusions and charts: seed 001's verdict on the six-bar's links,
//! a verdict of one link or none, the chart taking its sheet's room and breaking at the
//! six-bar's change point.

use crate::kinematics::{report_json, root, rows};
use tmm::construct::Drafting;

/// Seed 001's conclusion of W1 (l. 687–689), drawn from the six-bar's acceleration plan at
/// position 1: links 3 and 4 accelerate, link 2 decelerates — in the report's notes (both
/// routes agreeing) and on the kinematic sheet.
#[test]
fn the_six_bar_links_accelerate_and_decelerate_as_seed_001_concludes() {
    let v = report_json("constructions/six-bar.toml", "0.5");
    let notes: Vec<&str> = v["notes"]
        .as_array()
        .expect("notes")
        .iter()
        .filter_map(|n| n.as_str())
        .collect();
    let want = "position 1: accelerating (ω and ε in one sense) by the plans: links 3, 4; decelerating: links 2; the analytic twin agrees";
    assert!(notes.contains(&want), "{notes:#?}");
    let scene = tmm::load(&root().join("constructions/six-bar.toml")).expect("six-bar");
    let plates = tmm::render::plates(&scene, tmm::Lang::Ru, Drafting::EXACT).expect("plates");
    let texts: Vec<&String> = plates
        .iter()
        .flat_map(|(_, p)| p.texts.iter().flat_map(|t| t.lines.iter()))
        .collect();
    assert!(
        texts
            .iter()
            .any(|t| *t == "Пол. 1: ускоренно вращаются звенья 3, 4; замедленно — 2"),
        "{texts:#?}"
    );
}

/// The verdict of one link and of none reads as Russian does (a strict instructor's mark on
/// the four-bar: «вращаются звенья 3», «вращаются звенья нет»): one link in the singular, none
/// as a sentence of its own, in ru, uk and en.
#[test]
fn a_verdict_of_one_link_or_none_reads_in_its_number() {
    let scene = tmm::load(&root().join("constructions/four-bar.toml")).expect("four-bar");
    for (lang, one, none) in [
        (
            tmm::Lang::Ru,
            "Пол. 4: ускоренно вращается звено 3; замедленно — 2",
            "Пол. 10: ни одно звено не вращается ускоренно; замедленно — 2, 3",
        ),
        (
            tmm::Lang::Uk,
            "Пол. 4: прискорено обертається ланка 3; сповільнено — 2",
            "Пол. 10: жодна ланка не обертається прискорено; сповільнено — 2, 3",
        ),
        (
            tmm::Lang::En,
            "Pos. 4: accelerating (ω, ε in the same sense): link 3; decelerating: 2",
            "Pos. 10: no link accelerating; decelerating: 2, 3",
        ),
    ] {
        let plates = tmm::render::plates(&scene, lang, Drafting::new(0.5).expect("drafting"))
            .expect("plates");
        let texts: Vec<&String> = plates
            .iter()
            .flat_map(|(_, p)| p.texts.iter().flat_map(|t| t.lines.iter()))
            .collect();
        for want in [one, none] {
            assert!(
                texts.iter().any(|t| *t == want),
                "{lang:?}: {want}\n{texts:#?}"
            );
        }
    }
}

/// The displacement chart is drawn as large as its sheet allows: on the second of two sheets
/// the six-bar's (no chart scale given) takes 2π on 360 mm, the V engine's (two large
/// acceleration plans beside it) 2π on 300 mm; a one-sheet study keeps the textbook's 240 mm,
/// and the shaper's scene fixes μ_φ (the seed's; its diagrams go on a second sheet only when
/// the first sheet's packing leaves them no room).
#[test]
fn the_chart_takes_the_room_of_its_sheet() {
    use std::f64::consts::TAU;
    use tmm::study::{KinSheets, Session};
    for (scene, sheets, turn_mm) in [
        ("six-bar", KinSheets::Two, Some(360.0)),
        ("v-engine", KinSheets::Two, Some(300.0)),
        ("slider-crank", KinSheets::One, Some(240.0)),
        ("shaper", KinSheets::One, None),
    ] {
        let s =
            tmm::scene::load(&root().join(format!("constructions/{scene}.toml"))).expect("scene");
        let session = Session::new(&s, Drafting::EXACT);
        assert_eq!(session.kin_sheets().expect("sheets"), sheets, "{scene}");
        let sc = session.kin_scales().expect("scales");
        let d = session
            .kinematics(&sc)
            .expect("study")
            .diagrams
            .expect("diagrams");
        let phi = d.scales.x.value();
        match turn_mm {
            Some(mm) => assert!((TAU / phi - mm).abs() < 1e-9, "{scene}: {} mm", TAU / phi),
            None => assert_eq!(Some(d.scales.x), s.kinematics.scale_phi, "{scene}"),
        }
    }
}

/// The six-bar's change point (position 6, links 2 and 3 in line) is a corner of S(φ): the
/// chart draws S as a piece on each side and differentiates each alone, so the positions
/// beside it read their v and a off their own piece. One smooth curve across the corner read
/// v 28 % off at position 5 and 63 % at 7, a 95 % at 5.
#[test]
fn the_six_bar_chart_breaks_at_its_change_point() {
    let v = report_json("constructions/six-bar.toml", "0");
    let delta = |q: &str, position: &str| {
        rows(&v)
            .into_iter()
            .find(|r| {
                r["quantity"] == q && r["position"] == position && r["method"] == "diagram-chords"
            })
            .and_then(|r| r["rel_error"].as_f64())
            .unwrap_or_else(|| panic!("no {q} at {position}"))
            .abs()
    };
    for (q, position, bound) in [
        ("v_E", "5", 0.01),
        ("v_E", "7", 0.16),
        ("a_E", "4", 0.04),
        ("a_E", "5", 0.03),
        ("a_E", "7", 0.04),
    ] {
        let d = delta(q, position);
        assert!(d < bound, "{q} at {position}: {:.1} %", 100.0 * d);
    }
    let scene = tmm::load(&root().join("constructions/six-bar.toml")).expect("six-bar");
    let session = tmm::study::Session::new(&scene, Drafting::EXACT);
    let study = session
        .kinematics(&session.kin_scales().expect("scales"))
        .expect("kinematics");
    let chart = study.diagrams.as_ref().expect("the S chart");
    assert_eq!(
        chart
            .first
            .breaks
            .iter()
            .map(|b| b.node)
            .collect::<Vec<_>>(),
        vec![5],
        "position 6 is node 5"
    );
    let curves = |f: &tmm::construct::Figure| {
        (f.steps.iter())
            .filter(|s| matches!(s.item, tmm::construct::Item::Curve { .. }))
            .count()
    };
    // S and dS/dφ a piece on each side of the corner; d²S/dφ² likewise.
    assert_eq!(curves(&chart.first_figure), 4);
    assert_eq!(curves(&chart.second_figure), 2);
}

/// The six-bar's slider E stands four times a turn (issue 45): at 10′ and 6′, its extreme
/// positions, at the change point 6 (a kink of S, no stop), and at φ₁ = 229,06°, where D, C
/// and E line up and E reaches the same end as at 6′ (x_E = −OD − DC − CE = −1050 mm), comes
/// back 49 mm and reaches it again. The sheet names that stop with the
/// extreme positions; the slider-crank, which stands twice, names none.
#[test]
fn a_slider_that_reaches_its_end_twice_a_turn_says_where() {
    let stops = |scene: &str| {
        let scene = tmm::load(&root().join(format!("constructions/{scene}.toml"))).expect(scene);
        let plates = tmm::render::plates(&scene, tmm::Lang::Ru, Drafting::EXACT).expect("plates");
        plates
            .iter()
            .flat_map(|(_, p)| p.texts.iter().flat_map(|t| t.lines.iter()))
            .filter(|t| t.contains("= 0 также при"))
            .cloned()
            .collect::<Vec<String>>()
    };
    assert_eq!(
        stops("six-bar"),
        ["v_{E} = 0 также при φ_1 = 229,06° (крайнее положение, как 6′)"]
    );
    assert!(stops("slider-crank").is_empty());
}

/// The S chart is drawn through the extreme positions the plan draws between the numbered
/// ones, as the draughtsman plots them (issue 45): the six-bar's S reaches its stroke
/// H = 205,7 mm at 6′, between positions 6 and 7, where the curve through the numbered
/// positions alone stopped 1,7 mm lower on the sheet (7 mm of S), and touches 0 at 10′; both
/// are numbered on the φ axis. The shaper's 8′, 2,7 mm past position 8, is plotted but not
/// numbered there.
#[test]
fn the_s_chart_is_drawn_through_the_extreme_positions() {
    use tmm::construct::{Item, Role};
    for (scene, crest_between, marks) in [
        ("six-bar", (5.0, 6.0), &["6′", "10′"][..]),
        ("shaper", (7.0, 8.0), &[][..]),
    ] {
        let s =
            tmm::scene::load(&root().join(format!("constructions/{scene}.toml"))).expect("scene");
        let session = tmm::study::Session::new(&s, Drafting::EXACT);
        let study = session
            .kinematics(&session.kin_scales().expect("scales"))
            .expect("kinematics");
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
        let labels: Vec<&str> = (chart.first_figure.steps.iter())
            .filter(|st| st.note.ends_with("on the φ axis"))
            .filter_map(|st| st.label.as_ref().map(|l| l.text.as_str()))
            .filter(|t| t.contains('′'))
            .collect();
        assert_eq!(labels, marks, "{scene}");
    }
}

/// One of a crank turn's twelve intervals, rad.
const TAU_OVER_12: f64 = std::f64::consts::TAU / 12.0;
