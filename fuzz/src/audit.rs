//! The body of the `audit` target (`fuzz_targets/audit.rs`): a student's table read
//! (`tmm::audit::read_table`) and audited against the shipped shaper (seed 000), formatted as
//! `tmm audit` formats it (Markdown, JSON). The auditor (the shaper's report and its biased
//! readings) is built once.

use std::path::Path;
use std::sync::OnceLock;
use tmm::audit::{self, Auditor};
use tmm::Lang;

/// Table texts longer than this are skipped (the product's file-size cap is tested in the
/// main crate).
pub const MAX_INPUT: usize = 64 * 1024;

/// The auditor of `constructions/shaper.toml`, built on the first input.
fn auditor() -> &'static Auditor {
    static AUDITOR: OnceLock<Auditor> = OnceLock::new();
    AUDITOR.get_or_init(|| {
        let path = Path::new("shaper.toml");
        let scene = tmm::scene::parse(include_str!("../../constructions/shaper.toml"), path)
            .unwrap_or_else(|e| panic!("the shipped shaper: {e}"));
        Auditor::new(&scene).unwrap_or_else(|e| panic!("the shipped shaper's auditor: {e}"))
    })
}

/// Read the table `data` and audit its entries.
pub fn run(data: &[u8]) {
    if data.len() > MAX_INPUT {
        return;
    }
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let auditor = auditor();
    let Ok(entries) = audit::read_table(text, Path::new("table.csv"), auditor) else {
        return;
    };
    let audited = auditor.audit(&entries);
    assert_eq!(audited.len(), entries.len(), "a line audited or lost twice");
    let _ = audit::to_markdown("shaper", &audited, Lang::Ru);
    let _ = audit::to_json(&audited);
}
