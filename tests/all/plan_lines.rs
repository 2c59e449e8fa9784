//! The line types of the kinematic sheet, as a draughtsman draws them (ГОСТ 2.303, issue 19):
//! on a plan the vectors of the points nothing is built on (the centres of mass) thin, the
//! structural ones main lines, so that the vectors meeting at the pole stay apart; on the plan
//! of positions only position 1 (the one the letters name) in main lines; the pole distance
//! H of a chord-method diagram dimensioned under the fan of rays, clear of them. And the labels
//! of the plans stay off the lines of their own plan (item 6): a joint label such as
//! `d₅ ≡ e ≡ s₅` is not crossed, nor touched at its start, by the direction lines drawn
//! through its point — the label's box as the layout places it against the plan's segments
//! and vectors.

use std::path::PathBuf;
use tmm::construct::{Drafting, Item, Role};
use tmm::geom::DVec2;
use tmm::plate::{layout, PlacedLabel, Plate, Rect, View, LABEL_GAP_MM};
use tmm::scale::Lang;
use tmm::scene::PlateKind;
use tmm::study::Session;

/// The linkage scenes with a kinematic sheet.
const LINKAGES: &str = "shaper four-bar six-bar slider-crank tangent v-engine";

/// Clearance a label keeps from every line of its plan, mm (the placer weighs lines within
/// 0.5 mm of a box): a line ending closer than this runs into the text (`—d₅`). The shaper's
/// acceleration plan at position 3 had the slide's direction line 3.5 mm into `d₅′ ≡ e′ ≡ s₅′`.
const CLEAR_MM: f64 = 0.3;

fn sheets_of(scene: &str) -> Vec<Plate> {
    sheets_of_kind(scene, "kinematics")
}

/// The scene's sheets of one plate kind, in Russian.
fn sheets_of_kind(scene: &str, kind: &str) -> Vec<Plate> {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("constructions/{scene}.toml"));
    let s = tmm::load(&path).unwrap_or_else(|e| panic!("{scene}: {e}"));
    let kind = PlateKind::parse(kind).expect("a plate kind");
    tmm::build(&Session::new(&s, Drafting::EXACT), kind, Lang::Ru)
        .unwrap_or_else(|e| panic!("{scene}: {e}"))
}

fn views(scene: &str) -> Vec<View> {
    sheets_of(scene).into_iter().flat_map(|p| p.views).collect()
}

fn captioned(views: &[View], start: &str) -> Vec<View> {
    views
        .iter()
        .filter(|v| v.caption.as_deref().is_some_and(|c| c.starts_with(start)))
        .cloned()
        .collect()
}

/// The role of the vector `image <label>` of a plan.
fn image_role(v: &View, label: &str) -> Option<Role> {
    let note = format!("image {label}");
    v.figure
        .steps
        .iter()
        .find(|s| s.note == note && matches!(s.item, Item::Vector { .. }))
        .map(|s| s.role)
}

#[test]
fn centres_of_mass_are_thin_vectors_and_the_structural_points_main_ones() {
    let all = views("six-bar");
    let plans: Vec<View> = [captioned(&all, "Пол. "), captioned(&all, "План ускорений")].concat();
    assert!(plans.len() >= 12, "{} plans", plans.len());
    for v in &plans {
        let caption = v.caption.clone().unwrap_or_default();
        let prime = if caption.starts_with("План") {
            "′"
        } else {
            ""
        };
        for s in ["s_2", "s_3", "s_4"] {
            let role = image_role(v, &format!("{s}{prime}"));
            assert_eq!(role, Some(Role::Construction), "{caption}: {s}");
        }
        // C carries group 4–5: a structural point, drawn with the main line.
        for p in ["a", "b", "c", "e"] {
            let role = image_role(v, &format!("{p}{prime}"));
            assert_eq!(role, Some(Role::Result), "{caption}: {p}");
        }
    }
}

/// The image of a carrier's point under a slider's joint is an absolute vector from the
/// pole, the one the relative velocity adds to: drawn as a main line wherever it is found —
/// the shaper's pb₃ (where two direction lines meet) as the tangent mechanism's pb₁ (by
/// similarity on the crank; it had been thin as a centre of mass's).
#[test]
fn a_carriers_point_under_a_joint_is_a_main_vector() {
    for (scene, image) in [("tangent", "b_{1}"), ("shaper", "b_{3}")] {
        let all = views(scene);
        let plans: Vec<View> =
            [captioned(&all, "Пол. "), captioned(&all, "План ускорений")].concat();
        let mut seen = 0;
        for v in &plans {
            let caption = v.caption.clone().unwrap_or_default();
            let prime = if caption.starts_with("План") {
                "′"
            } else {
                ""
            };
            if let Some(role) = image_role(v, &format!("{image}{prime}")) {
                assert_eq!(role, Role::Result, "{scene} {caption}: {image}{prime}");
                seen += 1;
            }
        }
        assert!(seen >= 12, "{scene}: {seen} plans draw {image}");
    }
}

#[test]
fn only_position_one_is_drawn_in_main_lines_on_the_plan_of_positions() {
    for scene in ["six-bar", "shaper", "four-bar"] {
        let all = views(scene);
        let plan = captioned(&all, "План положений");
        assert_eq!(plan.len(), 1, "{scene}");
        let links: Vec<_> = plan[0]
            .figure
            .steps
            .iter()
            .filter(|s| s.note.starts_with("position ") && s.note.ends_with(": crank"))
            .collect();
        assert!(links.len() >= 12, "{scene}: {} cranks", links.len());
        for s in links {
            let want = if s.note == "position 1: crank" {
                Role::Given
            } else {
                Role::Construction
            };
            assert_eq!(s.role, want, "{scene}: {}", s.note);
        }
    }
}

/// Whether the segments `a`–`b` and `c`–`d` cross.
fn cross(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let side = |p: DVec2, q: DVec2, r: DVec2| (q - p).perp_dot(r - p);
    side(a, b, c) * side(a, b, d) < 0.0 && side(c, d, a) * side(c, d, b) < 0.0
}

#[test]
fn the_pole_distance_is_dimensioned_clear_of_the_rays() {
    let mut checked = 0;
    for scene in ["shaper", "six-bar", "slider-crank", "v-engine", "four-bar"] {
        for v in views(scene) {
            let steps = &v.figure.steps;
            for dim in steps.iter().filter(|s| s.note.starts_with("pole distance")) {
                let Item::Dimension { from, to, offset } = dim.item else {
                    panic!("{scene}: {} is not a dimension", dim.note);
                };
                let n = (to - from).normalize().perp() * offset;
                let line = (from + n, to + n);
                // The rays of the pole the dimension belongs to start at `from`.
                let rays: Vec<_> = steps
                    .iter()
                    .filter_map(|s| match s.item {
                        Item::Segment(g) if s.note.starts_with("ray ") && g.from == from => Some(g),
                        _ => None,
                    })
                    .collect();
                assert!(rays.len() >= 6, "{scene}: {} rays", rays.len());
                for r in rays {
                    assert!(
                        !cross(line.0, line.1, r.from, r.to),
                        "{scene}: a ray crosses the dimension line of {}",
                        dim.note
                    );
                }
                // The text over the line (3.5 mm high) is clear of the fan too: the lowest
                // ray ends at least 5 mm above the dimension line.
                let lowest = steps
                    .iter()
                    .filter_map(|s| match s.item {
                        Item::Segment(g) if s.note.starts_with("ray ") && g.from == from => {
                            Some(g.to.y)
                        }
                        _ => None,
                    })
                    .fold(f64::INFINITY, f64::min);
                assert!(lowest - line.0.y >= 5.0, "{scene}: {}", dim.note);
                checked += 1;
            }
        }
    }
    // H₁ and H₂ of four diagrams, H_ω of the shaper's and the four-bar's rockers.
    assert!(checked >= 8, "{checked} pole distances");
}

/// A free μ_v is chosen from the room: the slider-crank's crank pin velocity (ω₁·OA) drawn
/// at least 80 mm, the same μ_v stated on its sheet, which stays one sheet; a μ the scene
/// fixes (the six-bar's 0,026, the shaper's 0,05) is kept.
#[test]
fn a_free_velocity_scale_draws_the_crank_pin_at_least_80_mm_and_a_fixed_one_is_kept() {
    let load = |scene: &str| {
        let path =
            PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("constructions/{scene}.toml"));
        tmm::load(&path).unwrap_or_else(|e| panic!("{scene}: {e}"))
    };
    let s = load("slider-crank");
    let session = Session::new(&s, Drafting::EXACT);
    let sc = session.kin_scales().expect("scales");
    let plans = session.kinematics(&sc).expect("kinematics");
    let pin = plans
        .velocity_plans()
        .into_iter()
        .flatten()
        .next()
        .expect("a velocity plan")
        .images
        .iter()
        .map(|p| p.length())
        .fold(0.0f64, f64::max);
    assert!(pin >= 80.0 - 1e-9, "longest vector {pin} mm");
    let sheets = sheets_of("slider-crank");
    assert_eq!(sheets.len(), 1);
    let caption = sc.v.caption(Lang::Ru);
    assert!(
        sheets[0]
            .texts
            .iter()
            .any(|t| t.lines.iter().any(|l| l.contains(&caption))),
        "{caption} on the sheet"
    );
    for (scene, mu) in [("six-bar", 0.026), ("shaper", 0.05)] {
        let s = load(scene);
        let sc = Session::new(&s, Drafting::EXACT)
            .kin_scales()
            .expect("scales");
        assert_eq!(sc.v.value(), mu, "{scene}");
    }
}

/// Lines through the labelled point itself are left out within this distance of it, mm: the
/// label stands [`LABEL_GAP_MM`] from its point, beside the lines that meet there.
const NEAR_POINT_MM: f64 = LABEL_GAP_MM + 1.5;

/// Length of the segment `a`–`b` inside `r`, away from the labelled point `at`.
fn inside(a: DVec2, b: DVec2, r: &Rect, at: DVec2) -> f64 {
    let n = 400;
    let step = a.distance(b) / n as f64;
    (0..n)
        .map(|i| a + (b - a) * ((i as f64 + 0.5) / n as f64))
        .filter(|p| p.x >= r.min.x && p.x <= r.max.x && p.y >= r.min.y && p.y <= r.max.y)
        .filter(|p| p.distance(at) > NEAR_POINT_MM)
        .count() as f64
        * step
}

/// The labels of `sheets` (each with its scene's name) that `pick` chooses and a line of
/// their own view meets (within [`CLEAR_MM`]), and how many labels were looked at.
fn struck_labels(
    sheets: &[(&str, Plate)],
    pick: impl Fn(&View, &PlacedLabel) -> bool,
) -> (Vec<String>, usize) {
    let mut struck = Vec::new();
    let mut seen = 0;
    for (scene, p) in sheets {
        let l = layout(p);
        for x in &l.labels {
            let v = &p.views[x.view];
            if !pick(v, x) {
                continue;
            }
            seen += 1;
            let r = x.rect.inflate(CLEAR_MM);
            for s in &v.figure.steps {
                let (a, b) = match s.item {
                    Item::Segment(sg) => (sg.from, sg.to),
                    Item::Vector { from, to } => (from, to),
                    _ => continue,
                };
                let len = inside(v.to_sheet(a), v.to_sheet(b), &r, x.anchor);
                if len > 0.0 {
                    struck.push(format!(
                        "{scene}/{} “{}”: {} runs {len:.1} mm into “{}” at {:?}",
                        p.name,
                        v.caption.as_deref().unwrap_or(""),
                        s.note,
                        x.text,
                        x.rect
                    ));
                }
            }
        }
    }
    (struck, seen)
}

/// The joint labels of every plan on the linkage scenes' kinematic sheets that a line of
/// their own plan meets (within [`CLEAR_MM`]), and how many joint labels were looked at.
fn struck_joint_labels(scenes: &[&str], only: impl Fn(&str) -> bool) -> (Vec<String>, usize) {
    let sheets: Vec<(&str, Plate)> = scenes
        .iter()
        .flat_map(|scene| sheets_of(scene).into_iter().map(move |p| (*scene, p)))
        .collect();
    struck_labels(&sheets, |v, x| {
        let plan = v
            .caption
            .as_deref()
            .is_some_and(|c| c.starts_with("Пол. ") || c.starts_with("План ускорений"));
        x.steps.len() > 1 && only(&x.text) && plan
    })
}

/// `d₅ ≡ e ≡ s₅` on every velocity and acceleration plan of the shaper, clear of its lines.
#[test]
fn the_sliders_joint_label_is_clear_of_its_direction_lines() {
    let (struck, seen) = struck_joint_labels(&["shaper"], |t| t.contains("d_{5}"));
    // Twelve velocity plans, 8′ and two acceleration plans.
    assert!(seen >= 13, "{seen} labels of d₅");
    assert!(struck.is_empty(), "{}", struck.join("\n"));
}

/// Every joint label of every plan of the linkage scenes, clear of its plan's lines.
#[test]
fn no_joint_label_of_a_plan_is_struck_by_its_lines() {
    let (struck, seen) = struck_joint_labels(&LINKAGES.split(' ').collect::<Vec<_>>(), |_| true);
    assert!(seen > 30, "{seen} joint labels");
    assert!(struck.is_empty(), "{}", struck.join("\n"));
}

/// Every label of the force sheets (the groups with their forces, the polygons, Zhukovsky's
/// lever) clear of its view's lines (issue 19, item 6). v-engine forces-2's `R₀₋₃` was
/// struck by the other unknown's closing direction, drawn ±8 mm across the closing point
/// beside that short reaction; the closing directions now run from their points to the
/// closing point and 5 mm past it. The shaper's `R₃₋₄ ≡ R₄₋₅` at position 10 (its point
/// 7 mm from the frame, the block, G₄, G₅ and F_и₄ about it) was struck by G₄ until the
/// force views kept room for their long labels on the side the lines leave clear.
#[test]
fn no_label_of_a_force_sheet_is_struck_by_its_lines() {
    let sheets: Vec<(&str, Plate)> = ["shaper", "v-engine"]
        .into_iter()
        .flat_map(|scene| {
            sheets_of_kind(scene, "forces")
                .into_iter()
                .map(move |p| (scene, p))
        })
        .collect();
    assert!(sheets.len() >= 3, "{} force sheets", sheets.len());
    let (struck, seen) = struck_labels(&sheets, |_, _| true);
    assert!(seen > 60, "{seen} labels");
    assert!(struck.is_empty(), "{struck:#?}");
}

/// The diagrams of a point stacked on the kinematic sheet (S over dS/dφ over d²S/dφ², ω
/// over dω/dφ) keep their texts in rows of their own (item 6): the title at the top of a
/// lower diagram's ordinate axis shares no row with the position numbers under the φ axis
/// above it, nor with the pole distance H dimensioned under the fan above it. Before, `1
/// dS/dφ 3 4 …` read as one row under the S diagram, and `H₁ … d²S/dφ²` as another.
#[test]
fn a_stacked_diagrams_axis_title_has_a_row_of_its_own() {
    // Vertical room kept between the title's box and another text's, mm.
    const ROW_MM: f64 = 1.0;
    let mut titles = 0;
    for scene in LINKAGES.split(' ') {
        for p in sheets_of(scene) {
            let l = layout(&p);
            let note = |x: &tmm::plate::PlacedLabel| {
                let v = &p.views[x.view];
                v.figure.steps[x.steps[0].0 as usize].note.clone()
            };
            for t in l.labels.iter().filter(|x| {
                let n = note(x);
                n.starts_with("ordinate axis ") && !n.ends_with(" S")
            }) {
                let v = &p.views[t.view];
                titles += 1;
                let band = (t.rect.min.y - ROW_MM, t.rect.max.y + ROW_MM);
                for o in l
                    .labels
                    .iter()
                    .filter(|o| o.view == t.view && o.text != t.text)
                {
                    let shares = o.rect.max.y > band.0 && o.rect.min.y < band.1;
                    let near = (o.rect.min.x - t.rect.max.x).max(t.rect.min.x - o.rect.max.x);
                    assert!(
                        !(shares && near < 30.0),
                        "{scene}/{}: “{}” ({}) {:?} in the row of “{}” ({}) {:?}",
                        p.name,
                        t.text,
                        note(t),
                        t.rect,
                        o.text,
                        note(o),
                        o.rect
                    );
                }
                // The pole distance's dimension line of the diagram above.
                for s in &v.figure.steps {
                    if let Item::Dimension { from, to, offset } = s.item {
                        let n = (to - from).normalize().perp() * offset;
                        let (a, b) = (v.to_sheet(from + n), v.to_sheet(to + n));
                        let x_near = a.x.min(b.x) < t.rect.max.x + 30.0
                            && a.x.max(b.x) > t.rect.min.x - 30.0;
                        let y_in = a.y > band.0 - 3.5 && a.y < band.1 + 3.5;
                        assert!(
                            !(x_near && y_in),
                            "{scene}/{}: “{}” beside {} (its text 3.5 mm over the line)",
                            p.name,
                            t.text,
                            s.note
                        );
                    }
                }
            }
        }
    }
    assert!(titles >= 8, "{titles} axis titles");
}

/// Every kinematic sheet that draws velocity or acceleration plans at the common μ states that
/// μ on the sheet itself (in a caption or in its text): on two sheets the text goes onto the
/// second, so the first velocity plan's caption states μ_v and each acceleration plan's μ_a
/// (the shaper's, the six-bar's and the V engine's first sheets stated neither).
#[test]
fn every_sheet_states_the_scales_of_the_plans_it_draws() {
    let scenes = [
        "shaper",
        "six-bar",
        "v-engine",
        "four-bar",
        "slider-crank",
        "tangent",
    ];
    let mut looked = 0;
    for scene in scenes {
        let path =
            PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("constructions/{scene}.toml"));
        let s = tmm::load(&path).unwrap_or_else(|e| panic!("{scene}: {e}"));
        let sc = Session::new(&s, Drafting::EXACT)
            .kin_scales()
            .expect("scales");
        for p in sheets_of(scene) {
            let words: Vec<&str> = p
                .views
                .iter()
                .filter_map(|v| v.caption.as_deref())
                .chain(
                    p.texts
                        .iter()
                        .flat_map(|t| t.lines.iter().map(String::as_str)),
                )
                .collect();
            for (start, mu) in [("Пол. ", sc.v), ("План ускорений", sc.a)] {
                let at_common = p.views.iter().any(|v| {
                    v.figure.scale == mu
                        && v.caption.as_deref().is_some_and(|c| c.starts_with(start))
                });
                if !at_common {
                    continue;
                }
                looked += 1;
                let caption = mu.caption(Lang::Ru);
                assert!(
                    words.iter().any(|w| w.contains(&caption)),
                    "{scene}/{}: {start}… at {caption}, not stated",
                    p.name
                );
            }
        }
    }
    assert!(looked >= 12, "{looked} sheets with plans");
}

/// Issue 45: a point of a link turning about a fixed pivot is drawn on its trajectory as the
/// compass draws it — the arc about the pivot from one extreme to the other, the circle where
/// the link turns round — not a closed smooth curve through its positions, which on the
/// shaper's rocker parted into two lines about the arc of D. A point of a coupler keeps
/// its curve.
#[test]
fn a_pivoted_links_points_are_drawn_on_arcs_about_the_pivot() {
    let mut seen = std::collections::BTreeMap::<String, usize>::new();
    for scene in LINKAGES.split(' ') {
        let all = views(scene);
        let plan = captioned(&all, "План положений");
        let steps = &plan[0].figure.steps;
        let pivots: Vec<DVec2> = (steps.iter())
            .filter_map(|s| match s.item {
                Item::Joint { at, fixed: true } => Some(at),
                _ => None,
            })
            .collect();
        for s in steps
            .iter()
            .filter(|s| s.note.starts_with("trajectory of "))
        {
            let about = |c: DVec2| pivots.iter().any(|p| p.distance(c) < 1e-9);
            let kind = match &s.item {
                Item::Arc(a) => {
                    assert!(about(a.center), "{scene}: {} about no pivot", s.note);
                    assert!(a.sweep > 0.0 && a.sweep < std::f64::consts::TAU);
                    "arc"
                }
                Item::Circle(c) => {
                    assert!(about(c.center), "{scene}: {} about no pivot", s.note);
                    "circle"
                }
                Item::Curve { .. } => "curve",
                other => panic!("{scene}: {} drawn as {other:?}", s.note),
            };
            *seen
                .entry(format!("{scene} {}: {kind}", s.note))
                .or_default() += 1;
        }
    }
    for want in [
        "shaper trajectory of D: arc",
        "six-bar trajectory of S_3: arc",
        "tangent trajectory of C: circle",
    ] {
        assert!(seen.contains_key(want), "{want} not among {seen:?}");
    }
}

/// Issue 45: the tangent mechanism's block slides on the crank; the image of the crank's
/// point under it (b₁, b₁′), found by similarity, is the absolute velocity (acceleration)
/// the relative one adds to, so every velocity and acceleration plan draws it as a vector
/// from the pole to its labelled end — before, the similarity's line alone, with no
/// arrowhead. Where it vanishes it is a dot, never an arrowhead at the pole.
#[test]
fn the_crank_point_under_the_block_is_a_vector_from_the_pole() {
    let mut vectors = 0;
    for p in sheets_of("tangent") {
        for v in &p.views {
            for s in &v.figure.steps {
                if !(s.note == "image b_{1}" || s.note == "image b_{1}′") {
                    continue;
                }
                assert!(
                    s.label.is_some(),
                    "{}: {} unlabelled",
                    v.figure.title,
                    s.note
                );
                match s.item {
                    Item::Vector { from, to } => {
                        assert_eq!(from, DVec2::ZERO, "{}", v.figure.title);
                        assert!(to.length() > 0.1, "{}: {to:?}", v.figure.title);
                        vectors += 1;
                    }
                    Item::Point(at) => assert!(at.length() < 0.1, "{}", v.figure.title),
                    ref other => panic!("{}: {other:?}", v.figure.title),
                }
            }
        }
    }
    // Twelve velocity plans and the acceleration plans of positions 5 and 11.
    assert!(vectors >= 14, "{vectors} vectors b₁");
}
