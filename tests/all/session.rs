//! The study session: every position and every plan is constructed once, whatever asks for
//! it, and a scene without a mechanism is read and refused cleanly.

use crate::support;

use support::root;
use tmm::construct::Drafting;
use tmm::linkage::PlanKind;
use tmm::scale::Lang;
use tmm::scene::{self, PlateKind};
use tmm::sheets;
use tmm::study::{Constructed, Session};

/// Every construction of `log` is there once.
fn assert_once(stem: &str, log: &[Constructed]) {
    for (i, c) in log.iter().enumerate() {
        assert!(
            !log[..i].contains(c),
            "{stem}: {} at position {} (μ = {}) constructed twice",
            c.what,
            c.position,
            c.scale.value()
        );
    }
}

#[test]
fn every_scene_constructs_each_position_and_plan_once() {
    for path in support::scene_paths() {
        let s = scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        let session = Session::new(&s, Drafting::EXACT);
        // What `tmm render` and `tmm report` do: every plate in two languages and the report
        // through one session.
        for lang in [Lang::Ru, Lang::En] {
            sheets::build_all(&session, lang).unwrap_or_else(|(k, e)| panic!("{k:?}: {e}"));
        }
        session
            .report()
            .unwrap_or_else(|e| panic!("{}: {e}", s.stem));
        let log = session.constructions();
        assert_once(&s.stem, &log);
        // The plan of positions at the μ_l the session decided, and — when the scene analyses
        // forces and the force sheets draw their groups at a μ_l of their own — at that one.
        let positions: Vec<&Constructed> = log.iter().filter(|c| c.what == "position").collect();
        let mut scales = Vec::new();
        if s.mechanism.is_some() {
            scales.push(session.scale_l().expect("μ_l"));
        }
        if s.mechanism.is_some() && s.forces.is_some() {
            let l = session.force_scale_l().expect("force μ_l");
            if !scales.contains(&l) {
                scales.push(l);
            }
        }
        let expected = match s.mechanism {
            Some(_) => session.poses().expect("poses").positions.len() * scales.len(),
            None => 0,
        };
        assert_eq!(positions.len(), expected, "{}: {positions:?}", s.stem);
        assert!(
            positions.iter().all(|c| scales.contains(&c.scale)),
            "{}",
            s.stem
        );
    }
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
    assert_once("shaper", &log);
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

#[test]
fn tangent_report_at_drafting_reads_the_plans_its_plates_draw() {
    let s = scene::load(&root().join("constructions/tangent.toml")).expect("tangent");
    // `--drafting 0.5`.
    let session = Session::new(&s, Drafting::new(0.5).expect("drafting"));
    sheets::build_all(&session, Lang::Ru).unwrap_or_else(|(k, e)| panic!("{k:?}: {e}"));
    let drawn = session.constructions();
    let sc = session.kin_scales().expect("scales");
    // The plates draw the plan of positions at the session's μ_l, the plans at its μ_v, μ_a.
    let at = |what: &str| -> Vec<f64> {
        drawn
            .iter()
            .filter(|c| c.what == what)
            .map(|c| c.scale.value())
            .collect()
    };
    let positions = at("position");
    assert!(!positions.is_empty());
    assert!(
        positions.iter().all(|&l| l == sc.l.value()),
        "{positions:?}"
    );
    // Each plan at its μ: the common one, or its own where it is far larger than the rest
    // (near φ = 90°, 270°); every one of them drawn large enough to read.
    let plan = session.positions(sc.l).expect("positions");
    let mut own = 0;
    for (k, p) in plan.positions.iter().enumerate() {
        let mu = session.plan_scale(PlanKind::Velocity, k).expect("μ_v");
        let logged: Vec<f64> = drawn
            .iter()
            .filter(|c| c.what == "velocity plan" && c.position == p.label)
            .map(|c| c.scale.value())
            .collect();
        assert_eq!(logged, vec![mu.value()], "position {}", p.label);
        own += usize::from(mu != sc.v);
        let vel = session.velocity(&sc, k).expect("plan");
        let (lo, hi) = vel.plan().expect("built").figure.bounds().expect("drawn");
        assert!(
            (hi - lo).max_element() >= 30.0,
            "position {}: {:?}",
            p.label,
            hi - lo
        );
    }
    assert!(
        (1..plan.positions.len() / 2).contains(&own),
        "{own} plans at their own μ_v"
    );
    assert!(
        sc.v.value() < 0.4,
        "the common μ_v {} is set by the typical plans",
        sc.v.value()
    );
    for k in session.acceleration_positions().expect("positions") {
        let mu = session.plan_scale(PlanKind::Acceleration, k).expect("μ_a");
        let label = &plan.positions[k].label;
        assert!(drawn
            .iter()
            .any(|c| c.what == "acceleration plan" && &c.position == label && c.scale == mu));
    }
    // The plan fitted to its field: coarser than the crank drawn 50 mm (0.002).
    assert_eq!(sc.l.value(), 0.004);
    // The report constructs nothing new: it reads the very plans the plates draw.
    let report = session.report().expect("report");
    let new = session.constructions().split_off(drawn.len());
    assert!(new.is_empty(), "{new:?}");
    let read = session.kinematics(&sc).expect("kinematics").rows();
    let plan_rows = |rows: &[tmm::Row]| -> Vec<tmm::Row> {
        rows.iter()
            .filter(|r| r.method == tmm::Method::Plan)
            .cloned()
            .collect()
    };
    let rows = plan_rows(&report.rows);
    assert!(rows.len() > 20, "{}", rows.len());
    assert_eq!(rows, plan_rows(&read));
    // At 0.5 mm the readings are the drawing's: not exact.
    assert!(rows.iter().any(|r| r.graphical != r.analytic));
}

#[test]
fn plates_built_side_by_side_are_those_built_one_after_another() {
    // The shaper's sheets share their studies (the gear sheet's blocking contour runs on the
    // pool meanwhile). Built on plain threads from here, and on every thread of the pool at
    // once (where each builds them in turn: pool threads all waiting for threads whose
    // studies need the pool would wait for ever), within a bound rather than hanging.
    let s = scene::load(&root().join("constructions/shaper.toml")).expect("shaper");
    let svgs = |plates: Vec<(PlateKind, tmm::plate::Plate)>| -> Vec<String> {
        plates.iter().map(|(_, p)| tmm::plate::to_svg(p)).collect()
    };
    let side_by_side = svgs(
        sheets::build_all(&Session::new(&s, Drafting::EXACT), Lang::Ru)
            .unwrap_or_else(|(k, e)| panic!("{k:?}: {e}")),
    );
    // The contour traced afresh (each session its own), on the pool.
    let (tx, rx) = std::sync::mpsc::channel();
    let scene = s.clone();
    std::thread::spawn(move || {
        let built = rayon::broadcast(|_| {
            sheets::build_all(&Session::new(&scene, Drafting::EXACT), Lang::Ru)
                .map_err(|(k, e)| format!("{k:?}: {e}"))
        });
        let _ = tx.send(built);
    });
    let in_turn = rx
        .recv_timeout(std::time::Duration::from_secs(120))
        .expect("built on the pool's threads within two minutes");
    for built in in_turn {
        assert_eq!(svgs(built.unwrap_or_else(|e| panic!("{e}"))), side_by_side);
    }
}

/// A dynamic study at a count of its own (`[dynamics] count` ≠ `[positions] count`) builds its
/// own plan of positions and velocity plans: in the session's log, each once, and not again
/// when asked again.
#[test]
fn a_dynamics_count_of_its_own_is_constructed_once_and_logged() {
    let text = std::fs::read_to_string(root().join("constructions/shaper.toml")).expect("shaper");
    let text = text.replacen("[dynamics]\n", "[dynamics]\ncount = 24\n", 1);
    let s = scene::parse(&text, &root().join("constructions/shaper.toml")).expect("parsed");
    let session = Session::new(&s, Drafting::EXACT);
    session.dynamics().expect("dynamics");
    let log = session.constructions();
    assert_once("shaper, dynamics.count = 24", &log);
    let count = |what: &str| log.iter().filter(|c| c.what == what).count();
    assert_eq!(count("dynamics position"), 24);
    assert_eq!(count("dynamics velocity plan"), 24);
    session.dynamics().expect("dynamics again");
    assert_eq!(session.constructions().len(), log.len());
}

/// The acceleration plans are drawn where the forces are analysed: the inertia forces of a
/// force sheet are read off the plan of its position (seed 000 draws plans 3 and 10 for its
/// force sheets 3 and 10). A scene with `[forces]` and no `acceleration_positions` draws
/// them at the force positions (the V engine's 3 and 6, the slider-crank's 2 and 5, on the
/// kinematic sheets a student hands in); one that names its plans keeps them (the six-bar's
/// 1); a scene without forces keeps the textbook's middles of the two strokes.
#[test]
fn the_acceleration_plans_are_drawn_at_the_force_positions() {
    for (name, drawn) in [
        ("v-engine", vec!["3", "6"]),
        ("slider-crank", vec!["2", "5"]),
        ("shaper", vec!["3", "10"]),
        ("six-bar", vec!["1"]),
        ("four-bar", vec!["4", "10"]),
    ] {
        let s = scene::load(&root().join(format!("constructions/{name}.toml"))).expect("scene");
        let session = Session::new(&s, Drafting::EXACT);
        let kind = PlateKind::parse("kinematics").expect("kind");
        let captions: Vec<String> = tmm::build(&session, kind, Lang::Ru)
            .expect("sheets")
            .iter()
            .flat_map(|p| p.views.iter().filter_map(|v| v.caption.clone()))
            .filter(|c| c.starts_with("План ускорений"))
            .collect();
        let at: Vec<String> = captions
            .iter()
            .map(|c| {
                let pos = c.split("пол. ").nth(1).expect("a position");
                pos.split(',').next().unwrap_or(pos).to_string()
            })
            .collect();
        assert_eq!(at, drawn, "{name}: {captions:?}");
        if s.kinematics.acceleration_positions.is_none() {
            if let Some(f) = &s.forces {
                assert_eq!(f.positions, drawn, "{name}");
            }
        }
    }
}

/// `kinematics.own_scale_a`: the shaper's acceleration plan 3, whose largest vector
/// (a_B1 = 34,5 m/s²) is 35 mm at the seed's μ_a = 1, is drawn at a μ_a of its own, the crank
/// pin's acceleration at least 80 mm; plan 10 keeps the seed's μ_a and both velocity plans the
/// seed's μ_v. Without the key plan 3 is drawn at μ_a = 1; a position with no acceleration
/// plan is refused by name.
#[test]
fn an_acceleration_plan_takes_a_scale_of_its_own() {
    let text = std::fs::read_to_string(root().join("constructions/shaper.toml")).expect("scene");
    let line = "own_scale_a = [\"3\"]";
    assert!(text.contains(line), "the shaper asks for plan 3's own μ_a");
    let mu = |text: &str, kind: PlanKind, k: usize| {
        let s = scene::parse(text, &root().join("x.toml")).expect("scene");
        let session = Session::new(&s, Drafting::EXACT);
        session.plan_scale(kind, k).expect("μ").value()
    };
    // Position 3 is index 2, position 10 index 10 (8′ comes after 8).
    let (three, ten) = (2, 10);
    let a3 = mu(&text, PlanKind::Acceleration, three);
    let a_b1 = 0.14 * (5.0 * std::f64::consts::PI).powi(2);
    assert!(a_b1 / a3 >= 80.0 && a3 < 1.0, "μ_a of plan 3: {a3}");
    assert_eq!(mu(&text, PlanKind::Acceleration, ten), 1.0);
    assert_eq!(mu(&text, PlanKind::Velocity, three), 0.05);
    let without = text.replace(line, "");
    assert_eq!(mu(&without, PlanKind::Acceleration, three), 1.0);
    let wrong = text.replace(line, "own_scale_a = [\"4\"]");
    let s = scene::parse(&wrong, &root().join("x.toml")).expect("scene");
    let err = Session::new(&s, Drafting::EXACT)
        .report()
        .expect_err("no plan at 4")
        .to_string();
    assert!(
        err.contains("kinematics.own_scale_a: position 4 has no acceleration plan; the acceleration plans are at 3, 10"),
        "{err}"
    );
}

/// The two acceleration plans a scene gets by default show the mechanism in two different
/// configurations: the tangent mechanism's plans at 5 and 11 (half a turn apart) drew its
/// block where it stood, on the crank's one line, with the same accelerations.
#[test]
fn the_default_acceleration_plans_show_two_configurations() {
    for stem in ["tangent", "four-bar"] {
        let s = scene::load(&root().join(format!("constructions/{stem}.toml"))).expect("scene");
        let session = Session::new(&s, Drafting::EXACT);
        let poses = session.poses().expect("poses");
        let ks = session.acceleration_positions().expect("positions");
        assert_eq!(ks.len(), 2, "{stem}: {ks:?}");
        let (a, b) = (
            &poses.positions[ks[0]].pose.p,
            &poses.positions[ks[1]].pose.p,
        );
        let apart = a
            .iter()
            .zip(b)
            .map(|(p, q)| p.distance(*q))
            .fold(0.0, f64::max);
        // A point off the crank (link 1) moves by more than a millimetre between the two.
        let crank_pin_only = (0..a.len())
            .filter(|&k| a[k].distance(b[k]) > 1e-3)
            .all(|k| poses.program.owner(k) == 1);
        assert!(
            apart > 1e-3 && !crank_pin_only,
            "{stem}: plans at {ks:?} alike"
        );
    }
}

/// No acceleration plan of a shipped scene is drawn at less than a third of the largest
/// one's size: a plan that small at the common μ_a (the tangent mechanism's 12, 11 mm at
/// plan 5's μ_a) is drawn at a μ_a of its own (`own_scale_a`, stated in its caption).
#[test]
fn no_acceleration_plan_is_drawn_far_smaller_than_the_others() {
    let mut seen = 0;
    for path in support::scene_paths() {
        let s = scene::load(&path).expect("scene");
        let Some(kind) = sheets::drawn(&s)
            .into_iter()
            .find(|k| k.stem() == "kinematics")
        else {
            continue;
        };
        let session = Session::new(&s, Drafting::EXACT);
        let mut sizes = Vec::new();
        for p in tmm::build(&session, kind, Lang::Ru).expect("built") {
            let l = tmm::plate::layout(&p);
            for (v, laid) in p.views.iter().zip(&l.views) {
                let plan = v
                    .caption
                    .as_deref()
                    .filter(|c| c.starts_with("План ускорений"));
                if let (Some(c), Some(d)) = (plan, laid.drawn) {
                    sizes.push((c.to_string(), d.size().max_element()));
                }
            }
        }
        let largest = sizes.iter().map(|s| s.1).fold(0.0, f64::max);
        for (caption, size) in &sizes {
            seen += 1;
            assert!(
                *size >= largest / 3.0,
                "{}: «{caption}» {size:.0} mm beside {largest:.0} mm",
                s.stem
            );
        }
    }
    assert!(seen >= 8, "{seen} plans");
}
