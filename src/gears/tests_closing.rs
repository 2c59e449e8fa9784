//! Tests of the trains the source prints at one module (PZ2 examples 1 and 2): the module
//! that closes the carrier's arm, the triangles on it against Willis, the printed ratios
//! checked; and a differential by Willis's formula against a hand oracle for each of its
//! outputs.

use super::tests::ctx;
use super::train::tests::{pz2_example_1, pz2_example_2, pz2_james, train};
use super::*;
use crate::check::notes::TrainNote;

/// The module of wheel `name`.
fn module_of(t: &Train, name: &str) -> Option<f64> {
    t.wheels.iter().find(|w| w.name == name)?.module
}

/// PZ2 examples 1 and 2 as the seed works them (L546–L621): W = 3n − 2p₅ − p₄ = 1 (n = 5,
/// p₅ = 5, p₄ = 4; n = 4, p₅ = 4, p₄ = 3), the ratio by Willis and by the stages against the
/// seed's own arithmetic done by hand here: u₁₇ = [1 − (−48/88)(−44/4)]·(−17/25)(100/17) = 20
/// as printed (L584); u₁H = (−52/13)·[1 − (−33/15)(−45/11)] = 32, where the seed prints 20
/// (L621: its bracket takes 6 for (33/15)(45/11) = 9, an erratum). With one module neither is
/// coaxial (88 + 48 ≠ 4 + 44; 15 + 33 ≠ 11 + 45) and the triangles are refused; closed, the
/// satellite's second mesh takes m′ = m(z₁ + z₂)/(z₃ + z₄) (m(z₃ + z₄)/(z₅ + z₆)), and the
/// triangles read Willis's ratio to 1e-9.
#[test]
fn pz2_examples_1_and_2_closed_by_the_module_the_seed_leaves_out() {
    let m = 0.002;
    let (ex1, ex2) = (pz2_example_1(), pz2_example_2());
    assert_eq!(
        (ex1.mobility(), ex1.mobility().w()),
        (TrainMobility { n: 5, p5: 5, p4: 4 }, 1)
    );
    assert_eq!(
        (ex2.mobility(), ex2.mobility().w()),
        (TrainMobility { n: 4, p5: 4, p4: 3 }, 1)
    );
    let u17: f64 = (1.0 - (-48.0 / 88.0) * (-44.0 / 4.0)) * (-17.0 / 25.0) * (100.0 / 17.0);
    let u1h: f64 = (-52.0 / 13.0) * (1.0 - (-33.0 / 15.0) * (-45.0 / 11.0));
    assert!((u17 - 20.0).abs() < 1e-12 && (u1h - 32.0).abs() < 1e-12);
    let cases = [
        (
            &ex1,
            u17,
            ["3", "4"],
            m * (88.0 + 48.0) / (4.0 + 44.0),
            m * 68.0,
        ),
        (
            &ex2,
            u1h,
            ["5", "6"],
            m * (15.0 + 33.0) / (11.0 + 45.0),
            m * 24.0,
        ),
    ];
    for (t, u, [s, c], module, arm) in cases {
        let e = triangles::triangles(t, 1.0, &ctx(0.0)).unwrap_err();
        assert!(e.to_string().contains("coaxiality"), "{e}");
        assert!((t.ratio().unwrap() - u).abs() < 1e-12 * u);
        assert!((t.by_stages().unwrap() - u).abs() < 1e-12 * u);
        let (closed, closings) = t.closing().unwrap();
        assert_eq!(closings.len(), 1, "{closings:?}");
        let k = closings[0];
        let name = |w: usize| t.wheels[w].name.as_str();
        assert_eq!((name(k.mesh.0), name(k.mesh.1)), (s, c));
        assert!((k.module - module).abs() < 1e-12 * module, "{}", k.module);
        assert!((k.arm - arm).abs() < 1e-12 * arm);
        for w in [s, c] {
            assert_eq!(module_of(&closed, w), Some(k.module));
        }
        // Only the closed mesh changes: every other wheel keeps the train's module.
        let others = closed.wheels.iter().filter(|w| w.name != s && w.name != c);
        assert!(others.clone().all(|w| w.module.is_none()));
        // Willis needs the teeth only; the triangles on the closed train read it.
        assert!((closed.ratio().unwrap() - u).abs() < 1e-12 * u);
        let tri = triangles::triangles(&closed, 1.0, &ctx(0.0)).unwrap();
        assert!((tri.ratio - u).abs() < 1e-9 * u, "{}", tri.ratio);
    }
}

/// A coaxial train comes back from the closing as it is; a stage no module closes (a ring of
/// fewer teeth than its satellite) and a mesh whose wheel has the scene's own module are
/// left to the layout's refusal.
#[test]
fn the_closing_leaves_coaxial_trains_and_refuses_what_no_module_closes() {
    for t in [pz2_james(), pz2_example_1().closing().unwrap().0] {
        let (closed, closings) = t.closing().unwrap();
        assert!(closings.is_empty());
        assert_eq!(closed, t);
    }
    // Sun 20, satellite 30 and a "ring" of 25: the ring's teeth less the satellite's are
    // negative, no centre distance.
    let mut t = pz2_james();
    t.wheels[2].z = 25.0;
    let e = t.closing().unwrap_err();
    assert!(e.to_string().contains("coaxiality"), "{e}");
    // Example 1 with wheel 4 at a module of its own: the scene's, not closed.
    let mut t = pz2_example_1();
    t.wheels[3].module = Some(0.005);
    assert!(t.closing().is_err());
}

/// The printed ratio against the train's: example 2's printed 20 needs u₃₆^(H) = 6 of its
/// planetary stage, the other stage as its teeth give (u₁₂ = −4: −4·(1 − 6) = 20), whereas
/// the teeth give 9; example 1's printed 20 is reproduced.
#[test]
fn a_printed_ratio_is_reproduced_or_traced_to_its_stage() {
    let study = |train: Train, u: f64| {
        let spec = PlanetarySpec {
            train,
            n_input: None,
            n_output: None,
            satellites: None,
            closing: true,
            seed: TrainSeed {
                u: Some(u),
                w: Some(1),
            },
        };
        train_study(&spec, &ctx(0.0)).unwrap()
    };
    let ex2 = study(pz2_example_2(), 20.0);
    assert!(!TrainSeed::reproduces(20.0, ex2.ratio));
    let s = ex2.seed_stage().unwrap();
    assert_eq!((s.a.as_str(), s.f.as_str()), ("3", "6"));
    assert!((s.needed - 6.0).abs() < 1e-12 && (s.teeth - 9.0).abs() < 1e-12);
    let notes = ex2.notes();
    assert!(
        notes.iter().any(|n| matches!(n,
            TrainNote::SeedRatioErratum { name, printed, stage: Some(s), .. }
                if name == "u_A_H" && *printed == 20.0 && s.a == "3")),
        "{notes:?}"
    );
    assert!(
        notes.contains(&TrainNote::SeedMobility { w: 1 }),
        "{notes:?}"
    );
    let ex1 = study(pz2_example_1(), 20.0);
    assert!(TrainSeed::reproduces(20.0, ex1.ratio));
    assert!(ex1.notes().iter().any(|n| matches!(n,
        TrainNote::SeedRatio { name, printed, .. } if name == "u_A_E" && *printed == 20.0)));
    // The rounding a print allows, and no more.
    assert!(TrainSeed::reproduces(9.31, 9.30818) && !TrainSeed::reproduces(9.4, 9.30818));
}

/// A differential (W = 2) by Willis's formula for each of its outputs, against the formula
/// solved by hand: the James stage (sun a, z_a; satellite; ring b, z_b), u_ab^(H) = −z_b/z_a;
/// with the sun and the ring given, ω_H = (z_a ω_a + z_b ω_b)/(z_a + z_b); with the sun and
/// the carrier given, the ring's ω_b = ω_H − (z_a/z_b)(ω_a − ω_H); with the carrier and the
/// ring given, the sun's ω_a = ω_H − (z_b/z_a)(ω_b − ω_H). Each equals Willis's relations
/// solved together to 1e-12 and the triangles to 1e-9.
#[test]
fn a_differential_by_willis_formula_for_each_output() {
    let (za, zg, zb) = (20_u32, 30_u32, 80_u32);
    let (fa, fb) = (f64::from(za), f64::from(zb));
    let wheels = [
        ("A", "a", za, false),
        ("S", "g", zg, false),
        ("R", "b", zb, true),
    ];
    let meshes = [("a", "g"), ("g", "b")];
    // (input, second input, output, ω of the second per unit ω_in, the output's ω by hand,
    // u_ab^(H) of the central shafts in the order input, second, output).
    let cases: [(&str, &str, &str, f64, f64, f64); 3] = [
        ("A", "R", "H", 0.2, (fa + fb * 0.2) / (fa + fb), -fb / fa),
        ("A", "H", "R", 0.36, 0.36 - fa / fb * (1.0 - 0.36), -fb / fa),
        (
            "H",
            "R",
            "A",
            0.25 / 0.36,
            1.0 - fb / fa * (0.25 / 0.36 - 1.0),
            -fa / fb,
        ),
    ];
    for (input, second, output, w2, expected, u_ab) in cases {
        let mut t = train(&wheels, &meshes, (input, output), None, Some("H"), &["S"]);
        let k = t.shafts.iter().position(|s| s == second).unwrap();
        t.second = Some((k, w2));
        let d = t.differential().unwrap();
        assert!((d.u - u_ab).abs() < 1e-12, "{}", d.u);
        let willis = t.willis().unwrap();
        assert!((willis[t.output] - expected).abs() < 1e-12, "{output}");
        let u = t.by_differential().unwrap();
        assert!((1.0 / u - expected).abs() < 1e-12, "{output}: {}", 1.0 / u);
        let tri = triangles::triangles(&t, 1.0, &ctx(0.0)).unwrap();
        assert!((tri.ratio - u).abs() < 1e-9 * u.abs(), "{output}");
    }
    // One input: no differential's formula.
    let t = train(&wheels, &meshes, ("A", "H"), Some("R"), Some("H"), &["S"]);
    assert!(t.differential().is_none() && t.by_differential().is_none());
}
