//! Where a note's typesetting time goes: `cargo run --release --example note_profile SCENE
//! [SOURCE.typ]` composes the scene's note (ru), or takes its Typst source from SOURCE.typ
//! (a copy `note_source` wrote, edited to try a change of markup), typesets it once as a fresh
//! process does, and prints the time, each layout iteration Typst needed to settle its
//! introspection (contents, counters, pages), and every scope of Typst's own timing that took
//! over 2 % of it (a scope within one of its own name counts in both).

use std::collections::{BTreeMap, HashMap};
use std::path::PathBuf;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let scene = PathBuf::from(
        args.next()
            .ok_or("usage: note_profile SCENE [SOURCE.typ]")?,
    );
    let s = tmm::load(&scene)?;
    let session = tmm::Session::new(&s, tmm::Drafting::EXACT);
    let mut note = tmm::note::compose(&session, tmm::Lang::Ru)?;
    if let Some(source) = args.next() {
        note.source = std::fs::read_to_string(source)?;
    }
    typst_timing::enable();
    let start = Instant::now();
    let pdf = tmm::note::to_pdf(&note)?;
    let total = start.elapsed().as_secs_f64() * 1e3;
    typst_timing::disable();
    let mut json = Vec::new();
    typst_timing::export_json(&mut json, |_| (String::new(), 0))?;
    // Each scope's begin and end events, summed by name.
    let events: serde_json::Value = serde_json::from_slice(&json)?;
    let mut open: HashMap<(String, u64), Vec<f64>> = HashMap::new();
    let mut spent: BTreeMap<String, (f64, usize)> = BTreeMap::new();
    for e in events.as_array().into_iter().flatten() {
        let (Some(name), Some(ts)) = (e["name"].as_str(), e["ts"].as_f64()) else {
            continue;
        };
        let key = (name.to_string(), e["tid"].as_u64().unwrap_or(0));
        match e["ph"].as_str() {
            Some("B") => open.entry(key).or_default().push(ts),
            Some("E") => {
                if let Some(begin) = open.get_mut(&key).and_then(Vec::pop) {
                    let s = spent.entry(key.0).or_default();
                    s.0 += (ts - begin) / 1e3;
                    s.1 += 1;
                }
            }
            _ => {}
        }
    }
    println!("typeset in {total:.0} ms: {} bytes of PDF", pdf.len());
    let mut rows: Vec<_> = spent
        .into_iter()
        .filter(|(_, (ms, _))| *ms > 0.02 * total)
        .collect();
    rows.sort_by(|a, b| b.1 .0.total_cmp(&a.1 .0));
    for (name, (ms, calls)) in rows {
        println!("{ms:8.0} ms  {name} ({calls}×)");
    }
    Ok(())
}
