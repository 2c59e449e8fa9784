//! Mechanisms shared by the integration tests.

use tmm::geom::DVec2;
use tmm::linkage::*;

/// A four-bar O–A–B–D: crank `r` about O at the origin, D at (`d`, 0), coupler `la`, rocker
/// `lb`, B on the left of A → D, crank turning counter-clockwise at 10 rad/s.
#[allow(dead_code)]
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

/// The slotted-link (kulisa) group of the shaper with the crank as long as the centre
/// distance: A (0, 430) mm, C at the origin, crank A–B 430 mm turning clockwise at 5π rad/s,
/// block 2 at B sliding in rocker 3 about C, D on the rocker 710 mm from C. The pin B passes
/// through the pivot C at φ₁ = 270°.
#[allow(dead_code)]
pub fn kulisa() -> Mechanism {
    Mechanism {
        fixed: vec![
            FixedPoint {
                name: "A".into(),
                at: DVec2::new(0.0, 0.43),
            },
            FixedPoint {
                name: "C".into(),
                at: DVec2::ZERO,
            },
        ],
        crank: Crank {
            link: 1,
            centre: "A".into(),
            pin: "B".into(),
            length: 0.43,
            omega: 5.0 * std::f64::consts::PI,
            sense: Sense::Clockwise,
        },
        groups: vec![Group {
            links: [2, 3],
            dyad: Dyad::Rpr {
                a: "B".into(),
                c: "C".into(),
                offset: 0.0,
            },
        }],
        points: vec![LinkPoint {
            name: "D".into(),
            link: 3,
            along: 0.71,
            across: 0.0,
        }],
        redundant: vec![],
        outputs: vec![Output::Rocker { link: 3 }],
    }
}

/// A central slider-crank O–A–B: crank `r` about O at the origin turning counter-clockwise
/// at 10 rad/s, coupler `l`, slider B on the x axis ahead of A.
#[allow(dead_code)]
pub fn slider_crank(r: f64, l: f64) -> Mechanism {
    Mechanism {
        fixed: vec![FixedPoint {
            name: "O".into(),
            at: DVec2::ZERO,
        }],
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
            dyad: Dyad::Rrp {
                a: "A".into(),
                la: l,
                guide: Guide {
                    through: "O".into(),
                    dir: Dir::Fixed(0.0),
                    offset: 0.0,
                },
                joint: "B".into(),
                branch: Branch::Forward,
            },
        }],
        points: vec![],
        redundant: vec![],
        outputs: vec![Output::Slider {
            point: "B".into(),
            dir: 0.0,
        }],
    }
}
