//! The answer key of a batch: the template's `[answer_key]` values found in its report, and
//! each variant's exact values as CSV and as a sheet, written together.

use super::GridError;
use super::VariantOutcome;
use crate::check::Row;
use crate::construct::Drafting;
use crate::scene::{AnswerItem, Scene};
use crate::study::Session;
use std::path::{Path, PathBuf};

/// A column of the answer key: the item and the template's row it names (its quantity,
/// position, method and unit).
#[derive(Debug, Clone)]
pub struct KeyColumn {
    /// The report row it names.
    pub item: AnswerItem,
    /// The template's row.
    pub row: Row,
}

/// The first row of `rows` that `item` names.
pub(super) fn row_of<'r>(rows: &'r [Row], item: &AnswerItem) -> Option<&'r Row> {
    rows.iter().find(|r| item.names(r))
}

/// The answer key's columns: every `[answer_key]` value of `template`, each found in the
/// template's own report (which gives its unit).
///
/// # Errors
/// [`GridError::Template`] when the template's report cannot be made or lacks a row.
pub fn answer_columns(template: &Scene, drafting: Drafting) -> Result<Vec<KeyColumn>, GridError> {
    let refuse = |message: String| GridError::Template {
        path: template.path.clone(),
        message,
    };
    if template.answer_key.is_empty() {
        return Ok(Vec::new());
    }
    let report = Session::new(template, drafting)
        .report()
        .map_err(|e| refuse(format!("its report cannot be made: {e}")))?;
    template
        .answer_key
        .iter()
        .enumerate()
        .map(|(k, item)| {
            let row = row_of(&report.rows, item).ok_or_else(|| {
                refuse(format!(
                    "answer_key.values[{k}] = {:?}: the report has no such row (see `tmm report --format csv` for its quantities, positions and methods)",
                    item.name()
                ))
            })?;
            Ok(KeyColumn {
                item: item.clone(),
                row: row.clone(),
            })
        })
        .collect()
}

/// The answer key as CSV: `variant`, a column per value (`v_E@3 (m/s)`: the exact value,
/// SI, 6 significant digits), and `status` (`ok`, or why the variant was not drawn).
pub fn answer_key_csv(columns: &[KeyColumn], outcomes: &[VariantOutcome]) -> String {
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut header = vec!["variant".to_string()];
    header.extend(
        columns
            .iter()
            .map(|c| format!("{} ({})", c.item.name(), c.row.unit())),
    );
    header.push("status".into());
    let mut rows = vec![header];
    for o in outcomes {
        let mut row = vec![o.name.clone()];
        match &o.result {
            Ok((_, values)) => {
                row.extend(values.iter().map(|v| {
                    v.map(crate::scale::format_plain)
                        .unwrap_or_else(|| "—".into())
                }));
                row.push("ok".into());
            }
            Err(why) => {
                row.extend(columns.iter().map(|_| String::new()));
                row.push(why.replace('\n', " "));
            }
        }
        rows.push(row);
    }
    for r in rows {
        // Writing to memory cannot fail.
        let _ = w.write_record(&r);
    }
    w.into_inner()
        .map(|b| String::from_utf8_lossy(&b).into_owned())
        .unwrap_or_default()
}

/// The answer key as a PDF: the sheet of [`crate::sheets::answer_key`] in `lang` (a variant
/// not drawn marked as such).
///
/// # Errors
/// The sheet cannot be laid out or written as PDF (the message says why).
pub fn answer_key_pdf(
    template: &Scene,
    columns: &[KeyColumn],
    outcomes: &[VariantOutcome],
    lang: crate::scale::Lang,
) -> Result<Vec<u8>, String> {
    let heads: Vec<(Row, bool)> = columns
        .iter()
        .map(|c| (c.row.clone(), c.item.method.is_some()))
        .collect();
    let lines: Vec<crate::sheets::KeyLine> = outcomes
        .iter()
        .map(|o| {
            (
                o.name.clone(),
                o.result.as_ref().ok().map(|(_, v)| v.clone()),
            )
        })
        .collect();
    let plates =
        crate::sheets::answer_key(template, &heads, &lines, lang).map_err(|e| e.to_string())?;
    crate::plate::plates_to_pdf(&plates).map_err(|e| e.to_string())
}

/// The answer key written into `out` (`answer-key.csv`, and its sheet `answer-key.pdf` when
/// the template names values, in `lang`), both files or neither; the files written.
///
/// # Errors
/// The sheet cannot be made (`Err(None, message)`), or a file cannot be written
/// (`Err(Some(path), message)`; then neither is).
pub fn write_answer_key(
    template: &Scene,
    out: &Path,
    columns: &[KeyColumn],
    outcomes: &[VariantOutcome],
    lang: crate::scale::Lang,
) -> Result<Vec<PathBuf>, (Option<PathBuf>, String)> {
    let csv = answer_key_csv(columns, outcomes).into_bytes();
    let mut files = vec![(out.join("answer-key.csv"), csv)];
    if !columns.is_empty() {
        let pdf = answer_key_pdf(template, columns, outcomes, lang).map_err(|e| (None, e))?;
        files.push((out.join("answer-key.pdf"), pdf));
    }
    crate::plate::write_all_atomic(&files).map_err(|(path, e)| (Some(path), e.to_string()))?;
    Ok(files.into_iter().map(|(path, _)| path).collect())
}
