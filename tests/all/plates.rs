//! Visual regression of every plate of every scene (DESIGN §8): each plate is rendered to PNG
//! at a fixed width and compared with `tests/ref/<scene>-<plate>.png`. A pixel fails when any
//! channel differs by more than 1; no failing pixel is allowed. On failure a three-panel diff
//! (expected | mask | actual) goes to `out/diffs/`. `UPDATE_PLATES=1` rewrites the references
//! and still fails the run.

use resvg::tiny_skia::{Pixmap, PremultipliedColorU8};
use std::path::{Path, PathBuf};
use tmm::construct::Drafting;
use tmm::scale::Lang;
use tmm::scene::{self, PlateKind};

/// Width of the rendered test images, px.
const WIDTH: u32 = 1400;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The sheets of one plate of a scene, rendered: (sheet name, PNG). The sheets are built
/// with all the scene's plates, as `tmm render` builds them, so their numbering is the same.
fn render(scene_name: &str, plate: &str) -> Vec<(String, Vec<u8>)> {
    let path = root()
        .join("constructions")
        .join(format!("{scene_name}.toml"));
    let s = scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let kind = PlateKind::parse(plate).unwrap_or_else(|| panic!("unknown plate {plate}"));
    let all = tmm::render::plates(&s, Lang::Ru, Drafting::EXACT).unwrap_or_else(|e| panic!("{e}"));
    all.into_iter()
        .filter(|(k, _)| *k == kind)
        .map(|(_, p)| {
            let png = tmm::plate::to_png(&tmm::plate::to_svg(&p), WIDTH)
                .unwrap_or_else(|e| panic!("{e}"));
            (p.name, png)
        })
        .collect()
}

/// Count pixels differing by more than 1 in any channel and build the mask.
fn compare(expected: &Pixmap, actual: &Pixmap) -> (usize, Pixmap) {
    let (w, h) = (expected.width(), expected.height());
    let mut mask = Pixmap::new(w, h).expect("non-empty image");
    let mut failing = 0;
    for (k, (e, a)) in expected.pixels().iter().zip(actual.pixels()).enumerate() {
        let differs = [
            (e.red(), a.red()),
            (e.green(), a.green()),
            (e.blue(), a.blue()),
            (e.alpha(), a.alpha()),
        ]
        .iter()
        .any(|(x, y)| x.abs_diff(*y) > 1);
        let c = if differs {
            failing += 1;
            PremultipliedColorU8::from_rgba(255, 0, 0, 255)
        } else {
            PremultipliedColorU8::from_rgba(255, 255, 255, 255)
        };
        mask.pixels_mut()[k] = c.expect("opaque colour");
    }
    (failing, mask)
}

fn write_diff(name: &str, expected: &Pixmap, mask: &Pixmap, actual: &Pixmap) -> PathBuf {
    let (w, h) = (expected.width(), expected.height());
    let mut out = Pixmap::new(w * 3, h).expect("non-empty image");
    for (k, img) in [expected, mask, actual].into_iter().enumerate() {
        out.draw_pixmap(
            (w * k as u32) as i32,
            0,
            img.as_ref(),
            &Default::default(),
            Default::default(),
            None,
        );
    }
    let dir = root().join("out").join("diffs");
    let _ = std::fs::create_dir_all(&dir);
    let path = dir.join(format!("{name}.png"));
    let _ = out.save_png(&path);
    path
}

fn check(scene_name: &str, plate: &str) {
    let sheets = render(scene_name, plate);
    if std::env::var_os("UPDATE_PLATES").is_some() {
        for (sheet, png) in &sheets {
            let path = ref_path(&format!("{scene_name}-{sheet}"));
            let _ = std::fs::create_dir_all(path.parent().expect("tests/ref"));
            std::fs::write(&path, png).expect("write reference");
        }
        panic!("{scene_name}-{plate}: references rewritten; run again without UPDATE_PLATES");
    }
    for (sheet, png) in sheets {
        check_sheet(&format!("{scene_name}-{sheet}"), &png);
    }
}

fn ref_path(name: &str) -> PathBuf {
    root().join("tests").join("ref").join(format!("{name}.png"))
}

fn check_sheet(name: &str, png: &[u8]) {
    let ref_path = ref_path(name);
    let expected = Pixmap::load_png(&ref_path).unwrap_or_else(|e| {
        panic!(
            "{name}: no reference {} ({e}); create it with UPDATE_PLATES=1",
            ref_path.display()
        )
    });
    let actual = Pixmap::decode_png(png).expect("decode rendered plate");
    assert_eq!(
        (expected.width(), expected.height()),
        (actual.width(), actual.height()),
        "{name}: image size changed"
    );
    let (failing, mask) = compare(&expected, &actual);
    if failing > 0 {
        let diff = write_diff(name, &expected, &mask, &actual);
        panic!(
            "{name}: {failing} pixels differ by more than 1; diff at {}",
            diff.display()
        );
    }
}

macro_rules! plates {
    ($($test:ident: $scene:literal / $plate:literal),* $(,)?) => {
        $(
            #[test]
            fn $test() {
                check($scene, $plate);
            }
        )*
        const LISTED: &[(&str, &str)] = &[$(($scene, $plate)),*];
    };
}

plates! {
    shaper_kinematics: "shaper" / "kinematics",
    shaper_forces: "shaper" / "forces",
    shaper_dynamics: "shaper" / "dynamics",
    shaper_flywheel: "shaper" / "flywheel",
    slider_crank_kinematics: "slider-crank" / "kinematics",
    four_bar_kinematics: "four-bar" / "kinematics",
    six_bar_kinematics: "six-bar" / "kinematics",
    tangent_kinematics: "tangent" / "kinematics",
    rotor_static_balancing: "rotor-static" / "balancing",
    rotor_dynamic_balancing: "rotor-dynamic" / "balancing",
    friction_friction: "friction" / "friction",
    friction_follower_friction: "friction-follower" / "friction",
    shaper_gears: "shaper" / "gears",
    gears_pz1_gears: "gears-pz1" / "gears",
    gears_pz2_gears: "gears-pz2" / "gears",
    gears_pz2_ex1_gears: "gears-pz2-ex1" / "gears",
    gears_pz2_ex2_gears: "gears-pz2-ex2" / "gears",
    gears_differential_gears: "gears-differential" / "gears",
    gears_pz3_gears: "gears-pz3" / "gears",
    shaper_cam: "shaper" / "cam",
    cam_pz4_cam: "cam-pz4" / "cam",
    cam_pz5_cam: "cam-pz5" / "cam",
    cam_central_cam: "cam-central" / "cam",
    cam_undercut_cam: "cam-undercut" / "cam",
    cam_cusp_cam: "cam-cusp" / "cam",
    cam_shock_cam: "cam-shock" / "cam",
    cam_flat_rocker_cam: "cam-flat-rocker" / "cam",
    cam_sliding_cam: "cam-sliding" / "cam",
    v_engine_kinematics: "v-engine" / "kinematics",
    v_engine_forces: "v-engine" / "forces",
    v_engine_dynamics: "v-engine" / "dynamics",
    v_engine_flywheel: "v-engine" / "flywheel",
}

/// Every plate of every scene in `constructions/` has its test above.
#[test]
fn every_plate_of_every_scene_is_tested() {
    let dir = root().join("constructions");
    let mut missing = Vec::new();
    for entry in std::fs::read_dir(&dir).expect("constructions/") {
        let path = entry.expect("entry").path();
        if path.extension().is_none_or(|x| x != "toml") {
            continue;
        }
        let s = scene::load(Path::new(&path)).unwrap_or_else(|e| panic!("{e}"));
        for k in tmm::sheets::drawn(&s) {
            if !LISTED.contains(&(s.stem.as_str(), k.stem())) {
                missing.push(format!("{}/{}", s.stem, k.stem()));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "plates without a pixel test: {missing:?}"
    );
}
