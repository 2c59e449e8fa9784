//! The force-analysis sheet (placeholder while it is built).
use super::BuildError;
use crate::plate::Plate;
use crate::scale::Lang;
use crate::study::Session;

/// Build the force-analysis sheets.
pub fn build(_session: &Session<'_>, _lang: Lang) -> Result<Vec<Plate>, BuildError> {
    Ok(Vec::new())
}
