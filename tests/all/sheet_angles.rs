//! An angle or a shift a sheet writes in its text reads as its table's cell of it does
//! (issue 45: the friction's φ′ = 9,83° beside 9,826 in its table, the rotor's
//! α_уII = 25,6° beside 25,61, the gear pair's Δy = 0,180 beside 0,1798), and a round angle
//! as the textbook writes it (θ = 38°, not 38,00°).

use crate::support::scene;
use tmm::construct::Drafting;
use tmm::plate::Plate;
use tmm::scale::Lang;
use tmm::sheets;
use tmm::study::Session;

/// Every Russian sheet of the shipped scene `name`.
fn plates(name: &str) -> Vec<Plate> {
    let s = scene(name);
    let session = Session::new(&s, Drafting::EXACT);
    let all = sheets::build_all(&session, Lang::Ru).unwrap_or_else(|e| panic!("{name}: {e:?}"));
    all.into_iter().map(|(_, p)| p).collect()
}

/// The text lines of `plates`.
fn lines(plates: &[Plate]) -> Vec<&str> {
    (plates.iter())
        .flat_map(|p| &p.texts)
        .flat_map(|t| &t.lines)
        .map(String::as_str)
        .collect()
}

/// The table rows of `plates` with a cell `name` (the quantity's; a friction row starts with
/// its case's number).
fn rows<'a>(plates: &'a [Plate], name: &str) -> Vec<&'a [String]> {
    (plates.iter())
        .flat_map(|p| &p.tables)
        .flat_map(|t| &t.rows)
        .filter(|r| r.iter().any(|c| c == name))
        .map(Vec::as_slice)
        .collect()
}

#[test]
fn an_angle_reads_in_a_line_as_in_its_table() {
    // (scene, a line's words, the quantity's row, the cell both give)
    for (name, said, row, cell) in [
        ("friction", "φ′ = 9,826°", "φ′, °", "9,826"),
        ("rotor-dynamic", "α_{уII} = 25,57°", "α_{уII}", "25,57"),
        ("shaper", "Δy = 0,180", "Δy", "0,180"),
    ] {
        let plates = plates(name);
        assert!(
            lines(&plates).iter().any(|l| l.contains(said)),
            "{name}: «{said}» in {:#?}",
            lines(&plates)
        );
        let found = rows(&plates, row);
        assert!(
            found.iter().any(|r| r.iter().any(|c| c == cell)),
            "{name}: the row {row} gives {cell}: {found:?}"
        );
    }
    let shaper = plates("shaper");
    for said in ["ψ = θ = 38°", "холостой — 142°", "1 (φ_1 = 199°)"] {
        assert!(lines(&shaper).iter().any(|l| l.contains(said)), "«{said}»");
    }
}
