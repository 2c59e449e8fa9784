//! The look-up of a report's row the machine sections share (the kinetostatics and the
//! dynamics have their own files, the lecture cases theirs).

use crate::check::{Method, Row};

/// The row of `quantity` by `method` at `position` (`None`: of the whole scene).
pub(super) fn row<'r>(
    rows: &'r [Row],
    q: &str,
    method: Method,
    position: Option<&str>,
) -> Option<&'r Row> {
    rows.iter()
        .find(|r| r.quantity() == q && r.method == method && r.position().as_deref() == position)
}
