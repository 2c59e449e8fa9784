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
