//! The files `tmm render` writes: PNGs in grayscale at the very pixels of the drawing, tiled
//! rendering beyond tiny-skia's 8191 px anti-aliasing limit, and the bench's PNG timing.

use crate::support;
use resvg::tiny_skia::{Color, Pixmap, Transform};
use support::{pdf_dicts, pdf_pages, scratch, tmm};

/// The PNG's IHDR colour type (0 gray, 2 RGB, 6 RGBA) and its pHYs pixels per metre.
fn header(png: &[u8]) -> (u8, Option<u32>) {
    let phys = png
        .windows(4)
        .position(|w| w == b"pHYs")
        .map(|at| u32::from_be_bytes(png[at + 4..at + 8].try_into().unwrap()));
    (png[25], phys)
}

/// The SVG drawn the plain way: a white canvas of `w` × `h` px, resvg over it.
fn plain_render(svg: &str, w: u32, h: u32) -> Pixmap {
    let mut opt = resvg::usvg::Options {
        fontdb: tmm::plate::font_database(),
        ..Default::default()
    };
    opt.font_family = tmm::plate::FONT_FAMILY.into();
    let tree = resvg::usvg::Tree::from_str(svg, &opt).expect("parse");
    let mut canvas = Pixmap::new(w, h).expect("canvas");
    canvas.fill(Color::WHITE);
    let size = tree.size();
    let ts = Transform::from_scale(w as f32 / size.width(), h as f32 / size.height());
    resvg::render(&tree, ts, &mut canvas.as_mut());
    canvas
}

#[test]
fn render_writes_grayscale_pngs_with_the_drawings_pixels_and_their_resolution() {
    let out = scratch("gray");
    let o = tmm(&[
        "render",
        "constructions/four-bar.toml",
        "--out",
        out.to_str().unwrap(),
        "--dpi",
        "100",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let png = std::fs::read(out.join("four-bar/kinematics.png")).unwrap();
    // 100 dpi = 3937 px per metre.
    assert_eq!(header(&png), (0, Some(3937)));
    let got = Pixmap::decode_png(&png).expect("decode");
    assert_eq!((got.width(), got.height()), (3311, 2339), "A1 at 100 dpi");
    let svg = std::fs::read_to_string(out.join("four-bar/kinematics.svg")).unwrap();
    let want = plain_render(&svg, got.width(), got.height());
    assert!(
        got.data() == want.data(),
        "the grayscale PNG must decode to the pixels resvg draws"
    );
}

#[test]
fn a_png_wider_than_8191_px_is_tiled_and_anti_aliased_throughout() {
    // 100 × 60 mm at 2400 dpi: 9449 × 5669 px, two columns of tiles and several bands.
    let svg = r##"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="60mm" viewBox="0 0 100 60">
        <rect width="100" height="60" fill="#fff"/>
        <path d="M1 1 L99 59 M1 59 L99 1" stroke="#000" stroke-width="0.25" fill="none"/>
        <circle cx="88" cy="30" r="9" stroke="#000" stroke-width="0.7" fill="none"/>
    </svg>"##;
    let png = tmm::plate::to_png_dpi(svg, 2400.0).expect("a tiled PNG");
    assert_eq!(header(&png).0, 0);
    let img = Pixmap::decode_png(&png).expect("decode");
    assert_eq!((img.width(), img.height()), (9449, 5669));
    // Right of x = 8191 the diagonal's edges are still grey ramps, not hard steps.
    let mut levels = [false; 256];
    for y in 0..img.height() {
        for x in 8300..img.width() {
            levels[img.pixel(x, y).unwrap().red() as usize] = true;
        }
    }
    let used = levels.iter().filter(|&&l| l).count();
    // Aliased (one canvas past 8191 px) would be 2 levels; a 4 × 4 sub-sampled edge has 17.
    assert!(used > 8, "only {used} gray levels right of 8191 px");
    // The circle at the right edge is closed across the band seams: its ink is symmetric.
    let ink = |y0: u32, y1: u32| {
        (y0..y1)
            .flat_map(|y| (8000..img.width()).map(move |x| (x, y)))
            .filter(|&(x, y)| img.pixel(x, y).unwrap().red() < 128)
            .count() as f64
    };
    let (top, bottom) = (ink(0, 2834), ink(2835, 5669));
    assert!((top - bottom).abs() < 0.01 * top, "{top} vs {bottom}");
}

#[test]
fn the_bench_times_a_scenes_plates_as_png() {
    let out = scratch("bench");
    let o = tmm(&["bench", "--quick", "--json", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
    let row = v["throughput"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["name"] == "png shaper at 150 dpi")
        .expect("a PNG row");
    assert!(row["per_second"].as_f64().unwrap() > 0.0);
    assert!(row["note"].as_str().unwrap().contains("(8)"), "{row}");
}

/// The `/MediaBox [x0 y0 x1 y1]` of every page of a PDF written without object streams, in
/// millimetres (width, height), in file order.
fn media_boxes_mm(pdf: &[u8]) -> Vec<(f64, f64)> {
    let text = pdf_dicts(pdf);
    text.match_indices("/MediaBox[")
        .map(|(at, m)| {
            let rest = &text[at + m.len()..];
            let nums: Vec<f64> = rest[..rest.find(']').unwrap()]
                .split_whitespace()
                .map(|n| n.parse().unwrap())
                .collect();
            let mm = 25.4 / 72.0;
            ((nums[2] - nums[0]) * mm, (nums[3] - nums[1]) * mm)
        })
        .collect()
}

#[test]
fn render_writes_one_pdf_per_scene_with_every_sheet_a_page_at_1_to_1() {
    let out = scratch("pdf");
    let dir = out.to_str().unwrap();
    let o = tmm(&[
        "render",
        "constructions/shaper.toml",
        "--out",
        dir,
        "--format",
        "pdf",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let files: Vec<_> = std::fs::read_dir(out.join("shaper"))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    assert_eq!(files, ["shaper.pdf"], "--format pdf writes the PDF alone");
    let pdf = std::fs::read(out.join("shaper/shaper.pdf")).unwrap();
    assert!(pdf.starts_with(b"%PDF-"));
    let text = pdf_dicts(&pdf);
    assert_eq!(
        pdf_pages(&pdf),
        8,
        "the project's eight sheets, eight pages"
    );
    assert!(text.contains("/Count 8"));
    let boxes = media_boxes_mm(&pdf);
    assert_eq!(boxes.len(), 8, "{boxes:?}");
    // Seven A1 sheets and the flywheel's part drawing on an A2, each page its sheet's size.
    let a1 = |&(w, h): &(f64, f64)| (w - 841.0).abs() < 0.5 && (h - 594.0).abs() < 0.5;
    let a2 = |&(w, h): &(f64, f64)| (w - 594.0).abs() < 0.5 && (h - 420.0).abs() < 0.5;
    assert_eq!(boxes.iter().filter(|b| a1(b)).count(), 7, "{boxes:?}");
    assert_eq!(boxes.iter().filter(|b| a2(b)).count(), 1, "{boxes:?}");
    assert!(
        text.contains("/FontFile2") || text.contains("/FontFile3"),
        "font embedded"
    );
    assert!(text.contains("DejaVuSans"), "the bundled DejaVu");
    // The file ID is a hash of the content (the same bytes below), never a random one.
    assert!(!text.contains("/CreationDate"), "no date");

    // Deterministic, and written with the SVGs and PNGs in one run.
    let again = scratch("pdf-again");
    let o = tmm(&[
        "render",
        "constructions/shaper.toml",
        "--out",
        again.to_str().unwrap(),
        "--format",
        "svg,png,pdf",
        "--dpi",
        "20",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(std::fs::read(again.join("shaper/shaper.pdf")).unwrap(), pdf);
    let mut files: Vec<_> = std::fs::read_dir(again.join("shaper"))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    files.sort();
    assert_eq!(files.len(), 17, "{files:?}");
    assert!(
        files.iter().filter(|f| f.ends_with(".svg")).count() == 8,
        "{files:?}"
    );
}

#[test]
fn render_removes_the_stale_temporaries_of_a_killed_run_and_nothing_else() {
    let out = scratch("stale");
    let folder = out.join("four-bar");
    std::fs::create_dir_all(&folder).unwrap();
    // A run killed between staging and renaming left its temporaries (its pid is dead).
    let mut child = std::process::Command::new("true").spawn().unwrap();
    let dead = child.id();
    child.wait().unwrap();
    let stale = [
        format!(".kinematics.svg.tmp-{dead}"),
        format!(".kinematics.png.tmp-{dead}"),
    ];
    let kept = [
        format!(".notes.txt.tmp-{dead}"),
        format!("kinematics.svg.tmp-{dead}"),
        "mine.svg".to_string(),
    ];
    for n in stale.iter().chain(&kept) {
        std::fs::write(folder.join(n), vec![b'x'; 1 << 16]).unwrap();
    }
    let o = tmm(&[
        "render",
        "constructions/four-bar.toml",
        "--out",
        out.to_str().unwrap(),
        "--dpi",
        "10",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for n in &stale {
        assert!(!folder.join(n).exists(), "{n} is stale");
    }
    for n in &kept {
        assert!(folder.join(n).exists(), "{n} is not tmm's");
    }
    assert!(folder.join("kinematics.svg").is_file());
    let _ = std::fs::remove_dir_all(&out);
}
