//! The English of a report's notes: the one place where each typed note
//! ([`ReportNote`](crate::check::ReportNote)) becomes the sentence the report writes (Markdown, JSON),
//! with the verdicts ([`Finding`](crate::check::Finding)) it states in their place.

mod balancing;
mod blocking;
mod cam;
mod dynamics;
mod finding;
mod forces;
mod friction;
mod gears;
mod kinematics;
#[cfg(test)]
mod scan;
mod seed;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_gears;
mod train;

use crate::check::{Report, ReportNote};
use crate::scale::{format_sig, Lang};

/// A number in a note: `digits` significant digits, English decimal point.
fn sig(x: f64, digits: usize) -> String {
    format_sig(x, digits, Lang::En)
}

/// The note as the report writes it.
pub fn english(note: &ReportNote) -> String {
    match note {
        ReportNote::Cam(n) => cam::english(n),
        ReportNote::Dynamics(n) => dynamics::english(n),
        ReportNote::Gears(n) => gears::english(n),
        ReportNote::Train(n) => train::english(n),
        ReportNote::Forces(n) => forces::english(n),
        ReportNote::Seed(n) => seed::english(n),
        ReportNote::Balancing(n) => balancing::english(n),
        ReportNote::Friction(n) => friction::english(n),
        ReportNote::Kinematics(n) => kinematics::english(n),
        ReportNote::Blocking(n) => blocking::english(n),
    }
}

impl Report {
    /// The notes as the report writes them, in order.
    pub fn note_texts(&self) -> Vec<String> {
        self.notes.iter().map(english).collect()
    }
}
