//! Mechanisms shared by the integration tests.

use tmm::geom::DVec2;
use tmm::linkage::*;

/// A fixed point at (`x`, `y`) m.
fn pivot(name: &str, x: f64, y: f64) -> FixedPoint {
    FixedPoint {
        name: name.into(),
        at: DVec2::new(x, y),
    }
}

/// Crank 1 about `centre` with pin `pin`: length m, |ω₁| rad/s and sense.
fn crank(centre: &str, pin: &str, length: f64, omega: f64, sense: Sense) -> Crank {
    Crank {
        link: 1,
        centre: centre.into(),
        pin: pin.into(),
        length,
        omega,
        sense,
    }
}

/// One group of links 2, 3 after the crank, with the output `output` and further points.
fn mechanism(
    fixed: Vec<FixedPoint>,
    crank: Crank,
    dyad: Dyad,
    points: Vec<LinkPoint>,
    output: Output,
) -> Mechanism {
    Mechanism {
        fixed,
        crank,
        groups: vec![Group {
            links: [2, 3],
            dyad,
        }],
        points,
        redundant: vec![],
        outputs: vec![output],
        driving: false,
    }
}

/// A four-bar O–A–B–D: crank `r` about O at the origin, D at (`d`, 0), coupler `la`, rocker
/// `lb`, B on the left of A → D, crank turning counter-clockwise at 10 rad/s.
pub fn four_bar(r: f64, d: f64, la: f64, lb: f64) -> Mechanism {
    mechanism(
        vec![pivot("O", 0.0, 0.0), pivot("D", d, 0.0)],
        crank("O", "A", r, 10.0, Sense::CounterClockwise),
        Dyad::Rrr {
            a: "A".into(),
            la,
            b: "D".into(),
            lb,
            joint: "B".into(),
            branch: Branch::Left,
        },
        vec![],
        Output::Rocker { link: 3 },
    )
}

/// The slotted-link (kulisa) group of the shaper with the crank as long as the centre
/// distance: A (0, 430) mm, C at the origin, crank A–B 430 mm turning clockwise at 5π rad/s,
/// block 2 at B sliding in rocker 3 about C, D on the rocker 710 mm from C. The pin B passes
/// through the pivot C at φ₁ = 270°.
pub fn kulisa() -> Mechanism {
    mechanism(
        vec![pivot("A", 0.0, 0.43), pivot("C", 0.0, 0.0)],
        crank("A", "B", 0.43, 5.0 * std::f64::consts::PI, Sense::Clockwise),
        Dyad::Rpr {
            a: "B".into(),
            c: "C".into(),
            offset: 0.0,
        },
        vec![LinkPoint {
            name: "D".into(),
            link: 3,
            along: 0.71,
            across: 0.0,
        }],
        Output::Rocker { link: 3 },
    )
}

/// A central slider-crank O–A–B: crank `r` about O at the origin turning counter-clockwise
/// at 10 rad/s, coupler `l`, slider B on the x axis ahead of A.
pub fn slider_crank(r: f64, l: f64) -> Mechanism {
    mechanism(
        vec![pivot("O", 0.0, 0.0)],
        crank("O", "A", r, 10.0, Sense::CounterClockwise),
        Dyad::Rrp {
            a: "A".into(),
            la: l,
            guide: Guide {
                through: "O".into(),
                dir: Dir::Fixed(0.0),
                offset: 0.0,
                link: None,
            },
            joint: "B".into(),
            branch: Branch::Forward,
        },
        vec![],
        Output::Slider {
            point: "B".into(),
            dir: 0.0,
        },
    )
}
