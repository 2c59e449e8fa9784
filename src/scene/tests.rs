//! Scene loading: the example files give the right SI values; each class of bad input is
//! reported with its key and value.

use super::*;
use crate::linkage::{Branch, Dir, Dyad, Output, Sense};
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

/// A scene of `constructions/`.
fn construction(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("constructions")
        .join(name)
}

/// The shaper's text.
fn shaper_text() -> String {
    std::fs::read_to_string(construction("shaper.toml")).unwrap_or_default()
}

/// Load a constructions file, failing the test with the error text.
fn loaded(name: &str) -> Scene {
    match load(&construction(name)) {
        Ok(scene) => scene,
        Err(e) => panic!("{name} should load:\n{e}"),
    }
}

/// The shaper with `from` replaced by `to` (which must occur), parsed: its error text.
fn shaper_error(from: &str, to: &str) -> String {
    let text = shaper_text();
    assert!(text.contains(from), "the shaper has no {from:?}");
    match parse(
        &text.replacen(from, to, 1),
        Path::new("constructions/x.toml"),
    ) {
        Ok(_) => panic!("{from:?} → {to:?} should be refused"),
        Err(e) => e.to_string(),
    }
}

/// Assert that the message contains every one of `parts`.
fn assert_names(msg: &str, parts: &[&str]) {
    for p in parts {
        assert!(msg.contains(p), "wanted {p:?} in:\n{msg}");
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-12
}

#[test]
fn shaper_loads_in_si_units() {
    let s = loaded("shaper.toml");
    let m = s.mechanism.as_ref().expect("a mechanism");
    assert_eq!(s.stem, "shaper");
    assert_eq!(s.title.title, "Поперечно-строгальный станок");
    assert!(close(m.crank.length, 0.14));
    assert!(close(m.crank.omega, 5.0 * PI));
    assert_eq!(m.crank.sense, Sense::Clockwise);
    assert!(close(m.fixed[0].at.y, 0.43) && close(m.fixed[0].at.x, 0.0));
    assert_eq!(s.scale_l.map(|k| k.value()), Some(0.0025));
    let Dyad::Rpp {
        slide,
        guide,
        joint,
        ..
    } = &m.groups[1].dyad
    else {
        panic!("group 2 should be RPP");
    };
    assert_eq!(slide, &Dir::Fixed(PI / 2.0));
    assert!(close(guide.offset, 0.745));
    assert_eq!(joint, "E");
    assert!(close(m.points[0].along, 0.71));
    assert_eq!(m.redundant[0].links, [5, 0]);
    assert!(m.redundant[0].prismatic);
    assert_eq!(m.outputs[0], Output::Rocker { link: 3 });
    assert_eq!(
        s.positions,
        PositionSpec {
            count: 12,
            start: Start::WorkingStroke,
            other_extreme: true,
            continuity: false
        }
    );
    assert_eq!(
        s.plates,
        vec![
            PlateKind::Positions,
            PlateKind::Kinematics,
            PlateKind::Forces,
            PlateKind::Cam,
            PlateKind::Gears,
            PlateKind::Dynamics,
            PlateKind::Flywheel
        ]
    );
}

#[test]
fn slider_crank_loads_with_rpm() {
    let s = loaded("slider-crank.toml");
    let m = s.mechanism.as_ref().expect("a mechanism");
    assert!(close(m.crank.omega, 10.0 * PI));
    assert_eq!(m.crank.sense, Sense::CounterClockwise);
    let Dyad::Rrp {
        la, guide, branch, ..
    } = &m.groups[0].dyad
    else {
        panic!("group 1 should be RRP");
    };
    assert!(close(*la, 0.22) && close(guide.offset, 0.025));
    assert_eq!(*branch, Branch::Forward);
    assert_eq!(s.title.title, "Кривошипно-ползунный механизм");
    assert_eq!(s.scale_l, None);
}

#[test]
fn four_bar_loads_as_crank_rocker() {
    let s = loaded("four-bar.toml");
    let m = s.mechanism.as_ref().expect("a mechanism");
    assert!(close(m.crank.omega, 10.0));
    assert_eq!(m.crank.sense, Sense::Clockwise);
    let Dyad::Rrr { la, lb, branch, .. } = &m.groups[0].dyad else {
        panic!("group 1 should be RRR");
    };
    assert!(close(*la, 0.25) && close(*lb, 0.18));
    assert_eq!(*branch, Branch::Left);
    assert!(close(m.points[0].along, 0.125));
    assert_eq!(m.outputs[0], Output::Rocker { link: 3 });
}

#[test]
fn negative_length_is_refused() {
    let msg = shaper_error("length = 140.0", "length = -140");
    assert_names(
        &msg,
        &["constructions/x.toml: mechanism.crank.length = -140: expected a length > 0 mm"],
    );
}

#[test]
fn zero_length_is_refused() {
    let extra = "\n[[mechanism.point]]\nname = \"Q\"\nlink = 3\nalong = 0.0\nacross = -5.0\n";
    let zero_along =
        parse(&(shaper_text() + extra), Path::new("x.toml")).map_err(|e| e.to_string());
    assert!(zero_along.is_ok(), "along may be 0: {zero_along:?}");
    let msg = shaper_error("length = 140.0", "length = 0.0");
    assert_names(
        &msg,
        &["mechanism.crank.length = 0: expected a length > 0 mm"],
    );
}

#[test]
fn nan_is_refused() {
    let msg = shaper_error("offset = 745.0", "offset = nan");
    assert_names(
        &msg,
        &["mechanism.group[1].guide.offset = nan: expected a finite distance"],
    );
}

#[test]
fn inf_is_refused() {
    let msg = shaper_error("at = [0.0, 430.0]", "at = [0.0, inf]");
    assert_names(
        &msg,
        &["mechanism.fixed[0].at = inf: expected a finite coordinate"],
    );
}

#[test]
fn string_for_number_keeps_line_and_key() {
    let msg = shaper_error("length = 140.0", "length = \"140\"");
    let line = 1 + shaper_text()
        .lines()
        .position(|l| l.contains("length = 140.0"))
        .expect("the crank's length");
    assert_names(
        &msg,
        &[
            &format!("constructions/x.toml:{line}:"),
            "mechanism.crank.length = \"140\"",
            "invalid type",
        ],
    );
}

#[test]
fn missing_key_is_named() {
    let msg = shaper_error("length = 140.0\n", "");
    assert_names(
        &msg,
        &["mechanism.crank.length: missing: expected a length > 0 mm"],
    );
}

#[test]
fn unknown_key_is_named() {
    let msg = shaper_error("length = 140.0", "lenght = 140.0");
    assert_names(&msg, &["mechanism.crank.lenght", "unknown field `lenght`"]);
}

#[test]
fn unknown_point_name_is_named() {
    let msg = shaper_error("a = \"D\"", "a = \"X\"");
    assert_names(
        &msg,
        &["mechanism.group[1].a = \"X\": expected a known point"],
    );
}

#[test]
fn point_before_its_link_is_attached_is_refused() {
    let msg = shaper_error("a = \"B\"", "a = \"D\"");
    assert_names(
        &msg,
        &[
            "mechanism.group[0].a = \"D\"",
            "mechanism.point[0].name, not attached yet",
        ],
    );
}

#[test]
fn duplicate_link_number_is_refused() {
    let msg = shaper_error("links = [4, 5]", "links = [3, 5]");
    assert_names(&msg, &["mechanism.group[1].links = [3, 5]: expected a new link number; link 3 is already mechanism.group[0].links"]);
}

#[test]
fn duplicate_point_name_is_refused() {
    let msg = shaper_error("name = \"S_3\"", "name = \"D\"");
    assert_names(&msg, &["mechanism.point[1].name = \"D\": expected a new point name; it is already mechanism.point[0].name"]);
}

#[test]
fn wrong_branch_for_the_kind_is_refused() {
    let msg = shaper_error("offset = 0.0", "offset = 0.0\nbranch = \"left\"");
    assert_names(
        &msg,
        &["mechanism.group[0].branch = \"left\": not a key of an RPR group"],
    );
    let msg = shaper_error("offset = 0.0", "offset = 0.0\nla = 250.0");
    assert_names(
        &msg,
        &["mechanism.group[0].la = 250: not a key of an RPR group"],
    );
}

#[test]
fn branch_word_must_fit_the_kind() {
    let text = std::fs::read_to_string(construction("four-bar.toml")).unwrap_or_default();
    let bad = text.replacen("branch = \"left\"", "branch = \"forward\"", 1);
    let msg = parse(&bad, Path::new("x.toml"))
        .map(|_| ())
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert_names(
        &msg,
        &["mechanism.group[0].branch = \"forward\": expected \"left\" or \"right\""],
    );
}

#[test]
fn both_omega_and_n_are_refused() {
    let msg = shaper_error("sense = \"cw\"", "sense = \"cw\"\nn = 150.0");
    assert_names(
        &msg,
        &["mechanism.crank.omega = 15.707963267948966, n = 150: expected either omega"],
    );
}

#[test]
fn mobility_other_than_one_is_refused() {
    let msg = shaper_error("links = [5, 0]", "links = [5, 3]");
    assert_names(
        &msg,
        &[
            "mechanism: W = 3·5 − 2·(8 − 0) = -1: expected W = 1",
            "mechanism.redundant[0]",
        ],
    );
}

#[test]
fn zero_count_is_refused() {
    let msg = shaper_error("count = 12", "count = 0");
    assert_names(
        &msg,
        &["positions.count = 0: expected a number of positions from 1 to 360"],
    );
}

#[test]
fn no_output_is_refused() {
    let text = shaper_text();
    let cut = text.find("[[mechanism.output]]").unwrap_or(0);
    let rest = text.find("[positions]").unwrap_or(0);
    let bad = format!("{}{}", &text[..cut], &text[rest..]);
    let msg = parse(&bad, Path::new("x.toml"))
        .map(|_| ())
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert_names(&msg, &["mechanism.output: missing: expected at least one"]);
}

#[test]
fn several_problems_are_listed_one_per_line() {
    let text = shaper_text()
        .replacen("length = 140.0", "length = -1.0", 1)
        .replacen("count = 12", "count = 400", 1);
    let Err(e) = parse(&text, Path::new("x.toml")) else {
        panic!("should be refused");
    };
    assert_eq!(e.problems().len(), 2);
    assert_eq!(e.to_string().lines().count(), 2);
}

#[test]
fn defaults_apply() {
    let text = shaper_text();
    let cut = text.find("[positions]").unwrap_or(text.len());
    let s = parse(&text[..cut], Path::new("dir/bare.toml")).map_err(|e| e.to_string());
    let s = s.unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.positions.count, 12);
    assert_eq!(s.plates, vec![PlateKind::Positions]);
    assert_eq!(s.stem, "bare");
}

#[test]
fn cyrillic_kind_and_start_angle_are_accepted() {
    let text = shaper_text()
        .replacen("kind = \"RPR\"", "kind = \"впв\"", 1)
        .replacen("start = \"working-stroke\"", "start = 90", 1);
    let s = parse(&text, Path::new("x.toml")).map_err(|e| e.to_string());
    let s = s.unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.positions.start, Start::Angle(PI / 2.0));
}

#[test]
fn string_for_direction_is_refused_with_the_forms() {
    let msg = shaper_error("slide = 90.0", "slide = \"up\"");
    assert_names(
        &msg,
        &["mechanism.group[1].slide = \"up\": expected a direction"],
    );
}

#[test]
fn crank_centre_must_be_fixed() {
    let msg = shaper_error("centre = \"A\"", "centre = \"B\"");
    assert_names(
        &msg,
        &["mechanism.crank.centre = \"B\": expected a fixed point"],
    );
}

#[test]
fn unreadable_file_is_reported() {
    let msg = load(Path::new("constructions/no-such.toml"))
        .map(|_| ())
        .err()
        .map(|e| e.to_string());
    assert_names(
        &msg.unwrap_or_default(),
        &["constructions/no-such.toml: cannot read the file"],
    );
}

#[test]
fn shaper_kinematics_load() {
    let k = loaded("shaper.toml").kinematics;
    let value = |s: Option<crate::scale::Scale>| s.map(|s| s.value());
    assert_eq!(value(k.scale_v), Some(0.05));
    assert_eq!(value(k.scale_a), Some(1.0));
    assert_eq!(value(k.scale_s), Some(0.005));
    assert_eq!(value(k.scale_phi), Some(0.052));
    assert_eq!(
        k.scale_v.map(|s| s.quantity),
        Some(crate::scale::Quantity::Velocity)
    );
    assert_eq!(
        k.acceleration_positions,
        Some(vec!["3".to_string(), "10".to_string()])
    );
    assert_eq!(k.pole_h1, Some(28.0));
    assert_eq!(k.pole_h2, Some(7.5));
    assert_eq!(k.diagram_point.as_deref(), Some("S_5"));
    assert_eq!(k.hodograph.as_deref(), Some("S_3"));
}

#[test]
fn kinematics_defaults_to_none() {
    assert_eq!(
        loaded("four-bar.toml").kinematics,
        KinematicsSpec::default()
    );
}

#[test]
fn ascii_prime_is_normalised() {
    let text = shaper_text().replacen(
        "acceleration_positions = [\"3\", \"10\"]",
        "acceleration_positions = [\"8'\", \"10\"]",
        1,
    );
    let s = parse(&text, Path::new("x.toml")).map_err(|e| e.to_string());
    let labels = s.map(|s| s.kinematics.acceleration_positions);
    assert_eq!(labels, Ok(Some(vec!["8′".to_string(), "10".to_string()])));
}

#[test]
fn bad_kinematics_values_are_refused_by_key() {
    let cases = [
        (
            "scale_v = 0.05",
            "scale_v = 0.0",
            "kinematics.scale_v = 0: expected a scale μ_v > 0",
        ),
        (
            "pole_h1 = 28.0",
            "pole_h1 = nan",
            "kinematics.pole_h1 = nan: expected a pole distance H₁ > 0 mm",
        ),
        (
            "scale_phi = 0.052",
            "scale_phi = inf",
            "kinematics.scale_phi = inf: expected a scale μ_φ > 0",
        ),
        (
            "acceleration_positions = [\"3\", \"10\"]",
            "acceleration_positions = [\"3\", \"13\"]",
            "kinematics.acceleration_positions[1] = \"13\": expected a position label from \"1\" to \"12\"",
        ),
        (
            "acceleration_positions = [\"3\", \"10\"]",
            "acceleration_positions = [\"1\", \"2\", \"3\", \"4\", \"5\"]",
            "kinematics.acceleration_positions = [\"1\", \"2\", \"3\", \"4\", \"5\"]: expected 1 to 4",
        ),
        (
            "acceleration_positions = [\"3\", \"10\"]",
            "acceleration_positions = []",
            "kinematics.acceleration_positions = []: expected 1 to 4",
        ),
        (
            "diagram = \"S_5\"",
            "diagram = \"Z\"",
            "kinematics.diagram = \"Z\": expected a point of the mechanism",
        ),
        (
            "hodograph = \"S_3\"",
            "hodograph = \"\"",
            "kinematics.hodograph = \"\": expected a point of the mechanism",
        ),
    ];
    for (from, to, want) in cases {
        assert_names(&shaper_error(from, to), &[want]);
    }
    let msg = shaper_error("pole_h2 = 7.5", "pole_h3 = 7.5");
    assert_names(&msg, &["kinematics.pole_h3", "unknown field"]);
}

#[test]
fn kinematics_plate_kind_parses() {
    assert_eq!(PlateKind::parse("kinematics"), Some(PlateKind::Kinematics));
    assert_eq!(PlateKind::Kinematics.stem(), "kinematics");
    let section = |k: PlateKind| k.study().map(|s| s.section);
    assert_eq!(section(PlateKind::Kinematics), Some(Section::Mechanism));
    assert_eq!(
        section(PlateKind::Gears).map(|s| s.to_string()),
        Some("gears".into())
    );
    assert!(PlateKind::all().any(|k| k == PlateKind::Kinematics));
    let text = shaper_text().replacen(
        "wanted = [\"positions\", \"kinematics\", \"forces\", \"cam\", \"gears\", \"dynamics\", \"flywheel\"]",
        "wanted = [\"positions\", \"kinematics\"]",
        1,
    );
    let s = parse(&text, Path::new("x.toml")).map(|s| s.plates);
    assert_eq!(
        s.ok(),
        Some(vec![PlateKind::Positions, PlateKind::Kinematics])
    );
}

#[test]
fn six_bar_loads() {
    let s = loaded("six-bar.toml");
    let m = s.mechanism.as_ref().expect("a mechanism");
    assert_eq!(m.crank.sense, Sense::Clockwise);
    assert!(close(m.crank.omega, 100.0 * PI / 30.0));
    assert_eq!(m.groups[0].dyad.kind(), crate::linkage::DyadKind::Rrr);
    assert_eq!(m.groups[1].dyad.kind(), crate::linkage::DyadKind::Rrp);
    let c = &m.points[0];
    assert_eq!((c.name.as_str(), c.link), ("C", 3));
    assert!((c.along - 0.65 / 3.0).abs() < 1e-12);
    assert!((c.across + 0.05 * 56f64.sqrt() / 3.0).abs() < 1e-12);
    assert_eq!(s.positions.start, Start::Angle(-PI / 6.0));
    assert!(s.title.note.contains("реконструир"));
    assert_eq!(s.kinematics.diagram_point.as_deref(), Some("E"));
    assert_eq!(
        s.kinematics.acceleration_positions,
        Some(vec!["1".to_string()])
    );
}

#[test]
fn tangent_loads_with_a_crank_point_in_a_direction() {
    let s = loaded("tangent.toml");
    let m = s.mechanism.as_ref().expect("a mechanism");
    let Dyad::Prp {
        guide_i, guide_j, ..
    } = &m.groups[0].dyad
    else {
        panic!("group 1 should be PRP");
    };
    assert_eq!(guide_i.through, "A");
    assert_eq!(
        guide_i.dir,
        Dir::Along {
            from: "C".into(),
            to: "A".into(),
            angle: 0.0
        }
    );
    assert!(close(guide_j.offset, -0.2));
    assert_eq!(guide_j.dir, Dir::Fixed(PI / 2.0));
    assert_eq!(s.positions.start, Start::Angle(15f64.to_radians()));
}

#[test]
fn slider_output_across_its_guide_is_refused() {
    // E slides on the horizontal guide of group 2: along 90° its travel is 0 everywhere.
    let msg = shaper_error("slider = \"E\"\ndir = 0.0", "slider = \"E\"\ndir = 90.0");
    assert_names(
        &msg,
        &["mechanism.output[1].dir = 90: expected the direction of travel of E along its guide (mechanism.group[1], 0° or 180°)"],
    );
    // Along the guide, either way, it is accepted.
    let text = shaper_text().replacen(
        "slider = \"E\"\ndir = 0.0",
        "slider = \"E\"\ndir = 180.0",
        1,
    );
    parse(&text, Path::new("constructions/x.toml")).unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn mobility_counts_with_the_linkage_structure() {
    // A redundant pair that repeats the structure's E–frame prismatic pair is discounted.
    let s = loaded("shaper.toml");
    let st = crate::linkage::Structure::analyse(s.mechanism.as_ref().expect("a mechanism"));
    let w = st.mobility();
    assert_eq!((w.n, w.p5, w.p4, w.w), (5, 7, 0, 1));
}

/// A `[kinematics]` section that no sheet draws (no kinematics plate wanted) is read with a
/// warning naming its key and saying why; drawn, or absent, it gives none. No shipped scene
/// has one.
#[test]
fn kinematics_no_sheet_draws_is_warned_of() {
    let four_bar = std::fs::read_to_string(construction("four-bar.toml")).unwrap_or_default();
    let drawn = "[plates]\nwanted = [\"positions\", \"kinematics\"]\n";
    assert!(four_bar.contains(drawn));
    let section = "\n[kinematics]\nscale_v = 0.01\n";
    let warnings = |text: String| parse(&text, Path::new("x.toml")).map(|s| s.warnings);
    let no_table = warnings(four_bar.replacen(drawn, "", 1) + section).unwrap_or_default();
    assert_eq!(no_table.len(), 1, "{no_table:?}");
    assert_eq!(no_table[0].key, "kinematics");
    assert!(
        no_table[0].expected.contains("no [plates] table"),
        "{}",
        no_table[0]
    );
    let positions = "[plates]\nwanted = [\"positions\"]\n";
    let not_wanted = warnings(four_bar.replacen(drawn, positions, 1) + section);
    let not_wanted = not_wanted.unwrap_or_default();
    assert_eq!(not_wanted.len(), 1, "{not_wanted:?}");
    assert!(not_wanted[0].to_string().starts_with(
        "kinematics: no sheet draws it: [plates] wanted does not ask for the kinematics plate"
    ));
    assert_eq!(warnings(four_bar.clone() + section).ok(), Some(Vec::new()));
    assert_eq!(
        warnings(four_bar.replacen(drawn, "", 1)).ok(),
        Some(Vec::new())
    );
    let shipped = super::files_in(&construction("")).unwrap_or_default();
    assert!(shipped.len() >= 20, "{shipped:?}");
    for name in shipped {
        let s = load(&name).map(|s| s.warnings);
        assert_eq!(s.ok(), Some(Vec::new()), "{}", name.display());
    }
}
