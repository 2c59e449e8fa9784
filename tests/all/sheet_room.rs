//! The room of every sheet `tmm render` writes (kinematics, forces, cam, gears, balancing,
//! friction, dynamics): no sheet is left nearly empty (a table or a line of text alone), and
//! a sheet less than 30 % inked is listed here with the reason it stays so (issue 19). The
//! ink share is measured as `plate-legibility` measures it: the 20 mm cells of the field
//! (inside the frame, the title block left out) that hold any line of a view.

use std::collections::BTreeSet;
use std::path::PathBuf;
use tmm::construct::Drafting;
use tmm::plate::Plate;
use tmm::scale::Lang;
use tmm::scene;

/// Side of the cells of the ink share, mm.
const CELL_MM: f64 = 20.0;
/// The share the issue asks of a sheet.
const FULL: f64 = 0.30;
/// Below this a sheet holds hardly a drawing (friction's second sheet held only the last
/// drawing and the table: 1 %).
const NEARLY_EMPTY: f64 = 0.05;

/// The sheets under [`FULL`] and why (the commits that left them say the same), with the
/// share they must keep at least.
const JUSTIFIED: &[(&str, f64, &str)] = &[
    ("cam-central/cam", 0.28, "the diagrams (2π on 240 mm, the stroke 100 mm) fill the sheet's height; the profile at μ_l = 0,001 (140 mm): the next round μ_l, 0,0005, draws it 280 mm, past its 240 mm room"),
    ("cam-cusp/cam", 0.20, "the scene fixes μ_S (0,002 m/mm: the S diagram 33 mm tall, the combined diagram 190 × 110 mm)"),
    ("cam-pz4/cam", 0.25, "the diagrams fill the sheet's height; the profile at μ_l = 0,0005 (193 mm): 0,0004 draws it 241 mm, past its 240 mm room; the tables take the rest"),
    ("shaper/cam", 0.24, "the scene fixes the poles H₁, H₂ (the seed's), so the analogues' height is the seed's; the profile at μ_l = 0,002 (153 mm): 0,001 draws it 305 mm"),
    ("cam-shock/cam", 0.20, "the profile at μ_l = 0,001 (123 mm): 0,0005 draws it 246 mm, past its 240 mm room; the uniform law's d²S/dφ² is the axis with the shocks' arrows; the combined diagram draws its two rays, not a tick at every point"),
    ("cam-flat-rocker/cam", 0.25, "the profile at μ_l = 0,001: the face lines from the turned pivots (a = 120 mm) span 240 mm; 0,0005 draws them 480 mm, past their 240 mm room; the tables take the rest"),
    ("cam-sliding/cam", 0.20, "the translating cam at μ_l = 0,001 is its travel long and its stroke tall (360 × 70 mm): 0,0005 draws it 720 mm, wider than the sheet beside the diagrams"),
    ("cam-undercut/cam", 0.28, "the profile at μ_l = 0,0005 (229 mm tall): 0,0004 draws it 286 mm, past its 240 mm room"),
    ("friction/friction", 0.18, "every free scale as large as its 160 mm room holds: the schemes drawn to scale at μ_l = 0,0004 (the screw's turn 141 mm: 0,00025 draws it 226 mm), 0,001 (the journal 114 × 136 mm: 0,0005 draws it 228 × 238 mm) and 0,004 (the rollers 121 mm: 0,0025 draws them 178 mm); the force triangles at μ_F = 10 and 100 (Q = 1000 N drawn 100 mm: one step finer draws it 200 mm, and the cases spill onto a second sheet, 3 % inked); the inclines and the wedge are schematic (not to scale, about 60 mm)"),
    ("friction-follower/friction", 0.14, "every free scale as large as its 160 mm room holds: the guide at μ_l = 0,001 (Z 133 mm from the axis: 0,0005 draws it 267 mm), the rocker at 0,001 (L = 120 mm: 0,0005 draws it 240 mm), the force triangle at μ_F = 10 (P = 883 N drawn 88 mm: 5 draws it 177 mm); three views, the closed forms and the table on an A2, the friction sheet's smallest format"),
    ("gears-pz2/gears", 0.08, "one view: a vertical train's triangles (125 mm tall at μ_l = 0,001: 0,0005 draws them 265 mm, more than an A3 holds beside its data) and the slow links' picture beside them (its plan at the same h, no higher than the first's), on the smallest format, A3"),
    ("gears-pz2-ex1/gears", 0.12, "one view: the train's triangles with the plan of ω above and the scheme beside them, and the slow links' own picture beside those; the heights from the ring 7's axis 20,5 mm below the sun's to the satellites' 68 mm above drawn 177 mm at μ_l = 0,0005 (0,001 draws them 88 mm); with its data and table it goes on an A2"),
    ("gears-pz2-ex2/gears", 0.09, "one view: the train's triangles with the plan of ω above and the scheme beside them, and the slow links' own picture beside those; the heights from the input's axis to the satellites' 56,5 mm above drawn 141 mm at μ_l = 0,0004 (0,0005 draws them 113 mm); with its data and table it goes on an A2"),
    ("gears-differential/gears", 0.09, "one narrow figure: the differential's triangles with the plan of ω above and the scheme beside them, the ring's radius 80 mm drawn 160 mm at μ_l = 0,0005 (0,001 draws it 80 mm); with its data and its table of six rows it goes on an A2"),
    ("gears-pz3/gears", 0.13, "the scene fixes μ_l"),
    ("shaper/gears", 0.21, "the meshing picture at μ_l = 0,002 fills the sheet's height (329 mm: 0,001 draws it 658 mm); the two rack-cut pinions (§4.4.1 x = 0, §4.4.2 x = 0,8 shortened) at 1 : 1 beside it, so that they, the train and the two parts of the table share one A1 (at 2 : 1 the table went to a second sheet holding nothing else)"),
    ("rotor-static/balancing", 0.15, "one disc and one polygon, each as large as its room (162 and 200 mm: one round step finer doubles them); its 14 lines of data keep it off an A3"),
    ("shaper/dynamics", 0.27, "the scene fixes μ_M and μ_φ (the seed's); the flywheel is drawn on a sheet of its own"),
    ("shaper/flywheel", 0.26, "the part drawing at the seed's 1:4 (the D taken, 860 mm, drawn 215 mm with its section and the spokes' sections): too tall for an A3, and at 1:5 its table and data find no room there, so an A2; 1:2,5 draws D 344 mm, past the A2's 341 mm field with its dimensions"),
    ("v-engine/flywheel", 0.25, "a disc, its section and front view at 1:2,5 (the D taken, 380 mm, drawn 152 mm) with its table and data on an A3, the part drawing's smallest format; 1:2 draws it 190 mm, past the A3's field, and its A2 was 17 % inked"),
    ("v-engine/dynamics", 0.26, "the scene fixes μ_φ; the free diagrams' ordinates at their 80 mm; the flywheel is drawn on a sheet of its own"),
    ("shaper/kinematics", 0.21, "the scene fixes μ_l, μ_v, μ_a (the seed's; acceleration plan 3 at its own μ_a = 0,4): the plan of positions, twelve plans and two acceleration plans, and in the band under the plans the analytic and error tables, which hold no view line; the diagrams' stack (fixed μ_S, μ_φ, H₁, H₂: 405 mm tall) does not fit that band and opens sheet 2"),
    ("shaper/kinematics-2", 0.09, "the second of two sheets, begun once the first is filled (the tables went into its band under the plans): the structural analysis, the diagrams' stack at the seed's fixed scales (μ_S, μ_φ, H₁, H₂: 405 mm tall, more than the first sheet's free band), the rocker's ω diagram and the hodograph"),
    ("six-bar/kinematics", 0.25, "the scene fixes μ_v and μ_a (the seed's); the plan of positions at μ_l raised to fit its field"),
    ("six-bar/kinematics-2", 0.10, "the second of two sheets, begun once the first is filled (the plan of positions, the twelve velocity plans at the seed's μ_v, the analytic and error tables): the one acceleration plan at the seed's μ_a (96 × 65 mm), the structural analysis, the diagrams and the hodograph"),
    ("four-bar/kinematics", 0.22, "one sheet: the plans at the largest round μ their room allows (the velocity plans at 0,01, 110 × 99 mm: 0,005 draws them 199 × 178 mm, past their 150 mm room; the acceleration plans at 0,1: 0,05 draws them 241 × 209 mm) and the tables"),
    ("tangent/kinematics", 0.18, "the plan of positions is the slider's guide, 413 × 79 mm at μ_l = 0,004 (the slider runs to ±746 mm near φ = 90°: 0,0025 draws it 637 mm, past the field); the plans tall and narrow, each at the largest round μ its 150 mm room allows (the velocity plans 134 × 34 mm at 0,04: 0,025 draws them 203 mm tall)"),
    ("shaper/forces", 0.16, "the scene fixes μ_l and μ_F (the seed's): one position's kinetostatics (the textbook's sheet 2) — group 2–3 is 360 mm tall at μ_l, the lever's F_у stands 0,66 m out on the pitch circle's image, and the polygons and details beside them leave the bottom band free"),
    ("shaper/forces-2", 0.16, "as shaper/forces, at position 10"),
    ("v-engine/forces", 0.22, "the groups at the force sheets' own μ_l = 0,0005 (2:1), as large as their 300 mm room holds (group 4–5 272 × 237 mm, 2–3 284 × 183 mm: 0,0004 draws them 335 × 297 and 352 × 226 mm); the polygons at μ_F = 40 (the largest reaction 135 mm: 25 draws it 215 mm, and the position no longer fits one A1: the lever and the table go onto a second sheet); the groups are long links, thin on their field"),
    ("v-engine/forces-2", 0.22, "as v-engine/forces, at position 6 (group 4–5 191 × 281 mm at μ_l = 0,0005: 0,0004 draws it 234 × 349 mm)"),
    ("v-engine/kinematics-2", 0.27, "the second of two sheets: the acceleration plans at the force positions 3 and 6 at μ_a = 5, as large as their 250 mm room holds (plan 3 211 × 234 mm: 4 draws it about 260 × 290 mm), the diagrams beside them at 2π on 240 mm 1,5 times as tall (a longer chart does not stand beside the plans, and a taller one is too wide), the hodograph, the tables and texts, which hold no view line"),
];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The share of the field's cells that hold a view's line.
fn ink_share(p: &Plate) -> f64 {
    let (w, h) = p.sheet.size_mm();
    let fine: BTreeSet<(i64, i64)> = tmm::plate::view_ink(p, 1.0).into_iter().flatten().collect();
    // The tool's cells start at the frame's top-left corner (20, 5).
    let coarse: BTreeSet<(i64, i64)> = fine
        .iter()
        .map(|&(x, y)| {
            let (x, y) = (x as f64 + 0.5, y as f64 + 0.5);
            (
                ((x - 20.0) / CELL_MM).floor() as i64,
                ((y - 5.0) / CELL_MM).floor() as i64,
            )
        })
        .collect();
    let (nx, ny) = (((w - 25.0) / CELL_MM) as i64, ((h - 10.0) / CELL_MM) as i64);
    let mut cells = 0;
    let mut inked = 0;
    for i in 0..nx {
        for j in 0..ny {
            let (x, y) = (20.0 + i as f64 * CELL_MM, 5.0 + j as f64 * CELL_MM);
            if x >= w - 190.0 && y >= h - 60.0 {
                continue;
            }
            cells += 1;
            inked += usize::from(coarse.contains(&(i, j)));
        }
    }
    inked as f64 / cells.max(1) as f64
}

/// Every sheet of the scenes' plates but the force sheets, with its scene's stem.
fn sheets() -> Vec<(String, Plate)> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(root().join("constructions")).expect("constructions/") {
        let path = entry.expect("entry").path();
        if path.extension().is_none_or(|x| x != "toml") {
            continue;
        }
        let s = scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        let all =
            tmm::render::plates(&s, Lang::Ru, Drafting::EXACT).unwrap_or_else(|e| panic!("{e}"));
        out.extend(
            all.into_iter()
                .filter(|(kind, _)| kind.stem() != "positions")
                .map(|(_, p)| (s.stem.clone(), p)),
        );
    }
    out
}

/// Every sheet of the scenes' plates but the force sheets: (scene/sheet, ink share).
fn shares() -> Vec<(String, f64)> {
    let mut out: Vec<(String, f64)> = sheets()
        .iter()
        .map(|(stem, p)| (format!("{stem}/{}", p.name), ink_share(p)))
        .collect();
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// A train's triangles alone go on the smallest format (PZ2: an A3, not the A2 a 265 mm
/// tall figure needed), the slow links' own picture beside them.
#[test]
fn a_trains_triangles_go_on_an_a3() {
    let pz2: Vec<Plate> = sheets()
        .into_iter()
        .filter(|(stem, _)| stem == "gears-pz2")
        .map(|(_, p)| p)
        .collect();
    assert_eq!(pz2.len(), 1);
    assert_eq!(pz2[0].sheet.size, tmm::plate::SheetSize::A3);
}

#[test]
fn no_sheet_is_left_nearly_empty_and_a_thin_one_says_why() {
    let shares = shares();
    assert!(shares.len() >= 16, "{shares:?}");
    for (name, share) in &shares {
        eprintln!("{name}: {:.0} % inked", share * 100.0);
    }
    let mut bad = Vec::new();
    for (name, share) in &shares {
        if *share < NEARLY_EMPTY {
            bad.push(format!(
                "{name}: {:.0} % inked, nearly empty",
                share * 100.0
            ));
            continue;
        }
        if *share >= FULL {
            continue;
        }
        match JUSTIFIED.iter().find(|j| j.0 == name) {
            Some((_, floor, _)) if share >= floor => {}
            Some((_, floor, why)) => bad.push(format!(
                "{name}: {:.0} % inked, below its {:.0} % ({why})",
                share * 100.0,
                floor * 100.0
            )),
            None => bad.push(format!(
                "{name}: {:.0} % inked, not justified",
                share * 100.0
            )),
        }
    }
    assert!(bad.is_empty(), "{}\nall: {shares:.2?}", bad.join("\n"));
}

/// The size rule on these sheets: no drawing (diagram, polygon, plan, scheme) whose longest
/// dimension is under 30 mm.
#[test]
fn no_drawing_on_these_sheets_is_under_30_mm() {
    let mut small = Vec::new();
    let mut n = 0;
    for (stem, p) in sheets() {
        for v in &p.views {
            let Some((lo, hi)) = v.figure.bounds() else {
                continue;
            };
            // A sign (the roughness in a part drawing's corner) draws nothing of its own.
            let sign = (v.figure.steps.iter()).all(|s| s.role == tmm::construct::Role::Dimension);
            if sign {
                continue;
            }
            n += 1;
            let longest = (hi - lo).max_element();
            if longest < 30.0 {
                small.push(format!(
                    "{stem}/{}: “{}” {longest:.1} mm",
                    p.name, v.figure.title
                ));
            }
        }
    }
    assert!(n > 50, "{n} drawings");
    assert!(small.is_empty(), "{}", small.join("\n"));
}
