//! Gear trains end to end (seed 002 PZ2): examples 1 and 2 as the seed prints them (one
//! module, the stage's closed), the seed's printed answers as fixtures (a wrong one flagged,
//! not matched), a train that needs the closing refused without it on its key, the
//! differential (W = 2) against Willis's formula worked by hand, and every train scheme's
//! supports apart and named, read off the recorded figure.

use crate::support;
use support::{notes, num, report_json, scratch, tmm};

/// The report's row of quantity `q` by `method`.
fn row<'a>(v: &'a serde_json::Value, q: &str, method: &str) -> &'a serde_json::Value {
    v["rows"]
        .as_array()
        .expect("rows")
        .iter()
        .find(|r| r["quantity"] == q && r["method"] == method)
        .unwrap_or_else(|| panic!("no row {q} ({method})"))
}

/// The seed prints whole ratios: a printed value holds within half its last digit.
const PRINTED_HALF_UNIT: f64 = 0.5;

/// Examples 1 and 2 (L544–L621) worked as the seed works them, the module it leaves out
/// closed: the seed's W = 1 for both and u₁₇ = 20 (L584) reproduced; its u₁H = 20 for
/// example 2 (L621) is an erratum — (33/15)(45/11) = 9, not 6, and u₁H = −4·(1 − 9) = 32 —
/// flagged in the notes with the stage it needs, not matched. The ratio by Willis is the
/// hand computation's to 1e-12, the stages' and the triangles' to 1e-9.
#[test]
fn pz2_examples_1_and_2_as_printed() {
    // (scene, row, the seed's printed u, u by hand from the teeth, W's terms, the mesh closed
    // and its module m′ = m·arm's teeth/its teeth at m = 1 mm, the printed u reproduced).
    let u17: f64 = (1.0 - (-48.0 / 88.0) * (-44.0 / 4.0)) * (-17.0 / 25.0) * (100.0 / 17.0);
    let u1h: f64 = (-52.0 / 13.0) * (1.0 - (-33.0 / 15.0) * (-45.0 / 11.0));
    let cases = [
        (
            "gears-pz2-ex1",
            "u_1_7",
            20.0,
            u17,
            "3·5 − 2·5 − 4 = 1",
            "the mesh 3–4 at m′ = 2a/(z3 + z4) = 2.83333 mm",
            true,
        ),
        (
            "gears-pz2-ex2",
            "u_1_H",
            20.0,
            u1h,
            "3·4 − 2·4 − 3 = 1",
            "the mesh 5–6 at m′ = 2a/(z5 + z6) = 0.857143 mm",
            false,
        ),
    ];
    assert!((136.0_f64 / 48.0 - 2.83333).abs() < 5e-6 && (48.0_f64 / 56.0 - 0.857143).abs() < 5e-7);
    for (scene, q, printed, by_hand, w, closed, reproduced) in cases {
        let v = report_json(&format!("constructions/{scene}.toml"), Some("0"));
        for method in ["formula", "triangles"] {
            let r = row(&v, q, method);
            assert!(
                (num(r, "analytic") - by_hand).abs() < 1e-12 * by_hand,
                "{scene}"
            );
            assert!(
                (num(r, "graphical") - by_hand).abs() < 1e-9 * by_hand,
                "{scene} {method}: {}",
                num(r, "graphical")
            );
        }
        assert_eq!(
            (printed - by_hand).abs() <= PRINTED_HALF_UNIT,
            reproduced,
            "{scene}"
        );
        let n = notes(&v);
        assert!(
            n.contains(&format!("W = 3n − 2p5 − p4 = {w}")),
            "{scene}: {n}"
        );
        assert!(n.contains("the seed's W = 1 reproduced"), "{scene}: {n}");
        assert!(n.contains(closed), "{scene}: {n}");
        assert!(
            n.contains("the source gives no module of the mesh"),
            "{scene}: {n}"
        );
        if reproduced {
            assert!(
                n.contains(&format!("the seed's {q} = 20 reproduced")),
                "{n}"
            );
        } else {
            assert!(
                n.contains(&format!(
                    "erratum: the seed prints {q} = 20; Willis's relations give 32"
                )) && n
                    .contains("20 needs u_36^(H) = 6 of the planetary stage, whose teeth give 9"),
                "{n}"
            );
        }
    }
}

/// Example 1 at one module without `closing_module` is refused on `planetary.mesh` (not
/// coaxial), the message naming the key that draws it.
#[test]
fn one_module_without_the_closing_is_refused_naming_its_key() {
    let path = support::root().join("constructions/gears-pz2-ex1.toml");
    let text = std::fs::read_to_string(path).expect("scene");
    let open = text.replace("closing_module = true\n", "");
    assert_ne!(open, text);
    let dir = scratch("no-closing");
    let file = dir.join("no-closing.toml");
    std::fs::write(&file, open).expect("write scene");
    let o = tmm(&["check", file.to_str().expect("utf-8")]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    for part in [
        "planetary.mesh",
        "coaxiality condition fails",
        "planetary.closing_module = true",
    ] {
        assert!(err.contains(part), "`{part}` not in {err}");
    }
}

/// The differential scene (example 3's James stage with its ring freed): the sun at
/// n₃ = 1000 rpm and the ring at n₅ = 200 rpm. Willis's formula solved by hand,
/// (n₃ − n_H)/(n₅ − n_H) = −z₅/z₃, gives n_H = (z₃n₃ + z₅n₅)/(z₃ + z₅) = 360 rpm and the
/// satellite n₄ = n_H − (z₃/z₄)(n₃ − n_H); the report's ω₄, ω_H by the triangles (the given
/// ω₃, ω₅ are no rows) and u₃H by the formula equal them to 1e-9, the notes work the formula.
#[test]
fn the_differential_scene_by_willis_formula_and_the_triangles() {
    let (z3, z4, z5): (f64, f64, f64) = (20.0, 30.0, 80.0);
    let (n3, n5): (f64, f64) = (1000.0, 200.0);
    let nh = (z3 * n3 + z5 * n5) / (z3 + z5);
    let n4 = nh - z3 / z4 * (n3 - nh);
    assert!((nh - 360.0).abs() < 1e-12);
    let rad = std::f64::consts::PI / 30.0;
    let v = report_json("constructions/gears-differential.toml", Some("0"));
    // The inputs' speeds are the data the plan is drawn from: no row reads them back.
    for shaft in ["3", "5"] {
        let q = format!("omega_{shaft}");
        assert!(
            v["rows"]
                .as_array()
                .expect("rows")
                .iter()
                .all(|r| r["quantity"] != q.as_str()),
            "{q}"
        );
    }
    for (shaft, n) in [("4", n4), ("H", nh)] {
        let r = row(&v, &format!("omega_{shaft}"), "triangles");
        let (g, a) = (num(r, "graphical"), num(r, "analytic"));
        assert!((a - n * rad).abs() < 1e-9 * n3 * rad, "{shaft}: {a}");
        assert!((g - n * rad).abs() < 1e-9 * n3 * rad, "{shaft}: {g}");
    }
    for method in ["formula", "triangles"] {
        let g = num(row(&v, "u_3_H", method), "graphical");
        assert!((g - n3 / nh).abs() < 1e-9 * n3 / nh, "{method}: {g}");
    }
    let n = notes(&v);
    for part in [
        "W = 3n − 2p5 − p4 = 3·4 − 2·4 − 2 = 2 (a differential: the inputs 3 and 5, n = 1000 and 200 rpm)",
        "u = u35^(H) = (n3 − nH)/(n5 − nH) = (−30/20)·(80/30) = −4; nH = (n3 − u·n5)/(1 − u) = 360 rpm",
    ] {
        assert!(n.contains(part), "`{part}` not in {n}");
    }
}

/// A support of a train's scheme: the shaft it holds, the box the plate draws it in and the
/// box of its label as the plate places it (sheet mm), and the label's text.
struct Support {
    shaft: String,
    drawn: tmm::plate::Rect,
    label: Option<(String, tmm::plate::Rect)>,
}

/// The supports of a train's scheme, read off its recorded figure and laid out on its sheet.
fn supports(scene: &str) -> Vec<Support> {
    use tmm::plate::{layout, Rect, View};
    let path = support::root().join(format!("constructions/{scene}.toml"));
    let s = tmm::load(&path).expect("scene");
    let session = tmm::Session::new(&s, tmm::Drafting::EXACT);
    let plates =
        tmm::sheets::build(&session, tmm::PlateKind::Gears, tmm::Lang::Ru).expect("plates");
    let plate = plates
        .iter()
        .find(|p| {
            p.views
                .iter()
                .any(|v| v.figure.title == "velocity triangles")
        })
        .expect("the triangles' sheet");
    let index = plate
        .views
        .iter()
        .position(|v| v.figure.title == "velocity triangles")
        .expect("the triangles");
    let view = &plate.views[index];
    let placed = layout(plate);
    view.figure
        .steps
        .iter()
        .filter_map(|s| {
            let shaft = s
                .note
                .strip_prefix("the bearing of the shaft ")
                .or_else(|| {
                    s.note
                        .strip_prefix("the shaft ")
                        .and_then(|n| n.strip_suffix(" fixed to the frame"))
                })?;
            let (lo, hi) = View::step_bounds(s).expect("a support is drawn");
            // Figure y runs up, the sheet's down.
            let (a, b) = (view.to_sheet(lo), view.to_sheet(hi));
            let drawn = Rect::new(a.min(b), a.max(b));
            let label = placed
                .labels
                .iter()
                .find(|l| l.view == index && l.steps.contains(&s.id))
                .map(|l| (l.text.clone(), l.rect));
            Some(Support {
                shaft: shaft.to_string(),
                drawn,
                label,
            })
        })
        .collect()
}

/// The gap between two boxes, mm (0 when they touch or overlap).
fn gap(a: &tmm::plate::Rect, b: &tmm::plate::Rect) -> f64 {
    let dx = (b.min.x - a.max.x).max(a.min.x - b.max.x).max(0.0);
    let dy = (b.min.y - a.max.y).max(a.min.y - b.max.y).max(0.0);
    dx.hypot(dy)
}

/// How far a support's name may stand from it, mm.
const NAME_REACH_MM: f64 = 4.0;

/// Every train scheme draws one support for each shaft on the frame (every shaft but the
/// satellites'), no two overlapping, each named by its shaft where the plate writes its name
/// within 4 mm of it and clear of every other support: the differential's three coaxial
/// shafts (3, 5, H) included, whose supports were drawn over each other.
#[test]
fn every_support_of_a_train_scheme_is_apart_and_named() {
    let cases: [(&str, &[&str]); 5] = [
        ("gears-differential", &["3", "5", "H"]),
        ("gears-pz2", &["1", "2-3", "5", "H"]),
        ("gears-pz2-ex1", &["1", "4", "H", "6", "7"]),
        ("gears-pz2-ex2", &["1", "2-3", "6", "H"]),
        ("shaper", &["1", "2-3", "6", "H", "8"]),
    ];
    for (scene, shafts) in cases {
        let found = supports(scene);
        let mut names: Vec<&str> = found.iter().map(|s| s.shaft.as_str()).collect();
        names.sort_unstable();
        let mut want = shafts.to_vec();
        want.sort_unstable();
        assert_eq!(names, want, "{scene}: one support per shaft on the frame");
        for (i, a) in found.iter().enumerate() {
            let (text, rect) = a
                .label
                .as_ref()
                .unwrap_or_else(|| panic!("{scene}: the support of {} is not named", a.shaft));
            assert_eq!(text, &a.shaft, "{scene}");
            assert!(
                gap(rect, &a.drawn) <= NAME_REACH_MM,
                "{scene}: the name of {} stands {} mm off its support",
                a.shaft,
                gap(rect, &a.drawn)
            );
            for (j, b) in found.iter().enumerate().filter(|(j, _)| *j != i) {
                assert!(
                    gap(rect, &b.drawn) > 0.0,
                    "{scene}: the name of {} is on the support of {}",
                    a.shaft,
                    b.shaft
                );
                if j > i {
                    assert!(
                        gap(&a.drawn, &b.drawn) > 0.0,
                        "{scene}: the supports of {} ({:?}) and {} ({:?}) overlap",
                        a.shaft,
                        a.drawn,
                        b.shaft,
                        b.drawn
                    );
                }
            }
        }
    }
}

/// PZ2's examples read to 0,5 mm (issue 45): u = 20 and 32 put the output's intercept a few
/// millimetres from the foot of the plan of angular velocities, read 16,7 % and 4,2 % off on
/// one plan; the slow links' own picture reads them within 5 %.
#[test]
fn pz2_examples_read_by_hand_within_five_per_cent() {
    for (scene, q) in [("gears-pz2-ex1", "u_1_7"), ("gears-pz2-ex2", "u_1_H")] {
        let v = report_json(&format!("constructions/{scene}.toml"), Some("0.5"));
        let r = row(&v, q, "triangles");
        let (g, a) = (num(r, "graphical"), num(r, "analytic"));
        assert!(((g - a) / a).abs() < 0.05, "{scene}: {g} against {a}");
    }
}

/// How clear of another wheel's line or a shaft a wheel's name stands, sheet mm.
const NAME_CLEAR_MM: f64 = 1.0;

/// Every wheel of a train's scheme is named clear of every line that is not its own — the
/// other wheels', the shafts and axles: PZ2's ring «z₂ = 100» stood beside the satellite's
/// axle, level with it and touching its end, and read as the satellite's name.
#[test]
fn every_wheel_of_a_train_scheme_is_named_clear_of_the_other_lines() {
    use tmm::construct::Item;
    use tmm::plate::{layout, Rect, View};
    let mut near = Vec::new();
    for scene in [
        "gears-differential",
        "gears-pz2",
        "gears-pz2-ex1",
        "gears-pz2-ex2",
        "shaper",
    ] {
        let path = support::root().join(format!("constructions/{scene}.toml"));
        let s = tmm::load(&path).expect("scene");
        let session = tmm::Session::new(&s, tmm::Drafting::EXACT);
        let plates =
            tmm::sheets::build(&session, tmm::PlateKind::Gears, tmm::Lang::Ru).expect("plates");
        let (plate, index) = plates
            .iter()
            .find_map(|p| {
                let i = (p.views.iter()).position(|v| v.figure.title == "velocity triangles")?;
                Some((p, i))
            })
            .expect("the triangles' sheet");
        let view = &plate.views[index];
        let placed = layout(plate);
        let bounds = |s: &tmm::construct::Step| {
            let (lo, hi) = View::step_bounds(s).expect("drawn");
            let (a, b) = (view.to_sheet(lo), view.to_sheet(hi));
            Rect::new(a.min(b), a.max(b))
        };
        let wheel_of = |note: &str| {
            let rest = note
                .strip_prefix("wheel ")
                .or_else(|| note.strip_prefix("ring "))?;
            Some(rest.split([' ', '\'']).next()?.to_string())
        };
        let mut named = 0;
        for step in &view.figure.steps {
            let Some(wheel) = wheel_of(&step.note) else {
                continue;
            };
            let Some(label) =
                (placed.labels.iter()).find(|l| l.view == index && l.steps.contains(&step.id))
            else {
                continue;
            };
            named += 1;
            for other in view.figure.steps.iter().filter(|o| {
                matches!(o.item, Item::Segment(_))
                    && wheel_of(&o.note).as_deref() != Some(wheel.as_str())
                    && (o.note.starts_with("wheel ")
                        || o.note.starts_with("the shaft ")
                        || o.note.starts_with("the axle of ")
                        || o.note.starts_with("the carrier's arm"))
            }) {
                let g = gap(&label.rect, &bounds(other));
                if g <= NAME_CLEAR_MM {
                    near.push(format!(
                        "{scene}: «{}» {g:.2} mm from «{}»",
                        label.text, other.note
                    ));
                }
            }
        }
        assert!(named >= 3, "{scene}: {named} wheels named");
    }
    assert!(near.is_empty(), "{near:#?}");
}

/// The distance from a point to the segment a–b, mm.
fn to_segment(p: tmm::geom::DVec2, a: tmm::geom::DVec2, b: tmm::geom::DVec2) -> f64 {
    tmm::geom::Segment::new(a, b).distance_to(p)
}

#[test]
fn every_distribution_line_is_named_beside_itself_and_alone() {
    // Named at its end, where the next link's line starts from the pole's velocity, a line's
    // name was joined with the next one's into a point's «1 ≡ 2-3» (PZ2, example 2). The
    // textbook writes each link's number beside its line: the placed name is the link's alone,
    // its box within 3 mm of its line, its centre clear of the line's ends by 3 mm and nearer
    // its own line than any other link's (but for two lines that run 1 mm apart).
    use tmm::geom::DVec2;
    use tmm::plate::layout;
    let mut named = 0;
    for scene in [
        "gears-pz2",
        "gears-pz2-ex1",
        "gears-pz2-ex2",
        "gears-differential",
        "shaper",
    ] {
        let s = support::scene(scene);
        let session = tmm::Session::new(&s, tmm::Drafting::EXACT);
        let plates =
            tmm::sheets::build(&session, tmm::PlateKind::Gears, tmm::Lang::Ru).expect("plates");
        for plate in &plates {
            let placed = layout(plate);
            for (index, view) in plate.views.iter().enumerate() {
                for s in &view.figure.steps {
                    let Some(shaft) = s.note.strip_prefix("the distribution line of ") else {
                        continue;
                    };
                    let tmm::construct::Item::Segment(g) = s.item else {
                        panic!("{scene}: the line of {shaft} is not a segment");
                    };
                    let (a, b) = (view.to_sheet(g.from), view.to_sheet(g.to));
                    let label = (placed.labels.iter())
                        .find(|l| l.view == index && l.steps.contains(&s.id))
                        .unwrap_or_else(|| panic!("{scene}: {shaft}'s line unnamed"));
                    assert_eq!(label.text, shaft, "{scene}");
                    let r = label.rect;
                    let corners = [
                        r.min,
                        r.max,
                        DVec2::new(r.min.x, r.max.y),
                        DVec2::new(r.max.x, r.min.y),
                    ];
                    let near = corners
                        .iter()
                        .map(|c| to_segment(*c, a, b))
                        .fold(f64::INFINITY, f64::min);
                    assert!(near <= 3.0, "{scene}: {shaft} {near:.1} mm from its line");
                    if a.distance(b) > 12.0 {
                        let end = r.center().distance(a).min(r.center().distance(b));
                        assert!(
                            end >= 3.0,
                            "{scene}: {shaft} at its line's end ({end:.1} mm)"
                        );
                    }
                    // Nearer its own line than any other link's.
                    let own = to_segment(r.center(), a, b);
                    for o in &view.figure.steps {
                        if o.id == s.id || !o.note.starts_with("the distribution line of ") {
                            continue;
                        }
                        let tmm::construct::Item::Segment(h) = o.item else {
                            continue;
                        };
                        let (c, d) = (view.to_sheet(h.from), view.to_sheet(h.to));
                        let other = to_segment(r.center(), c, d);
                        // PZ2's first example: lines 6 and 7 leave the pole's velocity about 0,6 mm
                        // apart and run so along 6's whole length; beside 6 no place is nearer
                        // it than 7 by more than that.
                        assert!(
                            own < other + 1.0,
                            "{scene}: {shaft} nearer «{}» ({other:.1} mm) than its own ({own:.1} mm)",
                            o.note
                        );
                    }
                    named += 1;
                }
            }
        }
    }
    assert!(named >= 20, "{named} lines");
}

/// How near a ring's axis a shaft passes through its hub (nested shafts), figure mm.
const HUB_MM: f64 = 3.0;

/// No shaft or satellite's axle of a train's scheme runs through a ring's disc between its
/// hub and its rim: the shaper's axle 4–5, from satellite 4 to the carrier's arm, was drawn
/// through the disc of ring 3, which it turns inside.
#[test]
fn no_axle_of_a_train_scheme_runs_through_a_ring_disc() {
    use tmm::construct::Item;
    let mut pierced = Vec::new();
    for scene in ["gears-differential", "gears-pz2", "gears-pz2-ex1", "shaper"] {
        let path = support::root().join(format!("constructions/{scene}.toml"));
        let s = tmm::load(&path).expect("scene");
        let session = tmm::Session::new(&s, tmm::Drafting::EXACT);
        let plates =
            tmm::sheets::build(&session, tmm::PlateKind::Gears, tmm::Lang::Ru).expect("plates");
        let view = (plates.iter().flat_map(|p| &p.views))
            .find(|v| v.figure.title == "velocity triangles")
            .expect("the triangles");
        let steps = &view.figure.steps;
        let mut discs = 0;
        for disc in steps.iter().filter(|s| s.note.ends_with("'s rim and cup")) {
            let Item::Polyline { points, .. } = &disc.item else {
                panic!("{scene}: {} is not a polyline", disc.note);
            };
            let [_, top, hub] = points[..] else {
                panic!("{scene}: {} is not rim, disc", disc.note);
            };
            discs += 1;
            let (lo, hi) = (top.y.min(hub.y), top.y.max(hub.y));
            for shaft in steps.iter().filter(|s| s.note.starts_with("the shaft ")) {
                let Item::Segment(seg) = &shaft.item else {
                    continue;
                };
                let (a, b) = (seg.from.x.min(seg.to.x), seg.from.x.max(seg.to.x));
                let y = seg.from.y;
                let through_hub = (y - hub.y).abs() < HUB_MM;
                if a < top.x && top.x < b && lo < y && y < hi && !through_hub {
                    pierced.push(format!("{scene}: «{}» through «{}»", shaft.note, disc.note));
                }
            }
        }
        assert!(discs >= 1, "{scene}: no ring drawn");
    }
    assert!(pierced.is_empty(), "{pierced:#?}");
}
