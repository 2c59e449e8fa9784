//! The demonstration plate (every item kind and every role): determinism of its SVG and
//! its raster.

#[path = "support/demo.rs"]
mod demo;

use demo::demo_plate;
use resvg::tiny_skia::Pixmap;
use tmm::plate::{to_png, to_svg, Plate, TitleBlock};
use tmm::scale::Lang;

#[test]
fn svg_is_deterministic_with_stable_ids() {
    let a = to_svg(&demo_plate(Lang::Ru).unwrap());
    let b = to_svg(&demo_plate(Lang::Ru).unwrap());
    assert_eq!(a, b);
    assert!(a.contains(r#"id="view-0-step-0""#) && a.contains(r#"id="view-1-step-4""#));
    assert!(a.contains(r#"id="view-0-caption""#));
}

/// The PNG's width, height and number of dark pixels.
fn dark_pixels(png: &[u8]) -> (u32, u32, usize) {
    let pixmap = Pixmap::decode_png(png).unwrap();
    let dark = pixmap.pixels().iter().filter(|p| p.red() < 128).count();
    (pixmap.width(), pixmap.height(), dark)
}

#[test]
fn every_item_and_role_renders_to_png() {
    let demo = demo_plate(Lang::Ru).unwrap();
    let views = demo.views.clone();
    // The demo's sheet bare: the frame and an empty title block only.
    let mut bare = Plate {
        name: "t".into(),
        title_block: TitleBlock::default(),
        views: vec![],
        texts: vec![],
        tables: vec![],
        ..demo
    };
    // 2000 px across an A1 sheet: 2.4 px per mm, so a 0.5 mm main line prints dark.
    let (w, h, frame_only) = dark_pixels(&to_png(&to_svg(&bare), 2000).unwrap());
    assert_eq!((w, h), (2000, 1413));
    bare.views = views;
    let svg = to_svg(&bare);
    let png = to_png(&svg, 2000).unwrap();
    let (_, _, with_views) = dark_pixels(&png);
    assert!(
        with_views > frame_only + 1000,
        "views add only {} dark pixels",
        with_views - frame_only
    );
    assert_eq!(
        png,
        to_png(&svg, 2000).unwrap(),
        "PNG bytes differ between runs"
    );
}
