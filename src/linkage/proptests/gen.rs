//! Random mechanisms for the property tests.

use super::*;
use std::collections::HashMap;

/// A counter-clockwise crank O–B of length `r`, link 1.
pub(crate) fn crank(r: f64) -> Crank {
    Crank {
        link: 1,
        centre: "O".into(),
        pin: "B".into(),
        length: r,
        omega: 1.0,
        sense: Sense::CounterClockwise,
    }
}

/// The fixed points of a mechanism, by name and place.
pub(crate) fn fixed(v: &[(&str, DVec2)]) -> Vec<FixedPoint> {
    v.iter()
        .map(|&(name, at)| FixedPoint {
            name: name.into(),
            at,
        })
        .collect()
}

/// The point `name` carried by `link`, `along` its axis and `across` it.
pub(crate) fn point(name: &str, link: u32, along: f64, across: f64) -> LinkPoint {
    LinkPoint {
        name: name.into(),
        link,
        along,
        across,
    }
}

/// A crank `r` and one group on links 2, 3 carrying `points`; the output is link 3.
pub(crate) fn one_group(
    fixed: Vec<FixedPoint>,
    r: f64,
    dyad: Dyad,
    points: Vec<LinkPoint>,
) -> Mechanism {
    Mechanism {
        fixed,
        crank: crank(r),
        groups: vec![Group {
            links: [2, 3],
            dyad,
        }],
        points,
        redundant: vec![],
        outputs: vec![Output::Rocker { link: 3 }],
        driving: false,
    }
}

/// A crank `r` and one group on links 2, 3 with a point `S` carried by link 3.
pub(crate) fn mech(fixed_points: &[(&str, DVec2)], r: f64, dyad: Dyad) -> Mechanism {
    one_group(
        fixed(fixed_points),
        r,
        dyad,
        vec![point("S", 3, 0.07, 0.02)],
    )
}

/// The same mechanism after a rigid motion of the whole scene: every fixed point turned by
/// `rot` and shifted by `shift`, every frame direction turned by `rot`. Directions carried
/// by links, lengths and offsets are unchanged.
pub(crate) fn moved(m: &Mechanism, rot: f64, shift: DVec2) -> Mechanism {
    let t = |p: DVec2| DVec2::from_angle(rot).rotate(p) + shift;
    let d = |dir: &Dir| match dir {
        Dir::Fixed(a) => Dir::Fixed(a + rot),
        other => other.clone(),
    };
    let g = |gd: &Guide| Guide {
        dir: d(&gd.dir),
        ..gd.clone()
    };
    let mut out = m.clone();
    out.fixed.iter_mut().for_each(|f| f.at = t(f.at));
    for grp in &mut out.groups {
        match &mut grp.dyad {
            Dyad::Rrp { guide, .. } => *guide = g(guide),
            Dyad::Prp {
                guide_i, guide_j, ..
            } => {
                *guide_i = g(guide_i);
                *guide_j = g(guide_j);
            }
            Dyad::Rpp { slide, guide, .. } => {
                *slide = d(slide);
                *guide = g(guide);
            }
            Dyad::Rrr { .. } | Dyad::Rpr { .. } => {}
        }
    }
    out
}

/// The random draws for one dyad. What they become depends on what is known when the
/// dyad is attached ([`Known`]).
#[derive(Debug, Clone)]
pub(crate) struct Draw {
    kind: DyadKind,
    /// The carrier of the guide (index into [`Known::carriers`], modulo).
    carrier: usize,
    /// The carrier of the second guide of a PRP.
    carrier2: usize,
    /// Frame angle of a fixed guide, or the turn of a carried one.
    angle: f64,
    /// The same for the second guide (PRP) or the slide (RPP).
    angle2: f64,
    /// Guide offset (RRP, PRP, RPP) in units of 0.2 m; RPR offset as a fraction of 0.8·|AC|.
    offset: f64,
    /// Distance of the joint from `a` (RRR), or along the guide from the foot of `a` (RRP).
    reach: f64,
    /// Direction of the joint from `a` (RRR); its sign picks the RRP branch.
    heading: f64,
    /// Put an RRR or RRP group exactly at its toggle (links in line, or the link ⊥ the
    /// guide): the plan must refuse it or construct it, never return a wrong number.
    toggle: bool,
    /// Where link 3 translates, carry a guide of the second group at a frame direction
    /// through its joint C (a block sliding on the slider) instead of along link 3.
    slider3: bool,
}

prop_compose! {
    fn draw()(
        kind in 0..5usize,
        carrier in 0..3usize,
        carrier2 in 0..3usize,
        angle in -PI..PI,
        angle2 in -PI..PI,
        offset in -1.0..1.0f64,
        reach in 0.08..0.4f64,
        heading in -PI..PI,
        toggle in prop::bool::weighted(0.15),
        slider3 in prop::bool::ANY,
    ) -> Draw {
        let kind = [DyadKind::Rrr, DyadKind::Rrp, DyadKind::Rpr, DyadKind::Prp, DyadKind::Rpp][kind];
        Draw { kind, carrier, carrier2, angle, angle2, offset, reach, heading, toggle, slider3 }
    }
}

/// A link that can carry guides: the frame or a translating link named by `link` (`along` =
/// None: a frame direction), or the direction between two of its points.
struct Carrier {
    along: Option<(&'static str, &'static str)>,
    through: &'static str,
    link: Option<u32>,
}

/// What is known when a dyad is attached: the positions at the drawn crank angle, the
/// moving point `a` the dyad hangs on, a second pivot `b`, and the guide carriers.
struct Known {
    p: HashMap<String, DVec2>,
    a: &'static str,
    b: &'static str,
    carriers: Vec<Carrier>,
}

impl Known {
    fn at(&self, n: &str) -> DVec2 {
        self.p[n]
    }
    /// A guide on carrier `c` with the turn `angle` and `offset`, and its line now
    /// (a point and the unit direction).
    fn guide(&self, c: usize, angle: f64, offset: f64) -> (Guide, DVec2, DVec2) {
        let c = &self.carriers[c % self.carriers.len()];
        let (dir, theta) = match c.along {
            None => (Dir::Fixed(angle), angle),
            Some((from, to)) => {
                let v = self.at(to) - self.at(from);
                (
                    Dir::Along {
                        from: from.into(),
                        to: to.into(),
                        angle,
                    },
                    v.y.atan2(v.x) + angle,
                )
            }
        };
        let u = DVec2::from_angle(theta);
        let g = Guide {
            through: c.through.into(),
            dir,
            offset,
            link: c.link,
        };
        (g, self.at(c.through) + u.perp() * offset, u)
    }
    /// The slide of an RPP: the guide carrier's kind of direction, turned by `angle`.
    fn slide(&self, c: usize, angle: f64) -> Dir {
        self.guide(c, angle, 0.0).0.dir
    }
}

/// The dyad of `d` attached to `k`, generated from its position: the joint is placed first
/// and the lengths measured, so every dyad assembles at the drawn angle with the branch the
/// joint lies on. `None` when a drawn length degenerates.
fn dyad(d: &Draw, k: &Known, joint: &str) -> Option<Dyad> {
    let pa = k.at(k.a);
    let joint = joint.to_string();
    Some(match d.kind {
        DyadKind::Rrr => {
            let pb = k.at(k.b);
            let x = if d.toggle {
                // Stretched in line: la + lb = |ab|.
                pa + (pb - pa) * (0.2 + 0.6 * (d.reach - 0.08) / 0.32)
            } else {
                pa + DVec2::from_angle(d.heading) * d.reach
            };
            let (la, lb) = (x.distance(pa), x.distance(pb));
            if la.min(lb) < 0.02 {
                return None;
            }
            let left = (pb - pa).perp_dot(x - pa) >= 0.0;
            Dyad::Rrr {
                a: k.a.into(),
                la,
                b: k.b.into(),
                lb,
                joint,
                branch: if left { Branch::Left } else { Branch::Right },
            }
        }
        DyadKind::Rrp => {
            let (guide, g, u) = k.guide(d.carrier, d.angle, 0.2 * d.offset);
            let t0 = (pa - g).dot(u);
            let dt = if d.toggle {
                0.0
            } else {
                d.reach.copysign(d.heading)
            };
            let la = (g + u * (t0 + dt)).distance(pa);
            if la < 0.02 {
                return None;
            }
            Dyad::Rrp {
                a: k.a.into(),
                la,
                guide,
                joint,
                branch: if dt >= 0.0 {
                    Branch::Forward
                } else {
                    Branch::Backward
                },
            }
        }
        DyadKind::Rpr => Dyad::Rpr {
            a: k.a.into(),
            c: k.b.into(),
            offset: 0.8 * d.offset * pa.distance(k.at(k.b)),
        },
        DyadKind::Prp => Dyad::Prp {
            guide_i: k.guide(d.carrier, d.angle, 0.2 * d.offset).0,
            guide_j: k.guide(d.carrier2, d.angle2, -0.1 * d.offset).0,
            joint,
        },
        DyadKind::Rpp => Dyad::Rpp {
            a: k.a.into(),
            slide: k.slide(d.carrier, d.angle2),
            guide: k.guide(d.carrier, d.angle, 0.2 * d.offset).0,
            joint,
        },
    })
}

/// A random mechanism of two groups at a random crank angle, within 1 m of O: group 1 (links 2, 3, joint C)
/// hangs on the crank pin and the frame, with guides on the frame or the crank; group 2
/// (links 4, 5, joint F) hangs on the point S3 of link 3 and the frame, with guides on the
/// frame, the crank or link 3 — a carrier with angular acceleration, or, where link 3
/// translates, a frame direction through its joint C that names link 3. Every link carries a
/// further point `S<link>` off its axis.
pub(crate) fn mechanism() -> impl Strategy<Value = (Mechanism, f64)> {
    (
        0.05..0.2f64,
        0.0..2.0 * PI,
        (0.15..0.4f64, -PI..PI),
        (0.15..0.4f64, -PI..PI),
        draw(),
        draw(),
    )
        .prop_filter_map("a drawn length degenerates", |(r, phi, d, e, g1, g2)| {
            let d = DVec2::from_angle(d.1) * d.0;
            let e = DVec2::from_angle(e.1) * e.0;
            let frame = [("O", DVec2::ZERO), ("D", d), ("E", e)];
            let k1 = Known {
                p: [
                    ("O", DVec2::ZERO),
                    ("B", DVec2::from_angle(phi) * r),
                    ("D", d),
                    ("E", e),
                ]
                .into_iter()
                .map(|(n, p)| (n.to_string(), p))
                .collect(),
                a: "B",
                b: "D",
                carriers: vec![
                    Carrier {
                        along: None,
                        through: "D",
                        link: None,
                    },
                    Carrier {
                        along: Some(("O", "B")),
                        through: "B",
                        link: None,
                    },
                ],
            };
            let mut m = one_group(
                fixed(&frame),
                r,
                dyad(&g1, &k1, "C")?,
                vec![point("S2", 2, 0.05, -0.02), point("S3", 3, 0.06, 0.03)],
            );
            let prog = Program::compile(&m).ok()?;
            let pose = prog.solve(phi, None).ok()?;
            // The other point of link 3 along which its guides run.
            let on3 = if g1.kind == DyadKind::Rpr { "D" } else { "C" };
            let slider3 = m.groups[0].translating().contains(&3) && g2.slider3;
            let k2 = Known {
                p: prog.names.iter().cloned().zip(pose.p).collect(),
                a: "S3",
                b: "E",
                carriers: vec![
                    Carrier {
                        along: None,
                        through: "E",
                        link: None,
                    },
                    Carrier {
                        along: Some(("O", "B")),
                        through: "O",
                        link: None,
                    },
                    // A frame direction through C on link 3 where link 3 translates (a block
                    // on the slider), else along link 3.
                    if slider3 {
                        Carrier {
                            along: None,
                            through: "C",
                            link: Some(3),
                        }
                    } else {
                        Carrier {
                            along: Some((on3, "S3")),
                            through: "S3",
                            link: None,
                        }
                    },
                ],
            };
            m.groups.push(Group {
                links: [4, 5],
                dyad: dyad(&g2, &k2, "F")?,
            });
            m.points
                .extend([point("S4", 4, 0.04, 0.02), point("S5", 5, 0.05, -0.03)]);
            // The drawings are sized for a 1 m mechanism (1000 mm at μ_l = 1 mm/mm):
            // guides that cross at a shallow angle put the joint far outside it.
            let pose = Program::compile(&m).ok()?.solve(phi, None).ok()?;
            pose.p.iter().all(|p| p.length() <= 1.0).then_some((m, phi))
        })
}

/// The generator reaches a second group whose guide keeps a frame direction through the
/// joint C of a translating link 3 (a block sliding on the slider), carried by the link it
/// names.
#[test]
fn the_generator_puts_guides_on_translating_links() {
    use proptest::strategy::ValueTree;
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let strategy = mechanism();
    let mut on_slider = 0;
    for _ in 0..400 {
        let Ok(tree) = strategy.new_tree(&mut runner) else {
            continue;
        };
        let (m, _) = tree.current();
        let carried = m.groups[1]
            .dyad
            .guides()
            .into_iter()
            .flatten()
            .any(|g| g.link == Some(3) && g.through == "C");
        on_slider += usize::from(carried);
    }
    assert!(on_slider >= 10, "{on_slider} of 400");
}
