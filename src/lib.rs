//! `tmm` — the graphical methods of the Theory of Mechanisms and Machines (ТММ) as a
//! geometric construction engine.
//!
//! Every procedure exists three times: a **construction** carried out step by step through the
//! recorder ([`construct`]), an independent **analytic** twin, and a **check** comparing the two.
//! Plates ([`plate`]) draw exactly what the recorder recorded, at the textbook's μ scales.
//!
//! Module map (dependencies point one way):
//! `geom`, `scale` ← `construct`, `calculus`, `check` ← `linkage`, `kinematics` ← `scene` ←
//! `study` (the session over one scene: each study computed once, on demand) ← `sheets`,
//! `report` ← the `tmm` binary. `plate` draws recorded figures; `check` holds the typed rows
//! (graphical against analytic) every domain module emits and a scene's [`Report`] of them;
//! `report` only writes a report (nothing below it imports it); `render` turns a run's
//! scenes into SVG/PNG/PDF files written atomically (scene → session → sheets → files);
//! `bench` times each method against its error (`tmm bench`) and writes its own table and
//! plot.
//!
//! The way in, for a program using the library as the `tmm` binary does:
//! ```no_run
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! let scene = tmm::load("constructions/shaper.toml".as_ref())?;
//! let session = tmm::Session::new(&scene, tmm::Drafting::EXACT);
//! for &kind in &scene.plates {
//!     for sheet in tmm::build(&session, kind, tmm::Lang::Ru)? {
//!         let svg = tmm::plate::to_svg(&sheet);
//!         # let _ = svg;
//!     }
//! }
//! let report = session.report()?; // every reading, graphical against analytic
//! println!("{}", report.to_json());
//! # Ok(()) }
//! ```
//! The modules below are the layers; the compiled form of a mechanism (its operations and
//! resolved dyads) stays inside `linkage`.

pub mod audit;
pub mod balancing;
pub mod batch;
pub mod bench;
pub mod calculus;
pub mod cam;
pub mod check;
pub mod construct;
pub mod dynamics;
pub mod forces;
pub mod friction;
pub mod gears;
pub mod geom;
pub mod kept;
pub mod kinematics;
pub mod linkage;
pub mod note;
pub mod plate;
pub mod render;
pub mod report;
pub mod scale;
pub mod scene;
pub mod sheets;
pub mod studio;
pub mod study;
pub mod threads;
pub mod words;

pub use check::Report;
pub use check::{Key, Method, Row};
pub use construct::Drafting;
pub use scale::Lang;
pub use scene::{load, PlateKind, Scene};
pub use sheets::build;
pub use study::Session;
