//! The program's allocator (the binary's only; the library leaves the choice to its user).

/// jemalloc: a batch's peak memory stays flat over thousands of variants (69.4 MB for 300
/// shaper variants, 69.8 MB for 1 000), where glibc's heaps grew (82 → 93 → 99 MB for 300,
/// 1 000, 3 000) from fragments of the variants' sheets (docs/bench.md, "A department's class").
#[cfg(not(target_env = "msvc"))]
#[global_allocator]
static ALLOCATOR: tikv_jemallocator::Jemalloc = tikv_jemallocator::Jemalloc;
