//! The answer key of `tmm batch` as a sheet to print: one table over a class's variants of
//! the exact values the template names (`[answer_key]`), in the textbook's notation, on the
//! smallest landscape sheet from A3 up that holds it (further sheets when the class is long).

use super::captions::{unit_in, Text};
use super::layout::{lay_out_smallest, quantity, Block};
use super::BuildError;
use crate::check::Row;
use crate::plate::{Plate, SheetSize, TableBlock};
use crate::scale::{format_sig, Lang, Quantity, Scale};
use crate::scene::Scene;

/// The sheets tried, smallest first.
const SIZES: [SheetSize; 3] = [SheetSize::A3, SheetSize::A2, SheetSize::A1];
/// Text height of the table, mm.
const TABLE_MM: f64 = 3.0;

/// One variant's line of the key: its name and its values in the order of the columns, or
/// `None` when it was not drawn.
pub type KeyLine = (String, Option<Vec<Option<f64>>>);

/// The answer key over `lines`, its columns the template's report rows `columns` (each
/// headed by its quantity, position and unit, the method where it was asked for), values to
/// 4 significant digits, a variant not drawn marked as such.
///
/// # Errors
/// [`BuildError`] when the table does not fit even an A1.
pub fn answer_key(
    template: &Scene,
    columns: &[(Row, bool)],
    lines: &[KeyLine],
    lang: Lang,
) -> Result<Vec<Plate>, BuildError> {
    // Each column as wide as its heading: a heading condensed into its cell would carry
    // `textLength` over its subscripts.
    let width = |text: &str| (crate::plate::text::approx_width(text, TABLE_MM) + 4.0).max(22.0);
    let mut header = vec![(Text::Variant.get(lang).to_string(), 18.0)];
    for (row, with_method) in columns {
        let mut text = format!("{}, {}", quantity(row, lang), unit_in(row.unit(), lang));
        if *with_method {
            text = format!("{text}, {}", row.method.name(lang));
        }
        let w = width(&text);
        header.push((text, w));
    }
    let remark = Text::Remark.get(lang).to_string();
    header.push((remark, 30.0));
    let rows = lines
        .iter()
        .map(|(name, values)| {
            let mut cells = vec![name.clone()];
            match values {
                Some(values) => {
                    cells.extend(values.iter().map(|v| match v {
                        Some(x) => format_sig(*x, 4, lang),
                        None => "—".into(),
                    }));
                    cells.push(String::new());
                }
                None => {
                    cells.extend(columns.iter().map(|_| "—".to_string()));
                    cells.push(Text::NotDrawn.get(lang).into());
                }
            }
            cells
        })
        .collect();
    let blocks = vec![Block::Table(TableBlock {
        at: crate::geom::DVec2::ZERO,
        title: format!(
            "{} ({})",
            Text::AnswerKey.get(lang),
            Text::ExactValues.get(lang)
        ),
        columns: header,
        rows,
        size_mm: TABLE_MM,
    })];
    // The title block's scale cell: a table is drawn at no scale.
    let one = Scale::new(0.001, Quantity::Length).ok_or(BuildError::NoScale(0.001))?;
    let mut title = super::title_block(template, Text::AnswerKey.get(lang), one, lang);
    title.scale = "—".into();
    Ok(super::numbered(lay_out_smallest(
        &SIZES,
        blocks,
        "answer-key",
        &title,
        lang,
    )?))
}
