//! The speed-against-error plot of `tmm bench`: error against time per run, both on log
//! scales, one polyline per (method family, quantity).

use super::bench::{Bench, BenchRow};
use crate::geom::DVec2;
use crate::plate::text::{approx_width, Align, Placed};
use crate::plate::{num, FONT_FAMILY};
use std::fmt::Write as _;

/// Sheet size of the plot, mm.
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

#[derive(Debug, Clone, Copy)]
enum Marker {
    Circle,
    Square,
    Triangle,
    Diamond,
}

/// The decades `(lo, hi)` (powers of ten, `lo < hi`) that cover the positive `values`:
/// `lo = ⌊log₁₀ min⌋`, `hi = ⌈log₁₀ max⌉`, widened by one decade when both are equal.
/// `None` when no value is positive and finite.
pub fn decade_range(values: &[f64]) -> Option<(i32, i32)> {
    let positive = values.iter().copied().filter(|v| v.is_finite() && *v > 0.0);
    let (min, max) = positive.fold(None, |acc: Option<(f64, f64)>, v| match acc {
        None => Some((v, v)),
        Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
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

/// One drawn series: a method family on one quantity.
struct Series<'a> {
    family: &'a str,
    quantity: &'a str,
    unit: &'a str,
    /// `(time, error, resolution)`, sorted by resolution.
    points: Vec<(f64, f64, u32)>,
}

/// What was changed so that every point can be drawn.
#[derive(Default)]
struct Adjusted {
    zero_time: Option<f64>,
    zero_error: Option<f64>,
    omitted: usize,
}

/// The smallest positive finite value of `values`.
fn smallest_positive(values: impl Iterator<Item = f64>) -> Option<f64> {
    values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.min(v))))
}

/// Group the rows into series in first-appearance order; non-finite points are dropped and
/// zero (or negative) times and errors clamped to the smallest positive value of their axis.
fn series(rows: &[BenchRow]) -> (Vec<Series<'_>>, Adjusted) {
    let mut adjusted = Adjusted::default();
    let floor_t = smallest_positive(rows.iter().map(|r| r.time_s)).unwrap_or(1e-9);
    let floor_e = smallest_positive(rows.iter().map(|r| r.max_error)).unwrap_or(1e-12);
    let mut out: Vec<Series> = Vec::new();
    for r in rows {
        if !(r.time_s.is_finite() && r.max_error.is_finite()) {
            adjusted.omitted += 1;
            continue;
        }
        let mut t = r.time_s;
        if t <= 0.0 {
            t = floor_t;
            adjusted.zero_time = Some(floor_t);
        }
        let mut e = r.max_error;
        if e <= 0.0 {
            e = floor_e;
            adjusted.zero_error = Some(floor_e);
        }
        let (family, quantity) = (r.family(), r.quantity.as_str());
        let point = (t, e, r.resolution);
        match out
            .iter_mut()
            .find(|s| s.family == family && s.quantity == quantity)
        {
            Some(s) => s.points.push(point),
            None => out.push(Series {
                family,
                quantity,
                unit: &r.unit,
                points: vec![point],
            }),
        }
    }
    for s in &mut out {
        s.points.sort_by_key(|p| p.2);
    }
    (out, adjusted)
}

/// Writes the elements of the plot, numbering the texts.
struct Canvas {
    body: String,
    texts: usize,
}

impl Canvas {
    fn line(&mut self, a: DVec2, b: DVec2, stroke: &str, width: f64) {
        let _ = writeln!(
            self.body,
            r#"<path d="M{} {}L{} {}" fill="none" stroke="{stroke}" stroke-width="{}"/>"#,
            num(a.x),
            num(a.y),
            num(b.x),
            num(b.y),
            num(width)
        );
    }

    fn text(&mut self, placed: Placed) {
        self.texts += 1;
        self.body
            .push_str(&placed.to_xml(&format!("plot-text-{}", self.texts)));
        self.body.push('\n');
    }

    fn label(&mut self, at: DVec2, markup: &str, height: f64, align: Align) {
        self.text(Placed::new(at, markup, height, align));
    }

    fn polyline(&mut self, pts: &[DVec2], colour: &str) {
        let d: Vec<String> = pts
            .iter()
            .map(|p| format!("{},{}", num(p.x), num(p.y)))
            .collect();
        let _ = writeln!(
            self.body,
            r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="0.35" stroke-linejoin="round"/>"#,
            d.join(" ")
        );
    }

    fn marker(&mut self, p: DVec2, marker: Marker, colour: &str) {
        let r = 0.9;
        let (x, y) = (p.x, p.y);
        let shape = match marker {
            Marker::Circle => format!(r#"<circle cx="{}" cy="{}" r="{}""#, num(x), num(y), num(r)),
            Marker::Square => format!(
                r#"<rect x="{}" y="{}" width="{}" height="{}""#,
                num(x - r * 0.85),
                num(y - r * 0.85),
                num(r * 1.7),
                num(r * 1.7)
            ),
            Marker::Triangle => format!(
                r#"<path d="M{} {}L{} {}L{} {}Z""#,
                num(x),
                num(y - r * 1.15),
                num(x + r),
                num(y + r * 0.6),
                num(x - r),
                num(y + r * 0.6)
            ),
            Marker::Diamond => format!(
                r#"<path d="M{} {}L{} {}L{} {}L{} {}Z""#,
                num(x),
                num(y - r * 1.2),
                num(x + r),
                num(y),
                num(x),
                num(y + r * 1.2),
                num(x - r),
                num(y)
            ),
        };
        let _ = writeln!(
            self.body,
            r##"{shape} fill="#fff" stroke="{colour}" stroke-width="0.3"/>"##
        );
    }
}

/// Places the N labels of the points where they cover no marker and no other label.
struct Labeller {
    /// Boxes already used, `(min, max)` in mm.
    taken: Vec<(DVec2, DVec2)>,
}

impl Labeller {
    /// Half the size of the box kept free around a marker, mm.
    const MARKER: f64 = 1.1;
    /// Gap between a point and its label, mm.
    const GAP: f64 = 1.3;

    /// A labeller with every marker's box taken.
    fn around<'a>(points: impl Iterator<Item = &'a DVec2>) -> Self {
        let half = DVec2::splat(Self::MARKER);
        Self {
            taken: points.map(|&p| (p - half, p + half)).collect(),
        }
    }

    /// The label `text` of the point `p`: above right, below right, above left or below left,
    /// the first of these that is free and inside the plot area (above right when none is).
    fn place(&mut self, p: DVec2, text: &str) -> Placed {
        let (w, h, g) = (approx_width(text, POINT_H), POINT_H, Self::GAP);
        let candidates = [
            (DVec2::new(p.x + g, p.y - g), Align::Start),
            (DVec2::new(p.x + g, p.y + g + h), Align::Start),
            (DVec2::new(p.x - g, p.y - g), Align::End),
            (DVec2::new(p.x - g, p.y + g + h), Align::End),
        ];
        let bbox = |(at, align): (DVec2, Align)| {
            let x0 = if align == Align::End { at.x - w } else { at.x };
            (DVec2::new(x0, at.y - h), DVec2::new(x0 + w, at.y))
        };
        let free = |b: &(DVec2, DVec2)| {
            b.0.x >= LEFT
                && b.1.x <= RIGHT
                && b.0.y >= TOP
                && b.1.y <= BOTTOM
                && self
                    .taken
                    .iter()
                    .all(|t| b.1.x <= t.0.x || b.0.x >= t.1.x || b.1.y <= t.0.y || b.0.y >= t.1.y)
        };
        let chosen = candidates
            .iter()
            .copied()
            .find(|&c| free(&bbox(c)))
            .unwrap_or(candidates[0]);
        self.taken.push(bbox(chosen));
        Placed::new(chosen.0, text, POINT_H, chosen.1)
    }
}

/// A decade's label: `1e-6`, `1e0`, `1e3`.
fn decade_label(d: i32) -> String {
    format!("1e{d}")
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
                minor_or_major(c, p, horizontal, "#e3e3e3");
            }
        }
        let p = log_position(base, decades, from, to);
        minor_or_major(c, p, horizontal, "#9a9a9a");
        if horizontal {
            c.label(
                DVec2::new(p, BOTTOM + 1.5 + LABEL_H),
                &decade_label(d),
                LABEL_H,
                Align::Middle,
            );
        } else {
            c.label(
                DVec2::new(LEFT - 1.5, p + LABEL_H * 0.5),
                &decade_label(d),
                LABEL_H,
                Align::End,
            );
        }
    }
}

fn minor_or_major(c: &mut Canvas, p: f64, vertical_line: bool, stroke: &str) {
    if vertical_line {
        c.line(DVec2::new(p, TOP), DVec2::new(p, BOTTOM), stroke, 0.15);
    } else {
        c.line(DVec2::new(LEFT, p), DVec2::new(RIGHT, p), stroke, 0.15);
    }
}

/// The plot of `bench`: error (max over the cycle, y, log) against time per run (x, log),
/// 180 × 120 mm with a `viewBox` in mm, DejaVu Sans; one polyline with markers per
/// (method family, quantity) in first-appearance order, points labelled with their N;
/// decade grid lines labelled `1e-6`, `1e-5`, …; axis titles and a legend. Zero times or
/// errors are drawn at the smallest positive value of their axis and the legend says so;
/// non-finite points are left out and counted in the legend; without points the plot is an
/// empty frame with a note. Coordinates are rounded to 0.01 mm, so the bytes are stable.
pub(crate) fn bench_plot(bench: &Bench) -> String {
    let (all, adjusted) = series(&bench.rows);
    let mut c = Canvas {
        body: String::new(),
        texts: 0,
    };
    let times: Vec<f64> = all
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.0))
        .collect();
    let errors: Vec<f64> = all
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .collect();
    let x_dec = decade_range(&times);
    let y_dec = decade_range(&errors);
    c.label(
        DVec2::new(LEFT, TOP - 4.0),
        &escape_markup(&format!("Speed against error — {}", bench.machine)),
        TITLE_H,
        Align::Start,
    );
    if let (Some(xd), Some(yd)) = (x_dec, y_dec) {
        grid(&mut c, xd, true);
        grid(&mut c, yd, false);
    }
    let _ = writeln!(
        c.body,
        r##"<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#000" stroke-width="0.3"/>"##,
        num(LEFT),
        num(TOP),
        num(RIGHT - LEFT),
        num(BOTTOM - TOP)
    );
    c.label(
        DVec2::new((LEFT + RIGHT) * 0.5, BOTTOM + 11.0),
        "time per run, s",
        TITLE_H,
        Align::Middle,
    );
    let mut y_title = Placed::new(
        DVec2::new(LEFT - 11.0, (TOP + BOTTOM) * 0.5),
        "max error over the cycle",
        TITLE_H,
        Align::Middle,
    );
    y_title.rotate = -90.0;
    c.text(y_title);
    let mut legend_y = TOP + 2.0;
    match (x_dec, y_dec) {
        (Some(xd), Some(yd)) => {
            let drawn: Vec<Vec<DVec2>> = all
                .iter()
                .map(|s| {
                    s.points
                        .iter()
                        .map(|&(t, e, _)| {
                            DVec2::new(
                                log_position(t, xd, LEFT, RIGHT),
                                log_position(e, yd, BOTTOM, TOP),
                            )
                        })
                        .collect()
                })
                .collect();
            let mut labels = Labeller::around(drawn.iter().flatten());
            for (k, (s, pts)) in all.iter().zip(&drawn).enumerate() {
                let colour = COLOURS[k % COLOURS.len()];
                let marker = MARKERS[(k / COLOURS.len() + k) % MARKERS.len()];
                c.polyline(pts, colour);
                for (p, &(_, _, n)) in pts.iter().zip(&s.points) {
                    c.marker(*p, marker, colour);
                    c.text(labels.place(*p, &n.to_string()));
                }
                let sample = DVec2::new(LEGEND_X, legend_y);
                c.line(sample, sample + DVec2::new(7.0, 0.0), colour, 0.35);
                c.marker(sample + DVec2::new(3.5, 0.0), marker, colour);
                let text = format!("{}: {}, {}", s.family, s.quantity, s.unit);
                c.text(
                    Placed::centred(
                        sample + DVec2::new(9.0, 0.0),
                        &escape_markup(&text),
                        LABEL_H,
                        Align::Start,
                    )
                    .fit(WIDTH - LEGEND_X - 10.0),
                );
                legend_y += 5.0;
            }
            c.label(
                DVec2::new(LEGEND_X, legend_y + 1.0),
                "numbers at points: N",
                POINT_H,
                Align::Start,
            );
            legend_y += 5.0;
        }
        _ => c.label(
            DVec2::new((LEFT + RIGHT) * 0.5, (TOP + BOTTOM) * 0.5),
            "no finite points to plot",
            TITLE_H,
            Align::Middle,
        ),
    }
    let mut notes = Vec::new();
    if let Some(t) = adjusted.zero_time {
        notes.push(format!("time 0 drawn at {t:.2e} s"));
    }
    if let Some(e) = adjusted.zero_error {
        notes.push(format!("error 0 drawn at {e:.2e}"));
    }
    if adjusted.omitted > 0 {
        notes.push(format!("{} non-finite point(s) left out", adjusted.omitted));
    }
    for note in notes {
        c.text(
            Placed::new(
                DVec2::new(LEGEND_X, legend_y),
                &escape_markup(&note),
                POINT_H,
                Align::Start,
            )
            .fit(WIDTH - LEGEND_X - 2.0),
        );
        legend_y += 4.0;
    }
    format!(
        concat!(
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}mm" height="{h}mm" "#,
            r#"viewBox="0 0 {w} {h}" font-family="{font}">"#,
            "\n",
            r##"<rect id="background" x="0" y="0" width="{w}" height="{h}" fill="#fff"/>"##,
            "\n{body}</svg>\n"
        ),
        w = num(WIDTH),
        h = num(HEIGHT),
        font = FONT_FAMILY,
        body = c.body
    )
}

/// Plain text as label markup: `_`, `^` and `\` kept literally. The legend shows quantity
/// keys (`v_B3_B1`) as written, so they read the same as in the table and JSON.
fn escape_markup(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for ch in s.chars() {
        if matches!(ch, '_' | '^' | '\\') {
            out.push('\\');
        }
        out.push(ch);
    }
    out
}
