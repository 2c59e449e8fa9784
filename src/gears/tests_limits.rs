//! Tests of the gear domain's limits (issue 17): the exact involute–fillet junction at small
//! profile angles, a tip circle below the base circle, the diagnoses of a singular train,
//! the drafting that leaves nothing of the plan of angular velocities.

use super::*;
use crate::construct::{Context, Drafting};
use crate::geom::DVec2;

fn rack(alpha_deg: f64) -> BasicRack {
    BasicRack {
        alpha: alpha_deg.to_radians(),
        ..BasicRack::GOST_13755
    }
}

/// The polar angle of a point measured from +y (the tooth's axis), positive to the right.
fn off_axis(p: DVec2) -> f64 {
    p.x.atan2(p.y)
}

/// Independently of [`Cutting::junction`]: every crossing of the fillet with the involute
/// between the base and the tip circles, by dense sampling of the fillet's states from the
/// root out, comparing its polar angle with the involute's at the same radius: the radii of
/// the two samples that bracket each.
fn crossings(c: &Cutting) -> Vec<(f64, f64)> {
    let st = c.states();
    let (rb, ra) = (c.rb(), c.ra);
    let n = 200_000;
    let side = |q: f64| -> Option<f64> {
        let p = c.trochoid_at(q);
        let r = p.length();
        (r > rb && r < ra).then(|| off_axis(p) - off_axis(c.involute_at_radius(r)))
    };
    let mut out = Vec::new();
    let mut prev: Option<(f64, f64)> = None;
    for i in 0..=n {
        // From the root (q_bottom) toward the flank's end (q_j).
        let q = st.q_bottom + (st.q_j - st.q_bottom) * f64::from(i) / f64::from(n);
        match side(q) {
            Some(v) => {
                if let Some((q0, v0)) = prev {
                    if (v0 < 0.0) != (v < 0.0) {
                        let r0 = c.trochoid_at(q0).length();
                        let r1 = c.trochoid_at(q).length();
                        out.push((r0.min(r1), r0.max(r1)));
                    }
                }
                prev = Some((q, v));
            }
            None => prev = None,
        }
    }
    out
}

#[test]
fn the_junction_at_small_profile_angles_lies_on_the_tooth() {
    for alpha in [1.0, 2.0, 3.0, 5.0, 20.0] {
        for z in [8, 13, 30] {
            let c = Cutting::alone(0.01, z, 0.0, rack(alpha)).unwrap();
            // Without undercut the junction is the flank's end, tangential (no crossing).
            let undercut = c.undercut();
            assert_eq!(undercut, alpha < 20.0 || z < 17, "α = {alpha}, z = {z}");
            let (p, qi, _) = c.junction();
            let r = p.length();
            // Between the base and the tip circles (was 711.6 mm for α = 1°, z = 13, m = 10:
            // r_a = 75 mm).
            assert!(
                r > c.rb() && r < c.ra,
                "α = {alpha}, z = {z}: r = {r}, r_b = {}, r_a = {}",
                c.rb(),
                c.ra
            );
            // On the involute (at its own state) and at the dense scan's crossing.
            assert!((c.involute_at(qi) - p).length() < 1e-9 * c.module);
            assert!((c.involute_at_radius(r) - p).length() < 1e-9 * c.module);
            if !undercut {
                assert!((qi - c.states().q_j).abs() < 1e-15);
                continue;
            }
            let found = crossings(&c);
            assert!(
                found
                    .iter()
                    .any(|(lo, hi)| (lo - 1e-12 * c.module..=hi + 1e-12 * c.module).contains(&r)),
                "α = {alpha}, z = {z}: r = {r}, the dense scan's crossings {found:?}"
            );
        }
    }
}

#[test]
fn the_drawn_junction_meets_the_exact_one_at_one_degree() {
    let ctx = Context::for_model_size(400.0, Drafting::new(0.0).unwrap()).unwrap();
    // ρ_f* = 0 (a sharp tool corner) and ГОСТ's 0.38, where the fillet crosses the involute
    // at a very shallow angle and the drawing's halving pins it less closely.
    for (rho, within, r_mm) in [(0.0, 1e-12, 68.9905), (0.38, 1e-4, 67.8763)] {
        let c = Cutting::alone(0.01, 13, 0.0, BasicRack { rho, ..rack(1.0) }).unwrap();
        let g = generate::generate(&c, 90, generation_scale(&c).unwrap(), &ctx).unwrap();
        let exact = c.junction().0;
        // Was 78.1·m and 40.8·m apart (the exact root six pitch radii out).
        assert!(
            (g.junction - exact).length() < within * c.module,
            "ρ = {rho}: {} {}",
            g.junction,
            exact
        );
        assert!(
            (exact.length() * 1e3 - r_mm).abs() < 1e-4,
            "{}",
            exact.length()
        );
    }
}

#[test]
fn a_delta_y_that_puts_the_tip_inside_the_base_circle_is_named_so() {
    let spec = PairSpec {
        module: 0.014,
        z: [13, 30],
        x: [0.8, 0.471],
        rack: BasicRack::GOST_13755,
        dy_table: Some(2.5),
    };
    let p = GearPair::new(spec).unwrap();
    assert!(p.ra[0] < p.rb[0]);
    match GearPair::working(spec) {
        Err(GearError::TipInsideBase {
            wheel: 1,
            ra_mm,
            rb_mm,
        }) => {
            assert!((ra_mm - p.ra[0] * 1e3).abs() < 1e-9 && (rb_mm - p.rb[0] * 1e3).abs() < 1e-9);
            // r_a1 = r₁ + (h_a* + x₁ − Δy)m = 91 + (1 + 0.8 − 2.5)·14 = 81.2 mm.
            assert!((ra_mm - 81.2).abs() < 1e-9, "{ra_mm}");
        }
        other => panic!("{other:?}"),
    }
    // The seed's Δy = 0.18 gives ε_α = 1.1550 (the exact Δy 1.15524).
    let seed = GearPair::working(PairSpec {
        dy_table: Some(0.18),
        ..spec
    })
    .unwrap();
    assert!((seed.eps - 1.1550).abs() < 5e-5, "{}", seed.eps);
    let exact = GearPair::working(PairSpec {
        dy_table: None,
        ..spec
    })
    .unwrap();
    assert!((exact.eps - 1.15524).abs() < 5e-6, "{}", exact.eps);
}

#[test]
fn the_largest_rounding_of_the_tool_tooth_is_where_it_stops_fitting() {
    for alpha in [1.0, 10.0, 20.0, 25.0, 30.0] {
        let r = rack(alpha);
        let max = r.rho_max();
        assert!(max > 0.0);
        let with = |rho: f64| BasicRack { rho, ..r }.validate();
        assert!(with(max * (1.0 - 1e-9)).is_ok(), "α = {alpha}");
        assert!(with(max * (1.0 + 1e-9)).is_err(), "α = {alpha}");
    }
    // ГОСТ's 0.38 at α = 25° does not fit: ρ_f* ≤ 0.3179.
    let e = rack(25.0).validate().unwrap_err().to_string();
    assert!(e.contains("rho_f") && e.contains("0.3179"), "{e}");
}

fn wheel(name: &str, z: f64, shaft: usize) -> train::Wheel {
    train::Wheel {
        name: name.into(),
        z,
        shaft,
        internal: false,
        module: None,
    }
}

/// A train on fixed axes (no carrier) of module 1 mm: `shafts`, `wheels` on them, `meshes`,
/// `(input, output)` wheels and the `fixed` shaft.
fn fixed_axes(
    shafts: &[&str],
    wheels: Vec<train::Wheel>,
    meshes: Vec<Mesh>,
    (input, output): (usize, usize),
    fixed: Option<usize>,
) -> Train {
    Train {
        shafts: shafts.iter().map(|s| s.to_string()).collect(),
        wheels,
        meshes,
        input,
        output,
        fixed,
        carrier: None,
        satellites: vec![],
        module: 0.001,
        second: None,
    }
}

#[test]
fn a_locked_input_and_free_links_are_told_apart() {
    // 1–2, 2'–3 with 3 fixed: 2 and then 1 are held at rest; 4 meshes nothing.
    let locked = fixed_axes(
        &["1", "2", "3", "4"],
        vec![
            wheel("1", 20.0, 0),
            wheel("2", 40.0, 1),
            wheel("2'", 20.0, 1),
            wheel("3", 30.0, 2),
        ],
        vec![Mesh(0, 1), Mesh(2, 3)],
        (0, 3),
        Some(2),
    );
    match locked.willis() {
        Err(TrainError::InputLocked { input, moving }) => {
            assert_eq!(input, "1");
            assert_eq!(moving, vec!["4".to_string()]);
        }
        other => panic!("{other:?}"),
    }
    // 1–2 twice at the same ratio (a dependent relation); 3–4 mesh apart from them.
    let free = fixed_axes(
        &["1", "2", "3", "4"],
        vec![
            wheel("1", 20.0, 0),
            wheel("2", 40.0, 1),
            wheel("1'", 30.0, 0),
            wheel("2'", 60.0, 1),
            wheel("3", 20.0, 2),
            wheel("4", 25.0, 3),
        ],
        vec![Mesh(0, 1), Mesh(2, 3), Mesh(4, 5)],
        (0, 1),
        None,
    );
    match free.willis() {
        Err(TrainError::Free(shafts)) => assert_eq!(shafts, vec!["3", "4"]),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_drafting_that_reads_the_output_as_zero_is_named() {
    // 1 (z = 20) into 2 (z = 80): ω₂ = ω₁/4.
    let t = fixed_axes(
        &["1", "2"],
        vec![wheel("1", 20.0, 0), wheel("2", 80.0, 1)],
        vec![Mesh(0, 1)],
        (0, 1),
        None,
    );
    let at = |d: f64| {
        let ctx = Context::for_model_size(400.0, Drafting::new(d).unwrap()).unwrap();
        crate::gears::triangles::triangles(&t, 1.0, &ctx)
    };
    let exact = at(0.0).unwrap();
    assert!((exact.ratio + 4.0).abs() < 1e-9, "{}", exact.ratio);
    match at(1000.0) {
        Err(e @ TrainError::Unreadable { .. }) => {
            let TrainError::Unreadable {
                drawn_mm,
                resolution_mm,
                ..
            } = &e
            else {
                unreachable!()
            };
            assert_eq!(*resolution_mm, 1000.0);
            // Just below twice the smallest intercept the plan is read; just above, not.
            let limit = 2.0 * drawn_mm;
            assert!(at(limit * 0.999).is_ok());
            assert!(at(limit * 1.001).is_err());
            assert!(e.to_string().contains("--drafting 1000 mm"), "{e}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_generation_far_larger_or_smaller_than_a_sheet_neither_panics_nor_runs_away() {
    use crate::scale::{Quantity, Scale};
    let c = Cutting::alone(0.01, 13, 0.0, BasicRack::GOST_13755).unwrap();
    let ctx = Context::for_model_size(400.0, Drafting::new(0.0).unwrap()).unwrap();
    let at = |mu: f64| generate::generate(&c, 90, Scale::new(mu, Quantity::Length).unwrap(), &ctx);
    // μ_l = 1e-10: a 1.3e9 mm tooth; its undercut's hatching is refused before it is drawn
    // (it took 24 GB).
    match at(1e-10) {
        Err(e @ GearError::UndercutHatching(_)) => {
            assert!(e.to_string().contains("the undercut's hatching"), "{e}");
        }
        other => panic!("{:?}", other.map(|g| g.junction)),
    }
    // μ_l = 1e300: lyon's hatcher unwrapped `None` on the collapsed outline.
    assert!(at(1e300).is_ok());
}
