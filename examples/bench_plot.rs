//! Render the speed-against-error plot of sample data to `/tmp/bench_plot.svg` and `.png`
//! (for looking at it; not a reference).

use tmm::bench::{Bench, BenchRow, Throughput};

#[path = "../src/bench/sample.rs"]
mod sample;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let svg = sample::sample_bench().to_svg_plot();
    std::fs::write("/tmp/bench_plot.svg", &svg)?;
    std::fs::write("/tmp/bench_plot.png", tmm::plate::to_png(&svg, 1200)?)?;
    Ok(())
}
