//! The answer key of `tmm batch` as a sheet to print: one table over a class's variants of
//! the exact values the template names (`[answer_key]`), in the textbook's notation, on the
//! smallest landscape sheet from A3 up as wide as it (further sheets when the class is long);
//! and [`table_sheet`], a table on sheets, which `tmm audit`'s marked-up table shares.

use super::layout::{lay_out, quantity, Block};
use super::BuildError;
use crate::check::Row;
use crate::plate::{Plate, Sheet, SheetSize, TableBlock};
use crate::scale::{format_sig, Lang};
use crate::scene::Scene;
use crate::words::{unit_in, Text};

/// The sheets tried, smallest first.
const SIZES: [SheetSize; 3] = [SheetSize::A3, SheetSize::A2, SheetSize::A1];
/// Text height of the table, mm.
const TABLE_MM: f64 = 3.0;
/// The room the layout keeps around a block, mm (a generous bound).
const ROOM_MM: f64 = 10.0;

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
                        None => super::digits::NO_VALUE.into(),
                    }));
                    cells.push(String::new());
                }
                None => {
                    cells.extend(columns.iter().map(|_| super::digits::NO_VALUE.to_string()));
                    cells.push(Text::NotDrawn.get(lang).into());
                }
            }
            cells
        })
        .collect();
    let title = format!(
        "{} ({})",
        Text::AnswerKey.get(lang),
        Text::ExactValues.get(lang)
    );
    let name = Text::AnswerKey.get(lang);
    table_sheet(
        template,
        (&title, name),
        header,
        rows,
        (&SIZES, "answer-key"),
        lang,
    )
}

/// One table (`columns`: heading and width, mm; `rows`: the cells) as sheets with their
/// frame and title block — `titles` the table's title and the title block's name — on the
/// smallest landscape format of `sizes` whose field is as wide as the table, the rows
/// continued on further sheets of it (each part headed again), the sheets named `stem`.
///
/// # Errors
/// [`BuildError`] when the table is wider than the largest size.
pub fn table_sheet(
    scene: &Scene,
    titles: (&str, &str),
    columns: Vec<(String, f64)>,
    rows: Vec<Vec<String>>,
    (sizes, stem): (&[SheetSize], &str),
    lang: Lang,
) -> Result<Vec<Plate>, BuildError> {
    let width: f64 = columns.iter().map(|c| c.1).sum();
    let sheet_of = |size| Sheet {
        size,
        landscape: true,
    };
    let sheet = sizes
        .iter()
        .map(|&s| sheet_of(s))
        .find(|s| s.field().width() >= width + 2.0 * ROOM_MM)
        .or_else(|| sizes.last().map(|&s| sheet_of(s)))
        .unwrap_or_default();
    // The rows one part of the table holds: the field's height less the title, the heading
    // and the room the layout keeps.
    let row_mm = 2.0 * TABLE_MM;
    let per_part = ((sheet.field().height() - 2.0 * ROOM_MM - 1.6 * TABLE_MM) / row_mm - 1.0)
        .floor()
        .max(1.0) as usize;
    let continued = Text::Continued.get(lang);
    let blocks: Vec<Block> = rows
        .chunks(per_part)
        .enumerate()
        .map(|(k, part)| {
            Block::Table(TableBlock {
                at: crate::geom::DVec2::ZERO,
                title: if k == 0 {
                    titles.0.to_string()
                } else {
                    format!("{} {continued}", titles.0)
                },
                columns: columns.clone(),
                rows: part.to_vec(),
                size_mm: TABLE_MM,
            })
        })
        .collect();
    // The title block's scale cell: a table is drawn at no scale.
    let title = super::title_block(scene, titles.1, None, lang);
    Ok(super::numbered(lay_out(sheet, blocks, stem, &title, lang)?))
}
