//! Tests of the gear studies: seed values (with the seeds' errata not reproduced), analytic
//! oracles and properties.

use super::generate::{generate, Generation};
use super::involute::{
    inv_inverse_newton, inv_inverse_with_tan, involute_point, origin_angle, thickness_at,
};
use super::mesh::meshing;
use super::*;
use crate::check::notes::GearsNote;
use crate::construct::{Context, Drafting, Role};
use crate::geom::{DVec2, Segment};
use crate::scale::{Quantity, Scale};
use proptest::prelude::*;
use std::f64::consts::FRAC_PI_2;

const GOST: BasicRack = BasicRack::GOST_13755;

fn pair(m_mm: f64, z: [u32; 2], x: [f64; 2]) -> GearPair {
    GearPair::new(PairSpec {
        module: m_mm * 1e-3,
        z,
        x,
        rack: GOST,
        dy_table: None,
    })
    .unwrap()
}

fn seed000() -> GearPair {
    pair(14.0, [13, 30], [0.8, 0.471])
}

/// PZ3's pair the textbook's way: Δy = 0.160 from Kudryavtsev's table A.
fn pz3() -> GearPair {
    GearPair::new(PairSpec {
        dy_table: Some(0.160),
        ..pair(10.0, [13, 21], [0.694, 0.384]).spec
    })
    .unwrap()
}

pub(super) fn ctx(d: f64) -> Context {
    Context::for_model_size(400.0, Drafting::new(d).unwrap()).unwrap()
}

fn mu(v: f64) -> Scale {
    Scale::new(v, Quantity::Length).unwrap()
}

#[test]
fn seed000_pair_geometry() {
    let p = seed000();
    assert!(
        (p.alpha_w.to_degrees() / 26.58075 - 1.0).abs() < 1e-6,
        "{}",
        p.alpha_w.to_degrees()
    );
    assert!((p.a_w * 1e3 - 316.276).abs() < 5e-4, "{}", p.a_w);
    assert!((p.eps - 1.1550).abs() <= 5e-4, "{}", p.eps);
    assert!((p.y - 1.09117).abs() < 1e-5 && (p.dy - 0.17983).abs() < 1e-5);
    assert!((p.rb[0] * 1e3 - 85.512).abs() < 1e-3 && (p.rb[1] * 1e3 - 197.335).abs() < 1e-3);
    assert!((p.rw[0] * 1e3 - 95.6185).abs() < 1e-3 && (p.rw[1] * 1e3 - 220.658).abs() < 1e-3);
    assert!((p.ra[0] * 1e3 - 113.682).abs() < 1e-3 && (p.ra[1] * 1e3 - 228.076).abs() < 1e-3);
    assert!((p.rf[0] * 1e3 - 84.700).abs() < 1e-9 && (p.rf[1] * 1e3 - 199.094).abs() < 1e-9);
    assert!((p.s[0] * 1e3 - 30.144).abs() < 1e-3 && (p.s[1] * 1e3 - 26.791).abs() < 1e-3);
    assert!((p.sa[0] * 1e3 - 5.444).abs() < 5e-3 && (p.sa[1] * 1e3 - 11.133).abs() < 5e-3);
    assert!((p.clearance[0] * 1e3 - 3.5).abs() < 1e-9 && (p.clearance[1] * 1e3 - 3.5).abs() < 1e-9);
    assert!((p.g * 1e3 - 141.52).abs() < 5e-3 && (p.ab * 1e3 - 47.737).abs() < 1e-2);
    // Seed 000's erratum: the base pitch πm·cos α_w gives 1.21–1.22, never the answer.
    let wrong = p.ab / (p.p * p.alpha_w.cos());
    assert!(wrong > 1.2 && (p.eps - wrong).abs() > 0.05);
    let [l1, l2] = p.sliding(p.active_ends()[0]);
    assert!(
        (l1 + 0.8239).abs() < 5e-4 && (l2 - 0.4517).abs() < 5e-4,
        "{l1} {l2}"
    );
    let [l1, l2] = p.sliding(p.active_ends()[1]);
    assert!(
        (l1 - 0.6146).abs() < 5e-4 && (l2 + 1.5949).abs() < 5e-4,
        "{l1} {l2}"
    );
    assert_eq!(p.sliding(p.pole()).map(|v| (v.abs() < 1e-12) as u8), [1, 1]);
}

#[test]
fn pz3_pair_geometry_and_its_errata() {
    let p = pz3();
    assert!((p.a_w * 1e3 - 179.18).abs() < 5e-3, "{}", p.a_w);
    assert!((p.eps - 1.1637).abs() < 5e-5, "{}", p.eps);
    assert!((p.alpha_w.to_degrees() - 26.9331).abs() < 1e-4);
    assert!((p.rw[0] * 1e3 - 68.51).abs() < 5e-3 && (p.rw[1] * 1e3 - 110.67).abs() < 5e-3);
    assert!((p.ab * 1e3 - 34.352).abs() < 1e-3 && (p.p_b * 1e3 - 29.521).abs() < 1e-3);
    assert!((p.sa[0] * 1e3 - 4.374).abs() < 1e-3 && (p.sa[1] * 1e3 - 7.458).abs() < 1e-3);
    assert!((p.clearance[0] * 1e3 - 2.503).abs() < 1e-3);
    assert!((p.dy_exact - 0.1597).abs() < 1e-4);
    // With the exact Δy the tips are 3 µm longer and ε_α = 1.1640.
    let exact = pair(10.0, [13, 21], [0.694, 0.384]);
    assert!((exact.eps - 1.1640).abs() < 5e-5 && (exact.clearance[0] * 1e3 - 2.5).abs() < 1e-9);
    // The printed 180.79, 1.14 and "p = 14.13" are never produced.
    assert!((p.a_w * 1e3 - 180.79).abs() > 1.0);
    assert!((p.eps - 1.14).abs() > 0.02);
    assert!((p.p * 1e3 - 14.13).abs() > 10.0);
    // The seed's printed values flag what the pair does not reproduce; without them, nothing.
    let printed = rows::PairSeed {
        eps_alpha: Some(1.14),
        cos_alpha_w: Some(0.8836),
        a_w: Some(0.18079),
        pitch: Some(0.01413),
        ..Default::default()
    };
    let notes = rows::pair_notes(&p, Some(&printed));
    assert!(
        notes.contains(&GearsNote::CosMisread {
            read: 0.8836,
            a_w_read: p.a * p.spec.rack.alpha.cos() / 0.8836,
            printed: Some(0.18079),
            cos: p.alpha_w.cos(),
            a_w: p.a_w,
        }) && notes.contains(&GearsNote::Pitch {
            printed: 0.01413,
            pitch: p.p,
        }) && notes.contains(&GearsNote::EpsNotReproduced {
            printed: 1.14,
            eps: p.eps,
        }),
        "{notes:?}"
    );
    assert!(!rows::pair_notes(&p, None).iter().any(erratum));
}

/// A note that flags a value the seed prints.
fn erratum(n: &GearsNote) -> bool {
    matches!(
        n,
        GearsNote::EpsFromWrongBase(_)
            | GearsNote::EpsNotReproduced { .. }
            | GearsNote::CosMisread { .. }
            | GearsNote::AwNotReproduced { .. }
            | GearsNote::Pitch { .. }
            | GearsNote::InvTable {
                printed: Some(_),
                ..
            }
    )
}

#[test]
fn a_pair_without_printed_values_gets_no_erratum() {
    // A student's own pair (z = 12/28, m = 6): no seed, no seed's erratum.
    let p = pair(6.0, [12, 28], [0.3, 0.0]);
    let notes = rows::pair_notes(&p, None);
    assert!(!notes.iter().any(erratum), "{notes:?}");
    // Seed 000's printed ε_α = 1.22 and α_w = 26°34′45″ against its pair: both flagged, the
    // ε_α traced to the base radius r·cos α_w.
    let s0 = seed000();
    let printed = rows::PairSeed {
        eps_alpha: Some(1.22),
        alpha_w: Some((26.0 + 34.0 / 60.0 + 45.0 / 3600.0_f64).to_radians()),
        ..Default::default()
    };
    let notes = rows::pair_notes(&s0, Some(&printed));
    assert!(
        notes
            .iter()
            .any(|n| matches!(n, GearsNote::EpsFromWrongBase(w) if w.printed == 1.22)),
        "{notes:?}"
    );
    // 6″ off the table's own reading.
    assert!(
        notes.iter().any(|n| matches!(n,
            GearsNote::InvTable { table, printed: Some(a), .. }
                if ((a - table).abs().to_degrees() * 3600.0).round() == 6.0)),
        "{notes:?}"
    );
    // A printed value the pair reproduces is not flagged.
    let right = rows::PairSeed {
        eps_alpha: Some((s0.eps * 100.0).round() / 100.0),
        ..Default::default()
    };
    assert!(!rows::pair_notes(&s0, Some(&right)).iter().any(erratum));
}

#[test]
fn x_min_for_z13_and_the_textbook_rule() {
    assert!((x_min(13, &GOST) - 0.2396).abs() < 5e-5);
    assert!((x_min_textbook(13) - 0.2353).abs() < 5e-5);
    // z_min = 2h_a*/sin²α = 17.1: a zero wheel of 18 teeth is not undercut, of 17 it is
    // (by a hair: the textbook rounds z_min to 17).
    assert!(!Cutting::alone(0.01, 18, 0.0, GOST).unwrap().undercut());
    assert!(Cutting::alone(0.01, 17, 0.0, GOST).unwrap().undercut());
    // The feasible range: s_a = 0.3m at its upper end.
    let hi = x_for_tip(13, &GOST, MIN_TIP).unwrap();
    let c = Cutting::alone(1.0, 13, hi, GOST).unwrap();
    assert!((c.sa() - 0.3).abs() < 1e-9 && hi > x_min(13, &GOST));
}

#[test]
fn a_wheel_of_few_teeth_cannot_be_cut() {
    // Seed 002 PZ2 example 1's z₃ = 4: undercut up to x = 0,766, pointed from a smaller x.
    let (least, pointed) = super::uncuttable(4, &GOST).expect("z = 4 is not cut");
    assert!(
        (least - 0.7660).abs() < 5e-5 && pointed < least,
        "{least} {pointed}"
    );
    // The closed-form pointing shift is the drawn wheel's: z = 13 as Cutting cuts it.
    let drawn = x_for_tip(13, &GOST, 0.0).unwrap();
    let closed = crate::gears::rack::pointed_alone(13.0, &GOST, (-1.0, 3.0));
    assert!((drawn - closed).abs() < 1e-9, "{drawn} {closed}");
    // Every wheel from 8 teeth is cut: some shift leaves it neither undercut nor pointed.
    for z in 8..40 {
        assert!(super::uncuttable(z, &GOST).is_none(), "z = {z}");
    }
}

#[test]
fn inverse_involute_round_trip_on_0_to_60_degrees() {
    for k in 0..6000 {
        let a = (k as f64 * 0.01).to_radians();
        let back = inv_inverse(inv(a)).unwrap();
        assert!((back - a).abs() <= 1e-13 * a.max(1e-2), "{a} {back}");
    }
    assert!(inv_inverse(-1e-3).is_err() && inv_inverse(f64::NAN).is_err());
    assert!((inv(20f64.to_radians()) - 0.014904).abs() < 1e-6);
}

/// The tangent carried through the last Newton step is tg α to two ulps, from the smallest
/// angles (the series' range) to 89.9999°, where the bracket's bisection takes over.
#[test]
fn inverse_involute_with_its_tangent() {
    for k in 1..=9000 {
        let a = (k as f64 * 0.01).to_radians().min(FRAC_PI_2 - 1e-6);
        let (back, t) = inv_inverse_with_tan(inv(a)).unwrap();
        let exact = back.tan();
        assert!(
            (t - exact).abs() <= 2.0 * f64::EPSILON * exact,
            "{a}: {t} vs {exact}"
        );
    }
    assert_eq!(inv_inverse_with_tan(0.0).unwrap(), (0.0, 0.0));
    assert!(inv_inverse_with_tan(f64::INFINITY).is_err());
}

#[test]
fn compass_involute_against_the_exact_one() {
    let rb = 50.0;
    let p = DVec2::new(0.0, 70.0);
    let mut last = f64::INFINITY;
    for parts in [4, 8, 16, 32] {
        let c = compass_involute(DVec2::ZERO, rb, p, parts, 0, true).unwrap();
        // The point laid off at T is P itself; the error comes from the chords only.
        assert!((c.points[parts as usize] - p).length() < 1e-12);
        assert!(c.arc_minus_chord > 0.0 && c.deviation > 0.0);
        // The origin is off by parts × (arc − chord) along the base circle, and that is
        // the largest deviation: the involutes of one base circle are equidistant.
        assert!((c.deviation - parts as f64 * c.arc_minus_chord).abs() < 1e-9 * rb);
        assert!(
            c.deviation < last / 3.5,
            "{parts}: {} vs {last}",
            c.deviation
        );
        last = c.deviation;
    }
    assert!(compass_involute(DVec2::ZERO, rb, DVec2::new(10.0, 0.0), 4, 0, true).is_err());
}

#[test]
fn meshing_picture_reads_the_contact_ratio() {
    for p in [seed000(), pz3()] {
        let exact = meshing(&p, mu(0.002), &ctx(0.0)).unwrap();
        assert!((exact.eps - p.eps).abs() < 1e-9, "{} {}", exact.eps, p.eps);
        assert!((exact.a_w.value - p.a_w).abs() < 1e-12 && (exact.g.value - p.g).abs() < 1e-12);
        let read = meshing(&p, mu(0.002), &ctx(0.5)).unwrap();
        // B₁B₂ read to 0.5 mm at μ = 0.002 m/mm: within 0.25 mm × μ / p_b.
        let bound = 0.25 * 0.002 / p.p_b;
        assert!(
            (read.eps - p.eps).abs() <= bound + 1e-12,
            "{} {}",
            read.eps,
            p.eps
        );
        assert_eq!(read.ab.read_mm % 0.5, 0.0);
        for s in &exact.lambda {
            let e = p.sliding(s.x);
            assert!((s.read[0] - e[0]).abs() < 1e-9 && (s.read[1] - e[1]).abs() < 1e-9);
        }
    }
}

#[test]
fn rack_generation_touches_the_exact_curves_including_the_junction() {
    for (z, x) in [(13, 0.0), (13, 0.8), (10, 0.0), (30, 0.471), (13, 0.25)] {
        let c = Cutting::alone(0.014, z, x, GOST).unwrap();
        let g = generate(&c, 90, mu(0.0005), &ctx(0.0)).unwrap();
        assert!(
            g.touch_error < 1e-9 * c.module,
            "{z} {x}: {}",
            g.touch_error
        );
        // The touching points next to the junction: on the same curves, to 1e-9·m.
        let (_, qi, qf) = c.junction();
        let near = g
            .touches
            .iter()
            .filter(|t| (t.q - qi).abs() < 0.05 * c.module || (t.q - qf).abs() < 0.05 * c.module);
        for t in near {
            let twin = match t.piece {
                RackPiece::Flank => c.involute_at(t.q),
                RackPiece::Fillet => c.trochoid_at(t.q),
                RackPiece::Root => c.root_at(t.q),
            };
            assert!((t.at - twin).length() < 1e-9 * c.module);
        }
        // The involute twin by the polar angle agrees with the one by the roll angle.
        let q = c.states().q_p;
        assert!((c.involute_at(q) - c.involute_at_radius(c.r())).length() < 1e-12);
        assert!((g.sa - c.sa()).abs() < 1e-9 * c.module);
        assert_eq!(g.undercut, c.undercut(), "{z} {x}");
    }
}

#[test]
fn undercut_is_detected_for_z13_x0_and_not_for_x08() {
    let zero = Cutting::alone(0.014, 13, 0.0, GOST).unwrap();
    let shifted = Cutting::alone(0.014, 13, 0.8, GOST).unwrap();
    assert!(zero.undercut() && !shifted.undercut());
    let g0 = generate(&zero, 120, mu(0.0005), &ctx(0.0)).unwrap();
    let g8 = generate(&shifted, 120, mu(0.0005), &ctx(0.0)).unwrap();
    assert!(g0.undercut && !g8.undercut);
    // The undercut is drawn: the material between the uncut outline (the involute to r_b,
    // the radial line under it) and the fillet hatched on both flanks, between the root
    // circle and the junction, inside that outline.
    let hatching = |g: &Generation| -> Vec<Segment> {
        g.figure
            .steps
            .iter()
            .filter(|s| s.role == Role::Hatch)
            .flat_map(|s| s.item.hatch_strokes())
            .collect()
    };
    let strokes = hatching(&g0);
    assert!(strokes.iter().any(|s| s.from.x > 0.0) && strokes.iter().any(|s| s.from.x < 0.0));
    let (rf_mm, j_mm) = (zero.rf() / 0.0005, zero.junction().0.length() / 0.0005);
    let base = zero.involute_at(zero.states().q_p - zero.r() * GOST.alpha.tan());
    assert!((base.length() - zero.rb()).abs() < 1e-12);
    let edge = base.x.atan2(base.y);
    for s in &strokes {
        for p in [s.from, s.to] {
            assert!(
                p.length() > rf_mm && p.length() < j_mm + 0.01,
                "{p} {rf_mm} {j_mm}"
            );
            assert!(p.x.abs().atan2(p.y) < edge + 1e-4, "{p}");
        }
    }
    assert!(hatching(&g8).is_empty());
    // The drawn junction: the crossing of the drawn fillet and involute, pinned by setting
    // the rack between the crossing steps, is the exact intersection of involute and
    // trochoid to 1e-8·m (a peer generator misses it by 0.0076·m); the two curves cross at
    // a shallow angle, so rounding, not the method, sets that bound.
    let j = zero.junction().0;
    for n in [48, 60, 90, 120, 720] {
        let g = generate(&zero, n, mu(0.0005), &ctx(0.0)).unwrap();
        assert!(g.undercut, "{n}");
        assert!(
            (g.junction - j).length() < 1e-8 * zero.module,
            "{n}: {:?} {j:?}",
            g.junction
        );
    }
    // The exact junction lies on both curves.
    let o = origin_angle(DVec2::ZERO, zero.rb(), j, true).unwrap();
    assert!(crate::geom::wrap_pi(o - zero.theta0()).abs() < 1e-12);
    // x = 0.8 alone is pointed (s_a < 0.3m): the pair's Δy shortening saves seed 000's pinion.
    assert!(g8.pointed && !g0.pointed);
    assert!(seed000().sa[0] > MIN_TIP * 0.014);
}

/// The drawn tooth — the French curve touching the envelope at every touching point — falls
/// at least as N⁻² from the exact envelope (straight pieces would fall as N⁻²; the curve's
/// cubic pieces fall faster until their sub-chords show), and at N = 180 it is within
/// 1e-8·m over the course's range of shifts: the fillet traced at equal steps of its angle,
/// where equal rack steps left a wheel shifted far out 3.8e-5·m off near the root (x = 0.8,
/// whose fillet is a twentieth of the span; issue 49).
#[test]
fn envelope_deviation_falls_at_least_as_n_squared() {
    for x in [-0.5, 0.0, 0.5, 0.8] {
        let c = Cutting::alone(0.014, 13, x, GOST).unwrap();
        let d = |n| generate(&c, n, mu(0.0005), &ctx(0.0)).unwrap().deviation;
        let (a, b) = (d(45), d(180));
        let order = (a / b).ln() / 4f64.ln();
        assert!(order >= 1.9, "x = {x}: order {order}: {a} {b}");
        assert!(b <= 1e-8 * c.module, "x = {x}: {b} m at N = 180");
    }
}

#[test]
fn refusals_name_what_is_wrong() {
    let spec = |x: [f64; 2]| PairSpec {
        module: 0.01,
        z: [13, 21],
        x,
        rack: GOST,
        dy_table: None,
    };
    // Zero shifts on 13 teeth: the pinion's tip digs past N.
    let e = GearPair::working(spec([0.0, 0.0])).unwrap_err();
    assert!(matches!(e, GearError::Interference { wheel: 2, .. }), "{e}");
    assert!(matches!(
        GearPair::new(spec([-0.5, -0.5])),
        Err(GearError::InvoluteDomain { .. })
    ));
    let e = GearPair::working(spec([1.6, 0.0])).unwrap_err();
    assert!(matches!(e, GearError::Pointed { wheel: 1, .. }), "{e}");
    assert!(GearPair::working(spec([0.694, 0.384])).is_ok());
    let e = spec([0.5, 0.0]).x2_for_centre_distance(0.150).unwrap_err();
    assert!(matches!(e, GearError::CentreDistance { .. }));
    let x2 = spec([0.694, 0.0])
        .x2_for_centre_distance(pz3().a_w)
        .unwrap();
    assert!((x2 - 0.384).abs() < 1e-9);
    assert!(Cutting::alone(0.01, 13, 0.0, BasicRack { rho: 0.6, ..GOST }).is_err());
}

#[test]
fn thickness_on_the_pitch_circle_is_s() {
    let (s, r, a) = (0.02, 0.065, 20f64.to_radians());
    assert!((thickness_at(s, r, a, r) - s).abs() < 1e-15);
    // The exact involute through its origin: roll 0 is on the base circle.
    let p = involute_point(DVec2::ZERO, 1.0, 0.3, 0.0, true);
    assert!((p.length() - 1.0).abs() < 1e-15);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn contact_ratio_from_the_picture_equals_the_formula(
        z1 in 12u32..40, dz in 0u32..60, x1 in 0.0f64..0.8, x2 in -0.3f64..0.8, m in 2.0f64..20.0
    ) {
        let spec = PairSpec { module: m * 1e-3, z: [z1, z1 + dz], x: [x1, x2], rack: GOST, dy_table: None };
        if let Ok(p) = GearPair::working(spec) {
            let scale = Scale::round_for(p.a_w + p.ra[0] + p.ra[1], 360.0, Quantity::Length).unwrap();
            let mesh = meshing(&p, scale, &ctx(0.0)).unwrap();
            prop_assert!((mesh.eps - p.eps).abs() < 1e-9);
            prop_assert!((p.eps - p.eps_formula).abs() < 1e-9);
            prop_assert!((p.a_w - p.a_w_base).abs() < 1e-12);
            prop_assert!((p.alpha_w - inv_inverse_newton(p.inv_w).unwrap()).abs() < 1e-12);
        }
    }
}

#[test]
fn the_teeth_of_the_meshing_picture_touch_at_p_between_their_circles() {
    use crate::construct::Item;
    for p in [pz3(), seed000()] {
        let scale = 0.001;
        let m = meshing(&p, mu(scale), &ctx(0.0)).unwrap();
        let pole = DVec2::new(0.0, p.rw[0] / scale);
        let mut seen = 0;
        for s in &m.figure.steps {
            let Item::Polyline { points, .. } = &s.item else {
                continue;
            };
            if !s.note.starts_with("three teeth") {
                continue;
            }
            let i = usize::from(s.note.ends_with('2'));
            let c = DVec2::new(0.0, if i == 1 { p.a_w / scale } else { 0.0 });
            for q in points {
                let rho = (*q - c).length() * scale;
                assert!(
                    rho > p.rf[i] * (1.0 - 1e-9) && rho < p.ra[i] * (1.0 + 1e-9),
                    "{rho}"
                );
            }
            // The flank through P: the drawn outline passes P to its sampling (12 points a piece).
            let d = points
                .windows(2)
                .map(|w| {
                    let dd = w[1] - w[0];
                    let t = ((pole - w[0]).dot(dd) / dd.length_squared()).clamp(0.0, 1.0);
                    (pole - (w[0] + dd * t)).length()
                })
                .fold(f64::MAX, f64::min);
            assert!(d < 0.02, "wheel {}: {d} mm from P", i + 1);
            seen += 1;
        }
        assert_eq!(seen, 2);
    }
}

#[test]
fn the_inv_table_route_reads_alpha_w_to_its_resolution() {
    use super::involute::{alpha_by_table, dms, inv};
    // Seed 000: inv α_w = 0.036421 → 26°34′51″ from the table (exact 26°34′50.7″); the seed
    // prints 26°34′45″, six seconds off its own table, and that is not produced.
    let p = seed000();
    let table = alpha_by_table(p.inv_w).unwrap();
    assert_eq!(dms(table, 0), "26°34′51″");
    assert_eq!(dms(p.alpha_w, 1), "26°34′50.7″");
    assert_ne!(dms(table, 0), "26°34′45″");
    // The table's resolution: a row's rounding (5e-7) over its step (tan²α per radian) and
    // the second's rounding; within 1″ from 20° up.
    for k in 0..400 {
        let a = (20.0 + 40.0 * f64::from(k) / 400.0).to_radians();
        let read = alpha_by_table(inv(a)).unwrap();
        assert!(
            (read - a).abs() < (1.0 / 3600.0_f64).to_radians(),
            "{}",
            a.to_degrees()
        );
    }
    assert!(alpha_by_table(-1e-3).is_none() && alpha_by_table(10.0).is_none());
}

#[test]
fn the_tables_delta_y_reproduces_the_seeds_rounded_numbers() {
    // Seed 000 takes Δy = 0.18 from the tables: y = 1.091, a_w = 316.274 mm, r_a = 113.68 and
    // 228.074 mm (exact: Δy = 0.17983, a_w = 316.276, r_a = 113.682, 228.076).
    let p = GearPair::new(PairSpec {
        dy_table: Some(0.18),
        ..seed000().spec
    })
    .unwrap();
    assert!((super::rows::table_a_w(&p) * 1e3 - 316.274).abs() < 1e-9);
    assert!((p.ra[0] * 1e3 - 113.68).abs() < 1e-9 && (p.ra[1] * 1e3 - 228.074).abs() < 1e-9);
    assert!(
        (p.a_w * 1e3 - 316.2764).abs() < 1e-4,
        "the centre distance stays exact"
    );
    assert!(super::rows::pair_notes(&p, None).iter().any(|n| matches!(n,
        GearsNote::Tables { a_w, .. } if (a_w * 1e3 - 316.274).abs() < 5e-4)));
}
