//! The studio in a real browser (issue 47 §4): headless Chromium driven through chromedriver
//! (WebDriver) against `tmm serve`'s router on a free port of 127.0.0.1. It opens the
//! gallery, starts from the shaper, changes the crank length in the form and sees the
//! kinematic sheet and its report rows change, downloads the PDF and compares it with
//! `tmm render`'s bytes, clicks a velocity row of the report and sees the segment it is read
//! off drawn in red on its sheet, presses Enter on a row computed by formula and reads why
//! it has none, and types an impossible length and sees the message at its field.
//! A screenshot of each state goes to `out/studio/` for a person to look at.
//!
//! Needs Debian's `chromium` and `chromium-driver` (`.ci/run` installs them).

mod browser;
mod limits;

use browser::Browser;
use std::path::{Path, PathBuf};
use tmm::construct::Drafting;
use tmm::render::{self, Formats, Options};
use tmm::scale::Lang;
use tmm::studio::readings::{read_at, ReadAt};
use tmm::studio::{fields, gallery};

fn out_dir() -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("out/studio");
    std::fs::create_dir_all(&dir).expect("out/studio");
    dir
}

/// FNV-1a over the bytes (the page computes the same over what it downloads).
fn fnv(bytes: &[u8]) -> u32 {
    bytes.iter().fold(0x811c_9dc5_u32, |h, &b| {
        (h ^ u32::from(b)).wrapping_mul(0x0100_0193)
    })
}

/// The shaper's PDF as `tmm render --format pdf` writes it, with the crank `length`.
fn shaper_pdf(length: &str) -> Vec<u8> {
    let text = gallery::text("shaper").expect("shipped");
    let text = fields::set(text, "mechanism.crank.length", length).expect("set");
    let s = tmm::scene::parse(&text, Path::new("shaper.toml")).expect("scene");
    let options = Options {
        lang: Lang::Ru,
        drafting: Drafting::HAND,
        formats: Formats {
            pdf: true,
            ..Formats::default()
        },
        dpi: render::DEFAULT_DPI,
    };
    let files = render::files(&[s], Path::new(""), &options).expect("render");
    files.into_iter().next().expect("the pdf").1
}

/// The shaper with the crank `length` as the page draws it (ru, read to 0,5 mm): the index of
/// its report's row of `quantity` at position `at` and where that row is read, the index of
/// its first row computed by formula, and the sheets' names.
fn shaper_rows(length: &str, quantity: &str, at: &str) -> (usize, ReadAt, usize, Vec<String>) {
    let text = gallery::text("shaper").expect("shipped");
    let text = fields::set(text, "mechanism.crank.length", length).expect("set");
    let s = tmm::scene::parse(&text, Path::new("shaper.toml")).expect("scene");
    let session = tmm::study::Session::new(&s, Drafting::HAND);
    let plates = tmm::sheets::build_all(&session, Lang::Ru).expect("sheets");
    let rows = session.report().expect("report").rows;
    let found = read_at(&rows, &plates);
    let i = rows
        .iter()
        .position(|r| r.quantity() == quantity && r.position().as_deref() == Some(at))
        .expect("the row");
    let formula = rows
        .iter()
        .position(|r| r.method == tmm::check::Method::Formula)
        .expect("a row computed by formula");
    let names = plates.iter().map(|(_, p)| p.name.clone()).collect();
    (i, found[i].expect("read on a sheet"), formula, names)
}

/// A click on the row of v_B at position 1 (the shaper, crank 150 mm): its sheet shown, the
/// segment of the plan it is read off drawn in red over it (sheet mm, the SVG's viewBox units),
/// in view; Enter on a row computed by formula: the page says so in its place.
async fn where_read(b: &Browser, shots: &Path) {
    let (row, want, formula, names) = shaper_rows("150", "v_B", "1");
    b.click(&format!("#rows tbody tr:nth-child({})", row + 1))
        .await;
    let line = b
        .until("(l => l && [l.x1.baseVal.value, l.y1.baseVal.value, l.x2.baseVal.value, l.y2.baseVal.value, l.getAttribute('stroke'), l.getAttribute('stroke-width')])(document.querySelector('#canvas svg line.reading'))")
        .await;
    let ends = [want.x1, want.y1, want.x2, want.y2];
    for (k, w) in ends.iter().enumerate() {
        let got = line[k].as_f64().unwrap_or(f64::NAN);
        assert!(
            (got - w).abs() <= 0.05,
            "end {k}: {got} mm, expected {w} mm"
        );
    }
    assert_eq!(line[4], "#e00000");
    assert_eq!(line[5], "0.8");
    let shown = b
        .eval("return document.querySelector('#sheet-tabs button.on').textContent")
        .await;
    assert_eq!(shown, names[want.sheet].as_str());
    let inside = b
        .eval(
            "const l = document.querySelector('#canvas svg line.reading').getBoundingClientRect();
             const v = document.getElementById('viewport').getBoundingClientRect();
             return [l.left >= v.left, l.right <= v.right, l.top >= v.top, l.bottom <= v.bottom, l.width + l.height];",
        )
        .await;
    assert_eq!(
        inside.as_array().map(|a| a[..4].to_vec()),
        Some(vec![serde_json::Value::Bool(true); 4]),
        "the segment in view: {inside}"
    );
    assert!(
        inside[4].as_f64().unwrap_or(0.0) > 40.0,
        "zoomed to it: {inside}"
    );
    eprintln!(
        "v_B (1) read on {} from ({:.2}, {:.2}) to ({:.2}, {:.2}) mm",
        names[want.sheet], want.x1, want.y1, want.x2, want.y2
    );
    b.shot(&shots.join("5-reading.png")).await;

    // Enter on a row computed by formula: the page says so in its place, no segment drawn.
    b.press_enter(&format!("#rows tbody tr:nth-child({})", formula + 1))
        .await;
    let note = b
        .until("document.querySelector('#rows tr.chosen + tr.reading-note')?.textContent")
        .await;
    assert_eq!(note, "вычислено по формуле, не измерено на листе");
    assert!(
        b.eval("return !document.querySelector('#canvas svg line.reading')")
            .await
            == true
    );
    b.shot(&shots.join("6-computed.png")).await;
}

#[test]
fn a_student_edits_the_shaper_in_the_browser() {
    let runtime = tokio::runtime::Runtime::new().expect("tokio");
    runtime.block_on(async {
        let (listener, addr) = tmm::studio::bind(0).await.expect("bind");
        tokio::spawn(tmm::studio::serve_on(listener));
        let b = Browser::start().await;
        let shots = out_dir();
        b.goto(&format!("http://{addr}/")).await;
        b.until("document.querySelector('.card[data-stem=\"shaper\"] img')?.complete")
            .await;
        let headings = b.eval("return [...document.querySelectorAll('#gallery h2')].map(h => h.textContent)").await;
        assert_eq!(
            headings,
            serde_json::json!([
                "Курсовой проект",
                "Рычажные механизмы",
                "Кулачковые механизмы",
                "Зубчатые зацепления",
                "Зубчатые передачи",
                "Трение",
                "Уравновешивание"
            ])
        );
        b.shot(&shots.join("1-gallery.png")).await;

        b.click(".card[data-stem=\"shaper\"] button.from").await;
        b.until("document.querySelector('#canvas svg') && document.querySelector('#rows tbody tr')")
            .await;
        b.eval(
            "window.sheet0 = document.querySelector('#canvas svg').outerHTML;
             window.rows0 = document.querySelector('#rows tbody').textContent;",
        )
        .await;
        let tabs = b.eval("return [...document.querySelectorAll('#sheet-tabs button')].map(b => b.textContent)").await;
        assert_eq!(tabs[0], "kinematics", "{tabs}");
        assert_eq!(tabs.as_array().map(Vec::len), Some(8), "{tabs}");
        b.shot(&shots.join("2-shaper.png")).await;

        // The crank 140 → 150 mm: the sheet and the report change.
        b.type_into("mechanism.crank.length", "150").await;
        b.until("document.querySelector('#canvas svg').outerHTML !== window.sheet0")
            .await;
        b.until("document.querySelector('#rows tbody').textContent !== window.rows0")
            .await;
        let status = b.eval("return document.getElementById('status').textContent").await;
        eprintln!("the edit redrawn: {status}");
        b.shot(&shots.join("3-crank-150.png")).await;

        // The first velocity plan replayed from its first step to its last: each step's
        // element highlighted is the recorder's next step, its sentence marked.
        let figure = b
            .until("[...document.querySelectorAll('#figure option')].find(o => o.textContent.startsWith('Пол. 1,'))?.value")
            .await;
        let figure = figure.as_str().expect("a velocity plan").to_string();
        b.eval(&format!(
            "const s = document.getElementById('figure'); s.value = '{figure}'; s.dispatchEvent(new Event('change'));"
        ))
        .await;
        b.click("#r-first").await;
        let steps = b
            .eval("return replay.view.steps.map(s => [s.id, s.sentence])")
            .await;
        let steps = steps.as_array().expect("steps").clone();
        assert!(steps.len() >= 5, "{steps:?}");
        for (i, step) in steps.iter().enumerate() {
            let now = b
                .eval("const g = document.querySelector('#canvas .replay-now'); const li = document.querySelector('#r-steps li.now'); return [g && g.id, li && li.dataset.step, li && li.textContent, document.querySelectorAll('#canvas svg .replay-hidden').length]")
                .await;
            assert_eq!(now[0], format!("view-{figure}-step-{}", step[0]), "step {i}");
            assert_eq!(now[1], step[0].to_string(), "step {i}");
            assert_eq!(now[2], step[1], "step {i}");
            if i == 2 {
                b.shot(&shots.join("4-replay.png")).await;
            }
            if i + 1 < steps.len() {
                b.click("#r-forward").await;
            }
        }
        let first = steps[0][1].as_str().unwrap_or_default();
        eprintln!("the velocity plan's {} steps, the first: «{first}»", steps.len());

        // The PDF downloaded from the page is `tmm render`'s.
        let got = b
            .eval_async(
                "const done = arguments[arguments.length - 1];
                 fetch('/api/download', {method: 'POST', headers: {'content-type': 'application/json'},
                   body: JSON.stringify({...job(), what: 'pdf'})})
                 .then(r => r.arrayBuffer()).then(a => {
                   let h = 0x811c9dc5;
                   for (const b of new Uint8Array(a)) h = Math.imul(h ^ b, 0x01000193) >>> 0;
                   done([a.byteLength, h]);
                 });",
            )
            .await;
        let pdf = shaper_pdf("150");
        assert_eq!(got, serde_json::json!([pdf.len(), fnv(&pdf)]), "the page's PDF");

        where_read(&b, &shots).await;

        // An impossible length: the message at its field, the last sheets kept.
        b.type_into("mechanism.crank.length", "-5").await;
        let message = b
            .until("document.querySelector('.field.bad[data-key=\"mechanism.crank.length\"] .message')?.textContent")
            .await;
        let message = message.as_str().unwrap_or_default();
        assert!(message.contains("expected a length > 0 mm"), "{message}");
        assert!(b.eval("return !!document.querySelector('#canvas svg')").await == true);
        b.shot(&shots.join("7-impossible.png")).await;
        b.close().await;
    });
}
