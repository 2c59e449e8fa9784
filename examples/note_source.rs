//! Write a scene's explanatory note as its Typst source with its figures, to read it or to
//! typeset it by hand: `cargo run --release --example note_source SCENE [DIR] [ru|uk|en]`
//! writes `DIR/note.typ` and `DIR/fig/*.svg` (DIR defaults to `/tmp/note`).

use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let scene = PathBuf::from(args.next().ok_or("usage: note_source SCENE [DIR] [LANG]")?);
    let dir = PathBuf::from(args.next().unwrap_or_else(|| "/tmp/note".into()));
    let lang = args
        .next()
        .and_then(|l| tmm::Lang::parse(&l))
        .unwrap_or(tmm::Lang::Ru);
    let s = tmm::load(&scene)?;
    let session = tmm::Session::new(&s, tmm::Drafting::EXACT);
    let note = tmm::note::compose(&session, lang)?;
    std::fs::create_dir_all(dir.join("fig"))?;
    std::fs::write(dir.join("note.typ"), &note.source)?;
    for (path, bytes) in &note.files {
        std::fs::write(dir.join(path.trim_start_matches('/')), bytes)?;
    }
    Ok(())
}
