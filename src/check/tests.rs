use super::*;

/// One row of a test table: symbol, subject, position, method, graphical, analytic, scale.
type Line<'a> = (Symbol, &'a str, &'a str, Method, f64, f64, f64);

fn rows(table: &[Line]) -> Vec<Row> {
    table
        .iter()
        .map(|&(symbol, subject, at, method, g, a, scale)| Row {
            key: Key::at_position(symbol, subject, at),
            method,
            graphical: g,
            analytic: a,
            conditioning: None,
            scale,
        })
        .collect()
}

#[test]
fn keys_name_quantities_and_units() {
    let k = Key::at_position(Symbol::Velocity, "B3_B1", "3");
    assert_eq!(k.quantity(), "v_B3_B1");
    assert_eq!(k.symbol.unit(), "m/s");
    let whole = Key {
        symbol: Symbol::Displacement,
        subject: "E".into(),
        at: At::Scene,
    };
    assert_eq!(whole.at.label(), None);
}

#[test]
fn methods_keep_the_diagram_prefix() {
    assert_eq!(Method::DiagramChords.key(), "diagram-chords");
    assert!(Method::DiagramTangents.key().starts_with("diagram"));
    assert_eq!(Method::parse("diagram"), Some(Method::DiagramChords));
    assert_eq!(
        Method::parse("diagram-tangents"),
        Some(Method::DiagramTangents)
    );
    assert_eq!(Method::parse("plan"), Some(Method::Plan));
    assert_eq!(Method::parse("lathe"), None);
    assert_eq!(serde_json::to_string(&Method::Lever).unwrap(), "\"lever\"");
}

/// Hard case 3 of the independent check: a relative velocity that vanishes at a dead centre
/// (7e-15 read against 1.8e-15 analytic) is zero to rounding against the quantity's scale
/// over the cycle, not a 312 % error; two quantities with identical values get the same
/// verdict whatever other rows the report holds.
#[test]
fn zero_to_rounding_is_judged_against_the_cycle() {
    use Method::{DiagramChords, Plan};
    use Symbol::{Acceleration as A, AngularAcceleration as E};
    let rows = rows(&[
        (A, "B3_B1", "1", Plan, 7e-15, 1.8e-15, 12.0),
        (A, "B3_B1", "7", Plan, 7e-15, -2.1e-15, 12.0),
        (E, "2", "1", Plan, 3e-15, 2e-15, 40.0),
        (E, "3", "1", Plan, 3e-15, 2e-15, 40.0),
        (E, "3", "2", DiagramChords, 39.0, 40.0, 40.0),
    ]);
    let rel = rel_errors(&rows);
    assert_eq!(&rel[..4], &[None, None, None, None]);
    assert!((rel[4].unwrap() + 0.025).abs() < 1e-15);
    let s = Summary::of(&rows);
    assert_eq!(s.entries.len(), 1);
    assert_eq!(s.entries[0].quantity, "eps_3");
    // Without the cycle's scale, the old rule (largest |analytic| among the rows) would
    // have judged 1.8e-15 against 2.1e-15 and reported a 289 % error: the first two rows
    // again, with no scale.
    let alone: Vec<Row> = rows[..2]
        .iter()
        .map(|r| Row {
            scale: 0.0,
            ..r.clone()
        })
        .collect();
    assert!(rel_errors(&alone)[0].is_some_and(|d| d > 2.0));
}

#[test]
fn is_zero_is_scale_aware() {
    assert!(is_zero(1e-13, 1.0));
    assert!(!is_zero(1e-13, 1e-3));
    assert!(!is_zero(f64::NAN, 1.0));
    assert!(is_zero(0.0, 0.0));
}

/// The six-bar's ω₂ is −2,0944 rad/s at positions 3 and 10′ and is read −2,106 at both: the
/// two errors differ by the rounding of the analytic twin (1 ulp either way), and the first
/// position is the worst one whichever way the rounding falls.
#[test]
fn equal_errors_at_two_positions_go_to_the_first() {
    use Symbol::AngularVelocity as W;
    let analytic: f64 = -2.094_395_102_393_195_7;
    for later in [analytic, f64::from_bits(analytic.to_bits() - 1)] {
        let rows = rows(&[
            (W, "2", "1", Method::Plan, -2.522, -2.515, 10.7),
            (W, "2", "3", Method::Plan, -2.106, analytic, 10.7),
            (W, "2", "10′", Method::Plan, -2.106, later, 10.7),
        ]);
        let s = Summary::of(&rows);
        assert_eq!(s.entries[0].worst_position.as_deref(), Some("3"), "{later}");
    }
    // A larger error still wins.
    let rows = rows(&[
        (W, "2", "3", Method::Plan, -2.106, analytic, 10.7),
        (W, "2", "10′", Method::Plan, -2.107, analytic, 10.7),
    ]);
    assert_eq!(
        Summary::of(&rows).entries[0].worst_position.as_deref(),
        Some("10′")
    );
}

/// The crank pin's v_A read exactly at every position: its errors are rounding residues, and
/// no position is named as the worst (the note and the report write «—» or nothing there).
#[test]
fn errors_of_rounding_name_no_worst_position() {
    use Symbol::Velocity as V;
    let rows = rows(&[
        (V, "A", "1", Method::Plan, 0.8, 0.799_999_999_999_999_9, 0.8),
        (V, "A", "2", Method::Plan, 0.8, 0.8, 0.8),
        (V, "B", "1", Method::Plan, 0.31, 0.3139, 0.8),
    ]);
    let s = Summary::of(&rows);
    assert_eq!(s.entries[0].worst_position.as_deref(), Some("1"));
    assert_eq!(s.entries[0].worst_named(), None);
    assert_eq!(s.entries[1].worst_named(), Some("1"));
}
