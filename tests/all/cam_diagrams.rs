//! The cam sheet's diagrams (issue 19): d²S/dφ², dS/dφ and S each their own view with their
//! own axes, axis titles and caption, none over another; the return's construction apart
//! from the rise's; dS/dφ on the abscissa at the ends of a phase where the law has it there
//! (the integrand of S starts and ends where the law does); S without a step where a phase
//! meets a dwell.

use std::path::PathBuf;
use std::sync::Arc;
use tmm::cam::{Analogue, Cam};
use tmm::construct::{Drafting, Figure, Item, Role, Step};
use tmm::geom::DVec2;
use tmm::plate::{PlacedLabel, Plate, Rect};
use tmm::scene::PlateKind;
use tmm::study::Session;
use tmm::Lang;

/// Every cam scene of `constructions/`.
const SCENES: [&str; 7] = [
    "cam-central",
    "cam-cusp",
    "cam-pz4",
    "cam-pz5",
    "shaper",
    "cam-shock",
    "cam-undercut",
];

fn scene(name: &str) -> tmm::Scene {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("constructions")
        .join(format!("{name}.toml"));
    tmm::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

fn cam(name: &str) -> Arc<Cam> {
    let s = scene(name);
    let cam = Session::new(&s, Drafting::EXACT).cam();
    cam.unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// The first sheet of the scene's cam plate, in Russian.
fn plate(name: &str) -> Plate {
    let s = scene(name);
    let session = Session::new(&s, Drafting::EXACT);
    tmm::sheets::build_all(&session, Lang::Ru)
        .unwrap_or_else(|(k, e)| panic!("{name}: {k:?}: {e}"))
        .into_iter()
        .find(|(k, _)| *k == PlateKind::Cam)
        .map(|(_, p)| p)
        .unwrap_or_else(|| panic!("{name}: no cam plate"))
}

/// The three diagrams of a cam, named by their ordinate.
fn diagrams(cam: &Cam) -> [(&'static str, &Figure); 3] {
    let d = &cam.diagrams;
    [
        ("d^2S/dφ^2", &d.d2s_view),
        ("dS/dφ", &d.ds_view),
        ("S", &d.s_view),
    ]
}

/// The points of a drawn line (a curve, polyline or segment).
fn points(step: &Step) -> Vec<DVec2> {
    match &step.item {
        Item::Curve { points, .. } | Item::Polyline { points, .. } => points.clone(),
        Item::Segment(s) => vec![s.from, s.to],
        _ => Vec::new(),
    }
}

/// The one step of `fig` whose note starts with `note` in `group` (1 the rise, 2 the
/// return, 0 the rest).
fn step<'a>(fig: &'a Figure, group: u32, note: &str) -> &'a Step {
    let found: Vec<&Step> = fig
        .steps
        .iter()
        .filter(|s| s.group == group && s.note.starts_with(note))
        .collect();
    assert_eq!(found.len(), 1, "{}: “{note}” in group {group}", fig.title);
    found[0]
}

/// The bounds of the steps of one group.
fn group_bounds(fig: &Figure, group: u32) -> Option<(DVec2, DVec2)> {
    Figure {
        steps: fig
            .steps
            .iter()
            .filter(|s| s.group == group)
            .cloned()
            .collect(),
        ..fig.clone()
    }
    .bounds()
}

/// Distance from `p` to the segment `a`–`b`.
fn to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.length_squared().max(1e-300)).clamp(0.0, 1.0);
    p.distance(a + ab * t)
}

/// Each diagram is a view of its own: its abscissa φ and its ordinate named after it,
/// arrowed and titled, a caption naming it with its scales; on the sheet the three views and
/// every other view lie apart, and each caption under its own view, over no other.
#[test]
fn every_diagram_is_its_own_view_with_axes_titles_and_caption() {
    for name in SCENES {
        let cam = cam(name);
        for (title, fig) in diagrams(&cam) {
            for (axis, label) in [
                ("abscissa axis φ".to_string(), "φ"),
                (format!("ordinate axis {title}"), title),
            ] {
                let s = step(fig, 0, &axis);
                assert!(
                    matches!(s.item, Item::Vector { .. }),
                    "{name} {title}: {axis} arrowed"
                );
                let l = s.label.as_ref().map(|l| l.text.as_str());
                assert_eq!(l, Some(label), "{name} {title}: {axis} titled");
            }
        }
        let p = plate(name);
        let stack = cam.diagrams.stack(cam.spec.given);
        for (k, (which, fig)) in stack.iter().enumerate() {
            let v = &p.views[k];
            // The sheet writes the phases' symbols and angles in its language (issue 45).
            let unworded = |f: &tmm::construct::Figure| {
                let mut f = f.clone();
                for st in f.steps.iter_mut() {
                    if tmm::cam::PHASE_NOTES.contains(&st.note.as_str()) {
                        st.label = None;
                    }
                }
                f
            };
            assert_eq!(
                unworded(&v.figure),
                unworded(fig),
                "{name}: view {k} is the diagram {which:?}"
            );
            // The displacement diagram's phases dimensioned, each with its angle.
            let phases: Vec<&str> = v
                .figure
                .steps
                .iter()
                .filter(|st| tmm::cam::PHASE_NOTES.contains(&st.note.as_str()))
                .filter_map(|st| st.label.as_ref().map(|l| l.text.as_str()))
                .collect();
            if *which == Analogue::S {
                assert!(phases.len() >= 3, "{name}: {phases:?}");
                assert!(
                    phases
                        .iter()
                        .all(|t| t.starts_with("φ_{") && t.ends_with('°')),
                    "{name}: {phases:?}"
                );
            } else {
                assert!(phases.is_empty(), "{name}: {which:?} {phases:?}");
            }
            let caption = v.caption.as_deref().unwrap_or("");
            let symbol = match which {
                Analogue::D2s => "d^2S/dφ^2",
                Analogue::Ds => "dS/dφ",
                Analogue::S => "S",
            };
            assert!(caption.contains(symbol), "{name}: “{caption}”");
            assert!(caption.contains("μ_{φ}"), "{name}: “{caption}”");
        }
        let layout = tmm::plate::layout(&p);
        let boxes: Vec<(usize, Rect, Option<Rect>)> = layout
            .views
            .iter()
            .enumerate()
            .filter_map(|(i, v)| Some((i, v.drawn?, v.caption)))
            .collect();
        for (i, a, ca) in &boxes {
            assert!(ca.is_some(), "{name}: view {i} has a caption");
            for (j, b, cb) in &boxes {
                if i >= j {
                    continue;
                }
                assert!(!a.intersects(b), "{name}: views {i} and {j} overlap");
                for (c, d) in [(ca, b), (cb, a)] {
                    if let Some(c) = c {
                        assert!(!c.intersects(d), "{name}: a caption over view {i} or {j}");
                    }
                }
            }
        }
    }
}

/// The return's construction (its pole, rays, mid-interval ordinates, chords and curve) lies
/// apart from the rise's in each diagram: its pole stands past the end of the return, never
/// over the rise's rectangles of mid-interval ordinates.
#[test]
fn the_returns_construction_lies_apart_from_the_rises() {
    for name in SCENES {
        let cam = cam(name);
        for (title, fig) in diagrams(&cam) {
            let (Some(rise), Some(ret)) = (group_bounds(fig, 1), group_bounds(fig, 2)) else {
                panic!("{name} {title}: both phases drawn");
            };
            let apart = rise.1.x <= ret.0.x + 1e-9;
            assert!(
                apart,
                "{name} {title}: the rise spans x ≤ {:.2} mm, the return from {:.2} mm",
                rise.1.x, ret.0.x
            );
        }
        assert_eq!(
            cam.diagrams.drawn_poles,
            [name != "cam-shock", true],
            "{name}"
        );
        // The return's poles stand right of the return's end, the rise's left of φ = 0.
        let end = cam.diagrams.phi.to_mm(cam.spec.starts()[3]);
        for (title, fig) in diagrams(&cam) {
            let poles = fig
                .steps
                .iter()
                .filter(|s| s.note.starts_with("pole ") && s.label.is_some());
            let mut count = 0;
            for s in poles {
                let Item::Point(p) = s.item else {
                    continue;
                };
                count += 1;
                match s.group {
                    1 => assert!(p.x < 0.0, "{name} {title}: the rise's pole at {p}"),
                    2 => assert!(p.x > end, "{name} {title}: the return's pole at {p}"),
                    g => panic!("{name} {title}: a pole in group {g}"),
                }
            }
            // The given diagram of an integration carries no pole: S when d²S/dφ² is given;
            // nor does a d²S/dφ² with no ordinate on either phase (cam-shock's uniform law).
            let unpoled = title == "S" || (title == "d^2S/dφ^2" && name == "cam-shock");
            assert!(
                count == 2 || (count == 0 && unpoled),
                "{name} {title}: {count}"
            );
        }
    }
}

/// dS/dφ is drawn from the abscissa and back to it at the ends of each phase of the cosine,
/// "+ −" and sine laws (and from h/Φ for the uniform law): the curve the second integration
/// takes its mid-interval ordinates from starts and ends where the law does, and every one of
/// those ordinates reaches a chord drawn in the same view.
#[test]
fn ds_dphi_starts_and_ends_where_the_law_does() {
    for name in [
        "cam-pz5",
        "cam-pz4",
        "shaper",
        "cam-cusp",
        "cam-undercut",
        "cam-shock",
    ] {
        let cam = cam(name);
        let d = &cam.diagrams;
        let st = cam.spec.starts();
        for (group, phase) in [(1u32, 0usize), (2, 2)] {
            let curve = points(step(&d.ds_view, group, "smooth curve dS/dφ"));
            let (first, last) = (curve[0], curve[curve.len() - 1]);
            let at = |phi: f64, after: bool| {
                d.ds_scale
                    .to_mm(tmm::cam::motion::motion(&cam.spec, phi, after).ds)
            };
            let (want0, want1) = (at(st[phase], true), at(st[phase + 1], false));
            assert!(
                (first.y - want0).abs() < 0.01 && (last.y - want1).abs() < 0.01,
                "{name} phase {phase}: dS/dφ drawn from {:.3} to {:.3} mm, the law {want0:.3} \
                 to {want1:.3} mm",
                first.y,
                last.y
            );
            if name != "cam-shock" {
                assert!(want0.abs() < 1e-9 && want1.abs() < 1e-9, "{name}");
            }
            let x0 = d.phi.to_mm(st[phase]);
            assert!(
                (first.x - x0).abs() < 1e-9,
                "{name}: the curve starts at φ₀"
            );
            // The mid-interval ordinates of dS/dφ stand on its chords.
            let chords: Vec<(DVec2, DVec2)> = d
                .ds_view
                .steps
                .iter()
                .filter(|s| s.group == group && s.note.starts_with("chord "))
                .map(|s| {
                    let p = points(s);
                    (p[0], p[1])
                })
                .collect();
            assert_eq!(chords.len(), cam.spec.divisions, "{name}");
            let tops: Vec<DVec2> = d
                .ds_view
                .steps
                .iter()
                .filter(|s| s.group == group && s.note.starts_with("mean ordinate"))
                .map(|s| points(s)[1])
                .collect();
            assert_eq!(tops.len(), chords.len(), "{name}");
            for (k, (t, (a, b))) in tops.iter().zip(&chords).enumerate() {
                let off = to_segment(*t, *a, *b);
                assert!(
                    off < 1e-6,
                    "{name} phase {phase} interval {k}: {off} mm off"
                );
            }
            // And those of the given d²S/dφ² stand on its curve.
            let given = points(step(&d.d2s_view, group, "given d²S/dφ²"));
            let tops = d
                .d2s_view
                .steps
                .iter()
                .filter(|s| s.group == group && s.note.starts_with("mean ordinate"));
            for s in tops {
                let t = points(s)[1];
                let off = given
                    .windows(2)
                    .map(|w| to_segment(t, w[0], w[1]))
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    off < 1e-6,
                    "{name} phase {phase}: {} is {off} mm off",
                    s.note
                );
            }
        }
    }
}

/// S goes on without a step where a phase meets a dwell: the far dwell is drawn at the S
/// the rise's construction reached and the return starts there; the near dwell at the S
/// the return reached.
#[test]
fn s_has_no_step_where_a_phase_meets_a_dwell() {
    for name in SCENES {
        let cam = cam(name);
        let s = &cam.diagrams.s_view;
        let curve = |g: u32| {
            let c = s
                .steps
                .iter()
                .find(|x| {
                    x.group == g
                        && matches!(x.role, Role::Result | Role::Given)
                        && (x.note.starts_with("smooth curve S") || x.note.starts_with("given S"))
                })
                .unwrap_or_else(|| panic!("{name}: the S curve of group {g}"));
            points(c)
        };
        let (rise, ret) = (curve(1), curve(2));
        let far = points(step(s, 0, "far dwell"));
        let near = points(step(s, 0, "near dwell"));
        let joins = [
            ("rise → far dwell", rise[rise.len() - 1], far[0]),
            ("far dwell → return", far[1], ret[0]),
            ("return → near dwell", ret[ret.len() - 1], near[0]),
        ];
        for (what, a, b) in joins {
            assert!(
                a.distance(b) < 1e-9,
                "{name}: {what}: a step from {a} to {b}"
            );
        }
        // The S the table reports is the one drawn: the return's first point.
        let n = cam.spec.divisions;
        let s0 = cam.diagrams.s_scale.to_mm(cam.diagrams.s[n + 1]);
        assert!(
            (s0 - ret[0].y).abs() < 1e-9,
            "{name}: {s0} against {}",
            ret[0].y
        );
    }
}

/// When S is given and differentiated, the tangent the law fixes at a phase's ends is drawn
/// and taken where nothing is built on it (issue 19, item 2): d²S/dφ² starts and ends on the
/// abscissa under the sine law, whose acceleration does not jump there; before, it was its
/// smooth curve extended past the last mid-interval point, a hook at each phase end. Under
/// the cosine law it is not zero there (a soft shock) and stays extended. dS/dφ, whose chords
/// are drawn again, keeps its extended ends: the chord method's own error, which the test of
/// its convergence (tests/all/cam.rs) holds at second order.
#[test]
fn a_differentiated_s_gives_d2s_from_the_abscissa_where_the_law_has_it_there() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("constructions/cam-central.toml");
    let text = std::fs::read_to_string(&path).expect("cam-central");
    assert!(text.contains("law = \"sine\""));
    for (law, flat) in [("sine", true), ("cosine", false)] {
        let s = tmm::scene::parse(&text.replace("\"sine\"", &format!("\"{law}\"")), &path)
            .unwrap_or_else(|e| panic!("{law}: {e}"));
        let cam = Session::new(&s, Drafting::EXACT)
            .cam()
            .unwrap_or_else(|e| panic!("{law}: {e}"));
        let d = &cam.diagrams;
        let st = cam.spec.starts();
        for (group, phase) in [(1u32, 0usize), (2, 2)] {
            let curve = points(step(&d.d2s_view, group, "smooth curve d^2S/dφ^2"));
            let (first, last) = (curve[0], curve[curve.len() - 1]);
            assert!(
                (first.x - d.phi.to_mm(st[phase])).abs() < 1e-9
                    && (last.x - d.phi.to_mm(st[phase + 1])).abs() < 1e-9,
                "{law}: the curve spans the phase"
            );
            let off = first.y.abs().max(last.y.abs());
            let rays = d
                .d2s_view
                .steps
                .iter()
                .filter(|s| {
                    s.group == group
                        && s.note
                            .starts_with("ray from the pole parallel to the tangent")
                })
                .count();
            if flat {
                assert!(off < 1e-9, "{law} phase {phase}: {off} mm off the abscissa");
                assert_eq!(rays, 2, "{law} phase {phase}: the tangents' rays");
            } else {
                assert!(off > 1.0, "{law} phase {phase}: {off} mm");
                assert_eq!(rays, 0, "{law} phase {phase}");
            }
        }
    }
}

/// Every division point has its number on each diagram's φ axis, on every cam scene (issue
/// 45: cam-cusp and cam-undercut, 12 divisions of a 60° phase, 3,33 mm apart at the cycle's
/// 240 mm, numbered 13, 15, 17 … and left 14, 16 … out: two two-digit numbers need 3,7 mm
/// a row). The cycle is drawn 300 mm long there (1,2°/mm). Left out only where d²S crosses
/// the axis at a phase's middle so steeply that it would strike the number anywhere in its
/// column ([`crate::cam_axis_numbers`]: cam-central's 19, 2 mm right of its point, touched
/// the smooth d²S).
#[test]
fn every_point_is_numbered_on_every_phi_axis() {
    let mut left = Vec::new();
    for name in SCENES {
        let cam = cam(name);
        let d = &cam.diagrams;
        for (what, view) in [("d²S", &d.d2s_view), ("dS", &d.ds_view), ("S", &d.s_view)] {
            let middle = |p: &tmm::cam::motion::Point| {
                let last = cam.points.iter().filter(|q| q.phase == p.phase).count() - 1;
                2 * p.k == last
            };
            for p in &cam.points {
                let note = format!("number of point {} on the φ axis", p.label);
                if view.steps.iter().any(|s| s.note == note) {
                    continue;
                }
                assert!(
                    what == "d²S" && middle(p),
                    "{name} {what}: point {} has no number",
                    p.label
                );
                left.push(format!("{name} {}", p.label));
            }
        }
        let cycle = std::f64::consts::TAU / d.phi.value();
        let dense = matches!(name, "cam-cusp" | "cam-undercut");
        let expected = if dense { 300.0 } else { 240.0 };
        assert!(
            (cycle - expected).abs() < 1e-9,
            "{name}: the cycle {cycle} mm"
        );
    }
    assert_eq!(
        left,
        [
            "cam-central 19",
            "cam-cusp 19",
            "shaper 19",
            "cam-undercut 19"
        ],
        "the numbers left to a crossing"
    );
}

/// Every cam sheet of every cam scene, the special cams' too, in every language, as the
/// sheet lays it out: (scene and language, the sheet, its labels).
pub(crate) fn every_cam_sheet() -> Vec<(String, Plate, Vec<PlacedLabel>)> {
    let mut out = Vec::new();
    for name in SCENES.iter().chain(&["cam-flat-rocker", "cam-sliding"]) {
        let s = scene(name);
        let session = Session::new(&s, Drafting::HAND);
        for lang in [Lang::Ru, Lang::Uk, Lang::En] {
            let plates =
                tmm::build(&session, PlateKind::Cam, lang).unwrap_or_else(|e| panic!("{e}"));
            for p in plates {
                let labels = tmm::plate::layout(&p).labels;
                out.push((format!("{name} {lang:?}"), p, labels));
            }
        }
    }
    out
}

/// Whether label `l` of plate `p` names a step whose note starts with `note`.
pub(crate) fn noted(p: &Plate, l: &PlacedLabel, note: &str) -> bool {
    let steps = &p.views[l.view].figure.steps;
    (l.steps.iter()).any(|id| steps[id.0 as usize].note.starts_with(note))
}

/// Every number on a φ axis stands in its point's column as the sheet lays it out — its
/// middle at least 1 mm nearer its own point than any other numbered point of the axis, and
/// never on a leader — on every cam sheet, the special cams' too (issue 45: cam-flat-rocker
/// wrote 19 under 20, 3,5 mm off its point where the curve crosses the axis; cam-undercut put
/// 19 on a leader to the place it left).
#[test]
fn every_phi_axis_number_stands_under_its_point() {
    let mut seen = std::collections::BTreeMap::<String, usize>::new();
    for (at, p, labels) in every_cam_sheet() {
        let numbers: Vec<_> = (labels.iter())
            .filter(|l| noted(&p, l, "number of point "))
            .collect();
        *seen.entry(at.clone()).or_default() += numbers.len();
        for l in &numbers {
            let middle = (l.rect.min.x + l.rect.max.x) * 0.5;
            let own = (middle - l.anchor.x).abs();
            let other = (numbers.iter())
                .filter(|o| o.view == l.view && o.anchor.x != l.anchor.x)
                .map(|o| (middle - o.anchor.x).abs())
                .fold(f64::INFINITY, f64::min);
            assert!(
                own + 1.0 <= other + 1e-6 && l.leader.is_none(),
                "{at}: {} stands {own:.2} mm from its point, {other:.2} mm from the next{}",
                l.text,
                if l.leader.is_some() {
                    ", on a leader"
                } else {
                    ""
                }
            );
        }
    }
    assert_eq!(seen.len(), 27, "{seen:?}");
    for (at, n) in seen {
        assert!(n > 30, "{at}: {n} numbers on the φ axes");
    }
}

/// The pole distance's name (H₁, H₂) reads alone: no number of the φ axis stands on its row
/// within 4 mm of it, on every cam sheet in every language (issue 45: the rise's H₂, 6 mm
/// under the axis, stood in the second row of numbers and read «H₂ 0»).
#[test]
fn the_pole_distance_reads_apart_from_the_phi_axis_numbers() {
    let mut poles = std::collections::BTreeMap::<String, usize>::new();
    for (at, p, labels) in every_cam_sheet() {
        for h in labels.iter().filter(|l| noted(&p, l, "pole distance ")) {
            *poles.entry(at.clone()).or_default() += 1;
            for n in labels.iter().filter(|l| noted(&p, l, "number of point ")) {
                let (a, b) = (h.rect, n.rect);
                let same_row = a.min.y < b.max.y && b.min.y < a.max.y;
                let gap = (b.min.x - a.max.x).max(a.min.x - b.max.x);
                assert!(
                    !same_row || gap >= 4.0,
                    "{at}: «{} {}» on one row, {gap:.1} mm apart",
                    h.text,
                    n.text
                );
            }
        }
    }
    assert_eq!(poles.len(), 27, "{poles:?}");
    // H₁, H₁′, H₂, H₂′; cam-shock's H₂, H₂′ alone (its d²S/dφ² has no ordinate to integrate).
    for (at, n) in poles {
        let shock = at.starts_with("cam-shock");
        assert!(
            if shock { n == 2 } else { n >= 4 },
            "{at}: {n} pole distances named"
        );
    }
}
