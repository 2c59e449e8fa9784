//! The gear sheet's constructions read from its plate model: the rack generation with a few
//! numbered positions and the undercut in a detail, the rack positions drawn as recorded, the
//! plan of angular velocities with every ray named.

/// The gear sheets of a scene in `lang`: the views of every plate.
fn gear_views(scene: &str, lang: tmm::Lang) -> Vec<tmm::plate::View> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(scene);
    let s = tmm::load(&path).expect("scene");
    let session = tmm::Session::new(&s, tmm::Drafting::EXACT);
    let plates = tmm::sheets::build(&session, tmm::PlateKind::Gears, lang).expect("plates");
    assert_eq!(plates.len(), 1, "{scene}: one gear sheet");
    plates.into_iter().flat_map(|p| p.views).collect()
}

/// The label texts of the steps of `f` whose note starts with `note`.
fn labels_of(f: &tmm::construct::Figure, note: &str) -> Vec<String> {
    f.steps
        .iter()
        .filter(|s| s.note.starts_with(note))
        .filter_map(|s| s.label.as_ref().map(|l| l.text.clone()))
        .collect()
}

/// The hatch strokes of `f`.
fn hatching(f: &tmm::construct::Figure) -> Vec<tmm::geom::Segment> {
    use tmm::construct::{Item, Role};
    f.steps
        .iter()
        .filter(|s| s.role == Role::Hatch)
        .flat_map(|s| match &s.item {
            Item::Segment(seg) => vec![*seg],
            item => item.hatch_strokes(),
        })
        .collect()
}

/// The drawn rack positions' numbers read in order along the blank, as placed on the sheet:
/// seed 000's pinion at 1:1, whose positions' ends stand 1,4–2,8 mm apart (the numbers
/// carried out on leaders and spread: they stood 7 5 6 4 3 1 2, «2» inside r_a), and PZ1's
/// wheels at 5:1, whose ends stand apart (each number at its end), in Russian and English.
#[test]
fn the_rack_positions_numbers_read_in_order_along_the_blank() {
    for scene in ["constructions/shaper.toml", "constructions/gears-pz1.toml"] {
        for lang in [tmm::Lang::Ru, tmm::Lang::En] {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(scene);
            let s = tmm::load(&path).expect("scene");
            let session = tmm::Session::new(&s, tmm::Drafting::EXACT);
            let plates = tmm::sheets::build(&session, tmm::PlateKind::Gears, lang).expect("plates");
            let mut racks = 0;
            for plate in &plates {
                let l = tmm::plate::layout(plate);
                for (v, view) in plate.views.iter().enumerate() {
                    if view.figure.title != "generation" {
                        continue;
                    }
                    racks += 1;
                    let mut numbers: Vec<(usize, glam::DVec2, glam::DVec2)> = l
                        .labels
                        .iter()
                        .filter(|x| x.view == v)
                        .filter(|x| {
                            x.steps.iter().any(|id| {
                                view.figure.steps.iter().any(|s| {
                                    s.id == *id && s.note.starts_with("the number of rack position")
                                })
                            })
                        })
                        .map(|x| {
                            let k: usize = x.text.parse().expect("a number");
                            (k, x.anchor, (x.rect.min + x.rect.max) * 0.5)
                        })
                        .collect();
                    numbers.sort_by_key(|n| n.0);
                    assert!(numbers.len() >= 5, "{scene}: {} numbers", numbers.len());
                    let way = numbers[numbers.len() - 1].1 - numbers[0].1;
                    let along: Vec<f64> = numbers.iter().map(|n| n.2.dot(way)).collect();
                    assert!(
                        along.windows(2).all(|w| w[1] > w[0]),
                        "{scene} {lang:?}: the numbers stand out of order along the blank: {:?}",
                        numbers.iter().map(|n| (n.0, n.2)).collect::<Vec<_>>()
                    );
                }
            }
            assert_eq!(racks, 2, "{scene}: two rack cuttings");
        }
    }
}

#[test]
fn rack_generation_draws_a_few_numbered_positions_and_the_undercut_in_a_detail() {
    use tmm::construct::{Item, Role};
    let views = gear_views("constructions/gears-pz1.toml", tmm::Lang::Ru);
    let racks: Vec<&tmm::plate::View> = views
        .iter()
        .filter(|v| v.figure.title == "generation")
        .collect();
    assert_eq!(racks.len(), 2, "the zero and the shifted wheel");
    for v in &racks {
        let f = &v.figure;
        // The positions drawn: their outlines' groups, few of the 40 equal steps and the
        // fillet's 19 traced (with the device's four marks, 63 groups at most).
        let mut groups: Vec<u32> = f
            .steps
            .iter()
            .filter(|s| {
                s.note.starts_with("rack position ") && matches!(s.item, Item::Polyline { .. })
            })
            .map(|s| s.group)
            .collect();
        groups.dedup();
        assert!((5..=9).contains(&groups.len()), "{groups:?}");
        assert!(groups.iter().all(|g| *g >= 1 && *g <= 63), "{groups:?}");
        assert!(
            groups.last() > groups.first().map(|g| g + 30).as_ref(),
            "{groups:?}"
        );
        // Thin, each numbered 1, 2, … in order, its number in its own group.
        for s in f
            .steps
            .iter()
            .filter(|s| s.note.starts_with("rack position "))
        {
            assert_eq!(s.role, Role::Construction, "{}", s.note);
        }
        let numbers: Vec<(u32, String)> = f
            .steps
            .iter()
            .filter(|s| s.note.starts_with("the number of rack position"))
            .map(|s| (s.group, s.label.as_ref().expect("a number").text.clone()))
            .collect();
        let want: Vec<(u32, String)> = groups
            .iter()
            .enumerate()
            .map(|(k, g)| (*g, (k + 1).to_string()))
            .collect();
        assert_eq!(numbers, want);
        // The tooth bold, with its two neighbours (the spaces either side); the four circles
        // named.
        let teeth: Vec<&str> = f
            .steps
            .iter()
            .filter(|s| s.role == Role::Result)
            .map(|s| s.note.as_str())
            .collect();
        assert_eq!(
            teeth,
            [
                "the tooth: the envelope of the rack positions",
                "the neighbouring tooth",
                "the neighbouring tooth"
            ]
        );
        let mut circles = labels_of(f, "circle ");
        circles.sort();
        assert_eq!(circles, ["r", "r_a", "r_b", "r_f"]);
    }
    // The zero wheel (z = 10 < 17) is undercut: hatched on both flanks, its zone marked A and
    // drawn again at 20:1, where the hatching is 1 mm apart and each stroke is seen.
    let zero = &racks[0].figure;
    let hatch = hatching(zero);
    assert!(hatch.iter().any(|s| s.from.x > 0.0) && hatch.iter().any(|s| s.from.x < 0.0));
    assert_eq!(labels_of(zero, "the zone of the undercut's detail"), ["A"]);
    let detail = views
        .iter()
        .find(|v| v.figure.title == "detail of generation")
        .expect("the undercut's detail view");
    assert_eq!(detail.caption.as_deref(), Some("A (20:1)"));
    assert!((detail.figure.scale.value() - 5e-5).abs() < 1e-15);
    let strokes = hatching(&detail.figure);
    assert!(strokes.len() >= 10, "{}", strokes.len());
    // The strokes parallel, 1 mm apart across them (their offsets along the normal; the
    // hatcher works in f32 on the figure, whose strokes are 8 times shorter).
    let longest = strokes
        .iter()
        .max_by(|a, b| a.length().total_cmp(&b.length()))
        .expect("a stroke");
    let n = (longest.to - longest.from).normalize().perp();
    for s in strokes.iter().filter(|s| s.length() > 0.5) {
        assert!((s.to - s.from).normalize().dot(n).abs() < 1e-3);
    }
    let mut offsets: Vec<f64> = strokes.iter().map(|s| s.from.dot(n)).collect();
    offsets.sort_by(f64::total_cmp);
    for w in offsets.windows(2) {
        assert!((w[1] - w[0] - 1.0).abs() < 1e-3, "{offsets:?}");
    }
    let longest = strokes.iter().map(|s| s.length()).fold(0.0, f64::max);
    assert!(longest > 3.0, "{longest} mm");
    // Every detail stroke lies inside its border (the circle drawn last, before the names).
    let Some(border) = detail
        .figure
        .steps
        .iter()
        .rev()
        .find_map(|s| match &s.item {
            Item::Circle(c) => Some(c),
            _ => None,
        })
    else {
        panic!("the detail's border")
    };
    for s in &strokes {
        assert!(s.from.length() <= border.radius + 1e-9 && s.to.length() <= border.radius + 1e-9);
    }
    // The shifted wheel (x = 0.6 > x_min) has no undercut: nothing hatched, no detail.
    assert!(!racks[1].figure.steps.iter().any(|s| s.role == Role::Hatch));
    assert_eq!(
        views
            .iter()
            .filter(|v| v.figure.title == "detail of generation")
            .count(),
        1
    );
}

#[test]
fn the_drawn_rack_positions_are_recorded_ones() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("constructions/shaper.toml");
    let s = tmm::load(&path).expect("scene");
    let session = tmm::Session::new(&s, tmm::Drafting::EXACT);
    let g = session.gears().expect("gears");
    let r = &g.racks[0].generation;
    let drawn = r.drawing();
    // 60 steps and the device's marks traced, 7 drawn.
    let traced = r.figure.steps.iter().map(|s| s.group).max().unwrap_or(0);
    assert!(traced >= 60, "{traced}");
    assert_eq!(r.drawn.len(), 7);
    assert_eq!((r.drawn[0], r.drawn[6]), (1, traced));
    for step in &drawn.steps {
        assert_eq!(
            Some(step),
            r.figure.steps.get(step.id.0 as usize),
            "{}",
            step.note
        );
        assert!(step.group == 0 || r.drawn.contains(&step.group));
    }
    // The tooth drawn is the one traced from every position: the envelope within 1e-4·m.
    assert!(r.deviation < 1e-4 * r.cutting.module, "{}", r.deviation);
}

/// A plan of angular velocities: its μ_ω as printed and as a number, and ω of some shafts
/// (rad/s).
type Plan<'a> = (&'a str, f64, &'a [(&'a str, f64)]);

/// A scene's plans of angular velocities: the scene, the language, its first plan, and the
/// slow links' own, if any.
type PlanCase<'a> = (&'a str, tmm::Lang, Plan<'a>, Option<Plan<'a>>);

#[test]
fn the_plan_of_angular_velocities_names_every_ray_and_prints_mu_omega() {
    // PZ2 example 3 per unit input (no speed given): ω₁ = 1, ω₂₋₃ = z₁/z₂ = 0.25 (wheel 2
    // internal), ω_H = ω₂₋₃/(1 + z₅/z₃) = 0.05, the ring 5 at rest, the satellite
    // ω₄ = ω_H(1 − z₅/z₄) = −1/12.
    let omega_4 = 0.05 * (1.0 - 80.0 / 30.0);
    let w1 = 1400.0 * std::f64::consts::PI / 30.0;
    let u18 = (-74.0 / 29.0) * (1.0 - (48.0 * 76.0) / (106.0 * 18.0)) * (-100.0 / 25.0);
    let cases: [PlanCase<'_>; 3] = [
        (
            "constructions/gears-pz2.toml",
            tmm::Lang::Ru,
            (
                "μ_{ω} = μ_{v}/(μ_{l}·h) = 0,02 рад/(с·мм)",
                0.02,
                &[
                    ("1", 1.0),
                    ("2-3", 0.25),
                    ("H", 0.05),
                    ("4", omega_4),
                    ("5", 0.0),
                ],
            ),
            // H read 2,5 mm from the foot: the stage 3-4-5-H read again at the same h and
            // μ_v = 0,0001, five times finer: 2-3 at 62,5 mm, H at 12,5 mm.
            Some((
                "μ_{v} = 0,0001 м/(с·мм), μ_{ω} = μ_{v}/(μ_{l}·h) = 0,004 рад/(с·мм)",
                0.004,
                &[("2-3", 0.25), ("H", 0.05), ("4", omega_4), ("5", 0.0)],
            )),
        ),
        (
            "constructions/gears-pz2.toml",
            tmm::Lang::En,
            (
                "μ_{ω} = μ_{v}/(μ_{l}·h) = 0.02 rad/(s·mm)",
                0.02,
                &[("1", 1.0), ("H", 0.05)],
            ),
            Some((
                "μ_{v} = 0.0001 m/(s·mm), μ_{ω} = μ_{v}/(μ_{l}·h) = 0.004 rad/(s·mm)",
                0.004,
                &[("H", 0.05)],
            )),
        ),
        // Seed 000's reducer at n₁ = 1400 rpm: ω₁ = 146.608 rad/s, u₁₈ = i₁₂·i₃H·i₇₈ = −9.30818
        // (i₁₂ = −74/29, i₃H = 1 − z₄z₆/(z₃z₅), i₇₈ = −100/25).
        (
            "constructions/shaper.toml",
            tmm::Lang::Uk,
            (
                "μ_{ω} = μ_{v}/(μ_{l}·h) = 2,5 рад/(с·мм)",
                2.5,
                &[("1", w1), ("6", 0.0), ("8", w1 / u18)],
            ),
            None,
        ),
    ];
    for (scene, lang, first, slow) in cases {
        let views = gear_views(scene, lang);
        let v = views
            .iter()
            .find(|v| v.figure.title == "velocity triangles")
            .expect("the triangles");
        let f = &v.figure;
        // One plan, or two (the slow links' drawn after the first): each with its pole, its
        // foot, its h and its μ_ω.
        let plans: Vec<Plan<'_>> = std::iter::once(first).chain(slow).collect();
        let n = plans.len();
        assert_eq!(labels_of(f, "μ_ω of the plan"), [first.0], "{scene}");
        let second: Vec<&str> = slow.iter().map(|p| p.0).collect();
        assert_eq!(
            labels_of(f, "μ_ω of the slow links' plan"),
            second,
            "{scene}"
        );
        assert_eq!(labels_of(f, "the pole of the plan"), vec!["p_ω"; n]);
        assert_eq!(labels_of(f, "the foot of the pole"), vec!["0"; n]);
        assert_eq!(labels_of(f, "the pole distance H"), vec!["h"; n]);
        let feet: Vec<_> = f
            .steps
            .iter()
            .filter(|s| s.note.starts_with("the foot of the pole"))
            .filter_map(|s| s.label.as_ref())
            .map(|l| l.anchor)
            .collect();
        for (k, (_, mu_w, omegas)) in plans.iter().enumerate() {
            let foot = feet[k];
            for (shaft, omega) in omegas.iter() {
                // The plan's own ray of the shaft.
                let ray = f
                    .steps
                    .iter()
                    .filter(|s| s.note == format!("the ray of ω of {shaft}"))
                    .nth(k)
                    .unwrap_or_else(|| panic!("{scene}: the ray of {shaft} on plan {k}"));
                let label = ray.label.as_ref().expect("every ray named");
                assert_eq!(&label.text, shaft);
                // Named where it meets the reading line; its intercept from 0 reads ω at μ_ω.
                assert!((label.anchor.y - foot.y).abs() < 1e-9);
                let read = (label.anchor.x - foot.x) * mu_w;
                assert!(
                    (read - omega).abs() <= 1e-9 * omega.abs().max(1.0),
                    "{scene}: ω_{shaft} read {read} on plan {k}, want {omega}"
                );
                // And the intercept is marked.
                assert!(f
                    .steps
                    .iter()
                    .any(|s| s.note == format!("the intercept of ω of {shaft}")
                        && s.item == tmm::construct::Item::Point(label.anchor)));
            }
        }
        // Every link's ray named, none twice on a plan (the first draws every link's).
        let rays = labels_of(f, "the ray of ω of");
        let mut names = rays.clone();
        names.sort();
        names.dedup();
        let (one, two) = rays.split_at(names.len());
        for plan in [one, two] {
            let mut distinct = plan.to_vec();
            distinct.sort();
            distinct.dedup();
            assert_eq!(distinct.len(), plan.len(), "{scene}: {rays:?}");
        }
        assert_eq!(two.is_empty(), n == 1, "{scene}: {rays:?}");
        assert!(one.len() >= first.2.len());
    }
}

/// A rack-cut wheel's undercut, a sliver at the picture's 1:1, is hatched where it shows: the
/// caption sends the reader to the detail that draws it (the shaper's z = 13, x = 0 said
/// «подрез заштрихован» under a picture where no hatching can be seen), in ru, uk and en.
#[test]
fn the_undercut_is_said_to_be_hatched_in_its_detail() {
    for (lang, words) in [
        (tmm::Lang::Ru, "подрез заштрихован на выносном элементе A"),
        (tmm::Lang::Uk, "підріз заштриховано на виносному елементі A"),
        (tmm::Lang::En, "the undercut hatched in detail A"),
    ] {
        let captions: Vec<String> = gear_views("constructions/shaper.toml", lang)
            .into_iter()
            .filter_map(|v| v.caption)
            .collect();
        assert!(
            captions.iter().any(|c| c.starts_with("A (")),
            "{lang:?}: {captions:?}"
        );
        assert!(
            captions.iter().any(|c| c.ends_with(words)),
            "{lang:?}: {captions:?}"
        );
    }
}
