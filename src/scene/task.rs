//! `[task]`: the title block's and the title page's data, each text in the scene's own
//! language and, in `[task.ru]`, `[task.uk]` and `[task.en]`, in another; and the genre of the
//! work the scene is (`genre`, [`Genre`]), which decides the note's title, headings and
//! sources.

use super::check::Checker;
use super::genre::Genre;
use super::model::TitleInfo;
use super::raw::RawTask;
use crate::scale::Lang;

/// `[task]`, the title defaulting to the file stem, each language's table checked.
pub(super) fn title(check: &mut Checker, task: RawTask, stem: &str) -> TitleInfo {
    let genre = match task.genre.as_deref() {
        None => Genre::CourseProject,
        Some(v) => Genre::parse(v).unwrap_or_else(|| {
            check.push(
                "task.genre",
                Some(format!("\"{v}\"")),
                "expected \"course-project\", \"lecture\" or \"practicum-1\" … \"practicum-5\"",
            );
            Genre::CourseProject
        }),
    };
    let localised = [
        (Lang::Ru, task.ru),
        (Lang::Uk, task.uk),
        (Lang::En, task.en),
    ]
    .into_iter()
    .filter_map(|(lang, t)| t.map(|t| (lang, t)))
    .collect();
    TitleInfo {
        title: task.title.unwrap_or_else(|| stem.to_string()),
        designation: task.designation.unwrap_or_default(),
        author: task.author.unwrap_or_default(),
        checked: task.checked.unwrap_or_default(),
        organisation: task.organisation.unwrap_or_default(),
        university: task.university.unwrap_or_default(),
        city: task.city.unwrap_or_default(),
        group: task.group.unwrap_or_default(),
        year: task.year.unwrap_or_default(),
        note: task.note.unwrap_or_default(),
        genre,
        localised,
    }
}

impl TitleInfo {
    /// The texts in `lang`: each the language's table gives (`[task.uk]`), else the scene's
    /// own — the designation in Latin letters in English (ТММ.КП.000 → TMM.KP.000).
    pub fn in_lang(&self, lang: Lang) -> TitleInfo {
        let mut t = self.clone();
        if lang == Lang::En {
            t.designation = crate::scale::latin(&t.designation);
        }
        let Some((_, own)) = self.localised.iter().find(|(l, _)| *l == lang) else {
            return t;
        };
        for (field, value) in [
            (&mut t.title, &own.title),
            (&mut t.designation, &own.designation),
            (&mut t.author, &own.author),
            (&mut t.checked, &own.checked),
            (&mut t.organisation, &own.organisation),
            (&mut t.university, &own.university),
            (&mut t.city, &own.city),
            (&mut t.group, &own.group),
        ] {
            if let Some(v) = value {
                field.clone_from(v);
            }
        }
        t
    }
}
