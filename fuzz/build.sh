#!/usr/bin/env bash
# Build the libFuzzer targets (every `[[bin]]` of Cargo.toml) on the stable toolchain (no nightly, no -Zsanitizer): rustc's
# stable codegen flags run LLVM's SanitizerCoverage pass with the same options cargo-fuzz
# uses, and libfuzzer-sys links libFuzzer (compiled from its bundled C++ sources by the
# system C++ compiler). See README.md.
set -euo pipefail
cd "$(dirname "$0")"
export RUSTFLAGS="${RUSTFLAGS:-} \
 -Cpasses=sancov-module \
 -Cllvm-args=-sanitizer-coverage-level=4 \
 -Cllvm-args=-sanitizer-coverage-inline-8bit-counters \
 -Cllvm-args=-sanitizer-coverage-pc-table \
 -Cllvm-args=-sanitizer-coverage-trace-compares \
 --cfg fuzzing \
 -Cdebug-assertions \
 -Coverflow-checks"
# An explicit --target keeps RUSTFLAGS off build scripts and proc macros (which cannot link
# the coverage callbacks); the binaries land in target/<host>/release/<target>.
host=$(rustc -vV | sed -n "s/^host: //p")
exec cargo build --release --target "$host" --bins "$@"
