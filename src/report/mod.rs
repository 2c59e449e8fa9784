//! The writers of reports: graphical against analytic values, row by row, with the
//! section-1.6 summary of the seed (mean and largest relative error per quantity and method).
//!
//! The check of every construction produces typed rows; a study collects them into a report
//! together with its analytic tables — result data, kept in [`crate::check`]
//! ([`Row`](crate::check::Row), [`Report`](crate::check::Report),
//! [`Table`](crate::check::Table)). This module only writes a report: JSON
//! ([`Report::to_json`](crate::check::Report::to_json)), CSV
//! ([`Report::to_csv`](crate::check::Report::to_csv)) or Markdown
//! ([`Report::to_markdown`](crate::check::Report::to_markdown)); nothing below it (the checks,
//! the domains, the session) imports it. The bench's table and plot are in [`crate::bench`].
//!
//! Error conventions:
//! - `abs_error` = |graphical − analytic|, in the row's unit;
//! - `rel_error` = (graphical − analytic) / |analytic| (signed, as a fraction; the seed's
//!   tables print it in %), absent when the analytic value is zero to rounding against the
//!   quantity's scale over the cycle ([`crate::check::is_zero`]).
//!
//! Non-finite numbers: JSON has no NaN or infinity, so every writer writes a non-finite number
//! as `null`; a JSON row in which that happened carries an extra key `"non_finite"` listing
//! the fields concerned (rows with finite numbers have exactly the documented keys). CSV
//! writes such a number as Rust prints it (`NaN`, `inf`, `-inf`) so that it is not mistaken
//! for an absent value; Markdown writes it the same way.

mod format;
mod notes;
#[cfg(test)]
pub(crate) mod tests;

pub use format::CSV_HEADER;
pub(crate) use format::{finite, json, md_cell, md_header, md_row};
