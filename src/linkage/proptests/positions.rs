//! The plan of positions (moved here from the integration tests, unchanged).

use super::gen::{mech, moved};
use super::*;

fn pt(prog: &Program, b: &Built, name: &str) -> DVec2 {
    b.p[prog.index(name).expect("known point")] * MU
}

/// Distance of `p` from the line through `q` along `angle`, shifted `offset` to the left.
fn off_line(p: DVec2, q: DVec2, angle: f64, offset: f64) -> f64 {
    let e = DVec2::from_angle(angle);
    e.perp_dot(p - q) - offset
}

/// Construction = analytic twin, and invariance under a rigid motion of the scene.
fn common_checks(m: &Mechanism, phi: f64, rot: f64, shift: DVec2) -> Result<(), TestCaseError> {
    let (prog, b, pose) = build(m, phi).ok_or_else(|| TestCaseError::reject("not assembled"))?;
    for (k, name) in prog.names.iter().enumerate() {
        let d = (b.p[k] * MU - pose.p[k]).length();
        prop_assert!(
            d <= 1e-12,
            "point {name}: construction and analytic differ by {d:e} m"
        );
    }
    let (prog2, b2, _) = build(&moved(m, rot, shift), phi + rot)
        .ok_or_else(|| TestCaseError::fail("the moved scene did not assemble"))?;
    for (k, name) in prog.names.iter().enumerate() {
        let want = DVec2::from_angle(rot).rotate(b.p[k] * MU) + shift;
        let got = b2.p[prog2.index(name).expect("same names")] * MU;
        prop_assert!(
            (want - got).length() <= 1e-9,
            "point {name} moved differently: {want} vs {got}"
        );
    }
    Ok(())
}

fn rel(residual: f64, size: f64) -> f64 {
    residual.abs() / size
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, max_global_rejects: 4096, ..ProptestConfig::default() })]

    #[test]
    fn rrr_joint_keeps_both_lengths(r in 0.05..0.2f64, d in 0.2..0.6f64, la in 0.1..0.8f64, lb in 0.1..0.8f64, left in any::<bool>(), phi in 0.0..2.0 * PI, rot in -PI..PI, sx in -1.0..1.0f64, sy in -1.0..1.0f64) {
        let m = mech(&[("O", DVec2::ZERO), ("D", DVec2::new(d, 0.0))], r, Dyad::Rrr { a: "B".into(), la, b: "D".into(), lb, joint: "C".into(), branch: if left { Branch::Left } else { Branch::Right } });
        let Some((prog, b, _)) = build(&m, phi) else { return Err(TestCaseError::reject("not assembled")) };
        let (pb, pc, pd) = (pt(&prog, &b, "B"), pt(&prog, &b, "C"), pt(&prog, &b, "D"));
        prop_assert!(rel(pb.distance(pc) - la, la) <= 1e-12);
        prop_assert!(rel(pd.distance(pc) - lb, lb) <= 1e-12);
        let side = (pd - pb).perp_dot(pc - pb);
        let kept = if left { side >= -1e-12 } else { side <= 1e-12 };
        prop_assert!(kept, "branch left = {left} not kept");
        common_checks(&m, phi, rot, DVec2::new(sx, sy))?;
    }

    #[test]
    fn rrp_joint_on_guide_at_rod_length(r in 0.05..0.2f64, e in -0.1..0.1f64, alpha in -PI..PI, la in 0.32..0.8f64, fwd in any::<bool>(), phi in 0.0..2.0 * PI, rot in -PI..PI, sx in -1.0..1.0f64, sy in -1.0..1.0f64) {
        let guide = Guide { through: "O".into(), dir: Dir::Fixed(alpha), offset: e, link: None };
        let m = mech(&[("O", DVec2::ZERO)], r, Dyad::Rrp { a: "B".into(), la, guide, joint: "C".into(), branch: if fwd { Branch::Forward } else { Branch::Backward } });
        let (prog, b, _) = build(&m, phi).expect("always assembled: la > r + |e|");
        let (pb, pc) = (pt(&prog, &b, "B"), pt(&prog, &b, "C"));
        prop_assert!(rel(pb.distance(pc) - la, la) <= 1e-12);
        prop_assert!(rel(off_line(pc, DVec2::ZERO, alpha, e), la) <= 1e-12);
        let along = (pc - pb).dot(DVec2::from_angle(alpha));
        let kept = if fwd { along >= 0.0 } else { along <= 0.0 };
        prop_assert!(kept, "branch forward = {fwd} not kept: {along}");
        common_checks(&m, phi, rot, DVec2::new(sx, sy))?;
    }

    #[test]
    fn rpr_slide_line_passes_the_block_at_its_offset(r in 0.05..0.2f64, h in 0.3..0.6f64, e in -0.04..0.04f64, phi in 0.0..2.0 * PI, rot in -PI..PI, sx in -1.0..1.0f64, sy in -1.0..1.0f64) {
        let m = mech(&[("O", DVec2::ZERO), ("C", DVec2::new(0.0, -h))], r, Dyad::Rpr { a: "B".into(), c: "C".into(), offset: e });
        let (prog, b, _) = build(&m, phi).expect("always assembled: h − r > |e|");
        let (pb, pc) = (pt(&prog, &b, "B"), pt(&prog, &b, "C"));
        let th = b.angle[3];
        // The block's pin lies on the slide line, which passes `e` to the left of C.
        prop_assert!(rel(off_line(pb, pc, th, e), h) <= 1e-12, "{}", off_line(pb, pc, th, e));
        prop_assert!((b.angle[2] - th).abs() <= 1e-15);
        common_checks(&m, phi, rot, DVec2::new(sx, sy))?;
    }

    #[test]
    fn prp_joint_on_both_guides(r in 0.05..0.2f64, beta in 0.3..2.8f64, gamma in -PI..PI, e in -0.1..0.1f64, phi in 0.0..2.0 * PI, rot in -PI..PI, sx in -1.0..1.0f64, sy in -1.0..1.0f64) {
        let gi = Guide { through: "B".into(), dir: Dir::Along { from: "O".into(), to: "B".into(), angle: beta }, offset: 0.0, link: None };
        let gj = Guide { through: "O".into(), dir: Dir::Fixed(gamma), offset: e, link: None };
        let m = mech(&[("O", DVec2::ZERO)], r, Dyad::Prp { guide_i: gi, guide_j: gj, joint: "C".into() });
        let Some((prog, b, _)) = build(&m, phi) else { return Err(TestCaseError::reject("parallel guides")) };
        prop_assume!(b.crossing[0] > 0.05);
        let (pb, pc) = (pt(&prog, &b, "B"), pt(&prog, &b, "C"));
        let size = pc.length().max(r);
        prop_assert!(rel(off_line(pc, pb, phi + beta, 0.0), size) <= 1e-12);
        prop_assert!(rel(off_line(pc, DVec2::ZERO, gamma, e), size) <= 1e-12);
        common_checks(&m, phi, rot, DVec2::new(sx, sy))?;
    }

    #[test]
    fn rpp_joint_on_guide_and_slide(r in 0.05..0.2f64, alpha in -PI..PI, gamma in -PI..PI, e in -0.3..0.3f64, phi in 0.0..2.0 * PI, rot in -PI..PI, sx in -1.0..1.0f64, sy in -1.0..1.0f64) {
        prop_assume!((alpha - gamma).sin().abs() > 0.2);
        let guide = Guide { through: "O".into(), dir: Dir::Fixed(gamma), offset: e, link: None };
        let m = mech(&[("O", DVec2::ZERO)], r, Dyad::Rpp { a: "B".into(), slide: Dir::Fixed(alpha), guide, joint: "C".into() });
        let (prog, b, _) = build(&m, phi).expect("guide and slide cross");
        let (pb, pc) = (pt(&prog, &b, "B"), pt(&prog, &b, "C"));
        let size = pc.length().max(r);
        prop_assert!(rel(off_line(pc, DVec2::ZERO, gamma, e), size) <= 1e-12);
        prop_assert!(rel(off_line(pc, pb, alpha, 0.0), size) <= 1e-12);
        common_checks(&m, phi, rot, DVec2::new(sx, sy))?;
    }
}
