//! Charts: series of labelled points on two logarithmic axes, with a decade grid, axis
//! titles, a legend and point labels placed clear of each other, written as SVG.
//!
//! ```
//! use tmm::plate::chart::{Axis, Chart, ChartPoint, Series};
//! let chart = Chart {
//!     title: "error against time".into(),
//!     x: Axis::new("time per run, s", "time", "s"),
//!     y: Axis::new("max error", "error", ""),
//!     series: vec![Series {
//!         name: "chord: v_D, m/s".into(),
//!         points: vec![ChartPoint::new(1e-6, 1e-2, "12"), ChartPoint::new(4e-6, 2.5e-3, "24")],
//!     }],
//!     point_labels: Some("numbers at points: N".into()),
//! };
//! let svg = chart.to_svg();
//! assert_eq!(svg.matches("<polyline").count(), 1);
//! assert_eq!(svg, chart.to_svg());
//! ```

mod canvas;

use super::path::num;
use super::svg::FONT_FAMILY;
use super::text::{literal, Align, Placed};
use crate::geom::DVec2;
use canvas::{Canvas, Labeller, Marker};
use svg::node::element::Rectangle;
use svg::{Document, Node};

/// Sheet size of a chart, mm.
const WIDTH: f64 = 180.0;
const HEIGHT: f64 = 120.0;
/// The plot area, mm from the top-left corner.
const LEFT: f64 = 20.0;
const RIGHT: f64 = 118.0;
const TOP: f64 = 12.0;
const BOTTOM: f64 = 100.0;
/// Left edge of the legend, mm.
const LEGEND_X: f64 = 123.0;
/// Text heights, mm.
const TITLE_H: f64 = 3.5;
const LABEL_H: f64 = 2.5;
const POINT_H: f64 = 1.8;
/// Decades are kept within this range of exponents so that absurd input stays bounded.
const MAX_EXPONENT: i32 = 300;
/// Series colours, in series order (repeated with other markers when exhausted).
const COLOURS: [&str; 6] = [
    "#1f4e9c", "#c0392b", "#2e8b3a", "#8e44ad", "#d4800a", "#4a4a4a",
];
/// Marker shapes, cycled once the colours are exhausted.
const MARKERS: [Marker; 4] = [
    Marker::Circle,
    Marker::Square,
    Marker::Triangle,
    Marker::Diamond,
];
/// Stand-ins for the smallest positive value of an axis without one.
const FALLBACK_X: f64 = 1e-9;
const FALLBACK_Y: f64 = 1e-12;

/// One axis of a chart. Texts are plain (no label markup).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Axis {
    /// The axis title (`time per run, s`).
    pub title: String,
    /// Its short name in notes (`time`).
    pub name: String,
    /// Its unit in notes (`s`; empty when none).
    pub unit: String,
}

impl Axis {
    /// An axis with its title, short name and unit.
    pub fn new(title: &str, name: &str, unit: &str) -> Self {
        Self {
            title: title.into(),
            name: name.into(),
            unit: unit.into(),
        }
    }
}

/// A point of a series with its label (plain text).
#[derive(Debug, Clone, PartialEq)]
pub struct ChartPoint {
    /// Abscissa.
    pub x: f64,
    /// Ordinate.
    pub y: f64,
    /// The label written next to the point.
    pub label: String,
}

impl ChartPoint {
    /// A labelled point.
    pub fn new(x: f64, y: f64, label: &str) -> Self {
        Self {
            x,
            y,
            label: label.into(),
        }
    }
}

/// A series: a polyline with markers, one legend line.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// The legend text (plain).
    pub name: String,
    /// Points, joined in this order.
    pub points: Vec<ChartPoint>,
}

/// A log-log chart, 180 × 120 mm with a `viewBox` in mm, DejaVu Sans: the plot area with
/// decade grid lines labelled `1e-6`, `1e-5`, … (and the 2…9 lines between them), axis
/// titles, one polyline with markers per series, each point labelled, and a legend.
///
/// A point with a non-finite coordinate is left out and counted in the legend; a zero or
/// negative coordinate is drawn at the smallest positive value of its axis (over every
/// point) and the legend says so; a series left without points is not drawn; without any
/// point the chart is an empty frame with a note. Coordinates are rounded to 0.01 mm, so the
/// bytes are stable.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Chart {
    /// The title over the plot area (plain).
    pub title: String,
    /// The abscissa.
    pub x: Axis,
    /// The ordinate.
    pub y: Axis,
    /// The series, in drawing and legend order.
    pub series: Vec<Series>,
    /// A legend line after the series explaining the point labels (plain).
    pub point_labels: Option<String>,
}

/// The decades `(lo, hi)` (powers of ten, `lo < hi`) that cover the positive `values`:
/// `lo = ⌊log₁₀ min⌋`, `hi = ⌈log₁₀ max⌉`, widened by one decade when both are equal.
/// `None` when no value is positive and finite.
pub fn decade_range(values: &[f64]) -> Option<(i32, i32)> {
    let (min, max) = positive(values.iter().copied()).fold(None, |acc, v| match acc {
        None => Some((v, v)),
        Some((lo, hi)) => Some((v.min(lo), v.max(hi))),
    })?;
    let clamp = |e: f64| (e as i32).clamp(-MAX_EXPONENT, MAX_EXPONENT);
    let lo = clamp(min.log10().floor());
    let hi = clamp(max.log10().ceil()).max(lo + 1);
    Some((lo, hi))
}

/// Where `value` falls on a log axis whose decades `lo`…`hi` run from `from` to `to` (mm):
/// every decade gets the same length `(to − from) / (hi − lo)`. A non-positive or non-finite
/// value, or an empty decade range, maps to `from`.
pub fn log_position(value: f64, (lo, hi): (i32, i32), from: f64, to: f64) -> f64 {
    if !(value.is_finite() && value > 0.0) || hi <= lo {
        return from;
    }
    let t = (value.log10() - f64::from(lo)) / f64::from(hi - lo);
    from + t * (to - from)
}

/// The positive finite values.
fn positive(values: impl Iterator<Item = f64>) -> impl Iterator<Item = f64> {
    values.filter(|v| v.is_finite() && *v > 0.0)
}

/// A series as drawn: its finite points `(x, y, label)`, clamped to positive values.
struct Shown<'a> {
    series: &'a Series,
    points: Vec<(f64, f64, &'a str)>,
}

/// The series as drawn: non-finite points out, the others clamped to a positive value.
struct Drawable<'a> {
    series: Vec<Shown<'a>>,
    /// The value a zero or negative x (y) was drawn at, if any.
    zero_x: Option<f64>,
    zero_y: Option<f64>,
    omitted: usize,
}

impl<'a> Drawable<'a> {
    fn new(chart: &'a Chart) -> Self {
        let all = || chart.series.iter().flat_map(|s| &s.points);
        let smallest = |v: &dyn Fn(&ChartPoint) -> f64, fallback| {
            positive(all().map(v)).reduce(f64::min).unwrap_or(fallback)
        };
        let (floor_x, floor_y) = (
            smallest(&|p| p.x, FALLBACK_X),
            smallest(&|p| p.y, FALLBACK_Y),
        );
        let mut d = Drawable {
            series: Vec::new(),
            zero_x: None,
            zero_y: None,
            omitted: 0,
        };
        for s in &chart.series {
            let mut points = Vec::with_capacity(s.points.len());
            for p in &s.points {
                if !(p.x.is_finite() && p.y.is_finite()) {
                    d.omitted += 1;
                    continue;
                }
                let x = clamp(p.x, floor_x, &mut d.zero_x);
                let y = clamp(p.y, floor_y, &mut d.zero_y);
                points.push((x, y, p.label.as_str()));
            }
            if !points.is_empty() {
                d.series.push(Shown { series: s, points });
            }
        }
        d
    }

    /// The decade ranges of both axes, when there is a point.
    fn decades(&self) -> Option<((i32, i32), (i32, i32))> {
        let pts = || self.series.iter().flat_map(|s| &s.points);
        let xs: Vec<f64> = pts().map(|p| p.0).collect();
        let ys: Vec<f64> = pts().map(|p| p.1).collect();
        decade_range(&xs).zip(decade_range(&ys))
    }
}

/// `v`, or `floor` (noted in `used`) when `v` is not positive.
fn clamp(v: f64, floor: f64, used: &mut Option<f64>) -> f64 {
    if v > 0.0 {
        v
    } else {
        *used = Some(floor);
        floor
    }
}

/// Grid lines and labels of one axis' decades (and the 2…9 lines between them).
fn grid(c: &mut Canvas, decades: (i32, i32), horizontal: bool) {
    let (lo, hi) = decades;
    let (from, to) = if horizontal {
        (LEFT, RIGHT)
    } else {
        (BOTTOM, TOP)
    };
    for d in lo..=hi {
        let base = 10f64.powi(d);
        if d < hi {
            for k in 2..10 {
                let p = log_position(base * f64::from(k), decades, from, to);
                grid_line(c, p, horizontal, "#e3e3e3");
            }
        }
        let p = log_position(base, decades, from, to);
        grid_line(c, p, horizontal, "#9a9a9a");
        let (at, align) = if horizontal {
            (DVec2::new(p, BOTTOM + 1.5 + LABEL_H), Align::Middle)
        } else {
            (DVec2::new(LEFT - 1.5, p + LABEL_H * 0.5), Align::End)
        };
        c.label(at, &format!("1e{d}"), LABEL_H, align);
    }
}

/// A grid line across the plot area at `p` along the axis (vertical for the abscissa).
fn grid_line(c: &mut Canvas, p: f64, vertical_line: bool, stroke: &str) {
    if vertical_line {
        c.line(DVec2::new(p, TOP), DVec2::new(p, BOTTOM), stroke, 0.15);
    } else {
        c.line(DVec2::new(LEFT, p), DVec2::new(RIGHT, p), stroke, 0.15);
    }
}

/// The frame of the plot area and the title and axis titles.
fn frame(c: &mut Canvas, chart: &Chart) {
    c.doc.append(
        Rectangle::new()
            .set("x", num(LEFT))
            .set("y", num(TOP))
            .set("width", num(RIGHT - LEFT))
            .set("height", num(BOTTOM - TOP))
            .set("fill", "none")
            .set("stroke", "#000")
            .set("stroke-width", num(0.3)),
    );
    let x_title = DVec2::new((LEFT + RIGHT) * 0.5, BOTTOM + 11.0);
    c.label(x_title, &chart.x.title, TITLE_H, Align::Middle);
    let y_title = DVec2::new(LEFT - 11.0, (TOP + BOTTOM) * 0.5);
    let mut y_title = Placed::new(y_title, &literal(&chart.y.title), TITLE_H, Align::Middle);
    y_title.rotate = -90.0;
    c.text(y_title);
}

/// The series with their legend lines; returns the legend's next line position.
fn series(c: &mut Canvas, chart: &Chart, d: &Drawable, (xd, yd): ((i32, i32), (i32, i32))) -> f64 {
    let at = |&(x, y, _): &(f64, f64, &str)| {
        DVec2::new(
            log_position(x, xd, LEFT, RIGHT),
            log_position(y, yd, BOTTOM, TOP),
        )
    };
    let drawn: Vec<Vec<DVec2>> = d
        .series
        .iter()
        .map(|s| s.points.iter().map(at).collect())
        .collect();
    let mut labels = Labeller::around(drawn.iter().flatten());
    let mut legend_y = TOP + 2.0;
    for (k, (shown, pts)) in d.series.iter().zip(&drawn).enumerate() {
        let colour = COLOURS[k % COLOURS.len()];
        let marker = MARKERS[(k / COLOURS.len() + k) % MARKERS.len()];
        c.polyline(pts, colour);
        for (p, &(_, _, label)) in pts.iter().zip(&shown.points) {
            c.marker(*p, marker, colour);
            c.text(labels.place(*p, &literal(label)));
        }
        let sample = DVec2::new(LEGEND_X, legend_y);
        c.line(sample, sample + DVec2::new(7.0, 0.0), colour, 0.35);
        c.marker(sample + DVec2::new(3.5, 0.0), marker, colour);
        let at = sample + DVec2::new(9.0, 0.0);
        let text = Placed::centred(at, &literal(&shown.series.name), LABEL_H, Align::Start);
        c.text(text.fit(WIDTH - LEGEND_X - 10.0));
        legend_y += 5.0;
    }
    if let Some(note) = &chart.point_labels {
        c.label(
            DVec2::new(LEGEND_X, legend_y + 1.0),
            note,
            POINT_H,
            Align::Start,
        );
    }
    legend_y + 5.0
}

/// The notes under the legend: clamped zeros and omitted points.
fn notes(c: &mut Canvas, chart: &Chart, d: &Drawable, mut legend_y: f64) {
    let zero = |axis: &Axis, v: Option<f64>| {
        let unit = if axis.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", axis.unit)
        };
        v.map(|v| format!("{} 0 drawn at {v:.2e}{unit}", axis.name))
    };
    let omitted = (d.omitted > 0).then(|| format!("{} non-finite point(s) left out", d.omitted));
    for note in [zero(&chart.x, d.zero_x), zero(&chart.y, d.zero_y), omitted]
        .into_iter()
        .flatten()
    {
        let at = DVec2::new(LEGEND_X, legend_y);
        let text = Placed::new(at, &literal(&note), POINT_H, Align::Start);
        c.text(text.fit(WIDTH - LEGEND_X - 2.0));
        legend_y += 4.0;
    }
}

impl Chart {
    /// The chart as an SVG document (see [`Chart`]).
    pub fn to_svg(&self) -> String {
        let (w, h) = (num(WIDTH), num(HEIGHT));
        let doc = Document::new()
            .set("width", format!("{w}mm"))
            .set("height", format!("{h}mm"))
            .set("viewBox", format!("0 0 {w} {h}"))
            .set("font-family", FONT_FAMILY)
            .add(
                Rectangle::new()
                    .set("id", "background")
                    .set("x", 0)
                    .set("y", 0)
                    .set("width", w)
                    .set("height", h)
                    .set("fill", "#fff"),
            );
        let mut c = Canvas { doc, texts: 0 };
        let d = Drawable::new(self);
        let decades = d.decades();
        let title = DVec2::new(LEFT, TOP - 4.0);
        c.label(title, &self.title, TITLE_H, Align::Start);
        if let Some((xd, yd)) = decades {
            grid(&mut c, xd, true);
            grid(&mut c, yd, false);
        }
        frame(&mut c, self);
        let legend_y = match decades {
            Some(decades) => series(&mut c, self, &d, decades),
            None => {
                let mid = DVec2::new((LEFT + RIGHT) * 0.5, (TOP + BOTTOM) * 0.5);
                c.label(mid, "no finite points to plot", TITLE_H, Align::Middle);
                TOP + 2.0
            }
        };
        notes(&mut c, self, &d, legend_y);
        format!("{}\n", c.doc)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decades_are_equally_spaced() {
        let range = decade_range(&[3e-6, 4e-4]).unwrap();
        assert_eq!(range, (-6, -3));
        let at = |v: f64| log_position(v, range, 20.0, 110.0);
        assert!((at(1e-6) - 20.0).abs() < 1e-9);
        assert!((at(1e-3) - 110.0).abs() < 1e-9);
        let steps: Vec<f64> = [1e-6, 1e-5, 1e-4, 1e-3]
            .windows(2)
            .map(|w| at(w[1]) - at(w[0]))
            .collect();
        assert!(steps.iter().all(|s| (s - 30.0).abs() < 1e-9), "{steps:?}");
        // A downward axis (SVG y): same spacing, negative.
        assert!((log_position(1e-5, range, 100.0, 10.0) - 70.0).abs() < 1e-9);
        assert_eq!(decade_range(&[1e-3]), Some((-3, -2)));
        assert_eq!(decade_range(&[0.0, -1.0, f64::NAN]), None);
        assert_eq!(log_position(0.0, range, 5.0, 9.0), 5.0);
    }

    #[test]
    fn a_series_without_finite_points_is_left_out_and_counted() {
        let chart = Chart {
            series: vec![
                Series {
                    name: "nan".into(),
                    points: vec![ChartPoint::new(f64::NAN, 1.0, "1")],
                },
                Series {
                    name: "ok".into(),
                    points: vec![
                        ChartPoint::new(1.0, 0.0, "2"),
                        ChartPoint::new(2.0, 3.0, "3"),
                    ],
                },
            ],
            y: Axis::new("y", "error", ""),
            ..Chart::default()
        };
        let svg = chart.to_svg();
        assert_eq!(svg.matches("<polyline").count(), 1);
        // The smallest positive ordinate of every point, the left-out one's included.
        assert!(svg.contains("error 0 drawn at 1.00e0<"), "{svg}");
        assert!(svg.contains("1 non-finite point(s) left out"));
        assert!(!svg.contains(">nan<"));
    }
}
