use super::*;
use crate::check::notes::balancing::{BalancingNote, Inertia};
use crate::check::{Row, Symbol};
use crate::construct::{Context, Drafting};
use proptest::prelude::*;

fn ctx(drafting: f64) -> Context {
    let d = Drafting::new(drafting).expect("a drafting model");
    Context::for_model_size(300.0, d).expect("a context")
}

fn mass(mass: f64, radius: f64, deg: f64, z: f64) -> Mass {
    Mass {
        mass,
        radius,
        angle: deg.to_radians(),
        z,
    }
}

fn spec(masses: Vec<Mass>, correction: Correction, omega: Option<f64>) -> BalancingSpec {
    BalancingSpec {
        masses,
        correction,
        omega,
        scale_mr: None,
        scale_mrz: None,
        scale_l: None,
    }
}

/// Three masses of a thin disc (W4's ball among them), corrected at ρ_у = 0,1 m.
fn disc() -> BalancingSpec {
    spec(
        vec![
            mass(0.1, 0.1, 0.0, 0.0),
            mass(0.2, 0.05, 90.0, 0.0),
            mass(0.05, 0.12, 210.0, 0.0),
        ],
        Correction::Static { radius: 0.1 },
        Some(300.0),
    )
}

/// Three masses in three planes of a long rotor, corrected in planes I (z = 0) and II (0,4 m).
fn long_rotor() -> BalancingSpec {
    spec(
        vec![
            mass(0.2, 0.08, 30.0, 0.1),
            mass(0.15, 0.1, 150.0, 0.2),
            mass(0.1, 0.09, 270.0, 0.32),
        ],
        Correction::Dynamic {
            planes: [0.0, 0.4],
            radii: [0.1, 0.1],
        },
        Some(100.0),
    )
}

fn find<'a>(rows: &'a [Row], symbol: Symbol, subject: &str) -> &'a Row {
    rows.iter()
        .find(|r| r.key.symbol == symbol && r.key.subject == subject)
        .unwrap_or_else(|| panic!("no row {symbol:?} {subject}"))
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs().max(1e-300)
}

#[test]
fn static_twin_matches_the_hand_sum() {
    // Σ mρ = (0,01 + 0,006·cos 210°, 0,01 + 0,006·sin 210°) = (0,01 − 0,003√3, 0,007).
    let (sx, sy) = (0.01 - 0.003 * 3f64.sqrt(), 0.01 - 0.003);
    let u = analytic(&disc());
    assert_eq!(u.len(), 1);
    let m_y = (sx * sx + sy * sy).sqrt() / 0.1;
    assert!(close(u[0].mass(), m_y, 1e-12), "{} vs {m_y}", u[0].mass());
    assert!(close(u[0].mass(), 0.084_898, 1e-4));
    let angle = (-sy).atan2(-sx) + std::f64::consts::TAU;
    assert!(close(u[0].angle().expect("a direction"), angle, 1e-12));
    assert!((u[0].angle().expect("a direction").to_degrees() - 235.54).abs() < 0.01);
}

#[test]
fn dynamic_twin_matches_a_hand_couple() {
    // A couple: 0,01 kg·m at 0° in z = 0,1 m and at 180° in z = 0,3 m; the main vector is 0,
    // the moment about plane I is −0,002 x̂ kg·m², so U_II = 0,005 x̂ and U_I = −0,005 x̂.
    let s = spec(
        vec![mass(0.1, 0.1, 0.0, 0.1), mass(0.1, 0.1, 180.0, 0.3)],
        Correction::Dynamic {
            planes: [0.0, 0.4],
            radii: [0.05, 0.1],
        },
        None,
    );
    let u = analytic(&s);
    assert!((u[1].unbalance - DVec2::new(0.005, 0.0)).length() < 1e-15);
    assert!((u[0].unbalance - DVec2::new(-0.005, 0.0)).length() < 1e-15);
    assert!(close(u[0].mass(), 0.1, 1e-12) && close(u[1].mass(), 0.05, 1e-12));
    assert!(crate::geom::wrap_pi(u[1].angle().expect("a direction")).abs() < 1e-12);
    assert!(close(
        u[0].angle().expect("a direction"),
        std::f64::consts::PI,
        1e-12
    ));
}

#[test]
fn w4_ball_inertia_force_is_900_n_and_917_times_its_weight() {
    let (ball, omega) = W4;
    let p = inertia_force(&ball, omega);
    assert!(close(p, 900.0, 1e-12), "{p}");
    let ratio = p / (ball.mass * crate::scale::G);
    assert!((ratio - 917.43).abs() < 0.01, "{ratio}");
    assert!((ratio - 900.0).abs() > 10.0);
    // One note for the ball, then the erratum of its text, with the same numbers.
    let notes = inertia_notes(&[ball], omega);
    let BalancingNote::Inertia(m) = &notes[0] else {
        panic!("{notes:?}");
    };
    assert!(close(m.force, 900.0, 1e-12) && close(m.force / m.weight, ratio, 1e-15));
    assert_eq!(notes[1], w4_erratum());
    assert!(
        matches!(w4_erratum(), BalancingNote::W4Erratum(Inertia { force, .. }) if force == m.force)
    );
}

#[test]
fn polygons_close_at_drafting_zero() {
    for s in [disc(), long_rotor()] {
        let b = balance(&s, &ctx(0.0)).expect("balanced");
        let sum = main_vector(&s.masses);
        let scale: f64 = s.masses.iter().map(|m| m.mass * m.radius).sum();
        for (g, a) in b.graphical.iter().zip(&b.analytic) {
            let a = b.analytic.iter().find(|x| x.plane == g.plane).unwrap_or(a);
            assert!((g.unbalance - a.unbalance).length() <= 1e-12 * scale);
        }
        // The closing vector and the sum close the polygon of static moments.
        let closing: DVec2 = b.graphical.iter().map(|c| c.unbalance).sum();
        assert!(
            (closing + sum).length() <= 1e-12 * scale,
            "{:?}",
            closing + sum
        );
        for r in b.rows() {
            let err = r.abs_error();
            assert!(err <= 1e-12 * r.scale.max(r.analytic.abs()), "{r:?}");
        }
    }
}

#[test]
fn the_corrected_rotor_has_no_main_vector_and_no_main_moment() {
    let s = long_rotor();
    let b = balance(&s, &ctx(0.0)).expect("balanced");
    let scale: f64 = s.masses.iter().map(|m| m.mass * m.radius).sum();
    for c in [&b.analytic, &b.graphical] {
        assert!(residual_vector(&s.masses, c).length() <= 1e-12 * scale);
        // About any plane, since the main vector is zero.
        for z0 in [0.0, 0.17, 0.4, -1.0] {
            assert!(residual_moment(&s.masses, c, z0).length() <= 1e-12 * scale);
        }
    }
    let rows = b.rows();
    let before = find(&rows, Symbol::Force, "in");
    assert!(close(
        before.analytic,
        1e4 * main_vector(&s.masses).length(),
        1e-12
    ));
    for (sym, subject) in [(Symbol::Force, "res"), (Symbol::Moment, "res")] {
        let r = find(&rows, sym, subject);
        assert!(crate::check::is_zero(r.analytic, r.scale), "{r:?}");
        assert!(crate::check::is_zero(r.graphical, r.scale), "{r:?}");
    }
}

#[test]
fn drafting_half_a_millimetre_gives_a_percent_level_error() {
    for s in [disc(), long_rotor()] {
        let b = balance(&s, &ctx(0.5)).expect("balanced");
        let rows = b.rows();
        let mass_rows: Vec<&Row> = rows
            .iter()
            .filter(|r| r.key.symbol == Symbol::Mass)
            .collect();
        assert!(!mass_rows.is_empty());
        let worst = mass_rows
            .iter()
            .map(|r| r.rel_error(r.scale).expect("a nonzero mass").abs())
            .fold(0.0, f64::max);
        assert!(worst > 1e-6 && worst < 0.05, "{worst}");
        // The residual of the hand construction is not zero, but small beside the unbalance.
        let res = find(&rows, Symbol::Force, "res");
        let before = find(&rows, Symbol::Force, "in");
        assert!(res.graphical > 0.0 && res.graphical < 0.05 * before.analytic);
    }
}

#[test]
fn a_balanced_disc_needs_no_correction_and_does_not_fail() {
    let s = spec(
        vec![mass(0.1, 0.1, 0.0, 0.0), mass(0.1, 0.1, 180.0, 0.0)],
        Correction::Static { radius: 0.1 },
        None,
    );
    let b = balance(&s, &ctx(0.5)).expect("balanced");
    let rows = b.rows();
    assert!(find(&rows, Symbol::Mass, "y").graphical.abs() < 1e-9);
    assert!(rows.iter().all(|r| r.key.symbol != Symbol::Angle));
    assert!(
        b.notes()
            .contains(&BalancingNote::NoCorrection { plane: "y".into() }),
        "{:?}",
        b.notes()
    );
}

#[test]
fn masses_in_plane_one_give_an_empty_polygon_of_moments() {
    let s = spec(
        vec![mass(0.1, 0.1, 0.0, 0.0), mass(0.2, 0.1, 120.0, 0.0)],
        Correction::Dynamic {
            planes: [0.0, 0.3],
            radii: [0.1, 0.1],
        },
        Some(10.0),
    );
    let b = balance(&s, &ctx(0.0)).expect("balanced");
    let u = analytic(&s);
    assert!(u[1].unbalance.length() < 1e-15);
    let rows = b.rows();
    assert!(close(
        find(&rows, Symbol::Mass, "I").graphical,
        u[0].mass(),
        1e-12
    ));
    assert!(b
        .rows()
        .iter()
        .all(|r| r.analytic.is_finite() && r.graphical.is_finite()));
}

#[test]
fn no_masses_is_an_error() {
    let s = spec(Vec::new(), Correction::Static { radius: 0.1 }, None);
    assert_eq!(balance(&s, &ctx(0.0)), Err(BalancingError::NoMasses));
}

#[test]
fn polygon_scale_is_round_and_draws_the_polygon_at_most_120_mm() {
    let b = balance(&disc(), &ctx(0.0)).expect("balanced");
    let (lo, hi) = b.statics.bounds().expect("drawn");
    let size = (hi - lo).max_element();
    assert!((48.0..=120.0 + 1e-9).contains(&size), "{size}");
    assert_eq!(b.scale_mr.value(), 0.0001);
    let labels: Vec<String> = b
        .statics
        .steps
        .iter()
        .filter_map(|s| s.label.as_ref().map(|l| l.text.clone()))
        .collect();
    assert_eq!(
        labels,
        ["m_{1}ρ_{1}", "m_{2}ρ_{2}", "m_{3}ρ_{3}", "m_{у}ρ_{у}"]
    );
}

prop_compose! {
    fn any_mass()(m in 0.01f64..5.0, r in 0.01f64..0.5, deg in -360.0f64..360.0, z in -0.5f64..1.5)
        -> Mass { mass(m, r, deg, z) }
}

proptest! {
    #[test]
    fn random_rotors_are_balanced_by_both_constructions(
        masses in prop::collection::vec(any_mass(), 1..6),
        z1 in -0.2f64..0.2,
        len in 0.1f64..1.0,
    ) {
        let planes = [z1, z1 + len];
        let scale: f64 = masses.iter().map(|m| m.mass * m.radius).sum();
        let moment_scale = scale * (2.0 + len + masses.iter().map(|m| m.z.abs()).fold(0.0, f64::max));
        let s = spec(masses, Correction::Dynamic { planes, radii: [0.1, 0.2] }, Some(50.0));
        let b = balance(&s, &ctx(0.0)).expect("balanced");
        for c in [&b.analytic, &b.graphical] {
            prop_assert!(residual_vector(&s.masses, c).length() <= 1e-12 * scale);
            prop_assert!(residual_moment(&s.masses, c, planes[0]).length() <= 1e-12 * moment_scale);
        }
        let st = BalancingSpec { correction: Correction::Static { radius: 0.1 }, ..s.clone() };
        let b = balance(&st, &ctx(0.0)).expect("balanced");
        prop_assert!(residual_vector(&st.masses, &b.graphical).length() <= 1e-12 * scale);
    }
}
