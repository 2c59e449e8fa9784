//! The force polygons and the lever against the linear solve over random mechanisms of
//! every pair of dyad kinds with random loads, and the twin against the power balance; the
//! drawings predicted against the constructed (`predicted`), and a mechanism told wrongly
//! against the equilibrium check (`wrong_body`).

use super::loads::{loads, PositionMotion};
use super::polygons::{polygons, Board};
use super::twin::{power_balance, solve};
use super::*;
use crate::linkage::proptests::{build, gen, plan_context};
use crate::linkage::{kin_plan, Mechanism, PlanKind, PlanSetup};
use proptest::prelude::*;

mod predicted;
mod wrong_body;

/// Relative tolerance of polygon = lever = twin at drafting 0 (the plans' own, see
/// `linkage::proptests::plans`).
const REL: f64 = 1e-9;
/// Crossing sine from which positions are compared (as the plans' properties).
const WELL: f64 = 1e-2;

fn spec(masses: &[(f64, f64)], f5: (f64, f64), gear: Option<f64>) -> ForceSpec {
    ForceSpec {
        g: crate::scale::G,
        gravity_dir: -std::f64::consts::FRAC_PI_2,
        positions: vec!["1".into()],
        scale_f: None,
        links: masses
            .iter()
            .enumerate()
            .map(|(i, &(m, inertia))| LinkMass {
                link: i as u32 + 2,
                mass: m,
                centre: format!("S{}", i + 2),
                inertia,
                length: None,
            })
            .collect(),
        resistances: vec![Resistance {
            action: Action::Force {
                point: "S5".into(),
                link: None,
                magnitude: f5.0,
                dir: Some(f5.1),
            },
            stroke: Stroke::Always,
        }],
        indicators: Vec::new(),
        efficiency: None,
        drive: match gear {
            None => Drive::Coupling,
            Some(towards) => Drive::Gear(GearDrive {
                module: 0.004,
                teeth: 40,
                mate_teeth: Some(20),
                pressure_angle: 20f64.to_radians(),
                towards,
            }),
        },
        friction: None,
        seed: Vec::new(),
    }
}

/// One random position set up for its force analysis: the constructed position, its pose,
/// plans, both motions and both sets of loads, and μ_F.
struct Case {
    mech: Mechanism,
    prog: crate::linkage::Program,
    built: crate::linkage::Built,
    pose: crate::linkage::Pose,
    vp: crate::linkage::KinPlan,
    exact: PositionMotion,
    drawn: PositionMotion,
    le: Vec<Load>,
    lg: Vec<Load>,
    twin: Equilibrium,
    mu_l: Scale,
    mu_f: Scale,
}

const W1: f64 = -7.0;

fn case(m: &Mechanism, phi: f64, spec: &ForceSpec) -> Result<Case, TestCaseError> {
    let (prog, built, pose) =
        build(m, phi).ok_or_else(|| TestCaseError::reject("not assembled"))?;
    let s = pose.crossing_sin.iter().copied().fold(1.0, f64::min);
    prop_assume!(s >= WELL);
    let r = prog.crank_length;
    let mu_l = Scale::new(0.001, Quantity::Length).unwrap();
    let sv = Scale::new(W1.abs() * r / 50.0, Quantity::Velocity).unwrap();
    let sa = Scale::new(W1 * W1 * r / 50.0, Quantity::Acceleration).unwrap();
    let setup = PlanSetup {
        prog: &prog,
        built: &built,
        mu_l,
        w1: W1,
        ctx: plan_context(),
    };
    let vp = kin_plan(&setup, PlanKind::Velocity, sv, None)
        .map_err(|_| TestCaseError::reject("plan refused"))?;
    let ap = kin_plan(&setup, PlanKind::Acceleration, sa, Some(&vp))
        .map_err(|_| TestCaseError::reject("plan refused"))?;
    let exact = PositionMotion::analytic(&pose, W1);
    let le = loads(spec, &prog, &exact, None).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let twin = match solve(&prog, &pose, &le, &spec.drive, W1.signum()) {
        Ok(t) => t,
        Err(ForceError::Singular) => return Err(TestCaseError::reject("singular")),
        Err(e) => return Err(TestCaseError::fail(e.to_string())),
    };
    let drawn = PositionMotion {
        p: built.p.iter().map(|x| *x * mu_l.value()).collect(),
        v: vp.images.iter().map(|x| *x * sv.value()).collect(),
        a: ap.images.iter().map(|x| *x * sa.value()).collect(),
        omega: vp.rate.clone(),
        eps: ap.rate.clone(),
    };
    let lg = loads(spec, &prog, &drawn, None).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let big = twin.largest().max(1e-3);
    let mu_f = Scale::round_for(big, 100.0, Quantity::Force).unwrap();
    Ok(Case {
        mech: m.clone(),
        prog,
        built,
        pose,
        vp,
        exact,
        drawn,
        le,
        lg,
        twin,
        mu_l,
        mu_f,
    })
}

impl Case {
    fn board(&self) -> Board<'_> {
        Board {
            setup: PlanSetup {
                prog: &self.prog,
                built: &self.built,
                mu_l: self.mu_l,
                w1: W1,
                ctx: plan_context(),
            },
            mu_f: self.mu_f,
            own: Vec::new(),
        }
    }

    /// The position with friction in the pairs; a self-locking or singular position is
    /// rejected.
    fn with_friction(
        &self,
        spec: &ForceSpec,
        fr: &super::pair_friction::PairFriction,
    ) -> Result<WithFriction, TestCaseError> {
        let board = self.board();
        let route = Route {
            board: &board,
            vp: &self.vp,
            pose: &self.pose,
            drawn: &self.drawn,
            exact: &self.exact,
            loads: &self.lg,
            loads_exact: &self.le,
            label: "1",
        };
        match with_friction(spec, fr, &route) {
            Ok(w) => Ok(w),
            Err(
                ForceError::SelfLocking { .. }
                | ForceError::Singular
                | ForceError::SingularAt { .. },
            ) => Err(TestCaseError::reject("self-locking")),
            Err(e) => Err(TestCaseError::fail(e.to_string())),
        }
    }
}

/// Everything one random position gives: the twin, the polygons, the lever, the power.
fn analyse_random(
    m: &Mechanism,
    phi: f64,
    spec: &ForceSpec,
) -> Result<(Equilibrium, Polygons, lever::Lever, f64), TestCaseError> {
    let c = case(m, phi, spec)?;
    let power = power_balance(&c.le, &c.exact, W1);
    let pol = polygons(&c.board(), &c.lg, &spec.drive)
        .map_err(|(g, e)| TestCaseError::fail(format!("group {g}: {e}")))?;
    let board = c.board();
    let lev = lever::lever(&board.setup, &c.vp, &c.lg, &spec.drive, pol.arms);
    Ok((c.twin, pol, lev, power))
}

proptest! {
    // Random mechanisms are often not assembled or cross too flatly: rejected cases are
    // cheap, so allow many of them (a long run with PROPTEST_CASES must not abort).
    #![proptest_config(ProptestConfig { cases: 400, max_global_rejects: 1 << 20, ..ProptestConfig::default() })]

    /// Every group's polygon gives the linear solve's reactions, the driving link its
    /// balancing moment, the lever the same, and the power balance the same.
    #[test]
    fn polygons_and_lever_equal_the_linear_solve(
        (m, phi) in gen::mechanism(),
        masses in proptest::collection::vec((0.1..20.0f64, 0.0..0.5f64), 4),
        f5 in (1.0..500.0f64, -3.2..3.2f64),
        gear in proptest::option::of(-3.2..3.2f64),
    ) {
        let spec = spec(&masses, f5, gear);
        let (twin, pol, lev, power) = analyse_random(&m, phi, &spec)?;
        let big = twin.largest();
        let mut compared = 0;
        let graphical = pol.groups.iter().flat_map(|g| g.reactions.iter()).chain([&pol.driver.reaction]);
        for g in graphical {
            let t = twin.reaction(g.pair.from, g.pair.to).expect("the same pair in the twin");
            prop_assert!((g.force - t).length() <= REL * (big + t.length()), "R_{}_{}: {} vs {}", g.pair.from, g.pair.to, g.force, t);
            compared += 1;
        }
        prop_assert_eq!(compared, twin.reactions.len());
        // Every moment equation the drawings work balances with its unknown put in.
        let eqs = pol.groups.iter().flat_map(|g| &g.equations).chain([&pol.driver.equation, &lev.equation]);
        for e in eqs {
            let scale = e.terms.iter().map(|t| t.moment.abs()).fold(e.known().abs(), f64::max);
            prop_assert!(e.residue().abs() <= 1e-9 * scale.max(1e-12), "{e:?}");
        }
        let mb = twin.m_bal.abs() + big * 0.2;
        prop_assert!((pol.driver.m_bal - twin.m_bal).abs() <= REL * mb, "polygon {} vs {} (lever {}, power {}) {:?}", pol.driver.m_bal, twin.m_bal, lev.m_bal, power, twin.reactions.iter().map(|r| (r.pair.from, r.pair.to, r.offset)).collect::<Vec<_>>());
        prop_assert!((lev.m_bal - twin.m_bal).abs() <= REL * mb, "lever {} vs {}", lev.m_bal, twin.m_bal);
        prop_assert!((power - twin.m_bal).abs() <= REL * mb, "power {} vs {}", power, twin.m_bal);
        if let (Some(f), Some(t)) = (pol.driver.f_bal, twin.f_bal) {
            prop_assert!((f - t).abs() <= REL * (t.abs() + big));
            // A tooth only pushes: the force is on the flank that turns the crank as M_bal.
            prop_assert!(t >= 0.0 && f >= -REL * big, "F_bal {t} (polygon {f})");
            prop_assert!(lev.f_bal.is_some_and(|l| (l - t).abs() <= REL * (t + big)));
        }
    }

    /// With every load zero, every reaction and the balancing moment are zero.
    #[test]
    fn a_group_without_loads_has_no_reactions((m, phi) in gen::mechanism()) {
        let mut spec = spec(&[], (1.0, 0.0), None);
        spec.resistances.clear();
        let (twin, pol, lev, power) = analyse_random(&m, phi, &spec)?;
        for r in twin.reactions.iter().chain(pol.groups.iter().flat_map(|g| g.reactions.iter())) {
            prop_assert_eq!(r.force, crate::geom::DVec2::ZERO);
        }
        prop_assert_eq!(twin.m_bal, 0.0);
        prop_assert_eq!(pol.driver.m_bal, 0.0);
        prop_assert_eq!(lev.m_bal, 0.0);
        prop_assert_eq!(power, 0.0);
    }
}

proptest! {
    // Random mechanisms are often not assembled or cross too flatly: rejected cases are
    // cheap, so allow many of them (a long run with PROPTEST_CASES must not abort).
    #![proptest_config(ProptestConfig { cases: 200, max_global_rejects: 1 << 20, ..ProptestConfig::default() })]

    /// With friction in the pairs (successive approximations) the polygons, the lever and
    /// the power balance still equal the linear solve; a sliding pair's total reaction is
    /// turned from the normal by exactly φ = arctg f, a journal's reaction is tangent to its
    /// friction circle against the relative rotation, and the balancing moment's power grows
    /// by exactly the power the pairs lose.
    #[test]
    fn friction_turns_the_reactions_and_costs_power(
        (m, phi) in gen::mechanism(),
        masses in proptest::collection::vec((0.1..20.0f64, 0.0..0.5f64), 4),
        f5 in (1.0..500.0f64, -3.2..3.2f64),
        gear in proptest::option::of(-3.2..3.2f64),
        f in 0.01..0.3f64,
        radius in 0.0..0.03f64,
    ) {
        use super::pair_friction::PairFriction;
        use crate::friction::{friction_angle, friction_circle_tangent};
        let mut spec = spec(&masses, f5, gear);
        let fr = PairFriction { f, radius, radii: Vec::new() };
        spec.friction = Some(fr.clone());
        let c = case(&m, phi, &spec)?;
        let w = c.with_friction(&spec, &fr)?;
        let big = w.analysis.twin.largest();
        for g in w.analysis.polygons.reactions() {
            let t = w.analysis.twin.reaction(g.pair.from, g.pair.to).expect("the same pair in the twin");
            prop_assert!((g.force - t).length() <= REL * (big + t.length()), "R_{}_{}: {} vs {}", g.pair.from, g.pair.to, g.force, t);
        }
        let mb = w.analysis.twin.m_bal.abs() + big * 0.2;
        prop_assert!((w.analysis.polygons.driver.m_bal - w.analysis.twin.m_bal).abs() <= REL * mb);
        prop_assert!((w.analysis.lever.m_bal - w.analysis.twin.m_bal).abs() <= REL * mb, "lever {} vs {}", w.analysis.lever.m_bal, w.analysis.twin.m_bal);
        prop_assert!((w.analysis.m_power - w.analysis.twin.m_bal).abs() <= REL * mb, "power {} vs {}", w.analysis.m_power, w.analysis.twin.m_bal);
        // The balancing moment's power grows by what the pairs lose.
        prop_assert!(w.lost <= 0.0);
        let gained = (w.analysis.twin.m_bal - c.twin.m_bal) * W1;
        prop_assert!((gained + w.lost).abs() <= REL * (mb + c.twin.m_bal.abs()) * W1.abs(), "{gained} vs {}", w.lost);
        let omega = |l: usize| if l == 0 { 0.0 } else { c.exact.omega[l] };
        let rows = super::rows::reaction_rows("p", "_f", &w.analysis);
        for r in &w.analysis.twin.reactions {
            let (from, to) = (r.pair.from, r.pair.to);
            match r.pair.kind {
                PairKind::Prismatic { .. } => {
                    let name = format!("F_{{тр{from}-{to}}}");
                    let Some(fl) = w.analysis.loads_exact.iter().find(|l| l.link == to && l.name == name) else {
                        continue;
                    };
                    // The friction load is f·|R| of the previous approximation's R, which
                    // differs from the last by the settling tolerance (1e-13 of the largest
                    // reaction): compare where R is not tiny against that.
                    if r.force.length() < 1e-3 * big {
                        continue;
                    }
                    let total = r.force + fl.force;
                    let turned = r.force.angle_to(total).abs();
                    prop_assert!((turned - friction_angle(f)).abs() <= 1e-9, "turned {turned} vs φ {}", friction_angle(f));
                    // The row R_i_j_f is that total reaction, N·√(1 + f²), by both routes
                    // (not the normal force N the analysis solves for).
                    let q = format!("R_{from}_{to}_f");
                    let row = rows.iter().find(|x| x.quantity() == q).expect("the row");
                    let want = r.force.length() * (1.0 + f * f).sqrt();
                    prop_assert!((row.analytic - want).abs() <= 1e-9 * big, "{q}: {} vs N√(1 + f²) = {want}", row.analytic);
                    prop_assert!((row.graphical - want).abs() <= 1e-9 * big, "{q}: {} vs {want}", row.graphical);
                }
                PairKind::Revolute(k) => {
                    let name = format!("M_{{тр{from}-{to}}}");
                    let Some(fl) = w.analysis.loads_exact.iter().find(|l| l.link == to && l.name == name) else {
                        continue;
                    };
                    let rho = f * radius;
                    prop_assert!((fl.moment.abs() - rho * r.force.length()).abs() <= 1e-12 * big);
                    // R carried tangent to the friction circle has the couple's moment.
                    let centre = c.pose.p[k];
                    let line = friction_circle_tangent(centre, r.force, omega(to) - omega(from), rho).expect("a line");
                    // Its arm is a difference of points the size of the centre's: rounded
                    // to about 1e-16 of that, which a journal 1e-7 m across (ρ = 1e-9 m)
                    // feels.
                    let moment = (line.point - centre).perp_dot(r.force);
                    let rounding = 1e-13 * centre.length() * big;
                    prop_assert!((moment - fl.moment).abs() <= 1e-9 * (big * rho + 1e-12) + rounding, "{moment} vs {}", fl.moment);
                }
            }
        }
    }
}

/// A load at point `name` of the random mechanism, on the link the scene would name when the
/// point is a joint that needs one (`pick` chooses among the links there), with a 50 %
/// chance of naming a link anyway.
fn joint_load(
    prog: &crate::linkage::Program,
    name: &str,
    pick: usize,
    named: bool,
    force: (f64, f64),
) -> Option<Resistance> {
    let k = prog.index(name)?;
    let links: Vec<u32> = prog
        .links_of(k)
        .into_iter()
        .filter(|&l| l != 0)
        .map(|l| l as u32)
        .collect();
    let choice = links.get(pick % links.len().max(1)).copied();
    let link = match loads::carrier(prog, k, None) {
        Ok(_) if !named => None,
        Ok(_) | Err(loads::Uncarried::Ambiguous { .. }) => choice,
        Err(_) => return None,
    };
    Some(Resistance {
        action: Action::Force {
            point: name.into(),
            link,
            magnitude: force.0,
            dir: Some(force.1),
        },
        stroke: Stroke::Always,
    })
}

/// Both residuals of a route: its reactions and balancing load on the check's own picture
/// and motion.
fn verdict_of(
    spec: &ForceSpec,
    c: &Case,
    drawn: bool,
    reported: residual::Reported<'_>,
) -> residual::Residuals {
    let built_dir: Vec<crate::geom::DVec2> = c
        .built
        .angle
        .iter()
        .map(|a| crate::geom::DVec2::from_angle(*a))
        .collect();
    let state = residual::State {
        motion: if drawn { &c.drawn } else { &c.exact },
        dir: if drawn { &built_dir } else { &c.pose.dir },
        w1: W1,
        phase: None,
    };
    residual::residual(
        spec,
        &c.mech,
        &c.prog,
        &state,
        &reported,
        spec.friction.as_ref(),
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, max_global_rejects: 1 << 20, ..ProptestConfig::default() })]

    /// Loads at joints (the crank pin, the groups' joints), at centres of mass and at points
    /// off the links' axes, on the link the rule gives or the scene names, with and without
    /// friction: every moving link's own equations hold for the polygons' and the linear
    /// solve's reactions to 1e-9 of the largest force.
    #[test]
    fn every_link_is_in_equilibrium(
        (m, phi) in gen::mechanism(),
        masses in proptest::collection::vec((0.1..20.0f64, 0.0..0.5f64), 4),
        f5 in (1.0..500.0f64, -3.2..3.2f64),
        gear in proptest::option::of(-3.2..3.2f64),
        at in proptest::sample::select(vec!["B", "C", "F", "S2", "S3", "S4", "S5"]),
        pick in 0usize..2,
        named in proptest::bool::ANY,
        force in (1.0..800.0f64, -3.2..3.2f64),
        friction in proptest::option::of((0.01..0.3f64, 0.0..0.03f64)),
    ) {
        use super::pair_friction::PairFriction;
        let mut spec = spec(&masses, f5, gear);
        let prog = crate::linkage::Program::compile(&m).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let Some(extra) = joint_load(&prog, at, pick, named, force) else {
            return Err(TestCaseError::reject("no such point"));
        };
        spec.resistances.push(extra);
        let c = case(&m, phi, &spec)?;
        let pol = polygons(&c.board(), &c.lg, &spec.drive)
            .map_err(|(g, e)| TestCaseError::fail(format!("group {g}: {e}")))?;
        let t = verdict_of(&spec, &c, false, reported(&c.twin.reactions, c.twin.m_bal, c.twin.f_bal));
        prop_assert!(t.equilibrium <= REL && t.power <= REL, "twin residual {t:?}");
        let r = pol.reactions();
        let p = verdict_of(&spec, &c, true, reported(&r, pol.driver.m_bal, pol.driver.f_bal));
        prop_assert!(p.equilibrium <= REL && p.power <= REL, "polygons residual {p:?}");
        if let Some((f, radius)) = friction {
            let fr = PairFriction { f, radius, radii: Vec::new() };
            spec.friction = Some(fr.clone());
            let w = c.with_friction(&spec, &fr)?;
            let t = verdict_of(&spec, &c, false, reported(&w.analysis.twin.reactions, w.analysis.twin.m_bal, w.analysis.twin.f_bal));
            prop_assert!(t.equilibrium <= REL && t.power <= REL, "twin residual with friction {t:?}");
            let r = w.analysis.polygons.reactions();
            let p = verdict_of(&spec, &c, true, reported(&r, w.analysis.polygons.driver.m_bal, w.analysis.polygons.driver.f_bal));
            prop_assert!(p.equilibrium <= REL && p.power <= REL, "polygons residual with friction {p:?}");
        }
    }

    /// The residual sees a load put on the wrong link: the reactions of the load at a
    /// slider's joint solved on the other link leave a residual of the load's size.
    #[test]
    fn a_load_on_the_wrong_link_leaves_a_residual(
        (m, phi) in gen::mechanism(),
        force in (100.0..800.0f64, -3.2..3.2f64),
    ) {
        let prog = crate::linkage::Program::compile(&m).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let Some(k) = prog.index("C") else { return Err(TestCaseError::reject("no joint C")) };
        let Ok(right) = loads::carrier(&prog, k, None) else {
            return Err(TestCaseError::reject("C needs a named link"));
        };
        let Some(wrong) = prog.links_of(k).into_iter().find(|&l| l != 0 && l != right) else {
            return Err(TestCaseError::reject("one link at C"));
        };
        let mut spec = spec(&[], (1.0, 0.0), None);
        spec.resistances = vec![joint_load(&prog, "C", 0, false, force).expect("C is loaded")];
        let c = case(&m, phi, &spec)?;
        // The same load solved on the wrong link, as both routes did before the fix.
        let misplaced: Vec<Load> = c.le.iter().cloned().map(|l| Load { link: wrong, ..l }).collect();
        let Ok(twin) = solve(&c.prog, &c.pose, &misplaced, &spec.drive, W1.signum()) else {
            return Err(TestCaseError::reject("singular"));
        };
        let reported = residual::Reported { reactions: &twin.reactions, m_bal: twin.m_bal, f_bal: twin.f_bal };
        let t = verdict_of(&spec, &c, false, reported);
        // The inner pair's reaction is off by the whole load unless the group is at a toggle.
        prop_assert!(t.equilibrium > 1e-3, "residual {t:?} of a misplaced load");
    }
}

/// What a route reports, for [`residual_of`].
fn reported(reactions: &[Reaction], m_bal: f64, f_bal: Option<f64>) -> residual::Reported<'_> {
    residual::Reported {
        reactions,
        m_bal,
        f_bal,
    }
}
