//! The font database: only the DejaVu Sans faces bundled with the program.

use resvg::usvg::fontdb::Database;
use std::sync::{Arc, OnceLock};

/// The family every text and every generic family resolves to.
const FAMILY: &str = "DejaVu Sans";

/// The fonts text is rendered with: DejaVu Sans (regular, oblique, bold, bold oblique) from
/// the `dejavu` crate, with every generic family (serif, sans-serif, monospace, cursive,
/// fantasy) set to DejaVu Sans. System fonts are never loaded, so a plate renders the same
/// on every machine. Built once and shared.
pub fn font_database() -> Arc<Database> {
    static DB: OnceLock<Arc<Database>> = OnceLock::new();
    DB.get_or_init(|| {
        let mut db = Database::new();
        for face in faces() {
            db.load_font_data(face.to_vec());
        }
        db.set_serif_family(FAMILY);
        db.set_sans_serif_family(FAMILY);
        db.set_monospace_family(FAMILY);
        db.set_cursive_family(FAMILY);
        db.set_fantasy_family(FAMILY);
        Arc::new(db)
    })
    .clone()
}

/// The bundled faces: DejaVu Sans regular, oblique, bold, bold oblique.
pub(crate) fn faces() -> [&'static [u8]; 4] {
    [
        dejavu::sans::regular(),
        dejavu::sans::oblique(),
        dejavu::sans::bold(),
        dejavu::sans::bold_oblique(),
    ]
}

/// The family name the database answers to.
pub(crate) fn family() -> &'static str {
    FAMILY
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_bundled_faces_are_loaded() {
        let db = font_database();
        assert_eq!(db.len(), 4);
        assert!(db
            .faces()
            .all(|f| f.families.iter().any(|(name, _)| name == FAMILY)));
    }
}
