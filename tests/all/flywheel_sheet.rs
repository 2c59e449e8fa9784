//! The flywheel as a part drawing (issue 45): the shaper's set carries it as a sheet of its
//! own, the eighth, at 1:4 as seed 000 draws it, titled as the part with its material and
//! technical requirements; the flywheel is sized from the J_м the
//! dynamics sheet's construction gives (Wittenbauer's tangents), not the exact one; every
//! dimension on the sheet is its proportion of that D, worked here from the scene's numbers
//! and the seed's proportions (000 §5.7, L1471–1480), and the hub's keyway the standard's
//! for that d₁ (ГОСТ 23360); a machine that needs no flywheel,
//! or a scene without `[dynamics]`, has no such sheet.

use crate::support::root;
use tmm::check::{Method, Row, Symbol};
use tmm::construct::{Drafting, Item};
use tmm::plate::{Plate, SheetSize};
use tmm::scale::Lang;
use tmm::scene::{self, PlateKind, Scene};
use tmm::study::Session;

fn load(name: &str) -> Scene {
    scene::load(&root().join("constructions").join(name)).unwrap_or_else(|e| panic!("{e}"))
}

fn parse(text: &str) -> Scene {
    scene::parse(text, std::path::Path::new("flywheel-test.toml")).unwrap_or_else(|e| panic!("{e}"))
}

/// Every sheet of `s` in the order of the set.
fn sheets(s: &Scene, drafting: Drafting) -> Vec<(PlateKind, Plate)> {
    tmm::render::plates(s, Lang::Ru, drafting).unwrap_or_else(|e| panic!("{e}"))
}

/// Seed 000's dimensions of a rim with spokes of outer diameter `d` (L1471–1480, the
/// spokes' b/a = 0.4 of its values), m.
fn seed_dimensions(d: f64) -> Vec<(&'static str, f64)> {
    let b = 0.125 * d;
    let (a1, a2) = (1.1 * b, 0.88 * b);
    vec![
        ("D", d),
        ("d_{1}", 0.2 * d),
        ("d_{2}", 0.3 * d),
        ("d_{3}", 0.8 * d),
        ("b", b),
        ("b_{ст}", 1.05 * b),
        ("a_{1}", a1),
        ("a_{2}", a2),
        ("b_{1}", 0.4 * a1),
        ("b_{2}", 0.4 * a2),
    ]
}

/// The report's row `symbol`/`subject` found by Wittenbauer's tangents.
fn wittenbauer(rows: &[Row], symbol: Symbol, subject: &str) -> Row {
    rows.iter()
        .find(|r| {
            r.key.symbol == symbol && r.key.subject == subject && r.method == Method::Wittenbauer
        })
        .cloned()
        .unwrap_or_else(|| panic!("no {symbol:?} {subject} row by Wittenbauer"))
}

#[test]
fn the_shaper_set_draws_the_flywheel_as_its_eighth_sheet_at_1_4() {
    let s = load("shaper.toml");
    let all = sheets(&s, Drafting::EXACT);
    assert_eq!(
        all.len(),
        8,
        "{:?}",
        all.iter().map(|p| &p.1.name).collect::<Vec<_>>()
    );
    let (kind, p) = all.last().expect("a sheet");
    assert_eq!(*kind, PlateKind::Flywheel);
    assert_eq!(p.name, "flywheel");
    let tb = &p.title_block;
    assert_eq!((tb.sheet_no, tb.sheets), (8, 8));
    assert_eq!(tb.designation, "ТММ.КП.000.08");
    assert_eq!(tb.scale, "1:4");
    // A part drawing: the title block names the part, not the machine, and gives its
    // material; the technical requirements stand on the sheet, numbered.
    assert_eq!(tb.title, "Маховик");
    assert!(tb.sheet_title.is_empty(), "{}", tb.sheet_title);
    assert!(tb.material.starts_with("СЧ 15"), "{}", tb.material);
    let lines: Vec<&String> = p.texts.iter().flat_map(|t| &t.lines).collect();
    for item in [
        "1. Литейные радиусы",
        "2. Неуказанные предельные",
        "3. Маховик балансировать",
    ] {
        assert!(
            lines.iter().any(|l| l.starts_with(item)),
            "{item}: {lines:?}"
        );
    }
    // In English, the part's name and its designation in Latin letters.
    let en = tmm::render::plates(&s, Lang::En, Drafting::EXACT).unwrap_or_else(|e| panic!("{e}"));
    let (_, p) = en.last().expect("a sheet");
    assert_eq!(p.title_block.title, "Flywheel");
    assert_eq!(p.title_block.designation, "TMM.KP.000.08");
    // One drawing at μ_l = 0,004 m/mm, on a sheet no larger than A2 (and the corner's
    // roughness sign, which draws nothing of the part).
    let drawings = (p.views.iter())
        .filter(|v| (v.figure.steps.iter()).any(|s| s.role != tmm::construct::Role::Dimension))
        .count();
    assert_eq!(drawings, 1);
    assert!((p.views[0].figure.scale.value() - 0.004).abs() < 1e-15);
    assert!(p.sheet.width_mm() <= 594.0 && p.sheet.height_mm() <= 420.0);
    // The dynamics sheet no longer draws the flywheel.
    for (k, p) in &all {
        if *k == PlateKind::Dynamics {
            for v in &p.views {
                assert!(
                    v.figure
                        .steps
                        .iter()
                        .all(|st| !st.note.starts_with("dimension d_")),
                    "{}: {}",
                    p.name,
                    v.figure.title
                );
            }
        }
    }
}

/// A part an A3 holds at the next coarser round scale goes there rather than onto an A2 at
/// its own: the V engine's D = 380 mm is drawn at 1:2,5 (152 mm) on an A3, not at 1:2 on an
/// A2 18 % inked. The shaper's at 1:5 still leaves its table and data no room on an A3, so
/// it keeps the seed's 1:4 on an A2.
#[test]
fn a_part_takes_the_next_coarser_scale_before_a_larger_sheet() {
    for (scene, size, scale, label) in [
        ("v-engine.toml", SheetSize::A3, 0.0025, "1:2,5"),
        ("shaper.toml", SheetSize::A2, 0.004, "1:4"),
    ] {
        for drafting in [Drafting::EXACT, Drafting::HAND] {
            let all = sheets(&load(scene), drafting);
            let (_, p) = all
                .iter()
                .find(|(k, _)| *k == PlateKind::Flywheel)
                .expect("the flywheel's sheet");
            assert_eq!(p.sheet.size, size, "{scene}");
            assert_eq!(p.title_block.scale, label, "{scene}");
            let mu = p.views[0].figure.scale.value();
            assert!((mu - scale).abs() < 1e-15, "{scene}: {mu}");
        }
    }
}

#[test]
fn every_dimension_is_its_proportion_of_the_d_the_construction_gives() {
    let s = load("shaper.toml");
    let spec = s.dynamics.clone().expect("[dynamics]").flywheel;
    for drafting in [Drafting::EXACT, Drafting::new(0.5).expect("0.5 mm")] {
        let session = Session::new(&s, drafting);
        let rows = session.report().expect("report").rows;
        let j = wittenbauer(&rows, Symbol::Inertia, "flywheel");
        // The sizing's J_м is the construction's, not the exact one.
        let d = session.dynamics().expect("dynamics");
        assert_eq!(d.size.j, j.graphical);
        assert_ne!(j.graphical, j.analytic, "{j:?}");
        // D = (J_м/(K_j·ρ))^(1/5), taken at the whole 10 mm above, and the proportions of
        // the D taken, worked from the scene's numbers.
        let outer = (j.graphical / (spec.k_j * spec.rho)).powf(0.2);
        let taken = (outer * 100.0).ceil() / 100.0;
        assert!(taken > outer && taken < outer + 0.01, "{outer} → {taken}");
        let mut want = seed_dimensions(taken);
        // The hub's keyway for the shaft of d₁ = 0,2·D (ГОСТ 23360, the row over 170 up to
        // 200 mm: b = 45, t₂ = 10,4 mm): its width and d₁ + t₂.
        let d1 = 0.2 * taken;
        assert!(
            d1 > 0.170 && d1 <= 0.200,
            "d₁ = {d1} m: the test's row of the standard"
        );
        want.extend([("keyway b", 0.045), ("d_{1} + t_{2}", d1 + 0.0104)]);
        // The report's D_м row: this D against the exact J_м's.
        let dr = wittenbauer(&rows, Symbol::Length, "flywheel");
        assert!((dr.graphical - outer).abs() < 1e-12 * outer, "{dr:?}");
        let exact_d = (j.analytic / (spec.k_j * spec.rho)).powf(0.2);
        assert!((dr.analytic - exact_d).abs() < 1e-12 * exact_d, "{dr:?}");
        let mr = wittenbauer(&rows, Symbol::Mass, "flywheel");
        let mass = spec.k_m * spec.rho * outer.powi(3);
        assert!((mr.graphical - mass).abs() < 1e-9 * mass, "{mr:?}");

        let all = sheets(&s, drafting);
        let (_, p) = all
            .iter()
            .find(|(k, _)| *k == PlateKind::Flywheel)
            .expect("the flywheel's sheet");
        let figure = &p.views[0].figure;
        let mu = figure.scale.value();
        let mut seen = Vec::new();
        for st in &figure.steps {
            let Some(name) = st.note.strip_prefix("dimension ") else {
                continue;
            };
            let Item::Dimension { from, to, .. } = st.item else {
                panic!("{name}: not a dimension");
            };
            let value = want
                .iter()
                .find(|w| w.0 == name)
                .unwrap_or_else(|| panic!("{name}: not a dimension of the flywheel"))
                .1;
            // Drawn at μ, and written in whole millimetres.
            let drawn = from.distance(to) * mu;
            assert!(
                (drawn - value).abs() < 1e-9 * value,
                "{name}: {drawn} vs {value}"
            );
            let text = st.label.as_ref().expect("its text").text.clone();
            let diameter = ["D", "d_{1}", "d_{2}", "d_{3}"].contains(&name);
            assert_eq!(text.starts_with('⌀'), diameter, "{name}: {text}");
            // The bore with its fit H7, the keyway's width with JS9, its depth in tenths with
            // the upper deviation of t₂ (+0,3 for a key 25 mm high).
            let number = match name {
                "d_{1}" => text.strip_suffix("H7"),
                "keyway b" => text.strip_suffix("JS9"),
                "d_{1} + t_{2}" => text.strip_suffix("^{+0,3}"),
                _ => Some(text.as_str()),
            }
            .unwrap_or_else(|| panic!("{name}: {text}"));
            let written: f64 = number
                .trim_start_matches('⌀')
                .replace(',', ".")
                .parse()
                .expect(&text);
            let half_unit = if name == "d_{1} + t_{2}" { 0.05 } else { 0.5 };
            assert!(
                (written - value * 1e3).abs() <= half_unit + 1e-9,
                "{name}: {text} vs {} mm",
                value * 1e3
            );
            seen.push(name.to_string());
        }
        seen.sort();
        let mut names: Vec<String> = want.iter().map(|w| w.0.to_string()).collect();
        names.sort();
        assert_eq!(seen, names, "every dimension once");
        // The sheet states both J_м with the δ each gives.
        let text: String = p.texts.iter().flat_map(|t| t.lines.clone()).collect();
        let sig4 = |x: f64| tmm::scale::format_sig(x, 4, Lang::Ru);
        for x in [j.graphical, j.analytic] {
            assert!(text.contains(&sig4(x)), "{} not in {text}", sig4(x));
        }
        let delta = wittenbauer(&rows, Symbol::Irregularity, "");
        assert!(text.contains(&sig4(delta.graphical)), "{text}");
        // The D worked and the D taken, with the J_м of the flywheel made.
        let mm = |x: f64, n: usize| tmm::scale::format_fixed(x * 1e3, n, Lang::Ru);
        let taken_line = format!("= {} мм; принимаем D = {} мм", mm(outer, 1), mm(taken, 0));
        assert!(text.contains(&taken_line), "{taken_line} not in {text}");
        let j_made = spec.k_j * spec.rho * taken.powi(5);
        assert!(
            text.contains(&format!("K_{{j}}ρD^5 = {}", sig4(j_made))),
            "{text}"
        );
    }
}

#[test]
fn no_flywheel_no_part_sheet() {
    // A machine whose construction needs no flywheel for δ = 0,5.
    let text = std::fs::read_to_string(root().join("constructions/shaper.toml")).expect("shaper");
    let loose = text.replace("delta = 0.06666666666666667", "delta = 0.5");
    assert_ne!(loose, text);
    let s = parse(&loose);
    assert!(s.plates.contains(&PlateKind::Flywheel));
    let session = Session::new(&s, Drafting::EXACT);
    let d = session.dynamics().expect("dynamics");
    assert_eq!(d.diagrams.wittenbauer.j_fw, 0.0);
    let kinds: Vec<PlateKind> = tmm::sheets::build_all(&session, Lang::Ru)
        .unwrap_or_else(|(k, e)| panic!("{k:?}: {e}"))
        .into_iter()
        .map(|(k, _)| k)
        .collect();
    assert!(kinds.contains(&PlateKind::Dynamics));
    assert!(!kinds.contains(&PlateKind::Flywheel), "{kinds:?}");
    // A scene without [dynamics]: nothing to size; asking for the sheet is refused by key.
    let four = load("four-bar.toml");
    assert!(sheets(&four, Drafting::EXACT)
        .iter()
        .all(|(k, _)| *k != PlateKind::Flywheel));
    let text = std::fs::read_to_string(root().join("constructions/four-bar.toml")).expect("4");
    let asks = text.replace(
        "wanted = [\"positions\", \"kinematics\"]",
        "wanted = [\"positions\", \"flywheel\"]",
    );
    assert_ne!(asks, text);
    let e = scene::parse(&asks, std::path::Path::new("x.toml")).expect_err("refused");
    let msg = e.to_string();
    assert!(
        msg.contains("plates.wanted") && msg.contains("[dynamics]"),
        "{msg}"
    );
}

/// The part drawing's title block gives the flywheel's mass (kg, 3 significant digits) and its
/// material (ГОСТ 2.104 graphs 5 and 3); the sheet concludes on δ. The flywheel made (D of
/// the construction's J_м taken at the whole 10 mm above) keeps [δ] on both shipped machines;
/// over the plans' 12 positions alone the shaper's construction is 15 % short, and the sheet
/// says by how much J is short and which J_м and D keep δ — the numbers worked here from the
/// study's.
#[test]
fn the_part_sheet_names_its_mass_and_material_and_concludes_on_delta() {
    let text = std::fs::read_to_string(root().join("constructions/shaper.toml")).expect("shaper");
    let twelve = text.replace("[dynamics]\n", "[dynamics]\ncount = 12\n");
    assert_ne!(twelve, text);
    for (scene, material, keeps) in [
        (text, "СЧ 15 ГОСТ 1412–85", true),
        (
            std::fs::read_to_string(root().join("constructions/v-engine.toml")).expect("v"),
            "Сталь 35Л ГОСТ 977–88",
            true,
        ),
        (twelve, "СЧ 15 ГОСТ 1412–85", false),
    ] {
        let s = parse(&scene);
        let session = Session::new(&s, Drafting::HAND);
        let d = session.dynamics().unwrap_or_else(|e| panic!("{e}"));
        let p = tmm::sheets::build(&session, PlateKind::Flywheel, Lang::Ru)
            .unwrap_or_else(|e| panic!("{e}"))
            .remove(0);
        let name = &p.title_block.designation;
        let tb = &p.title_block;
        let sig3 = tmm::scale::format_sig(d.made.mass, 3, Lang::Ru);
        assert_eq!(tb.mass, sig3, "{name}");
        assert_eq!(tb.material, material, "{name}");
        // The flywheel made: D at the whole 10 mm above, J = K_j·ρ·D⁵.
        let fw = &d.spec.flywheel;
        let taken = (d.size.d * 100.0).ceil() / 100.0;
        assert!((d.made.d - taken).abs() < 1e-12, "{name}: {}", d.made.d);
        let j = fw.k_j * fw.rho * taken.powi(5);
        assert!((d.made.j - j).abs() < 1e-12 * j, "{name}");
        // It keeps δ exactly when its J is the exact flywheel's or more.
        assert_eq!(
            d.made.j >= d.exact.j_fw,
            keeps,
            "{name}: {j} vs {}",
            d.exact.j_fw
        );
        let lines: Vec<&str> = p
            .texts
            .iter()
            .flat_map(|t| t.lines.iter())
            .map(String::as_str)
            .collect();
        let (got, asked) = (d.delta_made, d.spec.delta);
        assert_eq!(got <= asked, keeps, "{name}: δ {got} against {asked}");
        let inv = |x: f64| tmm::scale::format_sig(1.0 / x, 3, Lang::Ru);
        let rel = if keeps { "≤" } else { ">" };
        let first = format!("Вывод: δ = 1/{} {rel} [δ] = 1/{}.", inv(got), inv(asked));
        let at = lines
            .iter()
            .position(|l| *l == first)
            .unwrap_or_else(|| panic!("{name}: no «{first}» in {lines:?}"));
        let mm = |x: f64| tmm::scale::format_fixed(x * 1e3, 0, Lang::Ru);
        if keeps {
            let met = format!("Маховик D = {} мм обеспечивает [δ].", mm(taken));
            assert_eq!(lines[at + 1], met, "{name}");
            continue;
        }
        let short = 100.0 * (1.0 - j / d.exact.j_fw);
        let pct = tmm::scale::format_fixed(short, 1, Lang::Ru);
        assert!(
            lines[at + 1].contains(&format!(
                "на {pct} % меньше точного J_{{м}} (по 12 положениям)"
            )),
            "{}",
            lines[at + 1]
        );
        assert!(
            lines[at + 2].contains(&format!("(D ≥ {} мм)", mm(d.exact_size.d))),
            "{}",
            lines[at + 2]
        );
    }
}

/// ГОСТ 2.316: a part drawing's technical requirements stand over its title block, their
/// left edge on the block's — on the shaper's and the V engine's flywheel, in ru, uk and
/// en, read exactly and to 0,5 mm, with nothing else of the sheet in their place. Before,
/// the packer left them under the dimensions' table at the top right.
#[test]
fn the_technical_requirements_stand_over_the_title_block() {
    each_flywheel_sheet(|at, p| {
        // The numbered items (ГОСТ 2.316): the block that begins with «1. ».
        let k = (p.texts.iter())
            .position(|t| t.lines.first().is_some_and(|l| l.starts_with("1. ")))
            .unwrap_or_else(|| panic!("{at}: no technical requirements"));
        let l = tmm::plate::layout(p);
        let (r, tb) = (l.texts[k], l.title_block);
        assert!((r.min.x - tb.min.x).abs() < 1e-9, "{at}: x {}", r.min.x);
        let gap = tb.min.y - r.max.y;
        assert!(
            (0.0..=10.0).contains(&gap),
            "{at}: {gap} mm over the title block"
        );
        let others = l.boxes().filter(|o| *o != r);
        for o in others {
            assert!(!o.intersects(&r), "{at}: {o:?} in their place {r:?}");
        }
    });
}

/// The flywheel sheet of the shaper and of the V engine, in ru, uk and en, read exactly and
/// to 0,5 mm, for `check` with the scene, language and drafting named.
fn each_flywheel_sheet(mut check: impl FnMut(&str, &Plate)) {
    for name in ["shaper.toml", "v-engine.toml"] {
        let s = load(name);
        for drafting in [Drafting::EXACT, Drafting::HAND] {
            let session = Session::new(&s, drafting);
            for lang in [Lang::Ru, Lang::Uk, Lang::En] {
                let p = tmm::sheets::build(&session, PlateKind::Flywheel, lang)
                    .unwrap_or_else(|e| panic!("{e}"))
                    .remove(0);
                check(&format!("{name} {lang:?} {}", drafting.resolution_mm()), &p);
            }
        }
    }
}

/// The roughness of the surfaces the part drawing does not mark stands in the sheet's top
/// right corner (ГОСТ 2.309): the sign of a surface left as cast (its legs and the inscribed
/// circle) and the basic sign in brackets, clear of everything else of the sheet, in every
/// language and drafting (issue 45: the V engine's flywheel had no such sign).
#[test]
fn the_other_surfaces_roughness_stands_in_the_top_right_corner() {
    each_flywheel_sheet(|at, p| {
        let k = (p.views.iter())
            .position(|v| v.figure.title == "roughness of the other surfaces")
            .unwrap_or_else(|| panic!("{at}: no roughness of the other surfaces"));
        let figure = &p.views[k].figure;
        let circles = (figure.steps.iter())
            .filter(|s| matches!(s.item, tmm::construct::Item::Circle(_)))
            .count();
        let arcs = (figure.steps.iter())
            .filter(|s| matches!(s.item, tmm::construct::Item::Arc(_)))
            .count();
        assert_eq!(
            (circles, arcs),
            (1, 2),
            "{at}: the cast sign and two brackets"
        );
        let l = tmm::plate::layout(p);
        let r = l.views[k].drawn.expect("drawn");
        assert!(
            l.frame.max.x - r.max.x < 10.0 && r.min.y - l.frame.min.y < 15.0,
            "{at}: {r:?} not in the corner of {:?}",
            l.frame
        );
        for o in l.boxes().filter(|o| *o != r) {
            assert!(!o.intersects(&r), "{at}: {o:?} over the sign {r:?}");
        }
    });
}
