//! Where the lines of a fan stand apart: thin lines from one point (the further positions of
//! a link about its fixed pivot, a cam rocker's positions about O₂) run together near it and
//! print there as a black spot. The draughtsman begins them where they stand apart — the
//! least radius at which no spot the eye reads as one holds more lines than it shows apart.

use std::f64::consts::TAU;

/// Side of the square the eye reads as one spot (the legibility measure's cell), mm.
pub const SPOT_MM: f64 = 5.0;
/// Thin lines a spot holds apart: a thin line prints about 0,5 mm wide (the 0,25 mm pen and
/// its anti-aliased edges), so five of them ink half of a spot.
const LINES_PER_SPOT: usize = 5;
/// The step of the radius tried, mm.
const STEP_MM: f64 = 0.5;
/// Lines whose directions differ by less than this print as one, radians.
const SAME_RAD: f64 = 1e-9;

/// Where the lines at `angles` (radians) from one point begin, mm. The fan is crowded when
/// one spot at `from` mm (an arc of [`SPOT_MM`] there) holds more than [`LINES_PER_SPOT`] of
/// its distinct lines; it then begins at the least radius past `from` (in steps of 0,5 mm,
/// at most `most`) at which no spot holds more. An uncrowded fan begins at its point (0).
pub fn fan_start(mut angles: Vec<f64>, (from, most): (f64, f64)) -> f64 {
    for a in &mut angles {
        *a = a.rem_euclid(TAU);
    }
    angles.sort_by(f64::total_cmp);
    angles.dedup_by(|a, b| (*a - *b).abs() < SAME_RAD);
    let crowded = |r: f64| most_within(&angles, SPOT_MM / r) > LINES_PER_SPOT;
    if from.is_nan() || from <= 0.0 || !crowded(from) {
        return 0.0;
    }
    let mut r = from;
    while r < most && crowded(r) {
        r += STEP_MM;
    }
    r.min(most)
}

/// The most of the sorted `angles` within one window `width` radians wide, round the circle.
fn most_within(angles: &[f64], width: f64) -> usize {
    let n = angles.len();
    (0..n)
        .map(|i| {
            (0..n)
                .filter(|&j| (angles[j] - angles[i]).rem_euclid(TAU) <= width)
                .count()
        })
        .max()
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    const MOST: f64 = 8.0;

    #[test]
    fn a_crank_fan_stands_apart_and_a_narrow_fan_begins_out() {
        // Twelve crank positions 30° apart and the extreme 5° past one of them stand apart.
        let mut crank: Vec<f64> = (0..12).map(|i| i as f64 * TAU / 12.0).collect();
        crank.push(5f64.to_radians());
        assert_eq!(fan_start(crank, (SPOT_MM, MOST)), 0.0);
        // 26 lines within 97°: five to a spot only at 5 mm / (97° · 5/26) ≈ 15 mm, capped.
        let narrow: Vec<f64> = (0..26)
            .map(|i| (180.0 + i as f64 * 97.0 / 25.0).to_radians())
            .collect();
        assert_eq!(fan_start(narrow.clone(), (SPOT_MM, MOST)), MOST);
        assert_eq!(fan_start(narrow, (SPOT_MM, 20.0)), 15.0);
        // Four lines 10° apart stand apart; six are crowded at 5 mm (all within 57°) and five
        // to a spot once its arc is under 50°: 5 mm / 6 mm = 47,7°.
        let four: Vec<f64> = (0..4).map(|i| (i as f64 * 10.0).to_radians()).collect();
        assert_eq!(fan_start(four, (SPOT_MM, MOST)), 0.0);
        let six: Vec<f64> = (0..6).map(|i| (i as f64 * 10.0).to_radians()).collect();
        assert_eq!(fan_start(six, (SPOT_MM, MOST)), 6.0);
    }

    #[test]
    fn lines_on_one_direction_count_once() {
        // Six positions of a dwell on one line and four more 10° apart: five distinct lines.
        let mut dwell = vec![1.0; 6];
        dwell.extend((1..5).map(|i| 1.0 + (i as f64 * 10.0).to_radians()));
        assert_eq!(fan_start(dwell, (SPOT_MM, MOST)), 0.0);
        // Not crowded where the search begins at no radius.
        assert_eq!(fan_start(vec![0.0; 40], (0.0, MOST)), 0.0);
    }
}
