//! `tmm render --format html`: the studio's page as one self-contained file,
//! `DIR/<stem>/<stem>.html` — every sheet as SVG, the replay of every figure and the report,
//! with the page's script and style inline and nothing fetched: an instructor publishes it,
//! a student opens it offline.

use super::redraw::{report_of, sheets_of};
use super::replay::{views_of, ReplayView};
use super::{SCRIPT, SHEETS, STYLE};
use crate::construct::Drafting;
use crate::render::RenderError;
use crate::scale::Lang;
use crate::scene::Scene;
use crate::study::Session;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// The page's skeleton, its script and style put in place of these marks.
const PAGE: &str = include_str!("assets/offline.html");

/// What the offline page shows: the scene's title, its sheets, their replays and its report.
#[derive(Serialize)]
struct Data<'a> {
    title: &'a str,
    lang: &'a str,
    sheets: Vec<super::PageSheet>,
    replays: Vec<Vec<ReplayView>>,
    report: Option<serde_json::Value>,
}

/// `s` in JSON that may stand inside a `<script>` element: no `</` closes it early.
pub(super) fn script_json<T: Serialize>(value: &T) -> String {
    serde_json::to_string(value)
        .unwrap_or_else(|_| "null".into())
        .replace("</", "<\\/")
        .replace("<!--", "<\\!--")
}

/// The text escaped for HTML.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The page of `s` in `lang`, drawn under `drafting`.
///
/// # Errors
/// A plate of the scene that cannot be built.
pub fn page(s: &Scene, lang: Lang, drafting: Drafting) -> Result<String, RenderError> {
    let session = Session::new(s, drafting);
    let plates =
        crate::sheets::build_all(&session, lang).map_err(|(kind, error)| RenderError::Build {
            scene: s.path.clone(),
            kind,
            error,
        })?;
    let title = s.title.in_lang(lang).title;
    let code = match lang {
        Lang::Ru => "ru",
        Lang::Uk => "uk",
        Lang::En => "en",
    };
    let data = Data {
        title: &title,
        lang: code,
        sheets: sheets_of(&plates),
        replays: plates.iter().map(|(_, p)| views_of(p, lang)).collect(),
        report: report_of(&session, &plates),
    };
    let script = SCRIPT.replace("</", "<\\/");
    Ok(fill(
        PAGE,
        &[
            ("{{lang}}", code),
            ("{{title}}", &escape(&title)),
            ("{{style}}", STYLE),
            ("{{words}}", &super::words_json()),
            ("{{sheets}}", SHEETS),
            ("{{data}}", &script_json(&data)),
            ("{{script}}", &script),
        ],
    ))
}

/// The template with each mark put in its value, in one pass: a value is never read for
/// marks (a title `{{script}}` stays text).
pub(super) fn fill(template: &str, marks: &[(&str, &str)]) -> String {
    let mut out = String::with_capacity(template.len());
    let mut rest = template;
    while let Some((at, (mark, value))) = marks
        .iter()
        .filter_map(|m| rest.find(m.0).map(|at| (at, *m)))
        .min_by_key(|(at, _)| *at)
    {
        out.push_str(&rest[..at]);
        out.push_str(value);
        rest = &rest[at + mark.len()..];
    }
    out.push_str(rest);
    out
}

/// The page of every scene, `<out>/<stem>/<stem>.html`, in memory.
///
/// # Errors
/// As [`page`].
pub fn files(
    scenes: &[Scene],
    out: &Path,
    lang: Lang,
    drafting: Drafting,
) -> Result<Vec<(PathBuf, Vec<u8>)>, RenderError> {
    scenes
        .iter()
        .map(|s| {
            let path = out.join(&s.stem).join(format!("{}.html", s.stem));
            Ok((path, page(s, lang, drafting)?.into_bytes()))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The four-bar's page holds its sheet, its figures' protocols and its report, fetches
    /// nothing, and a title of markup is text.
    #[test]
    fn the_page_is_one_file_that_fetches_nothing() {
        let text = super::super::gallery::text("four-bar").expect("shipped");
        let text = text.replacen("title = \"", "title = \"<script>x</script>", 1);
        let s = crate::scene::parse(&text, Path::new("four-bar.toml")).expect("scene");
        let html = page(&s, Lang::Ru, Drafting::HAND).expect("page");
        assert!(html.contains("<svg"), "the sheet");
        assert!(html.contains("откладываем"), "the replay's sentences");
        assert!(html.contains("\"rows\""), "the report");
        // Outside its two script elements the page names no resource at all.
        let outside: String = html
            .split("<script>")
            .map(|part| {
                part.split_once("</script>")
                    .map_or(part, |(_, after)| after)
            })
            .collect();
        for external in ["src=", "href=", "url(", "http", "@import"] {
            assert!(!outside.contains(external), "{external}");
        }
        assert!(
            html.contains("&lt;script&gt;x&lt;/script&gt;"),
            "the title as text"
        );
        assert_eq!(
            html.matches("</script>").count(),
            2,
            "no script closed early"
        );
    }
}
