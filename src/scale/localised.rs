//! A text a scene gives in each language of the sheets and the note: read by the scene's
//! loader, carried by the report's seed values, picked per [`Lang`] by the note.

use super::Lang;

/// A text the scene gives in each language of the sheets and the note (`{ ru = "…",
/// uk = "…", en = "…" }`), in label markup.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Localised {
    /// Russian.
    pub ru: String,
    /// Ukrainian.
    pub uk: String,
    /// English.
    pub en: String,
}

impl Localised {
    /// The text in `lang`.
    pub fn get(&self, lang: Lang) -> &str {
        lang.pick(&self.ru, &self.uk, &self.en)
    }
}
