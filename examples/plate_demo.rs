//! Render the demo plate to `/tmp/plate_demo.svg` and `/tmp/plate_demo.png`.
//!
//! Usage: `cargo run --example plate_demo [ru|uk|en] [width_px] [x y w h]`; the optional
//! rectangle (sheet mm) renders only that part of the sheet, to inspect details.

use std::path::Path;
use tmm::plate::{to_png, to_svg, write_atomic};

#[path = "../tests/all/support/demo.rs"]
mod demo;
use demo::demo_plate;
use tmm::scale::Lang;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let lang = args
        .first()
        .and_then(|s| Lang::parse(s))
        .unwrap_or_default();
    let width = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(2000);
    let plate = demo_plate(lang)?;
    let mut svg = to_svg(&plate);
    if let [x, y, w, h] = args.get(2..6).unwrap_or_default() {
        let full = format!(
            r#"height="{h0}mm" viewBox="0 0 {w0} {h0}" width="{w0}mm""#,
            w0 = plate.sheet.width_mm(),
            h0 = plate.sheet.height_mm()
        );
        svg = svg.replacen(
            &full,
            &format!(r#"height="{h}mm" viewBox="{x} {y} {w} {h}" width="{w}mm""#),
            1,
        );
    }
    write_atomic(Path::new("/tmp/plate_demo.svg"), svg.as_bytes())?;
    write_atomic(Path::new("/tmp/plate_demo.png"), &to_png(&svg, width)?)?;
    println!("wrote /tmp/plate_demo.svg and /tmp/plate_demo.png ({width} px)");
    Ok(())
}
