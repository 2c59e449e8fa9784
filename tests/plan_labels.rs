//! The labels of the velocity and acceleration plans stay off the lines of their own plan
//! (issue 19, item 6): a joint label such as `d₅ ≡ e ≡ s₅` is not crossed, nor touched at its
//! start, by the direction lines drawn through its point. Computed from the plate model: the
//! label's box as the layout places it against the plan's segments and vectors.

use std::path::PathBuf;
use tmm::construct::{Drafting, Item};
use tmm::geom::DVec2;
use tmm::plate::{layout, Plate, Rect, LABEL_GAP_MM};
use tmm::scale::Lang;
use tmm::scene::PlateKind;
use tmm::study::Session;

/// Clearance a label keeps from every line of its plan, mm (the placer weighs lines within
/// 0.5 mm of a box): a line ending closer than this runs into the text (`—d₅`). The shaper's
/// acceleration plan at position 3 had the slide's direction line 3.5 mm into `d₅′ ≡ e′ ≡ s₅′`.
const CLEAR_MM: f64 = 0.3;

fn sheets_of(scene: &str) -> Vec<Plate> {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("constructions/{scene}.toml"));
    let s = tmm::load(&path).unwrap_or_else(|e| panic!("{scene}: {e}"));
    let kind = PlateKind::parse("kinematics").expect("a plate kind");
    tmm::build(&Session::new(&s, Drafting::EXACT), kind, Lang::Ru)
        .unwrap_or_else(|e| panic!("{scene}: {e}"))
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

/// The joint labels of every plan on the linkage scenes' kinematic sheets that a line of
/// their own plan meets (within [`CLEAR_MM`]), and how many joint labels were looked at.
fn struck_joint_labels(scenes: &[&str], only: impl Fn(&str) -> bool) -> (Vec<String>, usize) {
    let mut struck = Vec::new();
    let mut seen = 0;
    for scene in scenes {
        for p in sheets_of(scene) {
            let l = layout(&p);
            for x in l
                .labels
                .iter()
                .filter(|x| x.steps.len() > 1 && only(&x.text))
            {
                let v = &p.views[x.view];
                let plan = v
                    .caption
                    .as_deref()
                    .is_some_and(|c| c.starts_with("Пол. ") || c.starts_with("План ускорений"));
                if !plan {
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
    }
    (struck, seen)
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
    let scenes = [
        "shaper",
        "four-bar",
        "six-bar",
        "slider-crank",
        "tangent",
        "v-engine",
    ];
    let (struck, seen) = struck_joint_labels(&scenes, |_| true);
    assert!(seen > 30, "{seen} joint labels");
    assert!(struck.is_empty(), "{}", struck.join("\n"));
}
