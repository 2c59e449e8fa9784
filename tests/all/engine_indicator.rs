//! An engine's gas forces as a hand-in shows them (issue 45): the indicator diagram p(θ) is
//! drawn on the dynamics sheet with an ordinate at each position the force sheets analyse,
//! and each force sheet states θ, the p read there and F_д = p·πd²/4 for every cylinder.
//! The values here are worked from the scene's table by the test's own interpolation; the
//! frame's guides through fixed points are stated in the data of every language.

use crate::support::root;
use tmm::construct::{Drafting, Item};
use tmm::plate::Plate;
use tmm::scale::Lang;
use tmm::scene::{self, PlateKind};

/// The sheets of the shipped scene `name` in `lang`.
fn sheets(name: &str, lang: Lang) -> Vec<(PlateKind, Plate)> {
    let s = scene::load(&root().join("constructions").join(name)).unwrap_or_else(|e| panic!("{e}"));
    tmm::render::plates(&s, lang, Drafting::EXACT).unwrap_or_else(|e| panic!("{e}"))
}

/// The V engine's sheets of `kind`, in Russian.
fn engine_sheets(kind: PlateKind) -> Vec<Plate> {
    sheets("v-engine.toml", Lang::Ru)
        .into_iter()
        .filter(|(k, _)| *k == kind)
        .map(|(_, p)| p)
        .collect()
}

/// The V engine's indicator diagram (`constructions/v-engine.toml`, both cylinders): θ°, MPa.
const TABLE: [(f64, f64); 16] = [
    (0.0, 2.6),
    (10.0, 4.2),
    (25.0, 3.4),
    (45.0, 2.0),
    (70.0, 1.1),
    (100.0, 0.55),
    (120.0, 0.3),
    (140.0, 0.05),
    (180.0, 0.0),
    (220.0, 0.05),
    (240.0, 0.12),
    (270.0, 0.3),
    (300.0, 0.65),
    (320.0, 1.05),
    (340.0, 1.7),
    (360.0, 2.6),
];

/// The table's pressure at θ (degrees in [0, 360]), MPa: linear between its rows.
fn pressure(theta: f64) -> f64 {
    let k = TABLE.iter().rposition(|r| r.0 <= theta).expect("θ ≥ 0");
    let ((t0, p0), (t1, p1)) = (TABLE[k], TABLE[(k + 1).min(TABLE.len() - 1)]);
    if t1 > t0 {
        p0 + (p1 - p0) * (theta - t0) / (t1 - t0)
    } else {
        p0
    }
}

/// Each cylinder's reading at each force position: (ordinate's label, θ°, p MPa). The crank
/// turns counter-clockwise from position 1 at 45°, 30° a position: positions 3 and 6 are at
/// 105° and 195°; B's cycle starts at 45°, C's at 135°.
fn readings() -> Vec<(String, f64, f64)> {
    let mut out = Vec::new();
    for (label, phi) in [("3", 105.0), ("6", 195.0)] {
        for (piston, start) in [("B", 45.0), ("C", 135.0)] {
            let theta = f64::rem_euclid(phi - start, 360.0);
            // The piston's point at the position, subscripted as on the plan: B₃ (issue 45:
            // «B3» read as a name of its own).
            out.push((format!("{piston}_{{{label}}}"), theta, pressure(theta)));
        }
    }
    out
}

#[test]
fn the_dynamics_sheet_draws_the_indicator_diagram_with_the_force_positions_ordinates() {
    let dynamics = engine_sheets(PlateKind::Dynamics);
    assert_eq!(dynamics.len(), 1, "the diagram fits the one dynamics sheet");
    let view = dynamics[0]
        .views
        .iter()
        .find(|v| v.figure.title == "indicator diagram")
        .expect("the indicator diagram on the dynamics sheet");
    let mu_p = view.figure.scale.value();
    // 4,2 MPa at most 60 mm tall at a round μ_p: 0,1 MPa/mm.
    assert!((mu_p - 1e5).abs() < 1e-6, "μ_p = {mu_p} Pa/mm");
    for (label, theta, p) in readings() {
        let step = view
            .figure
            .steps
            .iter()
            .find(|s| s.note == format!("the ordinate {label}"))
            .unwrap_or_else(|| panic!("no ordinate {label}"));
        let Item::Segment(s) = &step.item else {
            panic!("the ordinate {label} is {:?}", step.item)
        };
        let read = (s.to - s.from).length() * mu_p * 1e-6;
        assert!(
            (read - p).abs() < 1e-9,
            "{label} at θ = {theta}°: {read} MPa, {p} MPa"
        );
        assert_eq!(
            step.label.as_ref().map(|l| l.text.as_str()),
            Some(label.as_str())
        );
    }
    let caption = view.caption.as_deref().unwrap_or_default();
    assert!(
        caption.starts_with("p(θ), μ_{p} = 0,1 МПа/мм, μ_{θ} = "),
        "{caption}"
    );
}

/// `x` (> 0) to four significant digits with a decimal comma, as the sheets write a force.
fn four_digits(x: f64) -> String {
    let decimals = (3 - x.log10().floor() as i32).max(0) as usize;
    format!("{x:.decimals$}").replace('.', ",")
}

#[test]
fn each_force_sheet_states_the_pressure_and_the_gas_force_of_every_cylinder() {
    let forces = engine_sheets(PlateKind::Forces);
    assert_eq!(forces.len(), 2);
    let area = std::f64::consts::PI * 0.07 * 0.07 / 4.0;
    let all = readings();
    for (plate, position) in forces.iter().zip(["3", "6"]) {
        let lines: Vec<&String> = plate.texts.iter().flat_map(|t| &t.lines).collect();
        for (piston, slider) in [("B", 3), ("C", 5)] {
            let (_, theta, p) = all
                .iter()
                .find(|r| r.0 == format!("{piston}_{{{position}}}"))
                .expect("a reading");
            let line = lines
                .iter()
                .find(|l| l.starts_with(&format!("θ_{{{piston}}} = ")))
                .unwrap_or_else(|| panic!("position {position}: no θ_{piston} line in {lines:#?}"));
            let theta = format!("= {theta}°,");
            let force = format!(
                "F_{{д{slider}}} = p_{{{piston}}}·πd_{{{piston}}}^2/4 = {} Н",
                four_digits(p * 1e6 * area)
            );
            assert!(line.contains(&theta), "{line}: {theta}");
            assert!(line.contains("(по индикаторной диаграмме p(θ))"), "{line}");
            assert!(line.ends_with(&force), "{line}: {force}");
        }
    }
}

#[test]
fn the_data_states_a_guide_given_through_fixed_points() {
    for (lang, words) in [
        (Lang::Ru, "Направляющая ползуна E проходит через O и D"),
        (Lang::Uk, "Напрямна повзуна E проходить через O і D"),
        (Lang::En, "The guide of slider E passes through O and D"),
    ] {
        let plates = sheets("six-bar.toml", lang);
        let found = plates
            .iter()
            .flat_map(|(_, p)| &p.texts)
            .flat_map(|t| &t.lines)
            .filter(|l| l.as_str() == words)
            .count();
        assert_eq!(found, 1, "{lang:?}: «{words}» once");
    }
    let engine: Vec<String> = sheets("v-engine.toml", Lang::Ru)
        .iter()
        .flat_map(|(_, p)| p.texts.clone())
        .flat_map(|t| t.lines)
        .filter(|l| l.starts_with("Направляющая"))
        .collect();
    assert_eq!(
        engine,
        [
            "Направляющая ползуна B проходит через O",
            "Направляющая ползуна C проходит через O"
        ]
    );
    // The shaper's slider runs on a guide off its fixed points: its height says so, and no
    // such line is written.
    let shaper = sheets("shaper.toml", Lang::Ru);
    assert!(shaper
        .iter()
        .flat_map(|(_, p)| &p.texts)
        .flat_map(|t| &t.lines)
        .all(|l| !l.starts_with("Направляющая")));
}

#[test]
fn the_note_works_each_gas_force_from_the_indicator_diagram() {
    let s =
        scene::load(&root().join("constructions/v-engine.toml")).unwrap_or_else(|e| panic!("{e}"));
    let session = tmm::study::Session::new(&s, Drafting::EXACT);
    let note = tmm::note::compose(&session, Lang::Ru).expect("note");
    // The formulas' digits are set apart: compared without white space.
    let text: String = tmm::note::to_text(&note)
        .expect("typeset")
        .split_whitespace()
        .collect();
    let area = std::f64::consts::PI * 0.07 * 0.07 / 4.0;
    for (label, theta, p) in readings() {
        let piston = &label[..1];
        let force = four_digits(p * 1e6 * area);
        let worked = format!("p{piston}𝜋d2{piston}4=");
        let pressure =
            format!("давлениегазоввцилиндре{piston}поиндикаторнойдиаграммеприθ={theta}°,Па");
        assert!(
            text.contains(&format!("={force}Н")),
            "{label}: F_д = {force} Н"
        );
        assert!(text.contains(&worked), "{label}: {worked}");
        assert!(text.contains(&pressure), "{label}: {pressure}");
    }
    assert_eq!(
        text.matches("Силыдавлениягазовнапоршни").count(),
        2,
        "at both positions"
    );
}
