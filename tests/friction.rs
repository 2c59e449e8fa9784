//! The friction scene through the session: its report at drafting 0 agrees with the twins to
//! rounding, at 0.5 mm it shows the error a hand construction has; W3 gives the seed's
//! numbers.

use std::path::PathBuf;
use tmm::construct::Drafting;
use tmm::study::Session;

fn report(drafting: f64) -> tmm::Report {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("constructions/friction.toml");
    let s = tmm::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let d = Drafting::new(drafting).expect("a drafting resolution");
    Session::new(&s, d)
        .report()
        .unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn exact_reading_agrees_with_the_twins() {
    let r = report(0.0);
    assert_eq!(r.rows.len(), 20);
    for (row, rel) in r.rows.iter().zip(r.rel_errors()) {
        let rel = rel.unwrap_or(0.0).abs();
        assert!(rel < 1e-12, "{}: {rel}", row.quantity());
    }
    let value = |q: &str| {
        r.rows
            .iter()
            .find(|x| x.quantity() == q)
            .map(|x| x.graphical)
            .unwrap_or_else(|| panic!("no {q}"))
    };
    assert!((value("F_P_W3") - 15.1).abs() < 1e-9);
    assert!((value("F_Pslide_W3") - 1500.0).abs() < 1e-9);
    assert!(r.notes.iter().any(|n| n.contains("erratum")));
    assert!(r.notes.iter().any(|n| n.contains("misprints")));
}

#[test]
fn reading_to_half_a_millimetre_shows_percent_level_errors() {
    let r = report(0.5);
    let worst = r
        .rel_errors()
        .into_iter()
        .flatten()
        .fold(0.0f64, |m, e| m.max(e.abs()));
    assert!(worst > 1e-3 && worst < 0.2, "{worst}");
}
