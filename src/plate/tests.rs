//! Plate-level tests: layout, determinism, the SVG's numbers and the raster.

use super::*;
use crate::construct::{Item, Names, Role, Step, StepId};
use crate::geom::{Circle, Segment};
use crate::scale::{Quantity, Scale};
use resvg::tiny_skia::Pixmap;

fn figure(items: Vec<Item>) -> Figure {
    let steps = items
        .into_iter()
        .enumerate()
        .map(|(i, item)| Step {
            id: StepId(i as u32),
            note: String::new(),
            item,
            role: Role::Given,
            label: None,
            from: vec![],
            group: 0,
        })
        .collect();
    Figure {
        title: "test".into(),
        scale: Scale::new(0.001, Quantity::Length).unwrap(),
        steps,
        readings: Vec::new(),
    }
}

fn plate(sheet: Sheet, lang: Lang, views: Vec<View>) -> Plate {
    Plate {
        name: "t".into(),
        sheet,
        title_block: TitleBlock::default(),
        lang,
        views,
        texts: vec![],
        tables: vec![],
    }
}

#[test]
fn a1_frame_and_title_block_geometry() {
    let sheet = Sheet::default();
    assert_eq!((sheet.width_mm(), sheet.height_mm()), (841.0, 594.0));
    assert_eq!(
        sheet.frame(),
        Rect::new(DVec2::new(20.0, 5.0), DVec2::new(836.0, 589.0))
    );
    assert_eq!(
        sheet.title_block(),
        Rect::new(DVec2::new(651.0, 534.0), DVec2::new(836.0, 589.0))
    );
    assert_eq!(sheet.field().max.y, 534.0);
    let a4 = Sheet {
        size: SheetSize::A4,
        landscape: false,
    };
    assert_eq!((a4.width_mm(), a4.height_mm()), (210.0, 297.0));
    assert_eq!(a4.frame().width(), 185.0);
    let svg = to_svg(&plate(sheet, Lang::Ru, vec![]));
    assert!(svg.starts_with(r#"<svg font-family="DejaVu Sans" font-style="italic" height="594mm" viewBox="0 0 841 594" width="841mm""#), "{svg}");
    assert!(svg.contains(r#"d="M20,5 L836,5 L836,589 L20,589 Z""#));
}

#[test]
fn title_block_captions_follow_the_language() {
    let svg = |lang| to_svg(&plate(Sheet::default(), lang, vec![]));
    let ru = svg(Lang::Ru);
    assert!(
        ["Разраб.", "Пров.", "Масштаб", "Листов", "Лит."]
            .iter()
            .all(|c| ru.contains(c)),
        "{ru}"
    );
    let uk = svg(Lang::Uk);
    assert!(["Розроб.", "Перев.", "Арк.", "Аркушів", "Маса", "Літ."]
        .iter()
        .all(|c| uk.contains(c)));
    let en = svg(Lang::En);
    assert!([
        "Drawn",
        "Checked",
        "Tech. check",
        "Std. check",
        "Letter",
        ">of ",
        "Mass",
        "Scale"
    ]
    .iter()
    .all(|c| en.contains(c)));
    // "Sheet 1 of 2", as an English drawing writes it (issue 45), not "Sheets 1".
    assert!(!en.contains("Sheets"));
}

/// Every number in the SVG has at most two decimals and none is `-0`.
#[test]
fn svg_coordinates_are_rounded() {
    let third = 1.0 / 3.0;
    let f = figure(vec![
        Item::Segment(Segment::new(
            DVec2::new(third, -third),
            DVec2::new(-1e-9, 2.0 / 3.0),
        )),
        Item::Circle(Circle {
            center: DVec2::splat(third),
            radius: 7.0 / 3.0,
        }),
        Item::Vector {
            from: DVec2::ZERO,
            to: DVec2::new(10.0 * third, 7.0),
        },
    ]);
    let svg = to_svg(&plate(
        Sheet::default(),
        Lang::Ru,
        vec![View {
            figure: f,
            origin: DVec2::new(100.0 + third, 100.0),
            caption: None,
            caption_drop: 0.0,
        }],
    ));
    // Attribute values are the odd pieces between quotes; ids are names, not numbers.
    let pieces: Vec<&str> = svg.split('"').collect();
    let values = pieces
        .windows(2)
        .filter(|w| !w[0].ends_with("id="))
        .map(|w| w[1]);
    let numbers =
        values.flat_map(|v| v.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-')));
    for n in numbers.filter(|t| t.chars().any(|c| c.is_ascii_digit())) {
        let decimals = n.split_once('.').map_or(0, |(_, d)| d.len());
        assert!(decimals <= 2, "{n} has {decimals} decimals");
        assert!(n != "-0" && !n.starts_with("-0.00"), "negative zero {n}");
    }
}

#[test]
fn centred_view_reports_the_sizes_when_too_big() {
    let f = figure(vec![Item::Segment(Segment::new(
        DVec2::ZERO,
        DVec2::new(300.0, 50.0),
    ))]);
    let region = Rect::new(DVec2::new(0.0, 0.0), DVec2::new(200.0, 100.0));
    let err = View::centred(f.clone(), region, None).unwrap_err();
    assert_eq!(
        err,
        PlateError::DoesNotFit {
            view: "test".into(),
            need_w: 300.0,
            need_h: 50.0,
            have_w: 200.0,
            have_h: 100.0
        }
    );
    assert!(err.to_string().contains("300.0 × 50.0 mm"), "{err}");
    let wide = Rect::new(DVec2::new(10.0, 20.0), DVec2::new(410.0, 120.0));
    let v = View::centred(f, wide, None).unwrap();
    // Bounds (0,0)–(300,50) centred at (210, 70): origin (60, 95).
    assert_eq!(v.origin, DVec2::new(60.0, 95.0));
    assert_eq!(v.to_sheet(DVec2::new(300.0, 50.0)), DVec2::new(360.0, 45.0));
    assert!(View::centred(figure(vec![]), wide, Some("c".into())).is_ok());
}

#[test]
fn png_at_dpi_has_the_printed_size() {
    let a4 = plate(
        Sheet {
            size: SheetSize::A4,
            landscape: false,
        },
        Lang::En,
        vec![],
    );
    let png = Pixmap::decode_png(&to_png_dpi(&to_svg(&a4), 25.4).unwrap()).unwrap();
    assert_eq!((png.width(), png.height()), (210, 297));
    assert!(matches!(to_png_dpi("<svg", 150.0), Err(PlateError::Svg(_))));
    assert!(matches!(
        to_png_dpi(&to_svg(&a4), 0.0),
        Err(PlateError::Raster(_))
    ));
    assert!(matches!(
        to_png(&to_svg(&a4), 0),
        Err(PlateError::Raster(_))
    ));
}

#[test]
fn non_finite_geometry_never_panics_nor_leaks_nan() {
    let nan = f64::NAN;
    let f = figure(vec![
        Item::Segment(Segment::new(DVec2::splat(nan), DVec2::ZERO)),
        Item::Guide {
            segment: Segment::new(DVec2::ZERO, DVec2::new(f64::INFINITY, 0.0)),
            hatch: crate::geom::Side::Left,
        },
        Item::Arc(crate::geom::Arc {
            center: DVec2::ZERO,
            radius: 1e300,
            start: 0.0,
            sweep: f64::INFINITY,
        }),
        Item::Slider {
            at: DVec2::ZERO,
            angle: nan,
        },
        Item::Curve {
            points: vec![DVec2::ZERO, DVec2::splat(nan), DVec2::ONE],
            closed: true,
        },
    ]);
    let svg = to_svg(&plate(
        Sheet::default(),
        Lang::Ru,
        vec![View {
            figure: f,
            origin: DVec2::splat(100.0),
            caption: Some("x".into()),
            caption_drop: 0.0,
        }],
    ));
    assert!(!svg.contains("NaN") && !svg.contains("inf"));
    assert!(to_png(&svg, 200).is_ok());
}

/// A short unlabelled vector (a train's velocity of a pole, a side of a force polygon 2 mm
/// long) has its head fitted to it, not standing out behind its tail; one of a tenth of a
/// millimetre gives only its direction (an arc's arrowhead) and keeps its whole head.
#[test]
fn a_short_vector_keeps_its_head_within_it_and_an_arcs_arrowhead_is_whole() {
    let head = |to: f64| {
        let item = Item::Vector {
            from: DVec2::ZERO,
            to: DVec2::new(to, 0.0),
        };
        items::item_outlines(&item, (Role::Result, false), path::Map::SHEET)
            .into_iter()
            .filter_map(|o| match o.shape {
                items::Shape::Area(pts) => Some(pts),
                items::Shape::Line(..) => None,
            })
            .flatten()
            .fold(f64::INFINITY, |m, p| m.min(p.x))
    };
    assert!(head(2.5).abs() < 1e-12, "{}", head(2.5));
    assert!(head(0.1) < -3.0, "{}", head(0.1));
}

/// A plan's image shorter than its full arrowhead (the tangent's `pc`, 1,6 mm) has a dot at
/// its head, where its point is; a longer one, and a short force, have none. A labelled
/// vector's head takes at most its second half: a line shows where it starts.
#[test]
fn a_short_plan_image_has_a_dot_where_it_ends_and_a_line_before_its_head() {
    // The dots at its tip and where its head's base is.
    let drawn = |to: f64, names: Names| {
        let item = Item::Vector {
            from: DVec2::ZERO,
            to: DVec2::new(to, 0.0),
        };
        let mut label = crate::construct::Label::on(&item, "c", DVec2::ZERO, DVec2::Y);
        label.names = names;
        let step = Step {
            id: StepId(0),
            note: String::new(),
            label: Some(label),
            item,
            role: Role::Result,
            from: Vec::new(),
            group: 0,
        };
        let tip = DVec2::new(to, 0.0);
        let areas: Vec<Vec<DVec2>> = items::step_outlines(&step, path::Map::SHEET)
            .into_iter()
            .filter_map(|o| match o.shape {
                items::Shape::Area(pts) => Some(pts),
                items::Shape::Line(..) => None,
            })
            .collect();
        let centre = |pts: &[DVec2]| pts.iter().fold(DVec2::ZERO, |s, p| s + *p) / pts.len() as f64;
        let dots = (areas.iter())
            .filter(|pts| pts.len() == 4 && centre(pts).distance(tip) < 1e-9)
            .count();
        let base = (areas.iter().filter(|pts| pts.len() == 3).flatten())
            .fold(f64::INFINITY, |m, p| m.min(p.x));
        (dots, base)
    };
    let near = |(dots, base): (usize, f64), want: (usize, f64)| {
        dots == want.0 && (base - want.1).abs() < 1e-12
    };
    assert!(near(drawn(1.6, Names::Point), (1, 0.8)));
    assert!(near(drawn(3.2, Names::Point), (1, 1.6)));
    assert!(near(drawn(6.0, Names::Point), (0, 3.0)));
    assert!(near(drawn(9.0, Names::Point), (0, 5.0)));
    assert!(near(drawn(6.0, Names::Item), (0, 3.0)));
}
