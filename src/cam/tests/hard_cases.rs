//! The cam's hard cases as the findings name them: an undercut roller, a concave flat face,
//! rigid shocks and an offset on the wrong side.

use super::{ctx, fast, translating};
use crate::cam::*;
use crate::check::{Cusp, Finding};

#[test]
fn hard_case_undercut_is_detected() {
    let mut s = fast(translating(Law::Sine, 0.0));
    s.base_radius = Some(0.020);
    s.roller = Some(0.015);
    let cam = build(&s, &ctx(0.0)).unwrap();
    let rho = cam.exact_rho_min();
    assert!(rho < 0.015, "{rho}");
    assert!(cam
        .findings()
        .iter()
        .any(|f| matches!(f, Finding::Undercut { .. })));
}

#[test]
fn hard_case_concave_flat_face_is_detected() {
    let s = CamSpec {
        follower: Follower::Flat { offset: 0.0 },
        base_radius: Some(0.010),
        rho_min: 0.005,
        ..fast(translating(Law::Sine, 0.0))
    };
    let cam = build(&s, &ctx(0.0)).unwrap();
    assert!(cam.exact_rho_min() < 0.0);
    assert!(cam
        .findings()
        .iter()
        .any(|f| matches!(f, Finding::Cusp(Cusp::Flat { .. }))));
}

#[test]
fn hard_case_rigid_shocks_and_wrong_offset() {
    let s = translating(Law::Uniform, -0.004);
    let cam = build(&s, &ctx(0.0)).unwrap();
    let found = cam.findings();
    let shocks = found
        .iter()
        .filter(|f| matches!(f, Finding::RigidShock { .. }))
        .count();
    assert_eq!(shocks, 2, "{found:?}");
    assert!(
        found
            .iter()
            .any(|f| matches!(f, Finding::WrongSide { offset, .. } if *offset < 0.0)),
        "{found:?}"
    );
}
