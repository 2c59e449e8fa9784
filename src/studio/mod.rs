//! `tmm serve`: the studio, `tmm` in a browser. A local web server (axum on tokio) bound to
//! 127.0.0.1 serves one page, embedded in the binary with everything it needs (no network at
//! run time): the gallery of the shipped scenes, a scene as a form beside its text, its
//! sheets re-drawn as SVG after each edit with the report beside them (each row with where
//! its value is read on the sheets, [`readings`]), and the downloads — the same bytes
//! `tmm render` writes.
//!
//! Limits: a request body is at most a scene's size ([`MAX_BODY`]); at most [`RUNNING`]
//! scenes are built at once and [`WAITING`] more wait, a further one is told the server is
//! busy; nothing is kept between requests but the gallery's thumbnails (one per shipped
//! scene). No request names a file: scenes come from the request or the embedded gallery.

mod api;
pub mod fields;
pub mod gallery;
pub mod html;
pub mod readings;
mod redraw;
mod replay;

pub use redraw::{redraw, Job, PageProblem, PageSheet, Redrawn};
pub use replay::{replay, views_of, ReplayJob, ReplayStep, ReplayView};

use axum::extract::DefaultBodyLimit;
use axum::http::{header, StatusCode};
use axum::response::IntoResponse;
use axum::routing::{get, post};
use axum::Router;
use std::collections::HashMap;
use std::net::{Ipv4Addr, SocketAddr};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use thiserror::Error;
use tokio::sync::Semaphore;

/// The largest request body: a scene file's cap and room for the request around it.
pub const MAX_BODY: usize = crate::scene::MAX_SCENE_BYTES as usize + 4096;
/// Scenes built at once.
pub const RUNNING: usize = 2;
/// Requests that may wait for a build; one more is answered "busy" (503).
pub const WAITING: usize = 16;

/// The page and its script and style, embedded.
const PAGE: &str = include_str!("assets/index.html");
const SCRIPT: &str = include_str!("assets/studio.js");
const STYLE: &str = include_str!("assets/studio.css");
/// The sheets, their replay and the report: the part of the page the served and the offline
/// page share.
const SHEETS: &str = include_str!("assets/sheets.html");

/// Why the studio cannot serve.
#[derive(Debug, Error)]
pub enum StudioError {
    /// The port cannot be bound.
    #[error("127.0.0.1:{port}: cannot listen: {source}")]
    Bind {
        /// The port asked for.
        port: u16,
        /// Why.
        source: std::io::Error,
    },
    /// The server stopped on an error.
    #[error("the server stopped: {0}")]
    Serve(std::io::Error),
}

/// The server's state: the build slots and the thumbnails made.
pub struct Studio {
    slots: Semaphore,
    waiting: AtomicUsize,
    thumbnails: Mutex<HashMap<&'static str, Arc<String>>>,
}

/// A request turned away: too many builds wait already.
pub(crate) struct Busy;

impl IntoResponse for Busy {
    fn into_response(self) -> axum::response::Response {
        let msg = "the studio is busy with other scenes: try again in a moment";
        (StatusCode::SERVICE_UNAVAILABLE, msg).into_response()
    }
}

impl Studio {
    fn new() -> Self {
        Studio {
            slots: Semaphore::new(RUNNING),
            waiting: AtomicUsize::new(0),
            thumbnails: Mutex::new(HashMap::new()),
        }
    }

    /// Run the blocking `work` in a build slot, or [`Busy`] when [`WAITING`] requests wait.
    pub(crate) async fn run<T: Send + 'static>(
        &self,
        work: impl FnOnce() -> T + Send + 'static,
    ) -> Result<T, Busy> {
        if self.waiting.fetch_add(1, Ordering::SeqCst) >= RUNNING + WAITING {
            self.waiting.fetch_sub(1, Ordering::SeqCst);
            return Err(Busy);
        }
        let permit = self.slots.acquire().await;
        let out = match permit {
            Ok(_permit) => tokio::task::spawn_blocking(work).await.map_err(|_| Busy),
            Err(_) => Err(Busy),
        };
        self.waiting.fetch_sub(1, Ordering::SeqCst);
        out
    }
}

/// The page's words from the catalogue, as the script reads them: key → [ru, uk, en].
fn words_json() -> String {
    use crate::scale::Lang;
    let words: serde_json::Map<String, serde_json::Value> = crate::words::STUDIO_KEYS
        .iter()
        .map(|(key, w)| {
            let all = [Lang::Ru, Lang::Uk, Lang::En].map(|l| w.get(l));
            (key.to_string(), serde_json::json!(all))
        })
        .collect();
    html::script_json(&words)
}

/// The page with its words in place (made once).
fn page() -> &'static str {
    static PAGE_WITH_WORDS: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    PAGE_WITH_WORDS.get_or_init(|| {
        html::fill(
            PAGE,
            &[("{{words}}", &words_json()), ("{{sheets}}", SHEETS)],
        )
    })
}

/// The studio's routes.
pub fn router() -> Router {
    let asset = |kind: &'static str, body: &'static str| {
        get(move || async move { ([(header::CONTENT_TYPE, kind)], body) })
    };
    Router::new()
        .route(
            "/",
            get(|| async { ([(header::CONTENT_TYPE, "text/html; charset=utf-8")], page()) }),
        )
        .route(
            "/studio.js",
            asset("text/javascript; charset=utf-8", SCRIPT),
        )
        .route("/studio.css", asset("text/css; charset=utf-8", STYLE))
        .route("/api/gallery", get(api::gallery))
        .route("/api/scene/{stem}", get(api::scene_text))
        .route("/api/thumb/{stem}", get(api::thumbnail))
        .route("/api/fields", post(api::fields))
        .route("/api/set", post(api::set))
        .route("/api/render", post(api::render))
        .route("/api/download", post(api::download))
        .route("/api/replay", post(api::replay))
        .layer(DefaultBodyLimit::max(MAX_BODY))
        .with_state(Arc::new(Studio::new()))
}

/// Bind 127.0.0.1:`port` (0: a free port); the listener and its address.
///
/// # Errors
/// The port cannot be bound.
pub async fn bind(port: u16) -> Result<(tokio::net::TcpListener, SocketAddr), StudioError> {
    let bind = |source| StudioError::Bind { port, source };
    let listener = tokio::net::TcpListener::bind((Ipv4Addr::LOCALHOST, port))
        .await
        .map_err(bind)?;
    let addr = listener.local_addr().map_err(bind)?;
    Ok((listener, addr))
}

/// Serve the studio on `listener` until Ctrl-C.
///
/// # Errors
/// The server stops on an error.
pub async fn serve_on(listener: tokio::net::TcpListener) -> Result<(), StudioError> {
    axum::serve(listener, router())
        .with_graceful_shutdown(async {
            let _ = tokio::signal::ctrl_c().await;
        })
        .await
        .map_err(StudioError::Serve)
}

/// `tmm serve`: bind 127.0.0.1:`port`, call `ready` with the address (the CLI prints it and
/// may open a browser), and serve until Ctrl-C.
///
/// # Errors
/// The port cannot be bound, or the server stops on an error.
pub fn serve(port: u16, ready: impl FnOnce(SocketAddr)) -> Result<(), StudioError> {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .map_err(StudioError::Serve)?;
    runtime.block_on(async {
        let (listener, addr) = bind(port).await?;
        ready(addr);
        serve_on(listener).await
    })
}

/// Ask the system to open `url` in its browser (`xdg-open`, `open`, `start`); a system
/// without one leaves the printed address to the user.
pub fn open_browser(url: &str) {
    let (program, args): (&str, &[&str]) = if cfg!(target_os = "macos") {
        ("open", &[])
    } else if cfg!(windows) {
        ("cmd", &["/C", "start", ""])
    } else {
        ("xdg-open", &[])
    };
    let _ = std::process::Command::new(program)
        .args(args)
        .arg(url)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn();
}
