//! PNG output: the SVG rasterised by resvg with the bundled fonts only.

use super::fonts::{family, font_database};
use super::PlateError;
use resvg::tiny_skia::{Color, Pixmap, Transform};
use resvg::usvg::{Options, Tree};

/// The largest raster produced, pixels (≈ 1 GiB of RGBA); larger requests are an error.
pub const MAX_PIXELS: u64 = 1 << 28;
/// CSS pixels per inch: usvg converts `mm` sizes at this resolution.
const CSS_DPI: f32 = 96.0;

fn parse(svg: &str) -> Result<Tree, PlateError> {
    let opt = Options {
        fontdb: font_database(),
        font_family: family().into(),
        ..Options::default()
    };
    Tree::from_str(svg, &opt).map_err(|e| PlateError::Svg(e.to_string()))
}

/// Rasterise `svg` to a PNG exactly `width_px` wide (the height follows the aspect ratio) on
/// a white background. Deterministic bytes.
///
/// # Errors
/// [`PlateError::Svg`] when the SVG cannot be parsed, [`PlateError::Raster`] for a zero or
/// too large size, or when encoding fails.
pub fn to_png(svg: &str, width_px: u32) -> Result<Vec<u8>, PlateError> {
    let tree = parse(svg)?;
    render(&tree, width_px as f32 / tree.size().width())
}

/// Rasterise `svg` at `dpi` pixels per inch of the printed sheet (the CLI uses 150).
///
/// # Errors
/// As [`to_png`]; also [`PlateError::Raster`] for a non-positive or non-finite `dpi`.
pub fn to_png_dpi(svg: &str, dpi: f32) -> Result<Vec<u8>, PlateError> {
    if !(dpi.is_finite() && dpi > 0.0) {
        return Err(PlateError::Raster(format!(
            "resolution must be positive, got {dpi} dpi"
        )));
    }
    render(&parse(svg)?, dpi / CSS_DPI)
}

/// Render `tree` scaled by `zoom` (pixels per CSS pixel).
fn render(tree: &Tree, zoom: f32) -> Result<Vec<u8>, PlateError> {
    let size = tree.size();
    let (w, h) = (
        (size.width() * zoom).round(),
        (size.height() * zoom).round(),
    );
    let pixels = f64::from(w) * f64::from(h);
    if !(w >= 1.0 && h >= 1.0 && pixels <= MAX_PIXELS as f64) {
        return Err(PlateError::Raster(format!(
            "image of {w} × {h} px is empty or larger than {MAX_PIXELS} px"
        )));
    }
    let mut pixmap = Pixmap::new(w as u32, h as u32)
        .ok_or_else(|| PlateError::Raster(format!("cannot allocate {w} × {h} px")))?;
    pixmap.fill(Color::WHITE);
    resvg::render(
        tree,
        Transform::from_scale(w / size.width(), h / size.height()),
        &mut pixmap.as_mut(),
    );
    pixmap
        .encode_png()
        .map_err(|e| PlateError::Raster(e.to_string()))
}
