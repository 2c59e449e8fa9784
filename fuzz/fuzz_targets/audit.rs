//! The `audit` target: its body is `src/audit.rs` (see there and `README.md`).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| tmm_fuzz::audit::run(data));
