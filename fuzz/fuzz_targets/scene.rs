//! Scene text → load → every study (the report) → every plate in memory: SVG, and PNG at a low
//! resolution. The same library calls as `tmm check`, `tmm report` and `tmm render`; nothing is
//! written to disk. Any panic or abort is a finding; refusals (errors) are the expected answer
//! to most inputs.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tmm_fuzz::run(data));
