//! The body of the `grid` target (`fuzz_targets/grid.rs`): a batch's grid CSV read over a
//! shipped template (`tmm::batch::read_grid`, as `tmm batch` reads it), and, when the grid is
//! accepted, its first variants loaded as scenes (what `tmm batch` does next, before any
//! study). No study, no plate: the grid's reader is what is fuzzed.

use std::path::Path;

/// Grid texts longer than this are skipped (the product's file-size cap is tested in the
/// main crate).
pub const MAX_INPUT: usize = 64 * 1024;

/// The variants of an accepted grid loaded as scenes, at most.
pub const LOADED: usize = 8;

/// The templates a grid is read over, as shipped: the grids of `constructions/variants/`
/// name their keys.
const TEMPLATES: [(&str, &str); 2] = [
    (
        "four-bar.toml",
        include_str!("../../constructions/four-bar.toml"),
    ),
    (
        "shaper.toml",
        include_str!("../../constructions/shaper.toml"),
    ),
];

/// Read the grid `data` over each template; load the variants of those that accept it.
pub fn run(data: &[u8]) {
    if data.len() > MAX_INPUT {
        return;
    }
    let Ok(grid) = std::str::from_utf8(data) else {
        return;
    };
    for (name, template) in TEMPLATES {
        let Ok(variants) = tmm::batch::read_grid(template, grid, Path::new("grid.csv")) else {
            continue;
        };
        assert!(
            !variants.is_empty(),
            "{name}: a grid accepted with no variant"
        );
        for v in variants.iter().take(LOADED) {
            let text = v
                .text()
                .unwrap_or_else(|e| panic!("{name}: variant {} accepted, then: {e}", v.name));
            let _ = tmm::scene::parse(&text, Path::new(&format!("{}.toml", v.name)));
        }
    }
}
