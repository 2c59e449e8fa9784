//! What a strict instructor marks on a sheet that the legibility measure cannot see (issue
//! 45): a datum the drawing needs and the data leave out, a blank where a table has no
//! value, a symbol that says what it does not mean, a scale left out of the title block.

use std::path::PathBuf;
use tmm::construct::{Drafting, Item};
use tmm::geom::Segment;
use tmm::plate::Plate;
use tmm::scale::Lang;
use tmm::scene;
use tmm::sheets;
use tmm::study::Session;

fn plates(name: &str) -> Vec<Plate> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("constructions/{name}.toml"));
    let s = scene::load(&path).expect(name);
    let session = Session::new(&s, Drafting::EXACT);
    let all = sheets::build_all(&session, Lang::Ru).expect("plates");
    all.into_iter().map(|(_, p)| p).collect()
}

fn text_of(plates: &[Plate]) -> String {
    (plates.iter().flat_map(|p| &p.texts))
        .flat_map(|t| t.lines.clone())
        .collect::<Vec<_>>()
        .join("\n")
}

/// The V engine's cylinders stand at 45° and 135°: the scheme cannot be rebuilt from lengths
/// alone, so the data give each axis's angle. A vertical or horizontal guide (the tangent
/// mechanism's, the slider-crank's) is seen for what it is and gets none.
#[test]
fn a_slanted_cylinder_axis_is_given_by_its_angle() {
    let v = text_of(&plates("v-engine"));
    assert!(v.contains("β_{B} = 45°, β_{C} = 135°"), "{v}");
    for plain in ["tangent", "slider-crank", "shaper"] {
        let t = text_of(&plates(plain));
        let data = t.lines().filter(|l| l.contains("l_{") && l.contains("β_{"));
        assert_eq!(data.count(), 0, "{plain}: {t}");
    }
}

/// ГОСТ 2.105: a table's cell with no value holds a dash. The six-bar's rates at its change
/// point (position 6) are not determined; its analytic table's row 6 gives the angles and
/// the crank pin, and a dash for each rate.
#[test]
fn a_table_cell_without_a_value_is_a_dash() {
    let all = plates("six-bar");
    let table = (all.iter().flat_map(|p| &p.tables))
        .find(|t| t.title.starts_with("Аналитический"))
        .expect("the analytic table");
    let row6 = table.rows.iter().find(|r| r[0] == "6").expect("row 6");
    let col = |name: &str| {
        (table.columns.iter())
            .position(|(c, _)| c.starts_with(name))
            .unwrap_or_else(|| panic!("{name} in {:?}", table.columns))
    };
    assert_eq!(row6[col("ω_{2}")], "—", "{row6:?}");
    assert_eq!(row6[col("V_{E}")], "—", "{row6:?}");
    assert_eq!(row6[col("φ_{2}")], "180,0", "{row6:?}");
    let blank = (table.rows.iter().flatten())
        .filter(|c| c.is_empty())
        .count();
    assert_eq!(blank, 0, "{:?}", table.rows);
}

/// A fixed central wheel's shaft is hatched to the frame where it ends. When the carrier's
/// shaft runs on through it (PZ2's wheel 5 over the carrier H), the hatching stands on the
/// fixed shaft's outer side only: drawn across both, it would fix the carrier too.
#[test]
fn a_fixed_wheels_fixing_leaves_the_shaft_through_it_free() {
    for name in ["gears-pz2", "gears-pz2-ex2"] {
        let all = plates(name);
        let steps: Vec<_> = (all.iter().flat_map(|p| &p.views))
            .flat_map(|v| &v.figure.steps)
            .collect();
        let fixings: Vec<Segment> = (steps.iter())
            .filter(|s| s.note.ends_with("fixed to the frame"))
            .filter_map(|s| match &s.item {
                Item::Guide { segment, .. } => Some(*segment),
                _ => None,
            })
            .collect();
        assert!(!fixings.is_empty(), "{name}: a fixed shaft");
        let shafts: Vec<Segment> = (steps.iter())
            .filter(|s| s.note.starts_with("the shaft ") && !s.note.contains("fixed"))
            .filter_map(|s| match &s.item {
                Item::Segment(seg) => Some(*seg),
                _ => None,
            })
            .collect();
        for f in &fixings {
            // A shaft runs through the fixing where it passes its x at a height the fixing
            // spans (the fixed shaft itself ends there).
            let (x, lo, hi) = (f.from.x, f.from.y.min(f.to.y), f.from.y.max(f.to.y));
            let through: Vec<_> = (shafts.iter())
                .filter(|s| s.from.x.min(s.to.x) < x - 1e-6 && x + 1e-6 < s.from.x.max(s.to.x))
                .filter(|s| lo - 1e-6 < s.from.y && s.from.y < hi + 1e-6)
                .collect();
            assert!(
                through.is_empty(),
                "{name}: the fixing {f:?} crosses {through:?}"
            );
        }
    }
}

/// A sheet whose length drawings share one μ_l has that scale in its title block (ГОСТ
/// 2.104's «Масштаб»); the friction-follower's two cases are both drawn at 0,001 м/мм.
#[test]
fn a_sheet_whose_drawings_share_a_length_scale_states_it() {
    let all = plates("friction-follower");
    assert_eq!(all[0].title_block.scale, "1:1");
}
