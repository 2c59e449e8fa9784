//! The note's genre (`[task] genre`): a course project's explanatory note (seed 000), a
//! practical work's report on seed 002's form, or a lecture case's short report (seed 001).
//! The one place that turns the genre into the document's name, the title page's lines, the
//! headings of the sections it renames and the sources it cites.

use super::Writer;
use crate::scale::Lang;
use crate::scene::{Genre, Practicum};
use crate::words::{GenreText as G, NoteText as T};

impl Writer<'_, '_> {
    /// The scene's genre.
    pub(super) fn genre(&self) -> Genre {
        self.session.scene().title.genre
    }

    /// A section's heading (level 1): the course project's `t`, or what the genre calls it.
    pub(super) fn section(&mut self, t: T) {
        let title = heading(self.genre(), t, self.lang);
        self.doc.heading(1, title);
    }

    /// The document's name: «Пояснительная записка», «Отчёт о практической работе № 3».
    pub(super) fn document_name(&self) -> String {
        match self.genre() {
            Genre::CourseProject => self.word(T::ExplanatoryNote).into(),
            Genre::Practicum(p) => format!("{} {}", self.word(G::PracticumReport), p.number()),
            Genre::Lecture => self.word(G::LectureReport).into(),
        }
    }

    /// The line under the document's name: «к курсовому проекту по теории механизмов и
    /// машин», «по теории механизмов и машин».
    pub(super) fn document_of(&self) -> &'static str {
        match self.genre() {
            Genre::CourseProject => self.word(T::ToTheCourseProject),
            _ => self.word(G::InTheTheory),
        }
    }

    /// The designation with the document's code: a course project's note `… ПЗ`; a report
    /// has no code of ГОСТ 2.102.
    pub(super) fn designation(&self) -> String {
        let d = self.session.scene().title.in_lang(self.lang).designation;
        match self.genre() {
            Genre::CourseProject => format!("{d} {}", self.word(T::NoteCode)).trim().to_string(),
            _ => d,
        }
    }

    /// A practical work's topic and goal as seed 002's form states them.
    pub(super) fn practicum_form(&self) -> Option<(&'static str, &'static str)> {
        let Genre::Practicum(p) = self.genre() else {
            return None;
        };
        let (topic, goal) = match p {
            Practicum::RackGeneration => (G::Pz1Topic, G::Pz1Goal),
            Practicum::PlanetaryTrain => (G::Pz2Topic, G::Pz2Goal),
            Practicum::MeshGeometry => (G::Pz3Topic, G::Pz3Goal),
            Practicum::FlatCam => (G::Pz4Topic, G::CamGoal),
            Practicum::RollerCam => (G::Pz5Topic, G::CamGoal),
        };
        Some((self.word(topic), self.word(goal)))
    }

    /// The sources the note cites: the genre's seed and textbooks, then the standards of its
    /// form. A course project cites the example project (seed 000) when the scene holds
    /// values printed in it.
    pub(super) fn sources(&self) -> Vec<G> {
        let scene = self.session.scene();
        let follows_example = scene.forces.as_ref().is_some_and(|f| !f.seed.is_empty())
            || scene.dynamics.as_ref().is_some_and(|d| d.seed.is_some());
        match self.genre() {
            Genre::CourseProject => {
                let mut s = vec![G::SourceTextbook, G::SourceCourseDesign];
                if follows_example {
                    s.push(G::SourceExampleProject);
                }
                s.extend([G::SourceTextDocuments, G::SourceTitleBlocks]);
                s
            }
            Genre::Practicum(_) => vec![
                G::SourcePracticum,
                G::SourcePracticumTextbook,
                G::SourceTextDocuments,
            ],
            Genre::Lecture => vec![G::SourceLectures, G::SourceTextbook, G::SourceTextDocuments],
        }
    }
}

/// A heading as the genre words it in `lang`: the task, the studies' sections and the
/// conclusions of a practical work after its form, the task of a lecture case as its problem.
fn heading(genre: Genre, t: T, lang: Lang) -> &'static str {
    let own = match (genre, t) {
        (Genre::Practicum(_), T::Task) => G::GoalAndData,
        (Genre::Lecture, T::Task) => G::Problem,
        (Genre::Practicum(p), T::GearsSection | T::CamSection) => match p {
            Practicum::RackGeneration => G::Pz1Section,
            Practicum::PlanetaryTrain => G::Pz2Section,
            Practicum::MeshGeometry => G::Pz3Section,
            Practicum::FlatCam | Practicum::RollerCam => G::CamPracticumSection,
        },
        (Genre::Practicum(Practicum::RackGeneration), T::Conclusions) => G::Pz1Summary,
        (Genre::Practicum(Practicum::PlanetaryTrain), T::Conclusions) => G::Pz2Summary,
        _ => return t.get(lang),
    };
    own.get(lang)
}
