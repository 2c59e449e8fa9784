//! The body of the `scene` target (`fuzz_targets/scene.rs`): scene text → load → every
//! study → every plate in memory. The main crate's `tests/all/fuzz_regressions.rs` includes
//! this file and runs it without libFuzzer.

use std::path::Path;
use tmm::{plate, sheets, Drafting, Lang, Session};

/// Scene texts longer than this are skipped: the fuzzer's budget goes to the meaning of a
/// scene, not to its size (the product's own file-size cap is tested in the main crate).
pub const MAX_INPUT: usize = 64 * 1024;

/// PNG resolution inside the target (the CLI's default is 150 dpi): low, so that an
/// execution stays cheap while the whole raster path (resvg, text, encoding) still runs.
pub const DPI: f32 = 12.0;

/// One input in this many also renders a sheet to PNG.
pub const RASTER_ONE_IN: u64 = 16;

/// FNV-1a of the input: a stable choice of which inputs are rasterised.
fn fnv1a(data: &[u8]) -> u64 {
    data.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// Carry out every study of the scene text `data` and render every plate in memory.
pub fn run(data: &[u8]) {
    if data.len() > MAX_INPUT {
        return;
    }
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(scene) = tmm::scene::parse(text, Path::new("fuzz.toml")) else {
        return;
    };
    let session = Session::new(&scene, Drafting::EXACT);
    // Every study with its check rows, as `tmm report` formats them.
    if let Ok(report) = session.report() {
        let _ = report.to_markdown(Lang::Ru);
        let _ = report.to_csv();
        let _ = report.to_json();
    }
    // Every plate, as `tmm render` builds them, to SVG. Rasterising is most of an
    // execution's time (about 100 ms a sheet even at 12 dpi), so one input in
    // [`RASTER_ONE_IN`] (by a hash of its bytes) also renders one of its sheets (chosen by the
    // same hash) to PNG.
    let Ok(plates) = sheets::build_all(&session, Lang::Ru) else {
        return;
    };
    let h = fnv1a(data);
    let raster =
        (h % RASTER_ONE_IN == 0).then(|| (h / RASTER_ONE_IN) as usize % plates.len().max(1));
    for (k, (_, p)) in plates.iter().enumerate() {
        let svg = plate::to_svg(p);
        if Some(k) == raster
            && plate::png_size(p.sheet.width_mm(), p.sheet.height_mm(), DPI).is_ok()
        {
            let _ = plate::to_png_dpi(&svg, DPI);
        }
    }
}
