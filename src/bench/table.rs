//! The output of `tmm bench`: each method's resolution swept, time per run against error,
//! as a Markdown table, JSON and an SVG plot.

use crate::report::{finite, json, md_cell, md_header, md_row};
use serde::Serialize;
use std::fmt::Write as _;

/// One method at one resolution: its error on one quantity and its time per run.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchRow {
    /// The method with its resolution, e.g. `chord N=12`; the text before the first word
    /// holding `=` is the method family ([`BenchRow::family`]).
    pub method: String,
    /// The resolution: positions N, inversion steps, rack positions, …
    pub resolution: u32,
    /// The quantity compared, e.g. `v_D`.
    pub quantity: String,
    /// Largest |error| over the cycle, in `unit`.
    pub max_error: f64,
    /// Mean |error| over the cycle, in `unit`.
    pub mean_error: f64,
    /// Wall time of one run, seconds.
    pub time_s: f64,
    /// Unit of the errors.
    pub unit: String,
}

impl BenchRow {
    /// The method family: `method` up to its first word that holds `=` (`chord N=12` →
    /// `chord`), the whole text when there is none.
    pub fn family(&self) -> &str {
        let cut = self
            .method
            .split_whitespace()
            .find(|w| w.contains('='))
            .and_then(|w| self.method.find(w))
            .unwrap_or(self.method.len());
        let family = self.method[..cut].trim();
        if family.is_empty() {
            self.method.trim()
        } else {
            family
        }
    }
}

/// How many times per second a whole computation runs.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Throughput {
    /// What was run, e.g. `analytic four-bar`.
    pub name: String,
    /// Runs per second.
    pub per_second: f64,
    /// What one run is.
    pub note: String,
}

/// The result of `tmm bench`.
#[derive(Debug, Clone, PartialEq)]
pub struct Bench {
    /// The machine it ran on (CPU, cores, build profile).
    pub machine: String,
    /// Speed against error, one row per method, resolution and quantity.
    pub rows: Vec<BenchRow>,
    /// Throughput of whole computations.
    pub throughput: Vec<Throughput>,
}

#[derive(Serialize)]
struct JsonBench<'a> {
    machine: &'a str,
    rows: Vec<JsonBenchRow<'a>>,
    throughput: Vec<JsonThroughput<'a>>,
}

#[derive(Serialize)]
struct JsonBenchRow<'a> {
    method: &'a str,
    family: &'a str,
    resolution: u32,
    quantity: &'a str,
    unit: &'a str,
    max_error: Option<f64>,
    mean_error: Option<f64>,
    time_s: Option<f64>,
}

#[derive(Serialize)]
struct JsonThroughput<'a> {
    name: &'a str,
    per_second: Option<f64>,
    note: &'a str,
}

/// `x` in scientific notation with three significant digits (`1.23e-5`).
fn sci(x: f64) -> String {
    if x.is_finite() {
        format!("{x:.2e}")
    } else {
        format!("{x}")
    }
}

impl Bench {
    /// A Markdown page: a heading with the machine, one table row per [`BenchRow`] (method,
    /// N, quantity, unit, max error, mean error, time per run), then the throughput table.
    pub fn to_markdown(&self) -> String {
        let mut out = format!(
            "# tmm bench — {}\n\n## Speed against error\n\n",
            md_cell(&self.machine)
        );
        md_header(
            &mut out,
            &[
                "method",
                "N",
                "quantity",
                "unit",
                "max error",
                "mean error",
                "time per run, s",
            ],
        );
        for r in &self.rows {
            md_row(
                &mut out,
                &[
                    md_cell(&r.method),
                    r.resolution.to_string(),
                    md_cell(&r.quantity),
                    md_cell(&r.unit),
                    sci(r.max_error),
                    sci(r.mean_error),
                    sci(r.time_s),
                ],
            );
        }
        if !self.throughput.is_empty() {
            let _ = writeln!(out, "\n## Throughput\n");
            md_header(&mut out, &["computation", "runs per second", "note"]);
            for t in &self.throughput {
                md_row(
                    &mut out,
                    &[md_cell(&t.name), sci(t.per_second), md_cell(&t.note)],
                );
            }
        }
        out
    }

    /// JSON: `{"machine", "rows": [{"method", "family", "resolution", "quantity", "unit",
    /// "max_error", "mean_error", "time_s"}], "throughput": [{"name", "per_second",
    /// "note"}]}`, keys in this order; a non-finite number is written as `null`.
    pub fn to_json(&self) -> String {
        json(&JsonBench {
            machine: &self.machine,
            rows: self
                .rows
                .iter()
                .map(|r| JsonBenchRow {
                    method: &r.method,
                    family: r.family(),
                    resolution: r.resolution,
                    quantity: &r.quantity,
                    unit: &r.unit,
                    max_error: finite(r.max_error),
                    mean_error: finite(r.mean_error),
                    time_s: finite(r.time_s),
                })
                .collect(),
            throughput: self
                .throughput
                .iter()
                .map(|t| JsonThroughput {
                    name: &t.name,
                    per_second: finite(t.per_second),
                    note: &t.note,
                })
                .collect(),
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::bench::sample::sample_bench;
    use crate::plate::chart::{decade_range, log_position};
    use crate::report::tests::sorted_keys;
    use serde_json::Value;

    #[test]
    fn family_is_the_method_without_its_resolution() {
        let b = sample_bench();
        assert_eq!(b.rows[0].family(), "chord");
        assert_eq!(b.rows[2].family(), "inversion");
        let mut r = b.rows[0].clone();
        r.method = "rack".into();
        assert_eq!(r.family(), "rack");
        r.method = "N=3".into();
        assert_eq!(r.family(), "N=3");
    }

    #[test]
    fn markdown_has_one_row_per_bench_row() {
        let b = sample_bench();
        let md = b.to_markdown();
        let table_rows = md
            .lines()
            .filter(|l| l.starts_with("| chord") || l.starts_with("| inversion"))
            .count();
        assert_eq!(table_rows, b.rows.len());
        assert!(md.contains("| chord N=12 | 12 | v_D | m/s | 9.00e-2 | 4.00e-2 | 1.10e-6 |"));
        assert!(md.contains("| analytic four-bar | 2.50e6 |"));
    }

    #[test]
    fn json_keys() {
        let mut b = sample_bench();
        b.rows[1].time_s = f64::NAN;
        let text = b.to_json();
        assert!(!text.contains("NaN"));
        let v: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(sorted_keys(&v), ["machine", "rows", "throughput"]);
        assert_eq!(
            sorted_keys(&v["rows"][0]),
            [
                "family",
                "max_error",
                "mean_error",
                "method",
                "quantity",
                "resolution",
                "time_s",
                "unit"
            ]
        );
        let row = &v["rows"][0];
        assert_eq!(row["resolution"], 12);
        assert!(v["rows"][1]["time_s"].is_null());
        assert_eq!(v["throughput"][0]["per_second"].as_f64(), Some(2.5e6));
    }

    #[test]
    fn decades_are_the_charts() {
        // `report::{decade_range, log_position}` are the chart's (tested in plate::chart).
        assert_eq!(decade_range(&[3e-6, 4e-4]), Some((-6, -3)));
        assert_eq!(log_position(1e-5, (-6, -3), 100.0, 10.0), 70.0);
    }

    #[test]
    fn the_plot_is_deterministic_with_one_series_per_family_and_quantity() {
        let b = sample_bench();
        let svg = b.to_svg_plot();
        assert_eq!(svg, sample_bench().to_svg_plot());
        assert_eq!(svg.matches("<polyline").count(), 3);
        for attr in [
            r#"width="180mm""#,
            r#"height="120mm""#,
            r#"viewBox="0 0 180 120""#,
        ] {
            assert!(svg.contains(attr), "{attr}");
        }
        assert!(svg.contains(r#"font-family="DejaVu Sans""#));
        assert!(svg.contains(">1e-6<") && svg.contains(">1e-4<"));
        assert!(svg.contains("chord: v_D, m/s"));
        assert!(!svg.contains("NaN"));
    }

    #[test]
    fn edge_cases_do_not_panic() {
        let mut b = sample_bench();
        b.rows[0].max_error = 0.0;
        b.rows[1].time_s = 0.0;
        b.rows[2].max_error = f64::INFINITY;
        let svg = b.to_svg_plot();
        assert!(svg.contains("error 0 drawn at"));
        assert!(svg.contains("time 0 drawn at"));
        assert!(svg.contains("1 non-finite point(s) left out"));
        assert!(crate::plate::to_png(&svg, 300).is_ok());

        b.rows.truncate(1);
        let one = b.to_svg_plot();
        assert_eq!(one.matches("<polyline").count(), 1);
        assert!(crate::plate::to_png(&one, 300).is_ok());

        b.rows.clear();
        let empty = b.to_svg_plot();
        assert!(empty.contains("no finite points to plot"));
        assert!(crate::plate::to_png(&empty, 300).is_ok());
        assert!(b.to_markdown().contains("| method |"));
    }
}
