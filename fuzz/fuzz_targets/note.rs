//! The `note` target: its body is `src/note.rs` (see there and `README.md`).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| tmm_fuzz::note::run(data));
