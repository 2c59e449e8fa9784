//! A guide through a moving joint (`tests/scenes/block-on-slider.toml`): the block 5 slides
//! in a vertical guide on the slider 3, whose joint B it shares with the rod 2. The guide is
//! the slider's, as the scene names it: the velocities, the balancing moment of both routes
//! and the check's residuals against an oracle written here from the closed-form positions;
//! the guide without its `link`, or on a link that turns, refused at load.

use crate::support;
use serde_json::Value;
use support::{root, tmm};

const SCENE: &str = "tests/scenes/block-on-slider.toml";
/// ω₁ of the scene, rad/s (counter-clockwise).
const W1: f64 = 10.0;

/// The points of the mechanism at crank angle `phi`, m: A, B, S₂, C, S₄, and the angles of
/// the rod and the rocker, rad — straight from the scene's dimensions.
fn points(phi: f64) -> ([[f64; 2]; 5], [f64; 2]) {
    let (r, l, e) = (0.060, 0.220, 0.025);
    let (xe, ye, la) = (0.200, 0.150, 0.120);
    let a = [r * phi.cos(), r * phi.sin()];
    let b = [a[0] + (l * l - (e - a[1]).powi(2)).sqrt(), e];
    let c = [b[0], ye - (la * la - (b[0] - xe).powi(2)).sqrt()];
    let s2 = [
        a[0] + (b[0] - a[0]) * 80.0 / 220.0,
        a[1] + (b[1] - a[1]) * 80.0 / 220.0,
    ];
    let s4 = [(xe + c[0]) / 2.0, (ye + c[1]) / 2.0];
    let t2 = (b[1] - a[1]).atan2(b[0] - a[0]);
    let t4 = (c[1] - ye).atan2(c[0] - xe);
    ([a, b, s2, c, s4], [t2, t4])
}

/// Every coordinate of [`points`] as one vector.
fn flat(phi: f64) -> Vec<f64> {
    let (p, t) = points(phi);
    p.iter().flatten().copied().chain(t).collect()
}

/// The first and second derivatives of [`flat`] in φ by five-point central differences.
fn derivatives(phi: f64) -> (Vec<f64>, Vec<f64>) {
    let h = 1e-3;
    let f: Vec<Vec<f64>> = [-2.0, -1.0, 0.0, 1.0, 2.0]
        .iter()
        .map(|k| flat(phi + k * h))
        .collect();
    let d1 = (0..f[0].len())
        .map(|i| (f[0][i] - 8.0 * f[1][i] + 8.0 * f[3][i] - f[4][i]) / (12.0 * h))
        .collect();
    let d2 = (0..f[0].len())
        .map(|i| {
            (-f[0][i] + 16.0 * f[1][i] - 30.0 * f[2][i] + 16.0 * f[3][i] - f[4][i]) / (12.0 * h * h)
        })
        .collect();
    (d1, d2)
}

/// The balancing moment by the power balance with the oracle's motion, N·m, and |v_C|, m/s.
fn oracle(phi: f64) -> (f64, f64) {
    let g = 9.81;
    let (d1, d2) = derivatives(phi);
    let v = |k: usize| [d1[2 * k] * W1, d1[2 * k + 1] * W1];
    let a = |k: usize| [d2[2 * k] * W1 * W1, d2[2 * k + 1] * W1 * W1];
    // The centres of mass B (slider 3), S₂ (rod 2), C (block 5), S₄ (rocker 4) with masses.
    let masses = [(1, 5.0), (2, 3.0), (3, 0.5), (4, 2.0)];
    let mut power = 0.0;
    for (k, m) in masses {
        let (vk, ak) = (v(k), a(k));
        power += m * (-g * vk[1]) - m * (ak[0] * vk[0] + ak[1] * vk[1]);
    }
    let (w2, w4) = (d1[10] * W1, d1[11] * W1);
    let (e2, e4) = (d2[10] * W1 * W1, d2[11] * W1 * W1);
    let (j2, j4) = (3.0 * 0.22 * 0.22 / 12.0, 2.0 * 0.12 * 0.12 / 12.0);
    power -= j2 * e2 * w2 + j4 * e4 * w4;
    power += -20.0 * w4.signum() * w4;
    let vc = v(3);
    (-power / W1, vc[0].hypot(vc[1]))
}

fn num(r: &Value, k: &str) -> f64 {
    r[k].as_f64().unwrap_or(f64::NAN)
}

/// At both force positions: M_bal by the polygons, the lever and the linear solve equal the
/// oracle's power balance; v_C on the velocity plan and by the twin equals the oracle's; the
/// block turns with the slider (ω₅ = 0); both residual rows of both routes ≤ 1e-12.
#[test]
fn a_guide_through_a_moving_joint_is_carried_by_the_slider() {
    let v = support::report_json(SCENE, None);
    let table = &v["tables"][0];
    for label in ["2", "5"] {
        let row = table["rows"]
            .as_array()
            .expect("rows")
            .iter()
            .find(|r| r["position"] == label)
            .expect("the position's row");
        let phi = row["values"][0].as_f64().expect("φ₁");
        let (m_bal, vc) = oracle(phi.to_radians());
        let rows: Vec<&Value> = v["rows"]
            .as_array()
            .expect("rows")
            .iter()
            .filter(|r| r["position"] == label)
            .collect();
        let find = |q: &str, m: &str| {
            rows.iter()
                .find(|r| r["quantity"] == q && r["method"] == m)
                .unwrap_or_else(|| panic!("{q} by {m} at {label}"))
        };
        for m in ["polygon", "lever"] {
            let r = find("M_bal", m);
            for col in ["graphical", "analytic"] {
                let x = num(r, col);
                assert!(
                    (x - m_bal).abs() <= 1e-7 * m_bal.abs(),
                    "M_bal {m} {col} at {label}: {x} vs {m_bal}"
                );
            }
        }
        let r = find("v_C", "plan");
        for col in ["graphical", "analytic"] {
            assert!(
                (num(r, col) - vc).abs() <= 1e-8 * vc,
                "v_C {col} at {label}: {} vs {vc}",
                num(r, col)
            );
        }
        let r = find("omega_5", "plan");
        assert!(
            num(r, "graphical").abs() < 1e-12 && num(r, "analytic").abs() < 1e-12,
            "{r}"
        );
        for q in ["equilibrium_residual", "power_residual"] {
            let r = find(q, "polygon");
            assert!(
                num(r, "graphical") <= 1e-12 && num(r, "analytic") <= 1e-12,
                "{r}"
            );
        }
    }
}

/// Without `link`, the joint B of the rod and the slider leaves the guide's body open: refused
/// at `through`; on the rod, which turns, or on a link not at B: refused at `link`.
#[test]
fn a_guide_at_a_joint_names_the_link_that_translates() {
    let text = std::fs::read_to_string(root().join(SCENE)).expect("scene");
    let dir = support::scratch("guide-carrier");
    for (link, key, says) in [
        (
            "",
            "mechanism.group[1].guide.through",
            "name the link whose body carries it",
        ),
        (
            ", link = 2",
            "mechanism.group[1].guide.link",
            "link 2 turns",
        ),
        (
            ", link = 4",
            "mechanism.group[1].guide.link",
            "link 4 does not hold the guide's points",
        ),
    ] {
        let path = dir.join("s.toml");
        std::fs::write(&path, text.replace(", link = 3 }", &format!("{link} }}"))).expect("write");
        let out = tmm(&["check", path.to_str().expect("path")]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            !out.status.success() && err.contains(key) && err.contains(says),
            "{err}"
        );
    }
}
