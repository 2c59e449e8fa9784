//! Render the speed-against-error plot of sample data to `/tmp/bench_plot.svg` and `.png`
//! (for looking at it; not a reference).

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let svg = tmm::bench::sample_bench().to_svg_plot();
    std::fs::write("/tmp/bench_plot.svg", &svg)?;
    std::fs::write("/tmp/bench_plot.png", tmm::plate::to_png(&svg, 1200)?)?;
    Ok(())
}
