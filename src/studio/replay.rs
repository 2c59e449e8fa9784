//! The replay of a sheet's figures: for every view of one sheet, the construction protocol
//! ([`crate::sheets::protocol`]) in the recorder's order — the step ids the sheet's SVG
//! groups carry (`view-{k}-step-{id}`) with their sentences and position groups — and, for
//! each of the view's labels in the order the SVG writes them, the steps it names, so that
//! the page shows a label with its step.

use super::redraw::{plates_of, Job, PageProblem};
use crate::plate::{self, text::plain};
use crate::sheets::protocol::protocol;
use crate::study::Session;
use serde::{Deserialize, Serialize};

/// A step of the replay.
#[derive(Debug, Clone, Serialize)]
pub struct ReplayStep {
    /// The step's id in its figure (`view-{k}-step-{id}` in the SVG).
    pub id: usize,
    /// Its sentence in the language asked.
    pub sentence: String,
    /// Its group (a position's number on a plan of positions; 0 when unused): play stops
    /// where it changes.
    pub group: u32,
}

/// A figure of the sheet to replay.
#[derive(Debug, Clone, Serialize)]
pub struct ReplayView {
    /// The view's index on the sheet (`view-{k}` in the SVG).
    pub view: usize,
    /// Its caption, plain text.
    pub caption: String,
    /// Its steps in the recorder's order.
    pub steps: Vec<ReplayStep>,
    /// For each of its labels (`view-{k}-labels-text-{n}`, n from 1), the steps it names.
    pub labels: Vec<Vec<usize>>,
}

/// A replay request: a scene and the index of its sheet.
#[derive(Debug, Clone, Deserialize)]
pub struct ReplayJob {
    /// The scene.
    #[serde(flatten)]
    pub job: Job,
    /// The sheet's index in the set.
    pub sheet: usize,
}

/// The figures of sheet `r.sheet` of the scene, with their protocols; or the problems.
pub fn replay(r: &ReplayJob) -> Result<Vec<ReplayView>, Vec<PageProblem>> {
    let (s, drafting) = r.job.scene()?;
    let lang = r.job.lang();
    let session = Session::new(&s, drafting);
    let plates = plates_of(&session, lang)?;
    let Some((_, sheet)) = plates.get(r.sheet) else {
        return Err(vec![PageProblem {
            key: None,
            message: format!("sheet {}: the scene has {} sheets", r.sheet, plates.len()),
        }]);
    };
    Ok(views_of(sheet, lang))
}

/// The figures of `sheet` with their protocols in `lang`.
pub fn views_of(sheet: &plate::Plate, lang: crate::scale::Lang) -> Vec<ReplayView> {
    let laid = plate::layout(sheet);
    sheet
        .views
        .iter()
        .enumerate()
        .filter(|(_, v)| !v.figure.steps.is_empty())
        .map(|(k, v)| ReplayView {
            view: k,
            caption: v.caption.as_deref().map(plain).unwrap_or_default(),
            steps: protocol(&v.figure, lang)
                .into_iter()
                .zip(&v.figure.steps)
                .map(|(said, step)| ReplayStep {
                    id: said.step,
                    sentence: said.sentence,
                    group: step.group,
                })
                .collect(),
            labels: laid
                .labels
                .iter()
                .filter(|l| l.view == k)
                .map(|l| l.steps.iter().map(|s| s.0 as usize).collect())
                .collect(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::studio::gallery;

    /// Every figure of every sheet of every shipped scene replays its recorder's steps in
    /// order, each with a sentence in ru, uk and en (no template mark left).
    #[test]
    fn every_figure_replays_the_recorders_steps_in_order_in_every_language() {
        let mut figures = 0;
        for &(stem, text) in gallery::SHIPPED {
            for lang in ["ru", "uk", "en"] {
                let job = Job {
                    toml: text.into(),
                    stem: stem.into(),
                    lang: lang.into(),
                    drafting: 0.5,
                };
                let s = gallery::scene(stem).expect("scene");
                let session = Session::new(&s, crate::construct::Drafting::HAND);
                let sheets = crate::sheets::build_all(&session, job.lang()).expect("sheets");
                for (k, (_, sheet)) in sheets.iter().enumerate() {
                    let r = ReplayJob {
                        job: job.clone(),
                        sheet: k,
                    };
                    let views = replay(&r).unwrap_or_else(|_| panic!("{stem} {k}"));
                    for v in &views {
                        let fig = &sheet.views[v.view].figure;
                        let ids: Vec<usize> = v.steps.iter().map(|s| s.id).collect();
                        let recorded: Vec<usize> =
                            fig.steps.iter().map(|s| s.id.0 as usize).collect();
                        assert_eq!(ids, recorded, "{stem} sheet {k} view {}", v.view);
                        for s in &v.steps {
                            assert!(
                                !s.sentence.is_empty() && !s.sentence.contains('{'),
                                "{stem} {lang} sheet {k} view {} step {}: «{}»",
                                v.view,
                                s.id,
                                s.sentence
                            );
                        }
                        figures += 1;
                    }
                }
            }
        }
        assert!(figures > 300, "{figures} figures");
    }
}
