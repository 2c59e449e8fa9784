//! A variant's task sheet (`tmm batch`): the mechanism's structural scheme and the task's data
//! (lengths, ω₁, masses, moments of inertia, working resistances), one page to hand out.

use super::captions::{unit_in, NoteText, Text};
use super::data::{forces, mechanism};
use super::layout::{lay_out_smallest, Block};
use super::BuildError;
use crate::geom::DVec2;
use crate::plate::{Plate, SheetSize, TableBlock};
use crate::scale::Lang;
use crate::study::Session;

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
    let (scheme, _) = super::positions::structure(session, lang)?;
    let mut data = mechanism(m, lang);
    if let Some(f) = &scene.forces {
        data.extend(forces(f, lang));
    }
    let rows = data
        .into_iter()
        .map(|(symbol, value, unit)| vec![symbol, value, unit_in(&unit, lang)])
        .collect();
    let table = TableBlock {
        at: DVec2::ZERO,
        title: Text::Data.get(lang).into(),
        columns: vec![
            (Text::Quantity.get(lang).into(), 24.0),
            (NoteText::Value.get(lang).into(), 30.0),
            (Text::Unit.get(lang).into(), 20.0),
        ],
        rows,
        size_mm: TABLE_MM,
    };
    let sheet_title = format!(
        "{}, {} {variant}",
        NoteText::Task.get(lang),
        Text::Variant.get(lang)
    );
    let mut title = super::title_block(scene, &sheet_title, session.scale_l()?, lang);
    // The scheme's caption carries its own μ_l.
    title.scale = "—".into();
    Ok(super::numbered(lay_out_smallest(
        &SIZES,
        vec![scheme, Block::Table(table)],
        "task",
        &title,
        lang,
    )?))
}
