//! The crossing of two curves pinned by halving: each curve known by its points along a
//! parameter, a step of each that crosses halved at its middle, and the halves that cross
//! kept, until the steps come down to a given length.

use super::{DVec2, Segment};

/// A curve's parameter and its point there.
pub type CurvePoint = (f64, DVec2);

/// Pin the crossing of the curves `first` and `second` (each a point at a parameter, `None`
/// where it has none) from a step of each, `a` and `b`, whose chords cross: each step's
/// middle is traced, and of the four pairs of halves the one whose chords meet nearest to
/// both is kept (at rounding level, crossing chords may miss by an ulp). Stops after
/// `steps` halvings, where a curve has no point at a middle, where no pair of halves meets,
/// or once the two steps' chords are `narrow` long together. The last crossing found (at
/// first the given steps' chords'), `None` where those did not cross.
pub fn pin_crossing(
    (first, second): (impl Fn(f64) -> Option<DVec2>, impl Fn(f64) -> Option<DVec2>),
    [mut a, mut b]: [[CurvePoint; 2]; 2],
    steps: usize,
    narrow: f64,
) -> Option<DVec2> {
    let chord = |s: &[CurvePoint; 2]| Segment::new(s[0].1, s[1].1);
    let mut best = chord(&a).crossing(&chord(&b));
    for _ in 0..steps {
        let (qa, qb) = (0.5 * (a[0].0 + a[1].0), 0.5 * (b[0].0 + b[1].0));
        let (Some(ma), Some(mb)) = (first(qa), second(qb)) else {
            break;
        };
        let halves_a = [[a[0], (qa, ma)], [(qa, ma), a[1]]];
        let halves_b = [[b[0], (qb, mb)], [(qb, mb), b[1]]];
        let mut found: Option<([CurvePoint; 2], [CurvePoint; 2], DVec2, f64)> = None;
        for ha in &halves_a {
            for hb in &halves_b {
                if let Some((p, miss)) = chord(ha).meet(&chord(hb)) {
                    if found.as_ref().is_none_or(|f| miss < f.3) {
                        found = Some((*ha, *hb, p, miss));
                    }
                }
            }
        }
        let Some((ha, hb, p, _)) = found else { break };
        (a, b, best) = (ha, hb, Some(p));
        if (a[1].1 - a[0].1).length() + (b[1].1 - b[0].1).length() <= narrow {
            break;
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unit circle and the line y = x/2 cross at (2, 1)/√5: pinned from the steps
    /// φ ∈ [0, 1] of the circle and x ∈ [0, 2] of the line, to 1e-12.
    #[test]
    fn two_curves_crossing_is_pinned_by_halving_their_steps() {
        let circle = |phi: f64| Some(DVec2::from_angle(phi));
        let line = |x: f64| Some(DVec2::new(x, 0.5 * x));
        let a = [(0.0, circle(0.0).unwrap()), (1.0, circle(1.0).unwrap())];
        let b = [(0.0, line(0.0).unwrap()), (2.0, line(2.0).unwrap())];
        let p = pin_crossing((circle, line), [a, b], 80, 1e-12).expect("a crossing");
        let exact = DVec2::new(2.0, 1.0) / 5f64.sqrt();
        assert!(p.distance(exact) < 1e-12, "{p}");
        // Steps whose chords do not cross, and a curve with no point at the middle: none.
        let away = [(0.0, DVec2::new(5.0, 5.0)), (1.0, DVec2::new(6.0, 5.0))];
        assert_eq!(pin_crossing((circle, |_| None), [a, away], 80, 1e-12), None);
    }
}
