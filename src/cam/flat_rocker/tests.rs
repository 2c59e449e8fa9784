//! The flat-faced rocker's two routes against each other and their refusals.

use super::*;
use crate::cam::tests::seed000;
use crate::cam::{Law, Phases};
use crate::construct::Drafting;
use crate::scale::Quantity;

/// A rocker of arm 100 mm swinging 20° by the cosine law, rise and return over 120°.
fn spec(n: usize) -> CamSpec {
    CamSpec {
        phases: Phases {
            rise: 120f64.to_radians(),
            far: 30f64.to_radians(),
            ret: 120f64.to_radians(),
            near: 90f64.to_radians(),
        },
        rise: Law::Cosine,
        ret: Law::Cosine,
        stroke: 0.1 * 20f64.to_radians(),
        follower: Follower::Rocker {
            arm: 0.1,
            sense: RockerSense::Same,
        },
        divisions: n,
        ..seed000()
    }
}

const FRAME: FlatRocker = FlatRocker {
    centres: 0.12,
    face_offset: 0.0,
    base: 0.04,
};

fn board(s: &CamSpec, r: &FlatRocker) -> Result<RockerConstruction, FlatRockerError> {
    let ctx = Context::for_model_size(300.0, Drafting::EXACT).expect("a context");
    let mu = Scale::new(0.0005, Quantity::Length).expect("a μ");
    construct(s, r, mu, &ctx)
}

/// The largest distance of the drawn contacts from the exact ones, m: within the
/// phases, and at their ends (where the cosine law's S″ jumps, so does ρ: the middle of
/// the crossings is off by (ρ₊ − ρ₋)·δ/4 there, first order).
fn deviation(s: &CamSpec, r: &FlatRocker) -> (f64, f64) {
    let b = board(s, r).expect("the construction");
    let mut worst = (0.0_f64, 0.0_f64);
    for (p, c) in points(s).iter().zip(&b.contacts) {
        let e = exact(s, r, p.phi, p.after).expect("the envelope");
        let d = c.point.distance(e.point);
        if p.k == 0 || p.last {
            worst.1 = worst.1.max(d);
        } else {
            worst.0 = worst.0.max(d);
        }
    }
    worst
}

#[test]
fn the_exact_profile_touches_every_face_line_and_turns_by_its_radius() {
    let s = spec(12);
    let (arm, sigma, psi0) = frame(&s, &FRAME).unwrap();
    for k in 1..40 {
        let phi = 0.05 + 0.12 * k as f64;
        let c = exact(&s, &FRAME, phi, false).unwrap();
        let m = motion(&s, phi, false);
        let (foot, dir) = face_line(FRAME.centres, 0.0, psi0 + sigma * m.s / arm, phi);
        assert!(
            (c.point - foot).perp_dot(dir).abs() < 1e-15,
            "on the line at {phi}"
        );
        // Along the profile the point moves along its face line, by ρ per radian of the
        // normal's turn (central differences).
        let d = 1e-5;
        let (a, b) = (
            exact(&s, &FRAME, phi - d, false).unwrap(),
            exact(&s, &FRAME, phi + d, false).unwrap(),
        );
        let chord = b.point - a.point;
        assert!(chord.perp_dot(dir).abs() < 1e-9 * chord.length().max(1e-12));
        let turn = {
            let ma = motion(&s, phi - d, false);
            let mb = motion(&s, phi + d, false);
            (sigma * (mb.s - ma.s) / arm) - 2.0 * d
        };
        let rho = chord.dot(dir) / turn;
        assert!(
            (rho - c.rho).abs() < 1e-6 * c.rho.abs().max(1e-3),
            "ρ at {phi}"
        );
        // The face through O₂: no pressure angle.
        assert!(c.lambda.abs() < 1e-12);
    }
}

#[test]
fn the_board_agrees_with_the_envelope_to_second_order() {
    let errors: Vec<(f64, f64)> = [12, 24, 48]
        .iter()
        .map(|&n| deviation(&spec(n), &FRAME))
        .collect();
    assert!(errors[1].0 < 2e-3 * FRAME.centres, "{errors:?}");
    for w in errors.windows(2) {
        assert!(
            (w[0].0 / w[1].0).log2() > 1.8,
            "within the phases: {errors:?}"
        );
        assert!((w[0].1 / w[1].1).log2() > 0.9, "at the ends: {errors:?}");
    }
}

#[test]
fn the_board_reads_the_radius_and_the_angle_of_an_offset_face() {
    let r = FlatRocker {
        face_offset: 0.015,
        ..FRAME
    };
    let s = spec(48);
    let b = board(&s, &r).unwrap();
    let mut worst = (0.0_f64, 0.0_f64);
    for (p, c) in points(&s).iter().zip(&b.contacts) {
        let e = exact(&s, &r, p.phi, p.after).unwrap();
        if p.k != 0 && !p.last {
            worst.0 = worst.0.max((c.rho - e.rho).abs() / e.rho.abs());
        }
        worst.1 = worst.1.max((c.lambda - e.lambda).abs());
        assert!(e.lambda > 0.05, "an offset face has a pressure angle");
    }
    assert!(worst.0 < 0.01 && worst.1 < 2e-3, "{worst:?}");
}

#[test]
fn a_small_base_circle_is_concave_by_both_routes() {
    // The smallest ρ over a dense sampling against the board's at the points.
    let rho_min = |r: &FlatRocker| {
        (0..=3600)
            .map(|k| {
                exact(
                    &spec(24),
                    r,
                    k as f64 * std::f64::consts::TAU / 3600.0,
                    false,
                )
            })
            .map(|c| c.unwrap().rho)
            .fold(f64::INFINITY, f64::min)
    };
    let good = rho_min(&FRAME);
    assert!(good > 0.0);
    let board_good = board(&spec(48), &FRAME).unwrap().rho_min();
    assert!(
        (board_good - good).abs() < 0.02 * good,
        "{board_good} {good}"
    );
    let small = FlatRocker {
        base: 0.004,
        centres: 0.06,
        ..FRAME
    };
    assert!(rho_min(&small) < 0.0);
    assert!(board(&spec(48), &small).unwrap().rho_min() < 0.0);
}

#[test]
fn a_face_that_outruns_the_cam_and_a_frame_that_does_not_fit_are_refused() {
    // A 60° swing of a short arm over 40°: the face turns faster than the cam.
    let fast = CamSpec {
        phases: Phases {
            rise: 40f64.to_radians(),
            far: 140f64.to_radians(),
            ret: 40f64.to_radians(),
            near: 140f64.to_radians(),
        },
        stroke: 0.1 * 60f64.to_radians(),
        ..spec(12)
    };
    let mid = 20f64.to_radians();
    assert!(matches!(
        exact(&fast, &FRAME, mid, false),
        Err(FlatRockerError::Outruns { .. })
    ));
    assert!(matches!(
        board(&fast, &FRAME),
        Err(FlatRockerError::Outruns { .. })
    ));
    let wide = FlatRocker {
        base: 0.13,
        ..FRAME
    };
    assert!(matches!(
        board(&spec(12), &wide),
        Err(FlatRockerError::Frame { .. })
    ));
    let translating = CamSpec {
        follower: Follower::Translating { offset: 0.0 },
        ..spec(12)
    };
    assert_eq!(
        exact(&translating, &FRAME, 0.1, false),
        Err(FlatRockerError::NotARocker)
    );
}

/// Every position of the pivot turned back is numbered on its circle, in order (the review
/// saw only the phases' ends, 0, 12, 13 and 25, numbered).
#[test]
fn every_turned_back_pivot_is_numbered() {
    let s = spec(12);
    let b = board(&s, &FRAME).expect("the board");
    let labels: Vec<String> = b
        .figure
        .steps
        .iter()
        .filter(|st| st.note.starts_with("pivot O_2 turned back by"))
        .map(|st| st.label.as_ref().map_or(String::new(), |l| l.text.clone()))
        .collect();
    let want: Vec<String> = points(&s).iter().map(|p| p.label.clone()).collect();
    assert_eq!(labels, want);
    assert_eq!(labels.len(), 26);
}
