//! The structural and kinematic analysis: mobility by Chebyshev's formula, the Assur groups
//! and the structure formula; then the kinematics in the seed's order — the plan of positions
//! ([`super::positions`]), the velocity and acceleration plans ([`super::plans`]), the
//! diagrams and the hodograph ([`super::diagrams`]) and the analytic method
//! ([`super::analytic`]).

use super::markup::{label, num, sym, text, Align};
use super::worked::{Printed, Worked};
use super::{NoteError, Writer};
use crate::linkage::Structure;
use crate::words::{Meaning, NoteText as T, Text as S};

/// The structural analysis.
pub(super) fn structure(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let m = w.session.mechanism("the explanatory note")?;
    let s = Structure::analyse(m);
    let lang = w.lang;
    w.heading(1, T::StructureAndKinematics);
    w.heading(2, S::StructuralAnalysis);
    let redundant = s.pairs.iter().filter(|p| p.redundant).count() as u32;
    let n = |x: i64| num(x as f64, 6, lang);
    let chebyshev = |p5: u32, w_: i32| {
        Worked::new(
            sym("W"),
            format!("3{} - 2{} - {}", sym("n"), sym("p_{5}"), sym("p_{4}")),
            format!(
                "3 dot {} - 2 dot {} - {}",
                n(s.n as i64),
                n(p5 as i64),
                n(s.p4 as i64)
            ),
            Printed::plain(f64::from(w_), 6, lang),
        )
    };
    w.doc.par(&[
        text(w.word(T::MobilityChebyshev)),
        text(&format!("n = {}, p₅ = {}, p₄ = {}:", s.n, s.p5, s.p4)),
    ]);
    w.worked(chebyshev(s.p5, s.w));
    w.explain(&[
        ("W", w.word(Meaning::Mobility), ""),
        ("n", w.word(Meaning::MovingLinks), ""),
        ("p_{5}", w.word(Meaning::LowerPairs), ""),
        ("p_{4}", w.word(Meaning::HigherPairs), ""),
    ]);
    if redundant > 0 {
        let names: Vec<String> = s
            .pairs
            .iter()
            .filter(|p| p.redundant)
            .map(|p| p.name.clone())
            .collect();
        w.doc.par(&[label(&format!(
            "{} {}:",
            w.word(T::WithRedundantPairs),
            names.join(", ")
        ))]);
        w.worked(chebyshev(s.p5_all, s.w_all));
        w.doc.say(w.word(T::RedundantPairExplained));
    }
    w.doc.say(w.word(T::AssurGroups));
    let header = [
        text(w.word(S::Group)),
        text(w.word(T::KindWord)),
        text(w.word(T::Pairs)),
        text(w.word(T::GroupMobility)),
    ];
    let mut rows = vec![vec![
        text(&format!("I (0, {})", s.crank_link)),
        text(w.word(S::DrivingLink)),
        label(&s.pairs[0].name),
        text("W = 3·1 − 2·1 = 1"),
    ]];
    for g in &s.groups {
        let kind = format!(
            "{} {} ({})",
            w.word(T::KindWord),
            g.kind.number(),
            g.kind.letters_in(lang)
        );
        let pairs: Vec<String> = g
            .pairs
            .iter()
            .map(|p| {
                format!(
                    "{} ({}–{}, {})",
                    p.name,
                    p.links[0],
                    p.links[1],
                    if p.prismatic {
                        w.word(T::Prismatic)
                    } else {
                        w.word(T::Revolute)
                    }
                )
            })
            .collect();
        rows.push(vec![
            text(&format!("II ({}, {})", g.links[0], g.links[1])),
            text(&kind),
            label(&pairs.join("; ")),
            text("W = 3·2 − 2·3 = 0"),
        ]);
    }
    let caption = w.word(T::GroupsTable);
    w.doc.table(
        caption,
        &[Align::Left, Align::Left, Align::Left, Align::Centre],
        &header,
        &rows,
    );
    w.doc.par(&[
        text(w.word(S::StructureFormula)),
        text(&s.formula()),
        text(&format!("; {} {}.", w.word(T::ClassOfMechanism), s.class)),
    ]);
    Ok(())
}

/// The kinematic analysis.
pub(super) fn kinematics(w: &mut Writer<'_, '_>) -> Result<(), NoteError> {
    let sc = w.session.kin_scales()?;
    let kin = w.session.kinematics(&sc)?;
    let m = w.session.mechanism("the explanatory note")?;
    let s = Structure::analyse(m);
    super::positions::positions(w)?;
    let at = super::plans::worked_position(&w.report.rows);
    let plans = super::plan_reads::Plans {
        kin: &kin,
        m,
        s: &s,
        at: at.clone(),
    };
    super::plans::velocities(w, &plans)?;
    super::plans::accelerations(w, &plans)?;
    super::diagrams::diagrams(w, &kin, at.as_deref());
    super::diagrams::hodograph(w, &plans);
    super::analytic::analytic(w, at.as_deref(), kin.w1)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::{explain::Explained, markup::Markup, Writer};
    use super::*;
    use crate::scale::Lang;

    /// Every displayed formula of the structural and kinematic analysis of every linkage
    /// scene has its left side explained («где»), in every language.
    #[test]
    fn every_formula_of_the_kinematics_is_explained() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("constructions");
        let scenes = [
            "shaper",
            "four-bar",
            "slider-crank",
            "six-bar",
            "v-engine",
            "tangent",
        ];
        for name in scenes {
            let scene = crate::scene::load(&root.join(format!("{name}.toml"))).expect("scene");
            let session = crate::study::Session::new(&scene, crate::construct::Drafting::EXACT);
            for lang in [Lang::Ru, Lang::Uk, Lang::En] {
                let mut w = Writer {
                    session: &session,
                    lang,
                    report: session.report().expect("report"),
                    sheets: Vec::new(),
                    views: Vec::new(),
                    doc: Markup::default(),
                    files: Vec::new(),
                    explained: Explained::default(),
                    worked: Vec::new(),
                };
                structure(&mut w).expect("structure");
                kinematics(&mut w).expect("kinematics");
                w.explained.settle();
                assert!(
                    w.explained.missing.is_empty(),
                    "{name} {lang:?}: {:?}",
                    w.explained.missing
                );
            }
        }
    }
}
