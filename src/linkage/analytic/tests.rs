//! The analytic twin against finite differences.

use super::*;

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
