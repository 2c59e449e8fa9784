//! Every typed note written in English exactly as the studies wrote it before their notes were
//! typed: hand-built notes against the sentences of the shipped scenes' reports (their
//! numbers), the cases no shipped scene reaches, and whole scenes through the session.

use super::english;
use crate::check::notes::balancing::{BalancingNote, Inertia};
use crate::check::notes::forces::{ForcesNote, PositionFriction};
use crate::check::notes::friction::{FrictionNote, RollerMotion, SliderMotion};
use crate::check::notes::kinematics::{KinematicsNote, PinNearPivot};
use crate::check::notes::seed::{Analysed, SeedNote};
use crate::check::notes::train::{
    Across, Closing, FormulaBy, MeshNeeds, MeshRatio, SatelliteAssembly, SeedStage, SolvedFor,
    TrainNote, WillisDifferential,
};
use crate::check::{Method, ReportNote, SeedValue};
use crate::construct::Drafting;

/// `note` reads `text` in English.
pub(super) fn says(note: impl Into<ReportNote>, text: &str) {
    assert_eq!(english(&note.into()), text);
}

/// An owned string.
pub(super) fn s(x: &str) -> String {
    x.to_string()
}

#[test]
fn a_trains_notes_read_as_the_differential_scene_printed_them() {
    says(
        TrainNote::Inversion {
            rpm: true,
            cells: vec![(s("3"), 1000.0, 640.0), (s("4"), -200.0 / 3.0, -1280.0 / 3.0)],
        },
        "train: inversion (Willis): n before → n − n_H after stopping the carrier, rpm: 3: 1000 → 640; 4: −66.6667 → −426.667",
    );
    says(
        TrainNote::Mobility {
            n: 4,
            p5: 4,
            p4: 2,
            w: 2,
            inputs: Some((s("3"), s("5"), 1000.0, 200.0)),
        },
        "train: W = 3n − 2p5 − p4 = 3·4 − 2·4 − 2 = 2 (a differential: the inputs 3 and 5, n = 1000 and 200 rpm)",
    );
    says(
        TrainNote::Ratio {
            ratio: 25.0 / 9.0,
            formula: Some((25.0 / 9.0, FormulaBy::Differential)),
        },
        "train: u = 2.777778 by Willis, 2.777778 by Willis's formula of the differential; the output turns with the input",
    );
    says(
        TrainNote::Ratio {
            ratio: -9.308176,
            formula: Some((-9.308176, FormulaBy::Stages)),
        },
        "train: u = −9.308176 by Willis, −9.308176 by the stages; the output turns against the input",
    );
    let differential = |solved| WillisDifferential {
        names: [s("3"), s("5"), s("H")],
        meshes: vec![
            MeshRatio {
                negative: true,
                driven: 30.0,
                driving: 20.0,
            },
            MeshRatio {
                negative: false,
                driven: 80.0,
                driving: 30.0,
            },
        ],
        u: -4.0,
        solved,
        output: 360.0,
        speeds: [1000.0, 200.0, 360.0],
    };
    says(
        TrainNote::Differential(differential(SolvedFor::Carrier)),
        "train: a differential by Willis's formula: u = u35^(H) = (n3 − nH)/(n5 − nH) = (−30/20)·(80/30) = −4; nH = (n3 − u·n5)/(1 − u) = 360 rpm (n3 = 1000, n5 = 200, nH = 360 rpm)",
    );
    let solved = |s| english(&TrainNote::Differential(differential(s)).into());
    assert!(solved(SolvedFor::A).contains("; n3 = nH + u·(n5 − nH) = 360 rpm"));
    assert!(solved(SolvedFor::B).contains("; n5 = nH + (n3 − nH)/u = 360 rpm"));
}

#[test]
fn a_closing_mesh_reads_as_pz2_example_1_printed_it() {
    let across = |a: &str, b: &str| Across {
        first: s(a),
        second: s(b),
        ring: false,
    };
    says(
        TrainNote::Closing(Closing {
            mesh: (s("3"), s("4")),
            arm_mesh: (s("1"), s("2")),
            module: 1e-3,
            arm_across: across("1", "2"),
            arm: 0.068,
            across: across("3", "4"),
            teeth: 48.0,
            closing: 0.068 * 2.0 / 48.0,
            wheel: s("4"),
        }),
        "train: the source gives no module of the mesh 3–4: at the train's m = 1 mm the tooth sums do not close — the mesh 1–2 sets the carrier's arm a = m(z1 + z2)/2 = 68 mm, the mesh 3–4 reaches m(z3 + z4)/2 = 24 mm — so the train as given cannot be assembled; Willis's relations use the teeth only, and the velocity triangles take the mesh 3–4 at m′ = 2a/(z3 + z4) = 2.83333 mm (assumed: the module that brings wheel 4 onto the carrier's axis)",
    );
}

#[test]
fn a_seeds_train_values_read_as_reproduced_or_as_an_erratum() {
    says(
        TrainNote::SeedMobility { w: 1 },
        "train: the seed's W = 1 reproduced",
    );
    says(
        TrainNote::SeedMobilityErratum {
            printed: 2,
            n: 4,
            p5: 4,
            p4: 3,
            w: 1,
        },
        "train: erratum: the seed prints W = 2; W = 3·4 − 2·4 − 3 = 1",
    );
    says(
        TrainNote::SeedRatio {
            name: s("u_1_7"),
            printed: 20.0,
            ratio: 20.0,
        },
        "train: the seed's u_1_7 = 20 reproduced (Willis 20)",
    );
    says(
        TrainNote::SeedRatioErratum {
            name: s("u_1_H"),
            printed: 20.0,
            ratio: 32.0,
            formula: Some(32.0),
            triangles: 32.0,
            stage: Some(SeedStage {
                a: s("3"),
                f: s("6"),
                needed: 6.0,
                teeth: 9.0,
            }),
        },
        "train: erratum: the seed prints u_1_H = 20; Willis's relations give 32, the formula 32, the triangles 32; with the other stages as their teeth give, 20 needs u_36^(H) = 6 of the planetary stage, whose teeth give 9",
    );
}

#[test]
fn a_required_ratio_and_the_best_teeth_read_as_the_shaper_printed_them() {
    let (n_in, n_out, ratio) = (1400.0, 150.0, 9.308176);
    says(
        TrainNote::Required {
            n_in,
            n_out,
            required: n_in / n_out,
            ratio,
        },
        "train: required |u| = 1400/150 = 9.33333; the tooth numbers give 9.30818 (n_out = 150.405 rpm, −0.27 %)",
    );
    says(
        TrainNote::MeshNeeds(MeshNeeds {
            names: (s("1"), s("2")),
            want: 2.558621,
            best: vec![(34, 87, 0.0000793), (18, 46, -0.0012)],
            n_out,
            now: (29.0, 74.0),
        }),
        "train: mesh 1–2 needs z2/z1 = 2.55862: best 87/34 (0.00793 %, n_out = 149.988 rpm), 46/18 (−0.12 %, n_out = 150.18 rpm) (now 74/29 = 2.5517)",
    );
}

#[test]
fn the_satellites_conditions_read_as_pz2_printed_them_and_say_when_they_fail() {
    let neighbour = |chord| TrainNote::Neighbour {
        k: 4,
        chord,
        wheel: s("4"),
        tip: 0.064,
    };
    says(
        neighbour(0.0707107),
        "train: neighbour condition, k = 4: 2·a·sin(π/k) = 70.711 mm > d_a4 = 64 mm",
    );
    says(
        neighbour(0.06),
        "train: neighbour condition, k = 4: 2·a·sin(π/k) = 60 mm ≤ (fails:) d_a4 = 64 mm",
    );
    let assembly = |value, p, block, fits| {
        TrainNote::Assembly(SatelliteAssembly {
            k: 2,
            central: s("3"),
            fixed: s("6"),
            value,
            p,
            block,
            fits,
        })
    };
    says(
        assembly((-145, 3), Some(1), Some((-145, 1)), Ok(())),
        "train: assembly condition, k = 2: z3·u3H^(6)/k = (−145/3), (1 + kp)·(−145/3) whole for p = 1 (the textbook's); for identical blocks, z3·u3H·(z_f/gcd(z_g, z_f))/k = (−145): the 2 satellites assemble spaced equally",
    );
    says(
        assembly((25, 2), None, None, Err(vec![3, 5])),
        "train: assembly condition, k = 2: z3·u3H^(6)/k = 25/2, (1 + kp)·25/2 never whole (the textbook's): fails: 2 satellites cannot be spaced equally; k = 3, 5 can (assembly and neighbour)",
    );
}

#[test]
fn a_positions_forces_read_as_the_shaper_and_the_slider_crank_printed_them() {
    says(
        ForcesNote::PowerBalance {
            label: s("3"),
            power: -258.7523094,
            solve: -258.7523094,
        },
        "position 3: the balancing moment by the power balance Σ F·v + Σ M·ω + M_bal·ω₁ = 0 is −258.7523094 N·m; the linear solve of the links' equilibrium gives −258.7523094 N·m",
    );
    let lever = |polygons, lever| ForcesNote::Lever {
        label: s("3"),
        polygons,
        lever,
    };
    says(
        lever(-258.752, -258.752),
        "position 3: M_bal by the force polygons −258.752 N·m, by Zhukovsky's lever −258.752 N·m: they differ by 0 % of the polygons' value",
    );
    says(
        lever(-200.0, -201.0),
        "position 3: M_bal by the force polygons −200 N·m, by Zhukovsky's lever −201 N·m: they differ by 0.5 % of the polygons' value",
    );
    says(
        lever(0.0, 1.0),
        "position 3: M_bal by the force polygons 0 N·m, by Zhukovsky's lever 1 N·m: they differ by 0 % of the polygons' value",
    );
    says(
        ForcesNote::Friction {
            label: s("2"),
            friction: PositionFriction {
                with: 50.24377433,
                without: 43.86900985,
                lost: 200.269,
                by_power: 50.24377433,
                approximations: [6, 6],
            },
        },
        "position 2: with friction in the pairs M_bal_f = 50.24377433 N·m against M_bal = 43.86900985 N·m without: the pairs lose 200.269 W, the instantaneous efficiency η = M_bal/M_bal_f = 0.8731; the power balance with the friction's power gives 50.24377433 N·m; the friction equations (Newton's method on the friction loads' magnitudes) took 6 drawings of the force polygons and 6 linear solves",
    );
    says(
        ForcesNote::Opposes {
            label: s("7"),
            moment: 12.5,
            force: 300.0,
        },
        "position 7: the balancing moment 12.5 N·m opposes ω₁: the pinion holds the crank back, so its tooth pushes on the other flank and the balancing force F_bal = 300 N acts on the line of action mirrored about the line of centres",
    );
    says(
        ForcesNote::SliderOutside {
            label: s("5"),
            pair: (0, 5),
            force: 100.0,
            offset: 0.06,
            length: 0.1,
            ends: [110.0, -10.0],
        },
        "position 5: the reaction R_0_5 = 100 N acts 0.06 m from the slider's centre, outside the slider (length 0.1 m): a force at the centre and a couple on the ends, which carry 110 N and −10 N",
    );
}

#[test]
fn a_seeds_value_reads_as_off_by_its_per_cent_or_as_without_a_row() {
    let seed = |printed: &str| SeedValue {
        quantity: s("r_b1"),
        position: None,
        method: None,
        value: 0.08138,
        printed: s(printed),
        printed_value: 81.38,
        printed_unit: "mm",
        source: s("seed 000 §4"),
        why: None,
    };
    let note = |printed: &str, row| SeedNote {
        seed: seed(printed),
        row,
    };
    let row = Some(Analysed {
        graphical: 0.085512,
        analytic: 0.085512,
        unit: "m",
    });
    says(
        note("81.38 mm", row.clone()),
        "r_b1: the seed prints 81.38 mm = 0.08138 m (seed 000 §4); this analysis gives 0.085512 m (analytic 0.085512 m): the seed's value is −4.83 % off and is not reproduced",
    );
    says(
        note("0.08138 m", row),
        "r_b1: the seed prints 0.08138 m (seed 000 §4); this analysis gives 0.085512 m (analytic 0.085512 m): the seed's value is −4.83 % off and is not reproduced",
    );
    says(
        SeedNote {
            seed: SeedValue {
                position: Some(s("3")),
                method: Some(Method::Lever),
                ..seed("109 kgf")
            },
            row: None,
        },
        "position 3: r_b1 (lever): the seed prints 109 kgf (seed 000 §4), but this report has no such row",
    );
}

#[test]
fn balancing_notes_read_as_the_rotors_printed_them() {
    let ball = Inertia {
        index: 1,
        mass: 0.1,
        radius: 0.1,
        omega: 300.0,
        force: 900.0,
        weight: 0.981,
        g: 9.81,
    };
    says(
        BalancingNote::Inertia(ball.clone()),
        "balancing: m1 = 0.1 kg at ρ = 0.1 m, ω = 300 rad/s: inertia force P = m·ω²·ρ = 900 N; weight G = m·g = 0.981 N (g = 9.81 m/s²); P/G = ω²·ρ/g = 917.4",
    );
    says(
        BalancingNote::W4Erratum(ball),
        "balancing: erratum of seed 001 (lecture 19, W4: m = 0.1 kg, l = 0.1 m, ω = 300 1/s): its inertia force P = 900 N is called \"900 times\" the ball's weight; with g = 9.81 m/s² the ratio is 900 N / 0.981 N = 917.4 (900 holds only for g = 10 m/s²)",
    );
    says(
        BalancingNote::NoCorrection { plane: s("I") },
        "balancing: plane I: m·ρ = 0, no correcting mass is needed",
    );
}

#[test]
fn friction_notes_read_as_the_friction_scenes_printed_them() {
    let deg = f64::to_radians;
    says(
        FrictionNote::Guide {
            case: s("guide"),
            angle: deg(30.0),
            lock: deg(59.04),
            useful: 765.0058,
            across: 441.6763,
        },
        "guide: the follower moves while λ = 30.00° < λ_кр = 59.04° (tg λ_кр = b/(f(2l + b))); P·cos λ = 765.0058 N = Q + f(N₁ + N₂), the useful part of P; P·sin λ = 441.6763 N loads the guide",
    );
    says(
        FrictionNote::Pivot {
            case: s("pivot"),
            angle: deg(45.0),
            lock: deg(86.57),
            rho: 0.007184,
            lecture: deg(86.42),
        },
        "pivot: the rocker moves while λ = 45.00° < λ_кр = 86.57° (cos λ_кр = ρ/L, ρ = (d/2)·sin φ = 0.007184 m); the lecture's M_тр = P^n·f·d/2 gives tg λ_кр = 2L/(f·d): λ_кр = 86.42°",
    );
    for (up, sign) in [(true, "+"), (false, "−")] {
        says(
            FrictionNote::InclineErratum { case: s("up"), up },
            &format!("up: twin P = Q·sin(α {sign} φ)/cos(α {sign} φ − β′) from the vector solution of Q + P + R = 0; the seed's printed P = Q·sin(α + φ)/cos(α + β + φ) is an erratum (sin[π − x] is not cos x)"),
        );
        says(
            FrictionNote::ScrewErratum { case: s("M20"), up },
            &format!("M20: screw as an inclined plane of the lead angle, P = Q·tg(λ {sign} φ′), f′ = f/cos(δ/2); the seed's substitution cos(λ + π/2 + φ) = cos(λ + φ) is false as written"),
        );
    }
    says(
        FrictionNote::SelfLocking {
            case: s("M20"),
            lead: deg(2.5),
            phi: deg(9.83),
        },
        "M20: self-locking: λ = 2.50° ≤ φ′ = 9.83°",
    );
    says(
        FrictionNote::SelfBraking {
            case: s("down"),
            alpha: deg(10.0),
            phi: deg(11.31),
        },
        "down: self-braking: α = 10.00° ≤ φ = 11.31°, the body must be pushed down (P < 0)",
    );
    says(
        FrictionNote::Journal {
            case: s("journal"),
            rho: 0.004975,
            textbook: 0.005,
            moment: 25.0,
        },
        "journal: the friction circle drawn and read is ρ = r·sin φ = 0.004975 m; the textbook's ρ = f·r = 0.005000 m (M_f = f·Q·r = 25.0000 N·m) is 0.503% larger",
    );
    says(
        FrictionNote::Slider {
            case: s("rest"),
            alpha: deg(15.0),
            phi: deg(11.31),
            phi0: deg(26.57),
            by_angles: SliderMotion::Rest,
            by_triangle: SliderMotion::Accelerating,
            net: -22.4144,
        },
        "rest: α = 15.00°, φ = 11.31°, φ₀ = 26.57°: at rest by the angles, accelerating by the triangle (ΔP = -22.4144 N read)",
    );
}

#[test]
fn rollers_read_as_rolling_or_as_sliding_where_they_slide() {
    let rollers = |motion| FrictionNote::Rolling {
        case: s("W3"),
        first: (5e-4, 0.1),
        second: (1e-3, 0.15),
        motion,
    };
    says(
        rollers(RollerMotion::Rolling),
        "W3: k₁/d = 5.000e-4 < f₁ = 0.1, k₂/d = 1.000e-3 < f₂ = 0.15: pure rolling",
    );
    says(
        rollers(RollerMotion::OnRollers {
            p: 1000.0,
            rolling: 10050.0,
        }),
        "W3: k₁/d = 5.000e-4 < f₁ = 0.1, k₂/d = 1.000e-3 < f₂ = 0.15: the rollers slide: the load slides on them, P = Q·f₁ = 1000 N (rolling would take 10050 N)",
    );
    let plane = FrictionNote::Rolling {
        case: s("W3"),
        first: (5e-4, 0.1),
        second: (0.5, 0.1),
        motion: RollerMotion::OnPlane {
            p: 1010.0,
            rolling: 5000.5,
        },
    };
    says(
        plane,
        "W3: k₁/d = 5.000e-4 < f₁ = 0.1, k₂/d = 5.000e-1 ≥ f₂ = 0.1: the rollers slide: the load slides on the plane with them, P = (Q + 2G)·f₂ = 1010 N (rolling would take 5000.5 N)",
    );
    says(
        FrictionNote::RollingErratum {
            case: s("W3"),
            r_n2: 10100.0,
            gain: 99.3,
        },
        "W3: R_n1 = Q, R_n2 = Q + 2G = 10100 N (the seed misprints the second as R_n1); without rollers P = Q·f₂ is 99.3 times larger",
    );
}

#[test]
fn kinematics_notes_read_as_the_six_bar_and_the_four_bar_printed_them() {
    says(
        KinematicsNote::NoPlan {
            position: s("6"),
            why: s("group 1: no intersection"),
        },
        "position 6: no velocity plan: group 1: no intersection",
    );
    says(
        KinematicsNote::Toggle {
            position: s("6"),
            group: 0,
        },
        "position 6: the analytic velocities and accelerations are not determined (group 1 at its toggle): null",
    );
    says(
        KinematicsNote::Refused(s("the diagrams over a crank turn are refused")),
        "the diagrams over a crank turn are refused",
    );
    says(
        KinematicsNote::Turning {
            position: s("10"),
            accelerating: vec![],
            decelerating: vec![s("2"), s("3")],
            differ: vec![],
        },
        "position 10: accelerating (ω and ε in one sense) by the plans: none; decelerating: links 2, 3; the analytic twin agrees",
    );
    says(
        KinematicsNote::Turning {
            position: s("1"),
            accelerating: vec![s("3")],
            decelerating: vec![s("2"), s("4")],
            differ: vec![s("4")],
        },
        "position 1: accelerating (ω and ε in one sense) by the plans: links 3; decelerating: links 2, 4; the analytic twin differs for link 4",
    );
    says(
        KinematicsNote::NearPivot(PinNearPivot {
            position: s("1"),
            pin: s("B"),
            pivot: s("C"),
            distance: 1e-5,
            link: 3,
            group: 0,
            speed: 0.1,
            omega: 1e4,
        }),
        "position 1: the pin B passes 1.000e-5 m from the pivot C of the slotted link 3 (group 1, |dCB/dφ₁| = 0.1000 m): the link turns at ω_3 = 1.0000e4 rad/s, 1.00e4 times the crank's rate; the values at this position are true but ill-conditioned (a change of 1.0e-5 m in a length of the mechanism changes them by about 100 %)",
    );
}

/// The report's notes of `scene` at the hand's drafting, as `tmm report` writes them.
pub(super) fn scene_notes(scene: &str) -> Vec<String> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("constructions")
        .join(format!("{scene}.toml"));
    let scene = crate::scene::load(&path).expect("scene");
    let session = crate::study::Session::new(&scene, Drafting::HAND);
    session.report().expect("report").note_texts()
}

#[test]
fn a_scenes_typed_notes_read_as_its_report_printed_them_before_they_were_typed() {
    assert_eq!(
        scene_notes("gears-pz2"),
        [
            "train: inversion (Willis): n before → n − n_H after stopping the carrier (per unit input): 1: 1 → 0.95; 2-3: 0.25 → 0.2; 4: −0.0833333 → −0.133333; 5: 0 → −0.05; H: 0.05 → 0",
            "train: W = 3n − 2p5 − p4 = 3·4 − 2·4 − 3 = 1",
            "train: u = 20 by Willis, 20 by the stages; the output turns with the input",
            "train: neighbour condition, k = 4: 2·a·sin(π/k) = 70.711 mm > d_a4 = 64 mm",
            "train: assembly condition, k = 4: z3·u3H^(5)/k = 25, (1 + kp)·25 whole for p = 0 (the textbook's); for identical blocks, z3·u3H·(z_f/gcd(z_g, z_f))/k = 25: the 4 satellites assemble spaced equally",
        ]
    );
    assert!(scene_notes("rotor-static").contains(&s(
        "balancing: erratum of seed 001 (lecture 19, W4: m = 0.1 kg, l = 0.1 m, ω = 300 1/s): its inertia force P = 900 N is called \"900 times\" the ball's weight; with g = 9.81 m/s² the ratio is 900 N / 0.981 N = 917.4 (900 holds only for g = 10 m/s²)"
    )));
    let friction = scene_notes("friction");
    assert!(friction.contains(&s("M20: self-locking: λ = 2.50° ≤ φ′ = 9.83°")));
    assert!(friction.contains(&s("journal: the friction circle drawn and read is ρ = r·sin φ = 0.004975 m; the textbook's ρ = f·r = 0.005000 m (M_f = f·Q·r = 25.0000 N·m) is 0.499% larger")));
}
