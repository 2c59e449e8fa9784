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
use memmap2::MmapMut;
use rayon::prelude::*;
use resvg::tiny_skia::{PixmapMut, Transform};
use resvg::usvg::{Options, Tree};
use std::sync::{Mutex, PoisonError};

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
            let bh = tiles.first().map_or(0, |(_, t)| t.h);
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

/// The pixel buffers of finished tiles, kept for the next: a 150 dpi A1 sheet is one tile of
/// 70 MB, and a fresh one costs its page faults on every sheet (ten shaper variants as PNG:
/// 3.0 s of system time with fresh canvases, 0.17 s with kept ones).
static BUFFERS: Mutex<Vec<MmapMut>> = Mutex::new(Vec::new());

/// A transparent `w` × `h` RGBA canvas on a kept buffer, else on fresh memory; the buffer
/// goes back when dropped (at most one for each thread of the pool is kept, the largest).
///
/// Fresh memory is mapped anonymous, which the system hands over zeroed, and on Linux asked
/// for in huge pages (2 MB): a fresh A1 canvas then faults about 35 times instead of 17 000,
/// which was a quarter of what `tmm render` spent on the v-engine's five sheets (system time
/// 0.088 → 0.036 s, wall 0.218 → 0.178 s, medians).
struct Canvas {
    /// `None` only once handed back.
    data: Option<MmapMut>,
    w: u32,
    h: u32,
}

impl Canvas {
    fn new(w: u32, h: u32) -> Result<Self, PlateError> {
        let n = Self::bytes(w, h);
        let kept = {
            let mut kept = BUFFERS.lock().unwrap_or_else(PoisonError::into_inner);
            // The smallest buffer that holds the canvas.
            let fit = (0..kept.len())
                .filter(|&k| kept[k].len() >= n)
                .min_by_key(|&k| kept[k].len());
            fit.map(|k| kept.swap_remove(k))
        };
        let data = match kept {
            Some(mut b) => {
                b[..n].fill(0);
                b
            }
            None => {
                let b = MmapMut::map_anon(n).map_err(|e| {
                    PlateError::Raster(format!("cannot make a canvas of {w} × {h} px: {e}"))
                })?;
                // Only advice: without huge pages the canvas is the same, its faults slower.
                #[cfg(target_os = "linux")]
                let _ = b.advise(memmap2::Advice::HugePage);
                b
            }
        };
        Ok(Self {
            data: Some(data),
            w,
            h,
        })
    }

    /// The bytes of a `w` × `h` canvas.
    fn bytes(w: u32, h: u32) -> usize {
        w as usize * h as usize * 4
    }

    fn pixmap(&mut self) -> Result<PixmapMut<'_>, PlateError> {
        let (w, h) = (self.w, self.h);
        let n = Self::bytes(w, h);
        self.data
            .as_mut()
            .and_then(|d| PixmapMut::from_bytes(&mut d[..n], w, h))
            .ok_or_else(|| PlateError::Raster(format!("cannot make a canvas of {w} × {h} px")))
    }

    fn width(&self) -> u32 {
        self.w
    }

    /// Premultiplied RGBA, row by row.
    fn data(&self) -> &[u8] {
        let n = Self::bytes(self.w, self.h);
        self.data.as_deref().map_or(&[], |d| &d[..n])
    }
}

impl Drop for Canvas {
    fn drop(&mut self) {
        let Some(data) = self.data.take() else {
            return;
        };
        let mut kept = BUFFERS.lock().unwrap_or_else(PoisonError::into_inner);
        if kept.len() < rayon::current_num_threads() {
            kept.push(data);
        } else if let Some(small) = kept
            .iter_mut()
            .min_by_key(|b| b.len())
            .filter(|b| b.len() < data.len())
        {
            // A larger buffer serves every image a smaller one does.
            *small = data;
        }
    }
}

/// Rows converted and handed to the encoder at once.
const ROWS_AT_ONCE: usize = 16;

/// Premultiplied RGBA `src` composited on white into `dst`, as gray or RGB; `false` when a
/// pixel is not gray and gray was asked for.
fn convert(src: &[u8], dst: &mut [u8], channels: Channels) -> bool {
    if channels == Channels::Gray && opaque_gray(src, dst) {
        return true;
    }
    // Over white: c + (1 − α)·255; a premultiplied channel never exceeds α.
    let over_white = |p: &[u8], k: usize| p[k].saturating_add(255 - p[3]);
    match channels {
        Channels::Gray => {
            let mut colour = 0u8;
            for (p, o) in src.chunks_exact(4).zip(dst.iter_mut()) {
                let (r, g, b) = (over_white(p, 0), over_white(p, 1), over_white(p, 2));
                colour |= (r ^ g) | (g ^ b);
                *o = r;
            }
            colour == 0
        }
        Channels::Rgb => {
            for (p, o) in src.chunks_exact(4).zip(dst.chunks_exact_mut(3)) {
                for (k, c) in o.iter_mut().enumerate() {
                    *c = over_white(p, k);
                }
            }
            true
        }
    }
}

/// The fast path of a plate, which paints its white sheet first: every pixel opaque and
/// gray, its red channel is its gray. `false` (and `dst` to be rewritten) otherwise.
fn opaque_gray(src: &[u8], dst: &mut [u8]) -> bool {
    // Whole words, no early exit: the loop vectorises.
    let mut odd = 0u32;
    for (p, o) in src.chunks_exact(4).zip(dst.iter_mut()) {
        let v = <[u8; 4]>::try_from(p).map_or(0, u32::from_le_bytes);
        odd |= ((v >> 24) ^ 0xff) | ((v ^ (v >> 8)) & 0xffff);
        *o = v as u8;
    }
    odd == 0
}

#[cfg(test)]
mod tests {
    use super::*;
    use resvg::tiny_skia::{Color, Pixmap};

    /// A small sheet with lines, arcs, dashes and text crossing tile seams.
    const SVG: &str = r##"<svg xmlns="http://www.w3.org/2000/svg" width="60mm" height="40mm" viewBox="0 0 60 40">
        <rect width="60" height="40" fill="#fff"/>
        <path d="M2 3 L58 37 M5 35 L55 4" stroke="#000" stroke-width="0.35" fill="none"/>
        <circle cx="30" cy="20" r="13.3" stroke="#000" stroke-width="0.7" fill="none"/>
        <path d="M3 20 H57" stroke="#000" stroke-width="0.25" stroke-dasharray="3 1 0.5 1"/>
        <text x="8" y="12" font-size="5">Лист 2 ω₁</text>
    </svg>"##;

    fn decode(png: &[u8]) -> Pixmap {
        Pixmap::decode_png(png).expect("decodes")
    }

    #[test]
    fn tiles_never_exceed_the_limits() {
        let t = Tiling {
            side: 100,
            pixels: 2_000,
        };
        assert_eq!(t.tile(250, 80), (84, 8));
        assert_eq!(t.tile(50, 10), (50, 10));
        assert_eq!(TILING.tile(4967, 3508), (4967, 3508));
        let (tw, th) = TILING.tile(19866, 14031);
        assert!(tw <= 8191 && th <= 8191 && 19866 * u64::from(th) <= 1 << 25);
        assert_eq!(t.tile(1, 1), (1, 1));
    }

    #[test]
    fn a_plate_is_gray_and_tiles_move_edge_pixels_by_a_sub_sample_at_most() {
        let whole = to_png_dpi_tiled(SVG, 300.0, TILING).unwrap();
        // Colour type 0 (grayscale) in the IHDR chunk.
        assert_eq!(whole[25], 0);
        let tiled = to_png_dpi_tiled(
            SVG,
            300.0,
            Tiling {
                side: 128,
                pixels: 709 * 50,
            },
        )
        .unwrap();
        let (a, b) = (decode(&whole), decode(&tiled));
        assert_eq!((a.width(), a.height()), (709, 472));
        assert_eq!((b.width(), b.height()), (709, 472));
        // An edge that crosses a tile's top or left side starts at a negative coordinate,
        // which tiny-skia's fixed point rounds the other way: a few edge pixels gain or lose
        // at most one row of its 4 × 4 sub-samples (64 of 255); with 50-row bands here about
        // 6 % of the inked pixels, on a 150 dpi plate cut into 2000 × 1000 tiles 0.1 %.
        let (mut inked, mut moved) = (0usize, 0usize);
        for (x, y) in a.pixels().iter().zip(b.pixels()) {
            let d = x.red().abs_diff(y.red());
            assert!(d <= 64, "a tile seam moves a pixel by {d}");
            inked += usize::from(x.red() < 255);
            moved += usize::from(d > 1);
        }
        assert!(moved * 10 < inked, "{moved} of {inked} inked pixels moved");
    }

    #[test]
    fn a_kept_canvas_is_cleared_whatever_it_held() {
        // No white sheet: whatever the canvas held before would show through.
        let bare = SVG.replace(r##"<rect width="60" height="40" fill="#fff"/>"##, "");
        let dark = SVG.replace(r##"fill="#fff""##, r##"fill="#000""##);
        assert!(bare != SVG && dark != SVG);
        let fresh = to_png_dpi_tiled(&bare, 100.0, TILING).unwrap();
        // A black canvas larger than the next image is left behind, and drawn on again.
        to_png_dpi_tiled(&dark, 300.0, TILING).unwrap();
        assert_eq!(to_png_dpi_tiled(&bare, 100.0, TILING).unwrap(), fresh);
        // Paper and ink, as drawn on a clear canvas.
        let img = decode(&fresh);
        assert!(img.pixels().iter().any(|p| p.red() == 255));
        assert!(img.pixels().iter().any(|p| p.red() < 64));
    }

    #[test]
    fn colour_is_kept_as_rgb() {
        let svg = SVG.replace(
            r##"stroke="#000" stroke-width="0.7""##,
            r##"stroke="#c0392b" stroke-width="0.7""##,
        );
        let png = to_png(&svg, 300).unwrap();
        assert_eq!(png[25], 2);
        let img = decode(&png);
        assert!(img.pixels().iter().any(|p| p.red() != p.blue()));
    }

    #[test]
    fn a_kept_image_is_the_one_of_its_own_svg_and_resolution() {
        let other = SVG.replace("Лист 2", "Лист 3");
        let a = to_png_dpi(SVG, 100.0).unwrap();
        let b = to_png_dpi(&other, 100.0).unwrap();
        let c = to_png_dpi(SVG, 50.0).unwrap();
        assert_ne!(a, b);
        assert_ne!(a, c);
        assert_eq!(to_png_dpi(SVG, 100.0).unwrap(), a);
        assert_eq!(to_png_dpi(&other, 100.0).unwrap(), b);
        // As made afresh.
        assert_eq!(to_png_dpi_tiled(SVG, 100.0, TILING).unwrap(), a);
        assert_eq!(to_png_dpi_tiled(SVG, 50.0, TILING).unwrap(), c);
    }

    #[test]
    fn a_parsed_svg_gives_the_png_of_its_text() {
        let parsed = ParsedSvg::new(SVG).unwrap();
        // A resolution no other test asks for: made from the tree, not found kept.
        assert_eq!(
            png_of(&parsed, 77.0).unwrap(),
            to_png_dpi_tiled(SVG, 77.0, TILING).unwrap()
        );
        assert!(png_of(&parsed, 0.0).is_err());
        assert!(ParsedSvg::new("<svg").is_err());
        // The bench's rasteriser alone takes what the PNG takes, and refuses what it refuses.
        assert!(render_only(&parsed, 77.0).is_ok());
        assert!(render_only(&parsed, 0.0).is_err());
        assert!(render_only(&parsed, 1e6).is_err());
    }

    #[test]
    fn a_gray_png_decodes_to_the_canvas_pixels() {
        let tree = parse(SVG).unwrap();
        let mut canvas = Pixmap::new(300, 200).unwrap();
        canvas.fill(Color::WHITE);
        let s = 300.0 / tree.size().width();
        resvg::render(&tree, Transform::from_scale(s, s), &mut canvas.as_mut());
        assert_eq!(decode(&to_png(SVG, 300).unwrap()).data(), canvas.data());
    }

    #[test]
    fn too_large_names_the_limit_and_the_largest_resolution() {
        let e = png_size(841.0, 594.0, 2400.0).unwrap_err().to_string();
        assert!(e.contains("2^30") && e.contains("at most 1177 dpi"), "{e}");
        assert_eq!(png_size(841.0, 594.0, 150.0).unwrap(), (4967, 3508));
        assert_eq!(png_size(841.0, 594.0, 600.0).unwrap(), (19866, 14031));
        assert!(png_size(1.0, 1.0, 1.0).is_err());
    }
}
