//! Issue 44 §1: the kinetostatics and the dynamics of the note worked as seed 000 works
//! them — read off the typeset text of the shaper's note in ru, uk and en: each group's
//! reaction from its moment equation, the driving link's and Zhukovsky's balancing force,
//! the drive's power N = P·V/η, M_пр and J_пр at one position, H and μ_A, J_м by
//! Wittenbauer and by Mertsalov, the flywheel's D, m and rim speed — every number the study's,
//! as the note prints it; and no formula of these sections left without its «где» in any
//! scene with `[forces]` or `[dynamics]`.

use std::path::PathBuf;
use tmm::check::Method;
use tmm::forces::Unknown;
use tmm::{Drafting, Lang, Report, Session};

fn scene(name: &str) -> tmm::Scene {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("constructions")
        .join(format!("{name}.toml"));
    tmm::load(&path).expect("scene")
}

/// The typeset text of `note` without its white space (the typesetter may split a number's
/// run at its decimal sign) and its soft hyphens.
fn text_of(note: &tmm::note::Note) -> String {
    let text = tmm::note::to_text(note).expect("typeset");
    text.split_whitespace()
        .collect::<String>()
        .replace('\u{ad}', "")
}

/// Whether `text` shows the number `want` whole: not as the start of a longer number (the
/// table's 21,7554 is not the formula's 21,755).
fn shows(text: &str, want: &str) -> bool {
    text.match_indices(want).any(|(i, _)| {
        let mut next = text[i + want.len()..].chars();
        match (next.next(), next.next()) {
            (Some(c), _) if c.is_ascii_digit() => false,
            (Some('.' | ','), Some(d)) if d.is_ascii_digit() => false,
            _ => true,
        }
    })
}

/// `x` as the note's formulas print it: `sig` significant digits, without its sign.
fn shown(x: f64, sig: usize, lang: Lang) -> String {
    tmm::scale::format_sig(x.abs(), sig, lang)
}

/// The graphical value of the report's row.
fn row(r: &Report, q: &str, method: Method, position: Option<&str>) -> f64 {
    r.rows
        .iter()
        .find(|x| x.quantity() == q && x.method == method && x.position().as_deref() == position)
        .unwrap_or_else(|| panic!("no row {q} {method:?} {position:?}"))
        .graphical
}

/// Whether `text` shows `want` after the first `after` (words of the section, without
/// their spaces).
fn holds(text: &str, after: &str, want: &str) -> bool {
    let after: String = after.split_whitespace().collect();
    text.find(&after).is_some_and(|at| shows(&text[at..], want))
}

#[test]
fn the_shaper_note_works_the_kinetostatics_with_the_studys_numbers() {
    let s = scene("shaper");
    let session = Session::new(&s, Drafting::HAND);
    let report = session.report().expect("report");
    let sc = session.kin_scales().expect("scales");
    let first = session.force_positions().expect("positions")[0];
    let f = session.forces(&sc, first).expect("forces");
    let p = f.label.clone();
    let a = &f.analysis;
    for lang in [Lang::Ru, Lang::Uk, Lang::En] {
        let note = tmm::note::compose(&session, lang).expect("note");
        let text = text_of(&note);
        let lever_word = match lang {
            Lang::Ru => "рычага Жуковского",
            Lang::Uk => "важеля Жуковського",
            Lang::En => "Zhukovsky's lever:",
        };
        // Every group's moment equation: the unknown it gives, worked to the study's value.
        let mut worked = 0;
        for g in &a.polygons.groups {
            for e in g
                .equations
                .iter()
                .filter(|e| e.terms.iter().any(|t| t.moment != 0.0))
            {
                let value = match &e.unknown {
                    Unknown::Force { value, .. } | Unknown::Arm { value, .. } => *value,
                    Unknown::Couple { value, .. } => *value,
                };
                let want = shown(value, 5, lang);
                assert!(
                    shows(&text, &want),
                    "{lang:?}: group {:?} gives {want}",
                    g.links
                );
                worked += 1;
            }
        }
        assert!(worked >= 2, "{lang:?}: {worked} group equations worked");
        // The guide reaction's arm is the report's h₀₋₅ as the polygons give it.
        let h05 = row(&report, "h_0_5", Method::Polygon, Some(&p));
        assert!(shows(&text, &shown(h05, 5, lang)), "{lang:?}: h0-5 {h05}");
        // The balancing force by the driving link and by the lever, as the report's rows.
        let poly = row(&report, "F_bal", Method::Polygon, Some(&p));
        let lever = row(&report, "F_bal", Method::Lever, Some(&p));
        assert_eq!(a.polygons.driver.f_bal, Some(poly));
        assert_eq!(a.lever.f_bal, Some(lever));
        assert!(
            shows(&text, &format!("={}", shown(poly, 5, lang))),
            "{lang:?}: F_у {poly}"
        );
        assert!(
            holds(&text, lever_word, &format!("={}", shown(lever, 5, lang))),
            "{lang:?}: F_у by the lever {lever}"
        );
        // Every arm of the lever, in mm as read off it.
        for t in a.lever.equation.terms.iter().filter(|t| t.moment != 0.0) {
            let h = shown(t.arm_mm, 5, lang);
            assert!(
                holds(&text, lever_word, &h),
                "{lang:?}: lever arm {h} of {}",
                t.name
            );
        }
        // N = P·V/η with the ram's speed off the velocity plan and η = 0.8.
        let v = row(&report, "v_S5", Method::Plan, Some(&p));
        let n = 1275.3 * v / 0.8;
        assert!(
            shows(&text, &shown(n, 5, lang)),
            "{lang:?}: N = P·V/η = {n}"
        );
        assert!(ours(&note).is_empty(), "{lang:?}: {:?}", ours(&note));
    }
}

#[test]
fn the_shaper_note_works_the_dynamics_with_the_studys_numbers() {
    let s = scene("shaper");
    let session = Session::new(&s, Drafting::HAND);
    let report = session.report().expect("report");
    let d = session.dynamics().expect("dynamics");
    for lang in [Lang::Ru, Lang::Uk, Lang::En] {
        let note = tmm::note::compose(&session, lang).expect("note");
        let text = text_of(&note);
        // H and μ_A = μ_M·μ_φ·H: the seed's 2·0,026·192 = 9,984 J/mm.
        let g = &d.diagrams;
        assert_eq!(g.pole_h, 192.0);
        assert!(
            shows(&text, &shown(g.scale_a.value(), 5, lang)),
            "{lang:?}: μ_A"
        );
        assert!((g.scale_a.value() - 2.0 * 0.026 * 192.0).abs() < 1e-9);
        // J_м by Wittenbauer and by Mertsalov, as the report's rows (graphical).
        for m in [Method::Wittenbauer, Method::Mertsalov] {
            let j = row(&report, "J_flywheel", m, None);
            // Not the table's 21,7554.
            assert!(
                shows(&text, &format!("={}", shown(j, 5, lang))),
                "{lang:?}: J_м {m:?} {j}"
            );
        }
        // M_пр and J_пр worked at the tabled position (a plan's) of the largest reduced
        // moment, not a dead point.
        let (i, b) = d
            .tabled()
            .map(|(i, _)| (i, &d.analytic_shares[i]))
            .max_by(|x, y| x.1.reduced().m().abs().total_cmp(&y.1.reduced().m().abs()))
            .expect("positions");
        assert!(
            b.reduced().m().abs() > 100.0,
            "position {} far from a dead point",
            d.labels[i]
        );
        assert!(
            shows(&text, &shown(b.reduced().m(), 5, lang)),
            "{lang:?}: M_пр"
        );
        assert!(
            shows(&text, &shown(b.reduced().j, 5, lang)),
            "{lang:?}: J_пр"
        );
        // The flywheel: D = (J/(K_j·ρ))^(1/5), taken at the whole 10 mm above, its
        // J = K_j·ρ·D⁵, m = K_m·ρ·D³ and the rim speed under 25 m/s at the D taken.
        let size = &d.size;
        let want_d = (size.j / (0.0076 * 7540.0)).powf(0.2);
        assert!((size.d - want_d).abs() < 1e-12);
        assert!(shows(&text, &shown(size.d, 4, lang)), "{lang:?}: D");
        let taken = (want_d * 100.0).ceil() / 100.0;
        let made = &d.made;
        assert!((made.d - taken).abs() < 1e-12, "{}", made.d);
        assert!(shows(&text, &shown(taken, 4, lang)), "{lang:?}: D taken");
        let j = 0.0076 * 7540.0 * taken.powi(5);
        assert!(
            shows(&text, &shown(j, 5, lang)),
            "{lang:?}: J at the D taken"
        );
        assert!(shows(&text, &shown(made.mass, 4, lang)), "{lang:?}: m");
        let v = made.rim_speed(d.w_avg);
        assert!(
            v < 25.0 && shows(&text, &shown(v, 4, lang)),
            "{lang:?}: v = {v}"
        );
    }
}

/// The left sides the kinetostatics and dynamics sections write (Typst math as the note's
/// `sym` sets a symbol): a load, a reaction, an arm, a power, a moment, an inertia, an
/// energy, a scale of the work diagram, the flywheel's size, a difference, a vector
/// equation, an equation that starts with a minus.
const OURS: [&str; 16] = [
    "#qs[#\"F\"]",
    "#qs[#\"R\"]",
    "#qs[#\"M\"]",
    "#qs[#\"J\"]",
    "#qs[#\"T\"]",
    "#qs[#\"N\"]",
    "#qs[#\"h\"]",
    "#qs[#\"G\"]",
    "#qs[#\"D\"]",
    "#qs[#\"m\"]",
    "#qs[#\"v\"]",
    "#qs[#\"Δ\"]",
    "#qs[#\"μ\"]_(#qs[#\"A\"])",
    "arrow(",
    "-",
    "Δ",
];

/// The unexplained left sides of `note` that the machine sections write.
fn ours(note: &tmm::note::Note) -> Vec<&String> {
    note.unexplained
        .iter()
        .filter(|l| OURS.iter().any(|o| l.starts_with(o)))
        // A guide reaction's arm h₀₋₅ is ours; the kinematics' pole distances h₁, h₂ not.
        .filter(|l| !l.starts_with("#qs[#\"h\"]") || l.contains('-'))
        .collect()
}

#[test]
fn every_formula_of_the_machine_sections_is_explained() {
    for name in ["shaper", "v-engine", "slider-crank", "six-bar", "four-bar"] {
        let s = scene(name);
        for drafting in [Drafting::EXACT, Drafting::HAND] {
            let session = Session::new(&s, drafting);
            for lang in [Lang::Ru, Lang::Uk, Lang::En] {
                let note = tmm::note::compose(&session, lang).expect("note");
                assert!(ours(&note).is_empty(), "{name} {lang:?}: {:?}", ours(&note));
            }
        }
    }
}

#[test]
fn the_engine_note_speaks_of_an_engine() {
    let s = scene("v-engine");
    let session = Session::new(&s, Drafting::HAND);
    let note = tmm::note::compose(&session, Lang::Ru).expect("note");
    let text = text_of(&note);
    assert!(text.contains("Мощностьнавалу"));
    for machine_tool in ["Мощностьпривода", "полезногосопротивления"]
    {
        assert!(
            !text.contains(machine_tool),
            "the engine's note says «{machine_tool}»"
        );
    }
}

/// A symbol is explained once for each meaning (issue 45): in the shaper's note the cam's
/// μ_φ, μ_S, μ_S′, μ_S″ are the cam diagrams' scales, explained in the cam's section after the
/// kinematic diagrams explained theirs, each with its own unit (μ_S′ was the displacement's
/// scale in м/мм there).
#[test]
fn the_cams_scales_are_explained_as_the_cams() {
    let s = scene("shaper");
    let session = Session::new(&s, Drafting::HAND);
    let note = tmm::note::compose(&session, Lang::Ru).expect("note");
    // An explanation's meaning and unit as the note's markup writes them.
    let entry = |meaning: &str, unit: &str| format!("[#[#\"{meaning}\"], #[#\"{unit}\"]]");
    let src = &note.source;
    let crank = src
        .find(&entry("масштаб угла поворота кривошипа", "рад/мм"))
        .expect("the kinematics' μ_φ");
    for (meaning, unit) in [
        ("масштаб угла поворота кулачка", "рад/мм"),
        ("масштаб диаграммы перемещений толкателя", "м/мм"),
        ("масштаб диаграммы аналога скорости толкателя", "м/(рад·мм)"),
    ] {
        let at = src.find(&entry(meaning, unit));
        assert!(at.is_some_and(|at| at > crank), "{meaning}, {unit}");
    }
    assert!(src.contains("масштаб диаграммы аналога ускорения толкателя"));
    // μ_S′ was explained as the displacement's scale a second time.
    assert_eq!(
        src.matches("масштаб диаграммы перемещений толкателя")
            .count(),
        1
    );
}

/// A pair given the table's Δy (`[gears.pair] dy`: the shaper's 0,18, PZ3's 0,16) says in its
/// chain that Δy was taken from the tables, beside the formula's x₁ + x₂ − y, and works the
/// tip radius with it: seed 000's r_a1 = 91 + (1 + 0,8 − 0,18)·14 = 113,68 mm.
#[test]
fn a_pair_on_the_tables_equalising_shift_says_so_in_the_note() {
    for (name, table, exact) in [
        ("shaper", "0,18", "0,17983"),
        ("gears-pz3", "0,16", "0,15974"),
    ] {
        let s = scene(name);
        let session = Session::new(&s, Drafting::HAND);
        let note = tmm::note::compose(&session, Lang::Ru).expect("note");
        let text = text_of(&note);
        let said = "Коэффициент уравнительного смещения принят по таблицам";
        assert!(holds(&text, said, &format!("Δy={table}(")), "{name}");
        assert!(holds(&text, said, &format!("−y={exact})")), "{name}");
    }
    let s = scene("shaper");
    let note = tmm::note::compose(&Session::new(&s, Drafting::HAND), Lang::Ru).expect("note");
    assert!(shows(&text_of(&note), "91+(1+0,8−0,18)⋅14=113,68"));
}
