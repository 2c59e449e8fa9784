//! The studio server's limits (issue 47 §3): an oversized body, a path for a scene, markup in
//! a scene's strings, and many edits at once — each answered clearly.

use std::io::{Read, Write};
use std::net::{SocketAddr, TcpStream};

/// A raw HTTP/1.1 request; the status and body of the answer.
fn request(addr: SocketAddr, method: &str, path: &str, body: &[u8]) -> (u16, String) {
    let mut s = TcpStream::connect(addr).expect("connect");
    let head = format!(
        "{method} {path} HTTP/1.1\r\nHost: {addr}\r\nContent-Type: application/json\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
        body.len()
    );
    s.write_all(head.as_bytes()).expect("head");
    let _ = s.write_all(body);
    let mut answer = Vec::new();
    let _ = s.read_to_end(&mut answer);
    let answer = String::from_utf8_lossy(&answer).into_owned();
    let status = answer
        .split(' ')
        .nth(1)
        .and_then(|c| c.parse().ok())
        .unwrap_or(0);
    let body = answer
        .split("\r\n\r\n")
        .nth(1)
        .unwrap_or_default()
        .to_string();
    (status, body)
}

fn render_body(toml: &str, stem: &str) -> Vec<u8> {
    serde_json::to_vec(&serde_json::json!({ "toml": toml, "stem": stem })).expect("json")
}

/// `tmm serve --port 0` in a process of its own (its memory is its own), killed on drop.
struct Served {
    child: std::process::Child,
    addr: SocketAddr,
}

impl Drop for Served {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Served {
    fn start() -> Served {
        use std::io::BufRead as _;
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_tmm"))
            .args(["serve", "--port", "0"])
            .stdout(std::process::Stdio::piped())
            .spawn()
            .expect("tmm serve");
        let mut line = String::new();
        let stdout = child.stdout.take().expect("stdout");
        std::io::BufReader::new(stdout)
            .read_line(&mut line)
            .expect("its address");
        let addr = line
            .split("http://")
            .nth(1)
            .and_then(|a| a.split('/').next())
            .and_then(|a| a.parse().ok())
            .unwrap_or_else(|| panic!("no address in «{line}»"));
        Served { child, addr }
    }

    /// Its resident memory, KiB (Linux; 0 elsewhere).
    fn resident_kib(&self) -> u64 {
        std::fs::read_to_string(format!("/proc/{}/status", self.child.id()))
            .ok()
            .and_then(|s| {
                let line = s.lines().find(|l| l.starts_with("VmRSS:"))?.to_string();
                line.split_whitespace().nth(1)?.parse().ok()
            })
            .unwrap_or(0)
    }
}

#[test]
fn the_server_refuses_what_it_must_and_answers_the_rest() {
    let served = Served::start();
    let addr = served.addr;
    let four_bar = tmm::studio::gallery::text("four-bar").expect("shipped");
    // A body past the cap.
    let big = render_body(&"#".repeat(tmm::studio::MAX_BODY), "x");
    assert_eq!(request(addr, "POST", "/api/render", &big).0, 413);
    // A path where a scene's stem goes: nothing is read from disk.
    for p in [
        "/api/scene/..%2F..%2Fetc%2Fpasswd",
        "/api/thumb/%2Fetc%2Fpasswd",
    ] {
        let (status, body) = request(addr, "GET", p, b"");
        assert_eq!(status, 404, "{p}: {body}");
        assert!(!body.contains("root:"), "{body}");
    }
    let d =
        serde_json::json!({ "toml": four_bar, "stem": "four-bar", "what": "../../../etc/passwd" });
    let (status, body) = request(addr, "POST", "/api/download", d.to_string().as_bytes());
    assert_eq!(status, 422, "{body}");
    // Markup in a scene's strings is text on the sheet.
    let marked = four_bar.replacen("title = \"", "title = \"<script>alert(1)</script>", 1);
    let (status, body) = request(
        addr,
        "POST",
        "/api/render",
        &render_body(&marked, "<b>x</b>"),
    );
    assert_eq!(status, 200, "{body}");
    let v: serde_json::Value = serde_json::from_str(&body).expect("json");
    let svg = v["sheets"][0]["svg"].as_str().expect("a sheet");
    assert!(
        !svg.contains("<script>") && svg.contains("&lt;script&gt;"),
        "escaped"
    );
    // Markup in every string of the scene: refused with the program's message, or drawn as
    // text — never markup in a sheet.
    let strings: Vec<String> = tmm::studio::fields::fields(four_bar)
        .expect("fields")
        .into_iter()
        .filter(|f| f.value.starts_with('"'))
        .map(|f| f.key)
        .collect();
    assert!(strings.len() >= 5, "{strings:?}");
    for key in &strings {
        let text =
            tmm::studio::fields::set(four_bar, key, "\"<script>alert(1)</script>\"").expect("set");
        let (status, body) = request(addr, "POST", "/api/render", &render_body(&text, "x"));
        assert_eq!(status, 200, "{key}: {body}");
        let v: serde_json::Value = serde_json::from_str(&body).expect("json");
        let sheets = v["sheets"].as_array().cloned().unwrap_or_default();
        assert!(
            !sheets.is_empty() || !v["problems"].as_array().is_none_or(Vec::is_empty),
            "{key}: neither sheets nor a message"
        );
        for sheet in sheets {
            let svg = sheet["svg"].as_str().unwrap_or_default();
            assert!(!svg.contains("<script"), "{key}: markup in the sheet");
        }
    }
    let before = served.resident_kib();
    // Many edits at once: every one answered, each a sheet or "busy", none lost.
    let answers: Vec<u16> = std::thread::scope(|scope| {
        let all: Vec<_> = (0..24)
            .map(|k| {
                let text = four_bar.replace("length = 80.0", &format!("length = {}.0", 75 + k % 5));
                scope.spawn(move || {
                    request(addr, "POST", "/api/render", &render_body(&text, "four-bar")).0
                })
            })
            .collect();
        all.into_iter().map(|t| t.join().expect("thread")).collect()
    });
    assert!(
        answers.iter().all(|s| *s == 200 || *s == 503),
        "{answers:?}"
    );
    assert!(
        answers.iter().filter(|s| **s == 200).count() >= tmm::studio::RUNNING,
        "{answers:?}"
    );
    // Nothing is kept between requests: 24 edits leave the server about where one left it.
    let grown = served.resident_kib().saturating_sub(before);
    eprintln!(
        "resident memory after 24 concurrent edits: +{} MiB",
        grown / 1024
    );
    assert!(grown < 256 * 1024, "+{grown} KiB after 24 edits");
}
