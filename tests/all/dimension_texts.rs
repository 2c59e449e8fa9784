//! A dimension's text sits beside its dimension line, never on a line of its own view (issue
//! 19: `πd₁` and `ρ` of friction, `H` of the v-engine's dynamics were struck through): over
//! every sheet of every scene in `constructions/`, in every language, each dimension text's
//! box as written (turned with it) holds no line or symbol of its view.

use tmm::construct::Drafting;
use tmm::plate::struck_dimension_texts;
use tmm::plate::Plate;
use tmm::scale::Lang;
use tmm::scene;

/// Every sheet of every scene in `constructions/` in `lang`, read exactly: (scene, sheet).
fn all_sheets(lang: Lang) -> Vec<(String, Plate)> {
    let mut out = Vec::new();
    for path in crate::support::scene_paths() {
        let s = scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        let plates = tmm::render::plates(&s, lang, Drafting::EXACT)
            .unwrap_or_else(|e| panic!("{}: {e}", s.stem));
        out.extend(plates.into_iter().map(|(_, p)| (s.stem.clone(), p)));
    }
    out
}

#[test]
fn no_dimension_text_is_struck_by_a_line_of_its_view() {
    let mut struck = Vec::new();
    let mut sheets = 0;
    for lang in [Lang::Ru, Lang::En] {
        for (stem, p) in all_sheets(lang) {
            sheets += 1;
            struck.extend(struck_dimension_texts(&p).into_iter().map(|(v, t, mm)| {
                format!(
                    "{stem}/{} ({lang:?}) view {v}: “{t}” holds {mm:.2} mm of line",
                    p.name
                )
            }));
        }
    }
    assert!(sheets > 50, "{sheets} sheets");
    assert!(struck.is_empty(), "{}", struck.join("\n"));
}

/// Every dimension line carries its text (issue 45: the rack-cut tooth's s_a was a
/// dimension line with nothing on it): over every view of every sheet of every scene, each
/// step drawn as a dimension has its label, or a step drawn from it does.
#[test]
fn every_dimension_carries_its_text() {
    let mut bare = Vec::new();
    for (stem, p) in all_sheets(Lang::Ru) {
        for (v, view) in p.views.iter().enumerate() {
            let steps = &view.figure.steps;
            for st in steps {
                if !matches!(st.item, tmm::construct::Item::Dimension { .. }) {
                    continue;
                }
                let named = st.label.is_some()
                    || steps
                        .iter()
                        .any(|o| o.from.contains(&st.id) && o.label.is_some());
                if !named {
                    bare.push(format!("{stem}/{} view {v}: «{}»", p.name, st.note));
                }
            }
        }
    }
    assert!(bare.is_empty(), "{}", bare.join("\n"));
}
