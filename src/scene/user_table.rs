//! The tables a user writes beside a scene (a variant grid, a student's table): CSV with
//! `,` between fields, or — when the header holds `;` and no `,` — with `;` between fields
//! and decimal commas in the numbers; lines starting with `#` are comments. A field that is
//! refused is named by its line, column and key.

use std::path::PathBuf;
use thiserror::Error;

/// A reader of the table `text` and whether its numbers carry decimal commas.
pub fn reader(text: &str) -> (csv::Reader<&[u8]>, bool) {
    let header = text
        .lines()
        .find(|l| !l.trim_start().starts_with('#') && !l.trim().is_empty())
        .unwrap_or("");
    let semicolons = header.contains(';') && !header.contains(',');
    let reader = csv::ReaderBuilder::new()
        .delimiter(if semicolons { b';' } else { b',' })
        .comment(Some(b'#'))
        .flexible(true)
        .from_reader(text.as_bytes());
    (reader, semicolons)
}

/// One field of a table refused.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("{}: line {line}, column {column} ({key}): {message}", .path.display())]
pub struct CellError {
    /// The table's file.
    pub path: PathBuf,
    /// The line of the file, from 1 (the header is line 1).
    pub line: u64,
    /// The column, from 1.
    pub column: usize,
    /// The column's key.
    pub key: String,
    /// What is wrong with the value.
    pub message: String,
}
