//! The speed-against-error plot of `tmm bench` as a chart: error against time per run, both
//! on log scales, one series per (method family, quantity). The chart itself is drawn by
//! [`crate::plate::chart`].

use super::table::{Bench, BenchRow};
use crate::plate::chart::{Axis, Chart, ChartPoint, Series};

/// The rows as series, one per (method family, quantity) in the order of the first row that
/// can be drawn (finite time and error), the points sorted by resolution and labelled with
/// it; rows that cannot be drawn join their series after the others (the chart counts them).
fn series(rows: &[BenchRow]) -> Vec<Series> {
    let drawable = |r: &&BenchRow| r.time_s.is_finite() && r.max_error.is_finite();
    let ordered = rows
        .iter()
        .filter(drawable)
        .chain(rows.iter().filter(|r| !drawable(r)));
    let mut groups: Vec<Vec<&BenchRow>> = Vec::new();
    for r in ordered {
        let same =
            |g: &&mut Vec<&BenchRow>| g[0].family() == r.family() && g[0].quantity == r.quantity;
        match groups.iter_mut().find(same) {
            Some(g) => g.push(r),
            None => groups.push(vec![r]),
        }
    }
    groups
        .into_iter()
        .map(|mut g| {
            let name = format!("{}: {}, {}", g[0].family(), g[0].quantity, g[0].unit);
            g.sort_by_key(|r| r.resolution);
            let point =
                |r: &&BenchRow| ChartPoint::new(r.time_s, r.max_error, &r.resolution.to_string());
            Series {
                name,
                points: g.iter().map(point).collect(),
            }
        })
        .collect()
}

impl Bench {
    /// The speed-against-error plot as SVG: error (max over the cycle, y, log) against time
    /// per run (x, log), one series per (method family, quantity), points labelled with their
    /// N; see [`Chart`] for the layout and for how zero and non-finite values are shown.
    pub fn to_svg_plot(&self) -> String {
        Chart {
            title: format!("Speed against error — {}", self.machine),
            x: Axis::new("time per run, s", "time", "s"),
            y: Axis::new("max error over the cycle", "error", ""),
            series: series(&self.rows),
            point_labels: Some("numbers at points: N".into()),
        }
        .to_svg()
    }
}
