//! The studio's requests: the gallery, a shipped scene's text and thumbnail, the form's
//! fields and one set, a scene rendered to its SVG sheets and report, and the downloads —
//! every answer generated from the request's scene text, never a file read by a name the
//! request gives.

use super::redraw::{redraw, stem_of, Job};
use super::{fields, gallery, Studio};
use crate::construct::Drafting;
use crate::plate;
use crate::render::{self, Formats, Options};
use crate::scale::Lang;
use crate::study::Session;
use axum::extract::{Path as UrlPath, Query, State};
use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::Json;
use serde::Deserialize;
use std::path::Path;
use std::sync::Arc;

/// The language a request asks for (`?lang=uk`), Russian when absent or unknown.
#[derive(Debug, Deserialize)]
pub(super) struct LangQuery {
    lang: Option<String>,
}

/// `GET /api/gallery?lang=`: every shipped scene as a card.
pub(super) async fn gallery(Query(q): Query<LangQuery>) -> Json<Vec<gallery::Card>> {
    Json(gallery::cards(super::redraw::lang_of(q.lang.as_deref())))
}

/// `GET /api/scene/{stem}`: a shipped scene's text.
pub(super) async fn scene_text(UrlPath(stem): UrlPath<String>) -> Response {
    match gallery::text(&stem) {
        Some(t) => ([(header::CONTENT_TYPE, "text/plain; charset=utf-8")], t).into_response(),
        None => not_found(&stem),
    }
}

fn not_found(stem: &str) -> Response {
    let msg = format!("{stem}: no such shipped scene");
    (StatusCode::NOT_FOUND, msg).into_response()
}

/// `GET /api/thumb/{stem}`: the first sheet of a shipped scene, as SVG (made once).
pub(super) async fn thumbnail(
    State(studio): State<Arc<Studio>>,
    UrlPath(stem): UrlPath<String>,
) -> Response {
    let Some(&(stem, _)) = gallery::SHIPPED.iter().find(|(s, _)| *s == stem) else {
        return not_found(&stem);
    };
    let made = studio
        .thumbnails
        .lock()
        .ok()
        .and_then(|t| t.get(stem).cloned());
    let svg = match made {
        Some(svg) => svg,
        None => {
            let work = move || -> Option<Arc<String>> {
                let s = gallery::scene(stem)?;
                let first = render::plates(&s, Lang::Ru, Drafting::HAND).ok()?;
                Some(Arc::new(plate::to_svg(&first.first()?.1)))
            };
            let Ok(Some(svg)) = studio.run(work).await else {
                return (StatusCode::SERVICE_UNAVAILABLE, "busy or failed").into_response();
            };
            if let Ok(mut t) = studio.thumbnails.lock() {
                t.insert(stem, svg.clone());
            }
            svg
        }
    };
    (
        [(header::CONTENT_TYPE, "image/svg+xml")],
        svg.as_ref().clone(),
    )
        .into_response()
}

/// A scene text sent by the page.
#[derive(Debug, Deserialize)]
pub(super) struct Text {
    toml: String,
}

/// `POST /api/fields`: the form's fields of a scene text.
pub(super) async fn fields(Json(t): Json<Text>) -> Response {
    match fields::fields(&t.toml) {
        Ok(f) => Json(f).into_response(),
        Err(e) => (StatusCode::UNPROCESSABLE_ENTITY, e.to_string()).into_response(),
    }
}

/// One field to set.
#[derive(Debug, Deserialize)]
pub(super) struct SetField {
    toml: String,
    key: String,
    value: String,
}

/// `POST /api/set`: the scene text with one field set.
pub(super) async fn set(Json(s): Json<SetField>) -> Response {
    match fields::set(&s.toml, &s.key, &s.value) {
        Ok(toml) => Json(serde_json::json!({ "toml": toml })).into_response(),
        Err(e) => (StatusCode::UNPROCESSABLE_ENTITY, e.to_string()).into_response(),
    }
}

/// `POST /api/render`: the scene's sheets as SVG and its report.
pub(super) async fn render(State(studio): State<Arc<Studio>>, Json(job): Json<Job>) -> Response {
    match studio.run(move || redraw(&job)).await {
        Ok(r) => Json(r).into_response(),
        Err(busy) => busy.into_response(),
    }
}

/// A download: the scene, a sheet (`<sheet>.svg`, `<sheet>.png`), the set (`pdf`), the note
/// (`note`) or the report (`csv`).
#[derive(Debug, Deserialize)]
pub(super) struct Download {
    #[serde(flatten)]
    job: Job,
    what: String,
}

/// The bytes and file name of a download, as `tmm render` and `tmm report` write them.
fn download_bytes(d: &Download) -> Result<(String, Vec<u8>), String> {
    let stem = stem_of(&d.job.stem);
    if d.what == "scene" {
        return Ok((format!("{stem}.toml"), d.job.toml.clone().into_bytes()));
    }
    let (s, drafting) = d.job.scene().map_err(|p| {
        p.iter()
            .map(|p| p.message.as_str())
            .collect::<Vec<_>>()
            .join("\n")
    })?;
    if d.what == "csv" {
        let report = Session::new(&s, drafting)
            .report()
            .map_err(|e| e.to_string())?;
        return Ok((format!("{stem}.csv"), report.to_csv().into_bytes()));
    }
    let formats = Formats {
        svg: d.what.ends_with(".svg"),
        png: d.what.ends_with(".png"),
        pdf: d.what == "pdf",
        note: d.what == "note",
        dxf: false,
    };
    let options = Options {
        lang: d.job.lang(),
        drafting,
        formats,
        dpi: render::DEFAULT_DPI,
    };
    let files = render::files(std::slice::from_ref(&s), Path::new(""), &options)
        .map_err(|e| e.to_string())?;
    let wanted = match d.what.as_str() {
        "pdf" => format!("{stem}.pdf"),
        "note" => format!("{stem}-note.pdf"),
        sheet => sheet.to_string(),
    };
    files
        .into_iter()
        .find(|(p, _)| p.file_name().is_some_and(|n| n.to_string_lossy() == wanted))
        .map(|(_, bytes)| (wanted.clone(), bytes))
        .ok_or_else(|| format!("{}: the scene has no such file", d.what))
}

/// `POST /api/download`: a file of the scene, generated.
pub(super) async fn download(
    State(studio): State<Arc<Studio>>,
    Json(d): Json<Download>,
) -> Response {
    match studio.run(move || download_bytes(&d)).await {
        Ok(Ok((name, bytes))) => {
            let kind = match name.rsplit('.').next() {
                Some("svg") => "image/svg+xml",
                Some("png") => "image/png",
                Some("pdf") => "application/pdf",
                Some("csv") => "text/csv; charset=utf-8",
                _ => "text/plain; charset=utf-8",
            };
            let disposition = format!("attachment; filename=\"{name}\"");
            (
                [
                    (header::CONTENT_TYPE, kind.to_string()),
                    (header::CONTENT_DISPOSITION, disposition),
                ],
                bytes,
            )
                .into_response()
        }
        Ok(Err(message)) => (StatusCode::UNPROCESSABLE_ENTITY, message).into_response(),
        Err(busy) => busy.into_response(),
    }
}

/// `POST /api/replay`: the figures of one sheet with their construction protocols.
pub(super) async fn replay(
    State(studio): State<Arc<Studio>>,
    Json(r): Json<super::ReplayJob>,
) -> Response {
    match studio.run(move || super::replay(&r)).await {
        Ok(Ok(views)) => Json(views).into_response(),
        Ok(Err(problems)) => (StatusCode::UNPROCESSABLE_ENTITY, Json(problems)).into_response(),
        Err(busy) => busy.into_response(),
    }
}
