//! A gear study's typed notes written in English exactly as the pair's and the racks' notes
//! were written before they were typed.

use super::tests::{s, says, scene_notes};
use crate::check::notes::gears::GearsNote;

#[test]
fn a_gear_pairs_errata_read_as_pz3_printed_them() {
    says(
        GearsNote::EpsNotReproduced {
            printed: 1.14,
            eps: 1.16374,
        },
        "gears: erratum: the seed's ε_α = 1.14 is not reproducible; ε_α = 1.1637",
    );
    says(
        GearsNote::CosMisread {
            read: 0.8836,
            a_w_read: 0.18079,
            printed: Some(0.18079),
            cos: 0.8915,
            a_w: 0.1791826,
        },
        "gears: erratum: cos α_w read as 0.8836 (= cos 27.92°) gives a_w = 180.79 mm (the seed prints 180.79 mm); cos α_w = 0.8915 gives a_w = 179.18 mm",
    );
    says(
        GearsNote::AwNotReproduced {
            printed: 0.18079,
            a_w: 0.1791826,
        },
        "gears: erratum: the seed's a_w = 180.79 mm is not reproducible; a_w = 179.18 mm",
    );
    says(
        GearsNote::Pitch {
            printed: 0.01413,
            pitch: std::f64::consts::PI * 0.01,
        },
        "gears: erratum: the printed \"p = 14.13 mm\" contradicts p = πm = 31.416 mm",
    );
    says(
        GearsNote::Compass {
            deviation: 2.09e-5,
            step: 5.22e-6,
        },
        "gears: the compass involute of wheel 1 through P (N₁P in 4 parts) deviates from the exact one by 0.0209 mm (chord-vs-arc error of one step 0.00522 mm)",
    );
}

#[test]
fn a_wheel_cut_by_the_rack_reads_as_pz1_printed_it() {
    let pz1 = scene_notes("gears-pz1");
    for line in [
        "gears: wheel 0 (z = 10, x = 0) cut by the rack in 40 steps: undercut shown on the drawing (the fillet crosses the involute), undercut by the criterion (the flank's end 9.9997 mm below the pitch line, the limit r·sin²α = 5.8489 mm)",
        "gears: wheel 0: x_min = h_a* − z·sin²α/2 = 0.4151 (the textbook's (17 − z)/17 = 0.4118); feasible shift: x_min = 0.4151 … x(s_a = 0.3m) = 0.3877 (empty: no shift avoids both undercut and pointing)",
        "gears: wheel 0: the involute meets the fillet at r = 47.256 mm on the drawing, 47.256 mm exactly (the involute and the trochoid intersected): 8.38e−15·m apart; the touching points lie on the exact curves to 1.6e−15·m",
        "gears: wheel p (z = 10, x = 0.6) cut by the rack in 40 steps: undercut not shown on the drawing (the fillet meets the involute tangentially), no undercut by the criterion (the flank's end 3.9997 mm below the pitch line, the limit r·sin²α = 5.8489 mm)",
        "gears: wheel p: the involute meets the fillet at r = 47.2947 mm on the drawing, 47.2947 mm exactly (the involute and the trochoid intersected: they meet tangentially at the flank's end): 1.11e−15·m apart; the touching points lie on the exact curves to 2.8e−15·m",
    ] {
        assert!(pz1.contains(&s(line)), "{line}");
    }
    // The tip as `tmm report` reads it off pz1's drawing (the exact value at its drafting).
    let tip = |read: f64, pointed| GearsNote::Tip {
        wheel: s("p"),
        read,
        module: 0.01,
        exact: 1.0233e-3,
        pointed,
    };
    says(
        tip(1.0233e-3, true),
        "gears: wheel p: tip thickness s_a = 1.0233 mm = 0.1023·m read off the drawing (1.0233 mm exact): pointed (s_a < 0.3m)",
    );
    says(
        tip(5.8771e-3, false),
        "gears: wheel p: tip thickness s_a = 5.8771 mm = 0.5877·m read off the drawing (1.0233 mm exact)",
    );
    let shaper = scene_notes("shaper");
    for line in [
        "gears: pair z = 13/30, x = 0.8/0.471: α_w = 26.58075°, a_w = 316.2764 mm, y = 1.0912, Δy = 0.18, ε_α = 1.155; radial clearances 3.5024 and 3.5024 mm (c*·m = 3.5 mm)",
        "gears: by the tables: Δy = 0.18 (table), y = x_Σ − Δy = 1.091, a_w = m(z_Σ/2 + y) = 316.274 mm against the exact 316.2764 mm (y = 1.0912); the tip radii take the table's Δy",
        "gears: by the inv table (a row every 1′ to 6 decimals, read linearly): inv α_w = 0.036421 → α_w = 26°34′51″ (exact 26°34′50.7″); the seed prints 26°34′45″, 6″ off the table's own reading: not reproduced",
        "gears: erratum: the seed's ε_α = 1.22 comes from the base radii r·cos α_w = 81.382/187.8 mm and the base pitch πm·cos α_w = 39.334 mm (ε_α = B₁B₂/(πm·cos α_w) = 1.214); the base pitch is πm·cos α = 41.33 mm and ε_α = 1.155",
        "gears: wheel 1: x_min = h_a* − z·sin²α/2 = 0.2396 (the textbook's (17 − z)/17 = 0.2353); feasible shift: x_min = 0.2396 … x(s_a = 0.3m) = 0.5254",
    ] {
        assert!(shaper.contains(&s(line)), "{line}");
    }
}
