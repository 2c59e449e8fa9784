//! Mechanisms shared by the integration tests.

use tmm::geom::DVec2;
use tmm::linkage::*;

/// A four-bar O–A–B–D: crank `r` about O at the origin, D at (`d`, 0), coupler `la`, rocker
/// `lb`, B on the left of A → D, crank turning counter-clockwise at 10 rad/s.
pub fn four_bar(r: f64, d: f64, la: f64, lb: f64) -> Mechanism {
    Mechanism {
        fixed: vec![
            FixedPoint {
                name: "O".into(),
                at: DVec2::ZERO,
            },
            FixedPoint {
                name: "D".into(),
                at: DVec2::new(d, 0.0),
            },
        ],
        crank: Crank {
            link: 1,
            centre: "O".into(),
            pin: "A".into(),
            length: r,
            omega: 10.0,
            sense: Sense::CounterClockwise,
        },
        groups: vec![Group {
            links: [2, 3],
            dyad: Dyad::Rrr {
                a: "A".into(),
                la,
                b: "D".into(),
                lb,
                joint: "B".into(),
                branch: Branch::Left,
            },
        }],
        points: vec![],
        redundant: vec![],
        outputs: vec![Output::Rocker { link: 3 }],
    }
}
