//! The analytic twin against finite differences.

use super::*;
use crate::geom::DVec2;

/// The analogues agree with 5-point central differences of the positions (a consistency
/// check of the differentiation, not the method: the twin itself never differentiates
/// numerically). Truncation O(h⁴) at h = 2.5e-4 keeps the check's own error near 1e-10
/// even where the analogues vary fast (the PRP case).
#[test]
fn analogues_match_finite_differences_for_every_kind() {
    let h = 2.5e-4;
    for m in crate::linkage::tests::one_of_each_kind() {
        let prog = Program::compile(&m).unwrap();
        for k in 0..24 {
            let phi = 0.1 + k as f64 * 0.26;
            let poses: Option<Vec<Pose>> = [-2.0, -1.0, 0.0, 1.0, 2.0]
                .iter()
                .map(|s| prog.solve(phi + s * h, None).ok())
                .collect();
            let Some(q) = poses else { continue };
            let d5 = |f: &dyn Fn(&Pose) -> f64| {
                (-f(&q[4]) + 8.0 * f(&q[3]) - 8.0 * f(&q[1]) + f(&q[0])) / (12.0 * h)
            };
            let dd5 = |f: &dyn Fn(&Pose) -> f64| {
                (-f(&q[4]) + 16.0 * f(&q[3]) - 30.0 * f(&q[2]) + 16.0 * f(&q[1]) - f(&q[0]))
                    / (12.0 * h * h)
            };
            let close =
                |got: f64, want: f64, tol: f64| (got - want).abs() <= tol * (1.0 + want.abs());
            for idx in 0..prog.names.len() {
                for c in 0..2 {
                    let f = |p: &Pose| p.p[idx][c];
                    assert!(
                        close(d5(&f), q[2].dp[idx][c], 1e-8),
                        "{} at {phi}: d {} vs {}",
                        prog.names[idx],
                        d5(&f),
                        q[2].dp[idx][c]
                    );
                    assert!(
                        close(dd5(&f), q[2].ddp[idx][c], 1e-6),
                        "{} at {phi}: dd {} vs {}",
                        prog.names[idx],
                        dd5(&f),
                        q[2].ddp[idx][c]
                    );
                }
            }
            for l in 1..prog.link_count {
                // Unwrap the angles around the middle one.
                let f = |p: &Pose| q[2].angle(l) + crate::geom::wrap_pi(p.angle(l) - q[2].angle(l));
                assert!(close(d5(&f), q[2].dangle[l], 1e-8), "link {l} at {phi}");
                assert!(
                    close(dd5(&f), q[2].ddangle[l], 1e-6),
                    "link {l} at {phi}: {} vs {}",
                    dd5(&f),
                    q[2].ddangle[l]
                );
            }
        }
    }
}

/// A sweep gives, position by position, what solving each angle on its own with continuity
/// gives: the same angle, and values within the few ulps by which the crank's turned
/// direction differs from the one taken from sin and cos.
#[test]
fn a_sweep_is_each_angle_solved_on_its_own() {
    let (phi0, step, n) = (0.1, -0.013, 3 * SWEEP_ANCHOR + 5);
    for m in crate::linkage::tests::one_of_each_kind() {
        let prog = Program::compile(&m).unwrap();
        let mut alone = Pose::default();
        let mut swept = Pose::default();
        let mut seen = 0;
        let result = prog.sweep((phi0, step), n, &mut swept, |k, pose| {
            seen += 1;
            let phi = phi0 + k as f64 * step;
            assert_eq!(pose.phi, phi);
            prog.solve_into(phi, k > 0, &mut alone).unwrap();
            let close = |a: DVec2, b: DVec2| (a - b).length() <= 1e-12 * (1.0 + b.length());
            for i in 0..prog.names.len() {
                assert!(
                    close(pose.p[i], alone.p[i]),
                    "{} at step {k}",
                    prog.names[i]
                );
                assert!(
                    close(pose.dp[i], alone.dp[i]),
                    "{} at step {k}",
                    prog.names[i]
                );
                assert!(
                    close(pose.ddp[i], alone.ddp[i]),
                    "{} at step {k}",
                    prog.names[i]
                );
            }
            for l in 1..prog.link_count {
                assert!(close(pose.dir[l], alone.dir[l]), "link {l} at step {k}");
                let rates = DVec2::new(pose.dangle[l], pose.ddangle[l]);
                let want = DVec2::new(alone.dangle[l], alone.ddangle[l]);
                assert!(close(rates, want), "link {l} at step {k}");
            }
            assert_eq!(pose.crossing_sin.len(), alone.crossing_sin.len());
        });
        result.unwrap();
        assert_eq!(seen, n);
    }
}

/// A sweep stops at the first position that cannot be assembled, with that group's
/// diagnosis, after handing over every position before it.
#[test]
fn a_sweep_stops_where_the_mechanism_cannot_be_assembled() {
    let mut m = crate::linkage::tests::one_of_each_kind().remove(0);
    // Coupler and rocker 0.12 + 0.18 = 0.30 m cannot span the 0.36 m between the crank pin
    // and the rocker's pivot when the crank points away from it.
    let crate::linkage::Dyad::Rrr { la, .. } = &mut m.groups[0].dyad else {
        panic!("the first mechanism is a four-bar");
    };
    *la = 0.12;
    let prog = Program::compile(&m).unwrap();
    let step = std::f64::consts::TAU / 72.0;
    let first_unassembled = (0..72)
        .position(|k| prog.solve(k as f64 * step, None).is_err())
        .expect("a position that cannot be assembled");
    assert!(first_unassembled > 0);
    let mut seen = Vec::new();
    let err = prog
        .sweep((0.0, step), 72, &mut Pose::default(), |k, _| seen.push(k))
        .unwrap_err();
    assert_eq!(err.group, 0);
    assert_eq!(seen, (0..first_unassembled).collect::<Vec<_>>());
}
