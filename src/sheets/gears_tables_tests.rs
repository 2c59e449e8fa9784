//! The gear sheets' tables say how each value is obtained: a row under "графически" is read
//! off a drawing of its sheet ([`crate::studio::readings`]) or worked out from such readings
//! only; a row computed — by formula, or from the construction's points — stands in the
//! table of computed values.

use super::gears::tables_rows;
use crate::check::{is_zero, Method, Row, Symbol};
use crate::construct::Drafting;
use crate::plate::Plate;
use crate::scale::Lang;
use crate::scene::PlateKind;
use crate::studio::gallery;
use crate::studio::readings::{placed, read_at, ReadAt};
use crate::study::Session;

/// The rows measured on the drawn tooth (the thicknesses s_a, s_t, s_b and the space e_t
/// across the generated envelope, to the drafting resolution) whose measurement the
/// generation does not yet record as a [`crate::construct::Reading`]: known, listed here so
/// that any other unread row under "графически" fails.
const NOT_RECORDED: [(Symbol, Method); 2] = [
    (Symbol::ToothThickness, Method::Envelope),
    (Symbol::SpaceWidth, Method::Envelope),
];

/// The same value: a read-off row's graphical value against one worked out again here from
/// the sheet's readings, to the rounding of a quotient.
const SAME: f64 = 1e-9;

fn same(a: f64, b: f64) -> bool {
    (a - b).abs() <= SAME * a.abs().max(b.abs())
}

/// The length of a reading as the drafting model reads it on the sheet, mm.
fn read_mm(r: &ReadAt, drafting: Drafting) -> f64 {
    let (a, b) = r.ends();
    drafting.read(a.distance(b))
}

/// How a read-off row that is not one reading is worked out from the sheet's readings, or
/// `None` when it is not: a specific sliding λ is an ordinate of the sliding diagram read at
/// [`crate::gears::LAMBDA_MM`] per unit; the contact ratio by the meshing picture is the
/// B₁B₂ read over the base pitch p_b (a datum of the pair); a gear ratio by the triangles is
/// the quotient of two intercepts read on the plan of angular velocities.
fn derivation(
    row: &Row,
    rows: &[Row],
    all: &[ReadAt],
    (drafting, w_in): (Drafting, Option<f64>),
) -> Option<&'static str> {
    let v = row.graphical.abs();
    match (row.key.symbol, row.method) {
        (Symbol::SpecificSliding, Method::SlidingDiagram) => all
            .iter()
            .any(|r| same(read_mm(r, drafting) / crate::gears::LAMBDA_MM, v))
            .then_some("an ordinate of the sliding diagram / LAMBDA_MM"),
        (Symbol::ContactRatio, Method::Meshing) => {
            let of = |s: Symbol, sub: &str, m: Method| {
                rows.iter()
                    .find(|r| r.key.symbol == s && r.key.subject == sub && r.method == m)
            };
            let ab = of(Symbol::ActionLength, "B1B2", Method::Meshing)?;
            let pb = of(Symbol::Pitch, "b", Method::Formula)?;
            let read = all.iter().any(|r| same(r.value, ab.graphical.abs()));
            (read && same(ab.graphical / pb.analytic, v)).then_some("B₁B₂ read / p_b")
        }
        (Symbol::AngularVelocity, Method::Triangles) => {
            // ω_k = ω_in times the quotient of two intercepts of the plan of angular
            // velocities (the input's own ω is the datum the plan is drawn from).
            let q = v / w_in?;
            all.iter()
                .any(|a| {
                    all.iter().any(|b| {
                        (a.sheet, a.view) == (b.sheet, b.view)
                            && same(read_mm(a, drafting) / read_mm(b, drafting), q)
                    })
                })
                .then_some("ω_in × the quotient of two intercepts of one plan")
        }
        (Symbol::GearRatio, Method::Triangles) => all
            .iter()
            .any(|a| {
                all.iter()
                    .any(|b| (a.sheet, a.view) == (b.sheet, b.view) && same(a.value / b.value, v))
            })
            .then_some("two intercepts of one plan, one over the other"),
        _ => None,
    }
}

/// Every shipped gear sheet, exact and read to 0,5 mm: each row of the table read off the
/// drawings is a segment of the sheet giving its value ([`read_at`]), a zero read where a
/// point lies, or worked out from the sheet's readings only ([`derivation`]); every row of
/// the computed table is not graphical; the drawn envelope's deviation (fractions of a
/// micrometre) is among the computed ones.
#[test]
fn every_gear_row_under_graphical_is_read_off_its_sheet() {
    let (mut sheets, mut read, mut derived, mut computed) = (0, 0, 0, 0);
    let (mut wrong, mut unrecorded): (Vec<String>, Vec<String>) = (Vec::new(), Vec::new());
    for &(stem, _) in gallery::SHIPPED {
        let s = gallery::scene(stem).expect("a shipped scene");
        if !s.plates.contains(&PlateKind::Gears) {
            continue;
        }
        for drafting in [Drafting::EXACT, Drafting::HAND] {
            let session = Session::new(&s, drafting);
            let g = session.gears().expect("the gear study");
            let plates: Vec<(PlateKind, Plate)> = crate::sheets::build_all(&session, Lang::Ru)
                .expect("sheets")
                .into_iter()
                .filter(|(k, _)| *k == PlateKind::Gears)
                .collect();
            sheets += 1;
            let (off, by) = tables_rows(&g);
            // The input's ω as its intercept on the plan of angular velocities reads (the
            // datum the plan is drawn from, not a row of the table), rad/s.
            let w_in = g.train.as_ref().and_then(|t| {
                t.spec.n_input?;
                Some(t.triangles.omega[t.spec.train.input].abs())
            });
            let all = placed(&plates);
            let rows: Vec<Row> = off.iter().chain(&by).cloned().collect();
            for (row, at) in off.iter().zip(read_at(&off, &plates)) {
                let name = format!(
                    "{stem} ({} mm) {} {:?} = {}",
                    drafting.resolution_mm(),
                    row.quantity(),
                    row.method,
                    row.graphical
                );
                if at.is_some() || is_zero(row.graphical, row.scale) {
                    read += 1;
                } else if let Some(how) = derivation(row, &rows, &all, (drafting, w_in)) {
                    eprintln!("{name}: {how}");
                    derived += 1;
                } else if NOT_RECORDED.contains(&(row.key.symbol, row.method)) {
                    // Measured on the drawn tooth, but not yet recorded as a reading.
                    unrecorded.push(name);
                } else {
                    wrong.push(name);
                }
            }
            for row in &by {
                assert!(!row.is_read_off(), "{stem}: {}", row.quantity());
                computed += 1;
            }
            assert!(
                off.iter()
                    .all(|r| r.key.symbol != Symbol::EnvelopeDeviation),
                "{stem}: the envelope's deviation under \"графически\""
            );
        }
    }
    eprintln!(
        "{sheets} gear sheets: {read} rows read as one segment, {derived} worked out from \
         readings, {computed} computed, {} measured on the drawn tooth without a recorded \
         reading: {unrecorded:#?}",
        unrecorded.len()
    );
    assert!(
        wrong.is_empty(),
        "{} rows under \"графически\" not read off their sheet: {wrong:#?}",
        wrong.len()
    );
    assert!(
        sheets >= 10 && read >= 20,
        "{sheets} sheets, {read} rows read"
    );
}
