//! Tests of the gear trains: Willis, the stages and the velocity triangles against the seeds'
//! worked examples, the assembly condition, the first stage at a required ratio.

use crate::gears::tests::ctx;
use crate::gears::*;
use proptest::prelude::*;

/// A train from (shaft, wheel name, z, internal) and meshes by wheel names.
pub(in crate::gears) fn train(
    wheels: &[(&str, &str, u32, bool)],
    meshes: &[(&str, &str)],
    io: (&str, &str),
    fixed: Option<&str>,
    carrier: Option<&str>,
    satellites: &[&str],
) -> Train {
    let mut shafts: Vec<String> = Vec::new();
    let idx = |s: &str, shafts: &mut Vec<String>| match shafts.iter().position(|x| x == s) {
        Some(i) => i,
        None => {
            shafts.push(s.to_string());
            shafts.len() - 1
        }
    };
    let ws: Vec<train::Wheel> = wheels
        .iter()
        .map(|(s, n, z, int)| train::Wheel {
            name: n.to_string(),
            z: f64::from(*z),
            shaft: idx(s, &mut shafts),
            internal: *int,
            module: None,
        })
        .collect();
    let w = |n: &str| ws.iter().position(|x| x.name == n).unwrap();
    let ms = meshes.iter().map(|(a, b)| Mesh(w(a), w(b))).collect();
    let input = idx(io.0, &mut shafts);
    let output = idx(io.1, &mut shafts);
    let fixed = fixed.map(|f| idx(f, &mut shafts));
    let carrier = carrier.map(|c| idx(c, &mut shafts));
    let satellites = satellites.iter().map(|s| idx(s, &mut shafts)).collect();
    Train {
        shafts,
        wheels: ws,
        meshes: ms,
        input,
        output,
        fixed,
        carrier,
        satellites,
        module: 0.002,
        second: None,
    }
}

/// Seed 000's reducer with z₁/z₂.
fn reducer(z1: u32, z2: u32) -> Train {
    train(
        &[
            ("A", "1", z1, false),
            ("B", "2", z2, false),
            ("B", "3", 106, true),
            ("S", "4", 48, false),
            ("S", "5", 18, false),
            ("F", "6", 76, true),
            ("H", "7", 25, false),
            ("C", "8", 100, false),
        ],
        &[("1", "2"), ("3", "4"), ("5", "6"), ("7", "8")],
        ("A", "C"),
        Some("F"),
        Some("H"),
        &["S"],
    )
}

#[test]
fn seed000_reducer_by_willis_stages_and_triangles() {
    let t = reducer(29, 74);
    let u = t.ratio().unwrap();
    // i₁₂ = −74/29, i₃H = 1 − z₄z₆/(z₃z₅) = −0.91195, i₇₈ = −4.
    let i3h: f64 = 1.0 - (48.0 * 76.0) / (106.0 * 18.0);
    assert!((i3h + 0.91195).abs() < 1e-5);
    assert!((u - (-74.0 / 29.0) * i3h * -4.0).abs() < 1e-12, "{u}");
    assert!((u.abs() - 9.308).abs() < 5e-4);
    assert!((t.by_stages().unwrap() - u).abs() < 1e-12);
    let tri = triangles::triangles(&t, 1.0, &ctx(0.0)).unwrap();
    assert!((tri.ratio - u).abs() < 1e-9 * u.abs(), "{} {u}", tri.ratio);
    // Satellite speed relative to the carrier: 2533.3 rpm at n_H = 600 (seed: −1933.3 absolute).
    let w = t.willis().unwrap();
    let (wh, ws) = (w[t.carrier.unwrap()], w[t.satellites[0]]);
    assert!(((ws / wh) - (1.0 - 76.0 / 18.0)).abs() < 1e-12);
    // The required 1400/150 = 9.333: 87/34 fits better than the seed's 74/29.
    let required = 1400.0 / 150.0;
    let u87 = reducer(34, 87).ratio().unwrap().abs();
    assert!((u87 - required).abs() < (u.abs() - required).abs());
    let i12 = required / (i3h.abs() * 4.0);
    let best = train::best_pairs(i12, 17, 40, 5);
    assert_eq!((best[0].0, best[0].1), (34, 87), "{best:?}");
    // At 0.5 mm each intercept is read to 0.25 mm: the ratio within that bound.
    let read = triangles::triangles(&t, 1.0, &ctx(0.5)).unwrap();
    let x = |k: usize| (tri.omega[k] / tri.scale_w.value()).abs();
    let bound = 0.25 / x(t.input) + 0.25 / x(t.output);
    assert!(
        ((read.ratio - u) / u).abs() <= bound * 1.01,
        "{} {bound}",
        read.ratio
    );
}

/// PZ2 example 1 as printed (L546): sun 1, satellite block 2–3, wheel 4 fixed, carrier H
/// carrying wheel 5; 5–6–7 on fixed axes, 7 internal.
pub(in crate::gears) fn pz2_example_1() -> Train {
    train(
        &[
            ("A", "1", 88, false),
            ("S", "2", 48, false),
            ("S", "3", 4, false),
            ("F", "4", 44, false),
            ("H", "5", 25, false),
            ("D", "6", 17, false),
            ("E", "7", 100, true),
        ],
        &[("1", "2"), ("3", "4"), ("5", "6"), ("6", "7")],
        ("A", "E"),
        Some("F"),
        Some("H"),
        &["S"],
    )
}

/// PZ2 example 2 as printed (L588, L603–L607): 1–2 on fixed axes into the sun 3 (2 and 3 on
/// one shaft), the satellite block 4–5, wheel 6 fixed, the carrier H out; every mesh
/// external.
pub(in crate::gears) fn pz2_example_2() -> Train {
    train(
        &[
            ("A", "1", 13, false),
            ("B", "2", 52, false),
            ("B", "3", 15, false),
            ("S", "4", 33, false),
            ("S", "5", 11, false),
            ("F", "6", 45, false),
        ],
        &[("1", "2"), ("3", "4"), ("5", "6")],
        ("A", "H"),
        Some("F"),
        Some("H"),
        &["S"],
    )
}

#[test]
fn pz2_worked_examples_by_willis() {
    // Example 3: 1–2 internal, James stage 3–4–5 with the ring fixed: u1H = 20.
    let ex3 = train(
        &[
            ("A", "1", 25, false),
            ("B", "2", 100, true),
            ("B", "3", 20, false),
            ("S", "4", 30, false),
            ("F", "5", 80, true),
        ],
        &[("1", "2"), ("3", "4"), ("4", "5")],
        ("A", "H"),
        Some("F"),
        Some("H"),
        &["S"],
    );
    assert!((ex3.ratio().unwrap() - 20.0).abs() < 1e-12);
    assert!((ex3.by_stages().unwrap() - 20.0).abs() < 1e-12);
    let tri = triangles::triangles(&ex3, 1.0, &ctx(0.0)).unwrap();
    assert!((tri.ratio - 20.0).abs() < 1e-9 * 20.0);
    // Example 1 as printed (not coaxial, Willis only): u17 = 20.
    let ex1 = pz2_example_1();
    assert!((ex1.ratio().unwrap() - 20.0).abs() < 1e-12);
    assert!(triangles::triangles(&ex1, 1.0, &ctx(0.0)).is_err());
    // Example 2 as printed (not coaxial, Willis only): u1H = u12·u3H = −4·(1 − 9) = 32, not
    // the printed 20 (33·45/(15·11) = 9, not 6).
    let ex2 = pz2_example_2();
    let w = ex2.willis().unwrap();
    let (h, b) = (ex2.carrier.unwrap(), ex2.wheels[2].shaft);
    assert!((w[ex2.input] / w[b] - (-4.0)).abs() < 1e-12);
    assert!((w[b] / w[h] - (1.0 - 9.0)).abs() < 1e-12);
    assert!((ex2.ratio().unwrap() - 32.0).abs() < 1e-12);
    assert!(triangles::triangles(&ex2, 1.0, &ctx(0.0)).is_err());
}

#[test]
fn a_train_that_is_not_determined_is_refused() {
    let mut t = reducer(29, 74);
    t.fixed = None;
    let e = t.willis().unwrap_err();
    assert!(
        matches!(e, TrainError::Mobility { mobility, inputs: 1 } if mobility.w() == 2),
        "{e}"
    );
}

/// A differential (W = 2, seed 002 L419): the James stage with its ring freed, the sun and
/// the ring both driven. Willis's formula (ω_a − ω_H)/(ω_b − ω_H) = u_ab^(H) = −z_b/z_a gives
/// ω_H = (z_a ω_a + z_b ω_b)/(z_a + z_b); the linear system and the triangles give every
/// shaft's ω, equal to 1e-9. Without the second input it is refused: W = 2, one input.
#[test]
fn a_differential_solves_by_willis_and_by_the_triangles() {
    for (za, zg, w_ring) in [(20, 30, -0.5), (17, 23, 0.25), (40, 20, 2.0), (24, 36, 0.0)] {
        let zb = za + 2 * zg;
        let mut t = train(
            &[
                ("A", "a", za, false),
                ("S", "g", zg, false),
                ("R", "b", zb, true),
            ],
            &[("a", "g"), ("g", "b")],
            ("A", "H"),
            None,
            Some("H"),
            &["S"],
        );
        assert_eq!(t.mobility().w(), 2);
        assert!(matches!(
            t.willis(),
            Err(TrainError::Mobility { inputs: 1, .. })
        ));
        let ring = t.shafts.iter().position(|s| s == "R").unwrap();
        t.second = Some((ring, w_ring));
        let (fa, fb) = (f64::from(za), f64::from(zb));
        let w_h = (fa + fb * w_ring) / (fa + fb);
        let w = t.willis().unwrap();
        let h = t.carrier.unwrap();
        assert!((w[h] - w_h).abs() < 1e-12, "{} {w_h}", w[h]);
        // The satellite by its mesh with the sun, the carrier's frame: z_g(ω_g − ω_H) = −z_a(ω_a − ω_H).
        let s = t.satellites[0];
        let w_g = w_h - fa / f64::from(zg) * (1.0 - w_h);
        assert!((w[s] - w_g).abs() < 1e-12);
        for omega_in in [1.0, -7.5] {
            let tri = triangles::triangles(&t, omega_in, &ctx(0.0)).unwrap();
            for (k, wk) in w.iter().enumerate() {
                assert!(
                    (tri.omega[k] - wk * omega_in).abs() < 1e-9 * omega_in.abs(),
                    "shaft {k}: {} against {}",
                    tri.omega[k],
                    wk * omega_in
                );
            }
            assert!((tri.ratio - 1.0 / w_h).abs() < 1e-9 / w_h.abs());
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn willis_equals_the_triangles_on_random_james_trains(
        za in 12u32..60, zg in 12u32..60, z1 in 12u32..50, z2 in 12u32..120
    ) {
        // A pair 1–2 into the sun of a James stage, ring fixed, output the carrier.
        let t = train(
            &[("A", "1", z1, false), ("B", "2", z2, false), ("B", "a", za, false), ("S", "g", zg, false), ("F", "b", za + 2 * zg, true)],
            &[("1", "2"), ("a", "g"), ("g", "b")],
            ("A", "H"),
            Some("F"),
            Some("H"),
            &["S"],
        );
        let u = t.ratio().unwrap();
        let expect = -(f64::from(z2) / f64::from(z1)) * (1.0 + f64::from(za + 2 * zg) / f64::from(za));
        prop_assert!((u - expect).abs() < 1e-9 * expect.abs());
        prop_assert!((t.by_stages().unwrap() - u).abs() < 1e-9 * u.abs());
        let tri = triangles::triangles(&t, 1.0, &ctx(0.0)).unwrap();
        prop_assert!((tri.ratio - u).abs() < 1e-9 * u.abs());
    }
}

/// The assembly condition by placing the satellites: central wheel a (z_a, a ring when
/// `a_ring`) meshes the block's wheel g, the block's wheel f meshes the fixed b; both central
/// wheels stand still while k rigid blocks (g and f fixed to each other alike) are put in at
/// 2πj/k. Each mesh fixes the sum (external) or difference (internal) of the two wheels' tooth
/// phases at the contact direction; the first block sets both constants. True when every
/// block has an orientation meeting both.
fn blocks_fit(za: u32, a_ring: bool, zg: u32, zf: u32, zb: u32, b_ring: bool, k: u32) -> bool {
    use std::f64::consts::TAU;
    // The mesh phase of central z_c and satellite z_s with the block at θ turned by ψ.
    let phase = |zc: u32, ring: bool, zs: u32, theta: f64, psi: f64| {
        let c = f64::from(zc) * theta / TAU;
        if ring {
            c - f64::from(zs) * (theta - psi) / TAU
        } else {
            c + f64::from(zs) * (theta + TAU / 2.0 - psi) / TAU
        }
    };
    let whole = |x: f64| (x - x.round()).abs() < 1e-9;
    let (ca, cb) = (
        phase(za, a_ring, zg, 0.0, 0.0),
        phase(zb, b_ring, zf, 0.0, 0.0),
    );
    (1..k).all(|j| {
        let theta = TAU * f64::from(j) / f64::from(k);
        // The phase is linear in ψ with slope ±z_g/2π: ψ* meets the a-mesh exactly, and so
        // does ψ* + 2πn/z_g.
        let slope = if a_ring { 1.0 } else { -1.0 } * f64::from(zg) / TAU;
        let psi0 = (ca - phase(za, a_ring, zg, theta, 0.0)) / slope;
        (0..zg).any(|n| {
            let psi = psi0 + TAU * f64::from(n) / f64::from(zg);
            whole(phase(zb, b_ring, zf, theta, psi) - cb)
        })
    })
}

/// PZ2 example 3's James stage alone: sun 3 in, satellite 4, ring 5 fixed, carrier out.
pub(in crate::gears) fn pz2_james() -> Train {
    train(
        &[
            ("A", "3", 20, false),
            ("S", "4", 30, false),
            ("F", "5", 80, true),
        ],
        &[("3", "4"), ("4", "5")],
        ("A", "H"),
        Some("F"),
        Some("H"),
        &["S"],
    )
}

#[test]
fn assembly_condition_of_the_seed000_reducer_and_pz2() {
    // Seed 000: z₃·u₃H⁽⁶⁾/k = 106·(1 − 48·76/(106·18))/k = −290/(3k).
    let t = reducer(29, 74);
    let a3 = t.assembly(3).unwrap();
    assert_eq!(t.wheels[a3.central].name, "3");
    assert_eq!(
        (a3.value, a3.p, a3.block),
        ((-290, 9), None, Some((-290, 3)))
    );
    let a2 = t.assembly(2).unwrap();
    assert_eq!(
        (a2.value, a2.p, a2.block),
        ((-145, 3), Some(1), Some((-145, 1)))
    );
    // A block the textbook's (1 + kp) refuses though it fits turned by 2π·2/z_g:
    // z_a = 17, z_g = 14, z_f = 32, ring 68, k = 2: 187/8·(1 + 2p) is never whole, yet
    // 187/8·32/2 = 374 is.
    let b = train(
        &[
            ("A", "a", 17, false),
            ("S", "g", 14, false),
            ("S", "f", 32, false),
            ("F", "b", 68, true),
        ],
        &[("a", "g"), ("f", "b")],
        ("A", "H"),
        Some("F"),
        Some("H"),
        &["S"],
    )
    .assembly(2)
    .unwrap();
    assert_eq!((b.value, b.p, b.block), ((187, 8), None, Some((374, 1))));
    assert!(b.fits() && blocks_fit(17, false, 14, 32, 68, true, 2));
    assert!(!blocks_fit(106, true, 48, 18, 76, true, 3));
    assert!(blocks_fit(106, true, 48, 18, 76, true, 2));
    assert!(t.admits(2) && !t.admits(3));
    // One satellite has neither neighbours nor an assembly condition.
    assert!(t.assembly(1).is_none() && t.neighbour(1).is_none());
    // PZ2 example 3's James stage: (20 + 80)/k whole for k = 4, not for k = 3.
    let james = pz2_james();
    assert_eq!(
        james.assembly(4).map(|a| (a.value, a.p)),
        Some(((25, 1), Some(0)))
    );
    assert!(james
        .assembly(3)
        .is_some_and(|a| a.p.is_none() && !a.fits()));
    // Neighbours: (20 + 30)·sin(π/k) against 30 + 2 teeth: k = 4 fits, k = 5 does not.
    assert!(james.admits(4) && !james.admits(5));
}

#[test]
fn the_first_stage_at_the_required_ratio_gives_it_by_willis_and_the_triangles() {
    // Seed 000: U₁₋₈ = n₁/n₈ = 1400/150; the seed solves i₁₂ = U/(i₃H·i₇₈) = 2.5586.
    let t = reducer(29, 74).with_ratio(0, 1400.0 / 150.0).unwrap();
    let u = t.ratio().unwrap();
    assert!((u + 28.0 / 3.0).abs() < 1e-12, "{u}");
    assert!((t.wheels[1].z / t.wheels[0].z - 2.558_621).abs() < 1e-6);
    let tri = triangles::triangles(&t, 1.0, &ctx(0.0)).unwrap();
    assert!((tri.ratio - u).abs() < 1e-9 * u.abs());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn assembly_condition_equals_placing_the_satellites(
        za in 12u32..60, zg in 12u32..40, zf in 12u32..40, a_ring in any::<bool>(), b_ring in any::<bool>(), k in 2u32..7, dz in 0u32..30
    ) {
        // Any block (z_g, z_f) between a and b; coaxiality is not needed to place teeth.
        let zb = if b_ring { za + zg + zf + dz } else { 12 + dz };
        let t = train(
            &[("A", "a", za, a_ring), ("S", "g", zg, false), ("S", "f", zf, false), ("F", "b", zb, b_ring)],
            &[("a", "g"), ("f", "b")],
            ("A", "H"),
            Some("F"),
            Some("H"),
            &["S"],
        );
        let a = t.assembly(k).unwrap();
        prop_assert_eq!(a.fits(), blocks_fit(za, a_ring, zg, zf, zb, b_ring, k), "{:?}", a);
        // The textbook's (1 + kp) is sufficient.
        prop_assert!(a.p.is_none() || a.fits(), "{:?}", a);
    }
}

#[test]
fn the_required_stage_is_a_fixed_axis_mesh_or_none() {
    // A James stage alone: no fixed-axis mesh to size, the study stands without it.
    let james = pz2_james();
    assert_eq!(james.fixed_axis_mesh(), None);
    let spec = |train: Train| PlanetarySpec {
        train,
        n_input: Some(1000.0),
        n_output: Some(190.0),
        satellites: Some(4),
        closing: false,
        seed: TrainSeed::default(),
    };
    let s = train_study(&spec(james), &ctx(0.0)).unwrap();
    assert!(s.required.is_none() && (s.ratio - 5.0).abs() < 1e-12);
    // The seed's reducer: mesh 1–2, and the design gives the required 1000/190 exactly.
    let r = train_study(&spec(reducer(29, 74)), &ctx(0.0)).unwrap();
    let req = r.required.unwrap();
    assert!((req.ratio.abs() - 1000.0 / 190.0).abs() < 1e-12);
    assert!((req.triangles.ratio - req.ratio).abs() < 1e-9 * req.ratio.abs());
}

/// A slow output read on a picture of its own (issue 45): PZ2's examples at u = 20 and 32
/// put the output's intercept a few millimetres from the foot of one plan, where a reading
/// to 0,5 mm errs by a sixth; the links from a pivot to the output drawn again at their own
/// μ_v read u within the bound of the four intercepts read (each to 0,25 mm), and exactly
/// when read exactly.
#[test]
fn a_slow_output_is_read_on_a_picture_of_its_own() {
    for (t, u) in [(pz2_example_1(), 20.0), (pz2_example_2(), 32.0)] {
        let (t, _) = t.closing().unwrap();
        let exact = triangles::triangles(&t, 1.0, &ctx(0.0)).unwrap();
        assert!((exact.ratio.abs() - u).abs() < 1e-9 * u, "{}", exact.ratio);
        let tri = triangles::triangles(&t, 1.0, &ctx(0.5)).unwrap();
        let slow = tri
            .slow
            .as_ref()
            .unwrap_or_else(|| panic!("u = {u}: one plan"));
        assert!(slow.links.contains(&t.output) && slow.links.contains(&slow.pivot));
        assert!(!slow.links.contains(&t.input), "{:?}", slow.links);
        // The picture draws the route's stage only: every velocity at a pole of a mesh of
        // two of its links (the pivot's given one among them), its axis of heights no
        // higher than their poles and axes.
        let (ys, poles) = t.layout().unwrap();
        let lo = ys
            .iter()
            .chain(&poles)
            .fold(f64::INFINITY, |a, v| a.min(*v));
        let drawn = |y: f64| (y - lo) / tri.scale_l.value();
        let on = |w: usize| slow.links.contains(&t.wheels[w].shaft);
        let own: Vec<f64> = t
            .meshes
            .iter()
            .zip(&poles)
            .filter(|(m, _)| on(m.0) && on(m.1))
            .map(|(_, y)| drawn(*y))
            .collect();
        let top = slow
            .links
            .iter()
            .map(|k| drawn(ys[*k]))
            .chain(own.iter().copied())
            .fold(f64::NEG_INFINITY, f64::max);
        for step in &slow.figure.steps {
            match (&step.item, step.note.as_str()) {
                (crate::construct::Item::Vector { to, .. }, "the velocity of the pole") => {
                    assert!(own.iter().any(|y| (y - to.y).abs() < 1e-9), "u = {u}: {to}");
                }
                (crate::construct::Item::Segment(s), "the axis of heights") => {
                    assert!(s.from.y.max(s.to.y) <= top + 5.0 + 1e-9, "u = {u}: {s:?}");
                }
                _ => {}
            }
        }
        // The four intercepts as drawn: the input's and the pivot's on the first plan, the
        // pivot's and the output's on the second.
        let first = |k: usize| (exact.omega[k] / tri.scale_w.value()).abs();
        let second = |k: usize| (exact.omega[k] / slow.scale_w.value()).abs();
        let bound = 0.25 / first(t.input)
            + 0.25 / first(slow.pivot)
            + 0.25 / second(slow.pivot)
            + 0.25 / second(t.output);
        let err = ((tri.ratio.abs() - u) / u).abs();
        assert!(
            err <= bound * 1.01 && err < 0.05,
            "u = {u}: {} ({err} > {bound})",
            tri.ratio
        );
    }
}
