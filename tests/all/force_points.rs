//! The points of the force analysis's drawings (issue 45): each group drawn apart and the
//! driving link name their joints by their letters, as seed 000's group drawings name B, C,
//! S₃; and a detail view's letter never reads as a point's name (the Cyrillic «В» of a detail
//! beside the point «B», or the Latin «A» beside the crank's pivot A, in English).

use crate::support::root;
use tmm::construct::{Drafting, Figure, Item};
use tmm::geom::DVec2;
use tmm::scale::Lang;
use tmm::study::Session;

const SCENES: [&str; 3] = ["shaper", "v-engine", "six-bar"];

/// The letters a figure writes at a point: (text, where), mm.
fn letters(f: &Figure) -> Vec<(&str, DVec2)> {
    (f.steps.iter())
        .filter_map(|s| match (&s.item, &s.label) {
            (Item::Text(at) | Item::Point(at), Some(l)) => Some((l.text.as_str(), *at)),
            _ => None,
        })
        .collect()
}

/// Every hinge a drawing of the force analysis draws carries the letter of the point there.
#[test]
fn every_joint_of_a_force_drawing_is_lettered() {
    let mut joints = 0;
    for name in SCENES {
        let s =
            tmm::scene::load(&root().join(format!("constructions/{name}.toml"))).expect("scene");
        let session = Session::new(&s, Drafting::EXACT);
        let sc = session.kin_scales().expect("scales");
        let m = session.mechanism("test").expect("mechanism");
        let program = tmm::linkage::Program::compile(m).expect("program");
        for k in session.force_positions().expect("positions") {
            let f = session.forces(&sc, k).expect("forces");
            let p = &f.analysis.polygons;
            let drawings = (p.groups.iter().map(|g| &g.scheme)).chain([&p.driver.scheme]);
            for figure in drawings {
                let named = letters(figure);
                for at in figure.steps.iter().filter_map(|s| match s.item {
                    Item::Joint { at, .. } => Some(at),
                    _ => None,
                }) {
                    joints += 1;
                    let here: Vec<&str> = (named.iter())
                        .filter(|(_, p)| p.distance(at) < 1e-9)
                        .map(|(t, _)| *t)
                        .collect();
                    assert!(
                        here.len() == 1 && program.index(here[0]).is_some(),
                        "{name} pos. {}: {}: the joint at {at:?} is lettered {here:?}",
                        f.label,
                        figure.title
                    );
                }
            }
        }
    }
    assert!(joints > 30, "{joints} joints");
}

/// A detail view of a force sheet is captioned by a letter that is no point's name of the
/// mechanism nor looks like one (А, В, Е, К, М, Н, Р, С, Т, У against A, B, E, K, M, H, P,
/// C, T, Y), in every language.
#[test]
fn no_detail_letter_reads_as_a_point() {
    let looks = |c: char| match c {
        'А' => 'A',
        'В' => 'B',
        'Е' => 'E',
        'К' => 'K',
        'М' => 'M',
        'Н' => 'H',
        'Р' => 'P',
        'С' => 'C',
        'Т' => 'T',
        'У' => 'Y',
        c => c,
    };
    let mut details = 0;
    for name in SCENES {
        let s =
            tmm::scene::load(&root().join(format!("constructions/{name}.toml"))).expect("scene");
        let session = Session::new(&s, Drafting::HAND);
        let m = session.mechanism("test").expect("mechanism");
        let program = tmm::linkage::Program::compile(m).expect("program");
        // The points named by one letter.
        let initials: Vec<char> = ('A'..='Z')
            .filter(|c| program.index(&c.to_string()).is_some())
            .collect();
        for lang in [Lang::Ru, Lang::Uk, Lang::En] {
            let kind = tmm::scene::PlateKind::parse("forces").expect("kind");
            for plate in tmm::build(&session, kind, lang).expect("sheets") {
                for caption in plate.views.iter().filter_map(|v| v.caption.as_deref()) {
                    let Some((letter, _)) = caption.split_once(", μ_{F}") else {
                        continue;
                    };
                    let mut chars = letter.chars();
                    let (Some(c), None) = (chars.next(), chars.next()) else {
                        continue;
                    };
                    details += 1;
                    assert!(
                        !initials.contains(&looks(c)),
                        "{name} {lang:?} {}: detail «{c}» reads as a point of {initials:?}",
                        plate.name
                    );
                }
            }
        }
    }
    assert!(details >= 6, "{details} details");
}
