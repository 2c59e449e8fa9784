//! A variant's task sheet (`tmm batch`): the mechanism's kinematic scheme as a task gives it
//! (whole: its Assur groups are the student's to find) and every datum the variant's sheets
//! need (lengths, ω₁, masses, moments of inertia, working resistances; the gears, the cam's
//! phases and laws, the machine's ω_ср, δ and constant inertias), one page to hand out.

use super::data::{data_block, forces, gears, mechanism, DataPart, DataRow};
use super::layout::{lay_out_smallest, Block};
use super::BuildError;
use crate::geom::DVec2;
use crate::plate::{Plate, SheetSize, TableBlock};
use crate::scale::Lang;
use crate::scene::PlateKind;
use crate::study::Session;
use crate::words::{unit_in, NoteText, Text};

/// The sheets tried, smallest first.
const SIZES: [SheetSize; 3] = [SheetSize::A4, SheetSize::A3, SheetSize::A2];
/// Text height of the table, mm.
const TABLE_MM: f64 = 3.5;

/// The task sheet of the scene of `session` as variant `variant`: the structural scheme at
/// its own scale and the data table, the title block saying «Задание, вариант …».
///
/// # Errors
/// [`BuildError`] when the scene has no mechanism or the scheme cannot be drawn.
pub fn task_sheet(
    session: &Session<'_>,
    variant: &str,
    lang: Lang,
) -> Result<Vec<Plate>, BuildError> {
    let scene = session.scene();
    let m = session.mechanism("the task sheet")?;
    let scheme = super::positions::kinematic_scheme(session, lang)?;
    let mut data = mechanism(m, lang);
    if let Some(f) = &scene.forces {
        data.extend(forces(f, lang));
    }
    let mut tables = vec![data_table(Text::Data.get(lang), data, lang)];
    // The gears' parts (the pair, each wheel cut by the rack, the train), a table each
    // under the part's name: a data row with neither value nor unit names the part.
    if let Some(g) = &scene.gears {
        for row in gears(g, lang) {
            match (tables.last_mut(), row.1.is_empty() && row.2.is_empty()) {
                (Some(t), false) => t.rows.push(data_row(row, lang)),
                _ => tables.push(data_table(&row.0, Vec::new(), lang)),
            }
        }
    }
    let sheet_title = format!(
        "{}, {} {variant}",
        NoteText::Task.get(lang),
        Text::Variant.get(lang)
    );
    let mut title = super::title_block(scene, &sheet_title, Some(session.scale_l()?), lang);
    // The scheme's caption carries its own μ_l.
    title.scale = "—".into();
    let mut blocks = vec![scheme];
    blocks.extend(tables.into_iter().map(Block::Table));
    // The machine's and the cam's data as their sheets print them (one place for each line).
    let mut lines = Vec::new();
    for kind in [PlateKind::Dynamics, PlateKind::Cam] {
        if !scene.plates.contains(&kind) {
            continue;
        }
        let sheets = super::build(session, kind, lang)?;
        let data = data_block(&sheets, DataPart::Inputs, lang);
        if !data.is_empty() {
            lines.push(format!("{}:", kind_title(kind, lang)));
            lines.extend(data);
        }
    }
    if !lines.is_empty() {
        blocks.push(Block::Text {
            lines,
            size_mm: TABLE_MM,
        });
    }
    Ok(super::numbered(lay_out_smallest(
        &SIZES, blocks, "task", &title, lang,
    )?))
}

/// The heading of a study's data on the task sheet.
fn kind_title(kind: PlateKind, lang: Lang) -> &'static str {
    match kind {
        PlateKind::Cam => NoteText::CamSection.get(lang),
        _ => NoteText::Dynamics.get(lang),
    }
}

/// A table of data under `title`: symbol, value, unit.
fn data_table(title: &str, rows: Vec<DataRow>, lang: Lang) -> TableBlock {
    TableBlock {
        at: DVec2::ZERO,
        title: title.into(),
        columns: vec![
            (Text::Quantity.get(lang).into(), 24.0),
            (NoteText::Value.get(lang).into(), 30.0),
            (Text::Unit.get(lang).into(), 20.0),
        ],
        rows: rows.into_iter().map(|r| data_row(r, lang)).collect(),
        size_mm: TABLE_MM,
    }
}

/// A data row as the table's cells, the unit in `lang`.
fn data_row((symbol, value, unit): DataRow, lang: Lang) -> Vec<String> {
    vec![symbol, value, unit_in(&unit, lang)]
}
