//! Scene text → load → every study → every plate in memory (the body is `src/lib.rs`).
//!
//! A custom mutator helps libFuzzer with numbers: one mutation in eight replaces one number
//! of the scene (a maximal run of digits, `.`, `e`, `+`, `-`, `_` holding a digit) with an
//! edge value (the issue's −1, 0, nan, inf, 1e300, −1e-300, 1e-9, 1e9, and a few sizes that
//! stress work estimates); the rest are libFuzzer's own byte mutations with the dictionary.
#![no_main]

use libfuzzer_sys::{fuzz_mutator, fuzz_target, fuzzer_mutate};

fuzz_target!(|data: &[u8]| tmm_fuzz::scene::run(data));

/// The values a number is replaced with.
const EDGES: &[&str] = &[
    "-1", "0", "nan", "inf", "-inf", "1e300", "-1e-300", "1e-9", "1e9", "1e45", "1e-10", "2e7",
    "20000", "100000", "0.5", "1", "2", "3", "360", "720", "-0.0", "1e-300", "180", "90",
];

/// A small deterministic generator from libFuzzer's seed.
fn next(s: &mut u64) -> usize {
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    (*s >> 16) as usize
}

/// Replace one number of `data[..size]` by an edge value; `None` when there is none or the
/// result would exceed `max_size`.
fn replace_number(data: &mut [u8], size: usize, max_size: usize, seed: u32) -> Option<usize> {
    let text = &data[..size];
    let num = |b: u8| b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'+' | b'-' | b'_');
    let mut spans = Vec::new();
    let mut k = 0;
    while k < text.len() {
        if num(text[k]) {
            let start = k;
            while k < text.len() && num(text[k]) {
                k += 1;
            }
            if text[start..k].iter().any(u8::is_ascii_digit) {
                spans.push((start, k));
            }
        } else {
            k += 1;
        }
    }
    if spans.is_empty() {
        return None;
    }
    let mut s = u64::from(seed) | 1 << 40;
    let (a, b) = spans[next(&mut s) % spans.len()];
    let rep = EDGES[next(&mut s) % EDGES.len()].as_bytes();
    let new_size = size - (b - a) + rep.len();
    if new_size > max_size {
        return None;
    }
    let tail = data[b..size].to_vec();
    data[a..a + rep.len()].copy_from_slice(rep);
    data[a + rep.len()..new_size].copy_from_slice(&tail);
    Some(new_size)
}

fuzz_mutator!(|data: &mut [u8], size: usize, max_size: usize, seed: u32| {
    if seed % 8 == 0 {
        if let Some(n) = replace_number(data, size, max_size, seed) {
            return n;
        }
    }
    fuzzer_mutate(data, size, max_size)
});
