//! The friction scene through the session: its report at drafting 0 agrees with the twins to
//! rounding, at 0.5 mm it shows the error a hand construction has; W3 gives the seed's
//! numbers.

use crate::support;

use std::path::{Path, PathBuf};
use tmm::construct::Drafting;
use tmm::forces::{
    friction_loads, loads, phase, solve_twin, PairFriction, PairMotion, PositionMotion,
};
use tmm::study::Session;

fn report(drafting: f64) -> tmm::Report {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("constructions/friction.toml");
    let s = tmm::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let d = Drafting::new(drafting).expect("a drafting resolution");
    Session::new(&s, d)
        .report()
        .unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn exact_reading_agrees_with_the_twins() {
    let r = report(0.0);
    // 20 rows of the six seed cases, 4 of the slider (φ, R₀, N, ΔP).
    assert_eq!(r.rows.len(), 24);
    for (row, rel) in r.rows.iter().zip(r.rel_errors()) {
        let rel = rel.unwrap_or(0.0).abs();
        assert!(rel < 1e-12, "{}: {rel}", row.quantity());
    }
    let value = |q: &str| {
        r.rows
            .iter()
            .find(|x| x.quantity() == q)
            .map(|x| x.graphical)
            .unwrap_or_else(|| panic!("no {q}"))
    };
    assert!((value("F_P_W3") - 15.1).abs() < 1e-9);
    assert!((value("F_Pslide_W3") - 1500.0).abs() < 1e-9);
    // The slider within the static limit: the reserve 100(sin 15° − 0,5 cos 15°) < 0.
    let reserve = 100.0 * (15f64.to_radians().sin() - 0.5 * 15f64.to_radians().cos());
    assert!(
        (value("F_dP_rest") - reserve).abs() < 1e-9,
        "{}",
        value("F_dP_rest")
    );
    assert!(r
        .note_texts()
        .iter()
        .any(|n| n.contains("rest: α = 15.00°") && n.contains("at rest by the triangle")));
    assert!(r.note_texts().iter().any(|n| n.contains("erratum")));
    assert!(r.note_texts().iter().any(|n| n.contains("misprints")));
}

/// The largest relative error of a report's rows.
pub(crate) fn worst(r: &tmm::Report) -> f64 {
    r.rel_errors()
        .into_iter()
        .flatten()
        .fold(0.0f64, |m, e| m.max(e.abs()))
}

#[test]
fn reading_to_half_a_millimetre_shows_percent_level_errors() {
    let worst = worst(&report(0.5));
    assert!(worst > 1e-3 && worst < 0.2, "{worst}");
}

// ---------------------------------------------------------------------------------------
// Friction in the pairs of a force analysis (`[forces.friction]`): solved, not iterated.

/// `constructions/slider-crank.toml` at position 3 with `f` and journals of `radius` mm (the
/// crank pin's own 15 mm kept when `pin`), written to a scratch file.
fn slider_crank(f: f64, radius: f64, pin: bool, name: &str) -> PathBuf {
    let text = std::fs::read_to_string(support::root().join("constructions/slider-crank.toml"))
        .expect("the slider-crank scene");
    let text = text
        .replace("f = 0.1\n", &format!("f = {f}\n"))
        .replace("radius = 20.0\n", &format!("radius = {radius}\n"))
        .replace("positions = [\"2\", \"5\"]", "positions = [\"3\"]");
    let text = if pin {
        text
    } else {
        text.replace("radii = { A = 15.0 }", "")
    };
    let path = support::scratch(name).join("slider-crank.toml");
    std::fs::write(&path, text).expect("write the scene");
    path
}

/// The report of a scene, or its error's message.
fn analyse(path: &Path) -> Result<tmm::Report, String> {
    let s = tmm::load(path).map_err(|e| e.to_string())?;
    Session::new(&s, Drafting::new(0.0).expect("exact"))
        .report()
        .map_err(|e| e.to_string())
}

/// The analytic M_bal_f of the report at position 3.
fn m_bal_f(r: &tmm::Report) -> f64 {
    r.rows
        .iter()
        .find(|x| x.quantity() == "M_bal_f" && x.position().as_deref() == Some("3"))
        .map(|x| x.analytic)
        .expect("an M_bal_f row")
}

/// The textbook's plain successive approximations on the twin's linear solve, carried on as
/// long as they take (up to `steps`): the balancing moment they settle at (to 1e-12), or
/// `None` when they do not.
fn plain_approximations(path: &Path, f: f64, radius: f64, steps: usize) -> Option<f64> {
    let s = tmm::load(path).expect("the scene");
    let session = Session::new(&s, Drafting::new(0.0).expect("exact"));
    let plan = session
        .positions(session.scale_l().expect("μ_l"))
        .expect("the plan");
    let k = plan
        .positions
        .iter()
        .position(|p| p.label == "3")
        .expect("position 3");
    let (prog, pose) = (&plan.program, &plan.positions[k].pose);
    let spec = session.force_spec("forces").expect("[forces]");
    let w1 = 300.0 * std::f64::consts::TAU / 60.0;
    let motion = PositionMotion::analytic(pose, w1);
    let given = loads(spec, prog, &motion, phase(&plan, pose.phi, 1.0)).expect("loads");
    let fr = PairFriction {
        f,
        radius: radius * 1e-3,
        radii: Vec::new(),
    };
    let kin = PairMotion {
        prog,
        dir: pose.dir.clone(),
        origin: &pose.origin,
        motion: &motion,
    };
    let solve = |l: &[tmm::forces::Load]| solve_twin(prog, pose, l, &spec.drive, 1.0).ok();
    let mut eq = solve(&given)?;
    for _ in 0..steps {
        let mut all = given.clone();
        all.extend(friction_loads(&fr, &kin, &eq.reactions));
        let next = solve(&all)?;
        let change = (next.m_bal - eq.m_bal).abs();
        eq = next;
        if change <= 1e-12 * eq.m_bal.abs() {
            return Some(eq.m_bal);
        }
    }
    None
}

/// f = 1 with 55 mm journals (every journal, the crank pin too) at position 3: the textbook's
/// successive approximations need thousands of steps (they used to stop at 200 and call it a
/// lock); solved directly, M_bal_f = 1761.52 N·m (the working load on the slider that owns the joint B) — what the plain approximations settle at
/// when carried on long enough — and both routes agree.
#[test]
fn slow_friction_is_solved_not_called_a_lock() {
    let path = slider_crank(1.0, 55.0, false, "f1-r55");
    let r = analyse(&path).unwrap_or_else(|e| panic!("{e}"));
    let m = m_bal_f(&r);
    let plain =
        plain_approximations(&path, 1.0, 55.0, 1_000_000).expect("plain approximations settle");
    assert!((m - plain).abs() <= 1e-9 * m.abs(), "{m} vs {plain}");
    assert!(
        plain_approximations(&path, 1.0, 55.0, 200).is_none(),
        "200 plain steps suffice"
    );
    assert!((m - 1761.5164).abs() < 1e-3, "{m}");
    for (row, rel) in r.rows.iter().zip(r.rel_errors()) {
        if row.quantity().ends_with("_f") {
            assert!(
                rel.unwrap_or(0.0).abs() < 1e-9,
                "{}: {rel:?}",
                row.quantity()
            );
        }
    }
    // The crank pin at its own 15 mm: 560.05 N·m.
    let r = analyse(&slider_crank(1.0, 55.0, true, "f1-r55-pin")).unwrap_or_else(|e| panic!("{e}"));
    assert!((m_bal_f(&r) - 560.0508).abs() < 1e-3, "{}", m_bal_f(&r));
}

/// 70 mm journals: the friction equations have no solution (a lock), refused naming the
/// position, the group and the f past which there is none; just below that f the position is
/// solved (with a huge M_bal_f), just above it is refused again. Exit status 1 (a construction
/// that cannot be carried out), not 2.
#[test]
fn a_real_lock_names_the_position_and_the_group() {
    let path = slider_crank(1.0, 70.0, false, "f1-r70");
    let e = analyse(&path).expect_err("a lock");
    assert!(
        e.contains("position 3") && e.contains("group 1 (links 2, 3)") && e.contains("self-locks"),
        "{e}"
    );
    let f_lock: f64 = e
        .split("past f = ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("no f* in {e}"));
    assert!(f_lock > 0.9 && f_lock < 1.0, "{f_lock}");
    let below = analyse(&slider_crank(0.995 * f_lock, 70.0, false, "below"))
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(m_bal_f(&below) > 3000.0, "{}", m_bal_f(&below));
    let above = analyse(&slider_crank(1.005 * f_lock, 70.0, false, "above")).expect_err("a lock");
    assert!(above.contains("self-locks"), "{above}");
    let o = support::tmm(&["report", path.to_str().expect("a path")]);
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("position 3") && err.contains("group 1"),
        "{err}"
    );
}

/// The shaper with f = 0.88 … 0.99 (journals 20 mm), refused as a lock before, converges at
/// both positions (its RPP group — the block in the ram's perpendicular guides — locks only
/// at f = 1, tan φ = 1), both routes agreeing.
#[test]
fn the_shaper_with_large_friction_converges() {
    let text = std::fs::read_to_string(support::root().join("constructions/shaper.toml"))
        .expect("the shaper");
    let dir = support::scratch("shaper-f");
    for (f, ok) in [(0.88, true), (0.9, true), (0.99, true)] {
        let path = dir.join(format!("shaper-{f}.toml"));
        std::fs::write(
            &path,
            format!("{text}\n[forces.friction]\nf = {f}\nradius = 20.0\n"),
        )
        .expect("write");
        match analyse(&path) {
            Ok(r) => {
                assert!(ok, "f = {f} solved");
                let m: Vec<f64> = r
                    .rows
                    .iter()
                    .filter(|x| x.quantity() == "M_bal_f")
                    .map(|x| x.analytic)
                    .collect();
                assert_eq!(m.len(), 4, "f = {f}");
                for (row, rel) in r.rows.iter().zip(r.rel_errors()) {
                    if !row.quantity().ends_with("_f") {
                        continue;
                    }
                    assert!(
                        rel.unwrap_or(0.0).abs() < 1e-9,
                        "f = {f}: {}: {rel:?}",
                        row.quantity()
                    );
                }
            }
            Err(e) => {
                assert!(!ok, "f = {f}: {e}");
                assert!(
                    e.contains("position 3") && e.contains("group 2 (links 4, 5)"),
                    "{e}"
                );
            }
        }
    }
}

/// A wedge whose groove is flat (180°) is refused at load with its key and range (exit 2); a
/// groove of 179° is a wedge and is solved.
#[test]
fn a_flat_groove_is_refused_at_load() {
    let text = std::fs::read_to_string(support::root().join("constructions/friction.toml"))
        .expect("the friction scene");
    assert!(text.contains("groove = "), "the scene has a wedge");
    let dir = support::scratch("groove");
    for (deg, ok) in [("180.0", false), ("179.0", true)] {
        let body: String = text
            .lines()
            .map(|l| {
                if l.starts_with("groove = ") {
                    format!("groove = {deg}")
                } else {
                    l.to_string()
                }
            })
            .collect::<Vec<_>>()
            .join("\n");
        let path = dir.join(format!("groove-{deg}.toml"));
        std::fs::write(&path, body).expect("write");
        let o = support::tmm(&["report", path.to_str().expect("a path")]);
        let err = String::from_utf8_lossy(&o.stderr);
        if ok {
            assert!(o.status.success(), "{deg}: {err}");
        } else {
            assert_eq!(o.status.code(), Some(2), "{err}");
            assert!(
                err.contains(".groove = 180") && err.contains("(0°, 180°)"),
                "{err}"
            );
        }
    }
}

/// The friction cones as a reader finds them (issue 45): every normal's `n` written at the
/// normal's end past the cone's base — not on the base beside it, where it read as the
/// chord's name — and the slider at rest (case 7) names both its cones, the static φ₀ and
/// the sliding φ inside it.
#[test]
fn every_cone_names_its_normal_past_the_base_and_its_angles() {
    use tmm::construct::Item;
    let plate = crate::plate_model::sheet("friction/friction");
    let l = tmm::plate::layout(&plate);
    let mut normals = 0;
    for x in l.labels.iter().filter(|x| x.text == "n") {
        let view = &plate.views[x.view];
        let normal = crate::plate_model::step(view, x.steps[0]);
        assert!(normal.note.starts_with("the normal n–n"), "{}", normal.note);
        let Item::Segment(seg) = &normal.item else {
            panic!("{:?}", normal.item)
        };
        let base = view
            .figure
            .steps
            .iter()
            .find(|s| s.note.starts_with("f·N laid across the normal") && s.id > normal.id)
            .expect("the cone's base after its normal");
        let Item::Segment(b) = &base.item else {
            panic!("{:?}", base.item)
        };
        // The normal's end lies past the base (along the normal), and the label's box
        // clear of the base's line: nearer the normal's end than the base's middle.
        let n = (seg.to - seg.from).normalize();
        let mid = (b.from + b.to) * 0.5;
        assert!(
            (seg.to - mid).dot(n) >= 5.0,
            "{seg:?} ends at the base {b:?}"
        );
        let centre = (x.rect.min + x.rect.max) * 0.5;
        let end = view.to_sheet(seg.to);
        let base_mid = view.to_sheet(mid);
        assert!(
            centre.distance(end) < centre.distance(base_mid),
            "n at {centre:?}: the normal's end {end:?}, the base {base_mid:?}"
        );
        normals += 1;
    }
    // Cases 1, 2, 4 and 7 draw a cone each.
    assert_eq!(normals, 4);
    let angles: Vec<&str> = plate
        .views
        .iter()
        .flat_map(|v| &v.figure.steps)
        .filter(|s| {
            s.note.starts_with("φ₀, the static cone") || s.note.starts_with("φ, the sliding cone")
        })
        .filter_map(|s| s.label.as_ref().map(|l| l.text.as_str()))
        .collect();
    assert_eq!(angles, ["φ_{0}", "φ"]);
}
