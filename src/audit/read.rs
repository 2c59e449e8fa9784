//! Reading a student's table: its header, and each line's quantity, position, number, unit
//! and method.

use super::{units, AuditError, Auditor, Entry, NumberError, Unit, Written};
use crate::check::Method;
use crate::scene::user_table::{self, CellError};
use std::path::Path;

/// The columns of a student's table.
const COLUMNS: [&str; 5] = ["quantity", "position", "value", "unit", "method"];

/// The values of the student's table `text` (the file `path`), each in a unit of its
/// quantity's kind.
///
/// The table is CSV with a header naming its columns, in any order, each once: `quantity`
/// (the report's name, `v_B3`, or a column of its analytic table, `phi_3`, `L_3`),
/// `position` (its label, `3`, `8′` or `8'`; empty for a quantity of the whole scene),
/// `value`, `unit` (the textbook's: `m/s`, `мм`, `об/мин`, `кгс`) and, optionally, `method`
/// (a report method, `plan`, `lever`, or `analytic`). A header with `;` and no `,` is read
/// with `;` between fields and decimal commas. Lines starting with `#` are comments. A line
/// of a quantity, position or method the report lacks is read (its unit one of any kind):
/// [`Auditor::audit`] marks it.
///
/// # Errors
/// [`AuditError`] for the first problem of the file — a column missing, unknown or named
/// twice, a line of too few or too many fields, a value that is not a number (or beyond a
/// double's range), a unit not of the quantity's kind, a method that is none — with its line,
/// column and key; nothing is audited.
pub fn read_table(text: &str, path: &Path, auditor: &Auditor) -> Result<Vec<Entry>, AuditError> {
    let whole = |message: String| AuditError::Table {
        path: path.to_path_buf(),
        message,
    };
    let (mut reader, semicolons) = user_table::reader(text);
    let header: Vec<String> = reader
        .headers()
        .map_err(|e| whole(format!("the header: {e}")))?
        .iter()
        .map(|h| h.trim().to_lowercase())
        .collect();
    let column = |name: &str| header.iter().position(|h| h == name);
    for (k, h) in header.iter().enumerate() {
        if !COLUMNS.contains(&h.as_str()) {
            return Err(whole(format!(
                "the header names a column {h:?}: expected quantity, position, value, unit and, optionally, method"
            )));
        }
        if let Some(first) = header[..k].iter().position(|o| o == h) {
            return Err(whole(format!(
                "the header names the column `{h}` twice (columns {} and {}): which is the student's?",
                first + 1,
                k + 1
            )));
        }
    }
    let need = |name: &str| {
        column(name).ok_or_else(|| {
            whole(format!(
                "the header has no column `{name}` (expected quantity, position, value, unit and, optionally, method)"
            ))
        })
    };
    let (cq, cp, cv, cu) = (
        need("quantity")?,
        need("position")?,
        need("value")?,
        need("unit")?,
    );
    let cm = column("method");
    let mut entries = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| whole(e.to_string()))?;
        let line = record.position().map_or(0, |p| p.line());
        if record.iter().all(|f| f.trim().is_empty()) {
            continue;
        }
        let cell = |c: usize, message: String| {
            AuditError::Cell(CellError {
                path: path.to_path_buf(),
                line,
                column: c + 1,
                key: header[c].clone(),
                message,
            })
        };
        if record.len() != header.len() {
            let c = record.len().min(header.len() - 1);
            return Err(cell(
                c,
                format!("{} fields, the header has {}", record.len(), header.len()),
            ));
        }
        let field = |c: usize| record[c].trim();
        let quantity = field(cq).to_string();
        let position = Some(field(cp).replace('\'', "′")).filter(|p| !p.is_empty());
        let method = cm.map(|c| field(c).to_string()).filter(|m| !m.is_empty());
        if let Some(m) = &method {
            if m != "analytic" && Method::parse(m).is_none_or(|p| p.key() != m) {
                return Err(cell(
                    cm.unwrap_or(0),
                    format!("{m:?}: expected a report method (plan, diagram-chords, polygon, lever, …) or analytic"),
                ));
            }
        }
        let written = Written::parse(field(cv), semicolons).map_err(|e| {
            cell(
                cv,
                match e {
                    NumberError::NotANumber => format!("{:?}: not a number", field(cv)),
                    NumberError::OutOfRange => {
                        format!(
                            "{:?}: out of the range of a number (about 1e±308)",
                            field(cv)
                        )
                    }
                },
            )
        })?;
        let unit = unit(auditor.unit(&quantity), field(cu), &quantity).map_err(|m| cell(cu, m))?;
        entries.push(Entry {
            line,
            quantity,
            position,
            method,
            written,
            unit,
        });
    }
    if entries.is_empty() {
        return Err(whole("no value: expected a row after the header".into()));
    }
    Ok(entries)
}

/// The unit `written` of `quantity`, whose SI unit is `si` (`None`: a quantity the report
/// lacks, whose line is kept to be marked: a unit of any kind); why not, in words.
fn unit(si: Option<&str>, written: &str, quantity: &str) -> Result<Unit, String> {
    match si {
        Some(si) => units::find(si, written).ok_or_else(|| {
            let names: Vec<&str> = units::kind(si).iter().map(|u| u.name).collect();
            format!(
                "{written:?}: not a unit of {quantity} (expected one of {})",
                names.join(", ")
            )
        }),
        None => {
            units::any(written).ok_or_else(|| format!("{written:?}: not a unit the audit knows"))
        }
    }
}
