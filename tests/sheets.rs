//! The sheets' rules: the scene's scales are used as given, views that need more room go on
//! a further sheet, and a view too large for any sheet at its given scale is refused naming
//! the key and the largest scale that fits.

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

#[test]
fn the_shaper_sheets_print_the_scene_scales_as_given() {
    let s = scene::load(&root().join("constructions/shaper.toml")).expect("shaper");
    let session = Session::new(&s, Drafting::EXACT);
    let all = sheets::build_all(&session, Lang::Ru).expect("plates");
    assert_eq!(all.len(), 2, "one A1 sheet per plate");
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
    ] {
        assert!(text.contains(given), "{given} not on the sheets:\n{text}");
    }
    for bumped in ["μ_{l} = 0,004", "μ_{v} = 0,1 "] {
        assert!(!text.contains(bumped), "{bumped} on the sheets:\n{text}");
    }
    // Sheet k of n across the scene.
    let numbers: Vec<(u32, u32)> = all
        .iter()
        .map(|(_, p)| (p.title_block.sheet_no, p.title_block.sheets))
        .collect();
    assert_eq!(numbers, vec![(1, 2), (2, 2)]);
}

#[test]
fn a_view_too_large_at_its_given_scale_names_the_key_and_the_scale_that_fits() {
    let text = shaper_text().replace("scale_v = 0.05 ", "scale_v = 0.002 ");
    let s = scene::parse(&text, &root().join("big.toml")).expect("scene");
    let session = Session::new(&s, Drafting::EXACT);
    let err = sheets::build_all(&session, Lang::Ru)
        .expect_err("too large")
        .1
        .to_string();
    assert!(err.contains("kinematics.scale_v"), "{err}");
    assert!(
        err.contains("the largest scale at which it fits is μ_v = "),
        "{err}"
    );
}

#[test]
fn views_that_need_more_room_continue_on_a_further_sheet() {
    let s = scene::load(&root().join("constructions/six-bar.toml")).expect("six-bar");
    let session = Session::new(&s, Drafting::EXACT);
    let all = sheets::build_all(&session, Lang::Ru).expect("plates");
    let names: Vec<&str> = all.iter().map(|(_, p)| p.name.as_str()).collect();
    assert_eq!(names, ["positions", "kinematics", "kinematics-2"]);
    for (k, (_, p)) in all.iter().enumerate() {
        assert_eq!(p.title_block.sheet_no as usize, k + 1);
        assert_eq!(p.title_block.sheets, 3);
    }
}
