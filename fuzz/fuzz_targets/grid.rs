//! The `grid` target: its body is `src/grid.rs` (see there and `README.md`).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| tmm_fuzz::grid::run(data));
