//! The force sheets read from their plate model: every force of a polygon on it or on its
//! detail, the guide reaction at its arm and the balancing force at its arm's end, every arm
//! ending on its force's line of action, every caption under its drawing.

use crate::support;
use support::root;
use tmm::construct::Drafting;
use tmm::construct::Item;
use tmm::geom::DVec2;
use tmm::study::Session;

/// Every analysed position of the shaper and the v-engine, with its session's scales.
fn each_position(scene: &str, mut check: impl FnMut(&tmm::forces::PositionForces)) {
    let scene = tmm::scene::load(&root().join(scene)).expect("scene");
    let session = Session::new(&scene, Drafting::EXACT);
    let sc = session.kin_scales().expect("scales");
    for k in session.force_positions().expect("positions") {
        check(&session.forces(&sc, k).expect("forces"));
    }
}

/// Every polygon of every analysed position of `scene` with its details: (position,
/// polygon, details).
fn each_polygon(
    scene: &str,
    mut check: impl FnMut(&str, &tmm::construct::Figure, &[tmm::forces::PolygonDetail]),
) {
    each_position(scene, |f| {
        let p = &f.analysis.polygons;
        let all = (p.groups.iter().map(|g| (&g.polygon, &g.details)))
            .chain([(&p.driver.polygon, &p.driver.details)]);
        for (polygon, details) in all {
            check(&f.label, polygon, details);
        }
    });
}

/// Whether both ends `a`, `b` lie in the zone of `d`, polygon mm.
fn in_zone(d: &tmm::forces::PolygonDetail, a: DVec2, b: DVec2) -> bool {
    a.distance(d.zone.center) <= d.zone.radius && b.distance(d.zone.center) <= d.zone.radius
}

/// The drawn vectors of a figure: (note, from, to), mm.
fn vectors(f: &tmm::construct::Figure) -> Vec<(&str, DVec2, DVec2)> {
    f.steps
        .iter()
        .filter_map(|s| match s.item {
            Item::Vector { from, to } => Some((s.note.as_str(), from, to)),
            _ => None,
        })
        .collect()
}

/// The forces laid off on a polygon: its vectors, and the short lines of those its details
/// read (drawn without a head there): (note, from, to), mm.
fn laid(f: &tmm::construct::Figure) -> Vec<(&str, DVec2, DVec2)> {
    f.steps
        .iter()
        .filter(|s| {
            s.note.starts_with("lay off") && !s.note.ends_with("beside the vector on its line")
        })
        .filter_map(|s| match s.item {
            Item::Vector { from, to } => Some((s.note.as_str(), from, to)),
            Item::Segment(seg) => Some((s.note.as_str(), seg.from, seg.to)),
            _ => None,
        })
        .collect()
}

/// Issue 19 item 1: every force laid off on a polygon reads — at least 4 mm on the polygon,
/// or on its detail view (drawn at a larger μ_F, at least 4 mm there), whose zone holds it.
#[test]
fn every_force_of_a_polygon_reads_on_it_or_on_its_detail() {
    for scene in ["constructions/shaper.toml", "constructions/v-engine.toml"] {
        let mut details = 0;
        each_polygon(scene, |label, polygon, detail| {
            assert!(detail.len() <= 3);
            for (note, a, b) in laid(polygon) {
                let len = a.distance(b);
                if len >= 4.0 {
                    continue;
                }
                let d = detail
                    .iter()
                    .find(|d| in_zone(d, a, b))
                    .unwrap_or_else(|| panic!("{scene} {label}: {note}, {len} mm, in no detail"));
                let k = polygon.scale.value() / d.figure.scale.value();
                assert!(len * k >= 4.0, "{note}: {} mm on the detail", len * k);
                details += 1;
            }
        });
        assert!(details > 0, "{scene}: no small force was detailed");
    }
}

/// Issue 45: neither a polygon nor its detail names a force drawn too short to read on it
/// (the shaper's G₂, 2 mm at 10 N/mm, and the V engine's, under 1 mm at 40 N/mm, each named
/// beside a dot): a named vector of a polygon is at least 4 mm long there or outside every
/// zone of its details, which name it; one of a detail is at least 4 mm long there, the
/// detail circling the finer detail that reads the shorter ones (a detail of a detail,
/// ГОСТ 2.305). The shaper's group 2–3 has such a pair.
#[test]
fn a_polygon_and_its_details_name_only_the_forces_they_read() {
    let mut nested = 0;
    for scene in ["constructions/shaper.toml", "constructions/v-engine.toml"] {
        each_polygon(scene, |label, polygon, details| {
            for st in &polygon.steps {
                let (Item::Vector { from, to }, Some(l)) = (&st.item, &st.label) else {
                    continue;
                };
                let zoned = details.iter().any(|d| in_zone(d, *from, *to));
                assert!(
                    from.distance(*to) >= 4.0 || !zoned,
                    "{scene} {label}: {} named on its polygon, {:.2} mm, in a detail's zone",
                    l.text,
                    from.distance(*to)
                );
            }
            for d in details {
                nested += d.finer.len();
                for st in &d.figure.steps {
                    let (Item::Vector { from, to }, Some(l)) = (&st.item, &st.label) else {
                        continue;
                    };
                    let len = from.distance(*to);
                    assert!(
                        len >= 4.0,
                        "{scene} {label}: {} named on its detail, {len:.2} mm",
                        l.text
                    );
                }
                // Each finer zone it circles is drawn on it (arcs of the zone's circle, cut
                // by the detail's border).
                let circles = (d.figure.steps.iter())
                    .filter(|s| s.note.contains("finer detail"))
                    .count();
                let drawn = if d.finer.is_empty() {
                    circles == 0
                } else {
                    circles >= d.finer.len()
                };
                assert!(drawn, "{scene} {label}: {circles} arcs");
            }
        });
    }
    assert!(nested > 0, "no detail of a detail");
}

/// Issue 19 item 1: the guide's reaction on the shaper's ram (R₀₋₅) stands on the drawn
/// guide at its arm h₀₋₅ from the slider's joint, the arm dimensioned; the lever's F_у
/// starts at the end of its arm (the foot of the perpendicular from the pole).
#[test]
fn the_guide_reaction_stands_at_its_arm_and_the_balancing_force_at_the_end_of_its_arm() {
    each_position("constructions/shaper.toml", |f| {
        let g = &f.analysis.polygons.groups[0];
        assert_eq!(g.links, [4, 5]);
        let r05 = g.reactions.iter().find(|r| r.pair.from == 0).expect("R₀₋₅");
        let h = r05.offset.expect("its arm");
        let mu = g.scheme.scale.value();
        let steps = &g.scheme.steps;
        let guide = steps
            .iter()
            .find(|s| matches!(s.item, Item::Guide { .. }))
            .expect("the guide drawn");
        let dim = steps
            .iter()
            .find_map(|s| match s.item {
                Item::Dimension { from, to, .. } if s.note.ends_with("on the guide") => {
                    Some((from, to, s))
                }
                _ => None,
            })
            .expect("the arm dimensioned");
        assert!(
            (dim.0.distance(dim.1) - h.abs() / mu).abs() < 1e-9,
            "{}: dimension {} mm, h = {h} m",
            f.label,
            dim.0.distance(dim.1)
        );
        assert_eq!(
            dim.2.label.as_ref().map(|l| l.text.as_str()),
            Some("h_{0-5}")
        );
        let Item::Guide { segment, .. } = guide.item else {
            unreachable!()
        };
        let along = (segment.to - segment.from).normalize();
        // Signed distance from the guide's line, mm.
        let off = |p: DVec2| (p - segment.from).perp_dot(along);
        let (_, from, to) = vectors(&g.scheme)
            .into_iter()
            .find(|(n, ..)| *n == "load R_{0-5}")
            .expect("R₀₋₅ drawn");
        let on = if off(from).abs() < 1e-9 { from } else { to };
        assert!(
            off(on).abs() < 1e-9,
            "R₀₋₅ stands {} mm off its guide",
            off(on)
        );
        assert!(
            [dim.0, dim.1].iter().any(|p| p.distance(on) < 1e-9),
            "R₀₋₅ is not at the end of its arm"
        );
        // The loads along the slide's axis (F_и5, F_пс) keep off the guide's line: the
        // block rides against it.
        for (name, a, b) in vectors(&g.scheme) {
            if name == "load R_{0-5}" {
                continue;
            }
            assert!(
                off(a) * off(b) > 0.0 && off(a).abs().min(off(b).abs()) >= 2.0,
                "{}: {name} lies on the guide ({} mm, {} mm)",
                f.label,
                off(a),
                off(b)
            );
        }
        let lever = &f.analysis.lever.figure;
        let (_, at, to) = vectors(lever)
            .into_iter()
            .find(|(n, ..)| n.starts_with("F_{у}"))
            .expect("F_у on the lever");
        // Issue 45: F_у stands at the image of the pitch point, labelled, and its line of
        // action runs on to the foot of its arm (before, it was slid to the foot, 100 mm
        // from an unlabelled image).
        let e = (to - at).normalize();
        let image = lever
            .steps
            .iter()
            .find(|s| s.label.as_ref().is_some_and(|l| l.text == "p_{P}"))
            .expect("the image of P labelled");
        assert_eq!(image.item, Item::Point(at), "F_у is not at the image of P");
        let foot = at + e * (-at).dot(e);
        let reaches = |a: DVec2, b: DVec2| {
            lever.steps.iter().any(|s| {
                let (from, to) = match s.item {
                    Item::Segment(seg) => (seg.from, seg.to),
                    // An arm is dimensioned (issue 45).
                    Item::Dimension { from, to, .. } => (from, to),
                    _ => return false,
                };
                (from.distance(a) < 1e-9 && to.distance(b) < 1e-9)
                    || (from.distance(b) < 1e-9 && to.distance(a) < 1e-9)
            })
        };
        assert!(
            reaches(at, foot) || reaches(to, foot),
            "F_у's line of action does not reach its arm's foot"
        );
        assert!(reaches(DVec2::ZERO, foot), "F_у's arm is not drawn");
        assert!(foot.length() > 10.0, "its arm is {} mm", foot.length());
    });
}

/// Issue 19 item 1: a force whose moment a group's equation takes has its arm h drawn from
/// the moment centre at right angles to its line of action, and the line of action drawn on
/// to the arm's foot: the foot lies on the force's arrow or on a thin line from its point
/// (before, the arms of G₂ and F_и2 ended in empty paper, 100 mm from their forces).
#[test]
fn every_arm_ends_on_its_forces_line_of_action() {
    /// The distance from `p` to the segment `a`–`b`, mm.
    fn off(p: DVec2, a: DVec2, b: DVec2) -> f64 {
        let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
        p.distance(a + (b - a) * t)
    }
    let mut arms = 0;
    for scene in ["constructions/shaper.toml", "constructions/v-engine.toml"] {
        each_position(scene, |f| {
            for g in &f.analysis.polygons.groups {
                let steps = &g.scheme.steps;
                let about = |s: &&tmm::construct::Step| {
                    s.note.starts_with("arm of ") && s.note.ends_with(" about the moment centre")
                };
                for arm in steps.iter().filter(about) {
                    // Issue 45: an arm on other lines is dimensioned beside them.
                    let h = match arm.item {
                        Item::Segment(h) => h,
                        Item::Dimension { from, to, .. } => tmm::geom::Segment::new(from, to),
                        _ => panic!("{scene} {}: {} is not drawn", f.label, arm.note),
                    };
                    let name = arm
                        .note
                        .trim_start_matches("arm of ")
                        .split(" about")
                        .next()
                        .unwrap_or_default();
                    let lines: Vec<(DVec2, DVec2)> = steps
                        .iter()
                        .filter_map(|s| match s.item {
                            Item::Vector { from, to } if s.note == format!("load {name}") => {
                                Some((from, to))
                            }
                            // An arrow drawn past another on its line, joined to its point.
                            Item::Segment(l)
                                if s.note
                                    == format!(
                                        "line of action of {name} to the foot of its arm"
                                    )
                                    || s.note == format!("load {name}: to its point") =>
                            {
                                Some((l.from, l.to))
                            }
                            _ => None,
                        })
                        .collect();
                    assert!(!lines.is_empty(), "{scene} {}: {name} not drawn", f.label);
                    let (a, b) = lines[0];
                    let square = (h.to - h.from).normalize().dot((b - a).normalize());
                    assert!(square.abs() < 1e-9, "{}: arm of {name} not square", f.label);
                    let gap = lines
                        .iter()
                        .map(|&(a, b)| off(h.to, a, b))
                        .fold(f64::INFINITY, f64::min);
                    assert!(
                        gap < 1e-6,
                        "{scene} {}: the arm of {name} ends {gap} mm off it",
                        f.label
                    );
                    arms += 1;
                }
            }
        });
    }
    assert!(arms >= 8, "{arms} arms");
}

/// On every force sheet each view's caption stands under everything its figure draws — the
/// ground of the crank's pivot, drawn below the pivot, stood on the driving link's caption
/// ("Ведущее звено 1, μ_l = …" struck by its hatching).
#[test]
fn every_caption_of_a_force_sheet_stands_under_its_drawing() {
    let mut seen = 0;
    for name in ["constructions/shaper.toml", "constructions/v-engine.toml"] {
        let scene = tmm::scene::load(&root().join(name)).expect("scene");
        let session = Session::new(&scene, Drafting::EXACT);
        let kind = tmm::scene::PlateKind::parse("forces").expect("a plate kind");
        let plates = tmm::sheets::build(&session, kind, tmm::scale::Lang::Ru).expect("sheets");
        for p in &plates {
            for (v, l) in p.views.iter().zip(tmm::plate::layout(p).views) {
                let (Some(drawn), Some(caption)) = (l.drawn, l.caption) else {
                    continue;
                };
                seen += 1;
                assert!(
                    caption.min.y >= drawn.max.y,
                    "{name} {}: “{}” at {:.1} mm, its drawing down to {:.1} mm",
                    p.name,
                    v.caption.as_deref().unwrap_or_default(),
                    caption.min.y,
                    drawn.max.y
                );
            }
        }
    }
    assert!(seen >= 40, "{seen} captions");
}

/// Issue 45: an arm's name `h_{n}` names one arm of the sheet: the drawings of a position
/// (its groups, the driving link, the lever) number their arms on, as a student numbers
/// them on one sheet, instead of each starting again at h₁ (seed 000's shaper wrote h₁ on
/// four drawings of one sheet, each a different arm).
#[test]
fn no_arm_name_names_two_arms_of_a_sheet() {
    let mut arms = 0;
    for (name, plate) in crate::plate_model::every_sheet_in(tmm::scale::Lang::Ru, Drafting::EXACT) {
        let l = tmm::plate::layout(&plate);
        let mut views: std::collections::BTreeMap<&str, std::collections::BTreeSet<usize>> =
            Default::default();
        for x in &l.labels {
            for t in x.text.split(tmm::plate::JOINT_SEPARATOR) {
                let number = t.strip_prefix("h_{").and_then(|n| n.strip_suffix('}'));
                if number.is_some_and(|n| n.chars().all(|c| c.is_ascii_digit())) {
                    views.entry(t).or_default().insert(x.view);
                    arms += 1;
                }
            }
        }
        for (t, v) in views {
            assert!(v.len() == 1, "{name}: {t} names an arm on views {v:?}");
        }
    }
    assert!(arms >= 30, "{arms} numbered arms");
}

/// A group's drawing shows the loads on the group (issue 45): its outer pairs' reactions,
/// and the inner pair's only where its point is found on the drawing (a slide's); an inner
/// joint's reaction, a force between the group's own links, is read off the polygon alone
/// — drawn at the joint, the V engine's R₄₋₅ at C stood as one more load on slider 5.
#[test]
fn a_groups_drawing_shows_no_force_between_its_own_links_at_a_joint() {
    for scene in [
        "constructions/shaper.toml",
        "constructions/v-engine.toml",
        "constructions/six-bar.toml",
        "constructions/slider-crank.toml",
    ] {
        each_position(scene, |f| {
            for g in &f.analysis.polygons.groups {
                let labels: Vec<&str> = (g.scheme.steps.iter())
                    .filter_map(|s| s.label.as_ref().map(|l| l.text.as_str()))
                    .collect();
                for (k, r) in g.reactions.iter().enumerate() {
                    let name = format!("R_{{{}-{}}}", r.pair.from, r.pair.to);
                    let inner_joint =
                        k == 2 && matches!(r.pair.kind, tmm::forces::PairKind::Revolute(_));
                    let shown = labels.contains(&name.as_str());
                    assert!(
                        if inner_joint {
                            !shown
                        } else {
                            shown || r.force.length() < 1e-9
                        },
                        "{scene} {}: group {:?}, {name} (the {k}-th reaction) shown: {shown}",
                        f.label,
                        g.links
                    );
                }
            }
        });
    }
}
