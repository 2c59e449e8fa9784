//! Headless Chromium through chromedriver, for the studio's browser tests.

use fantoccini::{Client, ClientBuilder, Locator};
use serde_json::Value;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// How long a page may take to reach a state before the test fails.
const PATIENCE: Duration = Duration::from_secs(60);

/// A browser session and the chromedriver it runs through (killed on drop).
pub struct Browser {
    client: Option<Client>,
    driver: Child,
}

impl Drop for Browser {
    fn drop(&mut self) {
        let _ = self.driver.kill();
        let _ = self.driver.wait();
    }
}

fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .map(|a| a.port())
        .expect("a free port")
}

impl Browser {
    /// Start chromedriver on a free port and a headless Chromium session through it.
    pub async fn start() -> Browser {
        let port = free_port();
        let driver = Command::new("chromedriver")
            .arg(format!("--port={port}"))
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("chromedriver (Debian's chromium-driver; .ci/run installs it)");
        let profile = std::env::temp_dir().join(format!("tmm-studio-chromium-{port}"));
        let caps = serde_json::json!({
            "goog:chromeOptions": {
                "args": [
                    "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                    "--disable-quic", "--no-first-run", "--disable-background-networking",
                    "--disable-component-update", "--disable-sync", "--window-size=1600,1000",
                    format!("--user-data-dir={}", profile.display()),
                ]
            }
        });
        let caps = match caps {
            Value::Object(m) => m,
            _ => unreachable!(),
        };
        let started = Instant::now();
        let client = loop {
            let connector = hyper_util::client::legacy::connect::HttpConnector::new();
            let tried = ClientBuilder::new(connector)
                .capabilities(caps.clone())
                .connect(&format!("http://127.0.0.1:{port}"))
                .await;
            match tried {
                Ok(c) => break c,
                Err(e) if started.elapsed() > Duration::from_secs(20) => {
                    panic!("no WebDriver session on port {port}: {e}")
                }
                Err(_) => tokio::time::sleep(Duration::from_millis(200)).await,
            }
        };
        Browser {
            client: Some(client),
            driver,
        }
    }

    fn c(&self) -> &Client {
        self.client.as_ref().expect("open")
    }

    pub async fn goto(&self, url: &str) {
        self.c().goto(url).await.expect("goto");
    }

    /// The value of a script's `return`.
    pub async fn eval(&self, script: &str) -> Value {
        self.c()
            .execute(script, vec![])
            .await
            .unwrap_or_else(|e| panic!("{script}: {e}"))
    }

    /// The value an asynchronous script passes to its callback.
    pub async fn eval_async(&self, script: &str) -> Value {
        self.c()
            .execute_async(script, vec![])
            .await
            .unwrap_or_else(|e| panic!("{script}: {e}"))
    }

    /// Wait until the expression is truthy; its value.
    pub async fn until(&self, expr: &str) -> Value {
        let started = Instant::now();
        let script = format!("try {{ return ({expr}) || null; }} catch (e) {{ return null; }}");
        loop {
            let v = self.eval(&script).await;
            if !v.is_null() && v != Value::Bool(false) {
                return v;
            }
            assert!(started.elapsed() < PATIENCE, "never true: {expr}");
            tokio::time::sleep(Duration::from_millis(100)).await;
        }
    }

    pub async fn click(&self, css: &str) {
        let e = self.c().find(Locator::Css(css)).await.expect(css);
        e.click().await.expect("click");
    }

    /// Focus the element `css` and press Enter on it, as a keyboard user does.
    pub async fn press_enter(&self, css: &str) {
        let e = self.c().find(Locator::Css(css)).await.expect(css);
        self.c()
            .execute(
                "arguments[0].scrollIntoView({block: 'center'}); arguments[0].focus();",
                vec![serde_json::to_value(&e).expect("element")],
            )
            .await
            .expect("focus");
        e.send_keys("\u{E007}").await.expect("Enter");
    }

    /// Replace the text of the form's field `key` by `text`, as a user types it.
    pub async fn type_into(&self, key: &str, text: &str) {
        let css = format!("input[name=\"{key}\"]");
        let e = self.c().find(Locator::Css(&css)).await.expect(key);
        e.clear().await.expect("clear");
        e.send_keys(text).await.expect("type");
    }

    /// A screenshot of the window, written to `path`.
    pub async fn shot(&self, path: &Path) {
        let png = self.c().screenshot().await.expect("screenshot");
        std::fs::write(path, png).expect("write the screenshot");
    }

    pub async fn close(mut self) {
        if let Some(c) = self.client.take() {
            let _ = c.close().await;
        }
    }
}
