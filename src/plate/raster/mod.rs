//! PNG output: the SVG rasterised by resvg with the bundled fonts only.
//!
//! The image is rendered in tiles — bands of rows, split into columns when wider than
//! [`Tiling::side`] — composited on white while each tile is converted, and streamed into
//! the PNG encoder band by band, so memory stays bounded by a few tiles whatever the
//! resolution. A plate is black on white: it is written as 8-bit grayscale; an image with a
//! coloured pixel (a chart) is written as 8-bit RGB instead. Either decodes to the very pixels
//! of the rendered canvas. Tiles and plates are rendered in parallel (rayon).

use super::fonts::{family, font_database};
use super::PlateError;
use crate::kept::Recent;
use canvas::Canvas;
use gray::{convert, ROWS_AT_ONCE};
use rayon::prelude::*;
use resvg::tiny_skia::Transform;
use resvg::usvg::{Options, Tree};

mod canvas;
mod gray;

/// The largest image produced, pixels (2³⁰: an A1 sheet up to about 1170 dpi, A0 up to
/// about 830 dpi); larger requests are an error.
pub const MAX_PIXELS: u64 = 1 << 30;
/// CSS pixels per inch: usvg converts `mm` sizes at this resolution.
const CSS_DPI: f32 = 96.0;
/// Millimetres per inch.
const MM_PER_INCH: f32 = 25.4;

/// How an image is cut into tiles.
#[derive(Debug, Clone, Copy)]
struct Tiling {
    /// Largest tile side, px: tiny-skia anti-aliases a path only within 8191 px of the canvas
    /// origin (it draws it aliased beyond), so no tile is larger.
    side: u32,
    /// Largest band (a row of tiles), pixels (2²⁵ ≈ 128 MiB of RGBA): a 150 dpi A1 sheet is
    /// one tile.
    pixels: u64,
}

/// The tiling of every PNG written.
const TILING: Tiling = Tiling {
    side: 8191,
    pixels: 1 << 25,
};

impl Tiling {
    /// Column width and band height of the tiles of a `w` × `h` image.
    fn tile(self, w: u32, h: u32) -> (u32, u32) {
        let side = self.side.max(1);
        let tw = w.div_ceil(w.div_ceil(side).max(1)).max(1);
        let th = (self.pixels / u64::from(w.max(1))).clamp(1, u64::from(side.min(h.max(1))));
        (tw, th as u32)
    }
}

/// Channels written per pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Channels {
    Gray = 1,
    Rgb = 3,
}

/// Why an attempt to encode stopped.
enum Stop {
    /// A pixel is not gray: encode as RGB.
    NotGray,
    /// A real failure.
    Failed(PlateError),
}

impl From<PlateError> for Stop {
    fn from(e: PlateError) -> Self {
        Stop::Failed(e)
    }
}

fn raster_err(e: impl std::fmt::Display) -> PlateError {
    PlateError::Raster(e.to_string())
}

pub(super) fn parse(svg: &str) -> Result<Tree, PlateError> {
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
    encode(&tree, width_px as f32 / tree.size().width(), TILING)
}

/// Rasterise `svg` at `dpi` pixels per inch of the printed sheet (the CLI uses 150).
///
/// The last [`PNGS_KEPT`] images (each up to [`PNG_KEPT_BYTES`]) are kept with their SVG
/// ([`Recent`]): a class's variants share the sheets the grid does not change (the shaper
/// grid's cam and gear sheets, byte for byte the same SVG), and each is rasterised once.
///
/// # Errors
/// As [`to_png`]; also [`PlateError::Raster`] for a non-positive or non-finite `dpi`.
pub fn to_png_dpi(svg: &str, dpi: f32) -> Result<Vec<u8>, PlateError> {
    png_kept(svg, dpi, || to_png_dpi_tiled(svg, dpi, TILING))
}

/// A sheet's SVG parsed once, its text laid out, for its PNG ([`png_of`]) and its PDF page
/// ([`super::to_pdf_parsed`]) alike.
pub struct ParsedSvg<'a> {
    pub(super) svg: &'a str,
    pub(super) tree: Tree,
}

impl<'a> ParsedSvg<'a> {
    /// Parse `svg` with the bundled fonts only.
    ///
    /// # Errors
    /// [`PlateError::Svg`] when it cannot be parsed.
    pub fn new(svg: &'a str) -> Result<Self, PlateError> {
        Ok(Self {
            svg,
            tree: parse(svg)?,
        })
    }
}

/// [`to_png_dpi`] of a parsed SVG (the same bytes, the same images kept).
///
/// # Errors
/// As [`to_png_dpi`].
pub fn png_of(parsed: &ParsedSvg<'_>, dpi: f32) -> Result<Vec<u8>, PlateError> {
    png_kept(parsed.svg, dpi, || {
        check_dpi(dpi)?;
        encode(&parsed.tree, dpi / CSS_DPI, TILING)
    })
}

/// Render `parsed` at `dpi` as [`png_of`] does, band after band, and drop the pixels:
/// resvg's own share of a PNG, without the conversion and the encoding (the bench's floor
/// of what a sheet costs).
///
/// # Errors
/// As [`png_of`].
pub fn render_only(parsed: &ParsedSvg<'_>, dpi: f32) -> Result<(), PlateError> {
    check_dpi(dpi)?;
    let job = Job::new(&parsed.tree, dpi / CSS_DPI, TILING)?;
    for y0 in job.bands() {
        job.band(y0)?;
    }
    Ok(())
}

/// The image of `svg` at `dpi` as kept, or as `make` makes it (then kept).
fn png_kept(
    svg: &str,
    dpi: f32,
    make: impl FnOnce() -> Result<Vec<u8>, PlateError>,
) -> Result<Vec<u8>, PlateError> {
    let same = |(d, s): &(u32, String)| *d == dpi.to_bits() && s == svg;
    if let Some(png) = PNGS.find(same) {
        return Ok(png);
    }
    let png = make()?;
    if png.len() <= PNG_KEPT_BYTES {
        PNGS.keep((dpi.to_bits(), svg.to_string()), png.clone());
    }
    Ok(png)
}

/// The images [`to_png_dpi`] keeps.
const PNGS_KEPT: usize = 16;
/// The largest image kept, bytes (a 150 dpi A1 sheet is about 1 MB).
const PNG_KEPT_BYTES: usize = 8 << 20;
/// The images kept: the resolution's bits and the SVG, the PNG.
static PNGS: Recent<(u32, String), Vec<u8>> = Recent::new(PNGS_KEPT);

/// Forget the images [`to_png_dpi`] keeps (the bench times each run as a fresh process).
pub fn forget_pngs() {
    PNGS.clear();
}

/// [`to_png_dpi`] for several SVGs at once, rendered in parallel; the results in order.
pub fn to_png_dpi_all(svgs: &[String], dpi: f32) -> Vec<Result<Vec<u8>, PlateError>> {
    svgs.par_iter().map(|svg| to_png_dpi(svg, dpi)).collect()
}

/// The pixel size of a sheet of `width_mm` × `height_mm` rendered at `dpi`.
///
/// # Errors
/// [`PlateError::Raster`] naming the size and the largest resolution this sheet allows when
/// the image would be empty or larger than [`MAX_PIXELS`].
pub fn png_size(width_mm: f64, height_mm: f64, dpi: f32) -> Result<(u32, u32), PlateError> {
    let css = |mm: f64| mm as f32 * CSS_DPI / MM_PER_INCH;
    pixel_size(css(width_mm), css(height_mm), dpi / CSS_DPI)
}

fn to_png_dpi_tiled(svg: &str, dpi: f32, tiling: Tiling) -> Result<Vec<u8>, PlateError> {
    check_dpi(dpi)?;
    encode(&parse(svg)?, dpi / CSS_DPI, tiling)
}

/// A resolution a PNG can be made at: positive and finite.
fn check_dpi(dpi: f32) -> Result<(), PlateError> {
    if dpi.is_finite() && dpi > 0.0 {
        Ok(())
    } else {
        Err(PlateError::Raster(format!(
            "resolution must be positive, got {dpi} dpi"
        )))
    }
}

/// The pixel size of a `w` × `h` CSS px image scaled by `zoom`, within [`MAX_PIXELS`].
fn pixel_size(w: f32, h: f32, zoom: f32) -> Result<(u32, u32), PlateError> {
    let (pw, ph) = ((w * zoom).round(), (h * zoom).round());
    let pixels = f64::from(pw) * f64::from(ph);
    if pw >= 1.0 && ph >= 1.0 && pixels <= MAX_PIXELS as f64 {
        return Ok((pw as u32, ph as u32));
    }
    let dpi = f64::from(zoom * CSS_DPI);
    let area = f64::from(w) * f64::from(h) / f64::from(CSS_DPI).powi(2);
    let most = (MAX_PIXELS as f64 / area).sqrt().floor();
    Err(PlateError::Raster(if pixels.is_finite() && pixels >= 1.0 {
        format!(
            "{pw} × {ph} px at {dpi} dpi is more than the {MAX_PIXELS} px (2^30) a PNG may \
             have; this sheet allows at most {most} dpi"
        )
    } else {
        format!("an image of {pw} × {ph} px at {dpi} dpi is empty")
    }))
}

/// Render `tree` scaled by `zoom` (pixels per CSS pixel) and encode it: grayscale when every
/// pixel is gray, RGB otherwise.
fn encode(tree: &Tree, zoom: f32, tiling: Tiling) -> Result<Vec<u8>, PlateError> {
    let job = Job::new(tree, zoom, tiling)?;
    match job.encode(Channels::Gray) {
        Ok(png) => Ok(png),
        Err(Stop::NotGray) => job.encode(Channels::Rgb).map_err(|s| match s {
            Stop::Failed(e) => e,
            Stop::NotGray => PlateError::Raster("an RGB image refused a pixel".into()),
        }),
        Err(Stop::Failed(e)) => Err(e),
    }
}

/// One image to render.
struct Job<'a> {
    tree: &'a Tree,
    /// Pixels per CSS pixel along x and y.
    scale: (f32, f32),
    w: u32,
    h: u32,
    tiling: Tiling,
}

impl<'a> Job<'a> {
    /// `tree` scaled by `zoom` (pixels per CSS pixel), its size rounded to whole pixels.
    fn new(tree: &'a Tree, zoom: f32, tiling: Tiling) -> Result<Self, PlateError> {
        let size = tree.size();
        let (w, h) = pixel_size(size.width(), size.height(), zoom)?;
        Ok(Self {
            tree,
            scale: (w as f32 / size.width(), h as f32 / size.height()),
            w,
            h,
            tiling,
        })
    }

    fn encode(&self, channels: Channels) -> Result<Vec<u8>, Stop> {
        let mut out = Vec::new();
        let mut encoder = png::Encoder::new(&mut out, self.w, self.h);
        encoder.set_color(match channels {
            Channels::Gray => png::ColorType::Grayscale,
            Channels::Rgb => png::ColorType::Rgb,
        });
        encoder.set_depth(png::BitDepth::Eight);
        // fdeflate with the Sub filter: a line drawing compresses about as well as with the
        // adaptive filter (≈ 30 % larger) in half the time.
        encoder.set_compression(png::Compression::Fast);
        encoder.set_filter(png::Filter::Sub);
        // pHYs: the print resolution, so the PNG prints 1:1 too.
        let per_metre = (f64::from(self.scale.0 * CSS_DPI) / 0.0254).round() as u32;
        encoder.set_pixel_dims(Some(png::PixelDimensions {
            xppu: per_metre,
            yppu: per_metre,
            unit: png::Unit::Meter,
        }));
        let mut writer = encoder.write_header().map_err(raster_err)?;
        let mut stream = writer.stream_writer().map_err(raster_err)?;
        let ch = channels as usize;
        // Rows are converted and written a few at a time: no image-sized buffer but the tiles.
        let mut rows = vec![0u8; self.w as usize * ch * ROWS_AT_ONCE];
        for y0 in self.bands() {
            let tiles = self.band(y0)?;
            let bh = tiles.first().map_or(0, |(_, t)| t.height());
            for r0 in (0..bh as usize).step_by(ROWS_AT_ONCE) {
                let n = ROWS_AT_ONCE.min(bh as usize - r0);
                let rows = &mut rows[..self.w as usize * ch * n];
                let mut colour = false;
                for (r, dst) in rows.chunks_exact_mut(self.w as usize * ch).enumerate() {
                    for (x0, tile) in &tiles {
                        let stride = tile.width() as usize * 4;
                        let src = &tile.data()[(r0 + r) * stride..][..stride];
                        let at = *x0 as usize * ch;
                        let dst = &mut dst[at..at + tile.width() as usize * ch];
                        colour |= !convert(src, dst, channels);
                    }
                }
                if colour {
                    return Err(Stop::NotGray);
                }
                std::io::Write::write_all(&mut stream, rows).map_err(raster_err)?;
            }
        }
        stream.finish().map_err(raster_err)?;
        writer.finish().map_err(raster_err)?;
        Ok(out)
    }

    /// The first rows of the image's bands, top to bottom.
    fn bands(&self) -> impl Iterator<Item = u32> {
        let (_, th) = self.tiling.tile(self.w, self.h);
        (0..self.h).step_by(th as usize)
    }

    /// The tiles of the band from row `y0`, left to right, each with its first column,
    /// rendered side by side.
    fn band(&self, y0: u32) -> Result<Vec<(u32, Canvas)>, PlateError> {
        let (tw, th) = self.tiling.tile(self.w, self.h);
        let bh = th.min(self.h - y0);
        let xs: Vec<u32> = (0..self.w).step_by(tw as usize).collect();
        xs.par_iter()
            .map(|&x0| Ok((x0, self.tile(x0, y0, tw.min(self.w - x0), bh)?)))
            .collect()
    }

    /// The `tw` × `th` tile at (`x0`, `y0`), rendered on a transparent canvas (`convert`
    /// composites it on white; a plate paints its own white sheet first anyway).
    fn tile(&self, x0: u32, y0: u32, tw: u32, th: u32) -> Result<Canvas, PlateError> {
        let mut canvas = Canvas::new(tw, th)?;
        let mut pixmap = canvas.pixmap()?;
        let ts = Transform::from_row(
            self.scale.0,
            0.0,
            0.0,
            self.scale.1,
            -(x0 as f32),
            -(y0 as f32),
        );
        resvg::render(self.tree, ts, &mut pixmap);
        Ok(canvas)
    }
}

#[cfg(test)]
mod tests;
