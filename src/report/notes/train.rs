//! The English of a train study's notes ([`TrainNote`]).

use super::sig as num;
use crate::check::notes::train::{
    Across, Closing, FormulaBy, Fraction, MeshNeeds, MeshRatio, SatelliteAssembly, SolvedFor,
    TrainNote, WillisDifferential,
};

/// One mesh's ratio with the carrier stopped: `(−30/20)`.
fn mesh_text(m: &MeshRatio) -> String {
    let sign = if m.negative { "−" } else { "" };
    format!("({sign}{}/{})", m.driven, m.driving)
}

/// The teeth across a centre distance: `z1 + z2`, or `z5 − z4` for a ring 5.
fn across_text(a: &Across) -> String {
    let op = if a.ring { "−" } else { "+" };
    format!("z{} {op} z{}", a.first, a.second)
}

/// A fraction: whole, or n/d, parenthesised when negative.
fn frac((n, d): Fraction) -> String {
    match (n, d) {
        (n, 1) if n >= 0 => n.to_string(),
        (n, 1) => format!("(−{})", -n),
        (n, d) if n >= 0 => format!("{n}/{d}"),
        (n, d) => format!("(−{}/{d})", -n),
    }
}

/// The note in English.
pub(super) fn english(note: &TrainNote) -> String {
    match note {
        TrainNote::Inversion { rpm, cells } => {
            let cells: Vec<String> = cells
                .iter()
                .map(|(s, w, r)| format!("{s}: {} → {}", num(*w, 6), num(*r, 6)))
                .collect();
            format!(
                "train: inversion (Willis): n before → n − n_H after stopping the carrier{}: {}",
                if *rpm { ", rpm" } else { " (per unit input)" },
                cells.join("; ")
            )
        }
        TrainNote::Mobility {
            n,
            p5,
            p4,
            w,
            inputs,
        } => format!(
            "train: W = 3n − 2p5 − p4 = 3·{n} − 2·{p5} − {p4} = {w}{}",
            inputs
                .as_ref()
                .map_or(String::new(), |(a, b, na, nb)| format!(
                    " (a differential: the inputs {a} and {b}, n = {} and {} rpm)",
                    num(*na, 6),
                    num(*nb, 6)
                ))
        ),
        TrainNote::Ratio { ratio, formula } => format!(
            "train: u = {} by Willis{}; the output turns {} the input",
            num(*ratio, 7),
            formula.map_or(String::new(), |(s, by)| format!(
                ", {} by {}",
                num(s, 7),
                match by {
                    FormulaBy::Differential => "Willis's formula of the differential",
                    FormulaBy::Stages => "the stages",
                }
            )),
            if *ratio < 0.0 { "against" } else { "with" }
        ),
        TrainNote::Differential(d) => differential(d),
        TrainNote::Closing(c) => closing(c),
        TrainNote::SeedMobility { w } => format!("train: the seed's W = {w} reproduced"),
        TrainNote::SeedMobilityErratum {
            printed,
            n,
            p5,
            p4,
            w,
        } => format!(
            "train: erratum: the seed prints W = {printed}; W = 3·{n} − 2·{p5} − {p4} = {w}"
        ),
        TrainNote::SeedRatio {
            name,
            printed,
            ratio,
        } => format!(
            "train: the seed's {name} = {} reproduced (Willis {})",
            num(*printed, 6),
            num(*ratio, 7)
        ),
        TrainNote::SeedRatioErratum {
            name,
            printed,
            ratio,
            formula,
            triangles,
            stage,
        } => {
            let why = stage.as_ref().map_or(String::new(), |s| {
                format!(
                    "; with the other stages as their teeth give, {} needs u_{}{}^(H) = {} of the planetary stage, whose teeth give {}",
                    num(*printed, 6),
                    s.a,
                    s.f,
                    num(s.needed, 6),
                    num(s.teeth, 6)
                )
            });
            format!(
                "train: erratum: the seed prints {name} = {}; Willis's relations give {}{}, the triangles {}{why}",
                num(*printed, 6),
                num(*ratio, 7),
                formula.map_or(String::new(), |f| format!(", the formula {}", num(f, 7))),
                num(*triangles, 7),
            )
        }
        TrainNote::Required {
            n_in,
            n_out,
            required,
            ratio,
        } => format!(
            "train: required |u| = {}/{} = {}; the tooth numbers give {} (n_out = {} rpm, {} %)",
            num(*n_in, 6),
            num(*n_out, 6),
            num(*required, 6),
            num(*ratio, 6),
            num(n_in / ratio, 6),
            num((ratio / required - 1.0) * 100.0, 3)
        ),
        TrainNote::MeshNeeds(m) => mesh_needs(m),
        TrainNote::Neighbour {
            k,
            chord,
            wheel,
            tip,
        } => format!(
            "train: neighbour condition, k = {k}: 2·a·sin(π/k) = {} mm {} d_a{wheel} = {} mm",
            num(chord * 1e3, 5),
            if chord > tip { ">" } else { "≤ (fails:)" },
            num(tip * 1e3, 5)
        ),
        TrainNote::Assembly(a) => assembly(a),
    }
}

/// The note's English: differential.
fn differential(d: &WillisDifferential) -> String {
    let WillisDifferential {
        names: [a, b, hn],
        meshes,
        u,
        solved,
        output,
        speeds,
    } = d;
    let teeth: Vec<String> = meshes.iter().map(mesh_text).collect();
    let solved = match solved {
        SolvedFor::Carrier => format!("n{hn} = (n{a} − u·n{b})/(1 − u)"),
        SolvedFor::A => format!("n{a} = n{hn} + u·(n{b} − n{hn})"),
        SolvedFor::B => format!("n{b} = n{hn} + (n{a} − n{hn})/u"),
    };
    format!(
                "train: a differential by Willis's formula: u = u{a}{b}^({hn}) = (n{a} − n{hn})/(n{b} − n{hn}) = {} = {}; {solved} = {} rpm (n{a} = {}, n{b} = {}, n{hn} = {} rpm)",
                teeth.join("·"),
                num(*u, 6),
                num(*output, 6),
                num(speeds[0], 6),
                num(speeds[1], 6),
                num(speeds[2], 6),
            )
}

/// The note's English: closing.
fn closing(c: &Closing) -> String {
    let Closing {
        mesh,
        arm_mesh,
        module,
        arm_across,
        arm,
        across,
        teeth,
        closing,
        wheel,
    } = c;
    let m = module * 1e3;
    let name = format!("{}–{}", mesh.0, mesh.1);
    let arm_name = format!("{}–{}", arm_mesh.0, arm_mesh.1);
    format!(
                "train: the source gives no module of the mesh {name}: at the train's m = {} mm the tooth sums do not close — the mesh {arm_name} sets the carrier's arm a = m({})/2 = {} mm, the mesh {name} reaches m({})/2 = {} mm — so the train as given cannot be assembled; Willis's relations use the teeth only, and the velocity triangles take the mesh {name} at m′ = 2a/({}) = {} mm (assumed: the module that brings wheel {wheel} onto the carrier's axis)",
                num(m, 5),
                across_text(arm_across),
                num(arm * 1e3, 6),
                across_text(across),
                num(m * teeth / 2.0, 6),
                across_text(across),
                num(closing * 1e3, 6),
            )
}

/// The note's English: mesh needs.
fn mesh_needs(m: &MeshNeeds) -> String {
    let MeshNeeds {
        names: (a, b),
        want,
        best,
        n_out,
        now,
    } = m;
    let list: Vec<String> = best
        .iter()
        .map(|(z1, z2, e)| {
            format!(
                "{z2}/{z1} ({} %, n_out = {} rpm)",
                num(e * 100.0, 3),
                num(n_out / (1.0 + e), 6)
            )
        })
        .collect();
    format!(
        "train: mesh {a}–{b} needs z{b}/z{a} = {}: best {} (now {}/{} = {})",
        num(*want, 6),
        list.join(", "),
        now.1,
        now.0,
        num(now.1 / now.0, 5)
    )
}

/// The note's English: assembly.
fn assembly(a: &SatelliteAssembly) -> String {
    let SatelliteAssembly {
        k,
        central: z,
        fixed: b,
        value,
        p,
        block,
        fits,
    } = a;
    let value = frac(*value);
    let textbook = match p {
        Some(p) => format!("whole for p = {p}"),
        None => "never whole".to_string(),
    };
    let block = block.map_or(String::new(), |v| {
        format!(
            "; for identical blocks, z{z}·u{z}H·(z_f/gcd(z_g, z_f))/k = {}",
            frac(v)
        )
    });
    let verdict = match fits {
        Ok(()) => format!("the {k} satellites assemble spaced equally"),
        Err(fit) => {
            let fit: Vec<String> = fit.iter().map(u32::to_string).collect();
            format!(
                        "fails: {k} satellites cannot be spaced equally; k = {} can (assembly and neighbour)",
                        fit.join(", ")
                    )
        }
    };
    format!(
                "train: assembly condition, k = {k}: z{z}·u{z}H^({b})/k = {value}, (1 + kp)·{value} {textbook} (the textbook's){block}: {verdict}"
            )
}
