//! What an edit costs: a scene's text made into its sheets as SVG and its report — what the
//! studio answers to each edit, and what `tmm bench` times per shipped scene.

use crate::construct::Drafting;
use crate::plate;
use crate::scale::Lang;
use crate::scene::{self, PlateKind, Scene};
use crate::study::Session;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The language `s` names (`uk`), Russian when absent or unknown.
pub(crate) fn lang_of(s: Option<&str>) -> Lang {
    s.and_then(Lang::parse).unwrap_or_default()
}

/// A scene to render: its text, its stem (names it in messages and files), the language and
/// the drafting resolution.
#[derive(Debug, Clone, Deserialize)]
pub struct Job {
    /// The scene's text.
    pub toml: String,
    /// Its stem (`shaper`).
    #[serde(default)]
    pub stem: String,
    /// The language (`ru`, `uk`, `en`).
    #[serde(default)]
    pub lang: String,
    /// The drafting resolution, mm (0: exact).
    #[serde(default = "hand")]
    pub drafting: f64,
}

fn hand() -> f64 {
    Drafting::HAND.resolution_mm()
}

/// A problem the page shows at its field: the key it names, when it names one.
#[derive(Debug, Serialize)]
pub struct PageProblem {
    /// The scene key it names.
    pub key: Option<String>,
    /// The program's message.
    pub message: String,
}

/// A sheet as the page shows it.
#[derive(Debug, Serialize)]
pub struct PageSheet {
    /// The sheet's name (`kinematics`, `forces-2`).
    pub name: String,
    /// The sheet as SVG.
    pub svg: String,
}

/// What `POST /api/render` answers: the sheets, the report (as `tmm report --format json`),
/// or the problems; with the time the server took.
#[derive(Debug, Serialize, Default)]
pub struct Redrawn {
    /// Every sheet, in the set's order.
    pub sheets: Vec<PageSheet>,
    /// The report, as `tmm report --format json` gives it.
    pub report: Option<serde_json::Value>,
    /// Why there are no sheets.
    pub problems: Vec<PageProblem>,
    /// The time taken, ms.
    pub ms: f64,
}

/// The stem a page's scene is named by: its own letters, digits, `-` and `_` only.
pub(crate) fn stem_of(stem: &str) -> String {
    let clean: String = stem
        .chars()
        .filter(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_'))
        .take(64)
        .collect();
    if clean.is_empty() {
        "scene".into()
    } else {
        clean
    }
}

impl Job {
    fn path(&self) -> PathBuf {
        Path::new(&stem_of(&self.stem)).with_extension("toml")
    }

    pub(crate) fn lang(&self) -> Lang {
        lang_of(Some(&self.lang))
    }

    /// The scene, or the problems to show.
    pub(crate) fn scene(&self) -> Result<(Scene, Drafting), Vec<PageProblem>> {
        let drafting = Drafting::new(self.drafting).ok_or_else(|| {
            vec![PageProblem {
                key: None,
                message: format!("drafting {}: expected a resolution ≥ 0 mm", self.drafting),
            }]
        })?;
        let s = scene::parse(&self.toml, &self.path()).map_err(|e| {
            let listed: Vec<PageProblem> = e
                .problems()
                .iter()
                .map(|p| PageProblem {
                    key: Some(p.key.clone()),
                    message: p.to_string(),
                })
                .collect();
            match listed.is_empty() {
                true => vec![PageProblem {
                    key: toml_key(&e),
                    message: e.to_string(),
                }],
                false => listed,
            }
        })?;
        Ok((s, drafting))
    }
}

/// The key a TOML reader's message names.
fn toml_key(e: &scene::SceneError) -> Option<String> {
    match e {
        scene::SceneError::Toml { key, .. } => key.clone(),
        _ => None,
    }
}

/// The sheets of `session` in `lang`, or the problem to show: the plate that cannot be built.
pub(crate) fn plates_of(
    session: &Session<'_>,
    lang: Lang,
) -> Result<Vec<(PlateKind, plate::Plate)>, Vec<PageProblem>> {
    crate::sheets::build_all(session, lang).map_err(|(kind, error)| {
        vec![PageProblem {
            key: None,
            message: format!("{}: {error}", kind.stem()),
        }]
    })
}

/// Every sheet as the page shows it: its name and its SVG.
pub(crate) fn sheets_of(plates: &[(PlateKind, plate::Plate)]) -> Vec<PageSheet> {
    plates
        .iter()
        .map(|(_, p)| PageSheet {
            name: p.name.clone(),
            svg: plate::to_svg(p),
        })
        .collect()
}

/// The session's report as `tmm report --format json` gives it, each row with `read_at`:
/// where its value is read on `plates` ([`super::readings::read_at`]), `null` when it is
/// computed; `None` when the session has no report.
pub(crate) fn report_of(
    session: &Session<'_>,
    plates: &[(PlateKind, plate::Plate)],
) -> Option<serde_json::Value> {
    let report = session.report().ok()?;
    let mut json: serde_json::Value = serde_json::from_str(&report.to_json()).ok()?;
    let read = super::readings::read_at(&report.rows, plates);
    if let Some(rows) = json.get_mut("rows").and_then(|r| r.as_array_mut()) {
        for (row, at) in rows.iter_mut().zip(read) {
            if let Some(row) = row.as_object_mut() {
                row.insert("read_at".into(), serde_json::json!(at));
            }
        }
    }
    Some(json)
}

/// The sheets and report of `job` (blocking): what the studio answers to an edit.
pub fn redraw(job: &Job) -> Redrawn {
    let t0 = Instant::now();
    let mut out = Redrawn::default();
    let drawn = job.scene().and_then(|(s, drafting)| {
        let session = Session::new(&s, drafting);
        let plates = plates_of(&session, job.lang())?;
        Ok((sheets_of(&plates), report_of(&session, &plates)))
    });
    match drawn {
        Ok((sheets, report)) => (out.sheets, out.report) = (sheets, report),
        Err(problems) => out.problems = problems,
    }
    out.ms = t0.elapsed().as_secs_f64() * 1e3;
    out
}
