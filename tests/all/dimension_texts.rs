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

/// The texts past their arrows written on a leader's shelf instead (ГОСТ 2.307 allows either
/// where the line cannot run on): sheet, text, why.
const SHELVED: &[(&str, &str, &str)] = &[(
    "shaper/flywheel",
    "45JS9",
    "the keyway's width (11 mm at 1:4) inside the upper spoke, whose sides stand 9 mm from \
     the keyway: its text (13 mm) run on would cross them",
)];

/// A dimension's text written past its arrows stands over the dimension line run on under it
/// (ГОСТ 2.307), on every sheet in Russian and English as `render` reads it: the line's
/// continuation runs from the arrow's tip along the line to past the text (issue 45: cam-pz4's
/// «[ρ] = 10 мм» stood beside the axis 10 mm under its 9 mm dimension, on nothing).
#[test]
fn a_text_past_its_arrows_stands_over_the_line_run_on() {
    use tmm::construct::Item;
    let mut past = 0;
    let mut bad = Vec::new();
    for lang in [Lang::Ru, Lang::En] {
        for path in crate::support::scene_paths() {
            let s = scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
            let plates = tmm::render::plates(&s, lang, Drafting::HAND).expect("plates");
            for (_, p) in plates {
                let l = tmm::plate::layout(&p);
                for x in &l.labels {
                    let view = &p.views[x.view];
                    let Some(step) = view.figure.steps.iter().find(|s| s.id == x.steps[0]) else {
                        continue;
                    };
                    let Item::Dimension { from, to, offset } = step.item else {
                        continue;
                    };
                    let n = (to - from).normalize_or_zero().perp() * offset;
                    let (a, b) = (view.to_sheet(from + n), view.to_sheet(to + n));
                    let u = (b - a).normalize_or_zero();
                    let at = |q: glam::DVec2| (q - a).dot(u);
                    let corners = [
                        x.rect.min,
                        x.rect.max,
                        glam::DVec2::new(x.rect.min.x, x.rect.max.y),
                        glam::DVec2::new(x.rect.max.x, x.rect.min.y),
                    ];
                    let (lo, hi) = corners
                        .iter()
                        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| {
                            (lo.min(at(*c)), hi.max(at(*c)))
                        });
                    let length = a.distance(b);
                    let middle = 0.5 * (lo + hi);
                    if (0.0..=length).contains(&middle) {
                        continue;
                    }
                    past += 1;
                    let off_line = |q: glam::DVec2| (q - a).perp_dot(u).abs();
                    let runs_on = x.leader.is_some_and(|r| {
                        let reach = if middle > length {
                            at(r.end) >= hi
                        } else {
                            at(r.end) <= lo
                        };
                        off_line(r.knee) < 0.05 && off_line(r.end) < 0.05 && reach
                    });
                    let shelved = SHELVED.iter().any(|(sheet, text, _)| {
                        *sheet == format!("{}/{}", s.stem, p.name) && *text == x.text
                    });
                    if !runs_on && !shelved {
                        bad.push(format!("{}/{} {lang:?}: «{}»", s.stem, p.name, x.text));
                    }
                }
            }
        }
    }
    assert!(past > 10, "{past} texts past their arrows");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
