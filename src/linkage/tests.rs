//! Unit tests of the linkage core on hand-built mechanisms.

use super::*;
use crate::construct::{Context, Drafting, Recorder};
use crate::geom::DVec2;
use crate::scale::{Quantity, Scale};

/// The shaper of seed 000 (§000.3 geometry), built directly.
pub(crate) fn shaper() -> Mechanism {
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
            length: 0.14,
            omega: 5.0 * std::f64::consts::PI,
            sense: Sense::Clockwise,
        },
        groups: vec![
            Group {
                links: [2, 3],
                dyad: Dyad::Rpr {
                    a: "B".into(),
                    c: "C".into(),
                    offset: 0.0,
                },
            },
            Group {
                links: [4, 5],
                dyad: Dyad::Rpp {
                    a: "D".into(),
                    slide: Dir::Fixed(std::f64::consts::FRAC_PI_2),
                    guide: Guide {
                        through: "C".into(),
                        dir: Dir::Fixed(0.0),
                        offset: 0.745,
                        link: None,
                    },
                    joint: "E".into(),
                },
            },
        ],
        points: vec![
            LinkPoint {
                name: "D".into(),
                link: 3,
                along: 0.71,
                across: 0.0,
            },
            LinkPoint {
                name: "S_3".into(),
                link: 3,
                along: 0.29,
                across: 0.0,
            },
        ],
        redundant: vec![RedundantPair {
            name: "E′".into(),
            prismatic: true,
            links: [5, 0],
            reason: "bending".into(),
        }],
        outputs: vec![
            Output::Rocker { link: 3 },
            Output::Slider {
                point: "E".into(),
                dir: 0.0,
            },
        ],
        driving: false,
    }
}

#[test]
fn shaper_structure_matches_seed() {
    let s = Structure::analyse(&shaper());
    assert_eq!((s.n, s.p5, s.w), (5, 7, 1));
    assert_eq!((s.p5_all, s.w_all), (8, -1));
    assert_eq!(s.formula(), "I(0,1) → II(2,3) → II(4,5)");
    assert_eq!(s.groups[0].kind, DyadKind::Rpr);
    assert_eq!(s.groups[1].kind, DyadKind::Rpp);
    assert_eq!(s.groups[1].pairs[2].links, [5, 0]);
}

#[test]
fn shaper_extremes_are_exact() {
    let m = shaper();
    let prog = Program::compile(&m).unwrap();
    let ex = prog.extremes(&m.outputs, m.crank.sense, m.driving).unwrap();
    let theta = ex.theta.to_degrees();
    assert!((theta - 38.0016).abs() < 1e-4, "θ = {theta}");
    let exact = 2.0 * (0.14f64 / 0.43).asin();
    assert!(
        (ex.theta - exact).abs() < 1e-12,
        "θ = {} vs {}",
        ex.theta,
        exact
    );
    assert!((ex.k - 1.5352).abs() < 1e-4, "K = {}", ex.k);
    assert!(
        (ex.phi_start.to_degrees() - 199.0008).abs() < 1e-3,
        "{}",
        ex.phi_start.to_degrees()
    );
    assert!((ex.phi_other.to_degrees() - (360.0 - 19.0008)).abs() < 1e-3);
    let stroke = ex.ranges[1].max - ex.ranges[1].min;
    assert!(
        (stroke - 2.0 * 0.71 * 0.14 / 0.43).abs() < 1e-12,
        "H = {stroke}"
    );
    assert!((ex.ranges[0].max - ex.ranges[0].min - exact).abs() < 1e-12);
}

#[test]
fn construction_equals_analytic_on_the_shaper() {
    let m = shaper();
    let prog = Program::compile(&m).unwrap();
    let mu = 0.0025;
    let mut rec = Recorder::in_context(
        "t",
        Scale::new(mu, Quantity::Length).unwrap(),
        &Context::for_model_size(400.0, Drafting::EXACT).unwrap(),
    );
    let mut prev_b = None;
    let mut prev_a = None;
    for k in 0..12 {
        let phi = (199.0 - 30.0 * k as f64).to_radians();
        let a = prog.solve(phi, prev_a.as_ref()).unwrap();
        let b = prog
            .construct(&mut rec, phi, prev_b.as_ref(), &format!("{}", k + 1))
            .unwrap();
        for (i, (pa, pb)) in a.p.iter().zip(&b.p).enumerate() {
            let d = (*pa - *pb * mu).length();
            assert!(d < 1e-12, "position {k} point {}: {d}", prog.names[i]);
        }
        prev_a = Some(a);
        prev_b = Some(b);
    }
}

/// One small mechanism of every dyad kind, with guides on moving links where the kind allows
/// it, offsets, and a point carried by each new link.
pub(crate) fn one_of_each_kind() -> Vec<Mechanism> {
    use super::proptests::gen::{fixed, one_group, point};
    let mk = |fx: &[(&str, DVec2)], r: f64, dyad: Dyad| {
        let pts = vec![point("S2", 2, 0.05, 0.01), point("S3", 3, 0.08, -0.02)];
        one_group(fixed(fx), r, dyad, pts)
    };
    // A direction carried by the crank O–B, turned by `angle`.
    let on_crank = |angle: f64| Dir::Along {
        from: "O".into(),
        to: "B".into(),
        angle,
    };
    let guide = |through: &str, dir: Dir, offset: f64| Guide {
        through: through.into(),
        dir,
        offset,
        link: None,
    };
    let rpp = |slide: Dir, guide: Guide| Dyad::Rpp {
        a: "B".into(),
        slide,
        guide,
        joint: "C".into(),
    };
    let o = ("O", DVec2::ZERO);
    vec![
        mk(
            &[o, ("D", DVec2::new(0.28, 0.05))],
            0.08,
            Dyad::Rrr {
                a: "B".into(),
                la: 0.25,
                b: "D".into(),
                lb: 0.18,
                joint: "C".into(),
                branch: Branch::Left,
            },
        ),
        // A slider on a guide carried by the crank (turned 70° from it, offset 0.03).
        mk(
            &[o],
            0.1,
            Dyad::Rrp {
                a: "B".into(),
                la: 0.3,
                guide: guide("O", on_crank(1.2), 0.03),
                joint: "C".into(),
                branch: Branch::Forward,
            },
        ),
        mk(
            &[o, ("C", DVec2::new(0.05, -0.35))],
            0.12,
            Dyad::Rpr {
                a: "B".into(),
                c: "C".into(),
                offset: 0.04,
            },
        ),
        mk(
            &[o],
            0.1,
            Dyad::Prp {
                guide_i: guide("B", on_crank(1.4), 0.01),
                guide_j: guide("O", Dir::Fixed(0.3), 0.05),
                joint: "C".into(),
            },
        ),
        // Link j slides on a guide carried by the crank; its slide turns with it.
        mk(
            &[o],
            0.1,
            rpp(on_crank(2.0), guide("O", on_crank(-0.4), 0.2)),
        ),
        // The Scotch-yoke kind: a frame guide, a fixed slide.
        mk(
            &[o],
            0.1,
            rpp(Dir::Fixed(1.3), guide("O", Dir::Fixed(-0.2), 0.15)),
        ),
    ]
}

/// Velocity and acceleration plans, constructed, equal the analytic twin (every image as a
/// vector, every link rate) for every dyad kind at many crank angles.
#[test]
fn plans_equal_analytic_for_every_kind() {
    let mut mechs = one_of_each_kind();
    mechs.push(shaper());
    for (mi, m) in mechs.iter().enumerate() {
        let prog = Program::compile(m).unwrap();
        let mu_l = 0.001;
        let w1 = m.crank.sense.sign() * 7.0;
        for k in 0..18 {
            let phi = 0.05 + k as f64 * 0.35;
            let Ok(pose) = prog.solve(phi, None) else {
                continue;
            };
            if pose.toggle.is_some() {
                continue;
            }
            let mut rec = Recorder::in_context(
                "t",
                Scale::new(mu_l, Quantity::Length).unwrap(),
                &Context::for_model_size(1000.0, Drafting::EXACT).unwrap(),
            );
            let built = prog.construct(&mut rec, phi, None, "t").unwrap();
            let sv = Scale::new(0.01, Quantity::Velocity).unwrap();
            let sa = Scale::new(0.1, Quantity::Acceleration).unwrap();
            let setup = PlanSetup {
                prog: &prog,
                built: &built,
                mu_l: Scale::new(mu_l, Quantity::Length).unwrap(),
                w1,
                ctx: crate::linkage::proptests::plan_context(),
            };
            let vp = kin_plan(&setup, PlanKind::Velocity, sv, None)
                .unwrap_or_else(|e| panic!("mech {mi} φ {phi}: {e:?}"));
            let ap = kin_plan(&setup, PlanKind::Acceleration, sa, Some(&vp))
                .unwrap_or_else(|e| panic!("mech {mi} φ {phi}: {e:?}"));
            let vscale = w1.abs() * 0.5 + 1.0;
            for (idx, name) in prog.names.iter().enumerate() {
                let v = vp.images[idx] * 0.01;
                let want = pose.dp[idx] * w1;
                assert!(
                    (v - want).length() <= 1e-9 * (1.0 + want.length()) * vscale,
                    "mech {mi} φ {phi} v_{name}: {v} vs {want}"
                );
                let a = ap.images[idx] * 0.1;
                let want = pose.ddp[idx] * (w1 * w1);
                assert!(
                    (a - want).length() <= 1e-9 * (1.0 + want.length()) * vscale * vscale,
                    "mech {mi} φ {phi} a_{name}: {a} vs {want}"
                );
            }
            for l in 1..prog.link_count {
                let (w, want) = (vp.rate[l], pose.dangle[l] * w1);
                assert!(
                    (w - want).abs() <= 1e-9 * (1.0 + want.abs()),
                    "mech {mi} φ {phi} ω_{l}: {w} vs {want}"
                );
                let (e, want) = (ap.rate[l], pose.ddangle[l] * w1 * w1);
                assert!(
                    (e - want).abs() <= 1e-8 * (1.0 + want.abs()),
                    "mech {mi} φ {phi} ε_{l}: {e} vs {want}"
                );
            }
        }
    }
}

/// A guide along O → B with O fixed and B the crank pin is carried by the crank, not the frame.
#[test]
fn guide_along_the_crank_is_carried_by_the_crank() {
    let m = &one_of_each_kind()[1];
    let s = Structure::analyse(m);
    let slide = &s.groups[0].pairs[2];
    assert!(slide.prismatic);
    assert_eq!(slide.links, [3, 1]);
    assert_eq!(s.mobility(), Mobility::chebyshev(3, 4, 0));
    assert_eq!(s.mobility().w, 1);
}
