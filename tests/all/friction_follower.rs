//! The friction that jams a cam's follower (`constructions/friction-follower.toml`, seed 001
//! lectures 15–16): the report's readings against values worked here by hand from the
//! scene's data — the guide's equilibrium solved by Cramer's rule, the pivot's friction
//! circle and moment balance — the header's numbers, the note's worked formulas, and the
//! refusals of a follower that would jam.

use crate::support;

use std::path::PathBuf;
use tmm::check::Report;
use tmm::construct::Drafting;
use tmm::scale::Lang;
use tmm::study::Session;

fn scene() -> tmm::Scene {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("constructions/friction-follower.toml");
    tmm::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

fn report(drafting: f64) -> Report {
    let s = scene();
    let d = Drafting::new(drafting).expect("a drafting resolution");
    Session::new(&s, d)
        .report()
        .unwrap_or_else(|e| panic!("{e}"))
}

/// The graphical and analytic values of a row.
fn values(r: &Report, q: &str) -> (f64, f64) {
    r.rows
        .iter()
        .find(|x| x.quantity() == q)
        .map(|x| (x.graphical, x.analytic))
        .unwrap_or_else(|| panic!("no {q}"))
}

/// The 3×3 determinant.
fn det(m: [[f64; 3]; 3]) -> f64 {
    m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
}

/// The rod of the scene's guide case (Q = 500 N, λ = 30°, b = 40 mm, l = 60 mm, f = 0,15)
/// by hand: the unknowns (P, N₁, N₂); across the axis P sin λ − N₁ + N₂ = 0, along it
/// P cos λ − f(N₁ + N₂) = Q, moments about K: l·N₁ − (l + b)·N₂ = 0; by Cramer's rule.
fn guide_by_hand() -> [f64; 3] {
    let (q, f, b, l) = (500.0, 0.15, 0.040, 0.060);
    let (s, c) = 30f64.to_radians().sin_cos();
    let a = [[s, -1.0, 1.0], [c, -f, -f], [0.0, l, -(l + b)]];
    let rhs = [0.0, q, 0.0];
    let d = det(a);
    [0, 1, 2].map(|k| {
        let mut m = a;
        for (row, v) in m.iter_mut().zip(rhs) {
            row[k] = v;
        }
        det(m) / d
    })
}

#[test]
fn the_guide_reads_the_rods_equilibrium_and_its_jamming_angle() {
    let r = report(0.0);
    let [p, n1, n2] = guide_by_hand();
    let total = (1.0f64 + 0.15 * 0.15).sqrt();
    for (q, want) in [
        ("F_P_guide", p),
        ("R_1_guide", n1 * total),
        ("R_2_guide", n2 * total),
    ] {
        let (g, a) = values(&r, q);
        assert!((g - want).abs() < 1e-9 * want, "{q}: {g} vs {want}");
        assert!((a - want).abs() < 1e-9 * want, "{q}: {a} vs {want}");
    }
    // The header's numbers: P = 883,4 N against Q = 500 N; the nearer bearing carries more.
    assert!(
        (p - 883.4).abs() < 0.05 && n1 > n2 && n1 - n2 > 0.0,
        "{p} {n1} {n2}"
    );
    // Jamming: P's useful part P cos λ − f(N₁ + N₂) vanishes for every P when
    // cos λ = f sin λ (2l + b)/b, i.e. the rod's Z seen from K: Z = (b/(2f), l + b/2).
    let (zx, zy): (f64, f64) = (0.040 / (2.0 * 0.15), 0.060 + 0.020);
    let lock = zx.atan2(zy);
    let (g, a) = values(&r, "angle_lock_guide");
    assert!(
        (g - lock).abs() < 1e-12 && (a - lock).abs() < 1e-12,
        "{g} {a} {lock}"
    );
    assert!(
        (lock.to_degrees() - 59.04).abs() < 0.005,
        "{}",
        lock.to_degrees()
    );
}

#[test]
fn the_pivot_reads_its_friction_circle_couple_and_jamming_angle() {
    let r = report(0.0);
    // ρ = r·sin φ with sin(arctg f) = f/√(1 + f²): 25 mm · 0,3/√1,09.
    let rho = 0.025 * 0.3 / 1.09f64.sqrt();
    // The moments about O₂: P·L·cos λ = M_с + P·ρ.
    let h = 0.120 * 45f64.to_radians().cos() - rho;
    let p = 20.0 / h;
    let lock = (rho / 0.120).acos();
    for (q, want) in [
        ("h_rho_pivot", rho),
        ("h_pivot", h),
        ("F_P_pivot", p),
        ("angle_lock_pivot", lock),
    ] {
        let (g, a) = values(&r, q);
        assert!((g - want).abs() < 1e-9 * want, "{q}: {g} vs {want}");
        assert!((a - want).abs() < 1e-9 * want, "{q}: {a} vs {want}");
    }
    // The header's numbers: ρ = 7,18 mm, h = 77,67 mm, P = 257,5 N, λ_кр = 86,57°.
    assert!((rho * 1e3 - 7.18).abs() < 0.005, "{rho}");
    assert!((h * 1e3 - 77.67).abs() < 0.005, "{h}");
    assert!((p - 257.5).abs() < 0.05, "{p}");
    assert!(
        (lock.to_degrees() - 86.57).abs() < 0.005,
        "{}",
        lock.to_degrees()
    );
    // The lecture's tg λ_кр = 2L/(f·d) = 240/15 = 16: 86,42°, smaller, stated in the notes.
    assert!((16f64.atan().to_degrees() - 86.42).abs() < 0.005);
    assert!(r
        .note_texts()
        .iter()
        .any(|n| n.contains("pivot") && n.contains("86.42°")));
}

#[test]
fn reading_to_half_a_millimetre_shows_a_drafting_error() {
    let worst = crate::friction::worst(&report(0.5));
    assert!(worst > 1e-4 && worst < 0.1, "{worst}");
}

#[test]
fn the_note_works_both_cases_with_the_scenes_numbers() {
    let s = scene();
    let session = Session::new(&s, Drafting::EXACT);
    for (lang, words) in [
        (
            Lang::Ru,
            ["Случай 1: толкатель в направляющей", "заклинивает"],
        ),
        (Lang::En, ["Case 2: rocker in its pivot", "jams"]),
    ] {
        let note = tmm::note::compose(&session, lang).expect("note");
        let text = tmm::note::to_text(&note).expect("typeset");
        // The typeset formulas come out glyph by glyph: compared without white space.
        let text: String = text.split_whitespace().collect();
        for w in words {
            let w: String = w.split_whitespace().collect();
            assert!(text.contains(&w), "{lang:?}: {w}");
        }
        let mark = if lang == Lang::Ru { ',' } else { '.' };
        for number in [
            "883?4", "662?5", "669?9", "59?036", "7?184", "77?67", "257?5", "86?568", "86?424",
        ] {
            let number = number.replace('?', &mark.to_string());
            assert!(text.contains(&number), "{lang:?}: {number}");
        }
    }
}

/// A follower that would jam, a bearing behind the contact, a pivot wider than its arm, a
/// key of another kind: refused, naming the key.
#[test]
fn a_follower_that_would_jam_is_refused_with_its_key() {
    let dir = support::scratch("friction-follower-refused");
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("constructions/friction-follower.toml");
    let text = std::fs::read_to_string(path).expect("scene");
    for (from, to, key, why) in [
        (
            "angle = 30.0 ",
            "angle = 57.1 ",
            "friction.case[0].angle",
            "λ_кр = 59.04°",
        ),
        (
            "angle = 45.0 ",
            "angle = 84.6 ",
            "friction.case[1].angle",
            "λ_кр = 86.57°",
        ),
        (
            "overhang = 60.0",
            "overhang = -1.0",
            "friction.case[0].overhang",
            "l ≥ 0",
        ),
        (
            "length = 40.0",
            "length = 0.0",
            "friction.case[0].length",
            "length",
        ),
        (
            "diameter = 50.0",
            "diameter = 240.0",
            "friction.case[1].diameter",
            "smaller than the arm",
        ),
        (
            "moment = 20.0",
            "moment = 0.0",
            "friction.case[1].moment",
            "moment",
        ),
        ("moment = 20.0", "load = 20.0", "friction.case[1].load", ""),
    ] {
        assert!(text.contains(from), "{from}");
        let path = dir.join("s.toml");
        std::fs::write(&path, text.replace(from, to)).unwrap();
        let out = support::tmm(&["check", path.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(2), "{key}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(key) && err.contains(why), "{key}: {err}");
    }
    // Just below the 2° margin the follower is drawn.
    let path = dir.join("ok.toml");
    std::fs::write(&path, text.replace("angle = 30.0 ", "angle = 57.0 ")).unwrap();
    let out = support::tmm(&["check", path.to_str().unwrap()]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The sheet says which of its two jamming angles is the lecture's approximation (issue 45:
/// «86,57°» and «86,42°» stood in one line as if both were exact).
#[test]
fn the_sheet_calls_the_lectures_jamming_angle_an_approximation() {
    let plates = tmm::render::plates(&scene(), Lang::Ru, Drafting::EXACT).expect("plates");
    let lines: Vec<&String> = (plates.iter())
        .flat_map(|(_, p)| p.texts.iter().flat_map(|t| t.lines.iter()))
        .collect();
    assert!(
        (lines.iter()).any(|l| l.ends_with("(приближённо tg λ_{кр} = 2L/(f·d): 86,42°)")),
        "{lines:#?}"
    );
}
