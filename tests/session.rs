//! The study session: every position and every plan is constructed once, whatever asks for
//! it, and a scene without a mechanism is read and refused cleanly.

use std::path::PathBuf;
use tmm::construct::Drafting;
use tmm::scale::Lang;
use tmm::scene::{self, PlateKind};
use tmm::sheets;
use tmm::study::Session;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn shaper_render_constructs_each_position_and_plan_once() {
    let s = scene::load(&root().join("constructions/shaper.toml")).expect("shaper");
    let session = Session::new(&s, Drafting::EXACT);
    // What `tmm render constructions/shaper.toml` does: both plates through one session.
    for &kind in &s.plates {
        sheets::build(&session, kind, Lang::Ru).expect("plate");
    }
    let log = session.constructions();
    for (i, c) in log.iter().enumerate() {
        assert!(
            !log[..i].contains(c),
            "{} at position {} (μ = {}) constructed twice",
            c.what,
            c.position,
            c.scale.value()
        );
    }
    let count = |what: &str| log.iter().filter(|c| c.what == what).count();
    // 12 numbered positions and the extreme 8′.
    assert_eq!(count("velocity plan"), 13);
    assert_eq!(count("acceleration plan"), 2);
    // Both sheets draw the plan of positions at the scene's μ_l = 0.0025: each of the 13
    // positions is constructed once.
    let scales: Vec<f64> = log
        .iter()
        .filter(|c| c.what == "position")
        .map(|c| c.scale.value())
        .collect();
    assert!(scales.iter().all(|&s| s == 0.0025), "{scales:?}");
    assert_eq!(count("position"), 13);
    // The plates asked again, and the report at the sheet's scales, construct nothing new.
    for &kind in &s.plates {
        sheets::build(&session, kind, Lang::En).expect("plate");
    }
    assert_eq!(session.constructions().len(), log.len());
}

#[test]
fn report_reuses_the_positions_of_the_positions_sheet() {
    let s = scene::load(&root().join("constructions/shaper.toml")).expect("shaper");
    let session = Session::new(&s, Drafting::EXACT);
    sheets::build(&session, PlateKind::Positions, Lang::Ru).expect("plate");
    let before = session.constructions().len();
    let report = session.report().expect("report");
    let new: Vec<_> = session.constructions().split_off(before);
    // The report works at the scene's μ_l = 0.0025: the positions are there already.
    assert!(new.iter().all(|c| c.what != "position"), "{new:?}");
    assert_eq!(new.iter().filter(|c| c.what == "velocity plan").count(), 13);
    assert!(report.rows.len() > 100);
}

#[test]
fn a_scene_with_only_a_task_is_read() {
    let s = scene::parse("[task]\ntitle = \"Кулачок\"\n", &root().join("cam.toml"))
        .expect("a scene without a mechanism is valid");
    assert!(s.mechanism.is_none());
    assert!(s.plates.is_empty());
    let session = Session::new(&s, Drafting::EXACT);
    let err = session.report().unwrap_err().to_string();
    assert!(err.contains("no [mechanism]"), "{err}");
}

#[test]
fn sections_that_study_a_mechanism_need_one() {
    let text =
        "[task]\ntitle = \"x\"\n[positions]\ncount = 12\n[plates]\nwanted = [\"kinematics\"]\n";
    let msg = scene::parse(text, &root().join("x.toml"))
        .unwrap_err()
        .to_string();
    assert!(
        msg.contains("positions") && msg.contains("[mechanism]"),
        "{msg}"
    );
    assert!(msg.contains("plates.wanted[0]"), "{msg}");
}
