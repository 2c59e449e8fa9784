//! Realistic sample data for the bench table and its plot: test data of `bench::table`,
//! and included by path into `examples/bench_plot.rs` (whose crate root imports the same
//! names from `tmm::bench`).

use super::{Bench, BenchRow, Throughput};

/// Chord-method errors from 1e-1 down to 1e-4 and times from 1e-6 to 1e-3 s.
pub fn sample_bench() -> Bench {
    let mut rows = Vec::new();
    for (k, n) in [12u32, 24, 48, 96, 192].into_iter().enumerate() {
        let h = 2f64.powi(-(k as i32));
        let t = 1.1e-6 * 2.3f64.powi(k as i32 * 2);
        let mut push =
            |family: &str, quantity: &str, unit: &str, max: f64, mean: f64, time: f64| {
                rows.push(BenchRow {
                    method: format!("{family}{n}"),
                    resolution: n,
                    quantity: quantity.into(),
                    max_error: max,
                    mean_error: mean,
                    time_s: time,
                    unit: unit.into(),
                })
            };
        push("chord N=", "v_D", "m/s", 0.09 * h * h, 0.04 * h * h, t);
        push("chord N=", "a_D", "m/s^2", 0.1 * h, 0.05 * h, t * 1.3);
        push(
            "inversion steps=",
            "s_S5",
            "m",
            0.05 * h * h,
            0.01 * h * h,
            t * 0.5,
        );
    }
    Bench {
        machine: "2 cores, release".into(),
        rows,
        throughput: vec![Throughput {
            name: "analytic four-bar".into(),
            per_second: 2.5e6,
            note: "one position: angles, ω, ε".into(),
        }],
    }
}
