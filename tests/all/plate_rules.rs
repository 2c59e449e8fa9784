//! Rules every plate of every scene in `constructions/` must meet (issue 7), checked on the
//! plate's layout ([`tmm::plate::layout`]) — the same boxes the SVG writer writes from:
//! - no two texts of the drawing overlap: labels (a joint label `p ≡ b₃ ≡ d` is one box) and
//!   view captions among themselves, and labels with the text blocks and tables;
//! - everything drawn (every view's items, its caption and labels, the text blocks, the
//!   tables) lies inside the frame, clear of its line, and off the title block and the
//!   designation box.

use glam::DVec2;
use std::path::PathBuf;
use tmm::construct::Drafting;
use tmm::plate::{layout, Layout, Plate, Rect};
use tmm::scale::Lang;
use tmm::scene::{self, PlateKind};
use tmm::study::Session;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The sheets of plate `plate` of the scene `constructions/<scene_name>.toml`, in Russian.
fn sheets_of(scene_name: &str, plate: &str) -> Vec<Plate> {
    let file = format!("constructions/{scene_name}.toml");
    let built = tmm::load(&root().join(file)).map(|s| {
        let kind = PlateKind::parse(plate).expect("a plate kind");
        tmm::build(&Session::new(&s, Drafting::EXACT), kind, Lang::Ru)
    });
    match built {
        Ok(Ok(p)) => p,
        Ok(Err(e)) => panic!("{scene_name}/{plate}: {e}"),
        Err(e) => panic!("{scene_name}: {e}"),
    }
}

/// The first sheet of a plate.
fn plate_of(scene_name: &str, plate: &str) -> Plate {
    sheets_of(scene_name, plate).remove(0)
}

/// The layout of every sheet of a plate, with the sheet's name.
fn laid_out(scene_name: &str, plate: &str) -> Vec<(String, Layout)> {
    sheets_of(scene_name, plate)
        .iter()
        .map(|p| (p.name.clone(), layout(p)))
        .collect()
}

/// A named box of the layout.
struct Item {
    name: String,
    rect: Rect,
}

fn labels(l: &Layout) -> Vec<Item> {
    l.labels
        .iter()
        .map(|x| Item {
            name: format!("view {} label “{}”", x.view, x.text),
            rect: x.rect,
        })
        .collect()
}

fn captions(l: &Layout) -> Vec<Item> {
    l.views
        .iter()
        .enumerate()
        .filter_map(|(k, v)| {
            v.caption.map(|rect| Item {
                name: format!("view {k} caption"),
                rect,
            })
        })
        .collect()
}

fn blocks(l: &Layout) -> Vec<Item> {
    let texts = l.texts.iter().enumerate().map(|(k, &rect)| Item {
        name: format!("text block {k}"),
        rect,
    });
    let tables = l.tables.iter().enumerate().map(|(k, &rect)| Item {
        name: format!("table {k}"),
        rect,
    });
    texts.chain(tables).collect()
}

/// Every pair of overlapping texts, described.
fn overlaps(l: &Layout) -> Vec<String> {
    let texts: Vec<Item> = labels(l).into_iter().chain(captions(l)).collect();
    let mut out = Vec::new();
    for (i, a) in texts.iter().enumerate() {
        for b in texts[..i].iter().chain(&blocks(l)) {
            if a.rect.intersects(&b.rect) {
                out.push(format!("{} / {}", a.name, b.name));
            }
        }
    }
    out
}

/// How far everything drawn stays inside the frame, mm (the label placer's own clearance):
/// a text 0,95 mm from the frame's line (gears-pz3's a_w, whose view's bounds left out its
/// dimension's text) reads as written on it.
const FRAME_CLEAR_MM: f64 = 1.0;
/// How far a label stays inside the frame, mm: the V engine's F_и5 1,5 mm from the frame's
/// line, at the corner of the sheet, read as crowded against it (issue 45).
const LABEL_FRAME_CLEAR_MM: f64 = 2.5;

/// Everything drawn outside the frame, against it, or over the title block or the
/// designation box.
fn outside(l: &Layout) -> Vec<String> {
    let drawn = l.views.iter().enumerate().filter_map(|(k, v)| {
        v.drawn.map(|rect| Item {
            name: format!("view {k}"),
            rect,
        })
    });
    let others = drawn.chain(captions(l)).chain(blocks(l));
    let all = (others.map(|x| (x, FRAME_CLEAR_MM)))
        .chain(labels(l).into_iter().map(|x| (x, LABEL_FRAME_CLEAR_MM)));
    all.filter_map(|(x, clear)| {
        let mut why = Vec::new();
        if !l.frame.contains(&x.rect) {
            why.push("leaves the frame");
        } else if !l.frame.inflate(-clear).contains(&x.rect) {
            why.push("stands against the frame");
        }
        if x.rect.intersects(&l.title_block) {
            why.push("covers the title block");
        }
        if x.rect.intersects(&l.designation_box) {
            why.push("covers the designation box");
        }
        (!why.is_empty()).then(|| format!("{} {} ({:?})", x.name, why.join(", "), x.rect))
    })
    .collect()
}

fn assert_none(what: &str, scene: &str, plate: &str, found: Vec<String>) {
    assert!(
        found.is_empty(),
        "{scene}/{plate}: {} {what}:\n  {}",
        found.len(),
        found.join("\n  ")
    );
}

fn no_overlaps(scene: &str, plate: &str) {
    for (sheet, l) in laid_out(scene, plate) {
        assert_none("overlapping texts", scene, &sheet, overlaps(&l));
    }
}

fn inside_frame(scene: &str, plate: &str) {
    for (sheet, l) in laid_out(scene, plate) {
        assert_none("items off the field", scene, &sheet, outside(&l));
    }
}

macro_rules! rules {
    ($($overlap:ident, $frame:ident: $scene:literal / $plate:literal),* $(,)?) => {
        $(
            #[test]
            fn $overlap() {
                no_overlaps($scene, $plate);
            }
            #[test]
            fn $frame() {
                inside_frame($scene, $plate);
            }
        )*
        const LISTED: &[(&str, &str)] = &[$(($scene, $plate)),*];
    };
}

rules! {
    shaper_kinematics_texts_apart, shaper_kinematics_inside_frame: "shaper" / "kinematics",
    shaper_forces_texts_apart, shaper_forces_inside_frame: "shaper" / "forces",
    shaper_dynamics_texts_apart, shaper_dynamics_inside_frame: "shaper" / "dynamics",
    shaper_flywheel_texts_apart, shaper_flywheel_inside_frame: "shaper" / "flywheel",
    slider_crank_kinematics_texts_apart, slider_crank_kinematics_inside_frame: "slider-crank" / "kinematics",
    four_bar_kinematics_texts_apart, four_bar_kinematics_inside_frame: "four-bar" / "kinematics",
    six_bar_kinematics_texts_apart, six_bar_kinematics_inside_frame: "six-bar" / "kinematics",
    tangent_kinematics_texts_apart, tangent_kinematics_inside_frame: "tangent" / "kinematics",
    rotor_static_balancing_texts_apart, rotor_static_balancing_inside_frame: "rotor-static" / "balancing",
    rotor_dynamic_balancing_texts_apart, rotor_dynamic_balancing_inside_frame: "rotor-dynamic" / "balancing",
    friction_texts_apart, friction_inside_frame: "friction" / "friction",
    friction_follower_texts_apart, friction_follower_inside_frame: "friction-follower" / "friction",
    shaper_gears_texts_apart, shaper_gears_inside_frame: "shaper" / "gears",
    gears_pz1_texts_apart, gears_pz1_inside_frame: "gears-pz1" / "gears",
    gears_pz2_texts_apart, gears_pz2_inside_frame: "gears-pz2" / "gears",
    gears_pz2_ex1_texts_apart, gears_pz2_ex1_inside_frame: "gears-pz2-ex1" / "gears",
    gears_pz2_ex2_texts_apart, gears_pz2_ex2_inside_frame: "gears-pz2-ex2" / "gears",
    gears_differential_texts_apart, gears_differential_inside_frame: "gears-differential" / "gears",
    gears_pz3_texts_apart, gears_pz3_inside_frame: "gears-pz3" / "gears",
    shaper_cam_texts_apart, shaper_cam_inside_frame: "shaper" / "cam",
    cam_pz4_texts_apart, cam_pz4_inside_frame: "cam-pz4" / "cam",
    cam_pz5_texts_apart, cam_pz5_inside_frame: "cam-pz5" / "cam",
    cam_central_texts_apart, cam_central_inside_frame: "cam-central" / "cam",
    cam_undercut_texts_apart, cam_undercut_inside_frame: "cam-undercut" / "cam",
    cam_cusp_texts_apart, cam_cusp_inside_frame: "cam-cusp" / "cam",
    cam_shock_texts_apart, cam_shock_inside_frame: "cam-shock" / "cam",
    cam_flat_rocker_texts_apart, cam_flat_rocker_inside_frame: "cam-flat-rocker" / "cam",
    cam_sliding_texts_apart, cam_sliding_inside_frame: "cam-sliding" / "cam",
    v_engine_kinematics_texts_apart, v_engine_kinematics_inside_frame: "v-engine" / "kinematics",
    v_engine_forces_texts_apart, v_engine_forces_inside_frame: "v-engine" / "forces",
    v_engine_dynamics_texts_apart, v_engine_dynamics_inside_frame: "v-engine" / "dynamics",
    v_engine_flywheel_texts_apart, v_engine_flywheel_inside_frame: "v-engine" / "flywheel",
}

/// The scene files of `constructions/`.
fn scene_files() -> Vec<PathBuf> {
    let dir = std::fs::read_dir(root().join("constructions")).expect("constructions/");
    dir.map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect()
}

/// Every plate of every scene in `constructions/` is checked above.
#[test]
fn every_plate_of_every_scene_is_checked() {
    let mut missing = Vec::new();
    for path in scene_files() {
        let s = scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        for k in tmm::sheets::drawn(&s) {
            if !LISTED.contains(&(s.stem.as_str(), k.stem())) {
                missing.push(format!("{}/{}", s.stem, k.stem()));
            }
        }
    }
    assert!(missing.is_empty(), "plates not checked: {missing:?}");
}

/// The rules see what they are meant to: a view moved off the sheet and onto another one
/// breaks both.
#[test]
fn the_rules_catch_a_misplaced_view() {
    let mut p = plate_of("shaper", "kinematics");
    let l = layout(&p);
    assert!(l.views.iter().all(|v| v.drawn.is_some()));
    assert!(l.labels.len() > 50);
    // Two velocity plans (views 3 and 4, after the structural scheme, the plan of positions
    // and plan 1) drawn at one place: their captions collide and their ink lies on each other.
    let mut copy = p.views[3].clone();
    copy.origin = p.views[4].origin;
    // Its caption where plan 3's is (a caption may stand lower than its plan ends).
    copy.caption_drop = p.views[4].caption_drop;
    p.views.push(copy);
    p.views[0].origin -= DVec2::new(100.0, 0.0);
    let l = layout(&p);
    assert!(!overlaps(&l).is_empty());
    let last = p.views.len() - 1;
    let on = views_on_views(&p);
    assert!(
        on.iter()
            .any(|x| x.starts_with(&format!("view 4 / view {last}:"))),
        "{on:?}"
    );
    let out = outside(&l);
    assert!(out.iter().any(|x| x.starts_with("view 0 ")), "{out:?}");
}

/// Every label of every step is written once: coincident ones in one joint label, the pole
/// first, and the SVG writes exactly the layout's labels.
#[test]
fn every_label_is_written_once() {
    let p = plate_of("shaper", "kinematics");
    let l = layout(&p);
    let svg = tmm::plate::to_svg(&p);
    for (k, view) in p.views.iter().enumerate() {
        let mut labelled: Vec<_> = view
            .figure
            .steps
            .iter()
            .filter(|s| s.label.is_some())
            .map(|s| s.id)
            .collect();
        let mut written: Vec<_> = l
            .labels
            .iter()
            .filter(|x| x.view == k)
            .flat_map(|x| x.steps.iter().copied())
            .collect();
        labelled.sort();
        written.sort();
        assert_eq!(labelled, written, "view {k}");
        let texts = svg
            .matches(&format!(r#"id="view-{k}-labels-text-"#))
            .count();
        assert_eq!(texts, l.labels.iter().filter(|x| x.view == k).count());
    }
    let joint: Vec<_> = l.labels.iter().filter(|x| x.steps.len() > 1).collect();
    assert!(
        !joint.is_empty(),
        "the shaper's plans have coincident images"
    );
    for x in joint {
        let names: Vec<_> = x.text.split(tmm::plate::JOINT_SEPARATOR).collect();
        assert_eq!(names.len(), x.steps.len(), "{}", x.text);
        if names.contains(&"p") {
            assert_eq!(names[0], "p", "{}", x.text);
        }
    }
}

/// The side of the grid cells in which the ink of two views is compared, mm.
const INK_CELL_MM: f64 = 1.0;

/// Every pair of views of a sheet whose ink shares a cell of the grid, with the shared area.
fn views_on_views(p: &Plate) -> Vec<String> {
    let ink = tmm::plate::view_ink(p, INK_CELL_MM);
    let mut out = Vec::new();
    for (i, a) in ink.iter().enumerate() {
        for (j, b) in ink.iter().enumerate().skip(i + 1) {
            let shared = a.intersection(b).count();
            if shared > 0 {
                let mm2 = shared as f64 * INK_CELL_MM * INK_CELL_MM;
                out.push(format!("view {i} / view {j}: {mm2:.0} mm²"));
            }
        }
    }
    out
}

/// The view rule: the ink of two views never lies on the ink of another (each plan, polygon
/// and diagram is drawn apart, with its construction), on every sheet of every plate.
#[test]
fn no_view_is_drawn_over_another() {
    let mut found = Vec::new();
    for (scene, plate) in LISTED {
        for p in sheets_of(scene, plate) {
            found.extend(
                views_on_views(&p)
                    .into_iter()
                    .map(|x| format!("{scene}/{}: {x}", p.name)),
            );
        }
    }
    assert!(
        found.is_empty(),
        "views drawn over each other:\n  {}",
        found.join("\n  ")
    );
}

/// Every plate's SVG reads alike in every renderer: a text with sub- or superscripts (its
/// `<tspan>`s) is anchored at its start, since a renderer that anchors each `<tspan>` on its
/// own (cairosvg, which `plate-legibility` reads with) would scatter a centred caption's
/// pieces over the neighbouring views.
#[test]
fn scripted_texts_are_anchored_at_their_start() {
    let mut found = Vec::new();
    for (scene, plate) in LISTED {
        for p in sheets_of(scene, plate) {
            let svg = tmm::plate::to_svg(&p);
            let scripted = svg
                .split("<text ")
                .skip(1)
                .filter_map(|t| t.split_once("</text>").map(|(t, _)| t))
                .filter(|t| t.contains("<tspan"));
            let mut n = 0;
            for t in scripted {
                n += 1;
                if !t.contains(r#"text-anchor="start""#) {
                    found.push(format!("{scene}/{}: {}", p.name, &t[..t.len().min(80)]));
                }
            }
            assert!(n > 0, "{scene}/{}: no scripted text", p.name);
        }
    }
    assert!(
        found.is_empty(),
        "anchored mid-text:\n  {}",
        found.join("\n  ")
    );
}

/// The smallest a plan, polygon or diagram may be drawn, mm (its longest side).
const SMALLEST_VIEW_MM: f64 = 30.0;

/// The scene keys that fix the scale of a drawing of `q` (a scene that gives one keeps its
/// μ, however small the drawing comes out).
fn fixing_keys(q: tmm::scale::Quantity) -> &'static [(&'static str, &'static str)] {
    use tmm::scale::Quantity as Q;
    match q {
        Q::Velocity => &[("kinematics", "scale_v")],
        Q::Acceleration => &[("kinematics", "scale_a")],
        Q::Force => &[("forces", "scale_f"), ("friction", "scale_f")],
        Q::Moment => &[("dynamics", "scale_m")],
        _ => &[],
    }
}

/// The size rule: every plan, polygon and diagram (a view at a scale of velocity,
/// acceleration, force, moment, work, inertia …, the plan of positions and the structural
/// scheme left out) is drawn at least `SMALLEST_VIEW_MM` long unless the scene fixes its
/// scale, on every sheet of every plate drawn for every scene. The force sheets (the lead's,
/// issue 19 item 1) are left out until their polygons are redrawn.
#[test]
fn every_plan_polygon_and_diagram_is_large_enough_to_read() {
    let mut small = Vec::new();
    for path in scene_files() {
        let text = std::fs::read_to_string(&path).expect("scene text");
        let table: toml::Table = text.parse().expect("toml");
        let fixed = |q| {
            fixing_keys(q)
                .iter()
                .any(|(sec, key)| table.get(*sec).and_then(|t| t.get(*key)).is_some())
        };
        let s = scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        let session = Session::new(&s, Drafting::EXACT);
        let all = tmm::sheets::build_all(&session, Lang::Ru).unwrap_or_else(|(_, e)| panic!("{e}"));
        for (_, p) in all {
            for v in &p.views {
                let q = v.figure.scale.quantity;
                if matches!(
                    q,
                    tmm::scale::Quantity::Length | tmm::scale::Quantity::Angle
                ) || fixed(q)
                {
                    continue;
                }
                let Some((lo, hi)) = v.figure.bounds() else {
                    continue;
                };
                let long = (hi - lo).max_element();
                if long < SMALLEST_VIEW_MM {
                    small.push(format!(
                        "{}/{}: “{}” {:.1} mm",
                        s.stem,
                        p.name,
                        v.caption.as_deref().unwrap_or(&v.figure.title),
                        long
                    ));
                }
            }
        }
    }
    assert!(
        small.is_empty(),
        "drawn too small to read:\n  {}",
        small.join("\n  ")
    );
}

/// The kinematic sheets of the linkage scenes, laid out.
fn kinematic_sheets() -> Vec<(String, Plate, Layout)> {
    let mut out = Vec::new();
    for scene in [
        "shaper",
        "four-bar",
        "six-bar",
        "slider-crank",
        "tangent",
        "v-engine",
    ] {
        for p in sheets_of(scene, "kinematics") {
            let l = layout(&p);
            out.push((format!("{scene}/{}", p.name), p, l));
        }
    }
    out
}

/// The kinematic sheets of the four-bar's variants (`constructions/variants/four-bar.csv`) and
/// of V engines with other angles between the cylinders (60°, 90° and 120°): layouts where the
/// plans go around a plan of positions of other proportions, laid out.
fn variant_sheets() -> Vec<(String, Plate, Layout)> {
    let mut scenes = Vec::new();
    let four_bar =
        std::fs::read_to_string(root().join("constructions/four-bar.toml")).expect("four-bar");
    let grid_path = root().join("constructions/variants/four-bar.csv");
    let grid = std::fs::read_to_string(&grid_path).expect("grid");
    for v in tmm::batch::read_grid(&four_bar, &grid, &grid_path).expect("variants") {
        scenes.push((format!("four-bar {}", v.name), v.text().expect("text")));
    }
    let v_engine =
        std::fs::read_to_string(root().join("constructions/v-engine.toml")).expect("v-engine");
    for half in [30.0, 60.0] {
        let text = v_engine
            .replace("dir = 45.0", &format!("dir = {}", 90.0 - half))
            .replace("dir = 135.0", &format!("dir = {}", 90.0 + half));
        scenes.push((format!("v-engine {}°", 2.0 * half), text));
    }
    let kind = PlateKind::parse("kinematics").expect("kind");
    let mut out = Vec::new();
    for (name, text) in scenes {
        let s = scene::parse(&text, &root().join("constructions/variant.toml"))
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let plates = tmm::build(&Session::new(&s, Drafting::EXACT), kind, Lang::Ru)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        for p in plates {
            let l = layout(&p);
            out.push((format!("{name}/{}", p.name), p, l));
        }
    }
    out
}

/// Whether the plans `a` then `b` of one sheet read in order: `b` to the right of `a` on its
/// row, with no other drawing between them (a row does not run on across the plan of
/// positions), or on a new row under it.
fn read_in_order(a: Rect, b: Rect, others: &[Rect]) -> bool {
    let below = b.min.y > a.max.y;
    let right = b.min.x > a.max.x && b.min.y < a.max.y;
    let (top, bottom) = (a.min.y.max(b.min.y), a.max.y.min(b.max.y));
    let between = others
        .iter()
        .any(|o| o.min.x < b.min.x && o.max.x > a.max.x && o.min.y < bottom && o.max.y > top);
    below || right && !between
}

/// The velocity plans read in the order of their positions (1 … 12 with 8′ in its place):
/// each to the right of the one before on its row, no other drawing between them, or on a
/// new row under it — on the shipped scenes' sheets and on the four-bar and V layouts of
/// [`variant_sheets`].
#[test]
fn the_plans_read_in_the_order_of_their_positions() {
    let mut found = Vec::new();
    let all = kinematic_sheets().into_iter().chain(variant_sheets());
    let mut n = 0;
    for (sheet, p, l) in all {
        n += 1;
        let is_plan = |c: &Option<String>| c.as_deref().is_some_and(|c| c.starts_with("Пол. "));
        let plans: Vec<Rect> = p
            .views
            .iter()
            .zip(&l.views)
            .filter(|(v, _)| is_plan(&v.caption))
            .filter_map(|(_, v)| v.drawn)
            .collect();
        let others: Vec<Rect> = p
            .views
            .iter()
            .zip(&l.views)
            .filter(|(v, _)| !is_plan(&v.caption))
            .filter_map(|(_, v)| v.drawn)
            .collect();
        for w in plans.windows(2) {
            if !read_in_order(w[0], w[1], &others) {
                found.push(format!("{sheet}: {:?} then {:?}", w[0], w[1]));
            }
        }
    }
    assert!(n > 30, "{n} sheets");
    assert!(found.is_empty(), "{}", found.join("\n"));
}

/// The order rule sees a row run on across another drawing.
#[test]
fn the_order_rule_sees_a_row_across_the_plan_of_positions() {
    let r = |x0: f64, y0: f64, x1: f64, y1: f64| Rect::new(DVec2::new(x0, y0), DVec2::new(x1, y1));
    let (a, b) = (r(20.0, 200.0, 120.0, 280.0), r(500.0, 210.0, 600.0, 300.0));
    assert!(read_in_order(a, b, &[]));
    assert!(!read_in_order(a, b, &[r(150.0, 20.0, 450.0, 260.0)]));
    assert!(read_in_order(a, b, &[r(150.0, 20.0, 450.0, 190.0)]));
    assert!(read_in_order(a, r(20.0, 300.0, 120.0, 380.0), &[]));
}

/// A plan's labels stay off the other views: the pole of a plan where every point coincides
/// (the shaper's 8′: `p ≡ b₃ ≡ d ≡ s₃ ≡ d₅ ≡ e ≡ s₅`, about 70 mm) is given room in its block.
#[test]
fn long_joint_labels_stay_off_the_next_plan() {
    let mut found = Vec::new();
    let mut longest = 0.0f64;
    for (sheet, _, l) in kinematic_sheets() {
        // The labels of a pole where five points or more coincide.
        for x in l.labels.iter().filter(|x| x.steps.len() >= 5) {
            longest = longest.max(x.rect.width());
            for (k, v) in l.views.iter().enumerate() {
                if k != x.view && v.drawn.is_some_and(|d| d.intersects(&x.rect)) {
                    found.push(format!(
                        "{sheet}: “{}” of view {} on view {k}",
                        x.text, x.view
                    ));
                }
            }
        }
    }
    assert!(
        longest > 60.0,
        "the shaper's joint label at 8′: {longest} mm"
    );
    assert!(found.is_empty(), "{}", found.join("\n"));
}
