//! The cam scenes through the session: seed 000's cam at drafting 0 (the closed-form law to
//! 1e-9, r_min about 70 mm with the seed's 40 mm flagged, the inversion on the exact pitch
//! curve), at 0.5 mm the error a hand construction has; every hard-case scene diagnosed; bad
//! input refused at load with the key named.

use std::path::{Path, PathBuf};
use tmm::cam::Rotation;
use tmm::check::Method;
use tmm::construct::Drafting;
use tmm::study::Session;

fn scene(name: &str) -> tmm::Scene {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("constructions")
        .join(format!("{name}.toml"));
    tmm::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

fn report(name: &str, drafting: f64) -> tmm::Report {
    let s = scene(name);
    let d = Drafting::new(drafting).expect("a drafting resolution");
    Session::new(&s, d)
        .report()
        .unwrap_or_else(|e| panic!("{e}"))
}

fn rows<'a>(r: &'a tmm::Report, q: &str) -> Vec<&'a tmm::Row> {
    r.rows.iter().filter(|x| x.quantity() == q).collect()
}

#[test]
fn seed000_report_matches_the_closed_form() {
    let r = report("shaper", 0.0);
    let s = rows(&r, "s");
    assert_eq!(s.len(), 26);
    let s_max = s.iter().map(|x| x.analytic).fold(0.0, f64::max);
    assert!((s_max - 0.05236).abs() < 5e-6, "{s_max}");
    assert!((s_max - 0.12 * 25f64.to_radians()).abs() < 1e-12);
    let a = rows(&r, "d2s_dphi2");
    let rise = 4.0 * s_max / 113.6f64.to_radians().powi(2);
    let ret = 4.0 * s_max / 109f64.to_radians().powi(2);
    assert!((rise - 0.053278).abs() < 5e-7 && (ret - 0.057870).abs() < 5e-7);
    for (i, row) in a.iter().enumerate() {
        let want = match i {
            0..=6 => rise,
            7..=12 => -rise,
            13..=19 => -ret,
            _ => ret,
        };
        assert!((row.analytic - want).abs() < 1e-9, "point {i}");
        assert!((row.graphical - want).abs() < 1e-9, "point {i}");
        assert_eq!(row.method, Method::Integration);
    }
    // The "+ −" law's analogue is piecewise constant: integrated exactly at the nodes.
    for q in ["s", "ds_dphi"] {
        for row in rows(&r, q) {
            assert!(row.abs_error() < 1e-12, "{q} at {:?}", row.position());
        }
    }
    let rmin = rows(&r, "r_min");
    assert_eq!(rmin.len(), 1);
    let rmin = rmin[0];
    assert_eq!(rmin.method, Method::CombinedDiagram);
    assert!(rmin.position().is_none());
    assert!((rmin.analytic - 0.0699).abs() < 0.001, "{}", rmin.analytic);
    // The graphical r_min within the drafting resolution (0.5 mm at μ_S = 0.001 m/mm).
    assert!((rmin.graphical - rmin.analytic).abs() < 0.0005);
    // The seed's 40 mm is flagged, never produced.
    assert!((rmin.analytic - 0.040).abs() > 0.02 && (rmin.graphical - 0.040).abs() > 0.02);
    assert!(r
        .note_texts()
        .iter()
        .any(|n| n.contains("ERRATUM") && n.contains("40 mm")));
    // γ ≥ 60° over the whole cycle; the transmission angle per point by inversion.
    let g = rows(&r, "transmission_angle");
    assert_eq!(g.len(), 26);
    assert!(g.iter().all(|x| x.analytic >= 60f64.to_radians() - 1e-6));
    let worst = g
        .iter()
        .map(|x| (x.graphical - x.analytic).abs())
        .fold(0.0, f64::max);
    assert!(
        worst > 1e-6 && worst < 3f64.to_radians(),
        "{}",
        worst.to_degrees()
    );
    for q in ["profile_deviation", "rho_min", "r_roller"] {
        assert_eq!(rows(&r, q).len(), 1, "{q}");
    }
    assert_eq!(rows(&r, "profile_radius").len(), 26);
}

#[test]
fn reading_to_half_a_millimetre_shows_the_drafting_error() {
    let exact = report("shaper", 0.0);
    let drawn = report("shaper", 0.5);
    let r0 = rows(&exact, "r_min")[0];
    let r1 = rows(&drawn, "r_min")[0];
    assert_eq!(r0.analytic, r1.analytic);
    let s_err = rows(&drawn, "s")
        .iter()
        .map(|x| x.abs_error())
        .fold(0.0, f64::max);
    // Readings to half a millimetre at μ_S = 0.001 m/mm, carried through two integrations.
    assert!(s_err > 1e-5 && s_err < 0.002, "{s_err}");
}

#[test]
fn every_cam_scene_reports_and_every_hard_case_is_diagnosed() {
    for (name, needle) in [
        ("cam-pz4", "assumed"),
        ("cam-pz5", "assumed"),
        ("cam-central", "pressure angle"),
        ("cam-undercut", "UNDERCUT"),
        ("cam-cusp", "CUSP"),
        ("cam-shock", "RIGID SHOCKS"),
        ("cam-shock", "WRONG SIDE"),
    ] {
        let r = report(name, 0.0);
        assert!(
            r.note_texts().iter().any(|n| n.contains(needle)),
            "{name}: no note with {needle}: {:?}",
            r.note_texts()
        );
    }
    // Undercut: the largest admissible roller is below the given one.
    let r = report("cam-undercut", 0.0);
    let rho = rows(&r, "rho_min")[0].analytic;
    assert!(rho < 0.015, "{rho}");
    // Cusp: the flat profile's ρ = r₀ + S + S″ is negative.
    let r = report("cam-cusp", 0.0);
    assert!(rows(&r, "rho_min")[0].analytic < 0.0);
}

fn refused(text: &str) -> String {
    match tmm::scene::parse(text, Path::new("bad.toml")) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => e.to_string(),
    }
}

const GOOD: &str = r#"
[cam]
follower = "translating"
law = "cosine"
phases = [130.0, 50.0, 130.0, 50.0]
stroke = 30.0
"#;

#[test]
fn bad_cam_input_is_refused_with_the_key_named() {
    assert!(tmm::scene::parse(GOOD, Path::new("good.toml")).is_ok());
    let e = refused(&GOOD.replace("50.0, 130.0, 50.0", "50.0, 130.0, 60.0"));
    assert!(e.contains("cam.phases") && e.contains("360"), "{e}");
    let e = refused(&GOOD.replace("stroke = 30.0", "stroke = -30.0"));
    assert!(e.contains("cam.stroke"), "{e}");
    let e = refused(&format!("{GOOD}base_radius = 20.0\nroller = 20.0\n"));
    assert!(
        e.contains("cam.roller") && e.contains("smaller than the base radius"),
        "{e}"
    );
    let e = refused(&GOOD.replace("\"cosine\"", "\"parabolic\""));
    assert!(e.contains("cam.law"), "{e}");
    let e = refused(&format!("{GOOD}divisions = 1\n"));
    assert!(e.contains("cam.divisions"), "{e}");
    let e = refused(&GOOD.replace("[cam]", "[plates]\nwanted = [\"balancing\"]\n[cam]"));
    assert!(e.contains("plates.wanted"), "{e}");
}

/// Lecture 17's central cam starts from S (`given = "s"`): S is read off the given diagram
/// exactly at drafting 0, dS/dφ and d²S/dφ² come from differentiating it twice by chords
/// (method `diagram-chords`) and converge to the closed form at the chord method's rate —
/// at least 3.5× smaller per doubling of the intervals.
#[test]
fn a_cam_given_by_s_is_differentiated_by_chords() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("constructions/cam-central.toml");
    let text = std::fs::read_to_string(&path).expect("scene");
    assert!(text.contains("given = \"s\""));
    let errors = |n: usize| -> [f64; 3] {
        let text = text.replace("divisions = 12", &format!("divisions = {n}"));
        let s = tmm::scene::parse(&text, &path).unwrap_or_else(|e| panic!("{e}"));
        let r = Session::new(&s, Drafting::EXACT)
            .report()
            .unwrap_or_else(|e| panic!("{e}"));
        ["s", "ds_dphi", "d2s_dphi2"].map(|q| {
            let rs = rows(&r, q);
            assert_eq!(rs.len(), 2 * n + 2, "{q}");
            assert!(rs.iter().all(|x| x.method == Method::DiagramChords), "{q}");
            rs.iter()
                .map(|x| (x.graphical - x.analytic).abs())
                .fold(0.0, f64::max)
        })
    };
    let (a, b, c) = (errors(24), errors(48), errors(96));
    for e in [a, b, c] {
        assert!(e[0] <= 1e-12, "S read off the given diagram: {}", e[0]);
    }
    for k in 1..3 {
        assert!(
            a[k] > 3.5 * b[k] && b[k] > 3.5 * c[k],
            "{k}: {a:?} {b:?} {c:?}"
        );
    }
    // dS/dφ to 0.01 % of its peak h·2/Φ at 96 intervals.
    assert!(c[1] < 1e-4 * 0.025 * 2.0 / 90f64.to_radians(), "{c:?}");
}

/// A clockwise cam (`rotation = "cw"`) is the mirror image of the counter-clockwise one with
/// the offset on the other side: PZ5 turned clockwise with e = −3 mm has every row of PZ5
/// (e = +3 mm counter-clockwise), and its profile and centre construction are PZ5's
/// mirrored; the same cam clockwise with e = +3 mm has the offset on the wrong side.
#[test]
fn a_clockwise_cam_is_the_mirror_image() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("constructions/cam-pz5.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let ccw = scene("cam-pz5");
    let cw = tmm::scene::parse(
        &text.replace("offset = 3.0", "offset = -3.0\nrotation = \"cw\""),
        &path,
    )
    .unwrap();
    let d = Drafting::new(0.0).unwrap();
    let (a, b) = (Session::new(&ccw, d), Session::new(&cw, d));
    let (ra, rb) = (a.report().unwrap(), b.report().unwrap());
    assert_eq!(ra.rows.len(), rb.rows.len());
    for (x, y) in ra.rows.iter().zip(&rb.rows) {
        assert_eq!(x.quantity(), y.quantity());
        assert!((x.graphical - y.graphical).abs() <= 1e-12 * x.graphical.abs().max(1e-9));
        assert!((x.analytic - y.analytic).abs() <= 1e-12 * x.analytic.abs().max(1e-9));
    }
    let (ca, cb) = (a.cam().unwrap(), b.cam().unwrap());
    assert!(cb.rotation == Rotation::Cw && ca.rotation == Rotation::Ccw);
    assert_eq!(ca.inversion.figure.mirrored_x(), cb.inversion.figure);
    assert_eq!(ca.radius.figure.mirrored_x(), cb.radius.figure);
    // The scene's own offset in the notes.
    assert!(
        rb.note_texts()
            .iter()
            .any(|n| n.contains("the scene's e = −3 mm")),
        "{:?}",
        rb.note_texts()
    );
    let wrong = tmm::scene::parse(
        &text.replace("offset = 3.0", "offset = 3.0\nrotation = \"cw\""),
        &path,
    )
    .unwrap();
    let rw = Session::new(&wrong, d).report().unwrap();
    assert!(
        rw.note_texts()
            .iter()
            .any(|n| n.contains("OFFSET ON THE WRONG SIDE: e = 3 mm")),
        "{:?}",
        rw.note_texts()
    );
    let e = refused(&format!("{GOOD}rotation = \"left\"\n"));
    assert!(e.contains("cam.rotation"), "{e}");
}

/// Issue 17 §5: meaningless cam values are refused at load, naming the key and the range
/// (a negative ρ_min was taken as 0; γ_min = 1e-6° drew a cam of 4e-25 m).
#[test]
fn meaningless_cam_values_are_refused_with_key_and_range() {
    for (edit, key, range) in [
        ("rho_min = -5.0", "cam.rho_min", "≥ 0"),
        ("gamma_min = 1e-6", "cam.gamma_min", "10 ≤ γ_min ≤ 80"),
        ("gamma_min = 85.0", "cam.gamma_min", "10 ≤ γ_min ≤ 80"),
        ("gamma_min = 1e30", "cam.gamma_min", "10 ≤ γ_min ≤ 80"),
        ("poles = [1e30, 40.0]", "cam.poles", "from 5 to 200 mm"),
        ("poles = [30.0, 1e-30]", "cam.poles", "from 5 to 200 mm"),
        ("ratio = 1e-9", "cam.ratio", "0.1 ≤ ratio ≤ 0.9"),
        ("ratio = 0.99", "cam.ratio", "0.1 ≤ ratio ≤ 0.9"),
        ("divisions = 721", "cam.divisions", "from 2 to 720"),
    ] {
        let e = refused(&format!("{GOOD}{edit}\n"));
        assert!(e.contains(key) && e.contains(range), "{edit}: {e}");
    }
    let e = refused(&GOOD.replace("[130.0, 50.0, 130.0, 50.0]", "[1e-9, 180.0, 130.0, 50.0]"));
    assert!(e.contains("cam.phases[0]") && e.contains("≥ 1°"), "{e}");
    let e = refused(&GOOD.replace("[130.0, 50.0, 130.0, 50.0]", "[1e30, 50.0, 130.0, 50.0]"));
    assert!(e.contains("cam.phases"), "{e}");
    // The ends of the ranges are accepted.
    for edit in [
        "rho_min = 0.0",
        "gamma_min = 10.0",
        "gamma_min = 80.0",
        "poles = [5.0, 200.0]",
        "ratio = 0.1",
        "ratio = 0.9",
    ] {
        let text = format!("{GOOD}{edit}\n");
        assert!(
            tmm::scene::parse(&text, Path::new("good.toml")).is_ok(),
            "{edit}"
        );
    }
    // The command line: exit 2 naming the key.
    let dir = std::env::temp_dir().join(format!("tmm-cam-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch");
    let path = dir.join("bad-rho.toml");
    std::fs::write(&path, format!("{GOOD}rho_min = -5.0\n")).expect("write");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_tmm"))
        .args(["check", path.to_str().expect("path")])
        .output()
        .expect("run tmm");
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("cam.rho_min"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 17 §5: every documented number of intervals works: 2 (the "+ −" law integrated from
/// two mid-interval ordinates; it failed with "a diagram needs at least 2 intervals") and
/// many (the table of points continues on further sheets instead of failing to fit).
#[test]
fn every_documented_number_of_divisions_draws() {
    for (name, n) in [
        ("shaper", 2usize),
        ("cam-central", 2),
        ("cam-pz4", 2),
        ("cam-central", 60),
        ("shaper", 200),
    ] {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("constructions")
            .join(format!("{name}.toml"));
        let text = std::fs::read_to_string(&path).expect("scene");
        let text = if text.contains("divisions =") {
            text.lines()
                .map(|l| {
                    if l.starts_with("divisions =") {
                        format!("divisions = {n}")
                    } else {
                        l.to_string()
                    }
                })
                .collect::<Vec<_>>()
                .join("\n")
        } else {
            text.replace("[cam]", &format!("[cam]\ndivisions = {n}"))
        };
        let s = tmm::scene::parse(&text, &path).unwrap_or_else(|e| panic!("{name} {n}: {e}"));
        let session = Session::new(&s, Drafting::EXACT);
        let r = session
            .report()
            .unwrap_or_else(|e| panic!("{name} {n}: {e}"));
        assert_eq!(rows(&r, "s").len(), 2 * n + 2, "{name} {n}");
        let plates = tmm::sheets::build_all(&session, tmm::scale::Lang::En)
            .unwrap_or_else(|(k, e)| panic!("{name} {n}: {k:?}: {e}"));
        let rows_drawn: usize = plates
            .iter()
            .flat_map(|(_, p)| &p.tables)
            .filter(|t| t.title.starts_with("Points of the diagrams"))
            .map(|t| t.rows.len())
            .sum();
        assert_eq!(rows_drawn, 2 * n + 2, "{name} {n}: every point in a table");
    }
}
