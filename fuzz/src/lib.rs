//! The bodies of the fuzz targets, one file each, shared by `fuzz_targets/*.rs` (libFuzzer)
//! and the main crate's `tests/all/fuzz_regressions.rs` (which includes each file and runs it
//! over the committed inputs and `regressions/<target>/`, without libFuzzer). A body uses
//! only `tmm`, the standard library and `tmm`'s own dependencies, so that it compiles in both.

pub mod audit;
pub mod grid;
pub mod note;
pub mod scene;
