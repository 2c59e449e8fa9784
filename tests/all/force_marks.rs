//! The force sheets' instructor marks (issue 45): the balancing moment of a coupling drawn
//! on the driving link and its force on Zhukovsky's lever at the crank pin's image; only the
//! arms needed on the lever, every arm label naming a dimension one can see; each polygon at
//! its own μ_F, its short reactions read to the course's few per cent.

use crate::support;

use serde_json::Value;
use support::{root, tmm};
use tmm::construct::{Drafting, Figure, Item};
use tmm::forces::{GroupPolygon, PositionForces, Unknown};
use tmm::geom::DVec2;
use tmm::study::Session;

const SCENES: [&str; 3] = [
    "constructions/shaper.toml",
    "constructions/v-engine.toml",
    "constructions/six-bar.toml",
];

/// Every analysed position of `scene`, exactly.
fn each_position(scene: &str, mut check: impl FnMut(&PositionForces)) {
    let scene = tmm::scene::load(&root().join(scene)).expect("scene");
    let session = Session::new(&scene, Drafting::EXACT);
    let sc = session.kin_scales().expect("scales");
    for k in session.force_positions().expect("positions") {
        check(&session.forces(&sc, k).expect("forces"));
    }
}

/// The labelled steps of a figure: (label, item).
fn labelled(f: &Figure) -> Vec<(&str, &Item)> {
    f.steps
        .iter()
        .filter_map(|s| s.label.as_ref().map(|l| (l.text.as_str(), &s.item)))
        .collect()
}

/// The line a step draws where it is drawn (a dimension's at its offset), mm.
fn line(item: &Item) -> Option<(DVec2, DVec2)> {
    match *item {
        Item::Segment(s) => Some((s.from, s.to)),
        Item::Vector { from, to } => Some((from, to)),
        Item::Dimension { from, to, offset } => {
            let n = (to - from).normalize_or_zero().perp() * offset;
            Some((from + n, to + n))
        }
        _ => None,
    }
}

/// Whether `a`–`b` runs along `p`–`q` for more than a millimetre, within 0.5 mm of it.
fn along(a: DVec2, b: DVec2, p: DVec2, q: DVec2) -> bool {
    let Some(u) = (q - p).try_normalize() else {
        return false;
    };
    let off = |x: DVec2| (x - p).perp_dot(u).abs();
    let (s0, s1) = ((a - p).dot(u), (b - p).dot(u));
    let shared = s0.max(s1).min((q - p).length()) - s0.min(s1).max(0.0);
    off(a) < 0.5 && off(b) < 0.5 && shared > 1.0
}

/// Every arm label `h_{n}` of `figure` names one arm — a thin line or a dimension — that
/// lies on no other line drawn (a link, an arrow, another arm): it can be seen.
fn arms_are_dimensioned(figure: &Figure, what: &str) -> usize {
    let steps = labelled(figure);
    let mut seen = 0;
    for (text, item) in &steps {
        if !text.starts_with("h_") {
            continue;
        }
        assert!(
            matches!(item, Item::Dimension { .. } | Item::Segment(_)),
            "{what}: {text} labels no arm"
        );
        assert_eq!(
            steps.iter().filter(|(t, _)| t == text).count(),
            1,
            "{what}: {text} twice"
        );
        let (a, b) = line(item).expect("a line");
        for other in &figure.steps {
            if std::ptr::eq(&other.item, *item) {
                continue;
            }
            if let Some((p, q)) = line(&other.item) {
                assert!(
                    !along(a, b, p, q),
                    "{what}: the dimension {text} lies on {}",
                    other.note
                );
            }
        }
        seen += 1;
    }
    seen
}

/// Issue 45 item 1: the v-engine's coupling draws the balancing moment M_у on the driving
/// link about O, and on the lever the balancing force F_у at the image a of the crank pin,
/// at right angles to pa, whose arm is the ray pa; M_у = F_у·l_OA equals the linear solve.
#[test]
fn an_engines_balancing_moment_is_on_its_crank_and_its_force_on_the_lever() {
    let mut seen = 0;
    each_position("constructions/v-engine.toml", |f| {
        let d = &f.analysis.polygons.driver;
        let arcs: Vec<_> = labelled(&d.scheme)
            .into_iter()
            .filter(|(t, i)| *t == "M_{у}" && matches!(i, Item::Moment(_)))
            .collect();
        assert_eq!(arcs.len(), 1, "{}: M_у on the driving link", f.label);
        let lever = &f.analysis.lever;
        let steps = labelled(&lever.figure);
        let a = steps
            .iter()
            .find_map(|(t, i)| match i {
                Item::Point(x) if *t == "a" => Some(*x),
                _ => None,
            })
            .expect("the image a");
        let (from, to) = lever
            .figure
            .steps
            .iter()
            .find_map(|s| match s.item {
                Item::Vector { from, to } if s.note.starts_with("F_{у}") => Some((from, to)),
                _ => None,
            })
            .expect("F_у on the lever");
        assert!(from.distance(a) < 1e-9, "{}: F_у is not at a", f.label);
        let square = (to - from).normalize().dot(a.normalize());
        assert!(square.abs() < 1e-9, "{}: F_у is not ⊥ pa", f.label);
        let Unknown::Force { label, arm_mm, .. } = &lever.equation.unknown else {
            panic!("{}: the lever gives no force", f.label);
        };
        assert_eq!(label.as_deref(), Some("pa"));
        assert!((arm_mm - a.length()).abs() < 1e-9);
        assert_eq!(lever.crank_arm, Some(0.04));
        let m = f.analysis.twin.m_bal;
        assert!(
            (lever.m_bal - m).abs() < 1e-9 * m.abs(),
            "{}: {} against {m}",
            f.label,
            lever.m_bal
        );
        let force = lever.f_bal.expect("F_у");
        assert!((force * 0.04 - m.abs()).abs() < 1e-9 * m.abs());
        seen += 1;
    });
    assert_eq!(seen, 2);
}

/// Issue 45 item 2: the lever carries only the arms it needs — a couple's two forces have
/// the segment between their images for arm, a force ⊥ to its image's ray the ray — each
/// label names a dimension drawn (h_n) or a segment of the turned plan drawn between two
/// named points (pb, ab); every term's arm is named. The v-engine's lever had 12 arms.
#[test]
fn a_lever_draws_only_the_arms_it_needs_each_named() {
    for scene in SCENES {
        each_position(scene, |f| {
            let lever = &f.analysis.lever;
            let what = format!("{scene} {}", f.label);
            let h = arms_are_dimensioned(&lever.figure, &what);
            let steps = labelled(&lever.figure);
            let point = |name: &str| {
                steps.iter().find_map(|(t, i)| match i {
                    Item::Point(x) if *t == name => Some(*x),
                    _ => None,
                })
            };
            let e = &lever.equation;
            let unknown = match &e.unknown {
                Unknown::Force { label, .. } => label.clone(),
                _ => None,
            };
            let labels = e
                .terms
                .iter()
                .filter(|t| t.moment != 0.0)
                .map(|t| t.label.clone());
            let mut used = std::collections::BTreeSet::new();
            let arms = e.terms.iter().filter(|t| t.moment != 0.0).map(|t| t.arm_mm);
            let unknown_mm = match &e.unknown {
                Unknown::Force { arm_mm, .. } => *arm_mm,
                _ => 0.0,
            };
            for (label, mm) in labels.chain([unknown]).zip(arms.chain([unknown_mm])) {
                // An arm too short to draw (the line through the pole) is named by none.
                let Some(label) = label else {
                    assert!(mm <= 0.5, "{what}: an arm of {mm} mm unnamed");
                    continue;
                };
                if label.starts_with("h_") {
                    assert!(steps.iter().any(|(t, _)| *t == label), "{what}: {label}");
                    used.insert(label);
                    continue;
                }
                // A segment of the turned plan: from the pole p or between two images.
                let ends = (1..label.len())
                    .filter(|&k| label.is_char_boundary(k))
                    .map(|k| label.split_at(k))
                    .find_map(|(x, y)| {
                        let x = if x == "p" {
                            Some(DVec2::ZERO)
                        } else {
                            point(x)
                        };
                        Some((x?, point(y)?))
                    })
                    .unwrap_or_else(|| panic!("{what}: {label} names no two points"));
                let drawn = lever.figure.steps.iter().any(|s| match s.item {
                    Item::Segment(seg) => {
                        along(seg.from, seg.to, ends.0, ends.1)
                            && along(ends.0, ends.1, seg.from, seg.to)
                    }
                    _ => false,
                });
                assert!(drawn, "{what}: the segment {label} is not drawn");
            }
            assert_eq!(used.len(), h, "{what}: an arm drawn that no moment takes");
            if scene.contains("v-engine") {
                assert!(h <= 6, "{what}: {h} arms h on the lever");
            }
        });
    }
}

/// Issue 45 item 3: on every group's drawing and the driving link's, each arm label names
/// an arm drawn where it can be seen — dimensioned beside a link or a load's arrow it would
/// lie on (the shaper's group 4–5 drew h₁ on the ram's weight G₅) — and names it once.
#[test]
fn every_arm_of_a_group_drawing_is_dimensioned_where_it_shows() {
    let mut arms = 0;
    for scene in SCENES {
        each_position(scene, |f| {
            let p = &f.analysis.polygons;
            for g in &p.groups {
                let what = format!("{scene} {} group {:?}", f.label, g.links);
                arms += arms_are_dimensioned(&g.scheme, &what);
                for e in &g.equations {
                    for t in e.terms.iter().filter(|t| t.moment != 0.0 && !t.couple) {
                        let l = t.label.as_deref().unwrap_or("h");
                        let named = labelled(&g.scheme).iter().any(|(x, _)| *x == l);
                        assert!(named || t.arm_mm <= 0.5, "{what}: {} by {l}", t.name);
                    }
                }
            }
            arms += arms_are_dimensioned(&p.driver.scheme, &format!("{scene} driver"));
        });
    }
    assert!(arms >= 10, "{arms} arms");
}

/// Issue 45 item 4: read to 0.5 mm, every reaction of the v-engine is within the course's
/// few per cent of the linear solve — R₀₋₃ at position 6 (68 N) was 1,7 mm on the
/// position's μ_F and read 11,8 % short; each polygon is drawn at its own μ_F.
#[test]
fn a_small_reaction_is_read_on_a_polygon_at_its_own_scale() {
    let out = tmm(&[
        "report",
        "constructions/v-engine.toml",
        "--format",
        "json",
        "--drafting",
        "0.5",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).expect("json");
    let mut n = 0;
    for r in v["rows"].as_array().expect("rows") {
        let q = r["quantity"].as_str().unwrap_or_default();
        if !q.starts_with("R_") {
            continue;
        }
        let e = r["rel_error"].as_f64().expect("an error").abs();
        assert!(e < 0.04, "{q} at {}: {:.1} %", r["position"], e * 100.0);
        n += 1;
    }
    assert!(n >= 14, "{n} reactions");
    // Each polygon at its own μ_F: group 2–3 at position 6 (largest force R₁₋₂ = 1844 N)
    // at 10 N/mm, not the position's 40.
    each_position("constructions/v-engine.toml", |f| {
        let scales: Vec<f64> = f
            .analysis
            .polygons
            .groups
            .iter()
            .map(|g| g.polygon.scale.value())
            .collect();
        if f.label == "6" {
            assert!(scales.contains(&10.0), "{scales:?}");
        }
        assert!(scales.iter().all(|&s| s <= f.scale_f.value()));
    });
}

/// Issue 45 item 1 in the note: the engine's lever is worked for F_у at the crank pin (its
/// arm the ray pa, in mm), then M_у = F_у·l_OA with the lever's numbers, in ru, uk and en.
#[test]
fn the_engines_note_turns_the_levers_force_into_the_balancing_moment() {
    let scene = tmm::scene::load(&root().join("constructions/v-engine.toml")).expect("scene");
    let session = Session::new(&scene, Drafting::HAND);
    let sc = session.kin_scales().expect("scales");
    let k = session.force_positions().expect("positions")[0];
    let lever = session
        .forces(&sc, k)
        .expect("forces")
        .analysis
        .lever
        .clone();
    let force = lever.f_bal.expect("F_у");
    for (lang, words) in [
        (
            tmm::scale::Lang::Ru,
            "приложенавточкеAкривошипаперпендикулярноOA",
        ),
        (
            tmm::scale::Lang::Uk,
            "прикладенавточціAкривошипаперпендикулярнодоOA",
        ),
        (tmm::scale::Lang::En, "pointAatrightanglestoOA"),
    ] {
        let note = tmm::note::compose(&session, lang).expect("note");
        let text: String = tmm::note::to_text(&note)
            .expect("typeset")
            .split_whitespace()
            .collect::<String>()
            .replace('\u{ad}', "");
        let at = text
            .find(words)
            .unwrap_or_else(|| panic!("{lang:?}: no M_у = F_у·l_OA"));
        let after = &text[at..];
        for x in [force, lever.m_bal] {
            let shown = tmm::scale::format_sig(x.abs(), 5, lang);
            assert!(after.contains(&shown), "{lang:?}: {shown} not shown");
        }
    }
}

/// The vectors a figure draws, with their labels: (label, tail, head), mm.
fn arrows(f: &Figure) -> Vec<(&str, DVec2, DVec2)> {
    f.steps
        .iter()
        .filter_map(|s| match (&s.item, &s.label) {
            (Item::Vector { from, to }, Some(l)) => Some((l.text.as_str(), *from, *to)),
            _ => None,
        })
        .collect()
}

type Arrow<'a> = (&'a str, DVec2, DVec2);

/// Every group's drawing of every analysed position of every scene, exactly; `check` sees
/// the scene and position named, and the group.
fn each_group(mut check: impl FnMut(&str, &GroupPolygon)) {
    for scene in SCENES {
        each_position(scene, |f| {
            for g in &f.analysis.polygons.groups {
                check(&format!("{scene} {}", f.label), g);
            }
        });
    }
}

/// Every two of the labelled vectors `figure` draws.
fn pairs(figure: &Figure) -> Vec<(Arrow<'_>, Arrow<'_>)> {
    let v = arrows(figure);
    (0..v.len())
        .flat_map(|k| (k + 1..v.len()).map(move |j| (k, j)))
        .map(|(k, j)| (v[k], v[j]))
        .collect()
}

/// Issue 45 (the V-engine's force sheets): on a group's drawing two loads that share a line
/// are two arrows — F_и5 and R₄₋₅ from C a few degrees apart printed as one arrow with a
/// doubled head — and every force is an arrow, its head clear of the joints (R₀₋₅ pulling
/// the piston to its guide had its head under the joint C, a line with no arrowhead).
#[test]
fn a_groups_loads_are_arrows_apart_with_their_heads_in_sight() {
    let mut along_one_line = 0;
    each_group(|what, g| {
        for ((n1, a1, b1), (n2, a2, b2)) in pairs(&g.scheme) {
            if (b1 - a1).normalize().dot((b2 - a2).normalize()) < 15f64.to_radians().cos() {
                continue;
            }
            along_one_line += 1;
            let apart = b1.distance(b2);
            assert!(
                apart >= 4.0,
                "{what}: {n1} and {n2} have their heads {apart} mm apart"
            );
        }
        // Every head's base clear of every joint's circle (1.5 mm), drawn over it.
        for s in &g.scheme.steps {
            let Item::Joint { at, .. } = s.item else {
                continue;
            };
            for (name, tail, head) in arrows(&g.scheme) {
                let base = head + (tail - head).normalize() * 4.0;
                let clear = base.distance(at) > 1.6;
                assert!(
                    clear,
                    "{what}: the head of {name} lies under the joint at {at}"
                );
            }
        }
    });
    assert!(along_one_line > 0, "no two loads along one line were met");
}

/// Issue 45: a force polygon lets a reader follow each vector — two forces along one line
/// (F_д5 laid back over F_и5) drawn side by side, not one over the other.
#[test]
fn no_vector_of_a_polygon_lies_on_another() {
    let mut beside = 0;
    each_group(|what, g| {
        for ((n1, a1, b1), (n2, a2, b2)) in pairs(&g.polygon) {
            // A short vector is read on the polygon's detail.
            let long = a1.distance(b1) >= 4.0 && a2.distance(b2) >= 4.0;
            let on = long && along(a1, b1, a2, b2);
            assert!(!on, "{what}: {n1} lies on {n2} on the polygon");
        }
        let notes = g.polygon.steps.iter().map(|s| s.note.as_str());
        beside += notes
            .filter(|n| n.ends_with("beside the vector on its line"))
            .count();
    });
    assert!(beside > 0, "no polygon drew a vector beside another");
}

/// Issue 45 (arrowheads of forces too short to draw): a force a polygon's detail reads is
/// drawn on the polygon as the short line it is, without a head — the V engine's G₄ and G₅,
/// 0,3 mm at 40 N/mm, were bare 4 mm arrowheads beside the circles Б and Г — and its detail
/// draws it as a named arrow.
#[test]
fn a_force_read_on_a_detail_has_no_head_on_its_polygon() {
    let (mut lines, mut details) = (0, 0);
    each_group(|what, g| {
        let zones: Vec<_> = g.details.iter().map(|d| d.zone).collect();
        let inside = |p: DVec2| zones.iter().any(|z| p.distance(z.center) <= z.radius);
        for s in &g.polygon.steps {
            match s.item {
                Item::Vector { from, to } => assert!(
                    from.distance(to) >= 4.0 || !(inside(from) && inside(to)),
                    "{what}: {} drawn {:.2} mm with a head inside a detail's zone",
                    s.note,
                    from.distance(to)
                ),
                // A force's line, not the thin joins of one drawn beside another.
                Item::Segment(seg)
                    if s.note.starts_with("lay off ")
                        && !s.note.ends_with("beside the vector on its line") =>
                {
                    assert!(inside(seg.from) && inside(seg.to), "{what}: {}", s.note);
                    lines += 1;
                }
                _ => {}
            }
        }
        for d in &g.details {
            details += 1;
            assert!(
                !arrows(&d.figure).is_empty(),
                "{what}: a detail with no named arrow"
            );
        }
    });
    assert!(
        lines >= 2 && details >= 2,
        "{lines} lines, {details} details"
    );
}

/// A resistance of the data that does not act at the sheet's position is said to be nought
/// there (issue 45: the shaper's sheet of position 10, on the return stroke, drew no F_пс
/// while its data gave «F_пс = 1275,3 Н»): position 10's sheet says it acts on the working
/// stroke only, in each language's notation; position 3's, where it acts, says nothing.
#[test]
fn a_resting_resistance_is_said_to_be_nought() {
    use tmm::scale::Lang;
    let s = tmm::scene::load(&root().join(SCENES[0])).expect("shaper");
    let session = Session::new(&s, Drafting::EXACT);
    let kind = tmm::scene::PlateKind::parse("forces").expect("kind");
    for (lang, want) in [
        (
            Lang::Ru,
            "F_{пс} = 0: F_{пс} действует только на рабочем ходу",
        ),
        (Lang::Uk, "F_{пк} = 0: F_{пк} діє лише на робочому ході"),
        (Lang::En, "F_{r} = 0: F_{r} acts on the working stroke only"),
    ] {
        let sheets = tmm::build(&session, kind, lang).expect("sheets");
        let said: Vec<bool> = (sheets.iter())
            .map(|p| p.texts.iter().flat_map(|t| &t.lines).any(|l| l == want))
            .collect();
        assert_eq!(said, [false, true], "{lang:?}: «{want}» on positions 3, 10");
    }
}

/// Issue 45: a polygon names each reaction it reads as the table and the report name it —
/// the force of the first-named link on the second — on the polygon or on its details: the
/// V engine's polygon 4–5 named R₅₋₄ what its table lists as R₄₋₅.
#[test]
fn a_polygon_names_each_reaction_as_the_table_does() {
    let mut named = 0;
    each_group(|at, g| {
        let shown: Vec<&str> = std::iter::once(&g.polygon)
            .chain(g.details.iter().map(|d| &d.figure))
            .flat_map(|f| labelled(f).into_iter().map(|(text, _)| text))
            .collect();
        for r in g.reactions.iter().filter(|r| r.force.length() > 0.0) {
            let name = tmm::forces::reaction_name(r.pair.from, r.pair.to);
            assert!(
                shown.contains(&name.as_str()),
                "{at}: {name} not among {shown:?}"
            );
            named += 1;
        }
    });
    assert!(named >= 12, "{named} reactions named");
}
