//! The sheets' rules: the scene's scales are used as given, views that need more room go on
//! a further sheet, and a view too large for any sheet at its given scale is refused naming
//! the key and the largest scale that fits.

use crate::support;

use std::path::PathBuf;
use tmm::construct::Drafting;
use tmm::scale::Lang;
use tmm::scene;
use tmm::sheets;
use tmm::study::Session;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn shaper_text() -> String {
    std::fs::read_to_string(root().join("constructions/shaper.toml")).expect("shaper")
}

/// Every text of a plate: view captions, text lines, table titles.
fn texts(p: &tmm::plate::Plate) -> Vec<String> {
    let mut out: Vec<String> = p.views.iter().filter_map(|v| v.caption.clone()).collect();
    out.extend(p.texts.iter().flat_map(|t| t.lines.clone()));
    out
}

/// Every text of every sheet of a scene, in Russian.
fn sheet_text(s: &tmm::Scene) -> String {
    let session = Session::new(s, Drafting::EXACT);
    let all = sheets::build_all(&session, Lang::Ru).expect("plates");
    all.iter()
        .flat_map(|(_, p)| texts(p))
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn the_shaper_sheets_print_the_scene_scales_as_given() {
    let s = scene::load(&root().join("constructions/shaper.toml")).expect("shaper");
    let session = Session::new(&s, Drafting::EXACT);
    let all = sheets::build_all(&session, Lang::Ru).expect("plates");
    assert_eq!(
        all.len(),
        8,
        "the project's set: kinematics on two sheets, the force analysis one per position, the cam, the gears, the dynamics, the flywheel"
    );
    let text = all
        .iter()
        .flat_map(|(_, p)| texts(p))
        .collect::<Vec<_>>()
        .join("\n");
    // seed 000: μ_l = 0,0025 м/мм, μ_v = 0,05, μ_a = 1, μ_S = 0,005, μ_φ = 0,052, H₁ = 28, H₂ = 7,5
    for given in [
        "μ_{l} = 0,0025 м/мм",
        "μ_{v} = 0,05 м/(с·мм)",
        "μ_{a} = 1 м/(с^2·мм)",
        "μ_{S} = 0,005",
        "μ_{φ} = 0,052",
        "H_{1} = 28",
        "H_{2} = 7,5",
        "μ_{F} = 20 Н/мм",
        // seed 000 §5: μ_M = 2 Н·м/мм, μ_φ = 0,026 рад/мм, H = 192 мм
        "μ_{M} = 2 Н·м/мм",
        "μ_{φ} = 0,026 рад/мм",
        "H = 192 мм",
    ] {
        assert!(text.contains(given), "{given} not on the sheets:\n{text}");
    }
    // The linkage's sheets (the gear train's triangles have a μ_v of their own).
    let linkage = all
        .iter()
        .filter(|(kind, _)| *kind != scene::PlateKind::Gears)
        .flat_map(|(_, p)| texts(p))
        .collect::<Vec<_>>()
        .join("\n");
    for bumped in ["μ_{l} = 0,004", "μ_{v} = 0,1 "] {
        assert!(
            !linkage.contains(bumped),
            "{bumped} on the sheets:\n{linkage}"
        );
    }
    // Sheet k of n across the project, each with the set's designation and its number.
    let numbers: Vec<(u32, u32, String)> = all
        .iter()
        .map(|(_, p)| {
            let tb = &p.title_block;
            (tb.sheet_no, tb.sheets, tb.designation.clone())
        })
        .collect();
    let want: Vec<(u32, u32, String)> = (1..=8)
        .map(|k| (k, 8, format!("ТММ.КП.000.{k:02}")))
        .collect();
    assert_eq!(numbers, want);
}

#[test]
fn the_force_sheets_take_one_position_each_with_its_table_and_the_balancing_moment() {
    let s = scene::load(&root().join("constructions/shaper.toml")).expect("shaper");
    let session = Session::new(&s, Drafting::EXACT);
    let plates = sheets::build(&session, scene::PlateKind::Forces, Lang::Ru).expect("forces");
    let names: Vec<&str> = plates.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["forces", "forces-2"]);
    for (p, label) in plates.iter().zip(["3", "10"]) {
        let title = &p.title_block.sheet_title;
        assert_eq!(title, &format!("Силовой анализ, положение {label}"));
        let text = texts(p).join("\n");
        for caption in [
            "Группа 4–5 (ВПП), μ_{l} = 0,0025 м/мм",
            "План сил группы 4–5, μ_{F} = 20 Н/мм",
            "Группа 2–3 (ВПВ)",
            "План сил группы 2–3",
            "Ведущее звено 1",
            "План сил ведущего звена",
            "Рычаг Жуковского, μ_{v} = 0,04 м/(с·мм)",
            "M_{у}: по плану сил",
            "F_{у}: по плану сил",
            // The data the loads come from, a link's mass and moment of inertia together.
            "Исходные данные\nm_{2} = 2 кг, m_{3} = 16 кг, J_{S3} = 0,3924 кг·м^2, m_{4} = 2 кг\nm_{5} = 22 кг, F_{пс} = 1275,3 Н",
        ] {
            assert!(
                text.contains(caption),
                "{caption} not on {}:\n{text}",
                p.name
            );
        }
        let table = &p.tables[0];
        let quantities: Vec<&str> = table.rows.iter().map(|r| r[0].as_str()).collect();
        for q in [
            "F_{и3}, Н",
            "M_{и3}, Н·м",
            "R_{0-3}, Н",
            "R_{4-5}, Н",
            "M_{у}, Н·м",
        ] {
            assert!(quantities.contains(&q), "{q} not in {quantities:?}");
        }
    }
}

#[test]
fn a_force_polygon_too_large_at_the_given_scale_names_forces_scale_f() {
    let text = shaper_text().replace("scale_f = 20.0 ", "scale_f = 0.5 ");
    let s = scene::parse(&text, &root().join("big.toml")).expect("scene");
    let session = Session::new(&s, Drafting::EXACT);
    let err = sheets::build(&session, scene::PlateKind::Forces, Lang::Ru)
        .expect_err("too large")
        .to_string();
    assert!(err.contains("forces.scale_f"), "{err}");
}

/// μ_v sets every velocity plan (kinematics plate) and the Zhukovsky lever (forces plate): the
/// scale that fits the first plan alone (0.004) does not fit the others, nor does the one that
/// fits every plan (0.01) fit the lever. The suggestion is verified on every plate: 0.025,
/// which renders.
#[test]
fn a_view_too_large_at_its_given_scale_names_the_key_and_the_scale_that_fits() {
    let text = shaper_text().replace("scale_v = 0.05 ", "scale_v = 0.002 ");
    let path = root().join("big.toml");
    let s = scene::parse(&text, &path).expect("scene");
    let session = Session::new(&s, Drafting::EXACT);
    let Err((
        _,
        sheets::BuildError::TooLarge {
            fits: Some((key, first)),
            ..
        },
    )) = sheets::build_all(&session, Lang::Ru)
    else {
        panic!("too large");
    };
    assert_eq!(key.key.path(), "kinematics.scale_v");
    // Every velocity plan of the plate, not the first alone.
    assert_eq!(first.value(), 0.01);
    let fit = sheets::verified_fit(&s, key.key, first, Drafting::EXACT, Lang::Ru);
    let sheets::Fit::Verified(fit) = fit else {
        panic!("verified: {fit:?}");
    };
    assert_eq!(fit.value(), 0.025);
    for (v, fits) in [("0.01", false), ("0.025", true)] {
        let text = shaper_text().replace("scale_v = 0.05 ", &format!("scale_v = {v} "));
        let s = scene::parse(&text, &path).expect("scene");
        let built = sheets::build_all(&Session::new(&s, Drafting::EXACT), Lang::Ru);
        assert_eq!(built.is_ok(), fits, "{v}");
    }
}

/// The CLI names the verified scale (forces.scale_f: 0.5 first suggested 2.5, then 4, and the
/// polygons fit at 10).
#[test]
fn the_cli_suggests_a_force_scale_that_fits() {
    let dir = std::env::temp_dir().join(format!("tmm-sheets-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let scene = dir.join("big.toml");
    std::fs::write(
        &scene,
        shaper_text().replace("scale_f = 20.0 ", "scale_f = 0.5 "),
    )
    .expect("write");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_tmm"))
        .args(["check", scene.to_str().expect("utf-8")])
        .output()
        .expect("tmm");
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("the largest scale at which it fits is forces.scale_f = 10 N/mm"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn views_that_need_more_room_continue_on_a_further_sheet() {
    let s = scene::load(&root().join("constructions/six-bar.toml")).expect("six-bar");
    let session = Session::new(&s, Drafting::EXACT);
    let all = sheets::build_all(&session, Lang::Ru).expect("plates");
    let names: Vec<&str> = all.iter().map(|(_, p)| p.name.as_str()).collect();
    // The plan of positions is folded into the kinematic sheets (the textbook's sheet 1): no
    // sheet of its own; what one A1 does not hold continues on a second, once the first is
    // filled, and the second holds a drawing (never a table alone).
    assert_eq!(names, ["kinematics", "kinematics-2"]);
    for (k, (_, p)) in all.iter().enumerate() {
        assert_eq!(p.title_block.sheet_no as usize, k + 1);
        assert_eq!(p.title_block.sheets, 2);
        assert!(!p.views.is_empty(), "{}: {} views", p.name, p.views.len());
    }
    // The first sheet reads: the structural scheme, the plan of positions, the velocity plans
    // 1 … 12 with 10′ in its place; the structural analysis is written on one of the two.
    let first = &all[0].1;
    let captions: Vec<&str> = first
        .views
        .iter()
        .filter_map(|v| v.caption.as_deref())
        .collect();
    assert!(captions[0].starts_with("Структурная схема"), "{captions:?}");
    assert!(captions[1].starts_with("План положений"), "{captions:?}");
    let lines: Vec<&String> = all
        .iter()
        .flat_map(|(_, p)| &p.texts)
        .flat_map(|t| &t.lines)
        .collect();
    assert!(
        lines.iter().any(|l| l.contains("Формула строения")),
        "{lines:?}"
    );
}

fn report(stem: &str) -> tmm::Report {
    let s = scene::load(&root().join(format!("constructions/{stem}.toml"))).expect("scene");
    Session::new(&s, Drafting::EXACT).report().expect("report")
}

#[test]
fn a_diagram_across_an_asymptote_is_refused_with_a_note() {
    // tangent.toml: at φ₁ = 90° and 270° the guides are parallel and the slider runs off.
    let r = report("tangent");
    assert!(r.rows.iter().all(|row| row.method == tmm::Method::Plan));
    assert!(
        r.note_texts()
            .iter()
            .any(|n| n.contains("φ₁ = 90.00°") && n.contains("refused")),
        "{:?}",
        r.note_texts()
    );
    let s = scene::load(&root().join("constructions/tangent.toml")).expect("scene");
    let text = sheet_text(&s);
    assert!(
        text.contains("не строятся") && text.contains("φ_{1} = 90°"),
        "{text}"
    );
}

/// At the six-bar's change point (position 6) the analytic rates are not determined: the
/// analytic table leaves them empty (null, never 0). The diagrams' readings there are read
/// off the piece that starts at 6, and are checked against that branch's one-sided limit
/// (see `kinematic_verdicts`), not left without a twin.
#[test]
fn values_undetermined_at_the_change_point_are_null_not_zero() {
    let r = report("six-bar");
    for q in ["v_E", "a_E"] {
        let row = r
            .rows
            .iter()
            .find(|row| row.quantity() == q && row.position().as_deref() == Some("6"))
            .expect("a diagram row at 6");
        assert!(
            row.analytic.is_finite() && row.analytic > 0.0,
            "{q}: {}",
            row.analytic
        );
    }
    assert!(
        r.note_texts().iter().any(|n| n.contains("not determined")),
        "{:?}",
        r.note_texts()
    );
    // The analytic table leaves the rates empty there, keeps the angles and the crank pin.
    let t = &r.tables[0];
    let (_, row6) = t.rows.iter().find(|(l, _)| l == "6").expect("row 6");
    let col = |name: &str| t.columns.iter().position(|c| c.name == name).expect(name);
    assert_eq!(row6[col("ω_2")], None);
    assert_eq!(row6[col("V_E")], None);
    let json: serde_json::Value = serde_json::from_str(&r.to_json()).expect("json");
    let in_json = (json["tables"][0]["rows"].as_array().expect("rows").iter())
        .find(|row| row["position"] == "6")
        .expect("row 6 in the JSON");
    assert!(in_json["values"][col("V_E")].is_null(), "{in_json}");
    assert!(row6[col("φ_2")].is_some() && row6[col("V_A")].is_some());
}

#[test]
fn tables_use_the_textbook_notation_and_omit_a_slider_link() {
    let s = scene::load(&root().join("constructions/shaper.toml")).expect("shaper");
    let session = Session::new(&s, Drafting::EXACT);
    let all = sheets::build_all(&session, Lang::Ru).expect("plates");
    let cells: Vec<String> = all
        .iter()
        .flat_map(|(_, p)| p.tables.iter())
        .flat_map(|t| {
            t.rows
                .iter()
                .flatten()
                .cloned()
                .chain(t.columns.iter().map(|c| c.0.clone()))
        })
        .collect();
    assert!(cells.iter().any(|c| c == "ω_{3}"), "{cells:?}");
    // The crank's ω₁ and ε₁ are given: no table sets them against themselves.
    assert!(
        !cells.iter().any(|c| c == "ω_{1}" || c == "ε_{1}"),
        "{cells:?}"
    );
    assert!(cells.iter().any(|c| c == "V_{B3B1}"), "{cells:?}");
    assert!(!cells.iter().any(|c| c.contains("omega") || c == "v B3 B1"));
    assert!(cells.iter().any(|c| c.ends_with(", м/с")), "{cells:?}");
    assert!(!cells.iter().any(|c| c.ends_with("m/s")), "{cells:?}");
    // The slider-crank's slider (link 3) only translates: no φ_3, ω_3, ε_3 columns.
    let t = &report("slider-crank").tables[0];
    assert!(
        !t.columns.iter().any(|c| c.name.ends_with("_3")),
        "{:?}",
        t.columns
    );
    assert!(t.columns.iter().any(|c| c.name == "ω_2"));
}

#[test]
fn out_of_range_numbers_are_refused_when_the_scene_is_read() {
    for (from, to, key) in [
        ("length = 140.0", "length = 1e300", "mechanism.crank.length"),
        (
            "omega = 15.707963267948966",
            "omega = 1e300",
            "mechanism.crank.omega",
        ),
        (
            "at = [0.0, 430.0]",
            "at = [0.0, 4.3e300]",
            "mechanism.fixed[0].at",
        ),
    ] {
        let text = shaper_text().replace(from, to);
        assert_ne!(text, shaper_text(), "{from}");
        let err = scene::parse(&text, &root().join("x.toml"))
            .expect_err("out of range")
            .to_string();
        assert!(err.contains(key), "{key}: {err}");
    }
}

#[test]
fn an_unknown_position_label_names_the_valid_ones() {
    let text = shaper_text().replace(
        "acceleration_positions = [\"3\", \"10\"]",
        "acceleration_positions = [\"3\", \"7′\"]",
    );
    let s = scene::parse(&text, &root().join("x.toml")).expect("scene");
    let err = Session::new(&s, Drafting::EXACT)
        .report()
        .expect_err("no 7′")
        .to_string();
    assert!(
        err.contains("there is no position 7′; the positions are 1…12, 8′"),
        "{err}"
    );
}

#[test]
fn a_long_table_goes_on_inside_the_frame() {
    // 24 and 36 positions: the analytic table grows; every item stays inside the frame.
    for count in [24, 36] {
        let text = shaper_text().replace("count = 12", &format!("count = {count}"));
        let s = scene::parse(&text, &root().join("x.toml")).expect("scene");
        let session = Session::new(&s, Drafting::EXACT);
        let all = sheets::build_all(&session, Lang::Ru).expect("plates");
        for (_, p) in &all {
            let l = tmm::plate::layout(p);
            let f = l.frame;
            let inside = |r: &tmm::plate::Rect| {
                r.min.x >= f.min.x && r.min.y >= f.min.y && r.max.x <= f.max.x && r.max.y <= f.max.y
            };
            for r in l.tables.iter().chain(&l.texts) {
                assert!(inside(r), "count {count}, {}: {r:?}", p.name);
                assert!(
                    !r.intersects(&l.title_block),
                    "count {count}, {}: {r:?}",
                    p.name
                );
            }
        }
    }
}

/// The example of constructions/README.md: a guide along a moving link, from its pivot.
#[test]
fn a_guide_along_a_moving_link_is_written_directly() {
    let readme = std::fs::read_to_string(root().join("constructions/README.md")).expect("readme");
    let start = readme
        .find("```toml\n[[mechanism.point]]\nname = \"D\"")
        .expect("the example");
    let example = &readme[start + 8..];
    let example = &example[..example.find("```").expect("its end")];
    let four_bar =
        std::fs::read_to_string(root().join("constructions/four-bar.toml")).expect("four-bar");
    let text = four_bar.replace(
        "[[mechanism.output]]",
        &format!("{example}\n[[mechanism.output]]"),
    );
    let s = scene::parse(&text, &root().join("moving.toml")).expect("the example is valid");
    let session = Session::new(&s, Drafting::EXACT);
    let all = sheets::build_all(&session, Lang::Ru).expect("it is constructed and drawn");
    assert!(!all.is_empty());
    let report = session.report().expect("report");
    let plan_rows = report.rows.iter().filter(|r| r.method == tmm::Method::Plan);
    assert!(plan_rows.clone().any(|r| r.quantity() == "v_C"));
    for r in plan_rows {
        assert!(
            (r.graphical - r.analytic).abs() <= 1e-9 * r.scale.max(1.0),
            "{r:?}"
        );
    }
}

/// Every scale any scene of constructions/ gives is printed on its sheets as given.
#[test]
fn every_scene_prints_the_scales_it_gives() {
    for entry in std::fs::read_dir(root().join("constructions")).expect("constructions/") {
        let path = entry.expect("entry").path();
        if path.extension().is_none_or(|x| x != "toml") {
            continue;
        }
        let s = scene::load(&path).expect("scene");
        let k = &s.kinematics;
        let given = [s.scale_l, k.scale_v, k.scale_a, k.scale_s, k.scale_phi];
        let text = sheet_text(&s);
        for scale in given.into_iter().flatten() {
            let caption = scale.caption(Lang::Ru);
            // The chart's μ_S and μ_φ are written in the diagrams' line with their own symbols.
            let value = caption.split(" = ").nth(1).expect("μ = value unit");
            assert!(
                text.contains(value),
                "{}: {caption} not printed:\n{text}",
                s.stem
            );
        }
    }
}

/// Every scene of `constructions/` names its set in the title block (issue 19's audit:
/// four-bar, slider-crank, tangent and v-engine printed an empty designation field and an
/// empty rotated box), and no two scenes share one.
#[test]
fn every_scene_has_a_designation_of_its_own() {
    let mut seen: Vec<(String, String)> = Vec::new();
    for path in support::scene_paths() {
        let s = scene::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let d = s.title.designation.clone();
        let name = path.file_stem().map(|n| n.to_string_lossy().into_owned());
        let name = name.unwrap_or_default();
        assert!(!d.trim().is_empty(), "{name}: no designation in [task]");
        if let Some((other, _)) = seen.iter().find(|(_, o)| *o == d) {
            panic!("{name} and {other} both carry {d}");
        }
        seen.push((name, d));
    }
}

/// The structural analysis states Grashof's condition as a student writes it (issue 45): the
/// six-bar's O–A–B–D is a change-point linkage (100 + 500 = 300 + 300 mm), its velocity plan
/// refused at position 6; the four-bar's 80 + 280 < 250 + 180 has no change point.
#[test]
fn the_structural_analysis_states_grashofs_condition() {
    let six = scene::load(&root().join("constructions/six-bar.toml")).expect("six-bar");
    let text = sheet_text(&six);
    for line in [
        "Условие Грасгофа (O–A–B–D): l_{min} + l_{max} ≤ l′ + l″",
        "l_{OA} + l_{AB} = 100 + 500 = 600 мм = l_{DB} + l_{OD} = 300 + 300 = 600 мм",
        "Кривошип существует",
        "Равенство: звенья ложатся на одну прямую (особое положение)",
        "Пол. 6: план скоростей не строится",
    ] {
        assert!(text.lines().any(|l| l == line), "{line} not in:\n{text}");
    }
    let four = scene::load(&root().join("constructions/four-bar.toml")).expect("four-bar");
    let text = sheet_text(&four);
    for line in [
        "l_{O1A} + l_{O1O3} = 80 + 280 = 360 мм < l_{AB} + l_{O3B} = 250 + 180 = 430 мм",
        "Кривошип существует",
    ] {
        assert!(text.lines().any(|l| l == line), "{line} not in:\n{text}");
    }
    assert!(!text.contains("Равенство"), "{text}");
}

/// The closed forms on a sheet use the symbols of its own table and data (issue 45): the
/// friction sheet wrote M_f = Q·ρ over a table of M_тр, «без катков: P = Q·f₂» over P_ск,
/// k₁/h with an h the data never define (they give d), and α = 15,00° beside the data's
/// 15°; the dynamics sheet wrote m = K_mρD³ = 216,8 кг beside a table's 210,0 (taken at the
/// D before it is rounded up) without saying at which D. Now the mass is worked at the D
/// taken.
#[test]
fn closed_forms_write_the_tables_symbols_and_their_data() {
    let friction =
        sheet_text(&scene::load(&root().join("constructions/friction.toml")).expect("friction"));
    for written in [
        "M_{тр} = Q·ρ = 24,88",
        "k_{1}/d = 0,0005 < f_{1} = 0,1; k_{2}/d = 0,001 < f_{2} = 0,15",
        "без катков: P_{ск} = Q·f_{2} = 1500",
        "7: α = 15° < φ_{0} = 26,57°",
        // The forces P₁, P₂ are cut off at the moment balance's own scale.
        "μ_{d} = 0,004 м/мм, μ_{P} = 0,2 Н/мм",
    ] {
        assert!(friction.contains(written), "«{written}» in\n{friction}");
    }
    for gone in ["M_{f}", "/h = ", "15,00°"] {
        assert!(!friction.contains(gone), "«{gone}» in\n{friction}");
    }
    let shaper =
        sheet_text(&scene::load(&root().join("constructions/shaper.toml")).expect("shaper"));
    // The D found with its mass, as the table has them, then the D taken with its own.
    let mass =
        "мм, m = K_{m}ρD^3 = 209,5 кг; принимаем D = 860 мм: m = 0,0452·7540·0,86^3 = 216,8 кг";
    assert!(shaper.contains(mass), "«{mass}» in\n{shaper}");
}

#[test]
fn an_engines_force_sheets_give_the_masses_and_every_cylinder_its_loads_come_from() {
    // The V engine's gas forces come from each cylinder's bore and indicator diagram: the
    // force sheets state them (before, only the title block's «Масса» said anything).
    let s = scene::load(&root().join("constructions/v-engine.toml")).expect("v-engine");
    let session = Session::new(&s, Drafting::EXACT);
    let plates = sheets::build(&session, scene::PlateKind::Forces, Lang::Ru).expect("forces");
    for p in &plates {
        let text = texts(p).join("\n");
        let data = "Исходные данные\nm_{2} = 1,2 кг, J_{S2} = 0,00256 кг·м^2, m_{3} = 0,9 кг\nm_{4} = 1,2 кг, J_{S4} = 0,00256 кг·м^2, m_{5} = 0,9 кг\nd_{B} = 70 мм, p_{max B} = 4,2 МПа, φ_{0 B} = 45°\nd_{C} = 70 мм, p_{max C} = 4,2 МПа, φ_{0 C} = 135°";
        assert!(text.contains(data), "{}:\n{text}", p.name);
    }
}

#[test]
fn a_point_off_its_links_line_is_given_by_the_triangles_two_sides() {
    // The six-bar's C and S₃ lie on the triangular rocker DBC off its line DB: the data give
    // both sides from D and from B (before, neither: the drawn mechanism could not be
    // rebuilt from its data).
    let s = scene::load(&root().join("constructions/six-bar.toml")).expect("six-bar");
    let text = sheet_text(&s);
    let sides = "l_{DC} = 250 мм, l_{BC} = 150 мм, l_{AS2} = 250 мм, l_{DS3} = 177,17 мм";
    assert!(text.contains(sides), "«{sides}» in\n{text}");
}
